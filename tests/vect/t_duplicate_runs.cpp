// Chains of identical points and chains that one range fits, pinned by work counts (not times): the exact
// partition search decides a range of identical points exactly (residual 0, whatever rounding its prefix sums
// carry far from the origin) and answers a chain that one range fits with that range, so these inputs cost a
// linear number of fits. Before, the rounding noise of the sums made ranges of identical points fit at random,
// and the search visited O(N^2) of them: 1,324 copies of (1e15, 1e15) took FTLS<float, double> (sigma 0.033,
// delta 1) ~0.3 s and returned false; 1,486 copies of (123.456, 1e5) took AFTLS<float, float> (a subnormal
// sigma, delta 3.4) ~0.7 s.
#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "rtl/Vectorization.h"

namespace
{
    template<typename E, typename C>
    struct Ftls : rtl::VectorizerFTLSPolyline2D<E, C>
    {
        auto work() const { return this->pipeline.searchWork(); }
    };
    template<typename E, typename C>
    struct Aftls : rtl::VectorizerAFTLSPolyline2D<E, C>
    {
        auto work() const { return this->pipeline.searchWork(); }
    };

    template<typename E>
    std::vector<rtl::VectorND<2, E>> copies(size_t n, E x, E y)
    {
        return std::vector<rtl::VectorND<2, E>>(n, rtl::VectorND<2, E>(x, y));
    }

    TEST(DuplicateRuns, FarCopiesFitAsOneRange)
    {
        // Before: false after ~N^2 / 2 fits (the sums of 1e30-sized squares cancel into noise far above sigma^2).
        const size_t n = 1324;
        Ftls<float, double> v;
        v.setSigma(0.033f);
        v.setDelta(1.0f);
        ASSERT_TRUE(v(copies<float>(n, 1e15f, 1e15f)));
        ASSERT_EQ(v.indices().size(), 1u);
        EXPECT_EQ(v.indices()[0], std::make_pair(size_t(0), n));
        EXPECT_LE(v.work().fits, 4 * n);
        EXPECT_LE(v.work().states, 4 * n);
    }

    TEST(DuplicateRuns, ZeroSigmaCopiesAreInfeasibleInLinearWork)
    {
        // sigma^2 underflows to 0 in float: only 2-point ranges fit, and their lines (all the same degenerate
        // line) never cross, so no partition exists. Before: the same answer after ~N^2 / 2 fits.
        const size_t n = 1486;
        const float sigma = std::numeric_limits<float>::denorm_min() * 64;
        ASSERT_EQ(sigma * sigma, 0.0f);
        Aftls<float, float> v;
        v.setSigma(sigma);
        v.setDelta(3.4f);
        EXPECT_FALSE(v(copies<float>(n, 123.456f, 1e5f)));
        EXPECT_TRUE(v.indices().empty());
        EXPECT_LE(v.work().fits, 40 * n);
        EXPECT_LE(v.work().states, 40 * n);
    }

    TEST(DuplicateRuns, RangesOfIdenticalPointsFitWhateverTheirSums)
    {
        // The search itself on copies far from the origin, double and float sums: one range, one fit.
        for (double c : {1.0, 1e8, 1e15, -3e150})
        {
            const size_t n = 3000;
            rtl::PrecArrayBlocked<2, double, double> a;
            a.resize(n);
            const std::vector<rtl::Vector2d> pts(n, rtl::Vector2d(c, -0.5 * c));
            a.precompute(pts);
            rtl::PartitionSearch2D<rtl::PrecArrayBlocked<2, double, double>, rtl::ApproximationTlsLine2D<double, double>> s;
            s.setSigma(1e-3);
            s.setDelta(1.0);
            std::vector<rtl::ApproximationTlsLine2D<double, double>> lines;
            std::vector<std::pair<size_t, size_t>> idx;
            ASSERT_TRUE(s(pts, a, lines, idx)) << c;
            ASSERT_EQ(idx.size(), 1u);
            EXPECT_EQ(idx[0].second, n);
            EXPECT_EQ(s.work().fits, 1u) << c;
            EXPECT_EQ(s.polylineStarts(), std::vector<size_t>{0});
            EXPECT_TRUE(s.breaks().empty());
        }
    }

