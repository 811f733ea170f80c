// The SVG back-end of Drawing2D: a standalone SVG of the same drawing that LaTeXTikz2D writes as TikZ.
// Complexity: linear in the drawing's primitives, marks and polyline points. Output is deterministic (same
// drawing, same bytes) and independent of the locale.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <fstream>
#include <map>
#include <ostream>
#include <stdexcept>
#include <string>
#include <vector>

#include "rtl/io/Drawing2D.h"
#include "rtl/io/LaTeXUtility.h"
#include "rtl/io/SvgStyle.h"
#include "rtl/io/TextSink.h"

namespace rtl
{
    namespace detail
    {
        //! Writes one drawing: paper coordinates in cm (1 user unit = 1 cm), y pointing down.
        class SvgWriter
        {
        public:
            explicit SvgWriter(const Drawing2D &drawing)
                    : d(drawing), f(drawing.frame()), colors(drawing.registry().colorList())
            {
                x0 = f.min_x - f.ox;
                x1 = f.max_x + f.ox;
                y0 = f.min_y - f.oy;
                y1 = f.max_y + f.oy;
                // The view: the data frame, widened by the overrun where grids or axes reach it, or the clip region.
                double vx0 = f.min_x, vx1 = f.max_x, vy0 = f.min_y, vy1 = f.max_y;
                if (!d.grids().empty() || !d.axes().empty())
                {
                    vx0 = x0;
                    vx1 = x1;
                    vy0 = y0;
                    vy1 = y1;
                }
                if (d.clipped())
                {
                    std::vector<float> c = d.clipRegion();
                    vx0 = c[0];
                    vy0 = c[1];
                    vx1 = c[2];
                    vy1 = c[3];
                }
                left = vx0;
                top = vy1;
                // Margin: the border, room for marks at the edge, and for tick labels and descriptions.
                double max_scale = 1;
                for (const auto &m : d.markDefs())
                    max_scale = std::max(max_scale, static_cast<double>(std::abs(m.second.scale)));
                margin = d.border() + 2.0 * d.markRadius() * std::min(max_scale, 100.0);
                bool labels = !d.descriptionX().empty() || !d.descriptionY().empty();
                for (const auto &a : d.axes())
                    labels = labels || !a.format.empty();
                if (labels)
                    margin += 1.6;
                const double data_w = finiteOr((vx1 - vx0) * f.sx, 0), data_h = finiteOr((vy1 - vy0) * f.sy, 0);
                // Text nodes (a title above the data, a label at an edge) reach beyond the data: each side gets the
                // margin or, if more, room for the text boxes that cross it (estimated from the font size).
                pad_left = pad_right = pad_top = pad_bottom = margin;
                for (const auto &p : d.primitives())
                {
                    if (p.kind != Drawing2D::Kind::text || p.points.empty())
                        continue;
                    const auto [bx0, by0, bx1, by1] = textBox(p.text, style(p.style).anchor, X(p.points[0].first),
                                                             Y(p.points[0].second));
                    pad_left = std::max(pad_left, d.border() - bx0);
                    pad_top = std::max(pad_top, d.border() - by0);
                    pad_right = std::max(pad_right, bx1 - data_w + d.border());
                    pad_bottom = std::max(pad_bottom, by1 - data_h + d.border());
                }
                width = data_w + pad_left + pad_right;
                height = data_h + pad_top + pad_bottom;
            }

