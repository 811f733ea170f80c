// rtl::detail::firstBeyond (core/CoordinateCheck.h): the first out-of-bounds number at every position, inside and
// across the branch-free blocks, for double and float, with and without gaps, and the copy made in the same pass.
#include <cmath>
#include <cstddef>
#include <limits>
#include <vector>

#include <gtest/gtest.h>

#include "rtl/core/CoordinateCheck.h"

using rtl::detail::firstBeyond;
using rtl::detail::kCheckBlock;

namespace
{
    template<typename E>
    std::vector<E> ramp(std::size_t n)
    {
        std::vector<E> x(n);
        for (std::size_t i = 0; i < n; ++i) x[i] = static_cast<E>((i % 7 == 0 ? -1.0 : 1.0) * static_cast<double>(i % 100));
        return x;
    }

    // Every bad value at every position of inputs of several lengths (around one and two blocks): the index found is
    // that position, also with a second bad value further on.
    template<typename E>
    void eachPosition()
    {
        const E inf = std::numeric_limits<E>::infinity(), nan = std::numeric_limits<E>::quiet_NaN();
        for (std::size_t n : {std::size_t(1), std::size_t(5), kCheckBlock - 1, kCheckBlock, kCheckBlock + 3, 2 * kCheckBlock + 9})
        {
            const std::vector<E> good = ramp<E>(n);
            EXPECT_EQ(firstBeyond(good.data(), n, 100.0, false), n);
            EXPECT_EQ(firstBeyond(good.data(), n, 98.0, false), n > 99 ? std::size_t(99) : n);
            for (std::size_t i = 0; i < n; ++i)
            {
                for (E bad : {inf, -inf, nan, static_cast<E>(1e6)})
                {
                    std::vector<E> x = good;
                    x[i] = bad;
                    if (i + 2 < n) x[n - 1] = inf;  // a later bad value: still i is reported
                    EXPECT_EQ(firstBeyond(x.data(), n, 1000.0, false), i) << n << " " << i << " " << bad;
                    const std::size_t withGaps = firstBeyond(x.data(), n, 1000.0, true);
                    if (std::isnan(bad))
                        EXPECT_EQ(withGaps, i + 2 < n ? n - 1 : n) << n << " " << i;  // NaN is a gap
                    else
                        EXPECT_EQ(withGaps, i) << n << " " << i << " " << bad;
                }
            }
        }
    }
} // namespace

TEST(CoordinateCheck, FirstBeyondDouble) { eachPosition<double>(); }
TEST(CoordinateCheck, FirstBeyondFloat) { eachPosition<float>(); }

TEST(CoordinateCheck, LimitAtLeastTheLargestFiniteStillRejectsInfinity)
{
    std::vector<double> x = {1.0, std::numeric_limits<double>::max(), -std::numeric_limits<double>::max(), 2.0};
    EXPECT_EQ(firstBeyond(x.data(), x.size(), HUGE_VAL, false), x.size());
    x[3] = -HUGE_VAL;
    EXPECT_EQ(firstBeyond(x.data(), x.size(), HUGE_VAL, true), 3u);
    std::vector<float> f = {1.0f, std::numeric_limits<float>::max(), std::numeric_limits<float>::infinity()};
    EXPECT_EQ(firstBeyond(f.data(), f.size(), 1e300, false), 2u);
    EXPECT_EQ(firstBeyond(f.data(), 0, 1.0, false), 0u);
}

TEST(CoordinateCheck, CopiesInTheSamePass)
{
    const std::size_t n = 3 * kCheckBlock + 5;
    std::vector<double> x = ramp<double>(n), dst(n, -7.0);
    x[17] = std::numeric_limits<double>::quiet_NaN();
    EXPECT_EQ(firstBeyond(x.data(), n, 1000.0, true, dst.data()), n);
    for (std::size_t i = 0; i < n; ++i)
        if (i == 17) EXPECT_TRUE(std::isnan(dst[i]));
        else EXPECT_EQ(dst[i], x[i]) << i;
}
