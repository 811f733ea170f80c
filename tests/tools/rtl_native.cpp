// Native twin of the wasm module for the JavaScript tests and benchmarks: runs the same adapter code
// (wasm/src/seg_ops.h, vect_ops.h) on the same numbers, natively, and prints JSON.
//
//   rtl_native segment   <points.f64> <dim> <step> <lower> <upper> [--split=<counts.u32>] [--reps=N] [--summary]
//   rtl_native vectorize <points.f64> <dim> <method 0-4> <plane 0|1> <sigma> <delta> <epsilon> <simplexShift>
//                        <maxIterations> [--split=<counts.u32>] [--split-corners] [--reps=N] [--summary]
// points.f64: interleaved little-endian doubles. Output: the result as JSON (numbers with 17 significant digits),
// plus "seconds": the median time of one call over N repetitions (default 1), for the wasm-vs-native benchmarks.
// With --split, points.f64 holds several inputs one after the other, counts.u32 their point counts (uint32), and
// the output is a JSON array with one result per input. --split-corners: FTLS/AFTLS 2D in split mode (the JS default).
//   rtl_native --serve: reads such commands from stdin, one a line, and answers each with one line.
// --summary: only "seconds" and "count" (clusters or segments), for the benchmarks: the full JSON of a 100k-point
// segmentation is ~1.4 MB, and parsing it in the benchmark's process disturbed the wasm calls timed right after.
// Eigen's explicit SIMD is off, like in the wasm build, so that both do the same arithmetic in the same order.
#define EIGEN_DONT_VECTORIZE
#include "../../wasm/src/seg_ops.h"
#include "../../wasm/src/vect_ops.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <iterator>
#include <sstream>
#include <string>
#include <vector>

namespace {

bool summaryOnly = false;  // --summary

std::vector<double> readDoubles(const std::string& path) {
  std::ifstream f(path, std::ios::binary);
  if (!f) throw std::runtime_error("cannot open " + path);
  std::vector<char> bytes((std::istreambuf_iterator<char>(f)), std::istreambuf_iterator<char>());
  if (bytes.size() % sizeof(double) != 0) throw std::runtime_error(path + ": size is not a multiple of 8");
  std::vector<double> v(bytes.size() / sizeof(double));
  std::copy(bytes.begin(), bytes.end(), reinterpret_cast<char*>(v.data()));
  return v;
}

template <class T>
void array(std::ostream& os, const char* name, const std::vector<T>& v) {
  os << '"' << name << "\":[";
  char buf[32];
  for (std::size_t i = 0; i < v.size(); ++i) {
    if constexpr (std::is_floating_point_v<T>) {
      const double x = static_cast<double>(v[i]);  // JSON has no infinity: 1e999 parses to it
      if (std::isinf(x)) std::snprintf(buf, sizeof buf, "%s", x > 0 ? "1e999" : "-1e999");
      else std::snprintf(buf, sizeof buf, "%.17g", x);
    }
    else std::snprintf(buf, sizeof buf, "%lld", static_cast<long long>(v[i]));
    os << (i ? "," : "") << buf;
  }
  os << ']';
}

template <class F>
double medianSeconds(int reps, F&& f) {
  std::vector<double> t;
  for (int r = 0; r < reps; ++r) {
    const auto a = std::chrono::steady_clock::now();
    f();
    t.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - a).count());
  }
  std::sort(t.begin(), t.end());
  return t[t.size() / 2];
}

int usage() {
  std::cerr << "usage: rtl_native segment <points.f64> <dim> <step> <lower> <upper> [--reps=N] [--summary]\n"
               "       rtl_native vectorize <points.f64> <dim> <method> <plane> <sigma> <delta> <epsilon> <simplexShift> "
               "<maxIterations> [--reps=N] [--summary]\n";
  return 2;
}

void segmentOne(std::ostream& os, const double* pts, std::size_t n, int dim, const rtl_ops::SegmentParams& p, int reps) {
  rtl_ops::SegmentOutput o;
  const double s = medianSeconds(reps, [&] {
    o = dim == 3 ? rtl_ops::segment<3>(pts, n, p) : rtl_ops::segment<2>(pts, n, p);
  });
  if (summaryOnly) {
    os << "{\"seconds\":" << s << ",\"count\":" << (o.offsets.empty() ? 0 : o.offsets.size() - 1) << '}';
    return;
  }
  os << "{\"seconds\":" << s << ',';
  array(os, "labels", o.labels);
  os << ',';
  array(os, "indices", o.indices);
  os << ',';
  array(os, "offsets", o.offsets);
  os << '}';
}

