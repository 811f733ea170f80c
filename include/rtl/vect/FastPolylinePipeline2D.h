// FastPolylinePipeline2D: the stages of VectorizerFTLSPolyline2D (optimize = false) and VectorizerAFTLSPolyline2D
// (optimize = true), shared so that both decide feasibility, failures and split mode the same way.
//
//   extraction (ExtractorChainFast) -> [AFTLS: total-error optimizer] -> continuity repair -> polyline
// - The continuity repair ends, when its local repairs fail, in the exact search (PartitionSearch2D), and so does
//   a failed extraction: a false return proves that no partition meets sigma and delta.
// - AFTLS also keeps FTLS's candidate (extraction -> continuity, without the optimizer) and returns whichever has
//   the lower total squared error, so its error never exceeds FTLS's (the repair after the optimizer could
//   raise it above the extractor's).
// - Strict mode (default, RTL's behaviour): false when no partition exists; failure() names the corner.
//   Split mode (setSplitAtInfeasibleCorners(true)): the exact search may break the polyline at
//   corners that cannot be met within delta (fewest breaks), so the result is several polylines covering the
//   whole chain; polylineOffsets() and breaks() describe them. Where no partition into fitting ranges exists at
//   all (e.g. 3, 5 or 7 points whose short ranges do not fit), PartitionSearch2D::cover() lets consecutive ranges
//   share one point, so split mode returns false only for invalid input (fewer than 2 points, non-finite points,
//   invalid sigma or delta).
// - A result that ElementType cannot hold (an errSquared() or a polyline vertex that overflows it, e.g. float
//   points beyond ~1e19 whose squared residuals exceed FLT_MAX) is rejected: false, with no failure() corner
//   rather than returning true with infinite numbers.
// - Observer (last, default NoTrace): the events of FtlsTrace.h, from every stage.
#pragma once

#include <cmath>
#include <cstddef>
#include <limits>
#include <optional>
#include <utility>
#include <vector>

#include "rtl/core/Trace.h"
#include "rtl/vect/ExtractorChainFast.h"
#include "rtl/vect/FtlsTrace.h"
#include "rtl/vect/OptimizerContinuity2D.h"
#include "rtl/vect/OptimizerTotalError.h"
#include "rtl/vect/PartitionSearch2D.h"
#include "rtl/vect/PostprocessorPolyline2D.h"

namespace rtl::detail
{
    template<class PrecArrayType, class Approximation, bool optimize, class Observer = NoTrace>
    class FastPolylinePipeline2D
    {
    public:
        typedef typename Approximation::ElementType ElementType;
        typedef typename Approximation::ComputeType ComputeType;
        typedef typename Approximation::VectorType VectorType;
        typedef typename Approximation::ConstrainedType OutputType;
        typedef std::pair<size_t, size_t> IndexType;

        void setMaxSize(size_t size)
        {
            prec.resize(size);
            if constexpr (optimize)
            {
                cand_lines.reserve(size / 2 + 1);
                cand_idx.reserve(size / 2 + 1);
            }
            offsets.reserve(2);
        }
        void setSplit(bool split) { split_ = split; }
        [[nodiscard]] bool split() const { return split_; }
        OptimizerTotalError<PrecArrayType, Approximation, Observer> &optimizer() { return optimizer_; }
        void setObserver(Observer *observer)
        {
            observer_ = observer;
            extractor.setObserver(observer);
            optimizer_.setObserver(observer);
            continuity.setObserver(observer, 0);
        }

