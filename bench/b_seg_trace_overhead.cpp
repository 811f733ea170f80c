// The untraced segmenters, for bench/trace_overhead.sh: the same source is compiled against the headers before
// tracing (base) and the current ones, and both binaries must time the same work. Synthetic closed 2D float scans
// (1e6 points, 1000 clusters; 1e5 points with 100 clusters as a second size), windows of 1, 2 and 3 previous
// points: IA at step w; CAR at step w + 1 in the current tree (window step - 1) and at step w in the base tree
// (whose CAR compared `step` points). The thresholds are clamped to the bounds on this data (noise below the lower
// bound, jumps above the upper bound), so both trees find the same clusters; the `check` lines prove it.
// Contract (see trace_overhead.sh): `time_ns <case> <ns>` (thread CPU time, fastest of 7 runs) and `check <case> ...`
// lines. Run by CTest with --smoke.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <random>
#include <string>
#include <vector>

#include <time.h>

#include "rtl/seg/CAR_Segmenter.h"
#include "rtl/seg/IA_Segmenter.h"

#if __has_include("rtl/seg/SegTrace.h")
constexpr size_t car_step_for_window = 1;   // current tree: CAR at step s compares s - 1 points
#else
constexpr size_t car_step_for_window = 0;   // base tree: CAR at step s compared s points
#endif

namespace
{
    using V = rtl::VectorND<2, float>;

    std::vector<V> scan(size_t n, size_t k)
    {
        std::mt19937 rng(7);
        std::uniform_real_distribution<float> noise(-0.0025f, 0.0025f);
        std::vector<V> pts(n);
        for (size_t i = 0; i < n; ++i)
        {
            const double a = 2 * M_PI * static_cast<double>(i) / static_cast<double>(n);
            const double r = ((i * k / n) % 2 ? 12.0 : 10.0) + noise(rng);
            pts[i] = V(static_cast<float>(r * std::cos(a)), static_cast<float>(r * std::sin(a)));
        }
        return pts;
    }

    double threadCpuNs()
    {
        timespec t{};
        clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
        return 1e9 * static_cast<double>(t.tv_sec) + static_cast<double>(t.tv_nsec);
    }

    //! The fastest of `reps` calls, in thread CPU time: the machine is shared, and waiting for a core (or another
    //! process's cache traffic) only ever adds time, so the minimum is the least disturbed measurement.
    template<class F>
    double minCpuNs(F &&fn, int reps)
    {
        fn();
        double best = 1e300;
        for (int r = 0; r < reps; ++r)
        {
            const double t0 = threadCpuNs();
            fn();
            best = std::min(best, threadCpuNs() - t0);
        }
        return best;
    }

    void run(size_t n, size_t k, size_t window, int reps)
    {
        const auto pts = scan(n, k);
        const std::string tag = "n" + std::to_string(n) + "_w" + std::to_string(window);

        size_t car_clusters = 0, car_points = 0;
        rtl::CAR_Segmenter<V> car(window + car_step_for_window, 0.05f, 0.5f);
        const double t_car = minCpuNs([&] {
            car.loadData(pts);
            car_clusters = car_points = 0;
            while (car.clustersAvailable() > 0)
            {
                car_points += car.grabCluster().size();
                ++car_clusters;
            }
        }, reps);

        size_t ia_clusters = 0, ia_points = 0;
        const double t_ia = minCpuNs([&] {
            rtl::IA_Segmenter<V> ia(window, 0.05f, 0.5f, rtl::detail::circularScaling<float>(window + 1, n));
            ia_clusters = ia_points = 0;
            for (const auto &p : pts)
            {
                ia.addPoint(p);
                while (ia.closedClustersAvailable() > 0)
                {
                    ia_points += ia.grabCluster().size();
                    ++ia_clusters;
                }
            }
            ia.flush();
            while (ia.closedClustersAvailable() > 0)
            {
                ia_points += ia.grabCluster().size();
                ++ia_clusters;
            }
        }, reps);

        std::printf("time_ns car_%s %.0f\ncheck car_%s %zu %zu\n", tag.c_str(), t_car, tag.c_str(), car_clusters, car_points);
        std::printf("time_ns ia_%s %.0f\ncheck ia_%s %zu %zu\n", tag.c_str(), t_ia, tag.c_str(), ia_clusters, ia_points);
        std::fflush(stdout);
    }
}

int main(int argc, char **argv)
{
    const bool smoke = argc > 1 && std::strcmp(argv[1], "--smoke") == 0;
    const int reps = smoke ? 1 : 7;
    for (size_t window : {1, 2, 3})
    {
        run(smoke ? 10000 : 1000000, smoke ? 10 : 1000, window, reps);
        run(smoke ? 20000 : 100000, smoke ? 10 : 100, window, reps);
    }
    return 0;
}
