// Segmenter throughput on 1M-point synthetic closed scans with about 10 and about 10,000 clusters, in 2D and 3D,
// against a floor measured in the same run: one pass computing the squared distance of each point to its
// predecessor (stored to an array). Each segmenter row covers the whole job: CAR = loadData + grabbing every cluster;
// IA = addPoint for every point, grabbing closed clusters as they appear, flush at the end.
// Published implementation on this machine: about 4e7 points/s (CAR, 2D, 10 clusters) and 1.3e7 (IA, 2D, 10k
// clusters). Goal: >= 2e8 for both, not slowing down with the number of clusters.
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <string>
#include <vector>

#include "b_seg_timing.h"
#include "bench_util.h"
#include "rtl/seg/CAR_Segmenter.h"
#include "rtl/seg/IA_Segmenter.h"

namespace
{
    // Closed scan of n points around the origin, k clusters: runs alternating between radius 10 and 12 (jumps of 2 m,
    // over the 0.5 m upper bound), 5 mm noise (under the 0.05 m lower bound). 3D adds a height that follows the angle.
    template<class V>
    std::vector<V> scan(size_t n, size_t k, unsigned seed)
    {
        std::mt19937 rng(seed);
        std::uniform_real_distribution<float> noise(-0.0025f, 0.0025f);
        std::vector<V> pts(n);
        for (size_t i = 0; i < n; ++i)
        {
            const size_t cluster = i * k / n;
            const double a = 2 * M_PI * static_cast<double>(i) / static_cast<double>(n);
            const double r = (cluster % 2 ? 12.0 : 10.0) + noise(rng);
            typename V::EigenType e;
            e[0] = static_cast<typename V::ElementType>(r * std::cos(a));
            e[1] = static_cast<typename V::ElementType>(r * std::sin(a));
            if constexpr (V::dimensionality() == 3) e[2] = static_cast<typename V::ElementType>(0.5 * std::sin(3 * a) + noise(rng));
            pts[i] = V(e);
        }
        return pts;
    }

    template<class V>
    rtl::bench::seg::Timing floorSeconds(const std::vector<V> &pts, std::vector<typename V::ElementType> &out, int reps)
    {
        return rtl::bench::seg::measure([&] {
            for (size_t i = 1; i < pts.size(); ++i) out[i] = V::distanceSquared(pts[i], pts[i - 1]);
            rtl::bench::doNotOptimize(out.data());
        }, reps);
    }

    //! window: how many previous points each point is compared with; CAR at step window + 1, IA at step window
    //! with CAR's scaling, so that both do the same work.
    template<class V>
    void run(const char *dim, size_t n, size_t k, size_t window, const rtl::bench::Options &opt)
    {
        using E = typename V::ElementType;
        const auto pts = scan<V>(n, k, 7);
        std::vector<E> d2(n);
        const auto t_floor = floorSeconds(pts, d2, opt.repetitions);

        size_t car_clusters = 0, car_points = 0;
        rtl::CAR_Segmenter<V> car(window + 1, E(0.05), E(0.5));
        const auto t_car = rtl::bench::seg::measure([&] {
            car.loadData(pts);
            car_clusters = car_points = 0;
            while (car.clustersAvailable() > 0)
            {
                car_points += car.grabCluster().size();
                ++car_clusters;
            }
        }, opt.repetitions);

        size_t ia_clusters = 0, ia_points = 0;
        const auto t_ia = rtl::bench::seg::measure([&] {
            rtl::IA_Segmenter<V> ia(window, E(0.05), E(0.5), rtl::detail::circularScaling<E>(window + 1, n));
            ia_clusters = ia_points = 0;
            for (const auto &p : pts)
            {
                ia.addPoint(p);
                while (ia.closedClustersAvailable() > 0)
                {
                    ia_points += ia.grabCluster().size();
                    ++ia_clusters;
                }
            }
            ia.flush();
            while (ia.closedClustersAvailable() > 0)
            {
                ia_points += ia.grabCluster().size();
                ++ia_clusters;
            }
        }, opt.repetitions);

        // CAR sees a closed loop (clusters = k); the stream has no seam, which changes nothing here as k is even
        if (car_clusters != k || ia_clusters != k || car_points != n || ia_points != n)
        {
            std::fprintf(stderr, "wrong result: %zu/%zu CAR clusters/points, %zu/%zu IA, expected %zu/%zu\n", car_clusters,
                         car_points, ia_clusters, ia_points, k, n);
            std::exit(1);
        }
        const std::string tag = std::string(dim) + " " + (sizeof(E) == 4 ? "float" : "double") + " k=" + std::to_string(k) +
                                " window " + std::to_string(window);
        rtl::bench::seg::row("floor (consecutive d^2) " + tag, n, t_floor, t_floor);
        rtl::bench::seg::row("CAR batch " + tag, n, t_car, t_floor);
        rtl::bench::seg::row("IA stream " + tag, n, t_ia, t_floor);
    }
}

int main(int argc, char **argv)
{
    const auto opt = rtl::bench::parseOptions(argc, argv);
    const size_t n = opt.smoke ? 100000 : 1000000;   // smoke: clusters of 10 points, too far apart for a window of 3
    rtl::bench::printHeader("segmenters on synthetic closed scans (ratio = time / floor time)");
    for (size_t k : {size_t(10), size_t(10000)})
    {
        run<rtl::VectorND<2, float>>("2D", n, k, 1, opt);
        run<rtl::VectorND<3, float>>("3D", n, k, 1, opt);
    }
    for (size_t k : {size_t(10), size_t(10000)})
    {
        run<rtl::VectorND<2, float>>("2D", n, k, 3, opt);
        run<rtl::VectorND<3, float>>("3D", n, k, 3, opt);
        run<rtl::VectorND<2, double>>("2D", n, k, 1, opt);
    }
    return 0;
}
