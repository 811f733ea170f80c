// The TikZ/LaTeX text the exporters write: escaping, number labels, names, every 2D primitive, the 3D camera and
// depth order, tables. (t_io_latex_pdf compiles such output with the real pdflatex.)
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <cstdlib>
#include <sstream>
#include <string>
#include <vector>

#include "rtl/io/LaTeXDoc.h"

using rtl::LaTeXTable;
using rtl::LaTeXTikz2D;
using rtl::LaTeXTikz3D;
using rtl::Vector2f;
using rtl::Vector3f;

namespace
{
    //! Every distinct document and table the tests below write; the last test compiles them all with pdflatex.
    std::vector<std::string> &written()
    {
        static std::vector<std::string> docs;
        return docs;
    }
    std::vector<std::pair<LaTeXTable, std::string>> &writtenTables()
    {
        static std::vector<std::pair<LaTeXTable, std::string>> tables;
        return tables;
    }
    void remember(std::vector<std::string> &list, const std::string &text)
    {
        if (std::find(list.begin(), list.end(), text) == list.end())
            list.push_back(text);
    }

    std::string tex(LaTeXTikz2D &le)
    {
        std::ostringstream os;
        le.writeTEX(os);
        remember(written(), os.str());
        return os.str();
    }
    std::string tex(LaTeXTikz3D &le)
    {
        std::ostringstream os;
        le.writeTEX(os);
        remember(written(), os.str());
        return os.str();
    }
    //! The primitives: the text between the last setup line and \end{tikzpicture}.
    std::string body(const std::string &doc, const std::string &after)
    {
        size_t b = doc.rfind(after);
        size_t e = doc.find("\\end{tikzpicture}");
        if (b == std::string::npos || e == std::string::npos)
            return "";
        b = doc.find('\n', b) + 1;
        return doc.substr(b, e - b);
    }
    std::string body2(const std::string &doc)
    {
        std::string b = body(doc, "\\pgfmathsetmacro{\\MarkRadius}"), out;
        std::istringstream is(b);
        for (std::string l; std::getline(is, l);)
            if (l.rfind("\\newcommand", 0) != 0)
                out += l + "\n";
        return out;
    }
    std::string body3(const std::string &doc) { return body(doc, "\\clip ("); }

    std::vector<std::string> lines(const std::string &s)
    {
        std::vector<std::string> v;
        std::istringstream is(s);
        for (std::string l; std::getline(is, l);)
            if (!l.empty())
                v.push_back(l);
        return v;
    }
    //! Parses "(x,y)" at s[pos]; false if the text there is not a plain numeric coordinate.
    bool coordAt(const std::string &s, size_t pos, double &x, double &y)
    {
        if (pos >= s.size() || s[pos] != '(')
            return false;
        const char *b = s.c_str() + pos + 1;
        char *e = nullptr;
        x = std::strtod(b, &e);
        if (e == b || *e != ',')
            return false;
        b = e + 1;
        y = std::strtod(b, &e);
        return e != b && *e == ')';
    }
    //! All "(x,y)" coordinates in a text, with whether each is joined to the previous one by " -- ".
    struct Coord
    {
        double x, y;
        bool joined;
    };
    std::vector<Coord> coordList(const std::string &s)
    {
        std::vector<Coord> v;
        for (size_t p = s.find('('); p != std::string::npos; p = s.find('(', p + 1))
        {
            double x, y;
            if (coordAt(s, p, x, y))
                v.push_back({x, y, p >= 3 && s.compare(p - 3, 3, "-- ") == 0});
        }
        return v;
    }
    std::vector<std::pair<double, double>> coords(const std::string &s)
    {
        std::vector<std::pair<double, double>> v;
        for (const auto &c : coordList(s))
            v.emplace_back(c.x, c.y);
        return v;
    }
    double optionValue(const std::string &doc, const std::string &key)
    {
        size_t p = doc.find(key + "=");
        if (p == std::string::npos)
            return NAN;
        return std::strtod(doc.c_str() + p + key.size() + 1, nullptr);
    }
    size_t count(const std::string &s, const std::string &what)
    {
        size_t n = 0;
        for (size_t p = s.find(what); p != std::string::npos; p = s.find(what, p + what.size()))
            ++n;
        return n;
    }
}

TEST(LaTeXUtility, EscapesEverySpecialCharacter)
{
    using rtl::LaTeX::escapeLaTeXCharacters;
    EXPECT_EQ(escapeLaTeXCharacters("a&b%c$d#e_f{g}h"), "a\\&b\\%c\\$d\\#e\\_f\\{g\\}h");
    EXPECT_EQ(escapeLaTeXCharacters("~"), "\\textasciitilde ");
    EXPECT_EQ(escapeLaTeXCharacters("x^2"), "x\\textasciicircum 2");
    EXPECT_EQ(escapeLaTeXCharacters("C:\\dir"), "C:\\textbackslash dir");
    EXPECT_EQ(escapeLaTeXCharacters("a<b>c"), "a$<$b$>$c");
    // Adjacent math shifts are separated so that "$$" never starts display math; the empty start is not inspected.
    EXPECT_EQ(escapeLaTeXCharacters("<>"), "$<$ $>$");
    EXPECT_EQ(escapeLaTeXCharacters("$<"), "\\$ $<$");
    EXPECT_EQ(escapeLaTeXCharacters(""), "");
    EXPECT_EQ(escapeLaTeXCharacters("plain text 1.5"), "plain text 1.5");
}

