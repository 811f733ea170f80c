// libFuzzer harness for the PCD reader (rtl/io/PcdFile.h): any bytes either give a cloud that keeps the reader's
// promises or throw its one documented exception, rtl::PcdError. Each input is read three ways: strictly with float
// and double coordinates, and with keep_partial. Anything else (another exception, a crash, a sanitizer report, an
// allocation beyond the RSS limit, a broken invariant) is a finding.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <optional>
#include <string>

#include "fuzz_common.h"
#include "rtl/io/PcdFile.h"

namespace
{
    using fuzz::require;

    bool sameBits(float a, float b) { return std::memcmp(&a, &b, sizeof a) == 0 || (std::isnan(a) && std::isnan(b)); }

    template<typename E>
    void checkCloud(const rtl::PcdCloud<E> &c, const rtl::PcdOptions &options)
    {
        require(c.width == c.header.width && c.height == c.header.height && c.header.points == c.width * c.height);
        require(c.points.size() <= c.header.points);
        require(c.complete() == (c.error.empty() && c.points.size() == c.header.points));
        require(c.fields.size() <= options.fields.size());
        for (const auto &f : c.fields)
        {
            require(c.header.find(f.name) != rtl::PcdError::npos && f.count == c.header.fields[c.header.find(f.name)].count);
            require(f.values.size() == c.points.size() * f.count);
        }
        if (c.complete() && c.height > 0 && c.width > 0)
        {
            const auto o = c.toOrganized();
            require(o.beams == c.height && o.columns == c.width && o.points.size() == c.points.size());
            require(o.intensity.size() == c.points.size());
        }
    }

    std::optional<rtl::PcdError> read(const std::uint8_t *data, std::size_t size, const rtl::PcdOptions &options,
                                      std::optional<rtl::PcdCloud<float>> &out)
    {
        try
        {
            out = rtl::readPcdBytes<float>(data, size, options);
            checkCloud(*out, options);
            return std::nullopt;
        }
        catch (const rtl::PcdError &e)
        {
            const std::string what = e.what();
            require(what.rfind("PCD, ", 0) == 0 && e.file().empty() && !e.reason().empty());
            require(e.byteOffset() == rtl::PcdError::npos || e.byteOffset() <= size);
            return e;
        }
    }
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size)
{
    rtl::PcdOptions strict;
    strict.fields = {"intensity", "ring", "_", "rgb"};
    std::optional<rtl::PcdCloud<float>> cloud, partial_cloud;
    const auto error = read(data, size, strict, cloud);

    rtl::PcdOptions partial = strict;
    partial.keep_partial = true;
    const auto partial_error = read(data, size, partial, partial_cloud);
    if (!error)
    {
        // A good file: the partial reading is the same cloud.
        require(!partial_error && partial_cloud->complete() && partial_cloud->points.size() == cloud->points.size());
        for (std::size_t i = 0; i < cloud->points.size(); ++i)
            for (int d = 0; d < 3; ++d) require(sameBits(cloud->points[i][d], partial_cloud->points[i][d]));
    }
    else if (partial_error)
    {
        // Only header errors (a header line, no point) escape keep_partial, and they are the strict reading's.
        require(partial_error->point() == rtl::PcdError::npos && partial_error->line() != rtl::PcdError::npos);
        require(std::string(partial_error->what()) == error->what());
    }
    else
    {
        // A data error: the partial cloud holds the points before the faulty one, and says why it stopped.
        require(!partial_cloud->complete() && partial_cloud->error == error->what());
        if (error->point() != rtl::PcdError::npos) require(partial_cloud->points.size() == error->point());
    }

    // Double coordinates: the same outcome.
    try
    {
        const auto wide = rtl::readPcdBytes<double>(data, size, strict);
        require(!error && wide.points.size() == cloud->points.size());
    }
    catch (const rtl::PcdError &e)
    {
        require(error && std::string(e.what()) == error->what());
    }
    return 0;
}
