// Issue 15: pictures beyond TeX's dimensions (16383.99998 pt, about 575 cm; "! Dimension too large"). The TikZ
// writers refuse a picture extent, mark size, border, export size or clip corner beyond 500 cm with
// std::length_error before writing anything, reduce angles beyond +-3600 degrees modulo 360, clamp the scale of 3D
// marks near the camera, and Drawing2D tracks circle/ellipse boxes that overflow float; an axis crossing outside the
// frame is seen and a tiny border has no exponent. Pictures at the limits compile.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iterator>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "rtl/io/LaTeXTikz2D.h"
#include "rtl/io/LaTeXTikz3D.h"
#include "pdflatex_run.h"

namespace fs = std::filesystem;
using rtl::LaTeXTikz2D;
using rtl::LaTeXTikz3D;
using rtl::Vector2f;
using rtl::Vector3f;

namespace
{
    //! A small ordinary drawing: a polyline with robot marks from (0, 0) to (1, 1).
    LaTeXTikz2D drawing()
    {
        LaTeXTikz2D d;
        d.addPlot(std::vector<Vector2f>{Vector2f(0, 0), Vector2f(1, 1)}, "draw=black", "fill=red", LaTeXTikz2D::latex_mark_robot);
        return d;
    }
    //! Writes with `write`; true if it threw the TeX refusal and wrote nothing.
    bool refused(const std::function<void(std::ostream &)> &write)
    {
        std::ostringstream os;
        try
        {
            write(os);
        }
        catch (const std::length_error &e)
        {
            EXPECT_NE(std::string(e.what()).find("beyond TeX's dimensions"), std::string::npos) << e.what();
            EXPECT_EQ(os.str(), "");
            return true;
        }
        return false;
    }
    bool refused2D(const LaTeXTikz2D &d) { return refused([&](std::ostream &os) { rtl::writeTikz(d, os); }); }
    bool refusedPicture2D(const LaTeXTikz2D &d) { return refused([&](std::ostream &os) { rtl::writeTikzPicture(d, os); }); }
    bool refused3D(LaTeXTikz3D &d) { return refused([&](std::ostream &os) { d.writeTEX(os); }); }
    bool refusedPicture3D(LaTeXTikz3D &d) { return refused([&](std::ostream &os) { d.writeTikz(os); }); }
    std::string tikz(LaTeXTikz3D &d)
    {
        std::ostringstream os;
        d.writeTikz(os);
        return os.str();
    }
    LaTeXTikz3D scene()
    {
        LaTeXTikz3D d;
        d.addMark(Vector3f(0, 0, 0), "fill=red", LaTeXTikz3D::latex_mark_robot);
        d.addLine(rtl::LineSegment3f(Vector3f(-1, -1, -1), Vector3f(1, 1, 1)), "draw=black");
        return d;
    }
}

TEST(TikzTexLimits, Drawing2DBeyond500cmIsRefusedBeforeWriting)
{
    EXPECT_FALSE(refused2D(drawing()));
    auto with = [](const std::function<void(LaTeXTikz2D &)> &set) {
        LaTeXTikz2D d = drawing();
        set(d);
        return d;
    };
    // Paper extents: the size (with its 5 % overruns), an axis scale, an absolute overrun.
    EXPECT_FALSE(refused2D(with([](LaTeXTikz2D &d) { d.setSize(450, 450); })));   // 495 cm
    EXPECT_TRUE(refused2D(with([](LaTeXTikz2D &d) { d.setSize(460, 10); })));     // 506 cm
    EXPECT_TRUE(refused2D(with([](LaTeXTikz2D &d) { d.setScaleY(1e6f); })));
    EXPECT_TRUE(refused2D(with([](LaTeXTikz2D &d) { d.setGridAxisOverrun(LaTeXTikz2D::overrun_absolute, 1e38f); })));
    EXPECT_TRUE(refusedPicture2D(with([](LaTeXTikz2D &d) { d.setScaleX(1e6f); })));
    // Marks: the radius, the scale, and their reach at the picture's edge.
    EXPECT_TRUE(refused2D(with([](LaTeXTikz2D &d) { d.setMarkRadius(1e19f); })));
    EXPECT_TRUE(refused2D(with([](LaTeXTikz2D &d) {
        d.addPlot(std::vector<Vector2f>{Vector2f(0.5f, 0.5f)}, "", "fill=blue", LaTeXTikz2D::latex_mark_dot, 1e6f);
    })));
    EXPECT_TRUE(refused2D(with([](LaTeXTikz2D &d) { d.setMarkRadius(300); })));   // 600 cm robot nose
    // The border is the document's: the picture alone is written.
    LaTeXTikz2D b = with([](LaTeXTikz2D &d) { d.setBorder(1e6f); });
    EXPECT_TRUE(refused2D(b));
    EXPECT_FALSE(refusedPicture2D(b));
}

