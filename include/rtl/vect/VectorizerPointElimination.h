// Point-elimination vectorizers in N dimensions: Douglas-Peucker and Reumann-Witkam. Both keep a subset of the
// input points and return the polyline through them as line segments.
// Observer (last template parameter, rtl/core/Trace.h): with an enabled one set by setObserver(), each call reports
// the DpStart/DpRange (RwStart/RwKeep/RwStrip/RwExit) events of rtl/vect/SimplifyTrace.h. The decisions are those
// of the untraced code; the traced path only adds the distance computations it reports.
#pragma once

#include <cmath>
#include <cstddef>
#include <cstring>
#include <algorithm>
#include <limits>
#include <type_traits>
#include <utility>
#include <vector>

#include "rtl/core/LineSegmentND.h"
#include "rtl/core/Trace.h"
#include "rtl/core/VectorND.h"
#include "rtl/vect/SimplifyCompatible.h"
#include "rtl/vect/SimplifyTrace.h"

namespace rtl
{
    namespace detail
    {
        //! Segment a -> b whose direction is the unit vector along b - a however short or long the segment: it is
        //! normalised after rescaling by its largest |component| (a subnormal difference, whose squares underflow to
        //! 0, still points along the segment; a difference that overflows is taken as b / 2 - a / 2). Only
        //! coincident end points (a degenerate segment, no direction of its own) get the first base vector.
        //! Precondition: finite a and b.
        template<class Segment, class Vector>
        Segment makeSegment(const Vector &a, const Vector &b)
        {
            typedef typename Vector::ElementType E;
            Vector d = b - a;
            const int dims = static_cast<int>(d.data().size());
            bool finite_d = true;
            for (int q = 0; q < dims; ++q)
                finite_d &= static_cast<bool>(std::isfinite(d[q]));
            if (!finite_d)
                d = b * E(0.5) - a * E(0.5);
            E m = 0;
            for (int q = 0; q < dims; ++q)
                m = std::max(m, static_cast<E>(std::abs(d[q])));
            if (m > 0 && std::isfinite(m))
            {
                d /= m;
                d /= d.length();
            }
            else
            {
                d = Vector::zeros();
                d[0] = 1;
            }
            return Segment(a, b, d);
        }

        //! Polyline through pts[keys[0]], pts[keys[1]], ... as segments.
        template<class Segment, class Vector>
        void polyline(const std::vector<Vector> &pts, const std::vector<size_t> &keys, std::vector<Segment> &out)
        {
            out.clear();
            if (keys.size() < 2)
                return;
            out.reserve(keys.size() - 1);
            for (size_t i = 0; i + 1 < keys.size(); ++i)
                out.push_back(makeSegment<Segment>(pts[keys[i]], pts[keys[i + 1]]));
        }

        //! Squared distance of p from the line through a and b (from a if they coincide), in double; NaN if not
        //! finite.
        template<class Vector>
        double lineDistance2(const Vector &p, const Vector &a, const Vector &b)
        {
            constexpr int d = Vector::dimensionality();
            double v[d], u[d], uu = 0, vu = 0;
            for (int k = 0; k < d; ++k)
            {
                v[k] = static_cast<double>(p[k]) - static_cast<double>(a[k]);
                u[k] = static_cast<double>(b[k]) - static_cast<double>(a[k]);
                uu += u[k] * u[k];
                vu += v[k] * u[k];
            }
            const double t = uu > 0 ? vu / uu : 0;
            double r2 = 0;
            for (int k = 0; k < d; ++k)
                r2 += (v[k] - u[k] * t) * (v[k] - u[k] * t);
            return r2;
        }
        template<class Vector>
        double lineDistance(const Vector &p, const Vector &a, const Vector &b) { return std::sqrt(lineDistance2(p, a, b)); }

        //! Power of two s with max|finite coordinate| * s in [0.5, 1) (1 when all are 0): exact rescaling so that
        //! no difference, product or square of rescaled coordinates overflows.
        inline double unitScale(double max_abs)
        {
            if (!(max_abs > 0) || !std::isfinite(max_abs))
                return 1;
            int e = 0;
            std::frexp(max_abs, &e);
            return std::ldexp(1.0, -e);
        }
    }

    //! What Douglas-Peucker measures: the distance to the chord's infinite line (RTL) or to the chord segment
    //! (simplify-js, Boost.Geometry).
    enum class DpDistance { Line, Segment };

