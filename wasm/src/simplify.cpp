// simplify(): the simplify-js compatible Douglas-Peucker (rtl/vect/SimplifyCompatible.h) on an interleaved point
// array in the wasm heap; returns the kept indices, from which the JS layer picks the caller's own objects.
#include "adapter.h"
#include "schema.h"

#include <rtl/vect/SimplifyCompatible.h>

namespace rtl_wasm {
namespace {

// simplify()'s options and results (wasm/js/simplify.js writes and reads them by these names; schema.h).
struct SimplifyOptions {
  int dim = 0;
  double tolerance = 0;
  bool highQuality = false;
  template <class F>
  void fields(F& f) {
    f("dim", dim);
    f("tolerance", tolerance);
    f("highQuality", highQuality);
  }
};
struct SimplifyResults {
  double computeMs = 0;
  std::vector<std::size_t> kept;  // indices of the kept points, increasing
  template <class F>
  void fields(F& f) {
    f.scalar("computeMs", computeMs);
    f.array("kept", kept);
  }
};

val simplify(std::uintptr_t ptr, std::size_t len, std::uintptr_t options) {
  return guarded([&] {
    const auto o = readOptions<SimplifyOptions>(options);
    const int dim = o.dim;
    const double tolerance = o.tolerance;
    const bool highQuality = o.highQuality;
    if (dim != 2 && dim != 3) throw std::invalid_argument("simplify: dim must be 2 or 3, got " + std::to_string(dim));
    const double* xyz = doubles(ptr);
    // Finite coordinates only; no magnitude limit: the library reproduces simplify-js's overflowing arithmetic. The
    // core checks them in its first pass over the input; the message naming the point is made only on failure.
    checkShape("simplify", len, static_cast<std::size_t>(dim), 0);
    if (len / static_cast<std::size_t>(dim) > 0xffffffffu) throw std::length_error("simplify: more than 2^32 - 1 points");
    const double t0 = nowMs();
    SimplifyResults r;
    try {
      r.kept = rtl::simplifyCompatibleIndices(xyz, len / static_cast<std::size_t>(dim), static_cast<std::size_t>(dim),
                                            tolerance, highQuality);
    } catch (const std::invalid_argument&) {
      checkPoints("simplify", xyz, len, static_cast<std::size_t>(dim), 0, false);  // throws with the point's index
      throw;
    }
    r.computeMs = nowMs() - t0;
    static_assert(sizeof(std::size_t) == sizeof(std::uint32_t), "wasm32: size_t indices copy straight into a Uint32Array");
    return val(writeResults(results(), r));
  });
}

}  // namespace
}  // namespace rtl_wasm

EMSCRIPTEN_BINDINGS(rtl_simplify) {
  rtl_wasm::registerCall<rtl_wasm::SimplifyOptions, rtl_wasm::SimplifyResults>("simplify"); emscripten::function("simplify", &rtl_wasm::simplify); }
