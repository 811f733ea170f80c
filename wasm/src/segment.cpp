// segment(): the batch CAR segmenter on an interleaved point array in the wasm heap (see seg_ops.h).
#include "adapter.h"
#include "seg_ops.h"

namespace rtl_wasm {
namespace {

val segment(std::uintptr_t ptr, std::size_t len, int dim, double step, double lower, double upper, double ox,
            double oy, double oz, bool trace) {
  return guarded([&] {
    if (dim != 2 && dim != 3) throw std::invalid_argument("segment: dim must be 2 or 3, got " + std::to_string(dim));
    const double* xyz = doubles(ptr);
    checkPoints("segment", xyz, len, static_cast<std::size_t>(dim), 0, true, HUGE_VAL, false);  // the numbers: while copying (seg_ops.h)
    rtl_ops::SegmentParams p;
    p.step = static_cast<std::size_t>(step);
    p.lowerBound = lower;
    p.upperBound = upper;
    p.origin[0] = ox;
    p.origin[1] = oy;
    p.origin[2] = oz;
    rtl_ops::FlatTrace flat;
    rtl_ops::FlatTrace* events = trace ? &flat : nullptr;
    const double t0 = nowMs();
    auto out = dim == 2 ? rtl_ops::segment<2>(xyz, len / 2, p, events) : rtl_ops::segment<3>(xyz, len / 3, p, events);
    if (out.badInput) checkPoints("segment", xyz, len, static_cast<std::size_t>(dim), 0, true);  // throws the message
    const double computeMs = nowMs() - t0;
    // The order of wasm/js/api.js's segment (SEGMENT_ARRAYS).
    const double res = results()
                           .scalar(computeMs)
                           .take(std::move(out.labels))
                           .take(std::move(out.indices))
                           .array(out.offsets)
                           .array(out.runs)
                           .array(out.runOffsets)
                           .finish();
    if (!trace) return val(res);
    val r = val::object();  // traced: {out: the block's address, trace}
    r.set("out", res);
    r.set("trace", traceValue(flat));
    return r;
  });
}

}  // namespace
}  // namespace rtl_wasm

EMSCRIPTEN_BINDINGS(rtl_segment) { emscripten::function("segment", &rtl_wasm::segment); }
