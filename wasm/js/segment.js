// segment(): CAR segmentation of one scan (rtl::CAR_Segmenter, wasm/src/segment.cpp); argument checks and the
// result's typed arrays only.
import { boolOption, boundsOptions, dimOption, num, options, originOption, toF64 } from './checks.js';
import { defaults } from './defaults.js';
import { partViews, traceEvents } from './views.js';

/** segment() of one module instance: ctx = {m, withInput, boundary, setComputeMs} (api.js). */
export function segmentApi({ m, withInput, boundary, setComputeMs }) {
  // The options and results of m.segment by name, as wasm/src/segment.cpp declares them (schema.js).
  const call = boundary.call('segment');
  /**
   * @overload
   * @param {import('./index.js').PointArray} points
   * @param {import('./index.js').SegmentOptions & { trace: true }} opts
   * @returns {import('./index.js').SegmentResult & { trace: import('./index.js').CarEvent[] }}
   */
  /**
   * @overload
   * @param {import('./index.js').PointArray} points
   * @param {import('./index.js').SegmentOptions} [opts]
   * @returns {import('./index.js').SegmentResult}
   */
  /**
   * @param {import('./index.js').PointArray} points
   * @param {import('./index.js').SegmentOptions} [opts]
   * @returns {import('./index.js').SegmentResult & { trace?: import('./index.js').CarEvent[] }}
   */
  function segment(points, opts) {
    const fn = 'segment';
    const o = options(opts, fn, ['dim', 'step', 'lowerBound', 'upperBound', 'origin', 'trace', 'view']);
    const dim = dimOption(o, fn);
    const trace = boolOption(o, 'trace', fn, false);
    const view = boolOption(o, 'view', fn, false);  // the arrays as views on the module's result block (schema.js)
    // Default 2: CAR compares each point with up to step - 1 previous points, so 2 links consecutive points.
    const d = defaults.segment;
    const step = num(o, 'step', fn, d.step, { min: 1, integer: true, max: 2 ** 31 });
    const [lower, upper] = boundsOptions(o, fn, d.lowerBound, d.upperBound);
    const origin = originOption(o, fn, dim);
    const xyz = toF64(points, fn, 'points');
    const settings = { dim, step, lowerBound: lower, upperBound: upper, origin, trace };
    const res = call.readResults(withInput(fn, xyz, (p, n) => m.segment(p, n, call.writeOptions(settings))), view);
    setComputeMs(res.scalars.computeMs);
    const { labels, indices, offsets, runs, runOffsets } = res.arrays;
    // Each cluster's arrays are views on `indices` and `runs` (copies or, with view, the result block).
    const parts = partViews(indices, offsets), ranges = partViews(runs, runOffsets), clusters = new Array(parts.length);
    for (let k = 0; k < parts.length; k++) clusters[k] = { indices: parts[k], ranges: ranges[k] };
    return trace ? { labels, clusters, trace: traceEvents(res.trace) } : { labels, clusters };
  }
  return { segment };
}