TEST(LaTeXUtility, NumberLabels)
{
    EXPECT_EQ(LaTeXTikz2D::numberToLatexString(42, "%d"), "$42$");
    EXPECT_EQ(LaTeXTikz2D::numberToLatexString(-7.9, "%d"), "$-7$");
    EXPECT_EQ(LaTeXTikz2D::numberToLatexString(255, "%x"), "$ff$");
    EXPECT_EQ(LaTeXTikz2D::numberToLatexString(2.5f, "%.2f"), "$2.50$");
    EXPECT_EQ(LaTeXTikz2D::numberToLatexString(12345.0, "%.2e"), "$1.23 \\cdot 10^{4}$");
    EXPECT_EQ(LaTeXTikz2D::numberToLatexString(1000.0, "%.0e"), "$10^{3}$");
    EXPECT_EQ(LaTeXTikz2D::numberToLatexString(0.05, "%.1e"), "$5.0 \\cdot 10^{-2}$");
    EXPECT_EQ(LaTeXTikz2D::numberToLatexString(1.0, "%.0e"), "$10^{0}$");
    EXPECT_EQ(LaTeXTikz2D::numberToLatexString(3, "%5d"), "$    3$");
    EXPECT_EQ(LaTeXTikz2D::numberToLatexString(3, "%ld"), "$3$");   // length modifier normalised, not UB
    EXPECT_EQ(LaTeXTikz2D::numberToLatexString(3, "%q"), "");
    EXPECT_EQ(LaTeXTikz2D::numberToLatexString(3, "%d %d"), "");    // two conversions: refused
    // The literal percent is escaped: a bare % would comment out the rest of the line in TeX.
    EXPECT_EQ(LaTeXTikz2D::numberToLatexString(3, "100%% %d"), "$100\\% 3$");
    EXPECT_EQ(LaTeXTikz2D::numberToLatexString(3, ""), "");
}

TEST(LaTeXUtility, GeneratedNamesUseLetters)
{
    EXPECT_EQ(rtl::detail::indexToLetters(0), "A");
    EXPECT_EQ(rtl::detail::indexToLetters(9), "J");
    EXPECT_EQ(rtl::detail::indexToLetters(10), "BA");
    EXPECT_EQ(rtl::detail::indexToLetters(105), "BAF");
    EXPECT_EQ(rtl::detail::number(1e5), "100000");
    EXPECT_EQ(rtl::detail::number(1e7), "1e07");   // no "+": TikZ does not read it
    EXPECT_EQ(rtl::detail::number(-0.25), "-0.25");
}

TEST(LaTeXTikz2D, DocumentFrameAndScale)
{
    LaTeXTikz2D le;
    le.setSize(8, 4);
    le.setBorder(0.5f);
    le.addLine(Vector2f(-1, 0), Vector2f(3, 2), "style={draw=red}");
    std::string doc = tex(le);
    EXPECT_EQ(doc.rfind("\\documentclass{minimal}\n\\usepackage[rgb]{xcolor}\n\\usepackage{tikz}\n"
                        "\\usepackage[active,tightpage]{preview}\n\\PreviewEnvironment{tikzpicture}\n"
                        "\\setlength\\PreviewBorder{0.5cm}\n", 0), 0u);
    EXPECT_NE(doc.find("\\begin{tikzpicture}[x=2cm, y=2cm,\n\tStyleA/.style={draw=red}]"), std::string::npos);
    EXPECT_NE(doc.find("\\pgfmathsetmacro{\\MaxX}{3}\n\\pgfmathsetmacro{\\MinX}{-1}\n\\pgfmathsetmacro{\\MaxY}{2}\n"
                       "\\pgfmathsetmacro{\\MinY}{0}\n\\pgfmathsetmacro{\\MarkGlobalScaleX}{0.5}\n"
                       "\\pgfmathsetmacro{\\MarkGlobalScaleY}{0.5}\n"), std::string::npos);
    EXPECT_EQ(body2(doc), "\\draw[StyleA] (-1,0) -- (3,2);\n");
    EXPECT_TRUE(doc.size() > 20 && doc.substr(doc.size() - 33) == "\\end{tikzpicture}\n\\end{document}\n");
    EXPECT_FLOAT_EQ(le.minX(), -1);
    EXPECT_FLOAT_EQ(le.maxY(), 2);
    EXPECT_FLOAT_EQ(le.scaleX(), 2);
    le.setScaleY(3);
    EXPECT_FLOAT_EQ(le.scaleY(), 6);
}

TEST(LaTeXTikz2D, EachPrimitive)
{
    LaTeXTikz2D le;
    const std::string s = "style={draw=blue}";
    le.addLine(rtl::LineSegment2f(0, 0, 1, 1), s);
    le.addCircle(Vector2f(1, 1), 0.5f, s);
    le.addRectangle(Vector2f(0, 0), Vector2f(2, 1), s);
    le.addTriangle(Vector2f(0, 0), Vector2f(1, 0), Vector2f(0.5f, 1), s);
    le.addQuadrilateral(Vector2f(0, 0), Vector2f(1, 0), Vector2f(1, 1), Vector2f(0, 1), s);
    le.addEllipse(Vector2f(1, 2), 2, 1, static_cast<float>(M_PI / 2), s);
    le.addPie(Vector2f(0, 0), 1, 0, static_cast<float>(M_PI / 2), s);
    le.addText("50% of a_b {x} & ~ ^ \\ # $", "style={anchor=west}", Vector2f(1, 0));
    le.addEdges(std::vector<rtl::LineSegment2f>{{Vector2f(0, 0), Vector2f(0, 1)}}, s, LaTeXTikz2D::edge_arrow_end);
    le.addEdge(rtl::LineSegment2f(0, 0, 1, 0), s, LaTeXTikz2D::edge_arrow_beg | LaTeXTikz2D::edge_arrow_end);
    auto l = lines(body2(tex(le)));
    ASSERT_EQ(l.size(), 10u);
    EXPECT_EQ(l[0], "\\draw[StyleA] (0,0) -- (1,1);");
    EXPECT_EQ(l[1], "\\draw[StyleA] (1,1) circle (0.5);");
    EXPECT_EQ(l[2], "\\draw[StyleA] (0,0) rectangle (2,1);");
    EXPECT_EQ(l[3], "\\draw[StyleA] (0,0) -- (1,0) -- (0.5,1) -- cycle;");
    EXPECT_EQ(l[4], "\\draw[StyleA] (0,0) -- (1,0) -- (1,1) -- (0,1) -- cycle;");
    EXPECT_EQ(l[5], "\\draw[StyleA, rotate around={90:(1,2)}] (1,2) ellipse (2 and 1);");
    EXPECT_EQ(l[6], "\\draw[StyleA] (0,0) -- ++(0:1) arc (0:90:1) -- cycle;");
    EXPECT_EQ(l[7], "\\node[StyleB] at (1,0) {50\\% of a\\_b \\{x\\} \\& \\textasciitilde  \\textasciicircum  "
                    "\\textbackslash  \\# \\$};");
    EXPECT_EQ(l[8], "\\draw[StyleA,->] (0,0) -- (0,1);");
    EXPECT_EQ(l[9], "\\draw[StyleA,<->] (0,0) -- (1,0);");
    // Bounds cover the ellipse rotated by 90 degrees (x extent 1, y extent 2 around (1, 2)).
    EXPECT_FLOAT_EQ(le.maxY(), 4);
    EXPECT_FLOAT_EQ(le.minY(), -1);   // pie/circle radius around the origin
}

