// ExtractorChainIncremental (incremental / "line tracking" method, Nguyen et al. 2007): adds points one by one to
// running sums and closes the current range, without the new point, as soon as the fit including it reaches
// sigma^2; the next range starts at that point. Sums are accumulated relative to the range's first point, which
// keeps the centred moments accurate, and the error test is division- and root-free (Approximation::errorBelow).
// A final single point is appended to the last range if it still fits, or takes the last range's last point with
// it as a 2-point range, or the last two ranges are re-cut so that the final points pair up, or the last ranges
// are re-partitioned by dynamic programming; only if no partition of that tail keeps every range within sigma is
// it left out (then indices end at N - 1).
// Observer (last template parameter, rtl/core/Trace.h): with an enabled one set by setObserver(), every step is
// reported as the ItlsStart/ItlsAdd/ItlsClose/ItlsTail/ItlsTailRange events of rtl/vect/SimplifyTrace.h; the
// decisions are the untraced ones (the reports only add RMS computations beside them).
#pragma once

#include <cmath>
#include <cstddef>
#include <limits>
#include <utility>
#include <vector>

#include "rtl/core/Trace.h"
#include "rtl/core/VectorND.h"
#include "rtl/vect/SimplifyTrace.h"

namespace rtl
{
    template<class Approximation, class Observer = NoTrace>
    class ExtractorChainIncremental
    {
    public:
        typedef typename Approximation::ElementType ElementType;
        typedef typename Approximation::ComputeType ComputeType;
        typedef typename Approximation::VectorType VectorType;
        typedef typename Approximation::PrecSumsType PrecSumsType;
        typedef std::pair<size_t, size_t> IndexType;
        static constexpr int dim = VectorType::dimensionality();
        static_assert(dim == 2 || dim == 3, "ExtractorChainIncremental supports 2D and 3D approximations");
        typedef VectorND<dim, ComputeType> ComputeVectorType;

        ExtractorChainIncremental() = default;
        ~ExtractorChainIncremental() = default;

        void setSigma(ElementType sigma) { sigma2 = static_cast<ComputeType>(sigma) * static_cast<ComputeType>(sigma); sig = sigma; }
        //! Observer of the following calls (nullptr: none); it must outlive them.
        void setObserver(Observer *observer) { observer_ = observer; }

