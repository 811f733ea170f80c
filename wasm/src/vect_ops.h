// Vectorization on flat arrays, shared by the wasm bindings (vectorize.cpp) and the native comparison tool
// (tests/tools/rtl_native.cpp): the same C++ on the same numbers. No emscripten here.
#pragma once

#include "opaque.h"  // first: it configures rtl/vect/SimplifyCompatible.h

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

#include <rtl/Vectorization.h>
#include <rtl/core/CoordinateCheck.h>
#include <rtl/vect/FtlsTrace.h>
#include <rtl/vect/SimplifyCompatible.h>
#include <rtl/vect/SimplifyTrace.h>

#include "kept.h"
#include "point_reader.h"
#include "trace_ops.h"

namespace rtl_ops {

enum class Method { FTLS = 0, AFTLS = 1, ITLS = 2, DP = 3, RW = 4 };

struct VectorizeParams {
  Method method = Method::FTLS;
  int dim = 2;
  bool plane = false;
  double sigma = 0.03, delta = 0.3, epsilon = 0.09;
  std::size_t maxSize = 0, simplexShift = 1, maxIterations = 10000;
  // DP: distance to the chord segment (simplify-js's, rtl/vect/SimplifyCompatible.h) instead of RTL's chord line.
  bool segmentDistance = false;
  bool split = false;  // FTLS/AFTLS 2D: break the polyline at corners that cannot be met within delta
  // Coordinates must be within +-maxMagnitude (NaN never passes), checked before the copy into the library's point
  // vector (rtl::detail::firstBeyond); otherwise the output has badAt set and nothing else.
  double maxMagnitude = HUGE_VAL;
};

// The line parameters (plane false) from a binding's options struct with fields dim, method, sigma, delta, epsilon,
// maxSize, simplexShift, maxIterations, split, segmentDistance (schema.h); coordinates within +-maxMagnitude.
template <class Options>
VectorizeParams vectorizeParams(const Options& o, double maxMagnitude) {
  VectorizeParams p;
  p.method = static_cast<Method>(o.method);
  p.dim = o.dim;
  p.sigma = o.sigma;
  p.delta = o.delta;
  p.epsilon = o.epsilon;
  p.maxSize = static_cast<std::size_t>(o.maxSize);
  p.simplexShift = static_cast<std::size_t>(o.simplexShift);
  p.maxIterations = static_cast<std::size_t>(o.maxIterations);
  p.split = o.split;
  p.segmentDistance = o.segmentDistance;
  p.maxMagnitude = maxMagnitude;
  return p;
}

// FTLS/AFTLS 2D: a corner that cannot be met within delta (rtl::CornerReport).
struct Corner {
  std::size_t boundary = 0;
  double crossingDistance = 0, delta = 0;
};

struct VectorizeOutput {
  bool ok = false;
  std::size_t count = 0;
  std::vector<double> segments;               // count * 2 * dim (lines)
  std::vector<std::vector<double>> polygons;  // planes: vertices, 3 numbers each
  std::vector<std::uint32_t> indices;         // 2 * count: half-open point ranges
  std::vector<double> params;                 // count * stride
  int stride = 0;
  std::vector<double> rms;                    // count
  std::vector<std::uint32_t> polylineOffsets;  // segment index where each polyline starts, then count
  std::vector<Corner> breaks;                 // split mode: where the polyline broke
  bool failed = false;                        // strict mode: `failure` is the corner that cannot be met
  Corner failure;
  std::size_t badAt = SIZE_MAX;               // the first coordinate beyond VectorizeParams::maxMagnitude or NaN

