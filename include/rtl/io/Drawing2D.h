// The back-end-neutral 2D drawing model behind LaTeXTikz2D and Svg2D: the drawing calls of LaTeXTikz2D record
// primitives, registered styles/colours/marks, grids, axes and data bounds; writeTikz (Tikz2DWriter.h) and writeSvg
// (Svg2D.h) turn the same model into TikZ or SVG.
//
// Why a model: RTL's exporter wrote TikZ while it was being called; recording the calls first lets one drawing be
// written as TikZ, as SVG, or thinned to fit pdflatex's memory, and lets the writers be tested on the model.
// Complexity: each drawing call is amortised O(1) (plus its point count); a writer is linear in the primitives,
// marks and polyline points. Invariant: the data bounds cover every finite coordinate recorded (grids and axes
// extend them by the overrun); non-finite points are skipped and break polylines.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "rtl/Core.h"
#include "rtl/Transformation.h"
#include "rtl/io/LaTeXTikzCommon.h"
#include "rtl/io/LaTeXUtility.h"

namespace rtl
{
    //! Records 2D primitives in data coordinates (log10 of them on log axes) in insertion order.
    //!
    //! Model conventions shared by the back-ends:
    //! - Styles are TikZ key/value text ("style={draw=red,thick}" or "draw=red"); each distinct text is registered
    //!   once as StyleA, StyleB, ... and primitives refer to that name. Colours (saveColor) become ColorA, ...; marks
    //!   (style, template, scale) become `\MarkA`, ... The registration order is the order of the calls.
    //! - On log10 axes every coordinate is replaced by its log10 before it is tracked (non-positive values are
    //!   dropped); grid and axis ticks are then decades. Non-finite points are skipped and break polylines.
    //! - The data bounds cover every drawn point (circles and ellipses by their bounding boxes, clamped to the float
    //!   range where those overflow), axis crossings and
    //!   setMinPlotRegion points; frame() maps them (or the clip region) to the requested size.
    class Drawing2D
    {
    public:
        static const unsigned int overrun_relative = 0, overrun_absolute = 1;
        static const unsigned int axis_type_linear = 0, axis_type_log10 = 1;
        static const unsigned int position_above = detail::tikz_position_above,
                                  position_below = detail::tikz_position_below,
                                  position_right = detail::tikz_position_right,
                                  position_left = detail::tikz_position_left;
        //! addEdge(s) options: arrow tips at the end and/or the beginning of each edge.
        static const unsigned int edge_arrow_end = 0x01, edge_arrow_beg = 0x02;

        //! Mark templates: TikZ code around the local origin, sized by `\MarkRadius`; "@style" becomes the style name.
        static inline const char *latex_mark_blank = detail::tikz_mark_blank;
        static inline const char *latex_mark_cross = detail::tikz_mark_cross;
        static inline const char *latex_mark_mark = detail::tikz_mark_mark;
        static inline const char *latex_mark_dot = detail::tikz_mark_dot;
        static inline const char *latex_mark_robot = detail::tikz_mark_robot;
        static inline const char *latex_var_style = detail::tikz_var_style;

        //! What one TikZ picture may hold by default, in mark equivalents (TikzBudget.h): below what pdflatex's
        //! default main memory held here (about 9,000 filled dot marks), with a margin.
        static constexpr size_t pdflatex_mark_limit = 8000;

        //! At most this many grid lines or axis ticks per grid/axis: beyond it the grid/axis draws no ticks at all
        //! (a tick that small relative to the range is a mistake, and TeX could not hold the output anyway).
        static constexpr size_t max_ticks = 10000;

        //! What a primitive is; its geometry lives in Primitive's fields as documented there.
        enum class Kind
        {
            polyline,   // points: one run of >= 2 finite points
            marks,      // marks: positions and directions; mark: the \MarkX name
            edge,       // points: begin, end; options: edge_arrow_*
            polygon,    // points: the closed polygon's vertices
            rectangle,  // points: two opposite corners
            circle,     // points: centre; r1: radius
            ellipse,    // points: centre; r1, r2: radii; a1: rotation in radians (counter-clockwise)
            pie,        // points: centre; r1: radius; a1, a2: start and end angle in radians
            text        // points: position; text: the user's text, not escaped
        };
        struct MarkPoint
        {
            float x, y, dx, dy;   // position and the (unnormalised) local direction, (0, 0) if none
        };
        struct Primitive
        {
            Kind kind;
            std::string style;                          // registered style name (StyleX)
            std::vector<std::pair<float, float>> points;
            std::vector<MarkPoint> marks;
            std::string mark;                           // \MarkX for Kind::marks
            std::string text;
            unsigned int options = 0;
            float r1 = 0, r2 = 0, a1 = 0, a2 = 0;
        };
        //! A registered mark: the style name, the template (latex_mark_* or user TikZ) and the scale.
        struct MarkDef
        {
            std::string style, templ;
            float scale;
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
        //! Data frame (empty drawing: [0,1]^2), scales in cm per data unit and grid/axis overruns in data units.
        struct Frame
        {
            double min_x, max_x, min_y, max_y, sx, sy, ox, oy;
        };

