// The hit test's fast forms (scan_polylines/RayGeometry.h) against the forms they replace: DirectionSpan (cross
// products) against AngularSpan (atan2 and wrapped angle differences) on random spans, wrap-around at +-pi, wide
// spans and degenerate ends included; distance and withinDistance against std::hypot across the double range.
#include "rtl/vect/scan_polylines/RayGeometry.h"   // first: the header compiles on its own

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <random>

namespace
{
    using rtl::scan_polylines::AngularSpan;
    using rtl::scan_polylines::DirectionSpan;
    using rtl::scan_polylines::Widening;
    constexpr double kPi = rtl::scan_polylines::kPi;

    //! Angular distance of direction `t` from the nearest end of the span (start, width) widened by w.
    double toEnds(const AngularSpan &s, double t, double w)
    {
        const double lo = s.width >= 0 ? s.start - w : s.start + s.width - w;
        const double hi = s.width >= 0 ? s.start + s.width + w : s.start + w;
        return std::min(std::abs(rtl::scan_polylines::wrapAngle(t - lo)), std::abs(rtl::scan_polylines::wrapAngle(t - hi)));
    }

    //! Compares both tests on `count` random spans whose end angles are drawn by `angle`, each with 40 directions
    //! (uniform, and just inside / outside either widened end); they must agree wherever the direction lies more than
    //! 1e-12 rad from an end. Returns how many comparisons were made.
    template<class Angle>
    std::size_t compareSpans(std::mt19937_64 &rng, Angle angle, double widen, std::size_t count, std::size_t &crossTested)
    {
        std::uniform_real_distribution<double> radius(0.05, 40.0), any(-kPi, kPi), near(-1e-6, 1e-6);
        const Widening w(widen);
        std::size_t compared = 0;
        for (std::size_t k = 0; k < count; ++k)
        {
            const double a = angle(rng), b = angle(rng), ra = radius(rng), rb = radius(rng);
            const double ax = ra * std::cos(a), ay = ra * std::sin(a), bx = rb * std::cos(b), by = rb * std::sin(b);
            const AngularSpan slow = AngularSpan::of(ax, ay, bx, by);
            const DirectionSpan fast = DirectionSpan::of(ax, ay, bx, by, w);
            if (!fast.by_angle) ++crossTested;
            const double lo = slow.width >= 0 ? slow.start - widen : slow.start + slow.width - widen;
            const double hi = slow.width >= 0 ? slow.start + slow.width + widen : slow.start + widen;
            for (int d = 0; d < 40; ++d)
            {
                double t = d < 20 ? any(rng) : (d % 2 ? lo : hi) + near(rng);
                t = rtl::scan_polylines::wrapAngle(t);
                if (toEnds(slow, t, widen) <= 1e-12) continue;
                const double r = radius(rng);
                const double ux = r * std::cos(t), uy = r * std::sin(t);
                const double at = std::atan2(uy, ux);
                EXPECT_EQ(fast.contains(ux, uy, at, w), slow.contains(at, widen))
                    << "span from " << a << " to " << b << " widened by " << widen << ", direction " << t;
                ++compared;
            }
        }
        return compared;
    }
}

TEST(DirectionSpan, AgreesWithAngularSpanOnRandomSpans)
{
    std::mt19937_64 rng(20261205);
    std::uniform_real_distribution<double> any(-kPi, kPi);
    std::size_t cross = 0;
    const std::size_t n = compareSpans(rng, [&](std::mt19937_64 &g) { return any(g); }, 1e-3, 20000, cross);
    EXPECT_GT(n, 700000u);
    EXPECT_GT(cross, 8000u);   // about half the spans are narrow enough for the cross products
}

TEST(DirectionSpan, AgreesAcrossTheWrapAroundAtPi)
{
    // Both ends within 0.3 rad of +-pi: the spans cross the atan2 branch cut, the case wrapAngle exists for.
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> off(-0.3, 0.3);
    std::size_t cross = 0;
    for (double widen : {0.0, 1e-3, 0.05})
    {
        const std::size_t before = cross;
        compareSpans(rng, [&](std::mt19937_64 &g) { const double o = off(g); return o >= 0 ? kPi - o : -kPi - o; }, widen, 5000, cross);
        EXPECT_EQ(cross - before, 5000u) << "all these spans are narrow: tested by cross products";
    }
}

TEST(DirectionSpan, SmallSpansLikeASegmentsOwnBeams)
{
    // Spans of a few beams (0.25-2 degrees) anywhere, the hit test's usual case, widened by 1e-3 rad.
    std::mt19937_64 rng(11);
    std::uniform_real_distribution<double> any(-kPi, kPi), width(-0.035, 0.035);
    double base = 0;
    bool second = false;   // compareSpans draws a span's two ends in turn: the start anywhere, the end near it
    std::size_t cross = 0;
    auto angle = [&](std::mt19937_64 &g) {
        second = !second;
        if (second) return base = any(g);
        return base + width(g);
    };
    compareSpans(rng, angle, 1e-3, 20000, cross);
    EXPECT_EQ(cross, 20000u);
}

