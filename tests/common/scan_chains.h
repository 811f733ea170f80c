// Chains of the test logs' scans: runs of finite points in scan order whose consecutive points lie at most `gap`
// apart, the pieces the tests and benchmarks hand to a polyline vectorizer. A non-finite point ends a chain; chains
// shorter than `min_size` are dropped. The log readers need RTL_TEST_DATA_DIR (defined by tests/ and bench/ CMake).
#pragma once

#include <cstddef>
#include <string>
#include <utility>
#include <vector>

#include "rtl/Core.h"
#include "rtl/io/CarmenLog.h"
#include "rtl/io/OrganizedLidar.h"

namespace test_data
{
    //! The chains of one sequence of points, in order.
    template<int d>
    std::vector<std::vector<rtl::VectorND<d, float>>> chains(const std::vector<rtl::VectorND<d, float>> &pts, float gap, std::size_t min_size)
    {
        std::vector<std::vector<rtl::VectorND<d, float>>> out;
        std::vector<rtl::VectorND<d, float>> cur;
        const auto flush = [&] {
            if (cur.size() >= min_size) out.push_back(cur);
            cur.clear();
        };
        for (const auto &p : pts)
        {
            if (p.hasNaN()) { flush(); continue; }
            if (!cur.empty() && (p - cur.back()).length() > gap) flush();
            cur.push_back(p);
        }
        flush();
        return out;
    }

#ifdef RTL_TEST_DATA_DIR
    //! Every chain of every scan of tests/data's intel.log and csail.log (2D laser scans), in log order.
    inline std::vector<std::vector<rtl::Vector2f>> laserChains(std::size_t min_size, float gap = 0.5f)
    {
        std::vector<std::vector<rtl::Vector2f>> all;
        for (const char *name : {"intel.log", "csail.log"})
            for (const auto &scan : rtl::readCarmenLogFile<float>(std::string(RTL_TEST_DATA_DIR) + "/" + name))
                for (auto &c : chains<2>(scan.points, gap, min_size)) all.push_back(std::move(c));
        return all;
    }

    //! Every chain of every beam (ring) of the given tests/data Ouster excerpts (name, beams), in file and beam order.
    inline std::vector<std::vector<rtl::Vector3f>> ousterChains(const std::vector<std::pair<const char *, int>> &files, std::size_t min_size,
                                                                float gap = 0.5f)
    {
        std::vector<std::vector<rtl::Vector3f>> all;
        for (const auto &[name, beams] : files)
        {
            const auto cloud = rtl::readOrganizedLidarFile<float>(std::string(RTL_TEST_DATA_DIR) + "/" + name, beams);
            for (std::size_t b = 0; b < cloud.beams; ++b)
                for (auto &c : chains<3>(cloud.ring(b), gap, min_size)) all.push_back(std::move(c));
        }
        return all;
    }
#endif
}
