// Standalone TikZ export of 3D scenes: perspective camera, marks, lines and faces in depth order
// (docs/reference.md, "LaTeXTikz3D").
//
// Complexity of writeTEX: the faces' BSP tree costs O(F log F) for F faces that rarely cross and up to O(F^2)
// fragments when many do; lines and marks are sorted into it (O(n log n)); the text is linear in what is drawn.
// Adding objects is amortised O(1) each. The scene is kept, so writeTEX may be called again (e.g. per view).
#pragma once

#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>
#include <list>
#include <map>
#include <memory>
#include <ostream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include <Eigen/Dense>

#include "rtl/Core.h"
#include "rtl/Transformation.h"
#include "rtl/io/LaTeXTikzCommon.h"
#include "rtl/io/LaTeXUtility.h"
#include "rtl/io/TikzBudget.h"

namespace rtl
{
    //! A small 3D renderer producing TikZ: objects are kept in world coordinates, and writeTEX maps them into the
    //! camera, clips them to the view frustum, orders them back to front and projects them.
    //!
    //! Conventions:
    //! - Camera: the view RigidTf3f maps world to camera coordinates; the camera sits at the origin looking down -z
    //!   with y up. A point projects to (f x / -z, f y / -z) * max(width, height) / 2 cm, f = 1 / tan(fov / 2). The
    //!   picture is exactly width x height cm, centred at (0, 0), and clipped to that rectangle (or to the
    //!   setExportClipping rectangle).
    //! - Auto-fit: a view translation containing NaN (and the default view, looking down -z) places the camera so
    //!   that the rendered region is centred and just fits the field of view.
    //! - Rendered region = min region, if set, united with the bounding boxes of all marks, lines and faces, then
    //!   intersected with the max region, if set. Axes are clipped to it (enlarged by the grid/axis overrun).
    //! - Hidden surfaces: faces form a BSP tree (split where they cross, epsilon relative to the scene size); lines
    //!   and marks are sorted into it, so everything is painted back to front. A face uses front_style when its
    //!   normal points towards the camera and back_style otherwise; an empty style leaves that side unpainted (the
    //!   style text is applied to `\path`, so it should say fill= and/or draw=). Edges of the original polygons are
    //!   drawn with line_style if it is non-empty (edges created by BSP splits are not).
    //! - Styles, colours and mark templates follow LaTeXTikz2D (StyleA, ColorA, `\MarkA`). 3D marks take four arguments
    //!   (x, y, rotation in degrees, scale); the scale is mark_radius times the perspective factor relative to the
    //!   centre of the rendered region, so a mark there is `\MarkRadius` = 0.1 cm * mark_radius.
    //! - pdflatex's memory (TikzBudget.h), an addition to RTL: a scene beyond texMarkLimit() mark equivalents
    //!   (default Drawing2D::pdflatex_mark_limit, 8,000; a mark counts 1, a line, axis, face fill or face outline
    //!   1/2; axis labels and BSP splits are not counted) is written with every k-th added mark only and a note below
    //!   the picture; scenes within it are written as before, byte for byte. If the lines, axes and faces alone
    //!   exceed it, writeTEX/writeTikz throw std::length_error before writing anything. setTexMarkLimit(0): no limit.
    //! - TeX's dimensions (about 575 cm), an addition to RTL: writeTikz throws std::length_error before writing anything
    //!   if the export size, a clip corner, the picture's extent (1.1 times the clip rectangle, which objects may
    //!   reach, on either side) or a mark's radius at the reference depth (0.1 cm * mark_radius) is beyond
    //!   latex_detail::tex_paper_limit_cm (500 cm); writeTEX also if the border or the page (extent plus two
    //!   borders) is. Near the camera a mark's scale is clamped (max_mark_scale; and within 250 cm of the centre
    //!   unless at most 100), mark rotations beyond +-3600 degrees are written modulo 360, and axis labels projected
    //!   beyond 250 cm (far outside the clip) are left out. Scenes within these limits are written as before.
    class LaTeXTikz3D
    {
    public:
        static const unsigned int overrun_relative = 0, overrun_absolute = 1, axis_type_linear = 0,
                                  axis_type_log10 = 1;
        static const unsigned int position_above = latex_detail::tikz_position_above,
                                  position_below = latex_detail::tikz_position_below,
                                  position_right = latex_detail::tikz_position_right,
                                  position_left = latex_detail::tikz_position_left;
        static inline const char *latex_mark_blank = latex_detail::tikz_mark_blank;
        static inline const char *latex_mark_cross = latex_detail::tikz_mark_cross;
        static inline const char *latex_mark_mark = latex_detail::tikz_mark_mark;
        static inline const char *latex_mark_dot = latex_detail::tikz_mark_dot;
        static inline const char *latex_mark_robot = latex_detail::tikz_mark_robot;
        static inline const char *latex_var_style = latex_detail::tikz_var_style;

        //! The largest perspective scale of a mark (`\MarkRadius` 0.1 cm * 1000: a dot of 200 cm across): nearer to the
        //! camera it stops growing.
        static constexpr double max_mark_scale = 1000.0;

