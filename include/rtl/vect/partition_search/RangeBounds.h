// The lower bounds of PartitionSearch2D's bounded rounds: member definitions of PartitionSearch2D (declared there).
//
// What: bounds, from below, on the number of ranges that a valid partition of the rest of the chain needs.
// - lowerBounds(): remaining[y], a bound on the fitting ranges that partition [y, N), corners ignored, from how far
//   a fitting range can reach (far[], per block of starts); non-increasing in y, O(N / block * log N) fits.
// - backward() with toEnd(), boundaryCounts(), lowerEnd(): the corner-aware to_end[r] of every fitting range r, a
//   bound on the ranges of a valid partition of the rest that starts with r, from the end of the chain; evaluated
//   on demand, O(F) fits for the F fitting ranges and corner tests only where a bound can matter.
// Invariant (what makes the bounded rounds exact): no bound exceeds the true count, and a range's predecessor needs
// at most one range more. Complexity and the schedule of rounds: PartitionSearch2D.h.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "rtl/vect/PartitionSearch2D.h"

namespace rtl
{
    template<class SumArray, class Approximation>
    inline void PartitionSearch2D<SumArray, Approximation>::lowerBounds(const SumArray &a, size_t n)
    {
        const size_t nb = (n + block - 1) / block;
        far.assign(nb, n);
        for (size_t b = 0; b < nb; ++b)
        {
            const size_t s0 = b * block, s1 = std::min(s0 + block, n) - 1;
            size_t c = n;
            for (int step = 0; step < 6 && s1 + 3 <= c; ++step)
            {
                const ComputeType limit = ComputeType(1.01) * sigma2 * static_cast<ComputeType>(c - s0) + ComputeType(1e-300);
                size_t lo = s1 + 3, hi = c + 1;   // the first z in [lo, c] with T(s1, z) > limit, or c + 1
                while (lo < hi)
                {
                    const size_t mid = lo + (hi - lo) / 2;
                    ComputeType total;
                    fits(a, s1, mid, total);
                    if (total > limit) hi = mid;
                    else lo = mid + 1;
                }
                if (lo > c)
                    break;
                c = lo - 1;
            }
            far[b] = std::max(c, std::min(s1 + 2, n));
            if (b > 0)
                far[b] = std::max(far[b], far[b - 1]);
        }
        remaining.assign(n + 1, 0);
        for (size_t y = n; y-- > 0;)
            remaining[y] = 1 + remaining[std::min(far[y / block], n)];
        first_within.assign(remaining[0] + 1, n);
        for (size_t y = n + 1; y-- > 0;)
            first_within[remaining[y]] = y;
        for (size_t k = 1; k < first_within.size(); ++k)
            first_within[k] = std::min(first_within[k], first_within[k - 1]);
    }

    template<class SumArray, class Approximation>
    inline size_t PartitionSearch2D<SumArray, Approximation>::backward(const std::vector<VectorType> &pts, const SumArray &a, size_t n)
    {
        r_off.assign(n + 1, 0);
        r_end.clear();
        r_start.clear();
        for (size_t x = 0; x + 2 <= n; ++x)
        {
            r_off[x] = r_end.size();
            if (deep(x))
                continue;   // no state ends there
            scanFits(a, x, n, x + 2, [&](size_t y, const auto &) {
                r_end.push_back(static_cast<uint32_t>(y));
                r_start.push_back(static_cast<uint32_t>(x));
            });
        }
        r_off[n - 1] = r_off[n] = r_end.size();
        const size_t nr = r_end.size();
        work_.states += nr;
        to_end.assign(nr, unknown);
        e_off.assign(n + 2, 0);
        for (size_t r = 0; r < nr; ++r)
            ++e_off[r_end[r] + 1];
        for (size_t y = 0; y <= n; ++y)
            e_off[y + 1] += e_off[y];
        by_end.resize(nr);
        std::vector<size_t> &fill = picks;   // scratch
        fill.assign(e_off.begin(), e_off.end() - 1);
        for (size_t x = 0; x + 2 <= n; ++x)
            for (size_t r = r_off[x]; r < r_off[x + 1]; ++r)
                by_end[fill[r_end[r]]++] = r;
        for (size_t k = e_off[n]; k < e_off[n + 1]; ++k)
            to_end[by_end[k]] = 1;
        v_min.assign(n + 1, none);
        v_more.assign(n + 1, 0);
        cand_off.assign(n + 1, none);
        cand_cnt.assign(n + 1, 0);
        cand_lines.clear();
        // Boundaries from the end: v_min[y], v_more[y] for every boundary that ends a range, and the chain start.
        for (size_t y = n - 1; ; --y)
        {
            if (y == 0 || e_off[y] != e_off[y + 1])
                boundaryCounts(pts, a, n, y);
            if (y == 0)
                break;
        }
        return v_min[0] == none ? unbounded : v_min[0];
    }

