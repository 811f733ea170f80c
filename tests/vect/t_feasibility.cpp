// The exact feasibility search of FTLS/AFTLS 2D (PartitionSearch2D), AFTLS never worse than FTLS, failure reports
// and split mode.
#include <cmath>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "rtl/Vectorization.h"
#include "rtl/io/CarmenLog.h"
#include "scan_chains.h"
#include "vect_reference.h"

using namespace vect_test;

namespace
{
    typedef rtl::ApproximationTlsLine2D<float, double> Line;
    typedef rtl::PrecArray2D<float, double> Arr;
    typedef rtl::PartitionSearch2D<Arr, Line> Search;

    //! Brute force over all 2^(n-1) partitions with the library's criteria (the search's, decided the same way):
    //! the fewest breaks any partition needs (-1: none exists), and the fewest ranges among those with no break.
    struct Brute { int min_breaks = -1; int min_ranges_strict = -1; };
    Brute bruteForce(const std::vector<rtl::Vector2f> &pts, double sigma, double delta)
    {
        Arr a;
        a.precompute(pts);
        const size_t n = pts.size();
        Brute out;
        for (unsigned mask = 0; mask < (1u << (n - 1)); ++mask)
        {
            std::vector<size_t> b{0};
            for (size_t i = 1; i < n; ++i)
                if (mask & (1u << (i - 1)))
                    b.push_back(i);
            b.push_back(n);
            bool ok = true;
            std::vector<Line> lines;
            for (size_t k = 0; k + 1 < b.size() && ok; ++k)
            {
                ok = b[k + 1] - b[k] >= 2 && (b[k + 1] - b[k] == 2 || Line::errorBelow(a.sums(b[k], b[k + 1]), sigma * sigma));
                lines.emplace_back(a.sums(b[k], b[k + 1]));
            }
            if (!ok)
                continue;
            int breaks = 0;
            for (size_t k = 0; k + 1 < lines.size(); ++k)
                breaks += rtl::detail::crossingDistanceSquared(pts, lines[k], lines[k + 1], b[k + 1]) <= delta * delta ? 0 : 1;
            if (out.min_breaks < 0 || breaks < out.min_breaks)
                out.min_breaks = breaks;
            const int ranges = static_cast<int>(lines.size());
            if (breaks == 0 && (out.min_ranges_strict < 0 || ranges < out.min_ranges_strict))
                out.min_ranges_strict = ranges;
        }
        return out;
    }

    //! Ranges partition the chain, each fits sigma (reference fits), and every corner that is not a break lies
    //! within delta; every break's crossing lies beyond delta.
    template<class V>
    void expectValidSplit(const V &v, const std::vector<rtl::Vector2f> &pts, double sigma, double delta)
    {
        expectPartition(v.indices(), pts.size());
        expectLineRms(pts, v.indices(), sigma);
        const auto &off = v.polylineOffsets();
        ASSERT_GE(off.size(), 2u);
        EXPECT_EQ(off.front(), 0u);
        EXPECT_EQ(off.back(), v.indices().size());
        ASSERT_EQ(off.size(), v.breaks().size() + 2);
        ASSERT_EQ(v.vertices().size(), v.indices().size() + off.size() - 1);
        ASSERT_EQ(v.lineSegments().size(), v.indices().size());
        for (size_t p = 1; p + 1 < off.size(); ++p)
        {
            EXPECT_EQ(v.breaks()[p - 1].boundary, v.indices()[off[p]].first);
            EXPECT_GT(v.breaks()[p - 1].crossingDistance, delta);
            EXPECT_DOUBLE_EQ(v.breaks()[p - 1].delta, static_cast<double>(static_cast<float>(delta)));
        }
        for (size_t p = 0; p + 1 < off.size(); ++p)
            for (size_t i = off[p]; i + 1 < off[p + 1]; ++i)
            {
                // Vertex between segments i and i + 1 of polyline p.
                const size_t m = v.indices()[i].second;
                const Eigen::Vector2d mid = (pts[m - 1].data().cast<double>() + pts[m].data().cast<double>()) / 2;
                EXPECT_LE((v.vertices()[i + 1 + p].data().template cast<double>() - mid).norm(), delta * (1 + 1e-6));
            }
    }

