// FTLS/AFTLS next to huge values: exact range sums after a far-off point (compensated blocked
// prefix sums), and no infinite numbers in a result that returns true.
#include <cmath>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "rtl/Vectorization.h"

namespace
{
    //! 400 points on the sides of a 10 x 10 square (spacing 0.1), with (1e9, 0) inserted at `outlier`.
    std::vector<rtl::Vector2f> squareWithOutlier(size_t outlier)
    {
        std::vector<rtl::Vector2f> pts;
        for (int i = 0; i < 400; ++i)
        {
            const float t = static_cast<float>(i % 100) * 0.1f;
            switch (i / 100)
            {
                case 0: pts.emplace_back(t, 0.0f); break;
                case 1: pts.emplace_back(10.0f, t); break;
                case 2: pts.emplace_back(10.0f - t, 10.0f); break;
                default: pts.emplace_back(0.0f, 10.0f - t); break;
            }
        }
        pts.insert(pts.begin() + static_cast<std::ptrdiff_t>(outlier), rtl::Vector2f(1e9f, 0.0f));
        return pts;
    }

    //! Mean squared orthogonal residual of pts[b, e) to a line, summed directly in double around the first point.
    template<class Line>
    double directError(const std::vector<rtl::Vector2f> &pts, size_t b, size_t e, const Line &l)
    {
        const double nx = l.normal().x(), ny = l.normal().y(), c = l.c();
        double s = 0;
        for (size_t i = b; i < e; ++i)
        {
            const double d = nx * pts[i].x() + ny * pts[i].y() + c;
            s += d * d;
        }
        return s / static_cast<double>(e - b);
    }

    template<class V>
    void expectSquareFound(V &v, size_t outlier)
    {
        const auto pts = squareWithOutlier(outlier);
        ASSERT_TRUE(v(pts)) << "outlier at " << outlier;
        // The four sides (the outlier is collinear with the bottom side, so it joins it).
        ASSERT_EQ(v.indices().size(), 4u);
        for (size_t r = 0; r < v.indices().size(); ++r)
        {
            const auto [b, e] = v.indices()[r];
            if (b <= outlier && outlier < e)
                continue;   // the line through 1e9 cannot be re-evaluated to 1e-3 from its float parameters
            const double direct = directError(pts, b, e, v.approximations()[r]);
            EXPECT_LT(direct, 0.03 * 0.03) << "range " << r;
            // The error from the prefix sums is the points' own (a plain prefix sum is off by ~100 / count here).
            EXPECT_NEAR(v.approximations()[r].errSquared(), direct, 1e-6) << "range " << r;
        }
        ASSERT_EQ(v.vertices().size(), 5u);
        // Corners of the square (10, 0), (10, 10), (0, 10); a range may take one point of the next side (< sigma).
        EXPECT_NEAR(v.vertices()[1].x(), 10.0f, 0.02f);
        EXPECT_NEAR(v.vertices()[1].y(), 0.0f, 0.02f);
        EXPECT_NEAR(v.vertices()[2].x(), 10.0f, 0.02f);
        EXPECT_NEAR(v.vertices()[2].y(), 10.0f, 0.02f);
        EXPECT_NEAR(v.vertices()[3].x(), 0.0f, 0.02f);
        EXPECT_NEAR(v.vertices()[3].y(), 10.0f, 0.02f);
    }
}

TEST(FastPrecision, SquareWithOutlierFtls)
{
    rtl::VectorizerFTLSPolyline2D<float, double> ftls;
    for (size_t outlier : {0u, 50u})
        expectSquareFound(ftls, outlier);
}

TEST(FastPrecision, SquareWithOutlierAftls)
{
    rtl::VectorizerAFTLSPolyline2D<float, double> aftls;
    for (size_t outlier : {0u, 50u})
        expectSquareFound(aftls, outlier);
}

