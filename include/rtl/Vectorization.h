// Vectorization: ordered point chains -> line segments (2D, 3D) or plane polygons (3D).
//
// Every Vectorizer* runs a fixed pipeline of the vect/ stages and returns false as soon as a stage fails; the
// results of the last call stay available through approximations(), indices() and the output accessor.
// Common preconditions, checked: at least 2 points, all coordinates finite, sigma > 0 (and delta > 0 where
// used); otherwise operator() returns false and the outputs are empty. Defaults: sigma 0.03, delta 3.
// setMaxSize(n) sizes the internal buffers for chains of up to n points, so later calls do not allocate for them.
#pragma once

#include <cmath>
#include <limits>
#include <list>
#include <map>
#include <optional>
#include <tuple>
#include <type_traits>
#include <utility>
#include <vector>

#include <Eigen/Dense>
#include <Eigen/Eigenvalues>

#include "rtl/Core.h"
#include "rtl/core/Trace.h"
#include "rtl/vect/ApproximationTlsLine2D.h"
#include "rtl/vect/ApproximationTlsLine3D.h"
#include "rtl/vect/ApproximationTlsPlane3D.h"
#include "rtl/vect/ExtractorChainFast.h"
#include "rtl/vect/ExtractorChainIncremental.h"
#include "rtl/vect/FastPolylinePipeline2D.h"
#include "rtl/vect/FtlsTrace.h"
#include "rtl/vect/OptimizerContinuity2D.h"
#include "rtl/vect/OptimizerTotalError.h"
#include "rtl/vect/PostprocessorPolyline2D.h"
#include "rtl/vect/PostprocessorProjectEndpoints.h"
#include "rtl/vect/PrecArray.h"
#include "rtl/vect/PrecArrayBlocked.h"
#include "rtl/vect/PrecSums.h"
#include "rtl/vect/ScanPolylines2D.h"
#include "rtl/vect/SimplifyCompatible.h"
#include "rtl/vect/SimplifyTrace.h"
#include "rtl/vect/VectorizerPointElimination.h"

namespace rtl
{
    namespace vect_detail
    {
        //! Every coordinate within [-limit, limit] (false for NaN). An integer AND over all coordinates, without an
        //! early exit, vectorises: this pass costs a fraction of a nanosecond per point instead of a branch per point.
        template<class V>
        bool allWithin(const std::vector<V> &pts, double limit)
        {
            typedef std::remove_cv_t<std::remove_reference_t<decltype(pts.front().data()(0))>> E;
            const E max = std::numeric_limits<E>::max();
            const E lim = limit >= static_cast<double>(max) ? max : static_cast<E>(limit);
            int ok = 1;
            for (const auto &p : pts)
                for (Eigen::Index k = 0; k < p.data().size(); ++k)
                    ok &= static_cast<int>(std::abs(p.data()(k)) <= lim);
            return ok != 0;
        }

        //! No NaN or infinite coordinate (|v| <= max is false exactly for those).
        template<class V>
        bool allFinite(const std::vector<V> &pts)
        {
            typedef std::remove_cv_t<std::remove_reference_t<decltype(pts.front().data()(0))>> E;
            return allWithin(pts, static_cast<double>(std::numeric_limits<E>::max()));
        }

        //! The largest |coordinate| for which n points' moments about a range's first point cannot overflow C:
        //! n * (2c)^2 <= max(C), with a factor 4 to spare for the cross terms and the error test.
        template<typename C>
        double momentSafeLimit(std::size_t n)
        {
            return std::sqrt(static_cast<double>(std::numeric_limits<C>::max()) / static_cast<double>(n > 0 ? n : 1)) / 8.0;
        }

        template<typename E>
        bool validParameter(E v) { return v > E(0) && std::isfinite(static_cast<double>(v)); }

        //! Shared state of the vectorizers: approximations and index ranges of the last call.
        template<class Approximation>
        class VectorizerBase
        {
        public:
            typedef typename Approximation::ElementType ElementType;
            typedef typename Approximation::ComputeType ComputeType;
            typedef typename Approximation::VectorType VectorType;
            typedef Approximation ApproximationType;
            typedef std::pair<size_t, size_t> IndexType;

            const std::vector<ApproximationType> &approximations() const { return approx; }
            const std::vector<IndexType> &indices() const { return idx; }

        protected:
            std::vector<ApproximationType> approx;
            std::vector<IndexType> idx;
            ElementType sigma{static_cast<ElementType>(0.03)};

            void reserveBase(size_t size) { approx.reserve(size / 2 + 1); idx.reserve(size / 2 + 1); }
            bool fail() { approx.clear(); idx.clear(); return false; }
        };
    }

