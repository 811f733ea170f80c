// extractPolylines: the package's whole-scan polyline extraction at a vertex budget against the same C++ run
// natively (tests/tools/polylines_native.cpp, built into $RTL_NATIVE_BUILD_DIR/tools by the native build) on the
// real scans of tests/data/intel.log; the budget, the measured figure the C++ test pins, errors, memory.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { execFileSync } from 'node:child_process';
import { mkdtempSync, readFileSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join, resolve } from 'node:path';
import { fileURLToPath } from 'node:url';
import init from 'rtl-wasm';
import { near, throwsWith } from './helpers.mjs';

const ROOT = fileURLToPath(new URL('../..', import.meta.url));
const TOOL = join(resolve(ROOT, process.env.RTL_NATIVE_BUILD_DIR || 'build/native'), 'tools', 'polylines_native');
const rtl = await init();
const scans = rtl.readCarmenLog(readFileSync(new URL('../data/intel.log', import.meta.url)));
const dir = mkdtempSync(join(tmpdir(), 'rtl-polylines-'));
process.on('exit', () => rmSync(dir, { recursive: true, force: true }));

function native(points, J, maxGap = 1, cost = 0.5) {
  const file = join(dir, 'beams.f64');
  writeFileSync(file, Buffer.from(points.buffer, points.byteOffset, points.byteLength));
  return JSON.parse(execFileSync(TOOL, [file, J, maxGap, cost].map(String), { encoding: 'utf8', maxBuffer: 1 << 26 }));
}

// Equal to TOL relative (NaN where native has null), the partition (offsets, counts) exactly: the same code on the
// same numbers, but compiled by another compiler (clang -msimd128 vs g++) with other libm functions (musl vs glibc).
// The radial refinement iterates until its step is small, so last-bit differences end up as large as its
// convergence tolerance: at most 4.4e-9 relative measured on these runs (~60 % of the numbers bit-identical); a real
// divergence (another partition or corner) differs by far more. The test prints both figures.
const stats = { numbers: 0, identical: 0, maxDiff: 0 };
const TOL = 1e-7;
function same(a, b, what) {
  assert.equal(a.length, b.length, `${what}: length`);
  for (let i = 0; i < b.length; i++) {
    stats.numbers++;
    if (b[i] === null) { assert.ok(Number.isNaN(a[i]), `${what}[${i}]: NaN expected, got ${a[i]}`); stats.identical++; continue; }
    const d = Math.abs(a[i] - b[i]) / Math.max(1, Math.abs(b[i]));
    if (d === 0) stats.identical++;
    stats.maxDiff = Math.max(stats.maxDiff, d);
    assert.ok(d <= TOL, `${what}[${i}]: wasm ${a[i]} vs native ${b[i]}`);
  }
}

