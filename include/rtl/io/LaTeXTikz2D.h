// Standalone TikZ export of 2D drawings: plots with marks, primitives, grids and axes (rtl-api §4.4).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <limits>
#include <map>
#include <ostream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "rtl/Core.h"
#include "rtl/Transformation.h"
#include "rtl/io/LaTeXTikzCommon.h"
#include "rtl/io/LaTeXUtility.h"

namespace rtl
{
    //! Collects 2D primitives in data coordinates and writes them as one standalone tikzpicture.
    //!
    //! TikZ conventions (those of the published RTL, so figures look the same; deviations are marked "rather than"):
    //! - The document is `minimal` with xcolor[rgb], tikz and preview[active,tightpage] (\PreviewBorder = border), so
    //!   the PDF page is cropped to the picture.
    //! - The picture works in data units: the unit vectors `x=<sx>cm, y=<sy>cm` map the data range (or the clip
    //!   region) to the requested size, times the user scales (scaleX()/scaleY() report sx, sy). Unit vectors rather
    //!   than xscale/yscale, because TikZ multiplies a coordinate by the unit vector before any transformation: with
    //!   xscale, a coordinate above ~575 (x 1 cm) overflows TeX's 16384 pt, with x=<sx>cm only the paper position
    //!   counts. Remaining TeX limit: sx, sy <= ~575 cm per unit, i.e. a 10 cm axis needs a data range >= ~0.02.
    //! - The picture always contains the data frame (\MinX,\MinY)-(\MaxX,\MaxY) as an invisible path.
    //! - Marks are `\newcommand{\MarkA}[3]{...}` (x, y, rotation in degrees) drawn in a scope shifted to (x, y) that
    //!   resets the unit vectors to 1 cm, so marks are \MarkRadius cm in size whatever the axis scaling.
    //!   \MarkGlobalScaleX/Y (= 1/sx, 1/sy: cm to data units) stay defined for hand-written TikZ. Along a polyline
    //!   each mark is rotated to the local direction (as seen on paper).
    //! - On log10 axes every coordinate is replaced by its log10 before it is tracked or drawn (non-positive values
    //!   are dropped); grid and axis ticks are then given in decades. Non-finite points are skipped and break lines.
    //! - User text (addText, descriptions) is escaped; number labels come from numberToLatexString.
    //! - Size limit of the consumer, not of the writer: a picture is one TeX box, and pdflatex's default main memory
    //!   (5e6 words) holds about 15,000 marks or a few 100,000 polyline points; use lualatex (dynamic memory) or
    //!   thin the data out for bigger figures. Writing stays linear in the number of points.
    class LaTeXTikz2D
    {
    public:
        static const unsigned int overrun_relative = 0, overrun_absolute = 1;
        static const unsigned int axis_type_linear = 0, axis_type_log10 = 1;
        static const unsigned int position_above = latex_detail::tikz_position_above,
                                  position_below = latex_detail::tikz_position_below,
                                  position_right = latex_detail::tikz_position_right,
                                  position_left = latex_detail::tikz_position_left;
        //! addEdge(s) options: arrow tips at the end and/or the beginning of each edge.
        static const unsigned int edge_arrow_end = 0x01, edge_arrow_beg = 0x02;

        //! Mark templates: TikZ code around the local origin, sized by \MarkRadius; "@style" becomes the style name.
        static inline const char *latex_mark_blank = latex_detail::tikz_mark_blank;
        static inline const char *latex_mark_cross = latex_detail::tikz_mark_cross;
        static inline const char *latex_mark_mark = latex_detail::tikz_mark_mark;
        static inline const char *latex_mark_dot = latex_detail::tikz_mark_dot;
        static inline const char *latex_mark_robot = latex_detail::tikz_mark_robot;
        static inline const char *latex_var_style = latex_detail::tikz_var_style;

