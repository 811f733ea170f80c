// Incremental TLS 2D and Douglas-Peucker 2D at the paper's setting (semicircle r 8, noise 0.01, sigma 0.03, eps
// 0.09) at 1e5, 1e6 and 1e7 points, with their floors (one pass of the five moments; one pass of squared distances
// to one chord and their maximum), in the untraced API only, so that bench/trace_overhead.sh can compile it against
// an older tree and the current one and run both alternately. Per size, the cases run in interleaved rounds
// (floors, ITLS, DP, floors, ...); a case's figure is the median CPU time (CLOCK_PROCESS_CPUTIME_ID) of the rounds.
// Prints `time_ns <case>_<size> <ns>` and `check <case>_<size> <segments> <checksum>` (both builds must agree).
// Options: --smoke (2000 points, one round), --reps=N, --size=N (one size only, e.g. for callgrind).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>
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
    double cpuSeconds()
    {
        timespec ts{};
        clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
        return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
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
    std::vector<size_t> sizes = opt.smoke ? std::vector<size_t>{2000} : std::vector<size_t>{100000, 1000000, 10000000};
    for (int i = 1; i < argc; ++i)
        if (std::strncmp(argv[i], "--size=", 7) == 0)
            sizes = {static_cast<size_t>(std::atof(argv[i] + 7))};
    for (size_t n : sizes)
    {
        const auto pts = semicircle(n, 42);
        rtl::VectorizerITLSProjections2D<float, double> itls;
        rtl::VectorizerDouglasPeucker2f dp(0.09f);
        itls.setSigma(0.03f);
        itls.setMaxSize(n);
        dp.setMaxSize(n);
        std::vector<rtl::LineSegment2f> out;
        out.reserve(n);
        const auto &a = pts.front(), &b = pts.back();
        const float ux = b.x() - a.x(), uy = b.y() - a.y();
        size_t s_itls = 0, s_dp = 0;
        bool ok = true;
        auto floor5 = [&] {
            double x = 0, y = 0, x2 = 0, y2 = 0, xy = 0;
            for (const auto &p : pts)
            {
                const double px = p.x(), py = p.y();
                x += px; y += py; x2 += px * px; y2 += py * py; xy += px * py;
            }
            rtl::bench::doNotOptimize(x + y + x2 + y2 + xy);
        };
        auto floorChord = [&] {
            float m = 0;
            for (const auto &p : pts)
            {
                const float c = (p.x() - a.x()) * uy - (p.y() - a.y()) * ux;
                m = std::max(m, c * c);
            }
            rtl::bench::doNotOptimize(m);
        };
        auto runItls = [&] { ok &= itls(pts); s_itls = itls.indices().size(); };
        auto runDp = [&] { dp(pts, out); s_dp = out.size(); };
        std::vector<double> t[4];
        floor5(); floorChord(); runItls(); runDp();   // warm-up
        for (int r = 0; r < opt.repetitions; ++r)
        {
            double s = cpuSeconds();
            floor5();
            double e = cpuSeconds(); t[0].push_back(e - s); s = e;
            floorChord();
            e = cpuSeconds(); t[1].push_back(e - s); s = e;
            runItls();
            e = cpuSeconds(); t[2].push_back(e - s); s = e;
            runDp();
            e = cpuSeconds(); t[3].push_back(e - s);
        }
        itls(pts);
        const double c_itls = segmentChecksum(itls.lineSegments());
        dp(pts, out);
        const double c_dp = segmentChecksum(out);
        const std::string sz = std::to_string(n);
        rtl::bench::printHeader(("ITLS / DP, 2D semicircle r=8, noise 0.01, " + sz + " points, CPU-time medians").c_str());
        const double f5 = median(t[0]), fc = median(t[1]);
        rtl::bench::printRow("floor: five moments", n, f5, f5);
        rtl::bench::printRow("floor: distance to one chord", n, fc, fc);
        rtl::bench::printRow("incremental TLS sigma 0.03 (/ moments)", n, median(t[2]), f5, "segs=" + std::to_string(s_itls));
        rtl::bench::printRow("Douglas-Peucker eps 0.09 (/ chord)", n, median(t[3]), fc, "segs=" + std::to_string(s_dp));
        std::printf("time_ns floor5_%s %.0f\ntime_ns floorchord_%s %.0f\ntime_ns itls_%s %.0f\ntime_ns dp_%s %.0f\n",
                    sz.c_str(), f5 * 1e9, sz.c_str(), fc * 1e9, sz.c_str(), median(t[2]) * 1e9, sz.c_str(), median(t[3]) * 1e9);
        std::printf("check itls_%s %zu %.9e\ncheck dp_%s %zu %.9e\n", sz.c_str(), s_itls, c_itls, sz.c_str(), s_dp, c_dp);
        if (!ok)
        {
            std::printf("!! the incremental vectorizer returned false\n");
            return 1;
        }
    }
    return 0;
}
