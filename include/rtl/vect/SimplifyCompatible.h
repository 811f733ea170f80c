// Polyline simplification that keeps exactly the points the simplify-js library keeps: its radial-distance
// pre-pass (skipped in high-quality mode) and its Douglas-Peucker on the squared distance to the chord *segment*.
// The arithmetic is that library's, in double and in its order, so the kept points are identical to a JavaScript
// run on the same doubles. Fused multiply-add would change roundings: GCC ignores FP_CONTRACT and clang's
// -ffp-contract=fast ignores its `fp contract(off)` pragma, so when GCC or clang targets FMA hardware every
// product passes an empty asm barrier that prevents fusing (elsewhere, e.g. wasm, there is no FMA to contract to;
// MSVC does not contract unless /fp:contract or /fp:fast is given). With GCC and clang (SSE2, NEON, wasm simd128)
// Douglas-Peucker's scan computes two points per vector instruction, each lane with the scalar operations in the
// scalar order (so the same doubles), and finds the first maximum without a branch per point (in 2D, ranges of
// up to 32 points do so inlined into the loop over ranges: farthestShort); in 2D, longer ranges are first filtered
// in float, four points per vector and without a division, and only the points within a proven rounding bound of
// the largest value get the exact double distance (farthestFiltered).
// The 2D radial pre-pass computes eight points' distances to the last kept point per step, each lane the scalar
// getSqDist, and goes point by point only from the first that passes (radialPass).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstring>
#include <limits>
#include <memory>
#include <stdexcept>
#include <type_traits>
#include <utility>
#include <vector>

#include "rtl/core/CoordinateCheck.h"

#if defined(__GNUC__) && defined(__SSE2__)
#include <emmintrin.h>
#elif defined(__GNUC__) && defined(__wasm_simd128__)
#include <wasm_simd128.h>
#endif

// The passes over all points (radialPass, copyAll) and Douglas-Peucker (simplify) are functions of their own, not
// inlined into simplifyIndices: a just-in-time compiler that optimizes hot functions one at a time then optimizes
// each pass early instead of waiting for the whole (measured in docs/vect.md, "Measurements behind the vect headers").
// noinline keeps the compiler from inlining them; Binaryen (wasm-opt, which emcc runs at link) still inlines a
// function with one caller, so the callers call them through RTL_SIMPLIFY_PASS_CALL(f): by default f itself; an
// includer that must keep each pass a function of its own defines it, before including this header, to hide which
// function f is from the optimizer (e.g. by reading f back through a volatile variable).
#if defined(__GNUC__)
#define RTL_SIMPLIFY_NOINLINE __attribute__((noinline))
#else
#define RTL_SIMPLIFY_NOINLINE
#endif
#ifndef RTL_SIMPLIFY_PASS_CALL
#define RTL_SIMPLIFY_PASS_CALL(...) (__VA_ARGS__)
#endif

namespace rtl
{
    namespace detail
    {
        //! a * b, never fused with a following addition.
        inline double product(double a, double b)
        {
#if defined(__GNUC__) && (defined(__FMA__) || defined(__aarch64__) || defined(__ARM_FEATURE_FMA))
            double p = a * b;
#if defined(__x86_64__) || defined(__i386__)
            asm("" : "+x"(p));
#elif defined(__aarch64__)
            asm("" : "+w"(p));
#else
            volatile double v = p;
            p = v;
#endif
            return p;
#else
            return a * b;
#endif
        }

        //! Squared distance of point p from point q (simplify-js getSqDist).
        template<int dim>
        inline double pointDistance2(const double *p, const double *q)
        {
#ifdef __clang__
#pragma clang fp contract(off)
#endif
            double s = product(p[0] - q[0], p[0] - q[0]);
            for (int k = 1; k < dim; ++k)
                s = s + product(p[k] - q[k], p[k] - q[k]);
            return s;
        }

        //! Chord a -> b prepared for segmentDistance2: its end points, difference and squared length.
        template<int dim>
        struct Chord
        {
            double a[dim], b[dim], d[dim], dd;
            Chord(const double *pa, const double *pb)
            {
#ifdef __clang__
#pragma clang fp contract(off)
#endif
                for (int k = 0; k < dim; ++k)
                {
                    a[k] = pa[k];
                    b[k] = pb[k];
                    d[k] = pb[k] - pa[k];
                }
                dd = product(d[0], d[0]);
                for (int k = 1; k < dim; ++k)
                    dd = dd + product(d[k], d[k]);
            }
        };

        //! Squared distance of p from the chord segment (simplify-js getSqSegDist), without branches. The library
        //! skips the projection when the chord has zero difference; then t is 0/0 = NaN here, which selects a just
        //! as the skip does, so no test is needed (a chord whose squared length underflows divides by 0 in both).
        template<int dim>
        inline double segmentDistance2(const double *p, const Chord<dim> &c)
        {
#ifdef __clang__
#pragma clang fp contract(off)
#endif
            double num = product(p[0] - c.a[0], c.d[0]);
            for (int k = 1; k < dim; ++k)
                num = num + product(p[k] - c.a[k], c.d[k]);
            const double t = num / c.dd;
            double s = 0;
            for (int k = 0; k < dim; ++k)
            {
                const double q = t > 1 ? c.b[k] : (t > 0 ? c.a[k] + product(c.d[k], t) : c.a[k]);
                const double e = p[k] - q;
                s = k == 0 ? product(e, e) : s + product(e, e);
            }
            return s;
        }

