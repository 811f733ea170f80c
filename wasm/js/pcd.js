// readPcd: the C++ core's PCD reader (wasm/src/pcd.cpp, in the extras module) over a file's bytes; argument checks
// and the cloud as typed arrays only.
import { bytesArgument, describe, options } from './checks.js';
import { organized } from './readers.js';

/** readPcd of one package instance: ctx.extras(fn) gives the extras module's {m, withHeap} (modules.js), or throws
 *  when it is not loaded. */
export function pcdApi({ extras }) {
  // PCD files (PCL's format; ascii, binary, binary_compressed) read by the C++ core's reader. Organised clouds
  // (height > 1) in readOrganizedLidar's shape (column-major, beams = rows; intensity from the "intensity" field,
  // NaN without one), unorganised ones as points in file order; both with width, height, the viewpoint
  // (tx, ty, tz, qw, qx, qy, qz) and the further fields asked for (default intensity, ring) by name.
  /**
   * @param {ArrayBuffer | ArrayBufferView} data
   * @param {import('./index.js').PcdOptions} [opts]
   * @returns {import('./index.js').PcdCloud}
   */
  function readPcd(data, opts) {
    const fn = 'readPcd';
    const { m, withHeap } = extras(fn);
    const u8 = bytesArgument(data, fn, 'data must be an ArrayBuffer or a typed array / DataView / Buffer');
    const o = options(opts, fn, ['fields']);
    const names = o.fields ?? ['intensity', 'ring'];
    if (!Array.isArray(names)) throw new TypeError(`${fn}: option fields must be an array of field names, got ${describe(names)}`);
    names.forEach((name, i) => {
      if (typeof name !== 'string') throw new TypeError(`${fn}: option fields[${i}] must be a string, got ${describe(name)}`);
      if (name === '' || /\s/.test(name)) throw new RangeError(`${fn}: option fields[${i}] must be a field name without spaces, got "${name}"`);
    });
    const r = withHeap(fn, [u8], (p, n) => m.readPcd(p, n, names.join(' ')));
    /** @type {Record<string, {count: number, values: Float64Array}>} */
    const fields = r.fields;
    const common = { width: r.width, height: r.height, viewpoint: r.viewpoint, fields };
    if (!r.organized) return { organized: /** @type {false} */ (false), points: r.points, ...common };
    const n = r.width * r.height, f = fields.intensity;
    const intensity = new Float32Array(n).fill(NaN);
    if (f) for (let i = 0; i < n; i++) intensity[i] = f.values[i * f.count];
    return { organized: /** @type {true} */ (true), ...organized(r.height, r.width, r.points, intensity), ...common };
  }

  return { readPcd };
}
