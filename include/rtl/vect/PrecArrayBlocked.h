// PrecArrayBlocked: the range-sum interface of PrecArray2D/3D (size(), sums(index), sums(beg, end)) that, for long
// chains, stores a prefix row only every 8 points. The precomputation is then one pass that accumulates every
// point but writes 1/8 of the rows (the full prefix array is bound by its row writes: 40 B per point in 2D, 72 B in
// 3D), and a query adds at most 14 points from the chain itself. Short chains (many short ranges, hence many
// queries per point) keep a row per point. Used by the FTLS vectorizers, whose few queries per range make that
// trade worthwhile. The point vector passed to precompute() must outlive the queries.
#pragma once

#include <cmath>
#include <cstddef>
#include <type_traits>
#include <vector>

#include "rtl/core/VectorND.h"
#include "rtl/vect/PrecSums.h"

namespace rtl
{
    template<int dimensions, typename Element, typename Compute>
    class PrecArrayBlocked
    {
        static_assert(dimensions == 2 || dimensions == 3, "PrecArrayBlocked supports 2D and 3D points");
        static constexpr size_t max_shift = 3;   // blocks of 8 points

    public:
        typedef Element ElementType;
        typedef Compute ComputeType;
        typedef std::conditional_t<dimensions == 2, PrecSums2D<Compute>, PrecSums3D<Compute>> SumsType;
        static constexpr int cols = static_cast<int>(SumsType::sumNr());

        //! Rows of the equivalent full prefix array: number of points + 1 (0 before precompute()).
        [[nodiscard]] size_t size() const { return pts ? pts->size() + 1 : 0; }

        //! Chains shorter than this get a row per point (queries then read two rows, like PrecArray); longer
        //! chains get a row per 8 points. Default 16384 points.
        void setMinBlockedSize(size_t size) { min_blocked = size; }

        //! Makes room for pts_cnt points (never shrinks).
        void resize(size_t pts_cnt)
        {
            const size_t need = (pts_cnt + 1) * static_cast<size_t>(cols);
            if (rows.size() < need)
                rows.resize(need);
        }

        void precompute(const std::vector<VectorND<dimensions, ElementType>> &vec)
        {
            pts = &vec;
            resize(vec.size());
            shift = vec.size() >= min_blocked ? max_shift : 0;
            if (shift == 0)
                precomputeBlocks<1>(vec);
            else
                precomputeBlocks<(size_t(1) << max_shift)>(vec);
        }

        //! True if every point (hence every sum) is finite.
        [[nodiscard]] bool allFinite() const
        {
            if (!pts)
                return false;
            const size_t n = pts->size();
            const ComputeType *last = rows.data() + (n >> shift) * cols;
            ComputeType sum = 0;
            for (int k = 0; k < cols; ++k)
                sum += last[k];
            for (size_t i = (n >> shift) << shift; i < n; ++i)
                for (int k = 0; k < dimensions; ++k)
                    sum += static_cast<ComputeType>((*pts)[i][k]);
            return std::isfinite(sum);
        }

        SumsType sums(size_t index) const { return sums(0, index); }

        //! Sums of the points [beg, end) (count = end - beg). Precondition: beg <= end < size().
        SumsType sums(size_t beg, size_t end) const
        {
            ComputeType s[cols] = {};
            const size_t mask = (size_t(1) << shift) - 1;
            if (end - beg <= (end & mask) + (beg & mask))   // summing the range directly is not dearer
            {
                for (size_t i = beg; i < end; ++i)
                    add(s, (*pts)[i]);
            }
            else
            {
                const ComputeType *re = rows.data() + (end >> shift) * cols, *rb = rows.data() + (beg >> shift) * cols;
                for (int k = 0; k < cols; ++k)
                    s[k] = re[k] - rb[k];
                for (size_t i = end & ~mask; i < end; ++i)
                    add(s, (*pts)[i]);
                ComputeType t[cols] = {};
                for (size_t i = beg & ~mask; i < beg; ++i)
                    add(t, (*pts)[i]);
                for (int k = 0; k < cols; ++k)
                    s[k] -= t[k];
            }
            SumsType out;
            for (int k = 0; k < cols; ++k)
                out.sums(k) = s[k];
            out.sums(cols) = static_cast<ComputeType>(end - beg);
            return out;
        }

    private:
        const std::vector<VectorND<dimensions, ElementType>> *pts{nullptr};
        std::vector<ComputeType> rows;
        size_t min_blocked{16384}, shift{0};

        template<size_t block>
        void precomputeBlocks(const std::vector<VectorND<dimensions, ElementType>> &vec)
        {
            ComputeType *row = rows.data();
            for (int k = 0; k < cols; ++k)
                row[k] = 0;
            // Scalar accumulators (kept in registers), one row written per full block.
            ComputeType a0 = 0, a1 = 0, a2 = 0, a3 = 0, a4 = 0, a5 = 0, a6 = 0, a7 = 0, a8 = 0;
            const size_t full = vec.size() / block;
            const VectorND<dimensions, ElementType> *p = vec.data();
            for (size_t b = 0; b < full; ++b, p += block)
            {
                for (size_t i = 0; i < block; ++i)
                {
                    const ComputeType x = static_cast<ComputeType>(p[i][0]), y = static_cast<ComputeType>(p[i][1]);
                    if constexpr (dimensions == 2)
                    {
                        a0 += x; a1 += y; a2 += x * x; a3 += y * y; a4 += x * y;
                    }
                    else
                    {
                        const ComputeType z = static_cast<ComputeType>(p[i][2]);
                        a0 += x; a1 += y; a2 += z; a3 += x * x; a4 += y * y; a5 += z * z; a6 += x * y; a7 += y * z; a8 += z * x;
                    }
                }
                row += cols;
                const ComputeType acc[9] = {a0, a1, a2, a3, a4, a5, a6, a7, a8};
                for (int k = 0; k < cols; ++k)
                    row[k] = acc[k];
            }
        }

        static void add(ComputeType *s, const VectorND<dimensions, ElementType> &p)
        {
            const ComputeType x = static_cast<ComputeType>(p[0]), y = static_cast<ComputeType>(p[1]);
            if constexpr (dimensions == 2)
            {
                s[0] += x; s[1] += y; s[2] += x * x; s[3] += y * y; s[4] += x * y;
            }
            else
            {
                const ComputeType z = static_cast<ComputeType>(p[2]);
                s[0] += x; s[1] += y; s[2] += z; s[3] += x * x; s[4] += y * y; s[5] += z * z;
                s[6] += x * y; s[7] += y * z; s[8] += z * x;
            }
        }
    };
}