        explicit Drawing2D(unsigned int axis_x = Drawing2D::axis_type_linear,
                           unsigned int axis_y = Drawing2D::axis_type_linear)
                : axis_type_x(axis_x == axis_type_log10 ? axis_type_log10 : axis_type_linear),
                  axis_type_y(axis_y == axis_type_log10 ? axis_type_log10 : axis_type_linear)
        {
            clearAll();
        }
        virtual ~Drawing2D() = default;
        Drawing2D(const Drawing2D &) = default;
        Drawing2D(Drawing2D &&) noexcept = default;
        Drawing2D &operator=(const Drawing2D &) = default;
        Drawing2D &operator=(Drawing2D &&) noexcept = default;

        //! Output size of the data range (or clip region) in cm; non-positive values give 10.
        void setSize(float width, float height)
        {
            size_w = width > 0 ? width : 10.0f;
            size_h = height > 0 ? height : 10.0f;
        }
        void setBorder(float border) { border_cm = std::max(0.0f, border); }
        void setMarkRadius(float radius) { mark_radius = std::max(0.0f, radius); }
        //! The TikZ writer's budget in mark equivalents (a mark 1, a polyline point 1/8, any other primitive, grid
        //! line or axis tick 1/2): a bigger drawing is thinned with a note in the picture (TikzBudget.h). 0: no limit
        //! (for lualatex, whose memory grows); default pdflatex_mark_limit.
        void setTexMarkLimit(size_t limit) { tex_mark_limit = limit; }
        size_t texMarkLimit() const { return tex_mark_limit; }
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
            tex_mark_limit = pdflatex_mark_limit;
            overrun_type = overrun_relative;
            overrun_magnitude = 5.0f;
            user_scale_x = user_scale_y = 1.0f;
            clip = false;
        }

        //! Removes primitives, styles, colours, marks, grids, axes, descriptions and the data bounds.
        void clearData()
        {
            names.clear();
            mark_defs.clear();
            prims.clear();
            grid_list.clear();
            axis_list.clear();
            description_x.clear();
            description_y.clear();
            min_x = min_y = std::numeric_limits<float>::max();
            max_x = max_y = -std::numeric_limits<float>::max();
        }

        //! Horizontal grid lines every `tick` in y (decades on a log10 axis); ignored unless tick is finite and > 0.
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
        //! Axis descriptions (escaped by the back-end), below the x range and left of the y range.
        void addDescriptionX(const std::string &description) { description_x = description; }
        void addDescriptionY(const std::string &description) { description_y = description; }

        //! Polyline through (x[i], y[i]) if line_style is non-empty, and marks at every point if mark_style and mark
        //! are non-empty. Nothing is drawn if the sizes differ or the input is empty.
        void addPlot(const std::vector<float> &x, const std::vector<float> &y, const std::string &line_style,
                     const std::string &mark_style = "", const std::string &mark = Drawing2D::latex_mark_blank,
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
                     const std::string &mark = Drawing2D::latex_mark_blank, float mark_scale = 1.0f)
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
            Primitive p = primitive(Kind::edge, style);
            p.options = options & (edge_arrow_end | edge_arrow_beg);
            track(x1, y1);
            track(x2, y2);
            p.points = {{x1, y1}, {x2, y2}};
            prims.push_back(std::move(p));
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
            Primitive p = primitive(Kind::rectangle, style);
            p.points = {{x1, y1}, {x2, y2}};
            prims.push_back(std::move(p));
        }
        //! Circle of `radius` data units (an ellipse on paper if the axes are scaled differently).
        void addCircle(const Vector2f &centre, float radius, const std::string &style)
        {
            round(Kind::circle, centre, radius, 0.0f, 0.0f, style);
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
            if (!std::isfinite(ex) || !std::isfinite(ey))
            {
                // The squares overflow float beyond about 1.8e19: the box in double, clamped to the float range, so
                // the bounds (and the writers' extent checks) still see the ellipse.
                auto half = [](double a, double b, double ca, double cb) {
                    return toFloatRange(std::sqrt(a * a * ca * ca + b * b * cb * cb));
                };
                ex = half(x_radius, y_radius, c, s);
                ey = half(x_radius, y_radius, s, c);
            }
            track(boundSum(x, -ex), boundSum(y, -ey));
            track(boundSum(x, ex), boundSum(y, ey));
            Primitive p = primitive(Kind::ellipse, style);
            p.points = {{x, y}};
            p.r1 = x_radius;
            p.r2 = y_radius;
            p.a1 = rotation;
            prims.push_back(std::move(p));
        }
        //! Circular sector from angle_beg to angle_end (radians, counter-clockwise).
        void addPie(const Vector2f &centre, float radius, float angle_beg, float angle_end, const std::string &style)
        {
            round(Kind::pie, centre, radius, angle_beg, angle_end, style);
        }
        void addLine(const Vector2f &beg, const Vector2f &end, const std::string &style)
        {
            addEdge(LineSegment2f(beg, end), style);
        }
        void addLine(const LineSegment2f &ls, const std::string &style) { addEdge(ls, style); }
        void addLines(const std::vector<LineSegment2f> &ls, const std::string &style) { addEdges(ls, style); }
        //! A text node at `position` (the back-end escapes it); `style` may set anchor, font, colour, ...
        void addText(const std::string &text_str, const std::string &style, const Vector2f &position)
        {
            float x = tx(position.x()), y = ty(position.y());
            if (!finite(x, y))
                return;
            track(x, y);
            Primitive p = primitive(Kind::text, style);
            p.points = {{x, y}};
            p.text = text_str;
            prims.push_back(std::move(p));
        }

