// The header of a PCD file (the Point Cloud Library's point cloud format, versions 0.6 and 0.7) and the one
// exception type of the PCD reader.
//
// A header is a sequence of text lines `KEY value...` ending with the DATA line; the point data follows the newline
// of that line. Keys: VERSION, FIELDS, SIZE, TYPE (I signed, U unsigned, F floating point), COUNT (values per field),
// WIDTH, HEIGHT (rows; 1 = unorganised), VIEWPOINT (tx ty tz qw qx qy qz), POINTS, DATA (ascii, binary,
// binary_compressed). Lines starting with '#' and empty lines are skipped. Version 0.6 headers have no VIEWPOINT and
// may lack COUNT; both are optional here (identity viewpoint, COUNT 1).
#pragma once

#include <array>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <limits>
#include <stdexcept>
#include <string>
#include <string_view>
#include <system_error>
#include <vector>

#include "rtl/io/TextTokens.h"

namespace rtl
{
    /*! The only exception the PCD reader throws for bad input (and an unreadable file). The message starts with
     *  "PCD", then the file when known, then where: `header line N (KEY)`, `data line N (point k)` for ascii data,
     *  or `point k at byte offset o` for binary data; the members give the same facts (npos = not applicable). */
    class PcdError : public std::runtime_error
    {
    public:
        static constexpr std::size_t npos = static_cast<std::size_t>(-1);

        PcdError(const std::string &file, std::size_t line, std::size_t point, std::size_t byte_offset,
                 const std::string &what)
            : std::runtime_error(compose(file, line, point, byte_offset, what)), file_(file), line_(line),
              point_(point), byte_offset_(byte_offset), reason_(what)
        {
        }

        //! The file's path, or empty for bytes read from memory or a stream.
        [[nodiscard]] const std::string &file() const { return file_; }
        //! 1-based line of the header or of ascii data, or npos.
        [[nodiscard]] std::size_t line() const { return line_; }
        //! 0-based index of the point being read, or npos (header errors).
        [[nodiscard]] std::size_t point() const { return point_; }
        //! Byte offset in the input where the faulty item starts, or npos.
        [[nodiscard]] std::size_t byteOffset() const { return byte_offset_; }
        //! The message without the location prefix.
        [[nodiscard]] const std::string &reason() const { return reason_; }

        //! The same error for a named file (the readers of paths add it to errors raised on the bytes).
        [[nodiscard]] PcdError inFile(const std::string &file) const
        {
            return PcdError(file, line_, point_, byte_offset_, reason_);
        }

    private:
        static std::string compose(const std::string &file, std::size_t line, std::size_t point, std::size_t offset,
                                   const std::string &what)
        {
            std::string s = "PCD";
            if (!file.empty()) s += " '" + file + "'";
            std::string where;
            if (line != npos && point == npos) where = "header line " + std::to_string(line);
            else if (line != npos) where = "data line " + std::to_string(line) + " (point " + std::to_string(point) + ")";
            else if (point != npos) where = "point " + std::to_string(point);
            if (offset != npos) where += (where.empty() ? "" : " ") + std::string("at byte offset ") + std::to_string(offset);
            if (!where.empty()) s += ", " + where;
            return s + ": " + what;
        }

        std::string file_;
        std::size_t line_, point_, byte_offset_;
        std::string reason_;
    };

    enum class PcdDataKind { Ascii, Binary, BinaryCompressed };

    //! One FIELDS entry. A field named "_" is padding: its bytes in binary records and its values in ascii lines are
    //! skipped, and binary_compressed data has no column for it (as PCL's PCDReader reads such files).
    struct PcdField
    {
        std::string name;
        char type = 'F';            //!< 'I', 'U' or 'F'
        std::size_t size = 4;       //!< bytes per value: 1, 2, 4, 8 (I, U) or 4, 8 (F)
        std::size_t count = 1;      //!< values per point
        std::size_t offset = 0;     //!< byte offset of the field in a binary point record
    };

