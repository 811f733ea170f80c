// The SVG back-end of Drawing3D: a standalone SVG of the same scene, camera and painter's order that LaTeXTikz3D
// writes as TikZ (Camera3D.h, DepthOrder3D.h), with the styles translated by SvgStyle.h.
//
// Layout: 1 user unit = 1 cm; the picture is width x height cm with its centre at the centre of the SVG, y up in
// the scene and down in SVG, a border around it, everything drawn clipped to the clip rectangle. Each face fill is
// one `<polygon>`, each face outline run one `<polyline>`, each line (or piece of a line split by a face) one `<line>`,
// each mark one `<circle>` (a dot of radius 0.1 cm times its perspective scale, filled with the style's fill or
// draw colour: SVG cannot run TikZ mark templates), each axis label one `<text>`. The mark budget thins marks as in
// TikZ; TeX's dimensions do not apply.
// Complexity: that of the depth ordering plus text linear in what is drawn. Output is deterministic (same scene,
// same bytes) and independent of the locale.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <map>
#include <string>
#include <vector>

#include <Eigen/Dense>

#include "rtl/io/Camera3D.h"
#include "rtl/io/DepthOrder3D.h"
#include "rtl/io/Drawing3D.h"
#include "rtl/io/LaTeXTikzCommon.h"
#include "rtl/io/LaTeXUtility.h"
#include "rtl/io/SvgStyle.h"
#include "rtl/io/TextSink.h"
#include "rtl/io/Tikz3DWriter.h"
#include "rtl/io/TikzBudget.h"

namespace rtl
{
    namespace detail
    {
        //! Writes one Drawing3D as SVG (see the file comment).
        class Svg3DWriter
        {
        public:
            explicit Svg3DWriter(const Drawing3D &drawing) : d(drawing), colors(drawing.registry().colorList()) {}

            //! Into a std::ostream or a std::string (TextSink.h). std::length_error as Tikz3DWriter's mark budget.
            template<class Out>
            void write(Out &target)
            {
                detail::TextOut<Out> os{target};
                const Drawing3D::Settings &s = d.settings();
                const double w = s.export_w, h = s.export_h, b = s.border_cm;
                std::string body;
                if (d.hasContent())
                {
                    const detail::TikzThinning thin = detail::tikz3dThinning(d);
                    detail::CameraScene3D cs = detail::cameraScene3D(d, s.clipLo(), s.clipHi(), thin.stride,
                                                                     0.5 * detail::tex_paper_limit_cm);
                    if (!cs.empty)
                        scene(cs, body);
                }
                const Eigen::Vector2d lo = s.clipLo(), hi = s.clipHi();
                os << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
                   << "<svg xmlns=\"http://www.w3.org/2000/svg\" version=\"1.1\" width=\"" << num(w + 2 * b)
                   << "cm\" height=\"" << num(h + 2 * b) << "cm\" viewBox=\"0 0 " << num(w + 2 * b) << " "
                   << num(h + 2 * b) << "\" font-family=\"serif\" font-size=\"0.35\">\n"
                   << "<defs>\n<clipPath id=\"clip\"><rect x=\"" << num(lo.x()) << "\" y=\"" << num(-hi.y())
                   << "\" width=\"" << num(hi.x() - lo.x()) << "\" height=\"" << num(hi.y() - lo.y())
                   << "\"/></clipPath>\n</defs>\n"
                   << "<g transform=\"translate(" << num(b + w / 2) << "," << num(b + h / 2) << ")\">\n"
                   << "<g clip-path=\"url(#clip)\">\n"
                   << body << "</g>\n";
                if (!s.frame_style.empty())
                {
                    const SvgStyle &f = parseTikzStyle(s.frame_style, colors);
                    os << "<rect x=\"" << num(-w / 2) << "\" y=\"" << num(-h / 2) << "\" width=\"" << num(w)
                       << "\" height=\"" << num(h) << "\"" << stroked(f) << " fill=\"none\"/>\n";
                }
                os << "</g>\n</svg>\n";
            }

        private:
            static std::string num(double v) { return detail::number(std::isfinite(v) ? v : 0.0); }
            static std::string pt(const detail::Projector3D &P, const Eigen::Vector3d &p)
            {
                return num(P.x(p)) + "," + num(-P.y(p));
            }

