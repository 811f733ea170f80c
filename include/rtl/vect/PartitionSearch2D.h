// PartitionSearch2D: the exact feasibility search behind FTLS/AFTLS 2D.
//
// What: the best partition of the chain [0, N) into ranges of >= 2 points, each fitting sigma exactly as in
// ExtractorChainFast (2 points always fit, otherwise mean squared residual < sigma^2), with every pair of
// consecutive lines crossing within delta of the midpoint of the two boundary points (OptimizerContinuity2D's
// criterion, detail::crossingDistanceSquared). Best = fewest breaks (split mode only), then fewest ranges, then
// least total squared residual. Without breaks a false return proves that no valid partition exists, and failure()
// says where: the furthest corner reached (the largest boundary b, 2 <= b <= N-2, ending a valid partition of
// [0, b)) with the smallest crossing distance over all line pairs tried there. With breaks allowed (split mode) a
// range may also start a new polyline where no incoming line meets it, so the result has the fewest breaks (none
// iff a strict result exists).
//
// Runs of identical points: no range ends (so none starts) deep inside a run of identical points, i.e. at a boundary
// more than run_margin = 8 points from both ends of the run. The partitions searched are those whose boundaries lie
// outside runs or near their ends; "no valid partition" above means none of those. Why: every range within a run of
// L points fits (residual exactly 0), so the L^2 / 2 ranges, and the corner tests among their lines (lines that only
// the rounding of their sums gives a direction), made the search quadratic or worse in L wherever it had to visit
// them all (proving infeasibility, split mode); a boundary deep inside a run is rarely the only way through it (it
// could be where the copies of the point are needed to bring the mean residual of the ranges on both sides below
// sigma^2). Chains whose runs have at most 2 run_margin + 1 points are searched in full.
//
// How: a dynamic programme over the breakpoints, each range's fit O(1) from prefix sums. A state is a fitting range
// [x, y) that ends a valid partition of [0, y); a state extends by any fitting range [y, z) whose line meets its own
// within delta. Incoming states of a boundary are tried cheapest first (ties by range start, a total order), so the
// first one that meets is the pick. Corners with many lines use chords: two lines cross inside the disc of radius
// delta about the boundary midpoint iff their chords' ends alternate around the circle, so the cheapest meeting line
// is a 2D range-minimum query; every comparison is widened by the angles' rounding bound and each candidate is
// confirmed by the exact test. Strict mode first runs the unbounded round up to N + 1024 states or 16 N + 4096
// fits, then rounds bounded by a range budget (a state is kept only if its ranges plus a lower bound on the ranges
// of the rest fit the budget: first a fits-only bound, then a corner-aware one from a backward pass), then, only if
// they fail, the first round continued without a cap, which alone proves infeasibility.
//
// Invariants (why the result does not depend on the rounds): every lower bound used never exceeds the true count,
// and a state's cheapest predecessor has at most one range less, so a round whose budget is >= the optimum's range
// count keeps the optimum's path and picks at each corner what the unbounded search picks. A range of identical
// points is decided from the points (residual exactly 0: it fits iff it has 2 points or sigma^2 > 0), not from its
// prefix sums, whose rounding far from the origin is noise above sigma^2. A chain that one range fits is answered by
// that range without the search (the unique partition with no break and one range). Decisions within rounding of
// the disc's edge may differ from testing every pair in cost order only where ComputeType does not resolve the
// crossing itself (near-parallel lines whose computed crossing lands in the disc).
//
// Complexity: O(N) to mark runs and for a chain that one range fits; otherwise O(F) fits and O(F log F) corner work
// for the F fitting ranges (those not ending deep inside a run), with F up to N * L for ranges of up to L points
// that fit sigma (work() counts it). A run of identical points adds O(run_margin^2) ranges within it and O(1) fits
// to every scan that crosses it, whatever its length. F is quadratic on long straight pieces whose corners no line
// pair meets; where the bounded rounds then find the optimum (a tight bound), the first round's fit cap keeps the
// search linear. Memory O(N + F).
//
// cover() is split mode's last resort, for chains that no partition fits at all (e.g. 3 points forming a corner).
// Consecutive ranges may then share their boundary point (range [s, e) followed by [e - 1, e')), so 2-point ranges
// always exist and a cover always exists for N >= 2: the fewest ranges, then the least total squared residual, each
// range fitting sigma with >= 2 points. Corners are judged afterwards (cornerDistanceSquared; at a shared point the
// reference is that point): within delta the polyline continues, else it breaks there.
//
// Where: this file holds the search (the rounds, the dynamic programme, runs, cover()); partition_search/RangeBounds.h
// the lower bounds of the bounded rounds (fits-only and the backward pass); partition_search/ChordSweep.h the corner
// tests and the chord query (with CornerChord.h and MinRankTree.h); CornerDistance.h the corner criterion.
//
// Measurements, the schedule of rounds and what was tried and not kept: docs/vect-partition-search.md.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <utility>
#include <vector>

