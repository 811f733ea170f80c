// readCarmenLog and readOrganizedLidar: the C++ core's readers (wasm/src/readers.cpp) over a file's text or bytes;
// argument checks and the scans as typed arrays only.
import { bytesArgument, describe, num, options } from './checks.js';

/** The readers of one module instance: ctx = {m, withHeap, boundary} (api.js). */
export function readersApi({ m, withHeap, boundary }) {
  // The options of m.readCarmenLog and m.readOrganizedLidar by name, as wasm/src/readers.cpp declares them (schema.js).
  const carmenCall = boundary.call('readCarmenLog'), lidarCall = boundary.call('readOrganizedLidar');
  // CARMEN logs: every FLASER line is a scan; beams without a return (range <= 0, non-finite or >= maxRange) are NaN
  // points; maxRange is the log's own no-return value unless given. Text as a string (UTF-8 encoded here) or bytes.
  function readCarmenLog(text, opts) {
    const fn = 'readCarmenLog';
    const u8 = typeof text === 'string' ? new TextEncoder().encode(text)
      : bytesArgument(text, fn, 'text must be a string, an ArrayBuffer or a typed array of the file');
    const o = options(opts, fn, ['maxRange']);
    // Default: detected from the log (NaN to the C++ reader); Infinity keeps every finite positive range.
    const maxRange = o.maxRange === Infinity ? Infinity : num(o, 'maxRange', fn, NaN, { min: 0, exclusiveMin: true });
    const r = withHeap(fn, [u8], (p, n) => m.readCarmenLog(p, n, carmenCall.writeOptions({ maxRange })));
    const scans = [];
    for (let k = 0; k + 1 < r.offsets.length; k++) {
      const b = r.offsets[k], e = r.offsets[k + 1];
      scans.push({
        points: r.points.slice(2 * b, 2 * e), ranges: r.ranges.slice(b, e),
        x: r.x[k], y: r.y[k], theta: r.theta[k], timestamp: r.timestamp[k], line: r.line[k],
        maxRange: r.maxRange, maxRangeSource: r.maxRangeSource,
      });
    }
    return scans;
  }

  // Organised LiDAR: 16-byte little-endian float32 records x, y, z, intensity; (0,0,0) = no return (NaN point).
  // The cloud is stored column-major whatever the file layout: beam b of column c is point c * beams + b.
  function readOrganizedLidar(data, opts) {
    const fn = 'readOrganizedLidar';
    const u8 = bytesArgument(data, fn, 'data must be an ArrayBuffer or a typed array / DataView / Buffer');
    if (opts === undefined) throw new TypeError(`${fn}: options {beams} are required`);
    const o = options(opts, fn, ['beams', 'layout']);
    if (o.beams === undefined) throw new TypeError(`${fn}: option beams is required`);
    const beams = num(o, 'beams', fn, 0, { min: 1, integer: true, max: 1 << 20 });
    const layout = o.layout ?? 'column-major';
    if (typeof layout !== 'string') throw new TypeError(`${fn}: option layout must be a string, got ${describe(layout)}`);
    if (layout !== 'column-major' && layout !== 'row-major')
      throw new RangeError(`${fn}: option layout must be 'column-major' or 'row-major', got '${layout}'`);
    const r = withHeap(fn, [u8], (p, n) => m.readOrganizedLidar(p, n, lidarCall.writeOptions({ beams, layout })));
    return organized(beams, r.columns, r.points, r.intensity);
  }

  return { readCarmenLog, readCarmen: readCarmenLog, readOrganizedLidar };
}

// An organised cloud's result (readOrganizedLidar, and readPcd in pcd.js): column-major points with ring() and column()
// accessors.
export function organized(beams, columns, points, intensity) {
  return {
    beams, columns, points, intensity,
    ring(b) {
      if (typeof b !== 'number') throw new TypeError(`ring: beam must be a number, got ${describe(b)}`);
      if (!Number.isInteger(b) || b < 0 || b >= beams) throw new RangeError(`ring: beam must be an integer in [0, ${beams - 1}], got ${b}`);
      const out = new Float64Array(3 * columns);
      for (let c = 0; c < columns; c++) out.set(points.subarray(3 * (c * beams + b), 3 * (c * beams + b) + 3), 3 * c);
      return out;
    },
    column(c) {
      if (typeof c !== 'number') throw new TypeError(`column: c must be a number, got ${describe(c)}`);
      if (!Number.isInteger(c) || c < 0 || c >= columns) throw new RangeError(`column: c must be an integer in [0, ${columns - 1}], got ${c}`);
      return points.slice(3 * c * beams, 3 * (c + 1) * beams);
    },
  };
}
