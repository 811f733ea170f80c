// The TikZ back-end of Drawing2D: the standalone document or only the tikzpicture, with the
// conventions of RTL's LaTeXTikz2D (docs/reference.md, "LaTeXTikz2D").
#pragma once

#include <algorithm>
#include <cmath>
#include <ostream>
#include <string>
#include <vector>

#include "rtl/io/Drawing2D.h"
#include "rtl/io/LaTeXTikzCommon.h"
#include "rtl/io/LaTeXUtility.h"
#include "rtl/io/TextSink.h"
#include "rtl/io/TikzBudget.h"

namespace rtl
{
    namespace detail
    {
        //! How data coordinates become TikZ coordinates. Normally (`paper` false) the picture works in data units
        //! with the unit vectors `x=<sx>cm, y=<sy>cm`. TeX cannot hold that when a unit vector or a coordinate is out
        //! of its range (dimensions < 16384 pt = 575 cm, pgfmath numbers < 16384, no exponent in "1e-05cm"), e.g. for a
        //! data range of 1e-3 or coordinates of 1e6: then (`paper` true) every coordinate is written in cm relative to
        //! the data minimum, (v - min) * s, with x=1cm, y=1cm; radii become "rx and ry" pairs.
        struct TikzMap
        {
            bool paper = false;
            double ox = 0, oy = 0, sx = 1, sy = 1;

            double X(double x) const { return paper ? (x - ox) * sx : x; }
            double Y(double y) const { return paper ? (y - oy) * sy : y; }
            std::string pt(double x, double y) const { return tikzPoint(X(x), Y(y)); }
            //! A radius of r data units: "r", or `"<r sx> and <r sy>"` on paper.
            std::string radius(double r) const { return paper ? number(r * sx) + " and " + number(r * sy) : number(r); }
            //! Data-unit distance along x / y as written.
            double dx(double d) const { return paper ? d * sx : d; }
            double dy(double d) const { return paper ? d * sy : d; }
        };

        //! Data units are safe if every unit vector and every coordinate the picture writes stays inside TeX's range.
        inline TikzMap tikzMap(const Drawing2D &d, const Drawing2D::Frame &f)
        {
            double ext_x = std::max(std::abs(f.min_x - f.ox), std::abs(f.max_x + f.ox));
            double ext_y = std::max(std::abs(f.min_y - f.oy), std::abs(f.max_y + f.oy));
            if (d.clipped())
            {
                std::vector<float> c = d.clipRegion();
                ext_x = std::max({ext_x, std::abs(static_cast<double>(c[0])), std::abs(static_cast<double>(c[2]))});
                ext_y = std::max({ext_y, std::abs(static_cast<double>(c[1])), std::abs(static_cast<double>(c[3]))});
            }
            auto ok = [](double s, double ext) { return s >= 1e-4 && s <= 500 && ext < 16000 && ext * s < 500; };
            TikzMap m;
            m.paper = !(ok(f.sx, ext_x) && ok(f.sy, ext_y));
            if (m.paper)
            {
                m.ox = f.min_x;
                m.oy = f.min_y;
                m.sx = f.sx;
                m.sy = f.sy;
            }
            return m;
        }