    double totalError(const std::vector<rtl::Vector2f> &pts, const std::vector<Range> &idx)
    {
        double s = 0;
        for (const auto &r : idx)
            s += refFit<2>(pts, r.first, r.second).lineErr() * static_cast<double>(r.second - r.first);
        return s;
    }

    std::vector<rtl::Vector2f> randomChain(std::mt19937 &g, size_t n)
    {
        std::uniform_real_distribution<double> u(0, 1);
        std::normal_distribution<double> nd(0, 0.01);
        std::vector<rtl::Vector2f> pts;
        double x = 0, y = 0, a = 0;
        for (size_t i = 0; i < n; ++i)
        {
            if (u(g) < 0.3)
                a += (u(g) - 0.5) * 3;
            x += 0.1 * std::cos(a);
            y += 0.1 * std::sin(a);
            pts.emplace_back(static_cast<float>(x + nd(g)), static_cast<float>(y + nd(g)));
        }
        return pts;
    }

}

// The search decides exactly what brute force over every partition decides, finds the fewest ranges, and in
// split mode the fewest breaks.
TEST(PartitionSearch2D, AgreesWithBruteForceOnSmallRandomChains)
{
    std::mt19937 g(7);
    size_t feasible = 0, infeasible = 0, with_breaks = 0;
    for (int trial = 0; trial < 400; ++trial)
    {
        const size_t n = 3 + static_cast<size_t>(trial % 11);
        const auto pts = randomChain(g, n);
        for (const auto &[sigma, delta] : {std::pair{0.01, 0.05}, std::pair{0.03, 0.3}, std::pair{0.02, 0.02}})
        {
            SCOPED_TRACE(testing::Message() << "trial " << trial << " n " << n << " sigma " << sigma << " delta " << delta);
            const Brute brute = bruteForce(pts, sigma, delta);
            Arr a;
            a.precompute(pts);
            Search s;
            s.setSigma(static_cast<float>(sigma));
            s.setDelta(static_cast<float>(delta));
            std::vector<Line> lines;
            std::vector<Range> idx;
            const bool ok = s(pts, a, lines, idx);
            ASSERT_EQ(ok, brute.min_ranges_strict >= 0);
            if (ok)
            {
                ++feasible;
                expectPartition(idx, n);
                EXPECT_EQ(static_cast<int>(idx.size()), brute.min_ranges_strict);
                EXPECT_EQ(s.polylineStarts().size(), 1u);
            }
            else
            {
                ++infeasible;
                EXPECT_TRUE(s.failure().crossingDistance > delta) << s.failure().crossingDistance;
                EXPECT_LE(s.failure().boundary, n - 2);
            }
            s.setAllowBreaks(true);
            ASSERT_EQ(s(pts, a, lines, idx), brute.min_breaks >= 0);
            if (brute.min_breaks >= 0)
            {
                expectPartition(idx, n);
                EXPECT_EQ(static_cast<int>(s.breaks().size()), brute.min_breaks);
                EXPECT_EQ(s.polylineStarts().size(), s.breaks().size() + 1);
                with_breaks += s.breaks().empty() ? 0 : 1;
            }
        }
    }
    EXPECT_GT(feasible, 100u);
    EXPECT_GT(infeasible, 50u);
    EXPECT_GT(with_breaks, 50u);
}

