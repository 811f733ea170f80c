// Polyline simplification that keeps exactly the points the simplify-js library keeps: its radial-distance
// pre-pass (skipped in high-quality mode) and its Douglas-Peucker on the squared distance to the chord *segment*.
// The arithmetic is that library's, in double and in its order, so the kept points are identical to a JavaScript
// run on the same doubles. Fused multiply-add would change roundings: GCC ignores FP_CONTRACT and clang's
// -ffp-contract=fast ignores its `fp contract(off)` pragma, so when GCC or clang targets FMA hardware every
// product passes an empty asm barrier that prevents fusing (elsewhere, e.g. wasm, there is no FMA to contract to;
// MSVC does not contract unless /fp:contract or /fp:fast is given). With GCC and clang (SSE2, NEON, wasm simd128)
// Douglas-Peucker's scan computes two points per vector instruction, each lane with the scalar operations in the
// scalar order (so the same doubles), and finds the first maximum without a branch per point.
#pragma once

#include <cmath>
#include <cstddef>
#include <cstring>
#include <stdexcept>
#include <type_traits>
#include <utility>
#include <vector>

#if defined(__GNUC__) && defined(__SSE2__)
#include <emmintrin.h>
#elif defined(__GNUC__) && defined(__wasm_simd128__)
#include <wasm_simd128.h>
#endif

namespace rtl
{
    namespace simplify_detail
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
        template<int dim>
        struct AxisPoints
        {
            std::size_t m = 0, stride = 0;
            std::vector<double> c;
            const double *axis(int k) const { return c.data() + static_cast<std::size_t>(k) * stride; }
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

        //! `v > h ? h : v` lane-wise for v not NaN (SSE2 minpd, wasm f64x2.pmin).
        inline Double2 minKeep(Double2 v, Double2 h)
        {
#if defined(__SSE2__)
            return _mm_min_pd(v, h);   // v < h ? v : h
#elif defined(__wasm_simd128__)
            return (Double2)wasm_f64x2_pmin((v128_t)v, (v128_t)h);
#else
            return h < v ? h : v;
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
        //! may become +0, which changes no square). `clamped`, for chords where a + d == b on every axis: as
        //! a + d min(max(t, 0), 1), which is b for t > 1; no selection at all.
        template<int dim, bool clamped>
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
            const Double2 tc = clamped ? minKeep(maxKeep(zero, t), one) : maxKeep(zero, t);
            Double2 s = zero;
            for (int k = 0; k < dim; ++k)
            {
                Double2 q = c.a[k] + product(c.d[k], tc);
                if (!clamped)
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
        template<int dim, bool clamped>
        std::size_t farthestPairs(const AxisPoints<dim> &pts, std::size_t first, std::size_t last,
                                  const ChordPair<dim> &c, double &best)
        {
            typedef long long Index2 __attribute__((vector_size(16)));
            constexpr std::size_t block = 16;
            const std::size_t begin = first + 1;
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
                        m0 = maxKeep(m0, segmentDistance2Pair<dim, clamped>(pts, i + q, c));
                        m1 = maxKeep(m1, segmentDistance2Pair<dim, clamped>(pts, i + q + 2, c));
                    }
                else
                    for (std::size_t q = 0; q < n; q += 2)
                        m0 = maxKeep(m0, segmentDistance2Pair<dim, clamped>(pts, i + q, c));
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
                    const Double2 s = segmentDistance2Pair<dim, clamped>(pts, start + q, c);
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
                const Double2 s = segmentDistance2Pair<dim, clamped>(pts, last - 1, c);
                if (s[0] > best) { best = s[0]; index = last - 1; }
            }
            return index;
        }
#endif

