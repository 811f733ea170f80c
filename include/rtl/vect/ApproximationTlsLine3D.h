// ApproximationTlsLine3D: total-least-squares line of a 3D point set from its PrecSums: through the centroid
// along the covariance eigenvector of the largest eigenvalue; errSquared() is the sum of the two smaller
// eigenvalues (mean squared orthogonal distance). Geometry is kept in ComputeType.
#pragma once

#include <algorithm>
#include <cmath>
#include <iterator>

#include <Eigen/Dense>

#include "rtl/core/LineSegmentND.h"
#include "rtl/core/VectorND.h"
#include "rtl/vect/PrecSums.h"
#include "rtl/vect/TlsDetail.h"

namespace rtl
{
    template<typename Element, typename Compute>
    class ApproximationTlsLine3D
    {
    public:
        typedef Element ElementType;
        typedef Compute ComputeType;
        typedef VectorND<3, ElementType> VectorType;
        typedef LineSegmentND<3, ElementType> ConstrainedType;
        typedef PrecSums3D<ComputeType> PrecSumsType;
        typedef Eigen::Matrix<ComputeType, 3, 1> ComputeEigen;

        ApproximationTlsLine3D() = default;
        explicit ApproximationTlsLine3D(PrecSumsType ps) { operator()(ps); }
        ~ApproximationTlsLine3D() = default;

        [[nodiscard]] VectorType direction() const { return VectorType(EigenVec(dir.template cast<ElementType>())); }
        //! The centroid of the fitted points.
        [[nodiscard]] VectorType point() const { return VectorType(EigenVec(centroid.template cast<ElementType>())); }
        [[nodiscard]] ElementType errSquared() const { return static_cast<ElementType>(err); }
        [[nodiscard]] ComputeType errSquaredCompute() const { return err; }
        [[nodiscard]] ComputeType count() const { return n; }

        //! Refits from sums. Coincident points (or an empty set) give the direction (1, 0, 0) and zero error.
        bool operator()(PrecSumsType ps)
        {
            const detail::Moments3D<ComputeType> m(ps);
            n = m.n;
            centroid = m.mean;
            Eigen::Matrix<ComputeType, 3, 1> values;
            Eigen::Matrix<ComputeType, 3, 3> vectors;
            detail::eigen3(m.cov, values, vectors, 2);
            err = std::max(ComputeType(0), values(0) + values(1));
            dir = vectors.col(2);
            const ComputeType len = dir.norm();
            if (len > ComputeType(0) && std::isfinite(len)) dir /= len;
            else dir = ComputeEigen::UnitX();
            return true;
        }

        //! Fit of points given relative to `origin` (sums of p - origin): better conditioned for far-off points.
        bool operator()(PrecSumsType ps, const VectorND<3, ComputeType> &origin)
        {
            operator()(ps);
            centroid += origin.data();
            return true;
        }

        ComputeEigen projectCompute(const ComputeEigen &p) const { return centroid + dir * (p - centroid).dot(dir); }
        VectorType project(const VectorType &pt) const
        {
            return VectorType(EigenVec(projectCompute(pt.data().template cast<ComputeType>()).template cast<ElementType>()));
        }

        //! Segment between the projections of beg and end, directed from beg to end.
        ConstrainedType trim(const VectorType &beg, const VectorType &end) const
        {
            const ComputeType s = (end.data().template cast<ComputeType>() - beg.data().template cast<ComputeType>()).dot(dir) < 0 ? -1 : 1;
            return ConstrainedType(project(beg), project(end), VectorType(EigenVec((s * dir).template cast<ElementType>())));
        }
        template<class Iter>
        ConstrainedType trim(Iter beg, Iter end) const { return trim(*beg, *std::prev(end)); }

        static ElementType getErrorSquared(PrecSumsType ps) { return static_cast<ElementType>(errorSquaredCompute(ps)); }
        //! Mean squared orthogonal distance from the sums (closed-form eigenvalues only).
        static ComputeType errorSquaredCompute(const PrecSumsType &ps)
        {
            const detail::Moments3D<ComputeType> m(ps);
            Eigen::SelfAdjointEigenSolver<Eigen::Matrix<ComputeType, 3, 3>> es;
            es.computeDirect(m.cov, Eigen::EigenvaluesOnly);
            return std::max(ComputeType(0), es.eigenvalues()(0) + es.eigenvalues()(1));
        }
        //! errorSquared(ps) < sigma2 without an eigen-decomposition: the two smaller eigenvalues sum below sigma2 iff
        //! the largest exceeds trace - sigma2, i.e. iff (trace - sigma2) I - cov is not positive semidefinite.
        static bool errorBelow(const PrecSumsType &ps, ComputeType sigma2) { return errorBelowRaw(ps.sums.data(), ps.cnt(), sigma2); }
        //! errorBelow on raw sums s[0..8] (PrecSums3D order) of n points.
        static bool errorBelowRaw(const ComputeType *s, ComputeType n, ComputeType sigma2)
        {
            const ComputeType t = n * n * sigma2;
            const ComputeType a = n * s[3] - s[0] * s[0], b = n * s[4] - s[1] * s[1], c = n * s[5] - s[2] * s[2];
            const ComputeType ab = n * s[6] - s[0] * s[1], bc = n * s[7] - s[1] * s[2], ca = n * s[8] - s[2] * s[0];
            const ComputeType l = a + b + c - t;
            return detail::notPsd3(l - a, l - b, l - c, -ab, -bc, -ca);
        }

    private:
        typedef typename VectorType::EigenType EigenVec;
        ComputeEigen centroid{ComputeEigen::Zero()}, dir{ComputeEigen::UnitX()};
        ComputeType err{0}, n{0};
    };
}
