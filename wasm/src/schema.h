// The wasm boundary's schema: each call declares its options and its results once, by name, in C++, and the
// JavaScript layer reads that declaration (boundarySchema()) instead of keeping its own list in step.
//
//  * Options: a struct with `template <class F> void fields(F& f)` that calls f("name", member) for each option in
//    a fixed order (members: double, bool, an integer type, or double[N]; an enumeration chosen by name with
//    f("name", member, {"first", "second", ...}), written as the name's index). JS writes the values, looked up by name,
//    into the module's options block (optionsBlock(): one double each, N for an array), and the binding decodes the
//    block with readOptions<Options>(address). Unknown or missing names fail on the JS side before the call.
//  * Results: a struct with `template <class F> void fields(F& f)` that calls f.scalar("name", double),
//    f.array("name", std::vector<T>) (copied into the block) or f.take("name", std::vector<T>) (moved into the
//    block's keeping: per-point arrays), in a fixed order. writeResults() lays them out in the ResultBlock
//    (adapter.h) and the JS layer reads each by name, as the typed array its element type gives.
//
// A call registers both with registerCall<Options, Results>("name") inside its EMSCRIPTEN_BINDINGS block;
// boundarySchema() returns every registered call as {name: {options: [[name, count, choices?]], scalars: [name],
// arrays: [[name, constructor]]}}. docs/wasm-boundary.md walks through adding a call.
#pragma once

#include <emscripten/val.h>

#include <cstddef>
#include <cstdint>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace rtl_wasm {

// The JS typed array constructor of an element type.
template <class T>
constexpr const char* typedArrayName() {
  if constexpr (std::is_same_v<T, double>) return "Float64Array";
  else if constexpr (std::is_same_v<T, float>) return "Float32Array";
  else if constexpr (std::is_same_v<T, std::int32_t>) return "Int32Array";
  else if constexpr (std::is_same_v<T, std::uint32_t>) return "Uint32Array";
  else if constexpr (std::is_same_v<T, std::size_t> && sizeof(std::size_t) == 4) return "Uint32Array";  // wasm32
  else if constexpr (std::is_same_v<T, std::uint8_t>) return "Uint8Array";
  else static_assert(sizeof(T) == 0, "no typed array for this element type");
}

// Capacity of the options block in doubles: the largest call's option count must fit (checked by registerCall).
constexpr std::size_t kOptionsCapacity = 64;

// The block JS writes a call's options into (static storage: its address never changes, even when memory grows).
inline double* optionsBlock() {
  static double block[kOptionsCapacity];
  return block;
}
inline std::uintptr_t optionsBlockAddress() { return reinterpret_cast<std::uintptr_t>(optionsBlock()); }

