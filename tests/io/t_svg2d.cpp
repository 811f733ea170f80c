// Svg2D / writeSvg: the SVG back-end of Drawing2D. One drawing is written both ways; the SVG is well-formed XML
// (checked by xml_check.h) with the primitives, marks, grids, axes, clip region and escaped text of the TikZ output,
// at the positions the frame gives.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <regex>
#include <sstream>
#include <string>

#include "rtl/io/LaTeXTikz2D.h"
#include "rtl/io/Svg2D.h"
#include "tikz2d_scenes.h"
#include "xml_check.h"

using rtl::Vector2f;

namespace
{
    std::string svg(const rtl::Drawing2D &d)
    {
        std::ostringstream os;
        rtl::writeSvg(d, os);
        return os.str();
    }
    std::string golden(const std::string &name)
    {
        std::ifstream in(std::filesystem::path(__FILE__).parent_path() / "golden" / ("tikz2d_" + name + ".tex"));
        return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
    }
    //! The numeric value of attribute `name` in the first element matching `element_regex`.
    double attribute(const std::string &doc, const std::string &element_regex, const std::string &name)
    {
        std::smatch m;
        std::regex e("<" + element_regex + "[^>]*\\s" + name + "=\"([-0-9.e]+)\"");
        if (!std::regex_search(doc, m, e))
            return -1e300;
        return std::stod(m[1]);
    }
}

TEST(Svg2D, OneDrawingWrittenAsTikzAndSvg)
{
    rtl::Svg2D d;
    tikz2d_scenes::drawLinear(d);
    std::ostringstream tikz;
    rtl::writeTikz(d, tikz);
    EXPECT_EQ(tikz.str(), golden("linear"));   // the same model gives LaTeXTikz2D's text
    EXPECT_EQ(rtl::tikzString(d), tikz.str());
    std::string s = svg(d);
    EXPECT_EQ(rtl::svgString(d), s);   // the string form (no stream; the package uses it)
    xml_check::Result r = xml_check::check(s);
    ASSERT_TRUE(r.ok) << r.error;
    EXPECT_EQ(r.elements["svg"], 1u);
    // 12 + 4 x 6 finite points with marks; 1 + 2 polyline runs (the NaNs break the second plot into 2, 3, 1 points).
    EXPECT_EQ(r.elements["use"], 36u);
    EXPECT_EQ(r.elements["polyline"], 3u);
    EXPECT_EQ(r.elements["polygon"], 2u);     // triangle, quadrilateral
    EXPECT_EQ(r.elements["rect"], 1u);
    EXPECT_EQ(r.elements["ellipse"], 3u);     // two circles, one ellipse
    EXPECT_EQ(r.elements["path"], 1u + 1u);   // the pie and the arrow marker's tip
    EXPECT_EQ(r.elements["marker"], 1u);
    // Texts: 2 nodes + 2 descriptions + tick labels (x: 0, 2, 4, 6 every 2 in [-1.8, 6.5]; y: -1 ... 5).
    EXPECT_EQ(r.elements["text"], 2u + 2u + 4u + 7u);
    // Marks defined once each: cross, dot, robot, mark, the user template.
    for (const char *id : {"MarkA", "MarkB", "MarkC", "MarkD", "MarkE"})
        EXPECT_NE(s.find(std::string("<g id=\"") + id + "\">"), std::string::npos) << id;
    EXPECT_NE(s.find("label: 5% &amp; $x_1$ {a} #2 ~ ^ \\ &lt;b&gt;"), std::string::npos);
    EXPECT_NE(s.find("x in m &amp; 50% of $#_{}~^\\&lt;&gt;"), std::string::npos);
    // Colours: ColorA = {rgb}{1,0,0}, named orange, gray!30 (30 % gray 0.5, 70 % white: 0.85), dotted and opacity keys.
    EXPECT_NE(s.find("stroke=\"#ff0000\" fill=\"none\" stroke-width=\"0.0281"), std::string::npos);
    EXPECT_NE(s.find("stroke=\"#ff8000\" fill=\"none\" stroke-width=\"0.0140"), std::string::npos);
    EXPECT_NE(s.find("stroke=\"#d9d9d9\""), std::string::npos);
    EXPECT_NE(s.find("opacity=\"0.5\""), std::string::npos);
    EXPECT_NE(s.find("stroke-dasharray="), std::string::npos);
}

