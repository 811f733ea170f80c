// 2D vectorization throughput in the papers' setting: semicircle of radius 8, Gaussian noise 0.01, sigma 0.03,
// delta 3, epsilon 0.09 (DP, RW), 1e3 .. 1e6 points; then the real laser scans of tests/data, chain by chain.
// Baseline ("floor", ratio 1.0): one pass accumulating x, y, x^2, y^2, xy in double, measured in the same run.
// Published figures on this machine at 1e5 points (points/s): RW 6.5e8, DP 1.2e8, incremental 3.8e7,
// FTLS 2.35e8, AFTLS 2.1e8.
#include <cmath>
#include <cstdio>
#include <random>
#include <string>
#include <vector>

#include "bench_semicircle.h"
#include "bench_util.h"
#include "scan_chains.h"
#include "rtl/Vectorization.h"
#include "rtl/io/CarmenLog.h"

namespace
{
    using rtl::bench::semicircle;
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

    //! The five vectorizers on one set of chains; times are summed over the chains.
    void run(const char *title, const std::vector<std::vector<rtl::Vector2f>> &chains, size_t max_size, int reps, bool published)
    {
        size_t points = 0;
        for (const auto &c : chains)
            points += c.size();
        rtl::VectorizerFTLSPolyline2D<float, double> ftls;
        rtl::VectorizerAFTLSPolyline2D<float, double> aftls;
        rtl::VectorizerITLSProjections2D<float, double> itls;
        rtl::VectorizerDouglasPeucker2f dp(0.09f);
        rtl::VectorizerReumannWitkam2f rw(0.09f);
        ftls.setSigma(0.03f); ftls.setDelta(3.f); ftls.setMaxSize(max_size);
        aftls.setSigma(0.03f); aftls.setDelta(3.f); aftls.setMaxSize(max_size);
        itls.setSigma(0.03f); itls.setMaxSize(max_size);
        dp.setMaxSize(max_size);
        rw.setMaxSize(max_size);
        std::vector<rtl::LineSegment2f> out;
        out.reserve(max_size);

        double sink = 0;
        const double t_floor = rtl::bench::medianSeconds([&] { for (const auto &c : chains) sink += floorPass(c); }, reps);
        rtl::bench::doNotOptimize(sink);
        size_t s_ftls = 0, s_aftls = 0, s_itls = 0, s_dp = 0, s_rw = 0;
        bool ok = true;
        const double t_ftls = rtl::bench::medianSeconds([&] { s_ftls = 0; for (const auto &c : chains) { ok &= ftls(c); s_ftls += ftls.indices().size(); } }, reps);
        const double t_aftls = rtl::bench::medianSeconds([&] { s_aftls = 0; for (const auto &c : chains) { ok &= aftls(c); s_aftls += aftls.indices().size(); } }, reps);
        const double t_itls = rtl::bench::medianSeconds([&] { s_itls = 0; for (const auto &c : chains) { ok &= itls(c); s_itls += itls.indices().size(); } }, reps);
        const double t_dp = rtl::bench::medianSeconds([&] { s_dp = 0; for (const auto &c : chains) { dp(c, out); s_dp += out.size(); } }, reps);
        const double t_rw = rtl::bench::medianSeconds([&] { s_rw = 0; for (const auto &c : chains) { rw(c, out); s_rw += out.size(); } }, reps);

        rtl::bench::printHeader(title);
        rtl::bench::printRow("floor (x, y, x2, y2, xy pass)", points, t_floor, t_floor);
        rtl::bench::printRow("Reumann-Witkam eps 0.09", points, t_rw, t_floor, rtl::bench::segmentsNote(s_rw, published ? 6.5e8 : 0));
        rtl::bench::printRow("Douglas-Peucker eps 0.09", points, t_dp, t_floor, rtl::bench::segmentsNote(s_dp, published ? 1.2e8 : 0));
        rtl::bench::printRow("incremental TLS sigma 0.03", points, t_itls, t_floor, rtl::bench::segmentsNote(s_itls, published ? 3.8e7 : 0, 5));
        rtl::bench::printRow("FTLS sigma 0.03 delta 3", points, t_ftls, t_floor, rtl::bench::segmentsNote(s_ftls, published ? 2.35e8 : 0));
        rtl::bench::printRow("AFTLS sigma 0.03 delta 3", points, t_aftls, t_floor, rtl::bench::segmentsNote(s_aftls, published ? 2.1e8 : 0));
        if (!ok)
            std::printf("!! a vectorizer returned false\n");
    }
}

int main(int argc, char **argv)
{
    const auto opt = rtl::bench::parseOptions(argc, argv);
    const std::vector<size_t> sizes = opt.smoke ? std::vector<size_t>{1000} : std::vector<size_t>{1000, 10000, 100000, 1000000};
    for (size_t n : sizes)
    {
        // Small inputs are repeated so that each timed run covers at least 1e5 points.
        const size_t copies = opt.smoke ? 1 : std::max<size_t>(1, 100000 / n);
        std::vector<std::vector<rtl::Vector2f>> chains(copies, semicircle(n, 42));
        const std::string title = "2D semicircle r=8, noise 0.01, " + std::to_string(n) + " points" +
                                  (copies > 1 ? " (x" + std::to_string(copies) + ")" : "");
        run(title.c_str(), chains, n, opt.repetitions, n == 100000);
    }

    // Real scans: chains of >= 10 finite points split at gaps > 0.5 m.
    const auto chains = test_data::laserChains(10);
    size_t longest = 0;
    for (const auto &c : chains) longest = std::max(longest, c.size());
    const std::string title = "real laser scans (Intel + CSAIL, 60 scans, " + std::to_string(chains.size()) + " chains)";
    run(title.c_str(), chains, longest, opt.repetitions, false);
    return 0;
}