        //! Refuses (std::length_error, before anything is written) a drawing TeX cannot hold: the mark radius or the
        //! scale of a drawn mark beyond tex_paper_limit_cm, or a picture coordinate, width or height on paper beyond
        //! it (the frame with its overruns, the clip rectangle and axis crossings, widened on every side by the reach
        //! of the largest drawn mark, 2 radius scale: a robot's nose); with `document` also the border and the page
        //! (picture plus two borders).
        inline void tikzTexLimits(const Drawing2D &d, const Drawing2D::Frame &f, const TikzMap &map, bool document)
        {
            const std::string who = "writeTikz";
            const double radius = d.markRadius();
            refuseBeyondTex(radius, "the mark radius", who);
            double reach = 0;
            for (const auto &p : d.primitives())
                if (p.kind == Drawing2D::Kind::marks && !p.marks.empty())
                {
                    const double scale = d.markDefs().at(p.mark).scale;
                    if (std::isnan(scale))
                        continue;   // written as 0
                    refuseBeyondTex(scale, "a mark scale", who);
                    reach = std::max(reach, 2.0 * radius * std::abs(scale));
                }
            // cm on paper: coordinates are written in cm, or in data units with x = sx cm, y = sy cm.
            auto px = [&](double x) { return map.paper ? map.X(x) : x * f.sx; };
            auto py = [&](double y) { return map.paper ? map.Y(y) : y * f.sy; };
            double lo_x = px(f.min_x - f.ox), hi_x = px(f.max_x + f.ox), lo_y = py(f.min_y - f.oy), hi_y = py(f.max_y + f.oy);
            if (d.clipped())
            {
                std::vector<float> c = d.clipRegion();
                lo_x = std::min(lo_x, px(c[0]));
                hi_x = std::max(hi_x, px(c[2]));
                lo_y = std::min(lo_y, py(c[1]));
                hi_y = std::max(hi_y, py(c[3]));
            }
            // Axis lines at their crossing, which a frame without data in the other direction leaves out.
            for (const auto &a : d.axes())
            {
                double &lo = a.is_x ? lo_y : lo_x, &hi = a.is_x ? hi_y : hi_x;
                const double c = a.is_x ? py(a.crossing) : px(a.crossing);
                lo = std::min(lo, c);
                hi = std::max(hi, c);
            }
            lo_x -= reach;
            hi_x += reach;
            lo_y -= reach;
            hi_y += reach;
            for (double v : {lo_x, hi_x, lo_y, hi_y})
                refuseBeyondTex(v, "a picture coordinate", who);
            refuseBeyondTex(hi_x - lo_x, "the picture width", who);
            refuseBeyondTex(hi_y - lo_y, "the picture height", who);
            if (document)
            {
                refuseBeyondTex(d.border(), "the border", who);
                refuseBeyondTex(hi_x - lo_x + 2.0 * d.border(), "the page width", who);
                refuseBeyondTex(hi_y - lo_y + 2.0 * d.border(), "the page height", who);
            }
        }

