// The package's picture of a scan (points coloured by cluster, fitted segments, a title), drawn through any 2D
// drawing with LaTeXTikz2D's calls (and its 3D counterpart through LaTeXTikz3D's), so that the package's toTikz/toSvg
// and C++ programs (tests/tools/draw_scan.cpp) produce the same figure byte for byte. No emscripten here.
// The palette is the package's: wasm/js/palette.js exports the same colours to JavaScript (tests/js/draw.test.mjs
// checks that the drawings use them).
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

#include <rtl/Core.h>

namespace rtl_ops
{
    //! Cluster k is drawn in scan_palette[k % 10] (HTML hex, no '#'): the Okabe-Ito colour-blind safe set plus darker
    //! companions. No pure red: that is kept for fitted lines. Unlabelled points are gray.
    inline constexpr std::array<const char *, 10> scan_palette = {"0072B2", "E69F00", "009E73", "D55E00", "CC79A7",
                                                                  "56B4E9", "8C6D1F", "1B7837", "762A83", "332288"};
    inline constexpr const char *scan_unlabelled_color = "808080";

    struct ScanDrawingOptions
    {
        //! The data range is fitted into width x height (the drawing's units: cm for TikZ) with one scale for both
        //! axes, so a scan keeps its shape.
        float width = 12.0f, height = 12.0f;
        //! Radius of a point mark (cm for TikZ); set on the drawing with setMarkRadius.
        float mark_radius = 0.03f;
    };

    //! The HTML colour of cluster `label` (-1: unlabelled).
    inline const char *scanColor(int label)
    {
        return label < 0 ? scan_unlabelled_color : scan_palette[static_cast<std::size_t>(label) % scan_palette.size()];
    }

    //! Draws n points xy (x, y interleaved; a point with a NaN coordinate is a gap and is not drawn), coloured by
    //! labels (nullptr: all unlabelled; -1 unlabelled, k >= 0 cluster k), then n_segments segments (x1, y1, x2, y2)
    //! in black and, if non-empty, the title (plain text, escaped by the drawing) centred above the data.
    //! Unlabelled points come first (beneath), then the clusters in ascending order, as unrotated dot marks.
    //! Drawing: LaTeXTikz2D or any class with its setSize/setScaleX/setScaleY/setMarkRadius/saveColor/addPlot/
    //! addEdge/addText calls. Preconditions (std::invalid_argument otherwise): xy finite or NaN (no infinities),
    //! labels >= -1, segment coordinates finite, options width/height > 0 and finite, mark_radius >= 0.
    template<class Drawing>
    void drawScan(Drawing &d, const double *xy, std::size_t n, const int *labels, const double *segments,
                  std::size_t n_segments, const std::string &title, const ScanDrawingOptions &options = {})
    {
        if (!(options.width > 0) || !(options.height > 0) || !std::isfinite(options.width) ||
            !std::isfinite(options.height))
            throw std::invalid_argument("drawScan: width and height must be positive and finite");
        if (!(options.mark_radius >= 0) || !std::isfinite(options.mark_radius))
            throw std::invalid_argument("drawScan: mark_radius must be finite and >= 0");
        for (std::size_t i = 0; i < 2 * n; ++i)
            if (std::isinf(xy[i]))
                throw std::invalid_argument("drawScan: point " + std::to_string(i / 2) + " has an infinite coordinate");
        for (std::size_t i = 0; i < 4 * n_segments; ++i)
            if (!std::isfinite(segments[i]))
                throw std::invalid_argument("drawScan: segment " + std::to_string(i / 4) +
                                            " has a non-finite coordinate");
        if (labels != nullptr)
            for (std::size_t i = 0; i < n; ++i)
                if (labels[i] < -1)
                    throw std::invalid_argument("drawScan: label " + std::to_string(i) + " is " +
                                                std::to_string(labels[i]) + ", expected >= -1");

        // Points as the drawing stores them (float), grouped by label; the bounds as the drawing will track them.
        float lo_x = std::numeric_limits<float>::infinity(), hi_x = -lo_x, lo_y = lo_x, hi_y = -lo_x;
        auto grow = [&](float x, float y) {
            lo_x = std::min(lo_x, x);
            hi_x = std::max(hi_x, x);
            lo_y = std::min(lo_y, y);
            hi_y = std::max(hi_y, y);
        };
        std::map<int, std::vector<rtl::Vector2f>> groups;
        for (std::size_t i = 0; i < n; ++i)
        {
            auto x = static_cast<float>(xy[2 * i]), y = static_cast<float>(xy[2 * i + 1]);
            if (!std::isfinite(x) || !std::isfinite(y))
                continue;   // a gap (or a double beyond float range, which the drawing would skip too)
            grow(x, y);
            groups[labels == nullptr ? -1 : labels[i]].emplace_back(x, y);
        }
        std::vector<rtl::LineSegment2f> lines;
        for (std::size_t i = 0; i < n_segments; ++i)
        {
            const double *s = segments + 4 * i;
            rtl::Vector2f a(static_cast<float>(s[0]), static_cast<float>(s[1]));
            rtl::Vector2f b(static_cast<float>(s[2]), static_cast<float>(s[3]));
            if (!std::isfinite(a.x()) || !std::isfinite(a.y()) || !std::isfinite(b.x()) || !std::isfinite(b.y()))
                continue;
            grow(a.x(), a.y());
            grow(b.x(), b.y());
            lines.emplace_back(a, b);
        }

        // One scale s for both axes: the drawing maps a range r to size / r, so give it r * s; an axis with no
        // extent gets scale 1 from the drawing, so set s through the user scale.
        const bool empty = lo_x > hi_x;
        const double rx = empty ? 0.0 : double(hi_x) - lo_x, ry = empty ? 0.0 : double(hi_y) - lo_y;
        double s = std::min(rx > 0 ? options.width / rx : HUGE_VAL, ry > 0 ? options.height / ry : HUGE_VAL);
        if (!std::isfinite(s))
            s = 1.0;
        d.setSize(rx > 0 ? static_cast<float>(rx * s) : options.width, ry > 0 ? static_cast<float>(ry * s) : options.height);
        d.setScaleX(rx > 0 ? 1.0f : static_cast<float>(s));
        d.setScaleY(ry > 0 ? 1.0f : static_cast<float>(s));
        d.setMarkRadius(options.mark_radius);

        for (const auto &g : groups)
        {
            const std::string c = d.saveColor(std::string("{HTML}{") + scanColor(g.first) + "}");
            const std::string style = "draw=" + c + ",fill=" + c + ",line width=0.1pt";
            // One plot per point: a plot turns each mark along its neighbours (atan2, whose last digit differs
            // between C libraries); dots need no direction, and so every platform writes the same bytes.
            for (const auto &p : g.second)
                d.addPlot(std::vector<rtl::Vector2f>{p}, "", style, Drawing::latex_mark_dot);
        }
        for (const auto &l : lines)
            d.addEdge(l, "draw=black,line width=0.6pt,line cap=round");
        if (!title.empty() && !empty)
            d.addText(title, "anchor=south", rtl::Vector2f((lo_x + hi_x) / 2, hi_y));
    }

