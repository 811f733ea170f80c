// simplify(): the simplify-js compatible Douglas-Peucker (rtl/vect/SimplifyCompatible.h) on an interleaved point
// array in the wasm heap; returns the kept indices, from which the JS layer picks the caller's own objects.
#include "adapter.h"

#include <rtl/vect/SimplifyCompatible.h>

namespace rtl_wasm {
namespace {

val simplify(std::uintptr_t ptr, std::size_t len, int dim, double tolerance, bool highQuality) {
  return guarded([&] {
    if (dim != 2 && dim != 3) throw std::invalid_argument("simplify: dim must be 2 or 3, got " + std::to_string(dim));
    const double* xyz = doubles(ptr);
    // Finite coordinates only; no magnitude limit: the library reproduces simplify-js's overflowing arithmetic. The
    // core checks them in its first pass over the input; the message naming the point is made only on failure.
    checkShape("simplify", len, static_cast<std::size_t>(dim), 0);
    if (len / static_cast<std::size_t>(dim) > 0xffffffffu) throw std::length_error("simplify: more than 2^32 - 1 points");
    const double t0 = nowMs();
    std::vector<std::size_t> kept;
    try {
      kept = rtl::simplifyCompatibleIndices(xyz, len / static_cast<std::size_t>(dim), static_cast<std::size_t>(dim),
                                            tolerance, highQuality);
    } catch (const std::invalid_argument&) {
      checkPoints("simplify", xyz, len, static_cast<std::size_t>(dim), 0, false);  // throws with the point's index
      throw;
    }
    const double computeMs = nowMs() - t0;
    static_assert(sizeof(std::size_t) == sizeof(std::uint32_t), "wasm32: size_t indices copy straight into a Uint32Array");
    return val(results().scalar(computeMs).array(kept).finish());  // wasm/js/simplify.js reads it as [Uint32Array]
  });
}

}  // namespace
}  // namespace rtl_wasm

EMSCRIPTEN_BINDINGS(rtl_simplify) { emscripten::function("simplify", &rtl_wasm::simplify); }
