// Both segmenters on every real scan in tests/data (30 Intel and 30 CSAIL laser scans, 4 rings of an Ouster OS1-64
// scan), in float and double, with several steps and bounds: every invariant of seg_check.h, stream/batch agreement,
// and float/double agreement up to pairs that sit on the threshold. Each case runs CAR at `step` (window: step - 1
// previous points) and IA at step - 1 (the same window) with CAR's scaling step * 2 pi / N.
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "rtl/io/CarmenLog.h"
#include "rtl/io/OrganizedLidar.h"
#include "seg_check.h"

namespace
{
    const std::string data_dir = RTL_TEST_DATA_DIR;

    struct Params
    {
        size_t step;   // CAR's step (>= 2); IA runs at step - 1
        double lb, ub;
    };
    const Params carmen_params[] = {{2, 0.05, 0.5}, {3, 0.03, 0.3}, {4, 0.0, INFINITY}};
    const Params ouster_params[] = {{2, 0.1, 1.0}, {3, 0.05, 0.5}, {5, 0.0, INFINITY}};

    template<class E>
    std::vector<std::vector<rtl::VectorND<2, E>>> carmenScans(const std::string &file, bool map_frame,
                                                               std::vector<rtl::VectorND<2, E>> *origins = nullptr)
    {
        std::vector<std::vector<rtl::VectorND<2, E>>> out;
        for (const auto &s : rtl::readCarmenLogFile<E>(data_dir + "/" + file))
        {
            auto pts = s.points;
            if (map_frame)
                for (auto &p : pts)
                {
                    const E c = std::cos(s.theta), si = std::sin(s.theta);
                    p = rtl::VectorND<2, E>(c * p.x() - si * p.y() + s.x, si * p.x() + c * p.y() + s.y);
                }
            if (origins) origins->push_back(map_frame ? rtl::VectorND<2, E>(s.x, s.y) : rtl::VectorND<2, E>::zeros());
            out.push_back(pts);
        }
        return out;
    }

    template<class E>
    std::vector<std::vector<rtl::VectorND<3, E>>> ousterRings()
    {
        const auto cloud = rtl::readOrganizedLidarFile<E>(data_dir + "/rellis3d-os1-4x2048.bin", 4);
        std::vector<std::vector<rtl::VectorND<3, E>>> out;
        for (size_t b = 0; b < cloud.beams; ++b) out.push_back(cloud.ring(b));
        return out;
    }

    //! All invariants on one scan; returns the number of batch clusters.
    template<class V>
    size_t checkScan(const std::vector<V> &pts, const V &origin, const Params &p, size_t scan, const std::string &name)
    {
        using E = typename V::ElementType;
        const std::string what = name + " scan " + std::to_string(scan) + " step " + std::to_string(p.step);
        const auto car = segcheck::checkCar(pts, origin, p.step, static_cast<E>(p.lb), static_cast<E>(p.ub), what + " CAR");
        const auto ia = segcheck::checkIa(pts, origin, p.step - 1, static_cast<E>(p.lb), static_cast<E>(p.ub), scan % 2 ? 1 : 0, what + " IA");
        segcheck::checkAgreement(pts, origin, p.step - 1, static_cast<E>(p.lb), static_cast<E>(p.ub), car, ia, what);
        size_t clusters = 0;
        for (size_t i = 0; i < car.size(); ++i) clusters += car[i] == i ? 1 : 0;
        return clusters;
    }

    template<class E>
    void carmenInvariants(const std::string &file, bool map_frame)
    {
        std::vector<rtl::VectorND<2, E>> origins;
        const auto scans = carmenScans<E>(file, map_frame, &origins);
        ASSERT_EQ(scans.size(), 30u);
        for (const auto &p : carmen_params)
        {
            size_t clusters = 0, points = 0;
            for (size_t k = 0; k < scans.size(); ++k)
            {
                clusters += checkScan(scans[k], origins[k], p, k, file + (map_frame ? " map" : " robot"));
                points += scans[k].size();
            }
            // sanity: the parameters give a real segmentation, neither one cluster per scan nor one per point
            std::printf("%s %s step %zu: %zu clusters, %zu points\n", file.c_str(), map_frame ? "map" : "robot", p.step, clusters, points);
            EXPECT_GT(clusters, 2 * scans.size()) << file << " step " << p.step;
            EXPECT_LT(clusters, points / 3) << file << " step " << p.step;
            if (::testing::Test::HasFailure()) return;
        }
    }

