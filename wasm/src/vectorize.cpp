// vectorize(): the rtl/Vectorization.h vectorizers on an interleaved point array in the wasm heap (see vect_ops.h).
// Its options and results cross by name (schema.h): VectorizeOptions and VectorizeResults are their one declaration.
#include "adapter.h"
#include "schema.h"
#include "vect_ops.h"

namespace rtl_wasm {
namespace {

// vectorize()'s options (wasm/js/vectorize.js writes them by these names after checking them; no defaults here:
// it writes every field, its defaults in wasm/js/defaults.js).
struct VectorizeOptions {
  int dim = 0;
  rtl_ops::Method method = rtl_ops::Method::FTLS;
  bool plane = false;
  double sigma = 0, delta = 0, epsilon = 0, maxSize = 0, simplexShift = 0, maxIterations = 0;
  bool split = false, trace = false, segmentDistance = false;
  template <class F>
  void fields(F& f) {
    f("dim", dim);
    f("method", method, {"ftls", "aftls", "itls", "dp", "rw"});  // rtl_ops::Method's order
    f("plane", plane);
    f("sigma", sigma);
    f("delta", delta);
    f("epsilon", epsilon);
    f("maxSize", maxSize);
    f("simplexShift", simplexShift);
    f("maxIterations", maxIterations);
    f("split", split);
    f("trace", trace);
    f("segmentDistance", segmentDistance);
  }
};

// vectorize()'s results (wasm/js/vectorize.js reads them by these names); vect_ops.h's VectorizeOutput says what
// each is. Corners are flat triples boundary, crossingDistance, delta (breaks; failure* when failed).
struct VectorizeResults {
  double computeMs = 0;
  rtl_ops::VectorizeOutput o;
  std::vector<double> polygonPoints;
  std::vector<std::uint32_t> polygonOffsets{0};
  std::vector<double> breaks;
  template <class F>
  void fields(F& f) {
    f.scalar("ok", o.ok);
    f.scalar("count", static_cast<double>(o.count));
    f.scalar("stride", o.stride);
    f.scalar("computeMs", computeMs);
    f.scalar("failed", o.failed);
    f.scalar("failureBoundary", static_cast<double>(o.failure.boundary));
    f.scalar("failureCrossingDistance", o.failure.crossingDistance);
    f.scalar("failureDelta", o.failure.delta);
    f.array("segments", o.segments);
    f.array("polygonPoints", polygonPoints);
    f.array("polygonOffsets", polygonOffsets);
    f.array("indices", o.indices);
    f.array("params", o.params);
    f.array("rms", o.rms);
    f.array("polylineOffsets", o.polylineOffsets);
    f.array("breaks", breaks);
  }
};

val vectorize(std::uintptr_t ptr, std::size_t len, std::uintptr_t options) {
  return guarded([&] {
    const auto opt = readOptions<VectorizeOptions>(options);
    const int dim = opt.dim;
    if (dim != 2 && dim != 3) throw std::invalid_argument("vectorize: dim must be 2 or 3, got " + std::to_string(dim));
    const int method = static_cast<int>(opt.method);
    if (method < 0 || method > 4) throw std::invalid_argument("vectorize: unknown method " + std::to_string(method));
    const double* xyz = doubles(ptr);
    checkShape("vectorize", len, static_cast<std::size_t>(dim), 2);  // the numbers: while copying (vect_ops.h)
    rtl_ops::VectorizeParams p = rtl_ops::vectorizeParams(opt, kMaxCoordinate);
    p.plane = opt.plane;
    rtl_ops::FlatTrace flat;
    rtl_ops::FlatTrace* events = opt.trace ? &flat : nullptr;
    VectorizeResults r;
    const double t0 = nowMs();
    r.o = dim == 2 ? rtl_ops::vectorize<2>(xyz, len / 2, p, events) : rtl_ops::vectorize<3>(xyz, len / 3, p, events);
    if (r.o.badAt < len) throwBadCoordinate("vectorize", xyz, r.o.badAt, static_cast<std::size_t>(dim));
    r.computeMs = nowMs() - t0;
    for (const auto& poly : r.o.polygons) {
      r.polygonPoints.insert(r.polygonPoints.end(), poly.begin(), poly.end());
      r.polygonOffsets.push_back(static_cast<std::uint32_t>(r.polygonPoints.size()));
    }
    for (const auto& b : r.o.breaks)
      r.breaks.insert(r.breaks.end(), {static_cast<double>(b.boundary), b.crossingDistance, b.delta});
    const double out = writeResults(results(), r);
    if (!opt.trace) return val(out);
    val t = val::object();  // traced: {out: the block's address, trace}
    t.set("out", out);
    t.set("trace", traceValue(flat));
    return t;
  });
}

}  // namespace
}  // namespace rtl_wasm

EMSCRIPTEN_BINDINGS(rtl_vectorize) {
  emscripten::function("vectorize", &rtl_wasm::vectorize);
  rtl_wasm::registerCall<rtl_wasm::VectorizeOptions, rtl_wasm::VectorizeResults>("vectorize");
  // The kept input buffer and objects (kept.h), shared by vectorize, segment and simplify.
  emscripten::function("inputBuffer", &rtl_wasm::inputBuffer);
  emscripten::function("viewBlock", &rtl_wasm::viewBlock);
  emscripten::function("releaseBuffers", &rtl_ops::releaseKept);
}