    struct PcdHeader
    {
        std::string version;                    //!< as written ("0.7", ".7", "0.6"); empty if absent
        std::vector<PcdField> fields;
        std::size_t width = 0, height = 1;      //!< height > 1: organised, row after row of `width` points
        std::size_t points = 0;                 //!< width * height
        std::array<double, 7> viewpoint{0, 0, 0, 1, 0, 0, 0};  //!< tx ty tz qw qx qy qz
        PcdDataKind data = PcdDataKind::Ascii;
        std::size_t data_offset = 0;            //!< first byte after the DATA line
        std::size_t data_line = 0;              //!< 1-based number of the DATA line
        std::size_t fields_line = 0;            //!< 1-based number of the FIELDS line
        std::size_t point_step = 0;             //!< bytes of one binary point record (sum of size * count)

        //! Index of the field called `name`, or npos.
        [[nodiscard]] std::size_t find(std::string_view name) const
        {
            for (std::size_t i = 0; i < fields.size(); ++i)
                if (fields[i].name == name) return i;
            return PcdError::npos;
        }
    };

    namespace detail
    {
        //! A whole token as an unsigned 64-bit integer (decimal digits only).
        inline bool parseUnsigned(std::string_view tok, std::uint64_t &v)
        {
            auto [end, ec] = std::from_chars(tok.data(), tok.data() + tok.size(), v);
            return ec == std::errc() && end == tok.data() + tok.size();
        }

        //! A whole token as a floating-point number of type T (from_chars rules: no '+', "nan" and "inf" accepted).
        //! Standard libraries without floating-point from_chars get the same rules on strtod / strtof.
        template<typename T>
        bool parseFloat(std::string_view tok, T &v)
        {
#if defined(__cpp_lib_to_chars)
            auto [end, ec] = std::from_chars(tok.data(), tok.data() + tok.size(), v);
            if (end != tok.data() + tok.size()) return false;
            if (ec == std::errc::result_out_of_range)
            {
                // Too small for T (1e-50 as a float) reads as a zero of its sign, as strtof gives it; too large is
                // an error. from_chars does not tell which, strtod does (its result is below 1 in magnitude).
                const std::string text(tok);
                if (!(std::abs(std::strtod(text.c_str(), nullptr)) < 1)) return false;
                v = tok.front() == '-' ? -T(0) : T(0);
                return true;
            }
            return ec == std::errc();
#else
            if (tok.empty() || tok.front() == '+' || tok.find_first_of("xX") != std::string_view::npos) return false;
            const std::string text(tok);
            char *end = nullptr;
            errno = 0;
            const T r = sizeof(T) == 4 ? static_cast<T>(std::strtof(text.c_str(), &end)) : static_cast<T>(std::strtod(text.c_str(), &end));
            if (end != text.c_str() + text.size() || (errno == ERANGE && std::isinf(r))) return false;
            v = r;
            return true;
#endif
        }

        struct Seen
        {
            std::size_t line = 0;    // 0: key absent
            std::vector<std::string_view> values;
        };

        [[noreturn]] inline void failPcd(std::size_t line, const std::string &what)
        {
            throw PcdError("", line, PcdError::npos, PcdError::npos, what);
        }

        inline std::uint64_t unsignedValue(const Seen &key, const char *name)
        {
            std::uint64_t v = 0;
            if (key.values.size() != 1 || !parseUnsigned(key.values[0], v))
                failPcd(key.line, std::string(name) + " needs one unsigned integer");
            return v;
        }
    }

