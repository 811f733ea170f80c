// CAR_Segmenter and IA_Segmenter on synthetic scans: known answers (2D arcs, 3D helix), regressions for the known
// defects of the published implementation (docs/reference.md, "Segmentation defects fixed here"), bad input, and random
// scans against a brute-force reference.
#include <cmath>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "rtl/seg/CAR_Segmenter.h"
#include "rtl/seg/IA_Segmenter.h"
#include "rtl/seg/SegTrace.h"
#include "seg_check.h"

namespace
{
    using V2f = rtl::VectorND<2, float>;
    using V2d = rtl::VectorND<2, double>;
    using V3f = rtl::VectorND<3, float>;
    using V3d = rtl::VectorND<3, double>;

    template<class V>
    V nanPoint() { return V::nan(); }

    //! One point per degree around the origin: r = 2 on [0, 90), 5 on [90, 180), 3 on [180, 300), 2 on [300, 360).
    template<class V>
    std::vector<V> arcs(const V &origin = V::zeros())
    {
        std::vector<V> pts;
        for (int i = 0; i < 360; ++i)
        {
            const double r = i < 90 ? 2 : i < 180 ? 5 : i < 300 ? 3 : 2, a = i * M_PI / 180;
            typename V::EigenType e = origin.data();
            e[0] += static_cast<typename V::ElementType>(r * std::cos(a));
            e[1] += static_cast<typename V::ElementType>(r * std::sin(a));
            pts.push_back(V(e));
        }
        return pts;
    }

    std::vector<size_t> range(size_t b, size_t e)
    {
        std::vector<size_t> r;
        for (size_t i = b; i < e; ++i) r.push_back(i);
        return r;
    }

    std::vector<size_t> concat(std::vector<size_t> a, const std::vector<size_t> &b)
    {
        a.insert(a.end(), b.begin(), b.end());
        return a;
    }

    template<class V>
    std::vector<std::vector<size_t>> carIndices(const std::vector<V> &pts, size_t step, typename V::ElementType lb,
                                                typename V::ElementType ub, const V &origin = V::zeros())
    {
        rtl::CAR_Segmenter<V> car(step, lb, ub);
        std::vector<size_t> labels;
        return segcheck::toIndices(pts, segcheck::runCar(car, pts, origin), labels, "car");
    }

    template<class V>
    std::vector<std::vector<size_t>> iaIndices(const std::vector<V> &pts, size_t step, typename V::ElementType lb,
                                               typename V::ElementType ub, typename V::ElementType scaling,
                                               const V &origin = V::zeros(), size_t grab_every = 1)
    {
        rtl::IA_Segmenter<V> ia(step, lb, ub, scaling);
        std::vector<size_t> labels;
        return segcheck::toIndices(pts, segcheck::runIa(ia, pts, origin, step, grab_every, "ia"), labels, "ia");
    }
}

template<class V>
class ArcsTest : public ::testing::Test {};
using PlaneTypes = ::testing::Types<V2f, V2d>;
TYPED_TEST_SUITE(ArcsTest, PlaneTypes);

TYPED_TEST(ArcsTest, KnownBreaks)
{
    using V = TypeParam;
    auto pts = arcs<V>();
    pts[150] = V::nan();
    // CAR step 2 compares the previous point: chords of 0.035 r (< lower bound 0.2); jumps between arcs >= 1
    // (> upper bound 0.5)
    const std::vector<std::vector<size_t>> step1 = {concat(range(300, 360), range(0, 90)), range(90, 150), range(151, 180), range(180, 300)};
    EXPECT_EQ(carIndices(pts, 2, 0.2, 0.5), step1);
    // CAR step 3 compares the two previous points: the gap at 150 is bridged (2 degrees at r = 5: 0.17 < 0.2)
    const std::vector<std::vector<size_t>> step2 = {concat(range(300, 360), range(0, 90)), concat(range(90, 150), range(151, 180)), range(180, 300)};
    EXPECT_EQ(carIndices(pts, 3, 0.2, 0.5), step2);
    // CAR step 1 compares nothing
    EXPECT_EQ(carIndices(pts, 1, 0.2, 0.5).size(), 359u);

    // the stream segmenter (window: the `step` previous points) has no seam and hands clusters out as they close
    const auto s = rtl::detail::circularScaling<typename V::ElementType>(1, 360);
    const std::vector<std::vector<size_t>> stream1 = {range(0, 90), range(90, 150), range(151, 180), range(180, 300), range(300, 360)};
    EXPECT_EQ(iaIndices(pts, 1, 0.2, 0.5, s), stream1);
    EXPECT_EQ(iaIndices(pts, 1, 0.2, 0.5, s, V::zeros(), 0), stream1);
    const std::vector<std::vector<size_t>> stream2 = {range(0, 90), concat(range(90, 150), range(151, 180)), range(180, 300), range(300, 360)};
    EXPECT_EQ(iaIndices(pts, 2, 0.2, 0.5, s), stream2);
}

