// The exact parts of ScanPolylines2D against brute force: the per-chain partition programme (every partition of a
// small chain into k ranges of >= 2 points enumerated), the point-vertex polyline programme (every choice of vertices
// enumerated) and the budget allocation (every combination of options).
#include "rtl/vect/scan_polylines/BudgetAllocation.h"
#include "rtl/vect/scan_polylines/ChainPartition.h"
#include "rtl/vect/scan_polylines/PointPolylines.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <limits>
#include <random>
#include <vector>

using rtl::scan_polylines::allocateBudget;
using rtl::scan_polylines::BudgetOption;
using rtl::scan_polylines::ChainPartition;
using rtl::scan_polylines::PointPolylines;

namespace
{
    //! Plain TLS error of points first..last, centred explicitly (independent of the prefix sums).
    double tlsError(const std::vector<double> &x, const std::vector<double> &y, std::size_t first, std::size_t last)
    {
        double mx = 0, my = 0;
        const double m = static_cast<double>(last - first + 1);
        for (std::size_t i = first; i <= last; ++i) { mx += x[i]; my += y[i]; }
        mx /= m; my /= m;
        double sxx = 0, sxy = 0, syy = 0;
        for (std::size_t i = first; i <= last; ++i)
        {
            sxx += (x[i] - mx) * (x[i] - mx); sxy += (x[i] - mx) * (y[i] - my); syy += (y[i] - my) * (y[i] - my);
        }
        const double h = 0.5 * (sxx - syy);
        return std::max(0.0, 0.5 * (sxx + syy) - std::sqrt(h * h + sxy * sxy));
    }

    //! Minimum over every partition of points [0, n) into k ranges of >= 2 points (inf if none).
    double bruteForce(const std::vector<double> &x, const std::vector<double> &y, std::size_t k)
    {
        const std::size_t n = x.size();
        double best = std::numeric_limits<double>::infinity();
        std::function<void(std::size_t, std::size_t, double)> rec = [&](std::size_t start, std::size_t left, double acc) {
            if (left == 0) { if (start == n) best = std::min(best, acc); return; }
            for (std::size_t end = start + 1; end < n; ++end)   // range start..end, >= 2 points
                rec(end + 1, left - 1, acc + tlsError(x, y, start, end));
        };
        rec(0, k, 0.0);
        return best;
    }

    //! Minimum over every choice of left-out head [0, a) and tail [b, n) (skip each per point) and every partition of
    //! the rest into k ranges of >= 2 points.
    double bruteForceTrimmed(const std::vector<double> &x, const std::vector<double> &y, std::size_t k, double skip)
    {
        const std::size_t n = x.size();
        double best = std::numeric_limits<double>::infinity();
        for (std::size_t a = 0; a < n; ++a)
            for (std::size_t b = a + 2 * k; b <= n; ++b)
            {
                const std::vector<double> xs(x.begin() + a, x.begin() + b), ys(y.begin() + a, y.begin() + b);
                best = std::min(best, bruteForce(xs, ys, k) + skip * static_cast<double>(a + n - b));
            }
        return best;
    }
}

namespace
{
    //! Squared orthogonal distances of points i+1..j-1 to the line through points i and j, computed directly.
    double chordError(const std::vector<double> &x, const std::vector<double> &y, std::size_t i, std::size_t j)
    {
        const double dx = x[j] - x[i], dy = y[j] - y[i], len = std::hypot(dx, dy);
        double sum = 0;
        for (std::size_t p = i + 1; p < j; ++p)
        {
            const double d = ((x[p] - x[i]) * dy - (y[p] - y[i]) * dx) / len;
            sum += d * d;
        }
        return sum;
    }

    //! Minimum over every polyline through k + 1 of the points (increasing indices) of its chord errors, the points
    //! before its first vertex and after its last left out at `skip` each (skip <= 0: vertices 0 and n - 1 fixed).
    double bruteForcePoints(const std::vector<double> &x, const std::vector<double> &y, std::size_t k, double skip)
    {
        const std::size_t n = x.size();
        double best = std::numeric_limits<double>::infinity();
        std::function<void(std::size_t, std::size_t, double)> rec = [&](std::size_t at, std::size_t left, double acc) {
            if (left == 0)
            {
                if (skip > 0) best = std::min(best, acc + skip * static_cast<double>(n - 1 - at));
                else if (at == n - 1) best = std::min(best, acc);
                return;
            }
            for (std::size_t next = at + 1; next < n; ++next) rec(next, left - 1, acc + chordError(x, y, at, next));
        };
        if (skip > 0)
            for (std::size_t first = 0; first < n; ++first) rec(first, k, skip * static_cast<double>(first));
        else
            rec(0, k, 0.0);
        return best;
    }
}

