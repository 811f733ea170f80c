// Standalone TikZ export of 2D drawings: plots with marks, primitives, grids and axes
// (docs/reference.md, "LaTeXTikz2D").
//
// RTL's interface over Drawing2D (the recorded drawing) and Tikz2DWriter.h (its TikZ text); Svg2D.h writes the
// same drawing as SVG. Complexity: each call amortised O(1) plus its point count; writeTEX linear in what was
// drawn. Output is deterministic and independent of the locale; drawings beyond pdflatex's memory are thinned
// (TikzBudget.h).
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
#include "rtl/io/Drawing2D.h"
#include "rtl/io/LaTeXTikzCommon.h"
#include "rtl/io/LaTeXUtility.h"
#include "rtl/io/Tikz2DWriter.h"

namespace rtl
{
    //! Collects 2D primitives in data coordinates (the Drawing2D model) and writes them as one standalone
    //! tikzpicture (the TikZ back-end, Tikz2DWriter.h).
    //!
    //! TikZ conventions (those of the published RTL, so figures look the same; deviations are marked "rather than"):
    //! - The document is `minimal` with xcolor[rgb], tikz and preview[active,tightpage] (`\PreviewBorder` = border), so
    //!   the PDF page is cropped to the picture.
    //! - The picture works in data units: the unit vectors `x=<sx>cm, y=<sy>cm` map the data range (or the clip
    //!   region) to the requested size, times the user scales (scaleX()/scaleY() report sx, sy). Unit vectors rather
    //!   than xscale/yscale, because TikZ multiplies a coordinate by the unit vector before any transformation: with
    //!   xscale, a coordinate above ~575 (x 1 cm) overflows TeX's 16384 pt, with `x=<sx>cm` only the paper position
    //!   counts. Where even that is out of TeX's range (a unit vector outside 1e-4..500 cm, e.g. a data range of 1e-3,
    //!   or coordinates >= 16000 or > 500 cm from the origin on paper, e.g. 1e6), the picture is written on paper
    //!   instead: x=1cm, y=1cm, every coordinate (v - min) * s in cm, `\MinX...` in cm, `\MarkGlobalScaleX/Y` = 1
    //!   (detail::TikzMap); such documents did not compile before.
    //! - The picture always contains the data frame (`\MinX`,`\MinY`)-(`\MaxX`,`\MaxY`) as an invisible path.
    //! - Marks are `\newcommand{\MarkA}[3]{...}` (x, y, rotation in degrees) drawn in a scope shifted to (x, y) that
    //!   resets the unit vectors to 1 cm, so marks are `\MarkRadius` cm in size whatever the axis scaling.
    //!   `\MarkGlobalScaleX/Y` (= 1/sx, 1/sy: cm to data units) stay defined for hand-written TikZ. Along a polyline
    //!   each mark is rotated to the local direction (as seen on paper).
    //! - On log10 axes every coordinate is replaced by its log10 before it is tracked or drawn (non-positive values
    //!   are dropped); grid and axis ticks are then given in decades. Non-finite points are skipped and break lines.
    //! - User text (addText, descriptions) is escaped; number labels come from numberToLatexString.
    //! - A picture is one TeX box, and pdflatex's default main memory (5e6 words) held about 9,000 dot marks here
    //!   (TikzBudget.h). An addition to RTL: a drawing beyond texMarkLimit() mark equivalents (default 8,000; a
    //!   polyline point counts 1/8) is written thinned, every k-th mark and polyline point, with a note below the
    //!   picture saying so; drawings within it are written as before, byte for byte. If grid lines, axis ticks and
    //!   primitives other than marks and polylines alone exceed it, writing throws std::length_error.
    //!   setTexMarkLimit(0) writes everything (lualatex's memory grows). Writing stays linear in the points.
    //! - TeX's dimensions end at about 575 cm: a picture whose extent (with overruns, clip and mark reach), mark
    //!   radius or scale, or document border is beyond 500 cm throws std::length_error before anything is written
    //!   (Tikz2DWriter.h); angles beyond +-3600 degrees are written modulo 360.
    class LaTeXTikz2D : public Drawing2D
    {
    public:
        explicit LaTeXTikz2D(unsigned int axis_x = LaTeXTikz2D::axis_type_linear,
                             unsigned int axis_y = LaTeXTikz2D::axis_type_linear)
                : Drawing2D(axis_x, axis_y)
        {
        }
        ~LaTeXTikz2D() override = default;
        LaTeXTikz2D(const LaTeXTikz2D &) = default;
        LaTeXTikz2D(LaTeXTikz2D &&) noexcept = default;
        LaTeXTikz2D &operator=(const LaTeXTikz2D &) = default;
        LaTeXTikz2D &operator=(LaTeXTikz2D &&) noexcept = default;

        //! Writes the standalone document; throws std::runtime_error if the file cannot be written, and
        //! std::length_error as described above before the file is opened (no file left, an earlier one untouched).
        void writeTEX(const std::string &file_name)
        {
            detail::writeTexFile(file_name, "LaTeXTikz2D", [this](std::ostream &os) { writeTEX(os); });
        }

        //! Writes the standalone document to a stream.
        void writeTEX(std::ostream &os) { rtl::writeTikz(*this, os); }

        //! Writes only the tikzpicture environment (colours, macros and marks are local to it), e.g. to `\input` it.
        void writeTikz(std::ostream &os) { rtl::writeTikzPicture(*this, os); }

        //! printf-formats `num` by the conversion letter ending `format` (see detail::numberToLatexString for
        //! the rules, including non-finite and out-of-range values), rewrites an exponent as `" \cdot 10^{exp}"`
        //! (a bare mantissa 1 gives "10^{exp}") and wraps the result in $...$.
        template<typename T>
        static std::string numberToLatexString(T num, std::string format)
        {
            return detail::numberToLatexString(num, format);
        }
    };
}
