// assign() and KalmanFilter: rtl::solveAssignment (Munkres / Hungarian) and rtl::KalmanX behind an integer handle
// (the JS class owns it). Matrices cross as row-major doubles in the wasm heap.
#include "adapter.h"
#include "schema.h"

#include <Eigen/Core>

#include <rtl/alg/kalman/KalmanX.h>
#include <rtl/alg/munkres/Assignment.h>

namespace rtl_wasm {
namespace {

using Kalman = rtl::KalmanX<double>;
using RowMajor = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;

// assign()'s options (wasm/js/alg.js writes them by these names; schema.h): the matrix shape (checked by the JS
// layer: integers, rows * cols = the costs' count) and the sense. The result is a small object built here.
struct AssignOptions {
  double rows = 0, cols = 0;
  bool maximize = false;
  template <class F>
  void fields(F& f) {
    f("rows", rows);
    f("cols", cols);
    f("maximize", maximize);
  }
};

val assign(std::uintptr_t ptr, std::size_t len, std::uintptr_t options) {
  return guarded([&] {
    const auto o = readOptions<AssignOptions>(options);
    const bool maximize = o.maximize;
    const auto r = static_cast<std::size_t>(o.rows), c = static_cast<std::size_t>(o.cols);
    if (r * c != len) throw std::invalid_argument("costs has " + str(len) + " numbers for a " + str(r) + " x " + str(c) + " matrix");
    const double* costs = doubles(ptr);
    const std::vector<std::size_t> col = rtl::solveAssignment(len ? costs : nullptr, r, c, maximize);
    std::vector<std::int32_t> columns(r);
    double total = 0;
    for (std::size_t i = 0; i < r; ++i) {
      columns[i] = col[i] == rtl::assignment_unassigned ? -1 : static_cast<std::int32_t>(col[i]);
      if (columns[i] >= 0) total += costs[i * c + col[i]];
    }
    val out = val::object();
    out.set("columns", i32(columns));
    out.set("total", total);
    return out;
  }, "solveAssignment");
}

Kalman* handle(std::uintptr_t h) { return reinterpret_cast<Kalman*>(h); }

// KalmanFilter's options (wasm/js/alg.js; schema.h): the dimensions (checked by the JS layer) and the noise scales
// of Q and R.
struct KalmanOptions {
  double stateDim = 0, measurementDim = 0, controlDim = 0, processNoise = 1, observationNoise = 1;
  template <class F>
  void fields(F& f) {
    f("stateDim", stateDim);
    f("measurementDim", measurementDim);
    f("controlDim", controlDim);
    f("processNoise", processNoise);
    f("observationNoise", observationNoise);
  }
};

val kalmanCreate(std::uintptr_t options) {
  return guarded([&] {
    const auto o = readOptions<KalmanOptions>(options);
    auto* k = new Kalman(static_cast<std::size_t>(o.stateDim), static_cast<std::size_t>(o.measurementDim),
                         static_cast<std::size_t>(o.controlDim), o.processNoise, o.observationNoise);
    return val(static_cast<double>(reinterpret_cast<std::uintptr_t>(k)));
  }, "KalmanX");
}

// which: 0 state x, 1 transition A, 2 control B, 3 covariance P, 4 measurement H, 5 process noise Q,
// 6 measurement noise R. The sizes were checked by the JS layer; KalmanX checks them again.
val kalmanSet(std::uintptr_t h, int which, std::uintptr_t ptr, std::size_t len) {
  return guarded([&] {
    Kalman& k = *handle(h);
    const auto n = static_cast<Eigen::Index>(k.state_dim()), m = static_cast<Eigen::Index>(k.measurement_dim()),
               c = static_cast<Eigen::Index>(k.control_dim());
    const Eigen::Index shape[7][2] = {{n, 1}, {n, n}, {n, c}, {n, n}, {m, n}, {n, n}, {m, m}};
    if (which < 0 || which > 6) throw std::invalid_argument("unknown matrix " + std::to_string(which));
    const Eigen::Index rows = shape[which][0], cols = shape[which][1];
    if (static_cast<std::size_t>(rows * cols) != len)
      throw std::invalid_argument("expected " + str(static_cast<std::size_t>(rows * cols)) + " numbers, got " + str(len));
    const Kalman::MatrixX a = Eigen::Map<const RowMajor>(doubles(ptr), rows, cols);
    switch (which) {
      case 0: k.set_states(a.col(0)); break;
      case 1: k.set_transision_matrix(a); break;
      case 2: k.set_control_matrix(a); break;
      case 3: k.set_covariance_matrix(a); break;
      case 4: k.set_measurement_matrix(a); break;
      case 5: k.set_process_noise_covariance_matrix(a); break;
      default: k.set_measurement_noise_covariance_matrix(a); break;
    }
    return val::undefined();
  }, "KalmanX");
}

val kalmanPredict(std::uintptr_t h, std::uintptr_t ptr, std::size_t len) {
  return guarded([&] {
    handle(h)->predict(Eigen::Map<const Kalman::VectorX>(doubles(ptr), static_cast<Eigen::Index>(len)));
    return val::undefined();
  }, "KalmanX");
}

val kalmanCorrect(std::uintptr_t h, std::uintptr_t ptr, std::size_t len) {
  return guarded([&] {
    handle(h)->correct(Eigen::Map<const Kalman::VectorX>(doubles(ptr), static_cast<Eigen::Index>(len)));
    return val::undefined();
  }, "KalmanX");
}

val kalmanState(std::uintptr_t h) {
  const auto& x = handle(h)->states();
  return f64(x.data(), static_cast<std::size_t>(x.size()));
}

val kalmanCovariance(std::uintptr_t h) {
  const RowMajor p = handle(h)->covariance();
  return f64(p.data(), static_cast<std::size_t>(p.size()));
}

void kalmanDestroy(std::uintptr_t h) { delete handle(h); }

}  // namespace
}  // namespace rtl_wasm

EMSCRIPTEN_BINDINGS(rtl_alg) {
  using namespace rtl_wasm;
  // Results built as JS objects here (assign: {columns, total}; kalmanCreate: the handle).
  registerCall<AssignOptions, NamedObjectResult>("assign");
  registerCall<KalmanOptions, NamedObjectResult>("kalmanCreate");
  emscripten::function("assign", &assign);
  emscripten::function("kalmanCreate", &kalmanCreate);
  emscripten::function("kalmanSet", &kalmanSet);
  emscripten::function("kalmanPredict", &kalmanPredict);
  emscripten::function("kalmanCorrect", &kalmanCorrect);
  emscripten::function("kalmanState", &kalmanState);
  emscripten::function("kalmanCovariance", &kalmanCovariance);
  emscripten::function("kalmanDestroy", &kalmanDestroy);
}
