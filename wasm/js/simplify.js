// simplify(): a drop-in for simplify-js's simplify(points, tolerance, highQuality). The algorithm is the C++
// core's (rtl/vect/SimplifyCompatible.h: simplify-js's radial pre-pass unless highQuality, then its
// segment-distance Douglas-Peucker), so the kept points are the ones simplify-js keeps; this file only moves the
// numbers. wasm/build.mjs puts it in front of api.js (same scope: describe, options, isNumericView, toF64 and check
// come from there), so no imports or exports here.

// withInputOf(fn, len, fill, f): api.js's writer into the module's kept input buffer; setComputeMs records the
// library's own time of the call (lastComputeMs).
function makeSimplify(m, withInputOf, setComputeMs) {
  const fn = 'simplify';

  function kept(len, dim, fill, tolerance, highQuality) {
    const r = withInputOf(fn, len, fill, (p, n) => m.simplify(p, n, dim, tolerance, highQuality));
    setComputeMs(r.computeMs);
    return r.kept;
  }

  // Objects {x, y} (or {x, y, z} with dim 3) go straight into wasm memory, x and y of each point in one loop.
  function fillObjects(points, dim) {
    return (heap, at) => {
      for (let i = 0; i < points.length; i++) {
        const q = points[i];
        if (q === null || typeof q !== 'object') throw new TypeError(`${fn}: points[${i}] is ${describe(q)}, expected an object {x, y${dim === 3 ? ', z' : ''}}`);
        const x = q.x, y = q.y;
        if (typeof x !== 'number' || typeof y !== 'number') throw new TypeError(`${fn}: points[${i}].x and .y must be numbers, got ${describe(typeof x !== 'number' ? x : y)}`);
        heap[at++] = x;
        heap[at++] = y;
        if (dim === 3) {
          const z = q.z;
          if (typeof z !== 'number') throw new TypeError(`${fn}: points[${i}].z must be a number (dim 3), got ${describe(z)}`);
          heap[at++] = z;
        }
      }
    };
  }

  return function simplify(points, tolerance, highQuality, opts) {
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
      const idx = kept(xyz.length, dim, (heap, at) => heap.set(xyz, at), t, hq);
      const out = new Float64Array(dim * idx.length);
      for (let k = 0; k < idx.length; k++) for (let c = 0; c < dim; c++) out[dim * k + c] = xyz[dim * idx[k] + c];
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
  };
}
