// simplify(): a drop-in for simplify-js's simplify(points, tolerance, highQuality). The algorithm is the C++
// core's (rtl/vect/SimplifyCompatible.h: simplify-js's radial pre-pass unless highQuality, then its
// segment-distance Douglas-Peucker), so the kept points are the ones simplify-js keeps; for {x, y} objects the
// radial pre-pass runs here, inside the one loop that reads the objects (see fillRadial), the rest only moves
// numbers. wasm/build.mjs puts it in front of api.js (same scope: describe, options, isNumericView, toF64 and check
// come from there), so no imports or exports here.

// withInputOf(fn, len, fill, f): api.js's writer into the module's kept input buffer; setComputeMs records the
// library's own time of the call (lastComputeMs); takeResults copies a binding's ResultBlock out (api.js).
function makeSimplify(m, withInputOf, setComputeMs, takeResults) {
  const fn = 'simplify';

  function kept(len, dim, fill, tolerance, highQuality, src) {
    let written = len;
    const r = takeResults(withInputOf(fn, len, (heap, at) => { written = fill(heap, at) ?? len; },
      (p) => m.simplify(p, written, dim, tolerance, highQuality), src), [Uint32Array]);
    setComputeMs(r.scalars[0]);
    return r.arrays[0];
  }

  const nonFinite = (v) => (Number.isNaN(v) ? 'NaN' : v > 0 ? 'Infinity' : '-Infinity');
  // The C++ check's message for the first non-finite coordinate (thrown after the loop, so that a wrong type
  // further on still wins, as when the core checked the numbers after the copy).
  function finiteError(points, i, dim) {
    const q = points[i], c = [q.x, q.y, q.z].findIndex((v, k) => k < dim && !Number.isFinite(v));
    return new RangeError(`${fn}: point ${i} has a non-finite coordinate (${nonFinite([q.x, q.y, q.z][c])}) at index ${dim * i + c}`);
  }
  const pointError = (q, i, dim) => (q === null || typeof q !== 'object'
    ? new TypeError(`${fn}: points[${i}] is ${describe(q)}, expected an object {x, y${dim === 3 ? ', z' : ''}}`)
    : typeof q.x !== 'number' || typeof q.y !== 'number'
      ? new TypeError(`${fn}: points[${i}].x and .y must be numbers, got ${describe(typeof q.x !== 'number' ? q.x : q.y)}`)
      : new TypeError(`${fn}: points[${i}].z must be a number (dim 3), got ${describe(q.z)}`));

  // Objects {x, y} (or {x, y, z} with dim 3) go straight into wasm memory, x and y of each point in one loop.
  function fillObjects(points, dim) {
    return (heap, at) => {
      for (let i = 0; i < points.length; i++) {
        const q = points[i];
        if (q === null || typeof q !== 'object') throw pointError(q, i, dim);
        const x = q.x, y = q.y;
        if (typeof x !== 'number' || typeof y !== 'number') throw pointError(q, i, dim);
        heap[at++] = x;
        heap[at++] = y;
        if (dim === 3) {
          const z = q.z;
          if (typeof z !== 'number') throw pointError(q, i, dim);
          heap[at++] = z;
        }
      }
    };
  }

  // simplify-js's radial pre-pass fused into the reading loop: the point objects are read once (the floor of any
  // {x, y} input) and only the points the pass keeps reach wasm memory, where the core's Douglas-Peucker runs on
  // them (highQuality there). The arithmetic is simplify-js's own (JavaScript doubles, its order, the same object
  // comparison for the last point), so the kept points are the ones it keeps. `from` receives the points' indices;
  // returns the count of numbers written.
  function fillRadial(points, dim, sqTolerance, from) {
    return dim === 3 ? radial3(points, sqTolerance, from) : radial2(points, sqTolerance, from);
  }
  function radial2(points, sqTolerance, from) {
    return (heap, at) => {
      const n = points.length, at0 = at;
      let q = points[0];
      if (q === null || typeof q !== 'object') throw pointError(q, 0, 2);
      let px = q.x, py = q.y, prev = q, bad = -1, k = 1;
      if (typeof px !== 'number' || typeof py !== 'number') throw pointError(q, 0, 2);
      if (px - px !== 0 || py - py !== 0) bad = 0;  // x - x is NaN for NaN and +-Infinity
      heap[at++] = px;
      heap[at++] = py;
      from[0] = 0;
      for (let i = 1; i < n; i++) {
        q = points[i];
        if (q === null || typeof q !== 'object') throw pointError(q, i, 2);
        const x = q.x, y = q.y;
        if (typeof x !== 'number' || typeof y !== 'number') throw pointError(q, i, 2);
        if (x - x !== 0 || y - y !== 0) { if (bad < 0) bad = i; continue; }
        const dx = x - px, dy = y - py;
        if (dx * dx + dy * dy > sqTolerance) {
          heap[at++] = x;
          heap[at++] = y;
          from[k++] = i;
          prev = q; px = x; py = y;
        }
      }
      if (bad >= 0) throw finiteError(points, bad, 2);
      if (prev !== q) {  // simplify-js appends the last point unless it is the last one kept (the same object)
        heap[at++] = q.x;
        heap[at++] = q.y;
        from[k] = n - 1;
      }
      return at - at0;
    };
  }
  function radial3(points, sqTolerance, from) {
    return (heap, at) => {
      const n = points.length, at0 = at;
      let prev = null, q = null, px = 0, py = 0, pz = 0, bad = -1, k = 0;
      for (let i = 0; i < n; i++) {
        q = points[i];
        if (q === null || typeof q !== 'object') throw pointError(q, i, 3);
        const x = q.x, y = q.y, z = q.z;
        if (typeof x !== 'number' || typeof y !== 'number' || typeof z !== 'number') throw pointError(q, i, 3);
        if (x - x !== 0 || y - y !== 0 || z - z !== 0) { if (bad < 0) bad = i; continue; }
        const dx = x - px, dy = y - py, dz = z - pz;
        if (i === 0 || dx * dx + dy * dy + dz * dz > sqTolerance) {
          heap[at++] = x;
          heap[at++] = y;
          heap[at++] = z;
          from[k++] = i;
          prev = q; px = x; py = y; pz = z;
        }
      }
      if (bad >= 0) throw finiteError(points, bad, 3);
      if (prev !== q) {
        heap[at++] = q.x;
        heap[at++] = q.y;
        heap[at++] = q.z;
        from[k] = n - 1;
      }
      return at - at0;
    };
  }
  // The kept points' indices; grown as needed and kept between calls like the module's buffers (kept.h), dropped
  // after an input above KEPT_POINTS points and by releaseBuffers().
  const KEPT_POINTS = 2 ** 21;
  let from = new Int32Array(0);
  const release = () => { from = new Int32Array(0); };

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
    if (hq || points.length <= 2) {
      const idx = kept(dim * points.length, dim, fillObjects(points, dim), t, true);
      if (points.length <= 2) return points;  // checked all the same; simplify-js returns such arrays as they are
      const out = new Array(idx.length);
      for (let k = 0; k < idx.length; k++) out[k] = points[idx[k]];  // the caller's own objects, as simplify-js returns
      return out;
    }
    if (from.length < points.length) from = new Int32Array(Math.max(points.length, Math.min(2 * from.length, KEPT_POINTS)));
    const idx = kept(dim * points.length, dim, fillRadial(points, dim, t * t, from), t, true);
    // One point kept (every point the same object as the first): simplify-js's Douglas-Peucker returns it twice.
    if (idx.length === 1) return [points[0], points[0]];
    const out = new Array(idx.length);
    for (let k = 0; k < idx.length; k++) out[k] = points[from[idx[k]]];
    if (points.length > KEPT_POINTS) release();
    return out;
  }
  return { simplify, release };
}
