// Readers for CARMEN logs and organised LiDAR binaries, on the excerpts in tests/data and on crafted bad input.
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iterator>
#include <limits>
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

// ---- the no-return value of a log

namespace
{
    std::string readText(const std::string &path)
    {
        std::ifstream f(path);
        std::ostringstream os;
        os << f.rdbuf();
        return os.str();
    }

    //! The log without its PARAM lines (line numbers of the scans change; their content does not).
    std::string withoutParams(const std::string &text)
    {
        std::istringstream is(text);
        std::string out, line;
        while (std::getline(is, line))
            if (line.rfind("PARAM", 0) != 0)
                out += line + "\n";
        return out;
    }

    //! An aces-like log (Radish "aces": 50.0 means no return, no PARAM lines): 12 scans of 16 beams over 180
    //! degrees, a room with walls 3-49 m away and 5 beams per scan without a return.
    std::string acesLikeLog(const std::string &params = "")
    {
        std::string s = "# aces-like log\n" + params + "ODOM 0 0 0 0 0 0 1 h 1\n";
        for (int k = 0; k < 12; ++k)
        {
            s += "FLASER 16";
            for (int i = 0; i < 16; ++i)
            {
                if (i % 3 == 1 && i < 15)
                    s += " 50.0";
                else
                {
                    char buf[32];
                    std::snprintf(buf, sizeof buf, " %.2f", 3.0 + 0.37 * i + 0.11 * k + (i == 9 ? 41.5 : 0.0));
                    s += buf;
                }
            }
            s += " 1.5 2.5 0.1 1.5 2.5 0.1 " + std::to_string(100 + k) + ".25 aces " + std::to_string(100 + k) + ".5\n";
        }
        return s;
    }

    size_t gapsOf(const std::vector<rtl::CarmenScan<double>> &scans)
    {
        size_t n = 0;
        for (const auto &s : scans) n += gaps(s.points);
        return n;
    }
}

TEST(CarmenNoReturn, IntelIsDetectedFromTheRecurringMaximum)
{
    const auto log = rtl::readCarmenLogFileDetailed<double>(data_dir + "/intel.log");
    EXPECT_EQ(log.max_range_source, rtl::CarmenMaxRangeSource::Recurring);   // intel.log has no max-range PARAM
    EXPECT_DOUBLE_EQ(log.max_range, 81.83);
    EXPECT_EQ(log.no_return_beams, 481u);
    EXPECT_EQ(gapsOf(log.scans), 481u);
    for (const auto &s : log.scans) EXPECT_DOUBLE_EQ(s.max_range, 81.83);
    const auto f = rtl::readCarmenLogFileDetailed<float>(data_dir + "/intel.log");
    EXPECT_FLOAT_EQ(f.max_range, 81.83f);
    EXPECT_EQ(f.no_return_beams, 481u);
}

TEST(CarmenNoReturn, CsailIsDetectedFromItsParameterOrItsRecurringMaximum)
{
    const std::string text = readText(data_dir + "/csail.log");
    std::istringstream in(text);
    const auto log = rtl::readCarmenLogDetailed<double>(in);
    EXPECT_EQ(log.max_range_source, rtl::CarmenMaxRangeSource::Parameter);
    EXPECT_EQ(log.max_range_parameter, "robot_front_laser_max");
    EXPECT_EQ(log.max_range_line, 12u);
    EXPECT_DOUBLE_EQ(log.max_range, 50.0);
    EXPECT_EQ(log.no_return_beams, 922u);   // every 81.91; no return lies in [50, 81.91)
    EXPECT_EQ(gapsOf(log.scans), 922u);
    std::istringstream bare(withoutParams(text));   // without parameters the 81.91 recurs
    const auto b = rtl::readCarmenLogDetailed<double>(bare);
    EXPECT_EQ(b.max_range_source, rtl::CarmenMaxRangeSource::Recurring);
    EXPECT_DOUBLE_EQ(b.max_range, 81.91);
    EXPECT_EQ(b.no_return_beams, 922u);
    ASSERT_EQ(b.scans.size(), log.scans.size());
    for (size_t k = 0; k < b.scans.size(); ++k)
        for (size_t i = 0; i < b.scans[k].points.size(); ++i)
            ASSERT_EQ(b.scans[k].points[i].hasNaN(), log.scans[k].points[i].hasNaN());
}

