// ScanPolylines2D: the budget, end vertices on their own beams, expected ranges in a hand-computed scene, refinement,
// bad input, float and double, and the score on a real scan excerpt (tests/data).
#include "rtl/vect/ScanPolylines2D.h"   // first: the header compiles on its own

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include "rtl/Core.h"
#include "rtl/io/CarmenLog.h"
#include "rtl/vect/scan_polylines/RayGeometry.h"
#include "scan_polylines_checks.h"

namespace
{
    using scan_polylines_checks::excerptScans;
    using scan_polylines_checks::expectScoreNeverRisesWithBudget;

    constexpr double kPi = 3.14159265358979323846;

    //! Range from the origin along angle a to the walls x = 2, y = 1.5, x = -1.2, y = -1 of a room around the sensor.
    double roomRange(double a)
    {
        const double c = std::cos(a), s = std::sin(a);
        double t = std::numeric_limits<double>::infinity();
        if (c > 0) t = std::min(t, 2.0 / c);
        if (s > 0) t = std::min(t, 1.5 / s);
        if (c < 0) t = std::min(t, -1.2 / c);
        if (s < 0) t = std::min(t, -1.0 / s);
        return t;
    }

    //! The room seen over -135..135 degrees in 1-degree steps (271 beams).
    template<typename T>
    std::vector<rtl::VectorND<2, T>> roomScan(std::vector<double> *angles = nullptr, std::vector<double> *ranges = nullptr)
    {
        std::vector<rtl::VectorND<2, T>> pts;
        for (int d = -135; d <= 135; ++d)
        {
            const double a = d * kPi / 180, r = roomRange(a);
            pts.emplace_back(static_cast<T>(r * std::cos(a)), static_cast<T>(r * std::sin(a)));
            if (angles) angles->push_back(a);
            if (ranges) ranges->push_back(r);
        }
        return pts;
    }

    template<typename T>
    void expectEndsOnOwnBeams(const rtl::ScanPolylines2D<T> &ex, const std::vector<rtl::VectorND<2, T>> &beams, double tol)
    {
        const auto &polys = ex.polylines();
        const auto &segs = ex.segments();
        std::size_t s = 0;
        for (std::size_t p = 0; p < polys.size(); ++p)
        {
            const std::size_t k = polys[p].size() - 1;
            ASSERT_LE(s + k, segs.size());
            const auto check = [&](const rtl::VectorND<2, T> &v, std::size_t beam) {
                const double bx = static_cast<double>(beams[beam][0]), by = static_cast<double>(beams[beam][1]);
                const double vx = static_cast<double>(v[0]), vy = static_cast<double>(v[1]);
                const double norm = std::hypot(vx, vy) * std::hypot(bx, by);
                EXPECT_NEAR((vx * by - vy * bx) / norm, 0.0, tol) << "polyline " << p << " beam " << beam;   // same line
                EXPECT_GT(vx * bx + vy * by, 0.0);                                                        // same ray
            };
            check(polys[p].front(), segs[s].beams.first);
            check(polys[p].back(), segs[s + k - 1].beams.second);
            for (std::size_t j = 0; j < k; ++j) EXPECT_EQ(segs[s + j].polyline, p);
            s += k;
        }
        EXPECT_EQ(s, segs.size());
    }
}

TEST(ScanPolylines2D, SquareRoomExpectedRangesAreTheTrueRanges)
{
    std::vector<double> angles, ranges;
    const auto beams = roomScan<double>(&angles, &ranges);
    rtl::ScanPolylines2D<double> ex;
    ex.setMaxVertices(10);
    ASSERT_TRUE(ex(beams));
    ASSERT_EQ(ex.expectedRanges().size(), beams.size());
    for (std::size_t i = 0; i < beams.size(); ++i) EXPECT_NEAR(ex.expectedRanges()[i], ranges[i], 1e-9) << "beam " << i;
    EXPECT_EQ(ex.explainedBeams(), beams.size());
    EXPECT_NEAR(ex.rmse(), 0.0, 1e-9);
    EXPECT_NEAR(ex.score(), 0.0, 1e-18);
    // the four visible walls need 5 vertices: the extractor finds the room's three corners among them
    ASSERT_LE(ex.vertexCount(), 10u);
    for (const auto &corner : {std::pair<double, double>{2, -1}, {2, 1.5}, {-1.2, 1.5}})
    {
        double nearest = 1e9;
        for (const auto &p : ex.polylines())
            for (const auto &v : p) nearest = std::min(nearest, std::hypot(v[0] - corner.first, v[1] - corner.second));
        EXPECT_LT(nearest, 1e-9) << corner.first << ", " << corner.second;
    }
    // segment lines in Hesse form through their vertices; walls at r = 2, 1.5, 1.2, 1
    for (const auto &seg : ex.segments())
    {
        EXPECT_GE(seg.r, 0.0);
        const bool wall = std::abs(seg.r - 2) < 1e-9 || std::abs(seg.r - 1.5) < 1e-9 || std::abs(seg.r - 1.2) < 1e-9 || std::abs(seg.r - 1) < 1e-9;
        EXPECT_TRUE(wall) << seg.r;
        EXPECT_GT(seg.covariance(0, 0), 0.0);
        EXPECT_GT(seg.covariance.determinant(), 0.0);
    }
    expectEndsOnOwnBeams(ex, beams, 1e-12);
}

