// extractPolylines(): whole-scan polyline extraction at a vertex budget (rtl::ScanPolylines2D, wasm/src/polylines.cpp);
// argument checks and the result object, from the typed arrays the call lays out by name (schema.js).
import { num, options, toF64 } from './checks.js';
import { defaults } from './defaults.js';

/** extractPolylines() of one module instance: ctx = {m, withInput, boundary, setComputeMs} (api.js). */
export function polylinesApi({ m, withInput, boundary, setComputeMs }) {
  // The options of m.extractPolylines by name, as wasm/src/polylines.cpp declares them (schema.js).
  const call = boundary.call('extractPolylines');
  /**
   * @param {import('./index.js').PointArray} points
   * @param {import('./index.js').ExtractPolylinesOptions} [opts]
   * @returns {import('./index.js').ExtractPolylinesResult}
   */
  function extractPolylines(points, opts) {
    const fn = 'extractPolylines';
    if (points === undefined) throw new TypeError(`${fn}: points (the scan's beams, interleaved x, y) are required`);
    const xy = toF64(points, fn, 'points');
    const o = options(opts, fn, ['maxVertices', 'maxGap', 'unexplainedCost']);
    // The C++ defaults (ScanPolylines2D), from defaults.js. Above 2^32 vertices means no budget.
    const d = defaults.extractPolylines;
    const maxVertices = num(o, 'maxVertices', fn, d.maxVertices, { min: 2, integer: true, max: 2 ** 32 - 1 });
    const maxGap = num(o, 'maxGap', fn, d.maxGap, { min: 0, exclusiveMin: true });
    const unexplainedCost = num(o, 'unexplainedCost', fn, d.unexplainedCost, { min: 0, exclusiveMin: true });
    if (xy.length % 2 !== 0)
      throw new RangeError(`${fn}: points has ${xy.length} numbers, not a multiple of 2 (interleaved x, y expected)`);
    const { scalars: s, arrays: a } = call.readResults(withInput(fn, xy, (p, n) => m.extractPolylines(p, n,
      call.writeOptions({ maxVertices, maxGap, unexplainedCost }))));
    setComputeMs(s.computeMs);
    const { vertices, offsets } = a;
    const polylines = [];
    for (let k = 0; k + 1 < offsets.length; k++) polylines.push(vertices.subarray(2 * offsets[k], 2 * offsets[k + 1]));
    return {
      polylines, vertices, offsets, expectedRanges: a.expectedRanges,
      segments: { polyline: a.polyline, firstBeam: a.firstBeam, lastBeam: a.lastBeam, r: a.r, theta: a.theta, covariance: a.covariance },
      vertexCount: s.vertexCount, returned: s.returned, explainedBeams: s.explainedBeams,
      rmse: s.rmse, explained: s.explained, score: s.score,
    };
  }
  return { extractPolylines };
}