        LaTeXTikz3D() { clearAll(); }
        LaTeXTikz3D(LaTeXTikz3D &&le) noexcept = default;
        LaTeXTikz3D &operator=(LaTeXTikz3D &&le) noexcept = default;
        LaTeXTikz3D(const LaTeXTikz3D &) = delete;
        LaTeXTikz3D &operator=(const LaTeXTikz3D &) = delete;
        ~LaTeXTikz3D() = default;

        //! Picture size in cm.
        void setExportSize(float width, float height)
        {
            export_w = width > 0 ? width : 10.0f;
            export_h = height > 0 ? height : 10.0f;
        }
        //! Clips the picture to this rectangle (cm, picture centred at the origin) instead of the export size.
        void setExportClipping(float p1_x, float p1_y, float p2_x, float p2_y)
        {
            clip_set = true;
            clip_min = Eigen::Vector2d(std::min(p1_x, p2_x), std::min(p1_y, p2_y));
            clip_max = Eigen::Vector2d(std::max(p1_x, p2_x), std::max(p1_y, p2_y));
        }
        //! fov in degrees; orientation maps world to camera coordinates (NaN translation: auto-fit).
        void setView(float fov, const RigidTf3f &orientation)
        {
            setFov(fov);
            view_rot = orientation.rotMat().data().cast<double>();
            view_tr = orientation.trVec().data().cast<double>();
        }
        //! Looks along camera_dir (world), keeping world +z up on the picture (+y if looking along z); auto-fit.
        void setView(float fov, const Vector3f &camera_dir)
        {
            setFov(fov);
            Eigen::Vector3d d = camera_dir.data().cast<double>();
            if (!(d.norm() > 0) || !d.allFinite())
                d = Eigen::Vector3d(0, 0, -1);
            d.normalize();
            Eigen::Vector3d zc = -d;
            Eigen::Vector3d up = std::abs(d.z()) > 0.999 ? Eigen::Vector3d(0, 1, 0) : Eigen::Vector3d(0, 0, 1);
            Eigen::Vector3d xc = up.cross(zc).normalized();
            Eigen::Vector3d yc = zc.cross(xc);
            view_rot.row(0) = xc.transpose();
            view_rot.row(1) = yc.transpose();
            view_rot.row(2) = zc.transpose();
            view_tr = Eigen::Vector3d::Constant(std::numeric_limits<double>::quiet_NaN());
        }
        void setBorder(float border) { border_cm = std::max(0.0f, border); }
        //! Budget in mark equivalents (see the class comment); 0: no limit (lualatex, whose memory grows).
        void setTexMarkLimit(size_t limit) { tex_mark_limit = limit; }
        size_t texMarkLimit() const { return tex_mark_limit; }
        //! Non-empty: a frame around the picture drawn with this TikZ option text, e.g. "draw=black, thick".
        void setFrameStyle(const std::string &style) { frame_style = style; }
        void setGridAxisOverrun(unsigned int type, float magnitude)
        {
            overrun_type = type == overrun_absolute ? overrun_absolute : overrun_relative;
            overrun_magnitude = std::max(0.0f, magnitude);
        }
        void setMaxPlotRegion(const Vector3f &p1, const Vector3f &p2)
        {
            max_region = true;
            max_lo = p1.data().cast<double>().cwiseMin(p2.data().cast<double>());
            max_hi = p1.data().cast<double>().cwiseMax(p2.data().cast<double>());
        }
        void setMinPlotRegion(const Vector3f &p1, const Vector3f &p2)
        {
            min_region = true;
            min_lo = p1.data().cast<double>().cwiseMin(p2.data().cast<double>());
            min_hi = p1.data().cast<double>().cwiseMax(p2.data().cast<double>());
        }

        //! Data and settings (size, border, frame, regions, overrun, clipping) back to defaults; the view stays.
        void clearAll()
        {
            clearData();
            export_w = export_h = 10.0f;
            border_cm = 0.1f;
            frame_style.clear();
            overrun_type = overrun_relative;
            overrun_magnitude = 5.0f;
            clip_set = false;
            min_region = max_region = false;
            tex_mark_limit = Drawing2D::pdflatex_mark_limit;
        }
        //! Removes objects, styles, colours and marks; keeps size, border, view and regions.
        void clearData()
        {
            names.clear();
            mark_items.clear();
            line_items.clear();
            face_items.clear();
            axis_items.clear();
        }

        //! Whether there is anything to draw: a mark, line or face, or a min region. Without, writeTEX writes
        //! nothing (as RTL): it neither creates nor touches the file.
        [[nodiscard]] bool hasContent() const
        {
            return min_region || !mark_items.empty() || !line_items.empty() || !face_items.empty();
        }

