// The cost of tracing the segmenters (seg/SegTrace.h), in the same run: the untraced segmenter (NoTrace, the floor
// of each group), the traced type with no observer set, and the traced type recording every event in a TraceLog
// (cleared before each run, its memory kept). Synthetic closed 2D float scans of 1e5 points with 100 clusters (as
// in b_seg_synthetic), windows of 1, 2 and 3 previous points (CAR step w + 1, IA step w with CAR's scaling). The
// zero cost of NoTrace against the headers before tracing is measured by bench/trace_overhead.sh with
// bench/b_seg_trace_overhead.cpp.
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "b_seg_common.h"
#include "b_seg_timing.h"
#include "bench_util.h"
#include "rtl/seg/CAR_Segmenter.h"
#include "rtl/seg/IA_Segmenter.h"
#include "rtl/seg/SegTrace.h"

namespace
{
    using V = rtl::VectorND<2, float>;

    std::vector<V> scan(size_t n, size_t k) { return rtl::bench::seg::closedScan<V>(n, k, 0.0025f); }

    template<class Log>
    size_t runCar(const std::vector<V> &pts, size_t step, Log *log, size_t &clusters)
    {
        rtl::CAR_Segmenter<V, Log> car(step, 0.05f, 0.5f);
        car.setObserver(log);
        size_t points = 0;
        clusters = 0;
        rtl::bench::seg::segmentCar(car, pts, [&](const std::vector<V> &c) {
            points += c.size();
            ++clusters;
        });
        return points;
    }

    template<class Log>
    size_t runIa(const std::vector<V> &pts, size_t step, Log *log, size_t &clusters)
    {
        rtl::IA_Segmenter<V, Log> ia(step, 0.05f, 0.5f, rtl::detail::circularScaling<float>(step + 1, pts.size()));
        ia.setObserver(log);
        size_t points = 0;
        clusters = 0;
        rtl::bench::seg::segmentIa(ia, pts, [&](const std::vector<V> &c) {
            points += c.size();
            ++clusters;
        });
        return points;
    }

    void check(bool ok, const char *what)
    {
        if (ok) return;
        std::fprintf(stderr, "wrong result: %s\n", what);
        std::exit(1);
    }

    //! One group: NoTrace (floor), traced type without observer, traced type recording. `Log` is the log type.
    template<class Log, class Run>
    void group(const char *name, const std::vector<V> &pts, size_t step, size_t k, Run &&run, const rtl::bench::Options &opt)
    {
        namespace sb = rtl::bench::seg;
        const size_t n = pts.size();
        size_t c0 = 0, c1 = 0, c2 = 0, p0 = 0, p1 = 0, p2 = 0;
        Log log;
        const auto t0 = sb::measure([&] { p0 = run(static_cast<rtl::NoTrace *>(nullptr), c0); }, opt.repetitions);
        const auto t1 = sb::measure([&] { p1 = run(static_cast<Log *>(nullptr), c1); }, opt.repetitions);
        const auto t2 = sb::measure([&] {
            log.clear();
            p2 = run(&log, c2);
        }, opt.repetitions);
        check(c0 == k && c1 == k && c2 == k && p0 == n && p1 == n && p2 == n, name);
        const std::string tag = std::string(name) + " step " + std::to_string(step);
        char note[64];
        std::snprintf(note, sizeof note, ", %.1f events/point", static_cast<double>(log.size()) / static_cast<double>(n));
        sb::row(tag + " NoTrace", n, t0, t0);
        sb::row(tag + " traced type, no observer", n, t1, t0);
        sb::row(tag + " recording a TraceLog", n, t2, t0, note);
    }
}

int main(int argc, char **argv)
{
    const auto opt = rtl::bench::parseOptions(argc, argv);
    const size_t n = opt.smoke ? 20000 : 100000, k = opt.smoke ? 10 : 100;
    const auto pts = scan(n, k);
    rtl::bench::printHeader("tracing cost of the segmenters, 2D float (ratio = time / NoTrace time)");
    for (size_t window : {1, 2, 3})
    {
        group<rtl::CarTraceLog>("CAR", pts, window + 1, k,
                                [&](auto *log, size_t &clusters) { return runCar(pts, window + 1, log, clusters); }, opt);
        group<rtl::IaTraceLog>("IA", pts, window, k,
                               [&](auto *log, size_t &clusters) { return runIa(pts, window, log, clusters); }, opt);
    }
    return 0;
}
