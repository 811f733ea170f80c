// Reader for PCD files, the Point Cloud Library's point cloud format (header: rtl/io/PcdHeader.h), in its three
// encodings, as PCL's PCDReader reads them:
//  - ascii: one text line per point, the values of every field in FIELDS order (a "_" padding field's values are
//    skipped unread; PCL's writer leaves "_" out of ascii headers);
//  - binary: point records of header.point_step bytes, little-endian, fields at their offsets (padding included);
//  - binary_compressed: two little-endian uint32 (compressed size, uncompressed size), then one LZF block
//    (rtl/io/LzfDecompress.h) that holds the fields column by column: every point's value of the first field, then
//    every point's value of the second field, and so on, with no column for a "_" padding field (the uncompressed
//    size is POINTS x the point size without padding).
// The result keeps the file's point order (row after row for an organised cloud), its width x height, the viewpoint,
// x, y, z of every point and, on request, further fields as doubles. NaN coordinates (PCL's "no return" in organised
// clouds) stay NaN.
#pragma once

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <istream>
#include <limits>
#include <stdexcept>
#include <string>
#include <string_view>
#include <system_error>
#include <vector>

#include "rtl/core/VectorND.h"
#include "rtl/io/LzfDecompress.h"
#include "rtl/io/OrganizedLidar.h"
#include "rtl/io/PcdHeader.h"

namespace rtl
{
    struct PcdOptions
    {
        //! Further fields to deliver as doubles, by name; a name the file lacks is skipped (PcdCloud::fields lists
        //! those found). x, y, z are always read.
        std::vector<std::string> fields{"intensity", "ring"};
        //! false: bad data throws PcdError. true: bad data ends the reading; the cloud holds every point read before
        //! the faulty one (fewer than width * height, unless the fault came after them: an extra ascii line), `error`
        //! holds the message and complete() is false. Header errors always throw.
        bool keep_partial = false;
    };

    //! The values of one further field: `count` values per point, point i's at values[i * count + k].
    struct PcdValues
    {
        std::string name;
        std::size_t count = 1;
        std::vector<double> values;
    };

    template<typename E>
    struct PcdCloud
    {
        PcdHeader header;
        std::size_t width = 0, height = 0;         //!< height > 1: organised; point (row r, column c) = points[r * width + c]
        std::vector<VectorND<3, E>> points;         //!< in file order; NaN coordinates kept
        std::vector<PcdValues> fields;              //!< the requested fields that the file has, in request order
        std::string error;                          //!< keep_partial: why the reading stopped; empty when complete

        [[nodiscard]] bool complete() const { return error.empty() && points.size() == width * height; }
        [[nodiscard]] bool organized() const { return height > 1; }
        //! The viewpoint: translation (tx, ty, tz) and orientation quaternion (qw, qx, qy, qz).
        [[nodiscard]] const std::array<double, 7> &viewpoint() const { return header.viewpoint; }

        //! The field called `name`, or nullptr if it was not read.
        [[nodiscard]] const PcdValues *field(std::string_view name) const
        {
            for (const auto &f : fields)
                if (f.name == name) return &f;
            return nullptr;
        }

        [[nodiscard]] const VectorND<3, E> &at(std::size_t row, std::size_t column) const
        {
            if (row >= height || column >= width || row * width + column >= points.size())
                throw std::out_of_range("PcdCloud: point (row " + std::to_string(row) + ", column " +
                                        std::to_string(column) + ") outside the points read of " +
                                        std::to_string(height) + " x " + std::to_string(width));
            return points[row * width + column];
        }

