// ApproximationTlsLine2D: total-least-squares line of a 2D point set, from its PrecSums in O(1).
//
// The line passes through the centroid along the major eigenvector of the covariance; errSquared() is the minor
// eigenvalue (the mean squared orthogonal residual). The eigenvector is taken in closed form from whichever of the
// two eigenvector formulas is better conditioned, so exactly axis-aligned sets get an exact axis direction (the
// published implementation was 90 degrees off there; docs/reference.md, "Vectorization defects fixed here", defect 1).
// Geometry is kept in ComputeType and crossings are computed in it (defect 2 there); accessors return ElementType.
#pragma once

#include <cmath>
#include <cstddef>
#include <cstring>
#include <iterator>
#include <limits>
#include <type_traits>

#include "rtl/core/LineSegmentND.h"
#include "rtl/core/VectorND.h"
#include "rtl/vect/PrecSums.h"
#include "rtl/vect/TlsDetail.h"

#if defined(__GNUC__) && defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace rtl
{
    template<typename Element, typename Compute>
    class ApproximationTlsLine2D
    {
    public:
        typedef Element ElementType;
        typedef Compute ComputeType;
        typedef VectorND<2, ElementType> VectorType;
        typedef LineSegmentND<2, ElementType> ConstrainedType;
        typedef PrecSums2D<ComputeType> PrecSumsType;
        typedef VectorND<2, ComputeType> ComputeVectorType;

        ApproximationTlsLine2D() = default;
        explicit ApproximationTlsLine2D(PrecSumsType ps) { operator()(ps); }
        ~ApproximationTlsLine2D() = default;

        //! Implicit equation a x + b y + c = 0 with (a, b) = normal().
        [[nodiscard]] ElementType a() const { return static_cast<ElementType>(-dy); }
        [[nodiscard]] ElementType b() const { return static_cast<ElementType>(dx); }
        [[nodiscard]] ElementType c() const { return static_cast<ElementType>(dy * mx - dx * my); }
        [[nodiscard]] VectorType direction() const { return VectorType(static_cast<ElementType>(dx), static_cast<ElementType>(dy)); }
        [[nodiscard]] VectorType normal() const { return VectorType(static_cast<ElementType>(-dy), static_cast<ElementType>(dx)); }
        //! The centroid of the fitted points (a point of the line).
        [[nodiscard]] VectorType point() const { return VectorType(static_cast<ElementType>(mx), static_cast<ElementType>(my)); }
        //! Mean squared orthogonal residual of the fitted points.
        [[nodiscard]] ElementType errSquared() const { return static_cast<ElementType>(err); }
        [[nodiscard]] ComputeType errSquaredCompute() const { return err; }
        [[nodiscard]] ComputeType count() const { return n; }

        //! Refits from the sums of a point set. An empty set gives the x axis with zero error; a set of coincident
        //! points (isotropic covariance) gets the direction (1, 0).
        bool operator()(PrecSumsType ps)
        {
            const detail::Moments2D<ComputeType> m(ps);
            n = m.n; mx = m.mx; my = m.my;
            const ComputeType hd = (m.cxx - m.cyy) / 2, r = std::hypot(hd, m.cxy), mean = (m.cxx + m.cyy) / 2;
            err = std::max(ComputeType(0), mean - r);
            ComputeType vx, vy;
            if (hd >= 0) { vx = hd + r; vy = m.cxy; }
            else { vx = m.cxy; vy = r - hd; }
            const ComputeType len = std::hypot(vx, vy);
            if (len > ComputeType(0) && std::isfinite(len)) { dx = vx / len; dy = vy / len; }
            else { dx = 1; dy = 0; }
            return true;
        }

        //! Fit of points given relative to `origin` (sums of p - origin): better conditioned for far-off points.
        bool operator()(PrecSumsType ps, const ComputeVectorType &origin)
        {
            operator()(ps);
            mx += origin.x(); my += origin.y();
            return true;
        }

        //! Orthogonal projection onto the line (computed in ComputeType).
        ComputeVectorType projectCompute(const ComputeVectorType &p) const
        {
            const ComputeType t = (p.x() - mx) * dx + (p.y() - my) * dy;
            return ComputeVectorType(mx + t * dx, my + t * dy);
        }
        VectorType project(const VectorType &pt) const { return projectCompute(pt.template cast<ComputeType>()).template cast<ElementType>(); }

        //! Segment between the projections of beg and end, directed from beg to end.
        ConstrainedType trim(const VectorType &beg, const VectorType &end) const
        {
            const VectorType pb = project(beg), pe = project(end);
            const ComputeType t = (static_cast<ComputeType>(end.x()) - beg.x()) * dx + (static_cast<ComputeType>(end.y()) - beg.y()) * dy;
            const ComputeType s = t < 0 ? -1 : 1;
            return ConstrainedType(pb, pe, VectorType(static_cast<ElementType>(s * dx), static_cast<ElementType>(s * dy)));
        }
        //! Trims by the first and the last element of [beg, end) (non-empty).
        template<class Iter>
        ConstrainedType trim(Iter beg, Iter end) const { return trim(*beg, *std::prev(end)); }

        //! Crossing of two lines in ComputeType; false if they are parallel (or the crossing is not finite).
        static bool getCrossingCompute(const ApproximationTlsLine2D &l1, const ApproximationTlsLine2D &l2, ComputeVectorType &crossing)
        {
            const ComputeType den = l1.dx * l2.dy - l1.dy * l2.dx;
            if (den == ComputeType(0))
                return false;
            const ComputeType t = ((l2.mx - l1.mx) * l2.dy - (l2.my - l1.my) * l2.dx) / den;
            const ComputeVectorType c(l1.mx + t * l1.dx, l1.my + t * l1.dy);
            if (!std::isfinite(c.x()) || !std::isfinite(c.y()))
                return false;
            crossing = c;
            return true;
        }
        //! Squared distance of the crossing of l1 and l2 from `ref`: getCrossingCompute's arithmetic without its
        //! checks, for hot loops that compare it with a finite bound. Parallel lines or a non-finite crossing give
        //! +infinity or NaN here (x / 0 is infinite or NaN, and a unit direction has a non-zero component), which no
        //! finite bound accepts, just as the checked path's +infinity, so every such comparison decides the same.
        static ComputeType crossingDistanceSquaredUnchecked(const ApproximationTlsLine2D &l1, const ApproximationTlsLine2D &l2, const ComputeVectorType &ref)
        {
            const ComputeType den = l1.dx * l2.dy - l1.dy * l2.dx;
            const ComputeType t = ((l2.mx - l1.mx) * l2.dy - (l2.my - l1.my) * l2.dx) / den;
            const ComputeVectorType c(l1.mx + t * l1.dx, l1.my + t * l1.dy);
            return (c - ref).lengthSquared();
        }
        static bool getCrossing(const ApproximationTlsLine2D &l1, const ApproximationTlsLine2D &l2, VectorType &crossing)
        {
            ComputeVectorType c;
            if (!getCrossingCompute(l1, l2, c))
                return false;
            crossing = c.template cast<ElementType>();
            return true;
        }

        //! Mean squared orthogonal residual of a point set given by its sums.
        static ElementType getErrorSquared(PrecSumsType ps) { return static_cast<ElementType>(errorSquaredCompute(ps)); }
        static ComputeType errorSquaredCompute(const PrecSumsType &ps)
        {
            const detail::Moments2D<ComputeType> m(ps);
            return std::max(ComputeType(0), (m.cxx + m.cyy) / 2 - std::hypot((m.cxx - m.cyy) / 2, m.cxy));
        }
        //! errorSquared(ps) < sigma2, decided without square roots (the minor eigenvalue is below sigma2 iff
        //! cov - sigma2 I is not positive semidefinite). False for NaN sums.
        static bool errorBelow(const PrecSumsType &ps, ComputeType sigma2) { return errorBelowRaw(ps.sums.data(), ps.cnt(), sigma2); }
        //! errorBelow on raw sums s[0..4] (PrecSums2D order) of n points.
        static bool errorBelowRaw(const ComputeType *s, ComputeType n, ComputeType sigma2)
        {
            const ComputeType t = n * n * sigma2;
            const ComputeType a = n * s[2] - s[0] * s[0] - t, b = n * s[3] - s[1] * s[1] - t, c = n * s[4] - s[0] * s[1];
            if (!std::isfinite(a + b + c))
                return false;
            return a < 0 || b < 0 || a * b < c * c;
        }

        //! errorBelowRaw for `block` consecutive states of one range, all at once: s[k * block + j] is sum k (PrecSums2D
        //! order) after point j, of n0 + j points. True iff errorBelowRaw holds for every j; the arithmetic per state
        //! is errorBelowRaw's, evaluated without branches, for double on GCC/clang vector lanes (SSE2: 2 per
        //! instruction), so the decisions are the same.
        //! On SSE2 the per-state decision is reduced to two running lane values instead of a mask per state:
        //! with a, b, c finite, "a < 0 || b < 0 || a * b < c * c" is "min(a * b - c * c, min(a, b)) < 0" (the rounded
        //! difference of two doubles has the sign of their exact difference; a * b and c * c both infinite give NaN,
        //! which minpd replaces by its second operand, min(a, b)), so the block passes iff the maximum of that over
        //! the states is negative; and a + b + c is finite for every state iff the sum of (f - f) is 0 (NaN otherwise).
        template<size_t block>
        static bool errorBelowRawAll(const ComputeType *s, ComputeType n0, ComputeType sigma2)
        {
#if defined(__GNUC__) && defined(__SSE2__)
            if constexpr (std::is_same_v<ComputeType, double> && block % 2 == 0)
            {
                const __m128d zero = _mm_setzero_pd(), two = _mm_set1_pd(2.0), sg = _mm_set1_pd(sigma2);
                __m128d n = _mm_set_pd(n0 + 1.0, n0);   // lanes: states j, j + 1 (n0 + j is exact: counts < 2^53)
                __m128d worst = _mm_set1_pd(-std::numeric_limits<double>::infinity()), nonfinite = zero;
                for (size_t j = 0; j < block; j += 2)
                {
                    const __m128d s0 = _mm_loadu_pd(s + j), s1 = _mm_loadu_pd(s + block + j), s2 = _mm_loadu_pd(s + 2 * block + j),
                                  s3 = _mm_loadu_pd(s + 3 * block + j), s4 = _mm_loadu_pd(s + 4 * block + j);
                    const __m128d t = _mm_mul_pd(_mm_mul_pd(n, n), sg);
                    const __m128d a = _mm_sub_pd(_mm_sub_pd(_mm_mul_pd(n, s2), _mm_mul_pd(s0, s0)), t);
                    const __m128d b = _mm_sub_pd(_mm_sub_pd(_mm_mul_pd(n, s3), _mm_mul_pd(s1, s1)), t);
                    const __m128d c = _mm_sub_pd(_mm_mul_pd(n, s4), _mm_mul_pd(s0, s1));
                    const __m128d f = _mm_add_pd(_mm_add_pd(a, b), c);
                    nonfinite = _mm_add_pd(nonfinite, _mm_sub_pd(f, f));
                    const __m128d g = _mm_min_pd(_mm_sub_pd(_mm_mul_pd(a, b), _mm_mul_pd(c, c)), _mm_min_pd(a, b));
                    worst = _mm_max_pd(worst, g);
                    n = _mm_add_pd(n, two);
                }
                return _mm_movemask_pd(_mm_and_pd(_mm_cmplt_pd(worst, zero), _mm_cmpeq_pd(nonfinite, zero))) == 3;
            }
#endif
#if defined(__GNUC__) && !defined(__SSE2__)
            if constexpr (std::is_same_v<ComputeType, double> && block % 2 == 0)
            {
                typedef double V __attribute__((vector_size(16)));
                typedef long long M __attribute__((vector_size(16)));
                M all = {-1, -1};
                const V zero = {0, 0};
                for (size_t j = 0; j < block; j += 2)
                {
                    V s0, s1, s2, s3, s4;
                    std::memcpy(&s0, s + j, sizeof(V));
                    std::memcpy(&s1, s + block + j, sizeof(V));
                    std::memcpy(&s2, s + 2 * block + j, sizeof(V));
                    std::memcpy(&s3, s + 3 * block + j, sizeof(V));
                    std::memcpy(&s4, s + 4 * block + j, sizeof(V));
                    const V n = V{n0 + static_cast<double>(j), n0 + static_cast<double>(j + 1)};
                    const V t = n * n * sigma2;
                    const V a = n * s2 - s0 * s0 - t, b = n * s3 - s1 * s1 - t, c = n * s4 - s0 * s1;
                    const V f = a + b + c;
                    all &= (f - f == zero) & ((a < zero) | (b < zero) | (a * b < c * c));
                }
                return (all[0] & all[1]) != 0;
            }
#endif
            bool all = true;
            for (size_t j = 0; j < block; ++j)
            {
                const ComputeType q[5] = {s[j], s[block + j], s[2 * block + j], s[3 * block + j], s[4 * block + j]};
                all &= errorBelowRaw(q, n0 + static_cast<ComputeType>(j), sigma2);
            }
            return all;
        }

    private:
        ComputeType mx{0}, my{0}, dx{1}, dy{0}, err{0}, n{0};
    };
}