        //! Runs the stages on finite points with valid sigma and delta; false (outputs to be cleared by the caller)
        //! if no valid result exists or the points are not finite.
        bool operator()(const std::vector<VectorType> &pts, ElementType sigma, ElementType delta, std::vector<Approximation> &lines,
                        std::vector<IndexType> &idx)
        {
            failure_.reset();
            breaks_.clear();
            multi = false;
            prec.precompute(pts);
            if (!prec.allFinite())
                return false;
            if constexpr (Observer::enabled)
                report(FtlsStart{pts.size(), static_cast<double>(sigma), static_cast<double>(delta), optimize, split_});
            extractor.setSigma(sigma);
            continuity.setSigma(sigma);
            continuity.setDelta(delta);
            search.setSigma(sigma);
            search.setDelta(delta);
            bool ok = extractor(prec, lines, idx);
            if (ok)
            {
                if constexpr (optimize)
                {
                    cand_lines = lines;
                    cand_idx = idx;
                    continuity.keepExactSearch(true);   // both branches ending in the exact search: searched once
                    const bool ftls_ok = continuity(pts, prec, cand_lines, cand_idx);
                    optimizer_.setSigma(sigma);
                    if constexpr (Observer::enabled)
                        continuity.setObserver(observer_, 1);
                    ok = optimizer_(pts, prec, lines, idx) && continuity(pts, prec, lines, idx);
                    continuity.keepExactSearch(false);
                    if constexpr (Observer::enabled)
                    {
                        continuity.setObserver(observer_, 0);
                        if (ftls_ok || ok)
                        {
                            const double inf = std::numeric_limits<double>::infinity();
                            const double ef = ftls_ok ? static_cast<double>(totalError(cand_lines)) : inf;
                            const double ea = ok ? static_cast<double>(totalError(lines)) : inf;
                            report(FtlsChoice{ef, ea, ftls_ok && (!ok || totalError(cand_lines) < totalError(lines)) ? 0 : 1});
                        }
                    }
                    if (ftls_ok && (!ok || totalError(cand_lines) < totalError(lines)))
                    {
                        lines.swap(cand_lines);
                        idx.swap(cand_idx);
                        ok = true;
                    }
                }
                else
                    ok = continuity(pts, prec, lines, idx);
                if (!ok)
                    failure_ = continuity.failure();
            }
            else
            {
                search.setAllowBreaks(false);
                ok = search(pts, prec, lines, idx);
                if (!ok)
                    failure_ = search.failure();
                else if constexpr (Observer::enabled)
                    reportRanges(FtlsExactSearch, pts.size(), idx);
            }
            if constexpr (Observer::enabled)
                if (!ok && failure_)
                    report(FtlsInfeasible{failure_->boundary, failure_->crossingDistance, failure_->delta});
            if (!ok && split_)
            {
                search.setAllowBreaks(true);
                ok = search(pts, prec, lines, idx);
                int method = FtlsSplitSearch;
                if (!ok)
                {
                    // No partition into fitting ranges at all: cover with ranges that may share a point.
                    ok = search.cover(pts, prec, lines, idx);
                    method = FtlsCoverSearch;
                }
                if (ok)
                {
                    if constexpr (Observer::enabled)
                        reportRanges(method, pts.size(), idx);
                    breaks_ = search.breaks();
                    multi = search.polylineStarts().size() > 1;
                }
            }
            if (!ok)
                return false;
            failure_.reset();
            if (!makePolylines(pts, lines, idx) || !representable(lines))
                return false;
            if constexpr (Observer::enabled)
                if (observer_)
                {
                    const auto segs = lineSegments();
                    for (size_t p = 0; p + 1 < offsets.size(); ++p)
                        for (size_t i = offsets[p]; i < offsets[p + 1]; ++i)
                            report(FtlsSegment{i, idx[i].first, idx[i].second, p, static_cast<double>(segs[i].beg().x()),
                                               static_cast<double>(segs[i].beg().y()), static_cast<double>(segs[i].end().x()),
                                               static_cast<double>(segs[i].end().y())});
                }
            return true;
        }

        //! Builds the outputs for `lines` (empty after a failure), as a single polyline.
        void clearOutputs(const std::vector<VectorType> &pts, const std::vector<Approximation> &lines, const std::vector<IndexType> &idx)
        {
            multi = false;
            breaks_.clear();
            polyline(pts, lines, idx);
            offsets.clear();
            offsets.push_back(0);
            offsets.push_back(0);
        }

