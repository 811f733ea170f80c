// The FTLS/AFTLS worst-case corpus: input `seed` of bench/b_vect_fast_worst_case.cpp's 300, shared
// by that benchmark and the tests that pin its slowest inputs' work. 300-1,500 points: noisy polylines with random
// corners (shape 0), arcs (1), steps (2) or spikes (3); sigma 0.01-0.06, delta 0.05-3. Deterministic (mt19937 and
// the standard distributions' libstdc++ sequences).
#pragma once

#include <cmath>
#include <cstddef>
#include <random>
#include <vector>

#include "rtl/Core.h"

namespace rtl::fast_corpus
{
    struct Case
    {
        unsigned seed;
        int shape;   // 0 polyline, 1 arc + polyline, 2 steps, 3 polyline with spikes
        size_t n;
        double sigma, delta, noise, seg;
        std::vector<rtl::Vector2d> pts;
    };

    inline Case makeCase(unsigned seed)
    {
        std::mt19937 g(seed);
        std::uniform_real_distribution<double> u(0, 1);
        Case c;
        c.seed = seed;
        c.shape = static_cast<int>(g() % 4);
        c.n = 300 + g() % 1201;
        c.sigma = 0.01 + 0.05 * u(g);
        c.delta = std::exp(std::log(0.05) + (std::log(3.0) - std::log(0.05)) * u(g));
        c.noise = c.sigma * (0.2 + 1.6 * u(g));
        c.seg = 0.2 + 4 * u(g);   // mean segment length in length units
        const double step = 0.01 + 0.04 * u(g);
        std::normal_distribution<double> nd(0, c.noise);
        double x = 0, y = 0, a = 2 * M_PI * u(g), curv = 0;
        double left = c.seg;
        for (size_t i = 0; i < c.n; ++i)
        {
            c.pts.push_back(rtl::Vector2d(x + nd(g), y + nd(g)));
            if (c.shape == 3 && g() % 97 == 0)
                c.pts.back() = rtl::Vector2d(x + 10 * c.noise * (u(g) - 0.5) * 20, y + 10 * c.noise * (u(g) - 0.5) * 20);
            left -= step;
            if (left <= 0)
            {
                left = c.seg * (0.3 + 1.4 * u(g));
                if (c.shape == 2)
                {
                    x += (u(g) - 0.5) * 4 * c.delta;
                    y += (u(g) - 0.5) * 4 * c.delta;
                }
                else
                    a += (u(g) - 0.5) * 2.5;
                curv = c.shape == 1 && u(g) < 0.5 ? (u(g) - 0.5) * 0.2 : 0;
            }
            a += curv;
            x += step * std::cos(a);
            y += step * std::sin(a);
        }
        return c;
    }

}
