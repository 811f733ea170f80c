// Ray geometry of a range scan seen from its sensor at the origin: where a beam meets a line, whether a beam lies in
// a segment's angular span, and the expected range r-hat of every beam under a set of polylines ("ray casting" onto
// a line map, the measurement model of probabilistic line extraction). Everything is computed in double.
#pragma once

#include <cmath>
#include <cstddef>
#include <limits>
#include <vector>

namespace rtl::scan_polylines
{
    constexpr double kPi = 3.14159265358979323846264338327950288;
    constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

    //! Distance t along the unit direction (ux, uy) from the origin to the line through a and b, or NaN where there is
    //! no such crossing in front of the sensor (ray parallel to the line, a == b, crossing behind the origin, t not
    //! finite). Solves cross(b - a, t u - a) = 0: t = cross(b, a) / cross(b - a, u).
    inline double rangeAlongRay(double ux, double uy, double ax, double ay, double bx, double by)
    {
        const double den = (bx - ax) * uy - (by - ay) * ux;
        const double t = (bx * ay - by * ax) / den;
        return (std::isfinite(t) && t > 0) ? t : kNaN;
    }

    //! Squared lengths within which dx * dx + dy * dy neither overflows nor loses bits to underflow: inside it the
    //! plain formulas below are used, outside it (and for non-finite input) std::hypot.
    constexpr double kPlainSquaredMin = 0x1p-960, kPlainSquaredMax = 0x1p+960;

    //! |(dx, dy)|: sqrt(dx^2 + dy^2) where that sum is safely inside the double range (then within 1 ulp of
    //! std::hypot, which is several times slower, most of all in wasm, whose libm computes it in double-double),
    //! std::hypot elsewhere.
    inline double distance(double dx, double dy)
    {
        const double s = dx * dx + dy * dy;
        return (s > kPlainSquaredMin && s < kPlainSquaredMax) ? std::sqrt(s) : std::hypot(dx, dy);
    }

    //! Whether |(dx, dy)| <= limit (false for NaN), comparing squares where both are safely inside the double range
    //! (no sqrt at all), std::hypot elsewhere. Both sides of the squared comparison carry a rounding error of at most
    //! ~2 ulp, so it can decide otherwise than the exact comparison only when |(dx, dy)| and limit agree to within
    //! ~4e-16 relative, where hypot's own rounding already decides.
    inline bool withinDistance(double dx, double dy, double limit)
    {
        const double s = dx * dx + dy * dy, l = limit * limit;
        if (s > kPlainSquaredMin && s < kPlainSquaredMax && l > kPlainSquaredMin && l < kPlainSquaredMax) return s <= l;
        return std::hypot(dx, dy) <= limit;
    }

    //! An angle difference wrapped to [-pi, pi] (differences of atan2 values lie in [-3 pi, 3 pi]: a branch or two is
    //! much cheaper than std::remainder, which dominated the hit tests; other finite values fall back to it).
    inline double wrapAngle(double a)
    {
        if (a > kPi) a -= 2 * kPi;
        else if (a < -kPi) a += 2 * kPi;
        return (a >= -kPi && a <= kPi) || std::isnan(a) ? a : std::remainder(a, 2 * kPi);
    }

    //! The angular span of a segment (a, b) seen from the origin: from angle `start` over the signed `width` in
    //! [-pi, pi] (the shorter way round, which is the segment's own span for a segment that misses the origin).
    struct AngularSpan
    {
        double start = 0, width = 0;

        static AngularSpan of(double ax, double ay, double bx, double by)
        {
            AngularSpan s;
            s.start = std::atan2(ay, ax);
            s.width = wrapAngle(std::atan2(by, bx) - s.start);
            return s;
        }

        //! Whether direction `angle` lies in the span widened by `widen` radians on each side (false for NaN).
        [[nodiscard]] bool contains(double angle, double widen) const
        {
            const double e = wrapAngle(angle - start);
            return width >= 0 ? (e >= -widen && e <= width + widen) : (e <= widen && e >= width - widen);
        }
    };

    //! A widening angle with its cosine and sine, computed once for many DirectionSpan::of.
    struct Widening
    {
        double angle = 0, cos = 1, sin = 0;
        explicit Widening(double w) : angle(w), cos(std::cos(w)), sin(std::sin(w)) {}
    };

    //! The hit test of AngularSpan (the span of a segment (a, b) seen from the origin, widened on each side) without
    //! atan2: AngularSpan::of costs two atan2 per segment, most of the hit test's time. The span's end directions a
    //! and b are rotated outward by the widening, to a' and b', and a direction u lies in the widened span when
    //!   s cross(a', u) >= 0  and  s cross(u, b') >= 0,   s = the span's orientation (sign of cross(a, b)).
    //! Why this is AngularSpan::contains: let L = |width| + 2 widen be the widened span's angle and theta the angle
    //! from a' to u in the span's direction, in [0, 2 pi). The first test holds for theta in [0, pi], the second for
    //! L - theta in [0, pi] mod 2 pi, i.e. theta in [0, L] or [L + pi, 2 pi); together, when L < pi, exactly theta in
    //! [0, L]: the widened span, which AngularSpan::contains tests through wrapped angle differences (no wrap-around
    //! matters there either, as its bounds -widen and width + widen then lie inside [-pi, pi]). L < pi holds when
    //! dot(a, b) >= 0 (|width| <= pi / 2) and widen <= kMaxCrossWiden; other spans (and ends of a squared length
    //! outside the plain range, e.g. a vertex at the origin) use AngularSpan itself. The two
    //! tests round differently, so they can disagree only for a direction within a few ulp of the widened span's
    //! ends (tests/vect/t_ray_geometry_fast.cpp compares them on random spans, wrap-around at +-pi included).
    struct DirectionSpan
    {
        static constexpr double kMaxCrossWiden = 0.5;
        double ax = 0, ay = 0, bx = 0, by = 0, s = 1;   //!< widened end directions (not unit) and orientation
        bool by_angle = false;                           //!< a wide span: tested by `angular` instead
        AngularSpan angular;

