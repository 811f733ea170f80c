// simplifyCompatibleIndices (rtl/vect/SimplifyCompatible.h) against a literal, recursive transcription of the
// simplify-js algorithm on point objects (the brute-force reference below), on hand-made cases where the segment
// and the line distance decide differently, semicircles, random walks, duplicates, 3D and float input; and its
// documented exceptions.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <random>
#include <stdexcept>
#include <vector>

#include <gtest/gtest.h>

#include "rtl/vect/SimplifyCompatible.h"

namespace
{
    struct P { double x, y, z; };

    // Reference: simplify-js, statement by statement, on objects; points are compared by index (object identity).
    //! a * b rounded on its own (volatile: never fused with an addition, whatever -ffp-contract says).
    double mul(double a, double b)
    {
        volatile double p = a * b;
        return p;
    }
    double sqDist(const P &a, const P &b, bool three)
    {
        const double dx = a.x - b.x, dy = a.y - b.y, dz = a.z - b.z;
        double s = mul(dx, dx) + mul(dy, dy);
        if (three) s = s + mul(dz, dz);
        return s;
    }
    double sqSegDist(const P &p, const P &p1, const P &p2, bool three)
    {
        double x = p1.x, y = p1.y, z = p1.z, dx = p2.x - x, dy = p2.y - y, dz = p2.z - z;
        if (dx != 0 || dy != 0 || (three && dz != 0))
        {
            const double num = three ? mul(p.x - x, dx) + mul(p.y - y, dy) + mul(p.z - z, dz) : mul(p.x - x, dx) + mul(p.y - y, dy);
            const double den = three ? mul(dx, dx) + mul(dy, dy) + mul(dz, dz) : mul(dx, dx) + mul(dy, dy);
            const double t = num / den;
            if (t > 1) { x = p2.x; y = p2.y; z = p2.z; }
            else if (t > 0) { x += mul(dx, t); y += mul(dy, t); z += mul(dz, t); }
        }
        dx = p.x - x; dy = p.y - y; dz = p.z - z;
        double s = mul(dx, dx) + mul(dy, dy);
        if (three) s = s + mul(dz, dz);
        return s;
    }
    //! How the reference breaks ties: simplify-js's `>` (the first maximum wins), or `>=` (the last one wins: a
    //! wrong kernel, to show that a test tells the two apart).
    enum class Ties { First, Last };
    //! Scans whose maximum above the tolerance occurs more than once (counted by the reference).
    size_t tied_scans = 0;
    void dpStep(const std::vector<P> &pts, size_t first, size_t last, double sqTol, std::vector<size_t> &out, bool three,
                Ties ties)
    {
        double maxSq = sqTol;
        size_t index = 0, equal = 0;
        for (size_t i = first + 1; i < last; ++i)
        {
            const double d = sqSegDist(pts[i], pts[first], pts[last], three);
            if (d > maxSq) { index = i; maxSq = d; equal = 1; }
            else if (d == maxSq && index != 0)
            {
                ++equal;
                if (ties == Ties::Last) index = i;
            }
        }
        if (equal > 1) ++tied_scans;
        if (maxSq > sqTol)
        {
            if (index - first > 1) dpStep(pts, first, index, sqTol, out, three, ties);
            out.push_back(index);
            if (last - index > 1) dpStep(pts, index, last, sqTol, out, three, ties);
        }
    }
    std::vector<size_t> reference(const std::vector<P> &input, double tolerance, bool hq, bool three, Ties ties = Ties::First)
    {
        std::vector<size_t> all;
        for (size_t i = 0; i < input.size(); ++i) all.push_back(i);
        if (input.size() <= 2) return all;
        const double sqTol = tolerance * tolerance;
        std::vector<size_t> radial = all;
        if (!hq)
        {
            radial = {0};
            size_t prev = 0;
            for (size_t i = 1; i < input.size(); ++i)
                if (sqDist(input[i], input[prev], three) > sqTol) { radial.push_back(i); prev = i; }
            if (prev != input.size() - 1) radial.push_back(input.size() - 1);
        }
        std::vector<P> pts;
        for (size_t i : radial) pts.push_back(input[i]);
        std::vector<size_t> local = {0};
        dpStep(pts, 0, pts.size() - 1, sqTol, local, three, ties);
        local.push_back(pts.size() - 1);
        std::vector<size_t> out;
        for (size_t i : local) out.push_back(radial[i]);
        return out;
    }