    //! Douglas-Peucker: keeps the end points, then recursively (with an explicit stack) the point farthest from the
    //! infinite line through the current end points while that distance exceeds epsilon. Coincident end points
    //! measure the distance to the point. Ties keep the first farthest point. Points with a NaN or infinite
    //! coordinate are never kept (the end points are always kept). Exact (up to rounding) for every finite
    //! coordinate and epsilon: chains within (max/256)^(1/4) (about 4e76 in double, 4e8 in float) take the fast
    //! Element scan; others, and ranges whose threshold eps^2 |u|^2 underflows, are measured in double on
    //! coordinates rescaled by a power of two (distances below about 1e-150 of the chain's extent count as 0).
    //! Addition: setDistance(DpDistance::Segment) measures the distance to the chord segment instead, with the
    //! arithmetic of simplifyCompatibleIndices in double compared with epsilon^2 in double (so for double input the
    //! kept points are simplify-js's high-quality ones).
    template<int dimensions, typename Element, class Observer = NoTrace>
    class VectorizerDouglasPeuckerND
    {
    public:
        typedef Element ElementType;
        typedef VectorND<dimensions, Element> VectorType;
        typedef LineSegmentND<dimensions, Element> LineSegmentType;

        VectorizerDouglasPeuckerND() = default;
        explicit VectorizerDouglasPeuckerND(ElementType eps) { setEpsilon(eps); }
        ~VectorizerDouglasPeuckerND() = default;

        void setEpsilon(ElementType eps) { eps2 = eps * eps; epsilon = static_cast<double>(eps); }
        //! Distance to the chord line (default, RTL's) or segment.
        void setDistance(DpDistance d) { distance_ = d; }
        DpDistance distance() const { return distance_; }
        //! Observer of the following calls (nullptr: none); it must outlive them.
        void setObserver(Observer *observer) { observer_ = observer; }
        //! Reserves the working buffers for inputs of up to `size` points.
        void setMaxSize(size_t size) { stack.reserve(size); keys.reserve(size); soa.reserve(dimensions * size); }

