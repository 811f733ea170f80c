// Incremental TLS 2D tests blocks of consecutive states at once (ApproximationTlsLine2D::errorBelowRawAll): the
// block test must decide exactly as errorBelowRaw per state (crafted states: ties a * b == c * c, signed zeros,
// overflowing products, NaN and infinite sums, at every position of a block), and the extractor with the block
// test must give the ranges and lines of the plain point-by-point loop (an approximation without errorBelowRawAll)
// on the paper's semicircle, random walks, small sigmas that close ranges inside blocks, and the real laser scans.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "rtl/Vectorization.h"
#include "rtl/io/CarmenLog.h"

namespace
{
    typedef rtl::ApproximationTlsLine2D<float, double> Tls;

    constexpr size_t block = 16;

    bool plainAll(const double *s, double n0, double sigma2)
    {
        bool all = true;
        for (size_t j = 0; j < block; ++j)
        {
            const double q[5] = {s[j], s[block + j], s[2 * block + j], s[3 * block + j], s[4 * block + j]};
            all &= Tls::errorBelowRaw(q, n0 + static_cast<double>(j), sigma2);
        }
        return all;
    }

    //! Raw sums (relative to the first point) of the states after each of `block` points on a noisy line.
    void lineStates(std::mt19937 &rng, double *states, double &n0, double noise)
    {
        std::normal_distribution<double> g(0.0, noise);
        const size_t before = 3 + rng() % 50;
        double s[5] = {};
        size_t i = 0;
        auto add = [&] {
            const double x = 0.01 * static_cast<double>(i), y = 0.002 * static_cast<double>(i) + g(rng);
            s[0] += x; s[1] += y; s[2] += x * x; s[3] += y * y; s[4] += x * y;
            ++i;
        };
        while (i < before)
            add();
        n0 = static_cast<double>(i + 1);
        for (size_t j = 0; j < block; ++j)
        {
            add();
            for (size_t k = 0; k < 5; ++k)
                states[k * block + j] = s[k];
        }
    }
}

TEST(ItlsBlock, BlockTestDecidesAsTheScalarTestPerState)
{
    std::mt19937 rng(7);
    const double inf = std::numeric_limits<double>::infinity(), nan = std::numeric_limits<double>::quiet_NaN();
    const double big = 1e160, huge = std::numeric_limits<double>::max();
    size_t trues = 0, falses = 0;
    for (int trial = 0; trial < 20000; ++trial)
    {
        double states[5 * block], n0;
        const double noise = trial % 3 == 0 ? 1e-3 : trial % 3 == 1 ? 0.02 : 0.2;
        lineStates(rng, states, n0, noise);
        const double sigma2 = 0.01 * 0.01 * (1 + static_cast<double>(rng() % 5));
        // Overwrite one state (or none) with a crafted one.
        const size_t j = rng() % block;
        const double nj = n0 + static_cast<double>(j);
        double *q[5];
        for (size_t k = 0; k < 5; ++k)
            q[k] = &states[k * block + j];
        const double t = nj * nj * sigma2;
        switch (trial % 13)
        {
        case 0: break;
        case 1: { // a * b == c * c with a, b > 0: a = b = c = 1 exactly
            *q[0] = 0; *q[1] = 0; *q[2] = (1 + t) / nj; *q[3] = (1 + t) / nj; *q[4] = 1 / nj;
            break;
        }
        case 2: *q[2] = (t + *q[0] * *q[0]) / nj; break;   // a near 0 (maybe exactly, maybe -0 or tiny)
        case 3: *q[0] = big; *q[1] = big; break;           // products overflow: a, b -> -inf, c finite or NaN
        case 4: *q[2] = huge; *q[3] = huge; *q[4] = huge; break;   // a, b, c beyond the range: inf
        case 5: *q[rng() % 5] = nan; break;
        case 6: *q[rng() % 5] = (rng() % 2 ? inf : -inf); break;
        case 7: { // a, b large and positive, c larger: a * b and c * c both overflow
            *q[0] = 0; *q[1] = 0; *q[2] = 1e200 / nj; *q[3] = 1e200 / nj; *q[4] = 1e201 / nj;
            break;
        }
        case 8: { // a * b overflows, c * c does not
            *q[0] = 0; *q[1] = 0; *q[2] = 1e200 / nj; *q[3] = 1e200 / nj; *q[4] = 1e100 / nj;
            break;
        }
        case 9: { // c * c overflows, a * b does not
            *q[0] = 0; *q[1] = 0; *q[2] = 1e10 / nj; *q[3] = 1e10 / nj; *q[4] = 1e200 / nj;
            break;
        }
        case 10: { // a + b + c overflows although a, b, c are finite
            *q[0] = 0; *q[1] = 0; *q[2] = huge / 1.5 / nj; *q[3] = huge / 1.5 / nj; *q[4] = huge / 1.5 / nj;
            break;
        }
        case 11: { // a * b one ulp either side of c * c
            const double c = 3.0, ab = std::nextafter(9.0, rng() % 2 ? 0.0 : 20.0);
            *q[0] = 0; *q[1] = 0; *q[2] = (3 + t) / nj; *q[3] = (ab / 3 + t) / nj; *q[4] = c / nj;
            break;
        }
        case 12: { // a, b < 0 with a * b and c * c both overflowing (passes by a < 0)
            *q[0] = 0; *q[1] = 0; *q[2] = (-1e200 + t) / nj; *q[3] = (-1e200 + t) / nj; *q[4] = 1e200 / nj;
            break;
        }
        }
        const bool expected = plainAll(states, n0, sigma2);
        ASSERT_EQ(Tls::errorBelowRawAll<block>(states, n0, sigma2), expected) << "trial " << trial << " state " << j;
        (expected ? trues : falses)++;
    }
    EXPECT_GT(trues, 2000u);
    EXPECT_GT(falses, 2000u);
}

