// simplifyCompatibleIndices (rtl/vect/SimplifyCompatible.h) on the cases of bench/js/b_simplify.mjs, natively:
// the noisy semicircle (r 8, noise 0.01 uniform, tolerance 0.01) and the random walk (steps uniform in +-0.5,
// tolerance 1), 1e5 and 1e6 points, double {x, y} interleaved, both quality modes. Each case is also run with an
// infinite tolerance, which scans the whole range against one chord once and splits nothing: its time per point
// is the cost of the Douglas-Peucker kernel (plus the copy into the working arrays), and case / one pass is the
// number of such passes the case costs. Rounds are interleaved, medians reported.
// --smoke: 2000 points, one round.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <functional>
#include <limits>
#include <string>
#include <vector>

#include "bench_util.h"
#include "rtl/vect/SimplifyCompatible.h"

namespace
{
    // The generators of bench/js/simplify_cases.mjs (the same LCG and formulas), so the kept counts match it.
    struct Lcg
    {
        std::uint32_t s;
        double operator()() { s = s * 1664525u + 1013904223u; return s / 4294967296.0; }
    };
    std::vector<double> semicircle(size_t n)
    {
        Lcg r{1};
        std::vector<double> xy;
        for (size_t i = 0; i < n; ++i)
        {
            const double a = M_PI * static_cast<double>(i) / static_cast<double>(n - 1);
            const double x = 8 * std::cos(a) + 0.01 * (r() - 0.5);
            xy.push_back(x);
            xy.push_back(8 * std::sin(a) + 0.01 * (r() - 0.5));
        }
        return xy;
    }
    std::vector<double> walk(size_t n)
    {
        Lcg r{2};
        std::vector<double> xy;
        double x = 0, y = 0;
        for (size_t i = 0; i < n; ++i)
        {
            x += r() - 0.5;
            xy.push_back(x);
            y += r() - 0.5;
            xy.push_back(y);
        }
        return xy;
    }
    double median(std::vector<double> v)
    {
        std::nth_element(v.begin(), v.begin() + static_cast<long>(v.size() / 2), v.end());
        return v[v.size() / 2];
    }
}

int main(int argc, char **argv)
{
    const auto opt = rtl::bench::parseOptions(argc, argv);
    const std::vector<size_t> sizes = opt.smoke ? std::vector<size_t>{2000} : std::vector<size_t>{100000, 1000000};
    const double inf = std::numeric_limits<double>::infinity();
    for (size_t n : sizes)
    {
        struct Case { std::string name; std::vector<double> xy; double tol; bool hq; std::vector<double> t; size_t kept = 0; };
        std::vector<Case> cases;
        for (bool hq : {false, true})
        {
            cases.push_back({"semicircle tol 0.01" + std::string(hq ? " hq" : ""), semicircle(n), 0.01, hq, {}});
            cases.push_back({"random walk tol 1" + std::string(hq ? " hq" : ""), walk(n), 1.0, hq, {}});
        }
        cases.push_back({"one pass (tol inf, hq)", semicircle(n), inf, true, {}});
        for (int r = 0; r <= opt.repetitions; ++r)
            for (auto &c : cases)
            {
                const auto start = std::chrono::steady_clock::now();
                const auto kept = rtl::simplifyCompatibleIndices(c.xy.data(), n, 2, c.tol, c.hq);
                const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
                c.kept = kept.size();
                if (r) c.t.push_back(s);   // round 0 warms up
            }
        std::printf("\n%zu points, medians of %d interleaved rounds\n", n, opt.repetitions);
        std::printf("%-28s %8s %10s %10s %8s\n", "case", "kept", "ms", "ns/point", "passes");
        const double pass = median(cases.back().t);
        for (auto &c : cases)
        {
            const double t = median(c.t);
            std::printf("%-28s %8zu %10.3f %10.3f %8.1f\n", c.name.c_str(), c.kept, 1e3 * t, 1e9 * t / static_cast<double>(n),
                        t / pass);
        }
    }
    return 0;
}
