// Douglas-Peucker over the whole finite range and its segment-distance option: the reported inputs
// (far points dropped when eps^2 |u|^2 and the squared cross product both overflowed), a brute-force long-double
// reference at scales from 1e-30 to 1e300, farthest points tied in Element rounding, and segment mode against
// simplifyCompatibleIndices.
#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "rtl/Core.h"
#include "rtl/vect/SimplifyCompatible.h"
#include "rtl/Vectorization.h"
#include "point_elimination_reference.h"

namespace
{
    using pe_test::keptBy;

    //! Random walks scaled to `scale`, eps a fraction of it; compared where the reference decides the same at
    //! eps (1 +- 1e-5) (no near-tie). Returns the number of chains compared.
    template<int d, typename T>
    int compareAtScale(double scale, unsigned seed)
    {
        std::mt19937 rng(seed);
        int compared = 0;
        for (int c = 0; c < 20; ++c)
        {
            const auto pts = pe_test::randomWalk<d, T>(rng, 200, scale);
            const double eps = scale * (0.5 + c % 5);
            const auto lo = pe_test::dpReference(pts, (long double)eps * (1 - 1e-5L));
            if (lo != pe_test::dpReference(pts, (long double)eps * (1 + 1e-5L))) continue;
            rtl::VectorizerDouglasPeuckerND<d, T> dp(static_cast<T>(eps));
            EXPECT_EQ(keptBy(dp, pts), lo) << "scale " << scale << " chain " << c;
            ++compared;
        }
        return compared;
    }
}

// Issue 15.5: 3f, eps 1e10, coordinates about 7e12: the squared cross product and eps^2 |u|^2 were both +inf.
TEST(DouglasPeuckerExact, IssueInput3f)
{
    using V = rtl::Vector3f;
    const std::vector<V> pts{V(7e12f, 7e12f, 7e12f), V(1.4e13f, 1.4e13f, 7e12f), V(2.1e13f, 7e12f, 7e12f)};
    rtl::VectorizerDouglasPeucker3f dp(1e10f);
    EXPECT_EQ(keptBy(dp, pts), (std::vector<size_t>{0, 1, 2}));   // the middle point is 7e12 off the chord
}

// 2D float from about 1e11.
TEST(DouglasPeuckerExact, IssueInput2f)
{
    using V = rtl::Vector2f;
    const std::vector<V> pts{V(1e11f, 1e11f), V(2e11f, 2e11f), V(3e11f, 1e11f), V(3.5e11f, 1.0001e11f), V(4e11f, 1e11f)};
    rtl::VectorizerDouglasPeucker2f dp(1e9f);
    EXPECT_EQ(keptBy(dp, pts), (std::vector<size_t>{0, 1, 2, 4}));   // 3 is 1e7 off chord 2-4
}

// Near the top of the double range: differences themselves overflow unless rescaled.
TEST(DouglasPeuckerExact, HugeDoubleCoordinates)
{
    using V = rtl::Vector2d;
    const double m = std::numeric_limits<double>::max();
    const std::vector<V> pts{V(-0.9 * m, 0), V(0, 0.8 * m), V(0.9 * m, 0), V(0.95 * m, 1e300)};
    rtl::VectorizerDouglasPeucker2d dp(1e306);
    EXPECT_EQ(keptBy(dp, pts), (std::vector<size_t>{0, 1, 2, 3}));
    dp.setEpsilon(0.81 * m);   // the spike, 0.8 max off the first chord, is within: only the ends remain
    EXPECT_EQ(keptBy(dp, pts), (std::vector<size_t>{0, 3}));
}

TEST(DouglasPeuckerExact, MatchesLongDoubleReferenceAtEveryScale)
{
    int compared = 0, expected = 0;
    for (double scale : {1e-30, 1e-5, 1.0, 1e8, 1e11, 1e15, 1e30, 1e36})
    {
        compared += compareAtScale<2, float>(scale, 1) + compareAtScale<3, float>(scale, 2);
        expected += 40;
    }
    for (double scale : {1e-300, 1e-30, 1.0, 1e30, 1e76, 1e77, 1e100, 1e153, 1e200, 1e300})
    {
        compared += compareAtScale<2, double>(scale, 3) + compareAtScale<3, double>(scale, 4);
        expected += 40;
    }
    EXPECT_GT(compared, expected * 9 / 10);   // near-ties are rare
}