        //! Writes the standalone document if hasContent(); throws std::runtime_error if the file cannot be written
        //! and std::length_error (file not touched: the document is made before the file is opened) if the scene
        //! cannot be thinned into texMarkLimit() or is beyond TeX's dimensions.
        void writeTEX(const std::string &file_name)
        {
            if (!hasContent())
                return;
            latex_detail::writeTexFile(file_name, "LaTeXTikz3D", [this](std::ostream &os) { writeTEX(os); });
        }
        void writeTEX(std::ostream &os) { writeTexTo(os); }
        //! What writeTEX writes, as a string, without any stream (not an overload of writeTEX: that takes file names).
        std::string texString()
        {
            return io_detail::textString([this](std::string &out) { writeTexTo(out); });
        }
        //! writeTEX into a std::ostream or a std::string (TextSink.h).
        template<class Out>
        void writeTexTo(Out &os)
        {
            if (!hasContent())
                return;
            texLimits(true);   // these throw before the preamble is written
            thinning();
            latex_detail::writeTikzDocument(os, border_cm, [this](Out &o) { writeTikzTo(o); });
        }
        //! Writes only the tikzpicture (everything it defines is local to it). A scene without objects and without
        //! a min region gives an empty picture of the export size. Thinned or std::length_error as in the class comment.
        void writeTikz(std::ostream &os) { writeTikzTo(os); }
        //! What writeTikz writes, as a string, without any stream.
        std::string tikzString()
        {
            return io_detail::textString([this](std::string &out) { writeTikzTo(out); });
        }
        //! writeTikz into a std::ostream or a std::string (TextSink.h).
        template<class Out>
        void writeTikzTo(Out &target)
        {
            io_detail::TextOut<Out> os{target};
            texLimits(false);
            const latex_detail::TikzThinning thin = thinning();
            std::string out = "\\begin{tikzpicture}[";
            out += names.styleOptions();
            out += "]\n";
            out += names.colorDefinitions();
            out += "\\pgfmathsetmacro{\\MarkRadius}{0.1}\n";
            out += names.markDefinitions();
            double hw = export_w / 2.0, hh = export_h / 2.0;
            out += "\\path (" + pt(-hw, -hh) + ") rectangle (" + pt(hw, hh) + ");\n";
            out += "\\begin{scope}\n";
            Eigen::Vector2d c_lo = clip_set ? clip_min : Eigen::Vector2d(-hw, -hh);
            Eigen::Vector2d c_hi = clip_set ? clip_max : Eigen::Vector2d(hw, hh);
            out += "\\clip (" + pt(c_lo.x(), c_lo.y()) + ") rectangle (" + pt(c_hi.x(), c_hi.y()) + ");\n";
            os << out;
            out.clear();
            render(out, c_lo, c_hi, thin);
            os << out;
            out = "\\end{scope}\n";
            if (thin.thinned())
                out += "\\node[anchor=north west, yshift=-0.1cm] at (" + pt(-hw, -hh) + ") {" +
                       latex_detail::tikzMarkThinningNote(thin) + "};\n";
            if (!frame_style.empty())
                out += "\\draw[" + frame_style + "] (" + pt(-hw, -hh) + ") rectangle (" + pt(hw, hh) + ");\n";
            out += "\\end{tikzpicture}\n";
            os << out;
        }

        //! A line along beg -> end extended across the rendered region (plus overrun), drawn in depth order, with
        //! labels numberToLatexString(t, num_format) every `tick` of the coordinate t along the axis direction
        //! (t = p . dir, i.e. the world coordinate for an axis along x, y or z through the origin).
        void addAxis(const std::string &style, std::string num_format, unsigned int num_position, float tick,
                     const Vector3f &beg, const Vector3f &end)
        {
            Eigen::Vector3d b = beg.data().cast<double>(), e = end.data().cast<double>();
            if (!b.allFinite() || !e.allFinite() || !((e - b).norm() > 0))
                return;
            axis_items.push_back({styleName(style), std::move(num_format), num_position, tick, b, e});
        }
        void addMark(const Vector3f &pos, const std::string &mark_style, const std::string &mark_template,
                     float rotation = 0.0f, float mark_radius = 1.0f)
        {
            Eigen::Vector3d p = pos.data().cast<double>();
            if (!p.allFinite() || mark_style.empty() || mark_template.empty())
                return;
            mark_items.push_back({p, markName(mark_style, mark_template), rotation, mark_radius});
        }
        void addMarks(const std::vector<Vector3f> &vpos, const std::string &mark_style,
                      const std::string &mark_template, float rotation = 0.0f, float mark_radius = 1.0f)
        {
            for (const auto &p : vpos)
                addMark(p, mark_style, mark_template, rotation, mark_radius);
        }
        void addLine(const LineSegment3f &ls, const std::string &style)
        {
            Eigen::Vector3d a = ls.beg().data().cast<double>(), b = ls.end().data().cast<double>();
            if (!a.allFinite() || !b.allFinite())
                return;
            line_items.push_back({a, b, styleName(style)});
        }
        void addLines(const std::vector<LineSegment3f> &vls, const std::string &style)
        {
            for (const auto &l : vls)
                addLine(l, style);
        }
        //! A planar polygon (>= 3 points); its normal() tells the front side.
        void addFace(const Polygon3Df &face, const std::string &front_style, const std::string &back_style,
                     const std::string &line_style)
        {
            const auto &pts = face.points();
            if (pts.size() < 3)
                return;
            Face f;
            for (const auto &p : pts)
            {
                f.pts.push_back(p.data().cast<double>());
                if (!f.pts.back().allFinite())
                    return;
            }
            f.normal = face.normal().data().cast<double>();
            if (!f.normal.allFinite() || !(f.normal.norm() > 0))
                f.normal = newell(f.pts);
            if (!(f.normal.norm() > 0))
                return;   // degenerate: all points on a line
            f.normal.normalize();
            f.front = front_style.empty() ? std::string() : styleName(front_style);
            f.back = back_style.empty() ? std::string() : styleName(back_style);
            f.line = line_style.empty() ? std::string() : styleName(line_style);
            face_items.push_back(std::move(f));
        }
        void addFace(const std::vector<Polygon3Df> &vfs, const std::string &front_style, const std::string &back_style,
                     const std::string &line_style)
        {
            for (const auto &f : vfs)
                addFace(f, front_style, back_style, line_style);
        }

