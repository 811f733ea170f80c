// PartitionSearch2D: the exact feasibility search behind FTLS/AFTLS 2D (issue 11 items 5, 6; issue 12 item 1).
//
// A valid result partitions the chain [0, N) into ranges of >= 2 points, each fitting sigma exactly as in
// ExtractorChainFast (2 points always fit, otherwise mean squared residual < sigma^2), with every pair of
// consecutive lines crossing within delta of the midpoint of the two boundary points (OptimizerContinuity2D's
// criterion, vect_detail::crossingDistanceSquared). Prefix sums make each range's fit O(1), so a dynamic programme
// over the breakpoints decides exactly whether such a partition exists, for chains of any length:
//   state = a fitting range [x, y) that ends a valid partition of [0, y); its cost = (breaks, ranges, total
//   squared residual), compared lexicographically; a state extends by any fitting range [y, z) whose line meets
//   its own within delta. Incoming states of a boundary are tried cheapest first, so the first one that meets the
//   corner is the best and the search stops there.
// Ranges are bounded by sigma: the total squared residual of [x, y) never decreases as y grows, so once it
// exceeds (N - x) sigma^2 no longer range from x can fit. The cost is O(F) fits for the F fitting ranges plus
// the corner checks (cheapest-first, usually one per range; quadratic per boundary only when corners fail).
//
// With breaks allowed (split mode), a range may also start a new polyline where no incoming line meets it; the
// cost counts such breaks first, so the result has the fewest breaks (none iff a strict result exists), then the
// fewest ranges, then the least squared error. Without breaks, a false return proves that no valid partition
// exists, and failure() says where: the furthest corner the search reached (the largest boundary b, 2 <= b <= N-2,
// ending a valid partition of [0, b)) with the smallest crossing distance over all line pairs tried there.
//
// cover() is split mode's last resort, for chains that no partition fits at all (e.g. 3 points forming a corner:
// a range needs 2 points, so [0, 2) [2, 3) is impossible). Consecutive ranges may then share their boundary point
// (range [s, e) followed by [e - 1, e')), so 2-point ranges always exist and a cover always exists for N >= 2. The
// same kind of dynamic programme finds the fewest ranges, then the least total squared residual (each range fits
// sigma, >= 2 points); state = the chain prefix [0, y) covered by ranges whose last one ends at y, extended by a
// fitting range starting at y or at y - 1. Corners are judged afterwards as everywhere (cornerDistanceSquared; at a
// shared point the reference is that point): within delta the polyline continues, else it breaks there.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <utility>
#include <vector>

#include "rtl/core/VectorND.h"

namespace rtl
{
    //! A corner of a 2D polyline that cannot be met within delta. boundary: chain index of the first point of the
    //! range after the corner; crossingDistance: distance of the two lines' crossing from the midpoint of points
    //! boundary - 1 and boundary (the continuity criterion's reference; +infinity for parallel lines, or when the
    //! failure is not at a corner, e.g. 3 points that fit no line: then boundary is 0); delta: the bound it exceeds.
    //! A break at a point shared by two ranges (split mode's cover, PartitionSearch2D::cover): boundary is the
    //! shared point, the first of the range after the corner, and the distance is measured from that point.
    struct CornerReport
    {
        size_t boundary{0};
        double crossingDistance{0};
        double delta{0};
    };

    namespace vect_detail
    {
        //! Squared distance of the crossing of l1 and l2 from the midpoint of pts[boundary - 1] and pts[boundary];
        //! +infinity if the lines do not cross (parallel or non-finite crossing).
        template<class Approximation, class Points>
        typename Approximation::ComputeType crossingDistanceSquared(const Points &pts, const Approximation &l1, const Approximation &l2, size_t boundary)
        {
            typedef typename Approximation::ComputeType C;
            VectorND<2, C> x;
            if (!Approximation::getCrossingCompute(l1, l2, x))
                return std::numeric_limits<C>::infinity();
            const VectorND<2, C> m = (pts[boundary - 1].template cast<C>() + pts[boundary].template cast<C>()) * C(0.5);
            return (x - m).lengthSquared();
        }