        explicit LaTeXTikz2D(unsigned int axis_x = LaTeXTikz2D::axis_type_linear,
                             unsigned int axis_y = LaTeXTikz2D::axis_type_linear)
                : axis_type_x(axis_x == axis_type_log10 ? axis_type_log10 : axis_type_linear),
                  axis_type_y(axis_y == axis_type_log10 ? axis_type_log10 : axis_type_linear)
        {
            clearAll();
        }
        ~LaTeXTikz2D() = default;

        //! Output size of the data range (or clip region) in cm.
        void setSize(float width, float height)
        {
            size_w = width > 0 ? width : 10.0f;
            size_h = height > 0 ? height : 10.0f;
        }
        void setBorder(float border) { border_cm = std::max(0.0f, border); }
        void setMarkRadius(float radius) { mark_radius = std::max(0.0f, radius); }
        //! overrun_relative: grids and axes extend `magnitude` percent of the range beyond the data;
        //! overrun_absolute: `magnitude` data units.
        void setGridAxisOverrun(unsigned int type, float magnitude)
        {
            overrun_type = type == overrun_absolute ? overrun_absolute : overrun_relative;
            overrun_magnitude = std::max(0.0f, magnitude);
        }
        void setScaleX(float scale) { user_scale_x = scale > 0 ? scale : 1.0f; }
        void setScaleY(float scale) { user_scale_y = scale > 0 ? scale : 1.0f; }
        //! Clips the picture to the rectangle and fits the size to it instead of to the data.
        void setClipRegion(float p1_x, float p1_y, float p2_x, float p2_y)
        {
            float x1 = tx(p1_x), x2 = tx(p2_x), y1 = ty(p1_y), y2 = ty(p2_y);
            if (!std::isfinite(x1) || !std::isfinite(x2) || !std::isfinite(y1) || !std::isfinite(y2))
                return;
            clip = true;
            clip_min_x = std::min(x1, x2);
            clip_max_x = std::max(x1, x2);
            clip_min_y = std::min(y1, y2);
            clip_max_y = std::max(y1, y2);
        }
        //! Widens the data bounds so that both points are inside.
        void setMinPlotRegion(float p1_x, float p1_y, float p2_x, float p2_y)
        {
            track(tx(p1_x), ty(p1_y));
            track(tx(p2_x), ty(p2_y));
        }

        //! Data and settings back to their defaults (the axis types stay).
        void clearAll()
        {
            clearData();
            size_w = size_h = 10.0f;
            border_cm = 0.1f;
            mark_radius = 0.1f;
            overrun_type = overrun_relative;
            overrun_magnitude = 5.0f;
            user_scale_x = user_scale_y = 1.0f;
            clip = false;
        }

        //! Removes primitives, styles, colours, marks, grids, axes, descriptions and the data bounds.
        void clearData()
        {
            names.clear();
            chunks.clear();
            grids.clear();
            axes.clear();
            description_x.clear();
            description_y.clear();
            min_x = min_y = std::numeric_limits<float>::max();
            max_x = max_y = -std::numeric_limits<float>::max();
        }

        //! Writes the standalone document; throws std::runtime_error if the file cannot be written.
        void writeTEX(const std::string &file_name)
        {
            latex_detail::writeTexFile(file_name, "LaTeXTikz2D", [this](std::ostream &os) { writeTEX(os); });
        }

        //! Writes the standalone document to a stream.
        void writeTEX(std::ostream &os)
        {
            latex_detail::writeTikzDocument(os, border_cm, [this](std::ostream &o) { writeTikz(o); });
        }

