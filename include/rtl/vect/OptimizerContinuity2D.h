// OptimizerContinuity2D: makes consecutive 2D lines meet near their shared boundary, so that the polyline built from
// their crossings (PostprocessorPolyline2D) follows the data. A pair passes when the lines cross within delta of
// the midpoint of the two boundary points (crossing computed in ComputeType).
//
// A failing pair is repaired by the first of these that works; every new range keeps >= 2 points and, when a sigma
// is set, an RMS residual < sigma (the published version let split ranges exceed sigma and gave up on pairs of
// fewer than 6 points; docs/reference.md, "Vectorization defects fixed here", defects 3 and 4):
//   1. move the boundary by up to 3 points, if both pieces then pass the pair test;
//   2. merge the pair into one range (the vertex disappears), if it fits and its new neighbour pairs pass;
//   3. split the combined range into three equal parts (the published repair), if all three fit and pass;
//   4. re-partition a window of neighbouring ranges: a small dynamic programme over candidate breakpoints near
//      the window's boundaries finds the fewest ranges that fit sigma and whose every pair (including the two
//      pairs with the ranges outside the window) passes (e.g. a 2-point "bridge" range across a step);
//   5. the exact search over the whole chain (PartitionSearch2D, any length): it finds a valid partition if one
//      exists, so if it finds none, operator() returns false and failure() says where.
//      Only when the ranges do not span the whole sum array (direct use on a part of it) does it instead bridge
//      the two boundary points without checking and let the loop re-check.
// The repaired pairs are re-checked; a work budget proportional to the input bounds the total effort (when it
// runs out, the exact search decides).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <utility>
#include <vector>

#include "rtl/core/Trace.h"
#include "rtl/core/VectorND.h"
#include "rtl/vect/FtlsTrace.h"
#include "rtl/vect/PartitionSearch2D.h"

namespace rtl
{
    //! Observer (last, default NoTrace): receives FtlsCorner, FtlsRepair and FtlsRepairRange events (FtlsTrace.h).
    template<class SumArray, class Approximation, class Observer = NoTrace>
    class OptimizerContinuity2D
    {
    public:
        typedef typename Approximation::ElementType ElementType;
        typedef typename Approximation::ComputeType ComputeType;
        typedef typename Approximation::VectorType VectorType;
        typedef typename Approximation::ConstrainedType LineSegmentType;
        typedef std::pair<size_t, size_t> IndexType;
        typedef VectorND<2, ComputeType> ComputeVectorType;

        OptimizerContinuity2D() = default;
        ~OptimizerContinuity2D() = default;

        void setDelta(ElementType delta)
        {
            delta2 = static_cast<ComputeType>(delta) * static_cast<ComputeType>(delta);
            search.setDelta(delta);
        }
        //! RMS bound that repaired ranges must respect (default: none, as in the published version).
        void setSigma(ElementType sigma) { sigma2 = static_cast<ComputeType>(sigma) * static_cast<ComputeType>(sigma); }

        //! Observer of the following calls (nullptr: none); it must outlive them. `branch` goes into the events.
        void setObserver(Observer *observer, int branch = 0) { observer_ = observer; branch_ = branch; }

        //! Keeps the exact search's answer for the following calls on the same chain, sigma and delta (AFTLS's
        //! two branches: the search does not depend on the partition it replaces); false forgets it.
        void keepExactSearch(bool keep)
        {
            keep_ = keep;
            kept_state = 0;
        }
        //! Work of the exact search since construction (PartitionSearch2D::work()).
        const typename PartitionSearch2D<SumArray, Approximation>::Work &searchWork() const { return search.work(); }

        //! After a false return: the corner that no partition can meet (see PartitionSearch2D::failure()).
        const CornerReport &failure() const { return search.failure(); }

