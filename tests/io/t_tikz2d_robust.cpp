// Hostile inputs for the 2D writers: tick generation ends and is capped,
// number labels are defined for every double, the escaper turns any bytes into compilable ASCII LaTeX, and the
// documents for extreme coordinates, hostile text and many marks compile with the real pdflatex (one batched run);
// the SVG of the same drawings is well-formed XML.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include "rtl/io/LaTeXDoc.h"
#include "rtl/io/LaTeXTikz2D.h"
#include "rtl/io/Svg2D.h"
#include "pdflatex_run.h"
#include "xml_check.h"

namespace fs = std::filesystem;
using rtl::Drawing2D;
using rtl::LaTeXTikz2D;
using rtl::Vector2f;

namespace
{
    const double qnan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();

    std::string tikz(const Drawing2D &d)
    {
        std::ostringstream os;
        rtl::writeTikzPicture(d, os);
        return os.str();
    }
    std::string svg(const Drawing2D &d)
    {
        std::ostringstream os;
        rtl::writeSvg(d, os);
        return os.str();
    }
    size_t count(const std::string &s, const std::string &what)
    {
        size_t n = 0;
        for (size_t p = s.find(what); p != std::string::npos; p = s.find(what, p + 1))
            ++n;
        return n;
    }

    //! Every special character, control characters, DEL, invalid UTF-8 and non-ASCII text.
    const std::string hostile = std::string("T&i%t$l#e_{x}~^\\<>|\"'[]") + '\x01' + '\x7f' + "\t\n\xff\xfe" +
                                "caf\xc3\xa9 \xce\xb1\xe2\x89\xa4\xce\xb2 \xe2\x82\xac \xf0\x9f\x98\x80 \xc3";
}

TEST(Tikz2DRobust, TicksEndOnceValueOverTickPasses2To53)
{
    // Issue 15.2: a flat range at 7.7e31 with tick 1 made `k += 1.0` stand still.
    std::vector<double> t = Drawing2D::ticks(7.7e31, 7.7e31, 1.0);
    ASSERT_EQ(t.size(), 1u);
    EXPECT_DOUBLE_EQ(t[0], 7.7e31);
    // Near 2^53 consecutive multiples of 1 are still distinct: every one is there; beyond, only distinct values.
    double p53 = 9007199254740992.0;
    EXPECT_EQ(Drawing2D::ticks(p53 - 4, p53 + 4, 1.0).size(), 7u);   // p53 + 1, p53 + 3 are not doubles
    std::vector<double> big = Drawing2D::ticks(1e16, 1e16 + 100, 1.0);
    for (size_t i = 1; i < big.size(); ++i)
        EXPECT_LT(big[i - 1], big[i]);
    EXPECT_LE(big.size(), 101u);
    // The cap: more than max_ticks multiples give none at all; exactly max_ticks are all there.
    EXPECT_TRUE(Drawing2D::ticks(0, 1e6, 1e-3).empty());
    EXPECT_EQ(Drawing2D::ticks(1, static_cast<double>(Drawing2D::max_ticks), 1.0).size(), Drawing2D::max_ticks);
    EXPECT_TRUE(Drawing2D::ticks(-inf, 1, 1).empty());
    EXPECT_TRUE(Drawing2D::ticks(0, qnan, 1).empty());
    EXPECT_TRUE(Drawing2D::ticks(1, 0, 1).empty());
}

TEST(Tikz2DRobust, IssueInputsWriteSmallDocuments)
{
    LaTeXTikz2D a;
    a.addText("t", "", Vector2f(0, 7.7e31f));
    a.addAxisY("draw=black", "%d", LaTeXTikz2D::position_left, 1.0f);
    std::string ta = tikz(a);
    EXPECT_LT(ta.size(), 4000u);
    EXPECT_EQ(count(ta, "node[anchor=east]"), 1u);   // the one tick at 7.7e31
    EXPECT_NE(ta.find("{$7.7 \\cdot 10^{31}$}"), std::string::npos);   // %d cannot hold it: printed as %g
    LaTeXTikz2D b;
    b.addPlot(std::vector<Vector2f>{Vector2f(1e16f, 0)}, "", "draw=red", LaTeXTikz2D::latex_mark_dot);
    b.addGridV("draw=gray", 1.0f);
    std::string tb = tikz(b);
    EXPECT_LT(tb.size(), 4000u);
    EXPECT_GE(count(tb, "\\draw[StyleB]"), 1u);
    EXPECT_TRUE(xml_check::check(svg(a)).ok);
    EXPECT_TRUE(xml_check::check(svg(b)).ok);
}

