// Shared by the Douglas-Peucker and Reumann-Witkam exactness tests: kept indices recovered from a vectorizer's
// output, long-double references of both documented rules, and the random walks they are compared on.
#pragma once

#include <cmath>
#include <random>
#include <vector>

#include "rtl/core/LineSegmentND.h"
#include "rtl/core/VectorND.h"

namespace pe_test
{
    //! Indices of the kept points, from the segment end points (the test chains have distinct points).
    template<class Vectorizer, int d, typename T>
    std::vector<size_t> keptBy(Vectorizer &vz, const std::vector<rtl::VectorND<d, T>> &pts)
    {
        std::vector<rtl::LineSegmentND<d, T>> segs;
        vz(pts, segs);
        std::vector<size_t> out;
        size_t i = 0;
        for (size_t s = 0; s <= segs.size() && !segs.empty(); ++s)
        {
            const auto &target = s < segs.size() ? segs[s].beg() : segs.back().end();
            while (i < pts.size() && !(pts[i] == target)) ++i;
            out.push_back(i);
        }
        return out;
    }

    //! Squared distance of p[i] from the line through p[a] and p[b] (from p[a] if they coincide), in long double
    //! (x87: squares of any double fit).
    template<int d, typename T>
    long double lineDistance2(const std::vector<rtl::VectorND<d, T>> &p, size_t i, size_t a, size_t b)
    {
        long double u[d], v[d], uu = 0, vu = 0;
        for (int k = 0; k < d; ++k)
        {
            u[k] = (long double)p[b][k] - (long double)p[a][k];
            v[k] = (long double)p[i][k] - (long double)p[a][k];
            uu += u[k] * u[k];
            vu += u[k] * v[k];
        }
        const long double t = uu > 0 ? vu / uu : 0;
        long double r = 0;
        for (int k = 0; k < d; ++k) r += (v[k] - u[k] * t) * (v[k] - u[k] * t);
        return r;
    }

    //! Douglas-Peucker (line distance, first maximum) in long double. With `tie` > 0, `tied` is set when a split
    //! point's distance is within `tie` of another point's: the vectorizer, measuring in its Element type, may pick
    //! either there.
    template<int d, typename T>
    std::vector<size_t> dpReference(const std::vector<rtl::VectorND<d, T>> &p, long double eps, long double tie = 0, bool *tied = nullptr)
    {
        std::vector<char> keep(p.size(), 0);
        keep.front() = keep.back() = 1;
        std::vector<std::pair<size_t, size_t>> stack{{0, p.size() - 1}};
        while (!stack.empty())
        {
            const auto [a, b] = stack.back();
            stack.pop_back();
            long double best = eps * eps, runner_up = -1;
            size_t far = 0;
            for (size_t i = a + 1; i < b; ++i)
            {
                const long double q = lineDistance2(p, i, a, b);
                if (q > best) { runner_up = far ? best : runner_up; best = q; far = i; }
                else if (q > runner_up) runner_up = q;
            }
            if (!far) continue;
            if (tied && runner_up >= 0 && std::sqrt(best) - std::sqrt(runner_up) <= tie) *tied = true;
            keep[far] = 1;
            stack.emplace_back(far, b);
            stack.emplace_back(a, far);
        }
        std::vector<size_t> out;
        for (size_t i = 0; i < p.size(); ++i) if (keep[i]) out.push_back(i);
        return out;
    }

    //! Reumann-Witkam's documented strip rule in long double: distance from the line through the key and the
    //! strip's second point (`through`), the last point inside becoming the next key.
    template<int d, typename T>
    std::vector<size_t> rwReference(const std::vector<rtl::VectorND<d, T>> &p, long double eps)
    {
        std::vector<size_t> keys{0};
        size_t k = 0, j = 1;
        while (j < p.size() && p[j] == p[k]) ++j;
        size_t through = j;
        for (size_t i = j + 1; i < p.size(); ++i)
            if (lineDistance2(p, i, k, through) > eps * eps) { k = i - 1; keys.push_back(k); through = i; }
        if (keys.back() != p.size() - 1) keys.push_back(p.size() - 1);
        return keys;
    }

    //! Random walk of n unit-normal steps per coordinate, times `scale`, cast to T.
    template<int d, typename T>
    std::vector<rtl::VectorND<d, T>> randomWalk(std::mt19937 &rng, size_t n, double scale)
    {
        std::normal_distribution<double> g(0, 1);
        std::vector<rtl::VectorND<d, T>> pts;
        double pos[d] = {};
        for (size_t i = 0; i < n; ++i)
        {
            rtl::VectorND<d, T> v;
            for (int k = 0; k < d; ++k) { pos[k] += g(rng); v[k] = static_cast<T>(pos[k] * scale); }
            pts.push_back(v);
        }
        return pts;
    }
}
