// View, projection and clipping of a Drawing3D: the camera pose (set or auto-fitted), the view frustum, and the
// scene mapped into camera space and clipped to it, ready for depth ordering (DepthOrder3D.h) and writing.
//
// Conventions (those of LaTeXTikz3D): the camera sits at the origin looking down -z with y up; a camera-space
// point p projects to (f x / -z, f y / -z) * k cm, f the focal factor 1 / tan(fov / 2), k = max(width, height) / 2.
// Complexity: linear in the scene (each face is clipped by five planes in O(its points)); axis labels cost O(1)
// each, at most 1000 per axis.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include <Eigen/Dense>

#include "rtl/io/Drawing3D.h"
#include "rtl/io/LaTeXUtility.h"

namespace rtl
{
    namespace detail
    {
        using V3 = Eigen::Vector3d;

        //! A face (or a part of it) in camera space.
        struct CameraPoly3D
        {
            std::vector<V3> v;
            std::vector<char> edge;   // edge i (v[i] -> v[i+1]) belongs to the original polygon outline
            size_t face;              // index into Drawing3D::faces()
            V3 normal;                // camera-space normal of the original face
        };
        //! A mark or a line (or a part of it) in camera space.
        struct CameraItem3D
        {
            bool is_mark;
            V3 a, b;      // mark: a; line: a -> b
            size_t ref;   // mark: index into Drawing3D::marks(); line: index into CameraScene3D::line_styles
            double depth() const { return is_mark ? a.norm() : ((a + b) / 2).norm(); }
        };
        //! An axis label position in camera space (in front of the camera), with its value.
        struct CameraLabel3D
        {
            V3 p;
            double value;
            size_t axis;   // index into Drawing3D::axes()
        };

        //! Camera-space projection with the focal factor f and the scale k (cm).
        struct Projector3D
        {
            double f, k;
            double x(const V3 &p) const { return f * p.x() / -p.z() * k; }
            double y(const V3 &p) const { return f * p.y() / -p.z() * k; }
        };

        //! The scene of one write in camera space, clipped to the view frustum.
        struct CameraScene3D
        {
            bool empty = true;                    // nothing to render (empty rendered region)
            std::vector<CameraPoly3D> polys;      // faces in insertion order
            std::vector<CameraItem3D> items;      // lines, then marks, then axes, each in insertion order
            std::vector<std::string> line_styles; // distinct line style names in first-use order
            std::vector<CameraLabel3D> labels;    // axis labels in axis, then value order
            Projector3D P{1, 1};
            double ref_depth = 1;                 // depth of the region's centre (1 if behind the camera)
            double eps = 0;                       // plane tolerance, relative to the scene size
        };

        //! A rotation (rows: camera axes in world coordinates) looking along dir, keeping world +z up on the picture
        //! (+y when looking along z). A zero or non-finite dir looks down -z.
        inline Eigen::Matrix3d lookAlong3D(V3 d)
        {
            if (!(d.norm() > 0) || !d.allFinite())
                d = V3(0, 0, -1);
            d.normalize();
            V3 zc = -d;
            V3 up = std::abs(d.z()) > 0.999 ? V3(0, 1, 0) : V3(0, 0, 1);
            V3 xc = up.cross(zc).normalized();
            V3 yc = zc.cross(xc);
            Eigen::Matrix3d r;
            r.row(0) = xc.transpose();
            r.row(1) = yc.transpose();
            r.row(2) = zc.transpose();
            return r;
        }

        //! Camera pose for a write: the set view, or (a non-finite translation) the one placing the region [lo, hi]
        //! centred and just inside the field of view.
        inline void cameraPose3D(const Drawing3D::Settings &s, const V3 &lo, const V3 &hi, Eigen::Matrix3d &R, V3 &t)
        {
            R = s.view_rot;
            t = s.view_tr;
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
            double m = std::max(s.export_w, s.export_h), ax = s.export_w / m, ay = s.export_h / m;
            double margin = 1e-3 * (hi - lo).norm() + 1e-9;
            double tz = std::numeric_limits<double>::infinity();
            for (const auto &p : c)
            {
                double need = std::max({s.focal * std::abs(p.x() + t.x()) / ax, s.focal * std::abs(p.y() + t.y()) / ay, margin});
                tz = std::min(tz, -p.z() - need);
            }
            t.z() = tz;
        }

