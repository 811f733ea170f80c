// ApproximationTlsPlane3D: total-least-squares plane of a 3D point set from its PrecSums: through the centroid,
// normal = covariance eigenvector of the smallest eigenvalue, errSquared() = that eigenvalue (mean squared
// orthogonal distance). project() is the orthogonal projection onto the plane (the published formula was wrong).
#pragma once

#include <algorithm>
#include <cmath>
#include <iterator>
#include <vector>

#include <Eigen/Dense>

#include "rtl/core/Polygon3D.h"
#include "rtl/core/VectorND.h"
#include "rtl/vect/PrecSums.h"
#include "rtl/vect/TlsDetail.h"

namespace rtl
{
    template<typename Element, typename Compute>
    class ApproximationTlsPlane3D
    {
    public:
        typedef Element ElementType;
        typedef Compute ComputeType;
        typedef VectorND<3, ElementType> VectorType;
        typedef Polygon3D<ElementType> ConstrainedType;
        typedef PrecSums3D<ComputeType> PrecSumsType;
        typedef Eigen::Matrix<ComputeType, 3, 1> ComputeEigen;

        ApproximationTlsPlane3D() = default;
        explicit ApproximationTlsPlane3D(PrecSumsType ps) { operator()(ps); }
        ~ApproximationTlsPlane3D() = default;

        [[nodiscard]] VectorType normal() const { return VectorType(EigenVec(nrm.template cast<ElementType>())); }
        //! Plane offset: normal() . x = d() for points x of the plane (centroid . normal).
        [[nodiscard]] ElementType d() const { return static_cast<ElementType>(centroid.dot(nrm)); }
        [[nodiscard]] VectorType point() const { return VectorType(EigenVec(centroid.template cast<ElementType>())); }
        [[nodiscard]] ElementType errSquared() const { return static_cast<ElementType>(err); }
        [[nodiscard]] ComputeType errSquaredCompute() const { return err; }
        [[nodiscard]] ComputeType count() const { return n; }

        //! Refits from sums. For collinear or coincident sets the normal is any unit vector orthogonal to the set
        //! (the fit is degenerate but the error, zero or the line residual, is still exact).
        bool operator()(PrecSumsType ps)
        {
            const detail::Moments3D<ComputeType> m(ps);
            n = m.n;
            centroid = m.mean;
            Eigen::Matrix<ComputeType, 3, 1> values;
            Eigen::Matrix<ComputeType, 3, 3> vectors;
            detail::eigen3(m.cov, values, vectors, 0);
            err = std::max(ComputeType(0), values(0));
            nrm = vectors.col(0);
            const ComputeType len = nrm.norm();
            if (len > ComputeType(0) && std::isfinite(len)) nrm /= len;
            else nrm = ComputeEigen::UnitZ();
            return true;
        }

        //! Fit of points given relative to `origin` (sums of p - origin): better conditioned for far-off points.
        bool operator()(PrecSumsType ps, const VectorND<3, ComputeType> &origin)
        {
            operator()(ps);
            centroid += origin.data();
            return true;
        }

        ComputeEigen projectCompute(const ComputeEigen &p) const { return p - nrm * (p - centroid).dot(nrm); }
        VectorType project(const VectorType &pt) const
        {
            return VectorType(EigenVec(projectCompute(pt.data().template cast<ComputeType>()).template cast<ElementType>()));
        }

        //! Polygon on the fitted plane with the points of [beg, end) projected onto it.
        template<class Iter>
        ConstrainedType trim(Iter beg, Iter end, size_t size_hint = 0) const
        {
            ConstrainedType poly(normal(), d());
            if (size_hint > 0)
                poly.reservePoints(size_hint);
            for (; beg != end; ++beg)
                poly.addPoint(*beg);
            return poly;
        }
        ConstrainedType trim(const std::vector<VectorType> &pts) const { return trim(pts.begin(), pts.end(), pts.size()); }

        static ElementType getErrorSquared(PrecSumsType ps) { return static_cast<ElementType>(errorSquaredCompute(ps)); }
        //! Mean squared orthogonal distance from the sums (closed-form eigenvalues only).
        static ComputeType errorSquaredCompute(const PrecSumsType &ps)
        {
            const detail::Moments3D<ComputeType> m(ps);
            Eigen::SelfAdjointEigenSolver<Eigen::Matrix<ComputeType, 3, 3>> es;
            es.computeDirect(m.cov, Eigen::EigenvaluesOnly);
            return std::max(ComputeType(0), es.eigenvalues()(0));
        }
        //! errorSquared(ps) < sigma2 without an eigen-decomposition (cov - sigma2 I is not positive semidefinite).
        static bool errorBelow(const PrecSumsType &ps, ComputeType sigma2) { return errorBelowRaw(ps.sums.data(), ps.cnt(), sigma2); }
        //! errorBelow on raw sums s[0..8] (PrecSums3D order) of n points.
        static bool errorBelowRaw(const ComputeType *s, ComputeType n, ComputeType sigma2)
        {
            const ComputeType t = n * n * sigma2;
            const ComputeType a = n * s[3] - s[0] * s[0], b = n * s[4] - s[1] * s[1], c = n * s[5] - s[2] * s[2];
            const ComputeType ab = n * s[6] - s[0] * s[1], bc = n * s[7] - s[1] * s[2], ca = n * s[8] - s[2] * s[0];
            return detail::notPsd3(a - t, b - t, c - t, ab, bc, ca);
        }

    private:
        typedef typename VectorType::EigenType EigenVec;
        ComputeEigen centroid{ComputeEigen::Zero()}, nrm{ComputeEigen::UnitZ()};
        ComputeType err{0}, n{0};
    };
}
