// Reumann-Witkam over the whole range: epsilon kept at full precision for double vectorizers, strip
// directions of tiny segments, and chains near the top of the range (rescaled), against a long-double reference.
#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "rtl/Core.h"
#include "rtl/Vectorization.h"
#include "point_elimination_reference.h"

namespace
{
    using pe_test::keptBy;
    using pe_test::rwReference;
}

// Issue 15.6: eps 1e-50 narrowed to 0 through setEpsilon(float).
TEST(ReumannWitkamExact, TinyEpsilonKeptInDouble)
{
    using V = rtl::Vector2d;
    const std::vector<V> pts{V(0, 0), V(1, 0), V(2, 1e-51), V(3, 0), V(4, 3e-50), V(5, 0)};
    rtl::VectorizerReumannWitkam2d rw(1e-50);
    EXPECT_EQ(keptBy(rw, pts), (std::vector<size_t>{0, 3, 4, 5}));   // 1e-51 inside, 3e-50 outside
    rw.setEpsilon(1e-50);
    EXPECT_EQ(keptBy(rw, pts), (std::vector<size_t>{0, 3, 4, 5}));
    volatile double tiny = 1e-50;
    rw.setEpsilon(static_cast<float>(tiny));   // RTL's float overload: 0 in float, so the 1e-51 point leaves the strip too
    EXPECT_EQ(keptBy(rw, pts), (std::vector<size_t>{0, 1, 2, 3, 4, 5}));
}

// Issue 15.6: eps 1e39 became inf in float and a 1e45 spike was dropped.
TEST(ReumannWitkamExact, HugeEpsilonKeepsTheSpike)
{
    using V = rtl::Vector2d;
    const std::vector<V> pts{V(0, 0), V(1e40, 0), V(2e40, 0), V(3e40, 1e45), V(4e40, 0)};
    rtl::VectorizerReumannWitkam2d rw(1e39);
    EXPECT_EQ(keptBy(rw, pts), (std::vector<size_t>{0, 2, 3, 4}));
}

// A segment far shorter than 1e-19 (its squared length underflows in float) still gives its own direction.
TEST(ReumannWitkamExact, TinySegmentDirection)
{
    using V = rtl::Vector2f;
    const std::vector<V> pts{V(0, 0), V(1e-25f, 1e-25f), V(1, 1), V(2, 2), V(3, 2.5f)};
    rtl::VectorizerReumannWitkam2f rw(0.01f);
    EXPECT_EQ(keptBy(rw, pts), (std::vector<size_t>{0, 3, 4}));
    const auto u = rtl::VectorizerReumannWitkam2f::direction(V(0, 0), V(3e-44f, 4e-44f));   // subnormal components
    EXPECT_NEAR(u[0], 0.6f, 0.03f);   // 3e-44 and 4e-44 are rounded to multiples of 1.4e-45
    EXPECT_NEAR(u[1], 0.8f, 0.03f);
    EXPECT_NEAR(u.length(), 1.0f, 1e-6f);
}

TEST(ReumannWitkamExact, MatchesLongDoubleReferenceAtEveryScale)
{
    std::mt19937 rng(11);
    std::normal_distribution<double> g(0, 1);
    int compared = 0;
    for (double scale : {1e-10, 1.0, 1e10, 1e18, 1e19, 1e30, 1e36})
        for (int c = 0; c < 10; ++c)
        {
            std::vector<rtl::Vector2f> pf;
            std::vector<rtl::Vector3d> pd;
            double x = 0, y = 0, z = 0;
            for (int i = 0; i < 300; ++i)
            {
                x += g(rng); y += g(rng); z += g(rng);
                pf.emplace_back(static_cast<float>(x * scale), static_cast<float>(y * scale));
                pd.emplace_back(x * scale * 1e270, y * scale * 1e270, z * scale * 1e270);
            }
            const double eps = scale * (0.5 + c % 3);
            if (rwReference(pf, eps * (1 - 1e-4L)) == rwReference(pf, eps * (1 + 1e-4L)))
            {
                rtl::VectorizerReumannWitkam2f rw(static_cast<float>(eps));
                EXPECT_EQ(keptBy(rw, pf), rwReference(pf, (long double)static_cast<float>(eps))) << scale << " " << c;
                ++compared;
            }
            const double epsd = eps * 1e270;
            if (rwReference(pd, epsd * (1 - 1e-6L)) == rwReference(pd, epsd * (1 + 1e-6L)))
            {
                rtl::VectorizerReumannWitkam3d rw(epsd);
                EXPECT_EQ(keptBy(rw, pd), rwReference(pd, (long double)epsd)) << scale << " " << c;
                ++compared;
            }
        }
    EXPECT_GT(compared, 120);
}

// A chain near 1e-30 in float: squared distances underflow unless rescaled (found by fuzz_vect_simplify).
TEST(ReumannWitkamExact, TinyChainRescaled)
{
    using V = rtl::Vector2f;
    const std::vector<V> pts{V(0, 0), V(1e-30f, 0), V(2e-30f, 1e-32f), V(3e-30f, 1e-32f), V(4e-30f, 1e-32f)};
    rtl::VectorizerReumannWitkam2f rw(1e-33f);
    // 2 leaves the x axis strip (1e-32 > 1e-33); 3 is 1e-32 below the strip 1 -> 2; 4 stays on y = 1e-32.
    EXPECT_EQ(keptBy(rw, pts), (std::vector<size_t>{0, 1, 2, 4}));
}