    template<typename T>
    std::vector<size_t> run(const std::vector<P> &pts, bool three, T tol, bool hq)
    {
        std::vector<T> flat;
        for (const P &p : pts)
        {
            flat.push_back(static_cast<T>(p.x));
            flat.push_back(static_cast<T>(p.y));
            if (three) flat.push_back(static_cast<T>(p.z));
        }
        return rtl::simplifyCompatibleIndices<T>(flat.data(), pts.size(), three ? 3 : 2, tol, hq);
    }

    std::vector<P> semicircle(size_t n, double noise, unsigned seed)
    {
        std::mt19937 rng(seed);
        std::normal_distribution<double> g(0, noise);
        std::vector<P> out;
        for (size_t i = 0; i < n; ++i)
        {
            const double a = M_PI * static_cast<double>(i) / static_cast<double>(n - 1);
            out.push_back({8 * std::cos(a) + g(rng), 8 * std::sin(a) + g(rng), 0});
        }
        return out;
    }
    std::vector<P> randomWalk(size_t n, unsigned seed, bool three)
    {
        std::mt19937 rng(seed);
        std::normal_distribution<double> g(0, 1);
        std::vector<P> out;
        P p{0, 0, 0};
        for (size_t i = 0; i < n; ++i)
        {
            out.push_back(p);
            p.x += g(rng); p.y += g(rng);
            if (three) p.z += g(rng);
        }
        return out;
    }
}

TEST(SimplifyCompatible, SmallInputsKeepAll)
{
    EXPECT_TRUE(run<double>({}, false, 1.0, false).empty());
    EXPECT_EQ(run<double>({{1, 2, 0}}, false, 1.0, false), (std::vector<size_t>{0}));
    EXPECT_EQ(run<double>({{1, 2, 0}, {1, 2, 0}}, false, 100.0, false), (std::vector<size_t>{0, 1}));
}

// The middle points lie near the chord's line but beyond its end: the line distance (0.1) would drop them, the
// segment distance (3) keeps the farthest one.
TEST(SimplifyCompatible, SegmentDistanceBeyondTheChord)
{
    const std::vector<P> pts{{0, 0, 0}, {5, 0.1, 0}, {3, 0, 0}, {-2, 0.1, 0}, {1, 0, 0}};
    // First chord (0,0)-(1,0): point 1 at 4 beyond b (sq 16.01), point 3 at 2 before a (sq 4.01): 1 is kept.
    const auto hq = run<double>(pts, false, 0.5, true);
    // Then chord (5,0.1)-(1,0): (-2,0.1) projects beyond (1,0), 3 away: kept; (3,0) is 0.05 off: dropped. The line
    // distance from y = 0 (at most 0.1) would have kept only the end points.
    EXPECT_EQ(hq, (std::vector<size_t>{0, 1, 3, 4}));
    EXPECT_EQ(hq, reference(pts, 0.5, true, false));
    // A point projecting inside the chord: segment and line distance agree (0.2 > 0.1 kept, 0.05 dropped).
    EXPECT_EQ(run<double>({{0, 0, 0}, {1, 0.2, 0}, {2, 0.05, 0}, {4, 0, 0}}, false, 0.1, true), (std::vector<size_t>{0, 1, 3}));
}

// A degenerate chord (closed loop) measures the distance to its end point.
TEST(SimplifyCompatible, DegenerateChordUsesTheEndPoint)
{
    const std::vector<P> loop{{0, 0, 0}, {1, 0, 0}, {1, 3, 0}, {0, 1, 0}, {0, 0, 0}};
    const auto got = run<double>(loop, false, 1.5, true);
    EXPECT_EQ(got, reference(loop, 1.5, true, false));
    // (1,3) is sqrt(10) from (0,0): kept; (1,0) and (0,1) are 0.95 and 0.32 from the new chords: dropped.
    EXPECT_EQ(got, (std::vector<size_t>{0, 2, 4}));
}

// Radial pre-pass: points within the tolerance of the last kept one are skipped; the last point is appended.
TEST(SimplifyCompatible, RadialPrePass)
{
    // Radial keeps 0, 2, 3 and appends 4 ((4.1,0) is 0.1 from (4,0)); DP then drops 3, 0.1 from chord 2-4.
    const std::vector<P> pts{{0, 0, 0}, {0.1, 0, 0}, {2, 2, 0}, {4, 0, 0}, {4.1, 0, 0}};
    EXPECT_EQ(run<double>(pts, false, 0.5, false), (std::vector<size_t>{0, 2, 4}));
    EXPECT_EQ(run<double>(pts, false, 0.5, false), reference(pts, 0.5, false, false));
    // Everything within tolerance: first and last only.
    EXPECT_EQ(run<double>(pts, false, 100.0, false), (std::vector<size_t>{0, 4}));
    EXPECT_EQ(run<double>(pts, false, std::numeric_limits<double>::infinity(), true), (std::vector<size_t>{0, 4}));
}

