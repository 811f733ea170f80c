// PLE's evaluation protocol (Schaefer et al., "Probabilistic line extraction from 2-D range scans", IROS 2018) for
// CARMEN logs: how a scan's beams are laid out and which beams count, and the ray metric of a line map.
//
// Beam angles: linspace(-fov/2, fov/2, n), fov = res * (n - 1) degrees where the log has the PARAM
// laser_front_laser_resolution (res, degrees), else pi. A beam is returned when 0 <= r <= rmax, rmax = the log's
// PARAM robot_front_laser_max, else 50 m. The metric (scan_polylines/RayGeometry.h): segments hit beams within their
// angular span widened by 1e-3 rad, the later segment counts, r-hat = distance along the beam to the segment's line;
// RMSE over the hit beams, f = hit / returned.
#pragma once

#include <cmath>
#include <cstdio>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "rtl/io/CarmenLog.h"
#include "rtl/vect/scan_polylines/RayGeometry.h"

namespace rtl::ple
{
    struct Scan
    {
        std::vector<double> angles, ranges;
        std::vector<bool> returned;
        std::vector<VectorND<2, double>> points;   //!< returned beams as points, NaN for the others
    };

    struct Log
    {
        std::vector<Scan> scans;
        double fov = 0, rmax = 0;
    };

    //! The value of `PARAM name value ...` in a log's text, or NaN.
    inline double parameter(const std::string &text, const std::string &name)
    {
        const std::string key = "PARAM " + name + " ";
        const std::size_t at = text.find(key);
        return at == std::string::npos ? std::nan("") : std::strtod(text.c_str() + at + key.size(), nullptr);
    }

    inline std::string readText(const std::string &path, bool gzip)
    {
        std::string s;
        if (gzip)
        {
            std::unique_ptr<FILE, int (*)(FILE *)> p(popen(("gzip -dc '" + path + "' 2>/dev/null").c_str(), "r"), pclose);
            if (!p) throw std::runtime_error("cannot run gzip on " + path);
            char buf[1 << 16];
            for (std::size_t got; (got = std::fread(buf, 1, sizeof buf, p.get())) > 0;) s.append(buf, got);
        }
        else
        {
            std::unique_ptr<FILE, int (*)(FILE *)> f(std::fopen(path.c_str(), "rb"), std::fclose);
            if (!f) throw std::runtime_error("cannot open " + path);
            char buf[1 << 16];
            for (std::size_t got; (got = std::fread(buf, 1, sizeof buf, f.get())) > 0;) s.append(buf, got);
        }
        if (s.empty()) throw std::runtime_error("cannot read " + path);
        return s;
    }

    //! The FLASER scans of a log (in order, counted from 0) laid out as PLE does.
    inline Log readLog(const std::string &path, bool gzip)
    {
        const std::string text = readText(path, gzip);
        CarmenOptions raw;
        raw.max_range = std::numeric_limits<double>::infinity();   // keep every range; PLE's rmax decides below
        const CarmenLog<double> carmen = readCarmenLogTextDetailed<double>(text, raw);
        const double res = parameter(text, "laser_front_laser_resolution");
        const double rmax_param = parameter(text, "robot_front_laser_max");
        Log log;
        log.rmax = std::isnan(rmax_param) ? 50.0 : rmax_param;
        for (const auto &cs : carmen.scans)
        {
            const std::size_t n = cs.ranges.size();
            const double fov = std::isnan(res) ? scan_polylines::kPi : res * static_cast<double>(n - 1) * scan_polylines::kPi / 180.0;
            log.fov = fov;
            Scan s;
            for (std::size_t i = 0; i < n; ++i)
            {
                const double a = n > 1 ? -fov / 2 + fov * static_cast<double>(i) / static_cast<double>(n - 1) : 0.0;
                const double r = cs.ranges[i];
                const bool ret = r >= 0 && r <= log.rmax;
                s.angles.push_back(a);
                s.ranges.push_back(r);
                s.returned.push_back(ret);
                s.points.emplace_back(ret ? r * std::cos(a) : std::nan(""), ret ? r * std::sin(a) : std::nan(""));
            }
            log.scans.push_back(std::move(s));
        }
        return log;
    }

    typedef scan_polylines::RayScore Metric;

    //! PLE's ray metric of a line map (polylines, any 2D vertex type with operator[]) on a scan.
    template<class Polylines>
    Metric score(const Scan &scan, const Polylines &polylines)
    {
        const std::vector<double> rhat = scan_polylines::expectedRangesOf(scan.angles, polylines, 1e-3);
        return scan_polylines::scoreExpected(scan.ranges, scan.returned, rhat);
    }
}
