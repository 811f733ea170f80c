// Shared helpers of the embind adapter. Rules:
//  * no C++ exception may cross into JS (with Emscripten 3.1.6 a C++ exception thrown through an embind call leaves
//    the wasm stack pointer moved): every binding runs inside guarded(), which turns an exception into a returned
//    {error, kind} object that the JS layer rethrows as RangeError/TypeError/Error, prefixed with the JS function's
//    name when the message does not start with it;
//  * large arrays come in as (pointer, count) into the wasm heap, written by JS with HEAPF64.set, or read in place
//    from the block the caller filled through pointBuffer() (viewBlock);
//  * results leave as JS typed arrays: copied in C++, or laid out in one kept block (ResultBlock) that the JS layer
//    copies out right after the call, so that JS keeps no view that memory growth could detach; with
//    segment()/vectorize()'s { view: true } it hands out views on the block instead (valid until the next call that
//    fills or frees it: documented in wasm/js/index.d.ts).
#pragma once

#include "opaque.h"  // first: it configures rtl/vect/SimplifyCompatible.h

#include <emscripten/bind.h>
#include <emscripten/emscripten.h>
#include <emscripten/val.h>

#include <algorithm>
#include <cfloat>
#include <climits>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <stdexcept>
#include <string>
#include <utility>
#include <memory>
#include <new>
#include <vector>

#include <rtl/core/CoordinateCheck.h>

#include "kept.h"