TEST(SimplifyCompatible, EqualsReferenceOnSemicirclesAndWalks)
{
    size_t cases = 0;
    for (unsigned seed = 1; seed <= 6; ++seed)
        for (size_t n : {3, 10, 57, 1000, 8000})
            for (bool hq : {false, true})
            {
                const auto s = semicircle(n, 0.01, seed);
                for (double tol : {0.0, 0.009, 0.09, 0.5})
                {
                    ASSERT_EQ(run<double>(s, false, tol, hq), reference(s, tol, hq, false)) << n << " " << tol;
                    ++cases;
                }
                for (bool three : {false, true})
                {
                    const auto w = randomWalk(n, seed, three);
                    for (double tol : {0.3, 1.0, 3.0})
                    {
                        ASSERT_EQ(run<double>(w, three, tol, hq), reference(w, tol, hq, three)) << n << " " << tol;
                        ++cases;
                    }
                }
            }
    EXPECT_EQ(cases, 6u * 5 * 2 * (4 + 6));
}

// Random walks keep different points with segment distance than with line distance (the reason for this
// function): check that the result is not simply the line-distance DP.
TEST(SimplifyCompatible, WalksDifferFromLineDistance)
{
    const auto w = randomWalk(5000, 3, false);
    const auto got = run<double>(w, false, 2.0, true);
    // Every dropped point is within the tolerance of the segment between its kept neighbours.
    size_t beyond_line_end = 0;
    for (size_t k = 0; k + 1 < got.size(); ++k)
        for (size_t i = got[k] + 1; i < got[k + 1]; ++i)
        {
            const P &a = w[got[k]], &b = w[got[k + 1]], &p = w[i];
            EXPECT_LE(sqSegDist(p, a, b, false), 4.0 * (1 + 1e-12));
            const double dx = b.x - a.x, dy = b.y - a.y;
            const double t = ((p.x - a.x) * dx + (p.y - a.y) * dy) / (dx * dx + dy * dy);
            beyond_line_end += (t < 0 || t > 1);
        }
    EXPECT_GT(beyond_line_end, 0u);   // some dropped points project outside their chord
}

TEST(SimplifyCompatible, FloatInputRunsInDouble)
{
    const auto s = semicircle(3000, 0.01, 9);
    std::vector<P> rounded;
    for (const P &p : s) rounded.push_back({static_cast<float>(p.x), static_cast<float>(p.y), 0});
    EXPECT_EQ(run<float>(s, false, 0.09f, false), reference(rounded, static_cast<float>(0.09f), false, false));
}

// Huge finite coordinates: differences overflow to inf; the result still equals the library's arithmetic.
TEST(SimplifyCompatible, HugeCoordinatesFollowTheLibrary)
{
    const std::vector<P> pts{{-1e308, 0, 0}, {0, 1e308, 0}, {1e308, 0, 0}, {1e308, -1e308, 0}, {0, 0, 0}};
    for (bool hq : {false, true})
        EXPECT_EQ(run<double>(pts, false, 1.0, hq), reference(pts, 1.0, hq, false));
}

// Long inputs of huge finite coordinates: the radial pass's four-point steps sum the squared distances to detect a
// non-finite coordinate; here that sum (and single squares) overflow to inf, which must neither throw nor change a
// decision (the coordinates are then checked one by one). Steps of 1e150 (squares ~1e300, their sum overflows) and
// 1e200 (every square overflows: every point passes the tolerance).
TEST(SimplifyCompatible, HugeCoordinatesLongInputsFollowTheLibrary)
{
    for (double scale : {1e150, 1e200})
        for (size_t n : {5u, 6u, 7u, 8u, 9u, 40u, 333u})
            for (bool three : {false, true})
            {
                std::vector<P> pts = randomWalk(n, 11, three);
                for (P &p : pts) { p.x *= scale; p.y *= scale; p.z *= scale; }
                for (bool hq : {false, true})
                    for (double tol : {1.0, 3 * scale, 1e300})
                    {
                        std::vector<size_t> got;
                        ASSERT_NO_THROW(got = run<double>(pts, three, tol, hq)) << scale << " " << n;
                        EXPECT_EQ(got, reference(pts, tol, hq, three)) << scale << " " << n << " " << tol;
                    }
            }
}

