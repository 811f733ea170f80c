// GeneticAlgorithm: elitism, fitness-proportional survival, crossover refill and mutation over a fixed population.
// Complexity: one epoch scores every agent once, sorts them (O(A log A) for A agents) and draws the survivors
// (O(A * survivors) by roulette without replacement). With surviving_elites > 0 the best agent survives unmutated,
// so with deterministic scores the best score never falls from one epoch to the next.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <numeric>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "rtl/alg/AlgorithmRandom.h"
#include "rtl/alg/genetic/Selection.h"

namespace rtl
{
    /*!
     * AgentType needs: static AgentType random(); a score() convertible to double (greater is fitter);
     * AgentType crossover(const AgentType&) const or non-const; void mutate().
     * Randomness comes from AlgorithmRandom: seed it for reproducible runs.
     */
    template<typename AgentType, size_t agents_in_epoch, size_t surviving_elites, size_t surviving_total, size_t mutations_per_epoch>
    class GeneticAlgorithm
    {
        static_assert(agents_in_epoch > surviving_total, "GeneticAlgorithm: agents_in_epoch must exceed surviving_total.");
        static_assert(surviving_elites < surviving_total, "GeneticAlgorithm: surviving_elites must be below surviving_total.");

    public:
        //! agents_in_epoch agents from AgentType::random().
        GeneticAlgorithm()
        {
            agents.reserve(agents_in_epoch);
            for (size_t i = 0; i < agents_in_epoch; ++i)
                agents.push_back(AgentType::random());
        }

        /*!
         * One epoch: scores every agent; the surviving_elites best survive, and surviving_total - surviving_elites
         * more are drawn from the rest by fitness-proportional selection on the normalised scores (score - min score);
         * the population is refilled by crossover of two distinct survivors drawn uniformly, then
         * mutations_per_epoch agents drawn uniformly (with repetition) are mutated, never the first one, which is the
         * best agent of the epoch whenever surviving_elites > 0. Scores should be finite (NaN ranks last).
         */
        void iterate_epoch()
        {
            const std::vector<size_t> order = ranking();
            std::vector<AgentType> next;
            next.reserve(agents_in_epoch);
            for (size_t k = 0; k < surviving_elites; ++k)
                next.push_back(agents[order[k]]);
            std::vector<double> rest_weights;
            double min_score = scores.empty() ? 0.0 : *std::min_element(scores.begin(), scores.end());
            for (size_t k = surviving_elites; k < order.size(); ++k)
                rest_weights.push_back(scores[order[k]] - min_score);
            for (size_t pick : selectProportional(rest_weights, surviving_total - surviving_elites))
                next.push_back(agents[order[surviving_elites + pick]]);
            while (next.size() < agents_in_epoch)
            {
                const size_t a = AlgorithmRandom::uniform<size_t>(0, surviving_total - 1);
                size_t b = a;   // a lone survivor mates with itself
                if constexpr (surviving_total > 1)
                {
                    b = AlgorithmRandom::uniform<size_t>(0, surviving_total - 2);
                    if (b >= a)
                        ++b;
                }
                next.push_back(next[a].crossover(next[b]));
            }
            for (size_t k = 0; k < mutations_per_epoch; ++k)
                next[AlgorithmRandom::uniform<size_t>(1, agents_in_epoch - 1)].mutate();
            agents = std::move(next);
        }

        //! The n-th best agent of the current population by score (0 = best; ties keep population order).
        //! \throws std::out_of_range when n >= agents_in_epoch.
        AgentType best_agent(size_t n = 0)
        {
            if (n >= agents_in_epoch)
                throw std::out_of_range("GeneticAlgorithm::best_agent: n = " + std::to_string(n) + " but only " +
                                        std::to_string(agents_in_epoch) + " agents");
            return agents[ranking()[n]];
        }

    private:
        // Scores the population (into scores) and returns the agents' indices, best first, stable among ties.
        std::vector<size_t> ranking()
        {
            scores.clear();
            for (AgentType &a : agents)
            {
                const double s = static_cast<double>(a.score());
                scores.push_back(std::isnan(s) ? -std::numeric_limits<double>::infinity() : s);
            }
            std::vector<size_t> order(agents.size());
            std::iota(order.begin(), order.end(), size_t(0));
            std::stable_sort(order.begin(), order.end(), [&](size_t i, size_t j) { return scores[i] > scores[j]; });
            return order;
        }

        std::vector<AgentType> agents;
        std::vector<double> scores;
    };
}