#include "rtl/core/VectorND.h"
#include "rtl/vect/partition_search/CornerChord.h"
#include "rtl/vect/partition_search/CornerDistance.h"
#include "rtl/vect/partition_search/MinRankTree.h"

namespace rtl
{
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
            markRuns(pts, n);
            // A chain that one range fits: that range is the optimum (no break, one range: no other partition
            // has as few), found without the search, which would visit every fitting range first.
            ComputeType whole_total;
            if (fits(a, 0, n, whole_total))
            {
                indices.emplace_back(0, n);
                lines.emplace_back(a.sums(0, n));
                starts.push_back(0);
                return true;
            }
            // Most searches are small: first an unbounded round that gives up beyond a state cap; then, strict
            // mode only, rounds bounded by a range budget (see the file comment), then the unbounded one, which
            // alone proves that no partition exists (and finds the failure corner).
            const bool bounded = !allow_breaks && prune_;
            // The first round also gives up past a number of fits: where most fitting ranges meet no incoming
            // line (e.g. inside a long run of identical points) it enumerates them without adding states.
            fit_limit = bounded ? work_.fits + fit_cap * n + 4096 : unbounded;
            const bool first_done = searchRound(pts, a, n, unbounded, bounded ? state_cap * n + 1024 : unbounded);
            fit_limit = unbounded;
            if (!first_done)
            {
                // Kept aside: the unbounded round, should it be needed, goes on from where this one stopped.
                swapFirstRound();
                first_next = stopped_at;
                incoming.resize(n + 1);
                for (auto &v : incoming)
                    v.clear();
                ++work_.bounded;
                lowerBounds(a, n);
                for (size_t budget = remaining[0]; budget <= remaining[0] + 1 && incoming[n].empty(); ++budget)
                    searchRound(pts, a, n, budget, unbounded);
                if (incoming[n].empty())
                {
                    // The fits-only bound was short (corners force extra ranges): a corner-aware count to the end
                    // from every fitting range (backward pass), then rounds on it, each given up past the state cap.
                    const size_t r = backward(pts, a, n);
                    exact_rest = true;
                    for (size_t budget = r; budget != unbounded && budget < r + rest_budgets && incoming[n].empty(); ++budget)
                        if (!searchRound(pts, a, n, budget, rest_cap * n + 1024))
                            break;
                    exact_rest = false;
                    if (incoming[n].empty())
                    {
                        // Proves infeasibility (and finds the corner): the first round, continued without a cap.
                        swapFirstRound();
                        continueRound(pts, a, n, unbounded, unbounded, first_next);
                    }
                }
            }
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
            markRuns(pts, n);
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

        //! How corners are searched: the `first` cheapest incoming lines are tried one by one, then all of them
        //! while that costs at most `share` tests per line at the boundary, else the chord query (defaults 16, 32;
        //! the result is the same, first = 1 and share = 0 make every boundary use the chord query).
        void setCornerScan(size_t first, size_t share) { scan_first = std::max<size_t>(first, 1); scan_share = share; }

        //! Strict mode's bounded rounds (default on; the result is the same, off searches every state at once).
        void setBoundedRounds(bool on) { prune_ = on; }

