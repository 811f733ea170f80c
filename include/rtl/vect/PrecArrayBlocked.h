// PrecArrayBlocked: the range-sum interface of PrecArray2D/3D (size(), sums(index), sums(beg, end)) that, for long
// chains, stores a prefix row only every 8 points. The precomputation is then one pass that accumulates every
// point but writes 1/8 of the rows (the full prefix array is bound by its row writes: 40 B per point in 2D, 72 B in
// 3D), and a query adds at most 14 points from the chain itself. Short chains (many short ranges, hence many
// queries per point) keep a row per point. Used by the FTLS/AFTLS vectorizers, whose few queries per range make
// that trade worthwhile. The point vector passed to precompute() must outlive the queries.
//
// Exact range sums next to huge values (issue 15 item 7): a plain prefix sum loses the low bits of every later row
// once one far-off point (x = 1e9: x^2 = 1e18) has been added, so the sums of a small range after it come out as a
// difference of two rounded 1e18s (error ~100 against sigma^2 ~ 1e-3). A query therefore reads only rows and points
// inside its own range (the rows at the first block boundary at or after beg and the last at or before end, plus
// the points between those and beg/end), and when one block's sum of squares exceeds 256 times the mean block's,
// the prefix is rebuilt as unevaluated sums hi + lo (an error-free TwoSum per block and sum). The sums of a range
// then carry the rounding of its own points only, whatever lies outside it. The plain pass is kept for chains
// without such outliers because the TwoSums would cost ~0.6 ns per point, as much as the pass itself.
#pragma once

#include <algorithm>
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
        static constexpr int row_len = 2 * cols;   // hi[cols], lo[cols]

        //! Rows of the equivalent full prefix array: number of points + 1 (0 before precompute()).
        [[nodiscard]] size_t size() const { return pts ? pts->size() + 1 : 0; }

        //! Chains shorter than this get a row per point (queries then read two rows, like PrecArray); longer
        //! chains get a row per 8 points. Default 16384 points.
        void setMinBlockedSize(size_t size) { min_blocked = size; }

        //! Makes room for pts_cnt points (never shrinks).
        void resize(size_t pts_cnt)
        {
            const size_t need = (pts_cnt + 1) * static_cast<size_t>(row_len);
            if (rows.size() < need)
                rows.resize(need);
        }

        void precompute(const std::vector<VectorND<dimensions, ElementType>> &vec)
        {
            pts = &vec;
            resize(vec.size());
            shift = vec.size() >= min_blocked ? max_shift : 0;
            compensated = false;
            if (shift == 0)
                precomputeBlocks<1, false>(vec);
            else
                precomputeBlocks<(size_t(1) << max_shift), false>(vec);
            if (hasOutlierBlock(vec.size() >> shift))
            {
                compensated = true;
                if (shift == 0)
                    precomputeBlocks<1, true>(vec);
                else
                    precomputeBlocks<(size_t(1) << max_shift), true>(vec);
            }
        }

        //! True if every point (hence every sum) is finite.
        [[nodiscard]] bool allFinite() const
        {
            if (!pts)
                return false;
            const size_t n = pts->size();
            const ComputeType *last = rows.data() + (n >> shift) * row_len;
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
            const size_t first_row = (beg + mask) >> shift, last_row = end >> shift;   // rows inside [beg, end]
            if (first_row >= last_row)   // no whole block inside: at most 14 points
            {
                for (size_t i = beg; i < end; ++i)
                    add(s, (*pts)[i]);
            }
            else
            {
                const ComputeType *re = rows.data() + last_row * row_len, *rb = rows.data() + first_row * row_len;
                for (int k = 0; k < cols; ++k)
                    s[k] = re[k] - rb[k];
                if (compensated)
                    for (int k = 0; k < cols; ++k)
                        s[k] += re[cols + k] - rb[cols + k];
                for (size_t i = beg; i < (first_row << shift); ++i)
                    add(s, (*pts)[i]);
                for (size_t i = last_row << shift; i < end; ++i)
                    add(s, (*pts)[i]);
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
        bool compensated{false};   // rows hold hi + lo (else hi only; lo unused)

        //! hi + lo += v exactly (Knuth's TwoSum: hi + lo is the unrounded sum of everything added).
        static void twoSumAdd(ComputeType &hi, ComputeType &lo, ComputeType v)
        {
            const ComputeType s = hi + v, bv = s - hi;
            lo += (hi - (s - bv)) + (v - bv);
            hi = s;
        }

        //! True if some block's sum of squares (from the plain rows) exceeds 256 times the mean block's: the plain
        //! rows after it then lose the low bits of the sums of small ranges.
        bool hasOutlierBlock(size_t blocks) const
        {
            if (blocks < 2)
                return false;
            const int sq = dimensions == 2 ? 2 : 3;   // first squared column
            const ComputeType *r = rows.data();
            ComputeType max_sq = 0;
            for (size_t b = 1; b <= blocks; ++b)
            {
                ComputeType d = 0;
                for (int k = sq; k < sq + dimensions; ++k)
                    d += r[b * row_len + k] - r[(b - 1) * row_len + k];
                max_sq = std::max(max_sq, d);
            }
            ComputeType total = 0;
            for (int k = sq; k < sq + dimensions; ++k)
                total += r[blocks * row_len + k];
            return max_sq > ComputeType(256) * total / static_cast<ComputeType>(blocks);
        }

        //! Fills the rows: plain prefix sums in hi, or (exact) hi + lo compensated per block.
        template<size_t block, bool exact>
        void precomputeBlocks(const std::vector<VectorND<dimensions, ElementType>> &vec)
        {
            ComputeType *row = rows.data();
            for (int k = 0; k < row_len; ++k)
                row[k] = 0;
            ComputeType h0 = 0, h1 = 0, h2 = 0, h3 = 0, h4 = 0, h5 = 0, h6 = 0, h7 = 0, h8 = 0;
            ComputeType l0 = 0, l1 = 0, l2 = 0, l3 = 0, l4 = 0, l5 = 0, l6 = 0, l7 = 0, l8 = 0;
            const size_t full = vec.size() / block;
            const VectorND<dimensions, ElementType> *p = vec.data();
            for (size_t b = 0; b < full; ++b, p += block)
            {
                // The block's own sums in scalar accumulators (kept in registers), then one add per sum.
                ComputeType a0 = 0, a1 = 0, a2 = 0, a3 = 0, a4 = 0, a5 = 0, a6 = 0, a7 = 0, a8 = 0;
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
                row += row_len;
                step<exact>(h0, l0, a0, row, 0); step<exact>(h1, l1, a1, row, 1); step<exact>(h2, l2, a2, row, 2);
                step<exact>(h3, l3, a3, row, 3); step<exact>(h4, l4, a4, row, 4);
                if constexpr (dimensions == 3)
                {
                    step<exact>(h5, l5, a5, row, 5); step<exact>(h6, l6, a6, row, 6); step<exact>(h7, l7, a7, row, 7);
                    step<exact>(h8, l8, a8, row, 8);
                }
            }
        }

        //! Adds a block sum (error-free if `exact`) and writes the row entries.
        template<bool exact>
        static void step(ComputeType &hi, ComputeType &lo, ComputeType v, ComputeType *row, int k)
        {
            if constexpr (exact)
            {
                twoSumAdd(hi, lo, v);
                row[cols + k] = lo;
            }
            else
                hi += v;
            row[k] = hi;
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
