// Split mode's cover: where no partition into ranges of >= 2 points fits sigma (3 points forming
// a corner, short zigzags), FTLS/AFTLS in split mode cover the chain with ranges that may share one point, so a
// real scan never comes back empty; strict mode keeps RTL's false return and its failure report.
#include <cmath>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "rtl/Segmentation.h"
#include "rtl/Vectorization.h"
#include "rtl/io/CarmenLog.h"
#include "vect_reference.h"

using namespace vect_test;

namespace
{
    typedef rtl::ApproximationTlsLine2D<float, double> Line;
    typedef rtl::PrecArray2D<float, double> Arr;
    typedef rtl::PartitionSearch2D<Arr, Line> Search;
    typedef rtl::VectorizerFTLSPolyline2D<float, double> Ftls;
    typedef rtl::VectorizerAFTLSPolyline2D<float, double> Aftls;

    bool fitsSigma(const Arr &a, size_t b, size_t e, double sigma)
    {
        return e - b == 2 || Line::errorBelow(a.sums(b, e), sigma * sigma);
    }

    //! Brute force over every cover of [0, n) by fitting ranges of >= 2 points where each range starts at the
    //! previous end or one point before it: the fewest ranges and the least total squared residual among those.
    struct BruteCover { size_t ranges = std::numeric_limits<size_t>::max(); double error = 0; };
    void bruteCover(const Arr &a, size_t n, double sigma, size_t end, size_t count, double err, BruteCover &best)
    {
        if (end == n)
        {
            if (count < best.ranges || (count == best.ranges && err < best.error))
                best = BruteCover{count, err};
            return;
        }
        for (size_t s : {end, end - 1})
        {
            if (end == 0 && s != 0) continue;
            for (size_t e = std::max(s + 2, end + 1); e <= n; ++e)
                if (fitsSigma(a, s, e, sigma))
                {
                    const double t = e - s <= 2 ? 0.0 : Line::errorSquaredCompute(a.sums(s, e)) * static_cast<double>(e - s);
                    bruteCover(a, n, sigma, e, count + 1, err + t, best);
                }
            if (end == 0) break;
        }
    }

    //! Ranges in order, covering [0, n), each adjoining the previous or sharing one point with it; shared points
    //! only when `overlap_allowed`.
    void expectCover(const std::vector<Range> &idx, size_t n, bool overlap_allowed)
    {
        ASSERT_FALSE(idx.empty());
        EXPECT_EQ(idx.front().first, 0u);
        EXPECT_EQ(idx.back().second, n);
        for (size_t i = 0; i < idx.size(); ++i)
        {
            EXPECT_GE(idx[i].second, idx[i].first + 2) << "range " << i;
            if (i + 1 < idx.size())
            {
                const size_t next = idx[i + 1].first, end = idx[i].second;
                EXPECT_TRUE(next == end || (overlap_allowed && next + 1 == end)) << "ranges " << i << ", " << i + 1;
                EXPECT_GT(idx[i + 1].second, end);
            }
        }
    }

    size_t sharedPoints(const std::vector<Range> &idx)
    {
        size_t k = 0;
        for (size_t i = 1; i < idx.size(); ++i)
            k += idx[i].first < idx[i - 1].second ? 1 : 0;
        return k;
    }

    //! A split-mode result: a cover within sigma, polylines as documented; a continuous corner's vertex within
    //! delta of the boundary midpoint or the shared point, every break beyond delta.
    template<class V>
    void expectValidSplitCover(const V &v, const std::vector<rtl::Vector2f> &pts, double sigma, double delta, bool overlap_allowed)
    {
        const auto &idx = v.indices();
        expectCover(idx, pts.size(), overlap_allowed);
        expectLineRms(pts, idx, sigma);
        const auto &off = v.polylineOffsets();
        ASSERT_GE(off.size(), 2u);
        EXPECT_EQ(off.front(), 0u);
        EXPECT_EQ(off.back(), idx.size());
        ASSERT_EQ(off.size(), v.breaks().size() + 2);
        ASSERT_EQ(v.vertices().size(), idx.size() + off.size() - 1);
        ASSERT_EQ(v.lineSegments().size(), idx.size());
        EXPECT_FALSE(v.failure().has_value());
        for (size_t p = 1; p + 1 < off.size(); ++p)
        {
            EXPECT_EQ(v.breaks()[p - 1].boundary, idx[off[p]].first);
            EXPECT_GT(v.breaks()[p - 1].crossingDistance, delta);
        }
        for (size_t p = 0; p + 1 < off.size(); ++p)
            for (size_t i = off[p]; i + 1 < off[p + 1]; ++i)
            {
                const Eigen::Vector2d ref = (pts[idx[i].second - 1].data().template cast<double>() + pts[idx[i + 1].first].data().template cast<double>()) / 2;
                EXPECT_LE((v.vertices()[i + 1 + p].data().template cast<double>() - ref).norm(), delta * (1 + 1e-6)) << "corner " << i;
            }
    }

