// Radial refinement of one polyline: Levenberg-Marquardt on its vertices, minimising the sum over its beams of the
// squared radial error (measured range - distance along the beam to the beam's segment), with every beam kept on the
// segment it was assigned to. The two end vertices move along their own beams (one parameter each), the inner
// vertices freely (two each), so a polyline of k segments has 2k parameters. A beam's error depends on the two
// vertices of its segment only, so the normal equations are banded (half bandwidth 3) and one iteration costs
// O(beams + k). Only steps that lower the cost are taken, so the result is never worse than the start.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <utility>
#include <vector>

#include "rtl/vect/scan_polylines/RayGeometry.h"

namespace rtl::scan_polylines
{
    //! Beams of a scan as unit directions and measured ranges (arrays indexed by beam).
    struct BeamArrays
    {
        const double *ux = nullptr, *uy = nullptr, *r = nullptr;
    };

    class RadialRefinement
    {
    public:
        void setMaxIterations(int n) { max_iter_ = n; }

        //! Refines vertices (vx, vy; k + 1 of them) of a polyline whose segment s explains beams segs[s].first..second
        //! (inclusive, beam indices into `beams`). Vertex 0 must lie on beam segs[0].first and vertex k on beam
        //! segs[k-1].second (they stay there). `invalid_cost` is charged for a beam that its segment's line does not
        //! cross in front of the sensor. Returns the final cost (sum of squared radial errors).
        double operator()(std::vector<double> &vx, std::vector<double> &vy, const std::vector<std::pair<std::size_t, std::size_t>> &segs,
                          const BeamArrays &beams, double invalid_cost)
        {
            const std::size_t k = segs.size();
            if (k == 0 || vx.size() != k + 1) return kNaN;
            const std::size_t P = 2 * k;
            const std::size_t bf = segs.front().first, bl = segs.back().second;
            const double ufx = beams.ux[bf], ufy = beams.uy[bf], ulx = beams.ux[bl], uly = beams.uy[bl];
            // work vectors are members, so that repeated calls do not allocate once they have grown
            std::vector<double> &p = p_, &trial = trial_;
            p.resize(P); trial.resize(P);
            p[0] = vx[0] * ufx + vy[0] * ufy;
            for (std::size_t v = 1; v < k; ++v) { p[2 * v - 1] = vx[v]; p[2 * v] = vy[v]; }
            p[P - 1] = vx[k] * ulx + vy[k] * uly;

            auto vertex = [&](const std::vector<double> &q, std::size_t v, double &x, double &y) {
                if (v == 0) { x = q[0] * ufx; y = q[0] * ufy; }
                else if (v == k) { x = q[P - 1] * ulx; y = q[P - 1] * uly; }
                else { x = q[2 * v - 1]; y = q[2 * v]; }
            };
            auto cost = [&](const std::vector<double> &q) {
                double c = 0;
                for (std::size_t s = 0; s < k; ++s)
                {
                    double ax, ay, bx, by;
                    vertex(q, s, ax, ay); vertex(q, s + 1, bx, by);
                    for (std::size_t i = segs[s].first; i <= segs[s].second; ++i)
                    {
                        const double t = rangeAlongRay(beams.ux[i], beams.uy[i], ax, ay, bx, by);
                        const double e = beams.r[i] - t;
                        c += std::isnan(t) ? invalid_cost : e * e;
                    }
                }
                return c;
            };

            band_.assign(P * 4, 0.0);
            grad_.assign(P, 0.0);
            double current = cost(p);
            double lambda = 1e-3;
            for (int it = 0; it < max_iter_; ++it)
            {
                std::fill(band_.begin(), band_.end(), 0.0);
                std::fill(grad_.begin(), grad_.end(), 0.0);
                for (std::size_t s = 0; s < k; ++s)
                {
                    double ax, ay, bx, by;
                    vertex(p, s, ax, ay); vertex(p, s + 1, bx, by);
                    // parameter indices and d(vertex)/d(parameter) of the segment's two vertices
                    std::size_t idx[4]; double jac[4]; std::size_t m = 0;
                    for (std::size_t i = segs[s].first; i <= segs[s].second; ++i)
                    {
                        const double ux = beams.ux[i], uy = beams.uy[i];
                        const double N = bx * ay - by * ax, D = (bx - ax) * uy - (by - ay) * ux;
                        const double t = N / D;
                        if (!(std::isfinite(t) && t > 0)) continue;
                        // dt = (dN - t dD) / D
                        const double dax = (-by + t * uy) / D, day = (bx - t * ux) / D;
                        const double dbx = (ay - t * uy) / D, dby = (-ax + t * ux) / D;
                        m = 0;
                        if (s == 0) { idx[m] = 0; jac[m++] = dax * ufx + day * ufy; }
                        else { idx[m] = 2 * s - 1; jac[m++] = dax; idx[m] = 2 * s; jac[m++] = day; }
                        if (s + 1 == k) { idx[m] = P - 1; jac[m++] = dbx * ulx + dby * uly; }
                        else { idx[m] = 2 * s + 1; jac[m++] = dbx; idx[m] = 2 * s + 2; jac[m++] = dby; }
                        const double e = beams.r[i] - t;
                        for (std::size_t a = 0; a < m; ++a)
                        {
                            grad_[idx[a]] += jac[a] * e;
                            for (std::size_t b = 0; b <= a; ++b) band_[idx[a] * 4 + (idx[a] - idx[b])] += jac[a] * jac[b];
                        }
                    }
                }
                bool improved = false;
                while (lambda < 1e10)
                {
                    if (solveDamped(P, lambda))
                    {
                        for (std::size_t i = 0; i < P; ++i) trial[i] = p[i] + step_[i];
                        const double c = cost(trial);
                        if (c < current)
                        {
                            const double gain = current - c;
                            p.swap(trial);
                            current = c;
                            lambda = std::max(lambda / 3, 1e-9);
                            improved = gain > 1e-12 * (current + 1e-30);
                            break;
                        }
                    }
                    lambda *= 4;
                }
                if (!improved) break;
            }
            for (std::size_t v = 0; v <= k; ++v) vertex(p, v, vx[v], vy[v]);
            return current;
        }