        /*! The cloud as the organised LiDAR reader gives it: beams = height (rows, top to bottom), columns = width,
         *  column-major storage; intensity from the "intensity" field if it was read, else NaN. Points are copied as
         *  read (PCL writes NaN for no return; an all-zero point stays zero). Precondition: complete(); throws
         *  std::invalid_argument otherwise. O(points). */
        [[nodiscard]] OrganizedCloud<E> toOrganized() const
        {
            if (!complete())
                throw std::invalid_argument("PcdCloud::toOrganized: incomplete cloud (" + std::to_string(points.size()) +
                                            " of " + std::to_string(width * height) + " points)");
            OrganizedCloud<E> c;
            c.beams = height;
            c.columns = width;
            c.points.resize(points.size());
            c.intensity.assign(points.size(), std::numeric_limits<E>::quiet_NaN());
            const PcdValues *in = field("intensity");
            for (std::size_t r = 0; r < height; ++r)
                for (std::size_t col = 0; col < width; ++col)
                {
                    const std::size_t src = r * width + col, dst = col * height + r;
                    c.points[dst] = points[src];
                    if (in) c.intensity[dst] = static_cast<E>(in->values[src * in->count]);
                }
            return c;
        }
    };

    namespace detail
    {
        //! A little-endian value of the field's type at p, converted to T.
        template<typename T>
        T load(const unsigned char *p, char type, std::size_t size)
        {
            std::uint64_t u = 0;
            for (std::size_t k = 0; k < size; ++k) u |= static_cast<std::uint64_t>(p[k]) << (8 * k);
            if (type == 'F')
            {
                if (size == 4)
                {
                    const auto u32 = static_cast<std::uint32_t>(u);
                    float f;
                    std::memcpy(&f, &u32, 4);
                    return static_cast<T>(f);
                }
                double d;
                std::memcpy(&d, &u, 8);
                return static_cast<T>(d);
            }
            if (type == 'U') return static_cast<T>(u);
            // sign-extend from size bytes
            const std::uint64_t sign = std::uint64_t(1) << (8 * size - 1);
            const std::int64_t i = size == 8 ? static_cast<std::int64_t>(u)
                                             : static_cast<std::int64_t>(u ^ sign) - static_cast<std::int64_t>(sign);
            return static_cast<T>(i);
        }

        //! One ascii token of the field's type as a double; false if it is not a value of that type.
        inline bool parseValue(std::string_view tok, const PcdField &f, double &v)
        {
            if (f.type == 'F')
            {
                if (f.size == 4)
                {
                    float x = 0;
                    if (!parseFloat(tok, x)) return false;
                    v = x;
                    return true;
                }
                return parseFloat(tok, v);
            }
            const unsigned bits = static_cast<unsigned>(8 * f.size);
            if (f.type == 'U')
            {
                std::uint64_t u = 0;
                if (!parseUnsigned(tok, u) || (bits < 64 && u >> bits != 0)) return false;
                v = static_cast<double>(u);
                return true;
            }
            std::int64_t i = 0;
            auto [end, ec] = std::from_chars(tok.data(), tok.data() + tok.size(), i);
            if (ec != std::errc() || end != tok.data() + tok.size()) return false;
            if (bits < 64)
            {
                const std::int64_t lim = std::int64_t(1) << (bits - 1);
                if (i < -lim || i >= lim) return false;
            }
            v = static_cast<double>(i);
            return true;
        }

        //! What the reader needs of each field: xyz positions and the requested fields.
        struct Plan
        {
            std::size_t xyz[3]{};                       // field indices of x, y, z
            std::vector<std::size_t> extra;             // field indices of the requested fields, in request order
        };

        inline Plan plan(const PcdHeader &h, const PcdOptions &options)
        {
            Plan p;
            const char *names[3] = {"x", "y", "z"};
            for (int k = 0; k < 3; ++k)
            {
                p.xyz[k] = h.find(names[k]);
                if (p.xyz[k] == PcdError::npos) failPcd(h.fields_line, std::string("no field '") + names[k] + "' (x, y and z are required)");
                if (h.fields[p.xyz[k]].count != 1)
                    failPcd(h.fields_line, std::string("field '") + names[k] + "' has COUNT " +
                                            std::to_string(h.fields[p.xyz[k]].count) + " (x, y and z need COUNT 1)");
            }
            for (const auto &name : options.fields)
            {
                const std::size_t i = h.find(name);
                if (i != PcdError::npos && name != "_") p.extra.push_back(i);
            }
            return p;
        }

