// One generic encoding of any rtl::TraceLog (rtl/core/Trace.h) as flat numbers, shared by the wasm bindings and the
// native comparison tool: each event names itself (`kind`) and lists its fields, so nothing here knows an algorithm.
// No emscripten here.
//
// Encoding (FlatTrace): `names` holds every kind and field name once; `data` holds, per event,
//     kindName, fieldCount, then per field: fieldName, type (0 number, 1 integer, 2 bool), value
// all as doubles (names are indices into `names`; integers are exact up to 2^53). The JS layer turns it into
// `{ kind, field: value, ... }` objects.
#pragma once

#include <cstddef>
#include <map>
#include <string>
#include <type_traits>
#include <variant>
#include <vector>

namespace rtl_ops {

struct FlatTrace {
  std::vector<std::string> names;
  std::vector<double> data;
  std::size_t events = 0;

  double name(const char* s) {
    const auto it = index_.find(s);
    if (it != index_.end()) return it->second;
    const double k = static_cast<double>(names.size());
    names.emplace_back(s);
    index_.emplace(s, k);
    return k;
  }

  template <class Event>
  void add(const Event& e) {
    data.push_back(name(Event::kind));
    const std::size_t countAt = data.size();
    data.push_back(0);
    e.fields([&](const char* field, const auto& v) {
      using V = std::decay_t<decltype(v)>;
      data.push_back(name(field));
      if constexpr (std::is_same_v<V, bool>) {
        data.push_back(2);
        data.push_back(v ? 1 : 0);
      } else if constexpr (std::is_integral_v<V> || std::is_enum_v<V>) {
        data.push_back(1);
        data.push_back(static_cast<double>(v));
      } else {
        static_assert(std::is_floating_point_v<V>, "trace fields are integers, floating-point numbers or bools");
        data.push_back(0);
        data.push_back(static_cast<double>(v));
      }
      data[countAt] += 1;
    });
    ++events;
  }

  // Appends every event of a TraceLog, in order.
  template <class Log>
  void append(const Log& log) {
    for (const auto& ev : log.events) std::visit([&](const auto& e) { add(e); }, ev);
  }

 private:
  std::map<std::string, double> index_;
};

}  // namespace rtl_ops
