// The PCD reader on files written by the Point Cloud Library's own PCDWriter (tests/data/pcd, made by
// make_pcd_files.sh there) in its three encodings: the points read back equal the source records bit for bit.
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "rtl/io/OrganizedLidar.h"
#include "rtl/io/PcdFile.h"

namespace
{
    const std::string data_dir = RTL_TEST_DATA_DIR;
    const char *const encodings[] = {"ascii", "binary", "compressed"};

    std::vector<unsigned char> fileBytes(const std::string &path)
    {
        std::ifstream f(path, std::ios::binary);
        return {std::istreambuf_iterator<char>(f), std::istreambuf_iterator<char>()};
    }

    struct Record
    {
        float x, y, z, i;
        std::size_t column, beam;
    };

    //! Record (column c, beam b) of a column-major float32 x y z intensity excerpt with `beams` beams.
    Record record(const std::vector<unsigned char> &bin, std::size_t beams, std::size_t c, std::size_t b)
    {
        float v[4];
        std::memcpy(v, bin.data() + (c * beams + b) * 16, 16);   // (little-endian host, as the excerpt)
        return {v[0], v[1], v[2], v[3], c, b};
    }

    std::uint32_t bits(float f)
    {
        std::uint32_t u;
        std::memcpy(&u, &f, 4);
        return u;
    }

    bool noReturn(const Record &r) { return r.x == 0.f && r.y == 0.f && r.z == 0.f; }
}

// Organised: columns 1000-1063 of the 4-beam excerpt, WIDTH 64 x HEIGHT 4, no returns written by PCL as NaN.
TEST(PcdPclFiles, OrganizedEqualsTheSourceRecordsInEveryEncoding)
{
    const auto bin = fileBytes(data_dir + "/rellis3d-os1-4x2048.bin");
    ASSERT_EQ(bin.size(), 4u * 2048 * 16);
    for (const char *encoding : encodings)
    {
        SCOPED_TRACE(encoding);
        const auto cloud = rtl::readPcdFile<float>(data_dir + "/pcd/organized." + encoding + ".pcd");
        ASSERT_TRUE(cloud.complete());
        EXPECT_TRUE(cloud.organized());
        EXPECT_EQ(cloud.width, 64u);
        EXPECT_EQ(cloud.height, 4u);
        ASSERT_EQ(cloud.points.size(), 256u);
        EXPECT_EQ(cloud.header.version, "0.7");
        EXPECT_EQ(cloud.viewpoint(), (std::array<double, 7>{0, 0, 0, 1, 0, 0, 0}));
        const rtl::PcdValues *intensity = cloud.field("intensity");
        ASSERT_NE(intensity, nullptr);
        EXPECT_EQ(cloud.field("ring"), nullptr);
        std::size_t gaps = 0;
        for (std::size_t b = 0; b < 4; ++b)
            for (std::size_t c = 0; c < 64; ++c)
            {
                const Record r = record(bin, 4, 1000 + c, b);
                const auto &p = cloud.at(b, c);
                if (noReturn(r))
                {
                    ++gaps;
                    EXPECT_TRUE(std::isnan(p.x()) && std::isnan(p.y()) && std::isnan(p.z())) << b << " " << c;
                }
                else
                {
                    EXPECT_EQ(bits(p.x()), bits(r.x)) << b << " " << c;
                    EXPECT_EQ(bits(p.y()), bits(r.y)) << b << " " << c;
                    EXPECT_EQ(bits(p.z()), bits(r.z)) << b << " " << c;
                }
                EXPECT_EQ(bits(static_cast<float>(intensity->values[b * 64 + c])), bits(r.i)) << b << " " << c;
            }
        EXPECT_EQ(gaps, 32u);   // the no returns of these columns (make_pcd_files.sh)
    }
}

