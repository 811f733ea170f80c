// vectorize(): the rtl/Vectorization.h vectorizers on an interleaved point array in the wasm heap (see vect_ops.h).
#include "adapter.h"
#include "vect_ops.h"

namespace rtl_wasm {
namespace {

val vectorize(std::uintptr_t ptr, std::size_t len, int dim, int method, bool plane, double sigma, double delta,
              double epsilon, double maxSize, double simplexShift, double maxIterations, bool split, bool trace,
              bool segmentDistance) {
  return guarded([&] {
    if (dim != 2 && dim != 3) throw std::invalid_argument("vectorize: dim must be 2 or 3, got " + std::to_string(dim));
    if (method < 0 || method > 4) throw std::invalid_argument("vectorize: unknown method " + std::to_string(method));
    const double* xyz = doubles(ptr);
    checkShape("vectorize", len, static_cast<std::size_t>(dim), 2);  // the numbers: while copying (vect_ops.h)
    rtl_ops::VectorizeParams p;
    p.method = static_cast<rtl_ops::Method>(method);
    p.dim = dim;
    p.plane = plane;
    p.sigma = sigma;
    p.delta = delta;
    p.epsilon = epsilon;
    p.maxSize = static_cast<std::size_t>(maxSize);
    p.simplexShift = static_cast<std::size_t>(simplexShift);
    p.maxIterations = static_cast<std::size_t>(maxIterations);
    p.split = split;
    p.segmentDistance = segmentDistance;
    p.maxMagnitude = kMaxCoordinate;
    rtl_ops::FlatTrace flat;
    rtl_ops::FlatTrace* events = trace ? &flat : nullptr;
    const double t0 = nowMs();
    const auto o = dim == 2 ? rtl_ops::vectorize<2>(xyz, len / 2, p, events) : rtl_ops::vectorize<3>(xyz, len / 3, p, events);
    if (o.badAt < len) throwBadCoordinate("vectorize", xyz, o.badAt, static_cast<std::size_t>(dim));
    const double computeMs = nowMs() - t0;
    std::vector<double> polys;
    std::vector<std::uint32_t> polyOffsets{0};
    for (const auto& poly : o.polygons) {
      polys.insert(polys.end(), poly.begin(), poly.end());
      polyOffsets.push_back(static_cast<std::uint32_t>(polys.size()));
    }
    // Corners as flat triples boundary, crossingDistance, delta (breaks; failure when failed).
    std::vector<double> breaks;
    for (const auto& b : o.breaks) breaks.insert(breaks.end(), {static_cast<double>(b.boundary), b.crossingDistance, b.delta});
    // The order of wasm/js/api.js's vectorize (VECTORIZE_ARRAYS).
    const double out = results()
                           .scalar(o.ok)
                           .scalar(static_cast<double>(o.count))
                           .scalar(o.stride)
                           .scalar(computeMs)
                           .scalar(o.failed)
                           .scalar(static_cast<double>(o.failure.boundary))
                           .scalar(o.failure.crossingDistance)
                           .scalar(o.failure.delta)
                           .array(o.segments)
                           .array(polys)
                           .array(polyOffsets)
                           .array(o.indices)
                           .array(o.params)
                           .array(o.rms)
                           .array(o.polylineOffsets)
                           .array(breaks)
                           .finish();
    if (!trace) return val(out);
    val r = val::object();  // traced: {out: the block's address, trace}
    r.set("out", out);
    r.set("trace", traceValue(flat));
    return r;
  });
}

}  // namespace
}  // namespace rtl_wasm

EMSCRIPTEN_BINDINGS(rtl_vectorize) {
  emscripten::function("vectorize", &rtl_wasm::vectorize);
  // The kept input buffer and objects (kept.h), shared by vectorize, segment and simplify.
  emscripten::function("inputBuffer", &rtl_wasm::inputBuffer);
  emscripten::function("viewBlock", &rtl_wasm::viewBlock);
  emscripten::function("releaseBuffers", &rtl_ops::releaseKept);
}
