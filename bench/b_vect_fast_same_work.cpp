// FTLS/AFTLS at the same work as their floors: the paper's semicircle (radius 8, noise
// 0.01, sigma 0.03, delta 3) at 1e5, 1e6 and 1e7 points. Each figure is the median time of a vectorizer call on a
// reused object divided by the median time of its floor, measured in interleaved rounds of the same run:
//   2D floor: one pass accumulating x, y, x^2, y^2, xy in double (the 5 prefix-sum moments);
//   3D floor: the 9 moments of a 3D point (semicircle in the xy plane, noise on all three axes).
// AFTLS linear in n means its ratio stays flat from 1e5 to 1e7. --smoke: 1e3 points, one round. Also prints the
// `time_ns` / `check` lines of bench/trace_overhead.sh (e.g. ROUNDS=7 bench/trace_overhead.sh
// bench/b_vect_fast_same_work.cpp <base-commit>).
// Times are the thread's CPU time (CLOCK_THREAD_CPUTIME_ID): on the shared 2-core VM wall time also counts the
// time the thread waits for a core (at load ~7 one wall-time run put AFTLS 2D at 5.5x the floor at 1M, the
// CPU-time run right after at 1.45x).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <time.h>
#include <type_traits>
#include <utility>
#include <vector>

#include "bench_util.h"
#include "rtl/Vectorization.h"

namespace
{
    template<class V>
    std::vector<V> semicircle(size_t n, unsigned seed)
    {
        std::mt19937 gen(seed);
        std::normal_distribution<double> nd(0.0, 0.01);
        std::vector<V> pts;
        pts.reserve(n);
        for (size_t i = 0; i < n; ++i)
        {
            const double a = M_PI * static_cast<double>(i) / static_cast<double>(n - 1);
            V p;
            p[0] = static_cast<float>(8 * std::cos(a) + nd(gen));
            p[1] = static_cast<float>(8 * std::sin(a) + nd(gen));
            if constexpr (std::is_same_v<V, rtl::Vector3f>)
                p[2] = static_cast<float>(nd(gen));
            pts.push_back(p);
        }
        return pts;
    }

    double floor2D(const std::vector<rtl::Vector2f> &pts)
    {
        double x = 0, y = 0, x2 = 0, y2 = 0, xy = 0;
        for (const auto &p : pts)
        {
            const double px = p.x(), py = p.y();
            x += px; y += py; x2 += px * px; y2 += py * py; xy += px * py;
        }
        return x + y + x2 + y2 + xy;
    }

    double floor3D(const std::vector<rtl::Vector3f> &pts)
    {
        double x = 0, y = 0, z = 0, x2 = 0, y2 = 0, z2 = 0, xy = 0, yz = 0, zx = 0;
        for (const auto &p : pts)
        {
            const double px = p.x(), py = p.y(), pz = p.z();
            x += px; y += py; z += pz; x2 += px * px; y2 += py * py; z2 += pz * pz; xy += px * py; yz += py * pz; zx += pz * px;
        }
        return x + y + z + x2 + y2 + z2 + xy + yz + zx;
    }

    double cpuNow()
    {
        timespec ts{};
        clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
        return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
    }

    template<class F>
    double seconds(F &&f)
    {
        const double t0 = cpuNow();
        f();
        return cpuNow() - t0;
    }

    double median(std::vector<double> v)
    {
        std::sort(v.begin(), v.end());
        return v[v.size() / 2];
    }
}

int main(int argc, char **argv)
{
    const auto opt = rtl::bench::parseOptions(argc, argv);
    const std::vector<size_t> sizes = opt.smoke ? std::vector<size_t>{1000} : std::vector<size_t>{100000, 1000000, 10000000};
    const int rounds = opt.smoke ? 1 : std::max(5, opt.repetitions);
    std::printf("FTLS/AFTLS against their moment floors (semicircle r 8, noise 0.01, sigma 0.03, delta 3), CPU-time medians of %d interleaved rounds\n",
                rounds);
    std::printf("%10s %12s %12s %10s %10s %12s %10s %10s\n", "points", "floor2D ns", "floor3D ns", "FTLS 2D", "AFTLS 2D", "FTLS 3D",
                "AFTLS 3D", "segs 2D");
    for (size_t n : sizes)
    {
        const auto p2 = semicircle<rtl::Vector2f>(n, 7);
        const auto p3 = semicircle<rtl::Vector3f>(n, 8);
        rtl::VectorizerFTLSPolyline2D<float, double> ftls2;
        rtl::VectorizerAFTLSPolyline2D<float, double> aftls2;
        rtl::VectorizerFTLSProjections3D<float, double> ftls3;
        rtl::VectorizerAFTLSProjections3D<float, double> aftls3;
        std::vector<double> f2, f3, t_ftls2, t_aftls2, t_ftls3, t_aftls3;
        bool ok = ftls2(p2) && aftls2(p2) && ftls3(p3) && aftls3(p3);   // warm-up (buffers sized once)
        double sink = 0;
        for (int r = 0; r < rounds; ++r)
        {
            f2.push_back(seconds([&] { sink += floor2D(p2); }));
            t_ftls2.push_back(seconds([&] { ok &= ftls2(p2); }));
            t_aftls2.push_back(seconds([&] { ok &= aftls2(p2); }));
            f3.push_back(seconds([&] { sink += floor3D(p3); }));
            t_ftls3.push_back(seconds([&] { ok &= ftls3(p3); }));
            t_aftls3.push_back(seconds([&] { ok &= aftls3(p3); }));
        }
        rtl::bench::doNotOptimize(sink);
        if (!ok)
        {
            std::fprintf(stderr, "a vectorizer failed on the semicircle of %zu points\n", n);
            return 1;
        }
        const double m2 = median(f2), m3 = median(f3);
        std::printf("%10zu %12.3f %12.3f %9.2fx %9.2fx %11.2fx %9.2fx %10zu\n", n, m2 / static_cast<double>(n) * 1e9,
                    m3 / static_cast<double>(n) * 1e9, median(t_ftls2) / m2, median(t_aftls2) / m2, median(t_ftls3) / m3,
                    median(t_aftls3) / m3, ftls2.indices().size());
        // bench/trace_overhead.sh lines: the same source built against an older tree gives the speed-up at equal
        // results (range counts of each vectorizer)
        const std::pair<const char *, double> cases[] = {{"floor2d", m2}, {"floor3d", m3}, {"ftls2d", median(t_ftls2)},
                                                         {"aftls2d", median(t_aftls2)}, {"ftls3d", median(t_ftls3)}, {"aftls3d", median(t_aftls3)}};
        for (const auto &c : cases)
            std::printf("time_ns %s_%zu %.0f\n", c.first, n, c.second * 1e9);
        std::printf("check ftls2d_%zu %zu\ncheck aftls2d_%zu %zu\ncheck ftls3d_%zu %zu\ncheck aftls3d_%zu %zu\n", n, ftls2.indices().size(), n,
                    aftls2.indices().size(), n, ftls3.indices().size(), n, aftls3.indices().size());
    }
    return 0;
}