        //! Clears `output` and fills it with the simplified polyline (empty for fewer than 2 points).
        void operator()(const std::vector<VectorType> &input, std::vector<LineSegmentType> &output)
        {
            const size_t n = input.size();
            keys.clear();
            if (n < 2) { output.clear(); return; }
            if constexpr (Observer::enabled)
                if (observer_)
                    (*observer_)(DpStart{n, epsilon});
            // `tame`: all coordinates finite with |c| <= (max/256)^(1/4), so no squared cross product (nor a
            // difference or product before it) overflows; the Element scans rely on it. Otherwise (and for ranges
            // whose threshold underflows) distances are measured in double on coordinates multiplied by `scale`,
            // which brings the largest finite one to [0.5, 1).
            const Element lim = std::sqrt(std::sqrt(std::numeric_limits<Element>::max() / 256));
            Element max_abs = 0;
            int ok = 1;
            if constexpr (dimensions == 2)
            {
                soa.resize(2 * n);
                Element *x = soa.data(), *y = x + n;
                size_t i = 0;
#if defined(__GNUC__)
                // Float/double: four/two points per step on vector lanes (de-interleaved by shuffles). The maximum
                // of the lane maxima is the scalar running maximum: max is associative on non-NaN values, |c| has no
                // -0, and a NaN is skipped by "m > max ? m : max" in either order. `ok` (every |c| <= lim) is that
                // maximum <= lim and no NaN, which the lanes' sums of |c| tell (non-negative terms: +inf at worst,
                // never NaN from numbers): additions, as GCC scalarises AND-ed 64-bit lane masks.
                if constexpr ((std::is_same_v<Element, float> || std::is_same_v<Element, double>) && sizeof(VectorType) == 2 * sizeof(Element))
                {
                    typedef Element V __attribute__((vector_size(16)));
                    typedef std::conditional_t<std::is_same_v<Element, float>, int, long long> I;
                    typedef I M __attribute__((vector_size(16)));
                    constexpr size_t lanes = 16 / sizeof(Element);
                    const Element *in = &input[0][0];
                    V vmax = V{}, vsum = V{};
                    const M absmask = M{} + std::numeric_limits<I>::max();
                    for (; i + lanes <= n; i += lanes)
                    {
                        V p0, p1, vx, vy;
                        std::memcpy(&p0, in + 2 * i, sizeof(V));
                        std::memcpy(&p1, in + 2 * i + lanes, sizeof(V));
                        if constexpr (lanes == 4)
                        {
#if defined(__clang__)
                            vx = __builtin_shufflevector(p0, p1, 0, 2, 4, 6), vy = __builtin_shufflevector(p0, p1, 1, 3, 5, 7);
#else
                            vx = __builtin_shuffle(p0, p1, M{0, 2, 4, 6}), vy = __builtin_shuffle(p0, p1, M{1, 3, 5, 7});
#endif
                        }
                        else
                        {
#if defined(__clang__)
                            vx = __builtin_shufflevector(p0, p1, 0, 2), vy = __builtin_shufflevector(p0, p1, 1, 3);
#else
                            vx = __builtin_shuffle(p0, p1, M{0, 2}), vy = __builtin_shuffle(p0, p1, M{1, 3});
#endif
                        }
                        std::memcpy(x + i, &vx, sizeof(V));
                        std::memcpy(y + i, &vy, sizeof(V));
                        const V mx = (V)((M)vx & absmask), my = (V)((M)vy & absmask);
                        vsum += mx + my;
                        vmax = mx > vmax ? mx : vmax;
                        vmax = my > vmax ? my : vmax;
                    }
                    for (size_t l = 0; l < lanes; ++l)
                    {
                        ok &= static_cast<int>(vmax[l] <= lim) & static_cast<int>(vsum[l] == vsum[l]);
                        max_abs = vmax[l] > max_abs ? vmax[l] : max_abs;
                    }
                }
#endif
                for (; i < n; ++i)
                {
                    const Element vx = input[i][0], vy = input[i][1];
                    x[i] = vx;
                    y[i] = vy;
                    const Element mx = std::abs(vx), my = std::abs(vy);
                    ok &= static_cast<int>(mx <= lim) & static_cast<int>(my <= lim);
                    max_abs = mx > max_abs ? mx : max_abs;
                    max_abs = my > max_abs ? my : max_abs;
                }
            }
            else if constexpr (dimensions == 3)
            {
                // Coordinates as separate arrays: the distance scans below then run on plain SIMD lanes.
                soa.resize(dimensions * n);
                for (size_t i = 0; i < n; ++i)
                    for (int k = 0; k < dimensions; ++k)
                    {
                        const Element v = input[i][k];
                        soa[k * n + i] = v;
                        const Element m = std::abs(v);
                        ok &= static_cast<int>(m <= lim);
                        max_abs = m > max_abs ? m : max_abs;
                    }
            }
            else
                for (size_t i = 0; i < n; ++i)
                    for (int k = 0; k < dimensions; ++k)
                    {
                        const Element m = std::abs(input[i][k]);
                        ok &= static_cast<int>(m <= lim);
                        max_abs = m > max_abs ? m : max_abs;
                    }
            tame = ok != 0;
            if (!tame)
            {
                max_abs = 0;   // the largest finite one
                for (size_t i = 0; i < n; ++i)
                    for (int k = 0; k < dimensions; ++k)
                        if (std::isfinite(input[i][k]) && std::abs(input[i][k]) > max_abs)
                            max_abs = std::abs(input[i][k]);
            }
            scale = detail::unitScale(static_cast<double>(max_abs));
            // Depth first, left range first: the ranges that are not split come in chain order, so their ends
            // after point 0 are the kept points in order.
            stack.clear();
            stack.emplace_back(0, n - 1);
            keys.push_back(0);
            while (!stack.empty())
            {
                const auto [a, b] = stack.back();
                stack.pop_back();
                const size_t far = b - a < 2 ? 0 : pick(input, a, b);
                if constexpr (Observer::enabled)
                    if (observer_ && b - a >= 2)
                        reportRange(input, a, b, far);
                if (far != 0)
                {
                    stack.emplace_back(far, b);
                    stack.emplace_back(a, far);
                }
                else
                    keys.push_back(b);
            }
            detail::polyline(input, keys, output);
        }

        static bool finite(const VectorType &p)
        {
            for (int k = 0; k < dimensions; ++k)
                if (!std::isfinite(p[k]))
                    return false;
            return true;
        }

