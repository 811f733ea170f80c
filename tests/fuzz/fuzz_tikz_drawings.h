// The TikZ harnesses' decoders (fuzz_tikz2d.cpp, fuzz_tikz3d.cpp): fuzz bytes -> a 2D drawing (Svg2D) or a 3D scene
// (LaTeXTikz3D). Shared with tests/io/t_tikz_fuzz_sample.cpp, which compiles what they decode with pdflatex.
#pragma once

#include <cstddef>
#include <cstdint>
#include <exception>
#include <string>
#include <vector>

#include "fuzz_tikz_input.h"
#include "rtl/io/LaTeXTikz2D.h"
#include "rtl/io/LaTeXTikz3D.h"
#include "rtl/io/Svg2D.h"

namespace fuzz_tikz
{
    //! A decoded 2D drawing and what its user texts bring into each output (one line per text, so that words do
    //! not join across texts): "nan" in a label is a finding, in a user's text not.
    struct Drawing2DCase
    {
        rtl::Svg2D d;
        std::string tex_texts, xml_texts;
    };

    //! The first byte picks the axis types (and a tiny mark budget: the thinning path and its note), then up to 64
    //! drawing calls.
    inline Drawing2DCase decodeDrawing2D(const uint8_t *data, size_t size)
    {
        using rtl::Vector2f;
        Reader in(data, size);
        uint8_t axes = in.byte();
        Drawing2DCase c{rtl::Svg2D(axes & 1, (axes >> 1) & 1), "", ""};
        rtl::Svg2D &d = c.d;
        if (axes & 4)
            d.setTexMarkLimit(1 + (axes >> 3));   // tiny budgets (1..32 marks)
        size_t grids = 0, ops = 0;
        auto v2 = [&]() { float x = in.value(); return Vector2f(x, in.value()); };
        auto text = [&]() {
            std::string t = in.text();
            c.tex_texts += rtl::LaTeX::escapeLaTeXCharacters(t) + "\n";
            c.xml_texts += rtl::detail::xmlEscape(t) + "\n";
            return t;
        };
        while (!in.empty() && ops++ < 64)
        {
            switch (in.byte() % 24)
            {
                case 0: d.setSize(in.value(), in.value()); break;
                case 1: d.setBorder(in.value()); break;
                case 2: d.setMarkRadius(in.value()); break;
                case 3: d.setGridAxisOverrun(in.byte() & 1, in.value()); break;
                case 4: d.setScaleX(in.value()); break;
                case 5: d.setScaleY(in.value()); break;
                case 6: { float a = in.value(), b = in.value(), e = in.value(); d.setClipRegion(a, b, e, in.value()); break; }
                case 7: { float a = in.value(), b = in.value(), e = in.value(); d.setMinPlotRegion(a, b, e, in.value()); break; }
                case 8:
                    if (grids++ < 6)
                        (in.byte() & 1) ? d.addGridH(in.pick(styles), in.value()) : d.addGridV(in.pick(styles), in.value());
                    break;
                case 9:
                    if (grids++ < 6)
                    {
                        bool x = in.byte() & 1;
                        std::string st = in.pick(styles), fmt = in.pick(formats);
                        unsigned pos = in.byte() & 15;
                        float tick = in.value();
                        x ? d.addAxisX(st, fmt, pos, tick, in.value()) : d.addAxisY(st, fmt, pos, tick, in.value());
                    }
                    break;
                case 10: { std::string t = text(); (in.byte() & 1) ? d.addDescriptionX(t) : d.addDescriptionY(t); break; }
                case 11:
                {
                    std::vector<Vector2f> v(in.byte() % 40);
                    for (auto &p : v)
                        p = v2();
                    std::string line = in.pick(styles), mark_style = in.pick(styles);
                    const char *const marks[] = {rtl::Drawing2D::latex_mark_cross, rtl::Drawing2D::latex_mark_dot,
                                                 rtl::Drawing2D::latex_mark_mark, rtl::Drawing2D::latex_mark_robot,
                                                 rtl::Drawing2D::latex_mark_blank};
                    d.addPlot(v, line, mark_style, in.pick(marks), in.value());
                    break;
                }
                case 12:
                {
                    std::vector<float> x(in.byte() % 20), y(in.byte() % 2 ? x.size() : x.size() + 1);
                    for (auto &a : x)
                        a = in.value();
                    for (auto &a : y)
                        a = in.value();
                    d.addPlot(x, y, in.pick(styles), in.pick(styles), rtl::Drawing2D::latex_mark_cross);
                    break;
                }
                case 13: { Vector2f a = v2(); d.addEdge(rtl::LineSegment2f(a, v2()), in.pick(styles), in.byte() & 3); break; }
                case 14: { Vector2f a = v2(); d.addLine(a, v2(), in.pick(styles)); break; }
                case 15: { Vector2f a = v2(), b = v2(); d.addTriangle(a, b, v2(), in.pick(styles)); break; }
                case 16: { Vector2f a = v2(); d.addRectangle(a, v2(), in.pick(styles)); break; }
                case 17: { Vector2f a = v2(), b = v2(), e = v2(); d.addQuadrilateral(a, b, e, v2(), in.pick(styles)); break; }
                case 18: { Vector2f a = v2(); d.addCircle(a, in.value(), in.pick(styles)); break; }
                case 19: { Vector2f a = v2(); float rx = in.value(), ry = in.value(); d.addEllipse(a, rx, ry, in.value(), in.pick(styles)); break; }
                case 20: { Vector2f a = v2(); float r = in.value(), b = in.value(); d.addPie(a, r, b, in.value(), in.pick(styles)); break; }
                case 21: { std::string t = text(); d.addText(t, in.pick(styles), v2()); break; }
                case 22: d.saveColor(in.pick(colors)); break;
                case 23: (in.byte() & 1) ? d.clearData() : d.clearAll(); break;
            }
        }
        return c;
    }

