// Prefix sums, the three TLS approximations against independent fits, and the point-elimination vectorizers
// against straightforward references.
#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "rtl/Vectorization.h"
#include "vect_reference.h"

using namespace vect_test;

using L2d = rtl::ApproximationTlsLine2D<double, double>;
using L3d = rtl::ApproximationTlsLine3D<double, double>;
using P3d = rtl::ApproximationTlsPlane3D<double, double>;

TEST(PrecSums, ArithmeticAndAverage)
{
    rtl::PrecSums2D<double> a(1, 2, 3, 4, 5, 2), b(rtl::Vector2d(2.0, 3.0));
    EXPECT_EQ(b.sx(), 2); EXPECT_EQ(b.sy2(), 9); EXPECT_EQ(b.sxy(), 6); EXPECT_EQ(b.cnt(), 1);
    auto c = a + b;
    EXPECT_EQ(c.sx(), 3); EXPECT_EQ(c.cnt(), 3);
    c -= b;
    EXPECT_TRUE((c.sums == a.sums).all());
    const auto av = a.averaged();
    EXPECT_EQ(av.sx(), 0.5); EXPECT_EQ(av.sxy(), 2.5); EXPECT_EQ(av.cnt(), 1);
    EXPECT_EQ(rtl::PrecSums2D<double>::sumNr(), 5u);
    EXPECT_EQ(rtl::PrecSums3D<float>::sumNr(), 9u);
    rtl::PrecSums3D<double> p(rtl::Vector3d(1.0, 2.0, 3.0));
    EXPECT_EQ(p.syz(), 6); EXPECT_EQ(p.szx(), 3); EXPECT_EQ(p.sz2(), 9);
    p.setZero();
    EXPECT_EQ(p.cnt(), 0);
    p.average();                 // empty set: no division by zero
    EXPECT_EQ(p.sx(), 0);
}

TEST(PrecArray, RowsOfTheSpecExample)
{
    std::vector<rtl::Vector2f> pts(10, rtl::Vector2f(1.f, 2.f));
    rtl::PrecArray2D<float, double> arr;
    arr.precompute(pts);
    ASSERT_EQ(arr.size(), 11u);
    for (int i = 0; i <= 10; ++i)
    {
        EXPECT_EQ(arr.array(i, 0), i); EXPECT_EQ(arr.array(i, 1), 2 * i); EXPECT_EQ(arr.array(i, 2), i);
        EXPECT_EQ(arr.array(i, 3), 4 * i); EXPECT_EQ(arr.array(i, 4), 2 * i);
        const auto s = arr.sums(static_cast<size_t>(i));
        EXPECT_EQ(s.sx(), i); EXPECT_EQ(s.cnt(), i);
        if (i > 0)
        {
            const auto r = arr.sums(static_cast<size_t>(i - 1), static_cast<size_t>(i));
            EXPECT_EQ(r.sx(), 1); EXPECT_EQ(r.sy(), 2); EXPECT_EQ(r.sx2(), 1); EXPECT_EQ(r.sy2(), 4); EXPECT_EQ(r.sxy(), 2);
            EXPECT_EQ(r.cnt(), 1);
        }
    }
    // Reuse with fewer points: no reallocation, row 0 stays zero.
    const double *buf = arr.array.data();
    arr.precompute(std::vector<rtl::Vector2f>(3, rtl::Vector2f(1.f, 1.f)));
    EXPECT_EQ(arr.size(), 4u);
    EXPECT_EQ(arr.array.data(), buf);
    EXPECT_EQ(arr.sums(0, 3).sx(), 3);

    std::vector<rtl::Vector3d> p3{{1, 2, 3}, {4, 5, 6}};
    rtl::PrecArray3D<double, double> a3;
    a3.precompute(p3);
    const auto s3 = a3.sums(0, 2);
    EXPECT_EQ(s3.sz(), 9); EXPECT_EQ(s3.syz(), 2 * 3 + 5 * 6); EXPECT_EQ(s3.szx(), 3 * 1 + 6 * 4); EXPECT_EQ(s3.cnt(), 2);
}