// A non-finite coordinate anywhere throws, in both modes, whatever the radial pass decides there: a NaN point
// passes no tolerance (the pass would drop it), an infinite one passes every finite one (it would be kept), and an
// infinite tolerance keeps nothing. Every position of short and longer inputs (the four-point steps and the tail).
TEST(SimplifyCompatible, NonFiniteCoordinateAnywhereThrows)
{
    const double inf = std::numeric_limits<double>::infinity();
    for (size_t n : {3u, 5u, 8u, 9u, 23u})
        for (bool three : {false, true})
        {
            const size_t dim = three ? 3 : 2;
            const std::vector<P> walk = randomWalk(n, 3, three);
            std::vector<double> flat;
            for (const P &p : walk)
            {
                flat.push_back(p.x);
                flat.push_back(p.y);
                if (three) flat.push_back(p.z);
            }
            for (size_t j = 0; j < flat.size(); ++j)
                for (double bad : {inf, -inf, std::nan("")})
                    for (bool hq : {false, true})
                        for (double tol : {0.5, inf})
                        {
                            std::vector<double> input = flat;
                            input[j] = bad;
                            EXPECT_THROW(rtl::simplifyCompatibleIndices(input.data(), n, dim, tol, hq), std::invalid_argument)
                                << n << " " << j << " " << bad << " " << hq << " " << tol;
                        }
        }
}

// Inputs where a fused multiply-add (one plausible contraction of the library's expressions) would round the
// distance differently and the tolerance sits between the two values: the result must follow the unfused
// arithmetic. Fails if the header's products get contracted (e.g. GCC -march=haswell without its barrier).
TEST(SimplifyCompatible, NoFusedMultiplyAdd)
{
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> u(-3, 3);
    size_t cases = 0;
    for (int attempt = 0; attempt < 200000 && cases < 300; ++attempt)
    {
        const P a{u(rng), u(rng), 0}, b{u(rng), u(rng), 0}, p{u(rng), u(rng), 0};
        const double du = sqSegDist(p, a, b, false);
        double x = a.x, y = a.y;
        const double dx = b.x - x, dy = b.y - y;
        const double t = std::fma(p.y - y, dy, mul(p.x - x, dx)) / std::fma(dy, dy, mul(dx, dx));
        if (t > 1) { x = b.x; y = b.y; }
        else if (t > 0) { x = std::fma(dx, t, x); y = std::fma(dy, t, y); }
        const double df = std::fma(p.y - y, p.y - y, mul(p.x - x, p.x - x));
        if (du == df)
            continue;
        // tol^2 in [min, max): one arithmetic keeps p, the other drops it.
        double tol = std::sqrt(std::min(du, df));
        while (mul(tol, tol) < std::min(du, df)) tol = std::nextafter(tol, 10.0);
        while (mul(tol, tol) >= std::max(du, df)) tol = std::nextafter(tol, 0.0);
        if (mul(tol, tol) < std::min(du, df))
            continue;
        const std::vector<P> pts{a, p, b};
        const std::vector<size_t> expected = du > df ? std::vector<size_t>{0, 1, 2} : std::vector<size_t>{0, 2};
        ASSERT_EQ(reference(pts, tol, true, false), expected);
        ASSERT_EQ(run<double>(pts, false, tol, true), expected) << attempt;
        ++cases;
    }
    EXPECT_EQ(cases, 300u);
}

TEST(SimplifyCompatible, PreconditionsThrowInvalidArgument)
{
    const double ok[6] = {0, 0, 1, 1, 2, 0};
    EXPECT_THROW(rtl::simplifyCompatibleIndices(ok, 3, 4, 1.0, false), std::invalid_argument);
    EXPECT_THROW(rtl::simplifyCompatibleIndices<double>(nullptr, 3, 2, 1.0, false), std::invalid_argument);
    EXPECT_THROW(rtl::simplifyCompatibleIndices(ok, 3, 2, std::nan(""), false), std::invalid_argument);
    const double bad[6] = {0, 0, std::numeric_limits<double>::infinity(), 1, 2, 0};
    EXPECT_THROW(rtl::simplifyCompatibleIndices(bad, 3, 2, 1.0, false), std::invalid_argument);
    const double nan[6] = {0, 0, 1, std::nan(""), 2, 0};
    EXPECT_THROW(rtl::simplifyCompatibleIndices(nan, 3, 2, 1.0, true), std::invalid_argument);
    EXPECT_NO_THROW(rtl::simplifyCompatibleIndices<double>(nullptr, 0, 2, 1.0, false));
}

