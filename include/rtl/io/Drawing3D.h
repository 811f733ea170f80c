// The 3D scene behind LaTeXTikz3D: what is drawn (marks, lines, faces, axes in world coordinates, with their
// registered styles) and how it is framed (picture size, clip rectangle, border, view, plot regions, mark budget).
// Camera3D.h maps it into the camera, DepthOrder3D.h orders it back to front, Tikz3DWriter.h writes it as TikZ.
//
// Why a model: as on the 2D side (Drawing2D.h), recording the calls first keeps the scene independent of the
// back-end, so one scene can be written per view, thinned to pdflatex's memory, or written by another writer.
// Complexity: each add call is amortised O(1) (plus a face's point count); region() is linear in the scene.
// Invariants: every stored coordinate and normal is finite; a stored face has >= 3 points and a unit normal;
// the style names stored refer to registry().
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include <Eigen/Dense>

#include "rtl/Core.h"
#include "rtl/Transformation.h"
#include "rtl/io/Drawing2D.h"
#include "rtl/io/LaTeXTikzCommon.h"
#include "rtl/io/LaTeXUtility.h"

namespace rtl
{
    //! Records a 3D scene in world coordinates, in insertion order. Its calls and their conventions are those of
    //! LaTeXTikz3D (see there); non-finite input and degenerate faces are dropped when added.
    class Drawing3D
    {
    public:
        using V3 = Eigen::Vector3d;
        static const unsigned int overrun_relative = 0, overrun_absolute = 1;

        struct MarkItem
        {
            V3 p;
            std::string mark;    // registered mark command, e.g. `\MarkA`
            std::string style;   // registered name of the mark's style (for back-ends that do not run templates)
            float rotation, radius;
        };
        struct LineItem
        {
            V3 a, b;
            std::string style;   // registered style name
        };
        struct Face
        {
            std::vector<V3> pts;
            V3 normal;                       // unit, towards the front side
            std::string front, back, line;   // registered style names; empty: not drawn
        };
        struct AxisItem
        {
            std::string style, format;
            unsigned int position;
            float tick;
            V3 beg, end;
        };
        //! How the scene is framed; the defaults are those of clearAll() and of a default view.
        struct Settings
        {
            float export_w = 10, export_h = 10, border_cm = 0.1f;
            double focal = 1.0 / std::tan(30.0 * detail::pi / 180.0);   // 60 degrees
            Eigen::Matrix3d view_rot = Eigen::Matrix3d::Identity();
            V3 view_tr = V3::Constant(std::numeric_limits<double>::quiet_NaN());   // NaN: auto-fit
            bool clip_set = false;
            Eigen::Vector2d clip_min = Eigen::Vector2d::Zero(), clip_max = Eigen::Vector2d::Zero();
            std::string frame_style;
            size_t tex_mark_limit = Drawing2D::pdflatex_mark_limit;
            unsigned int overrun_type = overrun_relative;
            float overrun_magnitude = 5;
            bool min_region = false, max_region = false;
            V3 min_lo = V3::Zero(), min_hi = V3::Zero(), max_lo = V3::Zero(), max_hi = V3::Zero();

            //! The clip rectangle in cm: the set one, or the export size centred at the origin.
            Eigen::Vector2d clipLo() const { return clip_set ? clip_min : Eigen::Vector2d(-export_w / 2.0, -export_h / 2.0); }
            Eigen::Vector2d clipHi() const { return clip_set ? clip_max : Eigen::Vector2d(export_w / 2.0, export_h / 2.0); }
        };

        void setExportSize(float width, float height)
        {
            s.export_w = width > 0 ? width : 10.0f;
            s.export_h = height > 0 ? height : 10.0f;
        }
        void setExportClipping(float p1_x, float p1_y, float p2_x, float p2_y)
        {
            s.clip_set = true;
            s.clip_min = Eigen::Vector2d(std::min(p1_x, p2_x), std::min(p1_y, p2_y));
            s.clip_max = Eigen::Vector2d(std::max(p1_x, p2_x), std::max(p1_y, p2_y));
        }
        //! fov in degrees (non-finite: 60, clamped to [0.001, 179]); rot and tr map world to camera coordinates.
        void setView(float fov, const Eigen::Matrix3d &rot, const V3 &tr)
        {
            setFov(fov);
            s.view_rot = rot;
            s.view_tr = tr;
        }
        void setBorder(float border) { s.border_cm = std::max(0.0f, border); }
        void setTexMarkLimit(size_t limit) { s.tex_mark_limit = limit; }
        void setFrameStyle(const std::string &style) { s.frame_style = style; }
        void setGridAxisOverrun(unsigned int type, float magnitude)
        {
            s.overrun_type = type == overrun_absolute ? overrun_absolute : overrun_relative;
            s.overrun_magnitude = std::max(0.0f, magnitude);
        }
        void setMaxPlotRegion(const Vector3f &p1, const Vector3f &p2)
        {
            s.max_region = true;
            s.max_lo = p1.data().cast<double>().cwiseMin(p2.data().cast<double>());
            s.max_hi = p1.data().cast<double>().cwiseMax(p2.data().cast<double>());
        }
        void setMinPlotRegion(const Vector3f &p1, const Vector3f &p2)
        {
            s.min_region = true;
            s.min_lo = p1.data().cast<double>().cwiseMin(p2.data().cast<double>());
            s.min_hi = p1.data().cast<double>().cwiseMax(p2.data().cast<double>());
        }

