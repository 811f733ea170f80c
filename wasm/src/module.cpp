// Module-level functions: the boundary schema, and the diagnostics (heap bytes in use (malloc) and linear memory
// size) used by the leak tests.
#include "adapter.h"
#include "schema.h"

#include <emscripten/heap.h>
#include <emscripten/stack.h>
#include <malloc.h>

namespace rtl_wasm {
namespace {

double heapInUse() { return static_cast<double>(mallinfo().uordblks); }
double memoryBytes() { return static_cast<double>(emscripten_get_heap_size()); }
// The shadow stack pointer: it must be the same before and after any call, failing or not.
double stackPointer() { return static_cast<double>(emscripten_stack_get_current()); }

}  // namespace
}  // namespace rtl_wasm

EMSCRIPTEN_BINDINGS(rtl_module) {
  emscripten::function("heapInUse", &rtl_wasm::heapInUse);
  emscripten::function("memoryBytes", &rtl_wasm::memoryBytes);
  emscripten::function("stackPointer", &rtl_wasm::stackPointer);
  // The calls' options and results by name (schema.h; read once per instance by wasm/js/schema.js).
  emscripten::function("boundarySchema", &rtl_wasm::boundarySchema);
}