    namespace vect_detail
    {
        //! Incremental TLS extraction -> projected end points, for 2D and 3D lines. An enabled Observer set by
        //! setObserver() receives the extractor's events and then one ItlsSegment per final range (SimplifyTrace.h).
        template<class Approximation, class Observer = NoTrace>
        class VectorizerIncremental : public VectorizerBase<Approximation>
        {
            typedef VectorizerBase<Approximation> Base;
        public:
            using typename Base::ElementType; using typename Base::ComputeType; using typename Base::VectorType;
            using typename Base::ApproximationType; using typename Base::IndexType;
            typedef typename ApproximationType::ConstrainedType OutputType;

            void setSigma(ElementType sigma) { this->sigma = sigma; }
            void setMaxSize(size_t size) { this->reserveBase(size); }
            //! Observer of the following calls (nullptr: none); it must outlive them.
            void setObserver(Observer *observer) { observer_ = observer; extractor.setObserver(observer); }

            bool operator()(const std::vector<VectorType> &pts)
            {
                // Coordinates whose squared moments would overflow ComputeType (|c| > momentSafeLimit, ~1e150 for
                // double sums of a million points) are rejected like non-finite ones: their fits would be inf or NaN
                // and ranges beyond sigma would pass (found by fuzz_vect_simplify).
                if (pts.size() < 2 || !validParameter(this->sigma) ||
                    !allWithin(pts, momentSafeLimit<ComputeType>(pts.size())) ||
                    (extractor.setSigma(this->sigma), !extractor(pts, this->approx, this->idx)) || !post(pts, this->approx, this->idx))
                {
                    this->fail();
                    post(pts, this->approx, this->idx);
                    return false;
                }
                if constexpr (Observer::enabled)
                    if (observer_)
                        reportSegments();
                return true;
            }
            const std::vector<OutputType> &lineSegments() const { return post.output(); }

        private:
            void reportSegments() const
            {
                constexpr int dims = VectorType::dimensionality();
                for (size_t r = 0; r < this->idx.size(); ++r)
                {
                    const auto &seg = post.output()[r];
                    const auto b = seg.beg(), e = seg.end();
                    (*observer_)(ItlsSegment{r, this->idx[r].first, this->idx[r].second, dims,
                                             static_cast<double>(b[0]), static_cast<double>(b[1]), dims == 3 ? static_cast<double>(b[dims - 1]) : 0.0,
                                             static_cast<double>(e[0]), static_cast<double>(e[1]), dims == 3 ? static_cast<double>(e[dims - 1]) : 0.0});
                }
            }

            Observer *observer_{nullptr};
            ExtractorChainIncremental<ApproximationType, Observer> extractor;
            PostprocessorProjectEndpoints<ApproximationType> post;
        };
    }

    //! Incremental TLS lines, trimmed by the projections of each range's end points. operator() is false for fewer
    //! than 2 points, an invalid sigma, a non-finite coordinate, or a coordinate beyond
    //! vect_detail::momentSafeLimit<Compute>(n) (= sqrt(max / n) / 8: ~1e150 for double sums of 1e6 points), where
    //! the sums would overflow. Observer: see
    //! vect_detail::VectorizerIncremental (e.g. rtl::ItlsTraceLog).
    template<typename Element, typename Compute, class Observer = NoTrace>
    class VectorizerITLSProjections2D : public vect_detail::VectorizerIncremental<ApproximationTlsLine2D<Element, Compute>, Observer>
    {
    public:
        VectorizerITLSProjections2D() = default;
        ~VectorizerITLSProjections2D() = default;
    };

    namespace vect_detail
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
        : public vect_detail::VectorizerFastPolyline2D<PrecArrayBlocked<2, Element, Compute>, ApproximationTlsLine2D<Element, Compute>, false, Observer>
    {
    public:
        VectorizerFTLSPolyline2D() = default;
        ~VectorizerFTLSPolyline2D() = default;
    };

    //! AFTLS: FTLS with the total-error optimizer between extraction and continuity repair; keeps FTLS's
    //! candidate when that has the lower total squared error (so AFTLS is never worse than FTLS).
    template<typename Element, typename Compute, class Observer = NoTrace>
    class VectorizerAFTLSPolyline2D
        : public vect_detail::VectorizerFastPolyline2D<PrecArrayBlocked<2, Element, Compute>, ApproximationTlsLine2D<Element, Compute>, true, Observer>
    {
    public:
        VectorizerAFTLSPolyline2D() = default;
        ~VectorizerAFTLSPolyline2D() = default;
        void setSimplexShift(size_t simplex_shift) { this->pipeline.optimizer().setSimplexShift(simplex_shift); }
        void setMaxIterations(size_t max_iterations) { this->pipeline.optimizer().setMaxIterations(max_iterations); }
    };

    //! Incremental TLS 3D lines, trimmed by the projections of each range's end points. Observer as in 2D.
    template<typename Element, typename Compute, class Observer = NoTrace>
    class VectorizerITLSProjections3D : public vect_detail::VectorizerIncremental<ApproximationTlsLine3D<Element, Compute>, Observer>
    {
    public:
        VectorizerITLSProjections3D() = default;
        ~VectorizerITLSProjections3D() = default;
    };

