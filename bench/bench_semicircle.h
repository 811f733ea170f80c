// The paper's test chain for the 2D vectorizers: a semicircle of radius 8 with Gaussian noise 0.01 on both axes
// (drawn in double, stored as float), and a checksum of a result's segments. Shared by the 2D vectorization
// benchmarks so that they time the same points and compare results the same way. Uses only API that older trees
// have too (bench/trace_overhead.sh compiles a benchmark against both).
#pragma once

#include <cmath>
#include <cstddef>
#include <random>
#include <vector>

#include "rtl/Core.h"

namespace rtl::bench
{
    inline std::vector<rtl::Vector2f> semicircle(size_t n, unsigned seed)
    {
        std::mt19937 gen(seed);
        std::normal_distribution<double> nd(0.0, 0.01);
        std::vector<rtl::Vector2f> pts;
        pts.reserve(n);
        for (size_t i = 0; i < n; ++i)
        {
            const double a = M_PI * static_cast<double>(i) / static_cast<double>(n - 1);
            pts.emplace_back(static_cast<float>(8 * std::cos(a) + nd(gen)), static_cast<float>(8 * std::sin(a) + nd(gen)));
        }
        return pts;
    }

    //! Sum of the segments' end coordinates: equal results give equal sums.
    template<class Segments>
    double segmentChecksum(const Segments &segs)
    {
        double s = 0;
        for (const auto &g : segs)
            s += static_cast<double>(g.beg().x()) + 2.0 * g.beg().y() + 3.0 * g.end().x() + 5.0 * g.end().y();
        return s;
    }
}
