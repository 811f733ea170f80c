// Munkres: the Hungarian assignment on a fixed-size N x N rtl::Matrix, built on solveAssignment().
// Complexity O(N^3). The published solver read an empty std::optional in one step (undefined behaviour that passed
// its tests at -O0 only); this one is a different, deterministic algorithm with exact integer arithmetic
// (Assignment.h). Results: result[r] is row r's column and its original cost; maximisation flips the costs.
#pragma once

#include <array>
#include <cstddef>
#include <optional>
#include <vector>

#include "rtl/alg/munkres/Assignment.h"
#include "rtl/core/Matrix.h"

namespace rtl
{
    template<typename T, size_t N>
    class Munkres
    {
    public:
        //! One assigned pair: row, its column and the original cost at (row, col).
        struct Result
        {
            Result() : row(0), col(0), cost(T{}) {}
            Result(size_t r, size_t c, T cst) : row(r), col(c), cost(cst) {}
            size_t row;
            size_t col;
            T cost;
        };

        /*!
         * Assignment with the least total cost (the greatest when max_cost is true); result[r] = {r, col, cost}.
         * Exact for integer and floating costs and deterministic among ties.
         * \throws std::invalid_argument when a cost is not finite.
         */
        static std::array<Result, N> solve(Matrix<static_cast<int>(N), static_cast<int>(N), T> cost_matrix, bool max_cost = false)
        {
            std::vector<T> row_major(N * N);
            for (size_t r = 0; r < N; ++r)
                for (size_t c = 0; c < N; ++c)
                    row_major[r * N + c] = cost_matrix(r, c);
            const std::vector<size_t> cols = solveAssignment(row_major, N, N, max_cost);
            std::array<Result, N> result;
            for (size_t r = 0; r < N; ++r)
                result[r] = Result(r, cols[r], cost_matrix(r, cols[r]));
            return result;
        }
    };
}
