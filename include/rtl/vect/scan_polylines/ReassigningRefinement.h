// Radial refinement of one polyline with its beams re-assigned by the hit test: rounds of single Levenberg-Marquardt
// iterations (RadialRefinement.h), after each of which every beam goes to the segment whose angular span holds its
// direction (the later segment where two spans meet, as the ray model counts), kept while the cost on the new
// assignment falls.
//
// Why: RadialRefinement keeps each beam on the segment it started on. When an inner vertex moves round, the beams
// it passes are then scored by the wrong segment's line, and the fixed-assignment optimum drifts away from the
// hit-tested one: on the benchmark, more LM iterations gave a worse hit-tested map than one. Here the cost a round
// is judged by is the hit-tested cost of the polyline's own beams (the beams between its end vertices).
//
// Preconditions: the polyline's end vertices lie on beams segs.front().first and segs.back().second (they stay there),
// beams in between turn one way with directions farther apart than `widen`. O(rounds x (beams + segments)).
#pragma once

#include <cmath>
#include <cstddef>
#include <utility>
#include <vector>

#include "rtl/vect/scan_polylines/RadialRefinement.h"
#include "rtl/vect/scan_polylines/RayGeometry.h"

namespace rtl::detail
{
    class ReassigningRefinement
    {
    public:
        typedef std::vector<std::pair<std::size_t, std::size_t>> Segments;

        //! Refines (vx, vy) with at most `rounds` rounds; `segs` receives the final assignment. `angles` are the
        //! beams' directions (radians), `invalid_cost` is charged for a beam its segment's line does not cross in
        //! front of the sensor. Returns the final cost on the final assignment.
        double operator()(std::vector<double> &vx, std::vector<double> &vy, Segments &segs, const scan_polylines::BeamArrays &beams,
                          const double *angles, double invalid_cost, int rounds, double widen = 1e-3)
        {
            double cost = assignedCost(vx, vy, segs, beams, invalid_cost);
            lm_.setMaxIterations(1);
            for (int r = 0; r < rounds; ++r)
            {
                x_ = vx; y_ = vy; s_ = segs;
                lm_(x_, y_, s_, beams, invalid_cost);
                if (!reassign(x_, y_, s_, angles, widen)) break;
                const double c = assignedCost(x_, y_, s_, beams, invalid_cost);
                if (!(c < cost * (1 - 1e-12))) break;
                cost = c;
                vx.swap(x_); vy.swap(y_); segs.swap(s_);
            }
            return cost;
        }

    private:
        //! Beams to segments by the vertices' directions; false (nothing changed) where a segment would get no beam
        //! (a vertex moved past its neighbour's direction).
        static bool reassign(const std::vector<double> &vx, const std::vector<double> &vy, Segments &segs, const double *angles, double widen)
        {
            const std::size_t k = segs.size(), first = segs.front().first, last = segs.back().second;
            if (k < 2) return true;
            const double dir = scan_polylines::wrapAngle(angles[last] - angles[first]) >= 0 ? 1.0 : -1.0;
            Segments out(k);
            std::size_t b = first;   // the first beam of segment s
            for (std::size_t s = 0; s < k; ++s)
            {
                out[s].first = b;
                std::size_t e = last;
                if (s + 1 < k)
                {
                    // segment s + 1 starts at the first beam at or past its first vertex's direction (less the widening)
                    const double a = std::atan2(vy[s + 1], vx[s + 1]);
                    std::size_t i = b + 1;
                    while (i <= last && dir * scan_polylines::wrapAngle(angles[i] - a) < -widen) ++i;
                    if (i > last) return false;
                    e = i - 1;
                    b = i;
                }
                out[s].second = e;
            }
            segs.swap(out);
            return true;
        }

        static double assignedCost(const std::vector<double> &vx, const std::vector<double> &vy, const Segments &segs,
                                   const scan_polylines::BeamArrays &beams, double invalid_cost)
        {
            double c = 0;
            for (std::size_t s = 0; s < segs.size(); ++s)
                for (std::size_t i = segs[s].first; i <= segs[s].second; ++i)
                {
                    const double t = scan_polylines::rangeAlongRay(beams.ux[i], beams.uy[i], vx[s], vy[s], vx[s + 1], vy[s + 1]);
                    const double e = beams.r[i] - t;
                    c += std::isnan(t) ? invalid_cost : e * e;
                }
            return c;
        }

        scan_polylines::RadialRefinement lm_;
        std::vector<double> x_, y_;
        Segments s_;
    };
}