        //! The first index in (first, last) whose squared segment distance from chord first -> last is the
        //! largest and exceeds `best` (which it then holds), or 0 if none does: simplify-js's scan, whose `>`
        //! lets a later equal distance lose.
        template<int dim>
        std::size_t farthest(const AxisPoints<dim> &pts, std::size_t first, std::size_t last, double &best)
        {
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
                bool exact_end = true;
                for (int k = 0; k < dim; ++k)
                    exact_end = exact_end && pa[k] + chord.d[k] == pb[k];
                const ChordPair<dim> c(chord);
                return exact_end ? farthestPairs<dim, true>(pts, first, last, c, best)
                                 : farthestPairs<dim, false>(pts, first, last, c, best);
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
        std::vector<std::size_t> simplify(const AxisPoints<dim> &pts, double sq_tolerance)
        {
            const std::size_t m = pts.m;
            std::vector<char> keep(m, 0);
            keep[0] = keep[m - 1] = 1;
            // Each range is independent of the others, so the order they are taken in does not change the result.
            std::vector<std::pair<std::size_t, std::size_t>> stack;
            stack.emplace_back(0, m - 1);
            while (!stack.empty())
            {
                const auto [first, last] = stack.back();
                stack.pop_back();
                double best = sq_tolerance;
                const std::size_t index = farthest<dim>(pts, first, last, best);
                if (best > sq_tolerance)
                {
                    keep[index] = 1;
                    if (index - first > 1) stack.emplace_back(first, index);
                    if (last - index > 1) stack.emplace_back(index, last);
                }
            }
            std::vector<std::size_t> kept;
            for (std::size_t i = 0; i < m; ++i)
                if (keep[i]) kept.push_back(i);
            return kept;
        }

        template<int dim, typename T>
        std::vector<std::size_t> simplifyIndices(const T *xyz, std::size_t n, double sq_tolerance, bool high_quality)
        {
            // The points DP runs on, as doubles, and (radial pre-pass) their indices in the input.
            std::vector<std::size_t> from;
            AxisPoints<dim> pts;
            pts.stride = n;
            pts.c.assign(dim * pts.stride, 0.0);
            double *axis[dim];
            for (int k = 0; k < dim; ++k)
                axis[k] = pts.c.data() + static_cast<std::size_t>(k) * pts.stride;
            if (high_quality)
            {
                for (std::size_t i = 0; i < n; ++i)
                    for (int k = 0; k < dim; ++k)
                        axis[k][i] = static_cast<double>(xyz[i * dim + k]);
                pts.m = n;
            }
            else
            {
                from.reserve(n);
                double prev[dim], p[dim] = {};
                const auto load = [&](std::size_t i, double *out) {
                    for (int k = 0; k < dim; ++k)
                        out[k] = static_cast<double>(xyz[i * dim + k]);
                };
                const auto push = [&](std::size_t i, const double *q) {
                    for (int k = 0; k < dim; ++k)
                        axis[k][from.size()] = q[k];
                    from.push_back(i);
                };
                load(0, prev);
                push(0, prev);
                for (std::size_t i = 1; i < n; ++i)
                {
                    load(i, p);
                    if (pointDistance2<dim>(p, prev) > sq_tolerance)
                    {
                        push(i, p);
                        for (int k = 0; k < dim; ++k)
                            prev[k] = p[k];
                    }
                }
                if (from.back() != n - 1)
                    push(n - 1, p);
                pts.m = from.size();
            }
            const std::size_t m = pts.m;
            std::vector<std::size_t> kept = m <= 2 ? std::vector<std::size_t>{} : simplify<dim>(pts, sq_tolerance);
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
        for (std::size_t i = 0; i < n * dim; ++i)
            if (!std::isfinite(xyz[i]))
                throw std::invalid_argument("simplifyCompatibleIndices: non-finite coordinate");
        std::vector<std::size_t> kept;
        if (n <= 2)
        {
            for (std::size_t i = 0; i < n; ++i)
                kept.push_back(i);
            return kept;
        }
        const double tol = static_cast<double>(tolerance);
        const double sq_tolerance = tol * tol;
        return dim == 2 ? simplify_detail::simplifyIndices<2>(xyz, n, sq_tolerance, high_quality)
                        : simplify_detail::simplifyIndices<3>(xyz, n, sq_tolerance, high_quality);
    }
}