        //! Repairs `lines`/`indices` in place. False if a pair could not be repaired (inputs then unspecified but
        //! consistent), if the inputs are inconsistent, or if delta is not positive.
        bool operator()(const std::vector<VectorType> &pts, const SumArray &sum_array, std::vector<Approximation> &lines,
                        std::vector<IndexType> &indices)
        {
            if (lines.size() != indices.size() || indices.empty() || !(delta2 > ComputeType(0)))
                return false;
            if (sum_array.size() == 0 || indices.back().second > sum_array.size() - 1 || indices.back().second > pts.size())
                return false;
            size_t budget = 16 * indices.size() + 4 * pts.size() + 64;
            size_t i = 0;
            while (i + 1 < indices.size())
            {
                const bool ok = pairOk(pts, lines, indices, i);
                if constexpr (Observer::enabled)
                    if (observer_)
                    {
                        const ComputeType d2 = detail::crossingDistanceSquared(pts, lines[i], lines[i + 1], indices[i].second);
                        (*observer_)(FtlsCorner{branch_, i, indices[i].second, static_cast<double>(std::sqrt(d2)), static_cast<double>(std::sqrt(delta2)), ok});
                    }
                if (ok) { ++i; continue; }
                if (budget == 0)
                    return exactSearch(pts, sum_array, lines, indices);
                --budget;
                if (!repair(pts, sum_array, lines, indices, i))
                    return false;
                i = i > 0 ? i - 1 : 0;
            }
            return true;
        }

    private:
        ComputeType delta2{9};
        ComputeType sigma2{std::numeric_limits<ComputeType>::infinity()};
        PartitionSearch2D<SumArray, Approximation> search;
        bool keep_{false};
        int kept_state{0};   // 0 none kept, 1 a partition, 2 none exists
        std::vector<Approximation> kept_lines;
        std::vector<IndexType> kept_indices;
        Observer *observer_{nullptr};
        int branch_{0};
        mutable int method_{0};   // the repair being tried, for the events
        // repartition's scratch, kept between calls (its tables are p^2 for up to ~130 candidates).
        mutable std::vector<size_t> rp_cand, rp_best, rp_from;
        mutable std::vector<char> rp_state;
        mutable std::vector<Approximation> rp_fit;
        mutable std::vector<std::pair<size_t, size_t>> rp_order;

        void reportRepair(size_t first, size_t end, const std::vector<IndexType> &ranges) const
        {
            if constexpr (Observer::enabled)
                if (observer_)
                {
                    (*observer_)(FtlsRepair{branch_, method_, first, end, ranges.size()});
                    for (const auto &r : ranges)
                        (*observer_)(FtlsRepairRange{r.first, r.second});
                }
        }

        //! Replaces the whole partition by the exact search's; false iff no valid partition exists. Its answer
        //! depends only on the chain, sigma and delta, so a kept one (keepExactSearch) is reused.
        bool exactSearch(const std::vector<VectorType> &pts, const SumArray &a, std::vector<Approximation> &lines, std::vector<IndexType> &indices)
        {
            const size_t end = indices.back().second;
            if (kept_state == 0 || !keep_)
            {
                search.setSigmaSquared(sigma2);
                search.setAllowBreaks(false);
                const bool found = search(pts, a, lines, indices);
                if (keep_)
                {
                    kept_state = found ? 1 : 2;
                    kept_lines = lines;
                    kept_indices = indices;
                }
                if (!found)
                    return false;
            }
            else
            {
                if (kept_state == 2)
                    return false;
                lines = kept_lines;
                indices = kept_indices;
            }
            method_ = FtlsExactSearch;
            reportRepair(0, end, indices);
            return true;
        }

        bool fits(const SumArray &a, size_t b, size_t e) const
        {
            return e - b >= 2 && (e - b == 2 || Approximation::errorBelow(a.sums(b, e), sigma2) || sigma2 == std::numeric_limits<ComputeType>::infinity());
        }

        bool crossingOk(const std::vector<VectorType> &pts, const Approximation &l1, const Approximation &l2, size_t boundary) const
        {
            return detail::crossingDistanceSquared(pts, l1, l2, boundary) <= delta2;
        }

        bool pairOk(const std::vector<VectorType> &pts, const std::vector<Approximation> &l, const std::vector<IndexType> &idx, size_t i) const
        {
            return crossingOk(pts, l[i], l[i + 1], idx[i].second);
        }