TYPED_TEST(ArcsTest, AdaptiveThreshold)
{
    using V = TypeParam;
    // step 2, 360 points: threshold scaling 2 * 2 pi / 360. 0.1 m spacing: within the threshold at 10 m (0.35), not
    // at 1 m (0.035)
    std::vector<V> pts;
    for (int i = 0; i < 20; ++i) pts.push_back(V(10, 0.1f * i));
    for (int i = 0; i < 5; ++i) pts.push_back(V(1, -1 + 0.1f * i));
    const auto inf = std::numeric_limits<typename V::ElementType>::infinity();
    std::vector<V> scan = pts;
    for (int i = 0; i < 335; ++i) scan.push_back(V::nan());
    const auto idx = carIndices(scan, 2, 0, inf);
    const std::vector<std::vector<size_t>> expected = {range(0, 20), {20}, {21}, {22}, {23}, {24}};
    EXPECT_EQ(idx, expected);
    // the upper bound caps the threshold at 10 m, the lower bound lifts it at 1 m
    EXPECT_EQ(carIndices(scan, 2, 0, 0.05).size(), 25u);
    EXPECT_EQ(carIndices(scan, 2, 0.15, inf).size(), 2u);
}

template<class V>
class HelixTest : public ::testing::Test {};
using SpaceTypes = ::testing::Types<V3f, V3d>;
TYPED_TEST_SUITE(HelixTest, SpaceTypes);

TYPED_TEST(HelixTest, KnownBreaks)
{
    using V = TypeParam;
    // three turns of 120 points, 1 m rise per turn; radius 4 on [0, 100), 6 on [100, 250), 4 on [250, 360)
    std::vector<V> pts;
    for (int i = 0; i < 360; ++i)
    {
        const double r = (i >= 100 && i < 250) ? 6 : 4, t = 2 * M_PI * i / 120;
        pts.push_back(V(static_cast<typename V::ElementType>(r * std::cos(t)), static_cast<typename V::ElementType>(r * std::sin(t)),
                        static_cast<typename V::ElementType>(i / 120.0)));
    }
    pts[200] = V::nan();
    // neighbours 0.21 m (r = 4) and 0.31 m (r = 6) apart, two places apart 0.63 m at r = 6, all within the lower
    // bound 0.7; radius jumps >= 2 m; the ends are 3 m apart in z, so nothing links across the seam. Windows of one
    // and two previous points: CAR at steps 2 and 3, IA at steps 1 and 2.
    const std::vector<std::vector<size_t>> step1 = {range(0, 100), range(100, 200), range(201, 250), range(250, 360)};
    EXPECT_EQ(carIndices(pts, 2, 0.7, 0.8), step1);
    const std::vector<std::vector<size_t>> step2 = {range(0, 100), concat(range(100, 200), range(201, 250)), range(250, 360)};
    EXPECT_EQ(carIndices(pts, 3, 0.7, 0.8), step2);
    EXPECT_EQ(iaIndices(pts, 1, 0.7, 0.8, 0.01f), step1);
    EXPECT_EQ(iaIndices(pts, 2, 0.7, 0.8, 0.01f), step2);
    const auto car = segcheck::checkCar(pts, V::zeros(), 4, 0.7, 0.8, "helix CAR step 4");
    const auto ia = segcheck::checkIa(pts, V::zeros(), 3, 0.7, 0.8, 1, "helix IA step 3");
    segcheck::checkAgreement(pts, V::zeros(), 3, typename V::ElementType(0.7), typename V::ElementType(0.8), car, ia, "helix");
}