        //! Writes only the tikzpicture environment (colours, macros and marks are local to it), e.g. to \input it.
        void writeTikz(std::ostream &os)
        {
            Frame f = frame();
            std::string out;
            out += "\\begin{tikzpicture}[x=" + latex_detail::number(f.sx) + "cm, y=" + latex_detail::number(f.sy) +
                   "cm";
            std::string style_options = names.styleOptions();
            if (!style_options.empty())
                out += ",\n\t" + style_options;
            out += "]\n";
            out += names.colorDefinitions();
            out += "\\pgfmathsetmacro{\\MaxX}{" + latex_detail::number(f.max_x) + "}\n";
            out += "\\pgfmathsetmacro{\\MinX}{" + latex_detail::number(f.min_x) + "}\n";
            out += "\\pgfmathsetmacro{\\MaxY}{" + latex_detail::number(f.max_y) + "}\n";
            out += "\\pgfmathsetmacro{\\MinY}{" + latex_detail::number(f.min_y) + "}\n";
            out += "\\pgfmathsetmacro{\\MarkGlobalScaleX}{" + latex_detail::number(1.0 / f.sx) + "}\n";
            out += "\\pgfmathsetmacro{\\MarkGlobalScaleY}{" + latex_detail::number(1.0 / f.sy) + "}\n";
            // The data frame as an invisible path: the picture is never empty (an empty one has zero size, which
            // \resizebox cannot scale) and always covers the plot region.
            out += "\\path (\\MinX,\\MinY) rectangle (\\MaxX,\\MaxY);\n";
            out += "\\pgfmathsetmacro{\\MarkRadius}{" + latex_detail::number(mark_radius) + "}\n";
            out += names.markDefinitions();
            if (clip)
                out += "\\clip (" + pt(clip_min_x, clip_min_y) + ") rectangle (" + pt(clip_max_x, clip_max_y) + ");\n";
            os << out;
            out.clear();
            writeGrids(out, f);
            writeAxes(out, f);
            os << out;
            for (const auto &ch : chunks)
            {
                if (ch.mark_name.empty())
                    os << ch.text;
                else
                {
                    out.clear();
                    out.reserve(ch.marks.size() * 32);
                    for (const auto &m : ch.marks)
                    {
                        // The rotation follows the direction as it appears on paper, i.e. after axis scaling.
                        double dx = static_cast<double>(m.dx) * f.sx, dy = static_cast<double>(m.dy) * f.sy;
                        double deg = (dx == 0.0 && dy == 0.0) ? 0.0 : std::atan2(dy, dx) * 180.0 / latex_detail::pi;
                        out += ch.mark_name;
                        out += '{';
                        latex_detail::appendNumber(out, m.x);
                        out += "}{";
                        latex_detail::appendNumber(out, m.y);
                        out += "}{";
                        latex_detail::appendNumber(out, deg);
                        out += "}\n";
                    }
                    os << out;
                }
            }
            os << "\\end{tikzpicture}\n";
        }

        //! Horizontal grid lines every `tick` in y (decades on a log10 axis).
        void addGridH(const std::string &style, float tick) { addGrid(true, style, tick); }
        //! Vertical grid lines every `tick` in x (decades on a log10 axis).
        void addGridV(const std::string &style, float tick) { addGrid(false, style, tick); }

        //! x axis at y = crossing, ticks every `tick`, labels printed with numberToLatexString(value, num_format)
        //! (no labels if num_format is empty) and placed by the position_* flags.
        void addAxisX(const std::string &style, std::string num_format, unsigned int num_position, float tick,
                      float crossing = 0.0f)
        {
            addAxis(true, style, std::move(num_format), num_position, tick, crossing);
        }
        void addAxisY(const std::string &style, std::string num_format, unsigned int num_position, float tick,
                      float crossing = 0.0f)
        {
            addAxis(false, style, std::move(num_format), num_position, tick, crossing);
        }
        //! Axis descriptions (escaped), below the x range and left of the y range.
        void addDescriptionX(const std::string &description) { description_x = description; }
        void addDescriptionY(const std::string &description) { description_y = description; }