        //! The m points Douglas-Peucker runs on, in double, one array per axis (axis k starts at k * stride), so
        //! that two consecutive points' coordinates load as one vector.
        //! g: the largest |coordinate| of the points (bounds the filter's rounding errors, farthestFiltered);
        //! f: the points as floats for that filter, each axis zero-padded to fstride (a multiple of four beyond m);
        //! scratch: the filter's values. c is not zero-filled: every value read is written first (zero-filling
        //! would be a pass over all of it for nothing).
        template<int dim>
        struct AxisPoints
        {
            std::size_t m = 0, stride = 0;
            double g = 0;
            std::unique_ptr<double[]> c;
            std::size_t fstride = 0;
            std::unique_ptr<float[]> f;   // 2D, when |coordinates| <= 1e9: x then y, fstride apart
            std::unique_ptr<float[]> scratch;   // fstride values, of a const search (each written before it is read)
            const double *axis(int k) const { return c.get() + static_cast<std::size_t>(k) * stride; }
        };

#if defined(__GNUC__)
        //! Two doubles in one SSE2 / NEON / wasm simd128 register: every lane computes the scalar formula with
        //! the same operations in the same order, so each lane's value is the scalar one bit for bit.
        typedef double Double2 __attribute__((vector_size(16)));

        //! a * b lane-wise, never fused with a following addition (see product()).
        inline Double2 product(Double2 a, Double2 b)
        {
            Double2 p = a * b;
#if defined(__FMA__) || defined(__aarch64__) || defined(__ARM_FEATURE_FMA)
#if defined(__x86_64__) || defined(__i386__)
            asm("" : "+x"(p));
#elif defined(__aarch64__)
            asm("" : "+w"(p));
#else
            volatile Double2 v = p;
            p = v;
#endif
#endif
            return p;
        }

        //! `m < v ? v : m` lane-wise: the larger, m when equal or when v is NaN. One instruction where the target
        //! has one of exactly this meaning (SSE2 maxpd, wasm f64x2.pmax; not NEON's NaN-propagating fmax).
        inline Double2 maxKeep(Double2 m, Double2 v)
        {
#if defined(__SSE2__)
            return _mm_max_pd(v, m);   // v > m ? v : m
#elif defined(__wasm_simd128__)
            return (Double2)wasm_f64x2_pmax((v128_t)m, (v128_t)v);
#else
            return m < v ? v : m;
#endif
        }

        //! The end of a short range's scan (farthestPairs, farthestShort): d2 holds the range's distances, mx
        //! their lane maxima taken from `best` on. The first index (from begin) holding the largest if it exceeds
        //! best (which it then holds), else 0.
        __attribute__((always_inline)) inline std::size_t firstOfMaximum(const double *d2, Double2 mx, std::size_t begin,
                                                                         double &best)
        {
            const double top = mx[0] < mx[1] ? mx[1] : mx[0];
            if (!(top > best))
                return 0;
            std::size_t q = 0;
            while (d2[q] != top)
                ++q;
            best = top;
            return begin + q;
        }

        //! Lane masks of Double2 comparisons: whether one is set, and the set lanes as bits (lane 0 the lowest),
        //! one instruction each where the target has one.
        typedef long long Index2 __attribute__((vector_size(16)));
        inline bool anyLane(Index2 m)
        {
#if defined(__SSE2__)
            return _mm_movemask_pd((__m128d)m) != 0;
#elif defined(__wasm_simd128__)
            return wasm_v128_any_true((v128_t)m);
#else
            return (m[0] | m[1]) != 0;
#endif
        }
        inline unsigned laneBits(Index2 m)
        {
#if defined(__SSE2__)
            return static_cast<unsigned>(_mm_movemask_pd((__m128d)m));
#elif defined(__wasm_simd128__)
            return static_cast<unsigned>(wasm_i64x2_bitmask((v128_t)m));
#else
            return (m[0] ? 1u : 0u) | (m[1] ? 2u : 0u);
#endif
        }

        //! The chord in vector lanes, both lanes alike.
        template<int dim>
        struct ChordPair
        {
            Double2 a[dim], b[dim], d[dim], dd;
            explicit ChordPair(const Chord<dim> &c)
            {
                for (int k = 0; k < dim; ++k)
                {
                    a[k] = Double2{} + c.a[k];
                    b[k] = Double2{} + c.b[k];
                    d[k] = Double2{} + c.d[k];
                }
                dd = Double2{} + c.dd;
            }
        };

        //! segmentDistance2 of points i and i + 1 (read from the axis arrays) from the chord, one per lane, for a
        //! chord whose differences d are finite. The scalar projection `t > 1 ? b : (t > 0 ? a + d t : a)` is
        //! computed as `t > 1 ? b : a + d max(t, 0)`: for t <= 0 or NaN, d * 0 is a zero and a + 0 is a (a -0
        //! may become +0, which changes no square).
        template<int dim>
        inline Double2 segmentDistance2Pair(const AxisPoints<dim> &pts, std::size_t i, const ChordPair<dim> &c)
        {
#ifdef __clang__
#pragma clang fp contract(off)
#endif
            Double2 p[dim];
            for (int k = 0; k < dim; ++k)
                std::memcpy(&p[k], pts.axis(k) + i, sizeof(Double2));
            Double2 num = product(p[0] - c.a[0], c.d[0]);
            for (int k = 1; k < dim; ++k)
                num = num + product(p[k] - c.a[k], c.d[k]);
            const Double2 t = num / c.dd;
            const Double2 zero = Double2{}, one = zero + 1.0;
            const Double2 tc = maxKeep(zero, t);
            Double2 s = zero;
            for (int k = 0; k < dim; ++k)
            {
                Double2 q = c.a[k] + product(c.d[k], tc);
                q = t > one ? c.b[k] : q;
                const Double2 e = p[k] - q;
                s = k == 0 ? product(e, e) : s + product(e, e);
            }
            return s;
        }

