// segmentAndVectorize(): segment() and vectorize() of every cluster of a scan in one call into the module
// (wasm/src/pipeline.cpp), for logs of many small scans, where a call per cluster cost more than the work.
import { boolOption, boundsOptions, describe, dimOption, num, options, originOption, toF64 } from './checks.js';
import { defaults } from './defaults.js';
import { partViews } from './views.js';
import { METHODS, corner, failureOf } from './vectorize.js';

/**
 * The result block's arrays (views on wasm memory) as copies: labels and indices (moved into the block, elsewhere in
 * memory) one each, the 15 others laid out back to back in the block in one copy, as views on it. 17 copies cost
 * ~8 us a scan (an ArrayBuffer each), a third of the call's JS time on a 360-beam scan.
 */
function copyOut(arrays) {
  const names = Object.keys(arrays), own = ['labels', 'indices'];
  let start = Infinity, end = 0;
  for (const k of names) {
    const a = arrays[k];
    if (own.includes(k) || a.length === 0) continue;   // an empty array's address may be anywhere (or 0)
    start = Math.min(start, a.byteOffset);
    end = Math.max(end, a.byteOffset + a.byteLength);
  }
  const copy = end > start ? new Uint8Array(arrays.labels.buffer, start, end - start).slice().buffer : new ArrayBuffer(0);
  /** @type {Record<string, any>} */
  const out = {};
  for (const k of names) {
    const a = arrays[k], Type = /** @type {any} */ (a.constructor);
    out[k] = own.includes(k) ? a.slice() : a.length === 0 ? new Type(0) : new Type(copy, a.byteOffset - start, a.length);
  }
  return out;
}