        //! The corner criterion between a range ending at `prev_end` and the next one starting at `next_first`:
        //! the distance of the crossing from the midpoint of pts[prev_end - 1] and pts[next_first], i.e. the two
        //! boundary points (next_first == prev_end) or the shared point (next_first == prev_end - 1, cover()).
        template<class Approximation, class Points>
        typename Approximation::ComputeType cornerDistanceSquared(const Points &pts, const Approximation &l1, const Approximation &l2, size_t prev_end,
                                                                  size_t next_first)
        {
            typedef typename Approximation::ComputeType C;
            VectorND<2, C> x;
            if (!Approximation::getCrossingCompute(l1, l2, x))
                return std::numeric_limits<C>::infinity();
            const VectorND<2, C> m = (pts[prev_end - 1].template cast<C>() + pts[next_first].template cast<C>()) * C(0.5);
            return (x - m).lengthSquared();
        }
    }

    template<class SumArray, class Approximation>
    class PartitionSearch2D
    {
    public:
        typedef typename Approximation::ElementType ElementType;
        typedef typename Approximation::ComputeType ComputeType;
        typedef typename Approximation::VectorType VectorType;
        typedef std::pair<size_t, size_t> IndexType;

        void setSigma(ElementType sigma) { sigma2 = static_cast<ComputeType>(sigma) * static_cast<ComputeType>(sigma); }
        //! The same bound squared (+infinity: every range fits).
        void setSigmaSquared(ComputeType sigma_squared) { sigma2 = sigma_squared; }
        void setDelta(ElementType delta) { delta_ = static_cast<ComputeType>(delta); delta2 = delta_ * delta_; }
        //! Split mode: a range may start a new polyline where no line meets it within delta (default false).
        void setAllowBreaks(bool allow) { allow_breaks = allow; }

        //! Fills `lines`/`indices` with the best valid partition of the chain of `sum_array` (points `pts`). False if
        //! none exists (without breaks; with breaks, when no partition into fitting ranges exists at all, e.g. 3, 5
        //! or 7 points whose short ranges do not fit: then cover() helps) or for fewer than 2 points.
        bool operator()(const std::vector<VectorType> &pts, const SumArray &a, std::vector<Approximation> &lines, std::vector<IndexType> &indices)
        {
            lines.clear();
            indices.clear();
            starts.clear();
            break_reports.clear();
            failure_ = CornerReport{0, std::numeric_limits<double>::infinity(), static_cast<double>(delta_)};
            const size_t n = a.size() > 0 ? a.size() - 1 : 0;
            if (n < 2 || n > pts.size() || n >= none)
                return false;
            states.clear();
            incoming.resize(n + 1);
            for (auto &v : incoming)
                v.clear();
            for (size_t x = 0; x + 2 <= n; ++x)
                if (x == 0 || !incoming[x].empty())
                    extend(pts, a, x, n);
            if (incoming[n].empty())
            {
                diagnose(pts, a, n);
                return false;
            }
            uint32_t best = incoming[n].front();
            for (uint32_t s : incoming[n])
                if (less(states[s], states[best]))
                    best = s;
            size_t end = n;
            for (uint32_t s = best; s != none; s = states[s].back)
            {
                indices.emplace_back(states[s].x, end);
                end = states[s].x;
            }
            std::reverse(indices.begin(), indices.end());
            for (const auto &r : indices)
                lines.emplace_back(a.sums(r.first, r.second));
            findBreaks(pts, lines, indices);
            return true;
        }