// The blocked prefix sums used by the FTLS vectorizers give the same range sums as the full array.
TEST(PrecArrayBlocked, MatchesPrecArray)
{
    std::mt19937 gen(21);
    std::uniform_real_distribution<float> u(-10.f, 10.f);
    for (size_t n : {0u, 1u, 7u, 8u, 9u, 16u, 17u, 100u, 1001u, 20001u})
    for (size_t min_blocked : {0u, 16384u})   // blocked for every size / only for long chains (default)
    {
        std::vector<rtl::Vector2f> p2;
        std::vector<rtl::Vector3f> p3;
        for (size_t i = 0; i < n; ++i)
        {
            p2.emplace_back(u(gen), u(gen));
            p3.emplace_back(u(gen), u(gen), u(gen));
        }
        rtl::PrecArray2D<float, double> a2;
        rtl::PrecArray3D<float, double> a3;
        rtl::PrecArrayBlocked<2, float, double> b2;
        rtl::PrecArrayBlocked<3, float, double> b3;
        b2.setMinBlockedSize(min_blocked);
        b3.setMinBlockedSize(min_blocked);
        a2.precompute(p2); a3.precompute(p3); b2.precompute(p2); b3.precompute(p3);
        ASSERT_EQ(b2.size(), n + 1);
        ASSERT_EQ(b3.size(), n + 1);
        EXPECT_TRUE(b2.allFinite() && b3.allFinite() && a2.allFinite() && a3.allFinite());
        for (size_t b = 0; b <= n; b += 1 + b / 3)
            for (size_t e = b; e <= n; e += 1 + e / 5 + e / 50)
            {
                // Blocked sums add each block's own sum, rounded differently from one running sum: within the running
                // sum's error bound n eps |total| (a missing or doubled point would be off by ~1 to 100).
                const double tol = 1e-15 + 4e-16 * static_cast<double>(n) *
                                   std::max(a3.sums(n).sums.abs().maxCoeff(), a2.sums(n).sums.abs().maxCoeff());
                EXPECT_LT((b2.sums(b, e).sums - a2.sums(b, e).sums).abs().maxCoeff(), tol) << b << " " << e;
                EXPECT_LT((b3.sums(b, e).sums - a3.sums(b, e).sums).abs().maxCoeff(), tol) << b << " " << e;
                EXPECT_EQ(b3.sums(b, e).cnt(), static_cast<double>(e - b));
            }
        if (n > 0)
        {
            EXPECT_LT((b2.sums(n).sums - a2.sums(n).sums).abs().maxCoeff(), 1e-15 + 4e-16 * static_cast<double>(n) * a2.sums(n).sums.abs().maxCoeff());
            p2[n / 2] = rtl::Vector2f(std::numeric_limits<float>::quiet_NaN(), 0.f);
            p3[n - 1] = rtl::Vector3f(0.f, std::numeric_limits<float>::infinity(), 0.f);
            b2.precompute(p2); b3.precompute(p3); a2.precompute(p2);
            EXPECT_FALSE(b2.allFinite());
            EXPECT_FALSE(b3.allFinite());
            EXPECT_FALSE(a2.allFinite());
        }
    }
}

namespace
{
    // Sign-insensitive comparison of unit vectors.
    template<class A, class B>
    double axisDiff(const A &a, const B &b) { return std::min((a - b).norm(), (a + b).norm()); }