            //! Into a std::ostream or a std::string (TextSink.h).
            template<class Out>
            void write(Out &target)
            {
                detail::TextOut<Out> os{target};
                std::string body;
                if (d.clipped())
                {
                    std::vector<float> c = d.clipRegion();
                    defs += "<clipPath id=\"clip\"><rect x=\"" + num(X(c[0])) + "\" y=\"" + num(Y(c[3])) +
                            "\" width=\"" + num((c[2] - c[0]) * f.sx) + "\" height=\"" + num((c[3] - c[1]) * f.sy) +
                            "\"/></clipPath>\n";
                    body += "<g clip-path=\"url(#clip)\">\n";
                }
                gridsAndAxes(body);
                for (const auto &p : d.primitives())
                    primitive(p, body);
                if (d.clipped())
                    body += "</g>\n";
                descriptions(body);
                for (const auto &m : d.markDefs())
                    markDef(m.first, m.second);
                os << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
                   << "<svg xmlns=\"http://www.w3.org/2000/svg\" version=\"1.1\" width=\"" << num(width)
                   << "cm\" height=\"" << num(height) << "cm\" viewBox=\"0 0 " << num(width) << " " << num(height)
                   << "\" font-family=\"serif\" font-size=\"" << num(font_cm) << "\">\n";
                if (!defs.empty())
                    os << "<defs>\n" << defs << "</defs>\n";
                os << "<g transform=\"translate(" << num(pad_left) << "," << num(pad_top) << ")\">\n"
                   << body << "</g>\n</svg>\n";
            }

        private:
            static double finiteOr(double v, double fallback) { return std::isfinite(v) ? v : fallback; }
            static std::string num(double v) { return detail::number(finiteOr(v, 0)); }
            double X(double x) const { return finiteOr((x - left) * f.sx, 0); }
            double Y(double y) const { return finiteOr((top - y) * f.sy, 0); }
            std::string pt(double x, double y) const { return num(X(x)) + "," + num(Y(y)); }

            const SvgStyle &style(const std::string &name)
            {
                auto it = styles.find(name);
                if (it == styles.end())
                    it = styles.emplace(name, parseTikzStyle(d.registry().styleText(name), colors)).first;
                return it->second;
            }

            //! Presentation attributes; `filled_default`: \filldraw-like (fill with the draw colour if none given).
            std::string attributes(const SvgStyle &s, bool closed, bool filled_default = false, unsigned int arrows = 0)
            {
                std::string stroke = s.draw_none ? "none" : s.stroke.empty() ? (s.fill.empty() || filled_default ? "#000000" : "none") : s.stroke;
                std::string fill = "none";
                if (closed && !s.fill_none)
                    fill = !s.fill.empty() ? s.fill : filled_default ? (s.stroke.empty() ? "#000000" : s.stroke) : "none";
                std::string a = " stroke=\"" + stroke + "\" fill=\"" + fill + "\"";
                if (stroke != "none")
                {
                    a += " stroke-width=\"" + num(s.line_width_cm) + "\"";
                    std::string dash = dashArray(s.dash, s.line_width_cm);
                    if (!dash.empty())
                        a += " stroke-dasharray=\"" + dash + "\"";
                }
                if (s.opacity < 1)
                    a += " opacity=\"" + num(s.opacity) + "\"";
                if (s.fill_opacity < 1)
                    a += " fill-opacity=\"" + num(s.fill_opacity) + "\"";
                if (s.stroke_opacity < 1)
                    a += " stroke-opacity=\"" + num(s.stroke_opacity) + "\"";
                bool end = s.arrow_end || (arrows & Drawing2D::edge_arrow_end);
                bool beg = s.arrow_beg || (arrows & Drawing2D::edge_arrow_beg);
                if ((end || beg) && stroke != "none")
                {
                    std::string id = arrow(stroke);
                    if (end)
                        a += " marker-end=\"url(#" + id + ")\"";
                    if (beg)
                        a += " marker-start=\"url(#" + id + ")\"";
                }
                return a;
            }

            //! An arrow-tip marker in the stroke's colour (auto-start-reverse points the start tip backwards).
            std::string arrow(const std::string &color)
            {
                auto it = arrows.find(color);
                if (it != arrows.end())
                    return it->second;
                std::string id = "Arrow" + detail::indexToLetters(arrows.size());
                arrows.emplace(color, id);
                defs += "<marker id=\"" + id + "\" viewBox=\"0 0 10 10\" refX=\"9\" refY=\"5\" markerWidth=\"5\" "
                        "markerHeight=\"5\" orient=\"auto-start-reverse\"><path d=\"M0,0 L10,5 L0,10 z\" fill=\"" +
                        color + "\"/></marker>\n";
                return id;
            }