        std::vector<OutputType> lineSegments() const { return multi ? segments_ : polyline.lineSegments(); }
        const std::vector<VectorType> &vertices() const { return multi ? vertices_ : polyline.vertices(); }
        const std::vector<size_t> &polylineOffsets() const { return offsets; }
        const std::vector<CornerReport> &breaks() const { return breaks_; }
        const std::optional<CornerReport> &failure() const { return failure_; }
        //! Work of both exact searches (the continuity repair's and the extraction fallback's / split mode's)
        //! since construction: fits, corner tests and states (PartitionSearch2D::Work).
        typename PartitionSearch2D<PrecArrayType, Approximation>::Work searchWork() const
        {
            auto w = continuity.searchWork();
            const auto &v = search.work();
            w.fits += v.fits;
            w.corners += v.corners;
            w.states += v.states;
            w.bounded += v.bounded;
            return w;
        }

    private:
        PrecArrayType prec;
        ExtractorChainFast<PrecArrayType, Approximation, Observer> extractor;
        OptimizerTotalError<PrecArrayType, Approximation, Observer> optimizer_;
        OptimizerContinuity2D<PrecArrayType, Approximation, Observer> continuity;
        Observer *observer_{nullptr};

        template<class Event>
        void report(const Event &e) const
        {
            if (observer_)
                (*observer_)(e);
        }
        void reportRanges(int method, size_t n, const std::vector<IndexType> &idx) const
        {
            if (!observer_)
                return;
            (*observer_)(FtlsRepair{0, method, 0, n, idx.size()});
            for (const auto &r : idx)
                (*observer_)(FtlsRepairRange{r.first, r.second});
        }
        PartitionSearch2D<PrecArrayType, Approximation> search;
        PostprocessorPolyline2D<Approximation> polyline;
        std::vector<Approximation> cand_lines;
        std::vector<IndexType> cand_idx;
        bool split_{false}, multi{false};
        std::optional<CornerReport> failure_;
        std::vector<CornerReport> breaks_;
        std::vector<size_t> offsets;
        std::vector<OutputType> segments_;
        std::vector<VectorType> vertices_;

        //! Every errSquared() and vertex finite in ElementType.
        bool representable(const std::vector<Approximation> &lines) const
        {
            for (const auto &l : lines)
                if (!std::isfinite(static_cast<double>(l.errSquared())))
                    return false;
            for (const auto &v : vertices())
                if (!std::isfinite(static_cast<double>(v.x())) || !std::isfinite(static_cast<double>(v.y())))
                    return false;
            return true;
        }

        static ComputeType totalError(const std::vector<Approximation> &lines)
        {
            ComputeType s = 0;
            for (const auto &l : lines)
                s += l.errSquaredCompute() * l.count();
            return s;
        }

        bool makePolylines(const std::vector<VectorType> &pts, const std::vector<Approximation> &lines, const std::vector<IndexType> &idx)
        {
            offsets.clear();
            if (!multi)
            {
                offsets.push_back(0);
                offsets.push_back(lines.size());
                return polyline(pts, lines, idx);
            }
            const auto &starts = search.polylineStarts();
            segments_.clear();
            vertices_.clear();
            for (size_t p = 0; p < starts.size(); ++p)
            {
                const size_t b = starts[p], e = p + 1 < starts.size() ? starts[p + 1] : lines.size();
                const std::vector<Approximation> sub_lines(lines.begin() + static_cast<std::ptrdiff_t>(b), lines.begin() + static_cast<std::ptrdiff_t>(e));
                const std::vector<IndexType> sub_idx(idx.begin() + static_cast<std::ptrdiff_t>(b), idx.begin() + static_cast<std::ptrdiff_t>(e));
                if (!polyline(pts, sub_lines, sub_idx))
                    return false;
                const auto segs = polyline.lineSegments();
                segments_.insert(segments_.end(), segs.begin(), segs.end());
                vertices_.insert(vertices_.end(), polyline.vertices().begin(), polyline.vertices().end());
                offsets.push_back(b);
            }
            offsets.push_back(lines.size());
            return true;
        }
    };
}