namespace rtl_wasm {

using emscripten::val;

// An argument error whose JS counterpart is a TypeError (wrong kind of value, as opposed to a bad value).
struct type_error : std::invalid_argument {
  using std::invalid_argument::invalid_argument;
};

inline val errorValue(const char* kind, const char* message) {
  val r = val::object();
  r.set("error", val(std::string(message)));
  r.set("kind", val(kind));
  return r;
}

// The library's own label of a message ("CARMEN log, line 3: ..." -> "line 3: ...", "TfTree: unknown ..." ->
// "unknown ..."): the JS layer puts the name of the function the user called in front instead.
inline std::string withoutLabel(const char* message, const char* label) {
  std::string m(message);
  if (label == nullptr) return m;
  const std::string l(label);
  if (m.compare(0, l.size(), l) != 0) return m;
  std::size_t k = l.size();
  if (k < m.size() && (m[k] == ',' || m[k] == ':')) ++k;
  while (k < m.size() && m[k] == ' ') ++k;
  return m.substr(k);
}

// The {error, kind} value of the exception being handled (kind: TypeError, RangeError or Error); called from a catch
// block only. One copy of the type dispatch for all the bindings, not one per guarded() instantiation.
// `label`: the library's name for the failing part, dropped from the message (see withoutLabel).
[[gnu::noinline]] inline val currentError(const char* label) noexcept {
  try {
    try {
      throw;
    } catch (const type_error& e) {
      return errorValue("TypeError", withoutLabel(e.what(), label).c_str());
    } catch (const std::invalid_argument& e) {
      return errorValue("RangeError", withoutLabel(e.what(), label).c_str());
    } catch (const std::out_of_range& e) {
      return errorValue("RangeError", withoutLabel(e.what(), label).c_str());
    } catch (const std::length_error& e) {
      return errorValue("RangeError", withoutLabel(e.what(), label).c_str());
    } catch (const std::runtime_error& e) {  // the library's readers: malformed input data
      return errorValue("RangeError", withoutLabel(e.what(), label).c_str());
    } catch (const std::bad_alloc&) {
      return errorValue("RangeError", "out of wasm memory");
    } catch (const std::exception& e) {
      return errorValue("Error", withoutLabel(e.what(), label).c_str());
    }
  } catch (...) {  // not a std::exception, or whatever building the message above threw
    return errorValue("Error", "unknown C++ exception");
  }
}

// Runs f() and returns its val; any exception becomes {error, kind} (currentError).
template <class F>
val guarded(F&& f, const char* label = nullptr) noexcept {
  try {
    return f();
  } catch (...) {
    return currentError(label);
  }
}

inline const double* doubles(std::uintptr_t p) { return reinterpret_cast<const double*>(p); }

// The input buffer kept between calls (kept.h): JS writes a call's numbers there with one HEAPF64.set instead of a
// malloc, copy and free per call. It only grows (uninitialised), up to the numbers of kKeptPoints 3D points;
// returns 0 for more (the JS layer then allocates and frees that input itself) or when memory cannot grow.
struct InputBuffer {
  std::unique_ptr<double[]> data;
  std::size_t capacity = 0;
  // At least max(count, 64) numbers (count within the limit above); the old block is freed before the new one is
  // taken, so growing never needs both at once.
  std::uintptr_t reserve(double count) {
    const auto n = std::max<std::size_t>(static_cast<std::size_t>(count), 64);
    if (n > capacity) {
      data.reset();
      data.reset(new (std::nothrow) double[n]);
      capacity = data ? n : 0;
    }
    return reinterpret_cast<std::uintptr_t>(data.get());
  }
};
inline std::uintptr_t inputBuffer(double count) {
  if (!(count >= 0) || count > 3.0 * static_cast<double>(rtl_ops::kKeptPoints)) return 0;
  return rtl_ops::kept<InputBuffer>().reserve(count);
}
// The block behind pointBuffer() (api.js): JS fills it through a Float64Array view and passes that view back, and
// the call then reads it in place (no copy). Not a kept.h type: only pointBuffer() (growing it) and releaseBuffers()
// (count < 0) free it, so a view stays valid across every other call. Same limit as the input buffer (0 above it).
inline std::uintptr_t viewBlock(double count) {
  static InputBuffer b;
  if (!(count >= 0) || count > 3.0 * static_cast<double>(rtl_ops::kKeptPoints)) {
    b.data.reset();
    b.capacity = 0;
    return 0;
  }
  return b.reserve(count);
}
inline const char* bytes(std::uintptr_t p) { return reinterpret_cast<const char*>(p); }

// Copies n numbers into a new JS typed array (the view is only used for the copy, inside this call).
template <class T>
val typedArray(const char* ctor, const T* data, std::size_t n) {
  return val::global(ctor).new_(emscripten::typed_memory_view(n, data));
}
inline val f64(const double* d, std::size_t n) { return typedArray("Float64Array", d, n); }
inline val f64(const std::vector<double>& v) { return f64(v.data(), v.size()); }
inline val f32(const std::vector<float>& v) { return typedArray("Float32Array", v.data(), v.size()); }
inline val u32(const std::vector<std::uint32_t>& v) { return typedArray("Uint32Array", v.data(), v.size()); }
inline val i32(const std::vector<std::int32_t>& v) { return typedArray("Int32Array", v.data(), v.size()); }

inline std::string str(std::size_t v) { return std::to_string(v); }

// A call's results handed to JS as one number: the address of a kept block holding the scalars and arrays, which
// wasm/js/api.js (takeResults) copies out right after the call (or hands out as views: { view: true }). Building a result object field by field through
// embind costs ~4 JS calls per array (the constructor looked up by name, a memory view, the copy, the key string):
// 15-30 us per vectorize() call, as much as FTLS's own time on a few thousand points. Layout, in doubles:
//   [scalar count S, scalars..., array count A, (byte address, element count) per array..., array bytes...]
// each array starting on an 8-byte boundary (or read where it is, see take). The caller's arrays must stay alive
// until finish().
class ResultBlock {
 public:
  // Not inlined: one copy of the push_back code, not one per field of every binding.
  [[gnu::noinline]] ResultBlock& scalar(double v) {
    scalars_.push_back(v);
    return *this;
  }
  template <class T>
  ResultBlock& array(const std::vector<T>& v) { return bytes(v.data(), v.size(), sizeof(T)); }
  // A per-point array moved into the block's keeping instead of copied (one copy less: JS copies it out, or views
  // it); the block holds it until the next call's take() or releaseKept().
  ResultBlock& take(std::vector<std::int32_t>&& v) {
    taken32_ = std::move(v);
    return bytes(taken32_.data(), taken32_.size(), 0);
  }
  ResultBlock& take(std::vector<std::uint32_t>&& v) {
    takenU32_ = std::move(v);
    return bytes(takenU32_.data(), takenU32_.size(), 0);
  }
  // Lays the block out and returns its address; the next call's results reuse it. It only grows, uninitialised
  // (no zero-fill), except that a block of over kKeptPoints doubles is given back when a later result needs less
  // than half of it (a one-off huge result does not pin it).
  [[gnu::noinline]] double finish() {
    const std::size_t head = 2 + scalars_.size() + 2 * arrays_.size();
    std::size_t words = head;
    for (const auto& a : arrays_) words += (a.bytes + 7) / 8;
    if (words > capacity_ || (capacity_ > rtl_ops::kKeptPoints && words < capacity_ / 2)) {
      block_.reset();
      block_.reset(new double[words]);
      capacity_ = words;
    }
    double* b = block_.get();
    std::size_t k = 0;
    b[k++] = static_cast<double>(scalars_.size());
    for (double v : scalars_) b[k++] = v;
    b[k++] = static_cast<double>(arrays_.size());
    std::size_t at = head;
    for (const auto& a : arrays_) {
      // bytes 0: taken, read where it is (or empty)
      b[k++] = static_cast<double>(reinterpret_cast<std::uintptr_t>(a.bytes ? b + at : a.data));
      b[k++] = static_cast<double>(a.n);
      if (a.bytes) std::memcpy(b + at, a.data, a.bytes);
      at += (a.bytes + 7) / 8;
    }
    scalars_.clear();
    arrays_.clear();
    return static_cast<double>(reinterpret_cast<std::uintptr_t>(b));
  }