// Equal maxima: the first one wins, as in simplify-js's `if (sqDist > maxSqDist)`. Point i and point j (> i) are
// both at distance exactly 1 from the first chord (0,0)-(1000,0); which one is kept changes the result (the
// other is then near the new chord, while the points between them at height 0.9 are not near a chord through
// j). Positions cover the kernel's layout: the scan starts at index 1 and takes blocks of 16 points, two per
// vector, then a partial block and, for an odd count, one point alone: both in one block, in one vector, in
// neighbouring vectors, across blocks (same and different lanes), in the partial block and the lone point.
namespace
{
    std::vector<P> twoPeaks(size_t n, size_t i, size_t j, double height_j)
    {
        std::vector<P> pts;
        for (size_t k = 0; k < n - 1; ++k)
        {
            const double x = static_cast<double>(k);
            if (k < i) pts.push_back({0, 0, 0});
            else if (k == i) pts.push_back({x, 1, 0});
            else if (k < j) pts.push_back({x, 0.9, 0});
            else if (k == j) pts.push_back({x, height_j, 0});
            else pts.push_back({1000, 0, 0});
        }
        pts.push_back({1000, 0, 0});
        return pts;
    }
}

TEST(SimplifyCompatible, EqualMaximaTheFirstWins)
{
    struct Pair { size_t n, i, j; };
    const std::vector<Pair> pairs{{60, 3, 10},  {60, 3, 4},   {60, 2, 3},   {60, 20, 21}, {60, 3, 40},  {60, 3, 19},
                                  {60, 4, 19},  {60, 16, 17}, {60, 5, 52},  {60, 50, 57}, {61, 10, 59}, {61, 49, 59},
                                  {200, 7, 180}, {19, 1, 17}};
    for (const Pair &c : pairs)
    {
        const auto pts = twoPeaks(c.n, c.i, c.j, 1.0);
        const P &a = pts.front(), &b = pts.back();
        ASSERT_EQ(sqSegDist(pts[c.i], a, b, false), 1.0);
        ASSERT_EQ(sqSegDist(pts[c.j], a, b, false), 1.0);
        const auto first = reference(pts, 0.3, true, false), last = reference(pts, 0.3, true, false, Ties::Last);
        // The case discriminates: the first peak is kept only when the first maximum wins.
        ASSERT_NE(first, last) << c.i << " " << c.j;
        ASSERT_TRUE(std::find(first.begin(), first.end(), c.i) != first.end());
        ASSERT_TRUE(std::find(last.begin(), last.end(), c.i) == last.end() ||
                    std::find(last.begin(), last.end(), c.j) != last.end());
        EXPECT_EQ(run<double>(pts, false, 0.3, true), first) << "n " << c.n << ", peaks " << c.i << " and " << c.j;
        EXPECT_EQ(run<double>(pts, false, 0.3, false), reference(pts, 0.3, false, false)) << c.i << " " << c.j;
    }
}

// Near-ties: the later peak one ulp higher wins (it is larger), one ulp lower loses; the kernel must compare the
// exact values, not approximations of them.
TEST(SimplifyCompatible, NearTiesFollowTheExactDistances)
{
    for (size_t n : {60, 61})
        for (const auto &ij : std::vector<std::pair<size_t, size_t>>{{3, 10}, {3, 4}, {2, 3}, {3, 40}, {50, 57}, {10, 59}})
        {
            if (ij.second >= n - 1) continue;
            for (double h : {std::nextafter(1.0, 2.0), std::nextafter(1.0, 0.0)})
            {
                const auto pts = twoPeaks(n, ij.first, ij.second, h);
                const P &a = pts.front(), &b = pts.back();
                const double di = sqSegDist(pts[ij.first], a, b, false), dj = sqSegDist(pts[ij.second], a, b, false);
                ASSERT_NE(di, dj);
                const auto expected = reference(pts, 0.3, true, false);
                // The larger one is kept whichever comes first.
                const size_t winner = dj > di ? ij.second : ij.first;
                ASSERT_TRUE(std::find(expected.begin(), expected.end(), winner) != expected.end());
                EXPECT_EQ(run<double>(pts, false, 0.3, true), expected) << n << " " << ij.first << " " << ij.second << " " << h;
            }
        }
}