// CAR_Segmenter's window: CAR at step s compares each point with the s - 1 previous points, cyclically; the threshold
// scales with s. IA's window stays the s previous points.
TEST(Regression, CarWindowIsStepMinusOne)
{
    typedef std::vector<std::vector<size_t>> Clusters;
    // 20 places, all gaps but the given points
    auto scan = [](std::initializer_list<std::pair<size_t, V2d>> given) {
        std::vector<V2d> s(20, V2d::nan());
        for (const auto &g : given) s[g.first] = g.second;
        return s;
    };
    // fixed threshold 1 m (lower = upper bound): points 5 and 8, three places apart, are 0.5 m apart
    const auto three = scan({{5, V2d(0, 0)}, {8, V2d(0, 0.5)}});
    EXPECT_EQ(carIndices(three, 3, 1.0, 1.0), (Clusters{{5}, {8}}));
    EXPECT_EQ(carIndices(three, 4, 1.0, 1.0), (Clusters{{5, 8}}));
    EXPECT_EQ(iaIndices(three, 2, 1.0, 1.0, 0.0), (Clusters{{5}, {8}}));
    EXPECT_EQ(iaIndices(three, 3, 1.0, 1.0, 0.0), (Clusters{{5, 8}}));
    // consecutive points: step 1 compares none, step 2 the previous point
    const auto two = scan({{5, V2d(0, 0)}, {6, V2d(0, 0.5)}});
    EXPECT_EQ(carIndices(two, 1, 1.0, 1.0), (Clusters{{5}, {6}}));
    EXPECT_EQ(carIndices(two, 2, 1.0, 1.0), (Clusters{{5, 6}}));
    // across the seam: 17 -> 0 is three places, 18 -> 0 two, 19 -> 0 one
    EXPECT_EQ(carIndices(scan({{0, V2d(0, 0)}, {17, V2d(0, 0.5)}}), 3, 1.0, 1.0), (Clusters{{0}, {17}}));
    EXPECT_EQ(carIndices(scan({{0, V2d(0, 0)}, {17, V2d(0, 0.5)}}), 4, 1.0, 1.0), (Clusters{{17, 0}}));
    EXPECT_EQ(carIndices(scan({{0, V2d(0, 0)}, {18, V2d(0, 0.5)}}), 3, 1.0, 1.0), (Clusters{{18, 0}}));
    EXPECT_EQ(carIndices(scan({{0, V2d(0, 0)}, {19, V2d(0, 0.5)}}), 1, 1.0, 1.0), (Clusters{{0}, {19}}));
    EXPECT_EQ(carIndices(scan({{0, V2d(0, 0)}, {19, V2d(0, 0.5)}}), 2, 1.0, 1.0), (Clusters{{19, 0}}));
    // a default segmenter links consecutive points (step 2)
    rtl::CAR_Segmenter<V2d> by_default;
    by_default.setLowerBound(1.0);
    by_default.setUpperBound(1.0);
    by_default.loadData(two);
    EXPECT_EQ(by_default.clustersAvailable(), 1u);
    // the threshold is step * 2 pi / N * range, not (step - 1) * ...: at step 2, point 6 (range 11.2) has threshold
    // 7.0 (3.5 with one step), 5 m from point 5; at step 3, point 7 (range 13.5) has 12.7 (8.5), 9 m from point 5
    const double inf = std::numeric_limits<double>::infinity();
    EXPECT_EQ(carIndices(scan({{5, V2d(10, 0)}, {6, V2d(10, 5)}}), 2, 0.0, inf), (Clusters{{5, 6}}));
    EXPECT_EQ(carIndices(scan({{5, V2d(10, 0)}, {7, V2d(10, 9)}}), 3, 0.0, inf), (Clusters{{5, 7}}));
    EXPECT_EQ(carIndices(scan({{5, V2d(10, 0)}, {7, V2d(10, 40)}}), 3, 0.0, inf), (Clusters{{5}, {7}}));   // 38.9 < 40
}