TEST(LaTeXTikz2D, StylesColoursAndNames)
{
    LaTeXTikz2D le;
    std::string c1 = le.saveColor("{hsb}{0.3,0.8,0.5}");
    std::string c2 = le.saveColor("{rgb}{1,0,0}");
    EXPECT_EQ(c1, "ColorA");
    EXPECT_EQ(c2, "ColorB");
    EXPECT_EQ(le.saveColor("{hsb}{0.3,0.8,0.5}"), "ColorA");
    for (int i = 0; i < 11; ++i)
        le.addLine(Vector2f(0, 0), Vector2f(1, static_cast<float>(i)), "style={draw=" + c1 + ",line width=" +
                                                                          std::to_string(i) + "pt}");
    le.addLine(Vector2f(0, 0), Vector2f(1, 1), "style={draw=" + c1 + ",line width=0pt}");   // registered already
    le.addLine(Vector2f(0, 0), Vector2f(1, 1), "draw=red");                                 // wrapped in style={}
    std::string doc = tex(le);
    EXPECT_NE(doc.find("\\definecolor{ColorA}{hsb}{0.3,0.8,0.5}\n\\definecolor{ColorB}{rgb}{1,0,0}\n"),
              std::string::npos);
    EXPECT_NE(doc.find("StyleA/.style={draw=ColorA,line width=0pt}"), std::string::npos);
    EXPECT_NE(doc.find("StyleBA/.style={draw=ColorA,line width=10pt}"), std::string::npos);
    EXPECT_NE(doc.find("StyleBB/.style={draw=red}"), std::string::npos);
    auto l = lines(body2(doc));
    ASSERT_EQ(l.size(), 13u);
    EXPECT_EQ(l[10], "\\draw[StyleBA] (0,0) -- (1,10);");
    EXPECT_EQ(l[11], "\\draw[StyleA] (0,0) -- (1,1);");
    EXPECT_EQ(l[12], "\\draw[StyleBB] (0,0) -- (1,1);");
}

TEST(LaTeXTikz2D, PlotLinesBreakAtNaNAndMarksFollowTheDirection)
{
    LaTeXTikz2D le;
    le.setMinPlotRegion(0, 0, 4, 4);   // equal scales in x and y, so the paper angle is the data angle
    std::vector<float> x = {0, 1, 2, NAN, 3, 4}, y = {0, 1, 1, 5, 2, 2};
    le.addPlot(x, y, "style={draw=black}", "style={fill=red}", LaTeXTikz2D::latex_mark_robot, 2.0f);
    std::string doc = tex(le);
    EXPECT_NE(doc.find("\\newcommand{\\MarkA}[3]{\\begin{scope}[shift={(#1,#2)}, x=1cm, "
                       "y=1cm, rotate=#3, scale=2] \\filldraw[StyleB] (0,0) circle (\\MarkRadius); "
                       "\\draw[StyleB] (0,0) -- (2*\\MarkRadius,0); \\end{scope}}"),
              std::string::npos);
    auto l = lines(body2(doc));
    ASSERT_EQ(l.size(), 7u);
    EXPECT_EQ(l[0], "\\draw[StyleA] (0,0) -- (1,1) -- (2,1);");
    EXPECT_EQ(l[1], "\\draw[StyleA] (3,2) -- (4,2);");
    EXPECT_EQ(l[2], "\\MarkA{0}{0}{45}");
    EXPECT_EQ(l[3], "\\MarkA{1}{1}{22.5}");   // mean of 45 and 0 degrees
    EXPECT_EQ(l[4], "\\MarkA{2}{1}{0}");      // the NaN breaks the polyline: only the incoming segment counts
    EXPECT_EQ(l[5], "\\MarkA{3}{2}{0}");
    EXPECT_EQ(l[6], "\\MarkA{4}{2}{0}");
    EXPECT_FLOAT_EQ(le.maxY(), 4);   // the NaN point's y = 5 is not tracked

    // Mismatched sizes and empty input draw nothing.
    LaTeXTikz2D e;
    e.addPlot(std::vector<float>{1, 2}, std::vector<float>{1}, "style={draw=black}");
    e.addPlot(std::vector<Vector2f>{}, "style={draw=black}", "style={fill=red}", LaTeXTikz2D::latex_mark_dot);
    EXPECT_EQ(body2(tex(e)), "");
}