    //! Strict mode: false with the exact search's failure report; split mode: a cover with shared points.
    template<class V>
    void expectStrictFalseSplitCover(const std::vector<rtl::Vector2f> &pts, double sigma, double delta, size_t expected_ranges)
    {
        Arr a;
        a.precompute(pts);
        Search s;
        s.setSigma(static_cast<float>(sigma));
        s.setDelta(static_cast<float>(delta));
        std::vector<Line> lines;
        std::vector<Range> idx;
        ASSERT_FALSE(s(pts, a, lines, idx));
        V strict, split;
        for (V *v : {&strict, &split}) { v->setSigma(static_cast<float>(sigma)); v->setDelta(static_cast<float>(delta)); }
        split.setSplitAtInfeasibleCorners(true);
        ASSERT_FALSE(strict(pts));
        EXPECT_TRUE(strict.indices().empty());
        EXPECT_TRUE(strict.lineSegments().empty());
        ASSERT_TRUE(strict.failure().has_value());
        EXPECT_EQ(strict.failure()->boundary, s.failure().boundary);
        EXPECT_EQ(strict.failure()->crossingDistance, s.failure().crossingDistance);
        EXPECT_EQ(strict.failure()->delta, s.failure().delta);
        ASSERT_TRUE(split(pts));
        expectValidSplitCover(split, pts, sigma, delta, true);
        EXPECT_EQ(split.indices().size(), expected_ranges);
        EXPECT_GE(sharedPoints(split.indices()), 1u);
    }

    std::vector<rtl::Vector2f> zigzag(size_t n)
    {
        std::vector<rtl::Vector2f> pts;
        for (size_t i = 0; i < n; ++i)
            pts.emplace_back(static_cast<float>(i), static_cast<float>(i % 2));
        return pts;
    }
}

// 3 points forming a right angle: no line fits them and [0, 2) [2, 3) is no partition. Strict: false, the failure
// is sigma (boundary 0, no crossing); split: [0, 2) [1, 3), one polyline through the corner point.
TEST(SplitCover, ThreePointCorner)
{
    const std::vector<rtl::Vector2f> pts{{0.f, 0.f}, {1.f, 0.f}, {1.f, 1.f}};
    expectStrictFalseSplitCover<Ftls>(pts, 0.03, 0.3, 2);
    expectStrictFalseSplitCover<Aftls>(pts, 0.03, 0.3, 2);
    Ftls strict, f;
    strict.setDelta(0.3f);
    ASSERT_FALSE(strict(pts));
    EXPECT_EQ(strict.failure()->boundary, 0u);
    EXPECT_EQ(strict.failure()->crossingDistance, std::numeric_limits<double>::infinity());
    EXPECT_DOUBLE_EQ(strict.failure()->delta, 0.3f);
    f.setDelta(0.3f);
    f.setSplitAtInfeasibleCorners(true);
    ASSERT_TRUE(f(pts));
    EXPECT_EQ(f.indices(), (std::vector<Range>{{0, 2}, {1, 3}}));
    EXPECT_EQ(f.polylineOffsets(), (std::vector<size_t>{0, 2}));
    EXPECT_TRUE(f.breaks().empty());
    ASSERT_EQ(f.vertices().size(), 3u);
    for (size_t i = 0; i < 3; ++i)
        EXPECT_LT((f.vertices()[i] - pts[i]).length(), 1e-5f) << i;
}

