// The PCD reader and its LZF decompressor on crafted input: every field type, padding and COUNT > 1 fields in the
// three encodings, header variants (0.6), and the errors with their header line, data line, point and byte offset.
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "rtl/io/LzfDecompress.h"
#include "rtl/io/PcdFile.h"

namespace
{
    template<typename T>
    void put(std::string &s, T v)
    {
        unsigned char b[sizeof(T)];
        std::memcpy(b, &v, sizeof(T));   // (little-endian host)
        s.append(reinterpret_cast<const char *>(b), sizeof(T));
    }

    void put32(std::string &s, std::uint32_t v) { put(s, v); }

    //! LZF with literal runs only (at most 32 bytes each): a valid stream of any data.
    std::string lzfLiterals(const std::string &data)
    {
        std::string out;
        for (std::size_t i = 0; i < data.size(); i += 32)
        {
            const std::size_t n = std::min<std::size_t>(32, data.size() - i);
            out.push_back(static_cast<char>(n - 1));
            out += data.substr(i, n);
        }
        return out;
    }

    template<typename E = double>
    rtl::PcdCloud<E> read(const std::string &s, const rtl::PcdOptions &options = {})
    {
        return rtl::readPcdBytes<E>(reinterpret_cast<const unsigned char *>(s.data()), s.size(), options);
    }

    std::string errorOf(const std::string &s)
    {
        try
        {
            static_cast<void>(read(s));
        }
        catch (const rtl::PcdError &e)
        {
            return e.what();
        }
        return "<no exception>";
    }

    // Fields in a deliberate order: rgb U4, 3 bytes of padding, z F8, normal F4 x 3, x I2, y U1, intensity F4.
    const char *mixedHeader = "# made by hand\nVERSION 0.7\nFIELDS rgb _ z normal x y intensity\nSIZE 4 1 8 4 2 1 4\n"
                              "TYPE U I F F I U F\nCOUNT 1 3 1 3 1 1 1\nWIDTH 3\nHEIGHT 1\n"
                              "VIEWPOINT 1.5 -2 3 0.5 0.5 -0.5 0.5\nPOINTS 3\n";
    struct Mixed
    {
        std::uint32_t rgb;
        double z;
        float normal[3];
        std::int16_t x;
        std::uint8_t y;
        float intensity;
    };
    const Mixed mixed[3] = {{0x00ff8000u, -1.25, {0.f, 0.f, 1.f}, -300, 7, 0.5f},
                            {1u, 1e300, {1.f, -0.f, 0.25f}, 32767, 255, -2.f},
                            {0xffffffffu, std::numeric_limits<double>::quiet_NaN(), {-1.f, 2.f, 3.f}, -32768, 0, 100.f}};

    std::string mixedRecord(const Mixed &m)
    {
        std::string s;
        put(s, m.rgb);
        s += std::string("\x01\x02\x03", 3);
        put(s, m.z);
        for (float f : m.normal) put(s, f);
        put(s, m.x);
        put(s, m.y);
        put(s, m.intensity);
        return s;
    }

    std::string mixedBinary()
    {
        std::string s = std::string(mixedHeader) + "DATA binary\n";
        for (const auto &m : mixed) s += mixedRecord(m);
        return s;
    }

    std::string mixedCompressed()
    {
        // Column by column: every point's rgb, every point's z, ...; padding has no column (as PCL reads it).
        const std::size_t sizes[] = {4, 3, 8, 12, 2, 1, 4};
        const bool padding[] = {false, true, false, false, false, false, false};
        std::string records[3], columns;
        for (int i = 0; i < 3; ++i) records[i] = mixedRecord(mixed[i]);
        std::size_t offset = 0;
        for (int f = 0; f < 7; ++f)
        {
            if (!padding[f])
                for (const auto &r : records) columns += r.substr(offset, sizes[f]);
            offset += sizes[f];
        }
        const std::string block = lzfLiterals(columns);
        std::string s = std::string(mixedHeader) + "DATA binary_compressed\n";
        put32(s, static_cast<std::uint32_t>(block.size()));
        put32(s, static_cast<std::uint32_t>(columns.size()));
        return s + block;
    }

    std::string mixedAscii()
    {
        // Values of the padding field are skipped unread (PCL's reader needs them there); the NaN as PCL writes it.
        return std::string(mixedHeader) + "DATA ascii\n"
                                          "16744448 1 2 3 -1.25 0 0 1 -300 7 0.5\n"
                                          "1 _ _ _ 1e+300 1 -0 0.25 32767 255 -2\r\n"
                                          "\n"
                                          "4294967295 0 0 0 nan -1 2 3 -32768 0 100\n";
    }
}