TEST(ItlsBlock, SignedZerosAndExactTies)
{
    // All states equal, built so that a, b, c take chosen exact values at n = 1 (n0 = 1, sigma2 = 0: t = 0, and
    // n grows with j, so only state 0 has them exactly; the others scale a, b, c by n).
    for (double a : {-0.0, 0.0, 1.0, -1.0})
        for (double b : {-0.0, 0.0, 2.0, -1.0})
            for (double c : {-0.0, 0.0, 1.0, std::sqrt(2.0)})
            {
                double states[5 * block];
                for (size_t j = 0; j < block; ++j)
                {
                    states[j] = 0; states[block + j] = 0;
                    states[2 * block + j] = a; states[3 * block + j] = b; states[4 * block + j] = c;
                }
                EXPECT_EQ(Tls::errorBelowRawAll<block>(states, 1.0, 0.0), plainAll(states, 1.0, 0.0)) << a << " " << b << " " << c;
            }
}

namespace
{
    //! The same approximation without the block test: ExtractorChainIncremental falls back to its plain loop.
    template<class E>
    struct PlainTls : rtl::ApproximationTlsLine2D<E, double>
    {
        template<size_t b>
        static bool errorBelowRawAll(const double *, double, double) = delete;
    };

    template<class V>
    void expectSameAsPlain(const std::vector<V> &pts, double sigma, const std::string &what)
    {
        typedef rtl::ApproximationTlsLine2D<typename V::ElementType, double> Fast;
        typedef PlainTls<typename V::ElementType> Plain;
        rtl::ExtractorChainIncremental<Fast> fast;
        rtl::ExtractorChainIncremental<Plain> plain;
        fast.setSigma(static_cast<typename V::ElementType>(sigma));
        plain.setSigma(static_cast<typename V::ElementType>(sigma));
        std::vector<Fast> af;
        std::vector<Plain> ap;
        std::vector<std::pair<size_t, size_t>> idf, idp;
        ASSERT_EQ(fast(pts, af, idf), plain(pts, ap, idp)) << what;
        ASSERT_EQ(idf, idp) << what;
        ASSERT_EQ(af.size(), ap.size()) << what;
        for (size_t r = 0; r < af.size(); ++r)
        {
            const double ef = af[r].errSquaredCompute(), ep = ap[r].errSquaredCompute();
            ASSERT_EQ(std::memcmp(&ef, &ep, sizeof ef), 0) << what << " range " << r;
            ASSERT_EQ(af[r].point().x(), ap[r].point().x()) << what << " range " << r;
            ASSERT_EQ(af[r].direction().y(), ap[r].direction().y()) << what << " range " << r;
        }
    }