        //! See LaTeXTikz2D::saveColor.
        std::string saveColor(const std::string &color) { return names.color(color); }

    private:
        using V3 = Eigen::Vector3d;

        struct MarkItem
        {
            V3 p;
            std::string mark;
            float rotation, radius;
        };
        struct LineItem
        {
            V3 a, b;
            std::string style;
        };
        struct Face
        {
            std::vector<V3> pts;
            V3 normal;
            std::string front, back, line;
        };
        struct AxisItem
        {
            std::string style, format;
            unsigned int position;
            float tick;
            V3 beg, end;
        };

        // Camera-space render items.
        struct Poly
        {
            std::vector<V3> v;
            std::vector<char> edge;   // edge i (v[i] -> v[i+1]) belongs to the original polygon outline
            size_t face;
            V3 normal;                // camera-space normal of the original face
        };
        struct Item
        {
            bool is_mark;
            V3 a, b;                  // mark: a; line: a -> b
            size_t ref;               // index into mark_items / the line style table
            double depth() const { return is_mark ? a.norm() : ((a + b) / 2).norm(); }
        };
        struct Node
        {
            V3 n;
            double d;
            std::vector<Poly> polys;
            std::vector<Item> on, front_items, back_items;
            std::unique_ptr<Node> front, back;
        };

        void setFov(float fov)
        {
            double f = std::isfinite(fov) ? fov : 60.0;
            f = std::clamp(f, 1e-3, 179.0);
            focal = 1.0 / std::tan(f * latex_detail::pi / 360.0);
        }

        static std::string pt(double x, double y) { return latex_detail::tikzPoint(x, y); }

        std::string styleName(const std::string &style) { return names.style(style); }

        //! 3D marks take the perspective scale as a fourth argument.
        std::string markName(const std::string &style, const std::string &templ)
        {
            return names.mark(style, templ, "", "[4]", "shift={(#1,#2)}, rotate=#3, scale=#4");
        }

        static V3 newell(const std::vector<V3> &p)
        {
            V3 n = V3::Zero();
            for (size_t i = 0; i < p.size(); ++i)
            {
                const V3 &a = p[i], &b = p[(i + 1) % p.size()];
                n.x() += (a.y() - b.y()) * (a.z() + b.z());
                n.y() += (a.z() - b.z()) * (a.x() + b.x());
                n.z() += (a.x() - b.x()) * (a.y() + b.y());
            }
            return n;
        }

        //! The rendered region; false if there is nothing to render.
        bool region(V3 &lo, V3 &hi) const
        {
            const double inf = std::numeric_limits<double>::infinity();
            lo = V3::Constant(inf);
            hi = V3::Constant(-inf);
            auto add = [&](const V3 &p) {
                lo = lo.cwiseMin(p);
                hi = hi.cwiseMax(p);
            };
            if (min_region)
            {
                add(min_lo);
                add(min_hi);
            }
            for (const auto &m : mark_items)
                add(m.p);
            for (const auto &l : line_items)
            {
                add(l.a);
                add(l.b);
            }
            for (const auto &f : face_items)
                for (const auto &p : f.pts)
                    add(p);
            if (!(lo.x() <= hi.x()))
                return false;
            if (max_region)
            {
                lo = lo.cwiseMax(max_lo);
                hi = hi.cwiseMin(max_hi);
                if (!(lo.array() <= hi.array()).all())
                    return false;
            }
            return true;
        }

        //! Camera pose for this write: the set view, or the auto-fitted one.
        void camera(const V3 &lo, const V3 &hi, Eigen::Matrix3d &R, V3 &t) const
        {
            R = view_rot;
            t = view_tr;
            if (t.allFinite())
                return;
            std::vector<V3> c;
            for (int i = 0; i < 8; ++i)
                c.push_back(R * V3(i & 1 ? hi.x() : lo.x(), i & 2 ? hi.y() : lo.y(), i & 4 ? hi.z() : lo.z()));
            V3 clo = c[0], chi = c[0];
            for (const auto &p : c)
            {
                clo = clo.cwiseMin(p);
                chi = chi.cwiseMax(p);
            }
            t.x() = -(clo.x() + chi.x()) / 2;
            t.y() = -(clo.y() + chi.y()) / 2;
            double m = std::max(export_w, export_h), ax = export_w / m, ay = export_h / m;
            double margin = 1e-3 * (hi - lo).norm() + 1e-9;
            double tz = std::numeric_limits<double>::infinity();
            for (const auto &p : c)
            {
                double need = std::max({focal * std::abs(p.x() + t.x()) / ax, focal * std::abs(p.y() + t.y()) / ay, margin});
                tz = std::min(tz, -p.z() - need);
            }
            t.z() = tz;
        }