// The organised cloud is the organised LiDAR reader's cloud of the same columns: same points, same gaps.
TEST(PcdPclFiles, OrganizedIsTheOrganizedLidarReadersCloud)
{
    const auto bin = fileBytes(data_dir + "/rellis3d-os1-4x2048.bin");
    const auto lidar = rtl::readOrganizedLidarBytes<double>(bin.data() + 1000 * 4 * 16, 64 * 4 * 16, 4);
    for (const char *encoding : encodings)
    {
        SCOPED_TRACE(encoding);
        const auto organized = rtl::readPcdFile<double>(data_dir + "/pcd/organized." + encoding + ".pcd").toOrganized();
        ASSERT_EQ(organized.beams, 4u);
        ASSERT_EQ(organized.columns, 64u);
        for (std::size_t k = 0; k < lidar.points.size(); ++k)
        {
            ASSERT_EQ(organized.points[k].hasNaN(), lidar.points[k].hasNaN()) << k;
            if (!lidar.points[k].hasNaN())
            {
                for (int d = 0; d < 3; ++d) EXPECT_EQ(organized.points[k][d], lidar.points[k][d]) << k;
            }
            EXPECT_EQ(organized.intensity[k], lidar.intensity[k]) << k;
        }
    }
}

// Unorganised: 300 returns of columns 600-679 of the 16-beam excerpt, with an F 8 field t and a U 2 field ring.
TEST(PcdPclFiles, UnorganizedWithDoubleAndIntegerFieldsEqualsTheSource)
{
    const auto bin = fileBytes(data_dir + "/rellis3d-os1-16x2048.bin");
    ASSERT_EQ(bin.size(), 16u * 2048 * 16);
    std::vector<Record> source;
    for (std::size_t c = 600; c < 680; ++c)
        for (std::size_t b = 0; b < 16; ++b)
            if (!noReturn(record(bin, 16, c, b)) && source.size() < 300) source.push_back(record(bin, 16, c, b));
    ASSERT_EQ(source.size(), 300u);
    rtl::PcdOptions options;
    options.fields = {"t", "ring", "intensity", "absent"};
    for (const char *encoding : encodings)
    {
        SCOPED_TRACE(encoding);
        const auto cloud = rtl::readPcdFile<float>(data_dir + "/pcd/unorganized." + encoding + ".pcd", options);
        ASSERT_TRUE(cloud.complete());
        EXPECT_FALSE(cloud.organized());
        EXPECT_EQ(cloud.width, 300u);
        EXPECT_EQ(cloud.height, 1u);
        ASSERT_EQ(cloud.fields.size(), 3u);   // in request order, "absent" skipped
        EXPECT_EQ(cloud.fields[0].name, "t");
        EXPECT_EQ(cloud.fields[1].name, "ring");
        EXPECT_EQ(cloud.fields[2].name, "intensity");
        ASSERT_EQ(cloud.points.size(), 300u);
        for (std::size_t k = 0; k < 300; ++k)
        {
            const Record &r = source[k];
            EXPECT_EQ(bits(cloud.points[k].x()), bits(r.x)) << k;
            EXPECT_EQ(bits(cloud.points[k].y()), bits(r.y)) << k;
            EXPECT_EQ(bits(cloud.points[k].z()), bits(r.z)) << k;
            EXPECT_EQ(cloud.fields[0].values[k], 10.0 + static_cast<double>(r.column) / 64.0) << k;
            EXPECT_EQ(cloud.fields[1].values[k], static_cast<double>(4 * r.beam)) << k;
            EXPECT_EQ(bits(static_cast<float>(cloud.fields[2].values[k])), bits(r.i)) << k;
        }
        // The same file read with double coordinates gives the same values.
        const auto wide = rtl::readPcdFile<double>(data_dir + "/pcd/unorganized." + encoding + ".pcd", options);
        for (std::size_t k = 0; k < 300; ++k)
            for (int d = 0; d < 3; ++d) EXPECT_EQ(wide.points[k][d], static_cast<double>(cloud.points[k][d])) << k;
    }
}