    private:
        //! Solves (A + lambda diag(A)) step = grad by a banded Cholesky factorisation (false if not positive).
        bool solveDamped(std::size_t P, double lambda)
        {
            chol_ = band_;
            for (std::size_t i = 0; i < P; ++i) chol_[i * 4] += lambda * std::max(band_[i * 4], 1e-12);
            auto L = [&](std::size_t i, std::size_t j) -> double & { return chol_[i * 4 + (i - j)]; };
            for (std::size_t i = 0; i < P; ++i)
            {
                const std::size_t lo = i >= 3 ? i - 3 : 0;
                for (std::size_t j = lo; j <= i; ++j)
                {
                    double sum = L(i, j);
                    for (std::size_t q = lo; q < j; ++q) sum -= L(i, q) * L(j, q);
                    if (i == j)
                    {
                        if (!(sum > 0)) return false;
                        L(i, i) = std::sqrt(sum);
                    }
                    else
                        L(i, j) = sum / L(j, j);
                }
            }
            step_.assign(P, 0.0);
            for (std::size_t i = 0; i < P; ++i)
            {
                double sum = grad_[i];
                for (std::size_t q = i >= 3 ? i - 3 : 0; q < i; ++q) sum -= L(i, q) * step_[q];
                step_[i] = sum / L(i, i);
            }
            for (std::size_t i = P; i-- > 0;)
            {
                double sum = step_[i];
                for (std::size_t q = i + 1; q < std::min(P, i + 4); ++q) sum -= L(q, i) * step_[q];
                step_[i] = sum / L(i, i);
            }
            for (double v : step_) if (!std::isfinite(v)) return false;
            return true;
        }

        int max_iter_ = 20;
        std::vector<double> band_, chol_, grad_, step_, p_, trial_;
    };
}
