// Assignment problem (Hungarian algorithm) on a runtime-size, possibly rectangular cost matrix.
//
// Shortest augmenting paths with row/column potentials (Jonker-Volgenant style), O(min(r,c)^2 * max(r,c)).
// The arithmetic runs in a wider type (see AssignmentWork) so that integer costs are exact and never overflow,
// and the iteration order is fixed, so equal inputs always give the same assignment (also among ties).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

namespace rtl
{
    //! Column given to a row that is left out (only when rows > cols).
    inline constexpr std::size_t assignment_unassigned = std::numeric_limits<std::size_t>::max();

    namespace detail
    {
        __extension__ typedef __int128 AssignmentInt128;

        // Working type: double for float (fewer rounding ties), T for other floating types, a signed integer
        // at least twice as wide for integral T (sums of potentials stay far from overflow).
        template<typename T>
        struct AssignmentWork
        {
            static_assert(std::is_arithmetic_v<T> && !std::is_same_v<T, bool>, "solveAssignment needs numeric costs.");
            using type = std::conditional_t<std::is_floating_point_v<T>,
                                            std::conditional_t<std::is_same_v<T, float>, double, T>,
                                            std::conditional_t<(sizeof(T) <= 4), std::int64_t, AssignmentInt128>>;
        };

        template<typename W>
        constexpr W assignmentInfinity()
        {
            if constexpr (std::is_floating_point_v<W>)
                return std::numeric_limits<W>::infinity();
            else
                return static_cast<W>(1) << (sizeof(W) * 8 - 4);  // far above any reduced cost, far below overflow
        }

        // n <= m, cost(i, j) for i < n, j < m (already negated for maximisation). Returns the column of every row.
        template<typename W, typename CostFn>
        std::vector<std::size_t> solveAssignmentSquareOrWide(std::size_t n, std::size_t m, const CostFn &cost)
        {
            const W inf = assignmentInfinity<W>();
            // 1-based arrays; column 0 is the virtual start of every augmenting path.
            std::vector<W> u(n + 1, W(0)), v(m + 1, W(0)), minv(m + 1);
            std::vector<std::size_t> p(m + 1, 0), way(m + 1, 0);
            std::vector<char> used(m + 1);
            for (std::size_t i = 1; i <= n; ++i)
            {
                p[0] = i;
                std::size_t j0 = 0;
                std::fill(minv.begin(), minv.end(), inf);
                std::fill(used.begin(), used.end(), 0);
                do
                {
                    used[j0] = 1;
                    const std::size_t i0 = p[j0];
                    W delta = inf;
                    std::size_t j1 = 0;
                    for (std::size_t j = 1; j <= m; ++j)
                    {
                        if (used[j])
                            continue;
                        const W cur = cost(i0 - 1, j - 1) - u[i0] - v[j];
                        if (cur < minv[j])
                        {
                            minv[j] = cur;
                            way[j] = j0;
                        }
                        if (minv[j] < delta)
                        {
                            delta = minv[j];
                            j1 = j;
                        }
                    }
                    for (std::size_t j = 0; j <= m; ++j)
                    {
                        if (used[j])
                        {
                            u[p[j]] += delta;
                            v[j] -= delta;
                        }
                        else
                            minv[j] -= delta;
                    }
                    j0 = j1;
                } while (p[j0] != 0);
                do      // augment along the path back to the virtual column
                {
                    const std::size_t j1 = way[j0];
                    p[j0] = p[j1];
                    j0 = j1;
                } while (j0 != 0);
            }
            std::vector<std::size_t> col_of_row(n, assignment_unassigned);
            for (std::size_t j = 1; j <= m; ++j)
                if (p[j] != 0)
                    col_of_row[p[j] - 1] = j - 1;
            return col_of_row;
        }
    }

    /*!
     * Optimal assignment of rows to columns.
     * \param costs row-major rows x cols matrix (rectangular allowed); may be null only when rows * cols == 0.
     * \param rows number of rows (agents).
     * \param cols number of columns (tasks).
     * \param maximize maximise the total instead of minimising it.
     * \return for each row its column, or assignment_unassigned for the rows > cols left out. Exactly
     *         min(rows, cols) rows get distinct columns, with the least (greatest) total cost over all such choices.
     * \throws std::invalid_argument when a cost is not finite (NaN or infinity).
     */
    template<typename T>
    std::vector<std::size_t> solveAssignment(const T *costs, std::size_t rows, std::size_t cols, bool maximize = false)
    {
        using W = typename detail::AssignmentWork<T>::type;
        if (rows == 0 || cols == 0)
            return std::vector<std::size_t>(rows, assignment_unassigned);
        if (cols > std::numeric_limits<std::size_t>::max() / rows)
            throw std::invalid_argument("solveAssignment: rows * cols overflows");
        if (costs == nullptr)
            throw std::invalid_argument("solveAssignment: null cost matrix");
        if constexpr (std::is_floating_point_v<T>)
            for (std::size_t k = 0; k < rows * cols; ++k)
                if (!std::isfinite(costs[k]))
                    throw std::invalid_argument("solveAssignment: cost at row " + std::to_string(k / cols) + ", column " +
                                                std::to_string(k % cols) + " is not finite");
        const W sign = maximize ? W(-1) : W(1);
        if (rows <= cols)
            return detail::solveAssignmentSquareOrWide<W>(rows, cols, [&](std::size_t i, std::size_t j) {
                return sign * static_cast<W>(costs[i * cols + j]);
            });
        // More rows than columns: assign every column a row on the transposed problem.
        const std::vector<std::size_t> row_of_col = detail::solveAssignmentSquareOrWide<W>(
            cols, rows, [&](std::size_t i, std::size_t j) { return sign * static_cast<W>(costs[j * cols + i]); });
        std::vector<std::size_t> col_of_row(rows, assignment_unassigned);
        for (std::size_t c = 0; c < cols; ++c)
            col_of_row[row_of_col[c]] = c;
        return col_of_row;
    }

    //! solveAssignment on a row-major vector; throws std::invalid_argument also when costs.size() != rows * cols.
    template<typename T>
    std::vector<std::size_t> solveAssignment(const std::vector<T> &costs, std::size_t rows, std::size_t cols, bool maximize = false)
    {
        if (rows != 0 && cols > std::numeric_limits<std::size_t>::max() / rows)
            throw std::invalid_argument("solveAssignment: rows * cols overflows");
        if (costs.size() != rows * cols)
            throw std::invalid_argument("solveAssignment: " + std::to_string(costs.size()) + " costs for a " +
                                        std::to_string(rows) + " x " + std::to_string(cols) + " matrix");
        return solveAssignment(costs.data(), rows, cols, maximize);
    }
}
