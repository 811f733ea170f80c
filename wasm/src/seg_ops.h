// Segmentation on flat arrays, shared by the wasm bindings (segment.cpp) and the native comparison tool
// (tests/tools/rtl_native.cpp), so that both run exactly the same C++ on the same numbers. No emscripten here.
#pragma once

#include "opaque.h"  // first: it configures rtl/vect/SimplifyCompatible.h

#include <cfloat>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include <rtl/core/CoordinateCheck.h>
#include <rtl/core/VectorND.h>
#include <rtl/seg/CAR_Segmenter.h>
#include <rtl/seg/SegTrace.h>

#include "kept.h"
#include "trace_ops.h"

namespace rtl_ops {

// The segmenter's settings; every caller sets them all (the package's defaults: wasm/js/defaults.js).
struct SegmentParams {
  std::size_t step = 2;
  double lowerBound = 0.1, upperBound = 0.5;
  double origin[3] = {0, 0, 0};
};

// The parameters from a binding's options struct with fields step, lowerBound, upperBound, origin (schema.h).
template <class Options>
SegmentParams segmentParams(const Options& o) {
  SegmentParams p;
  p.step = static_cast<std::size_t>(o.step);
  p.lowerBound = o.lowerBound;
  p.upperBound = o.upperBound;
  for (int k = 0; k < 3; ++k) p.origin[k] = o.origin[k];
  return p;
}

struct SegmentOutput {
  std::vector<std::int32_t> labels;        // per point, -1 for gaps
  std::vector<std::uint32_t> indices;      // all clusters' point indices, cluster after cluster
  std::vector<std::uint32_t> offsets;      // cluster k = indices[offsets[k] .. offsets[k+1])
  std::vector<std::uint32_t> runs;         // contiguous half-open index runs [b, e) of all clusters, flattened
  std::vector<std::uint32_t> runOffsets;   // cluster k = runs[runOffsets[k] .. runOffsets[k+1]) (2 numbers a run)
  // The index of the first coordinate that is +-Infinity (NaN is a gap), found while copying the input into the
  // segmenter's point vector (rtl::detail::firstBeyond); the rest of the output is then empty. SIZE_MAX: none.
  std::size_t badAt = SIZE_MAX;
};

// The untraced segmenter and its point vector, kept between calls (one per thread; the wasm module has one): the
// segmenter's work buffers and the points grow to the largest scan once instead of being allocated every call.
// Clusters are read as index ranges (CAR_Segmenter::grabClusterRanges), so the points need not carry their index.
template <int D>
struct SegmentWorkspace {
  std::vector<rtl::VectorND<D, double>> pts;
  std::vector<std::size_t> ranges;
  rtl::CAR_Segmenter<rtl::VectorND<D, double>> seg;
};

// The clusters of a loaded segmenter as labels, indices and runs (see SegmentOutput). A function of its own, not
// inlined into the binding: V8's TurboFan allocates registers per wasm function, and inside the one large function
// it kept the fill loops' counters in stack slots.
template <class Segmenter>
[[gnu::noinline]] void collectClusters(Segmenter& seg, std::size_t n, std::vector<std::size_t>& ranges, SegmentOutput& out) {
  out.labels.assign(n, -1);
  out.indices.resize(n);  // at most n points in clusters; trimmed below
  std::int32_t* labels = out.labels.data();
  std::uint32_t* idx = out.indices.data();
  std::size_t filled = 0;
  out.offsets.push_back(0);
  out.runOffsets.push_back(0);
  for (;;) {
    ranges.clear();
    if (seg.grabClusterRanges(ranges) == 0) break;
    const auto label = static_cast<std::int32_t>(out.offsets.size() - 1);
    for (std::size_t r = 0; r < ranges.size(); r += 2) {
      const auto b = static_cast<std::uint32_t>(ranges[r]), e = static_cast<std::uint32_t>(ranges[r + 1]);
      std::uint32_t* at = idx + filled;
      for (std::uint32_t i = b; i < e; ++i) {
        labels[i] = label;
        at[i - b] = i;
      }
      filled += e - b;
      // adjacent ranges of one cluster form one run
      if (r > 0 && b == out.runs.back()) out.runs.back() = e;
      else out.runs.insert(out.runs.end(), {b, e});
    }
    out.offsets.push_back(static_cast<std::uint32_t>(filled));
    out.runOffsets.push_back(static_cast<std::uint32_t>(out.runs.size()));
  }
  out.indices.resize(filled);
}

template <int D, class Observer>
SegmentOutput segmentWith(const double* xyz, std::size_t n, const SegmentParams& p, Observer* observer) {
  if (n > 0xffffffffu) throw std::length_error("segment: more than 2^32 - 1 points");
  const ReleaseKeptAbove release{n};
  auto& work = kept<SegmentWorkspace<D>>();
  auto& pts = work.pts;
  using Point = rtl::VectorND<D, double>;
  static_assert(sizeof(Point) == D * sizeof(double), "the points are copied as one array of coordinates");
  SegmentOutput out;
  pts.resize(n);  // zero-fills only beyond the last call's size; every point is assigned below
  // +-Infinity is refused; NaN is a gap. The points' storage is D * n contiguous doubles (the static_assert above).
  const std::size_t bad = rtl::detail::firstBeyond(xyz, D * n, DBL_MAX, true, n ? pts[0].data().data() : nullptr);
  if (bad < D * n) {
    out.badAt = bad;
    return out;
  }
  Point origin;
  for (int k = 0; k < D; ++k) origin[static_cast<std::size_t>(k)] = p.origin[k];
  // Traced: a fresh segmenter of the traced type (a one-off); untraced: the kept one, given this call's settings.
  rtl::CAR_Segmenter<Point, Observer> fresh;
  auto& seg = [&]() -> rtl::CAR_Segmenter<Point, Observer>& {
    if constexpr (Observer::enabled) return fresh;
    else return work.seg;
  }();
  seg.setStepSize(p.step);
  seg.setLowerBound(p.lowerBound);
  seg.setUpperBound(p.upperBound);
  if constexpr (Observer::enabled) seg.setObserver(observer);
  seg.setMaxSize(n);
  // a function of its own (opaque.h): it holds the segmentation's loops, optimized by V8 within a few calls
  using Segmenter = rtl::CAR_Segmenter<Point, Observer>;
  (seg.*opaque(static_cast<void (Segmenter::*)(const std::vector<Point>&, const Point&)>(&Segmenter::loadData)))(pts, origin);
  collectClusters(seg, n, work.ranges, out);
  return out;
}

// trace: nullptr for the untraced segmenter (CAR_Segmenter<P>, exactly RTL's type); otherwise the steps of a
// CAR_Segmenter<P, CarTraceLog> are appended to it. Never inlined: segment.cpp and pipeline.cpp then share one copy
// of each instantiation at link time instead of each inlining its own (the package's size budget).
template <int D>
__attribute__((noinline)) SegmentOutput segment(const double* xyz, std::size_t n, const SegmentParams& p, FlatTrace* trace = nullptr) {
  // each a function of its own (opaque.h), not inlined into one large binding
  if (trace == nullptr) return opaque(&segmentWith<D, rtl::NoTrace>)(xyz, n, p, nullptr);
  rtl::CarTraceLog log;
  SegmentOutput out = opaque(&segmentWith<D, rtl::CarTraceLog>)(xyz, n, p, &log);
  trace->append(log);
  return out;
}

}  // namespace rtl_ops
