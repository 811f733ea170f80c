// Exact allocation of a vertex budget across independent groups (a multiple-choice knapsack): every group picks
// exactly one of its options (vertices v, cost c), the sum of the chosen v stays <= budget, and the sum of the chosen
// c is minimal. A dynamic programme over (group, vertices used) on each group's Pareto front (an option is dropped when
// another with no more vertices costs no more: it can never be needed): O(groups x budget x front) time after
// O(options log options) per group, O(groups x budget) memory. Among options of equal cost the one with fewer
// vertices, then the one listed first, is kept. The same table holds the optimal choice for every smaller budget too
// (BudgetTable::plan), at O(groups) each.
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

    //! The knapsack's table for budgets 0..budget: cost(b) is the least total cost within b vertices, plan(b) a choice
    //! that reaches it. Costs must not be NaN.
    class BudgetTable
    {
    public:
        BudgetTable(const std::vector<std::vector<BudgetOption>> &groups, std::size_t budget)
            : groups_(&groups), G_(groups.size()), W_(budget + 1)
        {
            const double inf = std::numeric_limits<double>::infinity();
            best_.assign((G_ + 1) * W_, inf);
            pick_.assign(G_ * W_, 0);
            for (std::size_t b = 0; b < W_; ++b) best_[b] = 0;   // no group yet: any budget left over is fine
            std::vector<std::size_t> order, front;
            for (std::size_t g = 0; g < G_; ++g)
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
                const double *prev = &best_[g * W_];
                double *cur = &best_[(g + 1) * W_];
                for (std::size_t b = 0; b < W_; ++b)
                    for (std::size_t o : front)
                    {
                        const BudgetOption &opt = opts[o];
                        if (opt.vertices > b) continue;
                        const double v = prev[b - opt.vertices] + opt.cost;
                        if (v < cur[b]) { cur[b] = v; pick_[g * W_ + b] = o; }
                    }
            }
        }

        //! The largest budget of the table.
        [[nodiscard]] std::size_t budget() const { return W_ - 1; }
        //! Least total cost within b <= budget() vertices (infinite when no choice fits).
        [[nodiscard]] double cost(std::size_t b) const { return best_[G_ * W_ + b]; }

        //! The chosen option index of every group within b <= budget() vertices (empty when no choice fits).
        [[nodiscard]] std::vector<std::size_t> plan(std::size_t b) const
        {
            if (!(cost(b) < std::numeric_limits<double>::infinity())) return {};
            std::vector<std::size_t> chosen(G_);
            for (std::size_t g = G_; g > 0; --g)
            {
                const std::size_t o = pick_[(g - 1) * W_ + b];
                chosen[g - 1] = o;
                b -= (*groups_)[g - 1][o].vertices;
            }
            return chosen;
        }

    private:
        const std::vector<std::vector<BudgetOption>> *groups_;
        std::size_t G_, W_;
        std::vector<double> best_;
        std::vector<std::size_t> pick_;
    };

    //! The chosen option index of every group (each group needs an option of 0 vertices, or the budget may not be
    //! met: then the result is empty). Costs must not be NaN.
    inline std::vector<std::size_t> allocateBudget(const std::vector<std::vector<BudgetOption>> &groups, std::size_t budget)
    {
        return BudgetTable(groups, budget).plan(budget);
    }
}
