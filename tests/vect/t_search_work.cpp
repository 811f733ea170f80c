// The exact partition search's bounded corner work: on chains of long straight runs joined by
// steps that no line pair meets (where each boundary had to test every incoming line against every outgoing one),
// PartitionSearch2D finds the same optimum as a dynamic programme that tests every pair, with corner work within
// a log factor of its fits, by default and with the chord query at every boundary; AFTLS runs the exact search
// once when both of its branches need it.
#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "rtl/Vectorization.h"

namespace
{
    typedef rtl::ApproximationTlsLine2D<double, double> Line;
    typedef rtl::PrecArrayBlocked<2, double, double> Arr;
    typedef rtl::PartitionSearch2D<Arr, Line> Search;
    typedef std::pair<size_t, size_t> Range;

    //! Straight runs of `run` points (step 0.03, noise `noise`), each shifted sideways by a step of about 4 delta
    //! from the previous one: corners at the steps are met only through short bridge ranges.
    std::vector<rtl::Vector2d> steps(unsigned seed, size_t n, size_t run, double noise, double delta)
    {
        std::mt19937 g(seed);
        std::normal_distribution<double> nd(0, noise);
        std::uniform_real_distribution<double> u(-1, 1);
        std::vector<rtl::Vector2d> pts;
        double x = 0, y = 0, a = 0.3;
        for (size_t i = 0; i < n; ++i)
        {
            if (i > 0 && i % run == 0)
            {
                x += 2 * delta * u(g);
                y += 4 * delta * (u(g) > 0 ? 1 : -1);
                a += 0.3 * u(g);
            }
            pts.emplace_back(x + nd(g), y + nd(g));
            x += 0.03 * std::cos(a);
            y += 0.03 * std::sin(a);
        }
        return pts;
    }

    struct Optimum
    {
        bool found = false;
        unsigned breaks = 0, ranges = 0;
        double error = 0;
        size_t tests = 0;   // corner tests made
    };

    //! Every fitting range is a state; its cost is the least (breaks, ranges, error) over every state ending where
    //! it starts, each pair tested (with breaks: a pair that does not meet costs a break).
    Optimum everyPair(const std::vector<rtl::Vector2d> &pts, const Arr &a, double sigma, double delta, bool breaks)
    {
        struct St { size_t x; unsigned b, r; double e; };
        const size_t n = pts.size();
        std::vector<St> st;
        std::vector<std::vector<size_t>> ending(n + 1);
        Optimum o;
        auto less = [](const St &p, const St &q) {
            if (p.b != q.b) return p.b < q.b;
            if (p.r != q.r) return p.r < q.r;
            return p.e < q.e;
        };
        for (size_t x = 0; x + 2 <= n; ++x)
        {
            if (x > 0 && ending[x].empty())
                continue;
            std::vector<Line> in;
            for (size_t s : ending[x])
                in.emplace_back(a.sums(st[s].x, x));
            for (size_t y = x + 2; y <= n; ++y)
            {
                const auto sums = a.sums(x, y);
                if (y + 1 == n || !(y - x == 2 || Line::errorBelow(sums, sigma * sigma)))
                    continue;
                const double err = y - x == 2 ? 0 : Line::errorSquaredCompute(sums) * static_cast<double>(y - x);
                St best{x, std::numeric_limits<unsigned>::max(), 0, 0};
                if (x == 0)
                    best = St{0, 0, 1, err};
                const Line out(sums);
                for (size_t k = 0; k < in.size(); ++k)
                {
                    const St &p = st[ending[x][k]];
                    ++o.tests;
                    const bool meets = rtl::detail::crossingDistanceSquared(pts, in[k], out, x) <= delta * delta;
                    if (!meets && !breaks)
                        continue;
                    const St c{x, p.b + (meets ? 0u : 1u), p.r + 1, p.e + err};
                    if (less(c, best))
                        best = c;
                }
                if (best.b == std::numeric_limits<unsigned>::max())
                    continue;
                ending[y].push_back(st.size());
                st.push_back(best);
            }
        }
        for (size_t s : ending[n])
            if (!o.found || less(st[s], St{0, o.breaks, o.ranges, o.error}))
            {
                o.found = true;
                o.breaks = st[s].b;
                o.ranges = st[s].r;
                o.error = st[s].e;
            }
        return o;
    }