TEST(PcdFormat, FieldsAtAnyPositionOfAnyTypeWithPaddingAndCountsInEveryEncoding)
{
    rtl::PcdOptions options;
    options.fields = {"normal", "rgb", "intensity"};
    for (const std::string &file : {mixedBinary(), mixedCompressed(), mixedAscii()})
    {
        SCOPED_TRACE(file.substr(file.find("DATA"), 20));
        const auto c = read(file, options);
        ASSERT_TRUE(c.complete());
        EXPECT_EQ(c.header.point_step, 4u + 3 + 8 + 12 + 2 + 1 + 4);
        EXPECT_EQ(c.viewpoint(), (std::array<double, 7>{1.5, -2, 3, 0.5, 0.5, -0.5, 0.5}));
        ASSERT_EQ(c.points.size(), 3u);
        for (int i = 0; i < 3; ++i)
        {
            EXPECT_EQ(c.points[i].x(), mixed[i].x);
            EXPECT_EQ(c.points[i].y(), mixed[i].y);
            if (i == 2)
                EXPECT_TRUE(std::isnan(c.points[i].z()));
            else
                EXPECT_EQ(c.points[i].z(), mixed[i].z);
        }
        ASSERT_EQ(c.fields.size(), 3u);
        EXPECT_EQ(c.fields[0].count, 3u);
        ASSERT_EQ(c.fields[0].values.size(), 9u);
        for (int i = 0; i < 3; ++i)
        {
            for (int k = 0; k < 3; ++k) EXPECT_EQ(c.fields[0].values[i * 3 + k], mixed[i].normal[k]);
            EXPECT_EQ(c.fields[1].values[i], mixed[i].rgb);
            EXPECT_EQ(c.fields[2].values[i], mixed[i].intensity);
        }
        EXPECT_TRUE(std::signbit(c.fields[0].values[4]));   // -0 kept
        // float coordinates: 1e300 becomes +inf, as a cast does
        EXPECT_EQ(read<float>(file).points[1].z(), std::numeric_limits<float>::infinity());
    }
}

TEST(PcdFormat, IntegerExtremesAndTheirAsciiLimits)
{
    const std::string header = "FIELDS x y z\nSIZE 1 2 8\nTYPE I U I\nWIDTH 2\nPOINTS 2\n";
    std::string bin = header + "DATA binary\n";
    put<std::int8_t>(bin, -128);
    put<std::uint16_t>(bin, 65535);
    put<std::int64_t>(bin, -(std::int64_t(1) << 53));
    put<std::int8_t>(bin, 127);
    put<std::uint16_t>(bin, 0);
    put<std::int64_t>(bin, std::numeric_limits<std::int64_t>::min());
    const std::string ascii = header + "DATA ascii\n-128 65535 -9007199254740992\n127 0 -9223372036854775808\n";
    for (const auto &file : {bin, ascii})
    {
        const auto c = read(file);
        ASSERT_EQ(c.points.size(), 2u);
        EXPECT_EQ(c.points[0].x(), -128);
        EXPECT_EQ(c.points[0].y(), 65535);
        EXPECT_EQ(c.points[0].z(), -9007199254740992.0);
        EXPECT_EQ(c.points[1].x(), 127);
        EXPECT_EQ(c.points[1].z(), -9223372036854775808.0);
        EXPECT_TRUE(c.header.version.empty());
    }
    EXPECT_EQ(errorOf(header + "DATA ascii\n128 0 0\n0 0 0\n"),
              "PCD, data line 7 (point 0) at byte offset 63: bad value '128' for field 'x' (TYPE I, SIZE 1)");
    EXPECT_EQ(errorOf(header + "DATA ascii\n0 0 0\n0 -1 0\n"),
              "PCD, data line 8 (point 1) at byte offset 71: bad value '-1' for field 'y' (TYPE U, SIZE 2)");
    EXPECT_EQ(errorOf(header + "DATA ascii\n0 0 0\n0 0 0.5\n"),
              "PCD, data line 8 (point 1) at byte offset 73: bad value '0.5' for field 'z' (TYPE I, SIZE 8)");
    // F 4 range: 1e39 does not fit a float (PCL's parser would not give that value either).
    EXPECT_NE(errorOf("FIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nWIDTH 1\nDATA ascii\n1e39 0 0\n").find("bad value '1e39'"),
              std::string::npos);
    // Too small for its type: a zero of its sign (1e-40 is a subnormal float and stays one).
    const auto tiny = read("FIELDS x y z\nSIZE 4 8 4\nTYPE F F F\nWIDTH 1\nDATA ascii\n-1e-50 1e-400 1e-40\n");
    EXPECT_EQ(tiny.points[0].x(), 0.0);
    EXPECT_TRUE(std::signbit(tiny.points[0].x()));
    EXPECT_EQ(tiny.points[0].y(), 0.0);
    EXPECT_FALSE(std::signbit(tiny.points[0].y()));
    EXPECT_EQ(tiny.points[0].z(), static_cast<double>(1e-40f));
    EXPECT_NE(errorOf("FIELDS x y z\nSIZE 4 8 4\nTYPE F F F\nWIDTH 1\nDATA ascii\n0 1e400 0\n").find("bad value '1e400'"),
              std::string::npos);
}