        //! farthest() for a chord whose differences are finite. Blocks of 16 points (8 vectors of 2) are reduced
        //! to their lane maxima in two chains started from the running maxima (so NaN distances never enter);
        //! each lane remembers the first block where it raised its maximum (strict `>`), all without branches.
        //! At the end the largest lane value v wins; the first block where a lane reached v is the first block
        //! holding v, and a walk of that one block finds the first index of v: the scan's first maximum.
        template<int dim>
        std::size_t farthestPairs(const AxisPoints<dim> &pts, std::size_t first, std::size_t last,
                                  const ChordPair<dim> &c, double &best)
        {
            constexpr std::size_t block = 16;
            const std::size_t begin = first + 1;
            if (last - begin <= block)
            {
                // One block at most (most ranges at the bottom of the recursion): each distance once, their
                // maximum from `best` on (so NaN never enters), then the first index holding it if it exceeds
                // best: the library's scan, without its branch per point (mispredicted on ragged data). An odd
                // count's last pair reads point `last`, whose lane is set to best.
                alignas(16) double d2[block];
                const std::size_t n = last - begin;
                Double2 mx = Double2{} + best;
                std::size_t q = 0;
                for (; q + 2 <= n; q += 2)
                {
                    const Double2 v = segmentDistance2Pair<dim>(pts, begin + q, c);
                    std::memcpy(d2 + q, &v, sizeof v);
                    mx = maxKeep(mx, v);
                }
                if (q < n)
                {
                    Double2 v = segmentDistance2Pair<dim>(pts, begin + q, c);
                    v[1] = best;
                    std::memcpy(d2 + q, &v, sizeof v);
                    mx = maxKeep(mx, v);
                }
                return firstOfMaximum(d2, mx, begin, best);
            }
            // Whole blocks, then one partial block of pairs; an odd point left over is compared last.
            const std::size_t pairs_end = begin + ((last - begin) & ~std::size_t(1));
            Double2 mx = Double2{} + best;
            Index2 at = Index2{} - 1;
            long long number = 0;
            std::size_t i = begin;
            for (; i < pairs_end; i += block, ++number)
            {
                const std::size_t n = pairs_end - i < block ? pairs_end - i : block;
                Double2 m0 = mx, m1 = mx;
                if (n == block)
                    for (std::size_t q = 0; q < block; q += 4)
                    {
                        m0 = maxKeep(m0, segmentDistance2Pair<dim>(pts, i + q, c));
                        m1 = maxKeep(m1, segmentDistance2Pair<dim>(pts, i + q + 2, c));
                    }
                else
                    for (std::size_t q = 0; q < n; q += 2)
                        m0 = maxKeep(m0, segmentDistance2Pair<dim>(pts, i + q, c));
                const Double2 m = maxKeep(m0, m1);
                const Index2 raised = m > mx;
                at = raised ? Index2{} + number : at;
                mx = m;
            }
            std::size_t index = 0;
            const double top = mx[0] < mx[1] ? mx[1] : mx[0];
            if (top > best)
            {
                const long long b0 = mx[0] == top ? at[0] : -1, b1 = mx[1] == top ? at[1] : -1;
                const long long win = b0 < 0 ? b1 : (b1 < 0 || b0 < b1 ? b0 : b1);
                const std::size_t start = begin + static_cast<std::size_t>(win) * block;
                const std::size_t n = pairs_end - start < block ? pairs_end - start : block;
                alignas(16) double d2[block];
                for (std::size_t q = 0; q < n; q += 2)
                {
                    const Double2 s = segmentDistance2Pair<dim>(pts, start + q, c);
                    std::memcpy(d2 + q, &s, sizeof(Double2));
                }
                std::size_t q = 0;
                while (d2[q] != top)
                    ++q;
                best = top;
                index = start + q;
            }
            if (i > pairs_end)
                i = pairs_end;
            if (i < last)
            {
                // The odd point left over: after all the others, so it wins only by a larger value.
                const Double2 s = segmentDistance2Pair<dim>(pts, last - 1, c);
                if (s[0] > best) { best = s[0]; index = last - 1; }
            }
            return index;
        }

        //! Four floats in one SSE / wasm simd128 register, for the filter of farthestFiltered.
        typedef float Float4 __attribute__((vector_size(16)));
        inline Float4 maxKeep(Float4 m, Float4 v)
        {
#if defined(__SSE2__)
            return _mm_max_ps(v, m);
#elif defined(__wasm_simd128__)
            return (Float4)wasm_f32x4_pmax((v128_t)m, (v128_t)v);
#else
            return m < v ? v : m;
#endif
        }
        inline Float4 minKeep(Float4 v, Float4 h)
        {
#if defined(__SSE2__)
            return _mm_min_ps(v, h);
#elif defined(__wasm_simd128__)
            return (Float4)wasm_f32x4_pmin((v128_t)v, (v128_t)h);
#else
            return h < v ? h : v;
#endif
        }

