// Munkres and solveAssignment: the reference cases, brute force over all permutations (N <= 8, square and
// rectangular, min and max, integer with many ties and floating), extreme integers, invariance and errors.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numeric>
#include <random>
#include <stdexcept>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "rtl/Algorithms.h"

namespace
{
    __extension__ typedef __int128 Int128;
    template<typename T>
    using Sum = std::conditional_t<std::is_floating_point_v<T>, long double, Int128>;

    // Best total over all injective maps from the smaller side into the larger one, by enumeration.
    template<typename T>
    Sum<T> bruteBest(const std::vector<T> &c, size_t rows, size_t cols, bool maximize)
    {
        const bool wide = rows <= cols;
        const size_t k = wide ? rows : cols, m = wide ? cols : rows;
        std::vector<size_t> perm(m);
        std::iota(perm.begin(), perm.end(), size_t(0));
        bool first = true;
        Sum<T> best = 0;
        do
        {
            Sum<T> s = 0;
            for (size_t i = 0; i < k; ++i)
                s += static_cast<Sum<T>>(wide ? c[i * cols + perm[i]] : c[perm[i] * cols + i]);
            if (first || (maximize ? s > best : s < best))
                best = s;
            first = false;
        } while (std::next_permutation(perm.begin(), perm.end()));
        return best;
    }

    // Checks that the assignment is valid (distinct columns, exactly min(rows, cols) rows assigned) and returns its total.
    template<typename T>
    Sum<T> checkedTotal(const std::vector<size_t> &a, const std::vector<T> &c, size_t rows, size_t cols)
    {
        EXPECT_EQ(a.size(), rows);
        std::vector<char> used(cols, 0);
        size_t assigned = 0;
        Sum<T> s = 0;
        for (size_t r = 0; r < a.size(); ++r)
        {
            if (a[r] == rtl::assignment_unassigned)
                continue;
            EXPECT_LT(a[r], cols);
            if (a[r] >= cols)
                return 0;
            EXPECT_FALSE(used[a[r]]) << "column " << a[r] << " assigned twice";
            used[a[r]] = 1;
            ++assigned;
            s += static_cast<Sum<T>>(c[r * cols + a[r]]);
        }
        EXPECT_EQ(assigned, std::min(rows, cols));
        return s;
    }

    template<size_t N, typename T>
    rtl::Matrix<N, N, T> toMatrix(const std::vector<T> &v)
    {
        rtl::Matrix<N, N, T> m;
        for (size_t r = 0; r < N; ++r)
            for (size_t c = 0; c < N; ++c)
                m(r, c) = v[r * N + c];
        return m;
    }

    template<typename T>
    std::vector<T> randomCosts(std::mt19937 &rng, size_t n, T lo, T hi)
    {
        std::vector<T> v(n);
        for (T &x : v)
        {
            if constexpr (std::is_integral_v<T>)
                x = std::uniform_int_distribution<T>(lo, hi)(rng);
            else
                x = std::uniform_real_distribution<T>(lo, hi)(rng);
        }
        return v;
    }

    // Munkres<T, N> on `trials` random matrices against brute force, min and max.
    template<size_t N, typename T>
    void squareAgainstBruteForce(int trials, T lo, T hi, unsigned seed)
    {
        std::mt19937 rng(seed);
        for (int t = 0; t < trials; ++t)
        {
            const std::vector<T> c = randomCosts<T>(rng, N * N, lo, hi);
            for (bool maximize : {false, true})
            {
                const auto res = rtl::Munkres<T, N>::solve(toMatrix<N>(c), maximize);
                std::vector<size_t> cols(N);
                for (size_t r = 0; r < N; ++r)
                {
                    ASSERT_EQ(res[r].row, r);
                    cols[r] = res[r].col;
                    ASSERT_LT(res[r].col, N);
                    ASSERT_EQ(res[r].cost, c[r * N + res[r].col]);     // the original cost, also when maximising
                }
                const Sum<T> got = checkedTotal(cols, c, N, N), best = bruteBest(c, N, N, maximize);
                if constexpr (std::is_integral_v<T>)
                    ASSERT_TRUE(got == best) << "N=" << N << " trial " << t << " max=" << maximize << ": " << static_cast<long long>(got)
                                             << " vs brute force " << static_cast<long long>(best);
                else
                    ASSERT_NEAR(static_cast<double>(got), static_cast<double>(best), 1e-9 * N * std::max(std::abs(hi), std::abs(lo)))
                        << "N=" << N << " trial " << t << " max=" << maximize;
            }
        }
    }
}