TEST(ScanPolylines2D, FloatAndDoubleAgreeOnTheRoom)
{
    std::vector<double> angles, ranges;
    const auto beams = roomScan<float>(&angles, &ranges);
    rtl::ScanPolylines2D<float> ex;
    ex.setMaxVertices(10);
    ASSERT_TRUE(ex(beams));
    for (std::size_t i = 0; i < beams.size(); ++i) EXPECT_NEAR(ex.expectedRanges()[i], ranges[i], 2e-5) << "beam " << i;
    expectEndsOnOwnBeams(ex, beams, 1e-6);
}

TEST(ScanPolylines2D, BudgetIsRespectedAndUsedOnRealScans)
{
    const auto scans = excerptScans("intel.log");
    ASSERT_EQ(scans.size(), 30u);
    rtl::ScanPolylines2D<double> ex;
    for (std::size_t J : {2u, 3u, 7u, 20u, 50u})
    {
        ex.setMaxVertices(J);
        for (const auto &scan : scans)
        {
            ASSERT_TRUE(ex(scan));
            std::size_t v = 0;
            for (const auto &p : ex.polylines()) { EXPECT_GE(p.size(), 2u); v += p.size(); }
            EXPECT_EQ(v, ex.vertexCount());
            EXPECT_LE(v, J);
            expectEndsOnOwnBeams(ex, scan, 1e-9);
        }
    }
}

TEST(ScanPolylines2D, MoreVerticesNeverScoreWorseOnAverage)
{
    const auto scans = excerptScans("csail.log");
    rtl::ScanPolylines2D<double> ex;
    double last = std::numeric_limits<double>::infinity();
    for (std::size_t J : {4u, 10u, 20u, 40u})
    {
        ex.setMaxVertices(J);
        double mean = 0;
        for (const auto &scan : scans) { ASSERT_TRUE(ex(scan)); mean += ex.score(); }
        mean /= static_cast<double>(scans.size());
        EXPECT_LT(mean, last) << "J " << J;
        last = mean;
    }
}

TEST(ScanPolylines2D, ALargerBudgetNeverGivesAWorseMap)
{
    // With setRefineEveryBudget (the default): the plan of every J' <= J lies within J, so score(J) may not exceed
    // score(J') for any J' < J. Refining only J's own plan (setRefineEveryBudget(false)) breaks this (refinement gains differ between plans: 149
    // rises over the smaller budgets' best on these 60 scans at J = 2..60, up to +26 %). Chains interact only through
    // beams at their borders, which the per-chain costs leave out; no rise was measured here, so the tolerance only
    // absorbs rounding (sums of a few hundred terms).
    rtl::ScanPolylines2D<double> ex, own;
    own.setRefineEveryBudget(false);
    std::size_t lower = 0, runs = 0;
    for (const char *file : {"intel.log", "csail.log"})
    {
        const auto scans = excerptScans(file);
        for (std::size_t s = 0; s < scans.size(); ++s)
        {
            const std::string where = std::string(file) + " scan " + std::to_string(s);
            ASSERT_NO_FATAL_FAILURE(expectScoreNeverRisesWithBudget(ex, scans[s], 60, where, [&](std::size_t J) {
                if (J % 10 != 0) return;
                // never worse than J's own plan refined (it is among the plans; the fallback too)
                own.setMaxVertices(J);
                ASSERT_TRUE(own(scans[s])) << where << " J " << J;
                EXPECT_LE(ex.score(), own.score() * (1 + 1e-9)) << where << " J " << J;
                lower += ex.score() < own.score() * (1 - 1e-9) ? 1 : 0;
                ++runs;
            }));
        }
    }
    EXPECT_GT(lower, 0u) << runs << " runs";   // and it matters somewhere
}