        //! Lanes of a Float4 comparison as bits (lane 0 the lowest).
        typedef int Int4 __attribute__((vector_size(16)));
        inline unsigned laneBits4(Int4 m)
        {
#if defined(__SSE2__)
            return static_cast<unsigned>(_mm_movemask_ps((__m128)m));
#elif defined(__wasm_simd128__)
            return static_cast<unsigned>(wasm_i32x4_bitmask((v128_t)m));
#else
            return (m[0] ? 1u : 0u) | (m[1] ? 2u : 0u) | (m[2] ? 4u : 0u) | (m[3] ? 8u : 0u);
#endif
        }

        //! The filter of farthestFiltered: the error bound's factors (see there) and its limits (G <= 1e9, so that
        //! no square overflows a float; |d|^2 >= 1e-12, so that underflow costs less than filter_abs in distance;
        //! the part 4 eps G of the bound at most 1/64 of the tolerance, else the band of candidates is too wide to
        //! gain). Ranges of at most filter_min_points interior points are scanned exactly (farthestShort), longer
        //! ones filtered (32 measured best; docs/vect.md).
        constexpr double filter_eps = 0x1p-24, filter_abs = 1e-15, filter_max_g = 1e9, filter_min_dd = 1e-12;
        constexpr std::size_t filter_min_points = 32;

