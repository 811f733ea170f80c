// VectorizerBase: the state every TLS vectorizer shares, and the input checks they apply before any stage runs.
//
// VectorizerBase keeps the approximations and half-open index ranges of the last call (empty after a failed one)
// and sigma (default 0.03). The checks are linear passes over the points without an early exit (so they
// vectorise); momentSafeLimit bounds the coordinates whose moment sums cannot overflow the compute type.
#pragma once

#include <cmath>
#include <cstddef>
#include <limits>
#include <type_traits>
#include <utility>
#include <vector>

#include <Eigen/Dense>

#include "rtl/core/CoordinateCheck.h"

namespace rtl
{
    namespace detail
    {
        //! Every coordinate within [-limit, limit] (false for NaN): rtl::detail::firstBeyond (core/CoordinateCheck.h)
        //! over the points' coordinates, one pass without a branch per number.
        template<class V>
        bool allWithin(const std::vector<V> &pts, double limit)
        {
            typedef std::remove_cv_t<std::remove_reference_t<decltype(pts.front().data()(0))>> E;
            typedef std::remove_cv_t<std::remove_reference_t<decltype(pts.front().data())>> Storage;
            constexpr auto rows = Storage::SizeAtCompileTime;
            if constexpr (rows > 0 && sizeof(V) == rows * sizeof(E))
            {
                // fixed-size points stored back to back: one array of coordinates
                if (pts.empty()) return true;
                const std::size_t count = pts.size() * static_cast<std::size_t>(rows);
                return firstBeyond(&pts.front().data()(0), count, limit, false) == count;
            }
            else
            {
                for (const auto &p : pts)
                {
                    const auto count = static_cast<std::size_t>(p.data().size());
                    if (firstBeyond(p.data().data(), count, limit, false) != count) return false;
                }
                return true;
            }
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
}
