// Radial refinement of one polyline: Levenberg-Marquardt on its vertices, minimising the sum over its beams of the
// squared radial error (measured range - distance along the beam to the beam's segment), with every beam kept on the
// segment it was assigned to. The two end vertices move along their own beams (one parameter each), the inner
// vertices freely (two each), so a polyline of k segments has 2k parameters. A beam's error depends on the two
// vertices of its segment only, so the normal equations are banded (half bandwidth 3) and one iteration costs
// O(beams + k). Only steps that lower the cost are taken, so the result is never worse than the start.
//
// Hit-consistent refinement (setWedges): with a fixed assignment, an inner vertex may drift past a beam, and the hit
// test then predicts that beam by the other segment, so the cost the LM lowers is not the one the scan is scored by
// (more iterations can raise the hit-tested error). With wedges on, every inner vertex whose two segments meet between
// beams b and b + 1 is kept in the wedge between beam b (turned by kWedgeMargin towards b + 1) and beam b + 1: a
// trial step that leaves it is projected back onto the wedge's nearer edge. Then the hit test (spans widened by less
// than kWedgeMargin) assigns every beam as the refinement does and the refined cost is the polyline's hit-tested one.
// refineConsistent adds boundary shifts: a vertex resting on its wedge's edge hands that edge's beam to the other
// segment, the vertex alone is refined in its new wedge and the shift kept when its two segments' cost falls; after a
// pass with kept shifts the whole polyline is refined again (a local search over the assignment).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <utility>
#include <vector>

