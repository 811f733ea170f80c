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

    //! Expected ranges of beams (directions `angles`, radians) under polylines (each a vertex list; segment j joins
    //! vertices j and j + 1): a segment hits a beam whose direction lies in its angular span widened by `widen`, and
    //! gives r-hat = the distance along the beam to the segment's line when that is finite and > 0. Where several
    //! segments hit a beam, the later one (polyline after polyline, segment after segment) counts. NaN where none hits
    //! (and for a NaN angle). Complexity O(beams x segments).
    template<class Polylines>
    std::vector<double> expectedRangesOf(const std::vector<double> &angles, const Polylines &polylines, double widen)
    {
        std::vector<double> rhat(angles.size(), kNaN);
        std::vector<double> ux(angles.size()), uy(angles.size());
        for (std::size_t i = 0; i < angles.size(); ++i) { ux[i] = std::cos(angles[i]); uy[i] = std::sin(angles[i]); }
        for (const auto &poly : polylines)
            for (std::size_t j = 0; j + 1 < poly.size(); ++j)
            {
                const double ax = static_cast<double>(poly[j][0]), ay = static_cast<double>(poly[j][1]);
                const double bx = static_cast<double>(poly[j + 1][0]), by = static_cast<double>(poly[j + 1][1]);
                const AngularSpan span = AngularSpan::of(ax, ay, bx, by);
                for (std::size_t i = 0; i < angles.size(); ++i)
                    if (span.contains(angles[i], widen))
                    {
                        const double t = rangeAlongRay(ux[i], uy[i], ax, ay, bx, by);
                        if (!std::isnan(t)) rhat[i] = t;
                    }
            }
        return rhat;
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
