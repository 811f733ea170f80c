// segmentAndVectorize(): a scan segmented and each cluster vectorized in one call (pipeline_ops.h), so that a log's
// scan crosses the JS/wasm boundary once instead of once per cluster. Its options and results cross by name
// (schema.h): PipelineOptions and PipelineResults below are the one declaration of both.
#include "adapter.h"
#include "pipeline_ops.h"
#include "schema.h"

namespace rtl_wasm {
namespace {

// segmentAndVectorize()'s options (wasm/js/pipeline.js writes them by these names after checking them; no defaults
// here: the JS layer writes every field). method: 0 ftls, 1 aftls, 2 itls, 3 dp, 4 rw (rtl_ops::Method).
struct PipelineOptions {
  int dim = 0;
  double step = 0, lowerBound = 0, upperBound = 0;
  double origin[3] = {};
  double minPoints = 0;
  int method = 0;
  double sigma = 0, delta = 0, epsilon = 0, maxSize = 0, simplexShift = 0, maxIterations = 0;
  bool split = false, segmentDistance = false;
  template <class F>
  void fields(F& f) {
    f("dim", dim);
    f("step", step);
    f("lowerBound", lowerBound);
    f("upperBound", upperBound);
    f("origin", origin);
    f("minPoints", minPoints);
    f("method", method);
    f("sigma", sigma);
    f("delta", delta);
    f("epsilon", epsilon);
    f("maxSize", maxSize);
    f("simplexShift", simplexShift);
    f("maxIterations", maxIterations);
    f("split", split);
    f("segmentDistance", segmentDistance);
  }
};

// segmentAndVectorize()'s output arrays between calls (kept.h: released with the other kept buffers).
struct KeptOutput {
  rtl_ops::PipelineOutput out;
};

// segmentAndVectorize()'s results (wasm/js/pipeline.js reads them by these names); pipeline_ops.h's PipelineOutput
// says what each is. out: the kept output, or `own` (a scan above kKeptPoints; the schema's listing).
struct PipelineResults {
  double computeMs = 0;
  rtl_ops::PipelineOutput own;
  rtl_ops::PipelineOutput* out = &own;
  template <class F>
  void fields(F& f) {
    f.scalar("computeMs", computeMs);
    f.scalar("stride", static_cast<double>(out->stride));
    f.take("labels", out->seg.labels);
    f.take("indices", out->seg.indices);
    f.array("offsets", out->seg.offsets);
    f.array("runs", out->seg.runs);
    f.array("runOffsets", out->seg.runOffsets);
    f.array("vectorized", out->vectorized);
    f.array("flags", out->flags);
    f.array("failures", out->failures);
    f.array("segmentOffsets", out->segmentOffsets);
    f.array("segments", out->segments);
    f.array("segmentIndices", out->indices);
    f.array("params", out->params);
    f.array("rms", out->rms);
    f.array("polylineParts", out->polylineParts);
    f.array("polylineOffsets", out->polylineOffsets);
    f.array("breakOffsets", out->breakOffsets);
    f.array("breaks", out->breaks);
  }
};

val segmentAndVectorize(std::uintptr_t ptr, std::size_t len, std::uintptr_t options) {
  return guarded([&] {
    const char* fn = "segmentAndVectorize";
    const auto o = readOptions<PipelineOptions>(options);
    // wasm/js/pipeline.js checked both (a caller's mistake is its TypeError/RangeError): this guards the binding, in
    // few bytes (the package is at its size budget)
    if ((o.dim != 2 && o.dim != 3) || o.method < 0 || o.method > 4)
      throw std::invalid_argument("segmentAndVectorize: dim must be 2 or 3 and method 0 to 4");
    const auto dim = static_cast<std::size_t>(o.dim);
    const double* xyz = doubles(ptr);
    // one rule for the whole scan (gaps allowed): every coordinate within +-1e18, also in clusters too small to vectorize
    checkPoints(fn, xyz, len, dim, 0, true, kMaxCoordinate);
    const rtl_ops::SegmentParams s = rtl_ops::segmentParams(o);
    const rtl_ops::VectorizeParams v = rtl_ops::vectorizeParams(o, kMaxCoordinate);
    // A log's scans refill the last call's output arrays (kept, with their capacity) instead of growing ~20 vectors
    // from empty every scan. A scan above kKeptPoints releases the kept objects mid-call: it gets its own.
    const std::size_t n = len / dim;
    PipelineResults r;
    if (n <= rtl_ops::kKeptPoints) r.out = &rtl_ops::kept<KeptOutput>().out;
    const double t0 = nowMs();
    const auto min = static_cast<std::size_t>(o.minPoints);
    if (o.dim == 2) rtl_ops::segmentAndVectorize<2>(xyz, n, s, v, min, *r.out);
    else rtl_ops::segmentAndVectorize<3>(xyz, n, s, v, min, *r.out);
    if (r.out->badInput) throw std::logic_error("segmentAndVectorize: a point the input check passed was refused");
    r.computeMs = nowMs() - t0;
    return val(writeResults(results(), r));
  });
}

}  // namespace
}  // namespace rtl_wasm

EMSCRIPTEN_BINDINGS(rtl_pipeline) {
  emscripten::function("segmentAndVectorize", &rtl_wasm::segmentAndVectorize);
  rtl_wasm::registerCall<rtl_wasm::PipelineOptions, rtl_wasm::PipelineResults>("segmentAndVectorize");
}
