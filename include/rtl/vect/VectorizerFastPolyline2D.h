// Fast TLS 2D polyline vectorizers: VectorizerFTLSPolyline2D and VectorizerAFTLSPolyline2D.
//
// Both run FastPolylinePipeline2D.h (prefix sums, fast extraction, [total-error optimizer,] continuity repair with
// the exact partition search as the last resort, polyline of line crossings). Preconditions, checked: at least 2
// points, finite coordinates, sigma > 0 and delta > 0 (finite); otherwise operator() is false and the outputs are
// empty. Defaults: sigma 0.03, delta 3. Strict mode (default) matches RTL's return values; split mode is an addition.
#pragma once

#include <cstddef>
#include <optional>
#include <vector>

#include "rtl/core/Trace.h"
#include "rtl/vect/ApproximationTlsLine2D.h"
#include "rtl/vect/FastPolylinePipeline2D.h"
#include "rtl/vect/FtlsTrace.h"
#include "rtl/vect/PrecArrayBlocked.h"
#include "rtl/vect/VectorizerBase.h"

namespace rtl
{
    namespace detail
    {
        //! FTLS (optimize = false) and AFTLS (optimize = true) 2D polylines: see FastPolylinePipeline2D.h. An enabled
        //! Observer set by setObserver() receives the events of FtlsTrace.h (e.g. rtl::FtlsTraceLog).
        template<class PrecArray, class Approximation, bool optimize, class Observer = NoTrace>
        class VectorizerFastPolyline2D : public VectorizerBase<Approximation>
        {
            typedef VectorizerBase<Approximation> Base;
        public:
            using typename Base::ElementType; using typename Base::ComputeType; using typename Base::VectorType;
            using typename Base::ApproximationType; using typename Base::IndexType;
            typedef PrecArray PrecArrayType;
            typedef typename ApproximationType::ConstrainedType OutputType;

            void setSigma(ElementType sigma) { this->sigma = sigma; }
            void setDelta(ElementType delta) { this->delta = delta; }
            void setMaxSize(size_t size) { pipeline.setMaxSize(size); this->reserveBase(size); }
            //! Observer of the following calls (nullptr: none); it must outlive them.
            void setObserver(Observer *observer) { pipeline.setObserver(observer); }

            //! Split mode (an addition to RTL, default false = RTL's strict behaviour and return values): where a
            //! corner cannot be met within delta, the polyline breaks there, so the result is several polylines
            //! that together cover the chain. Where no partition into ranges of >= 2 points fitting sigma exists
            //! at all (e.g. 3 points forming a corner), consecutive ranges may share one point (see indices()), so
            //! split mode returns false only for invalid input (< 2 points, non-finite, invalid sigma or delta).
            void setSplitAtInfeasibleCorners(bool split) { pipeline.setSplit(split); }
            [[nodiscard]] bool splitAtInfeasibleCorners() const { return pipeline.split(); }

            bool operator()(const std::vector<VectorType> &pts)
            {
                if (pts.size() < 2 || !validParameter(this->sigma) || !validParameter(delta) ||
                    !pipeline(pts, this->sigma, delta, this->approx, this->idx))
                {
                    this->fail();
                    pipeline.clearOutputs(pts, this->approx, this->idx);
                    return false;
                }
                return true;
            }
            //! Half-open chain ranges [first, end) of the segments, in chain order. Strict mode: a partition of
            //! [0, N). Split mode: they cover [0, N) in order and adjoin (next first == end), except that they may
            //! overlap by one point (next first == end - 1) on chains that no partition fits; a corner at such a
            //! shared point is continuous when the lines cross within delta of it, else a break.
            const std::vector<IndexType> &indices() const { return this->idx; }
            //! The segments of all polylines, in chain order (segment i lies on approximations()[i]).
            std::vector<OutputType> lineSegments() const { return pipeline.lineSegments(); }
            //! Polyline vertices: segments + 1 per polyline, polyline after polyline (one polyline unless split).
            const std::vector<VectorType> &vertices() const { return pipeline.vertices(); }
            //! Segment index where each polyline starts, then the segment count ({0, n} for one polyline; {0, 0}
            //! after a false return). Polyline p has segments [o[p], o[p+1]) and vertices [o[p] + p, o[p+1] + p].
            const std::vector<size_t> &polylineOffsets() const { return pipeline.polylineOffsets(); }
            //! Split mode: each break (boundary = first chain index of the range that starts a new polyline, the
            //! crossing distance of the two lines there, from the boundary midpoint or the shared point, delta);
            //! empty when none.
            const std::vector<CornerReport> &breaks() const { return pipeline.breaks(); }
            //! Strict mode, after a false return because no partition meets delta: the corner that cannot be met
            //! (the furthest one the exact search reached, with the smallest crossing distance tried there);
            //! empty otherwise (success, invalid input).
            const std::optional<CornerReport> &failure() const { return pipeline.failure(); }

        protected:
            ElementType delta{3};
            FastPolylinePipeline2D<PrecArrayType, ApproximationType, optimize, Observer> pipeline;
        };
    }

    //! FTLS: prefix sums, fast chain extraction, continuity repair (exact search as the last resort), polyline of
    //! line crossings. Additions to RTL: setSplitAtInfeasibleCorners, polylineOffsets, breaks, failure, Observer.
    template<typename Element, typename Compute, class Observer = NoTrace>
    class VectorizerFTLSPolyline2D
        : public detail::VectorizerFastPolyline2D<PrecArrayBlocked<2, Element, Compute>, ApproximationTlsLine2D<Element, Compute>, false, Observer>
    {
    public:
        VectorizerFTLSPolyline2D() = default;
        ~VectorizerFTLSPolyline2D() = default;
    };

    //! AFTLS: FTLS with the total-error optimizer between extraction and continuity repair; keeps FTLS's
    //! candidate when that has the lower total squared error (so AFTLS is never worse than FTLS).
    template<typename Element, typename Compute, class Observer = NoTrace>
    class VectorizerAFTLSPolyline2D
        : public detail::VectorizerFastPolyline2D<PrecArrayBlocked<2, Element, Compute>, ApproximationTlsLine2D<Element, Compute>, true, Observer>
    {
    public:
        VectorizerAFTLSPolyline2D() = default;
        ~VectorizerAFTLSPolyline2D() = default;
        void setSimplexShift(size_t simplex_shift) { this->pipeline.optimizer().setSimplexShift(simplex_shift); }
        void setMaxIterations(size_t max_iterations) { this->pipeline.optimizer().setMaxIterations(max_iterations); }
    };
}
