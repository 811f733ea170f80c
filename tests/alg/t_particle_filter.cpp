// ParticleFilter, SimpleParticle and systematicResample: tracking within 5 of the truth, seeded reproducibility,
// and statistical checks that a resampler ignoring the weights fails (shown on such a broken resampler).
#include <cmath>
#include <functional>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "rtl/Algorithms.h"

namespace
{
    using Particle = rtl::SimpleParticle<float>;
    using Resampler = std::function<std::vector<size_t>(const std::vector<double> &, size_t, double)>;

    std::vector<size_t> ignoresWeights(const std::vector<double> &weights, size_t count, double offset)
    {
        std::vector<size_t> picked;
        for (size_t k = 0; k < count; ++k)
            picked.push_back(static_cast<size_t>((static_cast<double>(k) + offset) / static_cast<double>(count) * static_cast<double>(weights.size())));
        return picked;
    }

    // Mean |count_i - count * w_i| over 200 random weight vectors: below 1 for a correct systematic resampler.
    double meanCountError(const Resampler &resample)
    {
        std::mt19937 rng(17);
        std::uniform_real_distribution<double> u(0.0, 1.0);
        double err = 0;
        size_t terms = 0;
        for (int t = 0; t < 200; ++t)
        {
            std::vector<double> w(20);
            double total = 0;
            for (double &x : w)
                total += (x = std::pow(u(rng), 3.0));      // skewed weights, as likelihoods are
            const size_t count = 50;
            std::vector<size_t> hits(w.size(), 0);
            for (size_t i : resample(w, count, u(rng)))
                ++hits.at(i);
            for (size_t i = 0; i < w.size(); ++i, ++terms)
                err += std::abs(static_cast<double>(hits[i]) - static_cast<double>(count) * w[i] / total);
        }
        return err / static_cast<double>(terms);
    }

    // The filter's loop written with a chosen resampler (ParticleFilter<Particle, 1000, 100> uses systematicResample).
    template<size_t particles, size_t survivors>
    float trackWith(const Resampler &resample, unsigned seed, float truth0, float step, int iterations, float *truth_out)
    {
        rtl::AlgorithmRandom::seed(seed);
        std::vector<Particle> all;
        for (size_t i = 0; i < particles; ++i)
            all.push_back(Particle::random());
        std::vector<Particle> kept;
        std::mt19937 noise_rng(seed + 1);
        std::normal_distribution<float> noise(0.0f, 2.0f);
        float truth = truth0;
        for (int k = 0; k < iterations; ++k)
        {
            truth += step;
            const Particle::Measurement z(truth + noise(noise_rng));
            std::vector<double> w;
            for (Particle &p : all)
            {
                p.move(Particle::Action(step));
                w.push_back(p.belief(z));
            }
            const double offset = rtl::AlgorithmRandom::uniform(0.0, 1.0);
            kept.clear();
            for (size_t i : resample(w, survivors, offset))
                kept.push_back(all[i]);
            all = kept;
            while (all.size() < particles)
                all.push_back(Particle::random());
        }
        *truth_out = truth;
        return Particle::evaluation(kept).mean();
    }

    template<size_t particles, size_t survivors>
    Particle::Result runFilter(unsigned seed, float truth0, float step, int iterations, float *truth_out)
    {
        rtl::AlgorithmRandom::seed(seed);
        rtl::ParticleFilter<Particle, particles, survivors> pf;
        std::mt19937 noise_rng(seed + 1);
        std::normal_distribution<float> noise(0.0f, 2.0f);
        float truth = truth0;
        for (int k = 0; k < iterations; ++k)
        {
            truth += step;
            pf.iteration(Particle::Action(step), Particle::Measurement(truth + noise(noise_rng)));
        }
        *truth_out = truth;
        return pf.evaluate();
    }
}

TEST(ParticleFilter, SimpleParticle)
{
    Particle p(3.0f);
    p.move(Particle::Action(2.5f));
    const float peak = 1.0f / (10.0f * std::sqrt(2.0f * 3.14159265f));
    EXPECT_NEAR(p.belief(Particle::Measurement(5.5f)), peak, 1e-7f);
    EXPECT_NEAR(p.belief(Particle::Measurement(15.5f)), peak * std::exp(-0.5f), 1e-7f);
    EXPECT_NEAR(p.belief(Particle::Measurement(-14.5f)), peak * std::exp(-2.0f), 1e-7f);
    const auto r = Particle::evaluation({Particle(1), Particle(2), Particle(3), Particle(6)});
    EXPECT_FLOAT_EQ(r.mean(), 3.0f);
    EXPECT_FLOAT_EQ(r.std_dev(), std::sqrt(3.5f));     // population std-dev: (4 + 1 + 0 + 9) / 4
    rtl::AlgorithmRandom::seed(1);
    float lo = 1e9f, hi = -1e9f;
    for (int i = 0; i < 20000; ++i)
    {
        const float v = Particle::evaluation({Particle::random()}).mean();
        lo = std::min(lo, v);
        hi = std::max(hi, v);
    }
    EXPECT_GE(lo, -100.0f);
    EXPECT_LE(hi, 100.0f);
    EXPECT_LT(lo, -99.0f);
    EXPECT_GT(hi, 99.0f);
}