TEST(LaTeXTikz2D, LongPolylinesAreCutIntoPathsSharingTheirJoints)
{
    LaTeXTikz2D le;
    std::vector<float> x(1200), y(1200, 0.0f);
    for (size_t i = 0; i < x.size(); ++i)
        x[i] = static_cast<float>(i);
    le.addPlot(x, y, "style={draw=black}");
    std::string b = body2(tex(le));
    EXPECT_EQ(count(b, "\\draw[StyleA]"), 3u);   // 500 + 500 + 202 points, joints repeated
    EXPECT_EQ(count(b, " -- "), 1199u);            // every segment exactly once
    EXPECT_NE(b.find("(499,0);\n\\draw[StyleA] (499,0) -- (500,0)"), std::string::npos);
    EXPECT_NE(b.find("(998,0);\n\\draw[StyleA] (998,0) -- (999,0)"), std::string::npos);
}

TEST(LaTeXTikz2D, MarkTemplatesAndPaperAngles)
{
    LaTeXTikz2D le;
    le.setSize(10, 5);   // x: 10 cm per unit, y: 5 cm per unit -> a 45 degree data slope is atan(1/2) on paper
    le.addPlot(std::vector<Vector2f>{{0, 0}, {1, 1}}, "", "style={draw=blue}", LaTeXTikz2D::latex_mark_cross);
    le.addPlot(std::vector<Vector2f>{{0, 0}}, "", "style={draw=blue}", LaTeXTikz2D::latex_mark_mark);
    le.addPlot(std::vector<Vector2f>{{0, 0}}, "", "style={draw=blue}", LaTeXTikz2D::latex_mark_dot);
    le.addPlot(std::vector<Vector2f>{{0, 0}}, "", "style={draw=blue}", LaTeXTikz2D::latex_mark_cross);   // reused
    std::string doc = tex(le);
    EXPECT_NE(doc.find("\\draw[StyleA] (-\\MarkRadius,-\\MarkRadius) -- (\\MarkRadius,\\MarkRadius)"), std::string::npos);
    EXPECT_NE(doc.find("\\newcommand{\\MarkB}[3]{\\begin{scope}[shift={(#1,#2)}, x=1cm, y=1cm, rotate=#3, "
                       "scale=1] \\draw[StyleA] (0,-\\MarkRadius) -- "
                       "(0,\\MarkRadius); \\end{scope}}"), std::string::npos);
    EXPECT_NE(doc.find("\\filldraw[StyleA] (0,0) circle (\\MarkRadius);"), std::string::npos);
    EXPECT_EQ(count(doc, "\\newcommand"), 3u);
    auto l = lines(body2(doc));
    ASSERT_EQ(l.size(), 5u);
    EXPECT_EQ(l[0], "\\MarkA{0}{0}{26.5651}");
    EXPECT_EQ(l[4], "\\MarkA{0}{0}{0}");
    EXPECT_EQ(optionValue(doc, "[x"), 10);
    EXPECT_EQ(optionValue(doc, " y"), 5);
}

TEST(LaTeXTikz2D, GridsAxesAndDescriptions)
{
    LaTeXTikz2D le;
    le.setGridAxisOverrun(LaTeXTikz2D::overrun_absolute, 0.5f);
    le.setMinPlotRegion(0, 0, 2, 1);
    le.addGridH("style={draw=gray}", 1);
    le.addGridV("style={draw=gray}", 1);
    le.addAxisX("style={draw=black}", "%.1f", LaTeXTikz2D::position_below | LaTeXTikz2D::position_left, 1);
    le.addAxisY("style={draw=black}", "%d", LaTeXTikz2D::position_right, 1, 0.5f);
    le.addDescriptionX("x [m] _1");
    le.addDescriptionY("y^2");
    std::string b = body2(tex(le));
    // Horizontal lines at y = -0, 1 across x in [-0.5, 2.5]; vertical at x = 0, 1, 2 across y in [-0.5, 1.5].
    EXPECT_NE(b.find("\\draw[StyleA] (-0.5,0) -- (2.5,0);\n\\draw[StyleA] (-0.5,1) -- (2.5,1);\n"
                     "\\draw[StyleA] (0,-0.5) -- (0,1.5);\n\\draw[StyleA] (1,-0.5) -- (1,1.5);\n"
                     "\\draw[StyleA] (2,-0.5) -- (2,1.5);\n"), std::string::npos);
    // Axes with 0.1 cm ticks (y scale 10 cm per unit: +-0.005 units) and anchored labels.
    EXPECT_NE(b.find("\\draw[StyleB] (-0.5,0) -- (2.5,0);\n"), std::string::npos);
    EXPECT_NE(b.find("\\draw[StyleB] (1,-0.005) -- (1,0.005) (1,-0.005) node[anchor=north east] {$1.0$};"),
              std::string::npos);
    EXPECT_NE(b.find("\\draw[StyleB] (0.5,-0.5) -- (0.5,1.5);\n"), std::string::npos);
    EXPECT_NE(b.find("\\draw[StyleB] (0.49,1) -- (0.51,1) (0.51,1) node[anchor=west] {$1$};"), std::string::npos);
    EXPECT_NE(b.find("\\node[anchor=north, yshift=-0.7cm] at (1,-0.5) {x [m] \\_1};"), std::string::npos);
    EXPECT_NE(b.find("\\node[anchor=south, rotate=90, yshift=1.2cm] at (-0.5,0.5) {y\\textasciicircum 2};"),
              std::string::npos);
}

