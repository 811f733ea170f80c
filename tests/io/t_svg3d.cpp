// Svg3D: the SVG back-end of Drawing3D. One scene (crossing faces split by the depth order, lines cut by them,
// marks, an axis with labels) is written as TikZ by LaTeXTikz3D and as SVG from the same drawing: the SVG is
// well-formed XML (xml_check.h), paints the same pieces in the same back-to-front order, with the styles' colours.
#include <gtest/gtest.h>

#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "rtl/io/LaTeXTikz3D.h"
#include "rtl/io/Svg3D.h"
#include "xml_check.h"

using rtl::LaTeXTikz3D;
using rtl::Vector3f;

namespace
{
    size_t count(const std::string &s, const std::string &what)
    {
        size_t n = 0;
        for (size_t p = s.find(what); p != std::string::npos; p = s.find(what, p + 1))
            ++n;
        return n;
    }
    //! Two faces crossing each other, a line through both, marks on either side and an axis with labels.
    void scene(LaTeXTikz3D &le)
    {
        le.addLine(rtl::LineSegment3f(Vector3f(-2, 0, 0.2f), Vector3f(2, 0.3f, -0.2f)), "draw=orange");   // StyleA
        rtl::Polygon3Df a(Vector3f(0, 0, 1), 0), b(Vector3f(-1, 0, 0), 0);   // b turns its back to the camera
        for (auto q : {std::pair<float, float>{-1, -1}, {1, -1}, {1, 1}, {-1, 1}})
        {
            a.addPoint(Vector3f(q.first, q.second, 0));
            b.addPoint(Vector3f(0, q.first, q.second));
        }
        le.addFace(std::vector<rtl::Polygon3Df>{a, b}, "fill=red", "fill=blue", "draw=black");            // B, C, D
        for (float z : {-0.5f, 0.5f})
            le.addMark(Vector3f(0.5f, 0.5f, z), "fill=green", LaTeXTikz3D::latex_mark_dot);               // StyleE
        le.addMark(Vector3f(-0.5f, -0.5f, 0.7f), "fill=green", LaTeXTikz3D::latex_mark_dot);
        le.addAxis("draw=gray", "%.0f", LaTeXTikz3D::position_below, 1, Vector3f(0, 0, 0), Vector3f(1, 0, 0));  // F
        le.setView(50, Vector3f(-1, -0.7f, -0.5f));
    }

    //! The painting sequence of the tikzpicture: P a face fill, O an outline run, L a line, M a mark, T a label.
    std::string tikzSequence(const std::string &tikz)
    {
        std::string seq;
        std::istringstream in(tikz);
        bool inside = false;
        for (std::string l; std::getline(in, l);)
        {
            if (l.rfind("\\clip", 0) == 0)
                inside = true;
            else if (l == "\\end{scope}")
                inside = false;
            else if (!inside)
                continue;
            else if (l.rfind("\\path[StyleB]", 0) == 0 || l.rfind("\\path[StyleC]", 0) == 0)
                seq += 'P';
            else if (l.rfind("\\draw[StyleD]", 0) == 0)   // a run starts after "]" or after a point, not after "--"
                seq += std::string(count(l, "] (") + count(l, ") ("), 'O');
            else if (l.rfind("\\draw[StyleA]", 0) == 0 || l.rfind("\\draw[StyleF]", 0) == 0)
                seq += 'L';
            else if (l.rfind("\\MarkA{", 0) == 0)
                seq += 'M';
            else if (l.rfind("\\node[anchor=north", 0) == 0)
                seq += 'T';
            else
                ADD_FAILURE() << "unexpected TikZ line: " << l;
        }
        return seq;
    }

    std::string svgSequence(const std::string &svg)
    {
        std::string seq;
        const std::regex e("<(polygon|polyline|line|circle|text)[ >]");
        for (auto it = std::sregex_iterator(svg.begin(), svg.end(), e); it != std::sregex_iterator(); ++it)
        {
            const std::string n = (*it)[1];
            seq += n == "polygon" ? 'P' : n == "polyline" ? 'O' : n == "line" ? 'L' : n == "circle" ? 'M' : 'T';
        }
        return seq;
    }

}