TEST(Svg2D, SizeViewBoxAndPositionsFollowTheFrame)
{
    rtl::Svg2D d;
    d.setSize(10, 6);
    d.setBorder(0);
    d.setMarkRadius(0);
    d.addRectangle(Vector2f(-1, -1), Vector2f(1, 2), "draw=blue");
    d.addCircle(Vector2f(0, 0), 0.5f, "fill=red");
    std::string s = svg(d);
    ASSERT_TRUE(xml_check::check(s).ok) << xml_check::check(s).error;
    // Frame [-1, 1] x [-1, 2] -> 10 x 6 cm: sx = 5, sy = 2 cm per unit; no margin without border, marks or labels.
    EXPECT_NE(s.find("width=\"10cm\" height=\"6cm\" viewBox=\"0 0 10 6\""), std::string::npos) << s;
    EXPECT_NEAR(attribute(s, "rect", "x"), 0.0, 1e-9);
    EXPECT_NEAR(attribute(s, "rect", "y"), 0.0, 1e-9);
    EXPECT_NEAR(attribute(s, "rect", "width"), 10.0, 1e-9);
    EXPECT_NEAR(attribute(s, "rect", "height"), 6.0, 1e-9);
    EXPECT_NEAR(attribute(s, "ellipse", "cx"), 5.0, 1e-9);
    EXPECT_NEAR(attribute(s, "ellipse", "cy"), 4.0, 1e-9);   // y = 0 is 2 units below the top (y = 2)
    EXPECT_NEAR(attribute(s, "ellipse", "rx"), 2.5, 1e-9);
    EXPECT_NEAR(attribute(s, "ellipse", "ry"), 1.0, 1e-9);
    EXPECT_NE(s.find("fill=\"#ff0000\""), std::string::npos);
}

