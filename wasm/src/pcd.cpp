// readPcd: the C++ core's PCD reader (rtl/io/PcdFile.h) over a file's bytes in the wasm heap, through its in-memory
// entry point readPcdBytes (no stream). Organised clouds leave in the organised LiDAR reader's layout (toOrganized:
// column-major, beams = rows), unorganised ones in file order; further fields by name, in the points' order.
#include "adapter.h"

#include <string>

#include <rtl/io/PcdFile.h>

namespace rtl_wasm {
namespace {

// `names`: the further fields to read, separated by spaces (PCD field names hold no spaces).
val readPcd(std::uintptr_t ptr, std::size_t len, const std::string& names) {
  return guarded([&] {
    rtl::PcdOptions options;
    options.fields.clear();
    std::size_t k = 0;
    while (k < names.size()) {
      const std::size_t e = std::min(names.find(' ', k), names.size());
      if (e > k) options.fields.push_back(names.substr(k, e - k));
      k = e + 1;
    }
    const auto cloud = rtl::readPcdBytes<double>(reinterpret_cast<const unsigned char*>(bytes(ptr)), len, options);
    const bool organized = cloud.organized();
    const std::size_t n = cloud.points.size();
    // index of point i (file order) in the result: column-major for organised clouds, as toOrganized() lays it out
    auto at = [&](std::size_t i) { return organized ? (i % cloud.width) * cloud.height + i / cloud.width : i; };
    std::vector<double> xyz(3 * n);
    for (std::size_t i = 0; i < n; ++i)
      for (int c = 0; c < 3; ++c) xyz[3 * at(i) + static_cast<std::size_t>(c)] = cloud.points[i][c];
    val fields = val::object();
    for (const auto& f : cloud.fields) {
      std::vector<double> v(f.values.size());
      for (std::size_t i = 0; i < n; ++i)
        for (std::size_t c = 0; c < f.count; ++c) v[at(i) * f.count + c] = f.values[i * f.count + c];
      val entry = val::object();
      entry.set("count", static_cast<double>(f.count));
      entry.set("values", f64(v));
      fields.set(f.name, entry);
    }
    const auto& vp = cloud.viewpoint();
    val r = val::object();
    r.set("organized", organized);
    r.set("width", static_cast<double>(cloud.width));
    r.set("height", static_cast<double>(cloud.height));
    r.set("points", f64(xyz));
    r.set("viewpoint", f64(vp.data(), vp.size()));
    r.set("fields", fields);
    return r;
  }, "PCD");
}

}  // namespace
}  // namespace rtl_wasm

EMSCRIPTEN_BINDINGS(rtl_pcd) {
  emscripten::function("readPcd", &rtl_wasm::readPcd);
}