        //! Grid lines, axes with ticks and labels, and the axis descriptions of a drawing.
        inline void writeTikzGridsAndAxes(const Drawing2D &d, const Drawing2D::Frame &f, const TikzMap &map,
                                          std::string &out)
        {
            double x0 = f.min_x - f.ox, x1 = f.max_x + f.ox, y0 = f.min_y - f.oy, y1 = f.max_y + f.oy;
            for (const auto &g : d.grids())
            {
                for (double v : g.horizontal ? Drawing2D::ticks(y0, y1, g.tick) : Drawing2D::ticks(x0, x1, g.tick))
                {
                    if (g.horizontal)
                        out += "\\draw[" + g.style + "] (" + map.pt(x0, v) + ") -- (" + map.pt(x1, v) + ");\n";
                    else
                        out += "\\draw[" + g.style + "] (" + map.pt(v, y0) + ") -- (" + map.pt(v, y1) + ");\n";
                }
            }
            // Tick marks are 0.1 cm long on paper: convert to data units per axis.
            double tick_y = 0.05 / f.sy, tick_x = 0.05 / f.sx;
            for (const auto &a : d.axes())
            {
                std::string anc = tikzAnchor(a.position);
                bool log = (a.is_x ? d.axisTypeX() : d.axisTypeY()) == Drawing2D::axis_type_log10;
                if (a.is_x)
                    out += "\\draw[" + a.style + "] (" + map.pt(x0, a.crossing) + ") -- (" +
                           map.pt(x1, a.crossing) + ");\n";
                else
                    out += "\\draw[" + a.style + "] (" + map.pt(a.crossing, y0) + ") -- (" +
                           map.pt(a.crossing, y1) + ");\n";
                for (double v : a.is_x ? Drawing2D::ticks(x0, x1, a.tick) : Drawing2D::ticks(y0, y1, a.tick))
                {
                    if (a.is_x)
                        out += "\\draw[" + a.style + "] (" + map.pt(v, a.crossing - tick_y) + ") -- (" +
                               map.pt(v, a.crossing + tick_y) + ")";
                    else
                        out += "\\draw[" + a.style + "] (" + map.pt(a.crossing - tick_x, v) + ") -- (" +
                               map.pt(a.crossing + tick_x, v) + ")";
                    // On log axes the overrun can reach decades beyond double (10^400): no label there.
                    double value = log ? std::pow(10.0, v) : v;
                    std::string label = a.format.empty() || !std::isfinite(value) || (log && !(value > 0)) ? "" : numberToLatexString(value, a.format);
                    if (!label.empty())
                    {
                        // The label touches the tick end on the side the position flags name.
                        double lx = a.is_x ? v : a.crossing, ly = a.is_x ? a.crossing : v;
                        if (a.position & tikz_position_above)
                            ly += a.is_x ? tick_y : 0.0;
                        else if (a.position & tikz_position_below)
                            ly -= a.is_x ? tick_y : 0.0;
                        if (a.position & tikz_position_right)
                            lx += a.is_x ? 0.0 : tick_x;
                        else if (a.position & tikz_position_left)
                            lx -= a.is_x ? 0.0 : tick_x;
                        out += " (" + map.pt(lx, ly) + ") node[anchor=" + anc + "] {" + label + "}";
                    }
                    out += ";\n";
                }
            }
            // Descriptions sit outside the plot region (beyond the tick labels): centred below it and left of it.
            if (!d.descriptionX().empty())
                out += "\\node[anchor=north, yshift=-0.7cm] at (" + map.pt((x0 + x1) / 2, y0) + ") {" +
                       LaTeX::escapeLaTeXCharacters(d.descriptionX()) + "};\n";
            if (!d.descriptionY().empty())
                out += "\\node[anchor=south, rotate=90, yshift=1.2cm] at (" + map.pt(x0, (y0 + y1) / 2) + ") {" +
                       LaTeX::escapeLaTeXCharacters(d.descriptionY()) + "};\n";
        }

        //! One polyline; long ones are cut into paths of at most 500 points (sharing the joint) so that TeX does not
        //! run out of memory on one huge path.
        inline void writeTikzPolyline(const Drawing2D::Primitive &p, const TikzMap &map, std::string &out)
        {
            std::string path, last;
            size_t run = 0;
            for (const auto &q : p.points)
            {
                if (run == 500)
                {
                    out += path + ";\n";
                    path = "\\draw[" + p.style + "] (" + last + ")";
                    run = 1;
                }
                std::string xy;
                appendNumber(xy, map.X(q.first));
                xy += ',';
                appendNumber(xy, map.Y(q.second));
                path += run == 0 ? "\\draw[" + p.style + "] (" : std::string(" -- (");
                path += xy;
                path += ')';
                last = std::move(xy);
                if (++run % 8 == 0)
                    path += '\n';
            }
            out += path + ";\n";
        }

