// Fast TLS 3D vectorizers: VectorizerFTLSProjections3D, VectorizerAFTLSProjections3D (lines) and
// VectorizerAFTLSPlaneProjections3D (plane polygons).
//
// Pipeline: blocked prefix sums -> fast extraction -> [total-error optimizer] -> each range's primitive trimmed by
// the projections of its points. Preconditions, checked: at least 2 points, finite coordinates, sigma > 0 and
// finite; otherwise operator() is false and the outputs are empty. Also false when the element type cannot hold
// the result (see VectorizerFast3D).
#pragma once

#include <cstddef>
#include <vector>

#include "rtl/vect/ApproximationTlsLine3D.h"
#include "rtl/vect/ApproximationTlsPlane3D.h"
#include "rtl/vect/ExtractorChainFast.h"
#include "rtl/vect/OptimizerTotalError.h"
#include "rtl/vect/PostprocessorProjectEndpoints.h"
#include "rtl/vect/PrecArrayBlocked.h"
#include "rtl/vect/VectorizerBase.h"

namespace rtl
{
    namespace detail
    {
        //! Prefix sums -> fast extraction -> [total-error optimizer] -> projected end points, for 3D primitives.
        //! False also when ElementType cannot hold the result (an errSquared() or output vertex overflows it: float
        //! points beyond ~1.8e19 can give that; see PostprocessorProjectEndpoints::representable).
        template<class Approximation, bool optimize>
        class VectorizerFast3D : public VectorizerBase<Approximation>
        {
            typedef VectorizerBase<Approximation> Base;
        public:
            using typename Base::ElementType; using typename Base::ComputeType; using typename Base::VectorType;
            using typename Base::ApproximationType; using typename Base::IndexType;
            // Blocked prefix sums for both: the optimizer's evaluations are capped (setMaxIterations), so the full
            // array's 72 B per point of row writes would dominate long chains (AFTLS would grow superlinearly).
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
                // A result ElementType cannot hold (float coordinates beyond ~1.8e19) is rejected: false.
                return (post(pts, this->approx, this->idx) && post.representable(this->approx)) || failAll(pts);
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
    class VectorizerFTLSProjections3D : public detail::VectorizerFast3D<ApproximationTlsLine3D<Element, Compute>, false>
    {
    public:
        VectorizerFTLSProjections3D() = default;
        ~VectorizerFTLSProjections3D() = default;
        const std::vector<typename ApproximationTlsLine3D<Element, Compute>::ConstrainedType> &lineSegments() const { return this->post.output(); }
    };

    //! AFTLS 3D lines (total-error optimizer), trimmed by the projections of each range's end points.
    template<typename Element, typename Compute>
    class VectorizerAFTLSProjections3D : public detail::VectorizerFast3D<ApproximationTlsLine3D<Element, Compute>, true>
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
    class VectorizerAFTLSPlaneProjections3D : public detail::VectorizerFast3D<ApproximationTlsPlane3D<Element, Compute>, true>
    {
    public:
        VectorizerAFTLSPlaneProjections3D() = default;
        ~VectorizerAFTLSPlaneProjections3D() = default;
        void setSimplexShift(size_t simplex_shift) { this->optimizer.setSimplexShift(simplex_shift); }
        void setMaxIterations(size_t max_iterations) { this->optimizer.setMaxIterations(max_iterations); }
        const std::vector<typename ApproximationTlsPlane3D<Element, Compute>::ConstrainedType> &polygons() const { return this->post.output(); }
    };
}