// Walks on the integer grid (steps -1, 0, 1, up to 3D): many scans have their maximum more than once, at every
// position in the kernel's blocks; the result must be the reference's (first maximum), which differs from the
// last-maximum one on some of them.
TEST(SimplifyCompatible, GridWalksWithManyTies)
{
    tied_scans = 0;
    size_t differ = 0, cases = 0;
    for (unsigned seed = 1; seed <= 12; ++seed)
        for (bool three : {false, true})
            for (size_t n : {17, 18, 40, 333, 3000})
            {
                std::mt19937 rng(seed);
                std::uniform_int_distribution<int> step(-1, 1);
                std::vector<P> w;
                P p{0, 0, 0};
                for (size_t i = 0; i < n; ++i)
                {
                    w.push_back(p);
                    p.x += step(rng); p.y += step(rng);
                    if (three) p.z += step(rng);
                }
                for (double tol : {0.5, 1.0, 1.5, 3.0})
                    for (bool hq : {false, true})
                    {
                        const auto expected = reference(w, tol, hq, three);
                        ASSERT_EQ(run<double>(w, three, tol, hq), expected) << seed << " " << n << " " << tol << " " << hq;
                        differ += reference(w, tol, hq, three, Ties::Last) != expected;
                        ++cases;
                    }
            }
    EXPECT_EQ(cases, 12u * 2 * 5 * 4 * 2);
    EXPECT_GT(tied_scans, 1000u);
    EXPECT_GT(differ, 50u);
}

// The 2D scan of ranges longer than 64 points filters without a division (farthestFiltered: S = cross^2 + w^2,
// d.d times the squared segment distance, and a proven rounding margin around its maximum), then takes the exact
// distances of the blocks that pass. These cases put every point of a range within a few ulps of the same
// distance h from the chord segment: on the "stadium" around it (two parallel lines for 0 <= t <= 1, half circles
// around a and b beyond), in random order, so that the first maximum is decided by the roundings of the
// library's arithmetic, which the filter's own roundings do not follow. Scales from 1e-40 to 1e50 and offsets
// up to 7e6 chord lengths (the filter runs for |coordinates| <= 1e9, |d|^2 >= 1e-12 and 2^-24 G at most 1/256 of
// the tolerance, else the exact scan; offset 5e4 makes the bound's 4 eps G part, for float rounding of the
// coordinates, the largest). A filter without margin, without that part, or one that clamps w on one side only,
// keeps other points.
namespace
{
    std::vector<P> stadium(size_t n, double scale, double offset, double h, unsigned seed)
    {
        std::mt19937 rng(seed);
        std::uniform_real_distribution<double> u(0, 1);
        const double ax = offset, ay = offset * 0.75, bx = offset + 1000.3 * scale, by = offset * 0.75 + 377.7 * scale;
        const double len = std::hypot(bx - ax, by - ay), nx = -(by - ay) / len, ny = (bx - ax) / len;
        std::vector<P> pts{{ax, ay, 0}};
        for (size_t k = 0; k + 2 < n; ++k)
        {
            const double side = u(rng) < 0.5 ? -1 : 1, where = u(rng);
            if (where < 0.6)   // along the chord, at distance h
            {
                const double t = u(rng);
                pts.push_back({ax + t * (bx - ax) + side * h * scale * nx, ay + t * (by - ay) + side * h * scale * ny, 0});
            }
            else   // beyond an end, at distance h from it
            {
                const bool at_a = where < 0.8;
                const double phi = M_PI * u(rng), cx = at_a ? ax : bx, cy = at_a ? ay : by;
                const double along = (at_a ? -1 : 1) * std::sin(phi), across = std::cos(phi);
                pts.push_back({cx + h * scale * (along * (bx - ax) / len + across * nx),
                               cy + h * scale * (along * (by - ay) / len + across * ny), 0});
            }
        }
        pts.push_back({bx, by, 0});
        return pts;
    }
}

TEST(SimplifyCompatible, FilterMarginOnNearTiesAtAllScales)
{
    size_t cases = 0, ties_decided_by_rounding = 0;
    for (double scale : {1e-40, 1e-6, 1.0, 3e4, 1e50})
        for (double offset_units : {0.0, 1e3, 5e4, -7e6})
            for (unsigned seed = 1; seed <= 8; ++seed)
                for (size_t n : {66, 200, 1500})
                {
                    const double offset = offset_units * scale;
                    const auto pts = stadium(n, scale, offset, 2.0, seed);
                    // The distances of the first scan: how many are equal to their maximum, how many within 1e-12.
                    double top = 0;
                    for (size_t i = 1; i + 1 < n; ++i) top = std::max(top, sqSegDist(pts[i], pts.front(), pts.back(), false));
                    size_t near = 0;
                    for (size_t i = 1; i + 1 < n; ++i) near += sqSegDist(pts[i], pts.front(), pts.back(), false) >= top * (1 - 1e-12);
                    ties_decided_by_rounding += near > 1;
                    for (double tol : {1.0, 1.9})
                    {
                        ASSERT_EQ(run<double>(pts, false, tol * scale, true), reference(pts, tol * scale, true, false))
                            << "scale " << scale << " offset " << offset << " seed " << seed << " n " << n << " tol " << tol;
                        ++cases;
                    }
                }
    EXPECT_EQ(cases, 5u * 4 * 8 * 3 * 2);
    EXPECT_GT(ties_decided_by_rounding, 300u);
}

