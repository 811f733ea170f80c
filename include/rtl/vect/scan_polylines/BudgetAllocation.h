// Exact allocation of a vertex budget across independent groups (a multiple-choice knapsack): every group picks
// exactly one of its options (vertices v, cost c), the sum of the chosen v stays <= budget, and the sum of the chosen
// c is minimal. A dynamic programme over (group, vertices used) on each group's Pareto front (an option is dropped when
// another with no more vertices costs no more: it can never be needed): O(groups x budget x front) time after
// O(options log options) per group, O(groups x budget) memory. Among options of equal cost the one with fewer
// vertices, then the one listed first, is kept.
#pragma once

#include <algorithm>
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
        std::vector<std::size_t> order, front;
        for (std::size_t g = 0; g < G; ++g)
        {
            const std::vector<BudgetOption> &opts = groups[g];
            order.resize(opts.size());
            for (std::size_t o = 0; o < opts.size(); ++o) order[o] = o;
            std::sort(order.begin(), order.end(), [&](std::size_t u, std::size_t v) {
                if (opts[u].vertices != opts[v].vertices) return opts[u].vertices < opts[v].vertices;
                if (opts[u].cost != opts[v].cost) return opts[u].cost < opts[v].cost;
                return u < v;
            });
            front.clear();
            for (std::size_t o : order)
                if (front.empty() || opts[o].cost < opts[front.back()].cost) front.push_back(o);
            const double *prev = &best[g * W];
            double *cur = &best[(g + 1) * W];
            for (std::size_t b = 0; b < W; ++b)
                for (std::size_t o : front)
                {
                    const BudgetOption &opt = opts[o];
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