    template<int d>
    std::vector<rtl::VectorND<d, double>> randomCloud(std::mt19937 &gen, size_t n, const Eigen::Matrix<double, d, 1> &scale,
                                                     const Eigen::Matrix<double, d, 1> &offset)
    {
        std::uniform_real_distribution<double> u(-1, 1);
        Eigen::Matrix<double, d, d> rot = Eigen::Matrix<double, d, d>::Random();
        rot = Eigen::HouseholderQR<Eigen::Matrix<double, d, d>>(rot).householderQ();
        std::vector<rtl::VectorND<d, double>> pts;
        for (size_t i = 0; i < n; ++i)
        {
            Eigen::Matrix<double, d, 1> q;
            for (int k = 0; k < d; ++k)
                q(k) = u(gen) * scale(k);
            pts.emplace_back(Eigen::Matrix<double, d, 1>(rot * q + offset));
        }
        return pts;
    }
}

// "1e-9 relative": differences are measured against the size of the data (its spread and offset), the natural
// scale of the prefix-sum rounding; directions are unit vectors.
TEST(ApproximationTlsLine2D, MatchesIndependentFit)
{
    std::mt19937 gen(7);
    for (int trial = 0; trial < 200; ++trial)
    {
        const double len = std::pow(10.0, trial % 4 - 1), thick = len * std::pow(10.0, -(trial % 5));
        const Eigen::Vector2d off(trial % 3 == 0 ? 0.0 : 5.0, trial % 2 == 0 ? -3.0 : 2.0);
        const auto pts = randomCloud<2>(gen, 3 + static_cast<size_t>(trial) * 5, Eigen::Vector2d(len, thick), off);
        rtl::PrecArray2D<double, double> arr;
        arr.precompute(pts);
        const rtl::ApproximationTlsLine2D<double, double> line(arr.sums(0, pts.size()));
        const auto ref = refFit<2>(pts, 0, pts.size());
        const double scale = len + off.norm();
        EXPECT_NEAR(line.point().x(), ref.mean.x(), 1e-9 * scale);
        EXPECT_NEAR(line.point().y(), ref.mean.y(), 1e-9 * scale);
        EXPECT_NEAR(line.errSquared(), ref.values(0), 1e-9 * scale * scale) << trial;
        if (ref.values(1) - ref.values(0) > 1e-6 * ref.values(1))
        {
            EXPECT_LT(axisDiff(line.direction().data(), ref.major()), 1e-9 * scale * scale / (ref.values(1) - ref.values(0)) + 1e-12) << trial;
        }
        // Implicit form and normal are consistent with the direction.
        EXPECT_NEAR(line.normal().dot(line.direction()), 0.0, 1e-15);
        EXPECT_NEAR(line.a() * ref.mean.x() + line.b() * ref.mean.y() + line.c(), 0.0, 1e-9 * scale);
        EXPECT_NEAR(L2d::getErrorSquared(arr.sums(0, pts.size())), line.errSquared(), 1e-15 * scale * scale);
    }
}

// Published defect 1 (docs/reference.md, "Vectorization defects fixed here"): exactly axis-aligned sets got a direction
// 90 degrees off (or a zero normal).
TEST(ApproximationTlsLine2D, ExactlyAxisAlignedSets)
{
    using L = rtl::ApproximationTlsLine2D<float, double>;
    rtl::PrecArray2D<float, double> arr;
    std::vector<rtl::Vector2f> horiz{{0.f, 1.f}, {1.f, 1.f}, {2.f, 1.f}, {5.f, 1.f}};
    arr.precompute(horiz);
    L h(arr.sums(0, 4));
    EXPECT_FLOAT_EQ(std::abs(h.direction().x()), 1.f);
    EXPECT_FLOAT_EQ(h.direction().y(), 0.f);
    EXPECT_FLOAT_EQ(std::abs(h.c()), 1.f);
    EXPECT_FLOAT_EQ(h.errSquared(), 0.f);
    std::vector<rtl::Vector2f> vert{{-2.f, 0.f}, {-2.f, 3.f}, {-2.f, 4.f}};
    arr.precompute(vert);
    L v(arr.sums(0, 3));
    EXPECT_FLOAT_EQ(v.direction().x(), 0.f);
    EXPECT_FLOAT_EQ(std::abs(v.direction().y()), 1.f);
    EXPECT_FLOAT_EQ(std::abs(v.normal().x()), 1.f);
    EXPECT_FLOAT_EQ(std::abs(v.c()), 2.f);
    // Coincident points: a defined direction and zero error, no NaN.
    std::vector<rtl::Vector2f> same(4, rtl::Vector2f(3.f, 3.f));
    arr.precompute(same);
    L s(arr.sums(0, 4));
    EXPECT_FALSE(s.direction().hasNaN());
    EXPECT_FLOAT_EQ(s.direction().length(), 1.f);
    EXPECT_FLOAT_EQ(s.errSquared(), 0.f);
}