// Zigzags with unit steps: no 3 consecutive points fit 3 cm, so only 2-point ranges fit and an odd count has no
// partition; k such ranges cover at most 2k points, so 5 points need 3 ranges, 7 points 4.
TEST(SplitCover, FivePointZigzag)
{
    expectStrictFalseSplitCover<Ftls>(zigzag(5), 0.03, 0.3, 3);
    expectStrictFalseSplitCover<Aftls>(zigzag(5), 0.03, 0.3, 3);
    Ftls f;
    f.setDelta(0.3f);
    f.setSplitAtInfeasibleCorners(true);
    ASSERT_TRUE(f(zigzag(5)));
    // Adjoining zigzag ranges are parallel (a break); ranges sharing a point meet exactly at it (continuous).
    EXPECT_EQ(sharedPoints(f.indices()), 1u);
    EXPECT_EQ(f.breaks().size(), 1u);
    EXPECT_EQ(f.breaks()[0].crossingDistance, std::numeric_limits<double>::infinity());
}

TEST(SplitCover, SevenPoints)
{
    expectStrictFalseSplitCover<Ftls>(zigzag(7), 0.03, 0.3, 4);
    expectStrictFalseSplitCover<Aftls>(zigzag(7), 0.03, 0.3, 4);
    // A noisy 7-point arc at 1 mm: only 2-point ranges fit, 7 points need 4 of them.
    std::vector<rtl::Vector2f> arc;
    for (int i = 0; i < 7; ++i)
        arc.emplace_back(std::cos(0.5f * static_cast<float>(i)), std::sin(0.5f * static_cast<float>(i)));
    expectStrictFalseSplitCover<Ftls>(arc, 0.001, 0.3, 4);
    expectStrictFalseSplitCover<Aftls>(arc, 0.001, 0.3, 4);
}

// Where a partition exists, split mode never shares points (the cover is only the last resort); only invalid
// input returns false in split mode.
TEST(SplitCover, SharedPointsOnlyWithoutPartitionAndFalseOnlyForInvalidInput)
{
    Ftls f;
    f.setSplitAtInfeasibleCorners(true);
    f.setDelta(0.3f);
    ASSERT_TRUE(f(zigzag(6)));
    EXPECT_EQ(f.indices(), (std::vector<Range>{{0, 2}, {2, 4}, {4, 6}}));
    ASSERT_TRUE(f(std::vector<rtl::Vector2f>{{0.f, 0.f}, {1.f, 0.f}}));
    EXPECT_FALSE(f(std::vector<rtl::Vector2f>{{0.f, 0.f}}));
    EXPECT_FALSE(f(std::vector<rtl::Vector2f>{{0.f, 0.f}, {1.f, 0.f}, {std::nanf(""), 1.f}}));
    f.setSigma(-1.f);
    EXPECT_FALSE(f(zigzag(3)));
    EXPECT_TRUE(f.indices().empty());
}

// cover() finds the fewest ranges, then the least total squared residual, that brute force over every cover
// finds, on random chains of 2 .. 11 points at several sigmas; and where no partition exists at all, split mode
// returns exactly that many segments.
TEST(SplitCover, MinimalAgainstBruteForceOnSmallRandomChains)
{
    std::mt19937 g(1234);
    std::uniform_real_distribution<double> u(0, 1);
    std::normal_distribution<double> nd(0, 1);
    size_t without_partition = 0, shared = 0;
    for (int trial = 0; trial < 3000; ++trial)
    {
        const size_t n = 2 + static_cast<size_t>(trial % 10);
        const double noise = 0.005 + 0.03 * u(g), sigma = trial % 3 == 0 ? 0.01 : 0.03;
        std::vector<rtl::Vector2f> pts;
        double x = 0, y = 0, a = u(g) * 6;
        for (size_t i = 0; i < n; ++i)
        {
            if (u(g) < 0.3) a += (u(g) - 0.5) * 3;
            x += 0.1 * std::cos(a);
            y += 0.1 * std::sin(a);
            pts.emplace_back(static_cast<float>(x + noise * nd(g)), static_cast<float>(y + noise * nd(g)));
        }
        SCOPED_TRACE(testing::Message() << "trial " << trial << ", " << n << " points, sigma " << sigma);
        Arr arr;
        arr.precompute(pts);
        BruteCover best;
        bruteCover(arr, n, sigma, 0, 0, 0.0, best);
        ASSERT_NE(best.ranges, std::numeric_limits<size_t>::max());
        Search s, sb;
        for (Search *p : {&s, &sb}) { p->setSigma(static_cast<float>(sigma)); p->setDelta(0.3f); }
        sb.setAllowBreaks(true);
        std::vector<Line> lines;
        std::vector<Range> idx;
        ASSERT_TRUE(s.cover(pts, arr, lines, idx));
        expectCover(idx, n, true);
        EXPECT_EQ(idx.size(), best.ranges);
        double err = 0;
        for (const auto &r : idx)
            err += refFit<2>(pts, r.first, r.second).lineErr() * static_cast<double>(r.second - r.first);
        EXPECT_NEAR(err, best.error, 1e-7 + 1e-5 * best.error);
        if (sb(pts, arr, lines, idx))
            continue;
        ++without_partition;
        Ftls f;
        Aftls af;
        f.setSigma(static_cast<float>(sigma)); f.setDelta(0.3f); f.setSplitAtInfeasibleCorners(true);
        af.setSigma(static_cast<float>(sigma)); af.setDelta(0.3f); af.setSplitAtInfeasibleCorners(true);
        ASSERT_TRUE(f(pts));
        ASSERT_TRUE(af(pts));
        EXPECT_EQ(f.indices().size(), best.ranges);
        EXPECT_EQ(af.indices().size(), best.ranges);
        expectValidSplitCover(f, pts, sigma, 0.3, true);
        expectValidSplitCover(af, pts, sigma, 0.3, true);
        shared += sharedPoints(f.indices());
    }
    EXPECT_GT(without_partition, 100u);
    EXPECT_GE(shared, without_partition);
}

