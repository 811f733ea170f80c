// Native twin of segmentAndVectorize() for bench/js/b_logs.mjs: the same adapter code (wasm/src/pipeline_ops.h) on
// the same scans, natively, timed in CPU time.
//
//   pipeline_native <scans.f64> <points per scan> <dim> <scans to run> [--method=0-4]
// scans.f64: interleaved little-endian doubles, the scans one after the other; they are run in turn (cycling) until
// <scans to run> scans are done, with segment()'s and vectorize()'s package defaults (CAR step 2, bounds 0.1-0.5;
// FTLS sigma 0.03, delta 0.3, split at infeasible corners; clusters of >= 3 points). Prints one JSON line:
// {"scans", "seconds" (CPU time of all), "clusters", "segments"} (totals, to check the same work as the package's).
// Eigen's explicit SIMD is off, like in the wasm build, so that both do the same arithmetic in the same order.
#define EIGEN_DONT_VECTORIZE
#include "../../wasm/src/pipeline_ops.h"

#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <fstream>
#include <iostream>
#include <iterator>
#include <string>
#include <vector>

int main(int argc, char** argv) {
  if (argc < 5) {
    std::cerr << "usage: pipeline_native <scans.f64> <points per scan> <dim> <scans to run> [--method=0-4]\n";
    return 2;
  }
  std::ifstream in(argv[1], std::ios::binary);
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const std::size_t perScan = std::strtoul(argv[2], nullptr, 10), dim = std::strtoul(argv[3], nullptr, 10);
  const std::size_t runs = std::strtoul(argv[4], nullptr, 10);
  int method = 0;
  if (argc > 5 && std::string(argv[5]).rfind("--method=", 0) == 0) method = std::atoi(argv[5] + 9);
  const std::size_t numbers = perScan * dim;
  if (!in || perScan == 0 || (dim != 2 && dim != 3) || bytes.size() % (8 * numbers) != 0 || bytes.empty()) {
    std::cerr << "pipeline_native: cannot read whole scans of " << perScan << " points of dim " << dim << " from " << argv[1] << "\n";
    return 2;
  }
  std::vector<double> pts(bytes.size() / 8);
  std::copy(bytes.begin(), bytes.end(), reinterpret_cast<char*>(pts.data()));
  const std::size_t scans = pts.size() / numbers;
  rtl_ops::SegmentParams s;
  s.step = 2;
  s.lowerBound = 0.1;
  s.upperBound = 0.5;
  rtl_ops::VectorizeParams v;
  v.method = static_cast<rtl_ops::Method>(method);
  v.dim = static_cast<int>(dim);
  v.split = true;
  v.maxMagnitude = 1e18;
  rtl_ops::PipelineOutput out;
  std::size_t clusters = 0, segments = 0;
  const std::clock_t t0 = std::clock();
  for (std::size_t k = 0; k < runs; ++k) {
    const double* p = pts.data() + (k % scans) * numbers;
    if (dim == 2) rtl_ops::segmentAndVectorize<2>(p, perScan, s, v, 3, out);
    else rtl_ops::segmentAndVectorize<3>(p, perScan, s, v, 3, out);
    clusters += out.seg.offsets.size() - 1;
    segments += out.segmentOffsets.back();
  }
  const double seconds = static_cast<double>(std::clock() - t0) / CLOCKS_PER_SEC;
  std::printf("{\"scans\": %zu, \"seconds\": %.6f, \"clusters\": %zu, \"segments\": %zu}\n", runs, seconds, clusters, segments);
  return 0;
}