    //! The search on `pts` answers one range [0, N) after one fit, and FTLS/AFTLS give that range too.
    void expectOneRangeCheaply(const std::vector<rtl::Vector2d> &pts, double sigma, double delta, const char *what)
    {
        rtl::PrecArrayBlocked<2, double, double> a;
        a.resize(pts.size());
        a.precompute(pts);
        rtl::PartitionSearch2D<rtl::PrecArrayBlocked<2, double, double>, rtl::ApproximationTlsLine2D<double, double>> s;
        s.setSigma(sigma);
        s.setDelta(delta);
        std::vector<rtl::ApproximationTlsLine2D<double, double>> lines;
        std::vector<std::pair<size_t, size_t>> idx;
        ASSERT_TRUE(s(pts, a, lines, idx)) << what;
        ASSERT_EQ(idx.size(), 1u) << what;
        EXPECT_EQ(s.work().fits, 1u) << what;
        // The line is the one of the whole chain's sums, as the search's own state would have built it.
        const rtl::ApproximationTlsLine2D<double, double> whole(a.sums(0, pts.size()));
        EXPECT_EQ(lines[0].point().x(), whole.point().x()) << what;
        EXPECT_EQ(lines[0].direction().y(), whole.direction().y()) << what;
        Ftls<double, double> f;
        f.setSigma(sigma);
        f.setDelta(delta);
        ASSERT_TRUE(f(pts)) << what;
        ASSERT_EQ(f.indices().size(), 1u) << what;
        EXPECT_LE(f.work().fits, 1u) << what;
        Aftls<double, double> af;
        af.setSigma(sigma);
        af.setDelta(delta);
        ASSERT_TRUE(af(pts)) << what;
        ASSERT_EQ(af.indices().size(), 1u) << what;
        EXPECT_LE(af.work().fits, 1u) << what;
    }

    TEST(DuplicateRuns, ChainsThatOneRangeFits)
    {
        const size_t n = 4000;
        std::mt19937 g(7);
        std::uniform_real_distribution<double> u(-1, 1);
        std::vector<rtl::Vector2d> near, tiny, straight;
        for (size_t i = 0; i < n; ++i)
        {
            near.emplace_back(1e6 + 1e-9 * u(g), -2e6 + 1e-9 * u(g));   // near-duplicates
            tiny.emplace_back(0.25 + 1e-6 * u(g), 0.5 + 1e-6 * u(g));   // a chain of tiny extent
            straight.emplace_back(0.01 * i, 0.02 * i + 1e-3 * u(g));   // a straight chain, sigma above its noise
        }
        expectOneRangeCheaply(near, 1e-3, 0.1, "near-duplicates");
        expectOneRangeCheaply(tiny, 1e-3, 0.1, "tiny extent");
        expectOneRangeCheaply(straight, 0.05, 0.1, "straight");
    }

    TEST(DuplicateRuns, RunInsideAChainCostsLinearWork)
    {
        // A straight piece, N/3 copies of one point, another straight piece: the optimum needs three ranges, and
        // every one of the ~N^2 / 18 ranges within the run fits. Before: the first round enumerated them all
        // (117 fits per point at N = 2,000, 230 at 4,000) while adding almost no state.
        for (size_t n : {600u, 2000u, 4000u})
        {
            std::vector<rtl::Vector2d> pts;
            for (size_t i = 0; i < n; ++i)
            {
                const double x = 0.01 * static_cast<double>(i < n / 3 || i >= 2 * n / 3 ? i : n / 3);
                pts.emplace_back(x, i < n / 3 ? 0.0 : i >= 2 * n / 3 ? 1.0 : 0.5);
            }
            rtl::PrecArrayBlocked<2, double, double> a;
            a.resize(n);
            a.precompute(pts);
            rtl::PartitionSearch2D<rtl::PrecArrayBlocked<2, double, double>, rtl::ApproximationTlsLine2D<double, double>> s, full;
            for (auto *search : {&s, &full})
            {
                search->setSigma(0.033);
                search->setDelta(1.0);
            }
            full.setBoundedRounds(false);
            std::vector<rtl::ApproximationTlsLine2D<double, double>> lines, full_lines;
            std::vector<std::pair<size_t, size_t>> idx, full_idx;
            ASSERT_TRUE(s(pts, a, lines, idx)) << n;
            EXPECT_EQ(idx.size(), 3u) << n;
            if (n >= 2000)
                EXPECT_LE(s.work().fits, 32 * n) << n;
            else
            {
                // The same optimum, bit for bit, as the search without bounded rounds (which visits every fitting
                // range; at 600 points the first round's fit cap, 16 N + 4096, already stops it).
                EXPECT_EQ(s.work().bounded, 1u);
                ASSERT_TRUE(full(pts, a, full_lines, full_idx));
                EXPECT_EQ(idx, full_idx);
                for (size_t r = 0; r < idx.size() && r < full_idx.size(); ++r)
                {
                    EXPECT_EQ(lines[r].point().x(), full_lines[r].point().x());
                    EXPECT_EQ(lines[r].direction().y(), full_lines[r].direction().y());
                }
            }
        }
    }
}