// The spec's collinear test: direction matches and |c| equals the offset.
TEST(ApproximationTlsLine2D, CollinearWithOffset)
{
    for (int k = 0; k < 36; ++k)
    {
        const double a = k * M_PI / 18;
        const Eigen::Vector2d dir(std::cos(a), std::sin(a)), off = Eigen::Vector2d(-dir.y(), dir.x()) * 2.5;
        std::vector<rtl::Vector2f> pts;
        for (int i = -5; i <= 5; ++i)
            pts.emplace_back(Eigen::Vector2f((off + dir * i).cast<float>()));
        rtl::PrecArray2D<float, double> arr;
        arr.precompute(pts);
        rtl::ApproximationTlsLine2D<float, double> l(arr.sums(0, pts.size()));
        EXPECT_NEAR(std::abs(l.direction().x()), std::abs(dir.x()), 1e-4);
        EXPECT_NEAR(std::abs(l.direction().y()), std::abs(dir.y()), 1e-4);
        EXPECT_NEAR(std::abs(l.c()), 2.5, 1e-4);
        EXPECT_LT(l.errSquared(), 1e-10);
    }
}

// Published defect 2: crossings of nearly parallel lines must be computed in the compute type.
TEST(ApproximationTlsLine2D, CrossingInComputeType)
{
    using L = rtl::ApproximationTlsLine2D<float, double>;
    // Two lines at 1e-4 rad from each other, both through (1000.25, 0.5): float arithmetic puts the
    // crossing metres off; double keeps it on both lines.
    const double ang = 1e-4;
    std::vector<rtl::Vector2f> l1, l2;
    for (int i = 0; i < 50; ++i)
    {
        l1.emplace_back(static_cast<float>(i), 0.5f);
        l2.emplace_back(static_cast<float>(i), static_cast<float>(0.5 + (i - 1000.25) * std::tan(ang)));
    }
    rtl::PrecArray2D<float, double> a1, a2;
    a1.precompute(l1);
    a2.precompute(l2);
    const L f1(a1.sums(0, 50)), f2(a2.sums(0, 50));
    rtl::Vector2f x;
    ASSERT_TRUE(L::getCrossing(f1, f2, x));
    // The lines are fitted to float samples; the crossing of the fitted lines must lie on both fitted lines.
    const auto dist = [](const L &l, const rtl::Vector2f &p) { return std::abs(double(l.a()) * p.x() + double(l.b()) * p.y() + double(l.c())); };
    EXPECT_LT(dist(f1, x), 1e-3);
    EXPECT_LT(dist(f2, x), 1e-3);
    // Parallel lines: false.
    std::vector<rtl::Vector2f> l3;
    for (int i = 0; i < 50; ++i)
        l3.emplace_back(static_cast<float>(i), 2.5f);
    rtl::PrecArray2D<float, double> a3;
    a3.precompute(l3);
    EXPECT_FALSE(L::getCrossing(f1, L(a3.sums(0, 50)), x));
}