// Segment distance differs from line distance where a point projects beyond the chord.
TEST(DouglasPeuckerSegment, BeyondTheChordEnd)
{
    using V = rtl::Vector2d;
    const std::vector<V> pts{V(0, 0), V(5, 0.1), V(3, 0), V(-2, 0.1), V(1, 0)};
    rtl::VectorizerDouglasPeucker2d dp(0.5);
    EXPECT_EQ(dp.distance(), rtl::DpDistance::Line);
    EXPECT_EQ(keptBy(dp, pts), (std::vector<size_t>{0, 4}));   // all within 0.1 of the line y = 0
    dp.setDistance(rtl::DpDistance::Segment);
    EXPECT_EQ(keptBy(dp, pts), (std::vector<size_t>{0, 1, 3, 4}));
}

// For double input, segment mode keeps exactly simplify-js's high-quality points.
TEST(DouglasPeuckerSegment, EqualsSimplifyCompatibleHighQuality)
{
    std::mt19937 rng(7);
    std::normal_distribution<double> g(0, 1);
    for (int c = 0; c < 30; ++c)
    {
        std::vector<rtl::Vector2d> pts;
        std::vector<double> flat;
        double x = 0, y = 0;
        for (int i = 0; i < 2000; ++i)
        {
            x += g(rng); y += g(rng);
            if (c % 3 == 0) { x *= 1e100; y *= 1e100; }   // rescaled path: exact by a power of two
            pts.emplace_back(x, y);
            flat.push_back(x);
            flat.push_back(y);
            if (c % 3 == 0) { x /= 1e100; y /= 1e100; }
        }
        const double eps = (c % 3 == 0 ? 1e100 : 1.0) * (0.5 + c % 4);
        rtl::VectorizerDouglasPeucker2d dp(eps);
        dp.setDistance(rtl::DpDistance::Segment);
        EXPECT_EQ(keptBy(dp, pts), rtl::simplifyCompatibleIndices(flat.data(), pts.size(), 2, eps, true)) << c;
    }
}

// Non-finite points are never kept in segment mode either.
TEST(DouglasPeuckerSegment, NonFiniteNeverKept)
{
    using V = rtl::Vector3d;
    const double inf = std::numeric_limits<double>::infinity();
    const std::vector<V> pts{V(0, 0, 0), V(inf, 1, 1), V(1, 5, 0), V(std::nan(""), 0, 0), V(2, 0, 0)};
    rtl::VectorizerDouglasPeucker3d dp(0.1);
    dp.setDistance(rtl::DpDistance::Segment);
    std::vector<rtl::LineSegment3d> segs;
    dp(pts, segs);
    ASSERT_EQ(segs.size(), 2u);
    EXPECT_EQ(segs[0].end(), pts[2]);
}

// Found by fuzz_vect_simplify (2D float, a near-tie the harness's long-double model did not allow for): the
// farthest point is chosen in Element arithmetic, so two points whose distances differ below float rounding are
// a tie there and the first is kept, while double (and the exact distances) tell them apart. In exact integers
// the cross products with chord 0 -> 3 are 484521520 (point 1) and 484521536 (point 2); in float both round to
// 484521536.
TEST(DouglasPeuckerExact, FarthestPointTiedInElementRounding)
{
    const std::vector<rtl::Vector2f> pf{{8205, 15}, {29555, 29555}, {29553, 29555}, {-8203, 7}};
    std::vector<rtl::Vector2d> pd;
    for (const auto &p : pf) pd.emplace_back(p[0], p[1]);
    rtl::VectorizerDouglasPeucker2f dpf(2.0f);
    rtl::VectorizerDouglasPeucker2d dpd(2.0);
    EXPECT_EQ(keptBy(dpf, pf), (std::vector<size_t>{0, 1, 3}));   // tied in float: the first
    EXPECT_EQ(keptBy(dpd, pd), (std::vector<size_t>{0, 2, 3}));   // point 2 is farther, by 16 / |u| = 9.8e-4
    bool tied = false;
    EXPECT_EQ(pe_test::dpReference(pf, 2.0L, 1e-3L * 1.01L, &tied), (std::vector<size_t>{0, 2, 3}));
    EXPECT_TRUE(tied);   // the reference sees the near-tie (the fuzz harness skips such inputs)
    tied = false;
    pe_test::dpReference(pf, 2.0L, 1e-4L, &tied);
    EXPECT_FALSE(tied);
    // Every dropped point is still within epsilon of its chord in both.
    EXPECT_LE(std::sqrt(pe_test::lineDistance2(pf, 2, 1, 3)), 2.0L);
    EXPECT_LE(std::sqrt(pe_test::lineDistance2(pf, 1, 0, 2)), 2.0L);
}

