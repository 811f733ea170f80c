// Native twin of the package's toTikz/toSvg: draws the given scan with wasm/src/scan_drawing.h and the library's
// writers and prints the document, so that tests/js/draw-native.test.mjs can check that the package's output is
// the C++ library's byte for byte.
//
//   draw_scan tikz|tikz-bare|svg <points.f64> <labels.f64|-> <segments.f64|-> <title.txt|-> <width> <height> <markRadius>
//   draw_scan tikz3d <points.f64> <labels.f64|-> <segments.f64|-> <planes.f64|-> <planeCounts.f64|->
//                    <polygons.f64|-> <polygonCounts.f64|-> <fov|nan> <dirX> <dirY> <dirZ> <width> <height> <markRadius>
// .f64: little-endian doubles (labels and counts too, as the package passes them); '-': none.
#include <rtl/io/Drawing2D.h>
#include <rtl/io/LaTeXTikz3D.h>
#include "../../wasm/src/scan_drawing.h"
#include <rtl/io/Svg2D.h>
#include <rtl/io/Tikz2DWriter.h>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <iterator>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

std::string readFile(const std::string& path) {
  if (path == "-") return {};
  std::ifstream f(path, std::ios::binary);
  if (!f) throw std::runtime_error("cannot open " + path);
  return std::string((std::istreambuf_iterator<char>(f)), std::istreambuf_iterator<char>());
}

std::vector<double> readDoubles(const std::string& path) {
  const std::string bytes = readFile(path);
  if (bytes.size() % sizeof(double) != 0) throw std::runtime_error(path + ": size is not a multiple of 8");
  std::vector<double> v(bytes.size() / sizeof(double));
  std::copy(bytes.begin(), bytes.end(), reinterpret_cast<char*>(v.data()));
  return v;
}

template <class T>
std::vector<T> as(const std::vector<double>& v) {
  return std::vector<T>(v.begin(), v.end());
}

int run(int argc, char** argv) {
  const std::string mode = argc > 1 ? argv[1] : "";
  if ((mode == "tikz" || mode == "tikz-bare" || mode == "svg") && argc == 9) {
    const auto xy = readDoubles(argv[2]), segs = readDoubles(argv[4]);
    const auto labels = as<int>(readDoubles(argv[3]));
    rtl_ops::ScanDrawingOptions o;
    o.width = std::stof(argv[6]);
    o.height = std::stof(argv[7]);
    o.mark_radius = std::stof(argv[8]);
    rtl::Drawing2D d;
    rtl_ops::drawScan(d, xy.data(), xy.size() / 2, labels.empty() ? nullptr : labels.data(), segs.data(), segs.size() / 4,
                  readFile(argv[5]), o);
    if (mode == "svg")
      rtl::writeSvg(d, std::cout);
    else if (mode == "tikz")
      rtl::writeTikz(d, std::cout);
    else
      rtl::writeTikzPicture(d, std::cout);
    return 0;
  }
  if (mode == "tikz3d" && argc == 16) {
    const auto xyz = readDoubles(argv[2]), segs = readDoubles(argv[4]), planes = readDoubles(argv[5]),
               polygons = readDoubles(argv[7]);
    const auto labels = as<int>(readDoubles(argv[3]));
    const auto planeCounts = as<std::size_t>(readDoubles(argv[6])), polygonCounts = as<std::size_t>(readDoubles(argv[8]));
    rtl_ops::ScanDrawingOptions o;
    o.width = std::stof(argv[13]);
    o.height = std::stof(argv[14]);
    o.mark_radius = std::stof(argv[15]);
    rtl::LaTeXTikz3D d;
    const float fov = std::stof(argv[9]);
    if (!std::isnan(fov)) d.setView(fov, rtl::Vector3f(std::stof(argv[10]), std::stof(argv[11]), std::stof(argv[12])));
    rtl_ops::drawScene3D(d, xyz.data(), xyz.size() / 3, labels.empty() ? nullptr : labels.data(), segs.data(),
                     segs.size() / 6, planes.data(), planeCounts.data(), planeCounts.size(), polygons.data(),
                     polygonCounts.data(), polygonCounts.size(), o);
    d.writeTEX(std::cout);
    return 0;
  }
  std::cerr << "usage: see the head of tests/tools/draw_scan.cpp\n";
  return 2;
}

}  // namespace

int main(int argc, char** argv) {
  try {
    return run(argc, argv);
  } catch (const std::exception& e) {
    std::cerr << "draw_scan: " << e.what() << "\n";
    return 1;
  }
}
