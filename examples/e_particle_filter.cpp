// ParticleFilter: follow a point moving along a line from noisy position measurements with SimpleParticle.
#include <cmath>
#include <iostream>
#include <random>

#include "rtl/Algorithms.h"

int main()
{
    using Particle = rtl::SimpleParticle<float>;
    rtl::AlgorithmRandom::seed(7);          // reproducible run
    rtl::ParticleFilter<Particle, 1000, 100> pf;   // 1000 particles, 100 survive each resampling

    std::mt19937 rng(1);
    std::normal_distribution<float> noise(0.0f, 2.0f);
    float truth = -40.0f;
    for (int k = 1; k <= 20; ++k)
    {
        truth += 2.0f;
        pf.iteration(Particle::Action(2.0f), Particle::Measurement(truth + noise(rng)));
        if (k % 5 == 0)
        {
            const auto r = pf.evaluate();
            std::cout << "step " << k << ": truth " << truth << ", estimate " << r.mean() << " +- " << r.std_dev() << "\n";
        }
    }
    return std::abs(pf.evaluate().mean() - truth) < 5.0f ? 0 : 1;
}