// Found by fuzz_vect_simplify (3D double, raw coordinates): a chord far shorter than 1e-150 of the chain's extent
// counts as length 0 (documented), so the distance is measured from the first end point, not from the line.
TEST(DouglasPeuckerExact, ChordBelowTheResolvedRangeMeasuresFromItsStart)
{
    using V = rtl::Vector3d;
    rtl::VectorizerDouglasPeucker3d dp(1e250);
    // The line through the ends is the z axis; the middle point is 1e200 from it but 1e260 from the first end.
    EXPECT_EQ(keptBy(dp, std::vector<V>{V(0, 0, 0), V(1e200, 0, 1e260), V(0, 0, 1e-170)}), (std::vector<size_t>{0, 1, 2}));
    // A chord of 1e200 (1e-60 of the extent) is resolved: the line distance, 1e200, is within epsilon.
    EXPECT_EQ(keptBy(dp, std::vector<V>{V(0, 0, 0), V(1e200, 0, 1e260), V(0, 0, 1e200)}), (std::vector<size_t>{0, 2}));
}

// 2D float chains are copied and checked four points per vector step: a huge or non-finite coordinate at any
// position (every lane, the scalar tail) must send the chain to the rescaled double path. A point at y = 1e25
// overflows the float scan (the chord through it has |u|^2 = inf, so no point would beat eps^2 |u|^2 there),
// while the double path keeps its neighbours; the reference is the same chain in double (tame there).
TEST(DouglasPeuckerExact, HugeOrNonFiniteCoordinateAtEveryPositionOfTheCopyPass)
{
    const float nan = std::numeric_limits<float>::quiet_NaN(), inf = std::numeric_limits<float>::infinity();
    int checked = 0;
    for (size_t n = 4; n <= 14; ++n)
        for (size_t q = 1; q + 1 < n; ++q)
            for (float v : {1e25f, -1e25f, nan, inf})
                for (int axis = 0; axis < 2; ++axis)
                {
                    std::vector<rtl::Vector2f> pf;
                    std::vector<rtl::Vector2d> pd;
                    for (size_t i = 0; i < n; ++i)
                    {
                        rtl::Vector2f p(static_cast<float>(i), 0.0f);
                        if (i == q)
                            p[axis] = v;
                        pf.push_back(p);
                        pd.emplace_back(p.x(), p.y());
                    }
                    rtl::VectorizerDouglasPeucker2f dpf(0.5f);
                    rtl::VectorizerDouglasPeucker2d dpd(0.5);
                    std::vector<rtl::LineSegment2f> sf;
                    std::vector<rtl::LineSegment2d> sd;
                    dpf(pf, sf);
                    dpd(pd, sd);
                    ASSERT_EQ(sf.size(), sd.size()) << "n " << n << " q " << q << " v " << v << " axis " << axis;
                    for (size_t k = 0; k < sf.size(); ++k)
                    {
                        const bool same = (sf[k].end().x() == sd[k].end().x() || (std::isnan(sf[k].end().x()) && std::isnan(sd[k].end().x()))) &&
                                          (sf[k].end().y() == sd[k].end().y() || (std::isnan(sf[k].end().y()) && std::isnan(sd[k].end().y())));
                        EXPECT_TRUE(same) << "n " << n << " q " << q << " v " << v << " axis " << axis << " segment " << k;
                    }
                    if (axis == 1 && std::isfinite(v) && q >= 2)
                    {
                        EXPECT_GE(sf.size(), 3u) << "n " << n << " q " << q;   // q - 1, q and the ends at least
                    }
                    ++checked;
                }
    EXPECT_EQ(checked, 4 * 2 * 77);
}