        //! Data and settings (size, border, frame, regions, overrun, clipping, mark limit) back to defaults; the
        //! view stays.
        void clearAll()
        {
            clearData();
            s.export_w = s.export_h = 10.0f;
            s.border_cm = 0.1f;
            s.frame_style.clear();
            s.overrun_type = overrun_relative;
            s.overrun_magnitude = 5.0f;
            s.clip_set = false;
            s.min_region = s.max_region = false;
            s.tex_mark_limit = Drawing2D::pdflatex_mark_limit;
        }
        //! Removes objects, styles, colours and marks; keeps the settings.
        void clearData()
        {
            names.clear();
            mark_items.clear();
            line_items.clear();
            face_items.clear();
            axis_items.clear();
        }

        //! A mark, line or face, or a min region.
        [[nodiscard]] bool hasContent() const
        {
            return s.min_region || !mark_items.empty() || !line_items.empty() || !face_items.empty();
        }

        void addAxis(const std::string &style, std::string num_format, unsigned int num_position, float tick,
                     const Vector3f &beg, const Vector3f &end)
        {
            V3 b = beg.data().cast<double>(), e = end.data().cast<double>();
            if (!b.allFinite() || !e.allFinite() || !((e - b).norm() > 0))
                return;
            axis_items.push_back({names.style(style), std::move(num_format), num_position, tick, b, e});
        }
        void addMark(const Vector3f &pos, const std::string &mark_style, const std::string &mark_template,
                     float rotation, float mark_radius)
        {
            V3 p = pos.data().cast<double>();
            if (!p.allFinite() || mark_style.empty() || mark_template.empty())
                return;
            // 3D marks take the perspective scale as a fourth argument. The mark registers its style first anyway, so
            // naming the style here first changes no name.
            std::string style = names.style(mark_style);
            std::string mark = names.mark(mark_style, mark_template, "", "[4]", "shift={(#1,#2)}, rotate=#3, scale=#4");
            mark_items.push_back({p, std::move(mark), std::move(style), rotation, mark_radius});
        }
        void addLine(const LineSegment3f &ls, const std::string &style)
        {
            V3 a = ls.beg().data().cast<double>(), b = ls.end().data().cast<double>();
            if (!a.allFinite() || !b.allFinite())
                return;
            line_items.push_back({a, b, names.style(style)});
        }
        //! A planar polygon (>= 3 points); its normal() tells the front side (Newell's normal if it has none).
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
            f.front = front_style.empty() ? std::string() : names.style(front_style);
            f.back = back_style.empty() ? std::string() : names.style(back_style);
            f.line = line_style.empty() ? std::string() : names.style(line_style);
            face_items.push_back(std::move(f));
        }
        //! Name of a colour spec (ColorA, ...).
        std::string saveColor(const std::string &color) { return names.color(color); }

        //! The rendered region: the min region (if set) united with the bounding boxes of all marks, lines and
        //! faces, intersected with the max region (if set); false if that is empty. O(scene).
        bool region(V3 &lo, V3 &hi) const
        {
            const double inf = std::numeric_limits<double>::infinity();
            lo = V3::Constant(inf);
            hi = V3::Constant(-inf);
            auto add = [&](const V3 &p) {
                lo = lo.cwiseMin(p);
                hi = hi.cwiseMax(p);
            };
            if (s.min_region)
            {
                add(s.min_lo);
                add(s.min_hi);
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
            if (s.max_region)
            {
                lo = lo.cwiseMax(s.max_lo);
                hi = hi.cwiseMin(s.max_hi);
                if (!(lo.array() <= hi.array()).all())
                    return false;
            }
            return true;
        }

        //! Newell's normal of a closed polygon (not normalised; zero if its points are on a line).
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

        const Settings &settings() const { return s; }
        const std::vector<MarkItem> &marks() const { return mark_items; }
        const std::vector<LineItem> &lines() const { return line_items; }
        const std::vector<Face> &faces() const { return face_items; }
        const std::vector<AxisItem> &axes() const { return axis_items; }
        const detail::TikzNames &registry() const { return names; }

    private:
        void setFov(float fov)
        {
            double f = std::isfinite(fov) ? fov : 60.0;
            f = std::clamp(f, 1e-3, 179.0);
            s.focal = 1.0 / std::tan(f * detail::pi / 360.0);
        }

        Settings s;
        detail::TikzNames names;   // styles, colours, marks
        std::vector<MarkItem> mark_items;
        std::vector<LineItem> line_items;
        std::vector<Face> face_items;
        std::vector<AxisItem> axis_items;
    };
}
