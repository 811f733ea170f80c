// Incremental TLS rejects coordinates whose squared moments would overflow its sums (fuzz_vect_simplify found
// ranges beyond sigma accepted at coordinates ~1e270: the sums were inf and every error test passed); just inside
// the limit it still fits.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include "rtl/Vectorization.h"

namespace
{
    std::vector<rtl::Vector2d> zigzag(double scale)
    {
        std::vector<rtl::Vector2d> pts;
        for (int i = 0; i < 7; ++i)
            pts.emplace_back(scale * i, scale * (i % 2));   // no 3 points on a line
        return pts;
    }
}

TEST(ItlsRange, CoordinatesWhoseSquaresOverflowAreRejected)
{
    rtl::VectorizerITLSProjections2D<double, double> itls;
    itls.setSigma(1e-3);
    EXPECT_FALSE(itls(zigzag(1e270)));   // was true: one range over all 7 points of a zigzag
    EXPECT_TRUE(itls.lineSegments().empty());
    const double limit = rtl::detail::momentSafeLimit<double>(7);
    EXPECT_GT(limit, 1e150);
    EXPECT_FALSE(itls(zigzag(limit)));   // 6 * limit lies beyond it
}

TEST(ItlsRange, LargeCoordinatesInsideTheLimitStillFit)
{
    rtl::VectorizerITLSProjections2D<double, double> itls;
    const double scale = 1e140;
    itls.setSigma(scale * 1e-3);
    ASSERT_TRUE(itls(zigzag(scale)));
    // A zigzag of amplitude 1 (scaled) fits no line within sigma: ranges of 2 points, one per edge pair at most.
    EXPECT_GE(itls.lineSegments().size(), 3u);
    for (const auto &s : itls.lineSegments())
        EXPECT_TRUE(std::isfinite(s.beg().x()) && std::isfinite(s.end().y()));
}