TEST(LaTeXTikz2D, LogAxesAndClipping)
{
    LaTeXTikz2D le(LaTeXTikz2D::axis_type_log10, LaTeXTikz2D::axis_type_linear);
    le.addPlot(std::vector<float>{1, 10, 100, -1}, std::vector<float>{0, 1, 2, 3}, "style={draw=black}");
    le.addAxisX("style={draw=black}", "%.0e", LaTeXTikz2D::position_below, 1);
    EXPECT_FLOAT_EQ(le.minX(), 0);   // log10(1)
    EXPECT_FLOAT_EQ(le.maxX(), 2);   // log10(100); the non-positive x is dropped
    le.setClipRegion(1, -1, 1000, 3);
    std::string doc = tex(le);
    EXPECT_NE(doc.find("\\clip (0,-1) rectangle (3,3);"), std::string::npos);
    EXPECT_EQ(optionValue(doc, "[x"), 10.0 / 3.0 > 3.33332 ? optionValue(doc, "[x") : -1);
    EXPECT_NEAR(optionValue(doc, "[x"), 10.0 / 3.0, 1e-4);   // fitted to the clip region
    EXPECT_NE(doc.find("\\draw[StyleA] (0,0) -- (1,1) -- (2,2);"), std::string::npos);
    EXPECT_NE(doc.find("node[anchor=north] {$10^{2}$}"), std::string::npos);
    EXPECT_NE(doc.find("node[anchor=north] {$10^{0}$}"), std::string::npos);
}

TEST(LaTeXTikz2D, ClearDataAndClearAll)
{
    LaTeXTikz2D le;
    le.setSize(4, 4);
    le.addLine(Vector2f(0, 0), Vector2f(1, 1), "style={draw=red}");
    le.saveColor("{rgb}{1,0,0}");
    le.clearData();
    EXPECT_EQ(le.minX(), std::numeric_limits<float>::max());
    le.addLine(Vector2f(0, 0), Vector2f(2, 2), "style={draw=blue}");
    std::string doc = tex(le);
    EXPECT_EQ(doc.find("ColorA"), std::string::npos);
    EXPECT_NE(doc.find("StyleA/.style={draw=blue}"), std::string::npos);
    EXPECT_EQ(optionValue(doc, "[x"), 2);   // size 4 kept
    le.clearAll();
    le.addLine(Vector2f(0, 0), Vector2f(2, 2), "style={draw=blue}");
    EXPECT_EQ(optionValue(tex(le), "[x"), 5);   // size back to 10
}

// ---------------------------------------------------------------------------------------------------------------
// 3D

namespace
{
    rtl::Polygon3Df square(float z, float half, bool up = true)
    {
        rtl::Polygon3Df p(Vector3f(0, 0, up ? 1.0f : -1.0f), up ? z : -z);
        p.addPoint(Vector3f(-half, -half, z));
        p.addPoint(Vector3f(half, -half, z));
        p.addPoint(Vector3f(half, half, z));
        p.addPoint(Vector3f(-half, half, z));
        return p;
    }
    //! Camera at (0, 0, 10) looking down -z with fov 90 (f = 1), 10 x 10 cm: (x, y, z) -> 5 (x, y) / (10 - z).
    rtl::RigidTf3f lookDown() { return rtl::RigidTf3f(0.0f, Vector3f(0, 0, 1), Vector3f(0, 0, -10)); }
}

TEST(LaTeXTikz3D, PerspectiveProjection)
{
    LaTeXTikz3D le;
    le.setView(90, lookDown());
    le.addLine(rtl::LineSegment3f(Vector3f(1, 2, 0), Vector3f(-4, 0, 5)), "style={draw=red}");
    std::string doc = tex(le);
    EXPECT_NE(doc.find("\\begin{tikzpicture}[StyleA/.style={draw=red}]"), std::string::npos);
    EXPECT_NE(doc.find("\\path (-5,-5) rectangle (5,5);\n\\begin{scope}\n\\clip (-5,-5) rectangle (5,5);"),
              std::string::npos);
    EXPECT_EQ(body3(doc), "\\draw[StyleA] (0.5,1) -- (-4,0);\n\\end{scope}\n");
    le.setFrameStyle("draw=black, thick");
    le.setExportSize(20, 10);   // k = max(w, h) / 2 = 10
    doc = tex(le);
    EXPECT_NE(doc.find("\\draw[StyleA] (1,2) -- (-8,0);"), std::string::npos);
    EXPECT_NE(doc.find("\\draw[draw=black, thick] (-10,-5) rectangle (10,5);"), std::string::npos);
}

TEST(LaTeXTikz3D, FacesArePaintedBackToFrontWithTheVisibleSideStyle)
{
    LaTeXTikz3D le;
    le.setView(90, lookDown());
    // Added near first: the far square must still be painted first. The near one faces away from the camera.
    le.addFace(square(2, 1, false), "style={fill=red}", "style={fill=blue}", "");
    le.addFace(square(0, 2, true), "style={fill=green}", "style={fill=gray}", "");
    auto l = lines(body3(tex(le)));
    ASSERT_EQ(l.size(), 3u);
    EXPECT_EQ(l[0], "\\path[StyleC] (-1,-1) -- (1,-1) -- (1,1) -- (-1,1) -- cycle;");          // far, front side: green
    EXPECT_EQ(l[1], "\\path[StyleB] (-0.625,-0.625) -- (0.625,-0.625) -- (0.625,0.625) -- (-0.625,0.625) -- cycle;");
    // An empty style leaves that side unpainted.
    LaTeXTikz3D cull;
    cull.setView(90, lookDown());
    cull.addFace(square(0, 1, false), "style={fill=red}", "", "style={draw=black}");
    auto c = lines(body3(tex(cull)));
    ASSERT_EQ(c.size(), 2u);
    EXPECT_EQ(c[0], "\\draw[StyleB] (-0.5,-0.5) -- (0.5,-0.5) -- (0.5,0.5) -- (-0.5,0.5) -- (-0.5,-0.5);");
}