// Regression: a title placed above the data (anchor=south at the top edge, as the package's scan pictures do) was cut
// off at the top of the viewBox, and a one-line scan lost it entirely.
TEST(Svg2D, TextBeyondTheDataGetsRoomInTheViewBox)
{
    rtl::Svg2D d;
    d.setSize(10, 6);
    d.setBorder(0);
    d.setMarkRadius(0);
    d.addLine(Vector2f(0, 0), Vector2f(4, 0), "draw=black");   // a flat picture: zero height
    const std::string title = "scan 5 of intel.log, CAR step 2";
    d.addText(title, "anchor=south", Vector2f(2, 0));
    d.addText("right edge label", "anchor=west", Vector2f(4, 0));
    std::string s = svg(d);
    ASSERT_TRUE(xml_check::check(s).ok) << xml_check::check(s).error;
    std::smatch m;
    ASSERT_TRUE(std::regex_search(s, m, std::regex("viewBox=\"0 0 ([-0-9.e]+) ([-0-9.e]+)\"")));
    const double w = std::stod(m[1]), h = std::stod(m[2]);
    ASSERT_TRUE(std::regex_search(s, m, std::regex(R"(<g transform="translate\(([-0-9.e]+),([-0-9.e]+)\))")));
    const double tx = std::stod(m[1]), ty = std::stod(m[2]);
    // The title's baseline sits on the data's top edge (y = 0 inside the group): a 10 pt line above it fits.
    EXPECT_GE(ty, 1.25 * 0.3514 - 1e-4) << s;   // numbers are written with 6 digits
    EXPECT_GE(h, 1.25 * 0.3514 - 1e-4);
    // The label starts at the right end of the data (x = 10 cm) and its characters fit to the right of it.
    EXPECT_GE(w - tx - 10.0, 0.6 * 0.3514 * 16 - 1e-4) << s;
    EXPECT_NEAR(tx, 0.0, 1e-9);   // nothing reaches left: no padding there without a border
}

TEST(Svg2D, ClipRegionIsAClipPath)
{
    rtl::Svg2D d;
    tikz2d_scenes::drawClipped(d);
    std::string s = svg(d);
    xml_check::Result r = xml_check::check(s);
    ASSERT_TRUE(r.ok) << r.error;
    EXPECT_EQ(r.elements["clipPath"], 1u);
    EXPECT_NE(s.find("<g clip-path=\"url(#clip)\">"), std::string::npos);
    // Clip [-2, 2] x [-3, 3] at 6 x 4 cm, times the user scales 2 and 0.5: 12 x 2 cm.
    EXPECT_NEAR(attribute(s, "clipPath[^>]*><rect", "width"), 12.0, 1e-4);
    EXPECT_NEAR(attribute(s, "clipPath[^>]*><rect", "height"), 2.0, 1e-4);
}

TEST(Svg2D, LogAxesAndLabelsWithExponents)
{
    rtl::Svg2D d(rtl::Svg2D::axis_type_log10, rtl::Svg2D::axis_type_log10);
    tikz2d_scenes::drawLog(d);
    std::string s = svg(d);
    xml_check::Result r = xml_check::check(s);
    ASSERT_TRUE(r.ok) << r.error;
    // "%.0e" labels become 10 with a raised exponent.
    EXPECT_NE(s.find("10<tspan baseline-shift=\"super\" font-size=\"0.25\">3</tspan>"), std::string::npos);

    // A label hung below its x tick starts 0.1 cm below the tick's end, so its raised exponent clears the tick
    // (in the paper's speed figure "10" + "3" read as "+3" where the exponent touched the tick).
    std::regex label("<text x=\"([-0-9.e]+)\" y=\"([-0-9.e]+)\" text-anchor=\"middle\" dominant-baseline=\"hanging\""
                     "[^>]*>10<tspan");
    size_t labels = 0;
    for (std::sregex_iterator m(s.begin(), s.end(), label), end; m != end; ++m, ++labels)
    {
        std::string x = (*m)[1];
        // The tick: the 0.1 cm line at the label's x (the grid line there spans the picture).
        std::regex line("<line x1=\"" + x + "\" y1=\"([-0-9.e]+)\" x2=\"" + x + "\" y2=\"([-0-9.e]+)\"");
        double tick_end = std::nan("");
        for (std::sregex_iterator t(s.begin(), s.end(), line); t != end; ++t)
            if (std::abs(std::stod((*t)[2]) - std::stod((*t)[1]) - 0.1) < 1e-6)
                tick_end = std::stod((*t)[2]);
        ASSERT_FALSE(std::isnan(tick_end)) << "no tick at x = " << x;
        EXPECT_NEAR(std::stod((*m)[2]) - tick_end, 0.1, 1e-4) << "label at x = " << x;
    }
    EXPECT_GE(labels, 5u);
}

TEST(Svg2D, HostileTextStaysWellFormed)
{
    rtl::Svg2D d;
    std::string hostile = "a<b>&\"'\x01\x7f\x1b[0m]]>\xff\xc3(\xe2\x82 \xed\xa0\x80 </text><!-- caf\xc3\xa9 \xe2\x82\xac";
    d.addText(hostile, "anchor=north", Vector2f(0, 0));
    d.addText("&amp; stays literal", "", Vector2f(1, 1));
    d.addDescriptionX(hostile);
    d.addDescriptionY(std::string("\x02y\x03\x00", 4));
    d.addAxisX("draw=black", "100%% &#x %d", rtl::Svg2D::position_below, 1.0f);
    std::string s = svg(d);
    xml_check::Result r = xml_check::check(s);
    ASSERT_TRUE(r.ok) << r.error << "\n" << s;
    auto has = [&](const std::string &t) { return std::find(r.texts.begin(), r.texts.end(), t) != r.texts.end(); };
    EXPECT_TRUE(has("a&lt;b&gt;&amp;&quot;&apos;[0m]]&gt;\xef\xbf\xbd\xef\xbf\xbd(\xef\xbf\xbd\xef\xbf\xbd "
                          "\xef\xbf\xbd\xef\xbf\xbd\xef\xbf\xbd &lt;/text&gt;&lt;!-- caf\xc3\xa9 \xe2\x82\xac"));
    EXPECT_TRUE(has("&amp;amp; stays literal"));
    EXPECT_TRUE(has("y"));   // control characters (NUL included) are dropped
    EXPECT_TRUE(has("100% &amp;#x 1"));   // the label's literal text, unescaped from LaTeX, escaped for XML
}

TEST(Svg2D, WritesFilesAndReportsFailures)
{
    rtl::Svg2D d;
    d.addLine(Vector2f(0, 0), Vector2f(1, 1), "draw=red,->");
    std::filesystem::path p = std::filesystem::path(RTL_TEST_OUTPUT_DIR) / "svg2d_line.svg";
    d.writeSVG(p.string());
    std::ifstream in(p);
    std::string s((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    EXPECT_EQ(s, svg(d));
    EXPECT_NE(s.find("marker-end=\"url(#ArrowA)\""), std::string::npos);
    EXPECT_THROW(d.writeSVG("/nonexistent-dir/x.svg"), std::runtime_error);
}

TEST(SvgStyle, TikzStylesAndColoursTranslate)
{
    using namespace rtl::detail;
    ColorResolver colors({{"ColorA", "{hsb}{0.5,1,1}"}, {"ColorB", "{RGB}{255,128,0}"}, {"ColorC", "{HTML}{1f77B4}"}});
    EXPECT_EQ(colors.hex("ColorA"), "#00ffff");
    EXPECT_EQ(colors.hex("ColorB"), "#ff8000");
    EXPECT_EQ(colors.hex("ColorC"), "#1f77b4");
    EXPECT_EQ(colors.hex("red!50"), "#ff8080");
    EXPECT_EQ(colors.hex("red!30!blue"), "#4d00b3");
    EXPECT_EQ(colors.hex("blue!50!black!50"), "#8080bf");   // (50 % blue + 50 % black) = (0, 0, .5), then 50 % white
    EXPECT_EQ(colors.hex("nosuchcolour"), "");
    SvgStyle s = parseTikzStyle("style={draw=ColorB,fill=red!20,line width=2pt,densely dotted,opacity=0.4,->}", colors);
    EXPECT_EQ(s.stroke, "#ff8000");
    EXPECT_EQ(s.fill, "#ffcccc");
    EXPECT_NEAR(s.line_width_cm, 2.0 / 28.4527559, 1e-9);
    EXPECT_EQ(s.dash, "densely dotted");
    EXPECT_NEAR(s.opacity, 0.4, 1e-12);
    EXPECT_TRUE(s.arrow_end);
    EXPECT_FALSE(s.arrow_beg);
    SvgStyle t = parseTikzStyle("style={blue,very thick,anchor=north east}", colors);
    EXPECT_EQ(t.stroke, "#0000ff");
    EXPECT_EQ(t.text_color, "#0000ff");
    EXPECT_NEAR(t.line_width_cm, 1.2 / 28.4527559, 1e-9);
    EXPECT_EQ(t.anchor, "north east");
    EXPECT_EQ(xmlEscape("<a href='x'>&</a>"), "&lt;a href=&apos;x&apos;&gt;&amp;&lt;/a&gt;");
}