TEST(PcdFormat, Version06HeaderWithoutViewpointCountAndPoints)
{
    const auto c = read("# .PCD v.6 - Point Cloud Data file format\nVERSION .6\nFIELDS x y z\nSIZE 4 4 4\nTYPE F F F\n"
                        "WIDTH 2\nHEIGHT 1\nDATA ascii\n1 2 3\n4 5 6");   // (no newline after the last line)
    ASSERT_EQ(c.points.size(), 2u);
    EXPECT_EQ(c.points[1].z(), 6);
    EXPECT_EQ(c.header.version, ".6");
    EXPECT_EQ(c.viewpoint(), (std::array<double, 7>{0, 0, 0, 1, 0, 0, 0}));
    // POINTS alone: an unorganised cloud of that width.
    const auto p = read("FIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nPOINTS 1\nDATA ascii\n1 2 3\n");
    EXPECT_EQ(p.width, 1u);
    EXPECT_EQ(p.height, 1u);
    // An empty cloud, binary, with nothing after the DATA line.
    EXPECT_TRUE(read("FIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nWIDTH 0\nDATA binary\n").complete());
}

TEST(PcdFormat, HeaderErrorsNameTheLine)
{
    const std::string xyz = "FIELDS x y z\nSIZE 4 4 4\nTYPE F F F\n";
    const std::pair<std::string, std::string> cases[] = {
        {xyz + "WIDTH 10\nHEIGHT 2\nPOINTS 21\nDATA ascii\n",
         "PCD, header line 6: POINTS 21 differs from WIDTH x HEIGHT = 10 x 2 = 20"},
        {xyz + "WIDTH 1\nDATA lzf\n", "PCD, header line 5: unknown DATA kind 'lzf'"},
        {"FIELDS x y\nSIZE 4 4\nTYPE F F\nWIDTH 1\nDATA ascii\n1 2\n", "PCD, header line 1: no field 'z' (x, y and z are required)"},
        {"FIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nCOUNT 1 2 1\nWIDTH 1\nDATA ascii\n", "PCD, header line 1: field 'y' has COUNT 2 (x, y and z need COUNT 1)"},
        {xyz + "COUNT 1 1 4294967296\nWIDTH 1\nDATA ascii\n", "PCD, header line 4: field 'z': COUNT must be 1 to 4294967295, got '4294967296'"},
        {xyz + "COUNT 1 0 1\nWIDTH 1\nDATA ascii\n", "PCD, header line 4: field 'y': COUNT must be 1 to 4294967295, got '0'"},
        {"FIELDS x y z\nSIZE 4 4 2\nTYPE F F F\nWIDTH 1\nDATA ascii\n", "PCD, header line 2: field 'z': TYPE F with SIZE 2 (I/U take 1, 2, 4, 8; F takes 4, 8)"},
        {"FIELDS x y z\nSIZE 4 4 4\nTYPE F F D\nWIDTH 1\nDATA ascii\n", "PCD, header line 3: field 'z': TYPE D with SIZE 4 (I/U take 1, 2, 4, 8; F takes 4, 8)"},
        {"FIELDS x y z\nSIZE 4 4\nTYPE F F F\nWIDTH 1\nDATA ascii\n", "PCD, header line 2: 2 values for 3 FIELDS"},
        {"FIELDS x y x\nSIZE 4 4 4\nTYPE F F F\nWIDTH 1\nDATA ascii\n", "PCD, header line 1: field 'x' repeated"},
        {xyz + "WIDTH 1\nWIDTH 2\nDATA ascii\n", "PCD, header line 5: WIDTH repeated (first on line 4)"},
        {xyz + "WIDTH -1\nDATA ascii\n", "PCD, header line 4: WIDTH needs one unsigned integer"},
        {xyz + "WIDTH 4294967296\nHEIGHT 4294967296\nDATA binary\n", "PCD, header line 5: WIDTH x HEIGHT overflows"},
        {xyz + "HEIGHT 2\nPOINTS 2\nDATA ascii\n", "PCD, header line 4: HEIGHT without WIDTH"},
        {xyz + "DATA ascii\n", "PCD, header line 4: neither WIDTH nor POINTS before DATA"},
        {xyz + "WIDTH 1\nVIEWPOINT 0 0 0 1 0 0\nDATA ascii\n", "PCD, header line 5: VIEWPOINT needs 7 numbers (tx ty tz qw qx qy qz)"},
        {xyz + "WIDTH 1\nVIEWPOINT 0 0 nan 1 0 0 0\nDATA ascii\n", "PCD, header line 5: bad VIEWPOINT value 'nan'"},
        {"VERSION 0.8\n" + xyz + "WIDTH 1\nDATA ascii\n", "PCD, header line 1: unsupported VERSION '0.8' (0.6 and 0.7 are read)"},
        {xyz + "WIDTH 1\nCOLOR 3\nDATA ascii\n", "PCD, header line 5: unknown header key 'COLOR'"},
        {xyz + "WIDTH 1\n", "PCD, header line 5: no DATA line: the input ends in the header"},
        {"", "PCD, header line 1: no DATA line: the input ends in the header"},
        {"SIZE 4\nTYPE F\nWIDTH 1\nDATA ascii\n", "PCD, header line 4: no FIELDS before DATA"},
    };
    for (const auto &[file, message] : cases) EXPECT_EQ(errorOf(file), message) << file;
}