// Published defect 1 (see the file comment): a point that links two long clusters merges them completely.
TEST(Regression, RetroactiveMergeIsComplete)
{
    // two previous points compared (CAR step 3, IA step 2): even indices on y = 0, odd indices on y = 1.5, 0.5 m
    // apart along x; fixed threshold 1 m. Two chains that never touch, until index 40, half-way between them, links
    // both.
    std::vector<V2d> pts;
    for (int i = 0; i < 80; ++i) pts.push_back(i == 40 ? V2d(0.25 * i, 0.75) : V2d(0.25 * i, (i % 2) ? 1.5 : 0.0));
    const auto car = carIndices(pts, 3, 1.0, 1.0);
    ASSERT_EQ(car.size(), 1u);
    EXPECT_EQ(car[0], range(0, 80));
    const auto ia = iaIndices(pts, 2, 1.0, 1.0, 1.0);
    ASSERT_EQ(ia.size(), 1u);
    EXPECT_EQ(ia[0], range(0, 80));
    // without the bridge: the odd chain, the even chain cut in two at 40, and 40 alone
    pts[40] = V2d(0.25 * 40, 100);
    EXPECT_EQ(carIndices(pts, 3, 1.0, 1.0).size(), 4u);
}

// Published defect 2: the seam uses the origin, compares point 0 with point N - 1, and rotates at the right index.
TEST(Regression, SeamUsesOriginAndLastPoint)
{
    const V2d o(100, 50);
    // 8 points, step 2 (the previous point): scaling 2 * 2 pi / 8 = 1.571. Points 1..6 are 20 m apart (singletons
    // with upper bound 5).
    std::vector<V2d> pts;
    for (int i = 0; i < 8; ++i) pts.push_back(V2d(o.x(), o.y() + 20.0 * i));
    pts[0] = V2d(o.x() + 1, o.y());
    pts[7] = V2d(o.x() + 1, o.y() + 2);     // 2 m from point 0: over 1.571 * |p0 - o| = 1.571, under 1.571 * |p0| = 176
    EXPECT_EQ(carIndices(pts, 2, 0, 5, o).size(), 8u);
    pts[7] = V2d(o.x() + 1, o.y() + 0.5);   // 0.5 m: linked through the seam, the end part first
    const auto idx = carIndices(pts, 2, 0, 5, o);
    ASSERT_EQ(idx.size(), 7u);
    EXPECT_EQ(idx[0], (std::vector<size_t>{7, 0}));
    segcheck::checkCar(pts, o, 2, 0.0, 5.0, "seam origin");
}

TEST(Regression, WrappedClusterRotatesAtTheSeam)
{
    auto pts = arcs<V2f>(V2f(3, -2));
    pts[359] = V2f::nan();
    pts[0] = V2f::nan();
    // step 4 (three previous points) bridges 358 -> 1 (three places across the seam), step 3 does not
    const auto idx = carIndices(pts, 4, 0.2, 0.5, V2f(3, -2));
    ASSERT_EQ(idx.size(), 3u);
    EXPECT_EQ(idx[0], concat(range(300, 359), range(1, 90)));
    EXPECT_EQ(idx[1], range(90, 180));
    EXPECT_EQ(idx[2], range(180, 300));
    EXPECT_EQ(carIndices(pts, 3, 0.2, 0.5, V2f(3, -2)).size(), 4u);
}