TEST(Tikz2DRobust, NumberLabelsAreDefinedForEveryDouble)
{
    auto n = [](double v, const char *f) { return LaTeXTikz2D::numberToLatexString(v, f); };
    EXPECT_EQ(n(qnan, "%d"), "$nan$");
    EXPECT_EQ(n(inf, "%u"), "$inf$");
    EXPECT_EQ(n(-inf, "%x"), "$-inf$");
    EXPECT_EQ(n(-5.0, "%u"), "$-5$");        // negative for an unsigned conversion: %g
    EXPECT_EQ(n(-0.5, "%u"), "$0$");         // truncates to 0, which fits
    EXPECT_EQ(n(1e19, "%d"), "$10^{19}$");   // beyond long long
    EXPECT_EQ(n(1.5e19, "%u"), "$15000000000000000000$");   // fits unsigned long long
    EXPECT_EQ(n(2e19, "%u"), "$2 \\cdot 10^{19}$");
    EXPECT_EQ(n(-9.3e18, "%i"), "$-9.3 \\cdot 10^{18}$");
    EXPECT_EQ(n(1e300, "%X"), "$10^{300}$");
    EXPECT_EQ(n(qnan, "%.2f"), "$nan$");
    EXPECT_EQ(n(-4.0, "x=%u"), "$x=-4$");   // the literal prefix stays
    EXPECT_EQ(LaTeXTikz2D::numberToLatexString(std::numeric_limits<float>::quiet_NaN(), "%o"), "$nan$");
    EXPECT_EQ(LaTeXTikz2D::numberToLatexString(-3, "%u"), "$18446744073709551613$");   // integers convert (defined)
    EXPECT_EQ(n(1.0, "%d#&$"), "");          // conversion not at the end: refused
    EXPECT_EQ(n(2.0, "#&$ %d"), "$\\#\\&\\$ 2$");
    EXPECT_EQ(n(2.0, "}{%d"), "$\\}\\{2$");   // unbalanced braces are escaped
    EXPECT_EQ(n(2.0, "10^{%d}"), "");        // (not at the end)
    EXPECT_EQ(n(2.0, "{x}%d"), "${x}2$");    // balanced ones stay

    // Through the public axis API: a %u axis over negative data, a log axis with %d and a tick at 1e19.
    LaTeXTikz2D u;
    u.addPlot(std::vector<Vector2f>{Vector2f(-3, 0), Vector2f(3, 1)}, "draw=black");
    u.addAxisX("draw=black", "%u", LaTeXTikz2D::position_below, 1.0f);
    std::string tu = tikz(u);
    EXPECT_NE(tu.find("{$-3$}"), std::string::npos);
    EXPECT_NE(tu.find("{$3$}"), std::string::npos);
    LaTeXTikz2D l(LaTeXTikz2D::axis_type_log10, LaTeXTikz2D::axis_type_linear);
    l.addPlot(std::vector<Vector2f>{Vector2f(1e17f, 0), Vector2f(1e20f, 1)}, "draw=black");
    l.addAxisX("draw=black", "%d", LaTeXTikz2D::position_below, 1.0f);
    std::string tl = tikz(l);
    EXPECT_NE(tl.find("{$100000000000000000$}"), std::string::npos);   // 1e17 fits
    EXPECT_NE(tl.find("{$10^{19}$}"), std::string::npos);
    EXPECT_NE(tl.find("{$10^{20}$}"), std::string::npos);
}

TEST(Tikz2DRobust, EscaperTurnsAnyBytesIntoAsciiLaTeX)
{
    using rtl::LaTeX::escapeLaTeXCharacters;
    using rtl::LaTeX::sanitizeUtf8;
    EXPECT_EQ(escapeLaTeXCharacters(std::string("a\x01\x1f\x7f" "b\0c", 7)), "abc");   // controls, DEL, NUL dropped
    EXPECT_EQ(escapeLaTeXCharacters("a\tb\nc\rd"), "a b c d");
    EXPECT_EQ(escapeLaTeXCharacters("x\xff y\xc3"), "x? y?");                 // invalid UTF-8: U+FFFD, written "?"
    EXPECT_EQ(sanitizeUtf8("x\xff y\xc3"), "x\xef\xbf\xbd y\xef\xbf\xbd");
    std::string fffd = "\xef\xbf\xbd", nine;
    for (int i = 0; i < 9; ++i)
        nine += fffd;   // overlong, surrogate and > U+10FFFF: every byte replaced
    EXPECT_EQ(sanitizeUtf8("\xc0\xaf\xed\xa0\x80\xf4\x90\x80\x80"), nine);
    EXPECT_EQ(sanitizeUtf8("\xc2\x85 \xc3\xa9"), " \xc3\xa9");                  // C1 control dropped
    EXPECT_EQ(escapeLaTeXCharacters("caf\xc3\xa9 \xc3\x9c" "ber \xc3\xb1"), "caf\\'{e} \\\"{U}ber \\~{n}");
    EXPECT_EQ(escapeLaTeXCharacters("\xce\xb1\xe2\x89\xa4\xce\xb2"), "$\\alpha$ $\\leq$ $\\beta$");
    EXPECT_EQ(escapeLaTeXCharacters("25\xc2\xb0" "C \xc2\xb1 1"), "25$^\\circ$C $\\pm$ 1");
    EXPECT_EQ(escapeLaTeXCharacters("\xf0\x9f\x98\x80 \xe4\xb8\xad"), "? ?");   // no glyph in the OT1 fonts
    for (unsigned char c : escapeLaTeXCharacters(hostile))
        EXPECT_TRUE(c >= 0x20 && c < 0x7f) << static_cast<int>(c);
}

