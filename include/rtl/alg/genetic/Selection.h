// Fitness-proportional (roulette-wheel) selection without replacement, used by GeneticAlgorithm.
// O(n * count): each pick scans the remaining weights once.
#pragma once

#include <cmath>
#include <cstddef>
#include <vector>

#include "rtl/alg/AlgorithmRandom.h"

namespace rtl
{
    /*!
     * Picks min(count, weights.size()) distinct indices, each next one with probability proportional to its
     * weight among those not yet picked (weights that are negative or not finite count as 0; when no remaining
     * weight is positive, the remaining indices count equally). Draws from AlgorithmRandom; returned in pick order.
     */
    inline std::vector<size_t> selectProportional(const std::vector<double> &weights, size_t count)
    {
        std::vector<double> w(weights.size());
        for (size_t i = 0; i < w.size(); ++i)
            w[i] = std::isfinite(weights[i]) && weights[i] > 0 ? weights[i] : 0.0;
        std::vector<char> taken(w.size(), 0);
        std::vector<size_t> picked;
        for (size_t k = 0; k < count && k < w.size(); ++k)
        {
            double total = 0;
            for (size_t i = 0; i < w.size(); ++i)
                if (!taken[i])
                    total += w[i];
            const bool uniform = !(total > 0) || !std::isfinite(total);
            const double r = AlgorithmRandom::uniform(0.0, 1.0) * (uniform ? static_cast<double>(w.size() - k) : total);
            double cumulative = 0;
            size_t choice = w.size();
            for (size_t i = 0; i < w.size(); ++i)
            {
                if (taken[i] || (!uniform && w[i] == 0))
                    continue;
                choice = i;     // the last eligible index catches rounding at the top end
                cumulative += uniform ? 1.0 : w[i];
                if (r < cumulative)
                    break;
            }
            taken[choice] = 1;
            picked.push_back(choice);
        }
        return picked;
    }
}
