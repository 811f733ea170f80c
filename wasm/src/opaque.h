// rtl_ops::opaque(f): f (a function or member function pointer) read back through a volatile variable, so that no
// optimizer sees which function a call through it reaches, and the call stays a call.
//
// Why: V8 runs a wasm function in its baseline compiler (Liftoff) until its optimized code (TurboFan, compiled in
// the background, in time growing with the function's size) is ready. Binaryen (wasm-opt, which emcc runs at the
// link) inlines a function with one caller into that caller whatever noinline says, so a large algorithm became one
// function that ran in Liftoff for its first tens of calls of 100k points (e.g. the segment binding, ~23 KB: ~50
// calls; Douglas-Peucker's passes inlined into simplifyIndices: 55-120 calls at twice the optimized time). Called
// through opaque(), each part stays a function of its own that compiles and tiers up on its own. The cost is one
// indirect call per use: use it for calls that do a lot of work each.
//
// The core's simplify-js compatible passes (rtl/vect/SimplifyCompatible.h) offer RTL_SIMPLIFY_PASS_CALL for this:
// defined here, so every translation unit of the package that includes this header before any rtl/ header calls
// them through opaque(). (Included first by adapter.h, seg_ops.h and vect_ops.h.)
#pragma once

namespace rtl_ops
{
    template<typename F>
    F opaque(F f)
    {
        F volatile p = f;
        return p;
    }
}

#ifndef RTL_SIMPLIFY_PASS_CALL
#define RTL_SIMPLIFY_PASS_CALL(...) ::rtl_ops::opaque(__VA_ARGS__)
#endif
