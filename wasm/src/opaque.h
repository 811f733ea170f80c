// opaque(f): f through a volatile variable, so that no optimizer sees which function a call reaches and the call
// stays a call. Why: V8 runs a wasm function in its baseline compiler (Liftoff) until its optimized code (TurboFan,
// compiled in the background, in time growing with the function's size) is ready. Binaryen (wasm-opt, run by emcc at
// the link) inlines a function with one caller into it whatever noinline says, so a binding became one function of
// ~23 KB (segment: the 2D and 3D paths, traced and untraced, the segmenter's loadData) that ran in Liftoff for its
// first ~50 calls of 100k points. Works for function and member function pointers. No emscripten here.
#pragma once

namespace rtl_ops {

template <class F>
F opaque(F f) {
  F volatile p = f;
  return p;
}

}  // namespace rtl_ops
