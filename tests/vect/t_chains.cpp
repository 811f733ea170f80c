// Extractors, optimizers, postprocessors and the Vectorizer classes on synthetic chains: semicircles, polygons
// with known corners, staircases, helices and box faces; bad input; the known defects of the
// published version (docs/reference.md, "Vectorization defects fixed here").
#include <atomic>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <new>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "rtl/Vectorization.h"
#include "vect_reference.h"

using namespace vect_test;

// Counts heap allocations through operator new (std::vector and friends), to check buffer reuse. GCC cannot see
// that the replaced operator new and delete pair malloc with free.
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic ignored "-Wmismatched-new-delete"
#endif
static std::atomic<size_t> g_allocations{0};
void *operator new(std::size_t n)
{
    ++g_allocations;
    if (void *p = std::malloc(n ? n : 1))
        return p;
    throw std::bad_alloc();
}
void operator delete(void *p) noexcept { std::free(p); }
void operator delete(void *p, std::size_t) noexcept { std::free(p); }

namespace
{
    typedef rtl::ApproximationTlsLine2D<float, double> Line2;
    typedef rtl::ApproximationTlsLine3D<float, double> Line3;
    typedef rtl::ApproximationTlsPlane3D<float, double> Plane3;
    typedef rtl::PrecArray2D<float, double> Arr2;
    typedef rtl::PrecArray3D<float, double> Arr3;

    //! Total squared orthogonal residual of all ranges (reference fits).
    template<int d, typename E>
    double totalLineSsr(const std::vector<rtl::VectorND<d, E>> &pts, const std::vector<Range> &idx)
    {
        double s = 0;
        for (const auto &r : idx)
            s += refFit<d>(pts, r.first, r.second).lineErr() * static_cast<double>(r.second - r.first);
        return s;
    }

    //! Each 2D approximation equals the reference fit of exactly its range (1e-9 relative to the data scale).
    void expectLinesMatchRanges(const std::vector<rtl::Vector2f> &pts, const std::vector<Line2> &lines, const std::vector<Range> &idx, double scale)
    {
        ASSERT_EQ(lines.size(), idx.size());
        for (size_t i = 0; i < idx.size(); ++i)
        {
            const auto f = refFit<2>(pts, idx[i].first, idx[i].second);
            EXPECT_LT((lines[i].point().data().cast<double>() - f.mean).norm(), 1e-6 * scale) << i;   // float accessor
            EXPECT_NEAR(lines[i].errSquaredCompute(), f.values(0), 1e-9 * scale * scale) << i;
            if (f.values(1) > 1e3 * f.values(0) + 1e-12)
            {
                const Eigen::Vector2d dir = lines[i].direction().data().cast<double>();
                EXPECT_LT(std::min((dir - f.major()).norm(), (dir + f.major()).norm()), 1e-6) << i;   // float accessor
            }
        }
    }

    //! Polyline checks: n + 1 vertices, each interior vertex on both lines and within delta of the boundary midpoint.
    template<class V>
    void expectPolyline(const V &vec, const std::vector<rtl::Vector2f> &pts, double delta)
    {
        const auto &idx = vec.indices();
        const auto &v = vec.vertices();
        ASSERT_EQ(v.size(), idx.size() + 1);
        ASSERT_EQ(vec.lineSegments().size(), idx.size());
        for (size_t i = 0; i + 1 < idx.size(); ++i)
        {
            const size_t m = idx[i].second;
            const Eigen::Vector2d mid = (pts[m - 1].data().cast<double>() + pts[m].data().cast<double>()) / 2;
            EXPECT_LE((v[i + 1].data().template cast<double>() - mid).norm(), delta * (1 + 1e-6)) << "vertex " << i + 1;
            for (size_t k : {i, i + 1})
            {
                const auto &l = vec.approximations()[k];
                const double dist = std::abs(double(l.a()) * v[i + 1].x() + double(l.b()) * v[i + 1].y() + double(l.c()));
                EXPECT_LT(dist, 1e-4) << "vertex " << i + 1 << " off line " << k;
            }
        }
    }

