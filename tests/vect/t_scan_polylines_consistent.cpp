// Hit-consistent radial refinement (scan_polylines/RadialRefinement.h: setWedges, refineConsistent): the refined cost
// is the cost the hit test scores, and boundary shifts find the corner that a fixed assignment cannot reach.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <utility>
#include <vector>

#include "rtl/vect/scan_polylines/RadialRefinement.h"
#include "rtl/vect/scan_polylines/RayGeometry.h"

namespace
{
    using rtl::scan_polylines::BeamArrays;
    using rtl::scan_polylines::RadialRefinement;
    typedef std::vector<std::pair<std::size_t, std::size_t>> Segs;

    //! A scan of n beams at `step` radians from `start`, measuring walls: beams < corner see the line x = 4, the others
    //! the line y = 3 + 0.2 x (a corner near beam `corner`), with Gaussian radial noise.
    struct CornerScan
    {
        std::vector<double> angle, ux, uy, r;

        CornerScan(std::size_t n, double start, double step, double sigma, unsigned seed)
        {
            std::mt19937 rng(seed);
            std::normal_distribution<double> noise(0, sigma);
            for (std::size_t i = 0; i < n; ++i)
            {
                const double a = start + step * static_cast<double>(i);
                const double cx = std::cos(a), cy = std::sin(a);
                const double t1 = 4 / cx;                       // x = 4
                const double t2 = 3 / (cy - 0.2 * cx);          // y = 3 + 0.2 x
                const double t = (t1 > 0 && (t1 < t2 || !(t2 > 0))) ? t1 : t2;
                angle.push_back(a); ux.push_back(cx); uy.push_back(cy); r.push_back(t + noise(rng));
            }
        }
        BeamArrays arrays() const { return {ux.data(), uy.data(), r.data()}; }
        double px(std::size_t i) const { return r[i] * ux[i]; }
        double py(std::size_t i) const { return r[i] * uy[i]; }
    };

    //! Sum of squared radial errors of beams first..last under the polyline (vx, vy) by PLE's hit test (spans widened
    //! by 1e-3 rad, the later segment counts); beams no segment hits count `invalid` each.
    double hitTestedCost(const CornerScan &s, const std::vector<double> &vx, const std::vector<double> &vy, std::size_t first,
                         std::size_t last, double invalid)
    {
        std::vector<std::vector<std::vector<double>>> map(1);
        for (std::size_t v = 0; v < vx.size(); ++v) map[0].push_back({vx[v], vy[v]});
        const std::vector<double> rhat = rtl::scan_polylines::expectedRangesOf(s.angle, map, 1e-3);
        double sum = 0;
        for (std::size_t i = first; i <= last; ++i)
        {
            const double e = s.r[i] - rhat[i];
            sum += std::isnan(rhat[i]) ? invalid : e * e;
        }
        return sum;
    }

    //! The corner scan's true corner beam: the first beam that sees the second wall.
    std::size_t trueCorner(const CornerScan &s)
    {
        for (std::size_t i = 0; i < s.r.size(); ++i)
            if (std::abs(s.r[i] * s.ux[i] - 4) > 0.2) return i;
        return s.r.size();
    }
}