        //! Polyline through (x[i], y[i]) if line_style is non-empty, and marks at every point if mark_style and mark
        //! are non-empty. Nothing is drawn if the sizes differ or the input is empty.
        void addPlot(const std::vector<float> &x, const std::vector<float> &y, const std::string &line_style,
                     const std::string &mark_style = "", const std::string &mark = LaTeXTikz2D::latex_mark_blank,
                     float mark_scale = 1.0f)
        {
            if (x.size() != y.size() || x.empty())
                return;
            std::vector<std::pair<float, float>> p(x.size());
            for (size_t i = 0; i < x.size(); ++i)
                p[i] = {tx(x[i]), ty(y[i])};
            plot(p, line_style, mark_style, mark, mark_scale);
        }
        void addPlot(const std::vector<Vector2f> &v, const std::string &line_style, const std::string &mark_style = "",
                     const std::string &mark = LaTeXTikz2D::latex_mark_blank, float mark_scale = 1.0f)
        {
            if (v.empty())
                return;
            std::vector<std::pair<float, float>> p(v.size());
            for (size_t i = 0; i < v.size(); ++i)
                p[i] = {tx(v[i].x()), ty(v[i].y())};
            plot(p, line_style, mark_style, mark, mark_scale);
        }

        //! Straight edges of anything with beg()/end() returning points with x()/y() (e.g. LineSegment2f).
        template<class T>
        void addEdges(const std::vector<T> &edges, const std::string &style, unsigned int options = 0)
        {
            for (const auto &e : edges)
                addEdge(e, style, options);
        }
        template<class T>
        void addEdge(const T &edge, const std::string &style, unsigned int options = 0)
        {
            float x1 = tx(edge.beg().x()), y1 = ty(edge.beg().y()), x2 = tx(edge.end().x()), y2 = ty(edge.end().y());
            if (!finite(x1, y1) || !finite(x2, y2))
                return;
            std::string opt = styleName(style);
            if ((options & edge_arrow_end) && (options & edge_arrow_beg))
                opt += ",<->";
            else if (options & edge_arrow_end)
                opt += ",->";
            else if (options & edge_arrow_beg)
                opt += ",<-";
            track(x1, y1);
            track(x2, y2);
            text("\\draw[" + opt + "] (" + pt(x1, y1) + ") -- (" + pt(x2, y2) + ");\n");
        }

