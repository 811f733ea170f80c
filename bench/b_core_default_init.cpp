// Cost of zero-initialising default constructors (rtl::VectorND, rtl::Matrix) against Eigen's uninitialised
// defaults, measured in the same run:
//  - tight loops that default-construct an object and then fill it: the zero stores are dead and the optimiser
//    removes them, so the ratio should be ~1.0;
//  - bulk allocation (std::vector<T>(n), then filled): here the zeroing is a real extra pass over memory, reported
//    for completeness.
#include <cstdio>
#include <vector>

#include <Eigen/Dense>

#include "bench_util.h"
#include "rtl/Core.h"

namespace
{
    constexpr size_t pool = 3 * 1024;     // source values, small enough to stay in L1

    template<typename V>
    double vectorLoop(const std::vector<double> &src, size_t n)
    {
        const V w(0.5, -0.25, 2.0);
        double acc = 0;
        for (size_t i = 0; i < n; ++i)
        {
            const size_t k = (3 * i) % pool;
            V v;                                     // default construction under test
            v[0] = src[k];
            v[1] = src[k + 1];
            v[2] = src[k + 2];
            acc += v.dot(w);
        }
        return acc;
    }

    template<typename M>
    double matrixLoop(const std::vector<double> &src, size_t n)
    {
        double acc = 0;
        for (size_t i = 0; i < n; ++i)
        {
            const size_t k = (9 * i) % (pool - 9);
            M m;                                     // default construction under test
            for (size_t r = 0; r < 3; ++r)
                for (size_t c = 0; c < 3; ++c)
                    m(r, c) = src[k + 3 * r + c];
            acc += m.trace();
        }
        return acc;
    }

    template<typename V>
    double bulk(const std::vector<double> &src, size_t n)
    {
        std::vector<V> pts(n);                       // n default-constructed (rtl: zeroed) vectors
        for (size_t i = 0; i < n; ++i)
        {
            const size_t k = (3 * i) % pool;
            pts[i][0] = src[k];
            pts[i][1] = src[k + 1];
            pts[i][2] = src[k + 2];
        }
        return pts[n / 2][1] + pts.back()[2];
    }
}

int main(int argc, char **argv)
{
    const auto opt = rtl::bench::parseOptions(argc, argv);
    const size_t n = opt.smoke ? 100000 : 50000000;
    const size_t nBulk = opt.smoke ? 100000 : 10000000;
    std::vector<double> src(pool);
    for (size_t i = 0; i < pool; ++i)
        src[i] = double(i % 97) * 0.01 - 0.3;

    // Both variants must compute the same thing.
    if (vectorLoop<Eigen::Vector3d>(src, 1000) != vectorLoop<rtl::Vector3d>(src, 1000)
        || matrixLoop<Eigen::Matrix3d>(src, 1000) != matrixLoop<rtl::Matrix33d>(src, 1000))
    {
        std::fprintf(stderr, "results differ between Eigen and rtl types\n");
        return 1;
    }

    rtl::bench::printHeader("default construction: zero-initialised rtl types vs uninitialised Eigen types");
    double sink = 0;
    const double tEv = rtl::bench::medianSeconds([&] { sink += vectorLoop<Eigen::Vector3d>(src, n); }, opt.repetitions);
    const double tRv = rtl::bench::medianSeconds([&] { sink += vectorLoop<rtl::Vector3d>(src, n); }, opt.repetitions);
    rtl::bench::printRow("loop: Eigen::Vector3d (uninitialised)", n, tEv, tEv, "baseline");
    rtl::bench::printRow("loop: rtl::Vector3d (zeroed)", n, tRv, tEv, "construct + fill + dot");

    const double tEm = rtl::bench::medianSeconds([&] { sink += matrixLoop<Eigen::Matrix3d>(src, n / 4); }, opt.repetitions);
    const double tRm = rtl::bench::medianSeconds([&] { sink += matrixLoop<rtl::Matrix33d>(src, n / 4); }, opt.repetitions);
    rtl::bench::printRow("loop: Eigen::Matrix3d (uninitialised)", n / 4, tEm, tEm, "baseline");
    rtl::bench::printRow("loop: rtl::Matrix33d (zeroed)", n / 4, tRm, tEm, "construct + fill + trace");

    const double tEb = rtl::bench::medianSeconds([&] { sink += bulk<Eigen::Vector3d>(src, nBulk); }, opt.repetitions);
    const double tRb = rtl::bench::medianSeconds([&] { sink += bulk<rtl::Vector3d>(src, nBulk); }, opt.repetitions);
    rtl::bench::printRow("bulk: std::vector<Eigen::Vector3d>(n)", nBulk, tEb, tEb, "baseline");
    rtl::bench::printRow("bulk: std::vector<rtl::Vector3d>(n)", nBulk, tRb, tEb, "allocation zeroes memory once");
    rtl::bench::doNotOptimize(sink);
    return 0;
}
