// Reader for CARMEN laser logs: every `FLASER` line becomes one ordered 2D scan in the robot frame, with the
// corrected robot pose. Beams without a return become NaN points, i.e. gaps for the segmenters, and keep their raw
// value in `ranges`.
//
// Line format: FLASER n r_1 ... r_n x y theta odom_x odom_y odom_theta ipc_timestamp hostname logger_timestamp
// Beam i points at -pi/2 + i * res from the heading, counter-clockwise, where res = pi/n for an even n (Intel: 180
// beams, 1 degree) and pi/(n - 1) for an odd n (CSAIL: 361 beams, 0.5 degree, the last beam at +90 degrees).
// Other records (#, PARAM, ODOM, NEFF, RLASER, ...) carry no front laser scan and are skipped.
//
// "No return" is logged as a fixed range that differs between robots (Intel 81.83, CSAIL 81.91, aces 50.0). By
// default the reader finds it in the log itself (see readCarmenLogDetailed): ranges at or beyond it are gaps.
// An explicit max range overrides the detection.
//
// Complexity: linear in the log's size; every scan is kept in memory. A malformed FLASER line throws an error that
// names the line (and the file, for the file readers); lines of other records are skipped.
#pragma once

#include <algorithm>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstddef>
#include <cstdlib>
#include <fstream>
#include <istream>
#include <limits>
#include <map>
#include <stdexcept>
#include <string>
#include <string_view>
#include <system_error>
#include <utility>
#include <vector>