        //! Keeps the part of a polygon with h(p) = n.p + c <= 0; the cut edge is not an original edge.
        static Poly clipPoly(const Poly &in, const V3 &n, double c)
        {
            Poly out{{}, {}, in.face, in.normal};
            size_t k = in.v.size();
            for (size_t i = 0; i < k; ++i)
            {
                const V3 &a = in.v[i], &b = in.v[(i + 1) % k];
                double ha = n.dot(a) + c, hb = n.dot(b) + c;
                if (ha <= 0)
                {
                    out.v.push_back(a);
                    out.edge.push_back(in.edge[i]);   // the next vertex is b or a point on this edge
                }
                if ((ha <= 0) != (hb <= 0))
                {
                    out.v.push_back(a + (b - a) * (ha / (ha - hb)));
                    out.edge.push_back(hb <= 0 ? in.edge[i] : 0);
                }
            }
            if (out.v.size() < 3)
                out.v.clear();
            return out;
        }

        static bool clipLine(V3 &a, V3 &b, const V3 &n, double c)
        {
            double ha = n.dot(a) + c, hb = n.dot(b) + c;
            if (ha > 0 && hb > 0)
                return false;
            if (ha > 0)
                a = a + (b - a) * (ha / (ha - hb));
            else if (hb > 0)
                b = b + (a - b) * (hb / (hb - ha));
            return true;
        }

        //! Splits p by plane (n, d) with tolerance eps into front/back parts; coplanar polygons go to `on`.
        static void split(const Poly &p, const V3 &n, double d, double eps, std::vector<Poly> &front,
                          std::vector<Poly> &back, std::vector<Poly> &on)
        {
            size_t k = p.v.size();
            std::vector<double> s(k);
            bool any_f = false, any_b = false;
            for (size_t i = 0; i < k; ++i)
            {
                s[i] = n.dot(p.v[i]) - d;
                any_f |= s[i] > eps;
                any_b |= s[i] < -eps;
            }
            if (!any_f && !any_b)
                return on.push_back(p);
            if (!any_b)
                return front.push_back(p);
            if (!any_f)
                return back.push_back(p);
            Poly f{{}, {}, p.face, p.normal}, b{{}, {}, p.face, p.normal};
            for (size_t i = 0; i < k; ++i)
            {
                size_t j = (i + 1) % k;
                bool a_f = s[i] >= -eps, a_b = s[i] <= eps, b_f = s[j] >= -eps, b_b = s[j] <= eps;
                if (a_f)
                {
                    f.v.push_back(p.v[i]);
                    f.edge.push_back((s[i] > eps || b_f) ? p.edge[i] : 0);
                }
                if (a_b)
                {
                    b.v.push_back(p.v[i]);
                    b.edge.push_back((s[i] < -eps || b_b) ? p.edge[i] : 0);
                }
                if ((s[i] > eps && s[j] < -eps) || (s[i] < -eps && s[j] > eps))
                {
                    V3 x = p.v[i] + (p.v[j] - p.v[i]) * (s[i] / (s[i] - s[j]));
                    f.v.push_back(x);
                    f.edge.push_back(s[j] > eps ? p.edge[i] : 0);
                    b.v.push_back(x);
                    b.edge.push_back(s[j] < -eps ? p.edge[i] : 0);
                }
            }
            if (f.v.size() >= 3)
                front.push_back(std::move(f));
            if (b.v.size() >= 3)
                back.push_back(std::move(b));
        }

        static std::unique_ptr<Node> build(std::vector<Poly> polys, double eps)
        {
            if (polys.empty())
                return nullptr;
            auto node = std::make_unique<Node>();
            auto planeOf = [](const Poly &p, V3 &n, double &d) {
                n = newell(p.v);
                if (n.dot(p.normal) < 0)
                    n = -n;
                n.normalize();
                V3 centroid = V3::Zero();
                for (const auto &v : p.v)
                    centroid += v;
                d = n.dot(centroid / static_cast<double>(p.v.size()));
            };
            // Splitter: the best of up to 5 evenly spaced candidates (balanced sides, few splits), so that e.g. a
            // stack of parallel faces gives a tree of logarithmic depth instead of a list.
            size_t best = 0;
            if (polys.size() > 8)
            {
                double best_cost = std::numeric_limits<double>::infinity();
                for (size_t k = 0; k < 5; ++k)
                {
                    size_t c = k * (polys.size() - 1) / 4;
                    V3 n;
                    double d;
                    planeOf(polys[c], n, d);
                    size_t nf = 0, nb = 0, ns = 0;
                    for (const auto &p : polys)
                    {
                        bool f = false, b = false;
                        for (const auto &v : p.v)
                        {
                            double sd = n.dot(v) - d;
                            f |= sd > eps;
                            b |= sd < -eps;
                        }
                        nf += f && !b;
                        nb += b && !f;
                        ns += f && b;
                    }
                    double cost = std::abs(static_cast<double>(nf) - static_cast<double>(nb)) + 3.0 * static_cast<double>(ns);
                    if (cost < best_cost)
                    {
                        best_cost = cost;
                        best = c;
                    }
                }
            }
            std::swap(polys[0], polys[best]);
            const Poly &sp = polys.front();
            V3 n;
            planeOf(sp, n, node->d);
            node->n = n;
            std::vector<Poly> front, back;
            node->polys.push_back(sp);
            for (size_t i = 1; i < polys.size(); ++i)
                split(polys[i], n, node->d, eps, front, back, node->polys);
            polys.clear();
            node->front = build(std::move(front), eps);
            node->back = build(std::move(back), eps);
            return node;
        }