        void addTriangle(const Vector2f &a, const Vector2f &b, const Vector2f &c, const std::string &style)
        {
            polygon({a, b, c}, style);
        }
        void addQuadrilateral(const Vector2f &a, const Vector2f &b, const Vector2f &c, const Vector2f &d,
                              const std::string &style)
        {
            polygon({a, b, c, d}, style);
        }
        //! Axis-aligned rectangle with opposite corners p1, p2.
        void addRectangle(const Vector2f &p1, const Vector2f &p2, const std::string &style)
        {
            float x1 = tx(p1.x()), y1 = ty(p1.y()), x2 = tx(p2.x()), y2 = ty(p2.y());
            if (!finite(x1, y1) || !finite(x2, y2))
                return;
            track(x1, y1);
            track(x2, y2);
            text("\\draw[" + styleName(style) + "] (" + pt(x1, y1) + ") rectangle (" + pt(x2, y2) + ");\n");
        }
        //! Circle of `radius` data units (an ellipse on paper if the axes are scaled differently).
        void addCircle(const Vector2f &centre, float radius, const std::string &style)
        {
            float x = tx(centre.x()), y = ty(centre.y());
            if (!finite(x, y) || !std::isfinite(radius))
                return;
            radius = std::abs(radius);
            track(x - radius, y - radius);
            track(x + radius, y + radius);
            text("\\draw[" + styleName(style) + "] (" + pt(x, y) + ") circle (" + latex_detail::number(radius) + ");\n");
        }
        //! Ellipse with radii in data units, rotated by `rotation` radians counter-clockwise.
        void addEllipse(const Vector2f &centre, float x_radius, float y_radius, float rotation, const std::string &style)
        {
            float x = tx(centre.x()), y = ty(centre.y());
            if (!finite(x, y) || !finite(x_radius, y_radius) || !std::isfinite(rotation))
                return;
            x_radius = std::abs(x_radius);
            y_radius = std::abs(y_radius);
            float c = std::abs(std::cos(rotation)), s = std::abs(std::sin(rotation));
            float ex = std::sqrt(x_radius * x_radius * c * c + y_radius * y_radius * s * s);
            float ey = std::sqrt(x_radius * x_radius * s * s + y_radius * y_radius * c * c);
            track(x - ex, y - ey);
            track(x + ex, y + ey);
            text("\\draw[" + styleName(style) + ", rotate around={" + latex_detail::number(rotation * 180.0 / latex_detail::pi) +
                 ":(" + pt(x, y) + ")}] (" + pt(x, y) + ") ellipse (" + latex_detail::number(x_radius) + " and " +
                 latex_detail::number(y_radius) + ");\n");
        }
        //! Circular sector from angle_beg to angle_end (radians, counter-clockwise).
        void addPie(const Vector2f &centre, float radius, float angle_beg, float angle_end, const std::string &style)
        {
            float x = tx(centre.x()), y = ty(centre.y());
            if (!finite(x, y) || !std::isfinite(radius) || !finite(angle_beg, angle_end))
                return;
            radius = std::abs(radius);
            track(x - radius, y - radius);
            track(x + radius, y + radius);
            std::string b = latex_detail::number(angle_beg * 180.0 / latex_detail::pi), e = latex_detail::number(angle_end * 180.0 / latex_detail::pi),
                        r = latex_detail::number(radius);
            text("\\draw[" + styleName(style) + "] (" + pt(x, y) + ") -- ++(" + b + ":" + r + ") arc (" + b + ":" + e +
                 ":" + r + ") -- cycle;\n");
        }
        void addLine(const Vector2f &beg, const Vector2f &end, const std::string &style)
        {
            addEdge(LineSegment2f(beg, end), style);
        }
        void addLine(const LineSegment2f &ls, const std::string &style) { addEdge(ls, style); }
        void addLines(const std::vector<LineSegment2f> &ls, const std::string &style) { addEdges(ls, style); }
        //! A text node (escaped) at `position`; `style` may set anchor, font, colour, ...
        void addText(const std::string &text_str, const std::string &style, const Vector2f &position)
        {
            float x = tx(position.x()), y = ty(position.y());
            if (!finite(x, y))
                return;
            track(x, y);
            text("\\node[" + styleName(style) + "] at (" + pt(x, y) + ") {" + LaTeX::escapeLaTeXCharacters(text_str) +
                 "};\n");
        }

        //! Data bounds (log10 units on log axes); +-max float while empty.
        float maxX() { return max_x; }
        float minX() { return min_x; }
        float maxY() { return max_y; }
        float minY() { return min_y; }
        //! Effective scale (cm per data unit) that writeTEX would use now.
        float scaleX() { return static_cast<float>(frame().sx); }
        float scaleY() { return static_cast<float>(frame().sy); }

        //! printf-formats `num` by the conversion letter ending `format` (d i -> long long, u o x X -> unsigned long
        //! long, f F e E g G a A -> double; anything else gives ""), rewrites an exponent as " \cdot 10^{exp}" (a bare
        //! mantissa 1 gives "10^{exp}") and wraps the result in $...$.
        template<typename T>
        static std::string numberToLatexString(T num, std::string format)
        {
            return latex_detail::numberToLatexString(num, format);
        }

        //! Registers `\definecolor{ColorX}<color>` for a spec such as "{hsb}{0.3,0.8,0.5}" or "{rgb}{1,0,0}" and
        //! returns "ColorX"; the same spec always returns the same name.
        std::string saveColor(const std::string &color) { return names.color(color); }