TEST(ScanPolylines2D, EveryBudgetRefinementWithRepartitionAndPointCandidates)
{
    // The option re-partitions each refined candidate first when radial re-partition is on (monotone too: every
    // candidate is treated the same whatever J), and with point candidates it keeps the budget and scores no worse
    // on average than refining J's own plan.
    const auto scans = excerptScans("intel.log");
    rtl::ScanPolylines2D<double> radial;
    radial.setRadialRepartition(2);
    radial.setRefineEveryBudget(true);
    for (std::size_t s = 0; s < scans.size(); s += 3)
        ASSERT_NO_FATAL_FAILURE(expectScoreNeverRisesWithBudget(radial, scans[s], 30, "intel.log scan " + std::to_string(s)));
    rtl::ScanPolylines2D<double> every, own;
    every.setPointCandidates(true);
    own.setPointCandidates(true);
    own.setRefineEveryBudget(false);
    double mean_every = 0, mean_own = 0;
    for (std::size_t J : {10u, 30u})
    {
        every.setMaxVertices(J); own.setMaxVertices(J);
        for (const auto &scan : scans)
        {
            ASSERT_TRUE(every(scan)); ASSERT_TRUE(own(scan));
            EXPECT_LE(every.vertexCount(), J);
            mean_every += every.score(); mean_own += own.score();
        }
    }
    EXPECT_LE(mean_every, mean_own);
}

TEST(ScanPolylines2D, CsailScan16KeepsItsNineVertexMapAtTen)
{
    // csail excerpt scan 16: refined, J = 9's plan scores 0.0815 (f 0.776) and J = 10's own plan 0.1001 (f 0.630);
    // unrefined they are monotone (0.1053 -> 0.1009). At J = 10 the extractor must return a map at least as good as J = 9's.
    // Pinned with the candidate families of the time (no greedy family, 2 break candidates, no partition cap, one walk).
    const auto scans = excerptScans("csail.log");
    rtl::ScanPolylines2D<double> ex, own;   // the default refines every budget's plan
    for (auto *e : {&ex, &own})
    {
        e->setGreedyCandidates(false);
        e->setBreakCandidates(2);
        e->setPartitionSegments(0);
        e->setRefinedReallocation(false);
    }
    ex.setMaxVertices(9);
    ASSERT_TRUE(ex(scans[16]));
    const double nine = ex.score();
    EXPECT_NEAR(nine, 0.0815, 0.0005);
    ex.setMaxVertices(10);
    ASSERT_TRUE(ex(scans[16]));
    EXPECT_LE(ex.score(), nine);
    EXPECT_NEAR(ex.explainedFraction(), 0.776, 0.001);
    EXPECT_LE(ex.vertexCount(), 10u);
    // refining only J's own plan reproduces the rise
    own.setRefineEveryBudget(false);
    own.setMaxVertices(10);
    ASSERT_TRUE(own(scans[16]));
    EXPECT_NEAR(own.score(), 0.1001, 0.0005);
    EXPECT_NEAR(own.explainedFraction(), 0.630, 0.001);
}

TEST(ScanPolylines2D, ScoreIsThePleMetricOfTheOutput)
{
    // score(), rmse(), explainedFraction() and expectedRanges() agree with an independent ray cast of polylines().
    const auto scans = excerptScans("csail.log");
    rtl::ScanPolylines2D<double> ex;
    ex.setMaxVertices(30);
    for (std::size_t s = 0; s < scans.size(); s += 7)
    {
        ASSERT_TRUE(ex(scans[s]));
        std::vector<double> angles, ranges;
        std::vector<bool> returned;
        for (const auto &p : scans[s])
        {
            const bool ok = std::isfinite(p[0]) && std::isfinite(p[1]);
            returned.push_back(ok);
            angles.push_back(ok ? std::atan2(p[1], p[0]) : std::nan(""));
            ranges.push_back(ok ? std::hypot(p[0], p[1]) : 0.0);
        }
        const auto rhat = rtl::scan_polylines::expectedRangesOf(angles, ex.polylines(), 1e-3);
        const auto score = rtl::scan_polylines::scoreExpected(ranges, returned, rhat);
        EXPECT_EQ(score.hit, ex.explainedBeams());
        EXPECT_EQ(score.returned, ex.returnedBeams());
        EXPECT_NEAR(score.score(0.5), ex.score(), 1e-12);
        EXPECT_NEAR(score.rmse(), ex.rmse(), 1e-12);
        for (std::size_t i = 0; i < rhat.size(); ++i)
        {
            if (std::isnan(rhat[i])) { EXPECT_TRUE(std::isnan(ex.expectedRanges()[i])); }
            else { EXPECT_NEAR(ex.expectedRanges()[i], rhat[i], 1e-12); }
        }
    }
}

