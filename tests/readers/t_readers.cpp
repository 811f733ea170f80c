// Readers for CARMEN logs and organised LiDAR binaries, on the excerpts in tests/data and on crafted bad input.
#include <cmath>
#include <cstdint>
#include <cstring>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "rtl/io/CarmenLog.h"
#include "rtl/io/OrganizedLidar.h"

namespace
{
    const std::string data_dir = RTL_TEST_DATA_DIR;

    template<typename F>
    std::string errorOf(F &&f)
    {
        try
        {
            f();
        }
        catch (const std::exception &e)
        {
            return e.what();
        }
        return "<no exception>";
    }

    size_t gaps(const std::vector<rtl::VectorND<2, double>> &pts)
    {
        size_t n = 0;
        for (const auto &p : pts) n += p.hasNaN() ? 1 : 0;
        return n;
    }

    void appendRecord(std::string &s, float x, float y, float z, float i)
    {
        for (float f : {x, y, z, i})
        {
            std::uint32_t u;
            std::memcpy(&u, &f, 4);
            for (int k = 0; k < 4; ++k) s.push_back(static_cast<char>((u >> (8 * k)) & 0xffu));
        }
    }
}

TEST(CarmenLog, IntelExcerpt)
{
    const auto scans = rtl::readCarmenLogFile<double>(data_dir + "/intel.log");
    ASSERT_EQ(scans.size(), 30u);
    size_t total_gaps = 0;
    for (const auto &s : scans)
    {
        ASSERT_EQ(s.points.size(), 180u);
        ASSERT_EQ(s.ranges.size(), 180u);
        total_gaps += gaps(s.points);
        for (size_t i = 0; i < 180; ++i)
        {
            if (s.ranges[i] >= 80)
            {
                EXPECT_TRUE(s.points[i].hasNaN());
                continue;
            }
            const double a = -M_PI / 2 + static_cast<double>(i) * M_PI / 180;
            EXPECT_NEAR(s.points[i].x(), s.ranges[i] * std::cos(a), 1e-12);
            EXPECT_NEAR(s.points[i].y(), s.ranges[i] * std::sin(a), 1e-12);
        }
    }
    EXPECT_EQ(total_gaps, 481u);   // every 81.83 "no return" of the excerpt

    const auto &s = scans.front();
    EXPECT_EQ(s.line, 175u);
    EXPECT_DOUBLE_EQ(s.ranges[0], 1.09);
    EXPECT_NEAR(s.points[0].x(), 0.0, 1e-12);   // beam 0 at -90 degrees
    EXPECT_NEAR(s.points[0].y(), -1.09, 1e-12);
    EXPECT_NEAR(s.points[90].x(), 2.63, 1e-12); // beam 90 straight ahead
    EXPECT_NEAR(s.points[90].y(), 0.0, 1e-12);
    EXPECT_DOUBLE_EQ(s.x, 0.600266);
    EXPECT_DOUBLE_EQ(s.y, -0.0320327);
    EXPECT_DOUBLE_EQ(s.theta, -0.354665);
    EXPECT_DOUBLE_EQ(s.timestamp, 32.9068);
    EXPECT_EQ(scans.back().line, 722u);
}

TEST(CarmenLog, CsailExcerpt)
{
    const auto scans = rtl::readCarmenLogFile<double>(data_dir + "/csail.log");
    ASSERT_EQ(scans.size(), 30u);
    size_t total_gaps = 0;
    for (const auto &s : scans)
    {
        ASSERT_EQ(s.points.size(), 361u);
        total_gaps += gaps(s.points);
    }
    EXPECT_EQ(total_gaps, 922u);   // every 81.91 "no return" of the excerpt
    const auto &s = scans.front();
    EXPECT_EQ(s.line, 184u);
    EXPECT_TRUE(s.points[0].hasNaN());          // 81.91: no return
    EXPECT_DOUBLE_EQ(s.ranges[0], 81.91);
    EXPECT_NEAR(s.points[180].x(), 6.08, 1e-12); // 361 beams over 180 degrees: beam 180 straight ahead
    EXPECT_NEAR(s.points[180].y(), 0.0, 1e-12);
    EXPECT_NEAR(s.points[360].x(), 0.0, 1e-12);  // last beam at +90 degrees
    EXPECT_NEAR(s.points[360].y(), 2.12, 1e-12);
    EXPECT_DOUBLE_EQ(s.x, 0.154);
    EXPECT_DOUBLE_EQ(s.theta, 0.562729);
    EXPECT_EQ(scans.back().line, 407u);
}