    private:
        struct MarkPoint
        {
            float x, y, dx, dy;
        };
        struct Chunk
        {
            std::string text;                // literal TikZ code, or
            std::string mark_name;           // "\MarkX" applied to every entry of marks
            std::vector<MarkPoint> marks;
        };
        struct Grid
        {
            bool horizontal;
            std::string style;
            float tick;
        };
        struct Axis
        {
            bool is_x;
            std::string style, format;
            unsigned int position;
            float tick, crossing;
        };
        struct Frame
        {
            double min_x, max_x, min_y, max_y, sx, sy, ox, oy;
        };

        static bool finite(float a, float b) { return std::isfinite(a) && std::isfinite(b); }

        float tx(float x) const { return axis_type_x == axis_type_log10 ? (x > 0 ? std::log10(x) : std::numeric_limits<float>::quiet_NaN()) : x; }
        float ty(float y) const { return axis_type_y == axis_type_log10 ? (y > 0 ? std::log10(y) : std::numeric_limits<float>::quiet_NaN()) : y; }

        void track(float x, float y)
        {
            if (std::isfinite(x))
            {
                min_x = std::min(min_x, x);
                max_x = std::max(max_x, x);
            }
            if (std::isfinite(y))
            {
                min_y = std::min(min_y, y);
                max_y = std::max(max_y, y);
            }
        }

        static std::string pt(double x, double y) { return latex_detail::tikzPoint(x, y); }

        void text(const std::string &t)
        {
            if (chunks.empty() || !chunks.back().mark_name.empty())
                chunks.emplace_back();
            chunks.back().text += t;
        }

        std::string styleName(const std::string &style) { return names.style(style); }

        //! Marks reset the unit vectors to 1 cm, so they keep their size whatever the axis scaling.
        std::string markName(const std::string &style, const std::string &templ, float scale)
        {
            std::string s = latex_detail::number(scale);
            return names.mark(style, templ, "\n" + s, "[3]", "shift={(#1,#2)}, x=1cm, y=1cm, rotate=#3, scale=" + s);
        }

        void plot(const std::vector<std::pair<float, float>> &p, const std::string &line_style,
                  const std::string &mark_style, const std::string &mark, float mark_scale)
        {
            for (const auto &q : p)
                if (finite(q.first, q.second))
                    track(q.first, q.second);
            if (!line_style.empty())
            {
                // One \draw path per run of finite points; a run of a single point draws nothing.
                std::string name = styleName(line_style);
                std::string out, path, last;
                out.reserve(p.size() * 20);
                size_t run = 0;
                auto flush = [&]() {
                    if (run > 1)
                        out += path + ";\n";
                    path.clear();
                    run = 0;
                };
                for (const auto &q : p)
                {
                    if (!finite(q.first, q.second))
                    {
                        flush();
                        continue;
                    }
                    // Long polylines are cut into paths of at most 500 points (sharing the joint) so that TeX
                    // does not run out of memory on one huge path.
                    if (run == 500)
                    {
                        out += path + ";\n";
                        path = "\\draw[" + name + "] (" + last + ")";
                        run = 1;
                    }
                    std::string xy;
                    latex_detail::appendNumber(xy, q.first);
                    xy += ',';
                    latex_detail::appendNumber(xy, q.second);
                    path += run == 0 ? "\\draw[" + name + "] (" : std::string(" -- (");
                    path += xy;
                    path += ')';
                    last = std::move(xy);
                    if (++run % 8 == 0)
                        path += '\n';
                }
                flush();
                text(out);
            }
            if (!mark_style.empty() && !mark.empty())
            {
                Chunk ch;
                ch.mark_name = markName(mark_style, mark, mark_scale);
                ch.marks.reserve(p.size());
                for (size_t i = 0; i < p.size(); ++i)
                {
                    if (!finite(p[i].first, p[i].second))
                        continue;
                    // Direction: the mean of the adjacent (finite) segment directions.
                    float dx = 0, dy = 0;
                    auto add = [&](size_t a, size_t b) {
                        if (!finite(p[a].first, p[a].second) || !finite(p[b].first, p[b].second))
                            return;
                        float ux = p[b].first - p[a].first, uy = p[b].second - p[a].second;
                        float len = std::hypot(ux, uy);
                        if (len > 0)
                        {
                            dx += ux / len;
                            dy += uy / len;
                        }
                    };
                    if (i > 0)
                        add(i - 1, i);
                    if (i + 1 < p.size())
                        add(i, i + 1);
                    ch.marks.push_back({p[i].first, p[i].second, dx, dy});
                }
                chunks.push_back(std::move(ch));
            }
        }

