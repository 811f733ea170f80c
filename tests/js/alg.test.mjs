// assign (Munkres) and KalmanFilter: hand-checked numbers, brute force over all permutations, the native C++
// headers on the same inputs (tests/tools/alg_native.cpp, in $RTL_NATIVE_BUILD_DIR/tools), errors, disposal, leaks.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { execFileSync } from 'node:child_process';
import { mkdtempSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join, resolve } from 'node:path';
import { fileURLToPath } from 'node:url';
import init from 'rtl-wasm';
import { memoryProbe, nearArray, throwsWith } from './helpers.mjs';

const rtl = await init();
const ROOT = fileURLToPath(new URL('../..', import.meta.url));
const TOOL = join(resolve(ROOT, process.env.RTL_NATIVE_BUILD_DIR || 'build/native'), 'tools', 'alg_native');
const dir = mkdtempSync(join(tmpdir(), 'rtl-alg-'));
process.on('exit', () => rmSync(dir, { recursive: true, force: true }));
let files = 0;
const file = (a) => { const f = join(dir, `a${files++}.f64`); writeFileSync(f, Float64Array.from(a)); return f; };
const native = (args) => JSON.parse(execFileSync(TOOL, args.map(String), { encoding: 'utf8', maxBuffer: 1 << 26 }));

// A seeded generator (xorshift32), so that failures reproduce.
function rng(seed) {
  let s = seed >>> 0 || 1;
  return () => { s ^= s << 13; s >>>= 0; s ^= s >>> 17; s ^= s << 5; s >>>= 0; return s / 2 ** 32; };
}

// Best total over every injective map of the smaller side into the larger one.
function bruteForce(c, rows, cols, maximize) {
  let best = maximize ? -Infinity : Infinity;
  const used = new Array(Math.max(rows, cols)).fill(false);
  const k = Math.min(rows, cols), transposed = rows > cols;
  const at = (i, j) => (transposed ? c[j * cols + i] : c[i * cols + j]);
  const other = transposed ? rows : cols;
  (function rec(i, sum) {
    if (i === k) { best = maximize ? Math.max(best, sum) : Math.min(best, sum); return; }
    for (let j = 0; j < other; j++) if (!used[j]) { used[j] = true; rec(i + 1, sum + at(i, j)); used[j] = false; }
  })(0, 0);
  return k === 0 ? 0 : best;
}

function checkValid(r, c, rows, cols) {
  assert.equal(r.columns.length, rows);
  const seen = new Set();
  let total = 0, assigned = 0;
  r.columns.forEach((j, i) => {
    if (j === -1) return;
    assert.ok(j >= 0 && j < cols && !seen.has(j), `row ${i}: column ${j} valid and not used twice`);
    seen.add(j);
    total += c[i * cols + j];
    assigned++;
  });
  assert.equal(assigned, Math.min(rows, cols), 'min(rows, cols) rows assigned');
  assert.equal(r.total, total, 'total = sum of the assigned costs');
}

test('assign: hand-checked 3 x 3, maximize, rectangular, empty', () => {
  const r = rtl.assign([[4, 1, 3], [2, 0, 5], [3, 2, 2]]);
  assert.ok(r.columns instanceof Int32Array);
  assert.deepEqual([...r.columns], [1, 0, 2]);
  assert.equal(r.total, 5);
  // maximize: rows 0, 1, 2 -> columns 0, 2, 1 (4 + 5 + 2 = 11) is the only optimum of the 6 permutations
  assert.deepEqual([...rtl.assign([[4, 1, 3], [2, 0, 5], [3, 2, 2]], { maximize: true }).columns], [0, 2, 1]);
  // 3 rows, 2 columns: rows 0 and 2 get the cheap columns, row 1 is left out
  const t = rtl.assign([1, 9, 8, 7, 9, 2], { rows: 3, cols: 2 });
  assert.deepEqual([...t.columns], [0, -1, 1]);
  assert.equal(t.total, 3);
  // 2 rows, 3 columns, flat Float32Array with cols only
  const w = rtl.assign(new Float32Array([5, 1, 7, 2, 6, 9]), { cols: 3 });
  assert.deepEqual([...w.columns], [1, 0]);
  assert.equal(w.total, 3);
  assert.deepEqual(rtl.assign([]), { columns: new Int32Array(0), total: 0 });
  assert.deepEqual([...rtl.assign([4, 3, 2, 1]).columns], [1, 0], 'a flat square array needs no rows/cols');
});