    template<class V>
    void expectValid2D(V &vec, const std::vector<rtl::Vector2f> &pts, double sigma, double delta)
    {
        ASSERT_TRUE(vec(pts));
        expectPartition(vec.indices(), pts.size());
        expectLineRms(pts, vec.indices(), sigma);
        expectLinesMatchRanges(pts, vec.approximations(), vec.indices(), 10.0);
        expectPolyline(vec, pts, delta);
    }

    std::vector<rtl::Vector2f> staircase(size_t steps, size_t per_step, double rise, double noise, unsigned seed)
    {
        std::mt19937 gen(seed);
        std::normal_distribution<double> nd(0, noise);
        std::vector<rtl::Vector2f> pts;
        for (size_t s = 0; s < steps; ++s)
            for (size_t k = 0; k < per_step; ++k)
                pts.emplace_back(static_cast<float>(static_cast<double>(s) + static_cast<double>(k) / static_cast<double>(per_step) + nd(gen)),
                                 static_cast<float>(rise * static_cast<double>(s) + nd(gen)));
        return pts;
    }
}

TEST(ExtractorChainFast, SemicirclePartitionRmsAndFits)
{
    for (size_t n : {10u, 100u, 1000u, 20000u})
    {
        const auto pts = semicircle(n, 0.01, static_cast<unsigned>(n));
        Arr2 arr;
        arr.precompute(pts);
        rtl::ExtractorChainFast<Arr2, Line2> ex;
        ex.setSigma(0.03f);
        std::vector<Line2> lines(3);
        std::vector<Range> idx(2);
        ASSERT_TRUE(ex(arr, lines, idx));
        expectPartition(idx, n);
        expectLineRms(pts, idx, 0.03);
        expectLinesMatchRanges(pts, lines, idx, 10.0);
        // Locally maximal ranges: adding the next point breaks sigma (except at the chain end and where a range
        // was shortened by one point to avoid a single-point tail).
        for (size_t i = 0; i + 1 < idx.size(); ++i)
        {
            if (idx[i].second + 1 == n - 1 || idx[i].second + 2 == n)
                continue;
            EXPECT_GT(refFit<2>(pts, idx[i].first, idx[i].second + 1).values(0), 0.03 * 0.03 * (1 - 1e-6)) << n << " " << i;
        }
    }
}

TEST(ExtractorChainIncremental, SemicirclePartitionRmsAndFits)
{
    for (size_t n : {10u, 100u, 1000u, 20000u})
    {
        const auto pts = semicircle(n, 0.01, static_cast<unsigned>(n) + 1);
        rtl::ExtractorChainIncremental<Line2> ex;
        ex.setSigma(0.03f);
        std::vector<Line2> lines;
        std::vector<Range> idx;
        ASSERT_TRUE(ex(pts, lines, idx));
        expectPartition(idx, n);
        expectLineRms(pts, idx, 0.03);
        expectLinesMatchRanges(pts, lines, idx, 10.0);
        // Incremental semantics: every closed range would break sigma with its next point.
        for (size_t i = 0; i + 1 < idx.size(); ++i)
            if (idx[i].second + 1 < n)
            {
                EXPECT_GE(refFit<2>(pts, idx[i].first, idx[i].second + 1).values(0), 0.03 * 0.03 * (1 - 1e-6)) << n << " " << i;
            }
    }
}

