// The calls that moved into the extras module (toSvg, toTikz 2D/3D, toLatexTable, readPcd, assign, KalmanFilter),
// each on fixed inputs (the tests/data scans and PCD files, small matrices), as {case: sha256 of the output}.
// extras-golden.json holds these digests as the package gave them before the move (record-golden.mjs); the test
// (tests/js/extras-identical.test.mjs) computes them again: equal digests mean byte-identical outputs.
import { createHash } from 'node:crypto';
import { readFileSync, readdirSync } from 'node:fs';
import { scanDrawing } from '../helpers.mjs';

const DATA = new URL('../../data/', import.meta.url);
const sha = (s) => createHash('sha256').update(s).digest('hex');
// Typed arrays by their bytes, so that every bit of every number counts; methods (ring(), column()) left out.
const bytesOf = (a) => Buffer.from(a.buffer, a.byteOffset, a.byteLength).toString('hex');
function serialise(v) {
  if (ArrayBuffer.isView(v)) return `${v.constructor.name}:${bytesOf(v)}`;
  if (Array.isArray(v)) return `[${v.map(serialise).join(',')}]`;
  if (v !== null && typeof v === 'object')
    return `{${Object.keys(v).filter((k) => typeof v[k] !== 'function').sort().map((k) => `${k}=${serialise(v[k])}`).join(',')}}`;
  return `${typeof v}:${String(v)}`;
}

// Scans of both CARMEN logs (every 10th of csail, first of intel), segmented, clusters of >= 3 points vectorized
// with Douglas-Peucker: drawings as the CLI and the page make them (the core calls did not move).
function drawings(rtl) {
  const out = [];
  for (const [name, every] of [['intel.log', 1000], ['csail.log', 10]]) {
    const scans = rtl.readCarmenLog(readFileSync(new URL(name, DATA)));
    for (let k = 0; k < Math.min(scans.length, 30); k += every) {
      out.push([`${name}#${k}`, scanDrawing(rtl, scans[k].points, `${name} scan ${k} _&%`)]);
    }
  }
  return out;
}

const scene = {
  dim: 3,
  points: [0, 0, 1, 0.5, 0.5, 1, NaN, NaN, NaN, 1, 1, 1, 2, 0.5, 0.2, -1, 1.5, 0.7],
  labels: [0, 0, -1, 2, 1, 1],
  segments: [0, 0, 0, 1, 1, 1, 2, 0, 0, 2, 1, 0.5],
  planes: { vertices: [0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0], counts: [4] },
  polygons: [[0, 0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1]],
};

/** {case name: sha256 hex} of every moved call on the fixed inputs, computed with package instance rtl. */
export function goldenDigests(rtl) {
  const d = {};
  for (const [name, drawing] of drawings(rtl)) {
    d[`toSvg ${name}`] = sha(rtl.toSvg(drawing, { width: 640, height: 480 }));
    d[`toSvg default ${name}`] = sha(rtl.toSvg(drawing));
    d[`toTikz ${name}`] = sha(rtl.toTikz(drawing, { width: 10, height: 7, markRadius: 0.02 }));
    d[`toTikz bare ${name}`] = sha(rtl.toTikz({ ...drawing, standalone: false }));
  }
  d['toTikz 3D default'] = sha(rtl.toTikz(scene));
  d['toTikz 3D camera'] = sha(rtl.toTikz(scene, { camera: { fov: 50, direction: [-1, -2, -1] }, width: 9, height: 6 }));
  d['toTikz 3D bare'] = sha(rtl.toTikz({ ...scene, standalone: false }, { markRadius: 0.05 }));
  d.toLatexTable = sha(rtl.toLatexTable([['a_1', 2.5], null, ['50%', 'x&y']], { heading: ['name', 'value'], caption: 'Costs & #' }));
  d['toLatexTable raw'] = sha(rtl.toLatexTable([['$10^{3}$', 1e-7]], { escape: false, columns: 'l|r' }));
  const pcd = new URL('pcd/', DATA);
  for (const f of readdirSync(pcd).filter((n) => n.endsWith('.pcd')).sort()) {
    const bytes = readFileSync(new URL(f, pcd));
    d[`readPcd ${f}`] = sha(serialise(rtl.readPcd(bytes)));
    d[`readPcd ${f} fields`] = sha(serialise(rtl.readPcd(bytes, { fields: ['intensity'] })));
  }
  d['assign 3x3'] = sha(serialise(rtl.assign([[4, 1, 3], [2, 0, 5], [3, 2, 2]])));
  d['assign 2x4 maximize'] = sha(serialise(rtl.assign([1, 9, 3, 4, 7, 2, 8, 6], { rows: 2, cols: 4, maximize: true })));
  d['assign 4x2'] = sha(serialise(rtl.assign([[1.5, 2], [0.25, 9], [3, 0.5], [7, 7]])));
  // A constant-velocity filter in 2D (state x, y, vx, vy) through 20 noisy positions.
  const kf = new rtl.KalmanFilter({ stateDim: 4, measurementDim: 2, controlDim: 1, processNoise: 0.01, observationNoise: 0.25 });
  kf.setTransitionMatrix([1, 0, 0.1, 0, 0, 1, 0, 0.1, 0, 0, 1, 0, 0, 0, 0, 1]);
  kf.setMeasurementMatrix([1, 0, 0, 0, 0, 1, 0, 0]);
  kf.setControlMatrix([0, 0, 0.1, 0]);
  kf.setState([0, 0, 1, 0]);
  const trace = [];
  for (let i = 0; i < 20; i++) {
    kf.predict(i % 5 === 0 ? [1] : undefined);
    kf.correct([0.1 * i + 0.03 * Math.sin(7 * i), 0.02 * i * i + 0.03 * Math.cos(5 * i)]);
    trace.push(kf.state(), kf.covariance());
  }
  kf.dispose();
  d.KalmanFilter = sha(serialise(trace));
  return d;
}
