// libFuzzer harness for the CARMEN log reader (rtl/io/CarmenLog.h): any bytes either give scans that keep the
// reader's promises or throw one of its documented exceptions (std::runtime_error, std::invalid_argument).
// Anything else (another exception, a crash, a sanitizer report, a broken invariant) is a finding.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <sstream>
#include <stdexcept>
#include <string>

#include "rtl/io/CarmenLog.h"

namespace
{
    void require(bool ok) { if (!ok) std::abort(); }

    template<typename E>
    void check(const rtl::CarmenLog<E> &log)
    {
        require(log.max_range > E(0));
        std::size_t no_return = 0;
        for (const auto &s : log.scans)
        {
            require(!s.ranges.empty() && s.points.size() == s.ranges.size() && s.line > 0);
            require(std::isfinite(s.x) && std::isfinite(s.y) && std::isfinite(s.theta) && std::isfinite(s.timestamp));
            require(s.max_range == log.max_range);
            for (std::size_t i = 0; i < s.ranges.size(); ++i)
            {
                const E r = s.ranges[i];
                const bool gap = !(r > E(0)) || !std::isfinite(r) || !(r < log.max_range);
                require(s.points[i].hasNaN() == gap);
                if (!gap)   // a point lies at its range from the sensor (hypot: no overflow for ranges near 1e300)
                    require(std::abs(std::hypot(static_cast<double>(s.points[i].x()), static_cast<double>(s.points[i].y())) -
                                     static_cast<double>(r)) <= 1e-5 * static_cast<double>(r) + 1e-30);
                no_return += std::isfinite(r) && r >= log.max_range ? 1 : 0;
            }
        }
        require(no_return == log.no_return_beams);
    }

    template<typename E>
    void run(const std::string &text, double max_range)
    {
        rtl::CarmenOptions options;
        options.max_range = max_range;
        try
        {
            std::istringstream in(text);
            check(rtl::readCarmenLogDetailed<E>(in, options));
        }
        catch (const std::invalid_argument &)
        {
            require(!std::isnan(max_range) && !(max_range > 0));
        }
        catch (const std::runtime_error &e)
        {
            const std::string what = e.what();
            require(what.rfind("CARMEN log", 0) == 0);   // messages name the reader (and the line)
        }
    }
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size)
{
    const std::string text(reinterpret_cast<const char *>(data), size);
    run<double>(text, std::nan(""));
    run<float>(text, std::nan(""));
    // An explicit max range taken from the input's first byte (0 and negative ones must be rejected).
    const double explicit_range = size > 0 ? (static_cast<double>(data[0]) - 16.0) / 4.0 : 10.0;
    run<double>(text, explicit_range);
    return 0;
}