            //! One mark as a reusable group around the origin, sized by the mark radius times its scale.
            void markDef(const std::string &name, const Drawing2D::MarkDef &m)
            {
                const SvgStyle &s = style(m.style);
                double r = d.markRadius() * finiteOr(m.scale, 1);
                std::string id = name.substr(1), g = "<g id=\"" + id + "\">";
                std::string line = attributes(s, false), filled = attributes(s, true, true);
                auto seg = [&](double ax, double ay, double bx, double by) {
                    return "<line x1=\"" + num(ax) + "\" y1=\"" + num(ay) + "\" x2=\"" + num(bx) + "\" y2=\"" +
                           num(by) + "\"" + line + "/>";
                };
                if (m.templ == detail::tikz_mark_cross)
                    g += seg(-r, -r, r, r) + seg(-r, r, r, -r);
                else if (m.templ == detail::tikz_mark_mark)
                    g += seg(0, -r, 0, r);
                else if (m.templ == detail::tikz_mark_robot)
                    g += "<circle r=\"" + num(r) + "\"" + filled + "/>" + seg(0, 0, 2 * r, 0);
                else   // the dot, and user templates (TikZ code SVG cannot run) as dots
                    g += "<circle r=\"" + num(r) + "\"" + filled + "/>";
                defs += g + "</g>\n";
            }

            void primitive(const Drawing2D::Primitive &p, std::string &out)
            {
                using K = Drawing2D::Kind;
                const SvgStyle &s = style(p.style);
                auto points = [&]() {
                    std::string v;
                    for (size_t i = 0; i < p.points.size(); ++i)
                        v += (i ? " " : "") + pt(p.points[i].first, p.points[i].second);
                    return v;
                };
                double cx = p.points.empty() ? 0 : X(p.points[0].first), cy = p.points.empty() ? 0 : Y(p.points[0].second);
                switch (p.kind)
                {
                    case K::polyline:
                        out += "<polyline points=\"" + points() + "\"" + attributes(s, false) + "/>\n";
                        break;
                    case K::marks:
                        for (const auto &m : p.marks)
                        {
                            double dx = static_cast<double>(m.dx) * f.sx, dy = static_cast<double>(m.dy) * f.sy;
                            double deg = (dx == 0.0 && dy == 0.0) ? 0.0 : std::atan2(dy, dx) * 180.0 / detail::pi;
                            out += "<use href=\"#" + p.mark.substr(1) + "\" transform=\"translate(" + pt(m.x, m.y) +
                                   ")" + (deg != 0.0 ? " rotate(" + num(-deg) + ")" : std::string()) + "\"/>\n";
                        }
                        break;
                    case K::edge:
                        out += "<line x1=\"" + num(X(p.points[0].first)) + "\" y1=\"" + num(Y(p.points[0].second)) +
                               "\" x2=\"" + num(X(p.points[1].first)) + "\" y2=\"" + num(Y(p.points[1].second)) + "\"" +
                               attributes(s, false, false, p.options) + "/>\n";
                        break;
                    case K::polygon:
                        out += "<polygon points=\"" + points() + "\"" + attributes(s, true) + "/>\n";
                        break;
                    case K::rectangle:
                    {
                        double ax = X(p.points[0].first), bx = X(p.points[1].first);
                        double ay = Y(p.points[0].second), by = Y(p.points[1].second);
                        out += "<rect x=\"" + num(std::min(ax, bx)) + "\" y=\"" + num(std::min(ay, by)) +
                               "\" width=\"" + num(std::abs(bx - ax)) + "\" height=\"" + num(std::abs(by - ay)) + "\"" +
                               attributes(s, true) + "/>\n";
                        break;
                    }
                    case K::circle:
                        out += "<ellipse cx=\"" + num(cx) + "\" cy=\"" + num(cy) + "\" rx=\"" + num(p.r1 * f.sx) +
                               "\" ry=\"" + num(p.r1 * f.sy) + "\"" + attributes(s, true) + "/>\n";
                        break;
                    case K::ellipse:
                        // Rotated in data units, then scaled to paper: the stroke keeps its width.
                        out += "<ellipse transform=\"translate(" + num(cx) + "," + num(cy) + ") scale(" + num(f.sx) +
                               "," + num(-f.sy) + ") rotate(" + num(p.a1 * 180.0 / detail::pi) + ")\" rx=\"" +
                               num(p.r1) + "\" ry=\"" + num(p.r2) + "\" vector-effect=\"non-scaling-stroke\"" +
                               attributes(s, true) + "/>\n";
                        break;
                    case K::pie:
                        pie(p, s, cx, cy, out);
                        break;
                    case K::text:
                        text(xmlEscape(p.text), s, cx, cy, "", out);
                        break;
                }
            }