// Found by fuzz_seg_car: at step 2 a scan that is two adjacent runs joined only across the seam (0 - 1 linked,
// 1 - 2 not, 2 - 0 linked) came out as (2, 0, 1) untraced but (0, 1, 2) traced (the general algorithm). A cluster
// that covers every index without a skip is listed in increasing order by every path.
TEST(Regression, SeamJoinedRunsCoveringTheScanStayInOrder)
{
    const std::vector<V2d> pts = {V2d(0.09375, 3.75), V2d(0.0625, 3.71875), V2d(0.125, 3.75)};
    for (size_t step : {2, 3})
    {
        rtl::CAR_Segmenter<V2d> car(step, 0.03125, 0.0625);
        rtl::CarTraceLog log;
        rtl::CAR_Segmenter<V2d, rtl::CarTraceLog> traced(step, 0.03125, 0.0625);
        traced.setObserver(&log);
        traced.loadData(pts);
        car.loadData(pts);
        ASSERT_EQ(car.clustersAvailable(), 1u) << step;
        const auto c = car.grabCluster(), t = traced.grabCluster();
        EXPECT_EQ(c, pts) << step;
        EXPECT_EQ(t, pts) << step;
    }
    // with a gap between the runs the joined cluster wraps: end part first
    const std::vector<V2d> gapped = {pts[0], pts[1], V2d::nan(), pts[2]};
    rtl::CAR_Segmenter<V2d> car(2, 0.03125, 0.0625);
    car.loadData(gapped);
    ASSERT_EQ(car.clustersAvailable(), 1u);
    EXPECT_EQ(car.grabCluster(), (std::vector<V2d>{pts[2], pts[0], pts[1]}));
}

// Published defect 3: one segmenter object, growing and shrinking clouds, no setMaxSize.
TEST(Regression, LargerCloudWithoutSetMaxSize)
{
    std::mt19937 rng(3);
    std::normal_distribution<double> noise(0, 0.05);
    for (size_t step : {1, 2, 4})
    {
        rtl::CAR_Segmenter<V2d> car(step, 0.1, 0.5);
        for (size_t n : {10, 100000, 5, 200000, 1, 20000})
        {
            std::vector<V2d> pts(n);
            for (size_t i = 0; i < n; ++i)
            {
                const double a = 2 * M_PI * static_cast<double>(i) / static_cast<double>(n), r = 5 + ((i / 1000) % 3) + noise(rng);
                pts[i] = V2d(r * std::cos(a), r * std::sin(a));
            }
            const auto clusters = segcheck::runCar(car, pts, V2d::zeros());
            size_t total = 0;
            for (const auto &c : clusters) total += c.size();
            EXPECT_EQ(total, n);
            if (n <= 20000) segcheck::checkCar(pts, V2d::zeros(), step, 0.1, 0.5, "regrow n=" + std::to_string(n));
        }
    }
}

// Published defect 4: nothing stuck or lost in the stream segmenter, whatever the grab pattern.
TEST(Regression, StreamLosesNothingWhateverTheGrabPattern)
{
    std::mt19937 rng(4);
    std::uniform_real_distribution<float> u(0, 1);
    std::vector<V2f> pts;
    for (int i = 0; i < 3000; ++i)
    {
        const float r = 3 + (i % 7 == 0 ? 2.f : 0.f) + 0.3f * u(rng), a = i * 0.002f;
        pts.push_back(u(rng) < 0.05f ? V2f::nan() : V2f(r * std::cos(a), r * std::sin(a)));
    }
    for (size_t step : {1, 2, 4, 7})
    {
        const auto s = rtl::detail::circularScaling<float>(step, pts.size());
        const auto every = iaIndices(pts, step, 0.05f, 0.4f, s, V2f::zeros(), 1);
        EXPECT_EQ(iaIndices(pts, step, 0.05f, 0.4f, s, V2f::zeros(), 0), every);
        EXPECT_EQ(iaIndices(pts, step, 0.05f, 0.4f, s, V2f::zeros(), 37), every);
        // the batch segmenter with the same window: CAR at step + 1
        const auto ia = segcheck::checkIa(pts, V2f::zeros(), step, 0.05f, 0.4f, 1, "stream step " + std::to_string(step));
        const auto car = segcheck::checkCar(pts, V2f::zeros(), step + 1, 0.05f, 0.4f, "batch step " + std::to_string(step + 1));
        segcheck::checkAgreement(pts, V2f::zeros(), step, 0.05f, 0.4f, car, ia, "agreement step " + std::to_string(step));
    }
}

