// simplify(): a drop-in for simplify-js's simplify(points, tolerance, highQuality). The algorithm is the C++
// core's (rtl/vect/SimplifyCompatible.h: simplify-js's radial pre-pass unless highQuality, then its
// segment-distance Douglas-Peucker), so the kept points are the ones simplify-js keeps; this layer only reads the
// {x, y} objects into wasm memory and picks the kept ones out.
import { describe, isNumericView, options, toF64 } from './checks.js';

/**
 * simplify() of one module instance: ctx = {m, withInputOf, setComputeMs, boundary} (api.js; withInputOf writes
 * into the module's kept input buffer, setComputeMs records the library's own time of the call, boundary gives
 * the call's options and results by name).
 */
export function simplifyApi({ m, withInputOf, setComputeMs, boundary }) {
  const fn = 'simplify';
  // The options and results of m.simplify by name, as wasm/src/simplify.cpp declares them (schema.js).
  const call = boundary.call('simplify');

  function kept(len, dim, fill, tolerance, highQuality, src) {
    const r = call.readResults(withInputOf(fn, len, fill, (p) => m.simplify(p, len, call.writeOptions({ dim, tolerance, highQuality })), src));
    setComputeMs(r.scalars.computeMs);
    return r.arrays.kept;
  }

  const pointError = (q, i, dim) => (q === null || typeof q !== 'object'
    ? new TypeError(`${fn}: points[${i}] is ${describe(q)}, expected an object {x, y${dim === 3 ? ', z' : ''}}`)
    : typeof q.x !== 'number' || typeof q.y !== 'number'
      ? new TypeError(`${fn}: points[${i}].x and .y must be numbers, got ${describe(typeof q.x !== 'number' ? q.x : q.y)}`)
      : new TypeError(`${fn}: points[${i}].z must be a number (dim 3), got ${describe(q.z)}`));

  // Objects {x, y} (or {x, y, z} with dim 3) go straight into wasm memory, x and y of each point in one loop; the
  // core does the rest, radial pre-pass included. (simplify-js's pre-pass appends the last point unless it is the
  // same object as the last kept one; the core compares indices, which can append a copy of the last kept point,
  // and that changes no other decision: the same objects come out.)
  // The loop tests only the numbers: reading .x of null or undefined throws, and the catch names the point. A test
  // `q === null || typeof q !== 'object'` per point made the copy ~1.4x slower (100k points: ~0.29 -> ~0.20 ms
  // without it, Node 20); a primitive has no numeric .x, so it fails the number test (a function with numeric x
  // and y passes, as in simplify-js: ruling it out per point cost ~0.08 ms more). One function per dim, taking
  // everything as parameters: the loop inside fill's closure, reading points from its context, took ~10 % longer.
  function rethrow(points, i, dim, e) {
    const q = points[i];
    if (q === null || typeof q !== 'object') throw pointError(q, i, dim);  // null, undefined or a primitive
    throw e;  // ours, or thrown by a getter of the caller's
  }
  function copyXY(points, heap, at) {
    let i = 0;
    try {
      for (; i < points.length; i++) {
        const q = points[i];
        const x = q.x, y = q.y;
        if (typeof x !== 'number' || typeof y !== 'number') throw pointError(q, i, 2);
        heap[at++] = x;
        heap[at++] = y;
      }
    } catch (e) {
      rethrow(points, i, 2, e);
    }
  }
  function copyXYZ(points, heap, at) {
    let i = 0;
    try {
      for (; i < points.length; i++) {
        const q = points[i];
        const x = q.x, y = q.y, z = q.z;
        if (typeof x !== 'number' || typeof y !== 'number' || typeof z !== 'number') throw pointError(q, i, 3);
        heap[at++] = x;
        heap[at++] = y;
        heap[at++] = z;
      }
    } catch (e) {
      rethrow(points, i, 3, e);
    }
  }
  const fillObjects = (points, dim) => (dim === 2 ? (heap, at) => copyXY(points, heap, at) : (heap, at) => copyXYZ(points, heap, at));

  /**
   * @template {import('./index.js').SimplifyPoint} P
   * @overload
   * @param {P[]} points
   * @param {number} [tolerance]
   * @param {boolean} [highQuality]
   * @param {{ dim?: import('./index.js').Dim }} [opts]
   * @returns {P[]}
   */
  /**
   * @overload
   * @param {Float64Array | Float32Array} points
   * @param {number} [tolerance]
   * @param {boolean} [highQuality]
   * @param {{ dim?: import('./index.js').Dim }} [opts]
   * @returns {Float64Array}
   */
  /**
   * @param {import('./index.js').SimplifyPoint[] | Float64Array | Float32Array} points
   * @param {number} [tolerance]
   * @param {boolean} [highQuality]
   * @param {{ dim?: import('./index.js').Dim }} [opts]
   * @returns {import('./index.js').SimplifyPoint[] | Float64Array}
   */
  function simplify(points, tolerance, highQuality, opts) {
    const t = tolerance === undefined ? 1 : tolerance;  // simplify-js's default
    if (typeof t !== 'number') throw new TypeError(`${fn}: tolerance must be a number, got ${describe(t)}`);
    if (!(t >= 0)) throw new RangeError(`${fn}: tolerance must be >= 0 (or Infinity), got ${t}`);
    const hq = highQuality === undefined ? false : highQuality;
    if (typeof hq !== 'boolean') throw new TypeError(`${fn}: highQuality must be a boolean, got ${describe(hq)}`);
    const o = options(opts, fn, ['dim']);
    if (o.dim !== undefined && typeof o.dim !== 'number') throw new TypeError(`${fn}: option dim must be a number, got ${describe(o.dim)}`);
    if (o.dim !== undefined && o.dim !== 2 && o.dim !== 3) throw new RangeError(`${fn}: option dim must be 2 or 3, got ${o.dim}`);

    if (isNumericView(points)) {
      // Typed-array form: interleaved coordinates in, the kept points' coordinates out (Float64Array).
      const dim = o.dim ?? 2;
      const xyz = toF64(points, fn, 'points');
      if (xyz.length % dim) throw new RangeError(`${fn}: points has ${xyz.length} numbers, not a multiple of dim ${dim} (interleaved coordinates expected)`);
      const len = xyz.length, off = xyz.byteOffset;
      const idx = kept(len, dim, (heap, at) => heap.set(xyz, at), t, hq, xyz);
      // A pointBuffer() view detached by memory growth during the call: read its numbers through a new view.
      const src = xyz.length === len ? xyz : new Float64Array(m.HEAPF64.buffer, off, len);
      const out = new Float64Array(dim * idx.length);
      for (let k = 0; k < idx.length; k++) for (let c = 0; c < dim; c++) out[dim * k + c] = src[dim * idx[k] + c];
      return out;
    }
    if (!Array.isArray(points)) throw new TypeError(`${fn}: points must be an array of {x, y} objects or a typed array of interleaved coordinates, got ${describe(points)}`);
    // dim 3 when asked for, or when the first point has a numeric z (simplify-js's 3D variant); every point must then have one.
    const first = points[0];
    const dim = o.dim ?? (first !== null && typeof first === 'object' && typeof first.z === 'number' ? 3 : 2);
    const idx = kept(dim * points.length, dim, fillObjects(points, dim), t, hq);
    if (points.length <= 2) return points;  // checked all the same; simplify-js returns such arrays as they are
    const out = new Array(idx.length);
    for (let k = 0; k < idx.length; k++) out[k] = points[idx[k]];  // the caller's own objects, as simplify-js returns
    return out;
  }
  return { simplify };
}
