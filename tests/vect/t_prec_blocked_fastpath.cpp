// PrecArrayBlocked's packed (SSE2) precomputation against a scalar reference of the blocked prefix sums: every
// range sum must be bit-identical to the scalar pass's (a block's sums from 0 point by point, hi += block sum, the
// 256x-mean outlier test, then TwoSum hi + lo rows when it fires, and the query's rows-inside-the-range rule).
// Chain lengths give odd and even block counts and tails; values include huge outliers, -0, NaN and wide exponents.
#include <cmath>
#include <cstring>
#include <limits>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "rtl/vect/PrecArrayBlocked.h"

namespace
{
    //! The scalar blocked prefix sums, written plainly: cols sums per row, hi and lo.
    template<int D, typename E>
    struct Reference
    {
        static constexpr int cols = D == 2 ? 5 : 9;
        std::vector<double> hi, lo;
        const std::vector<rtl::VectorND<D, E>> *pts{nullptr};
        size_t shift{0};
        bool compensated{false};

        static void add(double *s, const rtl::VectorND<D, E> &p)
        {
            const double x = p[0], y = p[1];
            if constexpr (D == 2)
            {
                s[0] += x; s[1] += y; s[2] += x * x; s[3] += y * y; s[4] += x * y;
            }
            else
            {
                const double z = p[2];
                s[0] += x; s[1] += y; s[2] += z; s[3] += x * x; s[4] += y * y; s[5] += z * z;
                s[6] += x * y; s[7] += y * z; s[8] += z * x;
            }
        }

        void build(const std::vector<rtl::VectorND<D, E>> &v, size_t min_blocked)
        {
            pts = &v;
            shift = v.size() >= min_blocked ? 3 : 0;
            const size_t block = size_t(1) << shift, full = v.size() / block;
            const int sq = D == 2 ? 2 : 3;
            for (int pass = 0; pass < 2; ++pass)
            {
                const bool exact = pass == 1;
                hi.assign((full + 1) * cols, 0.0);
                lo.assign((full + 1) * cols, 0.0);
                double max_sq = 0;
                for (size_t b = 0; b < full; ++b)
                {
                    double a[9] = {};
                    for (size_t i = 0; i < block; ++i)
                        add(a, v[b * block + i]);
                    double d = 0;
                    for (int k = 0; k < cols; ++k)
                    {
                        double h = hi[b * cols + k], l = lo[b * cols + k];
                        if (exact)
                        {
                            const double s = h + a[k], bv = s - h;
                            l += (h - (s - bv)) + (a[k] - bv);
                            h = s;
                        }
                        else
                            h += a[k];
                        hi[(b + 1) * cols + k] = h;
                        lo[(b + 1) * cols + k] = exact ? l : 0.0;
                    }
                    for (int k = sq; k < sq + D; ++k)
                        d += hi[(b + 1) * cols + k] - hi[b * cols + k];
                    max_sq = std::max(max_sq, d);
                }
                if (exact)
                    return;
                double total = 0;
                for (int k = sq; k < sq + D; ++k)
                    total += hi[full * cols + k];
                compensated = full >= 2 && max_sq > 256.0 * total / static_cast<double>(full);
                if (!compensated)
                    return;
            }
        }

        std::vector<double> sums(size_t beg, size_t end) const
        {
            std::vector<double> s(cols + 1, 0.0);
            const size_t mask = (size_t(1) << shift) - 1, first = (beg + mask) >> shift, last = end >> shift;
            if (first >= last)
                for (size_t i = beg; i < end; ++i)
                    add(s.data(), (*pts)[i]);
            else
            {
                for (int k = 0; k < cols; ++k)
                    s[k] = hi[last * cols + k] - hi[first * cols + k];
                if (compensated)
                    for (int k = 0; k < cols; ++k)
                        s[k] += lo[last * cols + k] - lo[first * cols + k];
                for (size_t i = beg; i < (first << shift); ++i)
                    add(s.data(), (*pts)[i]);
                for (size_t i = last << shift; i < end; ++i)
                    add(s.data(), (*pts)[i]);
            }
            s[cols] = static_cast<double>(end - beg);
            return s;
        }
    };

    template<int D, typename E>
    void check(size_t n, int mode, size_t min_blocked, std::mt19937 &gen)
    {
        std::normal_distribution<double> nd(0.0, 1.0);
        std::vector<rtl::VectorND<D, E>> pts(n);
        for (size_t i = 0; i < n; ++i)
            for (int k = 0; k < D; ++k)
            {
                double v = 8 * std::cos(0.001 * static_cast<double>(i) + k) + 0.01 * nd(gen);
                if (mode == 1 && (i == n / 2 || i == n / 5))
                    v = 1e9;   // two far-off points: compensated rows
                if (mode == 2 && i % 13 == 0)
                    v = -0.0;
                if (mode == 3 && i == n / 3)
                    v = std::numeric_limits<double>::quiet_NaN();
                if (mode == 4)
                    v = std::ldexp(nd(gen), static_cast<int>(gen() % 60) - 30);
                pts[i][k] = static_cast<E>(v);
            }
        rtl::PrecArrayBlocked<D, E, double> arr;
        arr.setMinBlockedSize(min_blocked);
        arr.precompute(pts);
        Reference<D, E> ref;
        ref.build(pts, min_blocked);
        if (mode == 1 && (n >> ref.shift) >= 1024)
        {
            EXPECT_TRUE(ref.compensated);   // the TwoSum rows are exercised
        }
        std::uniform_int_distribution<size_t> u(0, n);
        size_t bad = 0;
        for (int t = 0; t < 3000; ++t)
        {
            size_t b = u(gen), e = u(gen);
            if (b > e)
                std::swap(b, e);
            if (t < 40 && size_t(t % 8 + t / 8) <= n)
            {
                b = static_cast<size_t>(t % 8);
                e = n - static_cast<size_t>(t / 8);
            }
            const auto got = arr.sums(b, e);
            const auto want = ref.sums(b, e);
            for (int k = 0; k <= Reference<D, E>::cols; ++k)
                bad += std::memcmp(&got.sums(k), &want[static_cast<size_t>(k)], sizeof(double)) != 0;
        }
        EXPECT_EQ(bad, 0u) << D << "D n " << n << " mode " << mode << " min_blocked " << min_blocked;
    }
}

TEST(PrecArrayBlockedFastPath, BitIdenticalToScalarBlockedSums)
{
    std::mt19937 gen(11);
    for (size_t n : {2, 3, 7, 8, 9, 16, 17, 23, 24, 25, 1001, 16384, 16385, 16392, 16400, 40007})
        for (int mode = 0; mode < 5; ++mode)
            for (size_t min_blocked : {size_t(16384), size_t(1), std::numeric_limits<size_t>::max()})
            {
                check<2, float>(n, mode, min_blocked, gen);
                check<3, float>(n, mode, min_blocked, gen);
                check<2, double>(n, mode, min_blocked, gen);
                check<3, double>(n, mode, min_blocked, gen);
            }
}