        void polygon(const std::vector<Vector2f> &pts, const std::string &style)
        {
            std::string s = "\\draw[" + styleName(style) + "] ";
            for (const auto &v : pts)
            {
                float x = tx(v.x()), y = ty(v.y());
                if (!finite(x, y))
                    return;
                track(x, y);
                s += "(" + pt(x, y) + ") -- ";
            }
            text(s + "cycle;\n");
        }

        void addGrid(bool horizontal, const std::string &style, float tick)
        {
            if (!(tick > 0) || !std::isfinite(tick))
                return;
            grids.push_back({horizontal, styleName(style), tick});
        }

        void addAxis(bool is_x, const std::string &style, std::string format, unsigned int position, float tick,
                     float crossing)
        {
            if (!(tick > 0) || !std::isfinite(tick))
                return;
            float c = is_x ? ty(crossing) : tx(crossing);
            if (!std::isfinite(c))
                return;
            if (is_x)
                track(std::numeric_limits<float>::quiet_NaN(), c);
            else
                track(c, std::numeric_limits<float>::quiet_NaN());
            axes.push_back({is_x, styleName(style), std::move(format), position, tick, c});
        }

        Frame frame() const
        {
            Frame f{};
            bool empty = min_x > max_x || min_y > max_y;
            f.min_x = empty ? 0.0 : min_x;
            f.max_x = empty ? 1.0 : max_x;
            f.min_y = empty ? 0.0 : min_y;
            f.max_y = empty ? 1.0 : max_y;
            double rx = clip ? clip_max_x - clip_min_x : f.max_x - f.min_x;
            double ry = clip ? clip_max_y - clip_min_y : f.max_y - f.min_y;
            f.sx = (rx > 0 ? size_w / rx : 1.0) * user_scale_x;
            f.sy = (ry > 0 ? size_h / ry : 1.0) * user_scale_y;
            f.ox = overrun_type == overrun_relative ? (f.max_x - f.min_x) * overrun_magnitude / 100.0 : overrun_magnitude;
            f.oy = overrun_type == overrun_relative ? (f.max_y - f.min_y) * overrun_magnitude / 100.0 : overrun_magnitude;
            return f;
        }

        //! Multiples of `tick` inside [lo, hi]; capped so that a tiny tick cannot explode the output.
        static std::vector<double> ticks(double lo, double hi, double tick)
        {
            std::vector<double> v;
            double first = std::ceil(lo / tick - 1e-6), last = std::floor(hi / tick + 1e-6);
            if (!(last - first < 10000))
                return v;
            for (double k = first; k <= last; k += 1.0)
                v.push_back(k * tick + 0.0);   // + 0.0 turns -0 into 0 (label "0", not "-0")
            return v;
        }

        void writeGrids(std::string &out, const Frame &f) const
        {
            double x0 = f.min_x - f.ox, x1 = f.max_x + f.ox, y0 = f.min_y - f.oy, y1 = f.max_y + f.oy;
            for (const auto &g : grids)
            {
                for (double v : g.horizontal ? ticks(y0, y1, g.tick) : ticks(x0, x1, g.tick))
                {
                    if (g.horizontal)
                        out += "\\draw[" + g.style + "] (" + pt(x0, v) + ") -- (" + pt(x1, v) + ");\n";
                    else
                        out += "\\draw[" + g.style + "] (" + pt(v, y0) + ") -- (" + pt(v, y1) + ");\n";
                }
            }
        }

