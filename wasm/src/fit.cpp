// fitLine: total-least-squares line through interleaved 2D or 3D points (centroid + covariance eigenvectors).
// TODO(js-api): switch to rtl/vect's ApproximationTlsLine2D/3D once they land (same numbers; this keeps the slice
// independent of them for now).
#include "adapter.h"

#include <Eigen/Eigenvalues>

namespace rtl_wasm {
namespace {

template <int D>
val fitLineImpl(const double* xy, std::size_t n) {
  using Vec = Eigen::Matrix<double, D, 1>;
  using Mat = Eigen::Matrix<double, D, D>;
  const Eigen::Map<const Eigen::Matrix<double, D, Eigen::Dynamic>> P(xy, D, static_cast<Eigen::Index>(n));
  // Two passes (centroid, then centred covariance): no cancellation for points far from the origin.
  const Vec c = P.rowwise().mean();
  const Mat cov = (P.colwise() - c) * (P.colwise() - c).transpose() / static_cast<double>(n);
  Eigen::SelfAdjointEigenSolver<Mat> es(cov);  // eigenvalues ascending
  if (!(es.eigenvalues()(D - 1) > 0))
    throw std::invalid_argument("fitLine: all " + str(n) + " points coincide, the line is undefined");
  Vec dir = es.eigenvectors().col(D - 1).normalized();

  val r = val::object();
  r.set("dim", D);
  r.set("count", static_cast<double>(n));
  r.set("centroid", f64(c.data(), D));
  if constexpr (D == 2) {
    Vec normal(-dir.y(), dir.x());
    double offset = -normal.dot(c);
    // Convention: offset <= 0, i.e. the normal points from the origin towards the line; through the origin,
    // the normal's first non-zero component is positive.
    if (offset > 0 || (offset == 0 && (normal.x() < 0 || (normal.x() == 0 && normal.y() < 0)))) {
      normal = -normal;
      offset = -offset;
    }
    normal = normal.array() + 0.0;       // no -0 in the output
    dir = Vec(normal.y() + 0.0, -normal.x() + 0.0);  // normal = (-dir.y, dir.x)
    offset += 0.0;
    const double ms = ((normal.transpose() * P).array() + offset).square().mean();
    r.set("normal", f64(normal.data(), 2));
    r.set("offset", offset);
    r.set("direction", f64(dir.data(), 2));
    r.set("rms", std::sqrt(ms));
  } else {
    // Direction sign: first non-zero component positive.
    for (int k = 0; k < D; ++k) {
      if (dir(k) == 0) continue;
      if (dir(k) < 0) dir = -dir;
      break;
    }
    dir = dir.array() + 0.0;
    const Eigen::Matrix<double, D, Eigen::Dynamic> Q = P.colwise() - c;
    const double ms = (Q.colwise().squaredNorm().array() - (dir.transpose() * Q).array().square()).max(0.0).mean();
    r.set("direction", f64(dir.data(), D));
    r.set("rms", std::sqrt(ms));
  }
  return r;
}

val fitLine(std::uintptr_t ptr, std::size_t len, int dim) {
  return guarded([&] {
    if (dim != 2 && dim != 3) throw std::invalid_argument("fitLine: dim must be 2 or 3, got " + std::to_string(dim));
    const double* xy = doubles(ptr);
    checkPoints("fitLine", xy, len, static_cast<std::size_t>(dim), 2, false);
    return dim == 2 ? fitLineImpl<2>(xy, len / 2) : fitLineImpl<3>(xy, len / 3);
  });
}

}  // namespace
}  // namespace rtl_wasm

EMSCRIPTEN_BINDINGS(rtl_fit) { emscripten::function("fitLine", &rtl_wasm::fitLine); }