namespace schema_detail {

// Reads options from the block, in declaration order.
struct OptionReader {
  const double* at;
  template <class T>
  void operator()(const char*, T& v) {
    if constexpr (std::is_array_v<T>) {
      for (auto& e : v) e = static_cast<std::remove_reference_t<decltype(e)>>(*at++);
    } else if constexpr (std::is_same_v<T, bool>) {
      v = *at++ != 0;
    } else {
      v = static_cast<T>(*at++);
    }
  }
  // An enumeration chosen by name: JS writes the index of the name in `choices`.
  template <class T, std::size_t N>
  void operator()(const char*, T& v, const char* const (&)[N]) {
    v = static_cast<T>(static_cast<int>(*at++));
  }
};

// An array [items...] (one copy of the val code for every lister below, not one per option or result type).
[[gnu::noinline]] inline emscripten::val listOf(emscripten::val a, emscripten::val b) {
  emscripten::val e = emscripten::val::array();
  e.call<void>("push", a);
  e.call<void>("push", b);
  return e;
}

// Lists the options as [name, count] pairs ([name, 1, [choice names]] for an enumeration). The templates only
// name the member's count; the lists are built by the non-template functions.
struct OptionLister {
  emscripten::val list = emscripten::val::array();
  [[gnu::noinline]] void add(const char* name, std::size_t n) {
    list.call<void>("push", listOf(emscripten::val(name), emscripten::val(static_cast<double>(n))));
  }
  [[gnu::noinline]] void addChoices(const char* name, const char* const* choices, std::size_t n) {
    emscripten::val names = emscripten::val::array();
    for (std::size_t i = 0; i < n; ++i) names.call<void>("push", emscripten::val(choices[i]));
    emscripten::val e = listOf(emscripten::val(name), emscripten::val(1.0));
    e.call<void>("push", names);
    list.call<void>("push", e);
  }
  template <class T>
  void operator()(const char* name, T&) {
    add(name, std::is_array_v<T> ? std::extent_v<T> : 1);
  }
  template <class T, std::size_t N>
  void operator()(const char* name, T&, const char* const (&choices)[N]) {
    addChoices(name, choices, N);
  }
};

// Lists the results as scalar names and [name, constructor] pairs.
struct ResultLister {
  emscripten::val scalars = emscripten::val::array(), arrays = emscripten::val::array();
  [[gnu::noinline]] void scalar(const char* name, double) { scalars.call<void>("push", emscripten::val(name)); }
  [[gnu::noinline]] void addArray(const char* name, const char* ctor) {
    arrays.call<void>("push", listOf(emscripten::val(name), emscripten::val(ctor)));
  }
  template <class T>
  void array(const char* name, const std::vector<T>&) { addArray(name, typedArrayName<T>()); }
  template <class T>
  void take(const char* name, std::vector<T>&) { addArray(name, typedArrayName<T>()); }
};

// {options, scalars, arrays} of the listers' results.
[[gnu::noinline]] inline emscripten::val describeLists(const OptionLister& ol, const ResultLister& rl) {
  emscripten::val d = emscripten::val::object();
  d.set("options", ol.list);
  d.set("scalars", rl.scalars);
  d.set("arrays", rl.arrays);
  return d;
}

// Writes the results into a ResultBlock (adapter.h), in declaration order.
template <class Block>
struct ResultWriter {
  Block& block;
  void scalar(const char*, double v) { block.scalar(v); }
  template <class T>
  void array(const char*, const std::vector<T>& v) { block.array(v); }
  template <class T>
  void take(const char*, std::vector<T>& v) { block.take(std::move(v)); }
};

using Describe = emscripten::val (*)();
struct Registry {
  std::vector<std::pair<const char*, Describe>> calls;
};
inline Registry& registry() {
  static Registry r;
  return r;
}

}  // namespace schema_detail

// The Results of a call whose result is a JS object built field by field in C++ (a stateful object's handle, or a
// small nested result): nothing crosses through the result block.
struct NamedObjectResult {
  template <class F>
  void fields(F&) {}
};

// The options of a call, decoded from the block at `address` (optionsBlockAddress(), passed by the JS layer).
template <class Options>
Options readOptions(std::uintptr_t address) {
  Options o;
  schema_detail::OptionReader r{reinterpret_cast<const double*>(address)};
  o.fields(r);
  return o;
}

// Lays `results` out in `block` and returns the block's address (ResultBlock::finish). Moves the take() fields.
template <class Block, class Results>
double writeResults(Block& block, Results& results) {
  schema_detail::ResultWriter<Block> w{block};
  results.fields(w);
  return block.finish();
}

// {options, scalars, arrays} of the call with these Options and Results types.
template <class Options, class Results>
emscripten::val describeCall() {
  Options o;
  schema_detail::OptionLister ol;
  o.fields(ol);
  Results r{};
  schema_detail::ResultLister rl;
  r.fields(rl);
  return schema_detail::describeLists(ol, rl);
}

// Registers a call's schema under its JS name (inside the call's EMSCRIPTEN_BINDINGS block).
template <class Options, class Results>
void registerCall(const char* name) {
  schema_detail::registry().calls.emplace_back(name, &describeCall<Options, Results>);
}

// Every registered call's schema, keyed by name (read once per module instance by wasm/js/schema.js).
inline emscripten::val boundarySchema() {
  emscripten::val all = emscripten::val::object();
  for (const auto& [name, describe] : schema_detail::registry().calls) all.set(name, describe());
  emscripten::val r = emscripten::val::object();
  r.set("calls", all);
  r.set("optionsBlock", static_cast<double>(optionsBlockAddress()));
  r.set("optionsCapacity", static_cast<double>(kOptionsCapacity));
  return r;
}

}  // namespace rtl_wasm