TEST(PcdFormat, AsciiDataErrorsNameTheLineThePointAndTheOffset)
{
    const std::string head = "FIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nWIDTH 3\nDATA ascii\n";   // 54 bytes, 5 lines
    EXPECT_EQ(errorOf(head + "1 2 3\n4 5\n7 8 9\n"), "PCD, data line 7 (point 1) at byte offset 60: 2 values, the fields need 3");
    EXPECT_EQ(errorOf(head + "1 2 3\n4 5 6\n"), "PCD, data line 7 (point 2) at byte offset 66: truncated data: 2 of POINTS 3 lines");
    EXPECT_EQ(errorOf(head + "1 2 3\n4 5 6\n7 8 9\n1 1 1\n"),
              "PCD, data line 9 (point 3) at byte offset 72: more data lines than POINTS 3");
    EXPECT_EQ(errorOf(head + "1 2 3\n4 x 6\n7 8 9\n"),
              "PCD, data line 7 (point 1) at byte offset 62: bad value 'x' for field 'y' (TYPE F, SIZE 4)");
    // keep_partial delivers the points before the faulty line, and the error.
    rtl::PcdOptions partial;
    partial.keep_partial = true;
    const auto c = read(head + "1 2 3\n4 x 6\n7 8 9\n", partial);
    ASSERT_EQ(c.points.size(), 1u);
    EXPECT_EQ(c.points[0].z(), 3);
    EXPECT_EQ(c.error, "PCD, data line 7 (point 1) at byte offset 62: bad value 'x' for field 'y' (TYPE F, SIZE 4)");
    EXPECT_FALSE(c.complete());
    // Header errors are thrown even then.
    EXPECT_THROW(read("FIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nWIDTH 2\nPOINTS 3\nDATA ascii\n", partial), rtl::PcdError);
}

TEST(PcdFormat, AbsurdSizesAreErrorsBeforeAnyAllocation)
{
    // 10^12 points of 16 bytes described by 16 bytes of data: the reader stops at point 1 (an allocation of their
    // size would fail or exhaust memory).
    std::string bin = "FIELDS x y z _\nSIZE 4 4 4 4\nTYPE F F F U\nWIDTH 1000000000000\nDATA binary\n";
    const std::size_t data = bin.size();
    bin += std::string(16, '\0');
    EXPECT_EQ(errorOf(bin), "PCD, point 1 at byte offset " + std::to_string(data + 16) +
                                ": truncated data: POINTS 1000000000000 of 16 bytes, the input ends 0 bytes into this point");
    EXPECT_EQ(errorOf("FIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nWIDTH 1000000000000\nDATA ascii\n1 2 3\n"),
              "PCD, data line 6 (point 1) at byte offset 72: truncated data: 1 of POINTS 1000000000000 lines");
    // A field of 2^32 - 1 values of 8 bytes: a point size of 34 GB that no byte of data backs.
    EXPECT_NE(errorOf("FIELDS x y z big\nSIZE 4 4 4 8\nTYPE F F F F\nCOUNT 1 1 1 4294967295\nWIDTH 1\nDATA binary\n")
                  .find("truncated data"),
              std::string::npos);
    // Compressed: a claimed 4 GB from a 3-byte block, and POINTS x point size beyond 2^32.
    std::string z = "FIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nWIDTH 357913941\nDATA binary_compressed\n";
    const std::size_t zdata = z.size();
    put32(z, 3);
    put32(z, 357913941u * 12);
    z += std::string("\xe0\xff\x00", 3);
    EXPECT_EQ(errorOf(z), "PCD, at byte offset " + std::to_string(zdata) + ": bad LZF stream: 3 compressed bytes cannot hold 4294967292");
    std::string w = "FIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nWIDTH 357913942\nDATA binary_compressed\n";
    put32(w, 0);
    put32(w, 0);
    EXPECT_NE(errorOf(w).find("uncompressed size 0 differs from POINTS x point size = 357913942 x 12"), std::string::npos);
}

