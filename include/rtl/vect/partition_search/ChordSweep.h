// The corner tests of PartitionSearch2D and its chord sweep: member definitions of PartitionSearch2D (declared
// there).
//
// What: choosePredecessors() gives, for every outgoing line at a boundary, the first incoming line in cost order
// (below a per-line limit) that meets it within delta of the boundary midpoint. The cheapest few are tested one by
// one (firstMeeting, meets); with many lines, by chords: a line crossing the disc of radius delta about the midpoint
// cuts a chord from it (chordOf, see CornerChord.h), and two lines cross inside the disc iff their chords' ends
// alternate around the circle, so the pick is a 2D range-minimum query (sweep: a sweep over one end angle, a
// MinRankTree over the other). Every comparison is widened by the angles' rounding bound, and every candidate is
// confirmed by the exact test, so no meeting pair is missed and the pick is the one testing every pair in cost
// order gives, except where ComputeType does not resolve the crossing itself.
// Complexity: O((I + O) log I) per boundary of I incoming and O outgoing lines, plus the lines near tangent to the
// disc, tested one by one. Every test counts in work().corners.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <vector>

#include "rtl/core/VectorND.h"
#include "rtl/vect/PartitionSearch2D.h"

namespace rtl
{
    template<class SumArray, class Approximation>
    inline bool PartitionSearch2D<SumArray, Approximation>::meets(size_t k, size_t j)
    {
        ++work_.corners;
        // The backward pass has the ranges after the corner as candidates (k) and those before it as queries (j).
        return meetsAt(reversed_ ? out_lines[j] : in_lines[k], reversed_ ? in_lines[k] : out_lines[j]);
    }

    template<class SumArray, class Approximation>
    inline bool PartitionSearch2D<SumArray, Approximation>::meetsAt(const Approximation &first, const Approximation &second) const
    {
        if (delta2 < std::numeric_limits<ComputeType>::infinity())
            return Approximation::crossingDistanceSquaredUnchecked(first, second, corner_mid) <= delta2;
        VectorND<2, ComputeType> c;
        if (!Approximation::getCrossingCompute(first, second, c))
            return std::numeric_limits<ComputeType>::infinity() <= delta2;
        return (c - corner_mid).lengthSquared() <= delta2;
    }

    template<class SumArray, class Approximation>
    template<bool fixed_first>
    inline size_t PartitionSearch2D<SumArray, Approximation>::firstMeeting(const Approximation *cand, size_t k0, size_t k1, const Approximation &fixed)
    {
        size_t k = k0;
        if (delta2 < std::numeric_limits<ComputeType>::infinity())
        {
            const VectorND<2, ComputeType> m = corner_mid;
            const ComputeType bound = delta2;
            for (; k < k1; ++k)
                if (Approximation::crossingDistanceSquaredUnchecked(fixed_first ? fixed : cand[k], fixed_first ? cand[k] : fixed, m) <= bound)
                    break;
        }
        else
            while (k < k1 && !meetsAt(fixed_first ? fixed : cand[k], fixed_first ? cand[k] : fixed))
                ++k;
        work_.corners += (k < k1 ? k + 1 : k1) - k0;
        return k;
    }

