// CAR_Segmenter::grabClusterRanges (an addition to RTL's API): the index ranges it gives must name exactly the
// points grabCluster() returns, in the same order, cluster after cluster, whatever the step, the gaps, clusters
// that wrap the seam, or how the two calls are interleaved on one segmenter; traced segmenters included.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include <rtl/seg/CAR_Segmenter.h>
#include <rtl/seg/SegTrace.h>

namespace
{
    template<class V>
    class CarRanges : public ::testing::Test {};
    using Types = ::testing::Types<rtl::VectorND<2, float>, rtl::VectorND<2, double>, rtl::VectorND<3, float>, rtl::VectorND<3, double>>;
    TYPED_TEST_SUITE(CarRanges, Types);

    // A closed scan of `walls` walls (0: 1 to 6 at random) at different ranges with NaN gaps; the first and last walls are at the same range,
    // so the cluster over the seam wraps.
    template<class V>
    std::vector<V> scan(size_t n, std::mt19937 &rng, size_t walls = 0)
    {
        using E = typename V::ElementType;
        std::uniform_real_distribution<double> u(0, 1);
        if (walls == 0) walls = 1 + static_cast<size_t>(u(rng) * 6);
        std::vector<V> pts;
        for (size_t i = 0; i < n; ++i)
        {
            const double a = 2 * M_PI * static_cast<double>(i) / static_cast<double>(n);
            const size_t wall = (i * walls / n) % walls;
            const double r = wall == 0 || wall + 1 == walls ? 3.0 : 3.0 + static_cast<double>(wall) * 0.7;
            typename V::EigenType e = V::EigenType::Zero();
            e[0] = static_cast<E>(r * std::cos(a));
            e[1] = static_cast<E>(r * std::sin(a));
            if (u(rng) < 0.06) e[static_cast<int>(u(rng) * V::dimensionality())] = std::numeric_limits<E>::quiet_NaN();
            pts.push_back(V(e));
        }
        return pts;
    }

    template<class V>
    bool same(const V &a, const V &b) { return std::memcmp(a.data().data(), b.data().data(), sizeof(typename V::ElementType) * V::dimensionality()) == 0; }

    // Expands `ranges` (from `from` on) into the points of `pts` they name.
    template<class V>
    std::vector<V> expand(const std::vector<V> &pts, const std::vector<size_t> &ranges, size_t from = 0)
    {
        std::vector<V> c;
        for (size_t r = from; r < ranges.size(); r += 2)
        {
            EXPECT_LT(ranges[r], ranges[r + 1]);
            EXPECT_LE(ranges[r + 1], pts.size());
            for (size_t i = ranges[r]; i < ranges[r + 1] && i < pts.size(); ++i) c.push_back(pts[i]);
        }
        return c;
    }

    template<class Seg, class V>
    void checkAgainstGrabCluster(Seg &byPoints, Seg &byRanges, const std::vector<V> &pts, const std::string &what)
    {
        size_t clusters = 0;
        std::vector<size_t> ranges{7, 9};   // appended to, never cleared
        while (byPoints.clustersAvailable() > 0)
        {
            ASSERT_EQ(byRanges.clustersAvailable(), byPoints.clustersAvailable()) << what;
            const std::vector<V> expected = byPoints.grabCluster();
            const size_t before = ranges.size();
            const size_t count = byRanges.grabClusterRanges(ranges);
            ASSERT_EQ(count, expected.size()) << what << " cluster " << clusters;
            const std::vector<V> got = expand(pts, ranges, before);
            ASSERT_EQ(got.size(), expected.size()) << what << " cluster " << clusters;
            for (size_t k = 0; k < got.size(); ++k) ASSERT_TRUE(same(got[k], expected[k])) << what << " cluster " << clusters << " point " << k;
            ++clusters;
        }
        EXPECT_EQ(byRanges.clustersAvailable(), 0u) << what;
        const size_t before = ranges.size();
        EXPECT_EQ(byRanges.grabClusterRanges(ranges), 0u) << what;
        EXPECT_EQ(ranges.size(), before) << what << ": nothing appended when no cluster is left";
        EXPECT_EQ(ranges[0], 7u);
        EXPECT_EQ(ranges[1], 9u);
    }