test('assign: optimal against brute force on 3000 random matrices up to 6 x 6 (ties included, both senses)', () => {
  const r = rng(7);
  for (let t = 0; t < 3000; t++) {
    const rows = 1 + Math.floor(r() * 6), cols = 1 + Math.floor(r() * 6);
    const ties = t % 2 === 0;
    const c = Array.from({ length: rows * cols }, () => (ties ? Math.floor(r() * 4) : Math.round((r() * 200 - 100) * 1e3) / 1e3));
    const maximize = t % 3 === 0;
    const res = rtl.assign(c, { rows, cols, maximize });
    checkValid(res, c, rows, cols);
    const best = bruteForce(c, rows, cols, maximize);
    assert.ok(Math.abs(res.total - best) <= 1e-9 * Math.max(1, Math.abs(best)), `${rows} x ${cols}: ${res.total} vs brute force ${best}`);
  }
});

test('assign: same columns and total as the native solveAssignment (40 x 60, 60 x 40, 100 x 100)', () => {
  const r = rng(11);
  for (const [rows, cols, maximize] of [[40, 60, false], [60, 40, true], [100, 100, false]]) {
    const c = Float64Array.from({ length: rows * cols }, () => r() * 1000);
    const js = rtl.assign(c, { rows, cols, maximize });
    const cpp = native(['assign', file(c), rows, cols, maximize ? 1 : 0]);
    assert.deepEqual([...js.columns], cpp.columns);
    assert.equal(js.total, cpp.total);
  }
});

const ASSIGN_ERRORS = [
  ['costs a string', () => rtl.assign('x'), TypeError, /^assign: costs must be a Float64Array/],
  ['flat not square', () => rtl.assign([1, 2, 3]), TypeError, /^assign: options rows and cols are required for a flat cost array of 3/],
  ['rows x cols mismatch', () => rtl.assign([1, 2, 3], { rows: 2, cols: 2 }), RangeError, /^assign: costs has 3 numbers, a 2 x 2 matrix needs 4/],
  ['ragged rows', () => rtl.assign([[1, 2], [3]]), RangeError, /^assign: costs\[1\] has 1 entries, costs\[0\] has 2/],
  ['NaN cost', () => rtl.assign([1, NaN, 3, 4]), RangeError, /^assign: the cost at row 0, column 1 is NaN/],
  ['Infinity cost', () => rtl.assign([[1, 2], [Infinity, 4]]), RangeError, /^assign: the cost at row 1, column 0 is Infinity/],
  ['cell not a number', () => rtl.assign([[1, 'a']]), TypeError, /^assign: costs\[0\]\[1\] is a string/],
  ['maximize not boolean', () => rtl.assign([1], { maximize: 1 }), TypeError, /^assign: option maximize must be a boolean/],
  ['rows negative', () => rtl.assign([1], { rows: -1 }), RangeError, /^assign: option rows must be >= 0/],
  ['unknown option', () => rtl.assign([1], { max: true }), TypeError, /^assign: unknown option "max"/],
];
for (const [name, f, type, re] of ASSIGN_ERRORS) test(`assign error: ${name}`, () => throwsWith(f, type, re));

// Constant-velocity model, dt = 1: x = [position, velocity], measured position.
function cvFilter(o = {}) {
  const k = new rtl.KalmanFilter({ stateDim: 2, measurementDim: 1, ...o });
  k.setTransitionMatrix([1, 1, 0, 1]);
  k.setMeasurementMatrix([1, 0]);
  return k;
}