namespace
{
    //! The fuzz harness's reproducer (tests/fuzz/seeds/vect_fast/in-chain-duplicate-run-timeout) at N = 1,324 and
    //! its shape at other N: copies of one float point far from the origin, then N/30 copies of another one. The
    //! ranges across the two runs are decided by the rounding of their sums.
    std::vector<rtl::Vector2f> twoFarRuns(size_t n)
    {
        std::vector<rtl::Vector2f> pts(n, rtl::Vector2f(999999986991104.0f, 999999986991104.0f));
        for (size_t i = n - n / 30; i < n; ++i)
            pts[i] = rtl::Vector2f(999999986991104.0f, 951685228789760.0f);
        return pts;
    }

    //! Three runs of N/3 copies making a corner: (0, 0), (1, 0), (1, 1).
    std::vector<rtl::Vector2d> cornerOfRuns(size_t n)
    {
        std::vector<rtl::Vector2d> pts;
        for (size_t k = 0; k < n; ++k)
            pts.emplace_back(k < n / 3 ? 0.0 : 1.0, k < 2 * n / 3 ? 0.0 : 1.0);
        return pts;
    }

    //! One exact search on `pts`; all its work (fits, corner tests, states pushed) and its ranges.
    template<typename E>
    size_t searchWork(const std::vector<rtl::VectorND<2, E>> &pts, double sigma, double delta, bool breaks, bool &ok,
                      std::vector<std::pair<size_t, size_t>> &idx)
    {
        rtl::PrecArrayBlocked<2, E, double> a;
        a.resize(pts.size());
        a.precompute(pts);
        rtl::PartitionSearch2D<rtl::PrecArrayBlocked<2, E, double>, rtl::ApproximationTlsLine2D<E, double>> s;
        s.setSigma(static_cast<E>(sigma));
        s.setDelta(static_cast<E>(delta));
        s.setAllowBreaks(breaks);
        std::vector<rtl::ApproximationTlsLine2D<E, double>> lines;
        ok = s(pts, a, lines, idx);
        return s.work().fits + s.work().corners + s.work().states;
    }

    TEST(DuplicateRuns, RunsInsideAChainCostLinearWorkAtEverySize)
    {
        // Every range within a run of L copies fits (residual exactly 0), so the L^2 / 2 of them, and the corner
        // tests among their lines, made the search quadratic or worse wherever it had to go through them all: to
        // prove that no strict partition exists (the reproducer: 1.7M fits and 128M corner tests for 1,324 points,
        // 1.4 s at -O2, over 10 s under the sanitizers) or in split mode, which has no bounded rounds (the corner of
        // runs: 388 fits and 48,749 corner tests per point at N = 1,000, 1,555 and 787,545 at 4,000, a minute).
        // Ranges no longer end deep inside a run, and the work per point stays below a constant at every size.
        for (size_t n : {1000u, 1324u, 16000u})
        {
            bool ok = false;
            std::vector<std::pair<size_t, size_t>> idx;
            const size_t w = searchWork(twoFarRuns(n), 1.0 / 32, 1.0, false, ok, idx);
            EXPECT_LE(w, 8 * n + 1024) << n;
        }
        for (size_t n : {400u, 1600u, 6400u})
        {
            bool ok = false;
            std::vector<std::pair<size_t, size_t>> idx;
            const size_t w = searchWork(cornerOfRuns(n), 0.01, 0.1, true, ok, idx);
            EXPECT_LE(w, 32 * n + 1024) << n;
            // The same result as before: two ranges, the first ending where the second run begins.
            ASSERT_TRUE(ok) << n;
            ASSERT_EQ(idx.size(), 2u) << n;
            EXPECT_EQ(idx[0], std::make_pair(size_t(0), n / 3 + 1)) << n;
            EXPECT_EQ(idx[1].second, n) << n;
        }
    }
}
