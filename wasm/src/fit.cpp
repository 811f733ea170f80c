// fitLine: total-least-squares line through interleaved 2D or 3D points, by rtl::ApproximationTlsLine2D/3D.
// The sums are taken about the centroid (two passes), so that points far from the origin keep full precision;
// the line is then shifted back.
#include "adapter.h"
#include "schema.h"

#include <rtl/vect/ApproximationTlsLine2D.h>
#include <rtl/vect/ApproximationTlsLine3D.h>
#include <rtl/vect/PrecSums.h>

namespace rtl_wasm {
namespace {

template <int D>
val fitLineImpl(const double* xy, std::size_t n) {
  double c[D] = {};
  for (std::size_t i = 0; i < n; ++i)
    for (int k = 0; k < D; ++k) c[k] += xy[D * i + static_cast<std::size_t>(k)];
  for (int k = 0; k < D; ++k) c[k] /= static_cast<double>(n);
  // Sums of centred coordinates: s[k] (first order), q[k][l] (second order).
  double s[D] = {}, q[D][D] = {};
  for (std::size_t i = 0; i < n; ++i) {
    double d[D];
    for (int k = 0; k < D; ++k) d[k] = xy[D * i + static_cast<std::size_t>(k)] - c[k];
    for (int k = 0; k < D; ++k) {
      s[k] += d[k];
      for (int l = k; l < D; ++l) q[k][l] += d[k] * d[l];
    }
  }
  double spread = 0;
  for (int k = 0; k < D; ++k) spread += q[k][k];
  if (!(spread > 0)) throw std::invalid_argument("fitLine: all " + str(n) + " points coincide, the line is undefined");

  val r = val::object();
  r.set("dim", D);
  r.set("count", static_cast<double>(n));
  r.set("centroid", f64(c, D));
  double ms = 0;
  if constexpr (D == 2) {
    const rtl::ApproximationTlsLine2D<double, double> line(
        rtl::PrecSums2D<double>(s[0], s[1], q[0][0], q[1][1], q[0][1], n));
    double a = line.a(), b = line.b(), off = line.c() - a * c[0] - b * c[1];
    // Convention: offset <= 0, i.e. the normal points from the origin towards the line; through the origin,
    // the normal's first non-zero component is positive. (+ 0.0 turns -0 into 0.)
    if (off > 0 || (off == 0 && (a < 0 || (a == 0 && b < 0)))) {
      a = -a;
      b = -b;
      off = -off;
    }
    const double normal[2] = {a + 0.0, b + 0.0}, dir[2] = {b + 0.0, -a + 0.0};
    for (std::size_t i = 0; i < n; ++i) {
      const double e = a * xy[2 * i] + b * xy[2 * i + 1] + off;
      ms += e * e;
    }
    r.set("normal", f64(normal, 2));
    r.set("offset", off + 0.0);
    r.set("direction", f64(dir, 2));
  } else {
    const rtl::ApproximationTlsLine3D<double, double> line(
        rtl::PrecSums3D<double>(s[0], s[1], s[2], q[0][0], q[1][1], q[2][2], q[0][1], q[1][2], q[0][2], n));
    const auto v = line.direction();
    double dir[3] = {v[0], v[1], v[2]};
    const double len = std::sqrt(dir[0] * dir[0] + dir[1] * dir[1] + dir[2] * dir[2]);
    // Direction sign: first non-zero component positive.
    double sign = 1;
    for (double x : dir)
      if (x != 0) {
        sign = x < 0 ? -1 : 1;
        break;
      }
    for (double& x : dir) x = sign * x / len + 0.0;
    for (std::size_t i = 0; i < n; ++i) {
      double d[3], along = 0, sq = 0;
      for (int k = 0; k < 3; ++k) {
        d[k] = xy[3 * i + static_cast<std::size_t>(k)] - c[k];
        along += d[k] * dir[k];
        sq += d[k] * d[k];
      }
      ms += std::max(0.0, sq - along * along);
    }
    r.set("direction", f64(dir, 3));
  }
  r.set("rms", std::sqrt(ms / static_cast<double>(n)));
  return r;
}

// fitLine()'s options (wasm/js/fitline.js writes them by these names after checking them; schema.h). The result is
// a small object built here (NamedObjectResult).
struct FitLineOptions {
  int dim = 0;
  template <class F>
  void fields(F& f) {
    f("dim", dim);
  }
};

val fitLine(std::uintptr_t ptr, std::size_t len, std::uintptr_t options) {
  return guarded([&] {
    const int dim = readOptions<FitLineOptions>(options).dim;
    if (dim != 2 && dim != 3) throw std::invalid_argument("fitLine: dim must be 2 or 3, got " + std::to_string(dim));
    const double* xy = doubles(ptr);
    checkPoints("fitLine", xy, len, static_cast<std::size_t>(dim), 2, false, kMaxCoordinate);
    return dim == 2 ? fitLineImpl<2>(xy, len / 2) : fitLineImpl<3>(xy, len / 3);
  });
}

}  // namespace
}  // namespace rtl_wasm

EMSCRIPTEN_BINDINGS(rtl_fit) {
  emscripten::function("fitLine", &rtl_wasm::fitLine);
  rtl_wasm::registerCall<rtl_wasm::FitLineOptions, rtl_wasm::NamedObjectResult>("fitLine");
}