test('KalmanFilter: RTL defaults, one hand-checked predict/correct step', () => {
  const k = new rtl.KalmanFilter({ stateDim: 2, measurementDim: 1 });
  assert.deepEqual([...k.state()], [0, 0]);
  assert.deepEqual([...k.covariance()], [1, 0, 0, 1]);
  k.predict();
  k.correct([5]);
  assert.deepEqual([...k.state()], [0, 0], 'the default H = 0 keeps the state at exactly 0');
  k.dispose();
  const f = cvFilter();
  f.predict();              // P = A I A^T + I = [[3, 1], [1, 2]]
  nearArray(f.covariance(), [3, 1, 1, 2], 1e-15, 'P after predict');
  f.correct([1]);           // S = 4, K = [3/4, 1/4]; Joseph form P = [[0.75, 0.25], [0.25, 1.75]]
  nearArray(f.state(), [0.75, 0.25], 1e-15, 'x');
  nearArray(f.covariance(), [0.75, 0.25, 0.25, 1.75], 1e-15, 'P');
  assert.equal(f.stateDim, 2);
  assert.equal(f.measurementDim, 1);
  assert.equal(f.controlDim, 0);
  f.dispose();
});

test('KalmanFilter: control input and the setters (row-major)', () => {
  const k = new rtl.KalmanFilter({ stateDim: 2, measurementDim: 2, controlDim: 1, processNoise: 0, observationNoise: 0.5 });
  k.setState([1, 2]);
  k.setTransitionMatrix([1, 0.5, 0, 1]);   // row-major: x0 += 0.5 x1
  k.setControlMatrix([0, 2]);
  k.setCovarianceMatrix([2, 0, 0, 1]);
  k.predict([3]);                            // x = [1 + 1, 2 + 6]
  nearArray(k.state(), [2, 8], 1e-15, 'x after predict');
  nearArray(k.covariance(), [2.25, 0.5, 0.5, 1], 1e-15, 'P = A P A^T (Q = 0)');
  k.setMeasurementMatrix([1, 0, 0, 1]);
  k.setMeasurementNoiseCovariance([1e-12, 0, 0, 1e-12]);
  k.setProcessNoiseCovariance([0, 0, 0, 0]);
  k.correct([10, 20]);                       // nearly exact measurement of the whole state
  nearArray(k.state(), [10, 20], 1e-9, 'x follows a precise measurement');
  k.dispose();
});

test('KalmanFilter: constant-velocity and constant-acceleration tracks equal the native KalmanX step by step', () => {
  const r = rng(3);
  for (const model of ['cv', 'ca']) {
    const n = model === 'cv' ? 2 : 3, dt = 0.1, T = 300;
    const A = model === 'cv' ? [1, dt, 0, 1] : [1, dt, dt * dt / 2, 0, 1, dt, 0, 0, 1];
    const H = model === 'cv' ? [1, 0] : [1, 0, 0];
    const z = Array.from({ length: T }, (_, t) => 2 + 1.5 * t * dt + (model === 'ca' ? 0.2 * (t * dt) ** 2 : 0) + (r() - 0.5) * 0.4);
    const k = new rtl.KalmanFilter({ stateDim: n, measurementDim: 1, processNoise: 0.01, observationNoise: 0.04 });
    k.setTransitionMatrix(A);
    k.setMeasurementMatrix(H);
    const states = [], covs = [];
    for (const zt of z) { k.predict(); k.correct([zt]); states.push(...k.state()); covs.push(...k.covariance()); }
    k.dispose();
    const cpp = native(['kalman', n, 1, 0, 0.01, 0.04, file(A), '-', file(H), file(z), '-']);
    nearArray(states, cpp.states, 1e-12, `${model} states`);
    nearArray(covs, cpp.covariances, 1e-12, `${model} covariances`);
    // and it tracks: the velocity estimate ends near 1.5 (cv) / 1.5 + 0.4 t (ca)
    const v = states[(T - 1) * n + 1], expected = model === 'cv' ? 1.5 : 1.5 + 0.4 * (T - 1) * dt;
    assert.ok(Math.abs(v - expected) < 0.5, `${model}: velocity ${v} near ${expected}`);
  }
});