            const SvgStyle &style(const std::string &name)
            {
                auto it = styles.find(name);
                if (it == styles.end())
                    it = styles.emplace(name, parseTikzStyle(d.registry().styleText(name), colors)).first;
                return it->second;
            }
            //! Stroke attributes of a `\draw`: the draw colour (black if none), width, dashes and opacity.
            static std::string stroked(const SvgStyle &s)
            {
                if (s.draw_none)
                    return " stroke=\"none\"";
                std::string a = " stroke=\"" + (s.stroke.empty() ? std::string("#000000") : s.stroke) +
                                "\" stroke-width=\"" + num(s.line_width_cm) + "\"";
                const std::string dash = dashArray(s.dash, s.line_width_cm);
                if (!dash.empty())
                    a += " stroke-dasharray=\"" + dash + "\"";
                if (s.opacity * s.stroke_opacity < 1)
                    a += " stroke-opacity=\"" + num(s.opacity * s.stroke_opacity) + "\"";
                return a;
            }
            //! Attributes of a `\path` with this style: filled and stroked only where the style says so.
            static std::string pathed(const SvgStyle &s)
            {
                std::string a = " fill=\"" + (s.fill.empty() || s.fill_none ? std::string("none") : s.fill) + "\"";
                if (!s.fill.empty() && s.opacity * s.fill_opacity < 1)
                    a += " fill-opacity=\"" + num(s.opacity * s.fill_opacity) + "\"";
                return a + (s.stroke.empty() ? std::string(" stroke=\"none\"") : stroked(s));
            }

            void scene(detail::CameraScene3D &cs, std::string &out)
            {
                const detail::Projector3D P = cs.P;
                const double ref_depth = cs.ref_depth;
                auto onItems = [&](const std::vector<detail::CameraItem3D> &items) {
                    for (const auto &it : items)
                    {
                        if (it.is_mark)
                        {
                            const Drawing3D::MarkItem &m = d.marks()[it.ref];
                            const double x = P.x(it.a), y = P.y(it.a);
                            const double scale = detail::tikz3dMarkScale(m.radius * ref_depth / -it.a.z(), x, y);
                            const SvgStyle &s = style(m.style);
                            const std::string fill = !s.fill.empty() ? s.fill : !s.stroke.empty() ? s.stroke : "#000000";
                            out += "<circle cx=\"" + num(x) + "\" cy=\"" + num(-y) + "\" r=\"" +
                                   num(std::abs(0.1 * scale)) + "\" fill=\"" + fill + "\" stroke=\"none\"/>\n";
                        }
                        else
                            out += "<line x1=\"" + num(P.x(it.a)) + "\" y1=\"" + num(-P.y(it.a)) + "\" x2=\"" +
                                   num(P.x(it.b)) + "\" y2=\"" + num(-P.y(it.b)) + "\"" +
                                   stroked(style(cs.line_styles[it.ref])) + "/>\n";
                    }
                };
                auto onPoly = [&](const detail::CameraPoly3D &p) {
                    const Drawing3D::Face &f = d.faces()[p.face];
                    Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
                    for (const auto &v : p.v)
                        centroid += v;
                    centroid /= static_cast<double>(p.v.size());
                    const std::string &name = p.normal.dot(-centroid) > 0 ? f.front : f.back;
                    if (!name.empty())
                    {
                        out += "<polygon points=\"";
                        for (size_t i = 0; i < p.v.size(); ++i)
                            out += (i ? " " : "") + pt(P, p.v[i]);
                        out += "\"" + pathed(style(name)) + "/>\n";
                    }
                    if (f.line.empty())
                        return;
                    // One polyline per run of original outline edges (split edges are not drawn), as in TikZ.
                    const std::string attrs = stroked(style(f.line)) + " fill=\"none\"";
                    std::string run;
                    for (size_t i = 0; i < p.v.size(); ++i)
                    {
                        if (!p.edge[i])
                        {
                            if (!run.empty())
                                out += "<polyline points=\"" + run + "\"" + attrs + "/>\n";
                            run.clear();
                            continue;
                        }
                        if (run.empty())
                            run = pt(P, p.v[i]);
                        run += " " + pt(P, p.v[(i + 1) % p.v.size()]);
                    }
                    if (!run.empty())
                        out += "<polyline points=\"" + run + "\"" + attrs + "/>\n";
                };
                std::vector<detail::CameraLabel3D> labels = cs.labels;
                detail::paintScene3D(cs, onPoly, onItems);
                for (const auto &l : labels)
                {
                    const Drawing3D::AxisItem &a = d.axes()[l.axis];
                    if (detail::numberToLatexString(l.value, a.format).empty())
                        continue;   // as in TikZ: no label where the format gives none
                    out += "<text x=\"" + num(P.x(l.p)) + "\" y=\"" + num(-P.y(l.p)) + "\">" +
                           xmlEscape(detail::number(l.value)) + "</text>\n";
                }
            }

            const Drawing3D &d;
            ColorResolver colors;
            std::map<std::string, SvgStyle> styles;
        };
    }

    //! The SVG of a 3D scene (the one LaTeXTikz3D::drawing() records); see Svg3D.h's file comment.
    inline std::string svg3DString(const Drawing3D &drawing)
    {
        detail::Svg3DWriter w(drawing);
        std::string out;
        w.write(out);
        return out;
    }
}
