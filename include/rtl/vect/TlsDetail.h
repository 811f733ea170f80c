// Shared numerics of the total-least-squares approximations: centred moments from PrecSums and division-free
// tests of "mean squared residual < sigma^2" used in the extractors' hot loops.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>

#include <Eigen/Dense>

#include "rtl/vect/PrecSums.h"

namespace rtl::detail
{
    //! Centroid and covariance (divided by the count) of a 2D point set given by its sums.
    template<typename C>
    struct Moments2D
    {
        C n{0}, mx{0}, my{0}, cxx{0}, cyy{0}, cxy{0};
        explicit Moments2D(const PrecSums2D<C> &ps)
        {
            n = ps.cnt();
            if (!(n > C(0)))
                return;
            const C inv = C(1) / n;
            mx = ps.sx() * inv;
            my = ps.sy() * inv;
            cxx = std::max(C(0), ps.sx2() * inv - mx * mx);
            cyy = std::max(C(0), ps.sy2() * inv - my * my);
            cxy = ps.sxy() * inv - mx * my;
        }
    };

    //! Centroid and covariance (divided by the count) of a 3D point set given by its sums.
    template<typename C>
    struct Moments3D
    {
        C n{0};
        Eigen::Matrix<C, 3, 1> mean{Eigen::Matrix<C, 3, 1>::Zero()};
        Eigen::Matrix<C, 3, 3> cov{Eigen::Matrix<C, 3, 3>::Zero()};
        explicit Moments3D(const PrecSums3D<C> &ps)
        {
            n = ps.cnt();
            if (!(n > C(0)))
                return;
            const C inv = C(1) / n;
            mean << ps.sx() * inv, ps.sy() * inv, ps.sz() * inv;
            cov(0, 0) = std::max(C(0), ps.sx2() * inv - mean(0) * mean(0));
            cov(1, 1) = std::max(C(0), ps.sy2() * inv - mean(1) * mean(1));
            cov(2, 2) = std::max(C(0), ps.sz2() * inv - mean(2) * mean(2));
            cov(0, 1) = cov(1, 0) = ps.sxy() * inv - mean(0) * mean(1);
            cov(1, 2) = cov(2, 1) = ps.syz() * inv - mean(1) * mean(2);
            cov(0, 2) = cov(2, 0) = ps.szx() * inv - mean(2) * mean(0);
        }
    };

    //! True iff the symmetric 3x3 matrix m is NOT positive semidefinite (some principal minor is negative).
    //! NaN entries give false.
    template<typename C>
    inline bool notPsd3(C a, C b, C c, C ab, C bc, C ca)
    {
        if (!std::isfinite(a + b + c + ab + bc + ca))
            return false;
        if (a < C(0) || b < C(0) || c < C(0))
            return true;
        if (a * b - ab * ab < C(0) || b * c - bc * bc < C(0) || a * c - ca * ca < C(0))
            return true;
        const C det = a * (b * c - bc * bc) - ab * (ab * c - bc * ca) + ca * (ab * bc - b * ca);
        return det < C(0);
    }

    //! Eigenvalues (ascending) and eigenvectors of a symmetric 3x3 covariance: closed form, with an iterative
    //! fallback when eigenvector `which` (0 = smallest, 2 = largest) is too close to its neighbour for the closed
    //! form to resolve it accurately.
    template<typename C>
    inline void eigen3(const Eigen::Matrix<C, 3, 3> &cov, Eigen::Matrix<C, 3, 1> &values, Eigen::Matrix<C, 3, 3> &vectors,
                       int which)
    {
        Eigen::SelfAdjointEigenSolver<Eigen::Matrix<C, 3, 3>> es;
        es.computeDirect(cov);
        values = es.eigenvalues();
        const C scale = std::max(std::abs(values(2)), std::numeric_limits<C>::min());
        const C tol = std::sqrt(std::numeric_limits<C>::epsilon()) * scale;
        const C gap = which == 0 ? values(1) - values(0) : values(2) - values(1);
        if (es.info() != Eigen::Success || !(gap >= tol))
        {
            es.compute(cov);
            values = es.eigenvalues();
        }
        vectors = es.eigenvectors();
    }
}