    namespace vect_detail
    {
        //! Prefix sums -> fast extraction -> [total-error optimizer] -> projected end points, for 3D primitives.
        template<class Approximation, bool optimize>
        class VectorizerFast3D : public VectorizerBase<Approximation>
        {
            typedef VectorizerBase<Approximation> Base;
        public:
            using typename Base::ElementType; using typename Base::ComputeType; using typename Base::VectorType;
            using typename Base::ApproximationType; using typename Base::IndexType;
            // Blocked prefix sums for both: the optimizer's evaluations are capped (setMaxIterations), so the full
            // array's 72 B per point of row writes would dominate long chains (AFTLS superlinear, issue 17 item 3).
            typedef PrecArrayBlocked<3, ElementType, ComputeType> PrecArrayType;
            typedef typename ApproximationType::ConstrainedType OutputType;

            void setMaxSize(size_t size) { prec.resize(size); this->reserveBase(size); }
            void setSigma(ElementType sigma) { this->sigma = sigma; }

            bool operator()(const std::vector<VectorType> &pts)
            {
                if (pts.size() < 2 || !validParameter(this->sigma))
                    return failAll(pts);
                prec.precompute(pts);
                if (!prec.allFinite())
                    return failAll(pts);
                extractor.setSigma(this->sigma);
                if (!extractor(prec, this->approx, this->idx))
                    return failAll(pts);
                if constexpr (optimize)
                {
                    optimizer.setSigma(this->sigma);
                    if (!optimizer(pts, prec, this->approx, this->idx))
                        return failAll(pts);
                }
                return post(pts, this->approx, this->idx) || failAll(pts);
            }

        protected:
            bool failAll(const std::vector<VectorType> &pts) { this->fail(); post(pts, this->approx, this->idx); return false; }
            PrecArrayType prec;
            ExtractorChainFast<PrecArrayType, ApproximationType> extractor;
            OptimizerTotalError<PrecArrayType, ApproximationType> optimizer;
            PostprocessorProjectEndpoints<ApproximationType> post;
        };
    }

    //! FTLS 3D lines, trimmed by the projections of each range's end points.
    template<typename Element, typename Compute>
    class VectorizerFTLSProjections3D : public vect_detail::VectorizerFast3D<ApproximationTlsLine3D<Element, Compute>, false>
    {
    public:
        VectorizerFTLSProjections3D() = default;
        ~VectorizerFTLSProjections3D() = default;
        const std::vector<typename ApproximationTlsLine3D<Element, Compute>::ConstrainedType> &lineSegments() const { return this->post.output(); }
    };

    //! AFTLS 3D lines (total-error optimizer), trimmed by the projections of each range's end points.
    template<typename Element, typename Compute>
    class VectorizerAFTLSProjections3D : public vect_detail::VectorizerFast3D<ApproximationTlsLine3D<Element, Compute>, true>
    {
    public:
        typedef typename ApproximationTlsLine3D<Element, Compute>::ConstrainedType LineSegmentType;
        VectorizerAFTLSProjections3D() = default;
        ~VectorizerAFTLSProjections3D() = default;
        void setSimplexShift(size_t simplex_shift) { this->optimizer.setSimplexShift(simplex_shift); }
        void setMaxIterations(size_t max_iterations) { this->optimizer.setMaxIterations(max_iterations); }
        const std::vector<LineSegmentType> &lineSegments() const { return this->post.output(); }
    };

    //! AFTLS 3D planes: polygons of each range's points projected onto its fitted plane.
    template<typename Element, typename Compute>
    class VectorizerAFTLSPlaneProjections3D : public vect_detail::VectorizerFast3D<ApproximationTlsPlane3D<Element, Compute>, true>
    {
    public:
        VectorizerAFTLSPlaneProjections3D() = default;
        ~VectorizerAFTLSPlaneProjections3D() = default;
        void setSimplexShift(size_t simplex_shift) { this->optimizer.setSimplexShift(simplex_shift); }
        void setMaxIterations(size_t max_iterations) { this->optimizer.setMaxIterations(max_iterations); }
        const std::vector<typename ApproximationTlsPlane3D<Element, Compute>::ConstrainedType> &polygons() const { return this->post.output(); }
    };

    using VectorizerDouglasPeucker2f = VectorizerDouglasPeuckerND<2, float>;
    using VectorizerDouglasPeucker2d = VectorizerDouglasPeuckerND<2, double>;
    using VectorizerDouglasPeucker3f = VectorizerDouglasPeuckerND<3, float>;
    using VectorizerDouglasPeucker3d = VectorizerDouglasPeuckerND<3, double>;
    using VectorizerReumannWitkam2f = VectorizerReumannWitkamND<2, float>;
    using VectorizerReumannWitkam2d = VectorizerReumannWitkamND<2, double>;
    using VectorizerReumannWitkam3f = VectorizerReumannWitkamND<3, float>;
    using VectorizerReumannWitkam3d = VectorizerReumannWitkamND<3, double>;
}