TEST(CarmenNoReturn, AcesLikeFiftyMetresAreGapsByDefault)
{
    std::istringstream in(acesLikeLog());
    const auto scans = rtl::readCarmenLog<double>(in);
    ASSERT_EQ(scans.size(), 12u);
    EXPECT_EQ(gapsOf(scans), 12u * 5u);   // the five 50.0 beams of each scan; the 47.8-49.0 m return stays a point
    for (const auto &s : scans)
    {
        EXPECT_DOUBLE_EQ(s.max_range, 50.0);
        for (size_t i = 0; i < 16; ++i) EXPECT_EQ(s.points[i].hasNaN(), s.ranges[i] == 50.0) << i;
        EXPECT_GT(s.ranges[9], 47.0);
        EXPECT_FALSE(s.points[9].hasNaN());
    }
    std::istringstream in2(acesLikeLog());
    const auto log = rtl::readCarmenLogDetailed<double>(in2);
    EXPECT_EQ(log.max_range_source, rtl::CarmenMaxRangeSource::Recurring);
    EXPECT_EQ(log.no_return_beams, 60u);

    // An explicit max range overrides the detection: 60 m keeps the 50.0 beams as points.
    std::istringstream in3(acesLikeLog());
    const auto kept = rtl::readCarmenLog<double>(in3, 60.0);
    EXPECT_EQ(gapsOf(kept), 0u);
    EXPECT_DOUBLE_EQ(kept[0].max_range, 60.0);
    rtl::CarmenOptions o;
    o.max_range = 45;   // and 45 m drops the 47.8-49.0 m return too
    std::istringstream in4(acesLikeLog());
    const auto cut = rtl::readCarmenLogDetailed<double>(in4, o);
    EXPECT_EQ(cut.max_range_source, rtl::CarmenMaxRangeSource::Explicit);
    EXPECT_EQ(gapsOf(cut.scans), 12u * 6u);
    std::istringstream in5(acesLikeLog());
    EXPECT_EQ(gapsOf(rtl::readCarmenLog<double>(in5, std::nan(""))), 60u);   // NaN: detect
}