            void pie(const Drawing2D::Primitive &p, const SvgStyle &s, double cx, double cy, std::string &out)
            {
                double rx = p.r1 * f.sx, ry = p.r1 * f.sy, delta = static_cast<double>(p.a2) - p.a1;
                auto at = [&](double a) { return num(cx + rx * std::cos(a)) + "," + num(cy - ry * std::sin(a)); };
                std::string arc = " A" + num(rx) + "," + num(ry) + " 0 ";
                std::string path = "M" + num(cx) + "," + num(cy) + " L" + at(p.a1);
                if (std::abs(delta) >= 2 * detail::pi)   // a full turn: two half arcs
                    path += arc + "1 0 " + at(p.a1 + detail::pi) + arc + "1 0 " + at(p.a1);
                else
                    path += arc + (std::abs(delta) > detail::pi ? "1 " : "0 ") + (delta > 0 ? "0 " : "1 ") + at(p.a2);
                out += "<path d=\"" + path + " Z\"" + attributes(s, true) + "/>\n";
            }

            //! The box (x0, y0, x1, y1) a text node covers on paper: the font is 0.3514 cm (10 pt); a character is
            //! taken as 0.6 of it wide (serif fonts average less), a line as 1.25 of it high.
            static std::array<double, 4> textBox(const std::string &t, const std::string &anchor, double x, double y)
            {
                std::size_t chars = 0;
                for (unsigned char c : t)
                    chars += (c & 0xC0) != 0x80 ? 1 : 0;   // UTF-8: count code points, not bytes
                const double w = 0.6 * font_cm * static_cast<double>(chars), h = 1.25 * font_cm;
                const double left = anchor.find("west") != std::string::npos ? x
                                    : anchor.find("east") != std::string::npos ? x - w : x - w / 2;
                const double top = anchor.find("north") != std::string::npos ? y
                                   : anchor.find("south") != std::string::npos ? y - h : y - h / 2;
                return {left, top, left + w, top + h};
            }

            //! A text node: the TikZ anchor names the side of the text that sits at the point.
            void text(const std::string &t, const SvgStyle &s, double x, double y, const std::string &extra,
                      std::string &out, const std::string &anchor_override = "")
            {
                std::string anchor = anchor_override.empty() ? s.anchor : anchor_override;
                std::string h = anchor.find("west") != std::string::npos ? "start"
                                : anchor.find("east") != std::string::npos ? "end" : "middle";
                std::string v = anchor.find("north") != std::string::npos ? "hanging"
                                : anchor.find("south") != std::string::npos ? "text-after-edge" : "central";
                std::string fill = s.text_color.empty() ? "#000000" : s.text_color;
                out += "<text x=\"" + num(x) + "\" y=\"" + num(y) + "\" text-anchor=\"" + h +
                       "\" dominant-baseline=\"" + v + "\" fill=\"" + fill + "\"" + extra + ">" + t + "</text>\n";
            }