        //! Clears the outputs and fills them. False (outputs empty) for fewer than 2 points or an invalid sigma.
        //! Non-finite points are the caller's responsibility (the Vectorizer classes reject them).
        bool operator()(const std::vector<VectorType> &pts, std::vector<Approximation> &approximations, std::vector<IndexType> &indices)
        {
            approximations.clear();
            indices.clear();
            const size_t n = pts.size();
            if (n < 2 || !(sig > ElementType(0)) || !std::isfinite(static_cast<ComputeType>(sig)))
                return false;
            if constexpr (Observer::enabled)
                if (observer_)
                    (*observer_)(ItlsStart{n, static_cast<double>(sig)});

            // Hot loop on plain scalars (sums of p - origin); the PrecSums object is only assembled for the test.
            size_t beg = 0;
            ComputeVectorType origin = pts[0].template cast<ComputeType>();
            ComputeType s[PrecSumsType::sumNr()] = {};
            [[maybe_unused]] size_t scalar_until = 0;   // after a block with a closing point: point by point
            for (size_t i = 0; i < n; ++i)
            {
                if constexpr (hasBlockTest<Approximation>(0))
                    if (i >= scalar_until && i - beg >= 2 && n - i >= block && !(Observer::enabled && observer_))
                    {
                        // The next `block` points added and tested as the loop below would (same sums, same
                        // test per point), the tests side by side; a block in which some point closes the range
                        // is redone point by point, so the decisions and sums are those of the plain loop.
                        ComputeType c[PrecSumsType::sumNr()], states[PrecSumsType::sumNr() * block];
                        for (size_t k = 0; k < PrecSumsType::sumNr(); ++k)
                            c[k] = s[k];
                        for (size_t j = 0; j < block; ++j)
                        {
                            ComputeType d[dim];
                            for (int k = 0; k < dim; ++k)
                                d[k] = static_cast<ComputeType>(pts[i + j][k]) - origin[k];
                            add(c, d, ComputeType(1));
                            for (size_t k = 0; k < PrecSumsType::sumNr(); ++k)
                                states[k * block + j] = c[k];
                        }
                        if (Approximation::template errorBelowRawAll<block>(states, static_cast<ComputeType>(i + 1 - beg), sigma2))
                        {
                            for (size_t k = 0; k < PrecSumsType::sumNr(); ++k)
                                s[k] = c[k];
                            i += block - 1;
                            continue;
                        }
                        scalar_until = i + block;
                    }
                ComputeType d[dim];
                for (int k = 0; k < dim; ++k)
                    d[k] = static_cast<ComputeType>(pts[i][k]) - origin[k];
                add(s, d, ComputeType(1));
                if constexpr (Observer::enabled)
                    if (observer_)
                        reportAdd(s, i, beg);
                if (i - beg >= 2 && !Approximation::errorBelowRaw(s, static_cast<ComputeType>(i + 1 - beg), sigma2))
                {
                    [[maybe_unused]] double rmsWithNext = 0;   // for the trace only
                    if constexpr (Observer::enabled)
                        if (observer_)
                            rmsWithNext = rms(makeSums(s, i + 1 - beg));
                    add(s, d, ComputeType(-1));
                    if constexpr (Observer::enabled)
                        if (observer_)
                        {
                            (*observer_)(ItlsClose{beg, i, rms(makeSums(s, i - beg)), rmsWithNext, static_cast<double>(sig), false});
                            // Point i starts the next range (its sums relative to itself are zero).
                            (*observer_)(ItlsAdd{i, i, 1, 0.0, static_cast<double>(sig), false, true});
                        }
                    emit(approximations, indices, makeSums(s, i - beg), origin, beg, i);
                    beg = i;
                    origin = pts[i].template cast<ComputeType>();
                    for (auto &v : s)
                        v = 0;
                }
            }
            const PrecSumsType sums = makeSums(s, n - beg);
            if (n - beg >= 2)
            {
                if constexpr (Observer::enabled)
                    if (observer_)
                        (*observer_)(ItlsClose{beg, n, rms(sums), std::numeric_limits<double>::quiet_NaN(),
                                               static_cast<double>(sig), true});
                emit(approximations, indices, sums, origin, beg, n);
            }
            else
            {
                attachLastPoint(pts, approximations, indices);
                if constexpr (Observer::enabled)
                    if (observer_)
                        reportTail(pts, indices, tail_);
            }
            return true;
        }

    private:
        static constexpr size_t block = 16;
        //! Whether Approximation tests several states of a range at once (errorBelowRawAll).
        template<class A>
        static constexpr auto hasBlockTest(int) -> decltype(A::template errorBelowRawAll<block>(nullptr, ComputeType(0), ComputeType(0)), bool()) { return true; }
        template<class A>
        static constexpr bool hasBlockTest(...) { return false; }

        //! How attachLastPoint placed the last point: the first `kept` ranges are unchanged; ItlsTailMethod.
        //! Recorded only for an enabled Observer (so that the untraced code is the code without tracing).
        struct TailPlacement { size_t kept; int method; };

        ElementType sig{0};

        static double rms(const PrecSumsType &sums)
        {
            return std::sqrt(static_cast<double>(Approximation::errorSquaredCompute(sums)));
        }

        //! The add event of point i to the range from beg (raw sums s include i), with the loop's own test.
        void reportAdd(const ComputeType *s, size_t i, size_t beg) const
        {
            const size_t count = i + 1 - beg;
            const bool tested = i - beg >= 2;
            const bool fits = !tested || Approximation::errorBelowRaw(s, static_cast<ComputeType>(count), sigma2);
            (*observer_)(ItlsAdd{i, beg, count, rms(makeSums(s, count)), static_cast<double>(sig), tested, fits});
        }