        //! Index in (a, b) of the first point farthest from line (pts[a], pts[b]) if that distance exceeds
        //! epsilon, else 0. Points with a non-finite coordinate are never picked.
        size_t farthest(const std::vector<VectorType> &pts, size_t a, size_t b) const
        {
            const VectorType &pa = pts[a];
            const VectorType u = pts[b] - pa;
            const Element l2 = u.lengthSquared();
            size_t best = 0;
            if constexpr (dimensions == 2 || dimensions == 3)
            {
                if (l2 > Element(0))
                {
                    // Compare |(p - a) x u|^2 against eps^2 * |u|^2: no division or root per point. Blocks of 8
                    // points first get their maximum without branches (vectorisable); only a block that beats the
                    // best so far is rescanned for its first maximal index.
                    Element best_c = eps2 * l2;
                    const auto cross2 = [&](const VectorType &p) {
                        if constexpr (dimensions == 2)
                        {
                            const Element c = (p[0] - pa[0]) * u[1] - (p[1] - pa[1]) * u[0];
                            return c * c;
                        }
                        else
                        {
                            const Element vx = p[0] - pa[0], vy = p[1] - pa[1], vz = p[2] - pa[2];
                            const Element cx = vy * u[2] - vz * u[1], cy = vz * u[0] - vx * u[2], cz = vx * u[1] - vy * u[0];
                            return cx * cx + cy * cy + cz * cz;
                        }
                    };
                    // Only reached when some coordinate is non-finite or huge (the SoA scan handles the rest):
                    // a plain scan that never keeps a point with a non-finite coordinate.
                    for (size_t i = a + 1; i < b; ++i)
                    {
                        if (!finite(pts[i]))
                            continue;
                        const Element c = cross2(pts[i]);
                        if (c > best_c) { best_c = c; best = i; }
                    }
                    return best;
                }
            }
            Element best_d = eps2;
            for (size_t i = a + 1; i < b; ++i)
            {
                if (!finite(pts[i]))
                    continue;
                const VectorType v = pts[i] - pa;
                Element d2;
                if (l2 > Element(0))
                    d2 = (v - u * (v.dot(u) / l2)).lengthSquared();
                else
                    d2 = v.lengthSquared();
                if (d2 > best_d) { best_d = d2; best = i; }
            }
            return best;
        }

    private:
        size_t pick(const std::vector<VectorType> &pts, size_t a, size_t b) const
        {
            if (distance_ == DpDistance::Segment)
                return farthestSegment(pts, a, b);
            if (!tame)
                return farthestScaled(pts, a, b);
            if constexpr (dimensions == 2 || dimensions == 3)
                return farthestSoa(pts, a, b);
            else
                return farthest(pts, a, b);
        }

        //! Coordinates of point i in double, times `scale`.
        void scaled(const VectorType &p, double *out) const
        {
            for (int k = 0; k < dimensions; ++k)
                out[k] = static_cast<double>(p[k]) * scale;
        }

        //! farthest() for any finite input: in double on rescaled coordinates (|c| < 1, so nothing overflows),
        //! comparing the squared distance with (epsilon * scale)^2.
        size_t farthestScaled(const std::vector<VectorType> &pts, size_t a, size_t b) const
        {
            double pa[dimensions], u[dimensions], v[dimensions];
            scaled(pts[a], pa);
            scaled(pts[b], u);
            double l2 = 0;
            for (int k = 0; k < dimensions; ++k)
            {
                u[k] -= pa[k];
                l2 += u[k] * u[k];
            }
            // A chord whose squared length is below the normal range (|u| < ~1.5e-154 of the extent) counts as
            // length 0. A longer one is brought to |u| ~ 1 by a power of two (exact: the same values wherever they
            // did not underflow), so that the cross product of a short chord with a distance above that threshold
            // does not underflow to 0 and drop the point (found by fuzz_vect_simplify: a chord of 1e-157 of the
            // extent, a point 1e-11 of it off the line, squared product 1e-337 -> 0).
            // (A non-finite end point gives l2 NaN, measured from the first end as before, or +inf, left as it is.)
            if (!(l2 >= std::numeric_limits<double>::min()))
                l2 = 0;
            else if (l2 <= std::numeric_limits<double>::max())
            {
                double top = 0;
                for (int k = 0; k < dimensions; ++k)
                    top = std::max(top, std::fabs(u[k]));
                const int shift = -std::ilogb(top);
                l2 = 0;
                for (int k = 0; k < dimensions; ++k)
                {
                    u[k] = std::ldexp(u[k], shift);
                    l2 += u[k] * u[k];
                }
            }
            const double e = epsilon * scale;
            double best_d = e * e;
            size_t best = 0;
            for (size_t i = a + 1; i < b; ++i)
            {
                if (!finite(pts[i]))
                    continue;
                scaled(pts[i], v);
                double d2 = 0;
                if constexpr (dimensions == 2)
                {
                    const double vx = v[0] - pa[0], vy = v[1] - pa[1];
                    if (l2 > 0)
                    {
                        const double c = vx * u[1] - vy * u[0];
                        d2 = c * c / l2;
                    }
                    else
                        d2 = vx * vx + vy * vy;
                }
                else if constexpr (dimensions == 3)
                {
                    const double vx = v[0] - pa[0], vy = v[1] - pa[1], vz = v[2] - pa[2];
                    if (l2 > 0)
                    {
                        const double cx = vy * u[2] - vz * u[1], cy = vz * u[0] - vx * u[2], cz = vx * u[1] - vy * u[0];
                        d2 = (cx * cx + cy * cy + cz * cz) / l2;
                    }
                    else
                        d2 = vx * vx + vy * vy + vz * vz;
                }
                else
                {
                    double vu = 0;
                    for (int k = 0; k < dimensions; ++k)
                    {
                        v[k] -= pa[k];
                        vu += v[k] * u[k];
                    }
                    const double t = l2 > 0 ? vu / l2 : 0;
                    for (int k = 0; k < dimensions; ++k)
                        d2 += (v[k] - u[k] * t) * (v[k] - u[k] * t);
                }
                if (d2 > best_d) { best_d = d2; best = i; }
            }
            return best;
        }

