// Exact allocation of a vertex budget across independent groups (a multiple-choice knapsack): every group picks
// exactly one of its options (vertices v, cost c), the sum of the chosen v stays <= budget, and the sum of the chosen
// c is minimal. A dynamic programme over (group, vertices used): O(groups x budget x options) time,
// O(groups x budget) memory. Ties go to the option listed first, then to fewer vertices.
#pragma once

#include <cstddef>
#include <limits>
#include <vector>

namespace rtl::scan_polylines
{
    struct BudgetOption
    {
        std::size_t vertices = 0;
        double cost = 0;
    };

    //! The chosen option index of every group (each group needs an option of 0 vertices, or the budget may not be
    //! met: then the result is empty). Costs must not be NaN.
    inline std::vector<std::size_t> allocateBudget(const std::vector<std::vector<BudgetOption>> &groups, std::size_t budget)
    {
        const double inf = std::numeric_limits<double>::infinity();
        const std::size_t G = groups.size(), W = budget + 1;
        std::vector<double> best((G + 1) * W, inf);
        std::vector<std::size_t> pick(G * W, 0);
        for (std::size_t b = 0; b < W; ++b) best[b] = 0;   // no group yet: any budget left over is fine
        for (std::size_t g = 0; g < G; ++g)
        {
            const double *prev = &best[g * W];
            double *cur = &best[(g + 1) * W];
            for (std::size_t b = 0; b < W; ++b)
                for (std::size_t o = 0; o < groups[g].size(); ++o)
                {
                    const BudgetOption &opt = groups[g][o];
                    if (opt.vertices > b) continue;
                    const double v = prev[b - opt.vertices] + opt.cost;
                    if (v < cur[b]) { cur[b] = v; pick[g * W + b] = o; }
                }
        }
        if (!(best[G * W + budget] < inf)) return {};
        std::vector<std::size_t> chosen(G);
        std::size_t b = budget;
        for (std::size_t g = G; g > 0; --g)
        {
            const std::size_t o = pick[(g - 1) * W + b];
            chosen[g - 1] = o;
            b -= groups[g - 1][o].vertices;
        }
        return chosen;
    }
}
