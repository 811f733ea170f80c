// The thin JavaScript layer over the embind module: argument checks (TypeError for a wrong kind of value,
// RangeError for a bad value, both naming the function and argument), typed arrays in and out, and no C++ object
// ever handed to the caller except the two stateful classes, which free themselves (dispose / FinalizationRegistry).
// wasm/build.mjs emits this file twice: as ES module (api.mjs) and as CommonJS (api.cjs); keep the single
// `export { ... }` line at the end and no imports.

const VERSION = '__RTL_VERSION__';

// ------------------------------------------------------------------------------------------------ argument checks
function describe(v) {
  if (v === null) return 'null';
  if (Array.isArray(v)) return 'an Array';
  if (ArrayBuffer.isView(v)) return `a ${v.constructor.name}`;
  if (typeof v === 'object') return `an object (${Object.prototype.toString.call(v).slice(8, -1)})`;
  if (typeof v === 'string') return `a string ("${v.length > 20 ? v.slice(0, 20) + '...' : v}")`;
  if (typeof v === 'number') return `the number ${v}`;
  return `${typeof v === 'undefined' ? '' : 'a '}${typeof v}`;
}

function isNumericView(v) {
  return ArrayBuffer.isView(v) && !(v instanceof DataView) &&
    !(typeof BigInt64Array !== 'undefined' && (v instanceof BigInt64Array || v instanceof BigUint64Array));
}

// The parts of a typed array between consecutive offsets (each offset counts `width` elements) as views on its
// buffer, made with the constructor: subarray() looks up the species constructor each time, ~2x slower (200
// clusters: 10 -> 5 us); a slice() per part allocates a backing store each.
function partViews(array, offsets, width = 1) {
  const Type = array.constructor, buf = array.buffer, base = array.byteOffset, bytes = Type.BYTES_PER_ELEMENT * width;
  const count = Math.max(0, offsets.length - 1), out = new Array(count);
  for (let k = 0; k < count; k++) out[k] = new Type(buf, base + bytes * offsets[k], width * (offsets[k + 1] - offsets[k]));
  return out;
}

// Points (or any number list) as a Float64Array: Float64Array as is, other numeric typed arrays and plain arrays
// (of numbers only) converted. Values are checked by the C++ side (NaN/Infinity rules depend on the function).
function toF64(v, fn, name) {
  if (v instanceof Float64Array) return v;
  if (isNumericView(v)) return new Float64Array(v);
  if (v !== null && typeof v === 'object' && !ArrayBuffer.isView(v) && typeof v.length === 'number' &&
      Number.isInteger(v.length) && v.length >= 0) {
    const out = new Float64Array(v.length);
    for (let i = 0; i < v.length; i++) {
      const x = v[i];
      if (typeof x !== 'number') throw new TypeError(`${fn}: ${name}[${i}] is ${describe(x)}, expected a number`);
      out[i] = x;
    }
    return out;
  }
  throw new TypeError(`${fn}: ${name} must be a Float64Array, a Float32Array or an array of numbers, got ${describe(v)}`);
}

function options(o, fn, known) {
  if (o === undefined || o === null) return {};
  if (typeof o !== 'object' || Array.isArray(o)) throw new TypeError(`${fn}: options must be an object, got ${describe(o)}`);
  for (const k of Object.keys(o)) {
    if (!known.includes(k)) throw new TypeError(`${fn}: unknown option "${k}" (known: ${known.join(', ')})`);
  }
  return o;
}

function num(o, key, fn, def, { min = -Infinity, max = Infinity, integer = false, exclusiveMin = false } = {}) {
  const v = o[key];
  if (v === undefined) return def;
  if (typeof v !== 'number') throw new TypeError(`${fn}: option ${key} must be a number, got ${describe(v)}`);
  if (!Number.isFinite(v)) throw new RangeError(`${fn}: option ${key} must be finite, got ${v}`);
  if (integer && !Number.isInteger(v)) throw new RangeError(`${fn}: option ${key} must be an integer, got ${v}`);
  if (exclusiveMin ? !(v > min) : v < min) throw new RangeError(`${fn}: option ${key} must be ${exclusiveMin ? '>' : '>='} ${min}, got ${v}`);
  if (v > max) throw new RangeError(`${fn}: option ${key} must be <= ${max}, got ${v}`);
  return v;
}