TEST(LaTeXTikz3D, ManyParallelFacesInRandomOrderArePaintedFarToNear)
{
    LaTeXTikz3D le;
    le.setView(90, rtl::RigidTf3f(0.0f, Vector3f(0, 0, 1), Vector3f(0, 0, -1000)));
    std::vector<int> order(400);
    for (size_t i = 0; i < order.size(); ++i)
        order[i] = static_cast<int>((i * 1237) % order.size());   // a permutation (gcd(1237, 400) = 1)
    for (int z : order)
        le.addFace(square(-0.25f * static_cast<float>(z), 400), "style={fill=red}", "style={fill=blue}", "");
    auto l = lines(body3(tex(le)));
    ASSERT_EQ(l.size(), order.size() + 1);
    // Each square's half size on paper is 5 * 400 / (1000 + 0.25 z): it must grow from line to line.
    double prev = 0;
    for (size_t i = 0; i < order.size(); ++i)
    {
        auto c = coords(l[i]);
        ASSERT_EQ(c.size(), 4u) << l[i];
        EXPECT_GT(c[1].first, prev) << "line " << i;
        prev = c[1].first;
    }
    EXPECT_NEAR(prev, 2.0, 1e-4);   // the nearest square (z = 0)
}

TEST(LaTeXTikz3D, CrossingFacesAreSplitWithoutDrawingTheCuts)
{
    LaTeXTikz3D le;
    le.setView(60, Vector3f(-1, -0.5f, -0.7f));
    rtl::Polygon3Df a(Vector3f(1, 0, 0), 0), b(Vector3f(0, 1, 0), 0);
    for (auto q : {std::pair<float, float>{-1, -1}, {1, -1}, {1, 1}, {-1, 1}})
    {
        a.addPoint(Vector3f(0, q.first, q.second));
        b.addPoint(Vector3f(q.first, 0, q.second));
    }
    le.addFace(a, "style={fill=red}", "style={fill=red!50}", "style={draw=black}");
    le.addFace(b, "style={fill=blue}", "style={fill=blue!50}", "style={draw=black}");
    std::string bd = body3(tex(le));
    EXPECT_EQ(count(bd, "\\path["), 3u);   // the second face is cut in two by the first
    // The outline pieces add up to the two original outlines: no edge created by the split is drawn.
    double drawn = 0;
    for (const auto &line : lines(bd))
    {
        if (line.rfind("\\draw[StyleC]", 0) != 0)
            continue;
        // Sum the "--" connections only; "(a) -- (b) (c) -- (d)" moves from b to c without drawing.
        auto c = coordList(line);
        for (size_t i = 1; i < c.size(); ++i)
            if (c[i].joined)
                drawn += std::hypot(c[i].x - c[i - 1].x, c[i].y - c[i - 1].y);
    }
    LaTeXTikz3D whole;   // the same outlines as plain lines
    whole.setView(60, Vector3f(-1, -0.5f, -0.7f));
    for (const auto &poly : {a, b})
        for (size_t i = 0; i < 4; ++i)
            whole.addLine(rtl::LineSegment3f(poly.points()[i], poly.points()[(i + 1) % 4]), "style={draw=black}");
    double expected = 0;
    for (const auto &line : lines(body3(tex(whole))))
    {
        auto c = coords(line);
        if (c.size() == 2)
            expected += std::hypot(c[1].first - c[0].first, c[1].second - c[0].second);
    }
    EXPECT_GT(expected, 5.0);
    EXPECT_NEAR(drawn, expected, 1e-3 * expected);
}

TEST(LaTeXTikz3D, MarksAndLinesAreSortedIntoTheFaces)
{
    LaTeXTikz3D le;
    le.setView(90, lookDown());
    le.addMark(Vector3f(0.5f, 0, 1), "style={fill=red}", LaTeXTikz3D::latex_mark_dot);          // in front
    le.addMark(Vector3f(0, 0.5f, -1), "style={fill=red}", LaTeXTikz3D::latex_mark_dot, 30, 2);  // behind
    le.addFace(square(0, 2), "style={fill=green}", "style={fill=gray}", "");
    le.addLine(rtl::LineSegment3f(Vector3f(0, 0, -1), Vector3f(0, 0, 1)), "style={draw=red}");   // pierces it
    std::string doc = tex(le);
    EXPECT_NE(doc.find("\\newcommand{\\MarkA}[4]{\\begin{scope}[shift={(#1,#2)}, rotate=#3, scale=#4] "
                       "\\filldraw[StyleA] (0,0) circle (\\MarkRadius); \\end{scope}}"), std::string::npos);
    auto l = lines(body3(doc));
    ASSERT_EQ(l.size(), 6u);
    // Behind the face: the mark (scaled by 2 and by perspective 10/11) and the far half of the line.
    EXPECT_EQ(l[0].rfind("\\MarkA{0}{0.227273}{30}{1.81818}", 0), 0u) << l[0];
    EXPECT_EQ(l[1], "\\draw[StyleD] (0,0) -- (0,0);");
    EXPECT_EQ(l[2].rfind("\\path[StyleB]", 0), 0u);
    EXPECT_EQ(l[3], "\\draw[StyleD] (0,0) -- (0,0);");
    EXPECT_EQ(l[4], "\\MarkA{0.277778}{0}{0}{1.11111}");
}

