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

const ERRORS = { TypeError, RangeError, Error };

// The C++ side returns {error, kind} instead of throwing (an exception crossing into JS leaks the wasm stack).
function check(r) {
  if (r !== null && typeof r === 'object' && typeof r.error === 'string') throw new (ERRORS[r.kind] || Error)(r.error);
  return r;
}

// ------------------------------------------------------------------------------------------------ the module
function wrap(m) {
  // Copies `arrays` (Float64Array) into the wasm heap, calls f(ptr0, len0, ptr1, len1, ...), frees them again.
  // HEAPF64 is read after every _malloc: memory growth replaces the buffer and detaches older views.
  function withHeap(arrays, f) {
    const ptrs = [];
    try {
      for (const a of arrays) {
        const p = m._malloc(Math.max(8, a.length * 8));
        if (!p) throw new RangeError(`out of wasm memory allocating ${a.length * 8} bytes`);
        ptrs.push(p);
      }
      const args = [];
      arrays.forEach((a, i) => { m.HEAPF64.set(a, ptrs[i] / 8); args.push(ptrs[i], a.length); });
      return check(f(...args));
    } finally {
      for (const p of ptrs) m._free(p);
    }
  }

  function fitLine(points, opts) {
    const fn = 'fitLine';
    const o = options(opts, fn, ['dim']);
    const dim = dimOption(o, fn);
    const xy = toF64(points, fn, 'points');
    return withHeap([xy], (p, n) => m.fitLine(p, n, dim));
  }

  return {
    version: VERSION,
    fitLine,
    heapInUse: () => m.heapInUse(),
    memoryBytes: () => m.memoryBytes(),
    stackPointer: () => m.stackPointer(),
  };
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

export { wrap, initOptions };
