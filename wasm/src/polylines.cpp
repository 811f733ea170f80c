// extractPolylines: whole-scan polyline extraction at a vertex budget (rtl/vect/ScanPolylines2D.h) over one scan's
// beams, read from the wasm heap; the result as typed arrays by name (vertices flat with per-polyline offsets, as
// the package gives clusters), laid out in the result block (schema.h) that wasm/js/polylines.js reads.
#include "adapter.h"
#include "schema.h"

#include <optional>

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

// extractPolylines()'s results (wasm/js/polylines.js builds the documented object from them). Kept between calls
// (kept.h) with the extractor, so that a repeated call allocates nothing once its vectors have grown.
struct PolylinesResults {
  double vertexCount = 0, returned = 0, explainedBeams = 0, rmse = 0, explained = 0, score = 0, computeMs = 0;
  std::vector<double> vertices, expectedRanges, r, theta, covariance;
  std::vector<std::uint32_t> offsets, polyline, firstBeam, lastBeam;
  std::vector<rtl::VectorND<2, double>> beams;  // the input as the extractor takes it (not a result)
  template <class F>
  void fields(F& f) {
    f.scalar("vertexCount", vertexCount);
    f.scalar("returned", returned);
    f.scalar("explainedBeams", explainedBeams);
    f.scalar("rmse", rmse);
    f.scalar("explained", explained);
    f.scalar("score", score);
    f.scalar("computeMs", computeMs);
    f.array("vertices", vertices);
    f.array("offsets", offsets);
    f.array("expectedRanges", expectedRanges);
    f.array("polyline", polyline);
    f.array("firstBeam", firstBeam);
    f.array("lastBeam", lastBeam);
    f.array("r", r);
    f.array("theta", theta);
    f.array("covariance", covariance);
  }
};

// Scans of up to this many beams run on the extractor kept between calls (kept.h): a fresh extractor per call
// allocated and zero-filled its work buffers every time (the partition DP's table alone holds (n + 1)^2 doubles for
// a chain of n beams), 1.2x the time of a repeated call in wasm, 2x natively. Above it (at most 33.6 MB of table
// kept: 2048 beams exceed every 2D scanner's revolution the package is used with), a call gets its own extractor,
// and the kept per-beam vectors (input, expected ranges) are given back after it.
constexpr std::size_t kKeptBeams = 2048;

val extractPolylines(std::uintptr_t ptr, std::size_t len, std::uintptr_t options) {
  return guarded([&] {
    const auto o = readOptions<PolylinesOptions>(options);
    const double* xy = doubles(ptr);
    checkPoints("extractPolylines", xy, len, 2, 0, true, kMaxCoordinate);
    PolylinesResults& res = rtl_ops::kept<PolylinesResults>();
    auto& beams = res.beams;
    beams.resize(len / 2);
    for (std::size_t i = 0; i < beams.size(); ++i) beams[i] = rtl::VectorND<2, double>(xy[2 * i], xy[2 * i + 1]);
    std::optional<rtl::ScanPolylines2D<double>> own;
    auto& extract = beams.size() <= kKeptBeams ? rtl_ops::kept<rtl::ScanPolylines2D<double>>() : own.emplace();
    // every setting is written on every call: the kept extractor carries nothing over from the previous one
    extract.setMaxVertices(static_cast<std::size_t>(o.maxVertices));
    extract.setMaxGap(o.maxGap);
    extract.setUnexplainedCost(o.unexplainedCost);
    const double t0 = nowMs();
    extract(beams);
    res.computeMs = nowMs() - t0;
    res.vertices.clear();
    res.offsets.assign(1, 0);
    for (const auto& p : extract.polylines()) {
      for (const auto& v : p) res.vertices.insert(res.vertices.end(), {v.x(), v.y()});
      res.offsets.push_back(static_cast<std::uint32_t>(res.vertices.size() / 2));
    }
    res.expectedRanges.assign(extract.expectedRanges().begin(), extract.expectedRanges().end());
    res.polyline.clear(); res.firstBeam.clear(); res.lastBeam.clear();
    res.r.clear(); res.theta.clear(); res.covariance.clear();
    for (const auto& s : extract.segments()) {
      res.polyline.push_back(static_cast<std::uint32_t>(s.polyline));
      res.firstBeam.push_back(static_cast<std::uint32_t>(s.beams.first));
      res.lastBeam.push_back(static_cast<std::uint32_t>(s.beams.second));
      res.r.push_back(s.r);
      res.theta.push_back(s.theta);
      res.covariance.insert(res.covariance.end(), {s.covariance(0, 0), s.covariance(0, 1), s.covariance(1, 0), s.covariance(1, 1)});
    }
    res.vertexCount = static_cast<double>(extract.vertexCount());
    res.returned = static_cast<double>(extract.returnedBeams());
    res.explainedBeams = static_cast<double>(extract.explainedBeams());
    res.rmse = extract.rmse();
    res.explained = extract.explainedFraction();
    res.score = extract.score();
    const double block = writeResults(results(), res);  // copies the arrays into the result block
    if (beams.size() > kKeptBeams) {  // a one-off large scan does not pin its per-beam vectors either
      std::vector<rtl::VectorND<2, double>>().swap(beams);
      std::vector<double>().swap(res.expectedRanges);
    }
    return val(block);
  });
}

}  // namespace
}  // namespace rtl_wasm

EMSCRIPTEN_BINDINGS(rtl_polylines) {
  emscripten::function("extractPolylines", &rtl_wasm::extractPolylines);
  rtl_wasm::registerCall<rtl_wasm::PolylinesOptions, rtl_wasm::PolylinesResults>("extractPolylines");
}