TEST(ScanPolylines2D, RefinementNeverRaisesTheScore)
{
    rtl::ScanPolylines2D<double> with, without;
    without.setRefinement(false);
    std::size_t lower = 0, scans_seen = 0;
    for (const char *file : {"intel.log", "csail.log"})
        for (const auto &scan : excerptScans(file))
            for (std::size_t J : {10u, 30u})
            {
                with.setMaxVertices(J); without.setMaxVertices(J);
                ASSERT_TRUE(with(scan));
                ASSERT_TRUE(without(scan));
                expectEndsOnOwnBeams(without, scan, 1e-9);   // before refinement, the construction puts them there
                EXPECT_LE(with.score(), without.score());
                lower += with.score() < without.score() ? 1 : 0;
                ++scans_seen;
            }
    // and it does something: most scans improve
    EXPECT_GT(lower, scans_seen / 2);
}

TEST(ScanPolylines2D, RealExcerptScoreMatchesTheMeasuredFigure)
{
    // Mean score over the 30 scans of tests/data/intel.log (library beam layout, NaN = no return), J = 20, defaults.
    // Measured when the greedy-removal family became the default (before: 0.026212 / 0.048569 / 0.908772); a change
    // of more than 2 % is a change of behaviour.
    const auto scans = excerptScans("intel.log");
    rtl::ScanPolylines2D<double> ex;
    ex.setMaxVertices(20);
    double mean = 0, rmse = 0, f = 0;
    for (const auto &scan : scans)
    {
        ASSERT_TRUE(ex(scan));
        mean += ex.score(); rmse += ex.rmse(); f += ex.explainedFraction();
    }
    mean /= 30; rmse /= 30; f /= 30;
    EXPECT_NEAR(mean, 0.025490, 0.02 * 0.025490);
    EXPECT_NEAR(rmse, 0.048814, 0.02 * 0.048814);
    EXPECT_NEAR(f, 0.912219, 0.005);
}

TEST(ScanPolylines2D, EndTrimmingLeavesClutterAtAChainEndOut)
{
    // A wall y = 2 seen by beams at 45..135 degrees (1-degree steps), its first 10 returns 0.8 m short (clutter within
    // the 1 m link distance, so one chain). With J = 2 (one segment) the plain extractor must span the clutter; with
    // end trimming the segment starts at the wall and the 10 beams are left unexplained at 0.5^2 each.
    std::vector<rtl::Vector2d> scan;
    for (int d = 45; d <= 135; ++d)
    {
        const double a = d * M_PI / 180, r = 2 / std::sin(a) - (d < 55 ? 0.8 : 0.0);
        scan.emplace_back(r * std::cos(a), r * std::sin(a));
    }
    const double n = static_cast<double>(scan.size());
    rtl::ScanPolylines2D<double> plain, trimmed;
    // the partition family's trimming is under test (the greedy family, on by default, trims ends by itself)
    plain.setGreedyCandidates(false);
    trimmed.setGreedyCandidates(false);
    plain.setMaxVertices(2);
    trimmed.setMaxVertices(2);
    trimmed.setEndTrimming(true);
    ASSERT_TRUE(plain(scan));
    ASSERT_TRUE(trimmed(scan));
    EXPECT_NEAR(plain.explainedFraction(), 1.0, 1e-12);
    EXPECT_NEAR(trimmed.explainedFraction(), (n - 10) / n, 1e-12);
    EXPECT_NEAR(trimmed.score(), 10 * 0.25 / n, 1e-6);   // the wall itself is explained exactly
    EXPECT_LT(trimmed.score(), 0.8 * plain.score());   // plain: about 0.040 (its line and LM compromise)
    for (std::size_t i = 0; i < 10; ++i) EXPECT_TRUE(std::isnan(trimmed.expectedRanges()[i])) << i;
    ASSERT_EQ(trimmed.polylines().size(), 1u);
    ASSERT_EQ(trimmed.polylines()[0].size(), 2u);
    EXPECT_NEAR(trimmed.polylines()[0][0].y(), 2.0, 1e-6);   // end vertices on their own (wall) beams
    EXPECT_NEAR(trimmed.polylines()[0][1].y(), 2.0, 1e-6);
}