            //! A numberToLatexString label ("$1.5 \cdot 10^{3}$") as SVG text: 1.5·10 with a raised exponent.
            static std::string labelText(const std::string &latex)
            {
                std::string s;
                for (char c : latex)
                    if (c != '$')
                        s += c;
                std::string out;
                size_t cdot = s.find(" \\cdot ");
                std::string mantissa = s, exponent;
                size_t pow = s.find("10^{");
                if (pow != std::string::npos && s.back() == '}')
                {
                    exponent = s.substr(pow + 4, s.size() - pow - 5);
                    mantissa = cdot != std::string::npos ? s.substr(0, cdot) + "\xc2\xb7" + "10" : s.substr(0, pow) + "10";
                }
                std::string m;
                for (size_t i = 0; i < mantissa.size(); ++i)
                    if (mantissa[i] != '\\')   // escaped literals (\% \#) lose their backslash
                        m += mantissa[i];
                out = xmlEscape(m);
                if (!exponent.empty())
                    out += "<tspan baseline-shift=\"super\" font-size=\"0.25\">" + xmlEscape(exponent) + "</tspan>";
                return out;
            }

            void gridsAndAxes(std::string &out)
            {
                for (const auto &g : d.grids())
                {
                    std::string a = attributes(style(g.style), false);
                    for (double v : g.horizontal ? Drawing2D::ticks(y0, y1, g.tick) : Drawing2D::ticks(x0, x1, g.tick))
                    {
                        double ax = g.horizontal ? x0 : v, ay = g.horizontal ? v : y0;
                        double bx = g.horizontal ? x1 : v, by = g.horizontal ? v : y1;
                        out += "<line x1=\"" + num(X(ax)) + "\" y1=\"" + num(Y(ay)) + "\" x2=\"" + num(X(bx)) +
                               "\" y2=\"" + num(Y(by)) + "\"" + a + "/>\n";
                    }
                }
                for (const auto &ax : d.axes())
                {
                    const SvgStyle &s = style(ax.style);
                    std::string a = attributes(s, false);
                    bool log = (ax.is_x ? d.axisTypeX() : d.axisTypeY()) == Drawing2D::axis_type_log10;
                    double c = ax.crossing;
                    if (ax.is_x)
                        out += "<line x1=\"" + num(X(x0)) + "\" y1=\"" + num(Y(c)) + "\" x2=\"" + num(X(x1)) +
                               "\" y2=\"" + num(Y(c)) + "\"" + a + "/>\n";
                    else
                        out += "<line x1=\"" + num(X(c)) + "\" y1=\"" + num(Y(y0)) + "\" x2=\"" + num(X(c)) +
                               "\" y2=\"" + num(Y(y1)) + "\"" + a + "/>\n";
                    SvgStyle tick_style = s;
                    tick_style.arrow_beg = tick_style.arrow_end = false;
                    std::string ta = attributes(tick_style, false);
                    for (double v : ax.is_x ? Drawing2D::ticks(x0, x1, ax.tick) : Drawing2D::ticks(y0, y1, ax.tick))
                    {
                        // Ticks are 0.1 cm long on paper, labels touch the tick end on the side the flags name.
                        double px = ax.is_x ? X(v) : X(c), py = ax.is_x ? Y(c) : Y(v);
                        if (ax.is_x)
                            out += "<line x1=\"" + num(px) + "\" y1=\"" + num(py - 0.05) + "\" x2=\"" + num(px) +
                                   "\" y2=\"" + num(py + 0.05) + "\"" + ta + "/>\n";
                        else
                            out += "<line x1=\"" + num(px - 0.05) + "\" y1=\"" + num(py) + "\" x2=\"" + num(px + 0.05) +
                                   "\" y2=\"" + num(py) + "\"" + ta + "/>\n";
                        double value = log ? std::pow(10.0, v) : v;   // no label beyond double on log axes
                        std::string label = ax.format.empty() || !std::isfinite(value) || (log && !(value > 0))
                                                    ? ""
                                                    : detail::numberToLatexString(value, ax.format);
                        if (label.empty())
                            continue;
                        double lx = px, ly = py;
                        if (ax.position & Drawing2D::position_above)
                            ly -= ax.is_x ? 0.05 : 0.0;
                        else if (ax.position & Drawing2D::position_below)
                            ly += ax.is_x ? 0.05 : 0.0;
                        // A label hung below its tick (SVG's "hanging" baseline) has its exponent raised above the
                        // mantissa's top, onto the tick: TikZ puts the top of the whole node there, so move it down.
                        if ((ax.position & Drawing2D::position_below) && label.find("10^{") != std::string::npos)
                            ly += exponent_rise_cm;
                        if (ax.position & Drawing2D::position_right)
                            lx += ax.is_x ? 0.0 : 0.05;
                        else if (ax.position & Drawing2D::position_left)
                            lx -= ax.is_x ? 0.0 : 0.05;
                        SvgStyle label_style;
                        text(labelText(label), label_style, lx, ly, "", out, detail::tikzAnchor(ax.position));
                    }
                }
            }