        //! Index in (a, b) of the first point farthest from the chord segment beyond epsilon, else 0: the
        //! arithmetic of simplifyCompatibleIndices (rescaled only when the chain is not tame, which is exact by a
        //! power of two unless that arithmetic would have overflowed). Non-finite points are never picked.
        size_t farthestSegment(const std::vector<VectorType> &pts, size_t a, size_t b) const
        {
            double pa[dimensions], pb[dimensions], p[dimensions];
            scaled(pts[a], pa);
            scaled(pts[b], pb);
            const detail::Chord<dimensions> chord(pa, pb);
            const double e = epsilon * scale;
            double best_d = e * e;
            size_t best = 0;
            for (size_t i = a + 1; i < b; ++i)
            {
                scaled(pts[i], p);
                const double d2 = detail::segmentDistance2<dimensions>(p, chord);
                if (d2 > best_d && finite(pts[i])) { best_d = d2; best = i; }
            }
            return best;
        }

        //! Distance reported by the trace: the measure in use, in double.
        double rangeDistance(const VectorType &p, const VectorType &a, const VectorType &b) const
        {
            if (distance_ == DpDistance::Line)
                return detail::lineDistance2(p, a, b);
            double pa[dimensions], pb[dimensions], q[dimensions];
            scaled(a, pa);
            scaled(b, pb);
            scaled(p, q);
            return detail::segmentDistance2<dimensions>(q, detail::Chord<dimensions>(pa, pb)) / (scale * scale);
        }

        //! The range event: the split decision is the untraced one (`far`); without a split, the farthest point
        //! is searched here (in double, finite points only) to show how far it is.
        void reportRange(const std::vector<VectorType> &pts, size_t a, size_t b, size_t far) const
        {
            size_t shown = far;
            double distance = 0;
            if (far != 0)
                distance = std::sqrt(rangeDistance(pts[far], pts[a], pts[b]));
            else
            {
                shown = a;
                double best2 = 0;
                for (size_t i = a + 1; i < b; ++i)
                {
                    const double d2 = rangeDistance(pts[i], pts[a], pts[b]);
                    if (d2 > best2 && finite(pts[i])) { best2 = d2; shown = i; }
                }
                distance = std::sqrt(best2);
            }
            (*observer_)(DpRange{a, b, shown, distance, epsilon, far != 0});
        }

