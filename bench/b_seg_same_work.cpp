// Segmenters at the same work as the published figures: CAR at step 3 and at the paper's step 10, IA at
// step 3 and 10, bounds 0.01 - 0.1, closed synthetic scans with about 10 and about 10,000 clusters, 2D float.
// Each time is a ratio to a floor measured in the same run that does the minimal work of the algorithm: for a window
// of w points, the w lagged squared distances per point, compared with a per-point threshold and summed into a
// per-point count (branch-free, vectorised). CAR compares step - 1 previous points, IA step previous points.
// A CAR row is loadData + grabbing every cluster; an IA row is addPoint per point with grabbing as clusters close,
// and flush. Output: a table, and the `time_ns <case> <ns>` / `check <case> ...` lines of bench/trace_overhead.sh,
// so that the same source built against an older commit measures the speed-up at identical clusters:
//     ROUNDS=7 bench/trace_overhead.sh bench/b_seg_same_work.cpp <base-commit>
// Options: --smoke (tiny, for CTest), --reps=R, --sizes=100000,1000000,10000000 (default 100k and 1M).
// Instruction counts and timings of the IA window's successive versions, and how far the tail-mode rows move with
// the heap layout alone, are in docs/seg.md ("IA segmenter at the same work").
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "b_seg_common.h"
#include "b_seg_timing.h"
#include "bench_util.h"
#include "rtl/seg/CAR_Segmenter.h"
#include "rtl/seg/IA_Segmenter.h"

namespace
{
    using V = rtl::VectorND<2, float>;
    constexpr float lower = 0.01f, upper = 0.1f;

    // Closed scan, 1 mm noise (under the lower bound, so that every point meets all its window neighbours in its
    // run; the jumps of 2 m are over the upper bound).
    std::vector<V> scan(size_t n, size_t k) { return rtl::bench::seg::closedScan<V>(n, k, 0.0005f); }

    // The floor for a window of w: per point, the w lagged squared distances against its threshold.
    rtl::bench::seg::Timing floorTime(const std::vector<V> &pts, size_t w, float scaling, int reps)
    {
        const size_t n = pts.size();
        std::vector<float> x(n), y(n), t(n);
        std::vector<std::uint8_t> count(n);
        for (size_t i = 0; i < n; ++i)
        {
            x[i] = pts[i].x();
            y[i] = pts[i].y();
        }
        return rtl::bench::seg::measure([&] {
            for (size_t i = 0; i < n; ++i)
            {
                float tt = scaling * scaling * (x[i] * x[i] + y[i] * y[i]);
                tt = tt < lower * lower ? lower * lower : tt;
                t[i] = tt > upper * upper ? upper * upper : tt;
                count[i] = 0;
            }
            for (size_t k = 1; k <= w; ++k)
                for (size_t i = k; i < n; ++i)
                {
                    const float dx = x[i] - x[i - k], dy = y[i] - y[i - k];
                    count[i] = static_cast<std::uint8_t>(count[i] + (dx * dx + dy * dy <= t[i] ? 1 : 0));
                }
            rtl::bench::doNotOptimize(count.data());
        }, reps);
    }

    struct Result
    {
        size_t clusters = 0, points = 0;
        std::uint64_t checksum = 0;   // order-sensitive: sizes of the clusters in hand-out order
        void add(const std::vector<V> &c)
        {
            ++clusters;
            points += c.size();
            checksum = checksum * 1000003u + c.size();
        }
    };

    void report(const std::string &name, size_t n, const rtl::bench::seg::Timing &t, const rtl::bench::seg::Timing &floor,
                const Result &r)
    {
        rtl::bench::seg::row(name, n, t, floor, ", " + std::to_string(r.clusters) + " clusters");
        std::printf("time_ns %s %.0f\n", name.c_str(), t.cpu * 1e9);
        std::printf("check %s %zu %zu %llu\n", name.c_str(), r.clusters, r.points, static_cast<unsigned long long>(r.checksum));
    }

    void run(size_t n, size_t k, int reps)
    {
        const auto pts = scan(n, k);
        const std::string tag = "_n" + std::to_string(n) + "_k" + std::to_string(k);
        for (size_t step : {size_t(3), size_t(10)})
        {
            // CAR at `step` compares step - 1 points (RTL's definition; the old headers of this project compared step)
            const float car_scaling = rtl::detail::circularScaling<float>(step, n);
            const auto car_floor = floorTime(pts, step - 1, car_scaling, reps);
            Result car_result;
            rtl::CAR_Segmenter<V> car(step, lower, upper);
            const auto t_car = rtl::bench::seg::measure([&] {
                car_result = Result();
                rtl::bench::seg::segmentCar(car, pts, [&](const std::vector<V> &c) { car_result.add(c); });
            }, reps);
            rtl::bench::seg::row("floor_w" + std::to_string(step - 1) + tag, n, car_floor, car_floor);
            report("CAR_step" + std::to_string(step) + tag, n, t_car, car_floor, car_result);

            const auto ia_floor = floorTime(pts, step, car_scaling, reps);
            Result ia_result;
            const auto t_ia = rtl::bench::seg::measure([&] {
                rtl::IA_Segmenter<V> ia(step, lower, upper, car_scaling);
                ia_result = Result();
                rtl::bench::seg::segmentIa(ia, pts, [&](const std::vector<V> &c) { ia_result.add(c); });
            }, reps);
            rtl::bench::seg::row("floor_w" + std::to_string(step) + tag, n, ia_floor, ia_floor);
            report("IA_step" + std::to_string(step) + tag, n, t_ia, ia_floor, ia_result);
            if (car_result.points != n || ia_result.points != n)
            {
                std::fprintf(stderr, "lost points: CAR %zu, IA %zu of %zu\n", car_result.points, ia_result.points, n);
                std::exit(1);
            }
        }
    }
}

int main(int argc, char **argv)
{
    const auto opt = rtl::bench::parseOptions(argc, argv);
    std::vector<size_t> sizes = {100000, 1000000};
    for (int i = 1; i < argc; ++i)
        if (std::strncmp(argv[i], "--sizes=", 8) == 0)
        {
            sizes.clear();
            for (const char *p = argv[i] + 8; *p;)
            {
                char *end = nullptr;
                sizes.push_back(std::strtoull(p, &end, 10));
                p = *end == ',' ? end + 1 : end;
                if (end == p && *p) break;
            }
        }
    if (opt.smoke) sizes = {20000};
    rtl::bench::printHeader("segmenters at the published parameters (ratio = cpu time / floor cpu time)");
    for (size_t n : sizes)
        for (size_t k : {size_t(10), size_t(10000)})
            if (k * 4 <= n) run(n, k, opt.repetitions);
    return 0;
}