TEST(ScanPolylinesPointPolylines, MatchesBruteForceOnSmallChains)
{
    std::mt19937 rng(5);
    std::normal_distribution<double> noise(0.0, 0.05);
    std::uniform_real_distribution<double> turn(-1.5, 1.5);
    for (int trial = 0; trial < 60; ++trial)
    {
        const std::size_t n = 2 + static_cast<std::size_t>(trial % 10);   // 2..11 points
        const double skip = trial % 2 ? 0.01 : 0.0;                        // odd trials: trimmable ends
        std::vector<double> x(n), y(n);
        double px = 3, py = 1, heading = turn(rng);
        for (std::size_t i = 0; i < n; ++i)
        {
            if (i % 3 == 0) heading += turn(rng);
            px += 0.2 * std::cos(heading); py += 0.2 * std::sin(heading);
            x[i] = px + noise(rng); y[i] = py + noise(rng);
        }
        PointPolylines pp;
        pp.load(x.data(), y.data(), n);
        pp.setEndSkipCost(skip);
        pp.solve(8);
        ASSERT_EQ(pp.maxSegments(), std::min<std::size_t>(8, n - 1));
        for (std::size_t i = 0; i < n; ++i)
            for (std::size_t j = i + 1; j < n; ++j)
            {
                const double direct = chordError(x, y, i, j);
                EXPECT_NEAR(pp.chordCost(i, j), direct, 1e-10 * (1 + direct));
                EXPECT_LE(pp.lineBound(i, j), pp.chordCost(i, j));
            }
        std::vector<std::size_t> v;
        for (std::size_t k = 1; k <= pp.maxSegments(); ++k)
        {
            const double brute = bruteForcePoints(x, y, k, skip);
            EXPECT_NEAR(pp.cost(k), brute, 1e-9 * (1 + brute)) << "n " << n << " k " << k << " skip " << skip;
            // the reported vertices are increasing and their chords (plus left-out ends) add up to cost(k)
            pp.vertices(k, v);
            ASSERT_EQ(v.size(), k + 1);
            if (skip <= 0) { EXPECT_EQ(v.front(), 0u); EXPECT_EQ(v.back(), n - 1); }
            double sum = skip > 0 ? skip * static_cast<double>(v.front() + n - 1 - v.back()) : 0.0;
            for (std::size_t s = 0; s < k; ++s)
            {
                ASSERT_LT(v[s], v[s + 1]);
                sum += chordError(x, y, v[s], v[s + 1]);
            }
            EXPECT_NEAR(sum, pp.cost(k), 1e-9 * (1 + sum));
        }
    }
}

TEST(ScanPolylinesPartition, MatchesBruteForceOnSmallChains)
{
    std::mt19937 rng(7);
    std::normal_distribution<double> noise(0.0, 0.05);
    std::uniform_real_distribution<double> turn(-1.5, 1.5);
    for (int trial = 0; trial < 60; ++trial)
    {
        const std::size_t n = 2 + static_cast<std::size_t>(trial % 11);   // 2..12 points
        std::vector<double> x(n), y(n);
        double px = 3, py = 1, heading = turn(rng);
        for (std::size_t i = 0; i < n; ++i)
        {
            if (i % 3 == 0) heading += turn(rng);          // a corner every few points
            px += 0.2 * std::cos(heading); py += 0.2 * std::sin(heading);
            x[i] = px + noise(rng); y[i] = py + noise(rng);
        }
        ChainPartition part;
        part.load(x.data(), y.data(), n);
        part.solve(10);
        ASSERT_EQ(part.maxSegments(), std::min<std::size_t>(10, n / 2));
        for (std::size_t k = 1; k <= part.maxSegments(); ++k)
        {
            const double brute = bruteForce(x, y, k);
            EXPECT_NEAR(part.cost(k), brute, 1e-9 * (1 + brute)) << "n " << n << " k " << k;
            // the reported ranges are a partition into >= 2-point ranges whose costs add up to cost(k)
            const auto ranges = part.ranges(k);
            ASSERT_EQ(ranges.size(), k);
            EXPECT_EQ(ranges.front().first, 0u);
            EXPECT_EQ(ranges.back().second, n - 1);
            double sum = 0;
            for (std::size_t s = 0; s < k; ++s)
            {
                EXPECT_GE(ranges[s].second, ranges[s].first + 1);
                if (s > 0) { EXPECT_EQ(ranges[s].first, ranges[s - 1].second + 1); }
                sum += tlsError(x, y, ranges[s].first, ranges[s].second);
            }
            EXPECT_NEAR(sum, part.cost(k), 1e-9 * (1 + sum));
        }
    }
}

