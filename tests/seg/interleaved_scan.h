// A synthetic 2D/3D scan for the segmenter tests: a circle whose radius jumps now and then (cluster ends), with
// every other point of some blocks pushed outwards (two chains interleaved point by point, so that alive lists are
// merged out of order), optional far outliers (isolated points) and NaN gaps.
#pragma once

#include <cmath>
#include <cstddef>
#include <random>
#include <vector>

namespace segcheck
{
    struct ScanShape
    {
        double jumpProbability;     //!< per point: the radius jumps to a new value in [2, 5)
        size_t block;               //!< odd points of blocks of this many points ...
        size_t cycle;               //!< ... whose index modulo cycle is 1 lie 1 further out
        double outlierProbability;  //!< per point: 7 further out (0: no draw)
        double nanProbability;      //!< per point: NaN instead of the point
    };

    template<class V>
    std::vector<V> interleavedScan(size_t n, unsigned seed, const ScanShape& shape)
    {
        using E = typename V::ElementType;
        std::mt19937 rng(seed);
        std::uniform_real_distribution<double> u(0, 1);
        std::vector<V> pts;
        double r = 3;
        for (size_t i = 0; i < n; ++i)
        {
            if (u(rng) < shape.jumpProbability) r = 2 + 3 * u(rng);
            const double a = 2 * M_PI * static_cast<double>(i) / static_cast<double>(n);
            double rr = r + ((i % 2) && (i / shape.block) % shape.cycle == 1 ? 1.0 : 0.0);
            if (shape.outlierProbability > 0 && u(rng) < shape.outlierProbability) rr += 7.0;
            typename V::EigenType e = V::zeros().data();
            e[0] = static_cast<E>(rr * std::cos(a));
            e[1] = static_cast<E>(rr * std::sin(a));
            pts.push_back(u(rng) < shape.nanProbability ? V::nan() : V(e));
        }
        return pts;
    }
}
