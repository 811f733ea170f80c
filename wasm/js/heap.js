// Moving arrays in and out of one module instance's wasm memory: copies into malloc'ed blocks, the module's kept
// input buffer and pointBuffer()'s zero-copy block (the result blocks the bindings return: schema.js).
import { check, describe, dimOption } from './checks.js';

/**
 * The memory functions of module instance m. HEAP* views are read after every allocation: memory growth replaces
 * the buffer and detaches older views.
 */
export function heapOf(m) {
  // Copies `arrays` (Float64Array or Uint8Array) into the wasm heap, calls f(ptr0, len0, ptr1, len1, ...) with
  // lengths in elements, frees them again, and returns check(f(...)).
  function withHeap(fn, arrays, f) {
    const ptrs = [];
    try {
      for (const a of arrays) {
        const p = m._malloc(Math.max(8, a.byteLength));
        if (!p) throw new RangeError(`${fn}: out of wasm memory allocating ${a.byteLength} bytes`);
        ptrs.push(p);
      }
      const args = [];
      arrays.forEach((a, i) => {
        if (a instanceof Float64Array) m.HEAPF64.set(a, ptrs[i] / 8);
        else m.HEAPU8.set(a, ptrs[i]);
        args.push(ptrs[i], a.length);
      });
      return check(f(...args), fn);
    } finally {
      for (const p of ptrs) m._free(p);
    }
  }

  // pointBuffer()'s block (adapter.h viewBlock): its address and capacity in numbers; 0 when there is none.
  let viewAt = 0, viewCap = 0;
  function pointBuffer(n, dim) {
    const fn = 'pointBuffer';
    if (typeof n !== 'number') throw new TypeError(`${fn}: n must be a number, got ${describe(n)}`);
    const d = dimOption({ dim }, fn);
    const len = n * d;
    if (!Number.isInteger(n) || n < 0) throw new RangeError(`${fn}: n must be an integer >= 0, got ${n}`);
    const p = m.viewBlock(len);
    if (!p) { viewAt = 0; throw new RangeError(`${fn}: ${n} points of dim ${d} exceed the limit or the wasm memory`); }
    viewCap = p === viewAt ? Math.max(viewCap, len) : Math.max(len, 64);
    viewAt = p;
    return new Float64Array(m.HEAPF64.buffer, p, len);
  }
  // The address to read `a` in place from, if it is (a part of) the current pointBuffer() view, else 0 (it is
  // copied). A view on wasm memory outside that block (stale, or made by hand) and a detached view are rejected:
  // the one would read freed memory, the other reads as no points.
  function inPlace(fn, a) {
    if (a.buffer === m.HEAPF64.buffer) {
      const at = a.byteOffset;
      if (viewAt && at >= viewAt && at + a.byteLength <= viewAt + 8 * viewCap) return at;
      throw new TypeError(`${fn}: points is a view on wasm memory outside the current pointBuffer() block`);
    }
    if (a.length === 0) {
      try { new Uint8Array(a.buffer, 0, 0); } catch { throw new TypeError(`${fn}: points is a detached view (wasm memory grew: take a new pointBuffer())`); }
    }
    return 0;
  }

  // Writes `len` numbers into the module's kept input buffer (wasm/src/adapter.h; fill(HEAPF64, index) writes them
  // from index on, straight into wasm memory) and returns check(f(ptr, len)). Inputs beyond the buffer's limit get
  // a block of their own, freed after the call. src: the input array, read in place if it is a pointBuffer() view.
  function withInputOf(fn, len, fill, f, src) {
    const at = src ? inPlace(fn, src) : 0;
    if (at) return check(f(at, len), fn);
    let p = m.inputBuffer(len), own = 0;
    if (!p) {
      own = p = m._malloc(Math.max(8, 8 * len));
      if (!p) throw new RangeError(`${fn}: out of wasm memory allocating ${8 * len} bytes`);
    }
    try {
      fill(m.HEAPF64, p / 8);  // read after inputBuffer/_malloc: growth detaches older views
      return check(f(p, len), fn);
    } finally {
      if (own) m._free(own);
    }
  }
  const withInput = (fn, a, f) => withInputOf(fn, a.length, (heap, at) => heap.set(a, at), f, a);

  // Frees the kept input buffer, vectorizers, segmenters and pointBuffer()'s block.
  const release = () => { m.releaseBuffers(); m.viewBlock(-1); viewAt = 0; };

  return { withHeap, pointBuffer, withInputOf, withInput, release };
}
