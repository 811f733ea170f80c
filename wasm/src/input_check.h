// The input checks of vectorize and segment (vect_ops.h, seg_ops.h), shared by the wasm bindings and the native
// comparison tool. A scalar test per coordinate inside the copy loop cost ~9 instructions a number (GCC does not
// vectorise a NaN-aware OR reduction); two lanes per step with GCC/clang vector extensions (SSE2 natively, wasm
// SIMD in the package) cost ~3.5, and the copy itself becomes a plain loop. No emscripten here.
#pragma once

#include <cmath>
#include <cstddef>
#include <cstring>

namespace rtl_ops {

// True if some x[i], i < count, is NaN (when nanIsBad) or has |x[i]| > limit.
inline bool anyBeyond(const double* x, std::size_t count, double limit, bool nanIsBad) {
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
    if (nanIsBad) {
      acc0 |= ~(a <= lim);  // NaN compares false: bad
      acc1 |= ~(b <= lim);
    } else {
      acc0 |= a > lim;  // NaN compares false: not bad
      acc1 |= b > lim;
    }
  }
  bad = (acc0[0] | acc0[1] | acc1[0] | acc1[1]) != 0;
#endif
  for (; i < count; ++i) bad |= nanIsBad ? !(std::fabs(x[i]) <= limit) : std::fabs(x[i]) > limit;
  return bad;
}

// Copies count numbers from x to dst and returns whether one has |x[i]| > limit (NaN passes: a gap): the input check
// and the copy in one pass over the input, two lanes per step. Not inlined: inside the one large wasm function of a
// binding, V8's TurboFan kept the loop's accumulator and pointers in stack slots (a store and a reload per step); the
// separate check and copy loops of segment took 0.125 + 0.05 ms there at 100k 2D points, 0.03 + 0.03 natively.
[[gnu::noinline]] inline bool copyBeyond(const double* x, std::size_t count, double* dst, double limit) {
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
    std::memcpy(dst + i, &a, sizeof a);
    std::memcpy(dst + i + 2, &b, sizeof b);
    acc0 |= (V)((M)a & absMask) > lim;  // NaN compares false: not bad
    acc1 |= (V)((M)b & absMask) > lim;
  }
  bad = ((acc0[0] | acc0[1]) | (acc1[0] | acc1[1])) != 0;
#endif
  for (; i < count; ++i) {
    dst[i] = x[i];
    bad |= std::fabs(x[i]) > limit;
  }
  return bad;
}

}  // namespace rtl_ops