//! One pdflatex run over every picture: extreme coordinate ranges (both signs, map frame), hostile text, 1 and many
//! marks. Each picture must compile without an error and become one page.
TEST(Tikz2DRobust, ExtremeDocumentsCompileWithPdflatex)
{
    ASSERT_TRUE(rtl::LaTeXDoc::pdflatexAvailable()) << "pdflatex is not on PATH (./run test installs TeX Live)";
    std::vector<std::string> pictures;
    std::vector<std::string> svgs;
    auto add = [&](const std::function<void(LaTeXTikz2D &)> &draw) {
        LaTeXTikz2D d;
        draw(d);
        pictures.push_back(tikz(d));
        svgs.push_back(svg(d));
    };
    auto scene = [](double lo, double hi, size_t n) {
        return [=](LaTeXTikz2D &d) {
            std::vector<Vector2f> v;
            for (size_t i = 0; i < n; ++i)
            {
                double t = n > 1 ? static_cast<double>(i) / static_cast<double>(n - 1) : 0.5;
                v.emplace_back(static_cast<float>(lo + (hi - lo) * t),
                               static_cast<float>(lo + (hi - lo) * (0.5 + 0.4 * std::sin(6 * t))));
            }
            d.addPlot(v, "draw=black", "draw=red", LaTeXTikz2D::latex_mark_cross);
            float tick = static_cast<float>((hi - lo) / 4);
            d.addAxisX("draw=black,->", "%g", LaTeXTikz2D::position_below, tick, static_cast<float>(lo));
            d.addAxisY("draw=black,->", "%.2e", LaTeXTikz2D::position_left, tick, static_cast<float>(lo));
            d.addGridH("draw=gray,thin", tick);
            d.addCircle(v[n / 2], static_cast<float>((hi - lo) / 10), "draw=blue");
            d.addEllipse(v[0], static_cast<float>((hi - lo) / 8), static_cast<float>((hi - lo) / 20), 0.5f, "draw=green");
            d.addPie(v[n - 1], static_cast<float>((hi - lo) / 10), 0.2f, 2.0f, "fill=orange");
            d.addText("lo", "anchor=west", v[0]);
        };
    };
    for (double s : {1.0, -1.0})
    {
        add(scene(s * 1e-3, s * 2e-3, 40));   // a range of 1e-3: unit vectors of 10,000 cm
        add(scene(s * 1e6, s * 2e6, 40));     // coordinates of 1e6: beyond pgfmath's numbers
        add(scene(s * 1e-3, s * 1e6, 40));
    }
    add(scene(-1e6, 1e6, 40));
    add(scene(1e6, 1e6 + 1, 40));             // a small range far from the origin
    add([](LaTeXTikz2D &d) {                 // a map-frame scan: x 1000-2000, y 750-850
        std::vector<Vector2f> v;
        for (int i = 0; i < 400; ++i)
            v.emplace_back(1000.0f + 2.5f * static_cast<float>(i), 800.0f + 50.0f * std::sin(0.05f * static_cast<float>(i)));
        d.addPlot(v, "", "draw=red", LaTeXTikz2D::latex_mark_dot);
        d.addAxisX("draw=black", "%.0f", LaTeXTikz2D::position_below, 250.0f, 750.0f);
    });
    add(scene(0, 1, 1));                      // one mark
    add(scene(0, 100, 1500));                 // many marks (15,000 take minutes on a loaded machine: see the note)
    add([](LaTeXTikz2D &d) {                 // hostile text everywhere text goes
        d.addText(hostile, "anchor=west", Vector2f(0, 0));
        d.addDescriptionX(hostile);
        d.addDescriptionY(hostile);
        d.addAxisX("draw=black", "#&$%%}{ %d", LaTeXTikz2D::position_below, 1.0f);
        d.addAxisY("draw=black", "%u", LaTeXTikz2D::position_left, 1.0f, -2.0f);
        d.addPlot(std::vector<Vector2f>{Vector2f(-3, -3), Vector2f(3, 3)}, "draw=black");
    });
    add([](LaTeXTikz2D &d) {                 // the reported inputs
        d.addText("t", "", Vector2f(0, 7.7e31f));
        d.addAxisY("draw=black", "%d", LaTeXTikz2D::position_left, 1.0f);
        d.addLine(Vector2f(1e16f, 0), Vector2f(1e16f, 1), "draw=black");
        d.addGridV("draw=gray", 1.0f);
    });

    for (size_t i = 0; i < svgs.size(); ++i)
    {
        xml_check::Result r = xml_check::check(svgs[i]);
        EXPECT_TRUE(r.ok) << "SVG " << i << ": " << r.error;
    }
    // The pictures that need it are written on paper (x=1cm, y=1cm), the map frame in data units.
    EXPECT_NE(pictures[0].find("[x=1cm, y=1cm"), std::string::npos);
    EXPECT_NE(pictures[1].find("[x=1cm, y=1cm"), std::string::npos);
    EXPECT_EQ(pictures[8].find("[x=1cm, y=1cm"), std::string::npos);

    fs::path dir = fs::path(RTL_TEST_OUTPUT_DIR) / "latex" / "robust2d";
    fs::remove_all(dir);
    fs::create_directories(dir);
    pdflatex_test::writePreviewDocument(dir, "robust", pictures);
    const auto run = pdflatex_test::compile(dir, "robust");
    EXPECT_EQ(run.rc, 0) << run.failure();
    EXPECT_NE(run.log.find("Output written on robust.pdf (" + std::to_string(pictures.size()) + " pages"),
              std::string::npos);
}