        //! One primitive; `thin` and the running mark count `mark_index` (over the whole drawing) say which marks
        //! and polyline points are written.
        inline void writeTikzPrimitive(const Drawing2D::Primitive &p, const Drawing2D::Frame &f, const TikzMap &map,
                                       const TikzThinning &thin, size_t &mark_index, std::string &out)
        {
            using K = Drawing2D::Kind;
            auto pt = [&](size_t i) { return map.pt(p.points[i].first, p.points[i].second); };
            switch (p.kind)
            {
                case K::polyline:
                    if (!thin.thinned())
                        writeTikzPolyline(p, map, out);
                    else
                    {
                        Drawing2D::Primitive q = p;
                        q.points.clear();
                        for (size_t i = 0; i < p.points.size(); ++i)
                            if (i % thin.stride == 0 || i + 1 == p.points.size())
                                q.points.push_back(p.points[i]);
                        writeTikzPolyline(q, map, out);
                    }
                    break;
                case K::marks:
                    for (const auto &m : p.marks)
                    {
                        if (!thin.keepMark(mark_index++))
                            continue;
                        // The rotation follows the direction as it appears on paper, i.e. after axis scaling.
                        double dx = static_cast<double>(m.dx) * f.sx, dy = static_cast<double>(m.dy) * f.sy;
                        double deg = (dx == 0.0 && dy == 0.0) ? 0.0 : std::atan2(dy, dx) * 180.0 / pi;
                        out += p.mark;
                        out += '{';
                        appendNumber(out, map.X(m.x));
                        out += "}{";
                        appendNumber(out, map.Y(m.y));
                        out += "}{";
                        appendNumber(out, deg);
                        out += "}\n";
                    }
                    break;
                case K::edge:
                {
                    std::string opt = p.style;
                    bool end = p.options & Drawing2D::edge_arrow_end, beg = p.options & Drawing2D::edge_arrow_beg;
                    opt += end && beg ? ",<->" : end ? ",->" : beg ? ",<-" : "";
                    out += "\\draw[" + opt + "] (" + pt(0) + ") -- (" + pt(1) + ");\n";
                    break;
                }
                case K::polygon:
                    out += "\\draw[" + p.style + "] ";
                    for (size_t i = 0; i < p.points.size(); ++i)
                        out += "(" + pt(i) + ") -- ";
                    out += "cycle;\n";
                    break;
                case K::rectangle: out += "\\draw[" + p.style + "] (" + pt(0) + ") rectangle (" + pt(1) + ");\n"; break;
                case K::circle: out += "\\draw[" + p.style + "] (" + pt(0) + ") " + (map.paper ? "ellipse (" : "circle (") + map.radius(p.r1) + ");\n"; break;
                case K::ellipse:
                    out += "\\draw[" + p.style + ", rotate around={" + number(tikzAngle(p.a1 * 180.0 / pi)) + ":(" + pt(0) +
                           ")}] (" + pt(0) + ") ellipse (" + number(map.dx(p.r1)) + " and " + number(map.dy(p.r2)) + ");\n";
                    break;
                case K::pie:
                {
                    double begin = p.a1 * 180.0 / pi, end = p.a2 * 180.0 / pi;
                    tikzArc(begin, end);
                    std::string b = number(begin), e = number(end), r = map.radius(p.r1);
                    out += "\\draw[" + p.style + "] (" + pt(0) + ") -- ++(" + b + ":" + r + ") arc (" + b + ":" + e +
                           ":" + r + ") -- cycle;\n";
                    break;
                }
                case K::text:
                    out += "\\node[" + p.style + "] at (" + pt(0) + ") {" + LaTeX::escapeLaTeXCharacters(p.text) +
                           "};\n";
                    break;
            }
        }
    }

    namespace detail
    {
        // (defined below the public overloads)
        template<class Out>
        void writeTikzPictureTo(const Drawing2D &d, Out &target);
        template<class Out>
        void writeTikzTo(const Drawing2D &d, Out &target);
    }

    //! Writes only the tikzpicture environment of `d` (colours, macros and marks are local to it), e.g. to `\input` it.
    //! A drawing beyond d.texMarkLimit() is thinned with a note; std::length_error (nothing written) if what cannot be
    //! thinned exceeds it (TikzBudget.h), and if the picture is beyond TeX's dimensions (tikzTexLimits: an extent on
    //! paper, the mark radius or a mark scale beyond detail::tex_paper_limit_cm, 500 cm). Rotations and arcs
    //! beyond +-3600 degrees are written modulo 360 (detail::tikzAngle, tikzArc).
    inline void writeTikzPicture(const Drawing2D &d, std::ostream &os) { detail::writeTikzPictureTo(d, os); }
    //! What writeTikzPicture writes, as a string, without any stream.
    inline std::string tikzPictureString(const Drawing2D &d)
    {
        return detail::textString([&d](std::string &out) { detail::writeTikzPictureTo(d, out); });
    }

