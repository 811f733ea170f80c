// Reader for organised LiDAR scans stored as raw little-endian float32 records (x, y, z, intensity), 16 bytes each.
// Two record orders exist:
//  - ColumnMajor (Ouster, e.g. RELLIS-3D): record k is beam k % beams of column k / beams;
//  - RowMajor (KITTI-style ring after ring): record k is column k % columns of beam k / columns.
// A point of exactly (0, 0, 0) means "no return" and becomes a NaN point: a gap for the segmenters.
// Complexity: linear in the number of records; the whole file is held in memory as the returned cloud.
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <istream>
#include <stdexcept>
#include <string>
#include <vector>

#include "rtl/core/VectorND.h"

namespace rtl
{
    enum class OrganizedLayout { ColumnMajor, RowMajor };

    //! An organised scan of `beams` rings by `columns` azimuth steps. Storage is column-major whatever the file
    //! layout: point (beam b, column c) is points[c * beams + b].
    template<typename E>
    struct OrganizedCloud
    {
        std::size_t beams = 0, columns = 0;
        std::vector<VectorND<3, E>> points;     //!< NaN where the sensor had no return
        std::vector<E> intensity;               //!< as logged, also for gaps

        [[nodiscard]] std::size_t index(std::size_t b, std::size_t c) const
        {
            if (b >= beams || c >= columns)
                throw std::out_of_range("OrganizedCloud: point (beam " + std::to_string(b) + ", column " + std::to_string(c) +
                                        ") outside " + std::to_string(beams) + " x " + std::to_string(columns));
            return c * beams + b;
        }
        [[nodiscard]] const VectorND<3, E> &at(std::size_t b, std::size_t c) const { return points[index(b, c)]; }

        //! Beam b over all columns: an ordered, circular cloud.
        [[nodiscard]] std::vector<VectorND<3, E>> ring(std::size_t b) const
        {
            if (b >= beams) throw std::out_of_range("OrganizedCloud::ring: beam " + std::to_string(b) + " of " + std::to_string(beams));
            std::vector<VectorND<3, E>> r(columns);
            for (std::size_t c = 0; c < columns; ++c) r[c] = points[c * beams + b];
            return r;
        }

        //! All beams of column c, top to bottom: an ordered vertical profile.
        [[nodiscard]] std::vector<VectorND<3, E>> column(std::size_t c) const
        {
            if (c >= columns) throw std::out_of_range("OrganizedCloud::column: column " + std::to_string(c) + " of " + std::to_string(columns));
            return std::vector<VectorND<3, E>>(points.begin() + static_cast<std::ptrdiff_t>(c * beams),
                                               points.begin() + static_cast<std::ptrdiff_t>((c + 1) * beams));
        }
    };

    namespace detail
    {
        inline float leFloat(const unsigned char *b)
        {
            const std::uint32_t u = static_cast<std::uint32_t>(b[0]) | static_cast<std::uint32_t>(b[1]) << 8 |
                                    static_cast<std::uint32_t>(b[2]) << 16 | static_cast<std::uint32_t>(b[3]) << 24;
            float f;
            std::memcpy(&f, &u, sizeof f);
            return f;
        }
    }

    template<typename E>
    OrganizedCloud<E> readOrganizedLidarBytes(const unsigned char *bytes, std::size_t size, std::size_t beams,
                                              OrganizedLayout layout = OrganizedLayout::ColumnMajor);

    //! Reads a whole stream of records. An empty stream gives an empty cloud (0 columns). Throws
    //! std::invalid_argument for beams == 0, std::runtime_error naming the byte offset for a truncated record or an
    //! incomplete last column (ColumnMajor) / ring (RowMajor).
    template<typename E>
    OrganizedCloud<E> readOrganizedLidar(std::istream &in, std::size_t beams, OrganizedLayout layout = OrganizedLayout::ColumnMajor)
    {
        if (beams == 0) throw std::invalid_argument("readOrganizedLidar: beams must be positive");
        std::vector<unsigned char> bytes;
        {
            char buf[1 << 16];
            while (in.read(buf, sizeof buf) || in.gcount() > 0)
                bytes.insert(bytes.end(), buf, buf + in.gcount());
            if (in.bad()) throw std::runtime_error("organised LiDAR: read error at byte offset " + std::to_string(bytes.size()));
        }
        return readOrganizedLidarBytes<E>(bytes.data(), bytes.size(), beams, layout);
    }

    //! readOrganizedLidar on `size` bytes in memory (the same cloud and errors), without any stream.
    template<typename E>
    OrganizedCloud<E> readOrganizedLidarBytes(const unsigned char *bytes, std::size_t size, std::size_t beams,
                                              OrganizedLayout layout)
    {
        if (beams == 0) throw std::invalid_argument("readOrganizedLidar: beams must be positive");
        constexpr std::size_t rec = 16;
        if (size % rec != 0)
            throw std::runtime_error("organised LiDAR: truncated record at byte offset " + std::to_string(size / rec * rec) +
                                     " (" + std::to_string(size) + " bytes is not a multiple of 16)");
        const std::size_t n = size / rec;
        if (n % beams != 0)
        {
            const std::size_t complete = n / beams * beams;
            throw std::runtime_error(std::string("organised LiDAR: incomplete ") +
                                     (layout == OrganizedLayout::ColumnMajor ? "column" : "ring") + " at byte offset " +
                                     std::to_string(complete * rec) + " (" + std::to_string(n) + " records is not a multiple of " +
                                     std::to_string(beams) + " beams)");
        }
        OrganizedCloud<E> cloud;
        cloud.beams = beams;
        cloud.columns = n / beams;
        cloud.points.resize(n);
        cloud.intensity.resize(n);
        for (std::size_t k = 0; k < n; ++k)
        {
            const unsigned char *r = bytes + k * rec;
            const float x = detail::leFloat(r), y = detail::leFloat(r + 4), z = detail::leFloat(r + 8);
            const std::size_t dst = layout == OrganizedLayout::ColumnMajor ? k : (k % cloud.columns) * beams + k / cloud.columns;
            cloud.points[dst] = (x == 0.f && y == 0.f && z == 0.f)
                                    ? VectorND<3, E>::nan()
                                    : VectorND<3, E>(static_cast<E>(x), static_cast<E>(y), static_cast<E>(z));
            cloud.intensity[dst] = static_cast<E>(detail::leFloat(r + 12));
        }
        return cloud;
    }

    //! readOrganizedLidar on a binary file; std::runtime_error if it cannot be opened (message names the path).
    template<typename E>
    OrganizedCloud<E> readOrganizedLidarFile(const std::string &path, std::size_t beams,
                                             OrganizedLayout layout = OrganizedLayout::ColumnMajor)
    {
        std::ifstream f(path, std::ios::binary);
        if (!f) throw std::runtime_error("organised LiDAR: cannot open '" + path + "'");
        try
        {
            return readOrganizedLidar<E>(f, beams, layout);
        }
        catch (const std::runtime_error &e)
        {
            throw std::runtime_error(path + ": " + e.what());
        }
    }
}