namespace
{
    //! The first DpRange event's farthest point (0 if the whole range is not split).
    template<typename T>
    size_t firstSplit(const std::vector<rtl::VectorND<2, T>> &pts, T eps)
    {
        rtl::DpTraceLog log;
        rtl::VectorizerDouglasPeuckerND<2, T, rtl::DpTraceLog> dp(eps);
        dp.setObserver(&log);
        std::vector<rtl::LineSegmentND<2, T>> segs;
        dp(pts, segs);
        for (const auto &e : log.events)
            if (const auto *r = std::get_if<rtl::DpRange>(&e))
                return r->split ? r->farthest : 0;
        return 0;
    }

    //! Douglas-Peucker driven by the public scalar farthest() (the in-order scan in Element arithmetic): the
    //! decisions the SoA block scan must reproduce on tame chains with non-degenerate chords.
    template<typename T>
    std::vector<size_t> keptByScalarScan(const std::vector<rtl::VectorND<2, T>> &pts, T eps)
    {
        rtl::VectorizerDouglasPeuckerND<2, T> dp(eps);
        std::vector<size_t> keys{0};
        std::vector<std::pair<size_t, size_t>> stack{{0, pts.size() - 1}};
        while (!stack.empty())
        {
            const auto [a, b] = stack.back();
            stack.pop_back();
            const size_t far = b - a < 2 ? 0 : dp.farthest(pts, a, b);
            if (far != 0)
            {
                stack.emplace_back(far, b);
                stack.emplace_back(a, far);
            }
            else
                keys.push_back(b);
        }
        return keys;
    }

    //! Points (i, 0) for i < n with chord (0, 0) -> (n - 1, 0): a point (i, h) has squared cross product
    //! (h (n - 1))^2, exact for the small integers and halves used here, so equal |h| tie exactly.
    template<typename T>
    std::vector<rtl::VectorND<2, T>> axisChain(size_t n)
    {
        std::vector<rtl::VectorND<2, T>> pts;
        for (size_t i = 0; i < n; ++i)
            pts.emplace_back(static_cast<T>(i), T(0));
        return pts;
    }

    template<typename T>
    void checkBlockPositions()
    {
        // The block scan runs over blocks of 16 from a + 1 (lanes of 2 doubles or 4 floats), then a scalar tail:
        // the farthest point at every position of ranges up to 4 blocks and a tail, with an exact tie later
        // (same or opposite side: the first is kept), smaller bumps before it in the same block, a point exactly
        // at epsilon (not beyond it: never picked), and the farthest point tied with an earlier lesser maximum.
        const T eps = T(0.5);
        for (size_t n = 3; n <= 72; ++n)
            for (size_t p = 1; p + 1 < n; ++p)
            {
                auto pts = axisChain<T>(n);
                pts[p][1] = T(4);
                EXPECT_EQ(firstSplit(pts, eps), p) << "n " << n << " p " << p;
                for (size_t q = p + 1; q + 1 < n; q += (q < p + 20 ? 1 : 7))
                {
                    auto tied = pts;
                    tied[q][1] = q % 2 ? T(-4) : T(4);
                    EXPECT_EQ(firstSplit(tied, eps), p) << "n " << n << " p " << p << " tie at " << q;
                }
                if (p >= 2)
                {
                    auto lesser = pts;
                    lesser[p - 1][1] = T(3.5);
                    lesser[1][1] = p > 2 ? T(-3) : lesser[1][1];
                    EXPECT_EQ(firstSplit(lesser, eps), p) << "n " << n << " p " << p << " lesser before";
                }
                auto at_eps = axisChain<T>(n);
                at_eps[p][1] = eps;   // (eps (n - 1))^2 equals the threshold eps^2 (n - 1)^2: not beyond
                EXPECT_EQ(firstSplit(at_eps, eps), size_t(0)) << "n " << n << " p " << p << " at epsilon";
                if (p + 2 < n)
                {
                    at_eps[p + 1][1] = T(0.75);
                    EXPECT_EQ(firstSplit(at_eps, eps), p + 1) << "n " << n << " p " << p << " after epsilon";
                }
            }
    }
}

TEST(DouglasPeuckerExact, BlockScanPicksTheFirstFarthestAtEveryPosition)
{
    checkBlockPositions<double>();
    checkBlockPositions<float>();
}