    template<class SumArray, class Approximation>
    inline void PartitionSearch2D<SumArray, Approximation>::choosePredecessors(const std::vector<VectorType> &pts, size_t x)
    {
        const size_t ni = in_lines.size(), no = out_lines.size();
        corner_mid = (pts[x - 1].template cast<ComputeType>() + pts[x].template cast<ComputeType>()) * ComputeType(0.5);
        picks = limits;   // no line at or beyond limits[j] is wanted for outgoing line j
        // The cheapest few first (they usually meet); the rest one by one only while that stays cheap.
        const size_t first = std::min(ni, scan_first);
        open_.clear();
        for (size_t j = 0; j < no; ++j)
        {
            const size_t f = std::min(first, limits[j]);
            const size_t k = reversed_ ? firstMeeting<true>(in_lines.data(), 0, f, out_lines[j]) : firstMeeting<false>(in_lines.data(), 0, f, out_lines[j]);
            if (k < f)
                picks[j] = k;
            else if (f < limits[j])
                open_.push_back(j);
        }
        if (open_.empty())
            return;
        if (open_.size() * (ni - first) <= scan_share * (ni + open_.size()))   // a bounded share of this boundary's lines
        {
            for (size_t j : open_)
            {
                const size_t k = reversed_ ? firstMeeting<true>(in_lines.data(), first, limits[j], out_lines[j])
                                           : firstMeeting<false>(in_lines.data(), first, limits[j], out_lines[j]);
                if (k < limits[j])
                    picks[j] = k;
            }
            return;
        }
        typedef VectorND<2, ComputeType> CV;
        const CV m = (pts[x - 1].template cast<ComputeType>() + pts[x].template cast<ComputeType>()) * ComputeType(0.5);
        ComputeType eta = 0;
        in_chords.resize(ni);
        out_chords.resize(no);
        for (size_t k = first; k < ni; ++k)
            in_chords[k] = chordOf(in_lines[k], m, eta);
        for (size_t j : open_)
            out_chords[j] = chordOf(out_lines[j], m, eta);
        eta *= 2;
        const ComputeType pi = std::acos(ComputeType(-1));
        auto wrap = [&](Chord &c) { if (c.kind == regular && (c.p < -pi + eta || c.q > pi - eta || !(eta < ComputeType(0.01)))) c.kind = tangent; };
        for (size_t k = first; k < ni; ++k) wrap(in_chords[k]);
        for (size_t j : open_) wrap(out_chords[j]);
        // Two chords cross inside the disc iff their ends alternate: p < u < q < v (case 1) or u < p < v < q
        // (case 2), here with every comparison widened by eta, so no meeting pair is missed.
        for (int c2 = 0; c2 < 2; ++c2)
        {
            items.clear();
            for (size_t k = first; k < ni; ++k)
                if (in_chords[k].kind == regular)
                    items.push_back(Item{c2 ? -in_chords[k].q : in_chords[k].p, c2 ? in_chords[k].p : in_chords[k].q, k});
            queries.clear();
            for (size_t j : open_)
                if (out_chords[j].kind == regular)
                    queries.push_back(Item{c2 ? -out_chords[j].q : out_chords[j].p, 0, j});
            sweep(eta);
        }
        for (size_t j : open_)
        {
            if (out_chords[j].kind == misses)
                continue;
            for (size_t k = first; k < std::min(picks[j], ni); ++k)
                if ((out_chords[j].kind == tangent ? in_chords[k].kind != misses : in_chords[k].kind == tangent) && meets(k, j))
                {
                    picks[j] = k;
                    break;
                }
        }
    }

    template<class SumArray, class Approximation>
    inline typename PartitionSearch2D<SumArray, Approximation>::Chord PartitionSearch2D<SumArray, Approximation>::chordOf(const Approximation &line, const VectorND<2, ComputeType> &m, ComputeType &eta) const
    {
        return detail::cornerChord(line, m, delta_, delta2, eta);
    }

    template<class SumArray, class Approximation>
    inline void PartitionSearch2D<SumArray, Approximation>::sweep(ComputeType eta)
    {
        if (items.empty() || queries.empty())
            return;
        std::sort(items.begin(), items.end(), ItemLess{true});
        vals.clear();
        const size_t ni = items.size();
        leaf_of.assign(in_lines.size(), 0);
        for (size_t i = 0; i < ni; ++i)
        {
            vals.push_back(items[i].val);
            leaf_of[items[i].index] = i;
        }
        tree.reset(ni);
        // the items by key, each with its rank in val order (its leaf); items of equal key enter the tree before
        // the same query, so their order among themselves does not matter
        by_key.clear();
        for (size_t i = 0; i < ni; ++i) by_key.push_back(Item{items[i].key, items[i].val, i});
        std::sort(by_key.begin(), by_key.end(), ItemLess{false});
        std::sort(queries.begin(), queries.end(), ItemLess{false});
        size_t next = 0;
        for (const Item &qu : queries)
        {
            while (next < ni && by_key[next].key < qu.key + eta)
            {
                tree.set(by_key[next].index, items[by_key[next].index].index);
                ++next;
            }
            const Chord &o = out_chords[qu.index];
            const size_t lo = static_cast<size_t>(std::upper_bound(vals.begin(), vals.end(), o.p - eta) - vals.begin());
            const size_t hi = static_cast<size_t>(std::lower_bound(vals.begin(), vals.end(), o.q + eta) - vals.begin());
            removed.clear();
            while (lo < hi)
            {
                ++work_.corners;
                const size_t k = tree.query(lo, hi);
                if (k == none_rank || k >= picks[qu.index])
                    break;
                if (meets(k, qu.index))
                {
                    picks[qu.index] = k;
                    break;
                }
                removed.push_back(k);
                tree.set(leaf_of[k], none_rank);
            }
            for (size_t k : removed)
                tree.set(leaf_of[k], k);
        }
    }
}