TEST(TikzTexLimits, Scene3DBeyond500cmIsRefusedBeforeWriting)
{
    LaTeXTikz3D ok = scene();
    EXPECT_FALSE(refused3D(ok));
    LaTeXTikz3D big = scene();
    big.setExportSize(600, 10);
    EXPECT_TRUE(refused3D(big));
    EXPECT_TRUE(refusedPicture3D(big));
    LaTeXTikz3D wide = scene();   // 1.1 x 460 cm: lines may reach beyond 500 cm
    wide.setExportSize(460, 10);
    EXPECT_TRUE(refused3D(wide));
    LaTeXTikz3D clip = scene();
    clip.setExportClipping(-1e4f, -1, 1, 1);
    EXPECT_TRUE(refusedPicture3D(clip));
    LaTeXTikz3D mark = scene();
    mark.addMark(Vector3f(1, 0, 0), "fill=blue", LaTeXTikz3D::latex_mark_dot, 0.0f, 1e19f);
    EXPECT_TRUE(refused3D(mark));
    LaTeXTikz3D border = scene();
    border.setBorder(1e6f);
    EXPECT_TRUE(refused3D(border));
    EXPECT_FALSE(refusedPicture3D(border));
}

TEST(TikzTexLimits, AnglesBeyond3600DegreesAreReducedModulo360)
{
    using rtl::detail::number;
    auto deg = [](float radians) { return radians * 180.0 / rtl::detail::pi; };   // as the writer converts
    LaTeXTikz2D d;
    const float rot = 5.2e31f, turns = 4 * static_cast<float>(rtl::detail::pi), b = 1e5f, e = 1e5f - 2 * turns;
    d.addEllipse(Vector2f(0, 0), 2, 1, rot, "draw=black");
    d.addEllipse(Vector2f(0, 0), 2, 1, turns, "draw=black");   // 720 degrees: as before
    d.addPie(Vector2f(0, 0), 1, 0, 1e12f, "fill=red");          // 5.7e13 degrees counter-clockwise
    d.addPie(Vector2f(0, 0), 1, b, e, "fill=blue");             // a start beyond 3600 degrees, a sweep of -1440
    std::ostringstream os;
    rtl::writeTikzPicture(d, os);
    const std::string t = os.str();
    EXPECT_NE(t.find("rotate around={" + number(std::fmod(deg(rot), 360.0)) + ":"), std::string::npos) << t;
    EXPECT_NE(t.find("rotate around={" + number(deg(turns)) + ":"), std::string::npos) << t;
    EXPECT_NE(t.find("arc (0:" + number(std::fmod(deg(1e12f), 360.0)) + ":"), std::string::npos) << t;
    const double start = std::fmod(deg(b), 360.0);
    EXPECT_NE(t.find("arc (" + number(start) + ":" + number(start + (deg(e) - deg(b))) + ":"), std::string::npos) << t;

    LaTeXTikz3D s = scene();
    s.addMark(Vector3f(0.5f, 0, 0), "fill=blue", LaTeXTikz3D::latex_mark_robot, 3e33f);
    EXPECT_NE(tikz(s).find("}{" + number(std::fmod(static_cast<double>(3e33f), 360.0)) + "}{"), std::string::npos) << tikz(s);
}

TEST(TikzTexLimits, MarksNearTheCameraHaveAClampedScale)
{
    // Camera at the origin looking down -z: the mark 1e-3 in front of it would be 50,000 times its size at the
    // centre of the region (depth 50), a 10,000 cm robot.
    LaTeXTikz3D d;
    d.setView(60, rtl::RigidTf3f(0.0f, Vector3f(0, 0, 1), Vector3f(0, 0, 0)));
    d.addMark(Vector3f(0, 0, -1e-3f), "fill=red", LaTeXTikz3D::latex_mark_robot);
    d.addMark(Vector3f(0, 0, -100), "fill=red", LaTeXTikz3D::latex_mark_robot);
    const std::string t = tikz(d);
    EXPECT_NE(t.find("{0}{0}{0}{1000}"), std::string::npos) << t;   // LaTeXTikz3D::max_mark_scale
    EXPECT_NE(t.find("{0}{0}{0}{0.500005}"), std::string::npos) << t;   // the far one as before: 50.0005 / 100
}

TEST(TikzTexLimits, EllipseAndCircleBoxesBeyondFloatAreTracked)
{
    LaTeXTikz2D d;
    d.addEllipse(Vector2f(0, 0), 1e30f, 1, 0.5f, "draw=black");   // its squares overflow float
    EXPECT_GT(d.maxX(), 8e29f);
    EXPECT_LT(d.minY(), -4e29f);
    d.addCircle(Vector2f(3e38f, 0), 3e38f, "draw=black");         // x + r overflows float
    EXPECT_EQ(d.maxX(), std::numeric_limits<float>::max());
    // Both fit the picture: written, and compiled below.
    EXPECT_FALSE(refused2D(d));
}