TEST(ScanPolylinesPartition, EndSkippingMatchesBruteForce)
{
    std::mt19937 rng(11);
    std::normal_distribution<double> noise(0.0, 0.05);
    std::uniform_real_distribution<double> turn(-1.5, 1.5), clutter(-0.6, 0.6);
    std::size_t trimmed = 0;
    for (int trial = 0; trial < 40; ++trial)
    {
        const std::size_t n = 3 + static_cast<std::size_t>(trial % 9);   // 3..11 points
        std::vector<double> x(n), y(n);
        double px = 3, py = 1, heading = turn(rng);
        for (std::size_t i = 0; i < n; ++i)
        {
            if (i % 4 == 0) heading += turn(rng);
            px += 0.2 * std::cos(heading); py += 0.2 * std::sin(heading);
            x[i] = px + noise(rng); y[i] = py + noise(rng);
        }
        // clutter at one end or both, which a line fits worse than leaving it out
        if (trial % 3 != 1) { x[0] += clutter(rng); y[0] += clutter(rng); }
        if (trial % 3 != 0) { x[n - 1] += clutter(rng); y[n - 1] += clutter(rng); }
        const double skip = 0.01;
        ChainPartition part;
        part.load(x.data(), y.data(), n);
        part.setEndSkipCost(skip);
        part.solve(10);
        for (std::size_t k = 1; k <= part.maxSegments(); ++k)
        {
            const double brute = bruteForceTrimmed(x, y, k, skip);
            EXPECT_NEAR(part.cost(k), brute, 1e-9 * (1 + brute)) << "n " << n << " k " << k;
            EXPECT_LE(part.cost(k), bruteForce(x, y, k) + 1e-12);
            // contiguous ranges of >= 2 points whose costs plus the left-out ends add up to cost(k)
            const auto ranges = part.ranges(k);
            ASSERT_EQ(ranges.size(), k);
            double sum = skip * static_cast<double>(ranges.front().first + (n - 1 - ranges.back().second));
            if (ranges.front().first > 0 || ranges.back().second < n - 1) ++trimmed;
            for (std::size_t s = 0; s < k; ++s)
            {
                EXPECT_GE(ranges[s].second, ranges[s].first + 1);
                if (s > 0) { EXPECT_EQ(ranges[s].first, ranges[s - 1].second + 1); }
                sum += tlsError(x, y, ranges[s].first, ranges[s].second);
            }
            EXPECT_NEAR(sum, part.cost(k), 1e-9 * (1 + sum));
        }
    }
    EXPECT_GT(trimmed, 10u);   // the clutter is really left out, so the skipping path is exercised
}

TEST(ScanPolylinesPartition, WeightedRangeCostIsTheWeightedTlsError)
{
    // Points on a line have zero cost at any weights; a weight of 4 on one off-line point quadruples its share.
    const std::vector<double> x{0, 1, 2, 3}, y{0, 0, 0.3, 0}, w{1, 1, 4, 1};
    ChainPartition plain, weighted;
    plain.load(x.data(), y.data(), 4);
    weighted.load(x.data(), y.data(), 4, w.data());
    EXPECT_NEAR(plain.rangeCost(0, 1), 0.0, 1e-15);
    // weighted TLS about the weighted best line: compare with explicit weighted moments
    double sw = 0, mx = 0, my = 0;
    for (int i = 0; i < 4; ++i) { sw += w[i]; mx += w[i] * x[i]; my += w[i] * y[i]; }
    mx /= sw; my /= sw;
    double sxx = 0, sxy = 0, syy = 0;
    for (int i = 0; i < 4; ++i)
    {
        sxx += w[i] * (x[i] - mx) * (x[i] - mx); sxy += w[i] * (x[i] - mx) * (y[i] - my); syy += w[i] * (y[i] - my) * (y[i] - my);
    }
    const double h = 0.5 * (sxx - syy);
    EXPECT_NEAR(weighted.rangeCost(0, 3), 0.5 * (sxx + syy) - std::sqrt(h * h + sxy * sxy), 1e-12);
    EXPECT_GT(weighted.rangeCost(0, 3), plain.rangeCost(0, 3) * 2);
}