#include "rtl/core/Constants.h"
#include "rtl/core/VectorND.h"
#include "rtl/io/TextTokens.h"

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
        E max_range = std::numeric_limits<E>::infinity();   //!< the no-return value used: ranges >= it are gaps
    };

    //! Where the no-return value of a log came from.
    enum class CarmenMaxRangeSource
    {
        Explicit,    //!< given by the caller
        Parameter,   //!< a PARAM line of the log (e.g. robot_front_laser_max)
        Recurring,   //!< the largest range of the log, hit exactly by many beams
        Default      //!< no evidence in the log: the SICK LMS maximum of 80 m
    };

    //! Options of readCarmenLogDetailed.
    struct CarmenOptions
    {
        //! Ranges >= max_range are gaps (must be > 0; +inf keeps every finite positive range). NaN (default):
        //! detect the log's no-return value.
        double max_range = std::numeric_limits<double>::quiet_NaN();
    };

    //! The scans of a log and the no-return value used for all of them.
    template<typename E>
    struct CarmenLog
    {
        std::vector<CarmenScan<E>> scans;
        E max_range = E(80);                                        //!< ranges >= max_range are gaps
        CarmenMaxRangeSource max_range_source = CarmenMaxRangeSource::Default;
        std::string max_range_parameter;                            //!< Parameter: the PARAM name
        std::size_t max_range_line = 0;                             //!< Parameter: its 1-based line
        std::size_t no_return_beams = 0;                            //!< beams with a finite range >= max_range
    };

    namespace detail
    {
        [[noreturn]] inline void failCarmen(std::size_t line, const std::string &what)
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
                failCarmen(line, std::string("bad ") + field + " '" + std::string(tok) + "'");
            return v;
        }

        //! A finite number (poses, odometry, timestamps): NaN or inf is an error naming the line.
        inline double finiteNumber(std::string_view tok, std::size_t line, const char *field)
        {
            const double v = number(tok, line, field);
            if (!std::isfinite(v))
                failCarmen(line, std::string("non-finite ") + field + " '" + std::string(tok) + "'");
            return v;
        }

        //! PARAM names that give the front laser's maximum range (robot module, laser module, old loggers).
        inline bool isMaxRangeParameter(std::string_view name)
        {
            for (const char *known : {"robot_front_laser_max", "laser_front_laser_max_range", "laser_laser1_max_range",
                                      "laser_max_range", "robot_laser_max", "robot_frontlaser_max"})
                if (name == known)
                    return true;
            return false;
        }

        //! Message types are upper-case identifiers (FLASER, ODOM, PARAM, ...).
        inline bool isRecordName(std::string_view tok)
        {
            for (char c : tok)
                if (!((c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_')) return false;
            return !tok.empty();
        }
    }

    //! Detection of the no-return value from the ranges alone. The no-return value is the top of the log's ranges and
    //! is hit exactly by many beams, while real returns spread over many values: it is the largest range v hit by at
    //! least 3 beams, by at least twice as many as any single other value in [v / 2, v), and by at least 4 times as
    //! many as all ranges above v together (a few glitches above the no-return value do not hide it).
    //! Returns (v, beams at v), or (NaN, 0) without such evidence.
    template<typename E>
    std::pair<E, std::size_t> carmenRecurringMaxRange(const std::vector<CarmenScan<E>> &scans)
    {
        std::map<E, std::size_t> count;   // beams per finite positive range
        for (const auto &s : scans)
            for (E r : s.ranges)
                if (std::isfinite(r) && r > E(0))
                    ++count[r];
        std::size_t above = 0;
        for (auto it = count.rbegin(); it != count.rend(); ++it)
        {
            const E v = it->first;
            const std::size_t n = it->second;
            if (above * 4 > n)
                break;   // too many ranges above v: v is not the top of the log
            if (n >= 3)
            {
                std::size_t most = 0;
                for (auto jt = count.lower_bound(v / 2); jt->first < v; ++jt)
                    most = std::max(most, jt->second);
                if (n >= 2 * most)
                    return {v, n};
            }
            above += n;
        }
        return {std::numeric_limits<E>::quiet_NaN(), 0};
    }

    namespace detail
    {
        //! Turns beams at or beyond max_range into gaps and records max_range in every scan.
        template<typename E>
        void applyMaxRange(CarmenLog<E> &log)
        {
            log.no_return_beams = 0;
            for (auto &s : log.scans)
            {
                s.max_range = log.max_range;
                for (std::size_t i = 0; i < s.ranges.size(); ++i)
                {
                    log.no_return_beams += std::isfinite(s.ranges[i]) && s.ranges[i] >= log.max_range ? 1 : 0;
                    if (!(s.ranges[i] < log.max_range))
                        s.points[i] = VectorND<2, E>::nan();
                }
            }
        }

        struct MaxRangeParameter
        {
            double value = std::numeric_limits<double>::quiet_NaN();
            std::string name;
            std::size_t line = 0;
        };

        //! Parses line number `line` (text without its '\n'): a FLASER line is appended to `scans` (gaps only where
        //! the range is not finite or not positive), the first usable max-range PARAM is remembered. Throws
        //! std::runtime_error naming the line.
        template<typename E>
        void parseLine(std::string_view text, std::size_t line, std::vector<CarmenScan<E>> &scans, MaxRangeParameter &param)
        {
            const auto tok = tokens(text);
            if (tok.empty() || tok[0][0] == '#') return;
            if (!isRecordName(tok[0])) failCarmen(line, "unknown record '" + std::string(tok[0]) + "'");
            if (tok[0] == "PARAM")
            {
                // PARAM name value [ipc_timestamp hostname logger_timestamp]; a value that is not a positive
                // number leaves the parameter unused (the log's ranges then decide).
                double v = 0;
                if (param.line == 0 && tok.size() >= 3 && isMaxRangeParameter(tok[1]) && parseDouble(tok[2], v) &&
                    std::isfinite(v) && v > 0)
                    param = {v, std::string(tok[1]), line};
                return;
            }
            if (tok[0] != "FLASER") return;

            if (tok.size() < 2) failCarmen(line, "FLASER without beam count");
            std::size_t n = 0;
            auto [end, ec] = std::from_chars(tok[1].data(), tok[1].data() + tok[1].size(), n);
            if (ec != std::errc() || end != tok[1].data() + tok[1].size() || n == 0)
                failCarmen(line, "bad beam count '" + std::string(tok[1]) + "'");
            // n ranges + x y theta odom_x odom_y odom_theta ipc_timestamp hostname logger_timestamp
            // (compared without n + 11, which wraps around for a beam count near SIZE_MAX)
            if (tok.size() - 2 < n || tok.size() - 2 - n != 9)
                failCarmen(line, "FLASER with " + std::to_string(n) + " beams needs " +
                               (n <= std::numeric_limits<std::size_t>::max() - 11 ? std::to_string(n + 11)
                                                                                   : std::to_string(n) + " + 11") +
                               " fields, found " + std::to_string(tok.size()));

            CarmenScan<E> s;
            s.line = line;
            s.ranges.resize(n);
            s.points.resize(n);
            const double res = (n % 2 == 1 && n > 1) ? C_PI<double> / static_cast<double>(n - 1) : C_PI<double> / static_cast<double>(n);
            for (std::size_t i = 0; i < n; ++i)
            {
                const double r = number(tok[2 + i], line, ("range " + std::to_string(i + 1)).c_str());
                s.ranges[i] = static_cast<E>(r);
                // Judged on the stored value: a range that rounds to 0 or inf in E (e.g. 1e-320 or 1e300 as a
                // float) is a gap, not a point at the origin or at infinity.
                if (!(s.ranges[i] > E(0)) || !std::isfinite(s.ranges[i]))
                    s.points[i] = VectorND<2, E>::nan();
                else
                {
                    const double a = -C_PI<double> / 2 + static_cast<double>(i) * res;
                    s.points[i] = VectorND<2, E>(static_cast<E>(r * std::cos(a)), static_cast<E>(r * std::sin(a)));
                }
            }
            s.x = static_cast<E>(finiteNumber(tok[2 + n], line, "x"));
            s.y = static_cast<E>(finiteNumber(tok[3 + n], line, "y"));
            s.theta = static_cast<E>(finiteNumber(tok[4 + n], line, "theta"));
            const char *odometry[3] = {"odom_x", "odom_y", "odom_theta"};
            for (std::size_t k = 0; k < 3; ++k) finiteNumber(tok[5 + k + n], line, odometry[k]);
            s.timestamp = finiteNumber(tok[8 + n], line, "ipc_timestamp");
            finiteNumber(tok[10 + n], line, "logger_timestamp");
            if (!std::isfinite(s.x) || !std::isfinite(s.y) || !std::isfinite(s.theta))
                failCarmen(line, "pose out of the element type's range");
            scans.push_back(std::move(s));
        }

        //! Every line of the stream through parseLine (std::getline's lines).
        template<typename E>
        std::vector<CarmenScan<E>> parse(std::istream &in, MaxRangeParameter &param)
        {
            std::vector<CarmenScan<E>> scans;
            std::string text;
            std::size_t line = 0;
            while (std::getline(in, text))
                parseLine<E>(text, ++line, scans, param);
            if (in.bad()) throw std::runtime_error("CARMEN log: read error after line " + std::to_string(line));
            return scans;
        }

        //! The same lines as std::getline would read from a stream holding `text`: split at '\n', a last line
        //! without one counts unless it is empty. No stream is involved (the WebAssembly package reads logs this way).
        template<typename E>
        std::vector<CarmenScan<E>> parse(std::string_view text, MaxRangeParameter &param)
        {
            std::vector<CarmenScan<E>> scans;
            std::size_t line = 0;
            for (std::size_t pos = 0; pos < text.size();)
            {
                std::size_t nl = text.find('\n', pos);
                if (nl == std::string_view::npos) nl = text.size();
                parseLine<E>(text.substr(pos, nl - pos), ++line, scans, param);
                pos = nl + 1;
            }
            return scans;
        }

        //! readCarmenLogDetailed on either input (a std::istream or the log's text).
        template<typename E, class In>
        CarmenLog<E> read(In &&in, const CarmenOptions &options)
        {
            if (!std::isnan(options.max_range) && !(static_cast<E>(options.max_range) > E(0)))   // (also in E)
                throw std::invalid_argument("readCarmenLog: max_range must be positive (or NaN to detect it), got " +
                                            std::to_string(options.max_range));
            CarmenLog<E> log;
            MaxRangeParameter param;
            log.scans = parse<E>(in, param);
            if (!std::isnan(options.max_range))
            {
                log.max_range = static_cast<E>(options.max_range);
                log.max_range_source = CarmenMaxRangeSource::Explicit;
            }
            else
            {
                const E recurring = carmenRecurringMaxRange(log.scans).first;
                const E from_param = static_cast<E>(param.value);
                // (a parameter that rounds to 0 in E, e.g. 1e-320 as a float, is unusable)
                if (param.line != 0 && from_param > E(0) && !(recurring < from_param))
                {
                    log.max_range = from_param;
                    log.max_range_source = CarmenMaxRangeSource::Parameter;
                    log.max_range_parameter = param.name;
                    log.max_range_line = param.line;
                }
                else if (!std::isnan(recurring))
                {
                    log.max_range = recurring;
                    log.max_range_source = CarmenMaxRangeSource::Recurring;
                }
                else
                {
                    log.max_range = E(80);
                    log.max_range_source = CarmenMaxRangeSource::Default;
                }
            }
            applyMaxRange(log);
            return log;
        }
    }

    /*! Reads every FLASER scan of a CARMEN log, with the no-return value used. Ranges that are not positive, not
     *  finite, or >= the max range are gaps (NaN points). The max range is options.max_range if it is a number;
     *  otherwise it is detected from the log:
     *   - a PARAM line naming the front laser's maximum range (robot_front_laser_max, laser_front_laser_max_range,
     *     laser_laser1_max_range, laser_max_range, robot_laser_max, robot_frontlaser_max; the first one counts),
     *   - else, or if it is smaller, the top range of the log when many beams hit it exactly (carmenRecurringMaxRange),
     *   - else 80 m (no evidence: the SICK LMS maximum, the reader's former default).
     *  Intel's excerpt detects 81.83 (recurring, 481 beams), CSAIL's 50 (robot_front_laser_max; its 922 no-return
     *  beams log 81.91 and no return lies between), an aces log 50.0.
     *  Throws std::invalid_argument for options.max_range <= 0, std::runtime_error naming the line for a malformed
     *  FLASER line, a non-finite pose, odometry or timestamp, or an unknown record. */
    template<typename E>
    CarmenLog<E> readCarmenLogDetailed(std::istream &in, const CarmenOptions &options = {})
    {
        return detail::read<E>(in, options);
    }

    //! readCarmenLogDetailed on the log's text in memory (the same scans, errors and detection as a stream holding
    //! it), without any stream.
    template<typename E>
    CarmenLog<E> readCarmenLogTextDetailed(std::string_view text, const CarmenOptions &options = {})
    {
        return detail::read<E>(text, options);
    }

    //! The scans of readCarmenLogDetailed with the detected no-return value (each scan's max_range tells it).
    template<typename E>
    std::vector<CarmenScan<E>> readCarmenLog(std::istream &in)
    {
        return readCarmenLogDetailed<E>(in).scans;
    }

    //! The scans with an explicit max range: ranges >= max_range are gaps (NaN: detect, as readCarmenLog(in)).
    template<typename E>
    std::vector<CarmenScan<E>> readCarmenLog(std::istream &in, E max_range)
    {
        CarmenOptions options;
        options.max_range = static_cast<double>(max_range);
        return readCarmenLogDetailed<E>(in, options).scans;
    }

    //! readCarmenLogDetailed on a file; std::runtime_error if it cannot be opened (message names the path), and every
    //! std::runtime_error of the reader prefixed with the path.
    template<typename E>
    CarmenLog<E> readCarmenLogFileDetailed(const std::string &path, const CarmenOptions &options = {})
    {
        std::ifstream f(path);
        if (!f) throw std::runtime_error("CARMEN log: cannot open '" + path + "'");
        try
        {
            return readCarmenLogDetailed<E>(f, options);
        }
        catch (const std::runtime_error &e)
        {
            throw std::runtime_error(path + ": " + e.what());
        }
    }

    template<typename E>
    std::vector<CarmenScan<E>> readCarmenLogFile(const std::string &path)
    {
        return readCarmenLogFileDetailed<E>(path).scans;
    }

    template<typename E>
    std::vector<CarmenScan<E>> readCarmenLogFile(const std::string &path, E max_range)
    {
        CarmenOptions options;
        options.max_range = static_cast<double>(max_range);
        return readCarmenLogFileDetailed<E>(path, options).scans;
    }
}