TEST(Tikz3DRobust, AxisLabelsStayFiniteAndTheirLoopEnds)
{
    // fuzz_tikz3d finding: an infinite tick gave the label "$-nan$"; a huge axis coordinate must not stall the loop.
    for (float tick : {std::numeric_limits<float>::infinity(), 1.0f})
    {
        for (float at : {0.0f, 7.7e31f, 3e38f})
        {
            rtl::LaTeXTikz3D d;
            d.addLine(rtl::LineSegment3f(rtl::Vector3f(at, 0, 0), rtl::Vector3f(at, 1, 1)), "draw=black");
            d.addAxis("draw=black", "%g", rtl::LaTeXTikz3D::position_above, tick, rtl::Vector3f(at, 0, 0),
                      rtl::Vector3f(at + 1.0f, 0, 0));
            std::ostringstream os;
            d.writeTEX(os);
            EXPECT_EQ(os.str().find("nan"), std::string::npos) << tick << " " << at;
            EXPECT_EQ(os.str().find("{$inf"), std::string::npos) << tick << " " << at;
            EXPECT_EQ(os.str().find("{$-inf"), std::string::npos) << tick << " " << at;
            EXPECT_LT(os.str().size(), 200000u);
        }
    }
}

TEST(Tikz2DRobust, LogAxisLabelsBeyondDoubleAreLeftOut)
{
    // fuzz_tikz2d finding: the overrun of a log axis reached 10^438, whose label was "$inf$" (and 10^-400 gave "$0$").
    rtl::Svg2D d(rtl::Svg2D::axis_type_linear, rtl::Svg2D::axis_type_log10);
    d.setGridAxisOverrun(rtl::Svg2D::overrun_absolute, 400.0f);
    // x up to 1e4: with x up to 1 the 400-unit overrun made the picture 8,010 cm wide, beyond TeX's dimensions
    // (now refused); this way it is 10.8 cm wide and 220 cm high.
    d.addPlot(std::vector<Vector2f>{Vector2f(0, 1), Vector2f(1e4f, 1e38f)}, "draw=black");
    d.addAxisY("draw=black", "%g", rtl::Svg2D::position_left, 100.0f);
    std::ostringstream t;
    rtl::writeTikz(d, t);
    EXPECT_EQ(t.str().find("inf"), std::string::npos);
    EXPECT_NE(t.str().find("{$10^{300}$}"), std::string::npos);
    EXPECT_EQ(count(t.str(), "node[anchor=east]"), 7u);   // -300 ... 300: 10^400 is inf and 10^-400 is 0 in double
    std::string s = svg(d);
    EXPECT_EQ(s.find(">inf<"), std::string::npos);
    EXPECT_TRUE(xml_check::check(s).ok);
}
