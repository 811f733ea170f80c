// FTLS/AFTLS 2D on chains of repeated points against a typical chain of the same size, measured in the same run:
//   far copies      N copies of (1e15, 1e15), float points, double sums, sigma 0.033, delta 1 (FTLS): the sums
//                   cancel into noise, so before the search decided ranges of identical points exactly, they fit at
//                   random and the exact search visited O(N^2) of them;
//   subnormal sigma N copies of (123.456, 1e5), float points and sums, sigma 2^-140 (its square is 0), delta 3.4
//                   (AFTLS);
//   run in a chain  a straight chain, then N/3 copies of one point, then another straight chain (FTLS, double);
//   two far runs    copies of (1e15, 1e15), then N/30 copies of (1e15, 9.5e14), float points, double sums, sigma
//                   1/32, delta 1 (FTLS): the fuzz harness's reproducer at N = 1,324, no strict partition;
//   baseline        a noisy polyline (pieces of 60 points, noise 0.005, turns of 30-90 degrees), sigma 0.03,
//                   delta 0.3 (FTLS, double).
// Each row: points per second, the time as a ratio to the baseline at the same N, and the exact search's fits per
// point (a work count, as tests/vect/t_duplicate_runs.cpp pins). --smoke: N = 200, one call. --max-n=N: only the
// sizes up to N (the search before ranges were kept from ending deep inside runs took minutes beyond 4,000).
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstdio>
#include <cstring>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "bench_util.h"
#include "rtl/Core.h"
#include "rtl/Vectorization.h"

namespace
{
    template<typename E, typename C>
    struct Ftls : rtl::VectorizerFTLSPolyline2D<E, C>
    {
        auto work() const { return this->pipeline.searchWork(); }
    };
    template<typename E, typename C>
    struct Aftls : rtl::VectorizerAFTLSPolyline2D<E, C>
    {
        auto work() const { return this->pipeline.searchWork(); }
    };

    //! A noisy polyline: straight pieces of 60 points (step 0.02, noise 0.005) turning by +-(30..90) degrees.
    std::vector<rtl::Vector2d> baselineChain(size_t n)
    {
        std::mt19937 g(1);
        std::normal_distribution<double> nd(0, 0.005);
        std::uniform_real_distribution<double> turn(0.5, 1.5);
        std::vector<rtl::Vector2d> p;
        double x = 0, y = 0, a = 0;
        for (size_t i = 0; i < n; ++i)
        {
            if (i > 0 && i % 60 == 0)
                a += (i / 60 % 2 ? 1 : -1) * turn(g);
            p.emplace_back(x + nd(g), y + nd(g));
            x += 0.02 * std::cos(a);
            y += 0.02 * std::sin(a);
        }
        return p;
    }

    std::vector<rtl::Vector2d> runInChain(size_t n)
    {
        std::vector<rtl::Vector2d> p;
        for (size_t i = 0; i < n; ++i)
        {
            const double x = 0.01 * static_cast<double>(i < n / 3 || i >= 2 * n / 3 ? i : n / 3);
            p.emplace_back(x, i < n / 3 ? 0.0 : i >= 2 * n / 3 ? 1.0 : 0.5);
        }
        return p;
    }

    std::vector<rtl::Vector2f> twoFarRuns(size_t n)
    {
        std::vector<rtl::Vector2f> p(n, rtl::Vector2f(999999986991104.0f, 999999986991104.0f));
        for (size_t i = n - n / 30; i < n; ++i)
            p[i] = rtl::Vector2f(999999986991104.0f, 951685228789760.0f);
        return p;
    }

    //! Median seconds of calls of v on pts (sigma, delta); the search's fits of one call and its result.
    template<class V, class P>
    double timeIt(V &v, const P &pts, double sigma, double delta, int reps, double &fits_per_call, bool &ok)
    {
        typedef typename V::ElementType E;
        v.setSigma(static_cast<E>(sigma));
        v.setDelta(static_cast<E>(delta));
        v.setMaxSize(pts.size());
        const size_t before = v.work().fits;
        ok = v(pts);
        fits_per_call = static_cast<double>(v.work().fits - before);
        return rtl::bench::medianSeconds([&] { const bool r = v(pts); rtl::bench::doNotOptimize(r); }, reps);
    }
}

int main(int argc, char **argv)
{
    const auto opt = rtl::bench::parseOptions(argc, argv);
    size_t max_n = std::numeric_limits<size_t>::max();
    for (int i = 1; i < argc; ++i)
        if (std::strncmp(argv[i], "--max-n=", 8) == 0)
            max_n = std::strtoul(argv[i] + 8, nullptr, 10);
    std::vector<size_t> sizes = opt.smoke ? std::vector<size_t>{200} : std::vector<size_t>{500, 1000, 1324, 1486, 2000, 4000, 16000};
    sizes.erase(std::remove_if(sizes.begin(), sizes.end(), [&](size_t n) { return n > max_n; }), sizes.end());
    rtl::bench::printHeader("FTLS/AFTLS 2D: repeated points against a typical chain (ratio: time / baseline at the same N)");
    for (size_t n : sizes)
    {
        double f = 0;
        bool ok = false;
        auto note = [&] { return std::string(ok ? "true" : "false") + ", search fits/point " + std::to_string(f / static_cast<double>(n)); };
        Ftls<double, double> base;
        const double tb = timeIt(base, baselineChain(n), 0.03, 0.3, opt.repetitions, f, ok);
        rtl::bench::printRow("baseline: noisy polyline, FTLS double", n, tb, tb, note());
        Ftls<float, double> far;
        const std::vector<rtl::Vector2f> far_pts(n, rtl::Vector2f(1e15f, 1e15f));
        const double t1 = timeIt(far, far_pts, 0.033, 1.0, opt.repetitions, f, ok);
        rtl::bench::printRow("far copies, FTLS float/double", n, t1, tb, note());
        Aftls<float, float> sub;
        const std::vector<rtl::Vector2f> sub_pts(n, rtl::Vector2f(123.456f, 1e5f));
        const double t2 = timeIt(sub, sub_pts, std::ldexp(1.0, -140), 3.4, opt.repetitions, f, ok);
        rtl::bench::printRow("subnormal sigma copies, AFTLS float/float", n, t2, tb, note());
        Ftls<double, double> run;
        const double t3 = timeIt(run, runInChain(n), 0.033, 1.0, opt.repetitions, f, ok);
        rtl::bench::printRow("N/3 copies inside a chain, FTLS double", n, t3, tb, note());
        Ftls<float, double> two;
        const double t4 = timeIt(two, twoFarRuns(n), 1.0 / 32, 1.0, opt.repetitions, f, ok);
        rtl::bench::printRow("two far runs, FTLS float/double", n, t4, tb, note());
    }
    return 0;
}
