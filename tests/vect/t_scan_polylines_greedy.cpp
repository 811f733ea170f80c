// Greedy vertex removal by the radial error (scan_polylines/GreedyPolylines.h) against brute force on small chains,
// and the extractor's greedy candidate family (ScanPolylines2D::setGreedyCandidates) on the real scan excerpts.
#include "rtl/vect/scan_polylines/GreedyPolylines.h"   // first: the header compiles on its own

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <utility>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "rtl/Core.h"
#include "rtl/io/CarmenLog.h"
#include "rtl/vect/ScanPolylines2D.h"
#include "rtl/vect/scan_polylines/RayGeometry.h"
#include "scan_polylines_checks.h"

namespace
{
    using scan_polylines_checks::excerptScans;
    using scan_polylines_checks::expectScoreNeverRisesWithBudget;

    struct Chain
    {
        std::vector<double> x, y;
    };

    //! n beams 0.02 rad apart seeing two or three noisy walls (a depth step or a corner between them).
    Chain randomChain(std::mt19937 &rng, std::size_t n)
    {
        std::uniform_real_distribution<double> uni(0, 1);
        std::normal_distribution<double> noise(0, 0.02);
        const std::size_t walls = 2 + rng() % 2;
        std::vector<double> d(walls), phi(walls);
        for (std::size_t w = 0; w < walls; ++w) { d[w] = 1 + 3 * uni(rng); phi[w] = -0.4 + 0.8 * uni(rng); }
        Chain c;
        const double a0 = -0.3 + 0.6 * uni(rng);
        for (std::size_t i = 0; i < n; ++i)
        {
            const double a = a0 + 0.02 * static_cast<double>(i);
            const std::size_t w = std::min(walls - 1, i * walls / n);
            const double r = d[w] / std::cos(a - phi[w]) + noise(rng);
            c.x.push_back(r * std::cos(a)); c.y.push_back(r * std::sin(a));
        }
        return c;
    }

    //! The ray model's cost of a chain under one polyline through the chain points `vertices` (none: all beams
    //! unexplained): squared radial error of each hit beam, c2 for the others.
    double hitTestedCost(const Chain &c, const std::vector<std::size_t> &vertices, double c2)
    {
        std::vector<double> angles;
        for (std::size_t i = 0; i < c.x.size(); ++i) angles.push_back(std::atan2(c.y[i], c.x[i]));
        std::vector<std::vector<rtl::Vector2d>> map(1);
        for (std::size_t v : vertices) map[0].emplace_back(c.x[v], c.y[v]);
        if (vertices.size() < 2) map.clear();
        const std::vector<double> rhat = rtl::scan_polylines::expectedRangesOf(angles, map, 1e-3);
        double sum = 0;
        for (std::size_t i = 0; i < c.x.size(); ++i)
        {
            const double e = std::hypot(c.x[i], c.y[i]) - rhat[i];
            sum += std::isnan(rhat[i]) ? c2 : e * e;
        }
        return sum;
    }

    //! The polyline after removing vertices[at] by the greedy's rules (two vertices: none left).
    std::vector<std::size_t> without(const std::vector<std::size_t> &vertices, std::size_t at)
    {
        if (vertices.size() <= 2) return {};
        std::vector<std::size_t> out = vertices;
        out.erase(out.begin() + static_cast<long>(at));
        return out;
    }

    //! Every polyline's end vertices lie on their own beams (the first and last beam of its segments).
    void expectEndsOnOwnBeams(const rtl::ScanPolylines2D<double> &ex, const std::vector<rtl::VectorND<2, double>> &beams)
    {
        std::size_t s = 0;
        for (const auto &poly : ex.polylines())
        {
            const std::size_t k = poly.size() - 1;
            ASSERT_LE(s + k, ex.segments().size());
            for (const auto &[v, beam] : {std::pair{poly.front(), ex.segments()[s].beams.first},
                                          std::pair{poly.back(), ex.segments()[s + k - 1].beams.second}})
            {
                const double bx = beams[beam][0], by = beams[beam][1];
                EXPECT_NEAR((v[0] * by - v[1] * bx) / (std::hypot(v[0], v[1]) * std::hypot(bx, by)), 0.0, 1e-9);
                EXPECT_GT(v[0] * bx + v[1] * by, 0.0);
            }
            s += k;
        }
        EXPECT_EQ(s, ex.segments().size());
    }
}

