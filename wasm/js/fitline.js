// fitLine(): the total-least-squares line of a point set (wasm/src/fit.cpp); argument checks only.
import { dimOption, options, toF64 } from './checks.js';

/** fitLine() of one module instance: ctx = {m, withHeap} (api.js). */
export function fitLineApi({ m, withHeap }) {
  function fitLine(points, opts) {
    const fn = 'fitLine';
    const o = options(opts, fn, ['dim']);
    const dim = dimOption(o, fn);
    const xy = toF64(points, fn, 'points');
    return withHeap(fn, [xy], (p, n) => m.fitLine(p, n, dim));
  }
  return { fitLine };
}
