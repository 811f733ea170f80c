// Radial refinement of a polyline whose vertices lie on beams, every vertex moved along its own beam only:
// Levenberg-Marquardt on the vertices' ranges, minimising the sum of squared radial errors of the beams between them.
//
// Why: with every vertex on its own beam, each segment's angular span stays the wedge between its vertices' beams,
// so the beams each segment explains never change and the cost minimised is exactly the ray model's hit-tested cost
// (a free inner vertex, as RadialRefinement moves it, carries beams across segments, and the fixed assignment it
// minimises drifts from the hit test). A beam's error depends on its segment's two vertex ranges only, so the normal
// equations are tridiagonal: O(beams + vertices) per iteration. Only steps that lower the cost are taken.
//
// Preconditions: vertex j lies on beam vb[j] (vb increasing), beam ranges and directions as in BeamArrays; segment j
// explains beams vb[j] .. vb[j+1] - 1, the last segment also beam vb[k].
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

#include "rtl/vect/scan_polylines/RadialRefinement.h"
#include "rtl/vect/scan_polylines/DampedStep.h"
#include "rtl/vect/scan_polylines/RayGeometry.h"

namespace rtl::detail
{
    class BeamRangeRefinement
    {
    public:
        void setMaxIterations(int n) { max_iter_ = n; }

        //! Refines the ranges rho (one per vertex, vertex j at rho[j] along beam vb[j]); `invalid_cost` is charged for a
        //! beam its segment's line does not cross in front of the sensor. Returns the final cost.
        double operator()(std::vector<double> &rho, const std::vector<std::size_t> &vb, const scan_polylines::BeamArrays &beams,
                          double invalid_cost)
        {
            const std::size_t m = rho.size();
            if (m < 2 || vb.size() != m) return scan_polylines::kNaN;
            double current = cost(rho, vb, beams, invalid_cost);
            double lambda = 1e-3;
            diag_.resize(m); off_.resize(m); grad_.resize(m); step_.resize(m); trial_.resize(m);
            for (int it = 0; it < max_iter_; ++it)
            {
                std::fill(diag_.begin(), diag_.end(), 0.0);
                std::fill(off_.begin(), off_.end(), 0.0);
                std::fill(grad_.begin(), grad_.end(), 0.0);
                for (std::size_t j = 0; j + 1 < m; ++j)
                {
                    const std::size_t a = vb[j], b = vb[j + 1];
                    const double ax = rho[j] * beams.ux[a], ay = rho[j] * beams.uy[a];
                    const double bx = rho[j + 1] * beams.ux[b], by = rho[j + 1] * beams.uy[b];
                    const std::size_t end = j + 2 == m ? b : b - 1;
                    for (std::size_t i = a; i <= end; ++i)
                    {
                        const double ux = beams.ux[i], uy = beams.uy[i];
                        const double D = (bx - ax) * uy - (by - ay) * ux;
                        const double t = (bx * ay - by * ax) / D;
                        if (!(std::isfinite(t) && t > 0)) continue;
                        // dt/da and dt/db (as in RadialRefinement), projected on the vertices' beams
                        const double ja = ((-by + t * uy) * beams.ux[a] + (bx - t * ux) * beams.uy[a]) / D;
                        const double jb = ((ay - t * uy) * beams.ux[b] + (-ax + t * ux) * beams.uy[b]) / D;
                        const double e = beams.r[i] - t;
                        grad_[j] += ja * e; grad_[j + 1] += jb * e;
                        diag_[j] += ja * ja; diag_[j + 1] += jb * jb; off_[j] += ja * jb;
                    }
                }
                const bool improved = scan_polylines::dampedStep(lambda, current,
                    [&](double l, double &c) {
                        if (!solve(m, l)) return false;
                        for (std::size_t j = 0; j < m; ++j) trial_[j] = rho[j] + step_[j];
                        c = cost(trial_, vb, beams, invalid_cost);
                        return true;
                    },
                    [&] { rho.swap(trial_); });
                if (!improved) break;
            }
            return current;
        }

        //! Sum of squared radial errors of the beams vb[0] .. vb[m-1] under the polyline of ranges rho.
        static double cost(const std::vector<double> &rho, const std::vector<std::size_t> &vb, const scan_polylines::BeamArrays &beams,
                           double invalid_cost)
        {
            double c = 0;
            const std::size_t m = rho.size();
            for (std::size_t j = 0; j + 1 < m; ++j)
            {
                const std::size_t a = vb[j], b = vb[j + 1];
                const double ax = rho[j] * beams.ux[a], ay = rho[j] * beams.uy[a];
                const double bx = rho[j + 1] * beams.ux[b], by = rho[j + 1] * beams.uy[b];
                const std::size_t end = j + 2 == m ? b : b - 1;
                for (std::size_t i = a; i <= end; ++i)
                {
                    const double t = scan_polylines::rangeAlongRay(beams.ux[i], beams.uy[i], ax, ay, bx, by);
                    const double e = beams.r[i] - t;
                    c += std::isnan(t) ? invalid_cost : e * e;
                }
            }
            return c;
        }

    private:
        //! (J^T J + lambda diag(J^T J)) step = J^T e, tridiagonal (Thomas algorithm); false when singular.
        bool solve(std::size_t m, double lambda)
        {
            std::vector<double> &c = work_c_, &d = work_d_;
            c.resize(m); d.resize(m);
            double prev_c = 0, prev_d = 0;
            for (std::size_t j = 0; j < m; ++j)
            {
                const double sub = j > 0 ? off_[j - 1] : 0.0;
                const double den = diag_[j] * (1 + lambda) + 1e-12 - sub * prev_c;
                if (!(std::abs(den) > 0) || !std::isfinite(den)) return false;
                c[j] = j + 1 < m ? off_[j] / den : 0.0;
                d[j] = (grad_[j] - sub * prev_d) / den;
                prev_c = c[j]; prev_d = d[j];
            }
            step_[m - 1] = d[m - 1];
            for (std::size_t j = m - 1; j-- > 0;) step_[j] = d[j] - c[j] * step_[j + 1];
            for (double v : step_) if (!std::isfinite(v)) return false;
            return true;
        }

        int max_iter_ = 20;
        std::vector<double> diag_, off_, grad_, step_, trial_, work_c_, work_d_;
    };
}
