// vectorize(): the vectorization methods of the C++ core (FTLS, AFTLS, ITLS, Douglas-Peucker, Reumann-Witkam;
// wasm/src/vectorize.cpp); argument checks, the result's typed arrays and the failure's message only.
import { MAX_MEMORY, boolOption, describe, dimOption, num, options, toF64 } from './checks.js';
import { defaults } from './defaults.js';
import { traceEvents } from './views.js';

export const METHODS = ['ftls', 'aftls', 'itls', 'dp', 'rw'];

// A corner of an FTLS polyline from the triple boundary, crossingDistance, delta at b[k]. At module level, not a
// closure in vectorize(): the build's keepNames gives every named closure its name with Object.defineProperty, per call.
/** @returns {import('./index.js').CornerReport} */
export function corner(b, k) {
  return { boundary: b[k], crossingDistance: b[k + 1], delta: b[k + 2] };
}

/** The failure of a strict FTLS/AFTLS run on n points from the triple at t[k], with vectorize()'s message (also
 *  segmentAndVectorize()'s per cluster: the same text for the same cluster).
 *  @returns {import('./index.js').VectorizeFailure} */
export function failureOf(t, k, n, sigma, split) {
  const fn = 'vectorize';
  const f = /** @type {import('./index.js').VectorizeFailure} */ (corner(t, k));  // message added below
  f.message = f.boundary === 0
    ? `${fn}: no partition of the ${n} points into ranges within sigma ${sigma} exists`
    : `${fn}: no polyline within sigma ${sigma} meets delta ${f.delta} at chain index ${f.boundary}: the lines of the ` +
      `ranges before and after it ${Number.isFinite(f.crossingDistance)
        ? `cross ${Number(f.crossingDistance.toPrecision(4))} from the middle of points ${f.boundary - 1} and ${f.boundary}`
        : 'do not cross'}${split ? '' : ' (raise delta, or use split: true to break the polyline there)'}`;
  return f;
}

/** vectorize() of one module instance: ctx = {m, withInput, boundary, setComputeMs} (api.js). */
export function vectorizeApi({ m, withInput, boundary, setComputeMs }) {
  // The options and results of m.vectorize by name, as wasm/src/vectorize.cpp declares them (schema.js).
  const call = boundary.call('vectorize');
  /**
   * @template {import('./index.js').VectorizeMethod} M
   * @overload
   * @param {import('./index.js').PointArray} points
   * @param {import('./index.js').VectorizeOptions & { method: M; trace: true }} opts
   * @returns {import('./index.js').VectorizeResult & { trace: import('./index.js').VectorizeEventByMethod[M][] }}
   */
  /**
   * @overload
   * @param {import('./index.js').PointArray} points
   * @param {import('./index.js').VectorizeOptions} opts
   * @returns {import('./index.js').VectorizeResult}
   */
  /**
   * @param {import('./index.js').PointArray} points
   * @param {import('./index.js').VectorizeOptions} opts
   * @returns {import('./index.js').VectorizeResult & { trace?: import('./index.js').VectorizeEventByMethod[import('./index.js').VectorizeMethod][] }}
   */
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
    const d = defaults.vectorize;
    const sigma = num(o, 'sigma', fn, d.sigma, { min: 0, exclusiveMin: true });
    const delta = num(o, 'delta', fn, d.delta, { min: 0, exclusiveMin: true });
    const epsilon = num(o, 'epsilon', fn, d.epsilon, { min: 0, exclusiveMin: true });
    // maxSize is a reservation hint: 2 GB of wasm memory (the module's maximum) cannot hold more points than this.
    const maxSize = num(o, 'maxSize', fn, d.maxSize, { min: 0, integer: true, max: Math.floor(MAX_MEMORY / (8 * dim)) });
    const simplexShift = num(o, 'simplexShift', fn, d.simplexShift, { min: 1, integer: true, max: 2 ** 32 - 1 });
    const maxIterations = num(o, 'maxIterations', fn, d.maxIterations, { min: 1, integer: true, max: 2 ** 32 - 1 });
    // split (FTLS/AFTLS 2D): break the polyline where a corner cannot be met within delta (default), or RTL's
    // strict behaviour (false: no result then, and `failure` says why).
    const split = boolOption(o, 'split', fn, d.split);
    const trace = boolOption(o, 'trace', fn, false);
    const view = boolOption(o, 'view', fn, false);  // the arrays as views on the module's result block (schema.js)
    if (trace && dim === 3 && (method === 'ftls' || method === 'aftls'))
      throw new RangeError(`${fn}: option trace is not available for method '${method}' in 3D (only itls, dp and rw trace in 3D)`);
    // distance (dp): to the chord's line (RTL's, default) or to the chord segment (simplify-js's).
    const distance = o.distance ?? 'line';
    if (distance !== 'line' && distance !== 'segment') throw new RangeError(`${fn}: option distance must be 'line' or 'segment', got ${describe(distance)}`);
    const segmentDistance = method === 'dp' && distance === 'segment';
    if (trace && segmentDistance) throw new RangeError(`${fn}: option trace is not available with distance 'segment'`);
    const xyz = toF64(points, fn, 'points');
    const n = xyz.length / dim;  // before the call: growth during it detaches a pointBuffer() view
    const settings = { dim, method, plane: primitive === 'plane', sigma, delta, epsilon, maxSize, simplexShift,
      maxIterations, split, trace, segmentDistance };
    const res = call.readResults(withInput(fn, xyz, (p, n) => m.vectorize(p, n, call.writeOptions(settings))), view);
    const { ok, count, stride, computeMs, failed, failureBoundary, failureCrossingDistance, failureDelta } = res.scalars;
    const { segments, polygonPoints, polygonOffsets, indices, params, rms, polylineOffsets, breaks: breakTriples } = res.arrays;
    setComputeMs(computeMs);
    const breaks = [];
    for (let k = 0; k < breakTriples.length; k += 3) breaks.push(corner(breakTriples, k));
    const failure = failed ? failureOf([failureBoundary, failureCrossingDistance, failureDelta], 0, n, sigma, split) : null;
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
  return { vectorize };
}
