// LaTeXTikz2D on top of the Drawing2D model writes exactly what the writer wrote before the model existed: the
// documents in tests/io/golden/ were captured from the pre-refactoring LaTeXTikz2D for the scenes of tikz2d_scenes.h
// (the package, CLI and README tests depend on this text).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>

#include "rtl/io/LaTeXTikz2D.h"
#include "tikz2d_scenes.h"

namespace
{
    std::string golden(const std::string &name)
    {
        std::filesystem::path p = std::filesystem::path(__FILE__).parent_path() / "golden" / ("tikz2d_" + name + ".tex");
        std::ifstream in(p, std::ios::binary);
        EXPECT_TRUE(in.good()) << p;
        return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
    }

    template<class F>
    void expectGolden(const std::string &name, F draw, unsigned int ax = 0, unsigned int ay = 0)
    {
        rtl::LaTeXTikz2D d(ax, ay);
        draw(d);
        std::ostringstream member, free_function;
        d.writeTEX(member);
        rtl::writeTikz(d, free_function);
        std::string want = golden(name);
        ASSERT_FALSE(want.empty()) << name;
        EXPECT_EQ(member.str(), want) << name;
        EXPECT_EQ(free_function.str(), want) << name;
        EXPECT_EQ(rtl::tikzString(d), want) << name;   // the string form (no stream; the package uses it)
    }
}

TEST(Tikz2DGolden, EveryCallOnLinearAxes) { expectGolden("linear", [](auto &d) { tikz2d_scenes::drawLinear(d); }); }
TEST(Tikz2DGolden, LongPolylineInTheMapFrame)
{
    expectGolden("long_polyline", [](auto &d) { tikz2d_scenes::drawLongPolyline(d); });
}
TEST(Tikz2DGolden, LogAxes) { expectGolden("log", [](auto &d) { tikz2d_scenes::drawLog(d); }, 1, 1); }
TEST(Tikz2DGolden, ClipRegionScalesAndOverrun)
{
    expectGolden("clipped", [](auto &d) { tikz2d_scenes::drawClipped(d); });
}
TEST(Tikz2DGolden, EmptyDrawing) { expectGolden("empty", [](auto &) {}); }
TEST(Tikz2DGolden, ClearDataAndClearAllForgetEverything)
{
    expectGolden("cleared", [](auto &d) {
        tikz2d_scenes::drawLinear(d);
        d.clearData();
        tikz2d_scenes::drawClipped(d);
        d.clearAll();
        d.addCircle(rtl::Vector2f(1, 2), 3.0f, "draw=red");
    });
}

TEST(Tikz2DGolden, TikzPictureIsTheDocumentBody)
{
    rtl::LaTeXTikz2D d;
    tikz2d_scenes::drawLinear(d);
    std::ostringstream pic;
    d.writeTikz(pic);
    std::string doc = golden("linear");
    size_t b = doc.find("\\begin{tikzpicture}"), e = doc.find("\\end{document}");
    ASSERT_NE(b, std::string::npos);
    EXPECT_EQ(pic.str(), doc.substr(b, e - b));
    EXPECT_EQ(rtl::tikzPictureString(d), pic.str());
}
