// Readers: CARMEN logs (rtl/io/CarmenLog.h) and organised LiDAR binaries (rtl/io/OrganizedLidar.h), from bytes
// in the wasm heap, through the readers' in-memory entry points: no std::istream (the stream and locale machinery
// would be ~20 KB gzipped of the package).
#include "adapter.h"
#include "schema.h"

#include <string_view>

#include <rtl/io/CarmenLog.h>
#include <rtl/io/OrganizedLidar.h>

namespace rtl_wasm {
namespace {

// The readers' options (wasm/js/readers.js writes them by these names after checking them; schema.h). Their results
// are objects built here (NamedObjectResult).
struct OrganizedLidarOptions {
  std::size_t beams = 0;
  int layout = 0;  // the index of its name in the choices below
  template <class F>
  void fields(F& f) {
    f("beams", beams);
    f("layout", layout, {"column-major", "row-major"});
  }
};
struct CarmenLogOptions {
  double maxRange = 0;  // NaN: the reader detects the log's no-return value
  template <class F>
  void fields(F& f) {
    f("maxRange", maxRange);
  }
};

val readOrganizedLidar(std::uintptr_t ptr, std::size_t len, std::uintptr_t options) {
  return guarded([&] {
    const auto o = readOptions<OrganizedLidarOptions>(options);
    const auto cloud = rtl::readOrganizedLidarBytes<double>(reinterpret_cast<const unsigned char*>(bytes(ptr)), len,
        o.beams, o.layout == 1 ? rtl::OrganizedLayout::RowMajor : rtl::OrganizedLayout::ColumnMajor);
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
  }, "organised LiDAR");
}

const char* sourceName(rtl::CarmenMaxRangeSource s) {
  switch (s) {
    case rtl::CarmenMaxRangeSource::Explicit: return "explicit";
    case rtl::CarmenMaxRangeSource::Parameter: return "parameter";
    case rtl::CarmenMaxRangeSource::Recurring: return "recurring";
    default: return "default";
  }
}

// All scans flat: points/ranges concatenated, scan k = beams offsets[k]..offsets[k+1]; per-scan pose and line.
val readCarmenLog(std::uintptr_t ptr, std::size_t len, std::uintptr_t options) {
  return guarded([&] {
    rtl::CarmenOptions reader;
    reader.max_range = readOptions<CarmenLogOptions>(options).maxRange;
    const auto log = rtl::readCarmenLogTextDetailed<double>(std::string_view(bytes(ptr), len), reader);
    const auto& scans = log.scans;
    std::vector<double> pts, ranges, x, y, theta, stamp, line;
    std::vector<std::uint32_t> offsets{0};
    for (const auto& s : scans) {
      for (const auto& p : s.points) pts.insert(pts.end(), {p.x(), p.y()});
      ranges.insert(ranges.end(), s.ranges.begin(), s.ranges.end());
      offsets.push_back(static_cast<std::uint32_t>(ranges.size()));
      x.push_back(s.x);
      y.push_back(s.y);
      theta.push_back(s.theta);
      stamp.push_back(s.timestamp);
      line.push_back(static_cast<double>(s.line));
    }
    val r = val::object();
    r.set("points", f64(pts));
    r.set("ranges", f64(ranges));
    r.set("offsets", u32(offsets));
    r.set("x", f64(x));
    r.set("y", f64(y));
    r.set("theta", f64(theta));
    r.set("timestamp", f64(stamp));
    r.set("line", f64(line));
    r.set("maxRange", static_cast<double>(log.max_range));
    r.set("maxRangeSource", val(sourceName(log.max_range_source)));
    return r;
  }, "CARMEN log");
}

}  // namespace
}  // namespace rtl_wasm

EMSCRIPTEN_BINDINGS(rtl_readers) {
  using namespace rtl_wasm;
  emscripten::function("readOrganizedLidar", &readOrganizedLidar);
  registerCall<OrganizedLidarOptions, NamedObjectResult>("readOrganizedLidar");
  emscripten::function("readCarmenLog", &readCarmenLog);
  registerCall<CarmenLogOptions, NamedObjectResult>("readCarmenLog");
}
