// segmentAndVectorize(): a scan segmented and each cluster vectorized in one call (pipeline_ops.h), so that a log's
// scan crosses the JS/wasm boundary once instead of once per cluster.
#include "adapter.h"
#include "pipeline_ops.h"

namespace rtl_wasm {
namespace {

val segmentAndVectorize(std::uintptr_t ptr, std::size_t len, int dim, double step, double lower, double upper,
                        double ox, double oy, double oz, double minPoints, int method, double sigma, double delta,
                        double epsilon, double maxSize, double simplexShift, double maxIterations, bool split,
                        bool segmentDistance) {
  return guarded([&] {
    const char* fn = "segmentAndVectorize";
    if (dim != 2 && dim != 3) throw std::invalid_argument(std::string(fn) + ": dim must be 2 or 3, got " + std::to_string(dim));
    if (method < 0 || method > 4) throw std::invalid_argument(std::string(fn) + ": unknown method " + std::to_string(method));
    const double* xyz = doubles(ptr);
    // one rule for the whole scan (gaps allowed): every coordinate within +-1e18, also in clusters too small to vectorize
    checkPoints(fn, xyz, len, static_cast<std::size_t>(dim), 0, true, kMaxCoordinate);
    rtl_ops::SegmentParams s;
    s.step = static_cast<std::size_t>(step);
    s.lowerBound = lower;
    s.upperBound = upper;
    s.origin[0] = ox;
    s.origin[1] = oy;
    s.origin[2] = oz;
    rtl_ops::VectorizeParams v;
    v.method = static_cast<rtl_ops::Method>(method);
    v.dim = dim;
    v.sigma = sigma;
    v.delta = delta;
    v.epsilon = epsilon;
    v.maxSize = static_cast<std::size_t>(maxSize);
    v.simplexShift = static_cast<std::size_t>(simplexShift);
    v.maxIterations = static_cast<std::size_t>(maxIterations);
    v.split = split;
    v.segmentDistance = segmentDistance;
    v.maxMagnitude = kMaxCoordinate;
    const double t0 = nowMs();
    rtl_ops::PipelineOutput o;
    const auto min = static_cast<std::size_t>(minPoints);
    if (dim == 2) rtl_ops::segmentAndVectorize<2>(xyz, len / 2, s, v, min, o);
    else rtl_ops::segmentAndVectorize<3>(xyz, len / 3, s, v, min, o);
    if (o.badInput) throw std::logic_error(std::string(fn) + ": a point the input check passed was refused");
    const double computeMs = nowMs() - t0;
    // The order of wasm/js/pipeline.js (PIPELINE_ARRAYS).
    return val(results()
                   .scalar(computeMs)
                   .scalar(o.stride)
                   .take(std::move(o.seg.labels))
                   .take(std::move(o.seg.indices))
                   .array(o.seg.offsets)
                   .array(o.seg.runs)
                   .array(o.seg.runOffsets)
                   .array(o.vectorized)
                   .array(o.flags)
                   .array(o.failures)
                   .array(o.segmentOffsets)
                   .array(o.segments)
                   .array(o.indices)
                   .array(o.params)
                   .array(o.rms)
                   .array(o.polylineParts)
                   .array(o.polylineOffsets)
                   .array(o.breakOffsets)
                   .array(o.breaks)
                   .finish());
  });
}

}  // namespace
}  // namespace rtl_wasm

EMSCRIPTEN_BINDINGS(rtl_pipeline) { emscripten::function("segmentAndVectorize", &rtl_wasm::segmentAndVectorize); }