TEST(VectorizerFTLS, SemicircleAllVectorizersValid)
{
    for (size_t n : {10u, 57u, 1000u, 20000u})
    {
        const auto pts = semicircle(n, 0.01, 100 + static_cast<unsigned>(n));
        rtl::VectorizerFTLSPolyline2D<float, double> f;
        f.setSigma(0.03f);
        f.setDelta(3.f);
        expectValid2D(f, pts, 0.03, 3.0);
        rtl::VectorizerAFTLSPolyline2D<float, double> af;
        af.setSigma(0.03f);
        af.setDelta(3.f);
        expectValid2D(af, pts, 0.03, 3.0);
        // AFTLS never has a larger total squared error than FTLS on the same input.
        EXPECT_LE(totalLineSsr(pts, af.indices()), totalLineSsr(pts, f.indices()) * (1 + 1e-9)) << n;
        EXPECT_LE(af.indices().size(), f.indices().size());

        rtl::VectorizerITLSProjections2D<float, double> it;
        it.setSigma(0.03f);
        ASSERT_TRUE(it(pts));
        expectPartition(it.indices(), n);
        expectLineRms(pts, it.indices(), 0.03);
        ASSERT_EQ(it.lineSegments().size(), it.indices().size());
        for (size_t i = 0; i < it.indices().size(); ++i)
        {
            // Projected end points: within a few sigma of the range's first/last point.
            EXPECT_LT((it.lineSegments()[i].beg() - pts[it.indices()[i].first]).length(), 0.2f);
            EXPECT_LT((it.lineSegments()[i].end() - pts[it.indices()[i].second - 1]).length(), 0.2f);
        }
    }
}

TEST(VectorizerFTLS, PolygonsWithKnownCorners)
{
    const std::vector<std::vector<Eigen::Vector2d>> shapes{
        {{0, 0}, {4, 0}, {4, 3}, {0, 3}, {0, 0.2}},                         // open square
        {{-2, 1}, {1, 1}, {1, -2}},                                          // L
        {{0, 0}, {1, 1.5}, {2, 0}, {3, 1.5}, {4, 0}, {5, 1.5}},             // zigzag
        {{0, 0}, {3, 0.3}, {5, 2}, {5.5, 5}}};                               // gently turning
    unsigned seed = 1;
    for (const auto &corners : shapes)
    {
        const auto pts = polylineSamples(corners, 0.01, 0.005, seed++);
        rtl::VectorizerFTLSPolyline2D<float, double> f;
        rtl::VectorizerAFTLSPolyline2D<float, double> af;
        f.setSigma(0.03f); f.setDelta(3.f);
        af.setSigma(0.03f); af.setDelta(3.f);
        expectValid2D(f, pts, 0.03, 3.0);
        expectValid2D(af, pts, 0.03, 3.0);
        for (const auto *v : {&f.vertices(), &af.vertices()})
        {
            ASSERT_EQ(v->size(), corners.size()) << "one segment per side";
            for (size_t i = 0; i < corners.size(); ++i)
                EXPECT_LT(((*v)[i].data().cast<double>() - corners[i]).norm(), 0.1) << "corner " << i;   // ~3 sigma
        }
        rtl::VectorizerITLSProjections2D<float, double> it;
        it.setSigma(0.03f);
        ASSERT_TRUE(it(pts));
        EXPECT_LE(it.indices().size(), corners.size() + 2);
    }
}

// Published defect 1: a noise-free L along the axes made FTLS and AFTLS return false.
TEST(VectorizerFTLS, NoiseFreeAxisAlignedL)
{
    std::vector<rtl::Vector2f> pts;
    for (int i = 0; i <= 50; ++i) pts.emplace_back(static_cast<float>(i) * 0.1f, 0.f);
    for (int i = 1; i <= 50; ++i) pts.emplace_back(5.f, static_cast<float>(i) * 0.1f);
    rtl::VectorizerFTLSPolyline2D<float, double> f;
    rtl::VectorizerAFTLSPolyline2D<float, double> af;
    f.setSigma(0.03f); f.setDelta(3.f);
    af.setSigma(0.03f); af.setDelta(3.f);
    expectValid2D(f, pts, 0.03, 3.0);
    expectValid2D(af, pts, 0.03, 3.0);
    for (const auto *v : {&f.vertices(), &af.vertices()})
    {
        ASSERT_EQ(v->size(), 3u);
        // FTLS ranges may take a point or two of the other leg while within sigma, tilting the line slightly.
        EXPECT_NEAR((*v)[1].x(), 5.f, 0.05);
        EXPECT_NEAR((*v)[1].y(), 0.f, 0.05);
    }
}