        template<typename E>
        void startFields(PcdCloud<E> &cloud, const Plan &p, std::size_t reserve)
        {
            cloud.points.reserve(reserve);
            for (std::size_t i : p.extra)
            {
                const auto &f = cloud.header.fields[i];
                cloud.fields.push_back({f.name, f.count, {}});
                cloud.fields.back().values.reserve(reserve <= std::numeric_limits<std::size_t>::max() / f.count ? reserve * f.count : 0);
            }
        }

        template<typename E>
        void readAscii(const unsigned char *bytes, std::size_t size, PcdCloud<E> &cloud, const Plan &p)
        {
            const PcdHeader &h = cloud.header;
            const std::string_view text(reinterpret_cast<const char *>(bytes), size);
            std::size_t per_line = 0;
            for (const auto &f : h.fields) per_line += f.count;   // (no overflow: at most point_step)
            // A point takes at least 2 bytes per value ("0 " or "0\n"): reserve no more than the data can hold.
            startFields(cloud, p, std::min(h.points, (size - h.data_offset) / per_line / 2 + 1));
            std::vector<std::string_view> tok;
            std::vector<double> value(h.fields.size());   // first value of each field on the current line
            std::vector<std::size_t> first(h.fields.size());
            std::size_t line = h.data_line, pos = h.data_offset, point = 0;
            while (pos < text.size())
            {
                ++line;
                const std::size_t start = pos;
                std::size_t nl = text.find('\n', pos);
                if (nl == std::string_view::npos) nl = text.size();
                tok = tokens(text.substr(pos, nl - pos));
                pos = nl + (nl < text.size() ? 1 : 0);
                if (tok.empty()) continue;
                if (point == h.points)
                    throw PcdError("", line, point, start, "more data lines than POINTS " + std::to_string(h.points));
                if (tok.size() != per_line)
                    throw PcdError("", line, point, start, std::to_string(tok.size()) + " values, the fields need " + std::to_string(per_line));
                std::size_t t = 0;
                for (std::size_t i = 0; i < h.fields.size(); ++i)
                {
                    const PcdField &f = h.fields[i];
                    first[i] = t;
                    if (f.name == "_")
                    {
                        t += f.count;   // padding: skipped unread, as PCL does
                        continue;
                    }
                    for (std::size_t k = 0; k < f.count; ++k, ++t)
                    {
                        double v = 0;
                        if (!parseValue(tok[t], f, v))
                            throw PcdError("", line, point, static_cast<std::size_t>(tok[t].data() - text.data()),
                                           "bad value '" + std::string(tok[t].substr(0, 40)) + "' for field '" + f.name +
                                               "' (TYPE " + f.type + ", SIZE " + std::to_string(f.size) + ")");
                        if (k == 0) value[i] = v;
                    }
                }
                cloud.points.emplace_back(static_cast<E>(value[p.xyz[0]]), static_cast<E>(value[p.xyz[1]]),
                                          static_cast<E>(value[p.xyz[2]]));
                for (std::size_t e = 0; e < p.extra.size(); ++e)
                {
                    const PcdField &f = h.fields[p.extra[e]];
                    for (std::size_t k = 0; k < f.count; ++k)
                    {
                        double v = 0;
                        parseValue(tok[first[p.extra[e]] + k], f, v);   // (validated above)
                        cloud.fields[e].values.push_back(v);
                    }
                }
                ++point;
            }
            if (point < h.points)
                throw PcdError("", line, point, size, "truncated data: " + std::to_string(point) + " of POINTS " +
                                                          std::to_string(h.points) + " lines");
        }

