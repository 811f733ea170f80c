// Drawings that exercise every LaTeXTikz2D / Drawing2D call, shared by the TikZ golden test (the output of the
// pre-refactoring writer is kept in tests/io/golden/) and the SVG tests, so that both back-ends see the same calls.
#pragma once

#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "rtl/Core.h"

namespace tikz2d_scenes
{
    using rtl::LineSegment2f;
    using rtl::Vector2f;

    //! Every primitive, mark template, style form, colour spec, axis, grid and description on linear axes.
    template<class D>
    void drawLinear(D &d)
    {
        const float nan = std::numeric_limits<float>::quiet_NaN();
        d.setSize(12.0f, 8.0f);
        d.setBorder(0.2f);
        d.setMarkRadius(0.05f);
        d.setGridAxisOverrun(D::overrun_absolute, 0.5f);
        std::string red = d.saveColor("{rgb}{1,0,0}");
        std::string green = d.saveColor("{hsb}{0.3,0.8,0.5}");
        std::string html = d.saveColor("{HTML}{1F77B4}");
        d.saveColor("{rgb}{1,0,0}");   // the same spec again: no new colour
        d.addGridH("style={draw=gray!30,thin}", 1.0f);
        d.addGridV("draw=gray,dotted", 2.0f);
        d.addAxisX("style={draw=black,->}", "%.1f", D::position_below, 2.0f);
        d.addAxisY("style={draw=black,->}", "%d", D::position_left | D::position_below, 1.0f, -1.0f);
        d.addDescriptionX("x in m & 50% of $#_{}~^\\<>");
        d.addDescriptionY("y");
        std::vector<float> x, y;
        for (int i = 0; i < 12; ++i)
        {
            x.push_back(0.5f * static_cast<float>(i) - 1.0f);
            y.push_back(std::sin(0.7f * static_cast<float>(i)) * 3.0f + 2.0f);
        }
        d.addPlot(x, y, "style={draw=" + red + ",line width=0.8pt}", "style={draw=" + red + "}", D::latex_mark_cross);
        std::vector<Vector2f> v = {Vector2f(0, 0), Vector2f(1, 1), Vector2f(nan, 1), Vector2f(2, 0.5f), Vector2f(3, 1.5f),
                                   Vector2f(4, 1), Vector2f(5, nan), Vector2f(6, 2)};
        d.addPlot(v, "style={draw=" + green + ",dashed}", "style={fill=" + green + ",draw=black}", D::latex_mark_dot, 1.5f);
        d.addPlot(v, "", "style={fill=" + html + "}", D::latex_mark_robot, 2.0f);
        d.addPlot(v, "", "draw=blue", D::latex_mark_mark);
        d.addPlot(v, "", "draw=blue", "\\draw[@style] (0,0) rectangle (\\MarkRadius,\\MarkRadius);");
        d.addPlot(std::vector<float>{1, 2}, std::vector<float>{1}, "draw=red");   // size mismatch: nothing
        std::vector<LineSegment2f> edges = {LineSegment2f(Vector2f(0, 3), Vector2f(1, 4)),
                                            LineSegment2f(Vector2f(1, 4), Vector2f(2, 3)),
                                            LineSegment2f(Vector2f(nan, 4), Vector2f(2, 3))};
        d.addEdges(edges, "draw=black", 0);
        d.addEdges(edges, "draw=black", D::edge_arrow_end);
        d.addEdge(edges[0], "draw=black", D::edge_arrow_beg);
        d.addEdge(edges[1], "draw=black", D::edge_arrow_beg | D::edge_arrow_end);
        d.addLine(Vector2f(-1, -1), Vector2f(5, 5), "style={draw=orange,opacity=0.5}");
        d.addLine(edges[1], "draw=orange");
        d.addLines(edges, "draw=purple");
        d.addTriangle(Vector2f(0, 0), Vector2f(1, 0), Vector2f(0.5f, 1), "style={fill=yellow,draw=black}");
        d.addRectangle(Vector2f(2, 2), Vector2f(3, 3.5f), "style={fill=" + red + ",fill opacity=0.3}");
        d.addQuadrilateral(Vector2f(3, 0), Vector2f(4, 0), Vector2f(4.5f, 1), Vector2f(3.2f, 1.2f), "draw=cyan");
        d.addCircle(Vector2f(1, 1), 0.75f, "style={draw=magenta,thick}");
        d.addCircle(Vector2f(1, 1), -0.25f, "draw=magenta");
        d.addEllipse(Vector2f(4, 3), 1.0f, 0.5f, 0.6f, "style={draw=brown}");
        d.addPie(Vector2f(-0.5f, 4), 0.8f, 0.2f, 1.9f, "style={fill=teal,draw=black}");
        d.addText("label: 5% & $x_1$ {a} #2 ~ ^ \\ <b>", "style={anchor=west}", Vector2f(0.2f, 4.5f));
        d.addText("plain", "", Vector2f(5, 4));
        d.addText("not drawn", "", Vector2f(nan, 4));
    }

    //! A polyline longer than one TikZ path (500 points) with marks rotated along it.
    template<class D>
    void drawLongPolyline(D &d)
    {
        std::vector<Vector2f> v;
        for (int i = 0; i < 1203; ++i)
        {
            float t = static_cast<float>(i) * 0.01f;
            v.emplace_back(1000.0f + t * 80.0f, 750.0f + 100.0f * std::cos(t));
        }
        d.addPlot(v, "draw=black", "draw=red", D::latex_mark_mark, 0.5f);
        d.addAxisX("draw=black", "%g", D::position_below, 20.0f, 750.0f);
        d.addAxisY("draw=black", "%.0f", D::position_left, 25.0f, 1000.0f);
    }

    //! log10 axes: decade ticks, non-positive values dropped, labels with exponents.
    template<class D>
    void drawLog(D &d)
    {
        std::vector<float> x, y;
        for (int i = -2; i < 30; ++i)
        {
            x.push_back(std::pow(10.0f, 0.25f * static_cast<float>(i)));
            y.push_back(i == 5 ? -1.0f : 3.0f * std::pow(10.0f, 0.1f * static_cast<float>(i)));
        }
        d.addGridV("draw=gray", 1.0f);
        d.addGridH("draw=gray", 1.0f);
        d.addAxisX("draw=black", "%.0e", D::position_below, 1.0f, 1.0f);
        d.addAxisY("draw=black", "%g", D::position_left, 1.0f, 1.0f);
        d.addPlot(x, y, "draw=blue", "draw=blue", D::latex_mark_cross);
        d.addCircle(Vector2f(10, 10), 0.2f, "draw=red");
        d.addText("decades", "anchor=south", Vector2f(100, 100));
    }

    //! Clip region, min plot region, user scales and relative overrun.
    template<class D>
    void drawClipped(D &d)
    {
        d.setSize(6.0f, 4.0f);
        d.setScaleX(2.0f);
        d.setScaleY(0.5f);
        d.setGridAxisOverrun(D::overrun_relative, 10.0f);
        d.setMinPlotRegion(-5.0f, -5.0f, 5.0f, 5.0f);
        d.setClipRegion(-2.0f, -3.0f, 2.0f, 3.0f);
        d.addGridH("draw=gray", 1.0f);
        d.addAxisX("draw=black", "%.2f", D::position_above | D::position_right, 2.5f);
        d.addCircle(Vector2f(0, 0), 4.0f, "fill=blue!20");
        d.addRectangle(Vector2f(-10, -10), Vector2f(10, 10), "draw=red");
    }
}