function dimOption(o, fn, allowed = [2, 3]) {
  const d = o.dim;
  if (d === undefined) return 2;
  if (typeof d !== 'number') throw new TypeError(`${fn}: option dim must be a number, got ${describe(d)}`);
  if (!allowed.includes(d)) throw new RangeError(`${fn}: option dim must be ${allowed.join(' or ')}, got ${d}`);
  return d;
}


function originOption(o, fn, dim) {
  if (o.origin === undefined) return [0, 0, 0];
  const a = toF64(o.origin, fn, 'option origin');
  if (a.length !== dim) throw new RangeError(`${fn}: option origin must have ${dim} numbers (dim ${dim}), got ${a.length}`);
  for (let i = 0; i < dim; i++) if (!Number.isFinite(a[i])) throw new RangeError(`${fn}: option origin[${i}] must be finite, got ${a[i]}`);
  return [a[0], a[1], dim === 3 ? a[2] : 0];
}

function boolOption(o, key, fn, def) {
  const v = o[key];
  if (v === undefined) return def;
  if (typeof v !== 'boolean') throw new TypeError(`${fn}: option ${key} must be a boolean, got ${describe(v)}`);
  return v;
}

// The C++ side's flat trace (wasm/src/trace_ops.h: names + numbers) as plain objects { kind, field: value, ... },
// one per event, in order. Field types: 0 number, 1 integer, 2 boolean.
function traceEvents(t) {
  const { names, data } = t;
  const out = [];
  for (let i = 0; i < data.length;) {
    const e = { kind: names[data[i]] };
    const fields = data[i + 1];
    i += 2;
    for (let k = 0; k < fields; k++, i += 3) e[names[data[i]]] = data[i + 1] === 2 ? data[i + 2] !== 0 : data[i + 2];
    out.push(e);
  }
  return out;
}

// A corner of an FTLS polyline from the triple boundary, crossingDistance, delta at b[k]. Here, not a closure in
// vectorize(): the build's keepNames gives every named closure its name with Object.defineProperty, per call.
function corner(b, k) {
  return { boundary: b[k], crossingDistance: b[k + 1], delta: b[k + 2] };
}

// Proximity bounds of the segmenters: 0 <= lowerBound <= upperBound (upperBound may be Infinity).
function boundsOptions(o, fn, lowerDefault, upperDefault) {
  const lower = num(o, 'lowerBound', fn, lowerDefault, { min: 0 });
  let upper = upperDefault;
  if (o.upperBound === Infinity) upper = Infinity;
  else upper = num(o, 'upperBound', fn, upperDefault, { min: 0 });
  if (!(upper >= lower)) throw new RangeError(`${fn}: option upperBound (${upper}) must be >= lowerBound (${lower})`);
  return [lower, upper];
}


const ERRORS = { TypeError, RangeError, Error };
const MAX_MEMORY = 2 ** 31;  // -sMAXIMUM_MEMORY of wasm/CMakeLists.txt
const DISPOSE = Symbol.dispose ?? Symbol.for('Symbol.dispose');

// The C++ side returns {error, kind} instead of throwing (an exception crossing into JS leaks the wasm stack).
// Every message starts with the name of the function the caller called (fn).
function check(r, fn) {
  if (r !== null && typeof r === 'object' && typeof r.error === 'string') {
    const msg = r.error.startsWith(`${fn}:`) ? r.error : `${fn}: ${r.error}`;
    throw new (ERRORS[r.kind] || Error)(msg);
  }
  return r;
}


// ------------------------------------------------------------------------------------------------ drawings
// toTikz, toSvg and toLatexTable live in draw.js (the C++ core draws and writes them).