TEST(CarmenNoReturn, ParametersAndTheirLimits)
{
    // A parameter of 40 m: ranges >= 40 are gaps (the 47.8-49.0 m return too).
    std::istringstream a(acesLikeLog("PARAM robot_front_laser_max 40 1 h 1\n"));
    const auto pa = rtl::readCarmenLogDetailed<double>(a);
    EXPECT_EQ(pa.max_range_source, rtl::CarmenMaxRangeSource::Parameter);
    EXPECT_EQ(pa.max_range_line, 2u);
    EXPECT_EQ(gapsOf(pa.scans), 72u);
    // A parameter above the recurring maximum: the recurring 50.0 still means no return.
    std::istringstream b(acesLikeLog("PARAM laser_front_laser_max_range 80\n"));
    const auto pb = rtl::readCarmenLogDetailed<double>(b);
    EXPECT_EQ(pb.max_range_source, rtl::CarmenMaxRangeSource::Recurring);
    EXPECT_DOUBLE_EQ(pb.max_range, 50.0);
    // A glitch above the no-return value does not hide it (it is a gap too).
    std::istringstream glitch(acesLikeLog() + "FLASER 3 900.5 2 3 0 0 0 0 0 0 200 aces 200\n");
    const auto pg = rtl::readCarmenLogDetailed<double>(glitch);
    EXPECT_EQ(pg.max_range_source, rtl::CarmenMaxRangeSource::Recurring);
    EXPECT_DOUBLE_EQ(pg.max_range, 50.0);
    EXPECT_EQ(pg.no_return_beams, 61u);
    EXPECT_EQ(gapsOf(pg.scans), 61u);
    EXPECT_EQ(rtl::carmenRecurringMaxRange(pg.scans).second, 60u);
    // An unusable value leaves the parameter unused; the first usable one counts.
    std::istringstream c(acesLikeLog("PARAM robot_front_laser_max abc 1 h 1\nPARAM robot_front_laser_max -5\n"
                                     "PARAM robot_front_laser_max 30\nPARAM robot_front_laser_max 20\n"));
    const auto pc = rtl::readCarmenLogDetailed<double>(c);
    EXPECT_EQ(pc.max_range_line, 4u);
    EXPECT_DOUBLE_EQ(pc.max_range, 30.0);
    // A parameter that rounds to 0 in float is unusable (found by fuzz_carmen_log), as is such an explicit value.
    const std::string tiny_param = acesLikeLog("PARAM robot_front_laser_max 1e-320\n");
    std::istringstream td(tiny_param), tf(tiny_param);
    EXPECT_EQ(rtl::readCarmenLogDetailed<double>(td).max_range_source, rtl::CarmenMaxRangeSource::Parameter);
    const auto pt = rtl::readCarmenLogDetailed<float>(tf);
    EXPECT_EQ(pt.max_range_source, rtl::CarmenMaxRangeSource::Recurring);
    EXPECT_FLOAT_EQ(pt.max_range, 50.f);
    rtl::CarmenOptions tiny;
    tiny.max_range = 1e-320;
    std::istringstream te(tiny_param);
    EXPECT_THROW(rtl::readCarmenLogDetailed<float>(te, tiny), std::invalid_argument);
    // No evidence (every range distinct, no parameter): 80 m, the former default.
    std::istringstream d("FLASER 4 1 2 85 3 0 0 0 0 0 0 1 h 1\nFLASER 4 1.5 2.5 79 3.5 0 0 0 0 0 0 2 h 2\n");
    const auto pd = rtl::readCarmenLogDetailed<double>(d);
    EXPECT_EQ(pd.max_range_source, rtl::CarmenMaxRangeSource::Default);
    EXPECT_DOUBLE_EQ(pd.max_range, 80.0);
    EXPECT_TRUE(pd.scans[0].points[2].hasNaN());
    EXPECT_FALSE(pd.scans[1].points[2].hasNaN());
    // A maximum hit by many beams but no more often than a value below it is a real return, not "no return".
    std::istringstream e("FLASER 8 6 6 6 6 7 7 7 7 0 0 0 0 0 0 1 h 1\n");
    const auto pe = rtl::readCarmenLogDetailed<double>(e);
    EXPECT_EQ(pe.max_range_source, rtl::CarmenMaxRangeSource::Default);
    EXPECT_EQ(gapsOf(pe.scans), 0u);
    // Explicit max ranges must be positive.
    std::istringstream f("");
    EXPECT_THROW(rtl::readCarmenLog<double>(f, 0.0), std::invalid_argument);
    rtl::CarmenOptions neg;
    neg.max_range = -1;
    EXPECT_THROW(rtl::readCarmenLogDetailed<float>(f, neg), std::invalid_argument);
    std::istringstream g("FLASER 2 1 1e300 0 0 0 0 0 0 1 h 1\n");   // +inf as max range keeps every finite range
    rtl::CarmenOptions all;
    all.max_range = INFINITY;
    EXPECT_EQ(gapsOf(rtl::readCarmenLogDetailed<double>(g, all).scans), 0u);
}