    //! Float and double results agree, except where a pair sits within a relative 1e-4 of the threshold: pairs that
    //! clearly meet the criterion (in double) share a float cluster, and a float cluster never joins points that are
    //! not linked even with the margin. Returns the number of scans with identical partitions.
    template<class V32, class V64>
    size_t floatMatchesDouble(const std::vector<V32> &pf, const std::vector<V64> &pd, const V64 &origin, const Params &p,
                              const std::string &what)
    {
        const size_t n = pd.size();
        rtl::CAR_Segmenter<V32> car_f(p.step, static_cast<float>(p.lb), static_cast<float>(p.ub));
        std::vector<size_t> lf;
        segcheck::toIndices(pf, segcheck::runCar(car_f, pf, origin.template cast<float>()), lf, what);
        const size_t window = segcheck::carWindow(p.step);
        const auto ld = segcheck::referenceLabels(pd, origin, window, rtl::detail::circularScaling<double>(p.step, n), p.lb, p.ub, true);
        const double scaling = rtl::detail::circularScaling<double>(p.step, n);
        segcheck::UnionFind loose(n);
        size_t split_clear = 0;
        segcheck::forEachWindowPair(n, window, true, [&](size_t j, size_t i) {
            if (segcheck::isGap(pd[i]) || segcheck::isGap(pd[j])) return;
            const double tsq = rtl::detail::SquaredThreshold<double>(scaling, p.lb, p.ub)((pd[i] - origin).lengthSquared());
            const double dsq = (pd[i] - pd[j]).lengthSquared();
            if (dsq <= tsq * (1 + 1e-4)) loose.unite(i, j);
            if (dsq < tsq * (1 - 1e-4) && lf[i] != lf[j]) ++split_clear;
        });
        size_t overmerged = 0;
        for (size_t i = 0; i < n; ++i)
            if (lf[i] != segcheck::gap && loose.find(i) != loose.find(lf[i])) ++overmerged;
        EXPECT_EQ(split_clear, 0u) << what << ": float splits a clearly close pair";
        EXPECT_EQ(overmerged, 0u) << what << ": float joins points that double keeps apart";
        return lf == ld ? 1 : 0;
    }
}

TEST(RealScans, IntelRobotFrame)
{
    carmenInvariants<float>("intel.log", false);
    carmenInvariants<double>("intel.log", false);
}

TEST(RealScans, CsailRobotFrame)
{
    carmenInvariants<float>("csail.log", false);
    carmenInvariants<double>("csail.log", false);
}

TEST(RealScans, MapFrameWithPoseAsOrigin)
{
    carmenInvariants<double>("intel.log", true);
    carmenInvariants<float>("csail.log", true);
}

TEST(RealScans, OusterRings)
{
    const auto rf = ousterRings<float>();
    const auto rd = ousterRings<double>();
    for (const auto &p : ouster_params)
        for (size_t b = 0; b < rf.size(); ++b)
        {
            const size_t cf = checkScan(rf[b], rtl::VectorND<3, float>::zeros(), p, b, "ouster float");
            const size_t cd = checkScan(rd[b], rtl::VectorND<3, double>::zeros(), p, b, "ouster double");
            EXPECT_GT(cf, 3u);
            EXPECT_LT(cf, 1000u);
            EXPECT_NEAR(static_cast<double>(cf), static_cast<double>(cd), 2.0);
        }
}

TEST(RealScans, FloatAgreesWithDouble)
{
    size_t identical = 0, total = 0;
    for (const char *file : {"intel.log", "csail.log"})
    {
        const auto sf = carmenScans<float>(file, false);
        const auto sd = carmenScans<double>(file, false);
        for (const auto &p : carmen_params)
            for (size_t k = 0; k < sd.size(); ++k, ++total)
                identical += floatMatchesDouble(sf[k], sd[k], rtl::VectorND<2, double>::zeros(), p,
                                                std::string(file) + " scan " + std::to_string(k));
    }
    const auto rf = ousterRings<float>();
    const auto rd = ousterRings<double>();
    for (const auto &p : ouster_params)
        for (size_t b = 0; b < rd.size(); ++b, ++total)
            identical += floatMatchesDouble(rf[b], rd[b], rtl::VectorND<3, double>::zeros(), p, "ouster ring " + std::to_string(b));
    std::printf("float/double partitions identical on %zu of %zu scans\n", identical, total);
    EXPECT_GE(identical * 10, total * 9);
}
