// Zero cost of the FTLS/AFTLS trace hooks when unused: the untraced API only, so the same source compiles against the
// headers before tracing (the base commit given to trace_overhead.sh) and after; bench/trace_overhead.sh compares both
// builds in one run. Cases: the semicircle of bench/b_vect_2d.cpp (r = 8, noise 0.01, 1e5 points) and the laser chains
// of tests/data (runs of >= 10 finite points split at gaps > 0.5 m), sigma 0.03, delta 3. Prints `time_ns <case>
// <median ns per pass>` and `check <case> <segments> <checksum>` (both builds must agree). AFTLS (which keeps the
// better of its own and FTLS's result) also runs FTLS's continuity pass on a copy, so its ratio includes that work,
// not only the hooks.
#include <cmath>
#include <cstdio>
#include <random>
#include <string>
#include <vector>

#include "bench_util.h"
#include "scan_chains.h"
#include "rtl/Vectorization.h"
#include "rtl/io/CarmenLog.h"

#ifndef RTL_TEST_DATA_DIR
#define RTL_TEST_DATA_DIR "tests/data"
#endif

namespace
{
    std::vector<rtl::Vector2f> semicircle(size_t n, unsigned seed)
    {
        std::mt19937 gen(seed);
        std::normal_distribution<double> nd(0.0, 0.01);
        std::vector<rtl::Vector2f> pts;
        for (size_t i = 0; i < n; ++i)
        {
            const double a = M_PI * static_cast<double>(i) / static_cast<double>(n - 1);
            pts.emplace_back(static_cast<float>(8 * std::cos(a) + nd(gen)), static_cast<float>(8 * std::sin(a) + nd(gen)));
        }
        return pts;
    }

    template<class V>
    void measure(const char *name, V &v, const std::vector<std::vector<rtl::Vector2f>> &chains, int reps)
    {
        size_t segs = 0;
        double sum = 0;
        const double t = rtl::bench::medianSeconds([&] {
            segs = 0;
            sum = 0;
            for (const auto &c : chains)
                if (v(c))
                {
                    segs += v.indices().size();
                    for (const auto &g : v.lineSegments())
                        sum += static_cast<double>(g.beg().x()) + 2.0 * g.beg().y() + 3.0 * g.end().x() + 5.0 * g.end().y();
                }
        }, reps);
        std::printf("time_ns %s %.0f\ncheck %s %zu %.6e\n", name, t * 1e9, name, segs, sum);
    }
}

int main(int argc, char **argv)
{
    const auto opt = rtl::bench::parseOptions(argc, argv);
    const std::vector<std::vector<rtl::Vector2f>> circle{semicircle(opt.smoke ? 1000 : 100000, 42)};
    const auto real = test_data::laserChains(10);
    rtl::VectorizerFTLSPolyline2D<float, double> ftls;
    rtl::VectorizerAFTLSPolyline2D<float, double> aftls;
    ftls.setSigma(0.03f); ftls.setDelta(3.f); ftls.setMaxSize(100000);
    aftls.setSigma(0.03f); aftls.setDelta(3.f); aftls.setMaxSize(100000);
    const int reps = std::max(opt.repetitions, 9);
    measure("ftls_semicircle", ftls, circle, reps);
    measure("aftls_semicircle", aftls, circle, reps);
    measure("ftls_real", ftls, real, reps);
    measure("aftls_real", aftls, real, reps);
    return 0;
}