// Noisy arcs and random walks (many nested ranges, records inside blocks, blocks that do not beat the best): the
// kept points equal those of the in-order scalar scan.
TEST(DouglasPeuckerExact, BlockScanEqualsTheScalarScan)
{
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> noise(-0.5, 0.5);
    for (int c = 0; c < 40; ++c)
    {
        const size_t n = 50 + 997 * static_cast<size_t>(c);
        std::vector<rtl::Vector2d> pd;
        std::vector<rtl::Vector2f> pf;
        double wx = 0, wy = 0;
        for (size_t i = 0; i < n; ++i)
        {
            double x, y;
            if (c % 2 == 0)
            {
                const double a = 3.14159265358979 * static_cast<double>(i) / static_cast<double>(n - 1);
                x = 8 * std::cos(a) + 0.01 * noise(rng);
                y = 8 * std::sin(a) + 0.01 * noise(rng);
            }
            else
            {
                x = wx += noise(rng);
                y = wy += noise(rng);
            }
            pd.emplace_back(x, y);
            pf.emplace_back(static_cast<float>(x), static_cast<float>(y));
        }
        const double eps = c % 2 == 0 ? 0.01 + 0.02 * (c % 5) : 0.5 + c % 3;
        rtl::VectorizerDouglasPeucker2d dpd(eps);
        rtl::VectorizerDouglasPeucker2f dpf(static_cast<float>(eps));
        EXPECT_EQ(keptBy(dpd, pd), keptByScalarScan(pd, eps)) << "chain " << c;
        EXPECT_EQ(keptBy(dpf, pf), keptByScalarScan(pf, static_cast<float>(eps))) << "chain " << c;
    }
}

// 2D double chains are copied and checked two points per vector step: a huge or non-finite coordinate at any
// position (either lane, the scalar tail) must send the chain to the rescaled path, as the 3D copy (one point at
// a time) does for the same chain with z = 0. A point at y = 1e100 overflows the tame scan (the squared cross
// products and eps^2 |u|^2 are inf for the chords through it: no point would beat the threshold), while the
// rescaled path keeps its neighbours.
TEST(DouglasPeuckerExact, HugeOrNonFiniteDoubleAtEveryPositionOfTheCopyPass)
{
    const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
    int checked = 0;
    for (size_t n = 3; n <= 12; ++n)
        for (size_t q = 0; q < n; ++q)
            for (double v : {1e100, -1e100, 1e300, 1e77, nan, inf, -inf})
                for (int axis = 0; axis < 2; ++axis)
                {
                    std::vector<rtl::Vector2d> p2;
                    std::vector<rtl::Vector3d> p3;
                    for (size_t i = 0; i < n; ++i)
                    {
                        rtl::Vector2d p(static_cast<double>(i), (i % 3) * 0.25);
                        if (i == q)
                            p[axis] = v;
                        p2.push_back(p);
                        p3.emplace_back(p.x(), p.y(), 0.0);
                    }
                    rtl::VectorizerDouglasPeucker2d dp2(0.5);
                    rtl::VectorizerDouglasPeucker3d dp3(0.5);
                    const auto k2 = keptBy(dp2, p2), k3 = keptBy(dp3, p3);
                    EXPECT_EQ(k2, k3) << "n " << n << " q " << q << " v " << v << " axis " << axis;
                    if (axis == 1 && std::abs(v) == 1e100 && q >= 2 && q + 1 < n)
                    {
                        EXPECT_GE(k2.size(), 4u) << "n " << n << " q " << q;   // q - 1, q and the ends at least
                    }
                    ++checked;
                }
    EXPECT_EQ(checked, 75 * 7 * 2);
}

