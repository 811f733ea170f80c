// The exact search's corner test in its hot loops: ApproximationTlsLine2D::
// crossingDistanceSquaredUnchecked compared with a finite bound must decide exactly as the checked crossing
// (detail::crossingDistanceSquared) does, for every line pair; with an infinite delta the search must keep the
// checked path (there the checked +infinity is accepted, the unchecked NaN of parallel lines would not be).
// Near-threshold cases: the bound set to the checked value itself and to its neighbours, on the line pairs of the
// worst-case corpus, so that any change of the arithmetic (order, side of the crossing, rounding) flips some decision.
#include <cmath>
#include <limits>
#include <vector>

#include <gtest/gtest.h>

#include "rtl/Vectorization.h"
#include "t_fast_corpus.h"

namespace
{
    typedef rtl::ApproximationTlsLine2D<double, double> Line;
    typedef rtl::PrecArrayBlocked<2, double, double> Arr;
    typedef rtl::VectorND<2, double> V;

    //! Two exactly parallel horizontal runs of 10 points, 1 apart: points 0-9 at y = 0, 10-19 at y = 1.
    std::vector<rtl::Vector2d> parallelRuns()
    {
        std::vector<rtl::Vector2d> pts;
        for (int i = 0; i < 20; ++i)
            pts.emplace_back(i, i < 10 ? 0.0 : 1.0);
        return pts;
    }

    //! Both decisions at `bound`; counts the pairs compared. False (with a message) at the first difference.
    ::testing::AssertionResult sameDecision(const std::vector<rtl::Vector2d> &pts, const Line &l1, const Line &l2, size_t b, double bound)
    {
        const double checked = rtl::detail::crossingDistanceSquared(pts, l1, l2, b);
        const V m = (pts[b - 1] + pts[b]) * 0.5;
        const double unchecked = Line::crossingDistanceSquaredUnchecked(l1, l2, m);
        if ((checked <= bound) == (unchecked <= bound))
            return ::testing::AssertionSuccess();
        return ::testing::AssertionFailure() << "boundary " << b << " bound " << bound << ": checked " << checked << ", unchecked " << unchecked;
    }
}

TEST(FastCorpusCorners, UncheckedDecidesAsCheckedAtTheThreshold)
{
    size_t pairs = 0, at_threshold = 0;
    for (unsigned seed = 1; seed <= 30; ++seed)
    {
        const auto c = rtl::fast_corpus::makeCase(seed);
        Arr a;
        a.resize(c.pts.size());
        a.precompute(c.pts);
        for (size_t b = 12; b + 12 < c.pts.size(); b += 7)
            for (size_t l1 : {2, 3, 5, 11})
                for (size_t l2 : {2, 4, 7, 12})
                {
                    const Line before(a.sums(b - l1, b)), after(a.sums(b, b + l2));
                    const double d2 = rtl::detail::crossingDistanceSquared(c.pts, before, after, b);
                    ++pairs;
                    if (!std::isfinite(d2))
                        continue;
                    ++at_threshold;
                    for (double bound : {d2, std::nextafter(d2, 0.0), std::nextafter(d2, 1e300), c.delta * c.delta})
                        ASSERT_TRUE(sameDecision(c.pts, before, after, b, bound)) << "seed " << seed;
                }
    }
    EXPECT_GT(pairs, 40000u);
    EXPECT_GT(at_threshold, 40000u);
}

TEST(FastCorpusCorners, UncheckedRejectsParallelAndNonFinite)
{
    const std::vector<rtl::Vector2d> pts = parallelRuns();
    Arr a;
    a.resize(pts.size());
    a.precompute(pts);
    const Line l1(a.sums(0, 10)), l2(a.sums(10, 20)), same(a.sums(0, 10));
    ASSERT_EQ(l1.direction().y(), 0.0);   // exactly horizontal: the crossing divides by exactly zero
    ASSERT_EQ(l2.direction().y(), 0.0);
    for (double bound : {0.0, 1.0, 1e300, std::numeric_limits<double>::max()})
    {
        EXPECT_TRUE(sameDecision(pts, l1, l2, 10, bound));   // parallel, apart: t infinite
        EXPECT_TRUE(sameDecision(pts, l1, same, 10, bound));   // identical: t is 0 / 0
    }
    // Non-finite sums give a non-finite line: no finite bound accepts either way.
    std::vector<rtl::Vector2d> bad = pts;
    bad[3] = rtl::Vector2d(std::numeric_limits<double>::quiet_NaN(), 0.0);
    Arr b;
    b.resize(bad.size());
    b.precompute(bad);
    const Line nan_line(b.sums(0, 10));
    for (double bound : {0.0, 1.0, 1e300})
        EXPECT_TRUE(sameDecision(bad, nan_line, l2, 10, bound));
}

TEST(FastCorpusCorners, InfiniteDeltaAcceptsParallelCorners)
{
    // Two exactly parallel horizontal runs: with delta = +infinity every corner meets (the checked path's +infinity
    // <= +infinity), so the strict search takes the two long ranges; the unchecked NaN would reject the corner.
    const std::vector<rtl::Vector2d> pts = parallelRuns();
    Arr a;
    a.resize(pts.size());
    a.precompute(pts);
    rtl::PartitionSearch2D<Arr, Line> s;
    s.setSigma(0.01);
    s.setDelta(std::numeric_limits<double>::infinity());
    std::vector<Line> lines;
    std::vector<std::pair<size_t, size_t>> idx;
    ASSERT_TRUE(s(pts, a, lines, idx));
    ASSERT_EQ(idx.size(), 2u);
    EXPECT_EQ(idx[0], std::make_pair(size_t(0), size_t(10)));
    EXPECT_EQ(idx[1], std::make_pair(size_t(10), size_t(20)));
}