        //! farthest() on the coordinate arrays in `soa` (same operations per point, so the same result): blocks of
        //! 16 points are compared with the best so far without branches; only in a block with a point beyond it is
        //! the first maximal index searched for.
        size_t farthestSoa(const std::vector<VectorType> &pts, size_t a, size_t b) const
        {
            const Element l2 = (pts[b] - pts[a]).lengthSquared();
            // A threshold below the normal range (tiny epsilon or chord, or epsilon 0) would lose the comparison
            // to underflow: measure such a range in double.
            if (!(l2 > Element(0)) || !(eps2 * l2 >= std::numeric_limits<Element>::min()))
                return farthestScaled(pts, a, b);
            const size_t n = pts.size();
            const Element *x = soa.data(), *y = x + n, *z = y + n;
            const Element ax = x[a], ay = y[a], az = dimensions == 3 ? z[a] : Element(0);
            const Element ux = x[b] - ax, uy = y[b] - ay, uz = dimensions == 3 ? z[b] - az : Element(0);
            Element best_c = eps2 * l2;
            size_t best = 0;
            const auto cross2 = [&](size_t i) {
                if constexpr (dimensions == 2)
                {
                    const Element c = (x[i] - ax) * uy - (y[i] - ay) * ux;
                    return c * c;
                }
                else
                {
                    const Element vx = x[i] - ax, vy = y[i] - ay, vz = z[i] - az;
                    const Element cx = vy * uz - vz * uy, cy = vz * ux - vx * uz, cz = vx * uy - vy * ux;
                    return cx * cx + cy * cy + cz * cz;
                }
            };
            constexpr size_t block = 16;
            size_t i = a + 1;
#if defined(__GNUC__)
            // 2D float/double: the same per-point operations on GCC/clang vector lanes (SSE2: 4 floats or 2 doubles
            // per instruction), so the same values. Per block, a running maximum per lane (one max instruction a
            // vector, no masks; exact, as `tame` excludes NaN) starting at the best so far; if its largest lane M
            // beats the best, the in-order scan would end the block at M on the first point equal to M, which is
            // then searched for.
            if constexpr (dimensions == 2 && (std::is_same_v<Element, float> || std::is_same_v<Element, double>))
            {
                typedef Element V __attribute__((vector_size(16)));
                constexpr size_t lanes = 16 / sizeof(Element);
                for (; i + block <= b; i += block)
                {
                    V m = V{} + best_c;
                    Element c2s[block];   // kept for the search: no recomputation (and it always ends in the block)
                    for (size_t q = 0; q < block; q += lanes)
                    {
                        V vx, vy;
                        std::memcpy(&vx, x + i + q, sizeof(V));
                        std::memcpy(&vy, y + i + q, sizeof(V));
                        const V c = (vx - ax) * uy - (vy - ay) * ux, c2 = c * c;
                        std::memcpy(c2s + q, &c2, sizeof(V));
                        m = m < c2 ? c2 : m;   // SSE2 maxpd/maxps, wasm f64x2/f32x4.pmax
                    }
                    Element top = m[0];
                    for (size_t l = 1; l < lanes; ++l)
                        top = top < m[l] ? m[l] : top;
                    if (top > best_c)
                    {
                        best_c = top;
                        size_t k = 0;
                        while (c2s[k] != top)
                            ++k;
                        best = i + k;
                    }
                }
            }
#endif
            for (; i + block <= b; i += block)
            {
                Element c2[block];
                for (size_t k = 0; k < block; ++k)
                    c2[k] = cross2(i + k);
                // Maximum by a tree of pairwise maxima (no NaN here: see `tame`).
                Element t8[8], t4[4];
                for (size_t k = 0; k < 8; ++k)
                    t8[k] = c2[k] > c2[k + 8] ? c2[k] : c2[k + 8];
                for (size_t k = 0; k < 4; ++k)
                    t4[k] = t8[k] > t8[k + 4] ? t8[k] : t8[k + 4];
                const Element m01 = t4[0] > t4[1] ? t4[0] : t4[1], m23 = t4[2] > t4[3] ? t4[2] : t4[3];
                const bool beats = (m01 > m23 ? m01 : m23) > best_c;
                if (beats)
                    for (size_t k = 0; k < block; ++k)
                        if (c2[k] > best_c) { best_c = c2[k]; best = i + k; }
            }
            for (; i < b; ++i)
            {
                const Element c = cross2(i);
                if (c > best_c) { best_c = c; best = i; }
            }
            return best;
        }

        Element eps2{static_cast<Element>(1e-6)};
        double epsilon{1e-3};
        Observer *observer_{nullptr};
        DpDistance distance_{DpDistance::Line};
        std::vector<Element> soa;
        bool tame{false};
        double scale{1};
        std::vector<std::pair<size_t, size_t>> stack;
        std::vector<size_t> keys;
    };