// The copy pass's largest |coordinate| (from either lane or the tail) sets the rescaling of the double path, taken
// by a range with coincident ends: with ends at the origin, points at x = 1e70 and, later, 2e70 among points at
// 1e-200, the farther one is kept and the nearer lies on its chord. Rescaled by the largest of the 1e-200 values
// instead, both distances would overflow to inf and tie, keeping the nearer.
TEST(DouglasPeuckerExact, CopyPassMaximumAtEveryPositionSetsTheRescaling)
{
    int checked = 0;
    for (size_t n = 4; n <= 11; ++n)
        for (size_t p = 1; p + 1 < n; ++p)
            for (size_t q = p + 1; q + 1 < n; ++q)
            {
                std::vector<rtl::Vector2d> pts(n, rtl::Vector2d(1e-200, 1e-200));
                pts.front() = pts.back() = rtl::Vector2d(0, 0);
                pts[p] = rtl::Vector2d(1e70, 0);
                pts[q] = rtl::Vector2d(2e70, 0);
                rtl::VectorizerDouglasPeucker2d dp(1e-100);
                EXPECT_EQ(keptBy(dp, pts), (std::vector<size_t>{0, q, n - 1})) << "n " << n << " p " << p << " q " << q;
                ++checked;
            }
    EXPECT_EQ(checked, 120);
}

// Found by fuzz_vect_simplify (2D double, raw coordinates, 900 s run): on the rescaled path the chord 0-19 is 1.3e-157
// of the chain's extent (5.1e303) and point 15 is 4.3e292 off its line (8e-12 of the extent); the cross product of the
// two, squared, underflowed to 0, so points 3, 15 and 18 were dropped though far beyond epsilon. The chord is now
// brought to unit size by a power of two first; chords below ~1.5e-154 of the extent still count as length 0.
TEST(DouglasPeuckerExact, ShortChordOnTheRescaledPathKeepsFarPoints)
{
    using V = rtl::Vector2d;
    const std::vector<V> pts{
        V(2.4178516392292583e+24, 1.6264853608840456e-307), V(1.0387856158083526e-13, 1.038785615237598e-13),
        V(-4.3861548445450414e+274, 1.0603943549172151e-294), V(2.3673056891731088e+241, 1.162222799345901e+188),
        V(-2.0309363421616846e-232, 2.9299397118705718e-260), V(-1.2726477352034457e-101, -1296298620.1356709),
        V(-6.3287055505565218e-34, 1.0976485103467615e-202), V(1.554446474734749e+245, -3.2800263486438781e-183),
        V(5.108448674964567e+303, 1.559899166308373e-280), V(-3.200969516124477e+106, -6.7544774303272707e-304),
        V(3.426811135596275e-310, 4.5196812751730681e-309), V(1.3580773871654897e-312, 1.4917595460798414e-154),
        V(-1.8123234264743482e+287, -1.0395309519563413e-269), V(1.7522456638589314e-307, 3.4900464790195377e-310),
        V(1.8078725116949103e-307, -8.2710427119047849e+116), V(8.1253199682476293e-260, -4.2507645365659048e+292),
        V(-2.2302733806792358e+123, 8.9840903803242501e-277), V(-4.9085318708800978e+297, -3.1404951670557488e+128),
        V(2.4667493631885146e-270, -1.8382596283468203e+294), V(-6.4904247898040017e+146, 1.4115455501684414e-320)};
    const double eps = 1.7049578831297719e-254;
    rtl::VectorizerDouglasPeucker2d dp(eps);
    const std::vector<size_t> kept = keptBy(dp, pts);
    ASSERT_GE(kept.size(), 2u);
    // Every dropped point within epsilon of the line through its chord, up to the documented resolution (distances
    // below ~1e-150 of the extent count as 0), in particular 15 (4.3e292 off chord 0-19 before the fix).
    for (size_t q = 0; q + 1 < kept.size(); ++q)
        for (size_t i = kept[q] + 1; i < kept[q + 1]; ++i)
        {
            // |cross| / |u| in long double: the projection form loses ~1e87 to cancellation at these magnitudes.
            const V &a = pts[kept[q]], &b = pts[kept[q + 1]], &p = pts[i];
            const long double ux = (long double)b.x() - a.x(), uy = (long double)b.y() - a.y();
            const long double vx = (long double)p.x() - a.x(), vy = (long double)p.y() - a.y();
            const long double dist = std::fabs(vx * uy - vy * ux) / std::sqrt(ux * ux + uy * uy);
            EXPECT_LE(dist, eps + 1e-150L * 5.108448674964567e+303L)   // documented: below ~1e-150 of the extent counts as 0
                << "point " << i << " dropped from chord " << kept[q] << "-" << kept[q + 1];
        }
    EXPECT_NE(std::find(kept.begin(), kept.end(), size_t(15)), kept.end());
}