TEST(ApproximationTlsLine2D, ProjectAndTrim)
{
    std::vector<rtl::Vector2d> pts{{0, 0}, {1, 1}, {2, 2}, {3, 3}};
    rtl::PrecArray2D<double, double> arr;
    arr.precompute(pts);
    rtl::ApproximationTlsLine2D<double, double> l(arr.sums(0, 4));
    const auto p = l.project(rtl::Vector2d(2, 0));
    EXPECT_NEAR(p.x(), 1, 1e-12); EXPECT_NEAR(p.y(), 1, 1e-12);
    const auto seg = l.trim(pts.begin(), pts.end());
    EXPECT_NEAR(seg.beg().x(), 0, 1e-12); EXPECT_NEAR(seg.end().y(), 3, 1e-12);
    EXPECT_NEAR(seg.direction().x(), std::sqrt(0.5), 1e-12);   // directed from beg to end
    const auto rev = l.trim(pts.back(), pts.front());
    EXPECT_NEAR(rev.direction().x(), -std::sqrt(0.5), 1e-12);
}

TEST(ApproximationTlsLine3D, MatchesIndependentFit)
{
    std::mt19937 gen(11);
    for (int trial = 0; trial < 200; ++trial)
    {
        const double len = std::pow(10.0, trial % 3), thick = len * std::pow(10.0, -1 - trial % 4);
        const Eigen::Vector3d off(trial % 2 ? 1.0 : -4.0, 2.0, trial % 3 == 0 ? 0.0 : 7.0);
        const auto pts = randomCloud<3>(gen, 3 + static_cast<size_t>(trial) * 4, Eigen::Vector3d(len, thick, thick * 0.5), off);
        rtl::PrecArray3D<double, double> arr;
        arr.precompute(pts);
        const rtl::ApproximationTlsLine3D<double, double> line(arr.sums(0, pts.size()));
        const auto ref = refFit<3>(pts, 0, pts.size());
        const double scale = len + off.norm();
        EXPECT_LT((line.point().data() - ref.mean).norm(), 1e-9 * scale);
        EXPECT_NEAR(line.errSquared(), ref.lineErr(), 1e-9 * scale * scale) << trial;
        EXPECT_NEAR(L3d::getErrorSquared(arr.sums(0, pts.size())), ref.lineErr(), 1e-9 * scale * scale);
        EXPECT_LT(axisDiff(line.direction().data(), ref.major()), 1e-9 * scale * scale / (ref.values(2) - ref.values(1)) + 1e-12) << trial;
        const auto seg = line.trim(pts.front(), pts.back());
        EXPECT_NEAR(seg.length(), std::abs((pts.back().data() - pts.front().data()).dot(ref.major())), 1e-6 * scale);
    }
}

TEST(ApproximationTlsPlane3D, MatchesIndependentFitAndProjects)
{
    std::mt19937 gen(13);
    for (int trial = 0; trial < 200; ++trial)
    {
        const double len = std::pow(10.0, trial % 3), thick = len * std::pow(10.0, -1 - trial % 4);
        const Eigen::Vector3d off(3.0, trial % 2 ? -1.0 : 6.0, 2.0);
        const auto pts = randomCloud<3>(gen, 4 + static_cast<size_t>(trial) * 4, Eigen::Vector3d(len, len * 0.6, thick), off);
        rtl::PrecArray3D<double, double> arr;
        arr.precompute(pts);
        const rtl::ApproximationTlsPlane3D<double, double> plane(arr.sums(0, pts.size()));
        const auto ref = refFit<3>(pts, 0, pts.size());
        const double scale = len + off.norm();
        EXPECT_NEAR(plane.errSquared(), ref.planeErr(), 1e-9 * scale * scale) << trial;
        EXPECT_LT(axisDiff(plane.normal().data(), ref.minor()), 1e-9 * scale * scale / (ref.values(1) - ref.values(0)) + 1e-12) << trial;
        EXPECT_NEAR(plane.d(), ref.mean.dot(plane.normal().data()), 1e-9 * scale);
        // Orthogonal projection: on the plane, and the offset is along the normal.
        const rtl::Vector3d q(1.0, 2.0, 3.0);
        const auto p = plane.project(q);
        EXPECT_NEAR(p.dot(plane.normal()), plane.d(), 1e-9 * scale);
        EXPECT_LT(axisDiff((q - p).normalized().data(), plane.normal().data()), 1e-9);
        const auto poly = plane.trim(pts);
        ASSERT_EQ(poly.points().size(), pts.size());
        EXPECT_NEAR(poly.points()[0].dot(plane.normal()), plane.d(), 1e-9 * scale);
    }
    // Collinear points: error 0, a unit normal orthogonal to the line.
    std::vector<rtl::Vector3d> line{{0, 0, 0}, {1, 1, 1}, {2, 2, 2}, {4, 4, 4}};
    rtl::PrecArray3D<double, double> arr;
    arr.precompute(line);
    const rtl::ApproximationTlsPlane3D<double, double> deg(arr.sums(0, 4));
    EXPECT_NEAR(deg.errSquared(), 0.0, 1e-12);
    EXPECT_NEAR(deg.normal().length(), 1.0, 1e-12);
    EXPECT_NEAR(deg.normal().dot(rtl::Vector3d(1, 1, 1)), 0.0, 1e-9);
}