    //! Reumann-Witkam: a strip of half-width epsilon around the line from the current key point through the next
    //! distinct point; the scan advances while points stay inside, and the last point inside becomes the next key
    //! (the new strip then runs from it through the first point outside). The polyline runs from the first to the
    //! last input point. Exact (up to rounding) for every finite coordinate: chains within sqrt(max)/8 (about
    //! 2e153 in double, 2e18 in float) are measured as they are; others on coordinates rescaled by a power of two
    //! (no square overflows). Strip directions are normalised with rescaling, so however short the segment (a
    //! subnormal difference included) the direction is its own, not an arbitrary axis. setEpsilon(float) is RTL's;
    //! for double (or wider) vectorizers the ElementType overload keeps the full value.
    template<int dimensions, typename Element, class Observer = NoTrace>
    class VectorizerReumannWitkamND
    {
    public:
        typedef Element ElementType;
        typedef VectorND<dimensions, Element> VectorType;
        typedef LineSegmentND<dimensions, Element> LineSegmentType;

        VectorizerReumannWitkamND() = default;
        explicit VectorizerReumannWitkamND(ElementType eps) { setEpsilon(eps); }
        ~VectorizerReumannWitkamND() = default;

        void setEpsilon(float eps) { setEps(static_cast<Element>(eps)); }
        //! Addition: epsilon without narrowing to float (only where ElementType is not float).
        template<class E = Element, std::enable_if_t<!std::is_same_v<E, float>, int> = 0>
        void setEpsilon(ElementType eps) { setEps(eps); }
        void setMaxSize(size_t size) { keys.reserve(size); }
        //! Observer of the following calls (nullptr: none); it must outlive them.
        void setObserver(Observer *observer) { observer_ = observer; }

        void operator()(const std::vector<VectorType> &input, std::vector<LineSegmentType> &output)
        {
            const size_t n = input.size();
            keys.clear();
            if (n < 2) { output.clear(); return; }
            keys.push_back(0);
            if constexpr (Observer::enabled)
                if (observer_)
                {
                    (*observer_)(RwStart{n, epsilon});
                    (*observer_)(RwKeep{0});
                }
            const Element lim = std::sqrt(std::numeric_limits<Element>::max()) / 8;
            bool tame = true;
            Element max_abs = 0;
            for (size_t i = 0; i < n; ++i)
                for (int q = 0; q < dimensions; ++q)
                {
                    const Element c = std::abs(input[i][q]);
                    tame &= c <= lim;
                    if (c > max_abs && std::isfinite(c)) max_abs = c;
                }
            // Outside the tame range, and where squares could underflow (a tiny chain, or eps^2 below the normal
            // range), distances are measured in double on coordinates rescaled so that the largest is about
            // 2^500 (below 2^1000 for tiny double chains): nothing overflows, and tiny distances keep their digits.
            const Element low = std::sqrt(std::numeric_limits<Element>::min()) * Element(1048576);
            if (tame && max_abs >= low && eps2 >= std::numeric_limits<Element>::min())
                scan<false>(input, 1);
            else
            {
                int e = 0;
                std::frexp(max_abs > 0 ? static_cast<double>(max_abs) : 1.0, &e);
                scan<true>(input, std::ldexp(1.0, std::min(500 - e, 1000)));
            }
            if (keys.back() != n - 1)
            {
                keys.push_back(n - 1);
                if constexpr (Observer::enabled)
                    if (observer_)
                        (*observer_)(RwKeep{n - 1});
            }
            detail::polyline(input, keys, output);
        }

        //! Squared distance of p from the line through a with unit direction u.
        static Element distance2(const VectorType &p, const VectorType &a, const VectorType &u)
        {
            if constexpr (dimensions == 2)
            {
                const Element c = (p[0] - a[0]) * u[1] - (p[1] - a[1]) * u[0];
                return c * c;
            }
            else if constexpr (dimensions == 3)
            {
                const Element vx = p[0] - a[0], vy = p[1] - a[1], vz = p[2] - a[2];
                const Element cx = vy * u[2] - vz * u[1], cy = vz * u[0] - vx * u[2], cz = vx * u[1] - vy * u[0];
                return cx * cx + cy * cy + cz * cz;
            }
            else
            {
                const VectorType v = p - a;
                return (v - u * v.dot(u)).lengthSquared();
            }
        }