// A 232-point chain (a CSAIL cluster of 44 points continued by a straight wall of 188) that has a
// valid partition; the previous code gave up (its exhaustive fallback stopped at 160 points).
TEST(VectorizerFTLS, LongChainWithAValidPartitionIsFound)
{
    std::vector<rtl::Vector2f> pts{
        {4.68050671f, 2.33361459f}, {4.55923557f, 2.37338781f}, {4.61781597f, 2.45533633f}, {4.44681454f, 2.41442323f},
        {4.48679924f, 2.48707342f}, {4.30826092f, 2.43749666f}, {4.38208866f, 2.52999997f}, {4.21336651f, 2.48186255f},
        {4.2429781f, 2.54943848f}, {4.10972548f, 2.51844311f}, {4.13847494f, 2.58600593f}, {3.99767542f, 2.54680014f},
        {4.03400564f, 2.61971378f}, {3.91092443f, 2.58858442f}, {3.92963815f, 2.65057445f}, {3.80746293f, 2.61679673f},
        {3.83363152f, 2.68433762f}, {3.71236682f, 2.64800549f}, {3.7376585f, 2.71556783f}, {3.62539434f, 2.6826508f},
        {3.64177799f, 2.74427652f}, {3.53042245f, 2.70898843f}, {3.5460484f, 2.77047658f}, {3.44347596f, 2.73906446f},
        {3.45829964f, 2.80047584f}, {3.35656691f, 2.76694036f}, {3.37059546f, 2.82826543f}, {3.26974559f, 2.79262662f},
        {3.28298664f, 2.8538568f}, {3.19055128f, 2.8227613f}, {3.19552279f, 2.87726164f}, {3.11131024f, 2.85099077f},
        {3.10825324f, 2.89849305f}, {3.03931856f, 2.88420558f}, {3.03561401f, 2.93145823f}, {2.95998931f, 2.90877342f},
        {2.95570636f, 2.95570636f}, {2.88073707f, 2.93145943f}, {2.87588573f, 2.97806668f}, {2.80160308f, 2.95227361f},
        {2.79619336f, 2.99855018f}, {2.74289632f, 2.99334598f}, {2.72336149f, 3.02459955f}, {2.67672086f, 3.07921505f}};
    const rtl::Vector2f e = pts.back(), d = pts.back() - pts[pts.size() - 2];
    const double len = d.length(), nx = -d.y() / len, ny = d.x() / len;
    for (size_t i = 1; pts.size() < 232; ++i)
        pts.emplace_back(static_cast<float>(e.x() + nx * 0.02 * static_cast<double>(i)), static_cast<float>(e.y() + ny * 0.02 * static_cast<double>(i)));
    ASSERT_EQ(pts.size(), 232u);
    rtl::VectorizerFTLSPolyline2D<float, double> f;
    rtl::VectorizerAFTLSPolyline2D<float, double> af;
    f.setSigma(0.03f); f.setDelta(0.3f);
    af.setSigma(0.03f); af.setDelta(0.3f);
    ASSERT_TRUE(f(pts));
    ASSERT_TRUE(af(pts));
    expectValidSplit(f, pts, 0.03, 0.3);
    expectValidSplit(af, pts, 0.03, 0.3);
    EXPECT_EQ(f.polylineOffsets().size(), 2u);
    EXPECT_FALSE(f.failure().has_value());
    EXPECT_LE(totalError(pts, af.indices()), totalError(pts, f.indices()) * (1 + 1e-9));
}