    /*! Parses the header at the start of `size` bytes. The data must start at header.data_offset; its size is not
     *  checked here. Throws PcdError naming the header line for: an unknown key or a repeated one, a line before the
     *  DATA line that never ends, a missing FIELDS or DATA line, SIZE/TYPE/COUNT lists whose length differs from
     *  FIELDS, a TYPE/SIZE pair other than I/U 1, 2, 4, 8 and F 4, 8, a COUNT of 0 or above 2^32 - 1, a repeated field
     *  name (other than "_"), a POINTS that differs from WIDTH * HEIGHT (or an overflowing product), a viewpoint
     *  that is not 7 finite numbers, an unknown DATA kind, an unsupported VERSION (other than 0.6, 0.7, .6, .7).
     *  WIDTH may be absent (then width = POINTS, height 1), HEIGHT (1), POINTS (width * height). O(header size). */
    inline PcdHeader parsePcdHeader(const unsigned char *bytes, std::size_t size)
    {
        using namespace detail;
        const std::string_view text(reinterpret_cast<const char *>(bytes), size);
        Seen version, fields, sizes, types, counts, width, height, viewpoint, points;
        PcdHeader h;
        std::size_t line = 0, pos = 0;
        bool data_seen = false;
        while (!data_seen)
        {
            if (pos >= text.size()) failPcd(line + 1, "no DATA line: the input ends in the header");
            ++line;
            std::size_t nl = text.find('\n', pos);
            const bool last = nl == std::string_view::npos;
            if (last) nl = text.size();
            const auto tok = tokens(text.substr(pos, nl - pos));
            pos = last ? text.size() : nl + 1;
            if (tok.empty() || tok[0][0] == '#') continue;
            const std::string_view key = tok[0];
            Seen *seen = nullptr;
            if (key == "VERSION") seen = &version;
            else if (key == "FIELDS") seen = &fields;
            else if (key == "SIZE") seen = &sizes;
            else if (key == "TYPE") seen = &types;
            else if (key == "COUNT") seen = &counts;
            else if (key == "WIDTH") seen = &width;
            else if (key == "HEIGHT") seen = &height;
            else if (key == "VIEWPOINT") seen = &viewpoint;
            else if (key == "POINTS") seen = &points;
            else if (key == "DATA")
            {
                if (tok.size() != 2) failPcd(line, "DATA needs one kind (ascii, binary, binary_compressed)");
                if (tok[1] == "ascii") h.data = PcdDataKind::Ascii;
                else if (tok[1] == "binary") h.data = PcdDataKind::Binary;
                else if (tok[1] == "binary_compressed") h.data = PcdDataKind::BinaryCompressed;
                else failPcd(line, "unknown DATA kind '" + std::string(tok[1]) + "'");
                h.data_line = line;
                h.data_offset = pos;
                data_seen = true;
                continue;
            }
            else
                failPcd(line, "unknown header key '" + std::string(key.substr(0, 40)) + "'");
            if (seen->line != 0) failPcd(line, std::string(key) + " repeated (first on line " + std::to_string(seen->line) + ")");
            seen->line = line;
            seen->values.assign(tok.begin() + 1, tok.end());
        }

        if (version.line != 0)
        {
            if (version.values.size() != 1) failPcd(version.line, "VERSION needs one value");
            const auto v = version.values[0];
            if (v != "0.7" && v != ".7" && v != "0.6" && v != ".6")
                failPcd(version.line, "unsupported VERSION '" + std::string(v.substr(0, 40)) + "' (0.6 and 0.7 are read)");
            h.version = std::string(v);
        }
        if (fields.line == 0 || fields.values.empty()) failPcd(fields.line ? fields.line : h.data_line, "no FIELDS before DATA");
        const std::size_t n = fields.values.size();
        if (sizes.line == 0) failPcd(h.data_line, "no SIZE before DATA");
        if (types.line == 0) failPcd(h.data_line, "no TYPE before DATA");
        for (const Seen *list : {&sizes, &types, &counts})
            if (list->line != 0 && list->values.size() != n)
                failPcd(list->line, std::to_string(list->values.size()) + " values for " + std::to_string(n) + " FIELDS");
        h.fields.resize(n);
        h.fields_line = fields.line;
        for (std::size_t i = 0; i < n; ++i)
        {
            PcdField &f = h.fields[i];
            f.name = std::string(fields.values[i]);
            if (f.name != "_")
                for (std::size_t j = 0; j < i; ++j)
                    if (h.fields[j].name == f.name) failPcd(fields.line, "field '" + f.name + "' repeated");
            std::uint64_t s = 0;
            if (!parseUnsigned(sizes.values[i], s)) failPcd(sizes.line, "bad SIZE '" + std::string(sizes.values[i].substr(0, 40)) + "'");
            if (types.values[i].size() != 1) failPcd(types.line, "bad TYPE '" + std::string(types.values[i].substr(0, 40)) + "'");
            f.type = types.values[i][0];
            const bool ok = ((f.type == 'I' || f.type == 'U') && (s == 1 || s == 2 || s == 4 || s == 8)) ||
                            (f.type == 'F' && (s == 4 || s == 8));
            if (!ok)
                failPcd(f.type == 'I' || f.type == 'U' || f.type == 'F' ? sizes.line : types.line,
                     "field '" + f.name + "': TYPE " + std::string(types.values[i]) + " with SIZE " +
                         std::string(sizes.values[i].substr(0, 40)) + " (I/U take 1, 2, 4, 8; F takes 4, 8)");
            f.size = static_cast<std::size_t>(s);
            if (counts.line != 0)
            {
                std::uint64_t c = 0;
                if (!parseUnsigned(counts.values[i], c) || c == 0 || c > 0xffffffffu)
                    failPcd(counts.line, "field '" + f.name + "': COUNT must be 1 to 4294967295, got '" +
                                          std::string(counts.values[i].substr(0, 40)) + "'");
                f.count = static_cast<std::size_t>(c);
            }
            // Checked: 8 * (2^32 - 1) bytes of one field already overflow a 32-bit size_t (WebAssembly).
            f.offset = h.point_step;
            const std::size_t max = std::numeric_limits<std::size_t>::max();
            if (f.count > max / f.size || f.size * f.count > max - h.point_step)
                failPcd(counts.line, "field '" + f.name + "': the point size overflows");
            h.point_step += f.size * f.count;
        }

        std::uint64_t w = 0, ht = 1, np = 0;
        if (height.line != 0) ht = unsignedValue(height, "HEIGHT");
        if (points.line != 0) np = unsignedValue(points, "POINTS");
        if (width.line != 0) w = unsignedValue(width, "WIDTH");
        else if (points.line == 0) failPcd(h.data_line, "neither WIDTH nor POINTS before DATA");
        else if (ht != 1) failPcd(height.line, "HEIGHT without WIDTH");
        else w = np;
        if (w != 0 && ht > std::numeric_limits<std::uint64_t>::max() / w)
            failPcd(height.line, "WIDTH x HEIGHT overflows");
        if (points.line == 0) np = w * ht;
        else if (np != w * ht)
            failPcd(points.line, "POINTS " + std::to_string(np) + " differs from WIDTH x HEIGHT = " + std::to_string(w) +
                                  " x " + std::to_string(ht) + " = " + std::to_string(w * ht));
        if (w > std::numeric_limits<std::size_t>::max() || ht > std::numeric_limits<std::size_t>::max() ||
            np > std::numeric_limits<std::size_t>::max())
            failPcd(points.line ? points.line : width.line, "point count too large for this platform");
        h.width = static_cast<std::size_t>(w);
        h.height = static_cast<std::size_t>(ht);
        h.points = static_cast<std::size_t>(np);

        if (viewpoint.line != 0)
        {
            if (viewpoint.values.size() != 7) failPcd(viewpoint.line, "VIEWPOINT needs 7 numbers (tx ty tz qw qx qy qz)");
            for (std::size_t k = 0; k < 7; ++k)
                if (!parseFloat(viewpoint.values[k], h.viewpoint[k]) || !std::isfinite(h.viewpoint[k]))
                    failPcd(viewpoint.line, "bad VIEWPOINT value '" + std::string(viewpoint.values[k].substr(0, 40)) + "'");
        }
        return h;
    }
}
