// The package's drawings, written by the C++ library so that its output is the library's byte for byte:
//   toTikz / toSvg (2D): scan_drawing.h's scan picture (points by cluster, segments, title) drawn once into an
//     rtl::Drawing2D and written by the TikZ or the SVG back-end;
//   toTikz (dim 3): scan_drawing.h's scene (points, segments, planes, polygons) rendered by rtl::LaTeXTikz3D;
//   toLatexTable: rows of text cells through rtl::LaTeXTable.
#include "adapter.h"
#include "scan_drawing.h"
#include "schema.h"

#include <rtl/io/Drawing2D.h>
#include <rtl/io/LaTeXTable.h>
#include <rtl/io/LaTeXTikz3D.h>
#include <rtl/io/LaTeXUtility.h>
#include <rtl/io/Svg2D.h>
#include <rtl/io/Tikz2DWriter.h>

#include <limits>
#include <string>

namespace rtl_wasm {
namespace {

// drawScan2D's options (wasm/js/draw.js writes them by these names; schema.h): the picture's size and mark radius
// in cm, and what to write.
enum class Format2D { tikz, tikzpicture, svg };
constexpr const char* const kFormats2D[] = {"tikz", "tikzpicture", "svg"};
struct Drawing2DOptions {
  double width = 12, height = 12, markRadius = 0.03;
  Format2D format = Format2D::tikz;
  template <class F>
  void fields(F& f) {
    f("width", width);
    f("height", height);
    f("markRadius", markRadius);
    f("format", format, kFormats2D);
  }
};

val drawScan2D(std::uintptr_t xy, std::size_t n_xy, std::uintptr_t labels, std::size_t n_labels, std::uintptr_t segs,
               std::size_t n_segs, std::string title, std::uintptr_t options) {
  return guarded([&] {
    const auto opt = readOptions<Drawing2DOptions>(options);
    if (n_xy % 2 != 0) throw std::invalid_argument("drawing.points is not x,y interleaved");
    if (n_segs % 4 != 0) throw std::invalid_argument("drawing.segments is not x1,y1,x2,y2 per segment");
    const std::size_t n = n_xy / 2;
    if (n_labels != 0 && n_labels != n) throw std::invalid_argument("one label per point expected");
    // Labels arrive as doubles (checked by the JS layer: integers >= -1); the drawing takes ints.
    std::vector<int> lab(n_labels);
    for (std::size_t i = 0; i < n_labels; ++i) {
      const double v = doubles(labels)[i];
      if (!(v >= -1 && v <= 2147483647.0) || v != std::floor(v))
        throw std::invalid_argument("drawing.labels[" + str(i) + "] must be an integer >= -1");
      lab[i] = static_cast<int>(v);
    }
    rtl_ops::ScanDrawingOptions o;
    o.width = static_cast<float>(opt.width);
    o.height = static_cast<float>(opt.height);
    o.mark_radius = static_cast<float>(opt.markRadius);
    rtl::Drawing2D d;
    rtl_ops::drawScan(d, doubles(xy), n, n_labels ? lab.data() : nullptr, doubles(segs), n_segs / 4, title, o);
    // The writers' string forms: no iostream in the package (rtl/io/TextSink.h, wasm/CMakeLists.txt).
    return val(opt.format == Format2D::svg           ? rtl::svgString(d)
               : opt.format == Format2D::tikzpicture ? rtl::tikzPictureString(d)
                                                     : rtl::tikzString(d));
  }, "drawScan");
}



// Vertex counts arrive as doubles (checked by the JS layer: integers >= 3 summing to the vertex count).
std::vector<std::size_t> counts(const double* p, std::size_t n, std::size_t vertices, const char* what) {
  std::vector<std::size_t> out(n);
  std::size_t sum = 0;
  for (std::size_t i = 0; i < n; ++i) {
    if (!(p[i] >= 0 && p[i] <= 4294967295.0) || p[i] != std::floor(p[i]))
      throw std::invalid_argument(std::string("drawing.") + what + ".counts[" + str(i) + "] must be a non-negative integer");
    out[i] = static_cast<std::size_t>(p[i]);
    sum += out[i];
  }
  if (sum != vertices)
    throw std::invalid_argument(std::string("drawing.") + what + ": the counts add up to " + str(sum) + " vertices, the vertices hold " +
                                str(vertices));
  return out;
}

// drawTikz3D's options (wasm/js/draw.js; schema.h): the camera (fov NaN: LaTeXTikz3D's own view, looking down -z,
// auto-fitted), the picture's size and mark radius in cm, and a whole document or the bare tikzpicture.
struct Drawing3DOptions {
  double fov = std::numeric_limits<double>::quiet_NaN();
  double direction[3] = {0, 0, -1};
  double width = 12, height = 12, markRadius = 0.03;
  bool standalone = true;
  template <class F>
  void fields(F& f) {
    f("fov", fov);
    f("direction", direction);
    f("width", width);
    f("height", height);
    f("markRadius", markRadius);
    f("standalone", standalone);
  }
};

val drawTikz3D(std::uintptr_t xyz, std::size_t n_xyz, std::uintptr_t labels, std::size_t n_labels, std::uintptr_t segs,
               std::size_t n_segs, std::uintptr_t planes, std::size_t n_planes, std::uintptr_t plane_counts,
               std::size_t n_plane_counts, std::uintptr_t polys, std::size_t n_polys, std::uintptr_t poly_counts,
               std::size_t n_poly_counts, std::uintptr_t options) {
  return guarded([&] {
    const auto opt = readOptions<Drawing3DOptions>(options);
    const double fov = opt.fov, dx = opt.direction[0], dy = opt.direction[1], dz = opt.direction[2];
    if (n_xyz % 3 != 0 || n_segs % 6 != 0 || n_planes % 3 != 0 || n_polys % 3 != 0)
      throw std::invalid_argument("toTikz: 3D arrays must hold whole points (3 numbers) / segments (6 numbers)");
    const std::size_t n = n_xyz / 3;
    if (n_labels != 0 && n_labels != n) throw std::invalid_argument("toTikz: one label per point expected");
    std::vector<int> lab(n_labels);
    for (std::size_t i = 0; i < n_labels; ++i) {
      const double v = doubles(labels)[i];
      if (!(v >= -1 && v <= 2147483647.0) || v != std::floor(v))
        throw std::invalid_argument("drawing.labels[" + str(i) + "] must be an integer >= -1");
      lab[i] = static_cast<int>(v);
    }
    const auto pc = counts(doubles(plane_counts), n_plane_counts, n_planes / 3, "planes");
    const auto qc = counts(doubles(poly_counts), n_poly_counts, n_polys / 3, "polygons");
    rtl_ops::ScanDrawingOptions o;
    o.width = static_cast<float>(opt.width);
    o.height = static_cast<float>(opt.height);
    o.mark_radius = static_cast<float>(opt.markRadius);
    rtl::LaTeXTikz3D d;
    if (!std::isnan(fov))
      d.setView(static_cast<float>(fov),
                rtl::Vector3f(static_cast<float>(dx), static_cast<float>(dy), static_cast<float>(dz)));
    rtl_ops::drawScene3D(d, doubles(xyz), n, n_labels ? lab.data() : nullptr, doubles(segs), n_segs / 6, doubles(planes),
                     pc.data(), pc.size(), doubles(polys), qc.data(), qc.size(), o);
    return val(opt.standalone ? d.texString() : d.tikzString());
  }, "drawScene3D");
}



// A JS array of strings (the JS layer checked and converted every cell).
std::vector<std::string> strings(const val& a) {
  const auto n = a["length"].as<unsigned>();
  std::vector<std::string> out;
  out.reserve(n);
  for (unsigned i = 0; i < n; ++i) out.push_back(a[i].as<std::string>());
  return out;
}

val latexTable(val rows, val heading, std::string caption, std::string columns, bool escape) {
  return guarded([&] {
    rtl::LaTeXTable t;
    if (!columns.empty()) t.setColumnStyle(columns);
    const auto h = strings(heading);
    if (escape)
      t.setHeadingEscaped(h);
    else
      t.setHeading(h);
    const auto n = rows["length"].as<unsigned>();
    for (unsigned i = 0; i < n; ++i) {
      const val r = rows[i];
      if (r.isNull()) {
        t.addHLine();
        continue;
      }
      const auto cells = strings(r);
      if (escape)
        t.addRowEscaped(cells);
      else
        t.addRow(cells);
    }
    return val(t.tableString(escape ? rtl::LaTeX::escapeLaTeXCharacters(caption) : caption));
  });
}

}  // namespace
}  // namespace rtl_wasm

EMSCRIPTEN_BINDINGS(rtl_draw) {
  // The results are strings (the documents), not arrays: nothing crosses through the result block.
  rtl_wasm::registerCall<rtl_wasm::Drawing2DOptions, rtl_wasm::NamedObjectResult>("drawScan2D");
  rtl_wasm::registerCall<rtl_wasm::Drawing3DOptions, rtl_wasm::NamedObjectResult>("drawTikz3D");
  emscripten::function("drawScan2D", &rtl_wasm::drawScan2D);
  emscripten::function("drawTikz3D", &rtl_wasm::drawTikz3D);
  emscripten::function("latexTable", &rtl_wasm::latexTable);
}