TEST(ScanPolylines2D, BadParametersThrowInvalidArgument)
{
    rtl::ScanPolylines2D<double> ex;
    EXPECT_THROW(ex.setMaxVertices(1), std::invalid_argument);
    EXPECT_THROW(ex.setMaxVertices(0), std::invalid_argument);
    EXPECT_NO_THROW(ex.setMaxVertices(2));
    const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
    for (double bad : {nan, inf, -inf, 0.0, -1.0})
    {
        EXPECT_THROW(ex.setMaxGap(bad), std::invalid_argument) << bad;
        EXPECT_THROW(ex.setUnexplainedCost(bad), std::invalid_argument) << bad;
        EXPECT_THROW(ex.setPointSigma(bad), std::invalid_argument) << bad;
    }
    // rejected values leave the settings unchanged
    EXPECT_EQ(ex.maxVertices(), 2u);
    EXPECT_EQ(ex.maxGap(), 1.0);
    EXPECT_EQ(ex.unexplainedCost(), 0.5);
}

TEST(ScanPolylines2D, NoReturnedBeamGivesFalseAndEmptyOutputs)
{
    rtl::ScanPolylines2D<float> ex;
    ASSERT_TRUE(ex(roomScan<float>()));            // outputs of a previous call are replaced
    EXPECT_FALSE(ex(std::vector<rtl::Vector2f>{}));
    EXPECT_TRUE(ex.polylines().empty());
    EXPECT_TRUE(ex.expectedRanges().empty());
    EXPECT_TRUE(std::isnan(ex.score()));
    const float nan = std::numeric_limits<float>::quiet_NaN(), inf = std::numeric_limits<float>::infinity();
    const std::vector<rtl::Vector2f> none{{nan, nan}, {inf, 1.f}, {0.f, 0.f}, {nan, 2.f}};
    EXPECT_FALSE(ex(none));
    EXPECT_TRUE(ex.polylines().empty());
    EXPECT_TRUE(ex.segments().empty());
    ASSERT_EQ(ex.expectedRanges().size(), 4u);
    for (float r : ex.expectedRanges()) EXPECT_TRUE(std::isnan(r));
    EXPECT_TRUE(std::isnan(ex.score()));
    EXPECT_TRUE(std::isnan(ex.rmse()));
    EXPECT_EQ(ex.returnedBeams(), 0u);
}

TEST(ScanPolylines2D, IsolatedBeamsAreLeftUnexplained)
{
    // one returned beam per chain (neighbours 5 m apart > maxGap): nothing can be fitted, every beam costs c^2
    const std::vector<rtl::Vector2d> beams{{1, 0}, {std::nan(""), 0}, {0, 6}, {-7, 0.5}};
    rtl::ScanPolylines2D<double> ex;
    ASSERT_TRUE(ex(beams));
    EXPECT_TRUE(ex.polylines().empty());
    EXPECT_EQ(ex.returnedBeams(), 3u);
    EXPECT_EQ(ex.explainedBeams(), 0u);
    EXPECT_DOUBLE_EQ(ex.score(), 0.25);
    EXPECT_DOUBLE_EQ(ex.explainedFraction(), 0.0);
}

TEST(ScanPolylines2D, TheGapSeparatesPolylines)
{
    // two parallel walls behind each other: with the default gap 1 m they are separate polylines; a larger gap joins
    // the beams into one chain, so one polyline may cross the jump
    std::vector<rtl::Vector2d> beams;
    for (int d = -30; d <= 30; ++d)
    {
        const double a = d * kPi / 180, x = d < 0 ? 2.0 : 3.5;
        beams.emplace_back(x, x * std::tan(a));
    }
    rtl::ScanPolylines2D<double> ex;
    ex.setMaxVertices(2);
    ASSERT_TRUE(ex(beams));
    ASSERT_EQ(ex.polylines().size(), 1u);     // two vertices: only one of the walls
    EXPECT_NEAR(ex.explainedFraction(), 30.0 / 61, 1.0 / 61 + 1e-12);
    ex.setMaxVertices(4);
    ASSERT_TRUE(ex(beams));
    EXPECT_EQ(ex.polylines().size(), 2u);
    EXPECT_NEAR(ex.score(), 0.0, 1e-20);
}