TEST(DirectionSpan, WideAndDegenerateSpansFallBackToAngles)
{
    const Widening w(1e-3);
    // more than pi / 2 wide: by angle
    EXPECT_TRUE(DirectionSpan::of(1, 0, -1, 0.5, w).by_angle);
    // an end at the origin, or NaN: by angle (AngularSpan's own answer)
    const DirectionSpan origin = DirectionSpan::of(0, 0, 1, 1, w);
    EXPECT_TRUE(origin.by_angle);
    EXPECT_EQ(origin.contains(1, 0.5, std::atan2(0.5, 1), w), AngularSpan::of(0, 0, 1, 1).contains(std::atan2(0.5, 1), 1e-3));
    const double nan = std::numeric_limits<double>::quiet_NaN();
    EXPECT_FALSE(DirectionSpan::of(nan, 0, 1, 1, w).contains(1, 0.5, std::atan2(0.5, 1), w));
    // a NaN direction is never inside
    const DirectionSpan s = DirectionSpan::of(1, 0, 1, 1, w);
    EXPECT_FALSE(s.by_angle);
    EXPECT_FALSE(s.contains(nan, nan, nan, w));
    EXPECT_TRUE(s.contains(1, 0.5, std::atan2(0.5, 1), w));
    // the widening: 0.5e-3 rad beyond an end is in, 2e-3 out, on both sides
    EXPECT_TRUE(s.contains(std::cos(-0.5e-3), std::sin(-0.5e-3), -0.5e-3, w));
    EXPECT_FALSE(s.contains(std::cos(-2e-3), std::sin(-2e-3), -2e-3, w));
    const double e = kPi / 4;
    EXPECT_TRUE(s.contains(std::cos(e + 0.5e-3), std::sin(e + 0.5e-3), e + 0.5e-3, w));
    EXPECT_FALSE(s.contains(std::cos(e + 2e-3), std::sin(e + 2e-3), e + 2e-3, w));
    // the reversed segment covers the same directions
    const DirectionSpan r = DirectionSpan::of(1, 1, 1, 0, w);
    EXPECT_TRUE(r.contains(std::cos(-0.5e-3), std::sin(-0.5e-3), -0.5e-3, w));
    EXPECT_FALSE(r.contains(std::cos(e + 2e-3), std::sin(e + 2e-3), e + 2e-3, w));
    // the opposite direction of a narrow span is not in it (the case the two half-plane tests alone would admit)
    EXPECT_FALSE(s.contains(-1, -0.5, std::atan2(-0.5, -1), w));
}

TEST(Distance, WithinAnUlpOfHypotAndExactOutsideThePlainRange)
{
    std::mt19937_64 rng(3);
    std::uniform_real_distribution<double> mant(-1, 1);
    std::uniform_int_distribution<int> expo(-1100, 1100);
    std::size_t plain = 0;
    for (int k = 0; k < 200000; ++k)
    {
        const double x = std::ldexp(mant(rng), expo(rng) / 2), y = std::ldexp(mant(rng), expo(rng) / 2);
        const double h = std::hypot(x, y), d = rtl::scan_polylines::distance(x, y);
        const double s = x * x + y * y;
        if (s > rtl::scan_polylines::kPlainSquaredMin && s < rtl::scan_polylines::kPlainSquaredMax)
        {
            ++plain;
            EXPECT_LE(std::abs(d - h), 2.3e-16 * h) << x << ", " << y;
        }
        else
            EXPECT_EQ(d, h) << x << ", " << y;
    }
    EXPECT_GT(plain, 100000u);
    EXPECT_EQ(rtl::scan_polylines::distance(1e300, 1e300), std::hypot(1e300, 1e300));
    EXPECT_EQ(rtl::scan_polylines::distance(3e-300, 4e-300), std::hypot(3e-300, 4e-300));
    EXPECT_TRUE(std::isnan(rtl::scan_polylines::distance(std::nan(""), 1)));
}

TEST(WithinDistance, DecidesAsHypotExceptAtTies)
{
    std::mt19937_64 rng(5);
    std::uniform_real_distribution<double> mant(-1, 1), ratio(0.5, 2.0);
    std::uniform_int_distribution<int> expo(-1100, 1100);
    for (int k = 0; k < 200000; ++k)
    {
        const int e = expo(rng) / 2;
        const double x = std::ldexp(mant(rng), e), y = std::ldexp(mant(rng), e);
        const double h = std::hypot(x, y), limit = h * ratio(rng);
        if (std::abs(limit - h) <= 1e-15 * h) continue;
        EXPECT_EQ(rtl::scan_polylines::withinDistance(x, y, limit), h <= limit) << x << ", " << y << " within " << limit;
    }
    // beyond the plain range: hypot decides (1e200^2 overflows, 1e-200^2 underflows)
    EXPECT_TRUE(rtl::scan_polylines::withinDistance(1e200, 1e200, 1.5e200));
    EXPECT_FALSE(rtl::scan_polylines::withinDistance(1e200, 1e200, 1.4e200));
    EXPECT_TRUE(rtl::scan_polylines::withinDistance(3e-200, 4e-200, 5.0000001e-200));
    EXPECT_FALSE(rtl::scan_polylines::withinDistance(3e-200, 4e-200, 4.9999999e-200));
    EXPECT_FALSE(rtl::scan_polylines::withinDistance(std::nan(""), 0, 1));
    EXPECT_FALSE(rtl::scan_polylines::withinDistance(0, 0, std::nan("")));
    EXPECT_TRUE(rtl::scan_polylines::withinDistance(0, 0, 0));
}
