// Timing for the segmentation benchmarks: the median wall time (what bench_util reports) and the median CPU time of
// the calling thread, which stays meaningful when the machine is shared and the process is descheduled.
#pragma once

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <ctime>
#include <string>
#include <vector>

#include "bench_util.h"

namespace rtl::bench::seg
{
    struct Timing
    {
        double wall = 0, cpu = 0;
    };

    inline double threadCpuSeconds()
    {
        timespec t{};
        clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
        return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
    }

    //! Medians of `reps` timed calls of fn(), after one untimed warm-up call.
    template<typename F>
    Timing measure(F &&fn, int reps)
    {
        fn();
        std::vector<double> wall, cpu;
        for (int r = 0; r < reps; ++r)
        {
            const auto w0 = std::chrono::steady_clock::now();
            const double c0 = threadCpuSeconds();
            fn();
            cpu.push_back(threadCpuSeconds() - c0);
            wall.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - w0).count());
        }
        auto median = [](std::vector<double> &v) {
            std::nth_element(v.begin(), v.begin() + static_cast<long>(v.size() / 2), v.end());
            return v[v.size() / 2];
        };
        return {median(wall), median(cpu)};
    }

    //! bench_util's row (wall time, ratio to the floor's wall time) plus the same two figures in CPU time.
    inline void row(const std::string &name, size_t points, const Timing &t, const Timing &floor, const std::string &note = "")
    {
        char cpu[96];
        std::snprintf(cpu, sizeof cpu, "cpu %.3e pts/s, cpu ratio %.2f", static_cast<double>(points) / t.cpu, t.cpu / floor.cpu);
        printRow(name, points, t.wall, floor.wall, std::string(cpu) + note);
    }
}
