// Native twin of the package's assign() and KalmanFilter for tests/js/alg.test.mjs: the same C++ headers
// (rtl/alg/munkres/Assignment.h, rtl/alg/kalman/KalmanX.h) on the same numbers, printed as JSON (17 digits).
//
//   alg_native assign <costs.f64> <rows> <cols> <maximize 0|1>          -> {"columns":[...],"total":t}
//   alg_native kalman <n> <m> <c> <q> <r> <A.f64> <B.f64|-> <H.f64> <z.f64> <u.f64|->
//       A, B, H row-major; z: T measurements of m numbers, u: T controls of c numbers (default zeros).
//       Each step is predict(u_t) then correct(z_t)  -> {"states":[T*n],"covariances":[T*n*n row-major]}
#include <rtl/alg/kalman/KalmanX.h>
#include <rtl/alg/munkres/Assignment.h>

#include <cstdio>
#include <fstream>
#include <iostream>
#include <iterator>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

std::vector<double> readDoubles(const std::string& path) {
  if (path == "-") return {};
  std::ifstream f(path, std::ios::binary);
  if (!f) throw std::runtime_error("cannot open " + path);
  const std::string bytes((std::istreambuf_iterator<char>(f)), std::istreambuf_iterator<char>());
  if (bytes.size() % sizeof(double) != 0) throw std::runtime_error(path + ": size is not a multiple of 8");
  std::vector<double> v(bytes.size() / sizeof(double));
  std::copy(bytes.begin(), bytes.end(), reinterpret_cast<char*>(v.data()));
  return v;
}

void print(const char* name, const std::vector<double>& v) {
  std::printf("\"%s\":[", name);
  for (std::size_t i = 0; i < v.size(); ++i) std::printf(i ? ",%.17g" : "%.17g", v[i]);
  std::printf("]");
}

using Mat = rtl::KalmanX<double>::MatrixX;
using RowMajor = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;
Mat matrix(const std::vector<double>& v, std::size_t rows, std::size_t cols) {
  if (v.size() != rows * cols) throw std::runtime_error("matrix of the wrong size");
  return Eigen::Map<const RowMajor>(v.data(), static_cast<Eigen::Index>(rows), static_cast<Eigen::Index>(cols));
}

int run(int argc, char** argv) {
  const std::string mode = argc > 1 ? argv[1] : "";
  if (mode == "assign" && argc == 6) {
    const auto costs = readDoubles(argv[2]);
    const std::size_t rows = std::stoul(argv[3]), cols = std::stoul(argv[4]);
    const auto col = rtl::solveAssignment(costs, rows, cols, std::string(argv[5]) == "1");
    double total = 0;
    std::vector<double> columns;
    for (std::size_t i = 0; i < rows; ++i) {
      columns.push_back(col[i] == rtl::assignment_unassigned ? -1.0 : static_cast<double>(col[i]));
      if (col[i] != rtl::assignment_unassigned) total += costs[i * cols + col[i]];
    }
    std::printf("{");
    print("columns", columns);
    std::printf(",\"total\":%.17g}\n", total);
    return 0;
  }
  if (mode == "kalman" && argc == 12) {
    const std::size_t n = std::stoul(argv[2]), m = std::stoul(argv[3]), c = std::stoul(argv[4]);
    rtl::KalmanX<double> k(n, m, c, std::stod(argv[5]), std::stod(argv[6]));
    k.set_transision_matrix(matrix(readDoubles(argv[7]), n, n));
    if (std::string(argv[8]) != "-") k.set_control_matrix(matrix(readDoubles(argv[8]), n, c));
    k.set_measurement_matrix(matrix(readDoubles(argv[9]), m, n));
    const auto z = readDoubles(argv[10]), u = readDoubles(argv[11]);
    const std::size_t steps = z.size() / m;
    std::vector<double> states, covariances;
    for (std::size_t t = 0; t < steps; ++t) {
      Eigen::VectorXd ut = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(c));
      for (std::size_t i = 0; i < c && !u.empty(); ++i) ut[static_cast<Eigen::Index>(i)] = u[t * c + i];
      k.predict(ut);
      k.correct(Eigen::Map<const Eigen::VectorXd>(z.data() + t * m, static_cast<Eigen::Index>(m)));
      for (Eigen::Index i = 0; i < k.states().size(); ++i) states.push_back(k.states()[i]);
      const RowMajor p = k.covariance();
      covariances.insert(covariances.end(), p.data(), p.data() + p.size());
    }
    std::printf("{");
    print("states", states);
    std::printf(",");
    print("covariances", covariances);
    std::printf("}\n");
    return 0;
  }
  std::cerr << "usage: see the head of tests/tools/alg_native.cpp\n";
  return 2;
}

}  // namespace

int main(int argc, char** argv) {
  try {
    return run(argc, argv);
  } catch (const std::exception& e) {
    std::cerr << "alg_native: " << e.what() << "\n";
    return 1;
  }
}
