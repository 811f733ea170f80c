// Polyline simplification that keeps exactly the points the simplify-js library keeps: its radial-distance
// pre-pass (skipped in high-quality mode) and its Douglas-Peucker on the squared distance to the chord *segment*.
// The arithmetic is that library's, in double and in its order, so the kept points are identical to a JavaScript
// run on the same doubles. Fused multiply-add would change roundings: GCC ignores FP_CONTRACT and clang's
// -ffp-contract=fast ignores its `fp contract(off)` pragma, so when GCC or clang targets FMA hardware every
// product passes an empty asm barrier that prevents fusing (elsewhere, e.g. wasm, there is no FMA to contract to;
// MSVC does not contract unless /fp:contract or /fp:fast is given).
#pragma once

#include <cmath>
#include <cstddef>
#include <stdexcept>
#include <type_traits>
#include <utility>
#include <vector>

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

        //! Indices (ascending) that simplify-js keeps of the m points in `pts` (interleaved, dim per point).
        template<int dim>
        std::vector<std::size_t> simplify(const std::vector<double> &pts, std::size_t m, double sq_tolerance)
        {
            std::vector<char> keep(m, 0);
            keep[0] = keep[m - 1] = 1;
            std::vector<std::pair<std::size_t, std::size_t>> stack;
            stack.emplace_back(0, m - 1);
            constexpr std::size_t block = 8;
            while (!stack.empty())
            {
                const auto [first, last] = stack.back();
                stack.pop_back();
                const Chord<dim> chord(&pts[first * dim], &pts[last * dim]);
                double best = sq_tolerance;
                std::size_t index = 0;
                std::size_t i = first + 1;
                // Blocks are first tested without branches; a block with a point beyond the best so far is
                // rescanned in order, so the first maximum wins as in the library's loop.
                for (; i + block <= last; i += block)
                {
                    double d2[block];
                    bool beats = false;
                    for (std::size_t q = 0; q < block; ++q)
                    {
                        d2[q] = segmentDistance2<dim>(&pts[(i + q) * dim], chord);
                        beats |= d2[q] > best;
                    }
                    if (beats)
                        for (std::size_t q = 0; q < block; ++q)
                            if (d2[q] > best) { best = d2[q]; index = i + q; }
                }
                for (; i < last; ++i)
                {
                    const double d2 = segmentDistance2<dim>(&pts[i * dim], chord);
                    if (d2 > best) { best = d2; index = i; }
                }
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
            // The points DP runs on, as doubles, and their indices in the input.
            std::vector<double> pts;
            std::vector<std::size_t> from;
            pts.reserve(n * dim);
            if (high_quality)
            {
                for (std::size_t i = 0; i < n * dim; ++i)
                    pts.push_back(static_cast<double>(xyz[i]));
            }
            else
            {
                from.reserve(n);
                double prev[dim], p[dim];
                const auto load = [&](std::size_t i, double *out) {
                    for (int k = 0; k < dim; ++k)
                        out[k] = static_cast<double>(xyz[i * dim + k]);
                };
                const auto push = [&](std::size_t i, const double *q) {
                    from.push_back(i);
                    pts.insert(pts.end(), q, q + dim);
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
            }
            const std::size_t m = pts.size() / dim;
            std::vector<std::size_t> kept = m <= 2 ? std::vector<std::size_t>{} : simplify<dim>(pts, m, sq_tolerance);
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