        //! Work done since construction: range fits evaluated, and corner tests plus chord-tree queries (a bound
        //! on either per call is what the fuzz harness checks, so that a slow case cannot pass unseen).
        struct Work
        {
            size_t fits{0}, corners{0}, states{0};   // states: those pushed, plus the backward pass's ranges
            size_t bounded{0};   // searches that went on to bounded rounds (beyond the first round's state cap)
        };
        const Work &work() const { return work_; }

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
        struct Key
        {
            uint32_t breaks, ranges, x;
            ComputeType error;
            uint32_t state;
        };
        std::vector<Key> keys;   // the incoming states of a boundary, sorted
        std::vector<std::vector<uint32_t>> incoming;   // states ending at each boundary
        std::vector<Approximation> in_lines, out_lines, state_lines;   // state_lines[s]: the line of state s's range
        // The first (unbounded, capped) round's states while the bounded rounds run, and where it stopped.
        std::vector<State> first_states;
        std::vector<Approximation> first_lines;
        std::vector<std::vector<uint32_t>> first_incoming;
        size_t first_next{0}, stopped_at{0};
        struct Out
        {
            size_t y;
            ComputeType total;
            size_t rest;   // with a budget: ranges this range and the rest of the chain need at least
        };
        std::vector<Out> outs;
        std::vector<size_t> picks, limits, open_, leaf_of, removed;
        detail::MinRankTree tree;   // ranks by val of the items in the sweep; min-query over val ranges
        static constexpr size_t none_rank = std::numeric_limits<size_t>::max();
        std::vector<ComputeType> vals;
        Work work_;
        size_t scan_first{16}, scan_share{32};
        typedef detail::CornerChord<ComputeType> Chord;
        struct Item;
        std::vector<Chord> in_chords, out_chords;
        std::vector<Item> items, queries, by_key;
        std::vector<size_t> starts;
        std::vector<CornerReport> break_reports;
        static constexpr size_t unbounded = std::numeric_limits<size_t>::max();
        static constexpr size_t block = 8;   // range starts per end bound (lowerBounds)
        static constexpr size_t state_cap = 1;   // states per point (+ 1024) of the first, unbounded round
        static constexpr size_t fit_cap = 16;   // fits per point (+ 4096) of the first round
        size_t fit_limit{unbounded};   // work_.fits beyond which the current round stops (the first round only)
        static constexpr size_t rest_cap = 4;   // states per point (+ 1024) of a round on the backward pass's bound
        // Rounds on the backward pass's bound: r and r + 1. On the corpus (direct strict searches of all 300 inputs)
        // the optimum was found at r 154 times, at r + 1 7 times, at r + 2 twice (seeds 169, 288), while a third
        // round cost every input that gets past it the most: higher budgets evaluate more to_end[] (seed 213, infeasible:
        // 0.4M, 2.4M, 13.4M instructions for r, r + 1, r + 2, each reaching the same furthest corner).
        static constexpr size_t rest_budgets = 2;
        bool prune_{true};
        VectorND<2, ComputeType> corner_mid;   // midpoint of the boundary points of the current choosePredecessors call
        bool exact_rest{false};   // the round's budget test uses to_end[] (backward pass) instead of remaining[]
        bool reversed_{false};   // choosePredecessors for the backward pass: candidates start at the corner, queries end there
        // Backward pass: the fitting ranges by start (r_start, r_end; ends ascending in r_off[x] .. r_off[x + 1]),
        // to_end[r]: a lower bound on the ranges of a valid partition of [x, N) that starts with range r (none: no
        // such partition); by_end: the ranges grouped by end.
        // to_end[r] is evaluated on demand (unknown until then, see toEnd); v_min[y], v_more[y]: the least count of
        // the ranges from y and whether another one that is not none exists; cand_lines[cand_off[y] ..
        // + cand_cnt[y]): the lines of the ranges from y with the least count (the candidates at corner y).
        std::vector<size_t> r_off, e_off, by_end;
        std::vector<uint32_t> r_start, r_end, to_end, v_min;
        std::vector<char> v_more;
        std::vector<size_t> cand_off, cand_cnt;
        std::vector<Approximation> cand_lines;
        static constexpr uint32_t unknown = none - 1;
        std::vector<size_t> far, remaining, first_within;
        std::vector<size_t> same_end, next_boundary;   // markRuns
        // Boundaries inside a run of identical points that ranges may end at: within run_margin points of its ends.
        static constexpr size_t run_margin = 8;
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
                const ComputeType d2 = detail::cornerDistanceSquared(pts, lines[i - 1], lines[i], indices[i - 1].second, indices[i].first);
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