        static DirectionSpan of(double ax, double ay, double bx, double by, const Widening &w)
        {
            DirectionSpan d;
            const double a2 = ax * ax + ay * ay, b2 = bx * bx + by * by;
            if (!(ax * bx + ay * by >= 0) || !(w.angle >= 0 && w.angle <= kMaxCrossWiden) || !(a2 > kPlainSquaredMin && a2 < kPlainSquaredMax)
                || !(b2 > kPlainSquaredMin && b2 < kPlainSquaredMax))
            {
                d.by_angle = true;
                d.angular = AngularSpan::of(ax, ay, bx, by);
                return d;
            }
            d.s = ax * by - ay * bx >= 0 ? 1.0 : -1.0;
            const double sn = d.s * w.sin;   // a turns back by the widening (against s), b on by it (along s)
            d.ax = ax * w.cos + ay * sn; d.ay = ay * w.cos - ax * sn;
            d.bx = bx * w.cos - by * sn; d.by = by * w.cos + bx * sn;
            return d;
        }

        //! Whether the direction (ux, uy) lies in the widened span (false for NaN). Its length is free as long as
        //! ux^2 + uy^2 lies within (kPlainSquaredMin, kPlainSquaredMax) (no product underflows); `angle`, its atan2,
        //! is read for wide spans only.
        [[nodiscard]] bool contains(double ux, double uy, double angle, const Widening &w) const
        {
            if (by_angle) return angular.contains(angle, w.angle);
            return s * (ax * uy - ay * ux) >= 0 && s * (ux * by - uy * bx) >= 0;
        }
    };

    //! Totals of a scan scored against a line map: returned beams, beams hit by a segment, and the sum of the hit
    //! beams' squared radial errors.
    struct RayScore
    {
        std::size_t returned = 0, hit = 0;
        double sum_squared = 0;

        //! Root mean square radial error over the hit beams (NaN when none is hit).
        [[nodiscard]] double rmse() const { return hit ? std::sqrt(sum_squared / static_cast<double>(hit)) : kNaN; }
        //! Fraction of the returned beams that are hit (NaN when none is returned).
        [[nodiscard]] double explained() const { return returned ? static_cast<double>(hit) / static_cast<double>(returned) : kNaN; }
        //! Mean per returned beam of the squared radial error (hit) or cost^2 (not hit): f * rmse^2 + (1 - f) * cost^2.
        [[nodiscard]] double score(double cost) const
        {
            return returned ? (sum_squared + static_cast<double>(returned - hit) * cost * cost) / static_cast<double>(returned) : kNaN;
        }
    };

    //! expectedRangesOf(angles, polylines, widen) (below) given the beams' unit directions (ux[i], uy[i]) = (cos, sin) of
    //! angles[i] (the caller's, so that they are not computed again).
    template<class Polylines>
    std::vector<double> expectedRangesOf(const std::vector<double> &angles, const double *ux, const double *uy,
                                         const Polylines &polylines, double widen)
    {
        std::vector<double> rhat(angles.size(), kNaN);
        const Widening w(widen);
        for (const auto &poly : polylines)
            for (std::size_t j = 0; j + 1 < poly.size(); ++j)
            {
                const double ax = static_cast<double>(poly[j][0]), ay = static_cast<double>(poly[j][1]);
                const double bx = static_cast<double>(poly[j + 1][0]), by = static_cast<double>(poly[j + 1][1]);
                const DirectionSpan span = DirectionSpan::of(ax, ay, bx, by, w);
                for (std::size_t i = 0; i < angles.size(); ++i)
                    if (span.contains(ux[i], uy[i], angles[i], w))
                    {
                        const double t = rangeAlongRay(ux[i], uy[i], ax, ay, bx, by);
                        if (!std::isnan(t)) rhat[i] = t;
                    }
            }
        return rhat;
    }

    //! Expected ranges of beams (directions `angles`, radians) under polylines (each a vertex list; segment j joins
    //! vertices j and j + 1): a segment hits a beam whose direction lies in its angular span widened by `widen`, and
    //! gives r-hat = the distance along the beam to the segment's line when that is finite and > 0. Where several
    //! segments hit a beam, the later one (polyline after polyline, segment after segment) counts. NaN where none hits
    //! (and for a NaN angle). Complexity O(beams x segments).
    template<class Polylines>
    std::vector<double> expectedRangesOf(const std::vector<double> &angles, const Polylines &polylines, double widen)
    {
        std::vector<double> ux(angles.size()), uy(angles.size());
        for (std::size_t i = 0; i < angles.size(); ++i) { ux[i] = std::cos(angles[i]); uy[i] = std::sin(angles[i]); }
        return expectedRangesOf(angles, ux.data(), uy.data(), polylines, widen);
    }

    //! Scores measured ranges against expected ones: returned beams are those with returned[i]; a returned beam is hit
    //! where rhat[i] is not NaN. Sizes must match.
    inline RayScore scoreExpected(const std::vector<double> &ranges, const std::vector<bool> &returned, const std::vector<double> &rhat)
    {
        RayScore s;
        for (std::size_t i = 0; i < ranges.size(); ++i)
        {
            if (!returned[i]) continue;
            ++s.returned;
            if (std::isnan(rhat[i])) continue;
            ++s.hit;
            const double e = ranges[i] - rhat[i];
            s.sum_squared += e * e;
        }
        return s;
    }
}