TEST(ScanPolylinesGreedy, EveryStepRemovesTheVertexThatRaisesTheHitTestedCostLeast)
{
    std::mt19937 rng(7);
    const double c2 = 0.25;
    rtl::detail::GreedyPolylines greedy;
    std::vector<std::size_t> vertices;
    for (int trial = 0; trial < 40; ++trial)
    {
        const std::size_t n = 2 + static_cast<std::size_t>(trial % 11);
        const Chain c = randomChain(rng, n);
        greedy.run(c.x.data(), c.y.data(), n, c2);
        ASSERT_EQ(greedy.states(), greedy.removals().size() + 1);
        ASSERT_EQ(greedy.vertexCount(0), n);
        ASSERT_EQ(greedy.vertexCount(greedy.states() - 1), 0u);
        for (std::size_t s = 0; s < greedy.states(); ++s)
        {
            greedy.vertices(s, vertices);
            ASSERT_EQ(vertices.size(), greedy.vertexCount(s)) << "trial " << trial << " state " << s;
            // the costs are the exact hit-tested costs of the polylines returned
            EXPECT_NEAR(greedy.cost(s), hitTestedCost(c, vertices, c2), 1e-9) << "trial " << trial << " state " << s;
            if (s + 1 == greedy.states()) break;
            // one vertex per step, two (the whole polyline) for the last
            const auto &r = greedy.removals()[s];
            EXPECT_EQ(r.removed, vertices.size() == 2 ? 2u : 1u);
            EXPECT_EQ(greedy.vertexCount(s + 1), vertices.size() - r.removed);
            // brute force: the least rise over every vertex of the state, and the state it leads to
            double least = std::numeric_limits<double>::infinity();
            std::size_t at = 0;
            const double now = hitTestedCost(c, vertices, c2);
            for (std::size_t v = 0; v < vertices.size(); ++v)
            {
                const double rise = hitTestedCost(c, without(vertices, v), c2) - now;
                if (rise < least - 1e-12) { least = rise; at = v; }
            }
            EXPECT_NEAR(r.delta, least, 1e-9) << "trial " << trial << " state " << s;
            std::vector<std::size_t> next;
            greedy.vertices(s + 1, next);
            EXPECT_EQ(next, without(vertices, at)) << "trial " << trial << " state " << s;
        }
    }
}

TEST(ScanPolylinesGreedy, ChainsOfFewerThanTwoPointsHaveNoPolyline)
{
    rtl::detail::GreedyPolylines greedy;
    const double x[2] = {1.0, 1.0}, y[2] = {0.0, 0.02};
    std::vector<std::size_t> v{9};
    greedy.run(x, y, 1, 0.25);
    EXPECT_EQ(greedy.states(), 1u);
    EXPECT_EQ(greedy.vertexCount(0), 0u);
    EXPECT_DOUBLE_EQ(greedy.cost(0), 0.25);
    greedy.vertices(0, v);
    EXPECT_TRUE(v.empty());
    greedy.run(x, y, 0, 0.25);
    EXPECT_EQ(greedy.states(), 1u);
    EXPECT_DOUBLE_EQ(greedy.cost(0), 0.0);
    // two points: one polyline of one segment, then nothing (both beams unexplained)
    greedy.run(x, y, 2, 0.25);
    ASSERT_EQ(greedy.states(), 2u);
    EXPECT_NEAR(greedy.cost(0), 0.0, 1e-15);
    EXPECT_EQ(greedy.removals()[0].removed, 2u);
    EXPECT_NEAR(greedy.cost(1), 0.5, 1e-15);
}

TEST(ScanPolylinesGreedy, CostsMatchTheHitTestOnRealChains)
{
    // Every chain of the intel excerpt's first 5 scans (chains split at missing returns and at gaps over 1 m), every
    // state with at most 30 vertices: the greedy's cost is the ray model's cost of the polyline it returns.
    rtl::detail::GreedyPolylines greedy;
    std::vector<std::size_t> vertices;
    const auto scans = excerptScans("intel.log");
    std::size_t checked = 0;
    for (std::size_t q = 0; q < 5; ++q)
    {
        const auto &scan = scans[q];
        std::size_t i = 0;
        while (i < scan.size())
        {
            if (!std::isfinite(scan[i][0])) { ++i; continue; }
            Chain c;
            std::size_t j = i;
            for (; j < scan.size() && std::isfinite(scan[j][0]); ++j)
            {
                if (j > i && std::hypot(scan[j][0] - scan[j - 1][0], scan[j][1] - scan[j - 1][1]) > 1.0) break;
                c.x.push_back(scan[j][0]); c.y.push_back(scan[j][1]);
            }
            i = j;
            greedy.run(c.x.data(), c.y.data(), c.x.size(), 0.25);
            for (std::size_t s = 0; s < greedy.states(); ++s)
                if (greedy.vertexCount(s) <= 30)
                {
                    greedy.vertices(s, vertices);
                    const double expected = hitTestedCost(c, vertices, 0.25);
                    ASSERT_NEAR(greedy.cost(s), expected, 1e-9 * (1 + expected)) << "scan " << q << " state " << s;
                    ++checked;
                }
        }
    }
    EXPECT_GT(checked, 100u);
}