TEST(ScanPolylines2D, ADepthStepInsideAChainBecomesABreakWhenTheBudgetAllows)
{
    // Two walls meeting the beams at a depth step of 0.3 m (less than the 1 m gap, so one chain): y = 3 + 1.5 x left
    // of x = 0 and y = 3.3 - 1.5 x right of it. Their lines cross at (0.1, 3.15), next to the step, so the corner is
    // accepted, and the beams between x = 0 and x = 0.1 are then predicted by the left wall's line. With four vertices
    // two separate segments explain every beam exactly; without break candidates the partitions offer no such map.
    std::vector<rtl::VectorND<2, double>> scan;
    for (int d = 60; d <= 120; ++d)
    {
        const double a = d * kPi / 180, c = std::cos(a), s = std::sin(a);
        // r on y = y0 + m x along (c, s): r (s - m c) = y0
        const double r = c > 1e-12 ? 3.3 / (s + 1.5 * c) : 3.0 / (s - 1.5 * c);
        scan.emplace_back(r * c, r * s);
    }
    rtl::ScanPolylines2D<double> with, without;
    with.setBreakCandidates(2);
    without.setBreakCandidates(0);
    for (auto *ex : {&with, &without})
    {
        ex->setGreedyCandidates(false);   // the partition family's structure is under test
        ex->setMaxVertices(4);
        ex->setRefinement(false);   // the structure is under test, not the refinement
        ASSERT_TRUE((*ex)(scan));
        EXPECT_LE(ex->vertexCount(), 4u);
    }
    EXPECT_LT(with.score(), 1e-10);   // two exact segments
    EXPECT_EQ(with.polylines().size(), 2u);
    EXPECT_NEAR(with.explainedFraction(), 1.0, 1e-12);
    EXPECT_GT(without.score(), 1e-4);   // the corner's misassigned beams
}

TEST(ScanPolylines2D, BreakCostsFromLocalGainsChooseAsWellAsHitTestedOnes)
{
    // Break candidates are priced as the partition's cost minus the local gains; hit-testing each instead must not
    // find better maps (on average over the real excerpt), and both must beat no break candidates at J = 50. Measured
    // on the partition family alone: short-chain point candidates (default) reach the same maps without breaks.
    rtl::ScanPolylines2D<double> local, exact, none;
    for (auto *ex : {&local, &exact, &none})
    {
        ex->setShortChainPoints(0);
        ex->setGreedyCandidates(false);
        ex->setPartitionSegments(0);
        ex->setBreakCandidates(2);
    }
    exact.setExactBreakCosts(true);
    none.setBreakCandidates(0);
    double s_local = 0, s_exact = 0, s_none = 0;
    for (const auto &scan : excerptScans("intel.log"))
    {
        for (auto *ex : {&local, &exact, &none}) { ex->setMaxVertices(50); ASSERT_TRUE((*ex)(scan)); }
        s_local += local.score(); s_exact += exact.score(); s_none += none.score();
    }
    EXPECT_NEAR(s_local, s_exact, 0.005 * s_exact);
    EXPECT_LT(s_local, 0.99 * s_none);
}

TEST(ScanPolylines2D, NeighbourRefinementLowersTheMeanScore)
{
    rtl::ScanPolylines2D<double> with, without;
    with.setNeighbourRefinement(2);
    double s_with = 0, s_without = 0;
    for (const char *file : {"intel.log", "csail.log"})
        for (const auto &scan : excerptScans(file))
            for (std::size_t J : {10u, 30u})
            {
                with.setMaxVertices(J); without.setMaxVertices(J);
                ASSERT_TRUE(with(scan));
                ASSERT_TRUE(without(scan));
                EXPECT_LE(with.vertexCount(), J);
                s_with += with.score(); s_without += without.score();
            }
    EXPECT_LT(s_with, s_without);
}

TEST(ScanPolylines2D, PointCandidatesKeepTheBudgetAndLowerTheMeanScore)
{
    // The point-vertex family offered beside the TLS partitions: the budget holds, end vertices stay on their own
    // beams, no scan scores worse than half a percent above the plain extractor (the knapsack may only gain on each
    // chain's own beams, other chains' overlap aside), and the mean score drops (measured on the full benchmark by
    // 2-6 %; here on the excerpts at J = 10 and 50).
    rtl::ScanPolylines2D<double> with, without;
    with.setPointCandidates(true);
    double s_with = 0, s_without = 0;
    for (const char *file : {"intel.log", "csail.log"})
        for (const auto &scan : excerptScans(file))
            for (std::size_t J : {10u, 50u})
            {
                with.setMaxVertices(J); without.setMaxVertices(J);
                ASSERT_TRUE(with(scan));
                ASSERT_TRUE(without(scan));
                EXPECT_LE(with.vertexCount(), J);
                expectEndsOnOwnBeams(with, scan, 1e-9);
                s_with += with.score(); s_without += without.score();
            }
    EXPECT_LT(s_with, 0.99 * s_without);
}