// Published defects 3 and 4: parallel consecutive lines (no crossing) made the published continuity optimizer
// split ranges across the jump (RMS far above sigma) or give up on short pairs.
TEST(OptimizerContinuity2D, StaircasesStayValid)
{
    for (size_t per_step : {4u, 5u, 8u, 40u})
        for (double rise : {0.2, 1.0})
        {
            const auto pts = staircase(6, per_step, rise, 0.002, static_cast<unsigned>(per_step));
            rtl::VectorizerFTLSPolyline2D<float, double> f;
            rtl::VectorizerAFTLSPolyline2D<float, double> af;
            f.setSigma(0.03f); f.setDelta(0.5f);
            af.setSigma(0.03f); af.setDelta(0.5f);
            SCOPED_TRACE(testing::Message() << "per_step " << per_step << " rise " << rise);
            expectValid2D(f, pts, 0.03, 0.5);
            expectValid2D(af, pts, 0.03, 0.5);
        }
}

TEST(OptimizerContinuity2D, DirectUseAndBadInput)
{
    const auto pts = polylineSamples({{0, 0}, {2, 0}, {2, 2}}, 0.05, 0.0, 3);
    Arr2 arr;
    arr.precompute(pts);
    rtl::ExtractorChainFast<Arr2, Line2> ex;
    ex.setSigma(0.01f);
    std::vector<Line2> lines;
    std::vector<Range> idx;
    ASSERT_TRUE(ex(arr, lines, idx));
    rtl::OptimizerContinuity2D<Arr2, Line2> opt;
    opt.setDelta(0.1f);
    opt.setSigma(0.01f);
    EXPECT_TRUE(opt(pts, arr, lines, idx));
    expectPartition(idx, pts.size());
    std::vector<Line2> fewer(lines.begin(), lines.end() - 1);
    EXPECT_FALSE(opt(pts, arr, fewer, idx));
    opt.setDelta(0.f);
    EXPECT_FALSE(opt(pts, arr, lines, idx));
}

TEST(OptimizerTotalError, NeverWorseAndKeepsSigma)
{
    std::mt19937 gen(5);
    for (int trial = 0; trial < 30; ++trial)
    {
        const size_t n = 200 + static_cast<size_t>(trial) * 300;
        const auto pts = trial % 2 ? semicircle(n, 0.01, static_cast<unsigned>(trial))
                                   : polylineSamples({{0, 0}, {3, 0.5}, {4, 3}, {1, 5}, {-2, 4}}, 15.0 / static_cast<double>(n), 0.01, static_cast<unsigned>(trial));
        Arr2 arr;
        arr.precompute(pts);
        rtl::ExtractorChainFast<Arr2, Line2> ex;
        ex.setSigma(0.03f);
        std::vector<Line2> lines;
        std::vector<Range> idx;
        ASSERT_TRUE(ex(arr, lines, idx));
        const double before = totalLineSsr(pts, idx);
        rtl::OptimizerTotalError<Arr2, Line2> opt;
        opt.setSigma(0.03f);
        opt.setSimplexShift(static_cast<size_t>(trial % 3));   // 0 is treated as 1
        ASSERT_TRUE(opt(pts, arr, lines, idx));
        expectPartition(idx, pts.size());
        expectLineRms(pts, idx, 0.03);
        expectLinesMatchRanges(pts, lines, idx, 10.0);
        EXPECT_LE(totalLineSsr(pts, idx), before * (1 + 1e-9)) << trial;
    }
    // Fewer than 2 pieces: untouched.
    std::vector<rtl::Vector2f> two{{0.f, 0.f}, {1.f, 0.f}, {2.f, 0.f}};
    Arr2 arr;
    arr.precompute(two);
    std::vector<Line2> lines{Line2(arr.sums(0, 3))};
    std::vector<Range> idx{{0, 3}};
    rtl::OptimizerTotalError<Arr2, Line2> opt;
    EXPECT_TRUE(opt(two, arr, lines, idx));
    EXPECT_EQ(idx, (std::vector<Range>{{0, 3}}));
}