#include "rtl/vect/scan_polylines/DampedStep.h"
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
            return refine(vx, vy, segs, beams, invalid_cost);
        }

        //! Keeps every inner vertex in the wedge of its boundary beams (see the file comment; default off). Needs beams
        //! more than 2 kWedgeMargin apart at the boundary; a vertex whose boundary beams are closer stays free.
        void setWedges(bool on) { wedges_ = on; }

        //! The refinement with wedges, then up to `rounds` passes of boundary shifts (see the file comment). `segs` is
        //! updated to the final assignment (every segment keeps at least one beam; the end beams do not change).
        //! Returns the final cost, which equals the polyline's hit-tested cost on its beams and is never above the cost
        //! of the start with its inner vertices projected into their wedges (the start itself where they lie inside,
        //! e.g. vertices on measured points). Each pass costs a refinement of one vertex (its two segments' beams) per
        //! vertex on a wedge edge, and one refinement of the whole polyline if a shift was kept.
        double refineConsistent(std::vector<double> &vx, std::vector<double> &vy, std::vector<std::pair<std::size_t, std::size_t>> &segs,
                                const BeamArrays &beams, double invalid_cost, int rounds)
        {
            const bool was = wedges_;
            wedges_ = true;
            double best = refine(vx, vy, segs, beams, invalid_cost);
            const std::size_t k = segs.size();
            for (int round = 0; round < rounds && k >= 2 && !std::isnan(best); ++round)
            {
                // Each shift is first tried with its vertex alone moving (its neighbours fixed: two segments' beams),
                // kept when that lowers the two segments' cost; then the whole polyline is refined again.
                bool shifted = false;
                for (std::size_t v = 1; v < k; ++v)
                {
                    const int side = wedgeEdge(vx[v], vy[v], segs[v - 1].second, segs[v].first, beams);
                    if (side == 0) continue;
                    std::pair<std::size_t, std::size_t> left = segs[v - 1], right = segs[v];
                    if (side < 0)   // on beam b's edge: beam b goes to the later segment
                    {
                        if (left.second <= left.first) continue;
                        --left.second; --right.first;
                    }
                    else            // on beam b + 1's edge: it goes to the earlier segment
                    {
                        if (right.second <= right.first) continue;
                        ++left.second; ++right.first;
                    }
                    const double before = pairCost(vx[v - 1], vy[v - 1], vx[v], vy[v], vx[v + 1], vy[v + 1], segs[v - 1], segs[v], beams, invalid_cost);
                    double x = vx[v], y = vy[v];
                    const double after = refineVertex(vx[v - 1], vy[v - 1], x, y, vx[v + 1], vy[v + 1], left, right, beams, invalid_cost);
                    if (after < before - 1e-12 * before)
                    {
                        vx[v] = x; vy[v] = y; segs[v - 1] = left; segs[v] = right;
                        shifted = true;
                    }
                }
                if (!shifted) break;
                best = refine(vx, vy, segs, beams, invalid_cost);
            }
            wedges_ = was;
            return best;
        }

        //! The angle (radians) by which a wedge's lower edge is turned from its beam: larger than the hit test's span
        //! widening (1e-3 rad in PLE's metric), so that a vertex on that edge leaves the beam to its own segment.
        static constexpr double kWedgeMargin = 1.5e-3;

    private:
        //! Squared radial errors of the beams of segments (a, v) (beams `left`) and (v, b) (beams `right`).
        static double pairCost(double ax, double ay, double vx, double vy, double bx, double by, std::pair<std::size_t, std::size_t> left,
                               std::pair<std::size_t, std::size_t> right, const BeamArrays &beams, double invalid_cost)
        {
            double c = 0;
            for (std::size_t i = left.first; i <= left.second; ++i)
            {
                const double t = rangeAlongRay(beams.ux[i], beams.uy[i], ax, ay, vx, vy), e = beams.r[i] - t;
                c += std::isnan(t) ? invalid_cost : e * e;
            }
            for (std::size_t i = right.first; i <= right.second; ++i)
            {
                const double t = rangeAlongRay(beams.ux[i], beams.uy[i], vx, vy, bx, by), e = beams.r[i] - t;
                c += std::isnan(t) ? invalid_cost : e * e;
            }
            return c;
        }

        //! LM on one inner vertex (x, y) between fixed neighbours a and b, its segments explaining beams `left` and
        //! `right`, kept in the wedge between left.second and right.first. Returns the two segments' final cost.
        static double refineVertex(double ax, double ay, double &x, double &y, double bx, double by, std::pair<std::size_t, std::size_t> left,
                                   std::pair<std::size_t, std::size_t> right, const BeamArrays &beams, double invalid_cost)
        {
            Wedge w;
            const bool wedged = wedgeOf(left.second, right.first, beams, w);
            auto project = [&](double &px, double &py) {
                if (!wedged) return;
                if (w.sign * (w.lx * py - w.ly * px) < 0) { const double t = std::max(0.0, px * w.lx + py * w.ly); px = t * w.lx; py = t * w.ly; }
                else if (w.sign * (px * w.uy - py * w.ux) < 0) { const double t = std::max(0.0, px * w.ux + py * w.uy); px = t * w.ux; py = t * w.uy; }
            };
            project(x, y);
            double current = pairCost(ax, ay, x, y, bx, by, left, right, beams, invalid_cost), lambda = 1e-3;
            for (int it = 0; it < 10; ++it)
            {
                double h00 = 0, h01 = 0, h11 = 0, g0 = 0, g1 = 0;
                auto add = [&](std::size_t i, double sx, double sy, double ex, double ey, bool vertexIsEnd) {
                    // segment from s to e; the vertex is e (vertexIsEnd) or s
                    const double ux = beams.ux[i], uy = beams.uy[i];
                    const double N = ex * sy - ey * sx, D = (ex - sx) * uy - (ey - sy) * ux, t = N / D;
                    if (!(std::isfinite(t) && t > 0)) return;
                    double jx, jy;
                    if (vertexIsEnd) { jx = (sy - t * uy) / D; jy = (-sx + t * ux) / D; }
                    else { jx = (-ey + t * uy) / D; jy = (ex - t * ux) / D; }
                    const double e = beams.r[i] - t;
                    h00 += jx * jx; h01 += jx * jy; h11 += jy * jy; g0 += jx * e; g1 += jy * e;
                };
                for (std::size_t i = left.first; i <= left.second; ++i) add(i, ax, ay, x, y, true);
                for (std::size_t i = right.first; i <= right.second; ++i) add(i, x, y, bx, by, false);
                double tx = x, ty = y;
                const bool improved = dampedStep(lambda, current,
                    [&](double l, double &c) {
                        const double a00 = h00 + l * std::max(h00, 1e-12), a11 = h11 + l * std::max(h11, 1e-12);
                        const double det = a00 * a11 - h01 * h01;
                        if (!(det > 0)) return false;
                        tx = x + (a11 * g0 - h01 * g1) / det; ty = y + (a00 * g1 - h01 * g0) / det;
                        project(tx, ty);
                        c = pairCost(ax, ay, tx, ty, bx, by, left, right, beams, invalid_cost);
                        return true;
                    },
                    [&] { x = tx; y = ty; });
                if (!improved) break;
            }
            return current;
        }

        //! -1 when (x, y) lies on the lower edge of the wedge between beams b and a = b + 1 (beam b turned by
        //! kWedgeMargin), +1 on the upper edge (beam a), 0 inside or when there is no wedge.
        int wedgeEdge(double x, double y, std::size_t b, std::size_t a, const BeamArrays &beams) const
        {
            Wedge w;
            if (a != b + 1 || !wedgeOf(b, a, beams, w)) return 0;
            const double norm = std::hypot(x, y);
            if (!(norm > 0)) return 0;
            const double tol = 1e-9 * norm;
            if (w.sign * (w.lx * y - w.ly * x) <= tol) return -1;
            if (w.sign * (x * w.uy - y * w.ux) <= tol) return +1;
            return 0;
        }

        struct Wedge
        {
            double lx = 0, ly = 0, ux = 0, uy = 0, sign = 0;
        };

        //! The wedge of the corner between beams b and a: false when they are not more than 2 kWedgeMargin apart.
        static bool wedgeOf(std::size_t b, std::size_t a, const BeamArrays &beams, Wedge &w)
        {
            const double bx = beams.ux[b], by = beams.uy[b], ax = beams.ux[a], ay = beams.uy[a];
            const double cross = bx * ay - by * ax, dot = bx * ax + by * ay;
            if (!(std::abs(std::atan2(cross, dot)) > 2 * kWedgeMargin)) return false;
            w.sign = cross >= 0 ? 1.0 : -1.0;
            const double th = w.sign * kWedgeMargin, c = std::cos(th), s = std::sin(th);
            w.lx = bx * c - by * s; w.ly = bx * s + by * c;
            w.ux = ax; w.uy = ay;
            return true;
        }

        double refine(std::vector<double> &vx, std::vector<double> &vy, const std::vector<std::pair<std::size_t, std::size_t>> &segs,
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

            // the wedge of every inner vertex (with setWedges), and the projection of a trial's inner vertices into them
            wedge_.assign(k + 1, Wedge{});
            if (wedges_)
                for (std::size_t v = 1; v < k; ++v)
                    if (segs[v].first == segs[v - 1].second + 1) wedgeOf(segs[v - 1].second, segs[v].first, beams, wedge_[v]);
            auto project = [&](std::vector<double> &q) {
                if (!wedges_) return;
                for (std::size_t v = 1; v < k; ++v)
                {
                    const Wedge &w = wedge_[v];
                    if (w.sign == 0) continue;
                    double &x = q[2 * v - 1], &y = q[2 * v];
                    if (w.sign * (w.lx * y - w.ly * x) < 0) { const double t = std::max(0.0, x * w.lx + y * w.ly); x = t * w.lx; y = t * w.ly; }
                    else if (w.sign * (x * w.uy - y * w.ux) < 0) { const double t = std::max(0.0, x * w.ux + y * w.uy); x = t * w.ux; y = t * w.uy; }
                }
            };
            project(p);
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
                const bool improved = dampedStep(lambda, current,
                    [&](double l, double &c) {
                        if (!solveDamped(P, l)) return false;
                        for (std::size_t i = 0; i < P; ++i) trial[i] = p[i] + step_[i];
                        project(trial);
                        c = cost(trial);
                        return true;
                    },
                    [&] { p.swap(trial); });
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
        bool wedges_ = false;
        std::vector<Wedge> wedge_;
        std::vector<double> band_, chol_, grad_, step_, p_, trial_;
    };
}
