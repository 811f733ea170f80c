// Standalone TikZ export of 3D scenes: perspective camera, marks, lines and faces in depth order
// (docs/reference.md, "LaTeXTikz3D").
//
// A thin composition, mirroring the 2D side: the scene is a Drawing3D (Drawing3D.h); view, projection and clipping
// are in Camera3D.h, the painter's ordering in DepthOrder3D.h, the TikZ text and TeX's limits in Tikz3DWriter.h.
//
// Complexity of writeTEX: the faces' BSP tree costs O(F log F) for F faces that rarely cross and up to O(F^2)
// fragments when many do; lines and marks are sorted into it (O(n log n)); the text is linear in what is drawn.
// Adding objects is amortised O(1) each. The scene is kept, so writeTEX may be called again (e.g. per view).
#pragma once

#include <cstddef>
#include <limits>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

#include <Eigen/Dense>

#include "rtl/Core.h"
#include "rtl/Transformation.h"
#include "rtl/io/Camera3D.h"
#include "rtl/io/Drawing3D.h"
#include "rtl/io/LaTeXTikzCommon.h"
#include "rtl/io/LaTeXUtility.h"
#include "rtl/io/TextSink.h"
#include "rtl/io/Tikz3DWriter.h"
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
    //!   detail::tex_paper_limit_cm (500 cm); writeTEX also if the border or the page (extent plus two
    //!   borders) is. Near the camera a mark's scale is clamped (max_mark_scale; and within 250 cm of the centre
    //!   unless at most 100), mark rotations beyond +-3600 degrees are written modulo 360, and axis labels projected
    //!   beyond 250 cm (far outside the clip) are left out. Scenes within these limits are written as before.
    class LaTeXTikz3D
    {
    public:
        static const unsigned int overrun_relative = Drawing3D::overrun_relative,
                                  overrun_absolute = Drawing3D::overrun_absolute, axis_type_linear = 0,
                                  axis_type_log10 = 1;
        static const unsigned int position_above = detail::tikz_position_above,
                                  position_below = detail::tikz_position_below,
                                  position_right = detail::tikz_position_right,
                                  position_left = detail::tikz_position_left;
        static inline const char *latex_mark_blank = detail::tikz_mark_blank;
        static inline const char *latex_mark_cross = detail::tikz_mark_cross;
        static inline const char *latex_mark_mark = detail::tikz_mark_mark;
        static inline const char *latex_mark_dot = detail::tikz_mark_dot;
        static inline const char *latex_mark_robot = detail::tikz_mark_robot;
        static inline const char *latex_var_style = detail::tikz_var_style;

        //! The largest perspective scale of a mark (`\MarkRadius` 0.1 cm * 1000: a dot of 200 cm across): nearer to the
        //! camera it stops growing.
        static constexpr double max_mark_scale = detail::tikz3d_max_mark_scale;

        LaTeXTikz3D() { clearAll(); }
        LaTeXTikz3D(LaTeXTikz3D &&le) noexcept = default;
        LaTeXTikz3D &operator=(LaTeXTikz3D &&le) noexcept = default;
        LaTeXTikz3D(const LaTeXTikz3D &) = delete;
        LaTeXTikz3D &operator=(const LaTeXTikz3D &) = delete;
        ~LaTeXTikz3D() = default;

        //! Picture size in cm.
        void setExportSize(float width, float height) { scene.setExportSize(width, height); }
        //! Clips the picture to this rectangle (cm, picture centred at the origin) instead of the export size.
        void setExportClipping(float p1_x, float p1_y, float p2_x, float p2_y)
        {
            scene.setExportClipping(p1_x, p1_y, p2_x, p2_y);
        }
        //! fov in degrees; orientation maps world to camera coordinates (NaN translation: auto-fit).
        void setView(float fov, const RigidTf3f &orientation)
        {
            scene.setView(fov, orientation.rotMat().data().cast<double>(), orientation.trVec().data().cast<double>());
        }
        //! Looks along camera_dir (world), keeping world +z up on the picture (+y if looking along z); auto-fit.
        void setView(float fov, const Vector3f &camera_dir)
        {
            scene.setView(fov, detail::lookAlong3D(camera_dir.data().cast<double>()),
                          Eigen::Vector3d::Constant(std::numeric_limits<double>::quiet_NaN()));
        }
        void setBorder(float border) { scene.setBorder(border); }
        //! Budget in mark equivalents (see the class comment); 0: no limit (lualatex, whose memory grows).
        void setTexMarkLimit(size_t limit) { scene.setTexMarkLimit(limit); }
        size_t texMarkLimit() const { return scene.settings().tex_mark_limit; }
        //! Non-empty: a frame around the picture drawn with this TikZ option text, e.g. "draw=black, thick".
        void setFrameStyle(const std::string &style) { scene.setFrameStyle(style); }
        void setGridAxisOverrun(unsigned int type, float magnitude) { scene.setGridAxisOverrun(type, magnitude); }
        void setMaxPlotRegion(const Vector3f &p1, const Vector3f &p2) { scene.setMaxPlotRegion(p1, p2); }
        void setMinPlotRegion(const Vector3f &p1, const Vector3f &p2) { scene.setMinPlotRegion(p1, p2); }

        //! Data and settings (size, border, frame, regions, overrun, clipping) back to defaults; the view stays.
        void clearAll() { scene.clearAll(); }
        //! Removes objects, styles, colours and marks; keeps size, border, view and regions.
        void clearData() { scene.clearData(); }

        //! Whether there is anything to draw: a mark, line or face, or a min region. Without, writeTEX writes
        //! nothing (as RTL): it neither creates nor touches the file.
        [[nodiscard]] bool hasContent() const { return scene.hasContent(); }

        //! Writes the standalone document if hasContent(); throws std::runtime_error if the file cannot be written
        //! and std::length_error (file not touched: the document is made before the file is opened) if the scene
        //! cannot be thinned into texMarkLimit() or is beyond TeX's dimensions.
        void writeTEX(const std::string &file_name)
        {
            if (!hasContent())
                return;
            detail::writeTexFile(file_name, "LaTeXTikz3D", [this](std::ostream &os) { writeTEX(os); });
        }
        void writeTEX(std::ostream &os) { writeTexTo(os); }
        //! What writeTEX writes, as a string, without any stream (not an overload of writeTEX: that takes file names).
        std::string texString()
        {
            return detail::textString([this](std::string &out) { writeTexTo(out); });
        }
        //! writeTEX into a std::ostream or a std::string (TextSink.h).
        template<class Out>
        void writeTexTo(Out &os)
        {
            if (!hasContent())
                return;
            detail::writeTex3D(scene, os);
        }
        //! Writes only the tikzpicture (everything it defines is local to it). A scene without objects and without
        //! a min region gives an empty picture of the export size. Thinned or std::length_error as in the class comment.
        void writeTikz(std::ostream &os) { writeTikzTo(os); }
        //! What writeTikz writes, as a string, without any stream.
        std::string tikzString()
        {
            return detail::textString([this](std::string &out) { writeTikzTo(out); });
        }
        //! writeTikz into a std::ostream or a std::string (TextSink.h).
        template<class Out>
        void writeTikzTo(Out &target)
        {
            detail::writeTikz3D(scene, target);
        }

        //! A line along beg -> end extended across the rendered region (plus overrun), drawn in depth order, with
        //! labels numberToLatexString(t, num_format) every `tick` of the coordinate t along the axis direction
        //! (t = p . dir, i.e. the world coordinate for an axis along x, y or z through the origin).
        void addAxis(const std::string &style, std::string num_format, unsigned int num_position, float tick,
                     const Vector3f &beg, const Vector3f &end)
        {
            scene.addAxis(style, std::move(num_format), num_position, tick, beg, end);
        }
        void addMark(const Vector3f &pos, const std::string &mark_style, const std::string &mark_template,
                     float rotation = 0.0f, float mark_radius = 1.0f)
        {
            scene.addMark(pos, mark_style, mark_template, rotation, mark_radius);
        }
        void addMarks(const std::vector<Vector3f> &vpos, const std::string &mark_style,
                      const std::string &mark_template, float rotation = 0.0f, float mark_radius = 1.0f)
        {
            for (const auto &p : vpos)
                addMark(p, mark_style, mark_template, rotation, mark_radius);
        }
        void addLine(const LineSegment3f &ls, const std::string &style) { scene.addLine(ls, style); }
        void addLines(const std::vector<LineSegment3f> &vls, const std::string &style)
        {
            for (const auto &l : vls)
                addLine(l, style);
        }
        //! A planar polygon (>= 3 points); its normal() tells the front side.
        void addFace(const Polygon3Df &face, const std::string &front_style, const std::string &back_style,
                     const std::string &line_style)
        {
            scene.addFace(face, front_style, back_style, line_style);
        }
        void addFace(const std::vector<Polygon3Df> &vfs, const std::string &front_style, const std::string &back_style,
                     const std::string &line_style)
        {
            for (const auto &f : vfs)
                addFace(f, front_style, back_style, line_style);
        }

        //! See LaTeXTikz2D::saveColor.
        std::string saveColor(const std::string &color) { return scene.saveColor(color); }

        //! The scene as recorded (for other writers of the same drawing).
        const Drawing3D &drawing() const { return scene; }

    private:
        Drawing3D scene;
    };
}