        void writeAxes(std::string &out, const Frame &f) const
        {
            double x0 = f.min_x - f.ox, x1 = f.max_x + f.ox, y0 = f.min_y - f.oy, y1 = f.max_y + f.oy;
            // Tick marks are 0.1 cm long on paper: convert to data units per axis.
            double tick_y = 0.05 / f.sy, tick_x = 0.05 / f.sx;
            for (const auto &a : axes)
            {
                std::string anc = latex_detail::tikzAnchor(a.position);
                bool log = a.is_x ? axis_type_x == axis_type_log10 : axis_type_y == axis_type_log10;
                if (a.is_x)
                {
                    out += "\\draw[" + a.style + "] (" + pt(x0, a.crossing) + ") -- (" + pt(x1, a.crossing) + ");\n";
                }
                else
                {
                    out += "\\draw[" + a.style + "] (" + pt(a.crossing, y0) + ") -- (" + pt(a.crossing, y1) + ");\n";
                }
                for (double v : a.is_x ? ticks(x0, x1, a.tick) : ticks(y0, y1, a.tick))
                {
                    if (a.is_x)
                        out += "\\draw[" + a.style + "] (" + pt(v, a.crossing - tick_y) + ") -- (" +
                               pt(v, a.crossing + tick_y) + ")";
                    else
                        out += "\\draw[" + a.style + "] (" + pt(a.crossing - tick_x, v) + ") -- (" +
                               pt(a.crossing + tick_x, v) + ")";
                    std::string label = a.format.empty() ? "" : numberToLatexString(log ? std::pow(10.0, v) : v, a.format);
                    if (!label.empty())
                    {
                        // The label touches the tick end on the side the position flags name.
                        double lx = a.is_x ? v : a.crossing, ly = a.is_x ? a.crossing : v;
                        if (a.position & position_above)
                            ly += a.is_x ? tick_y : 0.0;
                        else if (a.position & position_below)
                            ly -= a.is_x ? tick_y : 0.0;
                        if (a.position & position_right)
                            lx += a.is_x ? 0.0 : tick_x;
                        else if (a.position & position_left)
                            lx -= a.is_x ? 0.0 : tick_x;
                        out += " (" + pt(lx, ly) + ") node[anchor=" + anc + "] {" + label + "}";
                    }
                    out += ";\n";
                }
            }
            // Descriptions sit outside the plot region (beyond the tick labels): centred below it and left of it.
            if (!description_x.empty())
                out += "\\node[anchor=north, yshift=-0.7cm] at (" + pt((x0 + x1) / 2, y0) + ") {" +
                       LaTeX::escapeLaTeXCharacters(description_x) + "};\n";
            if (!description_y.empty())
                out += "\\node[anchor=south, rotate=90, yshift=1.2cm] at (" + pt(x0, (y0 + y1) / 2) + ") {" +
                       LaTeX::escapeLaTeXCharacters(description_y) + "};\n";
        }

        unsigned int axis_type_x, axis_type_y;
        float size_w = 10, size_h = 10, border_cm = 0.1f, mark_radius = 0.1f;
        unsigned int overrun_type = overrun_relative;
        float overrun_magnitude = 5;
        float user_scale_x = 1, user_scale_y = 1;
        bool clip = false;
        float clip_min_x = 0, clip_max_x = 0, clip_min_y = 0, clip_max_y = 0;
        float min_x, max_x, min_y, max_y;

        latex_detail::TikzNames names;                               // styles, colours, marks
        std::vector<Chunk> chunks;                                   // primitives in insertion order
        std::vector<Grid> grids;
        std::vector<Axis> axes;
        std::string description_x, description_y;
    };
}