        //! Puts an item that lies on `side` of node's plane into that subtree (or the node's side list).
        static void place(Node *node, const Item &it, int side, double eps)
        {
            std::unique_ptr<Node> &child = side > 0 ? node->front : node->back;
            if (!child)
                (side > 0 ? node->front_items : node->back_items).push_back(it);
            else
                insert(child.get(), it, eps);
        }

        static void insert(Node *node, const Item &it, double eps)
        {
            while (true)
            {
                double sa = node->n.dot(it.a) - node->d;
                double sb = it.is_mark ? sa : node->n.dot(it.b) - node->d;
                int side;   // 1 front, -1 back, 0 on
                if (std::abs(sa) <= eps && std::abs(sb) <= eps)
                    side = 0;
                else if (sa >= -eps && sb >= -eps)
                    side = 1;
                else if (sa <= eps && sb <= eps)
                    side = -1;
                else
                {
                    V3 x = it.a + (it.b - it.a) * (sa / (sa - sb));
                    Item fa = it, fb = it;
                    fa.b = x;
                    fb.a = x;
                    // Each half goes to its end's side without being tested against this plane again: with large
                    // coordinates the rounded split point can miss the plane by more than eps, and re-testing
                    // recursed without end (fuzz_tikz3d: stack overflow).
                    place(node, fa, sa > 0 ? 1 : -1, eps);
                    place(node, fb, sb > 0 ? 1 : -1, eps);
                    return;
                }
                if (side == 0)
                    return node->on.push_back(it);
                std::unique_ptr<Node> &child = side > 0 ? node->front : node->back;
                if (!child)
                    return (side > 0 ? node->front_items : node->back_items).push_back(it);
                node = child.get();
            }
        }

        struct Projector
        {
            double f, k;
            std::string operator()(const V3 &p) const { return pt(f * p.x() / -p.z() * k, f * p.y() / -p.z() * k); }
        };

        //! A mark's perspective scale, clamped near the camera: at most max_mark_scale, and its reach (0.2 cm times
        //! the scale: a robot's nose) not beyond 250 cm from the centre unless the scale is at most 100 (20 cm).
        static double markScale(double scale, double x, double y)
        {
            const double room = (0.5 * latex_detail::tex_paper_limit_cm - std::max(std::abs(x), std::abs(y))) / 0.2;
            const double max = std::min(max_mark_scale, std::max(100.0, room));
            return std::abs(scale) > max ? std::copysign(max, scale) : scale;
        }

        void emitItems(std::string &out, std::vector<Item> &items, const Projector &P, double ref_depth) const
        {
            std::sort(items.begin(), items.end(), [](const Item &a, const Item &b) { return a.depth() > b.depth(); });
            for (const auto &it : items)
            {
                if (it.is_mark)
                {
                    const MarkItem &m = mark_items[it.ref];
                    const double x = P.f * it.a.x() / -it.a.z() * P.k, y = P.f * it.a.y() / -it.a.z() * P.k;
                    out += m.mark + "{" + latex_detail::number(x) + "}{" + latex_detail::number(y) + "}{" +
                           latex_detail::number(latex_detail::tikzAngle(m.rotation)) + "}{" +
                           latex_detail::number(markScale(m.radius * ref_depth / -it.a.z(), x, y)) + "}\n";
                }
                else
                    out += "\\draw[" + line_styles[it.ref] + "] (" + P(it.a) + ") -- (" + P(it.b) + ");\n";
            }
        }

        void emitPoly(std::string &out, const Poly &p, const Projector &P) const
        {
            const Face &f = face_items[p.face];
            V3 centroid = V3::Zero();
            for (const auto &v : p.v)
                centroid += v;
            centroid /= static_cast<double>(p.v.size());
            bool facing = p.normal.dot(-centroid) > 0;
            const std::string &style = facing ? f.front : f.back;
            if (!style.empty())
            {
                out += "\\path[" + style + "] ";
                for (const auto &v : p.v)
                    out += "(" + P(v) + ") -- ";
                out += "cycle;\n";
            }
            if (f.line.empty())
                return;
            std::string path;
            bool open = false;
            for (size_t i = 0; i < p.v.size(); ++i)
            {
                if (!p.edge[i])
                {
                    open = false;
                    continue;
                }
                if (!open)
                    path += " (" + P(p.v[i]) + ")";
                path += " -- (" + P(p.v[(i + 1) % p.v.size()]) + ")";
                open = true;
            }
            if (!path.empty())
                out += "\\draw[" + f.line + "]" + path + ";\n";
        }

        void traverse(std::string &out, Node *node, const Projector &P, double ref_depth) const
        {
            bool cam_front = -node->d > 0;   // camera at the origin
            auto side = [&](bool front) {
                Node *child = front ? node->front.get() : node->back.get();
                if (child)
                    traverse(out, child, P, ref_depth);
                else
                    emitItems(out, front ? node->front_items : node->back_items, P, ref_depth);
            };
            side(!cam_front);
            for (const auto &p : node->polys)
                emitPoly(out, p, P);
            emitItems(out, node->on, P, ref_depth);
            side(cam_front);
        }