// Exact ties and one-ulp near-ties at every position of a 100-point range (filtered: blocks of 16 from index 1,
// then a partial block): two peaks at distance 1 from the chord (0,0)-(1000,0), the second one 1, 1 + ulp or 1 - ulp
// high; and peaks straight above a and b (t exactly 0 and 1), where the segment distance is the distance to the end.
TEST(SimplifyCompatible, FilterTiesAtEveryPosition)
{
    size_t cases = 0;
    const size_t n = 100;
    for (size_t i = 1; i + 2 < n; ++i)
        for (size_t j : {i + 1, i + 2, i + 15, i + 16, i + 17, n - 2})
        {
            if (j <= i || j >= n - 1) continue;
            for (double h : {1.0, std::nextafter(1.0, 2.0), std::nextafter(1.0, 0.0)})
            {
                const auto pts = twoPeaks(n, i, j, h);
                ASSERT_EQ(run<double>(pts, false, 0.3, true), reference(pts, 0.3, true, false)) << i << " " << j << " " << h;
                ++cases;
            }
        }
    // t exactly 0 and 1: points (0, +-1) and (1000, +-1) among points at height 0.5 along the chord.
    for (size_t i = 1; i + 2 < n; i += 3)
    {
        std::vector<P> pts(n, P{500, 0.5, 0});
        pts.front() = {0, 0, 0};
        pts.back() = {1000, 0, 0};
        pts[i] = {0, -1, 0};
        pts[n - 1 - i] = {1000, (i % 2) ? 1.0 : -1.0, 0};
        for (size_t k = 1; k + 1 < n; ++k)
            if (k != i && k != n - 1 - i) pts[k].x = static_cast<double>(k) * 10;
        ASSERT_EQ(sqSegDist(pts[i], pts.front(), pts.back(), false), 1.0);
        ASSERT_EQ(sqSegDist(pts[n - 1 - i], pts.front(), pts.back(), false), 1.0);
        ASSERT_EQ(run<double>(pts, false, 0.1, true), reference(pts, 0.1, true, false)) << i;
        ++cases;
    }
    EXPECT_GT(cases, 1500u);
}

// The radial pre-pass appends the last point unless it is the last one kept. simplify-js compares objects: for
// [a, b, a, c, a] (c within the tolerance of a) it keeps a, b, a and does not append the last a (the same object);
// by index the copy at 4 is appended, 2 is then on the chord's end and dropped: the same coordinates (objects) come
// out.
TEST(SimplifyCompatible, RadialPrePassRepeatedLastPoint)
{
    const double xy[10] = {0, 0, 5, 0, 0, 0, 0.1, 0, 0, 0};
    EXPECT_EQ(rtl::simplifyCompatibleIndices(xy, 5, 2, 1.0, false), (std::vector<size_t>{0, 1, 4}));
    const double same[6] = {1, 1, 1, 1, 1, 1};
    EXPECT_EQ(rtl::simplifyCompatibleIndices(same, 3, 2, 1.0, false), (std::vector<size_t>{0, 2}));
}

// Ranges of at most 32 interior points take a path of their own (farthestShort: pairs of points, the maximum,
// then its first index; an odd count's last lane reads the chord's end b and is masked). Every range length from
// 1 to 35 interior points (both sides of the limit), two peaks at every pair of positions, equal or one ulp apart;
// then small inputs on a coarse grid (duplicates, collinear runs, many ties, a zero chord) and with tolerance 0,
// where points equal to the chord's start have distance 0 and the end b's rounded residue would win if not masked.
TEST(SimplifyCompatible, ShortRangesEveryLengthAndPosition)
{
    size_t cases = 0;
    for (size_t n = 3; n <= 37; ++n)
        for (size_t i = 1; i + 1 < n; ++i)
            for (size_t j = i + 1; j + 1 < n; ++j)
                for (double h : {1.0, std::nextafter(1.0, 2.0), std::nextafter(1.0, 0.0)})
                {
                    const auto pts = twoPeaks(n, i, j, h);
                    ASSERT_EQ(run<double>(pts, false, 0.3, true), reference(pts, 0.3, true, false)) << n << " " << i << " " << j << " " << h;
                    ++cases;
                }
    EXPECT_GT(cases, 20000u);
    std::mt19937 rng(7);
    std::uniform_int_distribution<int> coarse(0, 3);
    std::uniform_real_distribution<double> fine(-1, 1);
    for (int round = 0; round < 3000; ++round)
    {
        const size_t n = 3 + static_cast<size_t>(round % 36);
        std::vector<P> pts;
        for (size_t k = 0; k < n; ++k)
            pts.push_back(round % 3 == 2 ? P{0.1 + fine(rng), 0.2 + fine(rng), 0} : P{0.5 * coarse(rng), 0.5 * coarse(rng), 0});
        for (double tol : {0.0, 0.25, 0.5, 1.0})
            for (bool hq : {false, true})
                ASSERT_EQ(run<double>(pts, false, tol, hq), reference(pts, tol, hq, false)) << round << " " << tol << " " << hq;
    }
    // Tolerance 0, interior points equal to a (distance exactly 0): nothing but the ends is kept, for a chord
    // whose end b = a + (b - a) does not hold in double.
    const double ax = 0.7, ay = 1.1, bx = 0.1, by = 0.2;
    ASSERT_TRUE(ax + (bx - ax) != bx || ay + (by - ay) != by);
    for (size_t n = 3; n <= 37; ++n)
    {
        std::vector<P> pts(n, P{ax, ay, 0});
        pts.back() = {bx, by, 0};
        ASSERT_EQ(run<double>(pts, false, 0.0, true), (std::vector<size_t>{0, n - 1})) << n;
    }
}