const kf = () => cvFilter();
const KALMAN_ERRORS = [
  ['no options', () => new rtl.KalmanFilter(), TypeError, /^KalmanFilter: options \{stateDim, measurementDim\} are required/],
  ['stateDim missing', () => new rtl.KalmanFilter({ measurementDim: 1 }), TypeError, /^KalmanFilter: option stateDim is required/],
  ['stateDim 0', () => new rtl.KalmanFilter({ stateDim: 0, measurementDim: 1 }), RangeError, /^KalmanFilter: option stateDim must be >= 1/],
  ['stateDim 1.5', () => new rtl.KalmanFilter({ stateDim: 1.5, measurementDim: 1 }), RangeError, /^KalmanFilter: option stateDim must be an integer/],
  ['noise NaN', () => new rtl.KalmanFilter({ stateDim: 1, measurementDim: 1, processNoise: NaN }), RangeError, /^KalmanFilter: option processNoise must be finite/],
  ['unknown option', () => new rtl.KalmanFilter({ stateDim: 1, measurementDim: 1, dt: 1 }), TypeError, /^KalmanFilter: unknown option "dt"/],
  ['A wrong length', () => kf().setTransitionMatrix([1, 2, 3]), RangeError, /^KalmanFilter\.setTransitionMatrix: expected 4 numbers \(2 x 2, row-major\), got 3/],
  ['H wrong length', () => kf().setMeasurementMatrix([1]), RangeError, /^KalmanFilter\.setMeasurementMatrix: expected 2 numbers/],
  ['x NaN', () => kf().setState([0, NaN]), RangeError, /^KalmanFilter\.setState: values\[1\] is NaN/],
  ['R a string', () => kf().setMeasurementNoiseCovariance('1'), TypeError, /^KalmanFilter\.setMeasurementNoiseCovariance: values must be a Float64Array/],
  ['correct without z', () => kf().correct(), TypeError, /^KalmanFilter\.correct: measurement is required/],
  ['correct wrong length', () => kf().correct([1, 2]), RangeError, /^KalmanFilter\.correct: measurement must have 1 numbers, got 2/],
  ['predict control without controlDim', () => kf().predict([1]), RangeError, /^KalmanFilter\.predict: control must have 0 numbers, got 1/],
];
for (const [name, f, type, re] of KALMAN_ERRORS) test(`KalmanFilter error: ${name}`, () => throwsWith(f, type, re));

test('KalmanFilter: dispose frees, is idempotent, and every later call is a TypeError', () => {
  const k = cvFilter();
  assert.equal(k.disposed, false);
  k.dispose();
  k.dispose();
  assert.equal(k.disposed, true);
  for (const [name, call] of [['predict', () => k.predict()], ['correct', () => k.correct([1])], ['state', () => k.state()],
    ['covariance', () => k.covariance()], ['setState', () => k.setState([0, 0])]])
    throwsWith(call, TypeError, new RegExp(`^KalmanFilter\\.${name}: the filter was disposed`));
  const u = cvFilter();
  u[Symbol.dispose ?? Symbol.for('Symbol.dispose')]();
  assert.equal(u.disposed, true);
});

test('assign and KalmanFilter leave the wasm heap, memory and stack as they were (calls and failures)', () => {
  const calls = () => {
    rtl.assign([[1, 2], [3, 4]]);
    try { rtl.assign([1, NaN, 3, 4]); } catch { /* expected */ }
    const k = cvFilter();
    k.predict(); k.correct([1]); k.state(); k.covariance();
    try { k.setTransitionMatrix([1]); } catch { /* expected */ }
    k.dispose();
  };
  calls();
  const memory = memoryProbe(rtl);
  for (let i = 0; i < 2000; i++) calls();
  memory.unchanged();
});