namespace
{
    //! CAR clusters (step 2, bounds 0.1 .. 0.5 m: the package defaults) of >= 3 points of every scan of tests/data.
    std::vector<std::vector<rtl::Vector2f>> carClusters()
    {
        std::vector<std::vector<rtl::Vector2f>> all;
        rtl::CAR_Segmenter<rtl::Vector2f> seg(2, 0.1f, 0.5f);
        for (const char *name : {"intel.log", "csail.log"})
            for (const auto &scan : rtl::readCarmenLogFile<float>(std::string(RTL_TEST_DATA_DIR) + "/" + name))
            {
                seg.loadData(scan.points);
                while (seg.clustersAvailable() > 0)
                {
                    auto c = seg.grabCluster();
                    if (c.size() >= 3)
                        all.push_back(std::move(c));
                }
            }
        return all;
    }
}

// Every CAR cluster of tests/data at three settings: split mode never returns empty (FTLS and AFTLS), its ranges
// share points exactly on the clusters no partition fits, and strict mode is unchanged there (false, a failure).
TEST(SplitCover, RealClustersNeverEmptyInSplitMode)
{
    const auto all = carClusters();
    ASSERT_GT(all.size(), 500u);
    size_t covers = 0;
    for (const auto &[sigma, delta] : {std::pair{0.03, 0.3}, std::pair{0.03, 1.0}, std::pair{0.01, 0.3}})
    {
        Ftls f, fs;
        Aftls af, afs;
        for (auto *v : {&f, &fs}) { v->setSigma(static_cast<float>(sigma)); v->setDelta(static_cast<float>(delta)); }
        for (auto *v : {&af, &afs}) { v->setSigma(static_cast<float>(sigma)); v->setDelta(static_cast<float>(delta)); }
        fs.setSplitAtInfeasibleCorners(true);
        afs.setSplitAtInfeasibleCorners(true);
        Search sb;
        sb.setSigma(static_cast<float>(sigma)); sb.setDelta(static_cast<float>(delta)); sb.setAllowBreaks(true);
        Arr a;
        std::vector<Line> lines;
        std::vector<Range> idx;
        for (size_t c = 0; c < all.size(); ++c)
        {
            const auto &pts = all[c];
            SCOPED_TRACE(testing::Message() << "cluster " << c << " (" << pts.size() << " points), sigma " << sigma << ", delta " << delta);
            a.precompute(pts);
            const bool partition = sb(pts, a, lines, idx);
            ASSERT_TRUE(fs(pts));
            ASSERT_TRUE(afs(pts));
            expectValidSplitCover(fs, pts, sigma, delta, !partition);
            expectValidSplitCover(afs, pts, sigma, delta, !partition);
            if (!partition)
            {
                ++covers;
                EXPECT_GE(sharedPoints(fs.indices()), 1u);
                EXPECT_FALSE(f(pts));
                EXPECT_FALSE(af(pts));
                EXPECT_TRUE(f.failure().has_value());
            }
        }
    }
    EXPECT_GT(covers, 0u);
}