TEST(Postprocessors, BadInput)
{
    rtl::PostprocessorPolyline2D<Line2> poly;
    rtl::PostprocessorProjectEndpoints<Line2> proj;
    std::vector<rtl::Vector2f> pts{{0.f, 0.f}, {1.f, 0.f}, {2.f, 0.f}, {3.f, 0.f}};
    Arr2 arr;
    arr.precompute(pts);
    std::vector<Line2> lines{Line2(arr.sums(0, 2)), Line2(arr.sums(2, 4))};
    std::vector<Range> idx{{0, 2}, {2, 4}};
    EXPECT_FALSE(poly(pts, lines, idx));              // parallel (collinear) lines have no crossing
    EXPECT_TRUE(poly.lineSegments().empty());
    EXPECT_FALSE(poly({}, lines, idx));
    EXPECT_FALSE(proj(pts, lines, {{0, 2}}));
    EXPECT_FALSE(proj(pts, {}, {}));
    EXPECT_FALSE(proj(pts, lines, {{0, 2}, {2, 9}}));
    EXPECT_TRUE(proj(pts, lines, idx));
    ASSERT_EQ(proj.output().size(), 2u);
    EXPECT_EQ(proj.output()[1].end(), rtl::Vector2f(3.f, 0.f));
}

TEST(Vectorizers, BadInputGivesFalseAndEmptyOutput)
{
    rtl::VectorizerFTLSPolyline2D<float, double> f;
    rtl::VectorizerAFTLSPolyline2D<float, double> af;
    rtl::VectorizerITLSProjections2D<float, double> it;
    const auto good = semicircle(200, 0.01, 1);
    const auto check = [&](const std::vector<rtl::Vector2f> &pts, bool expected, const char *what) {
        ASSERT_TRUE(f(good)); ASSERT_TRUE(af(good)); ASSERT_TRUE(it(good));   // stale results must be cleared
        EXPECT_EQ(f(pts), expected) << what;
        EXPECT_EQ(af(pts), expected) << what;
        EXPECT_EQ(it(pts), expected) << what;
        if (!expected)
        {
            EXPECT_TRUE(f.indices().empty() && f.approximations().empty() && f.lineSegments().empty()) << what;
            EXPECT_TRUE(af.indices().empty() && af.lineSegments().empty()) << what;
            EXPECT_TRUE(it.indices().empty() && it.lineSegments().empty()) << what;
        }
    };
    f.setSigma(0.03f); af.setSigma(0.03f); it.setSigma(0.03f);
    check({}, false, "empty");
    check({{1.f, 1.f}}, false, "one point");
    auto bad = good;
    bad[17] = rtl::Vector2f(std::numeric_limits<float>::quiet_NaN(), 0.f);
    check(bad, false, "NaN");
    bad[17] = rtl::Vector2f(0.f, std::numeric_limits<float>::infinity());
    check(bad, false, "Inf");
    check(std::vector<rtl::Vector2f>(50, rtl::Vector2f(2.f, 3.f)), true, "duplicates");
    EXPECT_EQ(f.indices().size(), 1u);
    check({{1.f, 1.f}, {2.f, 2.f}}, true, "two points");
    // Three points that fit no line within a tiny sigma and cannot be split into ranges of >= 2 points.
    f.setSigma(1e-4f); af.setSigma(1e-4f);
    EXPECT_FALSE(f({{0.f, 0.f}, {1.f, 1.f}, {2.f, 0.f}}));
    EXPECT_TRUE(f.indices().empty());
    for (float s : {0.f, -1.f, std::numeric_limits<float>::quiet_NaN(), std::numeric_limits<float>::infinity()})
    {
        f.setSigma(s); af.setSigma(s); it.setSigma(s);
        EXPECT_FALSE(f(good)); EXPECT_FALSE(af(good)); EXPECT_FALSE(it(good));
        f.setSigma(0.03f); af.setSigma(0.03f); it.setSigma(0.03f);
    }
    f.setDelta(0.f);
    EXPECT_FALSE(f(good));

    rtl::VectorizerFTLSProjections3D<float, double> f3;
    rtl::VectorizerAFTLSProjections3D<float, double> a3;
    rtl::VectorizerITLSProjections3D<float, double> i3;
    rtl::VectorizerAFTLSPlaneProjections3D<float, double> p3;
    auto h = helix(300, 1, 2, 0.01, 3);
    f3.setSigma(0.03f); a3.setSigma(0.03f); i3.setSigma(0.03f); p3.setSigma(0.03f);
    ASSERT_TRUE(f3(h)); ASSERT_TRUE(a3(h)); ASSERT_TRUE(i3(h)); ASSERT_TRUE(p3(h));
    h[5] = rtl::Vector3f(0.f, std::numeric_limits<float>::quiet_NaN(), 0.f);
    EXPECT_FALSE(f3(h)); EXPECT_FALSE(a3(h)); EXPECT_FALSE(i3(h)); EXPECT_FALSE(p3(h));
    EXPECT_TRUE(f3.lineSegments().empty() && a3.lineSegments().empty() && i3.lineSegments().empty() && p3.polygons().empty());
    EXPECT_FALSE(f3(std::vector<rtl::Vector3f>(1)));
}