TEST(FastPrecision, BlockedSumsAfterOutlierAreExact)
{
    std::mt19937 gen(5);
    std::uniform_real_distribution<float> u(-3.0f, 3.0f);
    for (size_t min_blocked : {size_t(0), size_t(1) << 20})   // a row per 8 points, and a row per point
    {
        std::vector<rtl::Vector3f> pts;
        for (int i = 0; i < 3000; ++i)
            pts.emplace_back(u(gen), u(gen), u(gen));
        pts[7] = rtl::Vector3f(1e9f, -2e9f, 3e9f);
        rtl::PrecArrayBlocked<3, float, double> arr;
        arr.setMinBlockedSize(min_blocked);
        arr.precompute(pts);
        for (size_t b : {8u, 9u, 16u, 100u, 2001u})
            for (size_t len : {3u, 17u, 40u, 500u})
            {
                const auto s = arr.sums(b, b + len);
                double x2 = 0, yz = 0, x = 0;
                for (size_t i = b; i < b + len; ++i)
                {
                    x += pts[i].x();
                    x2 += static_cast<double>(pts[i].x()) * pts[i].x();
                    yz += static_cast<double>(pts[i].y()) * pts[i].z();
                }
                // A plain prefix sum is off by ~1e2 here (rounded 1e18 + 4e18 + 9e18 rows).
                EXPECT_NEAR(s.sx2(), x2, 1e-9 * (1 + x2)) << b << " " << len;
                EXPECT_NEAR(s.syz(), yz, 1e-9 * (1 + std::abs(yz)));
                EXPECT_NEAR(s.sx(), x, 1e-6);
                EXPECT_EQ(s.cnt(), static_cast<double>(len));
            }
        // Ranges containing the outlier stay consistent with it.
        const auto all = arr.sums(0, 3000);
        EXPECT_NEAR(all.sx2(), 1e18, 1e6);
    }
}

TEST(FastPrecision, Ftls3DAfterOutlier)
{
    // Two perpendicular 3D lines; a far point collinear with the first one starts the chain.
    std::vector<rtl::Vector3f> pts{rtl::Vector3f(1e9f, 0.0f, 0.0f)};
    for (int i = 0; i < 200; ++i)
        pts.emplace_back(10.0f - 0.05f * static_cast<float>(i), 0.0f, 0.0f);
    for (int i = 0; i < 200; ++i)
        pts.emplace_back(0.0f, 0.05f * static_cast<float>(i + 1), 0.0f);
    rtl::VectorizerFTLSProjections3D<float, double> ftls;
    rtl::VectorizerAFTLSProjections3D<float, double> aftls;
    ASSERT_TRUE(ftls(pts));
    ASSERT_TRUE(aftls(pts));
    // Without exact sums the y-axis points' ranges see x^2 errors of ~100 and split into many pieces.
    EXPECT_LE(ftls.indices().size(), 3u);
    EXPECT_LE(aftls.indices().size(), 3u);
    EXPECT_EQ(ftls.indices().back().second, pts.size());
    // Each range clear of the outlier reports its points' own error (direct residuals to the fitted line).
    for (size_t r = 0; r < ftls.indices().size(); ++r)
    {
        const auto [b, e] = ftls.indices()[r];
        if (b == 0)
            continue;
        const auto &l = ftls.approximations()[r];
        const Eigen::Vector3d p0 = l.point().data().cast<double>(), d = l.direction().data().cast<double>().normalized();
        double s = 0;
        for (size_t i = b; i < e; ++i)
        {
            const Eigen::Vector3d q = pts[i].data().cast<double>() - p0;
            s += (q - q.dot(d) * d).squaredNorm();
        }
        EXPECT_NEAR(l.errSquaredCompute(), s / static_cast<double>(e - b), 1e-6) << "range " << r;
    }
}

TEST(FastPrecision, HugeCoordinatesNeverGiveInfinities)
{
    std::mt19937 gen(2);
    std::uniform_real_distribution<float> u(-1.0f, 1.0f);
    for (float scale : {1e18f, 1e19f, 1e20f, 1e25f, 1e30f})
    {
        std::vector<rtl::Vector2f> pts;
        for (int i = 0; i < 50; ++i)
            pts.emplace_back(scale * (1.0f + 0.1f * static_cast<float>(i)) * u(gen), scale * u(gen));
        rtl::VectorizerFTLSPolyline2D<float, double> ftls;
        rtl::VectorizerAFTLSPolyline2D<float, double> aftls;
        ftls.setSigma(scale);
        ftls.setDelta(10 * scale);
        aftls.setSigma(scale);
        aftls.setDelta(10 * scale);
        const bool okf = ftls(pts), oka = aftls(pts);
        // Up to 1e19 the squared residuals (~1e37) fit a float: a result; beyond, they do not: documented false.
        EXPECT_EQ(okf, scale <= 1e19f) << scale;
        EXPECT_EQ(oka, scale <= 1e19f) << scale;
        for (const auto &l : ftls.approximations())
            EXPECT_TRUE(!okf || std::isfinite(l.errSquared()));
        for (const auto &l : aftls.approximations())
            EXPECT_TRUE(!oka || std::isfinite(l.errSquared()));
        for (const auto &p : ftls.vertices())
            EXPECT_TRUE(std::isfinite(p.x()) && std::isfinite(p.y()));
        for (const auto &p : aftls.vertices())
            EXPECT_TRUE(std::isfinite(p.x()) && std::isfinite(p.y()));
    }
}