        //! Replaces ranges [i, i + cnt) by `ranges` (a partition of the same span) if `check` accepts the result.
        bool tryReplace(const std::vector<VectorType> &pts, const SumArray &a, std::vector<Approximation> &lines,
                        std::vector<IndexType> &indices, size_t i, size_t cnt, const std::vector<IndexType> &ranges, bool check) const
        {
            for (const auto &r : ranges)
                if (!fits(a, r.first, r.second))
                    return false;
            std::vector<Approximation> fitted;
            fitted.reserve(ranges.size());
            for (const auto &r : ranges)
                fitted.emplace_back(a.sums(r.first, r.second));
            if (check)
            {
                for (size_t k = 0; k + 1 < ranges.size(); ++k)
                    if (!crossingOk(pts, fitted[k], fitted[k + 1], ranges[k].second))
                        return false;
                if (i > 0 && !crossingOk(pts, lines[i - 1], fitted.front(), ranges.front().first))
                    return false;
                if (i + cnt < lines.size() && !crossingOk(pts, fitted.back(), lines[i + cnt], ranges.back().second))
                    return false;
            }
            reportRepair(ranges.front().first, ranges.back().second, ranges);
            const auto off = static_cast<std::ptrdiff_t>(i);
            lines.erase(lines.begin() + off, lines.begin() + off + static_cast<std::ptrdiff_t>(cnt));
            indices.erase(indices.begin() + off, indices.begin() + off + static_cast<std::ptrdiff_t>(cnt));
            lines.insert(lines.begin() + off, fitted.begin(), fitted.end());
            indices.insert(indices.begin() + off, ranges.begin(), ranges.end());
            return true;
        }

        //! Replaces ranges [r0, r1) by the fewest ranges with breakpoints within +-k of their current internal
        //! boundaries such that every range fits and every pair passes (including with ranges r0 - 1 and r1).
        //! The programme, over candidate breakpoints cand[0..p): best(x, y) = fewest ranges covering
        //! [start, cand[y]) whose last range is [cand[x], cand[y]); from(x, y) = the predecessor w of the smallest
        //! best(w, x) whose pair with [cand[x], cand[y]) passes, the smallest such w on ties. That is what a scan of
        //! w = 0, 1, ... keeping the first strict improvement gives; it is found here with fewer tests, the same
        //! decisions (so the same ranges, bit for bit):
        //! - the predecessors of x are tried in the order (best(w, x), w) and the first that passes is taken;
        //! - a row x that no range reaches (every best(w, x) unset) is skipped: none of its cells can be set, so
        //!   its ranges are never fitted (a range is fitted only when some predecessor may use it).
        //! Why: the scan of all w (p^3 / 6 steps) and the fits of all p^2 / 2 ranges dominated FTLS's time on inputs
        //! that never reach the exact search (measured in docs/vect.md).
        bool repartition(const std::vector<VectorType> &pts, const SumArray &a, std::vector<Approximation> &lines,
                         std::vector<IndexType> &indices, size_t r0, size_t r1, size_t k) const
        {
            const size_t start = indices[r0].first, end = indices[r1 - 1].second;
            std::vector<size_t> &cand = rp_cand;
            cand.assign(1, start);
            for (size_t r = r0; r + 1 < r1; ++r)
            {
                const size_t m = indices[r].second;
                for (size_t c = (m > start + k ? m - k : start + 1); c <= std::min(end - 1, m + k); ++c)
                    cand.push_back(c);
            }
            cand.push_back(end);
            std::sort(cand.begin(), cand.end());
            cand.erase(std::unique(cand.begin(), cand.end()), cand.end());
            const size_t p = cand.size();
            const size_t none = std::numeric_limits<size_t>::max();
            std::vector<size_t> &best = rp_best, &from = rp_from;
            best.assign(p * p, none);
            from.assign(p * p, none);
            // state[x * p + y]: 0 not tested, 1 fits (fit[x * p + y] set), 2 does not fit.
            std::vector<char> &state = rp_state;
            state.assign(p * p, 0);
            if (rp_fit.size() < p * p)
                rp_fit.resize(p * p);
            const auto fitted = [&](size_t x, size_t y) -> bool {
                char &st = state[x * p + y];
                if (st == 0)
                {
                    const auto ps = a.sums(cand[x], cand[y]);   // once for the test and the fit (fits()' test)
                    const size_t len = cand[y] - cand[x];
                    st = len >= 2 && (len == 2 || Approximation::errorBelow(ps, sigma2) || sigma2 == std::numeric_limits<ComputeType>::infinity()) ? 1 : 2;
                    if (st == 1)
                        rp_fit[x * p + y] = Approximation(ps);
                }
                return st == 1;
            };
            for (size_t y = 1; y < p; ++y)
                if (fitted(0, y) && (r0 == 0 || crossingOk(pts, lines[r0 - 1], rp_fit[y], start)))
                    best[y] = 1;
            std::vector<std::pair<size_t, size_t>> &order = rp_order;   // (best(w, x), w) of the set cells of column x
            for (size_t x = 1; x < p; ++x)
            {
                order.clear();
                for (size_t w = 0; w < x; ++w)
                    if (best[w * p + x] != none)
                        order.emplace_back(best[w * p + x], w);
                if (order.empty())
                    continue;
                std::sort(order.begin(), order.end());
                for (size_t y = x + 1; y < p; ++y)
                {
                    if (!fitted(x, y))
                        continue;
                    for (const auto &c : order)
                        if (crossingOk(pts, rp_fit[c.second * p + x], rp_fit[x * p + y], cand[x]))
                        {
                            best[x * p + y] = c.first + 1;
                            from[x * p + y] = c.second;
                            break;
                        }
                }
            }
            size_t last = none, count = none;
            for (size_t x = 0; x + 1 < p; ++x)
            {
                const size_t c = best[x * p + p - 1];
                if (c != none && c < count && (r1 == indices.size() || crossingOk(pts, rp_fit[x * p + p - 1], lines[r1], end)))
                {
                    count = c;
                    last = x;
                }
            }
            if (last == none)
                return false;
            std::vector<IndexType> ranges;
            for (size_t x = last, y = p - 1; ; )
            {
                ranges.emplace_back(cand[x], cand[y]);
                if (x == 0)
                    break;
                const size_t w = from[x * p + y];
                y = x;
                x = w;
            }
            std::reverse(ranges.begin(), ranges.end());
            return tryReplace(pts, a, lines, indices, r0, r1 - r0, ranges, false);
        }

