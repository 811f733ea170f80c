// StreamSegmenter: incremental (IA) segmentation of a stream of points (wasm/src/stream.cpp), a stateful object
// that owns a C++ segmenter behind an integer handle.
import { boolOption, boundsOptions, check, dimOption, num, options, originOption, toF64 } from './checks.js';
import { defaults } from './defaults.js';
import { CppObject, HANDLE } from './owned.js';
import { partViews, traceEvents } from './views.js';

// The clusters of a StreamSegmenter as views on the one array of points the call returned, as segment() does:
// a slice() per cluster allocated a backing store each.
const splitClusters = (r, dim) => partViews(r.points, r.offsets, dim);

/** The StreamSegmenter class of one module instance: ctx = {m, withHeap, boundary, registry} (api.js; see owned.js). */
export function streamApi({ m, withHeap, boundary, registry }) {
  // The options of m.streamCreate by name, as wasm/src/stream.cpp declares them (schema.js).
  const createCall = boundary.call('streamCreate');
  class StreamSegmenter extends CppObject {
    #dim;
    #traced;
    constructor(opts) {
      const fn = 'StreamSegmenter';
      const o = options(opts, fn, ['dim', 'step', 'lowerBound', 'upperBound', 'scaling', 'trace']);
      const dim = dimOption(o, fn);
      const traced = boolOption(o, 'trace', fn, false);
      const d = defaults.streamSegmenter;
      const step = num(o, 'step', fn, d.step, { min: 1, integer: true, max: 1 << 24 });
      const [lower, upper] = boundsOptions(o, fn, d.lowerBound, d.upperBound);
      const scaling = num(o, 'scaling', fn, d.scaling, { min: 0 });
      const settings = { dim, step, lowerBound: lower, upperBound: upper, scaling, trace: traced };
      super(check(m.streamCreate(createCall.writeOptions(settings)), fn), (h) => m.streamDestroy(h), registry,
        fn, 'segmenter');
      this.#dim = dim;
      this.#traced = traced;
    }
    get dim() { return this.#dim; }
    addPoints(points, origin) {
      const fn = 'StreamSegmenter.addPoints';
      const h = this[HANDLE]('addPoints');
      const o = originOption(origin === undefined ? {} : { origin }, fn, this.#dim);
      const xyz = toF64(points, fn, 'points');
      withHeap(fn, [xyz], (p, n) => m.streamAdd(h, p, n, this.#dim, o[0], o[1], o[2]));
    }
    get closedClustersAvailable() { return m.streamClosed(this[HANDLE]('closedClustersAvailable')); }
    get aliveClustersAvailable() { return m.streamAlive(this[HANDLE]('aliveClustersAvailable')); }
    takeClosedClusters() { return splitClusters(check(m.streamTakeClosed(this[HANDLE]('takeClosedClusters')), 'StreamSegmenter.takeClosedClusters'), this.#dim); }
    aliveClusters() { return splitClusters(check(m.streamAliveClusters(this[HANDLE]('aliveClusters')), 'StreamSegmenter.aliveClusters'), this.#dim); }
    flush() { check(m.streamFlush(this[HANDLE]('flush')), 'StreamSegmenter.flush'); }
    get traced() { return this.#traced; }
    // The steps recorded since the last call (the segmenter was made with { trace: true }), then forgotten.
    takeTrace() {
      const fn = 'StreamSegmenter.takeTrace';
      const h = this[HANDLE]('takeTrace');
      if (!this.#traced) throw new TypeError(`${fn}: the segmenter was made without { trace: true }`);
      return traceEvents(check(m.streamTakeTrace(h), fn));
    }
  }
  return { StreamSegmenter };
}
