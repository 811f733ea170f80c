// The exact search's work on the slowest inputs of the FTLS/AFTLS worst-case corpus: bounded
// rounds (PartitionSearch2D.h) keep only states whose range count plus a lower bound for the rest of the chain
// fits a budget. Pinned here with work counts, not times: on the inputs where the optimum needs about as many
// ranges as the fits alone, the states and fits per point are a small fraction of the unbounded search's (which
// was the only search before: 92-348 states per point on these inputs), and the result is the same partition,
// bit for bit, as the unbounded search's, through the vectorizers as well as the search itself.
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "rtl/Vectorization.h"
#include "t_fast_corpus.h"

namespace
{
    typedef rtl::ApproximationTlsLine2D<double, double> Line;
    typedef rtl::PrecArrayBlocked<2, double, double> Arr;
    typedef rtl::PartitionSearch2D<Arr, Line> Search;
    typedef std::pair<size_t, size_t> Range;

    struct Ftls : rtl::VectorizerFTLSPolyline2D<double, double>
    {
        auto work() const { return this->pipeline.searchWork(); }
    };
    struct Aftls : rtl::VectorizerAFTLSPolyline2D<double, double>
    {
        auto work() const { return this->pipeline.searchWork(); }
    };

    struct Result
    {
        bool ok = false;
        std::vector<Range> idx;
        std::vector<double> params;   // every line's point, direction and error, exactly
        Search::Work work;
    };

    Result search(const rtl::fast_corpus::Case &c, bool bounded)
    {
        Arr a;
        a.resize(c.pts.size());
        a.precompute(c.pts);
        Search s;
        s.setSigma(c.sigma);
        s.setDelta(c.delta);
        s.setBoundedRounds(bounded);
        std::vector<Line> lines;
        Result r;
        r.ok = s(c.pts, a, lines, r.idx);
        for (const auto &l : lines)
            for (double v : {l.point().x(), l.point().y(), l.direction().x(), l.direction().y(), l.errSquaredCompute()})
                r.params.push_back(v);
        r.work = s.work();
        return r;
    }

    //! The bounded search went on to the bounded rounds (once) and returned the unbounded search's optimum, bit for bit.
    void expectSameOptimumAfterBoundedRounds(const Result &full, const Result &fast)
    {
        EXPECT_EQ(fast.idx, full.idx);
        EXPECT_EQ(fast.params, full.params);
        EXPECT_EQ(fast.work.bounded, 1u);
    }
}

// Seeds 254, 191, 151 and 66: four of today's ten slowest corpus inputs (254 was the slowest: 0.25 s for 1,319
// points, 459,296 states), where the optimum has at most one range more than the fits-only bound.
TEST(PartitionSearch2D, CorpusWorstInputsBoundedRoundsSameOptimumFewStates)
{
    struct Pin
    {
        unsigned seed;
        size_t ranges;
    };
    for (const Pin &p : {Pin{254, 4}, Pin{191, 8}, Pin{151, 11}, Pin{66, 17}})
    {
        SCOPED_TRACE(testing::Message() << "corpus seed " << p.seed);
        const auto c = rtl::fast_corpus::makeCase(p.seed);
        const size_t n = c.pts.size();
        const Result full = search(c, false), fast = search(c, true);
        ASSERT_TRUE(full.ok);
        ASSERT_TRUE(fast.ok);
        EXPECT_EQ(full.idx.size(), p.ranges);
        EXPECT_EQ(fast.idx, full.idx);
        EXPECT_EQ(fast.params, full.params);
        EXPECT_EQ(full.work.bounded, 0u);
        EXPECT_EQ(fast.work.bounded, 1u);
        // The unbounded search: 70-350 states and fits per point; the bounded rounds: at most ~12 and ~70.
        EXPECT_GE(full.work.states, 60 * n);
        EXPECT_LE(fast.work.states, 16 * n);
        EXPECT_LE(fast.work.fits, 80 * n);
        EXPECT_LE(fast.work.corners, 320 * n);
    }
}

