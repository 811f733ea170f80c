// ParticleFilter: a generic particle filter with systematic resampling and random refill.
// Complexity: one iteration is O(P) calls of move and belief plus O(P) resampling work for P particles; no
// allocation beyond the particle and weight vectors.
#pragma once

#include <cstddef>
#include <vector>

#include "rtl/alg/AlgorithmRandom.h"
#include "rtl/alg/particle_filter/Resampling.h"

namespace rtl
{
    /*!
     * ParticleType needs: static ParticleType random(); void move(const Action&); a belief(const Measurement&)
     * convertible to double (a likelihood, >= 0); static Result evaluation(const std::vector<ParticleType>&);
     * and the nested types Action, Measurement and Result.
     * Randomness (the resampling offset, and whatever ParticleType::random() draws) comes from AlgorithmRandom:
     * seed it for reproducible runs.
     */
    template<typename ParticleType, size_t no_of_particles, size_t no_of_survivors>
    class ParticleFilter
    {
        static_assert(no_of_survivors > 0, "ParticleFilter needs at least one survivor.");
        static_assert(no_of_survivors <= no_of_particles, "ParticleFilter cannot keep more survivors than particles.");

    public:
        //! no_of_particles particles from ParticleType::random(); before the first iteration all of them survive.
        ParticleFilter()
        {
            particles.reserve(no_of_particles);
            for (size_t i = 0; i < no_of_particles; ++i)
                particles.push_back(ParticleType::random());
            survivors = particles;
        }

        //! Moves every particle, weighs it by its belief in the measurement, keeps no_of_survivors particles chosen
        //! at evenly spaced thresholds (random offset) of the normalised cumulative weights, then refills with random().
        void iteration(const typename ParticleType::Action &action, const typename ParticleType::Measurement &measurement)
        {
            std::vector<double> weights;
            weights.reserve(particles.size());
            for (ParticleType &p : particles)
            {
                p.move(action);
                weights.push_back(static_cast<double>(p.belief(measurement)));
            }
            const double offset = AlgorithmRandom::uniform(0.0, 1.0);
            survivors.clear();
            for (size_t i : systematicResample(weights, no_of_survivors, offset))
                survivors.push_back(particles[i]);
            particles = survivors;
            while (particles.size() < no_of_particles)
                particles.push_back(ParticleType::random());
        }

        //! ParticleType::evaluation() over the current survivors.
        typename ParticleType::Result evaluate() { return ParticleType::evaluation(survivors); }

    private:
        std::vector<ParticleType> particles;
        std::vector<ParticleType> survivors;
    };
}
