// PrecArrayBlocked: the range-sum interface of PrecArray2D/3D (size(), sums(index), sums(beg, end)) that, for long
// chains, stores a prefix row only every 8 points. The precomputation is then one pass that accumulates every
// point but writes 1/8 of the rows (the full prefix array is bound by its row writes: 40 B per point in 2D, 72 B in
// 3D), and a query adds at most 14 points from the chain itself. Short chains (many short ranges, hence many
// queries per point) keep a row per point. Used by the FTLS/AFTLS vectorizers, whose few queries per range make
// that trade worthwhile. The point vector passed to precompute() must outlive the queries.
//
// Exact range sums next to huge values: a plain prefix sum loses the low bits of every later row
// once one far-off point (x = 1e9: x^2 = 1e18) has been added, so the sums of a small range after it come out as a
// difference of two rounded 1e18s (error ~100 against sigma^2 ~ 1e-3). A query therefore reads only rows and points
// inside its own range (the rows at the first block boundary at or after beg and the last at or before end, plus
// the points between those and beg/end), and when one block's sum of squares exceeds 256 times the mean block's,
// the prefix is rebuilt as unevaluated sums hi + lo (an error-free TwoSum per block and sum). The sums of a range
// then carry the rounding of its own points only, whatever lies outside it. The plain pass is kept for chains
// without such outliers because the TwoSums would cost as much as the pass itself (docs/vect.md).
//
// Speed of the plain pass: it writes hi rows of 5/9 sums only (lo rows apart, written by the
// compensated pass); with SSE2 it accumulates two blocks at once, lane by lane in the scalar pass's order (rows
// bit-identical to the scalar pass's), and rules the outlier test out from its own block sums, reading the rows
// again only when it cannot (a margin of 1e-9 around the threshold, or an outlier).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <type_traits>
#include <vector>