  // As a new output, keeping the arrays' capacity.
  void reset() {
    ok = false;
    count = 0;
    segments.clear();
    polygons.clear();
    indices.clear();
    params.clear();
    stride = 0;
    rms.clear();
    polylineOffsets.clear();
    breaks.clear();
    failed = false;
    failure = Corner{};
    badAt = SIZE_MAX;
  }
};

namespace detail {

template <int D>
using Vec = rtl::VectorND<D, double>;

// The input as the vectorizers' point vector, copied into the kept vector after checking every coordinate against
// `limit` (`bad`: one is NaN or beyond it; then nothing is copied). Up to the previous call's size the points are
// assigned in place (~5 instructions a point); a larger call assign()s the whole input (point_reader.h), which constructs the
// points beyond that size straight from it. resize() zero-filled them first (VectorND's default constructor zeroes): FTLS at
// 100k points right after a 50-point call 1.15-1.25x -> 0.9-1.0x of steady. assign() on every call made the steady
// calls slower (its in-place copy loop: FTLS 0.154 -> 0.175 ms); insert() at the end for the growth cost 700 B gz.
template <int D>
const std::vector<Vec<D>>& points(const double* xyz, std::size_t n, double limit, std::size_t& badAt) {
  auto& v = kept<std::vector<Vec<D>>>();
  const std::size_t bad = rtl::detail::firstBeyond(xyz, D * n, limit, false);
  if (bad < D * n) {
    badAt = bad;
    n = 0;
  }
  if (n > v.size()) {
    v.assign(PointReader<D>{xyz}, PointReader<D>{xyz + D * n});
    return v;
  }
  v.erase(v.begin() + static_cast<std::ptrdiff_t>(n), v.end());
  Vec<D>* out = v.data();
  for (std::size_t i = 0; i < n; ++i)
    out[i] = Vec<D>(typename Vec<D>::EigenType(Eigen::Map<const typename Vec<D>::EigenType>(xyz + D * i)));
  return v;
}

// Runs f on a vectorizer of type Vz: the kept one when untraced (Obs = NoTrace), a fresh one when traced (a trace
// is a one-off, and the traced types would otherwise each hold their own buffers for good).
template <class Vz, class Obs, class F>
void withVectorizer(Obs* obs, F&& f) {
  if constexpr (Obs::enabled) {
    Vz vz;
    vz.setObserver(obs);
    f(vz);
  } else {
    f(kept<Vz>());
  }
}

template <int D, class Seg>
void pushSegment(VectorizeOutput& o, const Seg& s) {
  for (int k = 0; k < D; ++k) o.segments.push_back(s.beg()[static_cast<std::size_t>(k)]);
  for (int k = 0; k < D; ++k) o.segments.push_back(s.end()[static_cast<std::size_t>(k)]);
}

inline double rmsOf(double errSquared) { return std::sqrt(errSquared > 0 ? errSquared : 0.0); }

// Ranges, parameters and residuals of a TLS vectorizer's approximations.
template <class Vz>
void tlsRanges(VectorizeOutput& o, const Vz& vz) {
  for (const auto& r : vz.indices()) {
    o.indices.push_back(static_cast<std::uint32_t>(r.first));
    o.indices.push_back(static_cast<std::uint32_t>(r.second));
  }
  for (const auto& a : vz.approximations()) {
    using A = std::decay_t<decltype(a)>;
    if constexpr (std::is_same_v<A, rtl::ApproximationTlsLine2D<double, double>>) {
      o.params.insert(o.params.end(), {a.a(), a.b(), a.c()});
    } else if constexpr (std::is_same_v<A, rtl::ApproximationTlsLine3D<double, double>>) {
      const auto p = a.point(), d = a.direction();
      o.params.insert(o.params.end(), {p[0], p[1], p[2], d[0], d[1], d[2]});
    } else {
      const auto nrm = a.normal();
      o.params.insert(o.params.end(), {nrm[0], nrm[1], nrm[2], a.d()});
    }
    o.rms.push_back(rmsOf(a.errSquaredCompute()));
  }
}

// Douglas-Peucker / Reumann-Witkam keep input points: recover their indices by walking the input forward to each
// segment end (exact match), then describe each kept span by its chord.
template <int D, class Seg>
std::vector<std::size_t> keyIndices(const std::vector<Vec<D>>& pts, const std::vector<Seg>& segs) {
  std::vector<std::size_t> keys{0};
  std::size_t j = 0;
  for (const auto& s : segs) {
    const Vec<D> e = s.end();
    do ++j;
    while (j < pts.size() && pts[j].data() != e.data());  // inputs are finite: == is exact equality
    if (j >= pts.size()) throw std::logic_error("vectorize: a simplified vertex is not an input point");
    keys.push_back(j);
  }
  return keys;
}

// Ranges, chord parameters and residuals of the kept points `keys` (ascending, first and last point included).
template <int D>
void keptRanges(VectorizeOutput& o, const std::vector<Vec<D>>& pts, const std::vector<std::size_t>& keys) {
  for (std::size_t i = 0; i + 1 < keys.size(); ++i) {
    const std::size_t b = keys[i], e = keys[i + 1];
    o.indices.push_back(static_cast<std::uint32_t>(b));
    o.indices.push_back(static_cast<std::uint32_t>(e + 1));
    const Eigen::Matrix<double, D, 1> p0 = pts[b].data(), p1 = pts[e].data();
    const Eigen::Matrix<double, D, 1> chord = p1 - p0;
    const double len = chord.norm();
    const Eigen::Matrix<double, D, 1> dir = len > 0 ? Eigen::Matrix<double, D, 1>(chord / len) : Eigen::Matrix<double, D, 1>::Zero();
    double ss = 0;
    for (std::size_t k = b; k <= e; ++k) {
      const Eigen::Matrix<double, D, 1> q = pts[k].data() - p0;
      const double along = q.dot(dir);
      ss += q.squaredNorm() - along * along;
    }
    o.rms.push_back(rmsOf(ss / static_cast<double>(e - b + 1)));
    if constexpr (D == 2) {
      const double a = -dir.y(), bb = dir.x();
      o.params.insert(o.params.end(), {a, bb, -(a * p0.x() + bb * p0.y())});
    } else {
      o.params.insert(o.params.end(), {p0.x(), p0.y(), p0.z(), dir.x(), dir.y(), dir.z()});
    }
  }
}

// maxSize only reserves buffers; one call never uses more than its n points, and memory that wasm grows into stays
// allocated for good, so the reservation is capped at n.
inline std::size_t reservation(const VectorizeParams& p, std::size_t n) { return p.maxSize < n ? p.maxSize : n; }

// run(observer), as a function of its own for observed() below.
template <class Observer, class Run>
void runWith(Run& run, Observer* observer) {
  run(observer);
}

}  // namespace detail

// Runs run(observer) with an observer of type Log recording into `trace`, or with no observer (NoTrace: the
// vectorizer types are then exactly RTL's) when trace is nullptr. Each through opaque
// (opaque.h), a wasm function of its own: inlined here, the untraced and the traced AFTLS runs were one
// function of 18.9 KB that V8 took ~90-130 ms to optimize, so AFTLS ran its first 50-300 calls of 100k points in
// the baseline tier (Liftoff) at 1.4-1.6x its optimized time.
template <class Log, class Run>
void observed(FlatTrace* trace, Run&& run) {
  using R = std::remove_reference_t<Run>;
  if (trace == nullptr) {
    opaque(&detail::runWith<rtl::NoTrace, R>)(run, nullptr);
    return;
  }
  Log log;
  opaque(&detail::runWith<Log, R>)(run, &log);
  trace->append(log);
}

// trace: nullptr for the untraced vectorizers; otherwise their steps are appended to it (2D FTLS/AFTLS, ITLS, DP
// and RW; the 3D fast vectorizers report no steps: the caller rejects a trace for them). `o` is reset first and
// keeps its arrays' capacity: a caller vectorizing many small chains (segmentAndVectorize, pipeline_ops.h) reuses
// one output instead of allocating ~15 growing vectors per chain. Never inlined: vectorize.cpp and pipeline.cpp then
// share one copy of each instantiation at link time instead of each inlining its own (the package's size budget).
template <int D>
__attribute__((noinline)) void vectorizeInto(const double* xyz, std::size_t n, const VectorizeParams& p, FlatTrace* trace, VectorizeOutput& o) {
  using namespace detail;
  if (n > 0xffffffffu) throw std::length_error("vectorize: more than 2^32 - 1 points");
  const ReleaseKeptAbove release{n};
  o.reset();
  const auto& pts = points<D>(xyz, n, p.maxMagnitude, o.badAt);
  if (o.badAt != SIZE_MAX) return;
  o.stride = p.plane ? 4 : (D == 2 ? 3 : 6);
  auto finishLines = [&](bool ok, const auto& vz, const auto& segs) {
    o.ok = ok;
    if (!ok) return;
    for (const auto& s : segs) pushSegment<D>(o, s);
    tlsRanges(o, vz);
    o.count = vz.indices().size();
  };
  auto onePolyline = [&] { o.polylineOffsets = {0, static_cast<std::uint32_t>(o.count)}; };

  if (p.method == Method::DP || p.method == Method::RW) {
    std::vector<rtl::LineSegmentND<D, double>> segs;
    std::vector<std::size_t> keys;
    if (p.method == Method::DP && p.segmentDistance) {
      // simplify-js's Douglas-Peucker in high-quality mode (no radial pre-pass): the same recursion on the squared
      // distance to the chord segment; the kept indices come straight from it.
      if (n >= 2) keys = rtl::simplifyCompatibleIndices(xyz, n, static_cast<std::size_t>(D), p.epsilon, true);
      for (std::size_t k = 1; k < keys.size(); ++k) segs.emplace_back(pts[keys[k - 1]], pts[keys[k]]);
    } else if (p.method == Method::DP) {
      observed<rtl::DpTraceLog>(trace, [&](auto* obs) {
        using Obs = std::remove_pointer_t<decltype(obs)>;
        withVectorizer<rtl::VectorizerDouglasPeuckerND<D, double, Obs>>(obs, [&](auto& vz) {
          vz.setEpsilon(p.epsilon);
          if (p.maxSize) vz.setMaxSize(reservation(p, n));
          vz(pts, segs);
        });
      });
    } else {
      observed<rtl::RwTraceLog>(trace, [&](auto* obs) {
        using Obs = std::remove_pointer_t<decltype(obs)>;
        withVectorizer<rtl::VectorizerReumannWitkamND<D, double, Obs>>(obs, [&](auto& vz) {
          vz.setEpsilon(p.epsilon);
          if (p.maxSize) vz.setMaxSize(reservation(p, n));
          vz(pts, segs);
        });
      });
    }
    o.ok = n >= 2;
    for (const auto& s : segs) pushSegment<D>(o, s);
    if (keys.empty()) keys = keyIndices<D>(pts, segs);
    if (n >= 2) keptRanges<D>(o, pts, keys);
    o.count = segs.size();
    onePolyline();
    return;
  }

  if constexpr (D == 2) {
    if (p.method == Method::ITLS) {
      observed<rtl::ItlsTraceLog>(trace, [&](auto* obs) {
        using Obs = std::remove_pointer_t<decltype(obs)>;
        withVectorizer<rtl::VectorizerITLSProjections2D<double, double, Obs>>(obs, [&](auto& vz) {
          vz.setSigma(p.sigma);
          if (p.maxSize) vz.setMaxSize(reservation(p, n));
          const bool ok = vz(pts);
          finishLines(ok, vz, vz.lineSegments());
        });
      });
      onePolyline();
    } else {
      auto fast = [&](auto& vz) {
        vz.setSigma(p.sigma);
        vz.setDelta(p.delta);
        vz.setSplitAtInfeasibleCorners(p.split);
        if (p.maxSize) vz.setMaxSize(reservation(p, n));
        const bool ok = vz(pts);
        finishLines(ok, vz, vz.lineSegments());
        if (ok)
          for (const auto k : vz.polylineOffsets()) o.polylineOffsets.push_back(static_cast<std::uint32_t>(k));
        else
          onePolyline();
        for (const auto& b : vz.breaks()) o.breaks.push_back({b.boundary, b.crossingDistance, b.delta});
        if (vz.failure()) {
          o.failed = true;
          o.failure = {vz.failure()->boundary, vz.failure()->crossingDistance, vz.failure()->delta};
        }
      };
      if (p.method == Method::FTLS) {
        observed<rtl::FtlsTraceLog>(trace, [&](auto* obs) {
          using Obs = std::remove_pointer_t<decltype(obs)>;
          withVectorizer<rtl::VectorizerFTLSPolyline2D<double, double, Obs>>(obs, fast);
        });
      } else {
        observed<rtl::FtlsTraceLog>(trace, [&](auto* obs) {
          using Obs = std::remove_pointer_t<decltype(obs)>;
          withVectorizer<rtl::VectorizerAFTLSPolyline2D<double, double, Obs>>(obs, [&](auto& vz) {
            vz.setSimplexShift(p.simplexShift);
            vz.setMaxIterations(p.maxIterations);
            fast(vz);
          });
        });
      }
    }
  } else {
    if (p.plane) {
      auto& vz = kept<rtl::VectorizerAFTLSPlaneProjections3D<double, double>>();
      vz.setSigma(p.sigma);
      vz.setSimplexShift(p.simplexShift);
      vz.setMaxIterations(p.maxIterations);
      if (p.maxSize) vz.setMaxSize(reservation(p, n));
      o.ok = vz(pts);
      if (o.ok) {
        for (const auto& poly : vz.polygons()) {
          std::vector<double> v;
          for (const auto& q : poly.points()) v.insert(v.end(), {q[0], q[1], q[2]});
          o.polygons.push_back(std::move(v));
        }
        tlsRanges(o, vz);
        o.count = vz.indices().size();
      }
    } else if (p.method == Method::ITLS) {
      observed<rtl::ItlsTraceLog>(trace, [&](auto* obs) {
        using Obs = std::remove_pointer_t<decltype(obs)>;
        withVectorizer<rtl::VectorizerITLSProjections3D<double, double, Obs>>(obs, [&](auto& vz) {
          vz.setSigma(p.sigma);
          if (p.maxSize) vz.setMaxSize(reservation(p, n));
          const bool ok = vz(pts);
          finishLines(ok, vz, vz.lineSegments());
        });
      });
    } else if (p.method == Method::FTLS) {
      auto& vz = kept<rtl::VectorizerFTLSProjections3D<double, double>>();
      vz.setSigma(p.sigma);
      if (p.maxSize) vz.setMaxSize(reservation(p, n));
      const bool ok = vz(pts);
      finishLines(ok, vz, vz.lineSegments());
    } else {
      auto& vz = kept<rtl::VectorizerAFTLSProjections3D<double, double>>();
      vz.setSigma(p.sigma);
      vz.setSimplexShift(p.simplexShift);
      vz.setMaxIterations(p.maxIterations);
      if (p.maxSize) vz.setMaxSize(reservation(p, n));
      const bool ok = vz(pts);
      finishLines(ok, vz, vz.lineSegments());
    }
    onePolyline();
  }
}

template <int D>
VectorizeOutput vectorize(const double* xyz, std::size_t n, const VectorizeParams& p, FlatTrace* trace = nullptr) {
  VectorizeOutput o;
  vectorizeInto<D>(xyz, n, p, trace, o);
  return o;
}

}  // namespace rtl_ops