    //! The 3D counterpart (LaTeXTikz3D or any class with its setExportSize/saveColor/addMark/addLine/addFace calls;
    //! the camera is the caller's: setView before or after): n points xyz (NaN coordinate: gap) as dot marks coloured
    //! by labels as in drawScan, n_segments segments (6 numbers each) in black, planes as filled faces (plane k in
    //! scanColor(k), lighter on its back side, outlined) and polygons as outlines only. Planes and polygons are flat
    //! vertex lists (x, y, z per vertex) cut by counts (vertices per polygon, each >= 3); hidden parts are resolved
    //! by the drawing. width/height: the picture size; mark_radius: the mark radius (cm) at the scene's centre.
    //! Preconditions (std::invalid_argument otherwise): as drawScan, and every count >= 3.
    template<class Drawing3D>
    void drawScene3D(Drawing3D &d, const double *xyz, std::size_t n, const int *labels, const double *segments,
                     std::size_t n_segments, const double *plane_vertices, const std::size_t *plane_counts,
                     std::size_t n_planes, const double *polygon_vertices, const std::size_t *polygon_counts,
                     std::size_t n_polygons, const ScanDrawingOptions &options = {})
    {
        if (!(options.width > 0) || !(options.height > 0) || !std::isfinite(options.width) ||
            !std::isfinite(options.height))
            throw std::invalid_argument("drawScene3D: width and height must be positive and finite");
        if (!(options.mark_radius >= 0) || !std::isfinite(options.mark_radius))
            throw std::invalid_argument("drawScene3D: mark_radius must be finite and >= 0");
        for (std::size_t i = 0; i < 3 * n; ++i)
            if (std::isinf(xyz[i]))
                throw std::invalid_argument("drawScene3D: point " + std::to_string(i / 3) + " has an infinite coordinate");
        for (std::size_t i = 0; i < 6 * n_segments; ++i)
            if (!std::isfinite(segments[i]))
                throw std::invalid_argument("drawScene3D: segment " + std::to_string(i / 6) +
                                            " has a non-finite coordinate");
        if (labels != nullptr)
            for (std::size_t i = 0; i < n; ++i)
                if (labels[i] < -1)
                    throw std::invalid_argument("drawScene3D: label " + std::to_string(i) + " is " +
                                                std::to_string(labels[i]) + ", expected >= -1");
        auto faces = [](const char *what, const double *v, const std::size_t *counts, std::size_t k) {
            std::vector<rtl::Polygon3Df> out;
            std::size_t at = 0;
            for (std::size_t f = 0; f < k; ++f)
            {
                if (counts[f] < 3)
                    throw std::invalid_argument(std::string("drawScene3D: ") + what + " " + std::to_string(f) +
                                                " has " + std::to_string(counts[f]) + " vertices, at least 3 expected");
                std::vector<rtl::Vector3f> p;
                for (std::size_t i = 0; i < counts[f]; ++i, ++at)
                {
                    const double *q = v + 3 * at;
                    if (!std::isfinite(q[0]) || !std::isfinite(q[1]) || !std::isfinite(q[2]))
                        throw std::invalid_argument(std::string("drawScene3D: ") + what + " " + std::to_string(f) +
                                                    " has a non-finite vertex");
                    p.emplace_back(static_cast<float>(q[0]), static_cast<float>(q[1]), static_cast<float>(q[2]));
                }
                // The plane through the vertices by Newell's method (robust for slightly non-planar outlines);
                // the vertices are kept as given.
                Eigen::Vector3f nrm = Eigen::Vector3f::Zero(), c = Eigen::Vector3f::Zero();
                for (std::size_t i = 0; i < p.size(); ++i)
                {
                    const Eigen::Vector3f a = p[i].data(), b = p[(i + 1) % p.size()].data();
                    nrm += Eigen::Vector3f((a.y() - b.y()) * (a.z() + b.z()), (a.z() - b.z()) * (a.x() + b.x()),
                                           (a.x() - b.x()) * (a.y() + b.y()));
                    c += a;
                }
                c /= static_cast<float>(p.size());
                if (!(nrm.norm() > 0))
                    continue;   // all vertices on a line: nothing to paint
                nrm.normalize();
                rtl::Polygon3Df poly{rtl::Vector3f(nrm), nrm.dot(c)};
                for (const auto &q : p)
                    poly.addPointDirect(q);
                out.push_back(std::move(poly));
            }
            return out;
        };
        const auto planes = faces("plane", plane_vertices, plane_counts, n_planes);
        const auto polygons = faces("polygon", polygon_vertices, polygon_counts, n_polygons);

        d.setExportSize(options.width, options.height);
        std::map<int, std::vector<rtl::Vector3f>> groups;
        for (std::size_t i = 0; i < n; ++i)
        {
            const double *q = xyz + 3 * i;
            if (std::isnan(q[0]) || std::isnan(q[1]) || std::isnan(q[2]))
                continue;
            groups[labels == nullptr ? -1 : labels[i]].emplace_back(static_cast<float>(q[0]), static_cast<float>(q[1]),
                                                                    static_cast<float>(q[2]));
        }
        // 3D marks are 0.1 cm * their radius argument at the scene's centre.
        const float mark = options.mark_radius / 0.1f;
        for (const auto &g : groups)
        {
            const std::string c = d.saveColor(std::string("{HTML}{") + scanColor(g.first) + "}");
            d.addMarks(g.second, "draw=" + c + ",fill=" + c + ",line width=0.1pt", Drawing3D::latex_mark_dot, 0.0f, mark);
        }
        for (std::size_t i = 0; i < n_segments; ++i)
        {
            const double *s = segments + 6 * i;
            d.addLine(rtl::LineSegment3f(rtl::Vector3f(static_cast<float>(s[0]), static_cast<float>(s[1]), static_cast<float>(s[2])),
                                    rtl::Vector3f(static_cast<float>(s[3]), static_cast<float>(s[4]), static_cast<float>(s[5]))),
                      "draw=black,line width=0.6pt,line cap=round");
        }
        for (std::size_t k = 0; k < planes.size(); ++k)
        {
            const std::string c = d.saveColor(std::string("{HTML}{") + scanColor(static_cast<int>(k)) + "}");
            d.addFace(planes[k], "fill=" + c + "!45", "fill=" + c + "!20", "draw=" + c + ",line width=0.4pt");
        }
        for (const auto &p : polygons)
            d.addFace(p, "", "", "draw=black,line width=0.4pt");
    }
}