TEST(Vectorizers, BufferReuseGivesIdenticalResults)
{
    rtl::VectorizerAFTLSPolyline2D<float, double> reused;
    reused.setMaxSize(20000);
    reused.setSigma(0.03f);
    for (size_t n : {20000u, 500u, 7000u, 10u})
    {
        const auto pts = semicircle(n, 0.01, static_cast<unsigned>(n) * 3);
        rtl::VectorizerAFTLSPolyline2D<float, double> fresh;
        fresh.setSigma(0.03f);
        ASSERT_TRUE(reused(pts));
        ASSERT_TRUE(fresh(pts));
        EXPECT_EQ(reused.indices(), fresh.indices());
        EXPECT_EQ(reused.vertices(), fresh.vertices());
    }
}

TEST(Vectorizers3D, HelixLines)
{
    for (size_t n : {10u, 300u, 5000u, 30000u})
    {
        const auto pts = helix(n, 2, 3, 0.01, static_cast<unsigned>(n));
        rtl::VectorizerFTLSProjections3D<float, double> f;
        rtl::VectorizerAFTLSProjections3D<float, double> af;
        rtl::VectorizerITLSProjections3D<float, double> it;
        f.setSigma(0.03f); af.setSigma(0.03f); it.setSigma(0.03f);
        af.setSimplexShift(2);
        af.setMaxIterations(5000);
        ASSERT_TRUE(f(pts));
        ASSERT_TRUE(af(pts));
        ASSERT_TRUE(it(pts));
        for (const auto *idx : {&f.indices(), &af.indices(), &it.indices()})
        {
            expectPartition(*idx, n);
            expectLineRms(pts, *idx, 0.03);
        }
        EXPECT_LE(totalLineSsr(pts, af.indices()), totalLineSsr(pts, f.indices()) * (1 + 1e-9));
        // Approximations equal the reference fits; segments run along the data.
        for (size_t i = 0; i < af.indices().size(); ++i)
        {
            const auto r = af.indices()[i];
            const auto ref = refFit<3>(pts, r.first, r.second);
            const auto &a = af.approximations()[i];
            EXPECT_NEAR(a.errSquaredCompute(), ref.lineErr(), 1e-9 * 100);
            EXPECT_LT((a.point().data().cast<double>() - ref.mean).norm(), 1e-5);
            if (ref.values(2) > 1e3 * ref.values(1))
            {
                const Eigen::Vector3d dir = a.direction().data().cast<double>();
                EXPECT_LT(std::min((dir - ref.major()).norm(), (dir + ref.major()).norm()), 1e-6);
            }
            const auto &seg = af.lineSegments()[i];
            EXPECT_LT(seg.distanceToPoint(pts[r.first]), 0.1f);
            EXPECT_LT((seg.beg() - pts[r.first]).length(), 0.1f);
            EXPECT_LT((seg.end() - pts[r.second - 1]).length(), 0.1f);
        }
    }
}