TEST(PcdFormat, StreamAndBytesGiveTheSameCloud)
{
    const std::string file = mixedCompressed();
    std::istringstream in(file);
    const auto a = rtl::readPcd<float>(in);
    const auto b = read<float>(file);
    ASSERT_EQ(a.points.size(), b.points.size());
    for (std::size_t i = 0; i < a.points.size(); ++i)
        for (int d = 0; d < 3; ++d)
            EXPECT_TRUE(a.points[i][d] == b.points[i][d] || (std::isnan(a.points[i][d]) && std::isnan(b.points[i][d])));
    EXPECT_EQ(a.field("intensity")->values, b.field("intensity")->values);
}

TEST(LzfDecompress, LiteralsAndOverlappingBackReferences)
{
    // "abc", then a reference 3 back of length 7 (overlapping: "abcabca"), then a long one (7 + 10 + 2 = 19) 1 back.
    const std::uint8_t in[] = {2, 'a', 'b', 'c', (5 << 5) | 0, 2, (7 << 5) | 0, 10, 0};
    std::vector<std::uint8_t> out(3 + 7 + 19);
    const auto r = rtl::lzfDecompress(in, sizeof in, out.data(), out.size());
    ASSERT_EQ(r.error, nullptr);
    EXPECT_EQ(r.produced, out.size());
    EXPECT_EQ(std::string(out.begin(), out.end()), "abcabcabca" + std::string(19, 'a'));
}

TEST(LzfDecompress, BrokenStreamsAreErrorsWithTheirItemOffset)
{
    std::vector<std::uint8_t> out(16);
    const auto run = [&](std::vector<std::uint8_t> in, std::size_t out_size) {
        return rtl::lzfDecompress(in.data(), in.size(), out.data(), out_size);
    };
    auto r = run({2, 'a', 'b'}, 16);
    EXPECT_STREQ(r.error, "literal run past the end of the input");
    EXPECT_EQ(r.input_offset, 0u);
    r = run({0, 'a', (1 << 5) | 0, 1}, 16);   // distance 2 with 1 byte out
    EXPECT_STREQ(r.error, "back reference before the start of the output");
    EXPECT_EQ(r.input_offset, 2u);
    EXPECT_EQ(r.produced, 1u);
    r = run({0, 'a', (1 << 5)}, 16);
    EXPECT_STREQ(r.error, "back reference truncated");
    r = run({0, 'a', (7 << 5)}, 16);
    EXPECT_STREQ(r.error, "back reference truncated");
    r = run({0, 'a', (7 << 5), 0}, 16);
    EXPECT_STREQ(r.error, "back reference truncated");
    r = run({1, 'a', 'b'}, 1);
    EXPECT_STREQ(r.error, "literal run past the declared uncompressed size");
    r = run({0, 'a', (7 << 5), 20, 0}, 16);   // 29 bytes into 16
    EXPECT_STREQ(r.error, "back reference past the declared uncompressed size");
    r = run({0, 'a'}, 2);
    EXPECT_STREQ(r.error, "stream ends before the declared uncompressed size");
    EXPECT_EQ(r.produced, 1u);
    r = run({}, 0);
    EXPECT_EQ(r.error, nullptr);
    // The bound used before allocating: a 3-byte item gives at most 264 bytes.
    EXPECT_EQ(rtl::lzfMaxOutput(3), 528u);
    r = run({0, 'a', (7 << 5), 255, 0}, 0);
    EXPECT_NE(r.error, nullptr);
    std::vector<std::uint8_t> big(265);
    const std::uint8_t longest[] = {0, 'a', (7 << 5), 255, 0};
    r = rtl::lzfDecompress(longest, sizeof longest, big.data(), big.size());
    ASSERT_EQ(r.error, nullptr);
    EXPECT_EQ(r.produced, 1u + 264);
}
