// Readers: organised LiDAR binaries (rtl/io/OrganizedLidar.h) from bytes in the wasm heap.
#include "adapter.h"

#include <istream>

#include <rtl/io/OrganizedLidar.h>

namespace rtl_wasm {
namespace {

val readOrganizedLidar(std::uintptr_t ptr, std::size_t len, std::size_t beams, int layout) {
  return guarded([&] {
    MemoryBuffer buf(bytes(ptr), len);
    std::istream in(&buf);
    const auto cloud = rtl::readOrganizedLidar<double>(
        in, beams, layout == 1 ? rtl::OrganizedLayout::RowMajor : rtl::OrganizedLayout::ColumnMajor);
    std::vector<double> xyz(3 * cloud.points.size());
    for (std::size_t i = 0; i < cloud.points.size(); ++i)
      for (int k = 0; k < 3; ++k) xyz[3 * i + static_cast<std::size_t>(k)] = cloud.points[i][k];
    const std::vector<float> intensity(cloud.intensity.begin(), cloud.intensity.end());
    val r = val::object();
    r.set("beams", static_cast<double>(cloud.beams));
    r.set("columns", static_cast<double>(cloud.columns));
    r.set("points", f64(xyz));
    r.set("intensity", f32(intensity));
    return r;
  });
}

}  // namespace
}  // namespace rtl_wasm

EMSCRIPTEN_BINDINGS(rtl_readers) { emscripten::function("readOrganizedLidar", &rtl_wasm::readOrganizedLidar); }