            void descriptions(std::string &out)
            {
                SvgStyle plain;
                if (!d.descriptionX().empty())
                    text(xmlEscape(d.descriptionX()), plain, X((x0 + x1) / 2), Y(y0) + 0.7, "", out, "north");
                if (!d.descriptionY().empty())
                {
                    double x = X(x0) - 1.2, y = Y((y0 + y1) / 2);
                    text(xmlEscape(d.descriptionY()), plain, x, y,
                         " transform=\"rotate(-90 " + num(x) + " " + num(y) + ")\"", out, "south");
                }
            }

            const Drawing2D &d;
            Drawing2D::Frame f;
            ColorResolver colors;
            std::map<std::string, SvgStyle> styles;
            std::map<std::string, std::string> arrows;
            std::string defs;
            static constexpr double font_cm = 0.3514;   // the document's font-size (10 pt)
            // How far an exponent (font-size 0.25 cm, baseline-shift super) reaches above a 10 pt mantissa's top.
            static constexpr double exponent_rise_cm = 0.1;
            double x0, x1, y0, y1, left, top, margin, width, height, pad_left, pad_right, pad_top, pad_bottom;
        };
    }

    //! Writes `d` as a standalone SVG: width and height in cm, a viewBox in cm, the same primitives, marks, grids,
    //! axes, labels and clip region as the TikZ back-end. Styles are translated by detail::parseTikzStyle (draw,
    //! fill, color, line width and thickness keys, dash patterns, opacities, arrow tips, anchors; colours: xcolor
    //! base names, saveColor specs rgb/RGB/hsb/HTML/gray/cmyk and mixes like red!50!blue); other keys are ignored.
    //! User mark templates (TikZ code) are drawn as dots. Text is XML-escaped (and made valid UTF-8).
    inline void writeSvg(const Drawing2D &d, std::ostream &os)
    {
        detail::SvgWriter(d).write(os);
    }
    //! What writeSvg writes, as a string, without any stream.
    inline std::string svgString(const Drawing2D &d)
    {
        return detail::textString([&d](std::string &out) { detail::SvgWriter(d).write(out); });
    }

    //! A Drawing2D with SVG output (the same drawing calls as LaTeXTikz2D).
    class Svg2D : public Drawing2D
    {
    public:
        explicit Svg2D(unsigned int axis_x = Svg2D::axis_type_linear, unsigned int axis_y = Svg2D::axis_type_linear)
                : Drawing2D(axis_x, axis_y)
        {
        }

        void writeSVG(std::ostream &os) const { writeSvg(*this, os); }
        //! Throws std::runtime_error if the file cannot be written.
        void writeSVG(const std::string &file_name) const
        {
            std::ofstream ofs(file_name);
            if (!ofs)
                throw std::runtime_error("Svg2D::writeSVG: cannot open '" + file_name + "' for writing");
            writeSVG(ofs);
            if (!ofs)
                throw std::runtime_error("Svg2D::writeSVG: writing '" + file_name + "' failed");
        }
    };
}