test('extractPolylines: the same polylines, expected ranges, segments and score as native on intel.log', () => {
  assert.equal(scans.length, 30);
  const runs = [...scans.map((s) => [s, 20]), ...scans.slice(0, 6).flatMap((s) => [[s, 2], [s, 10], [s, 50]])];
  // A discrete choice between options of (nearly) equal cost is decided by last-bit differences: an exact tie between
  // maps (on intel.log scan 17 at J = 20, two 2-beam chains each explained exactly by one segment, with room for one of
  // them) or a refinement step kept on one side only (scan 1 at J = 50: one vertex 1e-4 m apart, scores 1.1e-5
  // relative apart). Such a run must still agree in vertex and explained-beam counts and in score to 1e-4 relative; it
  // may happen on at most 2 of the 48 runs, and every other run must agree number for number.
  const ties = [];
  for (const [k, [scan, J]] of runs.entries()) {
    const w = rtl.extractPolylines(scan.points, { maxVertices: J });
    const n = native(scan.points, J);
    const what = `run ${k} (J ${J})`;
    assert.equal(w.vertexCount, n.vertexCount, `${what}: vertexCount`);
    assert.equal(w.explainedBeams, n.explainedBeams, `${what}: explainedBeams`);
    assert.equal(w.returned, n.returned, `${what}: returned`);
    const before = { ...stats };   // the statistics count the runs that agree number for number
    try {
      assert.deepEqual([...w.offsets], n.offsets, `${what}: offsets`);
      same(w.vertices, n.vertices, `${what}: vertices`);
      same(w.expectedRanges, n.expectedRanges, `${what}: expectedRanges`);
      same(w.segments.r, n.r, `${what}: r`);
      same(w.segments.theta, n.theta, `${what}: theta`);
      same(w.segments.covariance, n.covariance, `${what}: covariance`);
    } catch (e) {
      assert.ok(Math.abs(w.score - n.score) <= 1e-4 * n.score, `${what}: maps differ (${e.message}) at scores ${w.score} vs ${n.score}`);
      ties.push(what);
      Object.assign(stats, before);
    }
    if (!ties.includes(what)) same([w.rmse, w.explained, w.score], [n.rmse, n.explained, n.score], `${what}: rmse, explained, score`);
  }
  assert.ok(ties.length <= 2, `maps of equal score differ on ${ties.length} runs: ${ties.join(', ')}`);
  console.log(`wasm vs native: ${stats.identical} of ${stats.numbers} numbers bit-identical, max relative difference ${stats.maxDiff}; ` +
    `maps of (nearly) equal score that differ: ${ties.length ? ties.join(', ') : 'none'}`);
});

test('extractPolylines: the budget is respected and the result is consistent', () => {
  for (const J of [2, 3, 10, 30]) {
    for (const scan of scans.slice(0, 10)) {
      const r = rtl.extractPolylines(scan.points, { maxVertices: J });
      assert.ok(r.vertexCount <= J && r.vertexCount >= 2, `J ${J}: ${r.vertexCount} vertices`);
      assert.equal(r.offsets[r.offsets.length - 1], r.vertexCount);
      assert.equal(r.vertices.length, 2 * r.vertexCount);
      assert.equal(r.polylines.length, r.offsets.length - 1);
      for (const p of r.polylines) assert.ok(p.length >= 4 && p.buffer === r.vertices.buffer);
      assert.equal(r.segments.r.length, r.vertexCount - r.polylines.length);
      assert.equal(r.expectedRanges.length, scan.points.length / 2);
      for (let s = 0; s < r.segments.r.length; s++) {
        const c = r.segments.covariance.subarray(4 * s, 4 * s + 4);
        assert.ok(r.segments.r[s] >= 0 && c[0] > 0 && c[3] > 0 && c[1] === c[2], `segment ${s}`);
        assert.ok(r.segments.firstBeam[s] <= r.segments.lastBeam[s]);
      }
      const hits = r.expectedRanges.filter((v) => !Number.isNaN(v)).length;
      assert.equal(hits, r.explainedBeams);
      near(r.explained, r.explainedBeams / r.returned, 1e-15, 'explained');
      near(r.score, r.explained * r.rmse ** 2 + (1 - r.explained) * 0.25, 1e-12, 'score');
    }
  }
});

test('extractPolylines: the mean figures on intel.log at J = 20 that the C++ test pins', () => {
  let score = 0, rmse = 0, f = 0;
  for (const scan of scans) {
    const r = rtl.extractPolylines(scan.points, { maxVertices: 20 });
    score += r.score / scans.length;
    rmse += r.rmse / scans.length;
    f += r.explained / scans.length;
  }
  near(score, 0.025490, 0.02 * 0.025490, 'mean score');
  near(rmse, 0.048814, 0.02 * 0.048814, 'mean rmse');
  near(f, 0.912219, 0.005, 'mean explained');
  // Options reach the C++ side: a tighter gap and cost change the result.
  const a = rtl.extractPolylines(scans[3].points, { maxVertices: 20 });
  const b = rtl.extractPolylines(scans[3].points, { maxVertices: 20, maxGap: 0.2, unexplainedCost: 0.1 });
  const n = native(scans[3].points, 20, 0.2, 0.1);
  same([b.score, b.rmse], [n.score, n.rmse], 'options');
  assert.notEqual(a.score, b.score);
});