        //! Marks the runs of identical points: same_end[i] is the end of the run of points equal to pts[i] from i;
        //! next_boundary[y] is y, or for a boundary deep inside a run [s, t) (s + run_margin < y < t - run_margin)
        //! the first boundary after it that a range may end at, t - run_margin (see the file comment).
        void markRuns(const std::vector<VectorType> &pts, size_t n)
        {
            same_end.resize(n + 1);
            same_end[n] = n;
            for (size_t i = n; i-- > 0;)
                same_end[i] = i + 1 < n && pts[i + 1] == pts[i] ? same_end[i + 1] : i + 1;
            next_boundary.resize(n + 1);
            for (size_t s = 0; s < n;)
            {
                const size_t t = same_end[s];
                for (size_t y = s; y < t; ++y)
                    next_boundary[y] = y > s + run_margin && y + run_margin < t ? t - run_margin : y;
                s = t;
            }
            next_boundary[n] = n;
        }

        //! A boundary that no range ends or starts at: deep inside a run of identical points.
        bool deep(size_t y) const { return next_boundary[y] != y; }

        //! [b, e) is one run of identical points: its residual is exactly 0, whatever rounding its sums carry (far
        //! from the origin they cancel into noise, which made such ranges fit at random: the quadratic cliff).
        bool identical(size_t b, size_t e) const { return e <= same_end[b]; }

        bool fits(const SumArray &a, size_t b, size_t e, ComputeType &total)
        {
            ++work_.fits;
            if (identical(b, e))
            {
                total = ComputeType(0);
                return e - b == 2 || sigma2 > ComputeType(0);
            }
            const auto s = a.sums(b, e);
            total = e - b <= 2 ? ComputeType(0) : Approximation::errorSquaredCompute(s) * static_cast<ComputeType>(e - b);
            return e - b == 2 || Approximation::errorBelow(s, sigma2);
        }

        //! Total squared residual of [x, y) beyond what any fitting range from x could have (monotone in y).
        bool beyondReach(ComputeType total, size_t x, size_t n) const
        {
            return total > ComputeType(1.01) * sigma2 * static_cast<ComputeType>(n - x) + ComputeType(1e-300);
        }

        //! One pass of the dynamic programme over the chain, keeping only states whose range count plus the
        //! lower bound for the rest of the chain is within `budget` (unbounded: every state).
        //! False if it stopped early because there were more than `cap` states.
        bool searchRound(const std::vector<VectorType> &pts, const SumArray &a, size_t n, size_t budget, size_t cap)
        {
            states.clear();
            state_lines.clear();
            incoming.resize(n + 1);
            for (auto &v : incoming)
                v.clear();
            return continueRound(pts, a, n, budget, cap, 0);
        }

        //! Sets the first round's states aside (first_*) or brings them back: the same swap both ways.
        void swapFirstRound()
        {
            std::swap(states, first_states);
            std::swap(state_lines, first_lines);
            std::swap(incoming, first_incoming);
        }

        //! searchRound from boundary x0 on, the states of boundaries before it already extended. When it stops
        //! early, stopped_at is the boundary to go on from (an extension depends only on the states it reads, so
        //! an unbounded round stopped and continued does exactly what one uninterrupted round does).
        bool continueRound(const std::vector<VectorType> &pts, const SumArray &a, size_t n, size_t budget, size_t cap, size_t x0)
        {
            for (size_t x = x0; x + 2 <= n; ++x)
            {
                if (x == 0 || !incoming[x].empty())
                    extend(pts, a, x, n, budget);
                if (states.size() > cap || work_.fits > fit_limit)
                {
                    stopped_at = x + 1;
                    return false;
                }
            }
            return true;
        }

