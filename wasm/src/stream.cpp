// StreamSegmenter: the streaming IA segmenter behind an integer handle. The JS class owns the handle and frees it
// with dispose() (or a FinalizationRegistry); plain functions keep embind's class machinery out of the way.
#include "adapter.h"
#include "schema.h"

#include <memory>

#include <rtl/core/VectorND.h>
#include <rtl/seg/IA_Segmenter.h>
#include <rtl/seg/SegTrace.h>

#include "trace_ops.h"

namespace rtl_wasm {
namespace {

struct StreamBase {
  virtual ~StreamBase() = default;
  virtual void add(const double* xyz, std::size_t n, const double* origin) = 0;
  virtual std::size_t closed() const = 0;
  virtual std::size_t alive() const = 0;
  virtual val takeClosed() = 0;
  virtual val aliveClusters() const = 0;
  virtual void flush() = 0;
  virtual val takeTrace() = 0;
};

// Observer: rtl::NoTrace (the untraced segmenter, exactly RTL's type) or rtl::IaTraceLog, which records the steps
// until takeTrace() hands them out.
template <int D, class Observer = rtl::NoTrace>
struct Stream final : StreamBase {
  using V = rtl::VectorND<D, double>;
  rtl::IA_Segmenter<V, Observer> seg;
  Observer log;
  Stream(std::size_t step, double lower, double upper, double scaling) : seg(step, lower, upper, scaling) {
    if constexpr (Observer::enabled) seg.setObserver(&log);
  }

  static V point(const double* p) {
    V v;
    for (int k = 0; k < D; ++k) v[static_cast<std::size_t>(k)] = p[k];
    return v;
  }
  void add(const double* xyz, std::size_t n, const double* origin) override {
    const V o = point(origin);
    for (std::size_t i = 0; i < n; ++i) seg.addPoint(point(xyz + D * i), o);
  }
  std::size_t closed() const override { return seg.closedClustersAvailable(); }
  std::size_t alive() const override { return seg.aliveClustersAvailable(); }

  // Clusters as one flat coordinate array plus offsets (in points): cluster k = points[offsets[k]..offsets[k+1]).
  template <class Range>
  static val flat(const Range& clusters) {
    std::vector<double> xyz;
    std::vector<std::uint32_t> offsets{0};
    for (const auto& c : clusters) {
      for (const auto& p : c)
        for (int k = 0; k < D; ++k) xyz.push_back(p[static_cast<std::size_t>(k)]);
      offsets.push_back(static_cast<std::uint32_t>(xyz.size() / D));
    }
    val r = val::object();
    r.set("points", f64(xyz));
    r.set("offsets", u32(offsets));
    return r;
  }
  val takeClosed() override {
    std::vector<std::vector<V>> out;
    while (seg.closedClustersAvailable() > 0) out.push_back(seg.grabCluster());
    return flat(out);
  }
  val aliveClusters() const override {
    std::vector<std::vector<V>> out;
    for (const auto& kv : seg.aliveClusters()) out.push_back(kv.second);
    return flat(out);
  }
  void flush() override { seg.flush(); }
  val takeTrace() override {
    rtl_ops::FlatTrace flat;
    if constexpr (Observer::enabled) {
      flat.append(log);
      log.clear();
    }
    return traceValue(flat);
  }
};

StreamBase* handle(std::uintptr_t h) { return reinterpret_cast<StreamBase*>(h); }

// StreamSegmenter's options (wasm/js/stream.js writes them by these names after checking them; schema.h).
struct StreamOptions {
  int dim = 0;
  double step = 0, lowerBound = 0, upperBound = 0, scaling = 0;
  bool trace = false;
  template <class F>
  void fields(F& f) {
    f("dim", dim);
    f("step", step);
    f("lowerBound", lowerBound);
    f("upperBound", upperBound);
    f("scaling", scaling);
    f("trace", trace);
  }
};

val streamCreate(std::uintptr_t options) {
  return guarded([&] {
    const auto o = readOptions<StreamOptions>(options);
    const int dim = o.dim;
    const bool trace = o.trace;
    const double lower = o.lowerBound, upper = o.upperBound, scaling = o.scaling;
    const auto s = static_cast<std::size_t>(o.step);
    StreamBase* p = nullptr;
    if (trace) p = dim == 3 ? static_cast<StreamBase*>(new Stream<3, rtl::IaTraceLog>(s, lower, upper, scaling))
                            : static_cast<StreamBase*>(new Stream<2, rtl::IaTraceLog>(s, lower, upper, scaling));
    else p = dim == 3 ? static_cast<StreamBase*>(new Stream<3>(s, lower, upper, scaling))
                      : static_cast<StreamBase*>(new Stream<2>(s, lower, upper, scaling));
    return val(static_cast<double>(reinterpret_cast<std::uintptr_t>(p)));
  });
}
val streamAdd(std::uintptr_t h, std::uintptr_t ptr, std::size_t len, int dim, double ox, double oy, double oz) {
  return guarded([&] {
    checkPoints("StreamSegmenter.addPoints", doubles(ptr), len, static_cast<std::size_t>(dim), 0, true);
    const double origin[3] = {ox, oy, oz};
    handle(h)->add(doubles(ptr), len / static_cast<std::size_t>(dim), origin);
    return val::undefined();
  });
}
double streamClosed(std::uintptr_t h) { return static_cast<double>(handle(h)->closed()); }
double streamAlive(std::uintptr_t h) { return static_cast<double>(handle(h)->alive()); }
val streamTakeClosed(std::uintptr_t h) { return guarded([&] { return handle(h)->takeClosed(); }); }
val streamAliveClusters(std::uintptr_t h) { return guarded([&] { return handle(h)->aliveClusters(); }); }
val streamFlush(std::uintptr_t h) {
  return guarded([&] {
    handle(h)->flush();
    return val::undefined();
  });
}
val streamTakeTrace(std::uintptr_t h) { return guarded([&] { return handle(h)->takeTrace(); }); }
void streamDestroy(std::uintptr_t h) { delete handle(h); }

}  // namespace
}  // namespace rtl_wasm

EMSCRIPTEN_BINDINGS(rtl_stream) {
  using namespace rtl_wasm;
  emscripten::function("streamCreate", &streamCreate);
  rtl_wasm::registerCall<StreamOptions, rtl_wasm::NamedObjectResult>("streamCreate");
  emscripten::function("streamAdd", &streamAdd);
  emscripten::function("streamClosed", &streamClosed);
  emscripten::function("streamAlive", &streamAlive);
  emscripten::function("streamTakeClosed", &streamTakeClosed);
  emscripten::function("streamAliveClusters", &streamAliveClusters);
  emscripten::function("streamFlush", &streamFlush);
  emscripten::function("streamTakeTrace", &streamTakeTrace);
  emscripten::function("streamDestroy", &streamDestroy);
}