        //! The tail event after attachLastPoint and the ranges that replaced all but the first `tail.kept`.
        void reportTail(const std::vector<VectorType> &pts, const std::vector<IndexType> &indices, const TailPlacement &tail) const
        {
            (*observer_)(ItlsTail{pts.size() - 1, tail.kept, tail.method});
            for (size_t r = tail.kept; r < indices.size(); ++r)
            {
                const ComputeVectorType o = pts[indices[r].first].template cast<ComputeType>();
                (*observer_)(ItlsTailRange{indices[r].first, indices[r].second, rms(rangeSums(pts, indices[r].first, indices[r].second, o))});
            }
        }

        //! Adds (w = 1) or removes (w = -1) the point d to/from the raw sums in PrecSums order.
        static void add(ComputeType *s, const ComputeType *d, ComputeType w)
        {
            if constexpr (dim == 2)
            {
                s[0] += w * d[0]; s[1] += w * d[1];
                s[2] += w * d[0] * d[0]; s[3] += w * d[1] * d[1]; s[4] += w * d[0] * d[1];
            }
            else
            {
                s[0] += w * d[0]; s[1] += w * d[1]; s[2] += w * d[2];
                s[3] += w * d[0] * d[0]; s[4] += w * d[1] * d[1]; s[5] += w * d[2] * d[2];
                s[6] += w * d[0] * d[1]; s[7] += w * d[1] * d[2]; s[8] += w * d[2] * d[0];
            }
        }
        static PrecSumsType makeSums(const ComputeType *s, size_t count)
        {
            if constexpr (dim == 2)
                return PrecSumsType(s[0], s[1], s[2], s[3], s[4], count);
            else
                return PrecSumsType(s[0], s[1], s[2], s[3], s[4], s[5], s[6], s[7], s[8], count);
        }
        ComputeType sigma2{0};
        Observer *observer_{nullptr};
        mutable TailPlacement tail_{0, 0};

        void emit(std::vector<Approximation> &approximations, std::vector<IndexType> &indices, const PrecSumsType &sums,
                  const ComputeVectorType &origin, size_t beg, size_t end) const
        {
            approximations.emplace_back();
            approximations.back()(sums, origin);
            indices.emplace_back(beg, end);
        }

        PrecSumsType rangeSums(const std::vector<VectorType> &pts, size_t beg, size_t end, const ComputeVectorType &origin) const
        {
            PrecSumsType s;
            s.setZero();
            for (size_t i = beg; i < end; ++i)
                s += PrecSumsType(ComputeVectorType(pts[i].template cast<ComputeType>() - origin));
            return s;
        }