    template<class SumArray, class Approximation>
    inline uint32_t PartitionSearch2D<SumArray, Approximation>::lowerEnd(size_t r, size_t n) const
    {
        const size_t z = r_end[r];
        if (z == n)
            return 1;
        return v_min[z] == none ? none : 1 + v_min[z];
    }

    template<class SumArray, class Approximation>
    inline void PartitionSearch2D<SumArray, Approximation>::boundaryCounts(const std::vector<VectorType> &pts, const SumArray &a, size_t n, size_t y)
    {
        const size_t r0 = r_off[y], r1 = r_off[y + 1];
        uint32_t lo = none, hi = 0;
        for (size_t r = r0; r < r1; ++r)
        {
            const uint32_t lb = lowerEnd(r, n);
            if (lb == none)
                to_end[r] = none;   // its end has no valid rest: what the corner test's branch gives too
            else
            {
                lo = std::min(lo, lb);
                hi = std::max(hi, lb);
            }
        }
        uint32_t cur = none;
        for (uint32_t level = lo; lo != none && level <= hi && level <= cur; ++level)
            for (size_t r = r0; r < r1; ++r)
                if (lowerEnd(r, n) == level)
                    cur = std::min(cur, toEnd(pts, a, r));
        v_min[y] = cur;
        if (cur == none)
            return;
        // Every range with lowerEnd <= cur is evaluated. Another count: an evaluated one, or an unevaluated one
        // (lowerEnd > cur) whose end has another count (then it is not none whatever its corner) or that meets.
        bool more = false;
        for (size_t r = r0; r < r1 && !more; ++r)
            more = to_end[r] != unknown ? to_end[r] != none && to_end[r] != cur : v_more[r_end[r]] != 0;
        for (size_t r = r0; r < r1 && !more; ++r)
            more = toEnd(pts, a, r) != none && to_end[r] != cur;
        v_more[y] = more;
    }

    template<class SumArray, class Approximation>
    inline uint32_t PartitionSearch2D<SumArray, Approximation>::toEnd(const std::vector<VectorType> &pts, const SumArray &a, size_t r)
    {
        if (to_end[r] != unknown)
            return to_end[r];
        const size_t z = r_end[r];
        const uint32_t vmin = v_min[z];
        if (vmin == none)
            return to_end[r] = none;
        if (cand_off[z] == none)
        {
            cand_off[z] = cand_lines.size();
            for (size_t q = r_off[z]; q < r_off[z + 1]; ++q)
                if (to_end[q] == vmin)
                    cand_lines.emplace_back(a.sums(z, r_end[q]));
            cand_cnt[z] = cand_lines.size() - cand_off[z];
        }
        const size_t c0 = cand_off[z], ni = cand_cnt[z];
        const uint32_t miss = v_more[z] ? 2 + vmin : none;
        corner_mid = (pts[z - 1].template cast<ComputeType>() + pts[z].template cast<ComputeType>()) * ComputeType(0.5);
        if (ni <= scan_first + scan_share)
        {
            const Approximation line(a.sums(r_start[r], z));
            return to_end[r] = firstMeeting<true>(cand_lines.data() + c0, 0, ni, line) < ni ? 1 + vmin : miss;
        }
        in_lines.assign(cand_lines.begin() + static_cast<std::ptrdiff_t>(c0), cand_lines.begin() + static_cast<std::ptrdiff_t>(c0 + ni));
        out_lines.clear();
        for (size_t k = e_off[z]; k < e_off[z + 1]; ++k)
            out_lines.emplace_back(a.sums(r_start[by_end[k]], z));
        limits.assign(out_lines.size(), in_lines.size());
        reversed_ = true;
        choosePredecessors(pts, z);
        reversed_ = false;
        for (size_t j = 0; j < out_lines.size(); ++j)
            to_end[by_end[e_off[z] + j]] = picks[j] < in_lines.size() ? 1 + vmin : miss;
        return to_end[r];
    }
}