        //! Appends points [0, n) of records where point i's field f starts at base + i * stride(f) + offset(f).
        template<typename E, class At>
        void gather(PcdCloud<E> &cloud, const Plan &p, std::size_t n, At at)
        {
            const PcdHeader &h = cloud.header;
            const PcdField &fx = h.fields[p.xyz[0]], &fy = h.fields[p.xyz[1]], &fz = h.fields[p.xyz[2]];
            for (std::size_t i = 0; i < n; ++i)
                cloud.points.emplace_back(load<E>(at(p.xyz[0], i), fx.type, fx.size), load<E>(at(p.xyz[1], i), fy.type, fy.size),
                                          load<E>(at(p.xyz[2], i), fz.type, fz.size));
            for (std::size_t e = 0; e < p.extra.size(); ++e)
            {
                const PcdField &f = h.fields[p.extra[e]];
                for (std::size_t i = 0; i < n; ++i)
                    for (std::size_t k = 0; k < f.count; ++k)
                        cloud.fields[e].values.push_back(load<double>(at(p.extra[e], i) + k * f.size, f.type, f.size));
            }
        }

        template<typename E>
        void readBinary(const unsigned char *bytes, std::size_t size, PcdCloud<E> &cloud, const Plan &p)
        {
            const PcdHeader &h = cloud.header;
            const std::size_t avail = size - h.data_offset, step = h.point_step;
            const std::size_t whole = std::min(h.points, avail / step);
            startFields(cloud, p, whole);
            gather(cloud, p, whole, [&](std::size_t f, std::size_t i) { return bytes + h.data_offset + i * step + h.fields[f].offset; });
            if (whole < h.points)
                throw PcdError("", PcdError::npos, whole, h.data_offset + whole * step,
                               "truncated data: POINTS " + std::to_string(h.points) + " of " + std::to_string(step) +
                                   " bytes, the input ends " + std::to_string(avail - whole * step) + " bytes into this point");
        }

        inline std::uint32_t le32(const unsigned char *b)
        {
            return static_cast<std::uint32_t>(b[0]) | static_cast<std::uint32_t>(b[1]) << 8 |
                   static_cast<std::uint32_t>(b[2]) << 16 | static_cast<std::uint32_t>(b[3]) << 24;
        }

        template<typename E>
        void readCompressed(const unsigned char *bytes, std::size_t size, PcdCloud<E> &cloud, const Plan &p)
        {
            const PcdHeader &h = cloud.header;
            const std::size_t at = h.data_offset, avail = size - at, n = h.points;
            const auto bad = [&](std::size_t offset, const std::string &what) { return PcdError("", PcdError::npos, PcdError::npos, offset, what); };
            if (avail < 8) throw bad(at, "truncated data: no compressed and uncompressed sizes");
            const std::size_t csize = le32(bytes + at), usize = le32(bytes + at + 4);
            if (csize > avail - 8)
                throw bad(at, "truncated data: a compressed block of " + std::to_string(csize) + " bytes, the input holds " +
                                  std::to_string(avail - 8) + " after its sizes");
            // Column f starts after the columns of the fields before it, padding fields having none.
            std::vector<std::size_t> column(h.fields.size());
            std::size_t packed = 0;
            for (std::size_t f = 0; f < h.fields.size(); ++f)
            {
                column[f] = packed;
                if (h.fields[f].name != "_") packed += h.fields[f].size * h.fields[f].count;
            }
            if ((n != 0 && packed > std::numeric_limits<std::size_t>::max() / n) || n * packed != usize)
                throw bad(at + 4, "uncompressed size " + std::to_string(usize) + " differs from POINTS x point size = " +
                                      std::to_string(n) + " x " + std::to_string(packed) + " (padding fields excluded)");
            if (usize > lzfMaxOutput(csize))
                throw bad(at, "bad LZF stream: " + std::to_string(csize) + " compressed bytes cannot hold " + std::to_string(usize));
            std::vector<std::uint8_t> data(usize);
            const LzfResult r = lzfDecompress(bytes + at + 8, csize, data.data(), usize);
            std::size_t whole = n;   // points whose needed fields were all decompressed
            if (r.error)
            {
                std::vector<std::size_t> needed(p.extra);
                needed.insert(needed.end(), p.xyz, p.xyz + 3);
                for (std::size_t f : needed)
                {
                    const std::size_t start = n * column[f], len = h.fields[f].size * h.fields[f].count;
                    whole = std::min(whole, r.produced < start ? 0 : (r.produced - start) / len);
                }
            }
            startFields(cloud, p, whole);
            gather(cloud, p, whole, [&](std::size_t f, std::size_t i) {
                return data.data() + n * column[f] + i * h.fields[f].size * h.fields[f].count;
            });
            if (r.error)
                throw PcdError("", PcdError::npos, whole, at + 8 + r.input_offset,
                               std::string("bad LZF stream: ") + r.error + " (compressed byte " + std::to_string(r.input_offset) +
                                   ", " + std::to_string(r.produced) + " of " + std::to_string(usize) + " bytes decompressed)");
        }
    }