TEST(Stream, AliveClustersAndStepChanges)
{
    // two far apart lines, alternating: with step 2 both clusters stay open, with step 1 every point is alone
    rtl::IA_Segmenter<V2d> ia(2, 0.5, 0.5, 0.0);
    for (int i = 0; i < 10; ++i) ia.addPoint(V2d(0.1 * i, (i % 2) ? 10.0 : 0.0));
    EXPECT_EQ(ia.closedClustersAvailable(), 0u);
    ASSERT_EQ(ia.aliveClustersAvailable(), 2u);
    const auto &alive = ia.aliveClusters();
    EXPECT_EQ(alive.begin()->first, 0u);
    EXPECT_EQ(alive.begin()->second.size(), 4u);   // 0, 2, 4, 6 (8 is in the window)
    EXPECT_DOUBLE_EQ(alive.begin()->second.back().x(), 0.6);
    EXPECT_EQ(std::next(alive.begin())->first, 1u);
    // shrinking the window pushes point 8 out; the next point joins neither cluster, so both close
    ia.setStepSize(1);
    EXPECT_EQ(ia.closedClustersAvailable(), 1u);   // the even cluster (its last point left the window)
    ia.addPoint(V2d(5, 5));
    EXPECT_EQ(ia.closedClustersAvailable(), 2u);
    EXPECT_EQ(ia.grabCluster().size(), 5u);
    EXPECT_EQ(ia.grabCluster().size(), 5u);
    ia.setStepSize(0);                              // treated as 1
    ia.flush();
    EXPECT_EQ(ia.grabCluster().size(), 1u);
    EXPECT_TRUE(ia.grabCluster().empty());
    EXPECT_EQ(ia.aliveClustersAvailable(), 0u);
}

TEST(Stream, LongClustersStayInOrder)
{
    // clusters longer than the step-1 staging block, observed while they grow, with step changes mid-cluster
    rtl::IA_Segmenter<V2d> ia(1, 0.05, 0.05, 0.0);
    auto point = [](int i) { return i < 1000 ? V2d(0.01 * i, 0) : V2d(0.01 * i, 5); };
    for (int i = 0; i < 1700; ++i)
    {
        if (i == 800) ia.setStepSize(3);
        if (i == 900) ia.setStepSize(1);
        ia.addPoint(point(i));
        if (i == 600 || i == 850 || i == 1500)
        {
            ASSERT_EQ(ia.aliveClustersAvailable(), 1u);
            const auto &c = ia.aliveClusters().begin()->second;
            const size_t window = i == 850 ? 3 : 1, first = i < 1000 ? 0 : 1000;
            ASSERT_EQ(c.size(), static_cast<size_t>(i) + 1 - window - first);
            for (size_t k = 0; k < c.size(); ++k) ASSERT_EQ(c[k], point(static_cast<int>(first + k))) << k;
        }
    }
    ia.flush();
    const auto a = ia.grabCluster(), b = ia.grabCluster();
    ASSERT_EQ(a.size(), 1000u);
    ASSERT_EQ(b.size(), 700u);
    for (int i = 0; i < 1000; ++i) ASSERT_EQ(a[static_cast<size_t>(i)], point(i));
    for (int i = 0; i < 700; ++i) ASSERT_EQ(b[static_cast<size_t>(i)], point(1000 + i));
}

TEST(BadInput, EmptySingleAllNan)
{
    rtl::CAR_Segmenter<V2f> car;
    car.loadData({});
    EXPECT_EQ(car.clustersAvailable(), 0u);
    EXPECT_TRUE(car.grabCluster().empty());
    car.loadData({V2f(1, 2)});
    ASSERT_EQ(car.clustersAvailable(), 1u);
    EXPECT_EQ(car.grabCluster().size(), 1u);
    car.loadData({V2f::nan()});
    EXPECT_EQ(car.clustersAvailable(), 0u);
    car.loadData(std::vector<V2f>(100, V2f::nan()));
    EXPECT_EQ(car.clustersAvailable(), 0u);
    rtl::CAR_Segmenter<V3f> car3(4, 0.1f, 1.f);
    car3.loadData(std::vector<V3f>(50, V3f::nan()));
    EXPECT_EQ(car3.clustersAvailable(), 0u);
    car3.loadData({V3f(1, 2, 3), V3f(1, 2, 3.01f)});     // fewer points than the step
    EXPECT_EQ(car3.clustersAvailable(), 1u);
    // infinite coordinates are gaps too
    const float inf = std::numeric_limits<float>::infinity();
    car.loadData({V2f(inf, 0), V2f(inf, 0), V2f(1, 0)});
    ASSERT_EQ(car.clustersAvailable(), 1u);
    EXPECT_EQ(car.grabCluster().size(), 1u);

    rtl::IA_Segmenter<V2f> ia;
    ia.flush();
    EXPECT_TRUE(ia.grabCluster().empty());
    ia.addPoint(V2f(1, 2));
    EXPECT_EQ(ia.closedClustersAvailable(), 0u);
    ia.flush();
    EXPECT_EQ(ia.grabCluster().size(), 1u);
    for (int i = 0; i < 100; ++i) ia.addPoint(V2f::nan());
    ia.flush();
    EXPECT_EQ(ia.closedClustersAvailable(), 0u);
    EXPECT_EQ(ia.aliveClustersAvailable(), 0u);
}

