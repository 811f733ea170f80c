// solveAssignment (Munkres / Hungarian) at N = 100 and 500, random integer and double costs, min and max.
// The floor measured in the same run is N^3 multiply-adds (a naive N x N matrix product), the order of work
// of the algorithm: the ratio says how many such N^3 passes one assignment costs.
#include <cstdio>
#include <random>
#include <vector>

#include "bench_util.h"
#include "rtl/alg/munkres/Assignment.h"

namespace
{
    double naiveProductSeconds(size_t n, int reps)
    {
        std::vector<double> a(n * n, 1.0001), b(n * n, 0.9999), c(n * n);
        return rtl::bench::medianSeconds([&] {
            for (size_t i = 0; i < n; ++i)
                for (size_t k = 0; k < n; ++k)
                {
                    const double aik = a[i * n + k];
                    for (size_t j = 0; j < n; ++j)
                        c[i * n + j] += aik * b[k * n + j];
                }
            rtl::bench::doNotOptimize(c[n + 1]);
        }, reps);
    }

    template<typename T>
    std::vector<T> randomCosts(size_t n, std::mt19937 &rng)
    {
        std::vector<T> v(n * n);
        for (T &x : v)
        {
            if constexpr (std::is_integral_v<T>)
                x = std::uniform_int_distribution<T>(0, 1000)(rng);
            else
                x = std::uniform_real_distribution<T>(0, 1)(rng);
        }
        return v;
    }
}

int main(int argc, char **argv)
{
    const auto opt = rtl::bench::parseOptions(argc, argv);
    const std::vector<size_t> sizes = opt.smoke ? std::vector<size_t>{8} : std::vector<size_t>{100, 500};
    std::mt19937 rng(1);
    rtl::bench::printHeader("solveAssignment vs N^3 multiply-adds (points = N)");
    for (size_t n : sizes)
    {
        const int reps = n >= 500 ? std::max(1, opt.repetitions / 2) : opt.repetitions;
        const double floor_s = naiveProductSeconds(n, reps);
        const auto ci = randomCosts<int>(n, rng);
        const auto cd = randomCosts<double>(n, rng);
        size_t sink = 0;
        const double ti = rtl::bench::medianSeconds([&] { sink += rtl::solveAssignment(ci, n, n)[0]; }, reps);
        const double td = rtl::bench::medianSeconds([&] { sink += rtl::solveAssignment(cd, n, n)[0]; }, reps);
        const double tm = rtl::bench::medianSeconds([&] { sink += rtl::solveAssignment(cd, n, n, true)[0]; }, reps);
        const double tr = rtl::bench::medianSeconds([&] { sink += rtl::solveAssignment(cd.data(), n / 2, n)[0]; }, reps);
        rtl::bench::doNotOptimize(sink);
        const std::string sz = " N=" + std::to_string(n);
        rtl::bench::printRow("floor: naive N^3 product" + sz, n, floor_s, floor_s, std::to_string(floor_s * 1e3) + " ms");
        rtl::bench::printRow("int costs 0..1000, min" + sz, n, ti, floor_s, std::to_string(ti * 1e3) + " ms");
        rtl::bench::printRow("double costs, min" + sz, n, td, floor_s, std::to_string(td * 1e3) + " ms");
        rtl::bench::printRow("double costs, max" + sz, n, tm, floor_s, std::to_string(tm * 1e3) + " ms");
        rtl::bench::printRow("double costs, N/2 x N" + sz, n, tr, floor_s, std::to_string(tr * 1e3) + " ms");
    }
    return 0;
}