test('extractPolylines: no returned beam gives the documented empty result', () => {
  for (const pts of [new Float64Array(0), new Float64Array(20).fill(NaN)]) {
    const r = rtl.extractPolylines(pts, { maxVertices: 10 });
    assert.equal(r.returned, 0);
    assert.equal(r.polylines.length, 0);
    assert.equal(r.vertexCount, 0);
    assert.equal(r.expectedRanges.length, pts.length / 2);
    assert.ok(r.expectedRanges.every(Number.isNaN));
    assert.ok(Number.isNaN(r.score) && Number.isNaN(r.rmse) && Number.isNaN(r.explained));
  }
});

test('extractPolylines: argument errors are TypeError/RangeError starting with its name; the module works on', () => {
  const p = scans[0].points;
  const sp = rtl.stackPointer();
  throwsWith(() => rtl.extractPolylines(), TypeError, /^extractPolylines: points/);
  throwsWith(() => rtl.extractPolylines('xy'), TypeError, /^extractPolylines: points must be/);
  throwsWith(() => rtl.extractPolylines(p, 5), TypeError, /^extractPolylines: options must be an object/);
  throwsWith(() => rtl.extractPolylines(p, { maxVertex: 5 }), TypeError, /^extractPolylines: unknown option "maxVertex"/);
  throwsWith(() => rtl.extractPolylines(p, { maxVertices: '5' }), TypeError, /^extractPolylines: option maxVertices must be a number/);
  for (const J of [1, 0, -3]) throwsWith(() => rtl.extractPolylines(p, { maxVertices: J }), RangeError, /^extractPolylines: option maxVertices must be >= 2/);
  throwsWith(() => rtl.extractPolylines(p, { maxVertices: 2.5 }), RangeError, /^extractPolylines: option maxVertices must be an integer/);
  for (const key of ['maxGap', 'unexplainedCost']) {
    for (const bad of [0, -1]) throwsWith(() => rtl.extractPolylines(p, { [key]: bad }), RangeError, new RegExp(`^extractPolylines: option ${key} must be > 0`));
    for (const bad of [NaN, Infinity]) throwsWith(() => rtl.extractPolylines(p, { [key]: bad }), RangeError, new RegExp(`^extractPolylines: option ${key} must be finite`));
  }
  throwsWith(() => rtl.extractPolylines(new Float64Array(5)), RangeError, /^extractPolylines: points has 5 numbers/);
  throwsWith(() => rtl.extractPolylines([1, 2, Infinity, 0]), RangeError, /^extractPolylines: point 1 has a non-finite coordinate \(Infinity\)/);
  throwsWith(() => rtl.extractPolylines([1, 2, 1e300, 0]), RangeError, /^extractPolylines: point 1 has the coordinate 1e\+300/);
  assert.equal(rtl.stackPointer(), sp);
  assert.ok(rtl.extractPolylines(p).vertexCount <= 50);  // default budget 50
});

test('extractPolylines: repeated calls leave the wasm heap and memory as they were', () => {
  for (const s of scans) rtl.extractPolylines(s.points, { maxVertices: 30 });  // warm-up: memory grows once
  const heap = rtl.heapInUse(), mem = rtl.memoryBytes();
  for (let k = 0; k < 5; k++) for (const s of scans) rtl.extractPolylines(s.points, { maxVertices: 30 });
  try { rtl.extractPolylines([1, 2, Infinity, 3]); } catch { /* a failing call, then the heap again */ }
  assert.equal(rtl.heapInUse(), heap, 'malloc heap in use');
  assert.equal(rtl.memoryBytes(), mem, 'wasm memory');
});
