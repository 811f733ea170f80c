// The TikZ back-end of Drawing3D: the standalone document or only the tikzpicture, with the conventions of RTL's
// LaTeXTikz3D (docs/reference.md, "LaTeXTikz3D"), within pdflatex's memory (TikzBudget.h) and TeX's dimensions.
//
// Complexity: the depth ordering's (DepthOrder3D.h) plus text linear in what is drawn.
// Invariants: nothing is written when a limit refuses the scene (std::length_error is thrown before the first
// character); every number written is finite and within TeX's dimensions.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <string>
#include <vector>

#include <Eigen/Dense>

#include "rtl/io/Camera3D.h"
#include "rtl/io/DepthOrder3D.h"
#include "rtl/io/Drawing3D.h"
#include "rtl/io/LaTeXTikzCommon.h"
#include "rtl/io/LaTeXUtility.h"
#include "rtl/io/TextSink.h"
#include "rtl/io/TikzBudget.h"

namespace rtl
{
    namespace detail
    {
        //! The largest perspective scale of a 3D mark (`\MarkRadius` 0.1 cm * 1000: a dot of 200 cm across).
        inline constexpr double tikz3d_max_mark_scale = 1000.0;

        //! A mark's perspective scale, clamped near the camera: at most tikz3d_max_mark_scale, and its reach (0.2 cm
        //! times the scale: a robot's nose) not beyond 250 cm from the centre unless the scale is at most 100 (20 cm).
        inline double tikz3dMarkScale(double scale, double x, double y)
        {
            const double room = (0.5 * tex_paper_limit_cm - std::max(std::abs(x), std::abs(y))) / 0.2;
            const double max = std::min(tikz3d_max_mark_scale, std::max(100.0, room));
            return std::abs(scale) > max ? std::copysign(max, scale) : scale;
        }

        //! std::length_error (refuseBeyondTex) if the picture (and, for a document, the page) is beyond TeX's
        //! dimensions: the export size, a clip corner, the extent objects may reach (1.1 times the clip rectangle on
        //! either side), a mark radius at the reference depth, the border.
        inline void tikz3dTexLimits(const Drawing3D &d, bool document)
        {
            const Drawing3D::Settings &s = d.settings();
            const std::string who = "LaTeXTikz3D::writeTikz";
            refuseBeyondTex(s.export_w, "the export width", who);
            refuseBeyondTex(s.export_h, "the export height", who);
            if (s.clip_set)
                for (double v : {s.clip_min.x(), s.clip_min.y(), s.clip_max.x(), s.clip_max.y()})
                    refuseBeyondTex(v, "a clip corner", who);
            // Lines, faces and marks reach 1.1 times the clip rectangle (the camera's frustum) on either side.
            const double w = 2.0 * std::max(s.export_w / 2.0, 1.1 * std::max(std::abs(s.clipLo().x()), std::abs(s.clipHi().x())));
            const double h = 2.0 * std::max(s.export_h / 2.0, 1.1 * std::max(std::abs(s.clipLo().y()), std::abs(s.clipHi().y())));
            refuseBeyondTex(w, "the picture width", who);
            refuseBeyondTex(h, "the picture height", who);
            for (const auto &m : d.marks())
                if (!std::isnan(m.radius))   // NaN is written as 0
                    refuseBeyondTex(0.1 * m.radius, "a mark radius", who);
            if (document)
            {
                refuseBeyondTex(s.border_cm, "the border", who);
                refuseBeyondTex(w + 2.0 * s.border_cm, "the page width", who);
                refuseBeyondTex(h + 2.0 * s.border_cm, "the page height", who);
            }
        }

        //! The mark thinning for the scene's budget: a mark counts 1, a line, axis, face fill or face outline 1/2
        //! (tikzMarkThinning; std::length_error if the fixed objects alone exceed it).
        inline TikzThinning tikz3dThinning(const Drawing3D &d)
        {
            size_t fixed = d.lines().size() + d.axes().size();
            for (const auto &f : d.faces())
                fixed += static_cast<size_t>(!f.front.empty() || !f.back.empty()) + static_cast<size_t>(!f.line.empty());
            return tikzMarkThinning(d.marks().size(), fixed, d.settings().tex_mark_limit, "LaTeXTikz3D::writeTikz");
        }

        //! The TikZ point of a camera-space point.
        inline std::string tikz3dPoint(const detail::Projector3D &P, const Eigen::Vector3d &p)
        {
            return tikzPoint(P.x(p), P.y(p));
        }