        //! std::length_error (refuseBeyondTex) if the picture is beyond TeX's dimensions; see the class comment.
        void texLimits(bool document) const
        {
            const std::string who = "LaTeXTikz3D::writeTikz";
            using latex_detail::refuseBeyondTex;
            refuseBeyondTex(export_w, "the export width", who);
            refuseBeyondTex(export_h, "the export height", who);
            if (clip_set)
                for (double v : {clip_min.x(), clip_min.y(), clip_max.x(), clip_max.y()})
                    refuseBeyondTex(v, "a clip corner", who);
            // Lines, faces and marks reach 1.1 times the clip rectangle (render's frustum) on either side.
            const double w = 2.0 * std::max(export_w / 2.0, 1.1 * std::max(std::abs(clipLo().x()), std::abs(clipHi().x())));
            const double h = 2.0 * std::max(export_h / 2.0, 1.1 * std::max(std::abs(clipLo().y()), std::abs(clipHi().y())));
            refuseBeyondTex(w, "the picture width", who);
            refuseBeyondTex(h, "the picture height", who);
            for (const auto &m : mark_items)
                if (!std::isnan(m.radius))   // NaN is written as 0
                    refuseBeyondTex(0.1 * m.radius, "a mark radius", who);
            if (document)
            {
                refuseBeyondTex(border_cm, "the border", who);
                refuseBeyondTex(w + 2.0 * border_cm, "the page width", who);
                refuseBeyondTex(h + 2.0 * border_cm, "the page height", who);
            }
        }
        Eigen::Vector2d clipLo() const { return clip_set ? clip_min : Eigen::Vector2d(-export_w / 2.0, -export_h / 2.0); }
        Eigen::Vector2d clipHi() const { return clip_set ? clip_max : Eigen::Vector2d(export_w / 2.0, export_h / 2.0); }

        latex_detail::TikzThinning thinning() const
        {
            size_t fixed = line_items.size() + axis_items.size();
            for (const auto &f : face_items)
                fixed += static_cast<size_t>(!f.front.empty() || !f.back.empty()) + static_cast<size_t>(!f.line.empty());
            return latex_detail::tikzMarkThinning(mark_items.size(), fixed, tex_mark_limit, "LaTeXTikz3D::writeTikz");
        }

        void render(std::string &out, const Eigen::Vector2d &c_lo, const Eigen::Vector2d &c_hi,
                    const latex_detail::TikzThinning &thin)
        {
            V3 lo, hi;
            if (!region(lo, hi))
                return;
            Eigen::Matrix3d R;
            V3 t;
            camera(lo, hi, R, t);
            double scene = (hi - lo).norm();
            double eps = 1e-6 * (scene + t.norm()) + 1e-12;
            double k = std::max(export_w, export_h) / 2.0;
            Projector P{focal, k};
            V3 centre = R * ((lo + hi) / 2) + t;
            double ref_depth = centre.z() < 0 ? -centre.z() : 1.0;

            // View frustum, a little larger than the visible rectangle, keeps projected coordinates bounded (TeX
            // dimensions overflow at about 575 cm) and removes everything behind the camera.
            double lim_x = 1.1 * std::max(std::abs(c_lo.x()), std::abs(c_hi.x())) / k + 1e-9;
            double lim_y = 1.1 * std::max(std::abs(c_lo.y()), std::abs(c_hi.y())) / k + 1e-9;
            double near = std::max(1e-6 * (scene + t.norm()), 1e-9);
            std::vector<std::pair<V3, double>> planes = {
                    {V3(0, 0, 1), near},                 // z <= -near
                    {V3(focal, 0, lim_x), 0.0},          // f x / -z <= lim_x
                    {V3(-focal, 0, lim_x), 0.0},
                    {V3(0, focal, lim_y), 0.0},
                    {V3(0, -focal, lim_y), 0.0}};

            std::vector<Poly> polys;
            for (size_t i = 0; i < face_items.size(); ++i)
            {
                const Face &f = face_items[i];
                Poly p{{}, std::vector<char>(f.pts.size(), 1), i, R * f.normal};
                for (const auto &v : f.pts)
                    p.v.push_back(R * v + t);
                for (const auto &pl : planes)
                {
                    if (p.v.empty())
                        break;
                    p = clipPoly(p, pl.first, pl.second);
                }
                if (p.v.size() >= 3)
                    polys.push_back(std::move(p));
            }
            line_styles.clear();
            std::vector<Item> items;
            std::map<std::string, size_t> style_index;
            for (const auto &l : line_items)
                addLineItem(items, R * l.a + t, R * l.b + t, l.style, style_index, planes);
            for (size_t i = 0; i < mark_items.size(); i += thin.stride)
            {
                V3 p = R * mark_items[i].p + t;
                bool inside = true;
                for (const auto &pl : planes)
                    inside = inside && pl.first.dot(p) + pl.second <= 0;
                if (inside)
                    items.push_back({true, p, p, i});
            }
            // Axes: the infinite line through beg/end cropped to the (overrun-enlarged) region.
            V3 over = V3::Constant(overrun_magnitude);
            if (overrun_type == overrun_relative)
                over = (hi - lo) * overrun_magnitude / 100.0;
            V3 alo = lo - over, ahi = hi + over;
            std::string labels;
            for (const auto &a : axis_items)
            {
                V3 dir = (a.end - a.beg).normalized();
                double t0, t1;
                if (!cropLine(a.beg, dir, alo, ahi, t0, t1))
                    continue;
                addLineItem(items, R * (a.beg + dir * t0) + t, R * (a.beg + dir * t1) + t, a.style, style_index, planes);
                if (a.format.empty() || !(a.tick > 0) || !std::isfinite(a.tick))
                    continue;
                double origin = a.beg.dot(dir);   // coordinate value at a.beg
                double v0 = std::ceil((origin + t0) / a.tick - 1e-9), v1 = std::floor((origin + t1) / a.tick + 1e-9);
                if (!std::isfinite(v0) || !std::isfinite(v1) || !(v1 - v0 < 1000))
                    continue;
                // Counted with an integer: `v += 1.0` stands still once |v| >= 2^53 (as in 2D).
                double last_value = -std::numeric_limits<double>::infinity();
                size_t count = v1 < v0 ? 0 : static_cast<size_t>(v1 - v0) + 1;
                for (size_t k = 0; k < count; ++k)
                {
                    double value = (v0 + static_cast<double>(k)) * a.tick;
                    if (!std::isfinite(value) || !(value > last_value))
                        continue;
                    last_value = value;
                    V3 p = R * (a.beg + dir * (value - origin)) + t;
                    if (p.z() >= -near || !p.allFinite())
                        continue;
                    const double lx = P.f * p.x() / -p.z() * P.k, ly = P.f * p.y() / -p.z() * P.k;
                    if (std::max(std::abs(lx), std::abs(ly)) > 0.5 * latex_detail::tex_paper_limit_cm)
                        continue;   // far outside the clip, and TeX could not hold the picture's extent
                    std::string label = latex_detail::numberToLatexString(value, a.format);
                    if (!label.empty())
                        labels += "\\node[anchor=" + latex_detail::tikzAnchor(a.position) + ", inner sep=1pt] at (" +
                                  P(p) + ") {" + label + "};\n";
                }
            }

            std::unique_ptr<Node> root = build(std::move(polys), eps);
            if (!root)
                emitItems(out, items, P, ref_depth);
            else
            {
                for (const auto &it : items)
                    insert(root.get(), it, eps);
                traverse(out, root.get(), P, ref_depth);
            }
            out += labels;
        }