        //! Unit direction from a to b (a != b), normalised after rescaling by the largest |component|, so that no
        //! square underflows or overflows.
        static VectorType direction(const VectorType &a, const VectorType &b)
        {
            VectorType d = b - a;
            bool finite_d = true;
            for (int q = 0; q < dimensions; ++q)
                finite_d &= static_cast<bool>(std::isfinite(d[q]));
            if (!finite_d)
                d = b * Element(0.5) - a * Element(0.5);
            Element m = 0;
            for (int q = 0; q < dimensions; ++q)
                m = std::max(m, std::abs(d[q]));
            if (!(m > 0) || !std::isfinite(m))
                return d.normalized();
            d /= m;
            return d / d.length();
        }

    private:
        void setEps(Element eps) { eps2 = eps * eps; eps_ = eps; epsilon = static_cast<double>(eps); }

        //! The scan after the first key; `rescaled`: distances on coordinates times s (a power of two), compared
        //! with (epsilon s)^2.
        template<bool rescaled>
        void scan(const std::vector<VectorType> &input, double s)
        {
            const size_t n = input.size();
            const double es = static_cast<double>(eps_) * s, e2 = es * es;
            const auto far = [&](const VectorType &p, const VectorType &a, const VectorType &u) {
                if constexpr (rescaled)
                {
                    double v[dimensions], vu = 0, r2 = 0;
                    for (int q = 0; q < dimensions; ++q)
                    {
                        v[q] = static_cast<double>(p[q]) * s - static_cast<double>(a[q]) * s;
                        vu += v[q] * static_cast<double>(u[q]);
                    }
                    for (int q = 0; q < dimensions; ++q)
                    {
                        const double r = v[q] - static_cast<double>(u[q]) * vu;
                        r2 += r * r;
                    }
                    return r2 > e2;
                }
                else
                    return distance2(p, a, u) > eps2;
            };
            size_t k = 0;
            size_t j = 1;
            while (j < n && input[j] == input[k])
                ++j;
            if (j < n)
            {
                VectorType dir = direction(input[k], input[j]);
                [[maybe_unused]] size_t through = j;   // the strip's second point, for the trace only
                if constexpr (Observer::enabled)
                    if (observer_)
                        (*observer_)(RwStrip{k, j, epsilon});
                size_t i = j + 1;
                constexpr size_t block = 8;
                while (i < n)
                {
                    // Whole blocks of 8 are tested without branches; the first point outside is searched only in
                    // a block that has one.
                    if (i + block <= n)
                    {
                        bool out = false;
                        for (size_t q = 0; q < block; ++q)
                            out |= far(input[i + q], input[k], dir);
                        if (!out) { i += block; continue; }
                    }
                    if (far(input[i], input[k], dir))
                    {
                        if constexpr (Observer::enabled)
                            if (observer_)
                            {
                                const double d = detail::lineDistance(input[i], input[k], input[through]);
                                (*observer_)(RwExit{i, k, d, epsilon});
                                (*observer_)(RwKeep{i - 1});
                                (*observer_)(RwStrip{i - 1, i, epsilon});
                                through = i;
                            }
                        k = i - 1;
                        keys.push_back(k);
                        // Equal points leave the strip only by rounding (epsilon about 0): keep the direction
                        // rather than take the NaN of a zero difference.
                        if (!(input[i] == input[k]))
                            dir = direction(input[k], input[i]);
                    }
                    ++i;
                }
            }
        }

        Element eps2{static_cast<Element>(1e-6)};
        Element eps_{static_cast<Element>(1e-3)};
        double epsilon{1e-3};
        Observer *observer_{nullptr};
        std::vector<size_t> keys;
    };

    // RTL's names for the common instantiations.
    using VectorizerDouglasPeucker2f = VectorizerDouglasPeuckerND<2, float>;
    using VectorizerDouglasPeucker2d = VectorizerDouglasPeuckerND<2, double>;
    using VectorizerDouglasPeucker3f = VectorizerDouglasPeuckerND<3, float>;
    using VectorizerDouglasPeucker3d = VectorizerDouglasPeuckerND<3, double>;
    using VectorizerReumannWitkam2f = VectorizerReumannWitkamND<2, float>;
    using VectorizerReumannWitkam2d = VectorizerReumannWitkamND<2, double>;
    using VectorizerReumannWitkam3f = VectorizerReumannWitkamND<3, float>;
    using VectorizerReumannWitkam3d = VectorizerReumannWitkamND<3, double>;
}