TEST(ApproximationTls, ErrorBelowAgreesWithErrSquared)
{
    std::mt19937 gen(17);
    std::uniform_real_distribution<double> u(1e-6, 1e-1);
    for (int trial = 0; trial < 300; ++trial)
    {
        const auto p2 = randomCloud<2>(gen, 5 + static_cast<size_t>(trial % 20), Eigen::Vector2d(1.0, 0.05), Eigen::Vector2d(1, 2));
        const auto p3 = randomCloud<3>(gen, 5 + static_cast<size_t>(trial % 20), Eigen::Vector3d(1.0, 0.05, 0.03), Eigen::Vector3d(1, 2, 3));
        rtl::PrecArray2D<double, double> a2;
        rtl::PrecArray3D<double, double> a3;
        a2.precompute(p2);
        a3.precompute(p3);
        const double s2 = u(gen) * u(gen);
        const auto ps2 = a2.sums(0, p2.size());
        const auto ps3 = a3.sums(0, p3.size());
        const double e2 = L2d::errorSquaredCompute(ps2);
        const double e3l = L3d::errorSquaredCompute(ps3);
        const double e3p = P3d::errorSquaredCompute(ps3);
        if (std::abs(e2 - s2) > 1e-9 * s2)
        {
            EXPECT_EQ(L2d::errorBelow(ps2, s2), e2 < s2);
        }
        if (std::abs(e3l - s2) > 1e-9 * s2)
        {
            EXPECT_EQ(L3d::errorBelow(ps3, s2), e3l < s2);
        }
        if (std::abs(e3p - s2) > 1e-9 * s2)
        {
            EXPECT_EQ(P3d::errorBelow(ps3, s2), e3p < s2);
        }
    }
    // NaN sums never pass.
    rtl::PrecSums2D<double> nan_sums(std::nan(""), 0, 0, 0, 0, 3);
    EXPECT_FALSE(L2d::errorBelow(nan_sums, 1.0));
}

// ---- Douglas-Peucker and Reumann-Witkam against straightforward references ----

namespace
{
    template<int d>
    double distToLine(const rtl::VectorND<d, double> &p, const rtl::VectorND<d, double> &a, const rtl::VectorND<d, double> &b)
    {
        const Eigen::Matrix<double, d, 1> u = b.data() - a.data(), v = p.data() - a.data();
        if (u.squaredNorm() == 0)
            return v.norm();
        return (v - u * (v.dot(u) / u.squaredNorm())).norm();
    }

    template<int d>
    void dpReference(const std::vector<rtl::VectorND<d, double>> &pts, size_t a, size_t b, double eps, std::vector<size_t> &keep)
    {
        double best = eps;
        size_t idx = 0;
        for (size_t i = a + 1; i < b; ++i)
        {
            const double dist = distToLine<d>(pts[i], pts[a], pts[b]);
            if (dist > best) { best = dist; idx = i; }
        }
        if (idx == 0)
            return;
        dpReference<d>(pts, a, idx, eps, keep);
        keep.push_back(idx);
        dpReference<d>(pts, idx, b, eps, keep);
    }