        //! Extends every state ending at x (or the chain start, x = 0) by every fitting range [x, y), keeping the
        //! new states within `budget` (ranges so far + remaining[y] <= budget).
        void extend(const std::vector<VectorType> &pts, const SumArray &a, size_t x, size_t n, size_t budget)
        {
            auto &in = incoming[x];
            // Cost order, ties by the range start (a total order, so that the pick does not depend on which
            // other states a bounded round dropped).
            keys.clear();
            for (uint32_t i : in)
                keys.push_back(Key{states[i].breaks, states[i].ranges, states[i].x, states[i].error, i});
            std::sort(keys.begin(), keys.end(), [](const Key &p, const Key &q) {
                if (p.breaks != q.breaks) return p.breaks < q.breaks;
                if (p.ranges != q.ranges) return p.ranges < q.ranges;
                if (p.error != q.error) return p.error < q.error;
                return p.x < q.x;
            });
            for (size_t k = 0; k < keys.size(); ++k)
                in[k] = keys[k].state;
            outs.clear();
            size_t y0 = x + 2;
            const size_t used_ranges = x == 0 ? 0 : states[in.front()].ranges;
            if (budget != unbounded)
            {
                // remaining[] does not increase along the chain: ends before first_within[k] need more than k
                // further ranges, where k is what the cheapest incoming state leaves.
                if (used_ranges + 1 > budget)
                    return;
                if (!exact_rest && budget - used_ranges - 1 < first_within.size())
                    y0 = std::max(y0, first_within[budget - used_ranges - 1]);
            }
            if (exact_rest)
            {
                // to_end[r] >= lowerEnd(r) (or none): a range that the bound already excludes is not evaluated.
                // Evaluated first, as an evaluation may reuse in_lines and out_lines.
                for (size_t r = r_off[x]; r < r_off[x + 1]; ++r)
                {
                    const uint32_t lb = lowerEnd(r, n);
                    if (lb != none && used_ranges + lb <= budget)
                        toEnd(pts, a, r);
                }
            }
            out_lines.clear();
            if (exact_rest)
            {
                // The ranges from x whose count to the end fits the budget (the cheapest incoming state's count).
                for (size_t r = r_off[x]; r < r_off[x + 1]; ++r)
                {
                    const uint32_t lb = lowerEnd(r, n);
                    if (lb == none || used_ranges + lb > budget || to_end[r] == none || used_ranges + to_end[r] > budget)
                        continue;
                    const size_t y = r_end[r];
                    ++work_.fits;
                    out_lines.emplace_back(a.sums(x, y));
                    outs.push_back(Out{y, y - x == 2 ? ComputeType(0) : out_lines.back().errSquaredCompute() * static_cast<ComputeType>(y - x), to_end[r]});
                }
            }
            else
                scanFits(a, x, n, y0, [&](size_t y, const auto &sums) {
                    out_lines.emplace_back(sums);
                    outs.push_back(Out{y, y - x == 2 ? ComputeType(0) : out_lines.back().errSquaredCompute() * static_cast<ComputeType>(y - x),
                                       budget == unbounded ? 0 : remaining[y] + 1});
                });
            if (x == 0)
            {
                for (size_t j = 0; j < outs.size(); ++j)
                    if (within(0, outs[j].rest, budget))
                        push(outs[j].y, State{0, none, 0, 1, outs[j].total}, out_lines[j]);
                return;
            }
            in_lines.clear();
            for (uint32_t s : in)
                in_lines.push_back(state_lines[s]);
            // With a budget, only the incoming states with few enough ranges for end y can be its predecessor: a
            // prefix of the cost order (ranges first), so the search for the first meeting line stops there.
            limits.assign(outs.size(), in.size());
            if (budget != unbounded)
                for (size_t j = 0; j < outs.size(); ++j)
                {
                    const size_t rest = outs[j].rest;
                    const size_t most = budget >= rest ? budget - rest : 0;   // the largest usable range count
                    limits[j] = budget >= rest ? static_cast<size_t>(std::upper_bound(keys.begin(), keys.end(), most, [](size_t r, const Key &k) { return r < k.ranges; }) - keys.begin()) : 0;
                }
            choosePredecessors(pts, x);
            for (size_t j = 0; j < outs.size(); ++j)
                if (picks[j] >= limits[j])
                    picks[j] = in.size();
            const State &cheapest = states[in.front()];
            const State broken{0, 0, cheapest.breaks + 1, cheapest.ranges, cheapest.error};
            for (size_t j = 0; j < outs.size(); ++j)
            {
                size_t pick = picks[j];
                // With breaks, a line met only by a state no cheaper than a break from the cheapest one breaks.
                if (allow_breaks && pick < in.size() && !less(states[in[pick]], broken))
                    pick = in.size();
                if (pick == in.size() && !allow_breaks)
                    continue;
                const uint32_t back = in[pick == in.size() ? 0 : pick];
                const State &prev = states[back];
                if (!within(prev.ranges, outs[j].rest, budget))
                    continue;
                push(outs[j].y, State{static_cast<uint32_t>(x), back, prev.breaks + (pick == in.size() ? 1u : 0u), prev.ranges + 1,
                                      prev.error + outs[j].total}, out_lines[j]);
            }
        }

        //! A state after `ranges` ranges whose own range and the rest need at least `rest` ranges fits `budget`.
        bool within(size_t ranges, size_t rest, size_t budget) const { return budget == unbounded || ranges + rest <= budget; }