        //! Data bounds (log10 units on log axes); +-max float while empty.
        float maxX() const { return max_x; }
        float minX() const { return min_x; }
        float maxY() const { return max_y; }
        float minY() const { return min_y; }
        //! Effective scale (cm per data unit) that a writer would use now.
        float scaleX() const { return static_cast<float>(frame().sx); }
        float scaleY() const { return static_cast<float>(frame().sy); }

        //! Registers a colour spec such as "{hsb}{0.3,0.8,0.5}", "{rgb}{1,0,0}", "{RGB}{255,0,0}", "{HTML}{FF0000}"
        //! and returns its name "ColorX"; the same spec always returns the same name.
        std::string saveColor(const std::string &color) { return names.color(color); }

        // --- The model, read by the back-ends ---
        const std::vector<Primitive> &primitives() const { return prims; }
        const std::vector<Grid> &grids() const { return grid_list; }
        const std::vector<Axis> &axes() const { return axis_list; }
        const std::string &descriptionX() const { return description_x; }
        const std::string &descriptionY() const { return description_y; }
        //! Registered style, colour and mark names (TikZ definitions and the normalised style texts).
        const detail::TikzNames &registry() const { return names; }
        //! Registered marks by name (`\MarkX`).
        const std::map<std::string, MarkDef> &markDefs() const { return mark_defs; }
        unsigned int axisTypeX() const { return axis_type_x; }
        unsigned int axisTypeY() const { return axis_type_y; }
        float border() const { return border_cm; }
        float markRadius() const { return mark_radius; }
        bool clipped() const { return clip; }
        //! The clip rectangle (min x, min y, max x, max y); meaningful if clipped().
        std::vector<float> clipRegion() const { return {clip_min_x, clip_min_y, clip_max_x, clip_max_y}; }

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

        //! The distinct multiples of `tick` inside [lo, hi], ascending; empty if there would be more than max_ticks
        //! or the bounds are not finite. Counted with an integer, so it ends even where |value / tick| >= 2^53 and
        //! consecutive multiples are no longer distinct doubles.
        static std::vector<double> ticks(double lo, double hi, double tick)
        {
            std::vector<double> v;
            double first = std::ceil(lo / tick - 1e-6), last = std::floor(hi / tick + 1e-6);
            if (!std::isfinite(first) || !std::isfinite(last) || !(last - first < static_cast<double>(max_ticks)))
                return v;
            if (last < first)
                return v;
            size_t n = static_cast<size_t>(last - first) + 1;
            for (size_t i = 0; i < n; ++i)
            {
                double value = (first + static_cast<double>(i)) * tick + 0.0;   // + 0.0: label "0", not "-0"
                if (!std::isfinite(value))
                    break;
                if (v.empty() || value > v.back())
                    v.push_back(value);
            }
            return v;
        }

    protected:
        static bool finite(float a, float b) { return std::isfinite(a) && std::isfinite(b); }

    private:
        float tx(float x) const { return axis_type_x == axis_type_log10 ? (x > 0 ? std::log10(x) : std::numeric_limits<float>::quiet_NaN()) : x; }
        float ty(float y) const { return axis_type_y == axis_type_log10 ? (y > 0 ? std::log10(y) : std::numeric_limits<float>::quiet_NaN()) : y; }

