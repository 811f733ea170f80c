// Objects kept alive between calls of the wasm bindings (and of the native twin, tests/tools/rtl_native.cpp): the
// vectorizers, the segmenter, the polyline extractor and their point vectors hold grow-only buffers (prefix sums,
// DP's stacks and tables, CAR's flags), so keeping one object per type means a repeated call neither allocates nor
// zero-fills them. Inputs above
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

// The release functions of the kept types, in a fixed table: registering a type never allocates.
struct KeptReleases {
  static constexpr std::size_t capacity = 64;
  void (*release[capacity])() = {};
  std::size_t count = 0;
};
inline KeptReleases& keptReleases() {
  static KeptReleases r;
  return r;
}

// Storage of the kept T: built on first use, destroyed by releaseKept() and built again on the next use, so that
// after a release the heap is exactly as before the first call (no default-constructed leftovers).
template <class T>
struct KeptSlot {
  alignas(T) unsigned char storage[sizeof(T)];
  bool alive = false;
  T* get() { return std::launder(reinterpret_cast<T*>(storage)); }
};
template <class T>
KeptSlot<T>& keptSlot() {
  static KeptSlot<T> slot;  // trivially destructible: the object inside lives until releaseKept() or exit
  return slot;
}

// The kept object of type T. Not thread-safe: one caller at a time (the wasm module has one thread).
template <class T>
T& kept() {
  static const bool registered = [] {
    auto& r = keptReleases();
    if (r.count == KeptReleases::capacity) throw std::logic_error("kept.h: more kept types than KeptReleases::capacity");
    r.release[r.count++] = [] {
      auto& s = keptSlot<T>();
      if (!s.alive) return;
      s.get()->~T();
      s.alive = false;
    };
    return true;
  }();
  (void)registered;
  auto& s = keptSlot<T>();
  if (!s.alive) {
    new (s.storage) T();
    s.alive = true;
  }
  return *s.get();
}

// Frees every kept object and its buffers (they are built again on their next use).
inline void releaseKept() {
  const auto& r = keptReleases();
  for (std::size_t k = 0; k < r.count; ++k) r.release[k]();
}

// Releases the kept buffers when it goes out of scope if the call's input had more than kKeptPoints points.
struct ReleaseKeptAbove {
  std::size_t n;
  ~ReleaseKeptAbove() {
    if (n > kKeptPoints) releaseKept();
  }
};

}  // namespace rtl_ops