    //! writeTikzPicture into a std::ostream or a std::string (TextSink.h).
    template<class Out>
    void detail::writeTikzPictureTo(const Drawing2D &d, Out &target)
    {
        detail::TextOut<Out> os{target};
        using detail::number;
        Drawing2D::Frame f = d.frame();
        detail::TikzMap map = detail::tikzMap(d, f);
        detail::tikzTexLimits(d, f, map, false);
        detail::TikzThinning thin = detail::tikzThinning(d, f);
        std::string out;
        out += "\\begin{tikzpicture}[x=" + number(map.paper ? 1.0 : f.sx) + "cm, y=" + number(map.paper ? 1.0 : f.sy) + "cm";
        std::string style_options = d.registry().styleOptions();
        if (!style_options.empty())
            out += ",\n\t" + style_options;
        out += "]\n";
        out += d.registry().colorDefinitions();
        out += "\\pgfmathsetmacro{\\MaxX}{" + number(map.X(f.max_x)) + "}\n";
        out += "\\pgfmathsetmacro{\\MinX}{" + number(map.X(f.min_x)) + "}\n";
        out += "\\pgfmathsetmacro{\\MaxY}{" + number(map.Y(f.max_y)) + "}\n";
        out += "\\pgfmathsetmacro{\\MinY}{" + number(map.Y(f.min_y)) + "}\n";
        out += "\\pgfmathsetmacro{\\MarkGlobalScaleX}{" + number(map.paper ? 1.0 : 1.0 / f.sx) + "}\n";
        out += "\\pgfmathsetmacro{\\MarkGlobalScaleY}{" + number(map.paper ? 1.0 : 1.0 / f.sy) + "}\n";
        // The data frame as an invisible path: the picture is never empty (an empty one has zero size, which
        // \resizebox cannot scale) and always covers the plot region.
        out += "\\path (\\MinX,\\MinY) rectangle (\\MaxX,\\MaxY);\n";
        out += "\\pgfmathsetmacro{\\MarkRadius}{" + number(d.markRadius()) + "}\n";
        out += d.registry().markDefinitions();
        if (d.clipped())
        {
            std::vector<float> c = d.clipRegion();
            out += "\\clip (" + map.pt(c[0], c[1]) + ") rectangle (" + map.pt(c[2], c[3]) + ");\n";
        }
        detail::writeTikzGridsAndAxes(d, f, map, out);
        os << out;
        // Primitives in chunks, so that a figure of millions of points is not held twice in memory.
        out.clear();
        size_t mark_index = 0;
        for (const auto &p : d.primitives())
        {
            detail::writeTikzPrimitive(p, f, map, thin, mark_index, out);
            if (out.size() > (1u << 16))
            {
                os << out;
                out.clear();
            }
        }
        if (thin.thinned())
        {
            // Below the frame, and below x tick labels and the x description if there are any.
            bool below = !d.descriptionX().empty() ||
                         std::any_of(d.axes().begin(), d.axes().end(), [](const Drawing2D::Axis &a) { return a.is_x; });
            out += "\\node[anchor=north west, yshift=" + std::string(below ? "-1.3cm" : "-0.1cm") +
                   "] at (\\MinX,\\MinY) {" + detail::tikzThinningNote(thin) + "};\n";
        }
        os << out << "\\end{tikzpicture}\n";
    }

    //! Writes `d` as a standalone LaTeX document (the `minimal` class cropped to the picture by preview). Refused as
    //! writeTikzPicture, and also if the border or the page (picture plus two borders) is beyond 500 cm.
    inline void writeTikz(const Drawing2D &d, std::ostream &os) { detail::writeTikzTo(d, os); }
    //! What writeTikz writes, as a string, without any stream.
    inline std::string tikzString(const Drawing2D &d)
    {
        return detail::textString([&d](std::string &out) { detail::writeTikzTo(d, out); });
    }

    //! writeTikz into a std::ostream or a std::string (TextSink.h).
    template<class Out>
    void detail::writeTikzTo(const Drawing2D &d, Out &os)
    {
        const Drawing2D::Frame f = d.frame();
        detail::tikzTexLimits(d, f, detail::tikzMap(d, f), true);   // these throw before the preamble
        detail::tikzThinning(d, f);
        detail::writeTikzDocument(os, d.border(), [&d](Out &o) { writeTikzPictureTo(d, o); });
    }
}