        static float toFloatRange(double v)
        {
            const double m = std::numeric_limits<float>::max();
            return static_cast<float>(std::clamp(v, -m, m));
        }
        //! a + b, or the float range's end where that overflows: a bound beyond float still widens the frame.
        static float boundSum(float a, float b)
        {
            float s = a + b;
            return std::isfinite(s) ? s : toFloatRange(static_cast<double>(a) + static_cast<double>(b));
        }

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

        Primitive primitive(Kind kind, const std::string &style)
        {
            Primitive p;
            p.kind = kind;
            p.style = names.style(style);
            return p;
        }

        //! Marks reset the unit vectors to 1 cm in TikZ, so they keep their size whatever the axis scaling.
        std::string markName(const std::string &style, const std::string &templ, float scale)
        {
            std::string s = detail::number(scale);
            std::string name =
                    names.mark(style, templ, "\n" + s, "[3]", "shift={(#1,#2)}, x=1cm, y=1cm, rotate=#3, scale=" + s);
            if (mark_defs.find(name) == mark_defs.end())
                mark_defs.emplace(name, MarkDef{names.style(style), templ, scale});
            return name;
        }

        void plot(const std::vector<std::pair<float, float>> &p, const std::string &line_style,
                  const std::string &mark_style, const std::string &mark, float mark_scale)
        {
            for (const auto &q : p)
                if (finite(q.first, q.second))
                    track(q.first, q.second);
            if (!line_style.empty())
            {
                // One polyline per run of finite points; a run of a single point draws nothing.
                std::string name = names.style(line_style);
                Primitive run;
                auto flush = [&]() {
                    if (run.points.size() > 1)
                    {
                        run.kind = Kind::polyline;
                        run.style = name;
                        prims.push_back(std::move(run));
                    }
                    run = Primitive();
                };
                for (const auto &q : p)
                {
                    if (!finite(q.first, q.second))
                        flush();
                    else
                        run.points.push_back(q);
                }
                flush();
            }
            if (!mark_style.empty() && !mark.empty())
            {
                Primitive ch;
                ch.kind = Kind::marks;
                ch.mark = markName(mark_style, mark, mark_scale);
                ch.style = mark_defs.at(ch.mark).style;
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
                prims.push_back(std::move(ch));
            }
        }

        //! A circle or pie: centre, |radius| and angles a1, a2 (unused by circles), tracked by the bounding box of the
        //! full circle; nothing is drawn (and no style registered) unless all are finite.
        void round(Kind kind, const Vector2f &centre, float radius, float a1, float a2, const std::string &style)
        {
            float x = tx(centre.x()), y = ty(centre.y());
            if (!finite(x, y) || !std::isfinite(radius) || !finite(a1, a2))
                return;
            radius = std::abs(radius);
            track(boundSum(x, -radius), boundSum(y, -radius));
            track(boundSum(x, radius), boundSum(y, radius));
            Primitive p = primitive(kind, style);
            p.points = {{x, y}};
            p.r1 = radius;
            p.a1 = a1;
            p.a2 = a2;
            prims.push_back(std::move(p));
        }

        void polygon(const std::vector<Vector2f> &pts, const std::string &style)
        {
            // The style is registered even if a vertex is not finite (as LaTeXTikz2D always did).
            Primitive p = primitive(Kind::polygon, style);
            for (const auto &v : pts)
            {
                float x = tx(v.x()), y = ty(v.y());
                if (!finite(x, y))
                    return;
                track(x, y);
                p.points.emplace_back(x, y);
            }
            prims.push_back(std::move(p));
        }

        void addGrid(bool horizontal, const std::string &style, float tick)
        {
            if (!(tick > 0) || !std::isfinite(tick))
                return;
            grid_list.push_back({horizontal, names.style(style), tick});
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
            axis_list.push_back({is_x, names.style(style), std::move(format), position, tick, c});
        }

        unsigned int axis_type_x, axis_type_y;
        float size_w = 10, size_h = 10, border_cm = 0.1f, mark_radius = 0.1f;
        size_t tex_mark_limit = pdflatex_mark_limit;
        unsigned int overrun_type = overrun_relative;
        float overrun_magnitude = 5;
        float user_scale_x = 1, user_scale_y = 1;
        bool clip = false;
        float clip_min_x = 0, clip_max_x = 0, clip_min_y = 0, clip_max_y = 0;
        float min_x, max_x, min_y, max_y;

        detail::TikzNames names;              // styles, colours, marks
        std::map<std::string, MarkDef> mark_defs;   // \MarkX -> definition
        std::vector<Primitive> prims;               // in insertion order
        std::vector<Grid> grid_list;
        std::vector<Axis> axis_list;
        std::string description_x, description_y;
    };
}