        bool repair(const std::vector<VectorType> &pts, const SumArray &a, std::vector<Approximation> &lines,
                    std::vector<IndexType> &indices, size_t i)
        {
            const size_t b = indices[i].first, m = indices[i].second, e = indices[i + 1].second;
            // 1. Move the boundary.
            method_ = FtlsMoveBoundary;
            for (size_t s = 1; s <= 3; ++s)
            {
                if (m >= b + 2 + s && tryReplace(pts, a, lines, indices, i, 2, {{b, m - s}, {m - s, e}}, true))
                    return true;
                if (m + s + 2 <= e && tryReplace(pts, a, lines, indices, i, 2, {{b, m + s}, {m + s, e}}, true))
                    return true;
            }
            // 2. Merge.
            method_ = FtlsMerge;
            if (tryReplace(pts, a, lines, indices, i, 2, {{b, e}}, true))
                return true;
            // 3. Three equal parts.
            method_ = FtlsThirds;
            const size_t len = e - b;
            if (len >= 6 && tryReplace(pts, a, lines, indices, i, 2, {{b, b + len / 3}, {b + len / 3, b + 2 * len / 3}, {b + 2 * len / 3, e}}, true))
                return true;
            // 4. Re-partition a window of ranges around the pair, wider on the second attempt.
            method_ = FtlsWindow;
            if (repartition(pts, a, lines, indices, i > 0 ? i - 1 : 0, std::min(indices.size(), i + 3), 6))
                return true;
            if (repartition(pts, a, lines, indices, i > 1 ? i - 2 : 0, std::min(indices.size(), i + 4), 12))
                return true;
            // 5. The exact search over the whole chain: if it finds none, no valid result exists.
            if (indices.front().first == 0 && indices.back().second + 1 == a.size())
                return exactSearch(pts, a, lines, indices);
            method_ = FtlsBridge;
            // Direct use on part of a sum array: bridge of the two boundary points (re-checked by the caller's loop).
            if (m >= b + 3 && m + 3 <= e && tryReplace(pts, a, lines, indices, i, 2, {{b, m - 1}, {m - 1, m + 1}, {m + 1, e}}, false))
                return true;
            if (m >= b + 3 && tryReplace(pts, a, lines, indices, i, 2, {{b, m - 1}, {m - 1, e}}, false))
                return true;
            if (m + 3 <= e && tryReplace(pts, a, lines, indices, i, 2, {{b, m + 1}, {m + 1, e}}, false))
                return true;
            return false;
        }
    };
}