        //! farthest() for a 2D range, without a division per point and four points per vector: a filter in
        //! float on the points' float copies (AxisPoints::f), then the library's exact double distances J of
        //! the few points that can be the farthest. The filter's value of a point p is S = cross^2 + w^2 (u = p - a,
        //! d = b - a, cross = u x d, w = u.d minus u.d clamped to [0, d.d]), in real numbers d.d times the squared
        //! distance from the segment: w is 0 where p projects inside it, u.d (t < 0) or (p - b).d (t > 1) outside,
        //! where |u|^2 d.d = (u.d)^2 + cross^2. Error bound rho on sqrt(S) / |d| against sqrt(J), eps = 2^-24, G the
        //! largest |coordinate|, |d| the float chord's length (exact in double):
        //!  - rounding p, a, b to float moves a point's distance from the segment by <= 2 sqrt(2) eps G;
        //!  - float arithmetic: u, d, their products and sums each err by eps relative, so cross and u.d by
        //!    <= 4 eps |u||d|, w by <= 9 eps |u||d|, sqrt(S) by <= 11.4 eps |u||d|, and |u| <= D + |d| (D: the
        //!    point's distance, at most the largest one, top, to within rho);
        //!  - the library's own J is within ~60 2^-53 G of the exact distance squared's root;
        //! so rho = 4 eps G + 16 eps (top + |d|) + 2^-46 G + filter_abs covers all with a margin. A point can hold
        //! the largest J, or a J > best, only if sqrt(S) >= max(sqrt(max S) - 2 rho |d|, (sqrt(best) - rho) |d|).
        //! Pass 1 writes every S (the lanes past the range -inf) to the scratch and keeps their maximum; pass 2
        //! computes J for the points whose S passes, in order, with the library's `>`: the first maximum and its
        //! value are simplify-js's, whatever the filter's roundings. One pass and one division per candidate
        //! (usually one per range), whatever the range's length: most ranges at the bottom of the recursion hold
        //! a few points, and this costs them less than an exact distance per point.
        inline std::size_t farthestFiltered(const AxisPoints<2> &pts, std::size_t first, std::size_t last,
                                            const Chord<2> &chord, double &best)
        {
            // Groups of four from first + 1; the last group's lanes past the range read the next points or the
            // zero padding (AxisPoints::f) and are set to -inf, which neither raises the maximum nor passes.
            const std::size_t begin = first + 1, n = last - begin, full = n & ~std::size_t(3);
            const float *xf = pts.f.get() + begin, *yf = xf + pts.fstride;
            const float ax = xf[-1], ay = yf[-1], dx = xf[n] - ax, dy = yf[n] - ay;
            const Float4 vax = Float4{} + ax, vay = Float4{} + ay, vdx = Float4{} + dx, vdy = Float4{} + dy,
                         vdd = Float4{} + (dx * dx + dy * dy), zero = Float4{};
            float *s = pts.scratch.get();
            const auto filter = [&](std::size_t q) {   // S of points begin + q .. begin + q + 3
                Float4 px, py;
                std::memcpy(&px, xf + q, sizeof px);
                std::memcpy(&py, yf + q, sizeof py);
                const Float4 ux = px - vax, uy = py - vay;
                const Float4 num = ux * vdx + uy * vdy, cross = ux * vdy - uy * vdx;
                const Float4 w = num - minKeep(maxKeep(zero, num), vdd);
                return cross * cross + w * w;
            };
            Float4 mx = zero - 1.0f;
            std::size_t q = 0;
            for (; q < full; q += 4)
            {
                const Float4 v = filter(q);
                std::memcpy(s + q, &v, sizeof v);
                mx = maxKeep(mx, v);
            }
            if (q < n)
            {
                const Float4 lane = {0, 1, 2, 3};
                Float4 v = filter(q);
                v = lane < Float4{} + static_cast<float>(n - q) ? v : Float4{} - __builtin_inff();
                std::memcpy(s + q, &v, sizeof v);
                mx = maxKeep(mx, v);
            }
            const double len = std::sqrt(double(dx) * dx + double(dy) * dy);   // exact square and sum
            const double top = std::sqrt(double(std::fmax(std::fmax(mx[0], mx[1]), std::fmax(mx[2], mx[3]))));
            const double rho = filter_eps * (4 * pts.g + 16 * (top / len * (1 + 0x1p-10) + len)) + 0x1p-46 * pts.g + filter_abs;
            const double low = std::fmax(top - 2 * rho * len, (std::sqrt(best) - rho) * len) * (1 - 0x1p-20);
            // S >= low^2, less a relative margin for the roundings of sqrt, *, - and the conversion to float
            const Float4 thr = Float4{} + (low > 0 ? static_cast<float>(low * low * (1 - 0x1p-20)) : -1.0f);
            // Pass 2: J of the points whose S passes (the others cannot win), in order.
            std::size_t index = 0;
            double p[2];
            const auto passing = [&](std::size_t g) {   // S >= thr in the group at g, as lane bits
                Float4 v;
                std::memcpy(&v, s + g, sizeof v);
                return v >= thr;
            };
            for (q = 0; q < n; q += 4)
            {
                // Sixteen at a time while whole: most fail (one point in a range is the farthest).
                if ((q & 15) == 0)
                    while (q + 16 <= n && !laneBits4((passing(q) | passing(q + 4)) | (passing(q + 8) | passing(q + 12))))
                        q += 16;
                if (q >= n)
                    break;
                for (unsigned bits = laneBits4(passing(q)); bits; bits &= bits - 1)
                {
                    const std::size_t i = begin + q + static_cast<std::size_t>(__builtin_ctz(bits));
                    p[0] = pts.axis(0)[i];
                    p[1] = pts.axis(1)[i];
                    const double d2 = segmentDistance2<2>(p, chord);
                    if (d2 > best) { best = d2; index = i; }
                }
            }
            return index;
        }
#endif

#if defined(__GNUC__)
        //! farthest() for a 2D range of 1 to filter_min_points interior points whose chord differences dx, dy are
        //! finite: the arithmetic of segmentDistance2Pair (so each lane's value is the scalar one), from values
        //! held in registers, inlined into the Douglas-Peucker loop. Most ranges are this short (docs/vect.md); the
        //! chord and lane set-up of the general path, or the filter's, cost them more than their distances. The maximum is taken from `best` on (so NaN never enters),
        //! then the first index holding it if it exceeds best: the library's scan, without its branch per point
        //! (mispredicted on ragged data). An odd count's last pair reads point `last`, whose lane is set to best.
        __attribute__((always_inline)) inline std::size_t farthestShort(const double *x, const double *y, std::size_t first,
                                                                        std::size_t last, double dx, double dy, double &best)
        {
#ifdef __clang__
#pragma clang fp contract(off)
#endif
            constexpr std::size_t most = filter_min_points;
            const std::size_t begin = first + 1, n = last - begin;
            const double dd = product(dx, dx) + product(dy, dy);
            const Double2 zero = Double2{}, one = zero + 1.0, ax = zero + x[first], ay = zero + y[first],
                          bx = zero + x[last], by = zero + y[last], vdx = zero + dx, vdy = zero + dy, vdd = zero + dd;
            alignas(16) double d2[most];
            Double2 mx = zero + best;
            for (std::size_t q = 0; q < n; q += 2)
            {
                Double2 px, py;
                std::memcpy(&px, x + begin + q, sizeof px);
                std::memcpy(&py, y + begin + q, sizeof py);
                const Double2 t = (product(px - ax, vdx) + product(py - ay, vdy)) / vdd;
                const Double2 tc = maxKeep(zero, t);
                const Double2 qx = t > one ? bx : ax + product(vdx, tc), qy = t > one ? by : ay + product(vdy, tc);
                const Double2 ex = px - qx, ey = py - qy;
                Double2 v = product(ex, ex) + product(ey, ey);
                if (q + 1 == n)
                    v[1] = best;
                std::memcpy(d2 + q, &v, sizeof v);
                mx = maxKeep(mx, v);
            }
            return firstOfMaximum(d2, mx, begin, best);
        }
#endif