    template<int d>
    std::vector<size_t> rwReference(const std::vector<rtl::VectorND<d, double>> &pts, double eps)
    {
        std::vector<size_t> keys{0};
        size_t k = 0, j = 1;
        while (j < pts.size() && pts[j] == pts[k])
            ++j;
        if (j < pts.size())
        {
            size_t through = j;
            for (size_t i = j + 1; i < pts.size(); ++i)
            {
                // Distance from the infinite line through pts[k] and pts[through].
                const Eigen::Matrix<double, d, 1> u = (pts[through].data() - pts[k].data()).normalized(), v = pts[i].data() - pts[k].data();
                if ((v - u * v.dot(u)).norm() > eps)
                {
                    k = i - 1;
                    keys.push_back(k);
                    through = i;
                }
            }
        }
        if (keys.back() != pts.size() - 1)
            keys.push_back(pts.size() - 1);
        return keys;
    }

    template<int d>
    std::vector<rtl::VectorND<d, double>> wiggly(std::mt19937 &gen, size_t n)
    {
        std::normal_distribution<double> nd(0, 0.05);
        std::vector<rtl::VectorND<d, double>> pts;
        for (size_t i = 0; i < n; ++i)
        {
            const double t = static_cast<double>(i) * 0.02;
            Eigen::Matrix<double, d, 1> q;
            q(0) = 4 * std::cos(t) + nd(gen);
            q(1) = 3 * std::sin(1.7 * t) + nd(gen);
            if constexpr (d == 3)
                q(2) = std::sin(0.5 * t) * 2 + nd(gen);
            pts.emplace_back(q);
        }
        return pts;
    }

    template<int d>
    std::vector<size_t> keysOf(const std::vector<rtl::VectorND<d, double>> &pts, const std::vector<rtl::LineSegmentND<d, double>> &segs)
    {
        // Map the segment end points back to input indices (the segments join kept input points exactly).
        std::vector<size_t> keys;
        size_t i = 0;
        for (size_t s = 0; s <= segs.size(); ++s)
        {
            const auto &p = s == 0 ? segs[0].beg() : segs[s - 1].end();
            while (i < pts.size() && !(pts[i] == p))
                ++i;
            keys.push_back(i);
        }
        return keys;
    }

    template<int d>
    void checkEliminationAgainstReferences(unsigned seed)
    {
        std::mt19937 gen(seed);
        for (size_t n : {2u, 3u, 10u, 57u, 1000u, 5000u})
            for (double eps : {0.01, 0.09, 0.5})
            {
                const auto pts = wiggly<d>(gen, n);
                std::vector<rtl::LineSegmentND<d, double>> out;
                rtl::VectorizerDouglasPeuckerND<d, double> dp(eps);
                dp(pts, out);
                std::vector<size_t> ref{0};
                dpReference<d>(pts, 0, n - 1, eps, ref);
                ref.push_back(n - 1);
                ASSERT_EQ(out.size() + 1, ref.size()) << "DP n=" << n << " eps=" << eps;
                EXPECT_EQ(keysOf<d>(pts, out), ref) << "DP n=" << n << " eps=" << eps;

                rtl::VectorizerReumannWitkamND<d, double> rw(static_cast<float>(eps));
                rw(pts, out);
                const auto rref = rwReference<d>(pts, static_cast<float>(eps));
                ASSERT_EQ(out.size() + 1, rref.size()) << "RW n=" << n << " eps=" << eps;
                EXPECT_EQ(keysOf<d>(pts, out), rref) << "RW n=" << n << " eps=" << eps;
                // Every input point lies within eps of the RW strip line of its piece (the strip's defining property).
                for (size_t s = 0; s + 1 < rref.size(); ++s)
                    EXPECT_EQ(rref[s + 1] > rref[s], true);
            }
    }
}