TEST(CarmenNoReturn, NonFinitePosesAndTimestampsAreRejectedNamingTheLine)
{
    const std::string head = "# c\nODOM 0 0 0 0 0 0 1 h 1\n";
    auto err = [&](const std::string &bad) {
        return errorOf([&] { std::istringstream in(head + bad + "\n"); rtl::readCarmenLog<double>(in); });
    };
    EXPECT_NE(err("FLASER 2 1 1 nan 0 0 0 0 0 1 h 2").find("line 3: non-finite x 'nan'"), std::string::npos);
    EXPECT_NE(err("FLASER 2 1 1 0 -inf 0 0 0 0 1 h 2").find("line 3: non-finite y '-inf'"), std::string::npos);
    EXPECT_NE(err("FLASER 2 1 1 0 0 NaN 0 0 0 1 h 2").find("line 3: non-finite theta 'NaN'"), std::string::npos);
    EXPECT_NE(err("FLASER 2 1 1 0 0 0 inf 0 0 1 h 2").find("line 3: non-finite odom_x"), std::string::npos);
    EXPECT_NE(err("FLASER 2 1 1 0 0 0 0 0 0 infinity h 2").find("line 3: non-finite ipc_timestamp 'infinity'"),
              std::string::npos);
    EXPECT_NE(err("FLASER 2 1 1 0 0 0 0 0 0 1 h nan").find("line 3: non-finite logger_timestamp 'nan'"),
              std::string::npos);
    // float: a pose beyond float's range is rejected too; a range beyond it is a gap.
    std::istringstream big("FLASER 2 1 1 1e300 0 0 0 0 0 1 h 2\n");
    EXPECT_NE(errorOf([&] { rtl::readCarmenLog<float>(big); }).find("line 1"), std::string::npos);
    std::istringstream far("FLASER 2 1 1e300 0 0 0 0 0 0 1 h 2\n");
    const auto s = rtl::readCarmenLog<float>(far);
    EXPECT_TRUE(s[0].points[1].hasNaN());
    EXPECT_FALSE(s[0].points[0].hasNaN());
    // A range that rounds to 0 in float is a gap, not a point at the origin (found by fuzz_carmen_log).
    std::istringstream tiny("FLASER 3 1e-320 1e-30 2 0 0 0 0 0 0 1 h 2\n");
    const auto t = rtl::readCarmenLog<float>(tiny);
    EXPECT_EQ(t[0].ranges[0], 0.f);
    EXPECT_TRUE(t[0].points[0].hasNaN());
    EXPECT_FALSE(t[0].points[1].hasNaN());   // 1e-30 is a float: a point at 1e-30 m
    EXPECT_FALSE(t[0].points[2].hasNaN());
    // Non-finite ranges stay gaps, not errors.
    std::istringstream inf_range("FLASER 3 inf nan 2 0 0 0 0 0 0 1 h 2\n");
    const auto r = rtl::readCarmenLog<double>(inf_range);
    EXPECT_TRUE(r[0].points[0].hasNaN());
    EXPECT_TRUE(r[0].points[1].hasNaN());
    EXPECT_FALSE(r[0].points[2].hasNaN());
}