    //! Up to 48 scene calls: marks, lines, faces, axes, regions, views and export settings.
    inline rtl::LaTeXTikz3D decodeScene3D(const uint8_t *data, size_t size)
    {
        using rtl::Vector3f;
        Reader in(data, size);
        rtl::LaTeXTikz3D d;
        size_t faces = 0, axes = 0, ops = 0;
        auto v3 = [&]() { float x = in.value(), y = in.value(); return Vector3f(x, y, in.value()); };
        const char *const marks[] = {rtl::LaTeXTikz3D::latex_mark_cross, rtl::LaTeXTikz3D::latex_mark_dot,
                                     rtl::LaTeXTikz3D::latex_mark_robot, rtl::LaTeXTikz3D::latex_mark_blank};
        while (!in.empty() && ops++ < 48)
        {
            switch (in.byte() % 14)
            {
                case 0: d.setExportSize(in.value(), in.value()); break;
                case 1: { float a = in.value(), b = in.value(), c = in.value(); d.setExportClipping(a, b, c, in.value()); break; }
                case 2: { float fov = in.value(); d.setView(fov, v3()); break; }
                case 3: d.setBorder(in.value()); break;
                case 4: d.setGridAxisOverrun(in.byte() & 1, in.value()); break;
                case 5: { Vector3f a = v3(); d.setMaxPlotRegion(a, v3()); break; }
                case 6: { Vector3f a = v3(); d.setMinPlotRegion(a, v3()); break; }
                case 7: { Vector3f p = v3(); float rot = in.value(); d.addMark(p, in.pick(styles), in.pick(marks), rot, in.value()); break; }
                case 8: { Vector3f a = v3(); d.addLine(rtl::LineSegment3f(a, v3()), in.pick(styles)); break; }
                case 9:
                    if (faces++ < 12)
                    {
                        Vector3f n = v3();
                        rtl::Polygon3Df f(n, in.value());
                        size_t k = 3 + in.byte() % 4;
                        for (size_t i = 0; i < k; ++i)
                            f.addPoint(v3());
                        d.addFace(f, in.pick(styles), in.pick(styles), in.pick(styles));
                    }
                    break;
                case 10:
                    if (axes++ < 4)
                    {
                        std::string st = in.pick(styles), fmt = in.pick(formats);
                        unsigned pos = in.byte() & 15;
                        float tick = in.value();
                        Vector3f a = v3();
                        d.addAxis(st, fmt, pos, tick, a, v3());
                    }
                    break;
                case 11: d.setFrameStyle(in.pick(styles)); break;
                case 12: d.saveColor(in.pick(colors)); break;
                case 13: (in.byte() & 1) ? d.clearData() : d.clearAll(); break;
            }
        }
        return d;
    }

    //! Whether a std::length_error is the writers' refusal of a picture beyond TeX's dimensions
    //! (detail::refuseBeyondTex), as opposed to the mark budget's.
    inline bool beyondTex(const std::exception &e)
    {
        return std::string(e.what()).find("beyond TeX's dimensions") != std::string::npos;
    }
}