// An Intel cluster where the continuity repair after the optimizer raised AFTLS's total squared
// error to 1.6 times FTLS's (9.06e-5 against 5.56e-5).
TEST(VectorizerAFTLS, NeverWorseThanFtlsOnARealCluster)
{
    const std::vector<rtl::Vector2f> pts{
        {3.58443713f, -3.71179342f}, {3.62745786f, -3.62745786f}, {3.69740653f, -3.570544f}, {3.84692049f, -3.58731127f},
        {3.85692167f, -3.47278786f}, {3.90184855f, -3.3918252f}, {3.9604497f, -3.32321191f}, {4.04893064f, -3.27875924f},
        {4.16069698f, -3.25069261f}};
    rtl::VectorizerFTLSPolyline2D<float, double> f;
    rtl::VectorizerAFTLSPolyline2D<float, double> af;
    f.setSigma(0.03f); f.setDelta(0.3f);
    af.setSigma(0.03f); af.setDelta(0.3f);
    ASSERT_TRUE(f(pts));
    ASSERT_TRUE(af(pts));
    expectValidSplit(f, pts, 0.03, 0.3);
    expectValidSplit(af, pts, 0.03, 0.3);
    const double ef = totalError(pts, f.indices()), ea = totalError(pts, af.indices());
    EXPECT_GT(ef, 1e-5);
    EXPECT_LE(ea, ef * (1 + 1e-9));
}

// The noise-free L that strict FTLS rejects: strict mode names the corner (the crossing (3, 0) lies 0.5 from
// the boundary midpoint, delta 0.3), split mode breaks the polyline there and covers all seven points.
TEST(VectorizerFTLS, FailureReportAndSplitModeOnANoiseFreeL)
{
    const std::vector<rtl::Vector2f> pts{{0, 0}, {1, 0}, {2, 0}, {3, 0}, {3, 1}, {3, 2}, {3, 3}};
    rtl::VectorizerFTLSPolyline2D<float, double> f;
    rtl::VectorizerAFTLSPolyline2D<float, double> af;
    f.setSigma(0.03f); f.setDelta(0.3f);
    af.setSigma(0.03f); af.setDelta(0.3f);
    EXPECT_FALSE(f.splitAtInfeasibleCorners());
    for (int k = 0; k < 2; ++k)
    {
        const bool ok = k == 0 ? f(pts) : af(pts);
        const auto &fail = k == 0 ? f.failure() : af.failure();
        EXPECT_FALSE(ok);
        EXPECT_TRUE((k == 0 ? f.indices() : af.indices()).empty());
        ASSERT_TRUE(fail.has_value());
        EXPECT_TRUE(fail->boundary == 3 || fail->boundary == 4) << fail->boundary;
        EXPECT_NEAR(fail->crossingDistance, 0.5, 1e-6);
        EXPECT_NEAR(fail->delta, 0.3, 1e-7);
        const auto &off = k == 0 ? f.polylineOffsets() : af.polylineOffsets();
        EXPECT_EQ(off, (std::vector<size_t>{0, 0}));
    }
    f.setSplitAtInfeasibleCorners(true);
    af.setSplitAtInfeasibleCorners(true);
    for (int k = 0; k < 2; ++k)
    {
        const bool ok = k == 0 ? f(pts) : af(pts);
        ASSERT_TRUE(ok);
        const auto &idx = k == 0 ? f.indices() : af.indices();
        const auto &br = k == 0 ? f.breaks() : af.breaks();
        ASSERT_EQ(idx.size(), 2u);
        ASSERT_EQ(br.size(), 1u);
        EXPECT_EQ(br[0].boundary, idx[1].first);
        EXPECT_NEAR(br[0].crossingDistance, 0.5, 1e-6);
        EXPECT_EQ(k == 0 ? f.polylineOffsets() : af.polylineOffsets(), (std::vector<size_t>{0, 1, 2}));
        EXPECT_FALSE((k == 0 ? f.failure() : af.failure()).has_value());
    }
    expectValidSplit(f, pts, 0.03, 0.3);
    expectValidSplit(af, pts, 0.03, 0.3);
    // Each polyline's end vertices are its end points projected on its line: the legs' end points.
    EXPECT_NEAR(f.vertices()[0].x(), 0.f, 1e-5);
    EXPECT_NEAR(f.vertices()[3].y(), 3.f, 1e-5);
}

