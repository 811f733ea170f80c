// Segmenter throughput on real scans: the excerpts in tests/data and, when RTL_FULL_DATA_DIR names the folder of the
// full files (intel-corrected.log.gz, csail-corrected.log.gz, rellis3d-os1-64x2048.bin), the full logs
// (910 Intel and 406 CSAIL laser scans, 64 rings of the RELLIS-3D Ouster scan). Ratio against a floor measured in the
// same run: one pass of squared distances between consecutive points of every scan. Small scans repeat so that every
// timed run covers at least about 1M points. CAR = loadData + grab every cluster, per scan; IA = addPoint per point,
// grabbing as clusters close, flush per scan.
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "b_seg_timing.h"
#include "bench_util.h"
#include "rtl/io/CarmenLog.h"
#include "rtl/io/OrganizedLidar.h"
#include "rtl/seg/CAR_Segmenter.h"
#include "rtl/seg/IA_Segmenter.h"

namespace
{
    bool exists(const std::string &path) { return std::ifstream(path).good(); }

    //! Decompresses a .gz log with the system's gzip (the shared logs are gzip'ed; no zlib dependency here).
    std::string gunzip(const std::string &path)
    {
        std::unique_ptr<FILE, int (*)(FILE *)> p(popen(("gzip -dc '" + path + "'").c_str(), "r"), pclose);
        std::string s;
        if (!p) return s;
        char buf[1 << 16];
        for (size_t got; (got = std::fread(buf, 1, sizeof buf, p.get())) > 0;) s.append(buf, got);
        return s;
    }

    std::vector<std::vector<rtl::VectorND<2, float>>> carmen(std::istream &in)
    {
        std::vector<std::vector<rtl::VectorND<2, float>>> out;
        for (auto &s : rtl::readCarmenLog<float>(in)) out.push_back(std::move(s.points));
        return out;
    }

    std::vector<std::vector<rtl::VectorND<3, float>>> rings(const std::string &path, size_t beams)
    {
        const auto c = rtl::readOrganizedLidarFile<float>(path, beams);
        std::vector<std::vector<rtl::VectorND<3, float>>> out;
        for (size_t b = 0; b < beams; ++b) out.push_back(c.ring(b));
        return out;
    }

    template<class V>
    void run(const std::string &name, const std::vector<std::vector<V>> &scans, float lb, float ub, const rtl::bench::Options &opt)
    {
        if (scans.empty()) return;
        size_t points = 0;
        for (const auto &s : scans) points += s.size();
        const size_t repeat = opt.smoke ? 1 : std::max<size_t>(1, 1000000 / points);
        const size_t total = points * repeat;

        std::vector<float> d2;
        const auto t_floor = rtl::bench::seg::measure([&] {
            for (size_t r = 0; r < repeat; ++r)
                for (const auto &s : scans)
                {
                    d2.resize(s.size());
                    for (size_t i = 1; i < s.size(); ++i) d2[i] = V::distanceSquared(s[i], s[i - 1]);
                    rtl::bench::doNotOptimize(d2.data());
                }
        }, opt.repetitions);

        size_t car_clusters = 0;
        rtl::CAR_Segmenter<V> car(2, lb, ub);   // step 2: each point compared with its predecessor
        const auto t_car = rtl::bench::seg::measure([&] {
            car_clusters = 0;
            for (size_t r = 0; r < repeat; ++r)
                for (const auto &s : scans)
                {
                    car.loadData(s);
                    while (car.clustersAvailable() > 0)
                    {
                        rtl::bench::doNotOptimize(car.grabCluster().size());
                        ++car_clusters;
                    }
                }
        }, opt.repetitions);

        size_t ia_clusters = 0;
        rtl::IA_Segmenter<V> ia(1, lb, ub, 0);
        const auto t_ia = rtl::bench::seg::measure([&] {
            ia_clusters = 0;
            for (size_t r = 0; r < repeat; ++r)
                for (const auto &s : scans)
                {
                    ia.setScaling(rtl::detail::circularScaling<float>(1, s.size()));
                    for (const auto &p : s)
                    {
                        ia.addPoint(p);
                        while (ia.closedClustersAvailable() > 0)
                        {
                            rtl::bench::doNotOptimize(ia.grabCluster().size());
                            ++ia_clusters;
                        }
                    }
                    ia.flush();
                    while (ia.closedClustersAvailable() > 0)
                    {
                        rtl::bench::doNotOptimize(ia.grabCluster().size());
                        ++ia_clusters;
                    }
                }
        }, opt.repetitions);

        const std::string per = " (" + std::to_string(scans.size()) + " scans, " + std::to_string(car_clusters / repeat) + " CAR / " +
                                std::to_string(ia_clusters / repeat) + " IA clusters)";
        rtl::bench::seg::row("floor " + name, total, t_floor, t_floor);
        rtl::bench::seg::row("CAR batch " + name, total, t_car, t_floor, per);
        rtl::bench::seg::row("IA stream " + name, total, t_ia, t_floor);
    }
}

int main(int argc, char **argv)
{
    const auto opt = rtl::bench::parseOptions(argc, argv);
    const char *full_dir = std::getenv("RTL_FULL_DATA_DIR");
    const std::string local = RTL_TEST_DATA_DIR, shared = full_dir ? full_dir : "";
    rtl::bench::printHeader("segmenters on real scans (ratio = time / floor time)");
    for (const char *f : {"intel.log", "csail.log"})
    {
        std::ifstream in(local + "/" + f);
        run("2D tests/data/" + std::string(f), carmen(in), 0.05f, 0.5f, opt);
    }
    run("3D tests/data/rellis 4 rings", rings(local + "/rellis3d-os1-4x2048.bin", 4), 0.1f, 1.0f, opt);
    if (opt.smoke) return 0;
    if (shared.empty())
    {
        std::printf("(full logs skipped: set RTL_FULL_DATA_DIR to the folder that holds them)\n");
        return 0;
    }

    for (const char *f : {"intel-corrected.log.gz", "csail-corrected.log.gz"})
    {
        const std::string path = shared + "/" + f;
        if (!exists(path))
        {
            std::printf("(skipped: %s not found)\n", path.c_str());
            continue;
        }
        std::istringstream in(gunzip(path));
        run("2D shared/" + std::string(f), carmen(in), 0.05f, 0.5f, opt);
    }
    const std::string ouster = shared + "/rellis3d-os1-64x2048.bin";
    if (exists(ouster)) run("3D shared/rellis 64 rings", rings(ouster, 64), 0.1f, 1.0f, opt);
    else std::printf("(skipped: %s not found)\n", ouster.c_str());
    return 0;
}