    //! Counts the exact-search repairs of a call.
    struct Exact
    {
        static constexpr bool enabled = true;
        size_t count = 0;
        template<class E> void operator()(const E &) {}
        void operator()(const rtl::FtlsRepair &r) { count += r.method == rtl::FtlsExactSearch; }
    };
    //! The vectorizers with their search work visible.
    struct Aftls : rtl::VectorizerAFTLSPolyline2D<double, double, Exact>
    {
        size_t states() const { return this->pipeline.searchWork().states; }
    };
    struct Ftls : rtl::VectorizerFTLSPolyline2D<double, double, Exact>
    {
        size_t states() const { return this->pipeline.searchWork().states; }
    };

    double totalError(const std::vector<Line> &lines)
    {
        double s = 0;
        for (const auto &l : lines)
            s += l.errSquaredCompute() * l.count();
        return s;
    }
}

TEST(PartitionSearch2D, SameOptimumAsEveryPairWithBoundedCornerWork)
{
    size_t found = 0, saved = 0;
    for (unsigned seed = 1; seed <= 6; ++seed)
        for (bool breaks : {false, true})
        {
            const double delta = 0.12, sigma = 0.04;
            const auto pts = steps(seed, 360, 60 + 15 * seed, 0.015 + 0.002 * seed, delta);
            SCOPED_TRACE(testing::Message() << "seed " << seed << " breaks " << breaks);
            Arr a;
            a.resize(pts.size());
            a.precompute(pts);
            const Optimum ref = everyPair(pts, a, sigma, delta, breaks);
            for (bool chords : {false, true})
            {
                SCOPED_TRACE(testing::Message() << "chord query everywhere " << chords);
                Search s;
                s.setSigma(sigma);
                s.setDelta(delta);
                s.setAllowBreaks(breaks);
                if (chords)
                    s.setCornerScan(1, 0);
                std::vector<Line> lines;
                std::vector<Range> idx;
                const bool ok = s(pts, a, lines, idx);
                ASSERT_EQ(ok, ref.found);
                if (ok)
                {
                    ++found;
                    EXPECT_EQ(s.breaks().size(), ref.breaks);
                    EXPECT_EQ(idx.size(), ref.ranges);
                    EXPECT_NEAR(totalError(lines), ref.error, 1e-9 * (1 + ref.error));
                    ASSERT_EQ(idx.front().first, 0u);
                    ASSERT_EQ(idx.back().second, pts.size());
                    for (size_t r = 1; r < idx.size(); ++r)
                        ASSERT_EQ(idx[r].first, idx[r - 1].second);
                }
                const auto &w = s.work();
                // Corner work within a log factor of the fits (testing every pair took up to fits x incoming).
                EXPECT_LE(w.corners, 64 * (w.fits + pts.size()) * static_cast<size_t>(std::log2(pts.size())));
                saved += chords && ref.tests > 10 * w.corners;
            }
        }
    EXPECT_GE(found, 16u);
    EXPECT_GE(saved, 4u);   // the chord query does a fraction of testing every pair
}

TEST(VectorizerAFTLS, BothBranchesInTheExactSearchSearchOnce)
{
    const double delta = 0.12;
    size_t both = 0;
    for (unsigned seed = 1; seed <= 16; ++seed)
    {
        const auto pts = steps(seed, 360, 60 + 15 * seed, 0.015 + 0.002 * seed, delta);
        Exact ea, ef;
        Aftls aftls;
        Ftls ftls;
        aftls.setObserver(&ea);
        ftls.setObserver(&ef);
        aftls.setSigma(0.04);
        aftls.setDelta(delta);
        ftls.setSigma(0.04);
        ftls.setDelta(delta);
        const bool okf = ftls(pts), oka = aftls(pts);
        if (ea.count < 2)
            continue;
        ++both;
        // The second branch reuses the first's search: AFTLS searches no more than FTLS does.
        EXPECT_EQ(ef.count, 1u);
        EXPECT_EQ(aftls.states(), ftls.states());
        EXPECT_EQ(oka, okf);
        if (oka)
        {
            EXPECT_EQ(aftls.indices(), ftls.indices());
        }
    }
    EXPECT_GE(both, 2u);
}
