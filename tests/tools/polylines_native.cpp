// Native twin of the package's extractPolylines() for tests/js/polylines.test.mjs: rtl::ScanPolylines2D<double> on
// the same numbers, printed as JSON (17 digits; NaN as null).
//
//   polylines_native <beams.f64> <maxVertices> <maxGap> <unexplainedCost> [reps]
//       beams: interleaved x, y (little-endian doubles), NaN for no return
//       reps (bench/js/b_polylines.mjs): the call is run that many times on the same object and "timeUs" and "wallUs"
//       (the median thread CPU and wall-clock time of a call, microseconds) are added to the output
//       -> {"vertices":[...],"offsets":[...],"expectedRanges":[...],"r":[...],"theta":[...],"covariance":[...],
//           "vertexCount":v,"explainedBeams":h,"returned":n,"rmse":e,"explained":f,"score":s}
#include <rtl/vect/ScanPolylines2D.h>

#include <algorithm>
#include <cmath>
#include <ctime>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

std::vector<double> readDoubles(const std::string& path) {
  std::ifstream f(path, std::ios::binary);
  if (!f) throw std::runtime_error("cannot open " + path);
  const std::string bytes((std::istreambuf_iterator<char>(f)), std::istreambuf_iterator<char>());
  if (bytes.size() % sizeof(double) != 0) throw std::runtime_error(path + ": size is not a multiple of 8");
  std::vector<double> v(bytes.size() / sizeof(double));
  std::copy(bytes.begin(), bytes.end(), reinterpret_cast<char*>(v.data()));
  return v;
}

void number(double v) {
  if (std::isnan(v)) std::printf("null");
  else std::printf("%.17g", v);
}

void array(const char* name, const std::vector<double>& v) {
  std::printf("\"%s\":[", name);
  for (std::size_t i = 0; i < v.size(); ++i) {
    if (i) std::printf(",");
    number(v[i]);
  }
  std::printf("],");
}

void scalar(const char* name, double v, bool last = false) {
  std::printf("\"%s\":", name);
  number(v);
  std::printf(last ? "}\n" : ",");
}

}  // namespace

int main(int argc, char** argv) {
  try {
    if (argc != 5 && argc != 6) throw std::runtime_error("usage: polylines_native <beams.f64> <maxVertices> <maxGap> <unexplainedCost> [reps]");
    const std::vector<double> xy = readDoubles(argv[1]);
    std::vector<rtl::VectorND<2, double>> beams(xy.size() / 2);
    for (std::size_t i = 0; i < beams.size(); ++i) beams[i] = rtl::VectorND<2, double>(xy[2 * i], xy[2 * i + 1]);
    rtl::ScanPolylines2D<double> ex;
    ex.setMaxVertices(std::strtoul(argv[2], nullptr, 10));
    ex.setMaxGap(std::strtod(argv[3], nullptr));
    ex.setUnexplainedCost(std::strtod(argv[4], nullptr));
    const int reps = argc == 6 ? std::max(1, std::atoi(argv[5])) : 1;
    std::vector<double> times, walls;
    auto us = [](const timespec& a, const timespec& b) {
      return static_cast<double>(b.tv_sec - a.tv_sec) * 1e6 + static_cast<double>(b.tv_nsec - a.tv_nsec) * 1e-3;
    };
    for (int k = 0; k < reps; ++k) {
      timespec c0{}, c1{}, w0{}, w1{};
      clock_gettime(CLOCK_MONOTONIC, &w0);
      clock_gettime(CLOCK_THREAD_CPUTIME_ID, &c0);
      ex(beams);
      clock_gettime(CLOCK_THREAD_CPUTIME_ID, &c1);
      clock_gettime(CLOCK_MONOTONIC, &w1);
      times.push_back(us(c0, c1));
      walls.push_back(us(w0, w1));
    }
    std::sort(times.begin(), times.end());
    std::sort(walls.begin(), walls.end());
    std::vector<double> vertices, offsets{0}, r, theta, cov;
    for (const auto& p : ex.polylines()) {
      for (const auto& v : p) vertices.insert(vertices.end(), {v.x(), v.y()});
      offsets.push_back(static_cast<double>(vertices.size() / 2));
    }
    for (const auto& s : ex.segments()) {
      r.push_back(s.r);
      theta.push_back(s.theta);
      cov.insert(cov.end(), {s.covariance(0, 0), s.covariance(0, 1), s.covariance(1, 0), s.covariance(1, 1)});
    }
    std::printf("{");
    array("vertices", vertices);
    array("offsets", offsets);
    array("expectedRanges", ex.expectedRanges());
    array("r", r);
    array("theta", theta);
    array("covariance", cov);
    scalar("vertexCount", static_cast<double>(ex.vertexCount()));
    scalar("explainedBeams", static_cast<double>(ex.explainedBeams()));
    scalar("returned", static_cast<double>(ex.returnedBeams()));
    scalar("rmse", ex.rmse());
    scalar("explained", ex.explainedFraction());
    if (argc == 6) {
      scalar("timeUs", times[times.size() / 2]);
      scalar("wallUs", walls[walls.size() / 2]);
    }
    scalar("score", ex.score(), true);
    return 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "polylines_native: %s\n", e.what());
    return 1;
  }
}