TEST(LaTeXTikz3D, AutoFitCentresTheRegionAndFillsTheView)
{
    LaTeXTikz3D le;
    le.setView(50, rtl::RigidTf3f(0.7f, Vector3f(1, 1, 0).normalized(), Vector3f::nan()));
    le.setExportSize(10, 6);
    std::vector<Vector3f> corners;
    for (int i = 0; i < 8; ++i)
        corners.emplace_back(i & 1 ? 3.0f : 1.0f, i & 2 ? 1.0f : -1.0f, i & 4 ? 5.0f : 4.0f);
    le.addMarks(corners, "style={fill=black}", LaTeXTikz3D::latex_mark_dot);
    auto l = lines(body3(tex(le)));
    ASSERT_EQ(l.size(), 9u);
    double min_x = 1e9, max_x = -1e9, min_y = 1e9, max_y = -1e9;
    for (size_t i = 0; i < 8; ++i)
    {
        ASSERT_EQ(l[i].rfind("\\MarkA{", 0), 0u) << l[i];
        char *e = nullptr;
        double x = std::strtod(l[i].c_str() + 7, &e);
        ASSERT_EQ(std::string(e, 2), "}{") << l[i];
        double y = std::strtod(e + 2, nullptr);
        min_x = std::min(min_x, x);
        max_x = std::max(max_x, x);
        min_y = std::min(min_y, y);
        max_y = std::max(max_y, y);
    }
    // Inside the 10 x 6 picture, touching it on at least one side.
    EXPECT_GE(min_x, -5.001);
    EXPECT_LE(max_x, 5.001);
    EXPECT_GE(min_y, -3.001);
    EXPECT_LE(max_y, 3.001);
    EXPECT_TRUE(std::abs(max_x - 5) < 1e-3 || std::abs(min_x + 5) < 1e-3 || std::abs(max_y - 3) < 1e-3 ||
                std::abs(min_y + 3) < 1e-3);
}

TEST(LaTeXTikz3D, GeometryBehindTheCameraIsClipped)
{
    LaTeXTikz3D le;
    le.setView(90, lookDown());
    le.addLine(rtl::LineSegment3f(Vector3f(0, 0, 0), Vector3f(0, 1, 20)), "style={draw=red}");   // crosses z = 10
    le.addMark(Vector3f(0, 0, 15), "style={fill=red}", LaTeXTikz3D::latex_mark_dot);            // behind: dropped
    le.addFace(square(12, 1), "style={fill=green}", "", "");                                     // behind: dropped
    auto l = lines(body3(tex(le)));
    ASSERT_EQ(l.size(), 2u);
    auto c = coords(l[0]);
    ASSERT_EQ(c.size(), 2u);
    EXPECT_EQ(c[0], std::make_pair(0.0, 0.0));
    EXPECT_NEAR(c[1].second, 5.5, 1e-3);   // cut where the line leaves the frustum (1.1 x the half height)
}

TEST(LaTeXTikz3D, AxesAreCroppedToTheRegionAndLabelled)
{
    LaTeXTikz3D le;
    le.setView(90, lookDown());
    le.setGridAxisOverrun(LaTeXTikz3D::overrun_absolute, 0);
    le.setMinPlotRegion(Vector3f(-2, -1, 0), Vector3f(2, 1, 0));
    le.addAxis("style={draw=black}", "%.0f", LaTeXTikz3D::position_left, 1, Vector3f(0, 0, 0), Vector3f(1, 0, 0));
    std::string b = body3(tex(le));
    EXPECT_NE(b.find("\\draw[StyleA] (-1,0) -- (1,0);"), std::string::npos);
    EXPECT_NE(b.find("\\node[anchor=east, inner sep=1pt] at (-1,0) {$-2$};"), std::string::npos);
    EXPECT_NE(b.find("\\node[anchor=east, inner sep=1pt] at (1,0) {$2$};"), std::string::npos);
    EXPECT_EQ(count(b, "\\node["), 5u);

}