TEST(CarmenLog, FloatAgreesWithDouble)
{
    const auto d = rtl::readCarmenLogFile<double>(data_dir + "/csail.log");
    const auto f = rtl::readCarmenLogFile<float>(data_dir + "/csail.log");
    ASSERT_EQ(d.size(), f.size());
    for (size_t k = 0; k < d.size(); ++k)
        for (size_t i = 0; i < d[k].points.size(); ++i)
        {
            ASSERT_EQ(d[k].points[i].hasNaN(), f[k].points[i].hasNaN());
            if (!d[k].points[i].hasNaN())
            {
                EXPECT_NEAR(static_cast<double>(f[k].points[i].x()), d[k].points[i].x(), 1e-5);
            }
        }
}

TEST(CarmenLog, MaxRangeAndSkippedRecords)
{
    // CRLF endings, comments, other records, a zero range and an explicit max range of 3 m.
    std::istringstream in("# comment\r\nPARAM robot_front_laser_max 50 1 host 1\r\nODOM 0 0 0 0 0 0 1 host 1\r\n\r\n"
                          "FLASER 4 1 0 3 2.5 0.1 0.2 0.3 0 0 0 12.5 host 12.6\r\nRLASER 1 2 3\r\n");
    const auto scans = rtl::readCarmenLog<float>(in, 3.f);
    ASSERT_EQ(scans.size(), 1u);
    const auto &s = scans[0];
    EXPECT_EQ(s.line, 5u);
    ASSERT_EQ(s.points.size(), 4u);
    EXPECT_FALSE(s.points[0].hasNaN());
    EXPECT_TRUE(s.points[1].hasNaN());      // zero range
    EXPECT_TRUE(s.points[2].hasNaN());      // at max range
    EXPECT_FALSE(s.points[3].hasNaN());
    EXPECT_NEAR(s.points[0].y(), -1.f, 1e-6f);
    EXPECT_NEAR(s.points[3].x(), 2.5f * std::cos(M_PI / 4), 1e-6);   // even n: pi/n steps, beam 3 at +45 degrees
    EXPECT_FLOAT_EQ(s.theta, 0.3f);
    EXPECT_DOUBLE_EQ(s.timestamp, 12.5);
}

TEST(CarmenLog, MalformedLinesNameTheLine)
{
    const std::string head = "# c\nODOM 0 0 0 0 0 0 1 h 1\n";
    auto err = [&](const std::string &bad) {
        return errorOf([&] { std::istringstream in(head + bad + "\n"); rtl::readCarmenLog<double>(in); });
    };
    EXPECT_NE(err("FLASER 3 1 2 0 0 0 0 0 0 1 h 1").find("line 3"), std::string::npos);          // one range short
    EXPECT_NE(err("FLASER 3 1 2 3 0 0 0 0 0 0 1 h 1 9").find("line 3"), std::string::npos);     // one field too many
    EXPECT_NE(err("FLASER 3 1 2x 3 0 0 0 0 0 0 1 h 1").find("range 2"), std::string::npos);
    EXPECT_NE(err("FLASER -3 1 2 3").find("bad beam count"), std::string::npos);
    EXPECT_NE(err("FLASER 0 0 0 0 0 0 0 1 h 1").find("bad beam count"), std::string::npos);
    EXPECT_NE(err("FLASER 99999999999999999999 1").find("line 3"), std::string::npos);
    EXPECT_NE(err("FLASER").find("line 3"), std::string::npos);
    EXPECT_NE(err("FLASER 2 1 2 0 nan? 0 0 0 0 1 h 1").find("bad y"), std::string::npos);
    EXPECT_NE(err("garbage 1 2 3").find("line 3: unknown record"), std::string::npos);
    EXPECT_NE(errorOf([] { rtl::readCarmenLogFile<double>("/nonexistent/x.log"); }).find("/nonexistent/x.log"), std::string::npos);

    std::istringstream empty("");
    EXPECT_TRUE(rtl::readCarmenLog<double>(empty).empty());
}

