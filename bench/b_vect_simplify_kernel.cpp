// simplifyCompatibleIndices (rtl/vect/SimplifyCompatible.h) on the cases of bench/js/b_simplify.mjs, natively:
// the noisy semicircle (r 8, noise 0.01 uniform, tolerance 0.01) and the random walk (steps uniform in +-0.5,
// tolerance 1), 1e5 and 1e6 points, double {x, y} interleaved, both quality modes. Each case is also run with an
// infinite tolerance, which scans the whole range against one chord once and splits nothing: its time per point
// is the cost of the Douglas-Peucker kernel (plus the copy into the working arrays), and case / one pass is the
// number of such passes the case costs. Rounds are interleaved, medians reported.
// Then, per fast-mode case, the call's phases (interleaved rounds, medians): the radial pass alone, prepare (the
// radial pass and the set-up of the working arrays, up to simplifyIndices' hook), Douglas-Peucker alone on the
// prepared points, and its ranges replayed apart by length (short: at most filter_min_points interior points,
// scanned exactly; long: filtered), each with its count of ranges and of points scanned: where the time of a call
// goes, and what bounds it.
// --smoke: 2000 points, one round.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <functional>
#include <limits>
#include <memory>
#include <string>
#include <utility>
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
    using namespace rtl::detail;
    using Range = std::pair<size_t, size_t>;

    //! farthest() of every range, in order; returns a checksum (keeps the calls).
    __attribute__((noinline)) size_t replay(const AxisPoints<2> &pts, const std::vector<Range> &ranges, double sq_tolerance)
    {
        size_t sum = 0;
        for (const auto &[first, last] : ranges)
        {
            double best = sq_tolerance;
            sum += farthest<2>(pts, first, last, best);
        }
        return sum;
    }

    //! The ranges Douglas-Peucker scans on pts (as simplify() does), split by length.
    void ranges(const AxisPoints<2> &pts, double sq_tolerance, std::vector<Range> &short_ranges, std::vector<Range> &long_ranges)
    {
        std::vector<Range> stack{{0, pts.m - 1}};
        while (!stack.empty())
        {
            const auto [first, last] = stack.back();
            stack.pop_back();
            (last - first - 1 <= filter_min_points ? short_ranges : long_ranges).push_back({first, last});
            double best = sq_tolerance;
            const size_t index = farthest<2>(pts, first, last, best);
            if (best > sq_tolerance)
            {
                if (index - first > 1) stack.push_back({first, index});
                if (last - index > 1) stack.push_back({index, last});
            }
        }
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
    // The phases of fast-mode calls.
    for (size_t n : sizes)
        for (int which = 0; which < 2; ++which)
        {
            const std::vector<double> xy = which ? walk(n) : semicircle(n);
            const double tol = which ? 1.0 : 0.01, sq = tol * tol;
            std::vector<Range> short_ranges, long_ranges;
            size_t m = 0;
            std::vector<double> t_radial, t_prepare, t_dp, t_short, t_long, t_call;
            std::vector<double> axes(2 * n);
            std::unique_ptr<size_t[]> kept_from(new size_t[n]);
            double *axis[2] = {axes.data(), axes.data() + n};
            using Clock = std::chrono::steady_clock;
            const auto seconds = [](auto &&fn) {
                const auto start = Clock::now();
                fn();
                return std::chrono::duration<double>(Clock::now() - start).count();
            };
            for (int r = 0; r <= opt.repetitions; ++r)
            {
                bool finite = true;
                const double radial = seconds([&] {
                    rtl::bench::doNotOptimize(radialPass<2, double>(xy.data(), n, sq, axis, kept_from.get(), finite));
                });
                // The core's own call, paused where its points are ready: the time to there, then Douglas-Peucker
                // and its ranges timed on those points (the call's own Douglas-Peucker then runs, untimed).
                double prep = 0, dp = 0, sh = 0, lo = 0;
                const auto start = Clock::now();
                const auto phases = [&](const AxisPoints<2> &pts) {
                    prep = std::chrono::duration<double>(Clock::now() - start).count();
                    if (short_ranges.empty() && long_ranges.empty())
                        ranges(pts, sq, short_ranges, long_ranges);
                    m = pts.m;
                    dp = seconds([&] { rtl::bench::doNotOptimize(simplify<2>(pts, sq).size()); });
                    sh = seconds([&] { rtl::bench::doNotOptimize(replay(pts, short_ranges, sq)); });
                    lo = seconds([&] { rtl::bench::doNotOptimize(replay(pts, long_ranges, sq)); });
                };
                rtl::bench::doNotOptimize(simplifyIndices<2>(xy.data(), n, sq, false, phases).size());
                const double call = seconds([&] { rtl::bench::doNotOptimize(rtl::simplifyCompatibleIndices(xy.data(), n, 2, tol, false).size()); });
                if (r)
                {
                    t_radial.push_back(radial); t_prepare.push_back(prep); t_dp.push_back(dp);
                    t_short.push_back(sh); t_long.push_back(lo); t_call.push_back(call);
                }
            }
            size_t short_points = 0, long_points = 0;
            for (const auto &r : short_ranges) short_points += r.second - r.first - 1;
            for (const auto &r : long_ranges) long_points += r.second - r.first - 1;
            std::printf("\n%s %zu fast (tol %g): %zu points after the radial pass; ms, medians of %d interleaved rounds\n",
                        which ? "random walk" : "semicircle", n, tol, m, opt.repetitions);
            std::printf("  call %.3f = prepare %.3f (radial pass alone %.3f) + Douglas-Peucker %.3f\n", 1e3 * median(t_call),
                        1e3 * median(t_prepare), 1e3 * median(t_radial), 1e3 * median(t_dp));
            std::printf("  Douglas-Peucker's ranges replayed: %zu short (%zu points) %.3f ms, %zu long (%zu points) %.3f ms\n",
                        short_ranges.size(), short_points, 1e3 * median(t_short), long_ranges.size(), long_points,
                        1e3 * median(t_long));
        }
    return 0;
}