TEST(ScanPolylinesConsistentRefinement, ShiftsTheBoundaryToTheCornerAndScoresAsTheHitTest)
{
    // 1 degree beams from 0 to 80 degrees; the polyline starts with its corner vertex on a measured point 6 beams
    // before the true corner, so the first segment is assigned 6 beams of the other wall.
    const CornerScan s(81, 0.0, 3.14159265358979 / 180, 0.01, 7);
    const std::size_t corner = trueCorner(s);
    ASSERT_GT(corner, 20u);
    ASSERT_LT(corner, 70u);
    const std::size_t start = corner - 6;
    std::vector<double> vx = {s.px(0), s.px(start), s.px(80)}, vy = {s.py(0), s.py(start), s.py(80)};
    Segs segs = {{0, start - 1}, {start, 80}};
    const double before = hitTestedCost(s, vx, vy, 0, 80, 0.25);

    std::vector<double> fx = vx, fy = vy;
    RadialRefinement fixed;
    fixed(fx, fy, segs, s.arrays(), 0.25);
    const double fixedHit = hitTestedCost(s, fx, fy, 0, 80, 0.25);

    RadialRefinement lm;
    const double cost = lm.refineConsistent(vx, vy, segs, s.arrays(), 0.25, 20);
    const double hit = hitTestedCost(s, vx, vy, 0, 80, 0.25);
    EXPECT_NEAR(cost, hit, 1e-9 * hit);                     // the refined cost is the scored one
    EXPECT_LT(hit, before);
    EXPECT_LT(hit, 0.5 * fixedHit);                          // the fixed assignment stays stuck on the wrong wall
    EXPECT_LE(std::abs(static_cast<long>(segs[1].first) - static_cast<long>(corner)), 1);
    EXPECT_LT(hit, 81 * 4 * 0.01 * 0.01);                    // within a few noise levels per beam
    EXPECT_EQ(segs.front().first, 0u);                       // the end beams stay
    EXPECT_EQ(segs.back().second, 80u);
    EXPECT_EQ(segs[0].second + 1, segs[1].first);
}

TEST(ScanPolylinesConsistentRefinement, WedgesKeepEveryRefinedCostEqualToItsHitTest)
{
    // Random polylines through measured points of noisy corner scans, both beam orders (increasing and decreasing
    // angles), 0.5 and 1 degree beams: with wedges the refined cost equals the hit-tested cost every time, and is no
    // higher than the start's (whose vertices lie on measured points, i.e. inside their wedges).
    std::mt19937 rng(11);
    int runs = 0, lowered = 0;
    for (unsigned seed = 0; seed < 40; ++seed)
    {
        const bool half = seed % 2 == 0, down = seed % 4 >= 2;
        const double step = (half ? 0.5 : 1.0) * 3.14159265358979 / 180 * (down ? -1 : 1);
        const std::size_t n = half ? 161 : 81;
        const CornerScan s(n, down ? 80 * 3.14159265358979 / 180 : 0.0, step, 0.02, seed);
        std::vector<std::size_t> idx = {0, n - 1};
        std::uniform_int_distribution<std::size_t> pick(2, n - 3);
        for (int v = 0; v < 3; ++v) idx.push_back(pick(rng));
        std::sort(idx.begin(), idx.end());
        idx.erase(std::unique(idx.begin(), idx.end()), idx.end());
        std::vector<double> vx, vy;
        Segs segs;
        for (std::size_t v = 0; v < idx.size(); ++v)
        {
            vx.push_back(s.px(idx[v])); vy.push_back(s.py(idx[v]));
            if (v + 1 < idx.size()) segs.push_back({idx[v], idx[v + 1] - (v + 2 < idx.size() ? 1 : 0)});
        }
        const double start = hitTestedCost(s, vx, vy, 0, n - 1, 0.25);
        for (int mode = 0; mode < 2; ++mode)
        {
            std::vector<double> x = vx, y = vy;
            Segs sg = segs;
            RadialRefinement lm;
            double cost;
            if (mode == 0) { lm.setWedges(true); cost = lm(x, y, sg, s.arrays(), 0.25); }
            else cost = lm.refineConsistent(x, y, sg, s.arrays(), 0.25, 5);
            const double hit = hitTestedCost(s, x, y, 0, n - 1, 0.25);
            EXPECT_NEAR(cost, hit, 1e-9 * hit + 1e-15) << "seed " << seed << " mode " << mode;
            EXPECT_LE(hit, start * (1 + 1e-12)) << "seed " << seed << " mode " << mode;
            ++runs;
            if (hit < 0.9 * start) ++lowered;
        }
    }
    EXPECT_EQ(runs, 80);
    EXPECT_GT(lowered, 60);   // the refinement does work: most starts through noisy points improve by > 10 %
}