    std::vector<rtl::Vector2f> semicircle(size_t n, double noise, unsigned seed)
    {
        std::mt19937 gen(seed);
        std::normal_distribution<double> nd(0.0, noise);
        std::vector<rtl::Vector2f> pts;
        for (size_t i = 0; i < n; ++i)
        {
            const double a = M_PI * static_cast<double>(i) / static_cast<double>(n - 1);
            pts.emplace_back(static_cast<float>(8 * std::cos(a) + nd(gen)), static_cast<float>(8 * std::sin(a) + nd(gen)));
        }
        return pts;
    }

    std::vector<rtl::Vector2f> randomWalk(size_t n, float step, unsigned seed)
    {
        std::mt19937 gen(seed);
        std::normal_distribution<float> nd(0.0f, step);
        std::vector<rtl::Vector2f> pts;
        float x = 100, y = -50;
        for (size_t i = 0; i < n; ++i)
        {
            x += step + nd(gen);
            y += nd(gen);
            pts.emplace_back(x, y);
        }
        return pts;
    }
}

TEST(ItlsBlock, ExtractorRangesEqualThePlainLoop)
{
    for (size_t n : {2u, 3u, 17u, 18u, 19u, 33u, 100u, 1000u, 100000u})
        for (double sigma : {0.03, 0.01, 0.003, 0.3})
            expectSameAsPlain(semicircle(n, 0.01, 42), sigma, "semicircle " + std::to_string(n) + " sigma " + std::to_string(sigma));
    for (unsigned seed = 1; seed <= 20; ++seed)
        for (double sigma : {0.05, 0.2, 1.0, 5.0})
            expectSameAsPlain(randomWalk(5000, 0.1f, seed), sigma, "walk " + std::to_string(seed) + " sigma " + std::to_string(sigma));
    // double points, far from the origin
    std::vector<rtl::Vector2d> far;
    std::mt19937 gen(3);
    std::normal_distribution<double> nd(0.0, 0.01);
    for (int i = 0; i < 20000; ++i)
        far.emplace_back(1e6 + 0.001 * i + nd(gen), -2e6 + 0.0005 * i * (i % 3000 < 1500 ? 1 : -1) + nd(gen));
    for (double sigma : {0.005, 0.02, 0.1})
        expectSameAsPlain(far, sigma, "far double sigma " + std::to_string(sigma));
}

TEST(ItlsBlock, ExtractorRangesEqualThePlainLoopOnLaserScans)
{
    size_t chains = 0;
    for (const char *name : {"intel.log", "csail.log"})
        for (const auto &scan : rtl::readCarmenLogFile<float>(std::string(RTL_TEST_DATA_DIR) + "/" + name))
        {
            std::vector<rtl::Vector2f> cur;
            auto flush = [&] {
                if (cur.size() >= 2)
                {
                    for (double sigma : {0.01, 0.03, 0.1})
                        expectSameAsPlain(cur, sigma, std::string(name) + " chain " + std::to_string(chains));
                    ++chains;
                }
                cur.clear();
            };
            for (const auto &p : scan.points)
            {
                if (p.hasNaN() || (!cur.empty() && (p - cur.back()).length() > 0.5f))
                    flush();
                if (!p.hasNaN())
                    cur.push_back(p);
            }
            flush();
        }
    EXPECT_GT(chains, 100u);
}