/** segmentAndVectorize() of one module instance: ctx = {m, withInput, boundary, setComputeMs} (api.js). */
export function pipelineApi({ m, withInput, boundary, setComputeMs }) {
  // The options and results of m.segmentAndVectorize by name, as wasm/src/pipeline.cpp declares them (schema.js).
  const call = boundary.call('segmentAndVectorize');
  /**
   * @param {import('./index.js').PointArray} points
   * @param {import('./index.js').SegmentAndVectorizeOptions} opts
   * @returns {import('./index.js').SegmentAndVectorizeResult}
   */
  function segmentAndVectorize(points, opts) {
    const fn = 'segmentAndVectorize';
    if (opts === undefined) throw new TypeError(`${fn}: options {vectorize: {method}} are required (method: ${METHODS.join(', ')})`);
    const o = options(opts, fn, ['dim', 'minPoints', 'segment', 'vectorize']);
    const dim = dimOption(o, fn);
    const minPoints = num(o, 'minPoints', fn, 3, { min: 2, integer: true, max: 2 ** 32 - 1 });
    const so = options(o.segment, fn, ['step', 'lowerBound', 'upperBound', 'origin']);
    const ds = defaults.segment;
    const step = num(so, 'step', fn, ds.step, { min: 1, integer: true, max: 2 ** 31 });
    const [lower, upper] = boundsOptions(so, fn, ds.lowerBound, ds.upperBound);
    const origin = originOption(so, fn, dim);
    if (o.vectorize === undefined) throw new TypeError(`${fn}: option vectorize {method} is required (method: ${METHODS.join(', ')})`);
    const vo = options(o.vectorize, fn, ['method', 'sigma', 'delta', 'epsilon', 'maxSize', 'simplexShift', 'maxIterations', 'split', 'distance']);
    if (vo.method === undefined) throw new TypeError(`${fn}: option method is required (${METHODS.join(', ')})`);
    if (typeof vo.method !== 'string') throw new TypeError(`${fn}: option method must be a string, got ${describe(vo.method)}`);
    const method = vo.method;
    if (!METHODS.includes(method)) throw new RangeError(`${fn}: option method must be one of ${METHODS.join(', ')}, got '${method}'`);
    const dv = defaults.vectorize;
    const sigma = num(vo, 'sigma', fn, dv.sigma, { min: 0, exclusiveMin: true });
    const delta = num(vo, 'delta', fn, dv.delta, { min: 0, exclusiveMin: true });
    const epsilon = num(vo, 'epsilon', fn, dv.epsilon, { min: 0, exclusiveMin: true });
    const maxSize = num(vo, 'maxSize', fn, dv.maxSize, { min: 0, integer: true, max: Math.floor(2 ** 31 / (8 * dim)) });
    const simplexShift = num(vo, 'simplexShift', fn, dv.simplexShift, { min: 1, integer: true, max: 2 ** 32 - 1 });
    const maxIterations = num(vo, 'maxIterations', fn, dv.maxIterations, { min: 1, integer: true, max: 2 ** 32 - 1 });
    const split = boolOption(vo, 'split', fn, dv.split);
    const distance = vo.distance ?? 'line';
    if (distance !== 'line' && distance !== 'segment') throw new RangeError(`${fn}: option distance must be 'line' or 'segment', got ${describe(distance)}`);
    const xyz = toF64(points, fn, 'points');
    const settings = { dim, step, lowerBound: lower, upperBound: upper, origin, minPoints, method: METHODS.indexOf(method),
      sigma, delta, epsilon, maxSize, simplexShift, maxIterations, split, segmentDistance: method === 'dp' && distance === 'segment' };
    // the arrays as views on the result block, then copied out at once (copyOut)
    const res = call.readResults(withInput(fn, xyz, (p, n) => m.segmentAndVectorize(p, n, call.writeOptions(settings))), true);
    setComputeMs(res.scalars.computeMs);
    const stride = res.scalars.stride;
    const { labels, indices, offsets, runs, runOffsets, vectorized, flags, failures: failureTriples, segmentOffsets, segments,
      segmentIndices, params, rms, polylineParts, polylineOffsets, breakOffsets, breaks } = copyOut(res.arrays);
    const parts = partViews(indices, offsets), ranges = partViews(runs, runOffsets), clusters = new Array(parts.length);
    for (let k = 0; k < parts.length; k++) clusters[k] = { indices: parts[k], ranges: ranges[k] };
    const ok = new Uint8Array(vectorized.length), failures = [];
    for (let j = 0; j < vectorized.length; j++) {
      ok[j] = flags[j] & 1;
      if (flags[j] & 2) failures.push({ vectorized: j, ...failureOf(failureTriples, 3 * j, parts[vectorized[j]].length, sigma, split) });
    }
    return {
      labels, clusters, method, dim, stride, vectorized, ok, segmentOffsets, segments, indices: segmentIndices, params, rms,
      polylineParts, polylineOffsets, breakOffsets, breaks, failures,
    };
  }

  /**
   * Vectorized cluster j of a segmentAndVectorize() result in vectorize()'s shape (views on the result's arrays):
   * for code written against vectorize()'s result, and to compare the two.
   * @param {import('./index.js').SegmentAndVectorizeResult} r
   * @param {number} j
   * @returns {import('./index.js').VectorizeResult}
   */
  function vectorizedCluster(r, j) {
    const fn = 'vectorizedCluster';
    if (r === null || typeof r !== 'object' || !(r.vectorized instanceof Uint32Array) || !(r.segmentOffsets instanceof Uint32Array))
      throw new TypeError(`${fn}: r must be a segmentAndVectorize() result, got ${describe(r)}`);
    if (typeof j !== 'number') throw new TypeError(`${fn}: j must be a number, got ${describe(j)}`);
    if (!Number.isInteger(j) || j < 0 || j >= r.vectorized.length)
      throw new RangeError(`${fn}: j must be an integer in [0, ${r.vectorized.length}), got ${j}`);
    const b = r.segmentOffsets[j], e = r.segmentOffsets[j + 1], w = 2 * r.dim;
    const bk = [];
    for (let k = r.breakOffsets[j]; k < r.breakOffsets[j + 1]; k++) bk.push(corner(r.breaks, 3 * k));
    const f = r.failures.find((x) => x.vectorized === j);
    let failure = null;
    if (f) { const { vectorized, ...rest } = f; void vectorized; failure = rest; }
    return {
      method: r.method, dim: r.dim, primitive: 'line', ok: r.ok[j] === 1, count: e - b,
      segments: r.segments.subarray(b * w, e * w), polygons: [], indices: r.indices.subarray(2 * b, 2 * e),
      params: r.params.subarray(b * r.stride, e * r.stride), stride: r.stride, rms: r.rms.subarray(b, e),
      polylineOffsets: r.polylineOffsets.subarray(r.polylineParts[j], r.polylineParts[j + 1]), breaks: bk, failure,
    };
  }
  return { segmentAndVectorize, vectorizedCluster };
}