        //! Split mode's last resort (see the file comment): the cover of [0, N) by the fewest fitting ranges of
        //! >= 2 points, then the least total squared residual, where consecutive ranges are in order and either
        //! adjoin or share one point. Breaks and polylineStarts() as after operator(). False only for N < 2.
        bool cover(const std::vector<VectorType> &pts, const SumArray &a, std::vector<Approximation> &lines, std::vector<IndexType> &indices)
        {
            lines.clear();
            indices.clear();
            starts.clear();
            break_reports.clear();
            failure_ = CornerReport{0, std::numeric_limits<double>::infinity(), static_cast<double>(delta_)};
            const size_t n = a.size() > 0 ? a.size() - 1 : 0;
            if (n < 2 || n > pts.size())
                return false;
            const Cost unreached{std::numeric_limits<size_t>::max(), ComputeType(0)};
            cover_cost.assign(n + 1, unreached);
            cover_from.assign(n + 1, 0);
            cover_prev.assign(n + 1, 0);
            cover_cost[0] = Cost{0, ComputeType(0)};
            // cover_cost[y] is final once every range ending at y (starting before y - 1) has been tried.
            for (size_t s = 0; s + 2 <= n; ++s)
            {
                // A range from s follows a cover ending at s (adjoining) or at s + 1 (sharing point s).
                size_t prev = s;
                if (s > 0 && cheaper(cover_cost[s + 1], cover_cost[prev]))
                    prev = s + 1;
                const Cost base = cover_cost[prev];
                if (base.ranges == unreached.ranges)
                    continue;
                for (size_t e = s + 2; e <= n; ++e)
                {
                    ComputeType total;
                    const bool ok = fits(a, s, e, total);
                    if (!ok && beyondReach(total, s, n))
                        break;
                    const Cost c{base.ranges + 1, base.error + total};
                    if (ok && cheaper(c, cover_cost[e]))
                    {
                        cover_cost[e] = c;
                        cover_from[e] = s;
                        cover_prev[e] = prev;
                    }
                }
            }
            if (cover_cost[n].ranges == unreached.ranges)
                return false;   // not reached for n >= 2: 2-point ranges always fit
            for (size_t e = n; e > 0; e = cover_prev[e])
                indices.emplace_back(cover_from[e], e);
            std::reverse(indices.begin(), indices.end());
            for (const auto &r : indices)
                lines.emplace_back(a.sums(r.first, r.second));
            findBreaks(pts, lines, indices);
            return true;
        }

        //! After a false return without breaks: the furthest corner reached and its smallest crossing distance.
        const CornerReport &failure() const { return failure_; }
        //! After a true return: indices of the ranges that start a polyline (0 first; more only with breaks).
        const std::vector<size_t> &polylineStarts() const { return starts; }
        //! After a true return: one report per break (the boundary, its crossing distance, delta).
        const std::vector<CornerReport> &breaks() const { return break_reports; }

    private:
        static constexpr uint32_t none = std::numeric_limits<uint32_t>::max();
        struct State
        {
            uint32_t x, back, breaks, ranges;
            ComputeType error;
        };
        ComputeType sigma2{ComputeType(0.03) * ComputeType(0.03)}, delta_{3}, delta2{9};
        bool allow_breaks{false};
        std::vector<State> states;
        std::vector<std::vector<uint32_t>> incoming;   // states ending at each boundary
        std::vector<Approximation> in_lines;
        std::vector<size_t> starts;
        std::vector<CornerReport> break_reports;
        CornerReport failure_;

        struct Cost
        {
            size_t ranges;
            ComputeType error;
        };
        std::vector<Cost> cover_cost;
        std::vector<size_t> cover_from, cover_prev;   // start of the last range ending at y; end of the cover before it

        static bool cheaper(const Cost &p, const Cost &q)
        {
            if (p.ranges != q.ranges) return p.ranges < q.ranges;
            return p.error < q.error;
        }

        //! Breaks: where consecutive lines do not meet within delta (the polyline starts a new one there).
        void findBreaks(const std::vector<VectorType> &pts, const std::vector<Approximation> &lines, const std::vector<IndexType> &indices)
        {
            starts.push_back(0);
            for (size_t i = 1; i < lines.size(); ++i)
            {
                const ComputeType d2 = vect_detail::cornerDistanceSquared(pts, lines[i - 1], lines[i], indices[i - 1].second, indices[i].first);
                if (!(d2 <= delta2))
                {
                    starts.push_back(i);
                    break_reports.push_back(CornerReport{indices[i].first, static_cast<double>(std::sqrt(d2)), static_cast<double>(delta_)});
                }
            }
        }