TEST(ScanPolylinesGreedy, GreedyCandidatesKeepTheBudgetAndLowerTheScore)
{
    // The family only adds candidates, so the knapsack's unrefined optimum can only fall; the refined result can
    // still rise on a scan: the plans are chosen on unrefined costs, and a greedy candidate that beats a partition
    // before refinement may gain less from it (its vertices already sit on measured points), so the partition's plan
    // is no longer among those refined. Measured here: 13 of 240 runs above the plain extractor (109 below), by at
    // most 4.9 % (intel scan 26, J = 10). Asserted: the budget and the end vertices hold, such rises stay rare and
    // small, and the mean score falls (here by 4.4 %; on the full benchmark by 0.7-11 %). Both with the free-vertex
    // LM of 1 iteration and the earlier defaults otherwise (2 break candidates, no partition cap or re-allocation).
    rtl::ScanPolylines2D<double> with, without;
    for (auto *ex : {&with, &without})
    {
        ex->setBreakCandidates(2);
        ex->setPartitionSegments(0);
        ex->setRefinedReallocation(false);
    }
    with.setGreedyCandidates(true, 1, rtl::ScanPolylines2D<double>::GreedyRefinement::FreeVertices);
    without.setGreedyCandidates(false);
    double s_with = 0, s_without = 0, worst = 0;
    std::size_t lower = 0, higher = 0, runs = 0;
    for (const char *file : {"intel.log", "csail.log"})
    {
        const auto scans = excerptScans(file);
        for (std::size_t q = 0; q < scans.size(); ++q)
            for (std::size_t J : {10u, 20u, 30u, 50u})
            {
                with.setMaxVertices(J); without.setMaxVertices(J);
                ASSERT_TRUE(with(scans[q]));
                ASSERT_TRUE(without(scans[q]));
                EXPECT_LE(with.vertexCount(), J);
                expectEndsOnOwnBeams(with, scans[q]);
                const double ratio = with.score() / without.score();
                lower += ratio < 1 - 1e-6 ? 1 : 0;
                higher += ratio > 1 + 1e-6 ? 1 : 0;
                worst = std::max(worst, ratio);
                s_with += with.score(); s_without += without.score();
                ++runs;
            }
    }
    std::printf("greedy family on the excerpts: %zu of %zu runs lower, %zu higher (worst x%.4f), mean score x%.4f\n", lower,
                runs, higher, worst, s_with / s_without);
    EXPECT_EQ(runs, 240u);
    EXPECT_LT(s_with, 0.97 * s_without);
    EXPECT_GT(lower, 4 * higher);
    EXPECT_LT(higher, runs / 10);
    EXPECT_LT(worst, 1.06);
}

TEST(ScanPolylinesGreedy, DefaultScoresLowerThanTheEarlierDefaultOnTheExcerpts)
{
    // The default (greedy family refined along the beams then freely, no break candidates, partitions of at most 10
    // ranges, refined reallocation) against the earlier default (no greedy family, 2 break candidates, no cap, no
    // re-allocation) on the 60 excerpt scans at J = 10, 30, 50: the budget and the end vertices hold and the mean
    // score falls (on the full benchmark by 2.5-14.3 %).
    rtl::ScanPolylines2D<double> proposed, standard;
    standard.setGreedyCandidates(false);
    standard.setBreakCandidates(2);
    standard.setPartitionSegments(0);
    standard.setRefinedReallocation(false);
    double s_proposed = 0, s_standard = 0, worst = 0;
    std::size_t lower = 0, higher = 0;
    for (const char *file : {"intel.log", "csail.log"})
        for (const auto &scan : excerptScans(file))
            for (std::size_t J : {10u, 30u, 50u})
            {
                proposed.setMaxVertices(J); standard.setMaxVertices(J);
                ASSERT_TRUE(proposed(scan));
                ASSERT_TRUE(standard(scan));
                EXPECT_LE(proposed.vertexCount(), J);
                expectEndsOnOwnBeams(proposed, scan);
                lower += proposed.score() < standard.score() * (1 - 1e-6) ? 1 : 0;
                higher += proposed.score() > standard.score() * (1 + 1e-6) ? 1 : 0;
                worst = std::max(worst, proposed.score() / standard.score());
                s_proposed += proposed.score(); s_standard += standard.score();
            }
    std::printf("default against the earlier default on the excerpts: %zu of 180 runs lower, %zu higher (worst x%.4f), mean score x%.4f\n", lower,
                higher, worst, s_proposed / s_standard);
    EXPECT_LT(s_proposed, 0.97 * s_standard);
    EXPECT_GT(lower, 3 * higher);
}