// Every chain of tests/data at three settings: AFTLS's total squared error never exceeds FTLS's, both return false
// exactly when the exact search proves that no valid partition exists (and then report a corner beyond delta),
// and split mode covers every chain (sharing points only where no partition fits at all: t_split_cover.cpp).
TEST(RealScans, AftlsNeverWorseAndFalseOnlyWhenProvenInfeasible)
{
    const auto all = test_data::laserChains(3);
    ASSERT_GT(all.size(), 500u);
    size_t falses = 0, split_breaks = 0, covers = 0;
    for (const auto &[sigma, delta] : {std::pair{0.03, 0.3}, std::pair{0.03, 1.0}, std::pair{0.01, 0.3}})
    {
        rtl::VectorizerFTLSPolyline2D<float, double> f, fs;
        rtl::VectorizerAFTLSPolyline2D<float, double> af, afs;
        for (auto *v : {&f, &fs}) { v->setSigma(static_cast<float>(sigma)); v->setDelta(static_cast<float>(delta)); }
        for (auto *v : {&af, &afs}) { v->setSigma(static_cast<float>(sigma)); v->setDelta(static_cast<float>(delta)); }
        fs.setSplitAtInfeasibleCorners(true);
        afs.setSplitAtInfeasibleCorners(true);
        Search s, sb;
        s.setSigma(static_cast<float>(sigma)); s.setDelta(static_cast<float>(delta));
        sb.setSigma(static_cast<float>(sigma)); sb.setDelta(static_cast<float>(delta)); sb.setAllowBreaks(true);
        Arr a;
        std::vector<Line> lines;
        std::vector<Range> idx;
        for (size_t c = 0; c < all.size(); ++c)
        {
            const auto &pts = all[c];
            SCOPED_TRACE(testing::Message() << "chain " << c << " (" << pts.size() << " points), sigma " << sigma << ", delta " << delta);
            a.precompute(pts);
            const bool feasible = s(pts, a, lines, idx);
            const bool okf = f(pts), oka = af(pts);
            ASSERT_EQ(okf, feasible);
            ASSERT_EQ(oka, feasible);
            if (feasible)
            {
                expectValidSplit(f, pts, sigma, delta);
                expectValidSplit(af, pts, sigma, delta);
                ASSERT_LE(totalError(pts, af.indices()), totalError(pts, f.indices()) * (1 + 1e-9) + 1e-15);
            }
            else
            {
                ++falses;
                ASSERT_TRUE(f.failure().has_value());
                ASSERT_TRUE(af.failure().has_value());
                EXPECT_EQ(f.failure()->boundary, s.failure().boundary);
                EXPECT_TRUE(f.failure()->crossingDistance > delta);
            }
            // Split mode never returns false on real data; ranges share points only where no partition exists.
            const bool coverable = sb(pts, a, lines, idx);
            ASSERT_TRUE(fs(pts));
            ASSERT_TRUE(afs(pts));
            if (coverable)
            {
                expectValidSplit(fs, pts, sigma, delta);
                expectValidSplit(afs, pts, sigma, delta);
                EXPECT_EQ(fs.breaks().size(), feasible ? 0u : sb.breaks().size());
                split_breaks += fs.breaks().size();
            }
            else
            {
                ++covers;
                for (const auto *v : {&fs.indices(), &afs.indices()})
                {
                    ASSERT_EQ(v->front().first, 0u);
                    ASSERT_EQ(v->back().second, pts.size());
                    size_t shared = 0;
                    for (size_t i = 1; i < v->size(); ++i)
                    {
                        ASSERT_TRUE((*v)[i].first == (*v)[i - 1].second || (*v)[i].first + 1 == (*v)[i - 1].second);
                        shared += (*v)[i].first < (*v)[i - 1].second ? 1 : 0;
                    }
                    EXPECT_GE(shared, 1u);
                    expectLineRms(pts, *v, sigma);
                }
            }
        }
    }
    EXPECT_GT(falses, 0u);
    EXPECT_GT(split_breaks, 0u);
    EXPECT_GT(covers, 0u);
}