TEST(ScanPolylines2D, PointCandidatesExplainADepthStepExactly)
{
    // A wall y = 2 over 60..120 degrees whose middle part (beams 80..100 degrees) stands 0.3 m nearer (steps inside
    // the 1 m link distance, so one chain). One polyline through the two ends and the four step points (six vertices,
    // all measured points) predicts every beam exactly; with J = 6 and point candidates the map does that.
    std::vector<rtl::Vector2d> scan;
    for (int d = 60; d <= 120; ++d)
    {
        const double a = d * M_PI / 180, wall = (d >= 80 && d <= 100) ? 1.7 : 2.0, r = wall / std::sin(a);
        scan.emplace_back(r * std::cos(a), r * std::sin(a));
    }
    rtl::ScanPolylines2D<double> points;
    points.setMaxVertices(6);
    points.setPointCandidates(true);
    ASSERT_TRUE(points(scan));
    EXPECT_EQ(points.vertexCount(), 6u);
    EXPECT_NEAR(points.explainedFraction(), 1.0, 1e-12);
    EXPECT_LT(points.score(), 1e-20);
    for (std::size_t i = 0; i < scan.size(); ++i)
        EXPECT_NEAR(points.expectedRanges()[i], std::hypot(scan[i][0], scan[i][1]), 1e-9) << "beam " << i;
    // and with one vertex fewer it cannot be exact
    points.setMaxVertices(5);
    ASSERT_TRUE(points(scan));
    EXPECT_GT(points.score(), 1e-4);
}

TEST(ScanPolylines2D, PointCandidatesSurviveRepeatedPointsAndHoles)
{
    // Runs of points that coincide in float (60 beams 1e-9 rad apart at one range: zero-length chords), single returns
    // between holes, a float instantiation: every budget is kept and the score stays finite and below the all-unexplained
    // cost.
    std::vector<rtl::Vector2f> scan;
    for (int d = 0; d < 180; ++d)
    {
        const double a = d < 60 ? 0.5 + d * 1e-9 : d < 120 ? 1.0 + (d - 60) * 1e-9 : 1.2 + (d - 120) * kPi / 180;
        const double r = d % 37 == 5 ? std::nan("") : d < 120 ? 2.0 : 2.0 + 0.3 * std::sin(0.2 * d);
        scan.emplace_back(static_cast<float>(r * std::cos(a)), static_cast<float>(r * std::sin(a)));
    }
    ASSERT_EQ(scan[10][0], scan[11][0]);   // the runs really coincide
    ASSERT_EQ(scan[10][1], scan[11][1]);
    rtl::ScanPolylines2D<float> points;
    points.setPointCandidates(true);
    for (std::size_t J : {2u, 3u, 5u, 10u, 50u})
    {
        points.setMaxVertices(J);
        ASSERT_TRUE(points(scan));
        EXPECT_LE(points.vertexCount(), J);
        EXPECT_TRUE(std::isfinite(points.score()));
        EXPECT_GE(points.score(), 0.0);
        EXPECT_LE(points.score(), 0.25);   // never worse than leaving every beam unexplained
    }
}

TEST(ScanPolylines2D, RadialRepartitionKeepsTheBudgetAndLowersTheMeanScore)
{
    // The chosen partitions' boundaries moved within 2 beams to minimise the ranges' own radial errors: replaced only
    // when their polylines need no more vertices and score lower on the chain (measured on the full benchmark: 0.1-1 %).
    rtl::ScanPolylines2D<double> with, without;
    with.setRadialRepartition(2);
    double s_with = 0, s_without = 0;
    std::size_t changed = 0;
    for (const char *file : {"intel.log", "csail.log"})
        for (const auto &scan : excerptScans(file))
            for (std::size_t J : {10u, 30u, 50u})
            {
                with.setMaxVertices(J); without.setMaxVertices(J);
                ASSERT_TRUE(with(scan));
                ASSERT_TRUE(without(scan));
                EXPECT_LE(with.vertexCount(), J);
                expectEndsOnOwnBeams(with, scan, 1e-9);
                s_with += with.score(); s_without += without.score();
                changed += with.score() != without.score() ? 1 : 0;
            }
    EXPECT_LT(s_with, s_without);
    EXPECT_GT(changed, 10u);   // it does something on many scans
}