TEST(Munkres, ReferenceThreeByThree)
{
    rtl::Matrix<3, 3, int> m;
    for (size_t r = 0; r < 3; ++r)
        for (size_t c = 0; c < 3; ++c)
            m(r, c) = static_cast<int>((r + 1) * (c + 1));
    const auto res = rtl::Munkres<int, 3>::solve(m);
    const size_t cols[3] = {2, 1, 0};
    const int costs[3] = {3, 4, 3};
    for (size_t r = 0; r < 3; ++r)
    {
        EXPECT_EQ(res[r].row, r);
        EXPECT_EQ(res[r].col, cols[r]);
        EXPECT_EQ(res[r].cost, costs[r]);
    }
    const auto mx = rtl::Munkres<int, 3>::solve(m, true);
    for (size_t r = 0; r < 3; ++r)
    {
        EXPECT_EQ(mx[r].col, r);
        EXPECT_EQ(mx[r].cost, static_cast<int>((r + 1) * (r + 1)));
    }
}

TEST(Munkres, SixBySixIntAndFourByFourFloatMax)
{
    // Unique optima (checked by brute force below): the 6x6 minimum is 0-3 1-0 2-4 3-1 4-5 5-2 with total 16.
    const std::vector<int> c6 = {7, 9, 8, 1, 6, 9,  2, 8, 7, 9, 8, 7,  9, 6, 8, 8, 3, 9,
                                 8, 2, 9, 7, 8, 6,  6, 9, 8, 7, 9, 4,  9, 7, 4, 8, 7, 9};
    const auto r6 = rtl::Munkres<int, 6>::solve(toMatrix<6>(c6));
    const size_t cols6[6] = {3, 0, 4, 1, 5, 2};
    const int costs6[6] = {1, 2, 3, 2, 4, 4};
    for (size_t r = 0; r < 6; ++r)
    {
        EXPECT_EQ(r6[r].row, r);
        EXPECT_EQ(r6[r].col, cols6[r]);
        EXPECT_EQ(r6[r].cost, costs6[r]);
    }
    EXPECT_TRUE(bruteBest(c6, 6, 6, false) == 16);

    const std::vector<float> c4 = {0.5f, 2.25f, 1.0f, 0.75f,  3.5f, 0.25f, 1.5f, 2.0f,
                                   1.25f, 1.75f, 0.5f, 4.0f,  2.5f, 3.0f, 3.25f, 0.5f};
    const auto r4 = rtl::Munkres<float, 4>::solve(toMatrix<4>(c4), true);
    const size_t cols4[4] = {1, 0, 3, 2};   // 2.25 + 3.5 + 4.0 + 3.25 = 13
    for (size_t r = 0; r < 4; ++r)
    {
        EXPECT_EQ(r4[r].row, r);
        EXPECT_EQ(r4[r].col, cols4[r]);
        EXPECT_FLOAT_EQ(r4[r].cost, c4[r * 4 + cols4[r]]);
    }
    EXPECT_EQ(static_cast<double>(bruteBest(c4, 4, 4, true)), 13.0);
}

TEST(Munkres, SquareAgainstBruteForce)
{
    // Integers from tiny ranges tie a lot; floats do not. 5400 matrices in all, each minimised and maximised.
    squareAgainstBruteForce<1, int>(100, -3, 3, 1);
    squareAgainstBruteForce<2, int>(500, 0, 2, 2);
    squareAgainstBruteForce<3, int>(1000, 0, 3, 3);
    squareAgainstBruteForce<4, int>(1000, -2, 2, 4);
    squareAgainstBruteForce<5, unsigned>(600, 0u, 4u, 5);
    squareAgainstBruteForce<6, long>(300, -1000000000000L, 1000000000000L, 6);
    squareAgainstBruteForce<7, int>(60, 0, 5, 7);
    squareAgainstBruteForce<8, int>(20, 0, 9, 8);
    squareAgainstBruteForce<3, double>(800, -10.0, 10.0, 9);
    squareAgainstBruteForce<5, float>(500, 0.0f, 1.0f, 10);
    squareAgainstBruteForce<6, double>(300, 0.0, 1e6, 11);
    squareAgainstBruteForce<8, double>(20, -1.0, 1.0, 12);
    squareAgainstBruteForce<4, uint8_t>(200, uint8_t(0), uint8_t(255), 13);
}