#if defined(__GNUC__) && defined(__SSE2__)
#include <emmintrin.h>
#endif

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
            if (lows.size() < need)
                lows.resize(need);
        }

        void precompute(const std::vector<VectorND<dimensions, ElementType>> &vec)
        {
            pts = &vec;
            resize(vec.size());
            shift = vec.size() >= min_blocked ? max_shift : 0;
            compensated = false;
            const bool outlier = shift == 0 ? precomputeBlocks<1, false>(vec) : precomputeBlocks<(size_t(1) << max_shift), false>(vec);
            if (outlier)
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
            const size_t first_row = (beg + mask) >> shift, last_row = end >> shift;   // rows inside [beg, end]
            if (first_row >= last_row)   // no whole block inside: at most 14 points
            {
                for (size_t i = beg; i < end; ++i)
                    add(s, (*pts)[i]);
            }
            else
            {
                const ComputeType *re = rows.data() + last_row * cols, *rb = rows.data() + first_row * cols;
                for (int k = 0; k < cols; ++k)
                    s[k] = re[k] - rb[k];
                if (compensated)
                {
                    const ComputeType *le = lows.data() + last_row * cols, *lb = lows.data() + first_row * cols;
                    for (int k = 0; k < cols; ++k)
                        s[k] += le[k] - lb[k];
                }
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
        // Row r of the prefix (r blocks) at rows[r * cols]: hi, and its lo at lows[r * cols] (read only when
        // compensated). Apart, so that the plain pass writes contiguous rows of cols entries.
        std::vector<ComputeType> rows, lows;
        size_t min_blocked{16384}, shift{0};
        bool compensated{false};   // the prefix is hi + lo (else hi only; lows unused)

        //! hi + lo += v exactly (Knuth's TwoSum: hi + lo is the unrounded sum of everything added).
        static void twoSumAdd(ComputeType &hi, ComputeType &lo, ComputeType v)
        {
            const ComputeType s = hi + v, bv = s - hi;
            lo += (hi - (s - bv)) + (v - bv);
            hi = s;
        }

        //! The scalar pass's outlier test from the hi rows (second pass; only when mayHaveOutlier() could not rule
        //! it out): some block's sum of squares exceeds 256 times the mean block's.
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
                    d += r[b * cols + k] - r[(b - 1) * cols + k];
                max_sq = std::max(max_sq, d);
            }
            ComputeType total = 0;
            for (int k = sq; k < sq + dimensions; ++k)
                total += r[blocks * cols + k];
            return max_sq > ComputeType(256) * total / static_cast<ComputeType>(blocks);
        }

        //! Fills the rows: plain prefix sums in hi, or (exact) hi + lo compensated per block. The plain pass also
        //! returns whether some block's sum of squares (the difference of its two hi rows) exceeds 256 times the
        //! mean block's: the plain rows after it then lose the low bits of the sums of small ranges.
        template<size_t block, bool exact>
        bool precomputeBlocks(const std::vector<VectorND<dimensions, ElementType>> &vec)
        {
#if defined(__GNUC__) && defined(__SSE2__)
            if constexpr (!exact && packed)
                return plainBlocksPacked<block>(vec);
#endif
            ComputeType *row = rows.data(), *low = lows.data();
            for (int k = 0; k < cols; ++k)
                row[k] = low[k] = 0;
            ComputeType h0 = 0, h1 = 0, h2 = 0, h3 = 0, h4 = 0, h5 = 0, h6 = 0, h7 = 0, h8 = 0;
            ComputeType l0 = 0, l1 = 0, l2 = 0, l3 = 0, l4 = 0, l5 = 0, l6 = 0, l7 = 0, l8 = 0;
            ComputeType max_sq = 0;
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
                row += cols;
                low += cols;
                const ComputeType o2 = h2, o3 = h3, o4 = h4, o5 = h5;   // hi before this block (squared columns)
                step<exact>(h0, l0, a0, row, low, 0); step<exact>(h1, l1, a1, row, low, 1);
                step<exact>(h2, l2, a2, row, low, 2); step<exact>(h3, l3, a3, row, low, 3);
                step<exact>(h4, l4, a4, row, low, 4);
                if constexpr (dimensions == 3)
                {
                    step<exact>(h5, l5, a5, row, low, 5); step<exact>(h6, l6, a6, row, low, 6);
                    step<exact>(h7, l7, a7, row, low, 7); step<exact>(h8, l8, a8, row, low, 8);
                }
                if constexpr (!exact)
                {
                    const ComputeType d = dimensions == 2 ? (h2 - o2) + (h3 - o3) : ((h3 - o3) + (h4 - o4)) + (h5 - o5);
                    max_sq = std::max(max_sq, d);   // a NaN d (non-finite points) leaves max_sq
                }
            }
            if constexpr (exact)
                return true;
            if (full < 2)
                return false;
            const ComputeType total = dimensions == 2 ? h2 + h3 : (h3 + h4) + h5;
            return max_sq > ComputeType(256) * total / static_cast<ComputeType>(full);
        }

