// ExtractorChainFast (FTLS, Jelinek, Zalud, Jilek 2019): greedy split of an ordered chain into ranges whose
// total-least-squares fit has mean squared residual < sigma^2, using prefix sums so that each trial fit is O(1).
//
// From each range start the extractor first tries the whole remainder, then gallops (lengths 4, 8, 16, ...) to
// the first failing length and bisects between the last passing and the first failing end. The error is not
// monotone in the end index, so the range found is locally maximal (its end passes, end + 1 fails) rather than
// globally longest; the cost is O(log k) fits for a range of k points. Every range has at least 2 points (two
// points always fit exactly), the ranges partition [0, N) in order, and a single-point tail is avoided by
// shortening the last range by one point, or re-splitting it, or (when the last three points fit no line)
// re-partitioning the last ranges by dynamic programming (over a window of up to 512 points). It returns false
// when that fails (e.g. three points forming a triangle much larger than sigma); the FTLS/AFTLS vectorizers then
// ask the exact search (PartitionSearch2D), which decides whether any valid partition exists.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <utility>
#include <vector>

#include "rtl/core/Trace.h"
#include "rtl/vect/FtlsTrace.h"

namespace rtl
{
    //! Observer (last, default NoTrace): receives FtlsTrial and FtlsRange events (FtlsTrace.h).
    template<class SumArray, class Approximation, class Observer = NoTrace>
    class ExtractorChainFast
    {
    public:
        typedef typename Approximation::ElementType ElementType;
        typedef typename Approximation::ComputeType ComputeType;
        typedef std::pair<size_t, size_t> IndexType;

        ExtractorChainFast() = default;
        ~ExtractorChainFast() = default;

        //! Maximal RMS orthogonal residual of a range; must be positive and finite for operator() to succeed.
        void setSigma(ElementType sigma) { sigma2 = static_cast<ComputeType>(sigma) * static_cast<ComputeType>(sigma); sig = sigma; }
        //! Observer of the following calls (nullptr: none); it must outlive them.
        void setObserver(Observer *observer) { observer_ = observer; }

        //! Clears the outputs and fills them. False (outputs empty) for fewer than 2 points, an invalid sigma, or
        //! (only for pathological sets such as 3 points that fit no line and no split) when no valid partition is found.
        bool operator()(const SumArray &sum_array, std::vector<Approximation> &approximations, std::vector<IndexType> &indices)
        {
            approximations.clear();
            indices.clear();
            const size_t n = sum_array.size() > 0 ? sum_array.size() - 1 : 0;
            if (n < 2 || !(sig > ElementType(0)) || !std::isfinite(static_cast<ComputeType>(sig)))
                return false;
            if (!partition(sum_array, 0, n, indices))
            {
                indices.clear();
                return false;
            }
            approximations.reserve(indices.size());
            for (const auto &r : indices)
                approximations.emplace_back(sum_array.sums(r.first, r.second));
            return true;
        }

    private:
        ElementType sig{0};
        ComputeType sigma2{0};
        Observer *observer_{nullptr};

        bool fits(const SumArray &a, size_t b, size_t e) const { return e - b <= 2 || Approximation::errorBelow(a.sums(b, e), sigma2); }
        //! fits() of a reported trial.
        bool fits(const SumArray &a, size_t b, size_t e, int phase) const
        {
            const bool pass = fits(a, b, e);
            if constexpr (Observer::enabled)
                if (observer_)
                    (*observer_)(FtlsTrial{b, e, phase, e - b <= 2 ? 0.0 : static_cast<double>(Approximation::errorSquaredCompute(a.sums(b, e))),
                                           static_cast<double>(sig), pass});
            return pass;
        }
        void accept(std::vector<IndexType> &out, size_t b, size_t e) const
        {
            out.emplace_back(b, e);
            if constexpr (Observer::enabled)
                if (observer_)
                    (*observer_)(FtlsRange{b, e});
        }

        //! A locally maximal passing end in [beg + 2, limit] for a range starting at beg (limit - beg >= 2).
        size_t findEnd(const SumArray &a, size_t beg, size_t limit) const
        {
            if (fits(a, beg, limit, FtlsWholeRemainder))
                return limit;
            size_t lo = beg + 2, hi = limit, len = 4;
            while (beg + len < limit)
            {
                if (fits(a, beg, beg + len, FtlsGallop)) { lo = beg + len; len *= 2; }
                else { hi = beg + len; break; }
            }
            while (hi - lo > 1)
            {
                const size_t mid = lo + (hi - lo) / 2;
                if (fits(a, beg, mid, FtlsBisection)) lo = mid;
                else hi = mid;
            }
            return lo;
        }

        //! Stuck with three points [beg, limit) that fit no line: re-partitions the tail from an earlier range
        //! boundary (at least 16 points back) into the fewest fitting ranges of >= 2 points by dynamic programming.
        bool repartitionTail(const SumArray &a, size_t limit, std::vector<IndexType> &out, size_t beg) const
        {
            size_t ws = beg;
            while (!out.empty() && limit - ws < 16)
            {
                ws = out.back().first;
                out.pop_back();
            }
            const size_t w = limit - ws;
            if (w > 512)
                return false;
            const size_t none = std::numeric_limits<size_t>::max();
            std::vector<size_t> best(w + 1, none), from(w + 1, none);
            best[0] = 0;
            for (size_t y = 2; y <= w; ++y)
                for (size_t x = 0; x + 2 <= y; ++x)
                    if (best[x] != none && best[x] + 1 < best[y] && fits(a, ws + x, ws + y))
                    {
                        best[y] = best[x] + 1;
                        from[y] = x;
                    }
            if (best[w] == none)
                return false;
            const size_t first = out.size();
            for (size_t y = w; y > 0; y = from[y])
                out.emplace_back(ws + from[y], ws + y);
            std::reverse(out.begin() + static_cast<std::ptrdiff_t>(first), out.end());
            if constexpr (Observer::enabled)
                if (observer_)
                    for (size_t r = first; r < out.size(); ++r)
                        (*observer_)(FtlsRange{out[r].first, out[r].second});
            return true;
        }

        //! Appends ranges covering [beg, limit) (limit - beg >= 2). False if no valid partition was found.
        bool partition(const SumArray &a, size_t beg, size_t limit, std::vector<IndexType> &out) const
        {
            while (beg < limit)
            {
                size_t e = findEnd(a, beg, limit);
                if (limit - e == 1)
                {
                    // Leave at least two points for the next range.
                    if (e - 1 >= beg + 2 && fits(a, beg, e - 1, FtlsTailAdjust)) e = e - 1;
                    else if (e - 1 >= beg + 2) e = findEnd(a, beg, e - 2 >= beg + 2 ? e - 2 : beg + 2);
                    else
                        return repartitionTail(a, limit, out, beg);
                }
                accept(out, beg, e);
                beg = e;
            }
            return true;
        }
    };
}
