// segment(): the batch CAR segmenter on an interleaved point array in the wasm heap (see seg_ops.h). Its options
// and results cross by name (schema.h): SegmentOptions and SegmentResults below are the one declaration of both.
#include "adapter.h"
#include "schema.h"
#include "seg_ops.h"

namespace rtl_wasm {
namespace {

// segment()'s options (wasm/js/segment.js writes them by these names after checking them).
// No defaults here: the JS layer writes every field (its defaults: wasm/js/defaults.js).
struct SegmentOptions {
  int dim = 0;
  double step = 0, lowerBound = 0, upperBound = 0;
  double origin[3] = {};
  bool trace = false;
  template <class F>
  void fields(F& f) {
    f("dim", dim);
    f("step", step);
    f("lowerBound", lowerBound);
    f("upperBound", upperBound);
    f("origin", origin);
    f("trace", trace);
  }
};

// segment()'s results (wasm/js/segment.js reads them by these names); seg_ops.h's SegmentOutput says what each is.
struct SegmentResults {
  double computeMs = 0;
  rtl_ops::SegmentOutput out;
  template <class F>
  void fields(F& f) {
    f.scalar("computeMs", computeMs);
    f.take("labels", out.labels);
    f.take("indices", out.indices);
    f.array("offsets", out.offsets);
    f.array("runs", out.runs);
    f.array("runOffsets", out.runOffsets);
  }
};

val segment(std::uintptr_t ptr, std::size_t len, std::uintptr_t options) {
  return guarded([&] {
    const auto o = readOptions<SegmentOptions>(options);
    if (o.dim != 2 && o.dim != 3) throw std::invalid_argument("segment: dim must be 2 or 3, got " + std::to_string(o.dim));
    const auto dim = static_cast<std::size_t>(o.dim);
    checkShape("segment", len, dim, 0);
    const double* xyz = doubles(ptr);
    const rtl_ops::SegmentParams p = rtl_ops::segmentParams(o);
    rtl_ops::FlatTrace flat;
    rtl_ops::FlatTrace* events = o.trace ? &flat : nullptr;
    SegmentResults r;
    const double t0 = nowMs();
    r.out = o.dim == 2 ? rtl_ops::segment<2>(xyz, len / 2, p, events) : rtl_ops::segment<3>(xyz, len / 3, p, events);
    // the numbers were checked while copying them (seg_ops.h); the message comes from that pass
    if (r.out.badAt < len) throwBadCoordinate("segment", xyz, r.out.badAt, dim);
    r.computeMs = nowMs() - t0;
    const double res = writeResults(results(), r);
    if (!o.trace) return val(res);
    val t = val::object();  // traced: {out: the block's address, trace}
    t.set("out", res);
    t.set("trace", traceValue(flat));
    return t;
  });
}

}  // namespace
}  // namespace rtl_wasm

EMSCRIPTEN_BINDINGS(rtl_segment) {
  emscripten::function("segment", &rtl_wasm::segment);
  rtl_wasm::registerCall<rtl_wasm::SegmentOptions, rtl_wasm::SegmentResults>("segment");
}