TEST(TikzTexLimits, PicturesAtTheLimitsCompile)
{
    std::vector<std::string> pictures;
    auto add2D = [&](const LaTeXTikz2D &d) {
        std::ostringstream os;
        rtl::writeTikzPicture(d, os);
        pictures.push_back(os.str());
    };
    LaTeXTikz2D big = drawing();   // 484 cm, robot marks of 2 x 2 cm
    big.setSize(440, 440);
    big.setMarkRadius(2);
    big.addGridH("draw=gray", 0.25f);
    add2D(big);
    LaTeXTikz2D marks = drawing();   // 11 cm of data, robot noses of 240 cm
    marks.setMarkRadius(120);
    add2D(marks);
    LaTeXTikz2D round;
    round.addEllipse(Vector2f(0, 0), 1e30f, 1, 0.5f, "draw=black");
    round.addCircle(Vector2f(3e38f, 0), 3e38f, "draw=black");
    round.addPie(Vector2f(0, 0), 1e30f, 0, 1e12f, "fill=red");
    add2D(round);
    LaTeXTikz3D wide = scene();   // 1.1 x 450 cm
    wide.setExportSize(450, 450);
    wide.addMark(Vector3f(0.9f, 0.9f, 0.9f), "fill=red", LaTeXTikz3D::latex_mark_robot, 3e33f, 4000);
    pictures.push_back(tikz(wide));
    LaTeXTikz3D near;
    near.setExportSize(450, 450);
    near.setView(60, rtl::RigidTf3f(0.0f, Vector3f(0, 0, 1), Vector3f(0, 0, 0)));
    for (float x : {-5e-4f, 0.0f, 5e-4f})   // up to 195 cm from the centre
        near.addMark(Vector3f(x, x, -1e-3f), "fill=red", LaTeXTikz3D::latex_mark_robot, 45);
    near.addMark(Vector3f(0, 0, -100), "fill=red", LaTeXTikz3D::latex_mark_robot);
    pictures.push_back(tikz(near));
    const fs::path dir = fs::path(RTL_TEST_OUTPUT_DIR) / "tikz_tex_limits";
    fs::create_directories(dir);
    pdflatex_test::writePreviewDocument(dir, "limits", pictures);
    const auto run = pdflatex_test::compile(dir, "limits");
    EXPECT_EQ(run.rc, 0) << run.failure();
}

TEST(TikzTexLimits, AnAxisCrossingOutsideTheFrameIsSeen)
{
    // t_tikz_fuzz_sample finding (seed found-axis-crossing-outside-empty-frame): a y axis tracks only its x crossing,
    // so a drawing without y data keeps the unit frame and the axis line was drawn 13,700,000 cm to its left.
    LaTeXTikz2D d;
    d.addAxisY("draw=black", "", LaTeXTikz2D::position_left, 1.0f, -1.37e6f);
    EXPECT_TRUE(refused2D(d));
    LaTeXTikz2D near;   // the same axis 1 unit left of the frame: 10 cm on paper
    near.addAxisY("draw=black", "", LaTeXTikz2D::position_left, 1.0f, -1.0f);
    EXPECT_FALSE(refused2D(near));
}

TEST(TikzTexLimits, ATinyBorderIsWrittenWithoutAnExponent)
{
    // t_tikz_fuzz_sample finding (seed found-border-1e-30-exponent): "\setlength\PreviewBorder{1e-30cm}" is
    // "Illegal unit of measure" (a TeX length has no exponent); below 1e-4 cm the border is written as 0.
    LaTeXTikz2D d = drawing();
    d.setBorder(1e-30f);
    std::ostringstream os;
    rtl::writeTikz(d, os);
    EXPECT_NE(os.str().find("\\setlength\\PreviewBorder{0cm}"), std::string::npos);
    LaTeXTikz3D s = scene();
    s.setBorder(5e-5f);
    std::ostringstream os3;
    s.writeTEX(os3);
    EXPECT_NE(os3.str().find("\\setlength\\PreviewBorder{0cm}"), std::string::npos);
    d.setBorder(2e-4f);   // as before
    std::ostringstream os2;
    rtl::writeTikz(d, os2);
    EXPECT_NE(os2.str().find("\\setlength\\PreviewBorder{0.0002cm}"), std::string::npos);
}

TEST(TikzTexLimits, ARefusedFileWriteLeavesNoFileAndKeepsAnEarlierOne)
{
    const fs::path dir = fs::path(RTL_TEST_OUTPUT_DIR) / "tikz_tex_limits_files";
    fs::remove_all(dir);
    fs::create_directories(dir);
    LaTeXTikz2D big = drawing();
    big.setSize(460, 10);
    LaTeXTikz3D far = scene();
    far.setExportSize(600, 600);
    for (const char *name : {"2d.tex", "3d.tex"})
    {
        const fs::path file = dir / name;
        const auto write = [&] { name[0] == '2' ? big.writeTEX(file.string()) : far.writeTEX(file.string()); };
        EXPECT_THROW(write(), std::length_error) << name;
        EXPECT_FALSE(fs::exists(file)) << name;   // was created empty before the document was refused
        {
            std::ofstream(file) << "earlier";
        }
        EXPECT_THROW(write(), std::length_error) << name;
        std::ifstream in(file);
        const std::string kept((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
        EXPECT_EQ(kept, "earlier") << name;
    }
    // An accepted drawing is still written.
    drawing().writeTEX((dir / "ok.tex").string());
    EXPECT_GT(fs::file_size(dir / "ok.tex"), 100u);
}