TEST(BadInput, BoundsStepAndOrigin)
{
    const std::vector<V2d> pts = {V2d(1, 1), V2d(1, 1), V2d(1, 1.001), V2d(1, 1.001), V2d(4, 4)};
    // zero bounds: only coincident points are close
    EXPECT_EQ(carIndices(pts, 2, 0, 0), (std::vector<std::vector<size_t>>{{0, 1}, {2, 3}, {4}}));
    EXPECT_EQ(iaIndices(pts, 1, 0, 0, 1), (std::vector<std::vector<size_t>>{{0, 1}, {2, 3}, {4}}));
    // step 0 is step 1, which compares nothing
    EXPECT_EQ(carIndices(pts, 0, 0.01, 0.01), (std::vector<std::vector<size_t>>{{0}, {1}, {2}, {3}, {4}}));
    EXPECT_EQ(carIndices(pts, 1, 0.01, 0.01), (std::vector<std::vector<size_t>>{{0}, {1}, {2}, {3}, {4}}));
    EXPECT_EQ(iaIndices(pts, 0, 0.01, 0.01, 1), iaIndices(pts, 1, 0.01, 0.01, 1));

    rtl::CAR_Segmenter<V2d> car(1, 2, 1);
    EXPECT_THROW(car.loadData(pts), std::invalid_argument);   // inverted bounds
    car.setLowerBound(-1);
    EXPECT_THROW(car.loadData(pts), std::invalid_argument);   // negative lower bound
    car.setLowerBound(std::nan(""));
    EXPECT_THROW(car.loadData(pts), std::invalid_argument);
    car.setLowerBound(0);
    car.setUpperBound(std::numeric_limits<double>::infinity());
    EXPECT_THROW(car.loadData(pts, V2d::nan()), std::invalid_argument);
    // step 2, threshold 2 * 2 pi / 5 * |p - origin| from (1, 1): 0 for point 0 (so no seam link from 4), 0.0025 for
    // 2, 10.7 for 4
    car.setStepSize(2);
    car.loadData(pts, V2d(1, 1));
    EXPECT_EQ(car.clustersAvailable(), 1u);

    rtl::IA_Segmenter<V2d> ia(1, 2, 1, 1);
    EXPECT_THROW(ia.addPoint(pts[0]), std::invalid_argument);
    ia.setLowerBound(0);
    ia.setScaling(std::nan(""));
    EXPECT_THROW(ia.addPoint(pts[0]), std::invalid_argument);
    ia.setScaling(1);
    EXPECT_THROW(ia.addPoint(pts[0], V2d::nan()), std::invalid_argument);
    ia.addPoint(pts[0]);
    ia.flush();
    EXPECT_EQ(ia.closedClustersAvailable(), 1u);
}

namespace
{
    // A point with one non-finite coordinate (any of them: addPoint starts its sums with the first) is a gap; an
    // origin with one is refused.
    template<class V>
    void iaOneNonFiniteCoordinate()
    {
        using E = typename V::ElementType;
        const E bad[] = {std::numeric_limits<E>::quiet_NaN(), std::numeric_limits<E>::infinity(), -std::numeric_limits<E>::infinity()};
        for (int k = 0; k < V::dimensionality(); ++k)
            for (E b : bad)
            {
                typename V::EigenType e = V::zeros().data();
                e[0] = 1;
                const V p0(e), p2(e);
                e[k] = b;
                const V gap(e);
                rtl::IA_Segmenter<V> ia(2, E(0.1), E(0.1), E(0));
                ia.addPoint(p0);
                ia.addPoint(gap);
                ia.addPoint(p2);   // links to p0 across the gap
                ia.flush();
                ASSERT_EQ(ia.closedClustersAvailable(), 1u) << "coordinate " << k << " value " << b;
                EXPECT_EQ(ia.grabCluster(), (std::vector<V>{p0, p2})) << "coordinate " << k << " value " << b;
                EXPECT_THROW(ia.addPoint(p0, gap), std::invalid_argument) << "coordinate " << k << " value " << b;
            }
    }
}