        //! The fitting ranges [x, y), y >= y0, in increasing y (visit(y, sums)); a range ending one point before the
        //! end is left out (it leaves a 1-point tail). Every fit counts in work().
        template<class Visit>
        void scanFits(const SumArray &a, size_t x, size_t n, size_t y0, Visit visit)
        {
            for (size_t y = y0; y <= n; ++y)
            {
                y = next_boundary[y];   // no range ends deep inside a run of identical points
                ++work_.fits;
                const auto sums = a.sums(x, y);
                const bool same = identical(x, y);
                const bool ok = y - x == 2 || (same ? sigma2 > ComputeType(0) : Approximation::errorBelow(sums, sigma2));
                if (same && !ok)
                {
                    // A zero sigma: no range of > 2 identical points fits; go on past the run.
                    y = same_end[x];
                    continue;
                }
                ComputeType total = 0;
                if (!ok)
                    total = Approximation::errorSquaredCompute(sums) * static_cast<ComputeType>(y - x);
                if (!ok && beyondReach(total, x, n))
                    break;
                if (ok && y + 1 != n)
                    visit(y, sums);
                // The total never decreases with y: no end z with (z - x) sigma^2 * 1.01 <= total can fit.
                if (!ok && total > ComputeType(0))
                {
                    const ComputeType reach = total / (ComputeType(1.01) * sigma2);
                    if (reach > static_cast<ComputeType>(y - x + 1))
                        y = std::max(y, x + (reach >= static_cast<ComputeType>(n - x) ? n - x : static_cast<size_t>(reach)) - 1);
                }
            }
        }

        //! The backward pass (strict mode): to_end[] for the fitting ranges, by boundaries from the end. Exactly, a
        //! range [x, y) would need 1 + the least to_end of the ranges from y whose line meets its own at y; here
        //! only the ranges from y with the least count v are tested (the candidates at y): 1 + v if one of them
        //! meets, else 2 + v if any range from y has another count that is not none (assumed to meet), else none.
        //! So to_end[] never exceeds the exact count, and a range's predecessor has at most one more, which the
        //! bounded rounds need. Returns the bound for the whole chain (unbounded if no valid partition exists).
        //! Evaluated on demand (toEnd, boundaryCounts): to_end[r] lies in {1 + v_min[z], 2 + v_min[z],
        //! none} for r's end z, so lowerEnd(r) = 1 + v_min[z] bounds it from below without a corner test. The least
        //! count at y only needs the ranges from y whose lowerEnd does not exceed it (the others can neither have
        //! the least count nor be candidates), and a round only the ranges whose lowerEnd fits its budget; the rest
        //! are never tested. Before, every fitting range was tested at its end (e.g. corpus seed 84: 92 per point,
        //! of which 15 have lowerEnd <= v_min of their start).
        //! The corner test of a range against the candidates is the exact pairwise test (meets(), in candidate
        //! order) when there are at most scan_first + scan_share of them, else choosePredecessors on all ranges
        //! ending there at once (the chord query bounds the work, as before). The pass used to run
        //! choosePredecessors on every boundary's ranges at once, whose chord query gives the same answer (whether
        //! some candidate meets) except where a near-parallel crossing is not resolved by ComputeType (see the file
        //! comment); either way to_end stays a valid bound, so the rounds return the same optimum, and on the
        //! worst-case corpus every result is the same bit for bit (t_fast_corpus_identity).
        size_t backward(const std::vector<VectorType> &pts, const SumArray &a, size_t n);

        //! Lower bound of to_end[r] without its corner test: 1 + v_min at its end (1 at the chain's end); none iff
        //! to_end[r] is none because no valid rest follows its end.
        uint32_t lowerEnd(size_t r, size_t n) const;

        //! v_min[y] = the least to_end of the ranges from y, v_more[y] = some range from y has another count that
        //! is not none. Evaluates (toEnd) only the ranges whose lower bound does not exceed the least count found
        //! (a range with lowerEnd > v_min[y] cannot have the least count, nor be a candidate at y, whatever its
        //! corner test says), in rising lowerEnd, then for v_more only as far as needed.
        void boundaryCounts(const std::vector<VectorType> &pts, const SumArray &a, size_t n, size_t y);

