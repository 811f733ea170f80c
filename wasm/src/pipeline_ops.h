// A scan's segmentation and the vectorization of each of its clusters in one pass on flat arrays, shared by the wasm
// binding (pipeline.cpp) and the native comparison tool (tests/tools/rtl_native.cpp). Each cluster's result is
// exactly vectorize()'s on that cluster's points (the same rtl_ops::vectorize on the same numbers); they are laid
// out back to back with offsets, so one call serves a whole scan. No emscripten here.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "kept.h"
#include "seg_ops.h"
#include "vect_ops.h"

namespace rtl_ops {

// Every vectorized cluster's VectorizeOutput, concatenated. V = the number of vectorized clusters (those of at least
// minPoints points, in the segmenter's cluster order); per-cluster arrays are sliced by the *Offsets arrays (V + 1
// entries, the first 0).
struct PipelineOutput {
  SegmentOutput seg;
  std::vector<std::uint32_t> vectorized;       // V: the cluster number of each vectorized cluster
  std::vector<std::uint32_t> flags;            // V: bit 0 ok, bit 1 failed (strict FTLS/AFTLS)
  std::vector<double> failures;                // 3V: boundary, crossingDistance, delta (zeros unless failed)
  std::vector<std::uint32_t> segmentOffsets;   // V + 1: cluster j has segments segmentOffsets[j] .. [j + 1] - 1
  std::vector<double> segments;                // 2 * dim numbers a segment
  std::vector<std::uint32_t> indices;          // 2 a segment: half-open ranges of chain indices within the cluster
  std::vector<double> params;                  // stride numbers a segment
  std::vector<double> rms;                     // 1 a segment
  std::vector<std::uint32_t> polylineParts;    // V + 1: cluster j's polylineOffsets are polylineOffsets[parts[j] .. parts[j+1])
  std::vector<std::uint32_t> polylineOffsets;  // each cluster's own polylineOffsets (cluster-local segment numbers)
  std::vector<std::uint32_t> breakOffsets;     // V + 1, in corners: cluster j's breaks are corners breakOffsets[j] .. [j + 1] - 1
  std::vector<double> breaks;                  // 3 a corner: boundary, crossingDistance, delta
  int stride = 0;
  VectorizeOutput cluster;                     // the current cluster's, reused (its arrays keep their capacity)
  // A coordinate is +-Infinity, or beyond VectorizeParams::maxMagnitude; the rest of the output is then incomplete.
  bool badInput = false;

  void clear() {
    vectorized.clear(); flags.clear(); failures.clear(); segments.clear(); indices.clear(); params.clear(); rms.clear();
    polylineOffsets.clear(); breaks.clear();
    segmentOffsets.assign(1, 0);
    polylineParts.assign(1, 0);
    breakOffsets.assign(1, 0);
    stride = 0;
    badInput = false;
  }
};

namespace detail {

// The gathered coordinates of one cluster (kept: grows to the largest cluster once).
struct ClusterPoints {
  std::vector<double> xyz;
};

template <class T>
void append(std::vector<T>& to, const std::vector<T>& from) {
  to.insert(to.end(), from.begin(), from.end());
}

}  // namespace detail

// Segments the n points of xyz (dim D; NaN: a gap) and vectorizes every cluster of at least minPoints (>= 2)
// points with v (untraced, lines: v.plane false). `out` is cleared first (its arrays keep their capacity). It may be
// a kept object only when n <= kKeptPoints: a scan or cluster above kKeptPoints releases those mid-call. badInput: a coordinate is +-Infinity, or one of a vectorized cluster is beyond v.maxMagnitude
// (the output is then incomplete). O(segment + sum of the clusters' vectorize) time.
template <int D>
void segmentAndVectorize(const double* xyz, std::size_t n, const SegmentParams& s, const VectorizeParams& v,
                         std::size_t minPoints, PipelineOutput& out) {
  out.clear();
  out.seg = segment<D>(xyz, n, s);
  if (out.seg.badAt != SIZE_MAX) {
    out.badInput = true;
    return;
  }
  const auto& offsets = out.seg.offsets;
  const std::uint32_t* idx = out.seg.indices.data();
  for (std::size_t k = 0; k + 1 < offsets.size(); ++k) {
    const std::size_t b = offsets[k], e = offsets[k + 1], m = e - b;
    if (m < minPoints) continue;
    // looked up per cluster: a cluster above kKeptPoints releases the kept objects at the end of its vectorize()
    auto& work = kept<detail::ClusterPoints>().xyz;
    work.resize(D * m);
    for (std::size_t j = 0; j < m; ++j)
      for (int d = 0; d < D; ++d) work[D * j + static_cast<std::size_t>(d)] = xyz[D * idx[b + j] + static_cast<std::size_t>(d)];
    VectorizeOutput& o = out.cluster;
    vectorizeInto<D>(work.data(), m, v, nullptr, o);
    if (o.badAt != SIZE_MAX) {
      out.badInput = true;
      return;
    }
    out.stride = o.stride;
    out.vectorized.push_back(static_cast<std::uint32_t>(k));
    out.flags.push_back((o.ok ? 1u : 0u) | (o.failed ? 2u : 0u));
    out.failures.insert(out.failures.end(), {static_cast<double>(o.failure.boundary), o.failure.crossingDistance, o.failure.delta});
    detail::append(out.segments, o.segments);
    detail::append(out.indices, o.indices);
    detail::append(out.params, o.params);
    detail::append(out.rms, o.rms);
    out.segmentOffsets.push_back(static_cast<std::uint32_t>(out.indices.size() / 2));
    detail::append(out.polylineOffsets, o.polylineOffsets);
    out.polylineParts.push_back(static_cast<std::uint32_t>(out.polylineOffsets.size()));
    for (const auto& c : o.breaks) out.breaks.insert(out.breaks.end(), {static_cast<double>(c.boundary), c.crossingDistance, c.delta});
    out.breakOffsets.push_back(static_cast<std::uint32_t>(out.breaks.size() / 3));
  }
  if (out.stride == 0) out.stride = D == 2 ? 3 : 6;
}

}  // namespace rtl_ops