 private:
  [[gnu::noinline]] ResultBlock& bytes(const void* data, std::size_t n, std::size_t size) {
    arrays_.push_back({data, n, n * size});
    return *this;
  }
  struct Array {
    const void* data;
    std::size_t n, bytes;
  };
  std::vector<double> scalars_;
  std::vector<Array> arrays_;
  std::vector<std::int32_t> taken32_;
  std::vector<std::uint32_t> takenU32_;
  std::unique_ptr<double[]> block_;
  std::size_t capacity_ = 0;
};
inline ResultBlock& results() { return rtl_ops::kept<ResultBlock>(); }

// A FlatTrace (trace_ops.h) as {names: string[], data: Float64Array}; the JS layer builds the event objects.
template <class Flat>
val traceValue(const Flat& t) {
  val names = val::array();
  for (const auto& s : t.names) names.call<void>("push", val(s));
  val r = val::object();
  r.set("names", names);
  r.set("data", f64(t.data));
  return r;
}

// Milliseconds since an arbitrary start (performance.now()): the bindings report the time spent in the library
// itself as `computeMs`, so that benchmarks can split a call into compute and array transfer.
inline double nowMs() { return emscripten_get_now(); }

// Largest coordinate magnitude that fitLine and vectorize accept. The TLS fits keep sums of squared coordinates
// over up to 2^27 points, and their solvers square those sums again: with |coordinate| <= 1e18 the largest of these
// stays below 1e90, far from overflow (a point near 1e200 used to give a normal (0, 1) and an RMS of Infinity).
constexpr double kMaxCoordinate = 1e18;

// The shape of an interleaved point array: a whole number of points of `dim` numbers, at least `minPoints`.
[[gnu::noinline]] inline void checkShape(const char* fn, std::size_t len, std::size_t dim, std::size_t minPoints) {
  if (len % dim != 0)
    throw std::invalid_argument(std::string(fn) + ": points has " + str(len) + " numbers, not a multiple of dim " +
                                str(dim) + " (interleaved coordinates expected)");
  const std::size_t n = len / dim;
  if (n < minPoints)
    throw std::invalid_argument(std::string(fn) + ": needs at least " + str(minPoints) + " points, got " + str(n));
}

// Throws the message for xy[i], the first out-of-bounds coordinate that rtl::detail::firstBeyond found (NaN here
// means gaps were not allowed; a finite one is beyond kMaxCoordinate): no second scan of the input.
[[noreturn, gnu::noinline]] inline void throwBadCoordinate(const char* fn, const double* xy, std::size_t i,
                                                           std::size_t dim) {
  const double v = xy[i];
  if (std::isfinite(v)) {
    char buf[32];
    for (int digits = 1; digits <= 17; ++digits) {  // the shortest text that reads back as v
      std::snprintf(buf, sizeof buf, "%.*g", digits, v);
      if (std::strtod(buf, nullptr) == v) break;
    }
    throw std::invalid_argument(std::string(fn) + ": point " + str(i / dim) + " has the coordinate " + buf +
                                " at index " + str(i) + "; coordinates must be within +-1e18 (their squares are summed)");
  }
  throw std::invalid_argument(std::string(fn) + ": point " + str(i / dim) + " has a non-finite coordinate (" +
                              (std::isnan(v) ? "NaN" : (v > 0 ? "Infinity" : "-Infinity")) + ") at index " + str(i));
}

// Checks an interleaved point array: its shape (checkShape) and all numbers finite (unless gaps are allowed, where a
// point with any NaN coordinate is a gap; +-Infinity is always rejected) and, if given, none larger than
// maxMagnitude in absolute value. One pass (rtl::detail::firstBeyond); the message names the first offending number.
// For the bindings that read the points in place; segment and vectorize check the numbers while copying them.
[[gnu::noinline]] inline void checkPoints(const char* fn, const double* xy, std::size_t len, std::size_t dim,
                                          std::size_t minPoints, bool allowGaps, double maxMagnitude = HUGE_VAL) {
  checkShape(fn, len, dim, minPoints);
  const std::size_t bad = rtl::detail::firstBeyond(xy, len, maxMagnitude, allowGaps);
  if (bad < len) throwBadCoordinate(fn, xy, bad, dim);
}

}  // namespace rtl_wasm