        //! The drawing commands of the scene (clipped to [c_lo, c_hi] cm), back to front, then the axis labels.
        inline void tikz3dRender(std::string &out, const Drawing3D &d, const Eigen::Vector2d &c_lo,
                                 const Eigen::Vector2d &c_hi, const TikzThinning &thin)
        {
            detail::CameraScene3D cs = detail::cameraScene3D(d, c_lo, c_hi, thin.stride, 0.5 * tex_paper_limit_cm);
            if (cs.empty)
                return;
            const detail::Projector3D &P = cs.P;
            const double ref_depth = cs.ref_depth;
            std::string labels;
            for (const auto &l : cs.labels)
            {
                const Drawing3D::AxisItem &a = d.axes()[l.axis];
                std::string label = numberToLatexString(l.value, a.format);
                if (!label.empty())
                    labels += "\\node[anchor=" + tikzAnchor(a.position) + ", inner sep=1pt] at (" +
                              tikz3dPoint(P, l.p) + ") {" + label + "};\n";
            }
            auto onItems = [&](const std::vector<detail::CameraItem3D> &items) {
                for (const auto &it : items)
                {
                    if (it.is_mark)
                    {
                        const Drawing3D::MarkItem &m = d.marks()[it.ref];
                        const double x = P.x(it.a), y = P.y(it.a);
                        out += m.mark + "{" + number(x) + "}{" + number(y) + "}{" + number(tikzAngle(m.rotation)) +
                               "}{" + number(tikz3dMarkScale(m.radius * ref_depth / -it.a.z(), x, y)) + "}\n";
                    }
                    else
                        out += "\\draw[" + cs.line_styles[it.ref] + "] (" + tikz3dPoint(P, it.a) + ") -- (" +
                               tikz3dPoint(P, it.b) + ");\n";
                }
            };
            auto onPoly = [&](const detail::CameraPoly3D &p) {
                const Drawing3D::Face &f = d.faces()[p.face];
                Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
                for (const auto &v : p.v)
                    centroid += v;
                centroid /= static_cast<double>(p.v.size());
                bool facing = p.normal.dot(-centroid) > 0;
                const std::string &style = facing ? f.front : f.back;
                if (!style.empty())
                {
                    out += "\\path[" + style + "] ";
                    for (const auto &v : p.v)
                        out += "(" + tikz3dPoint(P, v) + ") -- ";
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
                        path += " (" + tikz3dPoint(P, p.v[i]) + ")";
                    path += " -- (" + tikz3dPoint(P, p.v[(i + 1) % p.v.size()]) + ")";
                    open = true;
                }
                if (!path.empty())
                    out += "\\draw[" + f.line + "]" + path + ";\n";
            };
            detail::paintScene3D(cs, onPoly, onItems);
            out += labels;
        }

        //! Writes only the tikzpicture of the scene into a std::ostream or a std::string (TextSink.h).
        template<class Out>
        void writeTikz3D(const Drawing3D &d, Out &target)
        {
            detail::TextOut<Out> os{target};
            const Drawing3D::Settings &s = d.settings();
            tikz3dTexLimits(d, false);
            const TikzThinning thin = tikz3dThinning(d);
            const TikzNames &names = d.registry();
            std::string out = "\\begin{tikzpicture}[";
            out += names.styleOptions();
            out += "]\n";
            out += names.colorDefinitions();
            out += "\\pgfmathsetmacro{\\MarkRadius}{0.1}\n";
            out += names.markDefinitions();
            double hw = s.export_w / 2.0, hh = s.export_h / 2.0;
            out += "\\path (" + tikzPoint(-hw, -hh) + ") rectangle (" + tikzPoint(hw, hh) + ");\n";
            out += "\\begin{scope}\n";
            Eigen::Vector2d c_lo = s.clip_set ? s.clip_min : Eigen::Vector2d(-hw, -hh);
            Eigen::Vector2d c_hi = s.clip_set ? s.clip_max : Eigen::Vector2d(hw, hh);
            out += "\\clip (" + tikzPoint(c_lo.x(), c_lo.y()) + ") rectangle (" + tikzPoint(c_hi.x(), c_hi.y()) + ");\n";
            os << out;
            out.clear();
            tikz3dRender(out, d, c_lo, c_hi, thin);
            os << out;
            out = "\\end{scope}\n";
            if (thin.thinned())
                out += "\\node[anchor=north west, yshift=-0.1cm] at (" + tikzPoint(-hw, -hh) + ") {" +
                       tikzMarkThinningNote(thin) + "};\n";
            if (!s.frame_style.empty())
                out += "\\draw[" + s.frame_style + "] (" + tikzPoint(-hw, -hh) + ") rectangle (" + tikzPoint(hw, hh) + ");\n";
            out += "\\end{tikzpicture}\n";
            os << out;
        }

        //! Writes the standalone document of a scene with content (Drawing3D::hasContent) into a std::ostream or a
        //! std::string; the limits are checked before the preamble is written.
        template<class Out>
        void writeTex3D(const Drawing3D &d, Out &os)
        {
            tikz3dTexLimits(d, true);
            tikz3dThinning(d);
            writeTikzDocument(os, d.settings().border_cm, [&d](Out &o) { writeTikz3D(d, o); });
        }
    }
}