TEST(VectorizerDouglasPeucker, AndReumannWitkamMatchReferences2D) { checkEliminationAgainstReferences<2>(3); }
TEST(VectorizerDouglasPeucker, AndReumannWitkamMatchReferences3D) { checkEliminationAgainstReferences<3>(5); }

TEST(VectorizerDouglasPeucker, EdgeCases)
{
    std::vector<rtl::LineSegment2f> out(3);
    rtl::VectorizerDouglasPeucker2f dp(0.1f);
    dp(std::vector<rtl::Vector2f>{}, out);
    EXPECT_TRUE(out.empty());
    dp(std::vector<rtl::Vector2f>{{1.f, 1.f}}, out);
    EXPECT_TRUE(out.empty());
    // Closed loop (first == last point): distances to the point, no NaN.
    std::vector<rtl::Vector2f> loop{{0.f, 0.f}, {1.f, 0.f}, {1.f, 1.f}, {0.f, 1.f}, {0.f, 0.f}};
    dp(loop, out);
    ASSERT_GE(out.size(), 2u);
    for (const auto &s : out)
        EXPECT_FALSE(s.direction().hasNaN());
    // Coincident points: one zero-length segment with a finite direction.
    rtl::VectorizerReumannWitkam2f rw(0.1f);
    rw(std::vector<rtl::Vector2f>(5, rtl::Vector2f(2.f, 2.f)), out);
    ASSERT_EQ(out.size(), 1u);
    EXPECT_FALSE(out[0].direction().hasNaN());
    // Straight line: a single segment from first to last point.
    std::vector<rtl::Vector2f> line;
    for (int i = 0; i < 100; ++i)
        line.emplace_back(static_cast<float>(i), 2.f * static_cast<float>(i));
    dp(line, out);
    ASSERT_EQ(out.size(), 1u);
    rw(line, out);
    ASSERT_EQ(out.size(), 1u);
    EXPECT_EQ(out[0].end(), line.back());
}

namespace
{
    // A non-finite coordinate makes Douglas-Peucker leave its blockwise (SoA) farthest-point scan, which assumes
    // finite distances, for the plain scan. That scan must keep exactly the points of the reference, and a point
    // whose distance is NaN is never kept.
    template<int d>
    void checkDouglasPeuckerWithNonFinitePoints(unsigned seed)
    {
        std::mt19937 gen(seed);
        for (double bad : {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity()})
            for (double eps : {0.01, 0.09, 0.5})
            {
                auto pts = wiggly<d>(gen, 2000);
                const size_t bad_index = 777;
                Eigen::Matrix<double, d, 1> q = pts[bad_index].data();
                q(1) = bad;
                pts[bad_index] = rtl::VectorND<d, double>(q);
                std::vector<rtl::LineSegmentND<d, double>> out;
                rtl::VectorizerDouglasPeuckerND<d, double> dp(eps);
                dp(pts, out);
                std::vector<size_t> ref{0};
                dpReference<d>(pts, 0, pts.size() - 1, eps, ref);
                ref.push_back(pts.size() - 1);
                ASSERT_GT(ref.size(), 3u) << "eps=" << eps;
                ASSERT_EQ(out.size() + 1, ref.size()) << "bad=" << bad << " eps=" << eps;
                const auto keys = keysOf<d>(pts, out);
                EXPECT_EQ(keys, ref) << "bad=" << bad << " eps=" << eps;
                EXPECT_EQ(std::count(keys.begin(), keys.end(), bad_index), 0) << "bad=" << bad << " eps=" << eps;
            }
    }
}

TEST(VectorizerDouglasPeucker, NonFinitePointsTakeThePlainScanAndAreNeverKept2D) { checkDouglasPeuckerWithNonFinitePoints<2>(21); }
TEST(VectorizerDouglasPeucker, NonFinitePointsTakeThePlainScanAndAreNeverKept3D) { checkDouglasPeuckerWithNonFinitePoints<3>(22); }