TEST(OrganizedLidar, RellisExcerpt)
{
    const auto c = rtl::readOrganizedLidarFile<float>(data_dir + "/rellis3d-os1-4x2048.bin", 4);
    ASSERT_EQ(c.beams, 4u);
    ASSERT_EQ(c.columns, 2048u);
    ASSERT_EQ(c.points.size(), 8192u);
    const size_t returns[4] = {895, 1457, 2029, 1984};   // non-zero points of beams 24, 36, 44, 56 of the full scan
    for (size_t b = 0; b < 4; ++b)
    {
        const auto ring = c.ring(b);
        ASSERT_EQ(ring.size(), 2048u);
        size_t valid = 0;
        for (const auto &p : ring) valid += p.hasNaN() ? 0 : 1;
        EXPECT_EQ(valid, returns[b]);
    }
    EXPECT_FLOAT_EQ(c.at(1, 0).x(), 1.372073769569397f);   // record 1 = beam 1 of column 0
    EXPECT_FLOAT_EQ(c.at(1, 0).z(), -0.04841851443052292f);
    EXPECT_FLOAT_EQ(c.at(0, 1).x(), 1.457615852355957f);   // record 4 = beam 0 of column 1
    EXPECT_FLOAT_EQ(c.intensity[c.index(3, 0)], 0.00041199359111487865f);
    EXPECT_TRUE(c.at(0, 1000).hasNaN());                   // record 4000 is (-0, -0, 0): no return
    EXPECT_FLOAT_EQ(c.intensity[4000], 0.00012207217514514923f);
    const auto col = c.column(2047);
    ASSERT_EQ(col.size(), 4u);
    EXPECT_FLOAT_EQ(col[3].z(), -0.28493618965148926f);
    EXPECT_THROW(c.ring(4), std::out_of_range);
    EXPECT_THROW(c.column(2048), std::out_of_range);
    EXPECT_THROW(static_cast<void>(c.index(0, 2048)), std::out_of_range);
}

TEST(OrganizedLidar, RowMajorMatchesColumnMajor)
{
    // 2 beams x 3 columns: point (b, c) = (10b + c, 1, 2), with (beam 1, column 2) all zero.
    std::string col_major, row_major;
    for (int c = 0; c < 3; ++c)
        for (int b = 0; b < 2; ++b)
        {
            if (b == 1 && c == 2) appendRecord(col_major, 0, 0, 0, 7);
            else appendRecord(col_major, 10.f * b + c, 1, 2, 5);
        }
    for (int b = 0; b < 2; ++b)
        for (int c = 0; c < 3; ++c)
        {
            if (b == 1 && c == 2) appendRecord(row_major, 0, 0, 0, 7);
            else appendRecord(row_major, 10.f * b + c, 1, 2, 5);
        }
    std::istringstream ic(col_major), ir(row_major);
    const auto a = rtl::readOrganizedLidar<double>(ic, 2, rtl::OrganizedLayout::ColumnMajor);
    const auto k = rtl::readOrganizedLidar<double>(ir, 2, rtl::OrganizedLayout::RowMajor);
    ASSERT_EQ(a.columns, 3u);
    ASSERT_EQ(k.columns, 3u);
    for (size_t b = 0; b < 2; ++b)
        for (size_t c = 0; c < 3; ++c)
        {
            if (b == 1 && c == 2)
            {
                EXPECT_TRUE(a.at(b, c).hasNaN());
                EXPECT_TRUE(k.at(b, c).hasNaN());
                EXPECT_EQ(k.intensity[k.index(b, c)], 7.0);
                continue;
            }
            EXPECT_EQ(a.at(b, c).x(), 10.0 * b + c);
            EXPECT_EQ(k.at(b, c).x(), 10.0 * b + c);
            EXPECT_EQ(k.at(b, c).z(), 2.0);
        }
}

TEST(OrganizedLidar, BadInputNamesTheByteOffset)
{
    std::string s;
    for (int i = 0; i < 8; ++i) appendRecord(s, 1, 2, 3, 4);
    {
        std::istringstream in(s + "abcde");
        const auto e = errorOf([&] { rtl::readOrganizedLidar<float>(in, 4); });
        EXPECT_NE(e.find("truncated record at byte offset 128"), std::string::npos) << e;
    }
    {
        std::string five = s.substr(0, 5 * 16);
        std::istringstream in(five);
        const auto e = errorOf([&] { rtl::readOrganizedLidar<float>(in, 4); });
        EXPECT_NE(e.find("incomplete column at byte offset 64"), std::string::npos) << e;
        std::istringstream in2(five);
        const auto e2 = errorOf([&] { rtl::readOrganizedLidar<float>(in2, 2, rtl::OrganizedLayout::RowMajor); });
        EXPECT_NE(e2.find("incomplete ring at byte offset 64"), std::string::npos) << e2;
    }
    std::istringstream in(s);
    EXPECT_THROW(rtl::readOrganizedLidar<float>(in, 0), std::invalid_argument);
    std::istringstream empty("");
    const auto c = rtl::readOrganizedLidar<float>(empty, 4);
    EXPECT_EQ(c.columns, 0u);
    EXPECT_TRUE(c.points.empty());
    EXPECT_NE(errorOf([] { rtl::readOrganizedLidarFile<float>("/nonexistent/x.bin", 4); }).find("/nonexistent/x.bin"), std::string::npos);
}