        void attachLastPoint(const std::vector<VectorType> &pts, std::vector<Approximation> &approximations,
                             std::vector<IndexType> &indices) const
        {
            const size_t n = pts.size();
            IndexType &last = indices.back();
            const ComputeVectorType origin = pts[last.first].template cast<ComputeType>();
            const PrecSumsType with = rangeSums(pts, last.first, n, origin);
            if (Approximation::errorBelow(with, sigma2))
            {
                last.second = n;
                approximations.back()(with, origin);
                if constexpr (Observer::enabled)
                    tail_ = TailPlacement{indices.size() - 1, itlsTailAppended};
                return;
            }
            if (last.second - last.first >= 3)
            {
                const PrecSumsType without = rangeSums(pts, last.first, n - 2, origin);
                if (last.second - last.first == 3 || Approximation::errorBelow(without, sigma2))
                {
                    last.second = n - 2;
                    approximations.back()(without, origin);
                    const ComputeVectorType o2 = pts[n - 2].template cast<ComputeType>();
                    emit(approximations, indices, rangeSums(pts, n - 2, n, o2), o2, n - 2, n);
                    if constexpr (Observer::enabled)
                        tail_ = TailPlacement{indices.size() - 2, itlsTailLastSplit};
                    return;
                }
            }
            if (last.second - last.first == 2 && indices.size() >= 2)
            {
                // [.., n - 3) [n - 3, n - 1) {n - 1}: the previous range gives up a point or takes one, so that the
                // last points pair up: [.., n - 4) [n - 4, n - 2) [n - 2, n)  or  [.., n - 2) [n - 2, n).
                IndexType &prev = indices[indices.size() - 2];
                const ComputeVectorType po = pts[prev.first].template cast<ComputeType>();
                const PrecSumsType grown = rangeSums(pts, prev.first, n - 2, po);
                if (Approximation::errorBelow(grown, sigma2))
                {
                    prev.second = n - 2;
                    approximations[approximations.size() - 2](grown, po);
                    last = IndexType(n - 2, n);
                    const ComputeVectorType o2 = pts[n - 2].template cast<ComputeType>();
                    approximations.back()(rangeSums(pts, n - 2, n, o2), o2);
                    if constexpr (Observer::enabled)
                        tail_ = TailPlacement{indices.size() - 2, itlsTailPrevGrown};
                    return;
                }
                if (prev.second - prev.first >= 3)
                {
                    const PrecSumsType shrunk = rangeSums(pts, prev.first, n - 4, po);
                    if (prev.second - prev.first == 3 || Approximation::errorBelow(shrunk, sigma2))
                    {
                        prev.second = n - 4;
                        approximations[approximations.size() - 2](shrunk, po);
                        const ComputeVectorType o1 = pts[n - 4].template cast<ComputeType>(), o2 = pts[n - 2].template cast<ComputeType>();
                        last = IndexType(n - 4, n - 2);
                        approximations.back()(rangeSums(pts, n - 4, n - 2, o1), o1);
                        emit(approximations, indices, rangeSums(pts, n - 2, n, o2), o2, n - 2, n);
                        if constexpr (Observer::enabled)
                            tail_ = TailPlacement{indices.size() - 3, itlsTailPrevShrunk};
                        return;
                    }
                }
            }
            for (size_t reach : {16u, 64u, 256u})
                if (repartitionTail(pts, approximations, indices, reach))
                    return;
            if constexpr (Observer::enabled)
                tail_ = TailPlacement{indices.size(), itlsTailLeftOut};
        }

        //! Last resort for the final point: re-partitions the last ranges (at least `reach` points back, at most
        //! 512) into the fewest ranges of >= 2 points within sigma, by dynamic programming over window prefix sums.
        bool repartitionTail(const std::vector<VectorType> &pts, std::vector<Approximation> &approximations,
                             std::vector<IndexType> &indices, size_t reach) const
        {
            const size_t n = pts.size();
            size_t keep = indices.size(), ws = n - 1;
            while (keep > 0 && n - ws < reach)
                ws = indices[--keep].first;
            const size_t w = n - ws;
            if (w > 512 || w < 2)
                return false;
            const ComputeVectorType origin = pts[ws].template cast<ComputeType>();
            std::vector<PrecSumsType> prefix(w + 1);
            prefix[0].setZero();
            for (size_t i = 0; i < w; ++i)
                prefix[i + 1] = prefix[i] + PrecSumsType(ComputeVectorType(pts[ws + i].template cast<ComputeType>() - origin));
            const size_t none = static_cast<size_t>(-1);
            std::vector<size_t> best(w + 1, none), from(w + 1, none);
            best[0] = 0;
            for (size_t y = 2; y <= w; ++y)
                for (size_t x = 0; x + 2 <= y; ++x)
                    if (best[x] != none && best[x] + 1 < best[y] &&
                        (y - x == 2 || Approximation::errorBelow(prefix[y] - prefix[x], sigma2)))
                    {
                        best[y] = best[x] + 1;
                        from[y] = x;
                    }
            if (best[w] == none)
                return false;
            indices.resize(keep);
            approximations.resize(keep);
            if constexpr (Observer::enabled)
                tail_ = TailPlacement{keep, itlsTailRepartitioned};
            std::vector<IndexType> tail;
            for (size_t y = w; y > 0; y = from[y])
                tail.emplace_back(from[y], y);
            for (auto it = tail.rbegin(); it != tail.rend(); ++it)
                emit(approximations, indices, prefix[it->second] - prefix[it->first], origin, ws + it->first, ws + it->second);
            return true;
        }
    };
}