#if defined(__GNUC__) && defined(__SSE2__)
        //! float or double points of contiguous coordinates, double sums: the plain pass on SSE2 pairs.
        static constexpr bool packed = (std::is_same_v<ElementType, float> || std::is_same_v<ElementType, double>) &&
                                       std::is_same_v<ComputeType, double> &&
                                       sizeof(VectorND<dimensions, ElementType>) == dimensions * sizeof(ElementType);

        //! precomputeBlocks<block, false> for two blocks at a time: lane 0 of each register accumulates block b,
        //! lane 1 block b + 1, in the scalar pass's operations and order (a block's sums from 0, point by point,
        //! then hi += block sum, block after block), so the rows and the outlier test are bit-identical to it.
        //! Faster because a block's sums are 8 dependent adds (latency-bound when one block is in flight) and
        //! because x, y (and z) of two points are converted, added and multiplied together.
        template<size_t block>
        bool plainBlocksPacked(const std::vector<VectorND<dimensions, ElementType>> &vec)
        {
            ComputeType *row = rows.data();
            for (int k = 0; k < cols; ++k)
                row[k] = lows[k] = 0;
            const size_t full = vec.size() / block;
            const ElementType *first = vec.empty() ? nullptr : &vec[0][0];
            constexpr size_t stride = dimensions * block;   // coordinates per block
            const __m128d zero = _mm_setzero_pd();
            __m128d bound = zero;   // lane l: the largest computed block sum of squares of the lane-l blocks
            if constexpr (dimensions == 2)
            {
                __m128d h01 = zero, h23 = zero, h4 = zero;   // hi: (x, y), (x^2, y^2), (xy, -)
                for (size_t b = 0; b < full; b += 2)
                {
                    // an odd last block pairs with itself
                    const ElementType *p = first + b * stride, *q = b + 1 < full ? p + stride : p;
                    __m128d ax = zero, ay = zero, axx = zero, ayy = zero, axy = zero;   // lanes: blocks b, b + 1
                    const auto point = [&](__m128d x, __m128d y) {
                        ax = _mm_add_pd(ax, x);
                        ay = _mm_add_pd(ay, y);
                        axx = _mm_add_pd(axx, _mm_mul_pd(x, x));
                        ayy = _mm_add_pd(ayy, _mm_mul_pd(y, y));
                        axy = _mm_add_pd(axy, _mm_mul_pd(x, y));
                    };
                    if constexpr (block % 2 == 0 && std::is_same_v<ElementType, float>)   // loads of (x, y, x', y')
                        for (size_t i = 0; i < block; i += 2)
                        {
                            const __m128 u = _mm_loadu_ps(p + 2 * i), w = _mm_loadu_ps(q + 2 * i);
                            const __m128 l = _mm_unpacklo_ps(u, w), h = _mm_unpackhi_ps(u, w);   // (x_b, x_b+1, y_b, y_b+1)
                            point(_mm_cvtps_pd(l), _mm_cvtps_pd(_mm_movehl_ps(l, l)));
                            point(_mm_cvtps_pd(h), _mm_cvtps_pd(_mm_movehl_ps(h, h)));
                        }
                    else
                        for (size_t i = 0; i < block; ++i)
                        {
                            const __m128d u = load2(p + 2 * i), w = load2(q + 2 * i);
                            point(_mm_unpacklo_pd(u, w), _mm_unpackhi_pd(u, w));
                        }
                    bound = _mm_max_pd(_mm_add_pd(axx, ayy), bound);
                    const auto emit = [&](auto lane_tag) {
                        constexpr int l = decltype(lane_tag)::value;
                        h01 = _mm_add_pd(h01, lanes<l>(ax, ay));
                        h23 = _mm_add_pd(h23, lanes<l>(axx, ayy));
                        h4 = _mm_add_sd(h4, lane<l>(axy));
                        row += cols;
                        _mm_storeu_pd(row, h01);
                        _mm_storeu_pd(row + 2, h23);
                        _mm_store_sd(row + 4, h4);
                    };
                    emit(std::integral_constant<int, 0>());
                    if (b + 1 < full)
                        emit(std::integral_constant<int, 1>());
                }
                return mayHaveOutlier(bound, _mm_cvtsd_f64(_mm_add_sd(h23, _mm_unpackhi_pd(h23, h23))), full) && hasOutlierBlock(full);
            }
            else
            {
                // hi: (x, y), (z, -), (x^2, y^2), (z^2, -), (xy, yz), (zx, -)
                __m128d h01 = zero, h2 = zero, h34 = zero, h5 = zero, h67 = zero, h8 = zero;
                for (size_t b = 0; b < full; b += 2)
                {
                    const ElementType *p = first + b * stride, *q = b + 1 < full ? p + stride : p;
                    __m128d ax = zero, ay = zero, az = zero, axx = zero, ayy = zero, azz = zero, axy = zero, ayz = zero, azx = zero;
                    for (size_t i = 0; i < block; ++i)
                    {
                        const __m128d u = load2(p + 3 * i), w = load2(q + 3 * i);
                        const __m128d x = _mm_unpacklo_pd(u, w), y = _mm_unpackhi_pd(u, w);
                        const __m128d z = load1x2(p + 3 * i + 2, q + 3 * i + 2);
                        ax = _mm_add_pd(ax, x);
                        ay = _mm_add_pd(ay, y);
                        az = _mm_add_pd(az, z);
                        axx = _mm_add_pd(axx, _mm_mul_pd(x, x));
                        ayy = _mm_add_pd(ayy, _mm_mul_pd(y, y));
                        azz = _mm_add_pd(azz, _mm_mul_pd(z, z));
                        axy = _mm_add_pd(axy, _mm_mul_pd(x, y));
                        ayz = _mm_add_pd(ayz, _mm_mul_pd(y, z));
                        azx = _mm_add_pd(azx, _mm_mul_pd(z, x));
                    }
                    bound = _mm_max_pd(_mm_add_pd(_mm_add_pd(axx, ayy), azz), bound);
                    const auto emit = [&](auto lane_tag) {
                        constexpr int l = decltype(lane_tag)::value;
                        h01 = _mm_add_pd(h01, lanes<l>(ax, ay));
                        h2 = _mm_add_sd(h2, lane<l>(az));
                        h34 = _mm_add_pd(h34, lanes<l>(axx, ayy));
                        h5 = _mm_add_sd(h5, lane<l>(azz));
                        h67 = _mm_add_pd(h67, lanes<l>(axy, ayz));
                        h8 = _mm_add_sd(h8, lane<l>(azx));
                        row += cols;
                        _mm_storeu_pd(row, h01);
                        _mm_store_sd(row + 2, h2);
                        _mm_storeu_pd(row + 3, h34);
                        _mm_store_sd(row + 5, h5);
                        _mm_storeu_pd(row + 6, h67);
                        _mm_store_sd(row + 8, h8);
                    };
                    emit(std::integral_constant<int, 0>());
                    if (b + 1 < full)
                        emit(std::integral_constant<int, 1>());
                }
                return mayHaveOutlier(bound, _mm_cvtsd_f64(_mm_add_sd(_mm_add_sd(h34, _mm_unpackhi_pd(h34, h34)), h5)), full) &&
                       hasOutlierBlock(full);
            }
        }

        //! (a[l], b[l]): lane l of two registers.
        template<int l>
        static __m128d lanes(__m128d a, __m128d b) { return l == 0 ? _mm_unpacklo_pd(a, b) : _mm_unpackhi_pd(a, b); }
        //! (p[0], p[1]) as doubles.
        static __m128d load2(const float *p) { return _mm_cvtps_pd(_mm_castsi128_ps(_mm_loadl_epi64(reinterpret_cast<const __m128i *>(p)))); }
        static __m128d load2(const double *p) { return _mm_loadu_pd(p); }
        //! (*p, *q) as doubles.
        static __m128d load1x2(const float *p, const float *q) { return _mm_cvtps_pd(_mm_unpacklo_ps(_mm_load_ss(p), _mm_load_ss(q))); }
        static __m128d load1x2(const double *p, const double *q) { return _mm_unpacklo_pd(_mm_load_sd(p), _mm_load_sd(q)); }
        //! a[l] in lane 0.
        template<int l>
        static __m128d lane(__m128d a) { return l == 0 ? a : _mm_unpackhi_pd(a, a); }

        //! False only if no block can pass the scalar pass's outlier test. That test takes the difference d of a
        //! block's hi rows, which differs from the block's own computed sum s (bound) by the rounding of hi += s
        //! and of the subtraction: d <= s (1 + 5u) + u total (1 + 5u), u = 2^-53, as hi grows monotonically (sums
        //! of squares are >= 0). The margin of 1e-9 covers that; NaN and infinity go to the exact test.
        static bool mayHaveOutlier(__m128d bound, ComputeType total, size_t blocks)
        {
            if (blocks < 2)
                return false;
            const ComputeType m = std::max(_mm_cvtsd_f64(bound), _mm_cvtsd_f64(_mm_unpackhi_pd(bound, bound)));
            return !(m * (1 + 1e-9) + 1e-9 * total < ComputeType(256) * total / static_cast<ComputeType>(blocks));
        }
#endif

        //! Adds a block sum (error-free if `exact`) and writes the row entries.
        template<bool exact>
        static void step(ComputeType &hi, ComputeType &lo, ComputeType v, ComputeType *row, ComputeType *low, int k)
        {
            if constexpr (exact)
            {
                twoSumAdd(hi, lo, v);
                low[k] = lo;
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