    TYPED_TEST(CarRanges, RangesNameTheGrabbedPoints)
    {
        using V = TypeParam;
        using E = typename V::ElementType;
        std::mt19937 rng(11 + V::dimensionality() + static_cast<unsigned>(sizeof(E)));
        std::uniform_real_distribution<double> u(0, 1);
        size_t wrapped = 0;
        for (int trial = 0; trial < 200; ++trial)
        {
            const size_t n = 1 + static_cast<size_t>(u(rng) * (trial < 20 ? 12 : 600));
            const size_t step = 1 + static_cast<size_t>(u(rng) * 8);
            const std::vector<V> pts = scan<V>(n, rng);
            const E lb = static_cast<E>(0.05 + 0.2 * u(rng)), ub = lb + static_cast<E>(0.5 * u(rng));
            const std::string what = "trial " + std::to_string(trial) + " n=" + std::to_string(n) + " step=" + std::to_string(step);
            rtl::CAR_Segmenter<V> a(step, lb, ub), b(step, lb, ub);
            a.loadData(pts);
            b.loadData(pts);
            // a cluster over the seam lists its end-of-scan range first: its first range starts after its second
            {
                rtl::CAR_Segmenter<V> c(step, lb, ub);
                c.loadData(pts);
                std::vector<size_t> r;
                while (c.clustersAvailable() > 0)
                {
                    r.clear();
                    c.grabClusterRanges(r);
                    if (r.size() >= 4 && r[0] > r[2]) ++wrapped;
                }
            }
            checkAgainstGrabCluster(a, b, pts, what);
            if (::testing::Test::HasFailure()) return;
            // traced: the same clusters through the general window algorithm
            rtl::CarTraceLog log;
            rtl::CAR_Segmenter<V, rtl::CarTraceLog> ta(step, lb, ub), tb(step, lb, ub);
            ta.setObserver(&log);
            tb.setObserver(&log);
            ta.loadData(pts);
            tb.loadData(pts);
            checkAgainstGrabCluster(ta, tb, pts, what + " traced");
            if (::testing::Test::HasFailure()) return;
        }
        EXPECT_GT(wrapped, 10u) << "the scans must exercise clusters that wrap the seam";
    }

    TYPED_TEST(CarRanges, InterleavedWithGrabClusterAndReload)
    {
        using V = TypeParam;
        std::mt19937 rng(5);
        const std::vector<V> pts = scan<V>(400, rng, 6);
        rtl::CAR_Segmenter<V> ref(3, 0.1f, 0.5f), mixed(3, 0.1f, 0.5f);
        ref.loadData(pts);
        mixed.loadData(pts);
        ASSERT_GT(ref.clustersAvailable(), 3u);
        for (int k = 0; ref.clustersAvailable() > 0; ++k)
        {
            const std::vector<V> expected = ref.grabCluster();
            std::vector<V> got;
            if (k % 2 == 0) got = mixed.grabCluster();
            else
            {
                std::vector<size_t> r;
                ASSERT_EQ(mixed.grabClusterRanges(r), expected.size());
                got = expand(pts, r);
            }
            ASSERT_EQ(got.size(), expected.size()) << "cluster " << k;
            for (size_t i = 0; i < got.size(); ++i) ASSERT_TRUE(same(got[i], expected[i])) << "cluster " << k;
        }
        // a new scan after a partial grab replaces the clusters left
        mixed.loadData(pts);
        std::vector<size_t> r;
        ASSERT_GT(mixed.grabClusterRanges(r), 0u);
        mixed.loadData(pts);
        ref.loadData(pts);
        checkAgainstGrabCluster(ref, mixed, pts, "reloaded");
    }
}
