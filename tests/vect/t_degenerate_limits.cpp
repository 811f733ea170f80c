// Results at the ends of the element type's range: Douglas-Peucker segments between subnormal (and huge) end
// points point along the segment, coincident end points are the documented degenerate case; the 3D AFTLS plane
// and FTLS/AFTLS line vectorizers reject a result whose squared error or vertices a float cannot hold (float
// coordinates beyond ~1.8e19) instead of returning true with +inf, and keep working just below that limit.
#include <cmath>
#include <limits>
#include <vector>

#include <gtest/gtest.h>

#include "rtl/Core.h"
#include "rtl/Vectorization.h"

namespace
{
    using V2f = rtl::VectorND<2, float>;
    using V3f = rtl::VectorND<3, float>;

    //! The unit direction of segment s is (end - beg) / |end - beg|, computed here in long double.
    void expectAlong(const rtl::LineSegmentND<2, float> &s)
    {
        const long double dx = (long double)s.end().x() - s.beg().x(), dy = (long double)s.end().y() - s.beg().y();
        const long double len = std::sqrt(dx * dx + dy * dy);
        ASSERT_GT(len, 0);
        EXPECT_NEAR(s.direction().x(), (double)(dx / len), 1e-6);
        EXPECT_NEAR(s.direction().y(), (double)(dy / len), 1e-6);
        EXPECT_NEAR(s.direction().length(), 1.0, 1e-6);
    }

    TEST(DouglasPeuckerDirection, SubnormalSegmentPointsAlongItself)
    {
        // Before: the squares of the difference underflow, its length is 0 and the direction was (1, 0).
        const float tiny = std::numeric_limits<float>::denorm_min();
        const std::vector<V2f> pts{V2f(0, 0), V2f(3 * tiny, 4 * tiny)};
        rtl::VectorizerDouglasPeucker2f dp(1.0f);
        std::vector<rtl::LineSegmentND<2, float>> out;
        dp(pts, out);
        ASSERT_EQ(out.size(), 1u);
        expectAlong(out[0]);
        EXPECT_NEAR(out[0].direction().x(), 0.6, 1e-6);
        EXPECT_NEAR(out[0].direction().y(), 0.8, 1e-6);
    }

    TEST(DouglasPeuckerDirection, SubnormalVerticalAndNegative)
    {
        const float tiny = 5 * std::numeric_limits<float>::denorm_min();
        const std::vector<V2f> pts{V2f(tiny, tiny), V2f(tiny, -tiny), V2f(-tiny, -tiny)};
        rtl::VectorizerDouglasPeucker2f dp(std::numeric_limits<float>::denorm_min());
        std::vector<rtl::LineSegmentND<2, float>> out;
        dp(pts, out);
        ASSERT_EQ(out.size(), 2u);
        expectAlong(out[0]);
        EXPECT_FLOAT_EQ(out[0].direction().y(), -1.0f);
        expectAlong(out[1]);
        EXPECT_FLOAT_EQ(out[1].direction().x(), -1.0f);
    }

    TEST(DouglasPeuckerDirection, HugeSegmentPointsAlongItself)
    {
        // The difference overflows float: the direction is still along the segment, not NaN or an axis.
        const float big = 3e38f;
        const std::vector<V2f> pts{V2f(-big, -big), V2f(big, big)};
        rtl::VectorizerDouglasPeucker2f dp(1.0f);
        std::vector<rtl::LineSegmentND<2, float>> out;
        dp(pts, out);
        ASSERT_EQ(out.size(), 1u);
        EXPECT_NEAR(out[0].direction().x(), std::sqrt(0.5), 1e-6);
        EXPECT_NEAR(out[0].direction().y(), std::sqrt(0.5), 1e-6);
    }

    TEST(DouglasPeuckerDirection, CoincidentEndPointsAreTheDegenerateCase)
    {
        const std::vector<V2f> pts{V2f(2, 3), V2f(2, 3)};
        rtl::VectorizerDouglasPeucker2f dp(1.0f);
        std::vector<rtl::LineSegmentND<2, float>> out;
        dp(pts, out);
        ASSERT_EQ(out.size(), 1u);
        EXPECT_EQ(out[0].direction().x(), 1.0f);
        EXPECT_EQ(out[0].direction().y(), 0.0f);
    }