// Seeds 84 and 117: slow inputs whose optimum needs many short "bridge" ranges at corners (R = 18 against a bound
// of 9; 12 against 7): the bounded rounds fail, the backward pass's round finds the optimum, at most ~1.25x the work.
TEST(PartitionSearch2D, CorpusBridgeInputsFallBackToTheSameOptimum)
{
    for (unsigned seed : {84u, 117u})
    {
        SCOPED_TRACE(testing::Message() << "corpus seed " << seed);
        const auto c = rtl::fast_corpus::makeCase(seed);
        const Result full = search(c, false), fast = search(c, true);
        ASSERT_TRUE(full.ok);
        expectSameOptimumAfterBoundedRounds(full, fast);
        EXPECT_LE(fast.work.states, full.work.states * 5 / 4);
        EXPECT_LE(fast.work.fits, full.work.fits * 5 / 4 + 16 * c.pts.size());
    }
}

// Bridge inputs: the backward pass's corner-aware bound equals the optimum's R, so the round on it
// keeps only states on paths of R ranges (0.1-1.9 per point); the pass tests at each corner only the ranges with the
// least count. Corner work 0.38-0.70 x the unbounded search's; before the pass the last round was the unbounded
// one, ~1.0x (this test fails there).
TEST(PartitionSearch2D, CorpusBridgeInputsBackwardPassFewerCornerTests)
{
    struct Pin
    {
        unsigned seed;
        size_t ranges;
    };
    for (const Pin &p : {Pin{35, 17}, Pin{117, 12}, Pin{297, 13}, Pin{115, 15}})
    {
        SCOPED_TRACE(testing::Message() << "corpus seed " << p.seed);
        const auto c = rtl::fast_corpus::makeCase(p.seed);
        const Result full = search(c, false), fast = search(c, true);
        ASSERT_TRUE(full.ok);
        ASSERT_TRUE(fast.ok);
        EXPECT_EQ(full.idx.size(), p.ranges);
        expectSameOptimumAfterBoundedRounds(full, fast);
        EXPECT_LE(fast.work.corners, full.work.corners * 4 / 5);
        EXPECT_LE(fast.work.states, full.work.states * 5 / 4);
    }
}

// Through the vectorizers (continuity repair ending in the exact search; AFTLS sharing it between its branches):
// FTLS returns the search's partition, and both do the bounded work.
TEST(VectorizerFTLS, CorpusWorstInputThroughTheVectorizers)
{
    const auto c = rtl::fast_corpus::makeCase(254);
    const Result full = search(c, false);
    Ftls f;
    Aftls a;
    f.setSigma(c.sigma);
    f.setDelta(c.delta);
    a.setSigma(c.sigma);
    a.setDelta(c.delta);
    ASSERT_TRUE(f(c.pts));
    ASSERT_TRUE(a(c.pts));
    EXPECT_EQ(f.indices(), full.idx);
    // AFTLS keeps its optimizer branch here (5 ranges, lower total error than the search's 4): only its work.
    EXPECT_EQ(a.indices().size(), 5u);
    EXPECT_LE(f.work().states, 16 * c.pts.size());
    EXPECT_LE(a.work().states, 16 * c.pts.size());
    EXPECT_EQ(a.work().bounded, 1u);
}

// The backward pass tests a range's corner only when its lower bound (1 + the least count at its end) can matter:
// for the least count at its start or for a round's budget. On the bridge inputs the search then
// does 0.07-0.28 x the unbounded search's corner tests (it was 0.38-1.22 x, seed 84 the most, when every fitting
// range was tested at its end), for the same optimum. t_fast_corpus_identity pins the results on all 300 inputs
// (a planted off-by-one in the rule, skipping ranges whose bound equals the least count, changes 17 of them).
TEST(PartitionSearch2D, CorpusBridgeInputsBackwardPassTestsOnlyRangesThatCanMatter)
{
    for (unsigned seed : {84u, 35u, 117u, 297u, 115u})
    {
        SCOPED_TRACE(testing::Message() << "corpus seed " << seed);
        const auto c = rtl::fast_corpus::makeCase(seed);
        const Result full = search(c, false), fast = search(c, true);
        ASSERT_TRUE(fast.ok);
        expectSameOptimumAfterBoundedRounds(full, fast);
        EXPECT_LE(fast.work.corners, full.work.corners * 35 / 100);
    }
}
