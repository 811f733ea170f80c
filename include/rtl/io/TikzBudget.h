// How much of pdflatex's memory a TikZ picture of a Drawing2D takes, and how far to thin it so that it fits.
//
// A tikzpicture is one TeX box: everything in it stays in main memory until the page is shipped out, so a picture
// with too many pieces fails with "TeX capacity exceeded" in pdflatex's default memory. The budget counts "mark
// equivalents": a dot mark 1, a polyline point 1/8, any other primitive (an edge, a grid line, an axis tick) 1/2.
// Drawing2D::pdflatex_mark_limit (8,000) lies a margin below the largest picture that compiles in a default TeX
// Live installation. Those weights and the limit are measured, not derived (docs/io.md, "TikZ memory budget").
//
// Complexity: linear in the number of primitives and polyline points. Thinning is deterministic (every stride-th
// mark and polyline point, and each polyline's last), so the same drawing always gives the same picture.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <stdexcept>
#include <string>

#include "rtl/io/Drawing2D.h"

namespace rtl
{
    namespace detail
    {
        //! Every stride-th mark (counted over the whole drawing) and every stride-th point of each polyline (and its
        //! last) are written; stride 1 writes everything.
        struct TikzThinning
        {
            size_t stride = 1;
            size_t marks = 0;   // marks in the drawing
            size_t kept = 0;    // marks written
            bool thinned() const { return stride > 1; }
            bool keepMark(size_t index) const { return index % stride == 0; }
        };

        //! The thinning that brings `d` within d.texMarkLimit() mark equivalents. Throws std::length_error if what
        //! cannot be thinned (primitives other than marks and polylines, grid lines, axis ticks) alone exceeds it.
        inline TikzThinning tikzThinning(const Drawing2D &d, const Drawing2D::Frame &f)
        {
            TikzThinning t;
            size_t vertices = 0, fixed = 0;   // polyline points; the rest, in halves of a mark
            for (const auto &p : d.primitives())
            {
                if (p.kind == Drawing2D::Kind::marks)
                    t.marks += p.marks.size();
                else if (p.kind == Drawing2D::Kind::polyline)
                    vertices += p.points.size();
                else
                    ++fixed;
            }
            double x0 = f.min_x - f.ox, x1 = f.max_x + f.ox, y0 = f.min_y - f.oy, y1 = f.max_y + f.oy;
            for (const auto &g : d.grids())
                fixed += (g.horizontal ? Drawing2D::ticks(y0, y1, g.tick) : Drawing2D::ticks(x0, x1, g.tick)).size();
            for (const auto &a : d.axes())
                fixed += 2 * (a.is_x ? Drawing2D::ticks(x0, x1, a.tick) : Drawing2D::ticks(y0, y1, a.tick)).size();
            t.kept = t.marks;
            const double limit = static_cast<double>(d.texMarkLimit()), rest = 0.5 * static_cast<double>(fixed);
            const double thin = static_cast<double>(t.marks) + static_cast<double>(vertices) / 8.0;
            if (d.texMarkLimit() == 0 || thin + rest <= limit)
                return t;
            if (rest > limit)
                throw std::length_error("writeTikz: " + std::to_string(fixed) + " primitives, grid lines and axis ticks "
                                        "exceed pdflatex's memory (texMarkLimit " + std::to_string(d.texMarkLimit()) +
                                        " marks, one of these counts 1/2)");
            const double room = limit - rest >= 1.0 ? limit - rest : 1.0;
            t.stride = static_cast<size_t>(std::ceil(thin / room));
            if (t.stride < 2)
                t.stride = 2;
            t.kept = (t.marks + t.stride - 1) / t.stride;
            return t;
        }

        //! The visible note of a thinned picture, e.g. "Thinned for pdflatex's memory: 1 in 2 marks and line points
        //! drawn (7500 of 15000 marks)."
        inline std::string tikzThinningNote(const TikzThinning &t)
        {
            return "Thinned for pdflatex's memory: 1 in " + std::to_string(t.stride) + " marks and line points drawn (" +
                   std::to_string(t.kept) + " of " + std::to_string(t.marks) + " marks).";
        }

        //! The 3D writer's budget (LaTeXTikz3D.h): `marks` marks count 1 each, `fixed` other pieces (lines, axes, face
        //! fills and outlines) 1/2 each; only marks are thinned. 3D dot marks broke pdflatex between 10,000 and 11,000
        //! (same TeX as above), so the 2D default keeps a margin there too. Throws std::length_error if `fixed` alone
        //! exceeds `limit` (0: no limit).
        inline TikzThinning tikzMarkThinning(size_t marks, size_t fixed, size_t limit, const std::string &who)
        {
            TikzThinning t;
            t.marks = t.kept = marks;
            const double lim = static_cast<double>(limit), rest = 0.5 * static_cast<double>(fixed);
            if (limit == 0 || static_cast<double>(marks) + rest <= lim)
                return t;
            if (rest > lim)
                throw std::length_error(who + ": " + std::to_string(fixed) + " lines, axes and face paths exceed "
                                        "pdflatex's memory (texMarkLimit " + std::to_string(limit) +
                                        " marks, one of these counts 1/2)");
            const double room = lim - rest >= 1.0 ? lim - rest : 1.0;
            t.stride = std::max<size_t>(2, static_cast<size_t>(std::ceil(static_cast<double>(marks) / room)));
            t.kept = (marks + t.stride - 1) / t.stride;
            return t;
        }

        //! The note of a picture thinned by tikzMarkThinning, e.g. "Thinned for pdflatex's memory: 1 in 2 marks drawn
        //! (6000 of 12000 marks)."
        inline std::string tikzMarkThinningNote(const TikzThinning &t)
        {
            return "Thinned for pdflatex's memory: 1 in " + std::to_string(t.stride) + " marks drawn (" +
                   std::to_string(t.kept) + " of " + std::to_string(t.marks) + " marks).";
        }
    }
}