TEST(ParticleFilter, TracksWithinFiveOfTheTruth)
{
    for (unsigned seed : {1u, 2u, 3u, 4u, 5u})
    {
        float truth = 0;
        const auto r = runFilter<1000, 100>(seed, 30.0f, 1.5f, 25, &truth);
        EXPECT_NEAR(r.mean(), truth, 5.0f) << "seed " << seed;
        EXPECT_LT(r.std_dev(), 10.0f) << "seed " << seed;
    }
}

TEST(ParticleFilter, SameSeedSameResult)
{
    float t1 = 0, t2 = 0, t3 = 0;
    const auto a = runFilter<500, 50>(42, -20.0f, 1.0f, 10, &t1);
    const auto b = runFilter<500, 50>(42, -20.0f, 1.0f, 10, &t2);
    const auto c = runFilter<500, 50>(43, -20.0f, 1.0f, 10, &t3);
    EXPECT_EQ(a.mean(), b.mean());
    EXPECT_EQ(a.std_dev(), b.std_dev());
    EXPECT_NE(a.mean(), c.mean());
}

TEST(ParticleFilter, SystematicResampleHonoursWeights)
{
    // Deterministic property: each index is picked floor or ceil of count * w_i / sum times.
    const std::vector<double> w = {0.5, 0.0, 2.0, 1.0, 0.25, 0.25};
    for (double offset : {0.0, 0.3, 0.999})
    {
        std::vector<size_t> hits(w.size(), 0);
        for (size_t i : rtl::systematicResample(w, 16, offset))
            ++hits[i];
        for (size_t i = 0; i < w.size(); ++i)
        {
            const double expected = 16 * w[i] / 4.0;
            EXPECT_GE(static_cast<double>(hits[i]), std::floor(expected)) << i << " offset " << offset;
            EXPECT_LE(static_cast<double>(hits[i]), std::ceil(expected)) << i << " offset " << offset;
        }
    }
    EXPECT_LT(meanCountError(rtl::systematicResample), 0.5);
    EXPECT_GT(meanCountError(ignoresWeights), 1.0);     // the check catches a resampler that ignores the weights
    // Degenerate weights fall back to equal shares.
    EXPECT_EQ(rtl::systematicResample({0.0, 0.0, -1.0, std::nan("")}, 4, 0.5), (std::vector<size_t>{0, 1, 2, 3}));
    EXPECT_EQ(rtl::systematicResample({0.0, 1.0, 0.0}, 3, 0.999), (std::vector<size_t>{1, 1, 1}));
    EXPECT_TRUE(rtl::systematicResample({}, 3, 0.5).empty());
}

TEST(ParticleFilter, TrackingCheckCatchesABrokenResampler)
{
    // The test's loop with systematicResample is the filter itself (same numbers); with a resampler that ignores
    // the weights the estimate stays near the mean of uniform particles and the "within 5" check fails.
    int broken_within = 0;
    for (unsigned seed : {1u, 2u, 3u, 4u, 5u})
    {
        float truth_pf = 0, truth_loop = 0, truth_broken = 0;
        const float pf = runFilter<1000, 100>(seed, 30.0f, 1.5f, 25, &truth_pf).mean();
        EXPECT_EQ((trackWith<1000, 100>(rtl::systematicResample, seed, 30.0f, 1.5f, 25, &truth_loop)), pf);
        const float broken = trackWith<1000, 100>(ignoresWeights, seed, 30.0f, 1.5f, 25, &truth_broken);
        if (std::abs(broken - truth_broken) <= 5.0f)
            ++broken_within;
    }
    EXPECT_EQ(broken_within, 0);
}

TEST(ParticleFilter, MeasurementFarFromAllParticles)
{
    rtl::AlgorithmRandom::seed(9);
    rtl::ParticleFilter<Particle, 200, 20> pf;
    pf.iteration(Particle::Action(0.0f), Particle::Measurement(1e6f));     // every belief is 0: equal shares
    const auto r = pf.evaluate();
    EXPECT_TRUE(std::isfinite(r.mean()));
    EXPECT_LE(std::abs(r.mean()), 100.0f);
}