        //! Keeps the part of a polygon with h(p) = n.p + c <= 0; the cut edge is not an original edge.
        inline CameraPoly3D clipPoly3D(const CameraPoly3D &in, const V3 &n, double c)
        {
            CameraPoly3D out{{}, {}, in.face, in.normal};
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

        //! Keeps the part of the segment a -> b with n.p + c <= 0; false if none.
        inline bool clipLine3D(V3 &a, V3 &b, const V3 &n, double c)
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

        //! Parameters t0 <= t1 (along the unit dir from p) where the infinite line is inside the box.
        inline bool cropLine3D(const V3 &p, const V3 &dir, const V3 &lo, const V3 &hi, double &t0, double &t1)
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

        //! The scene of `d` in camera space, clipped to the view frustum of the clip rectangle [c_lo, c_hi] (cm),
        //! with every `mark_stride`-th mark (>= 1). Axis labels whose projection is beyond `label_reach` cm from the
        //! centre are left out.
        inline CameraScene3D cameraScene3D(const Drawing3D &d, const Eigen::Vector2d &c_lo, const Eigen::Vector2d &c_hi,
                                           size_t mark_stride, double label_reach)
        {
            const Drawing3D::Settings &s = d.settings();
            CameraScene3D cs;
            V3 lo, hi;
            if (!d.region(lo, hi))
                return cs;
            cs.empty = false;
            Eigen::Matrix3d R;
            V3 t;
            cameraPose3D(s, lo, hi, R, t);
            double scene = (hi - lo).norm();
            cs.eps = 1e-6 * (scene + t.norm()) + 1e-12;
            double k = std::max(s.export_w, s.export_h) / 2.0;
            cs.P = Projector3D{s.focal, k};
            V3 centre = R * ((lo + hi) / 2) + t;
            cs.ref_depth = centre.z() < 0 ? -centre.z() : 1.0;

            // View frustum, a little larger than the visible rectangle, keeps projected coordinates bounded (TeX
            // dimensions overflow at about 575 cm) and removes everything behind the camera.
            double lim_x = 1.1 * std::max(std::abs(c_lo.x()), std::abs(c_hi.x())) / k + 1e-9;
            double lim_y = 1.1 * std::max(std::abs(c_lo.y()), std::abs(c_hi.y())) / k + 1e-9;
            double near = std::max(1e-6 * (scene + t.norm()), 1e-9);
            const double focal = s.focal;
            std::vector<std::pair<V3, double>> planes = {
                    {V3(0, 0, 1), near},                 // z <= -near
                    {V3(focal, 0, lim_x), 0.0},          // f x / -z <= lim_x
                    {V3(-focal, 0, lim_x), 0.0},
                    {V3(0, focal, lim_y), 0.0},
                    {V3(0, -focal, lim_y), 0.0}};

            const auto &faces = d.faces();
            for (size_t i = 0; i < faces.size(); ++i)
            {
                const Drawing3D::Face &f = faces[i];
                CameraPoly3D p{{}, std::vector<char>(f.pts.size(), 1), i, R * f.normal};
                for (const auto &v : f.pts)
                    p.v.push_back(R * v + t);
                for (const auto &pl : planes)
                {
                    if (p.v.empty())
                        break;
                    p = clipPoly3D(p, pl.first, pl.second);
                }
                if (p.v.size() >= 3)
                    cs.polys.push_back(std::move(p));
            }
            std::map<std::string, size_t> style_index;
            auto addLine = [&](V3 a, V3 b, const std::string &style) {
                for (const auto &pl : planes)
                    if (!clipLine3D(a, b, pl.first, pl.second))
                        return;
                auto it = style_index.find(style);
                if (it == style_index.end())
                {
                    it = style_index.emplace(style, cs.line_styles.size()).first;
                    cs.line_styles.push_back(style);
                }
                cs.items.push_back({false, a, b, it->second});
            };
            for (const auto &l : d.lines())
                addLine(R * l.a + t, R * l.b + t, l.style);
            const auto &marks = d.marks();
            for (size_t i = 0; i < marks.size(); i += mark_stride)
            {
                V3 p = R * marks[i].p + t;
                bool inside = true;
                for (const auto &pl : planes)
                    inside = inside && pl.first.dot(p) + pl.second <= 0;
                if (inside)
                    cs.items.push_back({true, p, p, i});
            }
            // Axes: the infinite line through beg/end cropped to the (overrun-enlarged) region.
            V3 over = V3::Constant(s.overrun_magnitude);
            if (s.overrun_type == Drawing3D::overrun_relative)
                over = (hi - lo) * s.overrun_magnitude / 100.0;
            V3 alo = lo - over, ahi = hi + over;
            const auto &axes = d.axes();
            for (size_t ai = 0; ai < axes.size(); ++ai)
            {
                const Drawing3D::AxisItem &a = axes[ai];
                V3 dir = (a.end - a.beg).normalized();
                double t0, t1;
                if (!cropLine3D(a.beg, dir, alo, ahi, t0, t1))
                    continue;
                addLine(R * (a.beg + dir * t0) + t, R * (a.beg + dir * t1) + t, a.style);
                if (a.format.empty() || !(a.tick > 0) || !std::isfinite(a.tick))
                    continue;
                double origin = a.beg.dot(dir);   // coordinate value at a.beg
                double v0 = std::ceil((origin + t0) / a.tick - 1e-9), v1 = std::floor((origin + t1) / a.tick + 1e-9);
                if (!std::isfinite(v0) || !std::isfinite(v1) || !(v1 - v0 < 1000))
                    continue;
                // Counted with an integer: `v += 1.0` stands still once |v| >= 2^53 (as in 2D).
                double last_value = -std::numeric_limits<double>::infinity();
                size_t count = v1 < v0 ? 0 : static_cast<size_t>(v1 - v0) + 1;
                for (size_t j = 0; j < count; ++j)
                {
                    double value = (v0 + static_cast<double>(j)) * a.tick;
                    if (!std::isfinite(value) || !(value > last_value))
                        continue;
                    last_value = value;
                    V3 p = R * (a.beg + dir * (value - origin)) + t;
                    if (p.z() >= -near || !p.allFinite())
                        continue;
                    if (std::max(std::abs(cs.P.x(p)), std::abs(cs.P.y(p))) > label_reach)
                        continue;   // far outside the clip
                    cs.labels.push_back({p, value, ai});
                }
            }
            return cs;
        }
    }
}
