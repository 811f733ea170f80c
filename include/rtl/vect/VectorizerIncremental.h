// Incremental TLS vectorizers (ITLS) for 2D and 3D lines: VectorizerITLSProjections2D / 3D.
//
// Pipeline: input checks (VectorizerBase.h) -> incremental extraction (ExtractorChainIncremental.h) -> each range's
// line trimmed by the projections of its end points (PostprocessorProjectEndpoints.h). Preconditions, checked:
// at least 2 points, sigma > 0 and finite, every |coordinate| within momentSafeLimit; otherwise operator() is
// false and the outputs are empty. Cost: that of the extractor (linear in the points for typical chains).
#pragma once

#include <cstddef>
#include <vector>

#include "rtl/core/Trace.h"
#include "rtl/vect/ApproximationTlsLine2D.h"
#include "rtl/vect/ApproximationTlsLine3D.h"
#include "rtl/vect/ExtractorChainIncremental.h"
#include "rtl/vect/PostprocessorProjectEndpoints.h"
#include "rtl/vect/SimplifyTrace.h"
#include "rtl/vect/VectorizerBase.h"

namespace rtl
{
    namespace detail
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
    //! detail::momentSafeLimit<Compute>(n) (= sqrt(max / n) / 8: ~1e150 for double sums of 1e6 points), where
    //! the sums would overflow. Observer: see
    //! detail::VectorizerIncremental (e.g. rtl::ItlsTraceLog).
    template<typename Element, typename Compute, class Observer = NoTrace>
    class VectorizerITLSProjections2D : public detail::VectorizerIncremental<ApproximationTlsLine2D<Element, Compute>, Observer>
    {
    public:
        VectorizerITLSProjections2D() = default;
        ~VectorizerITLSProjections2D() = default;
    };

    //! Incremental TLS 3D lines, trimmed by the projections of each range's end points. Observer as in 2D.
    template<typename Element, typename Compute, class Observer = NoTrace>
    class VectorizerITLSProjections3D : public detail::VectorizerIncremental<ApproximationTlsLine3D<Element, Compute>, Observer>
    {
    public:
        VectorizerITLSProjections3D() = default;
        ~VectorizerITLSProjections3D() = default;
    };
}
