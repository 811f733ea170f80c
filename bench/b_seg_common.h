// Shared by the segmentation benchmarks: the synthetic closed scan and the loops that hand every cluster of a
// segmenter to a callback.
#pragma once

#include <cmath>
#include <cstddef>
#include <random>
#include <vector>

namespace rtl::bench::seg
{
    //! Closed scan of n points around the origin, k clusters: runs alternating between radius 10 and 12 (jumps of
    //! 2 m), radial noise uniform in [-noise, noise] (fixed seed, so every run sees the same points).
    template<class V>
    std::vector<V> closedScan(size_t n, size_t k, float noise)
    {
        std::mt19937 rng(7);
        std::uniform_real_distribution<float> dist(-noise, noise);
        std::vector<V> pts(n);
        for (size_t i = 0; i < n; ++i)
        {
            const double a = 2 * M_PI * static_cast<double>(i) / static_cast<double>(n);
            const double r = ((i * k / n) % 2 ? 12.0 : 10.0) + dist(rng);
            pts[i] = V(static_cast<float>(r * std::cos(a)), static_cast<float>(r * std::sin(a)));
        }
        return pts;
    }

    //! CAR: loads the scan and passes every cluster to take(cluster).
    template<class Car, class V, class Take>
    void segmentCar(Car &car, const std::vector<V> &pts, Take &&take)
    {
        car.loadData(pts);
        while (car.clustersAvailable() > 0) take(car.grabCluster());
    }

    //! IA: streams the scan, passing each cluster to take(cluster) as soon as it closes, then flushes.
    template<class Ia, class V, class Take>
    void segmentIa(Ia &ia, const std::vector<V> &pts, Take &&take)
    {
        for (const V &p : pts)
        {
            ia.addPoint(p);
            while (ia.closedClustersAvailable() > 0) take(ia.grabCluster());
        }
        ia.flush();
        while (ia.closedClustersAvailable() > 0) take(ia.grabCluster());
    }
}