TEST(Svg3D, PaintsTheSamePiecesInTheSameOrderAsTheTikzWriter)
{
    LaTeXTikz3D le;
    scene(le);
    const std::string tikz = le.tikzString(), svg = rtl::svg3DString(le.drawing());
    const xml_check::Result r = xml_check::check(svg);
    ASSERT_TRUE(r.ok) << r.error;
    EXPECT_EQ(r.elements.at("svg"), 1u);

    const std::string ts = tikzSequence(tikz), ss = svgSequence(svg);
    EXPECT_EQ(ts, ss);
    // The crossing faces are split (more than two fills), the marks are all visible, the axis has labels.
    EXPECT_GT(count(ts, "P"), 2u);
    EXPECT_EQ(count(ts, "M"), 3u);
    EXPECT_GE(count(ts, "T"), 2u);
    EXPECT_EQ(r.elements.at("polygon"), count(tikz, "\\path[Style"));
    EXPECT_EQ(r.elements.at("circle"), count(tikz, "\\MarkA{"));

    // Colours: each fill as often as its TikZ style, the marks green, the lines orange and grey, outlines black.
    EXPECT_EQ(count(svg, "<polygon") , count(svg, "fill=\"#ff0000\"") + count(svg, "fill=\"#0000ff\""));
    EXPECT_EQ(count(svg, "fill=\"#ff0000\""), count(tikz, "\\path[StyleB]"));
    EXPECT_EQ(count(svg, "fill=\"#0000ff\""), count(tikz, "\\path[StyleC]"));
    EXPECT_EQ(count(svg, "fill=\"#00ff00\""), 3u);
    EXPECT_EQ(count(svg, "<line") , count(svg, "stroke=\"#ff8000\"") + count(svg, "stroke=\"#808080\""));
    EXPECT_EQ(count(svg, "<polyline"), count(svg, "stroke=\"#000000\""));
    EXPECT_GT(count(tikz, "\\path[StyleB]"), 0u);
    EXPECT_GT(count(tikz, "\\path[StyleC]"), 0u);
}

TEST(Svg3D, APointProjectsToTheSamePositionAsInTikz)
{
    LaTeXTikz3D le;
    le.setExportSize(8, 6);
    le.setBorder(0.5f);
    le.addMark(Vector3f(1, 2, 3), "fill=red", LaTeXTikz3D::latex_mark_dot);
    le.addMark(Vector3f(-2, 1, 0), "fill=red", LaTeXTikz3D::latex_mark_dot);
    le.setView(60, Vector3f(0.3f, -1, -0.4f));
    const std::string tikz = le.tikzString(), svg = rtl::svg3DString(le.drawing());
    ASSERT_TRUE(xml_check::check(svg).ok);
    std::smatch mt, ms;
    ASSERT_TRUE(std::regex_search(tikz, mt, std::regex("\\\\MarkA\\{([-0-9.e]+)\\}\\{([-0-9.e]+)\\}")));
    ASSERT_TRUE(std::regex_search(svg, ms, std::regex("<circle cx=\"([-0-9.e]+)\" cy=\"([-0-9.e]+)\"")));
    EXPECT_NEAR(std::stod(ms[1]), std::stod(mt[1]), 1e-9);
    EXPECT_NEAR(std::stod(ms[2]), -std::stod(mt[2]), 1e-9);   // y down in SVG
    EXPECT_NE(svg.find("width=\"9cm\" height=\"7cm\""), std::string::npos);   // picture plus two borders
    EXPECT_NE(svg.find("translate(4.5,3.5)"), std::string::npos);             // centre
}

TEST(Svg3D, AnEmptySceneIsAnEmptyPictureOfTheExportSize)
{
    LaTeXTikz3D le;
    const std::string svg = rtl::svg3DString(le.drawing());
    const xml_check::Result r = xml_check::check(svg);
    ASSERT_TRUE(r.ok) << r.error;
    EXPECT_EQ(r.elements.count("polygon") + r.elements.count("line") + r.elements.count("circle"), 0u);
    EXPECT_NE(svg.find("width=\"10.2cm\""), std::string::npos);
}