void vectorizeOne(std::ostream& os, const double* pts, std::size_t n, const rtl_ops::VectorizeParams& p, int reps) {
  rtl_ops::VectorizeOutput o;
  const double s = medianSeconds(reps, [&] {
    o = p.dim == 3 ? rtl_ops::vectorize<3>(pts, n, p) : rtl_ops::vectorize<2>(pts, n, p);
  });
  if (summaryOnly) {
    os << "{\"seconds\":" << s << ",\"ok\":" << (o.ok ? "true" : "false") << ",\"count\":" << o.count << '}';
    return;
  }
  std::vector<double> polys;
  std::vector<std::uint32_t> polyOffsets{0};
  for (const auto& poly : o.polygons) {
    polys.insert(polys.end(), poly.begin(), poly.end());
    polyOffsets.push_back(static_cast<std::uint32_t>(polys.size()));
  }
  os << "{\"seconds\":" << s << ",\"ok\":" << (o.ok ? "true" : "false") << ",\"count\":" << o.count
     << ",\"stride\":" << o.stride << ',';
  array(os, "segments", o.segments);
  os << ',';
  array(os, "polygonPoints", polys);
  os << ',';
  array(os, "polygonOffsets", polyOffsets);
  os << ',';
  array(os, "indices", o.indices);
  os << ',';
  array(os, "params", o.params);
  os << ',';
  array(os, "rms", o.rms);
  os << ',';
  array(os, "polylineOffsets", o.polylineOffsets);
  std::vector<double> corners;
  for (const auto& b : o.breaks) corners.insert(corners.end(), {static_cast<double>(b.boundary), b.crossingDistance, b.delta});
  os << ',';
  array(os, "breaks", corners);
  std::vector<double> failure;
  if (o.failed) failure = {static_cast<double>(o.failure.boundary), o.failure.crossingDistance, o.failure.delta};
  os << ',';
  array(os, "failure", failure);
  os << '}';
}

}  // namespace

namespace {

// One command (the arguments of the usage lines): the exit code (0, 1 with the message on stderr, 2 for usage).
int runCommand(const std::vector<std::string>& all) {
  std::vector<std::string> args;
  int reps = 1;
  std::string split;
  bool splitCorners = false;
  summaryOnly = false;
  for (const std::string& a : all) {
    if (a.rfind("--reps=", 0) == 0) reps = std::max(1, std::atoi(a.c_str() + 7));
    else if (a.rfind("--split=", 0) == 0) split = a.substr(8);
    else if (a == "--split-corners") splitCorners = true;
    else if (a == "--summary") summaryOnly = true;
    else args.push_back(a);
  }
  try {
    const bool seg = args.size() == 6 && args[0] == "segment";
    const bool vec = args.size() == 10 && args[0] == "vectorize";
    if (!seg && !vec) return usage();
    const auto pts = readDoubles(args[1]);
    const int dim = std::stoi(args[2]);
    if (dim != 2 && dim != 3) throw std::runtime_error("dim must be 2 or 3");
    std::vector<std::size_t> counts;
    if (split.empty()) counts.push_back(pts.size() / static_cast<std::size_t>(dim));
    else {
      std::ifstream f(split, std::ios::binary);
      if (!f) throw std::runtime_error("cannot open " + split);
      for (std::uint32_t c; f.read(reinterpret_cast<char*>(&c), sizeof c);) counts.push_back(c);
    }
    rtl_ops::SegmentParams sp;
    rtl_ops::VectorizeParams vp;
    if (seg) {
      sp.step = std::stoul(args[3]);
      sp.lowerBound = std::stod(args[4]);
      sp.upperBound = std::stod(args[5]);
    } else {
      vp.dim = dim;
      vp.method = static_cast<rtl_ops::Method>(std::stoi(args[3]));
      vp.plane = args[4] == "1";
      vp.sigma = std::stod(args[5]);
      vp.delta = std::stod(args[6]);
      vp.epsilon = std::stod(args[7]);
      vp.simplexShift = std::stoul(args[8]);
      vp.maxIterations = std::stoul(args[9]);
      vp.split = splitCorners;
    }
    std::size_t offset = 0;
    if (!split.empty()) std::cout << '[';
    for (std::size_t k = 0; k < counts.size(); ++k) {
      if (offset + counts[k] * static_cast<std::size_t>(dim) > pts.size()) throw std::runtime_error("counts exceed the points");
      if (k) std::cout << ",\n";
      const double* p = pts.data() + offset;
      if (seg) segmentOne(std::cout, p, counts[k], dim, sp, reps);
      else vectorizeOne(std::cout, p, counts[k], vp, reps);
      offset += counts[k] * static_cast<std::size_t>(dim);
    }
    std::cout << (split.empty() ? "\n" : "]\n");
  } catch (const std::exception& e) {
    std::cerr << "rtl_native: " << e.what() << '\n';
    return 1;
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc == 2 && std::string(argv[1]) == "--serve") {
    // One command per input line (the arguments above, separated by spaces), one output line each ({"error": true}
    // when it fails). The benchmarks start the tool once instead of once per round: forking a child process
    // write-protects all of the parent's memory, so that each page it writes next faults once (~10 us each on a
    // VM), and those faults landed in the wasm calls timed after each native run.
    for (std::string line; std::getline(std::cin, line);) {
      std::istringstream words(line);
      std::vector<std::string> args;
      for (std::string w; words >> w;) args.push_back(w);
      if (runCommand(args) != 0) std::cout << "{\"error\":true}\n";
      std::cout.flush();
    }
    return 0;
  }
  return runCommand(std::vector<std::string>(argv + 1, argv + argc));
}