TEST(ScanPolylinesBudget, AllocationMatchesBruteForce)
{
    std::mt19937 rng(11);
    std::uniform_int_distribution<int> verts(2, 7), count(1, 4);
    std::uniform_real_distribution<double> cost(0.0, 10.0);
    for (int trial = 0; trial < 200; ++trial)
    {
        const std::size_t G = 1 + static_cast<std::size_t>(trial % 4);
        std::vector<std::vector<BudgetOption>> groups(G);
        for (auto &g : groups)
        {
            g.push_back({0, 10 + cost(rng)});   // leaving the group out
            for (int o = count(rng); o > 0; --o) g.push_back({static_cast<std::size_t>(verts(rng)), cost(rng)});
        }
        const std::size_t budget = static_cast<std::size_t>(trial % 16);
        // brute force over every combination
        double best = std::numeric_limits<double>::infinity();
        std::vector<std::size_t> pick(G, 0);
        std::function<void(std::size_t, std::size_t, double)> rec = [&](std::size_t g, std::size_t used, double acc) {
            if (g == G) { best = std::min(best, acc); return; }
            for (std::size_t o = 0; o < groups[g].size(); ++o)
                if (used + groups[g][o].vertices <= budget) rec(g + 1, used + groups[g][o].vertices, acc + groups[g][o].cost);
        };
        rec(0, 0, 0.0);
        const auto chosen = allocateBudget(groups, budget);
        ASSERT_EQ(chosen.size(), G);
        std::size_t used = 0;
        double total = 0;
        for (std::size_t g = 0; g < G; ++g) { used += groups[g][chosen[g]].vertices; total += groups[g][chosen[g]].cost; }
        EXPECT_LE(used, budget);
        EXPECT_NEAR(total, best, 1e-12) << "trial " << trial;
    }
}

TEST(ScanPolylinesBudget, NoFeasibleChoiceGivesEmpty)
{
    // a group without a 0-vertex option and a budget below its cheapest option
    const std::vector<std::vector<BudgetOption>> groups{{{3, 1.0}}};
    EXPECT_TRUE(allocateBudget(groups, 2).empty());
    EXPECT_EQ(allocateBudget(groups, 3).size(), 1u);
}

TEST(ScanPolylinesBudget, TablePlansEverySmallerBudgetOptimally)
{
    // One table for budget 15 gives, for every b <= 15, a plan within b whose cost is the table's cost(b) and equals
    // that of a separate allocation at b; costs never rise with b.
    std::mt19937 rng(23);
    std::uniform_int_distribution<int> verts(2, 7), count(1, 5);
    std::uniform_real_distribution<double> cost(0.0, 10.0);
    for (int trial = 0; trial < 100; ++trial)
    {
        std::vector<std::vector<BudgetOption>> groups(1 + static_cast<std::size_t>(trial % 5));
        for (auto &g : groups)
        {
            g.push_back({0, 10 + cost(rng)});
            for (int o = count(rng); o > 0; --o) g.push_back({static_cast<std::size_t>(verts(rng)), cost(rng)});
        }
        const rtl::scan_polylines::BudgetTable table(groups, 15);
        ASSERT_EQ(table.budget(), 15u);
        for (std::size_t b = 0; b <= 15; ++b)
        {
            const auto plan = table.plan(b), alone = allocateBudget(groups, b);
            ASSERT_EQ(plan.size(), groups.size());
            std::size_t used = 0;
            double total = 0, total_alone = 0;
            for (std::size_t g = 0; g < groups.size(); ++g)
            {
                used += groups[g][plan[g]].vertices; total += groups[g][plan[g]].cost; total_alone += groups[g][alone[g]].cost;
            }
            EXPECT_LE(used, b);
            EXPECT_NEAR(total, table.cost(b), 1e-12) << "trial " << trial << " b " << b;
            EXPECT_NEAR(total, total_alone, 1e-12) << "trial " << trial << " b " << b;
            if (b > 0) { EXPECT_LE(table.cost(b), table.cost(b - 1)); }
        }
    }
}
