// Refinements that follow the hit test: beams re-assigned after each LM iteration (scan_polylines/
// ReassigningRefinement.h) and vertices moved along their own beams (scan_polylines/BeamRangeRefinement.h). Their
// costs are the ray model's, they never rise, and they recover what the fixed assignment cannot.
#include "rtl/vect/scan_polylines/ReassigningRefinement.h"   // first: the header compiles on its own
#include "rtl/vect/scan_polylines/BeamRangeRefinement.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "rtl/vect/scan_polylines/RayGeometry.h"

namespace
{
    //! Beams 0.01 rad apart over 0.5..1.6 rad seeing a corner at (1, 2) of two walls: below the corner's direction
    //! the line through (1, 2) and (3, 0.5), above it the line through (1, 2) and (0, 2.2); Gaussian range noise.
    struct Corner
    {
        std::vector<double> angle, ux, uy, r;
        std::size_t n = 0;
    };

    double along(double ux, double uy, double ax, double ay, double bx, double by)
    {
        return rtl::scan_polylines::rangeAlongRay(ux, uy, ax, ay, bx, by);
    }

    Corner cornerScan(double noise, unsigned seed)
    {
        std::mt19937 rng(seed);
        std::normal_distribution<double> g(0, noise);
        Corner c;
        const double cornerAngle = std::atan2(2.0, 1.0);
        for (double a = 0.5; a < 1.6; a += 0.01)
        {
            const double ux = std::cos(a), uy = std::sin(a);
            // beams right of the corner direction see wall B, left of it wall A
            const double t = a < cornerAngle ? along(ux, uy, 1, 2, 3, 0.5) : along(ux, uy, 1, 2, 0, 2.2);
            c.angle.push_back(a); c.ux.push_back(ux); c.uy.push_back(uy); c.r.push_back(t + (noise > 0 ? g(rng) : 0.0));
        }
        c.n = c.r.size();
        return c;
    }

    //! The ray model's cost of one polyline on the beams between its end beams.
    double hitTested(const Corner &c, const std::vector<double> &vx, const std::vector<double> &vy, std::size_t first, std::size_t last)
    {
        std::vector<std::vector<std::vector<double>>> map(1);
        for (std::size_t v = 0; v < vx.size(); ++v) map[0].push_back({vx[v], vy[v]});
        const std::vector<double> rhat = rtl::scan_polylines::expectedRangesOf(c.angle, map, 1e-3);
        double sum = 0;
        for (std::size_t i = first; i <= last; ++i)
        {
            const double e = c.r[i] - rhat[i];
            sum += std::isnan(rhat[i]) ? 0.25 : e * e;
        }
        return sum;
    }
}

TEST(ScanPolylinesReassign, RecoversACornerThatTheFixedAssignmentMisses)
{
    const Corner c = cornerScan(0, 1);
    const rtl::scan_polylines::BeamArrays beams{c.ux.data(), c.uy.data(), c.r.data()};
    const std::size_t last = c.n - 1;
    std::size_t m = 0;   // the first beam past the corner's direction
    while (c.angle[m] < std::atan2(2.0, 1.0)) ++m;
    // the middle vertex starts on the measured point 8 beams past the corner, the beams assigned by it
    const std::size_t start = m + 8;
    auto initial = [&](std::vector<double> &vx, std::vector<double> &vy, rtl::detail::ReassigningRefinement::Segments &segs) {
        vx = {c.r[0] * c.ux[0], c.r[start] * c.ux[start], c.r[last] * c.ux[last]};
        vy = {c.r[0] * c.uy[0], c.r[start] * c.uy[start], c.r[last] * c.uy[last]};
        segs = {{0, start - 1}, {start, last}};
    };
    std::vector<double> vx, vy;
    rtl::detail::ReassigningRefinement::Segments segs;
    initial(vx, vy, segs);
    const double before = hitTested(c, vx, vy, 0, last);
    ASSERT_GT(before, 1e-3);

    rtl::scan_polylines::RadialRefinement fixed;
    std::vector<double> fx, fy;
    rtl::detail::ReassigningRefinement::Segments fsegs;
    initial(fx, fy, fsegs);
    fixed(fx, fy, fsegs, beams, 0.25);
    const double fixedCost = hitTested(c, fx, fy, 0, last);

    rtl::detail::ReassigningRefinement refine;
    const double cost = refine(vx, vy, segs, beams, c.angle.data(), 0.25, 50);
    EXPECT_NEAR(cost, hitTested(c, vx, vy, 0, last), 1e-12);   // its cost is the ray model's
    EXPECT_LT(cost, 1e-8);                                       // the corner found: noise-free beams explained
    EXPECT_GT(fixedCost, 100 * cost + 1e-6);                     // which the fixed assignment does not
    EXPECT_NEAR(vx[1], 1.0, 1e-4);
    EXPECT_NEAR(vy[1], 2.0, 1e-4);
    EXPECT_EQ(segs.front().first, 0u);
    EXPECT_EQ(segs.back().second, last);
    EXPECT_EQ(segs[1].first, m);
}