    /*! Reads a PCD file held in `size` bytes. Throws PcdError (message naming the header line, or the data line / point
     *  and byte offset) for a bad header (parsePcdHeader), a missing x, y or z field or one with COUNT > 1, and bad
     *  data: an ascii line with a wrong number of values (padding fields included) or a value that is not of its
     *  field's type (or out of its range: 1e39 for F 4), fewer or more ascii data lines than POINTS (empty lines are skipped), binary data shorter
     *  than POINTS records (bytes after them are ignored), a compressed block longer than the input, an uncompressed
     *  size other than POINTS x point size without padding, a bad LZF stream. With options.keep_partial, bad data instead ends the
     *  cloud at the faulty point (see PcdOptions). Allocation never exceeds what the input can describe: the points
     *  of the binary records present, 264 bytes per 3 compressed bytes, 1 point per 2 ascii bytes.
     *  O(size + points x fields). */
    template<typename E>
    PcdCloud<E> readPcdBytes(const unsigned char *bytes, std::size_t size, const PcdOptions &options = {})
    {
        PcdCloud<E> cloud;
        cloud.header = parsePcdHeader(bytes, size);
        cloud.width = cloud.header.width;
        cloud.height = cloud.header.height;
        const detail::Plan plan = detail::plan(cloud.header, options);
        try
        {
            switch (cloud.header.data)
            {
            case PcdDataKind::Ascii: detail::readAscii(bytes, size, cloud, plan); break;
            case PcdDataKind::Binary: detail::readBinary(bytes, size, cloud, plan); break;
            case PcdDataKind::BinaryCompressed: detail::readCompressed(bytes, size, cloud, plan); break;
            }
        }
        catch (const PcdError &e)
        {
            if (!options.keep_partial) throw;
            cloud.error = e.what();
            for (auto &f : cloud.fields) f.values.resize(cloud.points.size() * f.count);
        }
        return cloud;
    }

    //! readPcdBytes on the rest of a stream (read whole; PcdError for a read error).
    template<typename E>
    PcdCloud<E> readPcd(std::istream &in, const PcdOptions &options = {})
    {
        std::vector<unsigned char> bytes;
        char buf[1 << 16];
        while (in.read(buf, sizeof buf) || in.gcount() > 0) bytes.insert(bytes.end(), buf, buf + in.gcount());
        if (in.bad()) throw PcdError("", PcdError::npos, PcdError::npos, bytes.size(), "read error");
        return readPcdBytes<E>(bytes.data(), bytes.size(), options);
    }

    //! readPcdBytes on a file; PcdError if it cannot be opened, and every PcdError (and keep_partial's error) names
    //! the path.
    template<typename E>
    PcdCloud<E> readPcdFile(const std::string &path, const PcdOptions &options = {})
    {
        std::ifstream f(path, std::ios::binary);
        if (!f) throw PcdError(path, PcdError::npos, PcdError::npos, PcdError::npos, "cannot open the file");
        try
        {
            PcdCloud<E> cloud = readPcd<E>(f, options);
            if (!cloud.error.empty()) cloud.error = "PCD '" + path + "'" + cloud.error.substr(3);
            return cloud;
        }
        catch (const PcdError &e)
        {
            throw e.inFile(path);
        }
    }
}