TEST(Vectorizers3D, BoxFacePlanes)
{
    // Raster scans of three faces of a 2 x 2 x 2 box, one face after the other (rows zigzag within a face).
    std::mt19937 gen(9);
    std::normal_distribution<double> nd(0, 0.002);
    std::vector<rtl::Vector3f> pts;
    const Eigen::Vector3d normals[3] = {Eigen::Vector3d::UnitZ(), Eigen::Vector3d::UnitX(), Eigen::Vector3d::UnitY()};
    for (int face = 0; face < 3; ++face)
        for (int r = 0; r < 25; ++r)
            for (int c = 0; c < 25; ++c)
            {
                const double u = 2.0 * (r % 2 ? 24 - c : c) / 24, v = 2.0 * r / 24;
                Eigen::Vector3d p;
                if (face == 0) p << u, v, 2;
                else if (face == 1) p << 2, u, v;
                else p << u, 0, v;
                p += Eigen::Vector3d(nd(gen), nd(gen), nd(gen));
                pts.emplace_back(Eigen::Vector3f(p.cast<float>()));
            }
    rtl::VectorizerAFTLSPlaneProjections3D<float, double> planes;
    planes.setSigma(0.01f);
    ASSERT_TRUE(planes(pts));
    expectPartition(planes.indices(), pts.size());
    expectPlaneRms(pts, planes.indices(), 0.01);
    ASSERT_EQ(planes.polygons().size(), planes.indices().size());
    EXPECT_LE(planes.indices().size(), 6u);
    size_t covered = 0;
    for (size_t i = 0; i < planes.indices().size(); ++i)
    {
        const auto r = planes.indices()[i];
        if (r.second - r.first < 100)
            continue;
        covered += r.second - r.first;
        const Eigen::Vector3d nrm = planes.approximations()[i].normal().data().cast<double>();
        double best = 0;
        for (const auto &fn : normals)
            best = std::max(best, std::abs(nrm.dot(fn)));
        EXPECT_GT(best, std::cos(M_PI / 180)) << "plane " << i << " within 1 degree of a face normal";
        EXPECT_EQ(planes.polygons()[i].points().size(), r.second - r.first);
    }
    EXPECT_GT(covered, pts.size() * 9 / 10);
}

// setMaxSize (or one earlier call on a chain at least as long) makes later calls allocation-free.
TEST(Vectorizers, NoAllocationWhenBuffersAreReused)
{
    const auto big = semicircle(20000, 0.01, 1), small = semicircle(3000, 0.01, 2);
    const auto hbig = helix(20000, 2, 3, 0.01, 3), hsmall = helix(3000, 2, 3, 0.01, 4);
    rtl::VectorizerFTLSPolyline2D<float, double> f;
    rtl::VectorizerAFTLSPolyline2D<float, double> af;
    rtl::VectorizerITLSProjections2D<float, double> it;
    rtl::VectorizerFTLSProjections3D<float, double> f3;
    rtl::VectorizerAFTLSProjections3D<float, double> a3;
    rtl::VectorizerITLSProjections3D<float, double> i3;
    rtl::VectorizerDouglasPeucker2f dp(0.09f);
    rtl::VectorizerReumannWitkam2f rw(0.09f);
    std::vector<rtl::LineSegment2f> out;
    f.setMaxSize(20000); af.setMaxSize(20000); it.setMaxSize(20000);
    f3.setMaxSize(20000); a3.setMaxSize(20000); i3.setMaxSize(20000);
    dp.setMaxSize(20000); rw.setMaxSize(20000);
    // One warm-up call each sizes the output vectors.
    ASSERT_TRUE(f(big) && af(big) && it(big) && f3(hbig) && a3(hbig) && i3(hbig));
    dp(big, out);
    rw(big, out);
    const size_t before = g_allocations.load();
    for (int rep = 0; rep < 2; ++rep)
    {
        ASSERT_TRUE(f(small) && af(small) && it(small) && f3(hsmall) && a3(hsmall) && i3(hsmall));
        ASSERT_TRUE(f(big) && af(big) && it(big) && f3(hbig) && a3(hbig) && i3(hbig));
        dp(small, out);
        rw(big, out);
    }
    EXPECT_EQ(g_allocations.load() - before, 0u);
}
