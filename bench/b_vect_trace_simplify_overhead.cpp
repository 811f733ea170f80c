// Zero cost of the ITLS / Douglas-Peucker / Reumann-Witkam trace hooks when unused: the untraced API only, so the
// same source compiles against the headers before tracing and after (bench/trace_overhead.sh compares both builds
// in one run). Setting of bench/b_vect_2d.cpp: semicircle r = 8, noise 0.01, 1e5 points, sigma 0.03, epsilon 0.09.
// Ratios are to a floor pass (x, y, x2, y2, xy sums) measured in the same run. For bench/trace_overhead.sh it
// prints `time_ns <case> <median ns per call>` and `check <case> <segments> <checksum>` (the results of both builds
// must agree).
#include <cmath>
#include <cstdio>
#include <random>
#include <string>
#include <vector>

#include "bench_semicircle.h"
#include "bench_util.h"
#include "rtl/Vectorization.h"

namespace
{
    using rtl::bench::semicircle;
    using rtl::bench::segmentChecksum;
    double floorPass(const std::vector<rtl::Vector2f> &pts)
    {
        double x = 0, y = 0, x2 = 0, y2 = 0, xy = 0;
        for (const auto &p : pts)
        {
            const double px = p.x(), py = p.y();
            x += px; y += py; x2 += px * px; y2 += py * py; xy += px * py;
        }
        return x + y + x2 + y2 + xy;
    }
}

int main(int argc, char **argv)
{
    const auto opt = rtl::bench::parseOptions(argc, argv);
    const size_t n = opt.smoke ? 1000 : 100000;
    const auto pts = semicircle(n, 42);

    rtl::VectorizerITLSProjections2D<float, double> itls;
    rtl::VectorizerDouglasPeucker2f dp(0.09f);
    rtl::VectorizerReumannWitkam2f rw(0.09f);
    itls.setSigma(0.03f);
    itls.setMaxSize(n);
    dp.setMaxSize(n);
    rw.setMaxSize(n);
    std::vector<rtl::LineSegment2f> out;
    out.reserve(n);

    double sink = 0;
    size_t s_itls = 0, s_dp = 0, s_rw = 0;
    double c_itls = 0, c_dp = 0, c_rw = 0;
    bool ok = true;
    const double t_floor = rtl::bench::medianSeconds([&] { sink += floorPass(pts); }, opt.repetitions);
    rtl::bench::doNotOptimize(sink);
    const double t_itls = rtl::bench::medianSeconds([&] { ok &= itls(pts); s_itls = itls.indices().size(); }, opt.repetitions);
    c_itls = segmentChecksum(itls.lineSegments());
    const double t_dp = rtl::bench::medianSeconds([&] { dp(pts, out); s_dp = out.size(); }, opt.repetitions);
    c_dp = segmentChecksum(out);
    const double t_rw = rtl::bench::medianSeconds([&] { rw(pts, out); s_rw = out.size(); }, opt.repetitions);
    c_rw = segmentChecksum(out);

    rtl::bench::printHeader(("untraced ITLS / DP / RW, 2D semicircle r=8, noise 0.01, " + std::to_string(n) + " points").c_str());
    rtl::bench::printRow("floor (x, y, x2, y2, xy pass)", n, t_floor, t_floor);
    rtl::bench::printRow("incremental TLS sigma 0.03", n, t_itls, t_floor, "segs=" + std::to_string(s_itls));
    rtl::bench::printRow("Douglas-Peucker eps 0.09", n, t_dp, t_floor, "segs=" + std::to_string(s_dp));
    rtl::bench::printRow("Reumann-Witkam eps 0.09", n, t_rw, t_floor, "segs=" + std::to_string(s_rw));
    std::printf("time_ns floor %.0f\ntime_ns itls %.0f\ntime_ns dp %.0f\ntime_ns rw %.0f\n", t_floor * 1e9, t_itls * 1e9,
                t_dp * 1e9, t_rw * 1e9);
    std::printf("check itls %zu %.9e\ncheck dp %zu %.9e\ncheck rw %zu %.9e\n", s_itls, c_itls, s_dp, c_dp, s_rw, c_rw);
    if (!ok)
    {
        std::printf("!! the incremental vectorizer returned false\n");
        return 1;
    }
    return 0;
}