TEST(BadInput, IaOneNonFiniteCoordinateIsAGap)
{
    iaOneNonFiniteCoordinate<V2f>();
    iaOneNonFiniteCoordinate<V3d>();
}

TEST(BadInput, LoadDataReplacesPreviousResult)
{
    rtl::CAR_Segmenter<V2f> car(2, 0.1f, 0.1f);
    car.loadData({V2f(0, 0), V2f(5, 5), V2f(9, 9)});
    EXPECT_EQ(car.clustersAvailable(), 3u);
    car.grabCluster();
    car.loadData({V2f(0, 0), V2f(0, 0.05f)});
    ASSERT_EQ(car.clustersAvailable(), 1u);
    EXPECT_EQ(car.grabCluster().size(), 2u);
    EXPECT_EQ(car.clustersAvailable(), 0u);
}

// Random scans (runs, jumps, gaps, interleaved chains) against the brute-force reference: CAR at steps 1..7, IA at
// CAR's step - 1 (the same window) with CAR's scaling.
template<class V>
class RandomScans : public ::testing::Test {};
using AllTypes = ::testing::Types<V2f, V2d, V3f, V3d>;
TYPED_TEST_SUITE(RandomScans, AllTypes);

TYPED_TEST(RandomScans, MatchReference)
{
    using V = TypeParam;
    using E = typename V::ElementType;
    constexpr int D = V::dimensionality();
    std::mt19937 rng(42 + D);
    std::uniform_real_distribution<double> u(0, 1);
    for (int trial = 0; trial < 150; ++trial)
    {
        const size_t n = 1 + static_cast<size_t>(u(rng) * (trial < 20 ? 8 : 300));
        const size_t step = 1 + static_cast<size_t>(u(rng) * 7);
        const double interleave = u(rng) < 0.3 ? 1.5 : 0.0;
        typename V::EigenType oe;
        for (int d = 0; d < D; ++d) oe[d] = static_cast<E>(u(rng) * 4 - 2);
        const V origin(oe);
        std::vector<V> pts;
        double r = 2 + 3 * u(rng);
        for (size_t i = 0; i < n; ++i)
        {
            if (u(rng) < 0.05) r = 2 + 3 * u(rng);                         // jump
            r += 0.02 * (u(rng) - 0.5);
            const double a = 2 * M_PI * static_cast<double>(i) / static_cast<double>(n);
            const double rr = r + ((i % 2) ? interleave : 0.0);           // two interleaved chains
            typename V::EigenType e = origin.data();
            e[0] += static_cast<E>(rr * std::cos(a));
            e[1] += static_cast<E>(rr * std::sin(a));
            if (D == 3) e[D - 1] += static_cast<E>(0.1 * u(rng));
            pts.push_back(u(rng) < 0.08 ? V::nan() : V(e));
        }
        const E lb = static_cast<E>(0.2 * u(rng)), ub = lb + static_cast<E>(u(rng) < 0.2 ? 10.0 : 0.5 * u(rng));
        const std::string what = "trial " + std::to_string(trial) + " n=" + std::to_string(n) + " step=" + std::to_string(step);
        const auto car = segcheck::checkCar(pts, origin, step, lb, ub, what);
        if (step >= 2)
        {
            const auto ia = segcheck::checkIa(pts, origin, step - 1, lb, ub, trial % 3 == 0 ? 1 : 5, what);
            segcheck::checkAgreement(pts, origin, step - 1, lb, ub, car, ia, what);
        }
        if (::testing::Test::HasFailure()) return;
    }
}
