// Shared helpers for the transformation tests: fixed-seed generators and tolerance-based comparisons.
#pragma once

#include <algorithm>
#include <cmath>
#include <random>
#include <type_traits>

#include <Eigen/Dense>

#include "rtl/Core.h"
#include "rtl/Transformation.h"

namespace tf_test
{
    //! Tolerance for results of a handful of chained operations on unit-sized data.
    template<typename E> constexpr E tol() { return std::is_same_v<E, float> ? E(2e-4) : E(1e-10); }

    //! Uniform doubles in [lo, hi) from a fixed seed; callable through a const reference as random() requires.
    class Gen
    {
    public:
        explicit Gen(unsigned seed, double lo = -1.0, double hi = 1.0) : rng(seed), dist(lo, hi) {}
        double operator()() const { return dist(rng); }
    private:
        mutable std::mt19937 rng;
        mutable std::uniform_real_distribution<double> dist;
    };

    template<int d, typename E>
    rtl::VectorND<d, E> randomVector(const Gen &g)
    {
        typename rtl::VectorND<d, E>::EigenType e;
        for (int i = 0; i < d; ++i)
            e[i] = static_cast<E>(g());
        return rtl::VectorND<d, E>(e);
    }

    template<int d, typename E>
    E dist(const rtl::VectorND<d, E> &a, const rtl::VectorND<d, E> &b) { return (a.data() - b.data()).norm(); }

    template<int r, int c, typename E>
    E dist(const rtl::Matrix<r, c, E> &a, const rtl::Matrix<r, c, E> &b) { return (a.data() - b.data()).norm(); }

    //! Largest distance between the images of the origin and the unit vectors under tf1 and tf2: zero iff the two
    //! (affine) transformations are equal. Works for every transformation type that can be applied to a vector.
    template<int d, typename E, typename Tf1, typename Tf2>
    E tfDistance(const Tf1 &tf1, const Tf2 &tf2)
    {
        using V = rtl::VectorND<d, E>;
        E worst = dist(V(tf1(V::zeros())), V(tf2(V::zeros())));
        for (int i = 0; i < d; ++i)
        {
            typename V::EigenType e = V::EigenType::Unit(i);
            worst = std::max(worst, dist(V(tf1(V(e))), V(tf2(V(e)))));
        }
        return worst;
    }

    //! Orthonormality and orientation error of a rotation matrix: |R^T R - I| + |det R - 1|.
    template<int d, typename E>
    E rotationError(const rtl::Matrix<d, d, E> &m)
    {
        using EM = typename rtl::Matrix<d, d, E>::EigenType;
        return (m.data().transpose() * m.data() - EM::Identity()).norm() + std::abs(m.data().determinant() - E(1));
    }
}