TEST(ScanPolylinesGreedy, EveryRefinementSurvivesRepeatedPointsAndHoles)
{
    // Runs of points that coincide in float (60 beams 1e-9 rad apart at one range: zero-length segments, beams closer
    // than the hit test's widening), single returns between holes, a float instantiation, every refinement of the
    // family: every budget is kept and the score stays finite and below the all-unexplained cost.
    constexpr double kPi = 3.14159265358979323846;
    std::vector<rtl::Vector2f> scan;
    for (int d = 0; d < 180; ++d)
    {
        const double a = d < 60 ? 0.5 + d * 1e-9 : d < 120 ? 1.0 + (d - 60) * 1e-9 : 1.2 + (d - 120) * kPi / 180;
        const double r = d % 37 == 5 ? std::nan("") : d < 120 ? 2.0 : 2.0 + 0.3 * std::sin(0.2 * d);
        scan.emplace_back(static_cast<float>(r * std::cos(a)), static_cast<float>(r * std::sin(a)));
    }
    ASSERT_EQ(scan[10][0], scan[11][0]);   // the runs really coincide
    using R = rtl::ScanPolylines2D<float>::GreedyRefinement;
    for (R mode : {R::FreeVertices, R::Reassigning, R::AlongBeams, R::AlongBeamsThenFree})
    {
        rtl::ScanPolylines2D<float> ex;
        ex.setGreedyCandidates(true, 20, mode);
        ex.setBreakCandidates(0);
        ex.setPartitionSegments(10);
        ex.setRefinedReallocation(true);
        for (std::size_t J : {2u, 3u, 5u, 10u, 50u})
        {
            ex.setMaxVertices(J);
            ASSERT_TRUE(ex(scan));
            EXPECT_LE(ex.vertexCount(), J);
            EXPECT_TRUE(std::isfinite(ex.score())) << static_cast<int>(mode) << " J " << J;
            EXPECT_GE(ex.score(), 0.0);
            EXPECT_LE(ex.score(), 0.25);   // never worse than leaving every beam unexplained
        }
    }
}

TEST(ScanPolylinesGreedy, ALargerBudgetNeverGivesAWorseMapWithGreedyCandidates)
{
    // As ScanPolylines2D.ALargerBudgetNeverGivesAWorseMap, with the greedy family on: it is built in full before the
    // only allocation, so every budget's plans stay comparable. In the default setting (no break candidates, TLS
    // partitions of at most 10 ranges, greedy candidates refined along their beams, then freely, and a second walk over
    // the plans allocated on the refined costs) and with the earlier default otherwise (greedy candidates refined by
    // 1 free-vertex LM iteration, 2 break candidates, no cap, one walk).
    for (int setting = 0; setting < 2; ++setting)
    {
        rtl::ScanPolylines2D<double> ex;
        if (setting == 0)
        {
            ex.setGreedyCandidates(true, 1, rtl::ScanPolylines2D<double>::GreedyRefinement::FreeVertices);
            ex.setBreakCandidates(2);
            ex.setPartitionSegments(0);
            ex.setRefinedReallocation(false);
        }
        for (const char *file : {"intel.log", "csail.log"})
        {
            const auto scans = excerptScans(file);
            for (std::size_t s = 0; s < scans.size(); ++s)
                ASSERT_NO_FATAL_FAILURE(expectScoreNeverRisesWithBudget(ex, scans[s], 60, "setting " + std::to_string(setting) + " " + file + " scan " + std::to_string(s)));
        }
    }
}
