// fitLine(): the total-least-squares line of a point set (wasm/src/fit.cpp); argument checks only.
import { dimOption, options, toF64 } from './checks.js';

/** fitLine() of one module instance: ctx = {m, withInputOf, boundary} (api.js). */
export function fitLineApi({ m, withInputOf, boundary }) {
  // The options of m.fitLine by name, as wasm/src/fit.cpp declares them (schema.js).
  const call = boundary.call('fitLine');
  function fitLine(points, opts) {
    const fn = 'fitLine';
    const o = options(opts, fn, ['dim']);
    const dim = dimOption(o, fn);
    const xy = toF64(points, fn, 'points');
    // Through the module's kept input buffer (no malloc and free per call); the points are copied, as before, even
    // when they are a pointBuffer() view.
    return withInputOf(fn, xy.length, (heap, at) => heap.set(xy, at), (p, n) => m.fitLine(p, n, call.writeOptions({ dim })));
  }
  return { fitLine };
}
