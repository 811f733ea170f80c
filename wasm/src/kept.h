// Objects kept alive between calls of the wasm bindings (and of the native twin, tests/tools/rtl_native.cpp): the
// vectorizers, the segmenter and their point vectors hold grow-only buffers (prefix sums, DP's stacks, CAR's
// flags), so keeping one object per type means a repeated call neither allocates nor zero-fills them. Inputs above
// kKeptPoints points are served too, but their buffers are released after the call (releaseKeptAbove): a one-off
// huge scan should not pin hundreds of MB of the heap for good. No emscripten here.
#pragma once

#include <cstddef>
#include <new>
#include <stdexcept>

namespace rtl_ops {

// Largest input (points) whose buffers stay allocated after the call: twice the 1M-point scans the package is
// tuned for.
constexpr std::size_t kKeptPoints = std::size_t(1) << 21;

// The reset functions of the kept types, in a fixed table: registering a type never allocates, so releaseKept()
// brings the heap back to where it was before the first call.
struct KeptResets {
  static constexpr std::size_t capacity = 64;
  void (*reset[capacity])() = {};
  std::size_t count = 0;
};
inline KeptResets& keptResets() {
  static thread_local KeptResets r;
  return r;
}

// The kept object of type T (default constructed on first use; one per thread: the wasm module has one).
template <class T>
T& kept() {
  static thread_local T t;
  static thread_local const bool registered = [] {
    auto& r = keptResets();
    if (r.count == KeptResets::capacity) throw std::logic_error("kept.h: more kept types than KeptResets::capacity");
    // Destroy and rebuild rather than assign: types with a declared destructor have no move assignment, and a
    // copy assignment from a fresh object would keep the buffers' capacity.
    r.reset[r.count++] = [] {
      T& old = kept<T>();
      old.~T();
      new (&old) T();
    };
    return true;
  }();
  (void)registered;
  return t;
}

// Frees every kept object's buffers (each is replaced by a fresh one).
inline void releaseKept() {
  const auto& r = keptResets();
  for (std::size_t k = 0; k < r.count; ++k) r.reset[k]();
}

// Releases the kept buffers when it goes out of scope if the call's input had more than kKeptPoints points.
struct ReleaseKeptAbove {
  std::size_t n;
  ~ReleaseKeptAbove() {
    if (n > kKeptPoints) releaseKept();
  }
};

}  // namespace rtl_ops