        static bool less(const State &p, const State &q)
        {
            if (p.breaks != q.breaks) return p.breaks < q.breaks;
            if (p.ranges != q.ranges) return p.ranges < q.ranges;
            return p.error < q.error;
        }

        bool fits(const SumArray &a, size_t b, size_t e, ComputeType &total) const
        {
            const auto s = a.sums(b, e);
            total = e - b <= 2 ? ComputeType(0) : Approximation::errorSquaredCompute(s) * static_cast<ComputeType>(e - b);
            return e - b == 2 || Approximation::errorBelow(s, sigma2);
        }

        //! Total squared residual of [x, y) beyond what any fitting range from x could have (monotone in y).
        bool beyondReach(ComputeType total, size_t x, size_t n) const
        {
            return total > ComputeType(1.01) * sigma2 * static_cast<ComputeType>(n - x) + ComputeType(1e-300);
        }

        //! Extends every state ending at x (or the chain start, x = 0) by every fitting range [x, y).
        void extend(const std::vector<VectorType> &pts, const SumArray &a, size_t x, size_t n)
        {
            auto &in = incoming[x];
            std::sort(in.begin(), in.end(), [&](uint32_t p, uint32_t q) { return less(states[p], states[q]); });
            in_lines.clear();
            for (uint32_t s : in)
                in_lines.emplace_back(a.sums(states[s].x, x));
            for (size_t y = x + 2; y <= n; ++y)
            {
                ComputeType total;
                const bool ok = fits(a, x, y, total);
                if (!ok && beyondReach(total, x, n))
                    break;
                if (!ok || y + 1 == n)   // a range ending one point before the end leaves a 1-point tail
                    continue;
                State st{static_cast<uint32_t>(x), none, 0, 1, total};
                if (x > 0)
                {
                    const Approximation line(a.sums(x, y));
                    const State &cheapest = states[in.front()];
                    const State broken{0, 0, cheapest.breaks + 1, cheapest.ranges, cheapest.error};
                    size_t pick = in.size();
                    for (size_t k = 0; k < in.size(); ++k)
                    {
                        if (allow_breaks && !less(states[in[k]], broken))
                            break;
                        if (vect_detail::crossingDistanceSquared(pts, in_lines[k], line, x) <= delta2)
                        {
                            pick = k;
                            break;
                        }
                    }
                    if (pick == in.size() && !allow_breaks)
                        continue;
                    const State &prev = states[in[pick == in.size() ? 0 : pick]];
                    st.back = in[pick == in.size() ? 0 : pick];
                    st.breaks = prev.breaks + (pick == in.size() ? 1u : 0u);
                    st.ranges = prev.ranges + 1;
                    st.error = prev.error + total;
                }
                incoming[y].push_back(static_cast<uint32_t>(states.size()));
                states.push_back(st);
            }
        }

        //! The furthest corner reached, and the closest any line pair came to meeting there.
        void diagnose(const std::vector<VectorType> &pts, const SumArray &a, size_t n)
        {
            size_t b = n >= 2 ? n - 2 : 0;
            while (b >= 2 && incoming[b].empty())
                --b;
            if (b < 2)
                return;   // no corner reached: the failure is sigma (e.g. 3 points that fit no line)
            ComputeType best = std::numeric_limits<ComputeType>::infinity();
            for (uint32_t s : incoming[b])
            {
                const Approximation prev(a.sums(states[s].x, b));
                for (size_t y = b + 2; y <= n; ++y)
                {
                    ComputeType total;
                    const bool ok = fits(a, b, y, total);
                    if (!ok && beyondReach(total, b, n))
                        break;
                    if (ok && y + 1 != n)
                        best = std::min(best, vect_detail::crossingDistanceSquared(pts, prev, Approximation(a.sums(b, y)), b));
                }
            }
            failure_.boundary = b;
            failure_.crossingDistance = static_cast<double>(std::sqrt(best));
        }
    };
}
