// Argument checks shared by every function of the package: TypeError for a wrong kind of value, RangeError for a
// bad value, both with a message that starts with the name of the function the caller called. Also the one place
// that turns the C++ side's error results into exceptions (check).

/** The limit of wasm memory (-sMAXIMUM_MEMORY of wasm/CMakeLists.txt), in bytes. */
export const MAX_MEMORY = 2 ** 31;

/** The method name `using` looks for: Symbol.dispose where the engine has it, else the well-known registry key. */
/** @type {typeof Symbol.dispose} */
export const DISPOSE = /** @type {any} */ (Symbol.dispose ?? Symbol.for('Symbol.dispose'));

/** A short description of any value for an error message ("an Array", "the number 3", ...). */
export function describe(v) {
  if (v === null) return 'null';
  if (Array.isArray(v)) return 'an Array';
  if (ArrayBuffer.isView(v)) return `a ${v.constructor.name}`;
  if (typeof v === 'object') return `an object (${Object.prototype.toString.call(v).slice(8, -1)})`;
  if (typeof v === 'string') return `a string ("${v.length > 20 ? v.slice(0, 20) + '...' : v}")`;
  if (typeof v === 'number') return `the number ${v}`;
  return `${typeof v === 'undefined' ? '' : 'a '}${typeof v}`;
}

/** Whether v is a typed array of numbers (not a DataView, not a BigInt array). */
export function isNumericView(v) {
  return ArrayBuffer.isView(v) && !(v instanceof DataView) &&
    !(typeof BigInt64Array !== 'undefined' && (v instanceof BigInt64Array || v instanceof BigUint64Array));
}

/**
 * Points (or any number list) as a Float64Array: Float64Array as is, other numeric typed arrays and plain arrays
 * (of numbers only) converted. Values are checked by the C++ side (NaN/Infinity rules depend on the function).
 * @returns {Float64Array}
 */
export function toF64(v, fn, name) {
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

/**
 * A file's bytes as a Uint8Array over the same memory: an ArrayBuffer, or any ArrayBuffer view (typed array,
 * DataView, Buffer); else a TypeError `${fn}: ${expected}, got ...`.
 * @returns {Uint8Array}
 */
export function bytesArgument(v, fn, expected) {
  if (v instanceof ArrayBuffer) return new Uint8Array(v);
  if (ArrayBuffer.isView(v)) return new Uint8Array(v.buffer, v.byteOffset, v.byteLength);
  throw new TypeError(`${fn}: ${expected}, got ${describe(v)}`);
}

/** The options object of a call ({} when not given); an unknown key is a TypeError. */
export function options(o, fn, known) {
  if (o === undefined || o === null) return {};
  if (typeof o !== 'object' || Array.isArray(o)) throw new TypeError(`${fn}: options must be an object, got ${describe(o)}`);
  for (const k of Object.keys(o)) {
    if (!known.includes(k)) throw new TypeError(`${fn}: unknown option "${k}" (known: ${known.join(', ')})`);
  }
  return o;
}

/** Numeric option `key` of o (def when not given), finite and within the given limits. */
export function num(o, key, fn, def, { min = -Infinity, max = Infinity, integer = false, exclusiveMin = false } = {}) {
  const v = o[key];
  if (v === undefined) return def;
  if (typeof v !== 'number') throw new TypeError(`${fn}: option ${key} must be a number, got ${describe(v)}`);
  if (!Number.isFinite(v)) throw new RangeError(`${fn}: option ${key} must be finite, got ${v}`);
  if (integer && !Number.isInteger(v)) throw new RangeError(`${fn}: option ${key} must be an integer, got ${v}`);
  if (exclusiveMin ? !(v > min) : v < min) throw new RangeError(`${fn}: option ${key} must be ${exclusiveMin ? '>' : '>='} ${min}, got ${v}`);
  if (v > max) throw new RangeError(`${fn}: option ${key} must be <= ${max}, got ${v}`);
  return v;
}

/**
 * Option dim: 2 when not given, else one of `allowed`.
 * @returns {import('./index.js').Dim}
 */
export function dimOption(o, fn, allowed = [2, 3]) {
  const d = o.dim;
  if (d === undefined) return 2;
  if (typeof d !== 'number') throw new TypeError(`${fn}: option dim must be a number, got ${describe(d)}`);
  if (!allowed.includes(d)) throw new RangeError(`${fn}: option dim must be ${allowed.join(' or ')}, got ${d}`);
  return /** @type {import('./index.js').Dim} */ (d);
}

/** Option origin: dim finite numbers, as [x, y, z] (z 0 in 2D); the coordinate origin when not given. */
export function originOption(o, fn, dim) {
  if (o.origin === undefined) return [0, 0, 0];
  const a = toF64(o.origin, fn, 'option origin');
  if (a.length !== dim) throw new RangeError(`${fn}: option origin must have ${dim} numbers (dim ${dim}), got ${a.length}`);
  for (let i = 0; i < dim; i++) if (!Number.isFinite(a[i])) throw new RangeError(`${fn}: option origin[${i}] must be finite, got ${a[i]}`);
  return [a[0], a[1], dim === 3 ? a[2] : 0];
}

/** Boolean option `key` of o (def when not given). */
export function boolOption(o, key, fn, def) {
  const v = o[key];
  if (v === undefined) return def;
  if (typeof v !== 'boolean') throw new TypeError(`${fn}: option ${key} must be a boolean, got ${describe(v)}`);
  return v;
}

/** Proximity bounds of the segmenters: 0 <= lowerBound <= upperBound (upperBound may be Infinity). */
export function boundsOptions(o, fn, lowerDefault, upperDefault) {
  const lower = num(o, 'lowerBound', fn, lowerDefault, { min: 0 });
  let upper = upperDefault;
  if (o.upperBound === Infinity) upper = Infinity;
  else upper = num(o, 'upperBound', fn, upperDefault, { min: 0 });
  if (!(upper >= lower)) throw new RangeError(`${fn}: option upperBound (${upper}) must be >= lowerBound (${lower})`);
  return [lower, upper];
}

/** A vector argument of exactly n finite numbers. */
export function vector(v, fn, what, n) {
  const a = toF64(v, fn, what);
  if (a.length !== n) throw new RangeError(`${fn}: ${what} must have ${n} numbers, got ${a.length}`);
  for (let i = 0; i < n; i++) if (!Number.isFinite(a[i])) throw new RangeError(`${fn}: ${what}[${i}] must be finite, got ${a[i]}`);
  return a;
}

const ERRORS = { TypeError, RangeError, Error };

/**
 * The C++ side returns {error, kind} instead of throwing (an exception crossing into JS leaks the wasm stack): this
 * throws it as that kind of error, its message starting with the name of the function the caller called (fn), and
 * returns every other result as it is.
 */
export function check(r, fn) {
  if (r !== null && typeof r === 'object' && typeof r.error === 'string') {
    const msg = r.error.startsWith(`${fn}:`) ? r.error : `${fn}: ${r.error}`;
    throw new (ERRORS[r.kind] || Error)(msg);
  }
  return r;
}