TEST(Munkres, RectangularAgainstBruteForce)
{
    std::mt19937 rng(21);
    int cases = 0;
    for (size_t rows = 1; rows <= 7; ++rows)
        for (size_t cols = 1; cols <= 7; ++cols)
            for (int t = 0; t < 40; ++t, ++cases)
            {
                const std::vector<int> ci = randomCosts<int>(rng, rows * cols, -3, 3);
                const std::vector<double> cd = randomCosts<double>(rng, rows * cols, -5.0, 5.0);
                for (bool maximize : {false, true})
                {
                    ASSERT_TRUE(checkedTotal(rtl::solveAssignment(ci, rows, cols, maximize), ci, rows, cols) ==
                                bruteBest(ci, rows, cols, maximize))
                        << rows << "x" << cols << " trial " << t << " max=" << maximize;
                    ASSERT_NEAR(static_cast<double>(checkedTotal(rtl::solveAssignment(cd.data(), rows, cols, maximize), cd, rows, cols)),
                                static_cast<double>(bruteBest(cd, rows, cols, maximize)), 1e-9)
                        << rows << "x" << cols << " trial " << t << " max=" << maximize;
                }
            }
    EXPECT_EQ(cases, 49 * 40);
}

TEST(Munkres, ExtremeIntegersAreExact)
{
    // Reduced costs of these would overflow in the element type; the wide working type keeps them exact.
    const int64_t big = std::numeric_limits<int64_t>::max(), small = std::numeric_limits<int64_t>::min();
    const std::vector<int64_t> c = {big, small, 0, small + 1, big - 1, 5, 7, big, small};
    for (bool maximize : {false, true})
        EXPECT_TRUE(checkedTotal(rtl::solveAssignment(c, 3, 3, maximize), c, 3, 3) == bruteBest(c, 3, 3, maximize));
    const uint64_t top = std::numeric_limits<uint64_t>::max();
    const std::vector<uint64_t> u = {top, top - 1, 0, top - 2, 1, top, 3, top, top - 7, 2, 9, top};
    for (bool maximize : {false, true})
        for (auto [r, k] : {std::pair<size_t, size_t>{3, 4}, {4, 3}, {2, 6}, {6, 2}})
            EXPECT_TRUE(checkedTotal(rtl::solveAssignment(u, r, k, maximize), u, r, k) == bruteBest(u, r, k, maximize));
}

TEST(Munkres, DeterministicAndPermutationInvariant)
{
    std::mt19937 rng(31);
    const size_t n = 60;
    for (int t = 0; t < 4; ++t)
    {
        const std::vector<int> c = randomCosts<int>(rng, n * n, 0, 20);     // many ties
        const auto a = rtl::solveAssignment(c, n, n);
        EXPECT_EQ(rtl::solveAssignment(c, n, n), a);
        // The optimal total does not depend on the order of rows and columns.
        std::vector<size_t> pr(n), pc(n);
        std::iota(pr.begin(), pr.end(), size_t(0));
        std::iota(pc.begin(), pc.end(), size_t(0));
        std::shuffle(pr.begin(), pr.end(), rng);
        std::shuffle(pc.begin(), pc.end(), rng);
        std::vector<int> p(n * n);
        for (size_t r = 0; r < n; ++r)
            for (size_t k = 0; k < n; ++k)
                p[r * n + k] = c[pr[r] * n + pc[k]];
        EXPECT_TRUE(checkedTotal(a, c, n, n) == checkedTotal(rtl::solveAssignment(p, n, n), p, n, n));
        // A greedy or row-wise choice is no better; the row-minimum sum is a lower bound.
        Int128 lower = 0;
        for (size_t r = 0; r < n; ++r)
            lower += *std::min_element(c.begin() + static_cast<long>(r * n), c.begin() + static_cast<long>((r + 1) * n));
        EXPECT_TRUE(checkedTotal(a, c, n, n) >= lower);
    }
    // All costs equal: every assignment is optimal, the result is still the same every time.
    const std::vector<double> flat(25, 1.5);
    EXPECT_EQ(rtl::solveAssignment(flat, 5, 5), rtl::solveAssignment(flat, 5, 5));
}

TEST(Munkres, EmptyAndErrors)
{
    EXPECT_TRUE(rtl::solveAssignment(std::vector<int>{}, 0, 0).empty());
    EXPECT_EQ(rtl::solveAssignment(std::vector<int>{}, 3, 0), std::vector<size_t>(3, rtl::assignment_unassigned));
    EXPECT_THROW((rtl::solveAssignment(std::vector<int>{1, 2, 3}, 2, 2)), std::invalid_argument);
    EXPECT_THROW(rtl::solveAssignment(static_cast<const int *>(nullptr), 2, 2), std::invalid_argument);
    for (double bad : {std::nan(""), std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity()})
    {
        EXPECT_THROW((rtl::solveAssignment(std::vector<double>{1, 2, bad, 4}, 2, 2)), std::invalid_argument);
        rtl::Matrix<2, 2, double> m;
        m(1, 0) = bad;
        EXPECT_THROW((rtl::Munkres<double, 2>::solve(m)), std::invalid_argument);
    }
}