TEST(ScanPolylinesReassign, NeverRaisesTheCostAndKeepsTheEndsOnTheirBeams)
{
    for (unsigned seed = 0; seed < 20; ++seed)
    {
        const Corner c = cornerScan(0.02, seed);
        const rtl::scan_polylines::BeamArrays beams{c.ux.data(), c.uy.data(), c.r.data()};
        const std::size_t last = c.n - 1, a = 10 + seed, b = 60 + seed;
        std::vector<double> vx, vy;
        for (std::size_t i : {std::size_t{0}, a, b, last}) { vx.push_back(c.r[i] * c.ux[i]); vy.push_back(c.r[i] * c.uy[i]); }
        rtl::detail::ReassigningRefinement::Segments segs{{0, a - 1}, {a, b - 1}, {b, last}};
        const double before = hitTested(c, vx, vy, 0, last);
        rtl::detail::ReassigningRefinement refine;
        const double cost = refine(vx, vy, segs, beams, c.angle.data(), 0.25, 20);
        EXPECT_LE(cost, before) << "seed " << seed;
        EXPECT_NEAR(cost, hitTested(c, vx, vy, 0, last), 1e-9 * (1 + cost)) << "seed " << seed;
        // the end vertices stay on their own beams
        EXPECT_NEAR(vx.front() * c.uy[0] - vy.front() * c.ux[0], 0.0, 1e-12);
        EXPECT_NEAR(vx.back() * c.uy[last] - vy.back() * c.ux[last], 0.0, 1e-12);
    }
}

TEST(ScanPolylinesAlongBeams, FindsTheCornerRangeOnItsBeamAndNeverRaisesTheCost)
{
    // Noise-free corner, the middle vertex on the corner's nearest beam but at the wrong range: moving it along that
    // beam alone explains the two walls up to the one-beam wedge around the corner (its cost falls by > 100x), and
    // the cost returned is the hit test's. With noise: never above the start, the hit test's cost, and the vertex
    // directions (so the beams each segment explains) unchanged.
    const Corner c = cornerScan(0, 1);
    const rtl::scan_polylines::BeamArrays beams{c.ux.data(), c.uy.data(), c.r.data()};
    const std::size_t last = c.n - 1;
    std::size_t m = 0;
    while (c.angle[m] < std::atan2(2.0, 1.0)) ++m;
    std::vector<std::size_t> vb{0, m, last};
    std::vector<double> rho{c.r[0], c.r[m] + 0.3, c.r[last]};
    auto points = [&](const std::vector<double> &q, std::vector<double> &vx, std::vector<double> &vy) {
        vx.clear(); vy.clear();
        for (std::size_t j = 0; j < q.size(); ++j) { vx.push_back(q[j] * c.ux[vb[j]]); vy.push_back(q[j] * c.uy[vb[j]]); }
    };
    std::vector<double> vx, vy;
    points(rho, vx, vy);
    const double before = hitTested(c, vx, vy, 0, last);
    rtl::detail::BeamRangeRefinement refine;
    const double cost = refine(rho, vb, beams, 0.25);
    points(rho, vx, vy);
    EXPECT_NEAR(cost, hitTested(c, vx, vy, 0, last), 1e-12);
    EXPECT_LT(cost, before / 100);
    EXPECT_NEAR(rho[1], c.r[m], 0.05);   // the corner beam's own range, within the wedge's compromise

    for (unsigned seed = 0; seed < 20; ++seed)
    {
        const Corner n = cornerScan(0.02, seed);
        const rtl::scan_polylines::BeamArrays nb{n.ux.data(), n.uy.data(), n.r.data()};
        const std::size_t nl = n.n - 1;
        std::vector<std::size_t> idx{0, 10 + seed, 60 + seed, nl};
        std::vector<double> q;
        for (std::size_t i : idx) q.push_back(n.r[i]);
        auto hit = [&](const std::vector<double> &qq) {
            std::vector<double> x, y;
            for (std::size_t j = 0; j < qq.size(); ++j) { x.push_back(qq[j] * n.ux[idx[j]]); y.push_back(qq[j] * n.uy[idx[j]]); }
            return hitTested(n, x, y, 0, nl);
        };
        const double start = hit(q);
        const double got = refine(q, idx, nb, 0.25);
        EXPECT_LE(got, start) << "seed " << seed;
        EXPECT_NEAR(got, hit(q), 1e-9 * (1 + got)) << "seed " << seed;
        for (double v : q) EXPECT_GT(v, 0.0);
    }
}
