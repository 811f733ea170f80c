// 3D vectorization throughput on a helix (radius 8, pitch 3 per turn, 4 turns, Gaussian noise 0.01, sigma 0.03),
// 1e3 .. 1e6 points, and on the four Ouster rings of tests/data. Baseline ("floor", ratio 1.0): one pass
// accumulating the nine 3D sums (x, y, z, x^2, y^2, z^2, xy, yz, zx) in double, measured in the same run.
// Published figures on this machine, helix at 1e5 points (points/s): incremental 1.1e7, FTLS 1.35e8, AFTLS 4.2e7.
#include <cmath>
#include <cstdio>
#include <random>
#include <string>
#include <vector>

#include "bench_util.h"
#include "scan_chains.h"
#include "rtl/Vectorization.h"
#include "rtl/io/OrganizedLidar.h"

namespace
{
    std::vector<rtl::Vector3f> helix(size_t n, unsigned seed)
    {
        std::mt19937 gen(seed);
        std::normal_distribution<double> nd(0.0, 0.01);
        std::vector<rtl::Vector3f> pts;
        pts.reserve(n);
        for (size_t i = 0; i < n; ++i)
        {
            const double t = 4.0 * static_cast<double>(i) / static_cast<double>(n - 1), a = 2 * M_PI * t;
            pts.emplace_back(static_cast<float>(8 * std::cos(a) + nd(gen)), static_cast<float>(8 * std::sin(a) + nd(gen)),
                             static_cast<float>(3 * t + nd(gen)));
        }
        return pts;
    }

    double floorPass(const std::vector<rtl::Vector3f> &pts)
    {
        double s[9] = {};
        for (const auto &p : pts)
        {
            const double x = p.x(), y = p.y(), z = p.z();
            s[0] += x; s[1] += y; s[2] += z; s[3] += x * x; s[4] += y * y; s[5] += z * z; s[6] += x * y; s[7] += y * z; s[8] += z * x;
        }
        return s[0] + s[1] + s[2] + s[3] + s[4] + s[5] + s[6] + s[7] + s[8];
    }

    void run(const char *title, const std::vector<std::vector<rtl::Vector3f>> &chains, size_t max_size, int reps, bool published)
    {
        size_t points = 0;
        for (const auto &c : chains)
            points += c.size();
        rtl::VectorizerFTLSProjections3D<float, double> ftls;
        rtl::VectorizerAFTLSProjections3D<float, double> aftls;
        rtl::VectorizerITLSProjections3D<float, double> itls;
        rtl::VectorizerAFTLSPlaneProjections3D<float, double> planes;
        rtl::VectorizerDouglasPeucker3f dp(0.09f);
        rtl::VectorizerReumannWitkam3f rw(0.09f);
        ftls.setSigma(0.03f); ftls.setMaxSize(max_size);
        aftls.setSigma(0.03f); aftls.setMaxSize(max_size);
        itls.setSigma(0.03f); itls.setMaxSize(max_size);
        planes.setSigma(0.03f); planes.setMaxSize(max_size);
        dp.setMaxSize(max_size);
        rw.setMaxSize(max_size);
        std::vector<rtl::LineSegment3f> out;

        double sink = 0;
        const double t_floor = rtl::bench::medianSeconds([&] { for (const auto &c : chains) sink += floorPass(c); }, reps);
        rtl::bench::doNotOptimize(sink);
        size_t s_f = 0, s_a = 0, s_i = 0, s_p = 0, s_dp = 0, s_rw = 0;
        bool ok = true;
        const double t_f = rtl::bench::medianSeconds([&] { s_f = 0; for (const auto &c : chains) { ok &= ftls(c); s_f += ftls.indices().size(); } }, reps);
        const double t_a = rtl::bench::medianSeconds([&] { s_a = 0; for (const auto &c : chains) { ok &= aftls(c); s_a += aftls.indices().size(); } }, reps);
        const double t_i = rtl::bench::medianSeconds([&] { s_i = 0; for (const auto &c : chains) { ok &= itls(c); s_i += itls.indices().size(); } }, reps);
        const double t_p = rtl::bench::medianSeconds([&] { s_p = 0; for (const auto &c : chains) { ok &= planes(c); s_p += planes.indices().size(); } }, reps);
        const double t_dp = rtl::bench::medianSeconds([&] { s_dp = 0; for (const auto &c : chains) { dp(c, out); s_dp += out.size(); } }, reps);
        const double t_rw = rtl::bench::medianSeconds([&] { s_rw = 0; for (const auto &c : chains) { rw(c, out); s_rw += out.size(); } }, reps);

        rtl::bench::printHeader(title);
        rtl::bench::printRow("floor (nine 3D sums pass)", points, t_floor, t_floor);
        rtl::bench::printRow("Reumann-Witkam 3D eps 0.09", points, t_rw, t_floor, rtl::bench::segmentsNote(s_rw));
        rtl::bench::printRow("Douglas-Peucker 3D eps 0.09", points, t_dp, t_floor, rtl::bench::segmentsNote(s_dp));
        rtl::bench::printRow("incremental TLS 3D lines", points, t_i, t_floor, rtl::bench::segmentsNote(s_i, published ? 1.1e7 : 0, 5));
        rtl::bench::printRow("FTLS 3D lines", points, t_f, t_floor, rtl::bench::segmentsNote(s_f, published ? 1.35e8 : 0));
        rtl::bench::printRow("AFTLS 3D lines", points, t_a, t_floor, rtl::bench::segmentsNote(s_a, published ? 4.2e7 : 0));
        rtl::bench::printRow("AFTLS 3D planes", points, t_p, t_floor, rtl::bench::segmentsNote(s_p));
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
        const size_t copies = opt.smoke ? 1 : std::max<size_t>(1, 100000 / n);
        std::vector<std::vector<rtl::Vector3f>> chains(copies, helix(n, 42));
        const std::string title = "3D helix r=8, 4 turns, noise 0.01, " + std::to_string(n) + " points" +
                                  (copies > 1 ? " (x" + std::to_string(copies) + ")" : "");
        run(title.c_str(), chains, n, opt.repetitions, n == 100000);
    }

    const auto chains = test_data::ousterChains({{"rellis3d-os1-4x2048.bin", 4}}, 10);
    size_t longest = 0;
    for (const auto &c : chains) longest = std::max(longest, c.size());
    const std::string title = "real Ouster rings (4 x 2048, " + std::to_string(chains.size()) + " chains)";
    run(title.c_str(), chains, longest, opt.repetitions, false);
    return 0;
}