TEST(CarmenNoReturn, BeamCountNearSizeMaxIsAnErrorNotAnAllocation)
{
    // n + 11 wraps around to 2 for n = SIZE_MAX - 8: the field count check must not pass it.
    const std::string n = std::to_string(std::numeric_limits<size_t>::max() - 8);
    std::istringstream in("FLASER " + n + "\n");
    const auto e = errorOf([&] { rtl::readCarmenLog<double>(in); });
    EXPECT_NE(e.find("line 1: FLASER with " + n + " beams needs " + n + " + 11 fields, found 2"), std::string::npos) << e;
    std::istringstream in2("FLASER " + std::to_string(std::numeric_limits<size_t>::max() - 9) + " 1\n");
    EXPECT_NE(errorOf([&] { rtl::readCarmenLog<double>(in2); }).find("line 1: FLASER with"), std::string::npos);
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

// Issue 15.4: the reader promises std::runtime_error for malformed logs. Huge or wrapped beam counts, counts beyond
// size_t, and non-finite poses or timestamps all end in a std::runtime_error naming the line, never in
// std::length_error or std::bad_alloc from a resize sized by the log.
TEST(CarmenNoReturn, OnlyRuntimeErrorForHugeCountsAndNonFiniteFields)
{
    const std::string max = std::to_string(std::numeric_limits<size_t>::max());
    const std::vector<std::string> bad = {
        "FLASER 18446744073709551610 5 1 1",                 // the first reported input (n + 11 wraps to 5)
        "FLASER 18446744073709551605 0 0 0 0 0 0 0 0 0",     // n + 11 wraps to 0: exactly as many fields as n + 11
        "FLASER " + max,
        "FLASER " + max + " 1 2 3 4 5 6 7 8 9",
        "FLASER 18446744073709551616 1 1 0 0 0 0 0 0 1 h 1", // beyond size_t
        "FLASER 99999999999999999999999 1",
        "FLASER 4611686018427387904 1 2 3",                  // 2^62: resize would be a length_error
        "FLASER -1 1 0 0 0 0 0 0 1 h 1",
        "FLASER 2 1 1 0 0 0 0 0 0 nan h 1",
        "FLASER 2 1 1 inf 0 0 0 0 0 1 h 1",
        "FLASER 2 1 1 0 0 1e999 0 0 0 1 h 1",                // overflows to inf when parsed
        "FLASER 2 1 1 0 0 0 0 0 -nan 1 h 1",
    };
    for (const std::string &line : bad)
        for (int as_float = 0; as_float < 2; ++as_float)
        {
            std::istringstream in("PARAM robot_front_laser_max 50\n" + line + "\n");
            bool runtime = false;
            std::string what;
            try
            {
                if (as_float) rtl::readCarmenLog<float>(in);
                else rtl::readCarmenLog<double>(in);
            }
            catch (const std::runtime_error &e)
            {
                runtime = true;
                what = e.what();
            }
            catch (const std::exception &e)
            {
                what = std::string("other exception: ") + e.what();
            }
            EXPECT_TRUE(runtime) << line << ": " << what;
            EXPECT_EQ(what.rfind("CARMEN log, line 2: ", 0), 0u) << line << ": " << what;
        }
}

// The organised reader has no header: every allocation is bounded by the bytes read, whatever `beams` says, and
// bad input gives std::runtime_error (std::invalid_argument only for beams == 0, as documented).
TEST(OrganizedLidar, HugeBeamCountsAllocateNothingAndThrowRuntimeError)
{
    std::string s;
    for (int i = 0; i < 3; ++i) appendRecord(s, 1, 2, 3, 4);
    for (size_t beams : {size_t(2), size_t(1) << 40, std::numeric_limits<size_t>::max()})
    {
        std::istringstream in(s);
        EXPECT_THROW(rtl::readOrganizedLidar<float>(in, beams), std::runtime_error) << beams;
        std::istringstream in2(s);
        EXPECT_THROW(rtl::readOrganizedLidar<double>(in2, beams, rtl::OrganizedLayout::RowMajor), std::runtime_error) << beams;
    }
    std::istringstream empty("");
    EXPECT_EQ(rtl::readOrganizedLidar<float>(empty, std::numeric_limits<size_t>::max()).points.size(), 0u);
    // Non-finite coordinates are kept as logged (NaN and inf are gaps for the segmenters), not an error.
    std::string odd;
    appendRecord(odd, std::numeric_limits<float>::infinity(), 0, 0, std::nanf(""));
    appendRecord(odd, std::nanf(""), 1, 1, 1);
    std::istringstream in(odd);
    const auto c = rtl::readOrganizedLidar<float>(in, 2);
    EXPECT_TRUE(std::isinf(c.at(0, 0).x()));
    EXPECT_TRUE(std::isnan(c.intensity[0]));
    EXPECT_TRUE(std::isnan(c.at(1, 0).x()));
}

namespace
{
    std::string fileText(const std::string &path)
    {
        std::ifstream f(path, std::ios::binary);
        return {std::istreambuf_iterator<char>(f), std::istreambuf_iterator<char>()};
    }

    // The whole result of readCarmenLogDetailed, or its error message, as one comparable string.
    template<typename E, typename Read>
    std::string carmenResult(Read &&read)
    {
        std::string out;
        try
        {
            const rtl::CarmenLog<E> log = read();
            out = "max " + std::to_string(log.max_range) + " source " + std::to_string(int(log.max_range_source)) + " " +
                  log.max_range_parameter + " line " + std::to_string(log.max_range_line) + " no-return " +
                  std::to_string(log.no_return_beams) + "\n";
            for (const auto &s : log.scans)
            {
                out += std::to_string(s.line) + " " + std::to_string(s.x) + " " + std::to_string(s.y) + " " +
                       std::to_string(s.theta) + " " + std::to_string(s.timestamp) + ":";
                char buf[64];
                for (size_t i = 0; i < s.ranges.size(); ++i)
                {
                    std::snprintf(buf, sizeof buf, " %a %a,%a", double(s.ranges[i]), double(s.points[i].x()),
                                  double(s.points[i].y()));
                    out += buf;
                }
                out += "\n";
            }
        }
        catch (const std::exception &e)
        {
            out = std::string("error: ") + e.what();
        }
        return out;
    }
}

// The package reads logs and clouds from memory, without streams (readCarmenLogTextDetailed,
// readOrganizedLidarBytes): the same scans, detection and errors as the stream readers on the same bytes.
TEST(InMemoryReaders, CarmenTextEqualsTheStreamReader)
{
    const std::string flaser = "FLASER 3 1.0 2.0 3.0 0.5 0.25 0.1 0 0 0 12.5 host 12.6";
    std::vector<std::string> texts = {fileText(data_dir + "/intel.log"), fileText(data_dir + "/csail.log"), "", "\n",
                                      flaser, flaser + "\n", flaser + "\r\n\n\n" + flaser, "\n\n" + flaser + "\n\n",
                                      "# comment\n" + flaser + "\nBOGUS 1\n", flaser + "\nFLASER 2 1 2 3\n",
                                      "PARAM robot_front_laser_max 2.5\n" + flaser + "\n" + flaser,
                                      flaser + std::string("\0", 1) + "\n", flaser + "\nFLASER 3 1 2 nan 0 0 0 0 0 0 1 h 1"};
    ASSERT_GT(texts[0].size(), 1000u);
    ASSERT_GT(texts[1].size(), 1000u);
    for (const double max_range : {std::nan(""), 2.0, -1.0})
        for (const auto &t : texts)
        {
            rtl::CarmenOptions o;
            o.max_range = max_range;
            const std::string from_stream = carmenResult<double>([&] {
                std::istringstream in(t);
                return rtl::readCarmenLogDetailed<double>(in, o);
            });
            EXPECT_EQ(carmenResult<double>([&] { return rtl::readCarmenLogTextDetailed<double>(t, o); }), from_stream)
                    << t.substr(0, 200);
            EXPECT_EQ(carmenResult<float>([&] { return rtl::readCarmenLogTextDetailed<float>(t, o); }),
                      carmenResult<float>([&] {
                          std::istringstream in(t);
                          return rtl::readCarmenLogDetailed<float>(in, o);
                      }));
        }
    // (the comparison can fail: the error names the line, and the intel excerpt has scans)
    EXPECT_NE(carmenResult<double>([&] { return rtl::readCarmenLogTextDetailed<double>(texts[9]); }).find("line 2"),
              std::string::npos);
    EXPECT_GT(rtl::readCarmenLogTextDetailed<double>(texts[0]).scans.size(), 10u);
}

TEST(InMemoryReaders, OrganizedBytesEqualTheStreamReader)
{
    std::vector<std::string> inputs = {fileText(data_dir + "/rellis3d-os1-4x2048.bin"), ""};
    std::string small;
    for (int k = 0; k < 8; ++k) appendRecord(small, k == 3 ? 0.f : float(k), float(-k), 0.5f * float(k), float(k * k));
    inputs.push_back(small);
    inputs.push_back(small.substr(0, 17));   // truncated record
    inputs.push_back(small.substr(0, 48));   // incomplete column of 4 / ring of 2... of 3 records
    for (const auto &bytes : inputs)
        for (const size_t beams : {size_t(0), size_t(1), size_t(2), size_t(4), size_t(3)})
            for (const auto layout : {rtl::OrganizedLayout::ColumnMajor, rtl::OrganizedLayout::RowMajor})
            {
                auto describe = [](auto &&read) {
                    try
                    {
                        const auto c = read();
                        std::string s = std::to_string(c.beams) + "x" + std::to_string(c.columns);
                        char buf[96];
                        for (size_t i = 0; i < c.points.size(); ++i)
                        {
                            std::snprintf(buf, sizeof buf, " %a,%a,%a,%a", double(c.points[i].x()), double(c.points[i].y()),
                                          double(c.points[i].z()), double(c.intensity[i]));
                            s += buf;
                        }
                        return s;
                    }
                    catch (const std::exception &e)
                    {
                        return std::string("error: ") + e.what();
                    }
                };
                const std::string from_stream = describe([&] {
                    std::istringstream in(bytes);
                    return rtl::readOrganizedLidar<float>(in, beams, layout);
                });
                EXPECT_EQ(describe([&] {
                              return rtl::readOrganizedLidarBytes<float>(
                                      reinterpret_cast<const unsigned char *>(bytes.data()), bytes.size(), beams, layout);
                          }),
                          from_stream)
                        << bytes.size() << " bytes, " << beams << " beams";
            }
}