        void addLineItem(std::vector<Item> &items, V3 a, V3 b, const std::string &style,
                         std::map<std::string, size_t> &style_index,
                         const std::vector<std::pair<V3, double>> &planes)
        {
            for (const auto &pl : planes)
                if (!clipLine(a, b, pl.first, pl.second))
                    return;
            auto it = style_index.find(style);
            if (it == style_index.end())
            {
                it = style_index.emplace(style, line_styles.size()).first;
                line_styles.push_back(style);
            }
            items.push_back({false, a, b, it->second});
        }

        //! Parameters t0 <= t1 (along the unit dir from p) where the infinite line is inside the box.
        static bool cropLine(const V3 &p, const V3 &dir, const V3 &lo, const V3 &hi, double &t0, double &t1)
        {
            t0 = -std::numeric_limits<double>::infinity();
            t1 = std::numeric_limits<double>::infinity();
            for (int i = 0; i < 3; ++i)
            {
                if (std::abs(dir[i]) < 1e-12)
                {
                    if (p[i] < lo[i] || p[i] > hi[i])
                        return false;   // parallel to this slab and outside it
                    continue;
                }
                double a = (lo[i] - p[i]) / dir[i], b = (hi[i] - p[i]) / dir[i];
                t0 = std::max(t0, std::min(a, b));
                t1 = std::min(t1, std::max(a, b));
            }
            return t0 < t1 && std::isfinite(t0) && std::isfinite(t1);
        }

        float export_w = 10, export_h = 10, border_cm = 0.1f;
        double focal = 1.0 / std::tan(30.0 * latex_detail::pi / 180.0);   // 60 degrees
        Eigen::Matrix3d view_rot = Eigen::Matrix3d::Identity();
        V3 view_tr = V3::Constant(std::numeric_limits<double>::quiet_NaN());
        bool clip_set = false;
        Eigen::Vector2d clip_min = Eigen::Vector2d::Zero(), clip_max = Eigen::Vector2d::Zero();
        std::string frame_style;
        size_t tex_mark_limit = Drawing2D::pdflatex_mark_limit;
        unsigned int overrun_type = overrun_relative;
        float overrun_magnitude = 5;
        bool min_region = false, max_region = false;
        V3 min_lo = V3::Zero(), min_hi = V3::Zero(), max_lo = V3::Zero(), max_hi = V3::Zero();

        latex_detail::TikzNames names;   // styles, colours, marks
        std::vector<MarkItem> mark_items;
        std::vector<LineItem> line_items;
        std::vector<Face> face_items;
        std::vector<AxisItem> axis_items;
        std::vector<std::string> line_styles;   // per render: style names referenced by line items
    };
}
