// Independent references for the vectorization tests: TLS fits straight from the points (two-pass centred
// covariance, Eigen's iterative eigen-solver), partition and RMS checks, and test chains (semicircle, polylines,
// helix).
#pragma once

#include <cmath>
#include <random>
#include <utility>
#include <vector>

#include <Eigen/Dense>
#include <Eigen/Eigenvalues>
#include <gtest/gtest.h>

#include "rtl/Vectorization.h"

namespace vect_test
{
    typedef std::pair<size_t, size_t> Range;

    //! Reference TLS fit of points [b, e): two-pass centred covariance and Eigen's iterative solver.
    template<int d>
    struct RefFit
    {
        Eigen::Matrix<double, d, 1> mean;
        Eigen::Matrix<double, d, 1> values;          // ascending
        Eigen::Matrix<double, d, d> vectors;         // columns match values
        double lineErr() const { return values.sum() - values(d - 1); }
        double planeErr() const { return values(0); }
        Eigen::Matrix<double, d, 1> major() const { return vectors.col(d - 1); }
        Eigen::Matrix<double, d, 1> minor() const { return vectors.col(0); }
    };

    template<int d, typename E>
    RefFit<d> refFit(const std::vector<rtl::VectorND<d, E>> &pts, size_t b, size_t e)
    {
        RefFit<d> f;
        f.mean.setZero();
        for (size_t i = b; i < e; ++i)
            f.mean += pts[i].data().template cast<double>();
        f.mean /= static_cast<double>(e - b);
        Eigen::Matrix<double, d, d> cov = Eigen::Matrix<double, d, d>::Zero();
        for (size_t i = b; i < e; ++i)
        {
            const Eigen::Matrix<double, d, 1> q = pts[i].data().template cast<double>() - f.mean;
            cov += q * q.transpose();
        }
        cov /= static_cast<double>(e - b);
        Eigen::SelfAdjointEigenSolver<Eigen::Matrix<double, d, d>> es(cov);
        f.values = es.eigenvalues().cwiseMax(0.0);
        f.vectors = es.eigenvectors();
        return f;
    }

    //! Mean squared distance of points [b, e) from the line through p with unit direction u.
    template<int d, typename E>
    double lineMse(const std::vector<rtl::VectorND<d, E>> &pts, size_t b, size_t e, const Eigen::Matrix<double, d, 1> &p,
                   const Eigen::Matrix<double, d, 1> &u)
    {
        double s = 0;
        for (size_t i = b; i < e; ++i)
        {
            const Eigen::Matrix<double, d, 1> q = pts[i].data().template cast<double>() - p;
            s += (q - u * q.dot(u)).squaredNorm();
        }
        return s / static_cast<double>(e - b);
    }

    //! Ranges are in order, non-empty with >= 2 points, contiguous, and cover [0, n).
    inline void expectPartition(const std::vector<Range> &idx, size_t n)
    {
        ASSERT_FALSE(idx.empty());
        EXPECT_EQ(idx.front().first, 0u);
        EXPECT_EQ(idx.back().second, n);
        for (size_t i = 0; i < idx.size(); ++i)
        {
            EXPECT_GE(idx[i].second, idx[i].first + 2) << "range " << i;
            if (i + 1 < idx.size())
            {
                EXPECT_EQ(idx[i].second, idx[i + 1].first) << "range " << i;
            }
        }
    }

    //! Every range's reference TLS line has RMS residual <= sigma (tiny slack for the prefix-sum rounding).
    template<int d, typename E>
    void expectLineRms(const std::vector<rtl::VectorND<d, E>> &pts, const std::vector<Range> &idx, double sigma)
    {
        for (size_t i = 0; i < idx.size(); ++i)
        {
            const auto f = refFit<d>(pts, idx[i].first, idx[i].second);
            EXPECT_LE(std::sqrt(f.lineErr()), sigma * (1 + 1e-6)) << "range " << i << " [" << idx[i].first << ", " << idx[i].second << ")";
        }
    }

    template<typename E>
    void expectPlaneRms(const std::vector<rtl::VectorND<3, E>> &pts, const std::vector<Range> &idx, double sigma)
    {
        for (size_t i = 0; i < idx.size(); ++i)
        {
            const auto f = refFit<3>(pts, idx[i].first, idx[i].second);
            EXPECT_LE(std::sqrt(f.planeErr()), sigma * (1 + 1e-6)) << "range " << i;
        }
    }

    //! Points along a polyline through `corners`, spaced by `step`, with Gaussian noise.
    inline std::vector<rtl::Vector2f> polylineSamples(const std::vector<Eigen::Vector2d> &corners, double step, double noise, unsigned seed)
    {
        std::mt19937 gen(seed);
        std::normal_distribution<double> nd(0.0, noise);
        std::vector<rtl::Vector2f> pts;
        for (size_t c = 0; c + 1 < corners.size(); ++c)
        {
            const Eigen::Vector2d a = corners[c], b = corners[c + 1];
            const size_t cnt = static_cast<size_t>(std::ceil((b - a).norm() / step));
            for (size_t k = 0; k < cnt; ++k)
            {
                const Eigen::Vector2d p = a + (b - a) * (static_cast<double>(k) / static_cast<double>(cnt));
                pts.emplace_back(static_cast<float>(p.x() + nd(gen)), static_cast<float>(p.y() + nd(gen)));
            }
        }
        const Eigen::Vector2d l = corners.back();
        pts.emplace_back(static_cast<float>(l.x() + nd(gen)), static_cast<float>(l.y() + nd(gen)));
        return pts;
    }

    //! The papers' setting: semicircle of radius 8, n points, Gaussian noise.
    inline std::vector<rtl::Vector2f> semicircle(size_t n, double noise, unsigned seed)
    {
        std::mt19937 gen(seed);
        std::normal_distribution<double> nd(0.0, noise);
        std::vector<rtl::Vector2f> pts;
        pts.reserve(n);
        for (size_t i = 0; i < n; ++i)
        {
            const double a = M_PI * static_cast<double>(i) / static_cast<double>(n - 1);
            pts.emplace_back(static_cast<float>(8 * std::cos(a) + nd(gen)), static_cast<float>(8 * std::sin(a) + nd(gen)));
        }
        return pts;
    }

    //! Helix of radius 8 and the given pitch per turn over `turns` turns.
    inline std::vector<rtl::Vector3f> helix(size_t n, double turns, double pitch, double noise, unsigned seed)
    {
        std::mt19937 gen(seed);
        std::normal_distribution<double> nd(0.0, noise);
        std::vector<rtl::Vector3f> pts;
        pts.reserve(n);
        for (size_t i = 0; i < n; ++i)
        {
            const double t = turns * static_cast<double>(i) / static_cast<double>(n - 1), a = 2 * M_PI * t;
            pts.emplace_back(static_cast<float>(8 * std::cos(a) + nd(gen)), static_cast<float>(8 * std::sin(a) + nd(gen)),
                             static_cast<float>(pitch * t + nd(gen)));
        }
        return pts;
    }
}