        //! The first index in (first, last) whose squared segment distance from chord first -> last is the
        //! largest and exceeds `best` (which it then holds), or 0 if none does: simplify-js's scan, whose `>`
        //! lets a later equal distance lose.
        template<int dim>
        inline std::size_t farthest(const AxisPoints<dim> &pts, std::size_t first, std::size_t last, double &best)
        {
#if defined(__GNUC__)
            if constexpr (dim == 2)
                if (last - first <= filter_min_points + 1)
                {
                    const double *x = pts.axis(0), *y = pts.axis(1), dx = x[last] - x[first], dy = y[last] - y[first];
                    if (dx - dx == 0 && dy - dy == 0)
                        return farthestShort(x, y, first, last, dx, dy, best);
                }
#endif
            double pa[dim], pb[dim];
            bool finite_d = true;
            for (int k = 0; k < dim; ++k)
            {
                pa[k] = pts.axis(k)[first];
                pb[k] = pts.axis(k)[last];
                finite_d = finite_d && std::isfinite(pb[k] - pa[k]);
            }
            const Chord<dim> chord(pa, pb);
#if defined(__GNUC__)
            if (finite_d)
            {
                if constexpr (dim == 2)
                    if (pts.f && last - first > filter_min_points)
                    {
                        const float *xf = pts.f.get(), *yf = xf + pts.fstride;
                        const double dx = xf[last] - xf[first], dy = yf[last] - yf[first];
                        if (dx * dx + dy * dy >= filter_min_dd && 4 * filter_eps * pts.g * 64 <= std::sqrt(best))
                            return farthestFiltered(pts, first, last, chord, best);
                    }
                return farthestPairs<dim>(pts, first, last, ChordPair<dim>(chord), best);
            }
#else
            (void)finite_d;
#endif
            // Elsewhere, and for a chord whose difference overflowed (where d * 0 is NaN), point by point.
            std::size_t index = 0;
            double p[dim];
            for (std::size_t i = first + 1; i < last; ++i)
            {
                for (int k = 0; k < dim; ++k)
                    p[k] = pts.axis(k)[i];
                const double d2 = segmentDistance2<dim>(p, chord);
                if (d2 > best) { best = d2; index = i; }
            }
            return index;
        }

        //! Indices (ascending) that simplify-js keeps of the points in `pts`.
        template<int dim>
        RTL_SIMPLIFY_NOINLINE std::vector<std::size_t> simplify(const AxisPoints<dim> &pts, double sq_tolerance)
        {
            const std::size_t m = pts.m;
            std::vector<char> keep(m, 0);
            keep[0] = keep[m - 1] = 1;
            // Each range is independent of the others, so the order they are taken in does not change the result.
            // At most m - 2 ranges wait at once (each holds a point of its own that is not yet decided).
            std::unique_ptr<std::pair<std::size_t, std::size_t>[]> stack(new std::pair<std::size_t, std::size_t>[m]);
            std::size_t top = 0;
            stack[top++] = {0, m - 1};
            while (top)
            {
                const auto [first, last] = stack[--top];
                double best = sq_tolerance;
                const std::size_t index = farthest<dim>(pts, first, last, best);
                if (best > sq_tolerance)
                {
                    keep[index] = 1;
                    if (index - first > 1) stack[top++] = {first, index};
                    if (last - index > 1) stack[top++] = {index, last};
                }
            }
            std::vector<std::size_t> kept;
            for (std::size_t i = 0; i < m; ++i)
                if (keep[i]) kept.push_back(i);
            return kept;
        }

        //! simplifyIndices' input check and working copy: x's magnitude into g, false if x is not finite.
        inline bool magnitude(double x, double &g)
        {
            const double a = std::fabs(x);
            g = a > g ? a : g;
            return a <= std::numeric_limits<double>::max();
        }

        //! The largest |v[i]| of count values into g (NaN values are passed over, as by magnitude()).
        inline void largestMagnitude(const double *v, std::size_t count, double &g)
        {
            std::size_t i = 0;
#if defined(__GNUC__)
            // Two per vector: the scalar loop does not vectorize (its `>` is not a max to the compiler).
            typedef long long Bits2 __attribute__((vector_size(16)));
            const Bits2 abs_mask = Bits2{} + 0x7fffffffffffffffLL;
            Double2 top0 = Double2{}, top1 = Double2{};
            for (; i + 4 <= count; i += 4)
            {
                Double2 a, b;
                std::memcpy(&a, v + i, sizeof a);
                std::memcpy(&b, v + i + 2, sizeof b);
                top0 = maxKeep(top0, (Double2)((Bits2)a & abs_mask));
                top1 = maxKeep(top1, (Double2)((Bits2)b & abs_mask));
            }
            const Double2 top = maxKeep(top0, top1);
            magnitude(top[0], g);
            magnitude(top[1], g);
#endif
            for (; i < count; ++i)
                magnitude(v[i], g);
        }

        //! High quality: all n points into the axis arrays; their largest |coordinate| into g. False if a
        //! coordinate is not finite.
        template<int dim, typename T>
        RTL_SIMPLIFY_NOINLINE bool copyAll(const T *xyz, std::size_t n, double *const *axis, double &g)
        {
#if defined(__GNUC__)
            if constexpr (std::is_same_v<T, double>)
            {
                // Two numbers per vector: the largest magnitude, and v - v (0, or NaN when v is not finite) summed
                // into a NaN detector (the scalar loop does not vectorize).
                typedef long long Bits2 __attribute__((vector_size(16)));
                const Bits2 abs_mask = Bits2{} + 0x7fffffffffffffffLL;
                Double2 top = Double2{}, nan = Double2{};
                const std::size_t end = n * dim & ~std::size_t(1);
                for (std::size_t j = 0; j < end; j += 2)
                {
                    Double2 v;
                    std::memcpy(&v, xyz + j, sizeof v);
                    top = maxKeep(top, (Double2)((Bits2)v & abs_mask));
                    nan = nan + (v - v);
                    axis[j % dim][j / dim] = v[0];
                    axis[(j + 1) % dim][(j + 1) / dim] = v[1];
                }
                bool finite = nan[0] == 0 && nan[1] == 0;
                if (end < n * dim)
                {
                    finite &= magnitude(xyz[end], g);
                    axis[dim - 1][n - 1] = xyz[end];
                }
                const double m = top[0] < top[1] ? top[1] : top[0];
                g = m > g ? m : g;
                return finite;
            }
#endif
            bool finite = true;
            for (std::size_t i = 0; i < n; ++i)
                for (int k = 0; k < dim; ++k)
                {
                    const double v = static_cast<double>(xyz[i * dim + k]);
                    finite &= magnitude(v, g);
                    axis[k][i] = v;
                }
            return finite;
        }