// ------------------------------------------------------------------------------------------------ the module
function wrap(m) {
  let lastComputeMs = NaN;  // time spent in the C++ library by the last segment()/vectorize() call
  // Copies `arrays` (Float64Array or Uint8Array) into the wasm heap, calls f(ptr0, len0, ptr1, len1, ...) with lengths
  // in elements, frees them again. HEAP* views are read after every _malloc: memory growth replaces the buffer and
  // detaches older views.
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

  // The results of a binding that returns a ResultBlock (wasm/src/adapter.h: one number, the block's address; when
  // traced, {out: address, trace}): {scalars, arrays, trace}, each array copied out of wasm memory as types[i], or,
  // with view (segment/vectorize { view: true }), the types[i] view on the block itself: no copy, valid until the
  // next call that fills the block (segment, vectorize, simplify) or frees it (releaseBuffers), detached by memory
  // growth. Read right after the call: the next call reuses the block. One ArrayBuffer per copied array:
  // segment()'s labels and indices in one buffer (8 MB at 1M points) made its outside time 1 -> 23 ms (Node 20 on
  // glibc: the one large allocation faulted its pages in on every call, the two of half the size reused freed ones).
  function takeResults(r, types, view = false) {
    const traced = typeof r === 'object';
    const H = m.HEAPF64, buf = H.buffer;
    let k = (traced ? r.out : r) / 8;
    const S = H[k++], scalars = new Array(S);  // a plain array: H.slice() would allocate an ArrayBuffer per call
    for (let i = 0; i < S; i++) scalars[i] = H[k++];
    const A = H[k++], arrays = new Array(A);
    for (let i = 0; i < A; i++, k += 2) {
      const a = new types[i](buf, H[k], H[k + 1]);
      arrays[i] = view ? a : a.slice();
    }
    return { scalars, arrays, trace: traced ? r.trace : undefined };
  }

  function fitLine(points, opts) {
    const fn = 'fitLine';
    const o = options(opts, fn, ['dim']);
    const dim = dimOption(o, fn);
    const xy = toF64(points, fn, 'points');
    return withHeap(fn, [xy], (p, n) => m.fitLine(p, n, dim));
  }

  // The array types of the ResultBlocks of m.vectorize and m.segment, in the order of wasm/src/vectorize.cpp and
  // wasm/src/segment.cpp.
  const VECTORIZE_ARRAYS = [Float64Array, Float64Array, Uint32Array, Uint32Array, Float64Array, Float64Array, Uint32Array, Float64Array];
  const SEGMENT_ARRAYS = [Int32Array, Uint32Array, Uint32Array, Uint32Array, Uint32Array];

  function segment(points, opts) {
    const fn = 'segment';
    const o = options(opts, fn, ['dim', 'step', 'lowerBound', 'upperBound', 'origin', 'trace', 'view']);
    const dim = dimOption(o, fn);
    const trace = boolOption(o, 'trace', fn, false);
    const view = boolOption(o, 'view', fn, false);  // the arrays as views on the module's result block (takeResults)
    // Default 2: CAR compares each point with up to step - 1 previous points, so 2 links consecutive points.
    const step = num(o, 'step', fn, 2, { min: 1, integer: true, max: 2 ** 31 });
    const [lower, upper] = boundsOptions(o, fn, 0.1, 0.5);
    const origin = originOption(o, fn, dim);
    const xyz = toF64(points, fn, 'points');
    const res = takeResults(withInput(fn, xyz, (p, n) => m.segment(p, n, dim, step, lower, upper, origin[0], origin[1],
      origin[2], trace)), SEGMENT_ARRAYS, view);
    lastComputeMs = res.scalars[0];
    const [labels, indices, offsets, runs, runOffsets] = res.arrays;
    // Each cluster's arrays are views on `indices` and `runs` (copies or, with view, the result block).
    const parts = partViews(indices, offsets), ranges = partViews(runs, runOffsets), clusters = new Array(parts.length);
    for (let k = 0; k < parts.length; k++) clusters[k] = { indices: parts[k], ranges: ranges[k] };
    return trace ? { labels, clusters, trace: traceEvents(res.trace) } : { labels, clusters };
  }

  const METHODS = ['ftls', 'aftls', 'itls', 'dp', 'rw'];
  function vectorize(points, opts) {
    const fn = 'vectorize';
    if (opts === undefined) throw new TypeError(`${fn}: options {method} are required (method: ${METHODS.join(', ')})`);
    const o = options(opts, fn, ['dim', 'method', 'primitive', 'sigma', 'delta', 'epsilon', 'maxSize', 'simplexShift',
      'maxIterations', 'split', 'trace', 'distance', 'view']);
    const dim = dimOption(o, fn);
    if (o.method === undefined) throw new TypeError(`${fn}: option method is required (${METHODS.join(', ')})`);
    if (typeof o.method !== 'string') throw new TypeError(`${fn}: option method must be a string, got ${describe(o.method)}`);
    const method = o.method;
    if (!METHODS.includes(method)) throw new RangeError(`${fn}: option method must be one of ${METHODS.join(', ')}, got '${method}'`);
    // Options a method does not use (e.g. epsilon for 'ftls') are still checked, then ignored, so that one
    // settings object can drive every method.
    const primitive = o.primitive ?? 'line';
    if (primitive !== 'line' && primitive !== 'plane') throw new RangeError(`${fn}: option primitive must be 'line' or 'plane', got ${describe(primitive)}`);
    if (primitive === 'plane' && (dim !== 3 || method !== 'aftls'))
      throw new RangeError(`${fn}: primitive 'plane' needs dim 3 and method 'aftls'`);
    const sigma = num(o, 'sigma', fn, 0.03, { min: 0, exclusiveMin: true });
    const delta = num(o, 'delta', fn, 0.3, { min: 0, exclusiveMin: true });
    const epsilon = num(o, 'epsilon', fn, 0.09, { min: 0, exclusiveMin: true });
    // maxSize is a reservation hint: 2 GB of wasm memory (the module's maximum) cannot hold more points than this.
    const maxSize = num(o, 'maxSize', fn, 0, { min: 0, integer: true, max: Math.floor(MAX_MEMORY / (8 * dim)) });
    const simplexShift = num(o, 'simplexShift', fn, 1, { min: 1, integer: true, max: 2 ** 32 - 1 });
    const maxIterations = num(o, 'maxIterations', fn, 10000, { min: 1, integer: true, max: 2 ** 32 - 1 });
    // split (FTLS/AFTLS 2D): break the polyline where a corner cannot be met within delta (default), or RTL's
    // strict behaviour (false: no result then, and `failure` says why).
    const split = boolOption(o, 'split', fn, true);
    const trace = boolOption(o, 'trace', fn, false);
    const view = boolOption(o, 'view', fn, false);  // the arrays as views on the module's result block (takeResults)
    if (trace && dim === 3 && (method === 'ftls' || method === 'aftls'))
      throw new RangeError(`${fn}: option trace is not available for method '${method}' in 3D (only itls, dp and rw trace in 3D)`);
    // distance (dp): to the chord's line (RTL's, default) or to the chord segment (simplify-js's).
    const distance = o.distance ?? 'line';
    if (distance !== 'line' && distance !== 'segment') throw new RangeError(`${fn}: option distance must be 'line' or 'segment', got ${describe(distance)}`);
    const segmentDistance = method === 'dp' && distance === 'segment';
    if (trace && segmentDistance) throw new RangeError(`${fn}: option trace is not available with distance 'segment'`);
    const xyz = toF64(points, fn, 'points');
    const n = xyz.length / dim;  // before the call: growth during it detaches a pointBuffer() view
    const res = takeResults(withInput(fn, xyz, (p, n) => m.vectorize(p, n, dim, METHODS.indexOf(method),
      primitive === 'plane', sigma, delta, epsilon, maxSize, simplexShift, maxIterations, split, trace, segmentDistance)),
    VECTORIZE_ARRAYS, view);
    const [ok, count, stride, computeMs, failed, ...failureTriple] = res.scalars;
    const [segments, polygonPoints, polygonOffsets, indices, params, rms, polylineOffsets, breakTriples] = res.arrays;
    lastComputeMs = computeMs;
    const breaks = [];
    for (let k = 0; k < breakTriples.length; k += 3) breaks.push(corner(breakTriples, k));
    let failure = null;
    if (failed) {
      const f = corner(failureTriple, 0);
      f.message = f.boundary === 0
        ? `${fn}: no partition of the ${n} points into ranges within sigma ${sigma} exists`
        : `${fn}: no polyline within sigma ${sigma} meets delta ${f.delta} at chain index ${f.boundary}: the lines of the ` +
          `ranges before and after it ${Number.isFinite(f.crossingDistance)
            ? `cross ${Number(f.crossingDistance.toPrecision(4))} from the middle of points ${f.boundary - 1} and ${f.boundary}`
            : 'do not cross'}${split ? '' : ' (raise delta, or use split: true to break the polyline there)'}`;
      failure = f;
    }
    const polygons = [];
    const part = view ? (b, e) => polygonPoints.subarray(b, e) : (b, e) => polygonPoints.slice(b, e);
    for (let k = 0; k + 1 < polygonOffsets.length; k++) polygons.push(part(polygonOffsets[k], polygonOffsets[k + 1]));
    const out = {
      method, dim, primitive, ok: ok === 1, count, segments, polygons, indices, params, stride, rms,
      polylineOffsets, breaks, failure,
    };
    if (trace) out.trace = traceEvents(res.trace);  // not a spread of {} when untraced: that copied on every call
    return out;
  }

  // Stateful objects own a C++ object behind an integer handle: dispose() frees it, and if the caller forgets,
  // the FinalizationRegistry frees it after the wrapper is garbage collected (the held value does not reference
  // the wrapper, so it does not keep it alive).
  const registry = typeof FinalizationRegistry === 'function' ? new FinalizationRegistry((free) => free()) : null;

  // The clusters of a StreamSegmenter as views on the one array of points the call returned, as segment() does:
  // a slice() per cluster allocated a backing store each (572 clusters of 100k points: 4-9 ms of a 10 ms call).
  const splitClusters = (r, dim) => partViews(r.points, r.offsets, dim);

  class StreamSegmenter {
    #h = 0;
    #dim;
    #traced;
    constructor(opts) {
      const fn = 'StreamSegmenter';
      const o = options(opts, fn, ['dim', 'step', 'lowerBound', 'upperBound', 'scaling', 'trace']);
      this.#dim = dimOption(o, fn);
      this.#traced = boolOption(o, 'trace', fn, false);
      const step = num(o, 'step', fn, 3, { min: 1, integer: true, max: 1 << 24 });
      const [lower, upper] = boundsOptions(o, fn, 0.1, 0.5);
      const scaling = num(o, 'scaling', fn, 0.05, { min: 0 });
      const h = check(m.streamCreate(this.#dim, step, lower, upper, scaling, this.#traced), fn);
      this.#h = h;
      registry?.register(this, () => m.streamDestroy(h), this);
    }
    #handle(fn) {
      if (this.#h === 0) throw new TypeError(`StreamSegmenter.${fn}: the segmenter was disposed`);
      return this.#h;
    }
    get dim() { return this.#dim; }
    get disposed() { return this.#h === 0; }
    addPoints(points, origin) {
      const fn = 'StreamSegmenter.addPoints';
      const h = this.#handle('addPoints');
      const o = originOption(origin === undefined ? {} : { origin }, fn, this.#dim);
      const xyz = toF64(points, fn, 'points');
      withHeap(fn, [xyz], (p, n) => m.streamAdd(h, p, n, this.#dim, o[0], o[1], o[2]));
    }
    get closedClustersAvailable() { return m.streamClosed(this.#handle('closedClustersAvailable')); }
    get aliveClustersAvailable() { return m.streamAlive(this.#handle('aliveClustersAvailable')); }
    takeClosedClusters() { return splitClusters(check(m.streamTakeClosed(this.#handle('takeClosedClusters')), 'StreamSegmenter.takeClosedClusters'), this.#dim); }
    aliveClusters() { return splitClusters(check(m.streamAliveClusters(this.#handle('aliveClusters')), 'StreamSegmenter.aliveClusters'), this.#dim); }
    flush() { check(m.streamFlush(this.#handle('flush')), 'StreamSegmenter.flush'); }
    get traced() { return this.#traced; }
    // The steps recorded since the last call (the segmenter was made with { trace: true }), then forgotten.
    takeTrace() {
      const fn = 'StreamSegmenter.takeTrace';
      const h = this.#handle('takeTrace');
      if (!this.#traced) throw new TypeError(`${fn}: the segmenter was made without { trace: true }`);
      return traceEvents(check(m.streamTakeTrace(h), fn));
    }
    dispose() {
      if (this.#h === 0) return;
      registry?.unregister(this);
      m.streamDestroy(this.#h);
      this.#h = 0;
    }
    [DISPOSE]() { this.dispose(); }
  }

  function frameName(v, fn, what) {
    if (typeof v !== 'string') throw new TypeError(`${fn}: ${what} must be a string, got ${describe(v)}`);
    if (v.length === 0) throw new RangeError(`${fn}: ${what} must not be empty`);
    return v;
  }
  function vector(v, fn, what, n) {
    const a = toF64(v, fn, what);
    if (a.length !== n) throw new RangeError(`${fn}: ${what} must have ${n} numbers, got ${a.length}`);
    for (let i = 0; i < n; i++) if (!Number.isFinite(a[i])) throw new RangeError(`${fn}: ${what}[${i}] must be finite, got ${a[i]}`);
    return a;
  }

  // A transformation {angle, translation} (2D) or {quaternion | angle + axis, translation} (3D) -> [q0..q3, t0..t2]
  // with a unit quaternion [w, x, y, z] in 3D.
  function rigid(tf, fn, dim) {
    if (tf === null || typeof tf !== 'object' || Array.isArray(tf) || ArrayBuffer.isView(tf))
      throw new TypeError(`${fn}: the transformation must be an object, got ${describe(tf)}`);
    const known = dim === 2 ? ['angle', 'translation'] : ['quaternion', 'angle', 'axis', 'translation'];
    const o = options(tf, fn, known);
    const t = o.translation === undefined ? new Float64Array(dim) : vector(o.translation, fn, 'translation', dim);
    if (dim === 2) return [num(o, 'angle', fn, 0), 0, 0, 0, t[0], t[1], 0];
    let q;
    if (o.quaternion !== undefined) {
      if (o.angle !== undefined || o.axis !== undefined) throw new TypeError(`${fn}: give either quaternion or angle + axis, not both`);
      q = Array.from(vector(o.quaternion, fn, 'quaternion', 4));
    } else if (o.angle !== undefined || o.axis !== undefined) {
      const angle = num(o, 'angle', fn, 0);
      if (o.axis === undefined) throw new TypeError(`${fn}: angle needs an axis in 3D`);
      const axis = vector(o.axis, fn, 'axis', 3);
      const len = Math.hypot(axis[0], axis[1], axis[2]);
      if (!(len > 0)) throw new RangeError(`${fn}: axis must not be the zero vector`);
      const s = Math.sin(angle / 2) / len;
      q = [Math.cos(angle / 2), axis[0] * s, axis[1] * s, axis[2] * s];
    } else {
      q = [1, 0, 0, 0];
    }
    const qn = Math.hypot(...q);
    if (!(qn > 0)) throw new RangeError(`${fn}: quaternion must not be zero`);
    return [q[0] / qn, q[1] / qn, q[2] / qn, q[3] / qn, t[0], t[1], t[2]];
  }

  class TfTree {
    #h = 0;
    #dim;
    constructor(root, opts) {
      const fn = 'TfTree';
      frameName(root, fn, 'root');
      const o = options(opts, fn, ['dim']);
      this.#dim = dimOption(o, fn);
      const h = check(m.tfCreate(this.#dim, root), fn);
      this.#h = h;
      registry?.register(this, () => m.tfDestroy(h), this);
    }
    #handle(fn) {
      if (this.#h === 0) throw new TypeError(`TfTree.${fn}: the tree was disposed`);
      return this.#h;
    }
    get dim() { return this.#dim; }
    get disposed() { return this.#h === 0; }
    get size() { return m.tfSize(this.#handle('size')); }
    insert(name, parent, tf) {
      const fn = 'TfTree.insert';
      const h = this.#handle('insert');
      frameName(name, fn, 'name');
      frameName(parent, fn, 'parent');
      return check(m.tfInsert(h, name, parent, ...rigid(tf, fn, this.#dim)), fn);
    }
    erase(name) { return m.tfErase(this.#handle('erase'), frameName(name, 'TfTree.erase', 'name')); }
    contains(name) { return m.tfContains(this.#handle('contains'), frameName(name, 'TfTree.contains', 'name')); }
    tf(from, to) {
      const fn = 'TfTree.tf';
      const h = this.#handle('tf');
      return check(m.tfGet(h, frameName(from, fn, 'from'), frameName(to, fn, 'to')), fn);
    }
    transformPoints(from, to, points) {
      const fn = 'TfTree.transformPoints';
      const h = this.#handle('transformPoints');
      frameName(from, fn, 'from');
      frameName(to, fn, 'to');
      const xyz = toF64(points, fn, 'points');
      return withHeap(fn, [xyz], (p, n) => m.tfApply(h, from, to, p, n, this.#dim));
    }
    dispose() {
      if (this.#h === 0) return;
      registry?.unregister(this);
      m.tfDestroy(this.#h);
      this.#h = 0;
    }
    [DISPOSE]() { this.dispose(); }
  }

  // CARMEN logs: every FLASER line is a scan; beams without a return (range <= 0, non-finite or >= maxRange) are NaN
  // points; maxRange is the log's own no-return value unless given. Text as a string (UTF-8 encoded here) or bytes.
  function readCarmenLog(text, opts) {
    const fn = 'readCarmenLog';
    let u8;
    if (typeof text === 'string') u8 = new TextEncoder().encode(text);
    else if (text instanceof ArrayBuffer) u8 = new Uint8Array(text);
    else if (ArrayBuffer.isView(text)) u8 = new Uint8Array(text.buffer, text.byteOffset, text.byteLength);
    else throw new TypeError(`${fn}: text must be a string, an ArrayBuffer or a typed array of the file, got ${describe(text)}`);
    const o = options(opts, fn, ['maxRange']);
    // Default: detected from the log (NaN to the C++ reader); Infinity keeps every finite positive range.
    const maxRange = o.maxRange === Infinity ? Infinity : num(o, 'maxRange', fn, NaN, { min: 0, exclusiveMin: true });
    const r = withHeap(fn, [u8], (p, n) => m.readCarmenLog(p, n, maxRange));
    const scans = [];
    for (let k = 0; k + 1 < r.offsets.length; k++) {
      const b = r.offsets[k], e = r.offsets[k + 1];
      scans.push({
        points: r.points.slice(2 * b, 2 * e), ranges: r.ranges.slice(b, e),
        x: r.x[k], y: r.y[k], theta: r.theta[k], timestamp: r.timestamp[k], line: r.line[k],
        maxRange: r.maxRange, maxRangeSource: r.maxRangeSource,
      });
    }
    return scans;
  }

  // Organised LiDAR: 16-byte little-endian float32 records x, y, z, intensity; (0,0,0) = no return (NaN point).
  // The cloud is stored column-major whatever the file layout: beam b of column c is point c * beams + b.
  function readOrganizedLidar(data, opts) {
    const fn = 'readOrganizedLidar';
    let u8;
    if (data instanceof ArrayBuffer) u8 = new Uint8Array(data);
    else if (ArrayBuffer.isView(data)) u8 = new Uint8Array(data.buffer, data.byteOffset, data.byteLength);
    else throw new TypeError(`${fn}: data must be an ArrayBuffer or a typed array / DataView / Buffer, got ${describe(data)}`);
    if (opts === undefined) throw new TypeError(`${fn}: options {beams} are required`);
    const o = options(opts, fn, ['beams', 'layout']);
    if (o.beams === undefined) throw new TypeError(`${fn}: option beams is required`);
    const beams = num(o, 'beams', fn, 0, { min: 1, integer: true, max: 1 << 20 });
    const layout = o.layout ?? 'column-major';
    if (typeof layout !== 'string') throw new TypeError(`${fn}: option layout must be a string, got ${describe(layout)}`);
    if (layout !== 'column-major' && layout !== 'row-major')
      throw new RangeError(`${fn}: option layout must be 'column-major' or 'row-major', got '${layout}'`);
    const r = withHeap(fn, [u8], (p, n) => m.readOrganizedLidar(p, n, beams, layout === 'row-major' ? 1 : 0));
    const { columns, points } = r;
    return {
      beams, columns, points, intensity: r.intensity,
      ring(b) {
        if (typeof b !== 'number') throw new TypeError(`ring: beam must be a number, got ${describe(b)}`);
        if (!Number.isInteger(b) || b < 0 || b >= beams) throw new RangeError(`ring: beam must be an integer in [0, ${beams - 1}], got ${b}`);
        const out = new Float64Array(3 * columns);
        for (let c = 0; c < columns; c++) out.set(points.subarray(3 * (c * beams + b), 3 * (c * beams + b) + 3), 3 * c);
        return out;
      },
      column(c) {
        if (typeof c !== 'number') throw new TypeError(`column: c must be a number, got ${describe(c)}`);
        if (!Number.isInteger(c) || c < 0 || c >= columns) throw new RangeError(`column: c must be an integer in [0, ${columns - 1}], got ${c}`);
        return points.slice(3 * c * beams, 3 * (c + 1) * beams);
      },
    };
  }

  const simplifier = makeSimplify(m, withInputOf, (ms) => { lastComputeMs = ms; }, takeResults);
  const release = () => { m.releaseBuffers(); m.viewBlock(-1); viewAt = 0; };
  const api = {
    version: VERSION,
    fitLine,
    segment,
    vectorize,
    StreamSegmenter,
    TfTree,
    ...drawingApi(m, withHeap),
    ...algorithmsApi(m, withHeap, registry),
    readCarmenLog,
    readCarmen: readCarmenLog,
    readOrganizedLidar,
    simplify: simplifier.simplify,
    // Frees the input buffer, vectorizers and segmenters kept between calls (they grow back on the next call).
    // Also pointBuffer()'s block: its views must not be used afterwards.
    releaseBuffers: release,
    // Malloc heap in use once the kept buffers are released: equal figures before and after calls mean no leak.
    heapInUse: () => { release(); return m.heapInUse(); },
    pointBuffer,
    memoryBytes: () => m.memoryBytes(),
    stackPointer: () => m.stackPointer(),
  };
  Object.defineProperty(api, 'lastComputeMs', { get: () => lastComputeMs, enumerable: false });
  return api;
}

// Checks init()'s options and returns the ones handed to the Emscripten factory.
function initOptions(o) {
  if (o === undefined || o === null) return {};
  if (typeof o !== 'object' || Array.isArray(o)) throw new TypeError(`init: options must be an object, got ${describe(o)}`);
  const out = {};
  for (const k of Object.keys(o)) {
    if (k === 'wasmBinary') {
      const b = o.wasmBinary;
      if (!(b instanceof ArrayBuffer || b instanceof Uint8Array))
        throw new TypeError(`init: wasmBinary must be an ArrayBuffer or a Uint8Array, got ${describe(b)}`);
      out.wasmBinary = b;
    } else if (k === 'locateFile') {
      if (typeof o.locateFile !== 'function') throw new TypeError(`init: locateFile must be a function, got ${describe(o.locateFile)}`);
      out.locateFile = o.locateFile;
    } else {
      throw new TypeError(`init: unknown option "${k}" (known: wasmBinary, locateFile)`);
    }
  }
  return out;
}

// Starts the Emscripten module and wraps it, the same way for the three entries (Node ESM, CommonJS, browsers).
// The module gets its own print/printErr/onAbort, so that a failed start prints nothing (Emscripten would print
// "Aborted(...)" to stderr) and becomes the package's TypeError; after a successful start they forward to the console.
async function start(createModule, options, loadDefaultBinary) {
  const o = initOptions(options);
  if (o.wasmBinary !== undefined) {
    const bytes = o.wasmBinary instanceof ArrayBuffer ? new Uint8Array(o.wasmBinary) : o.wasmBinary;
    if (!WebAssembly.validate(bytes)) throw new TypeError(`init: wasmBinary is not a valid WebAssembly module (${bytes.length} bytes)`);
  } else if (loadDefaultBinary) {
    o.wasmBinary = await loadDefaultBinary();
  }
  let started = false, reason = null;
  const say = (log) => (...a) => { if (started) log(...a); else reason ??= a.join(' '); };
  o.print = say((...a) => console.log(...a));
  o.printErr = say((...a) => console.error(...a));
  o.onAbort = (what) => { if (!started) reason ??= String(what); };
  let module;
  try {
    module = await createModule(o);
    if (typeof module.fitLine !== 'function') throw new Error('the module has no rtl-wasm bindings');
  } catch (e) {
    throw new TypeError(`init: the WebAssembly module could not be started: ${reason ?? (e && e.message) ?? e}`);
  }
  started = true;
  return wrap(module);
}

export { start };
