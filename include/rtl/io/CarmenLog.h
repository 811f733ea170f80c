// Reader for CARMEN laser logs: every `FLASER` line becomes one ordered 2D scan in the robot frame, with the
// corrected robot pose. Beams without a return (range at or beyond the maximum) become NaN points, i.e. gaps for the
// segmenters, and keep their raw value in `ranges`.
//
// Line format: FLASER n r_1 ... r_n x y theta odom_x odom_y odom_theta ipc_timestamp hostname logger_timestamp
// Beam i points at -pi/2 + i * res from the heading, counter-clockwise, where res = pi/n for an even n (Intel: 180
// beams, 1 degree) and pi/(n - 1) for an odd n (CSAIL: 361 beams, 0.5 degree, the last beam at +90 degrees).
// Other records (#, PARAM, ODOM, NEFF, RLASER, ...) carry no front laser scan and are skipped.
#pragma once

#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstddef>
#include <cstdlib>
#include <fstream>
#include <istream>
#include <stdexcept>
#include <string>
#include <string_view>
#include <system_error>
#include <vector>

#include "rtl/core/VectorND.h"

namespace rtl
{
    //! One FLASER record.
    template<typename E>
    struct CarmenScan
    {
        std::vector<VectorND<2, E>> points;     //!< beam i as (r cos a_i, r sin a_i) in the robot frame; NaN = no return
        std::vector<E> ranges;                  //!< the raw ranges, as logged
        E x{}, y{}, theta{};                    //!< corrected robot pose in the map frame (metres, radians)
        double timestamp = 0;                   //!< ipc_timestamp (seconds)
        std::size_t line = 0;                   //!< 1-based line number in the log
    };

    namespace carmen_detail
    {
        constexpr double pi = 3.14159265358979323846264338327950288;

        inline std::vector<std::string_view> tokens(std::string_view s)
        {
            std::vector<std::string_view> t;
            std::size_t i = 0;
            while (i < s.size())
            {
                while (i < s.size() && (s[i] == ' ' || s[i] == '\t' || s[i] == '\r')) ++i;
                std::size_t b = i;
                while (i < s.size() && s[i] != ' ' && s[i] != '\t' && s[i] != '\r') ++i;
                if (i > b) t.push_back(s.substr(b, i - b));
            }
            return t;
        }

        [[noreturn]] inline void fail(std::size_t line, const std::string &what)
        {
            throw std::runtime_error("CARMEN log, line " + std::to_string(line) + ": " + what);
        }

        //! A whole token as a double, with std::from_chars' rules (no '+', no hex). Standard libraries without
        //! floating-point from_chars (libc++ before 17, e.g. Emscripten's) get the same rules on strtod, which
        //! follows the C locale that programs have unless they call setlocale.
        inline bool parseDouble(std::string_view tok, double &v)
        {
#if defined(__cpp_lib_to_chars)
            auto [end, ec] = std::from_chars(tok.data(), tok.data() + tok.size(), v);
            return ec == std::errc() && end == tok.data() + tok.size();
#else
            if (tok.empty() || tok.front() == '+' || tok.find_first_of("xX") != std::string_view::npos)
                return false;
            const std::string text(tok);
            char *end = nullptr;
            errno = 0;
            const double r = std::strtod(text.c_str(), &end);
            if (end != text.c_str() + text.size() || (errno == ERANGE && std::abs(r) == HUGE_VAL))
                return false;
            v = r;
            return true;
#endif
        }

        inline double number(std::string_view tok, std::size_t line, const char *field)
        {
            double v = 0;
            if (!parseDouble(tok, v))
                fail(line, std::string("bad ") + field + " '" + std::string(tok) + "'");
            return v;
        }