TEST(ScanPolylines2D, ShortChainPointsExplainAThreeBeamClusterExactly)
{
    // Two walls (y = 5 over beams 60..69.5 degrees, y = 4 over 72.5..80 degrees, 0.5-degree steps) and between them,
    // after a beam without a return, a clutter cluster of three beams at 2.0, 1.8 and 2.0 m (a chair leg seen edge on:
    // its own chain). A TLS range needs two beams, so the partition family can give the cluster one segment at most,
    // which misses its middle beam by ~0.1 m; the polyline through its three points explains it exactly. With J = 7
    // (2 + 3 + 2 vertices) the default map explains every beam exactly; without short-chain points it cannot.
    std::vector<rtl::Vector2d> scan;
    const double nan = std::numeric_limits<double>::quiet_NaN();
    auto beam = [&](int step, double r) {
        const double a = (60.0 + 0.5 * step) * M_PI / 180;
        scan.emplace_back(r * std::cos(a), r * std::sin(a));
    };
    for (int s = 0; s < 20; ++s) beam(s, 5.0 / std::sin((60.0 + 0.5 * s) * M_PI / 180));
    scan.emplace_back(nan, nan);
    beam(21, 2.0); beam(22, 1.8); beam(23, 2.0);
    scan.emplace_back(nan, nan);
    for (int s = 25; s <= 40; ++s) beam(s, 4.0 / std::sin((60.0 + 0.5 * s) * M_PI / 180));
    rtl::ScanPolylines2D<double> ex;
    ex.setMaxVertices(7);
    ASSERT_TRUE(ex(scan));
    EXPECT_EQ(ex.vertexCount(), 7u);
    EXPECT_NEAR(ex.explainedFraction(), 1.0, 1e-12);
    EXPECT_LT(ex.score(), 1e-20);
    EXPECT_NEAR(ex.expectedRanges()[22], 1.8, 1e-9);
    // a segment of the point family can own one beam (21 here): its covariance is still finite
    for (const auto &seg : ex.segments()) EXPECT_TRUE(seg.covariance.allFinite()) << "segment over beams " << seg.beams.first;
    // the partition family alone: one segment over the cluster (or none), never exact
    ex.setShortChainPoints(0);
    ex.setGreedyCandidates(false);
    ASSERT_TRUE(ex(scan));
    EXPECT_GT(ex.score(), 1e-4);
    EXPECT_GT(std::abs(ex.expectedRanges()[22] - 1.8), 0.02);
}

TEST(ScanPolylines2D, SegmentCovarianceIsNeverNaN)
{
    // Beams whose points lie 1e-300 m from the sensor: a segment's points spread along its line by ~1e-300 m, whose
    // square underflows, so the normal matrix is singular in double. The covariance then says "unknown" (infinite
    // variances, no correlation) instead of NaN; a wall at 2 m keeps finite ones.
    std::vector<rtl::Vector2d> scan;
    for (int d = 80; d <= 84; ++d)
    {
        const double a = d * M_PI / 180;
        scan.emplace_back(1e-300 * std::cos(a), 1e-300 * std::sin(a));
    }
    for (int d = 86; d <= 100; ++d)
    {
        const double a = d * M_PI / 180, r = 2 / std::sin(a);
        scan.emplace_back(r * std::cos(a), r * std::sin(a));
    }
    scan.insert(scan.begin() + 5, rtl::Vector2d(std::nan(""), std::nan("")));   // the two clusters apart
    rtl::ScanPolylines2D<double> ex;
    ex.setMaxVertices(10);
    ASSERT_TRUE(ex(scan));
    bool tiny = false, wall = false;
    for (const auto &s : ex.segments())
    {
        EXPECT_FALSE(s.covariance.hasNaN()) << "segment over beams " << s.beams.first << "-" << s.beams.second;
        EXPECT_EQ(s.covariance(0, 1), s.covariance(1, 0));
        EXPECT_GT(s.covariance(0, 0), 0.0);
        EXPECT_GT(s.covariance(1, 1), 0.0);
        if (s.beams.second < 5) { tiny = true; EXPECT_TRUE(std::isinf(s.covariance(1, 1))); }
        else { wall = true; EXPECT_TRUE(s.covariance.allFinite()); }
    }
    EXPECT_TRUE(tiny);
    EXPECT_TRUE(wall);
}