        //! simplify-js's radial pass over n >= 1 points: a point is kept when its squared distance to the last kept
        //! one exceeds sq_tolerance (its getSqDist, in its order); the kept points go into the axis arrays, their
        //! indices into `from`. One pass over the input, which also checks every coordinate: `finite` is false if
        //! one is not (v - v summed: 0 unless some v is infinite or NaN). Returns the number kept (the last point
        //! not yet appended).
        template<int dim, typename T>
        RTL_SIMPLIFY_NOINLINE std::size_t radialPass(const T *xyz, std::size_t n, double sq_tolerance, double *const *axis,
                                                     std::size_t *from, bool &finite)
        {
            double prev[dim], p[dim];
            double nan = 0;
            for (int k = 0; k < dim; ++k)
            {
                axis[k][0] = prev[k] = static_cast<double>(xyz[k]);
                nan = nan + (prev[k] - prev[k]);
            }
            from[0] = 0;
            std::size_t count = 1, i = 1;
#if defined(__GNUC__)
            if constexpr (dim == 2 && std::is_same_v<T, double>)
            {
                // Eight points per step against the same last kept point P: between two kept points (24 points
                // apart on the noisy semicircle) no lane passes and nothing depends on the previous step. Each
                // lane's distance is the scalar formula in its order: (x - Px)^2 then + (y - Py)^2. The first lane
                // that passes is the next kept point; the step after it starts at the point after it (eight rather
                // than four: measured, docs/vect.md).
                const Double2 tol = Double2{} + sq_tolerance;
                Double2 last = {prev[0], prev[1]}, sum = Double2{};
                const auto distances = [&](std::size_t j) {   // of points j and j + 1, one per lane
                    Double2 a, b;
                    std::memcpy(&a, xyz + 2 * j, sizeof a);
                    std::memcpy(&b, xyz + 2 * j + 2, sizeof b);
                    const Double2 ea = a - last, eb = b - last;
                    const Double2 sa = product(ea, ea), sb = product(eb, eb);
                    return Double2{sa[0], sb[0]} + Double2{sa[1], sb[1]};
                };
                for (; i + 8 <= n;)
                {
                    const Double2 d01 = distances(i), d23 = distances(i + 2), d45 = distances(i + 4), d67 = distances(i + 6);
                    sum = sum + ((d01 + d23) + (d45 + d67));
                    const Index2 p01 = d01 > tol, p23 = d23 > tol, p45 = d45 > tol, p67 = d67 > tol;
                    if (!anyLane((p01 | p23) | (p45 | p67)))
                    {
                        i += 8;
                        continue;
                    }
                    // The first passing lane, without a branch per lane (those mispredicted on the random walk).
                    const unsigned bits = laneBits(p01) | laneBits(p23) << 2 | laneBits(p45) << 4 | laneBits(p67) << 6;
                    i += static_cast<std::size_t>(__builtin_ctz(bits));
                    std::memcpy(&last, xyz + 2 * i, sizeof last);
                    axis[0][count] = last[0];
                    axis[1][count] = last[1];
                    from[count++] = i++;
                }
                prev[0] = last[0];
                prev[1] = last[1];
                // The sum of the distances is finite if every coordinate is: a point with an infinite or NaN
                // coordinate has an infinite or NaN distance. Finite coordinates can overflow it too: then the
                // coordinates are checked by the library's finite check (rtl/core/CoordinateCheck.h).
                if (!(sum[0] + sum[1] <= std::numeric_limits<double>::max()) &&
                    firstBeyond(xyz, 2 * i, std::numeric_limits<double>::infinity(), false) < 2 * i)
                    nan = std::numeric_limits<double>::quiet_NaN();
            }
#endif
            for (; i < n; ++i)
            {
                for (int k = 0; k < dim; ++k)
                {
                    p[k] = static_cast<double>(xyz[i * dim + k]);
                    nan = nan + (p[k] - p[k]);
                }
                if (pointDistance2<dim>(p, prev) > sq_tolerance)
                {
                    for (int k = 0; k < dim; ++k)
                        axis[k][count] = prev[k] = p[k];
                    from[count++] = i;
                }
            }
            finite = nan == 0;
            return count;
        }

        //! The default `prepared` of simplifyIndices: nothing.
        struct NoHook
        {
            template<int dim>
            void operator()(const AxisPoints<dim> &) const {}
        };