        //! to_end[r] (memoised): 1 + v_min[z] if one of the candidates at r's end z (the ranges from z with the least
        //! count, in range order) meets r's line there, else 2 + v_min[z] if v_more[z], else none. Boundaries with at
        //! most scan_first candidates test them in order (choosePredecessors' first loop: the answer does not depend
        //! on the other queries); others run choosePredecessors on all ranges ending at z at once, as it always did.
        uint32_t toEnd(const std::vector<VectorType> &pts, const SumArray &a, size_t r);

        //! remaining[y]: a lower bound on the number of fitting ranges that partition [y, N) (corners ignored),
        //! non-increasing in y; first_within[k]: the first y with remaining[y] <= k. From far[b], a bound on the
        //! end of any fitting range that starts in block b (of `block` points), made non-decreasing: a partition
        //! of [y, N) into k ranges has its i-th boundary at most far^i(y), so remaining[y] = 1 + remaining[far(y)].
        // far[b]: the total squared residual T of a range grows when it grows at either end, so for a start s in
        // [s0, s1] and an end z, T(s1, z) <= T(s, z), and [s, z) fits only if T(s, z) <= 1.01 sigma^2 (z - s) (as in
        // beyondReach). An end bound c therefore drops to z - 1 for the first z with T(s1, z) > 1.01 sigma^2 (c - s0)
        // (every end in [z, c] fails); repeated from c = N (each step a bisection, T being monotone in z).
        void lowerBounds(const SumArray &a, size_t n);

        void push(size_t y, const State &st, const Approximation &line)
        {
            ++work_.states;
            incoming[y].push_back(static_cast<uint32_t>(states.size()));
            states.push_back(st);
            state_lines.push_back(line);
        }

        //! The corner test at the boundary of the current choosePredecessors call: crossingDistanceSquared's
        //! arithmetic, with the boundary midpoint computed once per boundary (corner_mid) rather than per pair.
        bool meets(size_t k, size_t j);

        //! meets() on two given lines (first before the corner), uncounted.
        bool meetsAt(const Approximation &first, const Approximation &second) const;

        //! The first k in [k0, k1) whose line cand[k] meets `fixed` at the current corner (fixed_first: `fixed` is the
        //! line before the corner), or k1; every test counts in work(). The loop of meets() without its per-pair
        //! selection and counting, and, for a finite delta, without the crossing's checks (see
        //! crossingDistanceSquaredUnchecked: the same decisions): this loop is most of the search's corner work.
        template<bool fixed_first>
        size_t firstMeeting(const Approximation *cand, size_t k0, size_t k1, const Approximation &fixed);

        //! picks[j] = the first incoming line (in cost order) before limits[j] that meets outgoing line j within
        //! delta at boundary x, or limits[j] if none does. Few pairs: tried in order. Many: by chords (see the file comment),
        //! O((I + O) log I) plus the lines near tangent to the disc, which are tried one by one.
        void choosePredecessors(const std::vector<VectorType> &pts, size_t x);

        enum : int { regular = Chord::regular, tangent = Chord::tangent, misses = Chord::misses };
        struct Item
        {
            ComputeType key, val;
            size_t index;
        };
        //! Orders items by val or by key: one comparator type, so that both sorts share one std::sort (code size).
        struct ItemLess
        {
            bool by_val;
            bool operator()(const Item &p, const Item &q) const { return by_val ? p.val < q.val : p.key < q.key; }
        };

        //! The chord that `line` cuts from the disc of radius delta about m (see `CornerChord.h`).
        Chord chordOf(const Approximation &line, const VectorND<2, ComputeType> &m, ComputeType &eta) const;

        //! One case of the chord test: queries in increasing key; every item with key < query key + eta is in a
        //! min-tree of ranks ordered by val; the cheapest one with val in (u - eta, v + eta) that meets exactly wins.
        void sweep(ComputeType eta);

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
                    y = next_boundary[y];
                    ComputeType total;
                    const bool ok = fits(a, b, y, total);
                    if (!ok && beyondReach(total, b, n))
                        break;
                    if (ok && y + 1 != n)
                        best = std::min(best, detail::crossingDistanceSquared(pts, prev, Approximation(a.sums(b, y)), b));
                }
            }
            failure_.boundary = b;
            failure_.crossingDistance = static_cast<double>(std::sqrt(best));
        }
    };
}

// The definitions of the members declared above that compute the bounds and run the corner tests (each file states
// its part of the contract); after the class, which they need complete.
#include "rtl/vect/partition_search/ChordSweep.h"
#include "rtl/vect/partition_search/RangeBounds.h"