        //! Message types are upper-case identifiers (FLASER, ODOM, PARAM, ...).
        inline bool isRecordName(std::string_view tok)
        {
            for (char c : tok)
                if (!((c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_')) return false;
            return !tok.empty();
        }
    }

    //! Reads every FLASER scan of a CARMEN log. Ranges that are not positive, not finite, or >= max_range are gaps.
    //! The default 80 m suits both shared logs: Intel logs 81.83 and CSAIL 81.91 for "no return".
    //! Throws std::runtime_error naming the line for a malformed FLASER line or an unknown record.
    template<typename E>
    std::vector<CarmenScan<E>> readCarmenLog(std::istream &in, E max_range = E(80))
    {
        std::vector<CarmenScan<E>> scans;
        std::string text;
        std::size_t line = 0;
        while (std::getline(in, text))
        {
            ++line;
            const auto tok = carmen_detail::tokens(text);
            if (tok.empty() || tok[0][0] == '#') continue;
            if (!carmen_detail::isRecordName(tok[0])) carmen_detail::fail(line, "unknown record '" + std::string(tok[0]) + "'");
            if (tok[0] != "FLASER") continue;

            if (tok.size() < 2) carmen_detail::fail(line, "FLASER without beam count");
            std::size_t n = 0;
            auto [end, ec] = std::from_chars(tok[1].data(), tok[1].data() + tok[1].size(), n);
            if (ec != std::errc() || end != tok[1].data() + tok[1].size() || n == 0)
                carmen_detail::fail(line, "bad beam count '" + std::string(tok[1]) + "'");
            // n ranges + x y theta odom_x odom_y odom_theta ipc_timestamp hostname logger_timestamp
            if (tok.size() != n + 11)
                carmen_detail::fail(line, "FLASER with " + std::to_string(n) + " beams needs " + std::to_string(n + 11) +
                                              " fields, found " + std::to_string(tok.size()));

            CarmenScan<E> s;
            s.line = line;
            s.ranges.resize(n);
            s.points.resize(n);
            const double res = (n % 2 == 1 && n > 1) ? carmen_detail::pi / static_cast<double>(n - 1) : carmen_detail::pi / static_cast<double>(n);
            for (std::size_t i = 0; i < n; ++i)
            {
                const double r = carmen_detail::number(tok[2 + i], line, ("range " + std::to_string(i + 1)).c_str());
                s.ranges[i] = static_cast<E>(r);
                if (!(r > 0) || !std::isfinite(r) || !(static_cast<E>(r) < max_range))
                    s.points[i] = VectorND<2, E>::nan();
                else
                {
                    const double a = -carmen_detail::pi / 2 + static_cast<double>(i) * res;
                    s.points[i] = VectorND<2, E>(static_cast<E>(r * std::cos(a)), static_cast<E>(r * std::sin(a)));
                }
            }
            s.x = static_cast<E>(carmen_detail::number(tok[2 + n], line, "x"));
            s.y = static_cast<E>(carmen_detail::number(tok[3 + n], line, "y"));
            s.theta = static_cast<E>(carmen_detail::number(tok[4 + n], line, "theta"));
            for (std::size_t k = 5; k <= 7; ++k) carmen_detail::number(tok[k + n], line, "odometry");
            s.timestamp = carmen_detail::number(tok[8 + n], line, "ipc_timestamp");
            carmen_detail::number(tok[10 + n], line, "logger_timestamp");
            scans.push_back(std::move(s));
        }
        if (in.bad()) throw std::runtime_error("CARMEN log: read error after line " + std::to_string(line));
        return scans;
    }

    //! readCarmenLog on a file; std::runtime_error if it cannot be opened (message names the path).
    template<typename E>
    std::vector<CarmenScan<E>> readCarmenLogFile(const std::string &path, E max_range = E(80))
    {
        std::ifstream f(path);
        if (!f) throw std::runtime_error("CARMEN log: cannot open '" + path + "'");
        try
        {
            return readCarmenLog<E>(f, max_range);
        }
        catch (const std::runtime_error &e)
        {
            throw std::runtime_error(path + ": " + e.what());
        }
    }
}