        //! simplifyCompatibleIndices for n >= 3 points (see there). prepared(pts) is called once the points
        //! Douglas-Peucker runs on are ready, before it runs: bench/b_vect_simplify_kernel.cpp times the phases of
        //! a call there; the default does nothing (the set-up stays inline in this function: made a function of
        //! its own instead, it cost rtl.wasm 846 B, 302 B gzipped).
        template<int dim, typename T, typename Hook = NoHook>
        std::vector<std::size_t> simplifyIndices(const T *xyz, std::size_t n, double sq_tolerance, bool high_quality,
                                                 const Hook &prepared = Hook())
        {
            // The points DP runs on, as doubles, and (radial pre-pass) their indices in the input. The pass over the
            // input checks that every coordinate is finite; g is the largest |coordinate| of the points DP runs on
            // (the filter's bound, farthestFiltered).
            std::unique_ptr<std::size_t[]> from;
            AxisPoints<dim> pts;
            pts.stride = n;
            pts.c.reset(new double[dim * n]);
            double *axis[dim];
            for (int k = 0; k < dim; ++k)
                axis[k] = pts.c.get() + static_cast<std::size_t>(k) * pts.stride;
            bool finite = true;
            double g = 0;
            if (high_quality)
            {
                finite = RTL_SIMPLIFY_PASS_CALL(&copyAll<dim, T>)(xyz, n, axis, g);
                pts.m = n;
            }
            else
            {
                from.reset(new std::size_t[n]);
                std::size_t m = RTL_SIMPLIFY_PASS_CALL(&radialPass<dim, T>)(xyz, n, sq_tolerance, axis, from.get(), finite);
                // The last point is appended unless it is the last one kept. (simplify-js compares objects: when
                // the last object is also the last kept one, at an earlier index, it is not appended; appended, a
                // copy of the last kept point changes no other decision and the same object comes out.)
                if (from[m - 1] != n - 1)
                {
                    for (int k = 0; k < dim; ++k)
                        axis[k][m] = static_cast<double>(xyz[(n - 1) * dim + k]);
                    from[m++] = n - 1;
                }
                pts.m = m;
                for (int k = 0; k < dim; ++k)
                    largestMagnitude(axis[k], m, g);
            }
            if (!finite)
                throw std::invalid_argument("simplifyCompatibleIndices: non-finite coordinate");
            pts.g = g;
            const std::size_t m = pts.m;
#if defined(__GNUC__)
            if (dim == 2 && m > filter_min_points && g <= filter_max_g)
            {
                // Each axis padded with zeros to a multiple of four past m: the filter's last group reads them.
                pts.fstride = (m + 7) & ~std::size_t(3);
                pts.f.reset(new float[2 * pts.fstride]);
                for (std::size_t k = 0; k < 2; ++k)
                {
                    float *f = pts.f.get() + k * pts.fstride;
                    for (std::size_t i = 0; i < m; ++i)
                        f[i] = static_cast<float>(axis[k][i]);
                    std::fill(f + m, f + pts.fstride, 0.0f);
                }
                pts.scratch.reset(new float[pts.fstride]);
            }
#endif
            prepared(pts);
            std::vector<std::size_t> kept = m <= 2 ? std::vector<std::size_t>{} : RTL_SIMPLIFY_PASS_CALL(&simplify<dim>)(pts, sq_tolerance);
            if (m <= 2)
                for (std::size_t i = 0; i < m; ++i)
                    kept.push_back(i);
            if (!high_quality)
                for (auto &k : kept)
                    k = from[k];
            return kept;
        }
    }

    //! Indices (ascending) of the points that simplify-js's simplify(points, tolerance, high_quality) keeps, for
    //! n points of `dim` (2 or 3) coordinates interleaved in xyz (x0 y0 [z0] x1 ...). sqTolerance = tolerance^2;
    //! unless high_quality, a radial pre-pass keeps a point when its squared distance to the last kept point
    //! exceeds it (and appends the last point if it was not kept); then Douglas-Peucker on the squared distance to
    //! the chord segment keeps the first farthest point while it exceeds sqTolerance. First and last are always
    //! kept; n <= 2 keeps all. Runs in double whatever T is. A tolerance of +-inf keeps only the end points.
    //! Preconditions (else std::invalid_argument): dim is 2 or 3, xyz is not null when n > 0, every coordinate is
    //! finite, tolerance is not NaN. Finite coordinates whose differences overflow give the library's inf/NaN
    //! comparisons, so the result still matches it.
    template<typename T>
    std::vector<std::size_t> simplifyCompatibleIndices(const T *xyz, std::size_t n, std::size_t dim, T tolerance, bool high_quality)
    {
        static_assert(std::is_floating_point_v<T>, "simplifyCompatibleIndices: T must be a floating-point type");
        if (dim != 2 && dim != 3)
            throw std::invalid_argument("simplifyCompatibleIndices: dim must be 2 or 3");
        if (n > 0 && xyz == nullptr)
            throw std::invalid_argument("simplifyCompatibleIndices: xyz is null");
        if (std::isnan(tolerance))
            throw std::invalid_argument("simplifyCompatibleIndices: tolerance is NaN");
        std::vector<std::size_t> kept;
        if (n <= 2)
        {
            if (detail::firstBeyond(xyz, n * dim, std::numeric_limits<double>::infinity(), false) < n * dim)
                throw std::invalid_argument("simplifyCompatibleIndices: non-finite coordinate");
            for (std::size_t i = 0; i < n; ++i)
                kept.push_back(i);
            return kept;
        }
        const double tol = static_cast<double>(tolerance);
        const double sq_tolerance = tol * tol;
        return dim == 2 ? detail::simplifyIndices<2>(xyz, n, sq_tolerance, high_quality)
                        : detail::simplifyIndices<3>(xyz, n, sq_tolerance, high_quality);
    }
}
