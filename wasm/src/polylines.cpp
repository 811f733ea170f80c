// extractPolylines: whole-scan polyline extraction at a vertex budget (rtl/vect/ScanPolylines2D.h) over one scan's
// beams, read from the wasm heap; the result as typed arrays by name (vertices flat with per-polyline offsets, as
// the package gives clusters).
#include "adapter.h"
#include "schema.h"

#include <rtl/vect/ScanPolylines2D.h>

namespace rtl_wasm {
namespace {

// Beams: n interleaved (x, y) in the sensor frame, in beam order, NaN for no return (checked: finite or NaN, within
// kMaxCoordinate). No returned beam is not an error: ScanPolylines2D's documented empty result (score NaN).
// extractPolylines()'s options (wasm/js/polylines.js writes them by these names after checking them; schema.h).
struct PolylinesOptions {
  double maxVertices = 0, maxGap = 0, unexplainedCost = 0;
  template <class F>
  void fields(F& f) {
    f("maxVertices", maxVertices);
    f("maxGap", maxGap);
    f("unexplainedCost", unexplainedCost);
  }
};

val extractPolylines(std::uintptr_t ptr, std::size_t len, std::uintptr_t options) {
  return guarded([&] {
    const auto o = readOptions<PolylinesOptions>(options);
    const double maxVertices = o.maxVertices, maxGap = o.maxGap, unexplainedCost = o.unexplainedCost;
    const double* xy = doubles(ptr);
    checkPoints("extractPolylines", xy, len, 2, 0, true, kMaxCoordinate);
    std::vector<rtl::VectorND<2, double>> beams(len / 2);
    for (std::size_t i = 0; i < beams.size(); ++i) beams[i] = rtl::VectorND<2, double>(xy[2 * i], xy[2 * i + 1]);
    rtl::ScanPolylines2D<double> extract;
    extract.setMaxVertices(static_cast<std::size_t>(maxVertices));
    extract.setMaxGap(maxGap);
    extract.setUnexplainedCost(unexplainedCost);
    const double t0 = nowMs();
    extract(beams);
    const double ms = nowMs() - t0;
    std::vector<double> vertices;
    std::vector<std::uint32_t> offsets{0};
    for (const auto& p : extract.polylines()) {
      for (const auto& v : p) vertices.insert(vertices.end(), {v.x(), v.y()});
      offsets.push_back(static_cast<std::uint32_t>(vertices.size() / 2));
    }
    const auto& segs = extract.segments();
    std::vector<double> r, theta, cov;
    std::vector<std::uint32_t> polyline, first, last;
    for (const auto& s : segs) {
      polyline.push_back(static_cast<std::uint32_t>(s.polyline));
      first.push_back(static_cast<std::uint32_t>(s.beams.first));
      last.push_back(static_cast<std::uint32_t>(s.beams.second));
      r.push_back(s.r);
      theta.push_back(s.theta);
      cov.insert(cov.end(), {s.covariance(0, 0), s.covariance(0, 1), s.covariance(1, 0), s.covariance(1, 1)});
    }
    val segments = val::object();
    segments.set("polyline", u32(polyline));
    segments.set("firstBeam", u32(first));
    segments.set("lastBeam", u32(last));
    segments.set("r", f64(r));
    segments.set("theta", f64(theta));
    segments.set("covariance", f64(cov));
    val out = val::object();
    out.set("vertices", f64(vertices));
    out.set("offsets", u32(offsets));
    out.set("expectedRanges", f64(extract.expectedRanges()));
    out.set("segments", segments);
    out.set("vertexCount", static_cast<double>(extract.vertexCount()));
    out.set("returned", static_cast<double>(extract.returnedBeams()));
    out.set("explainedBeams", static_cast<double>(extract.explainedBeams()));
    out.set("rmse", extract.rmse());
    out.set("explained", extract.explainedFraction());
    out.set("score", extract.score());
    out.set("computeMs", ms);
    return out;
  });
}

}  // namespace
}  // namespace rtl_wasm

EMSCRIPTEN_BINDINGS(rtl_polylines) {
  emscripten::function("extractPolylines", &rtl_wasm::extractPolylines);
  rtl_wasm::registerCall<rtl_wasm::PolylinesOptions, rtl_wasm::NamedObjectResult>("extractPolylines");
}