TEST(LaTeXTikz3D, NothingToDrawWritesNothing)
{
    // RTL (docs/reference.md, "LaTeXTikz3D"): without objects and without a min region writeTEX writes nothing (no
    // file, no text).
    namespace fs = std::filesystem;
    fs::path dir = fs::path(RTL_TEST_OUTPUT_DIR) / "latex" / "tikz3d-empty";
    fs::create_directories(dir);
    fs::path file = dir / "empty.tex";
    fs::remove(file);
    LaTeXTikz3D empty;
    empty.setView(60, Vector3f(1, 1, -1));
    empty.addAxis("style={draw=black}", "%.0f", LaTeXTikz3D::position_left, 1, Vector3f(0, 0, 0), Vector3f(1, 0, 0));
    empty.addMark(Vector3f(NAN, 0, 0), "style={fill=red}", LaTeXTikz3D::latex_mark_dot);   // ignored: not finite
    EXPECT_FALSE(empty.hasContent());
    empty.writeTEX(file.string());
    EXPECT_FALSE(fs::exists(file));
    std::ostringstream os;
    empty.writeTEX(os);
    EXPECT_EQ(os.str(), "");
    {
        std::ofstream(file) << "earlier";   // an existing file is left alone
    }
    empty.writeTEX(file.string());
    std::ifstream in(file);
    std::string kept((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    EXPECT_EQ(kept, "earlier");

    LaTeXTikz3D region;   // a min region alone is something to draw: an empty picture of the export size
    region.setMinPlotRegion(Vector3f(0, 0, 0), Vector3f(1, 1, 1));
    EXPECT_TRUE(region.hasContent());
    EXPECT_EQ(body3(tex(region)), "\\end{scope}\n");
    LaTeXTikz3D mark;
    mark.addMark(Vector3f(0, 0, 0), "style={fill=red}", LaTeXTikz3D::latex_mark_dot);
    EXPECT_TRUE(mark.hasContent());
    EXPECT_NE(tex(mark).find("\\begin{tikzpicture}"), std::string::npos);
    mark.clearData();
    EXPECT_FALSE(mark.hasContent());
    std::ostringstream os2;
    mark.writeTEX(os2);
    EXPECT_EQ(os2.str(), "");
}

TEST(LaTeXTikz3D, RepeatedWritesAreIdenticalAndFollowTheView)
{
    LaTeXTikz3D le;
    le.addFace(square(0, 1), "style={fill=green}", "style={fill=gray}", "style={draw=black}");
    le.addMark(Vector3f(0, 0, 1), "style={fill=red}", LaTeXTikz3D::latex_mark_dot);
    le.setView(40, Vector3f(1, 1, -1));
    std::string first = tex(le);
    EXPECT_EQ(tex(le), first);   // writing does not change the scene (LaTeXDoc grids write one object many times)
    le.setView(40, Vector3f(-1, 1, -1));
    std::string other = tex(le);
    EXPECT_NE(other, first);
    le.setView(40, Vector3f(1, 1, -1));
    EXPECT_EQ(tex(le), first);
    LaTeXTikz2D le2;
    le2.addPlot(std::vector<Vector2f>{{0, 0}, {1, 2}}, "style={draw=black}", "style={fill=red}",
                LaTeXTikz2D::latex_mark_dot);
    std::string f2 = tex(le2);
    EXPECT_EQ(tex(le2), f2);
}

TEST(LaTeXTable, WritesTheDocumentedLayout)
{
    // RTL (docs/reference.md, "LaTeXTable"): cells and caption as given, joined by " & ", each row ending with "\\"
    // (no space before it).
    LaTeXTable t;
    t.setColumnStyle("c|c");
    EXPECT_EQ(t.columnsStyle(), "c|c");
    t.setHeading({"Item\\_name", "50\\%"});
    t.setHeading({});   // ignored
    t.addHLine();
    t.addRow({"$10^{3}$", "\\textbf{x}"});
    t.addRow({});       // ignored
    std::ostringstream os;
    t.writeTable(os, "segments \\& $\\sigma$");
    writtenTables().emplace_back(t, "segments \\& $\\sigma$");
    EXPECT_EQ(os.str(), "\\begin{table}\n\\begin{center}\n\\begin{tabular}{c|c}\n"
                        "\tItem\\_name & 50\\%\\\\\n\t\\hline\n\t$10^{3}$ & \\textbf{x}\\\\\n"
                        "\\end{tabular}\n\\end{center}\n\\caption{segments \\& $\\sigma$}\n\\end{table}\n\n");
    LaTeXTable u;   // no column style: one centred column per cell; no caption
    u.addRow({"1", "2", "3"});
    std::ostringstream os2;
    u.writeTable(os2, "");
    writtenTables().emplace_back(u, "");
    EXPECT_EQ(os2.str(), "\\begin{table}\n\\begin{center}\n\\begin{tabular}{ccc}\n\t1 & 2 & 3\\\\\n"
                         "\\end{tabular}\n\\end{center}\n\\end{table}\n\n");
    EXPECT_EQ(u.tableString(""), os2.str());
    EXPECT_EQ(t.tableString("segments \\& $\\sigma$"), os.str());
}

TEST(LaTeXTable, EscapedVariantsTakePlainText)
{
    LaTeXTable t;
    t.setHeadingEscaped({"name_1", "50%"});
    t.setHeadingEscaped({});   // ignored
    t.addRowEscaped({"a&b", "{x}"});
    t.addRowEscaped({});       // ignored
    t.addRow({"$10^{3}$", "1"});   // plain and escaped rows mix
    std::ostringstream os;
    t.writeTable(os, rtl::LaTeX::escapeLaTeXCharacters("segments & stats"));
    writtenTables().emplace_back(t, rtl::LaTeX::escapeLaTeXCharacters("segments & stats"));
    EXPECT_EQ(os.str(), "\\begin{table}\n\\begin{center}\n\\begin{tabular}{cc}\n"
                        "\tname\\_1 & 50\\%\\\\\n\ta\\&b & \\{x\\}\\\\\n\t$10^{3}$ & 1\\\\\n"
                        "\\end{tabular}\n\\end{center}\n\\caption{segments \\& stats}\n\\end{table}\n\n");
}

// Keep this test last: it compiles what the tests above wrote (one pdflatex run, figures \input into one document).
namespace
{
    //! A figure for LaTeXDoc::addLE that is already written text.
    struct WrittenFigure
    {
        std::string text;
        void writeTEX(const std::string &file) const { std::ofstream(file) << text; }
    };
}

TEST(LaTeXTextCompiles, EveryDocumentAndTableWrittenAboveCompilesWithPdflatex)
{
    ASSERT_TRUE(rtl::LaTeXDoc::pdflatexAvailable())
            << "pdflatex is not on PATH: the LaTeX tests need it (install texlive-latex-base texlive-pictures "
               "texlive-latex-extra poppler-utils; ./run test does)";
    ASSERT_GE(written().size(), 20u) << "run the whole test program: this test compiles what the others wrote";
    ASSERT_EQ(writtenTables().size(), 3u);
    namespace fs = std::filesystem;
    fs::path dir = fs::path(RTL_TEST_OUTPUT_DIR) / "latex" / "text";
    fs::remove_all(dir);
    fs::remove_all(dir.string() + "_tmp_text");
    bool ok;
    std::string tmp;
    {
        rtl::LaTeXDoc doc(dir.string(), "text");
        doc.setInlineFigures(true);
        doc.setRemoveTmpDir([](const std::string &) { return true; });
        for (const auto &d : written())
        {
            WrittenFigure f{d};
            doc.addLE(f, "a figure of t\\_latex\\_text");   // captions are LaTeX
        }
        for (const auto &t : writtenTables())
            doc.addTable(t.first, t.second);
        tmp = doc.tmpDir();
        ok = doc.finish();
        EXPECT_TRUE(doc.problems().empty()) << doc.problems().front();
    }
    EXPECT_TRUE(ok);
    std::ifstream log(fs::path(tmp) / "text.log");
    std::string line, errors;
    int context = 0;
    while (std::getline(log, line))
    {
        if (!line.empty() && line[0] == '!')
            context = 3;
        if (context-- > 0)
            errors += line + "\n";
    }
    EXPECT_EQ(errors, "");
}
