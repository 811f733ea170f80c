// The input checks of vectorize and segment (vect_ops.h, seg_ops.h), shared by the wasm bindings and the native
// comparison tool. A scalar test per coordinate inside the copy loop cost ~9 instructions a number (GCC does not
// vectorise a NaN-aware OR reduction); two lanes per step with GCC/clang vector extensions (SSE2 natively, wasm
// SIMD in the package) cost ~3.5, and the copy itself becomes a plain loop. No emscripten here.
#pragma once

#include <cmath>
#include <cstddef>
#include <cstring>

namespace rtl_ops {

// True if some x[i], i < count, is NaN or has |x[i]| > limit (vectorize's check; segment's, where NaN is a gap, is
// copyBeyond below).
inline bool anyBeyond(const double* x, std::size_t count, double limit) {
  std::size_t i = 0;
  bool bad = false;
#if defined(__GNUC__)
  typedef double V __attribute__((vector_size(16)));
  typedef long long M __attribute__((vector_size(16)));
  const M absMask = M{} + 0x7fffffffffffffffLL;
  const V lim = V{} + limit;
  M acc0{}, acc1{};
  for (; i + 4 <= count; i += 4) {
    V a, b;
    std::memcpy(&a, x + i, sizeof a);
    std::memcpy(&b, x + i + 2, sizeof b);
    a = (V)((M)a & absMask);
    b = (V)((M)b & absMask);
    acc0 |= ~(a <= lim);  // NaN compares false: bad
    acc1 |= ~(b <= lim);
  }
  bad = (acc0[0] | acc0[1] | acc1[0] | acc1[1]) != 0;
#endif
  for (; i < count; ++i) bad |= !(std::fabs(x[i]) <= limit);
  return bad;
}

// Copies count numbers from x to dst and returns whether one has |x[i]| > limit (NaN passes: a gap): the input check
// and the copy in one pass over the input. Not inlined: inside the one large wasm function of a binding, V8's
// TurboFan kept the loop's accumulators and pointers in stack slots (a store and a reload per step); the separate
// check and copy loops of segment took 0.125 + 0.05 ms there at 100k 2D points, 0.03 + 0.03 natively. The check
// keeps the largest |x[i]| per lane (a > m ? a : m skips NaN) rather than OR-ing comparison masks: clang makes
// v128.bitselect of the OR, three instructions in V8 against one for the maximum (f64x2.pmax); 200k numbers in
// wasm 0.056 -> 0.034 ms, natively 0.034 both ways. Eight numbers a step: V8 checks for interrupts once a step.
[[gnu::noinline]] inline bool copyBeyond(const double* x, std::size_t count, double* dst, double limit) {
  std::size_t i = 0;
  bool bad = false;
#if defined(__GNUC__)
  typedef double V __attribute__((vector_size(16)));
  typedef long long M __attribute__((vector_size(16)));
  const M absMask = M{} + 0x7fffffffffffffffLL;
  V m0{}, m1{};
  for (; i + 8 <= count; i += 8) {
    V a, b, c, d;
    std::memcpy(&a, x + i, sizeof a);
    std::memcpy(&b, x + i + 2, sizeof b);
    std::memcpy(&c, x + i + 4, sizeof c);
    std::memcpy(&d, x + i + 6, sizeof d);
    std::memcpy(dst + i, &a, sizeof a);
    std::memcpy(dst + i + 2, &b, sizeof b);
    std::memcpy(dst + i + 4, &c, sizeof c);
    std::memcpy(dst + i + 6, &d, sizeof d);
    a = (V)((M)a & absMask);
    b = (V)((M)b & absMask);
    c = (V)((M)c & absMask);
    d = (V)((M)d & absMask);
    m0 = a > m0 ? a : m0;
    m1 = b > m1 ? b : m1;
    m0 = c > m0 ? c : m0;
    m1 = d > m1 ? d : m1;
  }
  bad = (m0[0] > limit) | (m0[1] > limit) | (m1[0] > limit) | (m1[1] > limit);
#endif
  for (; i < count; ++i) {
    dst[i] = x[i];
    bad |= std::fabs(x[i]) > limit;
  }
  return bad;
}

}  // namespace rtl_ops