// PCL pads binary files to whole pages: the bytes after the last record are ignored, truncation inside a record is not.
TEST(PcdPclFiles, TruncatedFilesNameTheFileThePointAndTheByteOffset)
{
    const std::string out = std::string(RTL_TEST_OUTPUT_DIR) + "/pcd-truncated.pcd";
    auto bytes = fileBytes(data_dir + "/pcd/organized.binary.pcd");
    const std::string text(bytes.begin(), bytes.end());
    const std::size_t data = text.find("DATA binary\n") + 12;
    bytes.resize(data + 100 * 16 + 5);   // 100 whole points and 5 bytes of the 101st
    std::ofstream(out, std::ios::binary).write(reinterpret_cast<const char *>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
    try
    {
        static_cast<void>(rtl::readPcdFile<float>(out));
        FAIL() << "no exception";
    }
    catch (const rtl::PcdError &e)
    {
        EXPECT_EQ(e.file(), out);
        EXPECT_EQ(e.point(), 100u);
        EXPECT_EQ(e.byteOffset(), data + 1600);
        EXPECT_EQ(std::string(e.what()), "PCD '" + out + "', point 100 at byte offset " + std::to_string(data + 1600) +
                                             ": truncated data: POINTS 256 of 16 bytes, the input ends 5 bytes into this point");
    }
    // keep_partial: the 100 points before it are delivered, equal to those of the whole file.
    rtl::PcdOptions partial;
    partial.keep_partial = true;
    const auto cut = rtl::readPcdFile<float>(out, partial);
    const auto whole = rtl::readPcdFile<float>(data_dir + "/pcd/organized.binary.pcd");
    EXPECT_FALSE(cut.complete());
    EXPECT_EQ(cut.error.rfind("PCD '" + out + "', point 100", 0), 0u) << cut.error;
    ASSERT_EQ(cut.points.size(), 100u);
    ASSERT_EQ(cut.field("intensity")->values.size(), 100u);
    for (std::size_t k = 0; k < 100; ++k)
        for (int d = 0; d < 3; ++d)
            EXPECT_EQ(bits(cut.points[k][d]), bits(whole.points[k][d])) << k;
    EXPECT_THROW(static_cast<void>(cut.toOrganized()), std::invalid_argument);

    // A missing file names the path.
    try
    {
        static_cast<void>(rtl::readPcdFile<float>(data_dir + "/pcd/no-such-file.pcd"));
        FAIL() << "no exception";
    }
    catch (const rtl::PcdError &e)
    {
        EXPECT_EQ(std::string(e.what()), "PCD '" + data_dir + "/pcd/no-such-file.pcd': cannot open the file");
    }
}

// LZF has no checksum: a changed literal byte goes unnoticed, but a broken stream structure or a size that does not
// fit is a PcdError naming its byte offset, and never reads or writes outside the buffers.
TEST(PcdPclFiles, CorruptCompressedBlockIsAnError)
{
    const auto good = fileBytes(data_dir + "/pcd/organized.compressed.pcd");
    const std::string text(good.begin(), good.end());
    const std::size_t data = text.find("DATA binary_compressed\n") + 23;
    std::uint32_t csize = 0, usize = 0;
    std::memcpy(&csize, good.data() + data, 4);
    std::memcpy(&usize, good.data() + data + 4, 4);
    ASSERT_EQ(usize, 256u * 16);
    ASSERT_GT(csize, 100u);
    const auto error = [](const std::vector<unsigned char> &bytes) {
        try
        {
            static_cast<void>(rtl::readPcdBytes<float>(bytes.data(), bytes.size()));
        }
        catch (const rtl::PcdError &e)
        {
            return std::string(e.what());
        }
        return std::string("<no exception>");
    };
    // The first control byte made a back reference as far back as it can reach: before the output's start.
    auto bad = good;
    bad[data + 8] = 0xff;
    EXPECT_EQ(error(bad).rfind("PCD, point 0 at byte offset " + std::to_string(data + 8) +
                                   ": bad LZF stream: back reference before the start of the output", 0), 0u) << error(bad);
    // The stream cut short by 10 bytes (the compressed size says so).
    bad = good;
    const std::uint32_t shorter = csize - 10;
    std::memcpy(bad.data() + data, &shorter, 4);
    EXPECT_NE(error(bad).find("bad LZF stream"), std::string::npos) << error(bad);
    // An uncompressed size other than POINTS x point size.
    bad = good;
    const std::uint32_t more = usize + 16;
    std::memcpy(bad.data() + data + 4, &more, 4);
    EXPECT_EQ(error(bad), "PCD, at byte offset " + std::to_string(data + 4) +
                              ": uncompressed size 4112 differs from POINTS x point size = 256 x 16 (padding fields excluded)");
    // A compressed size beyond the input.
    bad = good;
    const std::uint32_t huge = 0xfffffff0u;
    std::memcpy(bad.data() + data, &huge, 4);
    EXPECT_NE(error(bad).find("truncated data: a compressed block of 4294967280 bytes"), std::string::npos) << error(bad);
}