    //! Six float points spanning a non-planar box of edge s.
    std::vector<V3f> box(float s)
    {
        return {V3f(0, 0, 0), V3f(s, 0, 0), V3f(0, s, 0), V3f(0, 0, s), V3f(s, s, 0), V3f(s, 0, s)};
    }

    bool allFinite(const std::vector<V3f> &v)
    {
        for (const auto &p : v)
            if (!std::isfinite(p.x()) || !std::isfinite(p.y()) || !std::isfinite(p.z())) return false;
        return true;
    }

    TEST(FloatLimits3D, PlaneResultBeyondFloatIsRejected)
    {
        // Before: true, one plane with errSquared() = +inf (the double sums were finite, the float result not).
        for (float s : {1e20f, 1e21f, 1e30f})
        {
            rtl::VectorizerAFTLSPlaneProjections3D<float, double> v;
            v.setSigma(s);
            EXPECT_FALSE(v(box(s))) << s;
            EXPECT_TRUE(v.approximations().empty());
            EXPECT_TRUE(v.indices().empty());
            EXPECT_TRUE(v.polygons().empty());
        }
    }

    TEST(FloatLimits3D, PlaneResultBelowTheLimitIsKept)
    {
        for (float s : {1.0f, 1e10f, 1e18f})
        {
            rtl::VectorizerAFTLSPlaneProjections3D<float, double> v;
            v.setSigma(s);
            ASSERT_TRUE(v(box(s))) << s;
            ASSERT_EQ(v.approximations().size(), 1u);
            // The mean squared distance from the best plane of the box: positive, of the order s^2, finite.
            const double e = v.approximations()[0].errSquared();
            EXPECT_TRUE(std::isfinite(e));
            EXPECT_GT(e, 0.01 * (double)s * s);
            EXPECT_LT(e, (double)s * s);
            ASSERT_EQ(v.polygons().size(), 1u);
            EXPECT_TRUE(allFinite(v.polygons()[0].points()));
        }
        // In double the same box at 1e20 is representable.
        std::vector<rtl::VectorND<3, double>> pts;
        for (const auto &p : box(1e20f)) pts.push_back(p.cast<double>());
        rtl::VectorizerAFTLSPlaneProjections3D<double, double> v;
        v.setSigma(1e20);
        EXPECT_TRUE(v(pts));
    }

    TEST(FloatLimits3D, LineResultBelowTheLimitIsKept)
    {
        const float s = 1e18f;
        std::vector<V3f> pts;
        for (int i = 0; i < 8; ++i) pts.emplace_back(i * s, (i % 2) * s, 0.f);
        rtl::VectorizerAFTLSProjections3D<float, double> a;
        a.setSigma(s);
        ASSERT_TRUE(a(pts));
        for (const auto &l : a.approximations()) EXPECT_TRUE(std::isfinite(l.errSquared()));
    }

    TEST(FloatLimits3D, LineResultBeyondFloatIsRejected)
    {
        // A zig-zag whose one line has a residual of order s^2: float cannot hold it beyond ~1.8e19.
        for (float s : {1e20f, 1e30f})
        {
            std::vector<V3f> pts;
            for (int i = 0; i < 8; ++i) pts.emplace_back(i * s, (i % 2) * s, 0.f);
            rtl::VectorizerAFTLSProjections3D<float, double> a;
            a.setSigma(s);
            rtl::VectorizerFTLSProjections3D<float, double> f;
            f.setSigma(s);
            // One line fits (mean squared residual s^2 / 4 < sigma^2), but s^2 / 4 overflows float. Before: true
            // with errSquared() = +inf.
            EXPECT_FALSE(a(pts)) << s;
            EXPECT_FALSE(f(pts)) << s;
            EXPECT_TRUE(a.lineSegments().empty());
            EXPECT_TRUE(f.lineSegments().empty());
        }
    }
}
