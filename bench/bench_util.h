// Minimal benchmark harness shared by bench/b_*.cpp.
// Figures are reported as ratios against a baseline measured in the same run, because the machines
// here are shared and noisy: absolute times drift, ratios taken seconds apart hardly do.
#pragma once

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

namespace rtl::bench
{
    struct Options
    {
        bool smoke = false;     // tiny sizes, one repetition: used by CTest to keep benchmarks working
        int repetitions = 7;    // the median of this many timed runs is reported
    };

    inline Options parseOptions(int argc, char **argv)
    {
        Options o;
        for (int i = 1; i < argc; ++i)
        {
            if (std::strcmp(argv[i], "--smoke") == 0) { o.smoke = true; o.repetitions = 1; }
            else if (std::strncmp(argv[i], "--reps=", 7) == 0) o.repetitions = std::max(1, std::atoi(argv[i] + 7));
        }
        return o;
    }

    // Keeps the compiler from discarding a computed value.
    template<typename T>
    inline void doNotOptimize(const T &value) { asm volatile("" : : "r,m"(value) : "memory"); }

    // Median wall time in seconds of `reps` calls of fn(), after one untimed warm-up call.
    template<typename F>
    double medianSeconds(F &&fn, int reps)
    {
        fn();
        std::vector<double> t;
        t.reserve(static_cast<size_t>(reps));
        for (int r = 0; r < reps; ++r)
        {
            auto start = std::chrono::steady_clock::now();
            fn();
            t.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
        }
        std::nth_element(t.begin(), t.begin() + static_cast<long>(t.size() / 2), t.end());
        return t[t.size() / 2];
    }

    inline void printHeader(const char *title)
    {
        std::printf("\n== %s ==\n%-44s %12s %14s %10s %s\n", title, "case", "points", "points/s", "ratio", "note");
    }

    // One result row: throughput, and the time ratio against the baseline (1.0 = as fast as the baseline).
    inline void printRow(const std::string &name, size_t points, double seconds, double baseline_seconds,
                         const std::string &note = "")
    {
        double ratio = baseline_seconds > 0 ? seconds / baseline_seconds : 0.0;
        std::printf("%-44s %12zu %14.3e %10.2f %s\n", name.c_str(), points, static_cast<double>(points) / seconds, ratio,
                    note.c_str());
        std::fflush(stdout);
    }

    //! A vectorizer row's note: its segment count and, when the paper published a throughput for the case, that
    //! figure and the goal (goal_factor times it).
    inline std::string segmentsNote(size_t segments, double published = 0, double goal_factor = 2)
    {
        char buf[128];
        if (published > 0)
            std::snprintf(buf, sizeof buf, "segs=%zu  published=%.2e goal=%.2e", segments, published, published * goal_factor);
        else
            std::snprintf(buf, sizeof buf, "segs=%zu", segments);
        return buf;
    }
}