// largestMagnitude (the filter's bound g over the radial pass's survivors): two lanes of two vectors per step, then
// a scalar tail. The largest magnitude, positive or negative, at every position of every count up to 13 (each lane,
// each step, the tail) among smaller values, NaN passed over, infinity taken, and g only raised.
TEST(SimplifyCompatible, LargestMagnitudeEveryPosition)
{
    using rtl::detail::largestMagnitude;
    for (size_t count = 0; count <= 13; ++count)
        for (size_t at = 0; at < count; ++at)
            for (double top : {7.5, -7.5, std::numeric_limits<double>::infinity()})
            {
                std::vector<double> v(count);
                for (size_t i = 0; i < count; ++i) v[i] = (i % 2 ? -1.0 : 1.0) * (1 + 0.25 * static_cast<double>(i % 5));
                v[at] = top;
                if (count > 1) v[(at + 1) % count] = std::numeric_limits<double>::quiet_NaN();
                double g = 0;
                largestMagnitude(v.data(), count, g);
                EXPECT_EQ(g, std::fabs(top)) << "count " << count << " at " << at;
                g = 100;
                largestMagnitude(v.data(), count, g);
                EXPECT_EQ(g, std::isinf(top) ? top : 100.0) << "count " << count << " at " << at;
            }
    double g = 3;
    largestMagnitude(nullptr, 0, g);
    EXPECT_EQ(g, 3.0);
}

// The one finite check covers every input length and element type: a non-finite coordinate at any position of one,
// two or more float or double points throws invalid_argument with the same message; the largest finite values and
// empty input do not throw.
template<typename T>
void expectFiniteCheck()
{
    const T inf = std::numeric_limits<T>::infinity(), big = std::numeric_limits<T>::max();
    for (size_t n : {1u, 2u, 3u, 4u, 7u})
        for (size_t dim : {2u, 3u})
        {
            std::vector<T> flat(n * dim);
            for (size_t j = 0; j < flat.size(); ++j)
                flat[j] = static_cast<T>(j % 5) - T(2);
            for (bool hq : {false, true})
            {
                std::vector<T> edge = flat;
                edge.front() = big;
                edge.back() = -big;
                EXPECT_NO_THROW(rtl::simplifyCompatibleIndices(edge.data(), n, dim, T(0.5), hq)) << n << " " << dim;
                for (size_t j = 0; j < flat.size(); ++j)
                    for (T bad : {inf, -inf, std::numeric_limits<T>::quiet_NaN()})
                    {
                        std::vector<T> input = flat;
                        input[j] = bad;
                        try
                        {
                            rtl::simplifyCompatibleIndices(input.data(), n, dim, T(0.5), hq);
                            ADD_FAILURE() << "no exception: n " << n << " dim " << dim << " at " << j << " " << bad;
                        }
                        catch (const std::invalid_argument &e)
                        {
                            EXPECT_STREQ(e.what(), "simplifyCompatibleIndices: non-finite coordinate") << n << " " << j;
                        }
                    }
            }
        }
    EXPECT_TRUE(rtl::simplifyCompatibleIndices(static_cast<const T *>(nullptr), 0, 2, T(1), false).empty());
}

TEST(SimplifyCompatible, NonFiniteCoordinateThrowsAtEveryLengthAndType)
{
    expectFiniteCheck<double>();
    expectFiniteCheck<float>();
}
