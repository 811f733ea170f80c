// Same results as native: the C++ segmenter and vectorizers run natively (tests/tools/rtl_native.cpp, built into
// $RTL_NATIVE_BUILD_DIR/tools by the native build) and in the wasm build, on every real scan in tests/data, with
// the same adapter code (wasm/src/seg_ops.h, vect_ops.h) and identical input numbers (read once, by the wasm
// readers). Labels, ranges, counts and ok flags must be equal; coordinates and parameters equal to 1e-12 relative
// (they are bit-identical unless a libm function such as hypot rounds differently in musl and glibc; the test
// prints how many are).
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { execFileSync } from 'node:child_process';
import { existsSync, mkdtempSync, readFileSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join, resolve } from 'node:path';
import { fileURLToPath } from 'node:url';
import init from 'rtl-wasm';

const ROOT = fileURLToPath(new URL('../..', import.meta.url));
const BUILD = resolve(ROOT, process.env.RTL_NATIVE_BUILD_DIR || 'build/native');
const TOOL = join(BUILD, 'tools', 'rtl_native');
const DATA = new URL('../data/', import.meta.url);
const rtl = await init();
const dir = mkdtempSync(join(tmpdir(), 'rtl-native-'));
process.on('exit', () => rmSync(dir, { recursive: true, force: true }));

const stats = { numbers: 0, identical: 0, maxDiff: 0 };
function sameNumbers(a, b, what) {
  assert.equal(a.length, b.length, `${what}: length`);
  for (let i = 0; i < a.length; i++) {
    stats.numbers++;
    if (Object.is(a[i] + 0, b[i] + 0)) { stats.identical++; continue; }
    const d = Math.abs(a[i] - b[i]) / Math.max(1, Math.abs(a[i]));
    stats.maxDiff = Math.max(stats.maxDiff, d);
    assert.ok(d <= 1e-12, `${what}[${i}]: wasm ${a[i]} vs native ${b[i]}`);
  }
}

// Runs the native tool on several inputs at once (--split) and returns one result per input.
let calls = 0;
function native(args, inputs, dim, flags = []) {
  const pts = new Float64Array(inputs.reduce((s, a) => s + a.length, 0));
  let o = 0;
  for (const a of inputs) { pts.set(a, o); o += a.length; }
  const f = join(dir, `in${calls}.f64`), c = join(dir, `in${calls++}.u32`);
  writeFileSync(f, pts);
  writeFileSync(c, Uint32Array.from(inputs.map((a) => a.length / dim)));
  const out = execFileSync(TOOL, [args[0], f, String(dim), ...args.slice(1).map(String), `--split=${c}`, ...flags],
    { encoding: 'utf8', maxBuffer: 1 << 28 });
  return JSON.parse(out);
}

// Real inputs: CARMEN scans (2D, NaN gaps) and the 4 rings of the Ouster excerpt (3D).
const scans2 = ['intel.log', 'csail.log'].flatMap((f) => rtl.readCarmenLog(readFileSync(new URL(f, DATA))).map((s) => s.points));
const cloud = rtl.readOrganizedLidar(readFileSync(new URL('rellis3d-os1-4x2048.bin', DATA)), { beams: 4 });
const scans3 = [0, 1, 2, 3].map((b) => cloud.ring(b));

const gather = (xy, idx, dim) => {
  const out = new Float64Array(idx.length * dim);
  idx.forEach((i, k) => { for (let d = 0; d < dim; d++) out[k * dim + d] = xy[i * dim + d]; });
  return out;
};

test('native tool is built', () => {
  assert.ok(existsSync(TOOL), `${TOOL} missing: build the native tree first (./run test does; or cmake --build <dir> --target rtl_native and set RTL_NATIVE_BUILD_DIR)`);
});

const SEG_PARAMS = [[2, 0.1, 0.5], [3, 0.1, 0.5], [1, 0.05, 0.2], [6, 0.2, 1.5]];
const clusters = { 2: [], 3: [] };

test('segment: identical labels and clusters, native vs wasm, on every real scan', { timeout: 120_000 }, () => {
  for (const [dim, scans] of [[2, scans2], [3, scans3]]) {
    for (const [step, lower, upper] of SEG_PARAMS) {
      const nat = native(['segment', step, lower, upper], scans, dim);
      scans.forEach((xy, k) => {
        const w = rtl.segment(xy, { dim, step, lowerBound: lower, upperBound: upper });
        assert.deepEqual(Array.from(w.labels), nat[k].labels, `dim ${dim} scan ${k} step ${step}: labels`);
        const flat = w.clusters.flatMap((c) => Array.from(c.indices));
        assert.deepEqual(flat, nat[k].indices, `dim ${dim} scan ${k}: cluster order and point order`);
        if (step === 3) for (const c of w.clusters) if (c.indices.length >= 3) clusters[dim].push(gather(xy, c.indices, dim));
      });
    }
  }
  assert.ok(clusters[2].length > 500 && clusters[3].length > 20, `${clusters[2].length} 2D and ${clusters[3].length} 3D clusters`);
});

const METHODS = ['ftls', 'aftls', 'itls', 'dp', 'rw'];
test('vectorize: identical results, native vs wasm, every method on every real cluster (2D, 3D lines, planes; split and strict)', { timeout: 300_000 }, () => {
  const opts = { sigma: 0.03, delta: 0.3, epsilon: 0.09, simplexShift: 1, maxIterations: 10000 };
  const runs = [];
  for (const dim of [2, 3]) for (const method of METHODS) runs.push({ dim, method, primitive: 'line', split: true });
  runs.push({ dim: 2, method: 'ftls', primitive: 'line', split: false }, { dim: 2, method: 'aftls', primitive: 'line', split: false });
  runs.push({ dim: 3, method: 'aftls', primitive: 'plane', split: true });
  let compared = 0, failedBoth = 0, broken = 0;
  for (const { dim, method, primitive, split } of runs) {
    const chains = clusters[dim];
    const nat = native(['vectorize', METHODS.indexOf(method), primitive === 'plane' ? 1 : 0, opts.sigma, opts.delta,
      opts.epsilon, opts.simplexShift, opts.maxIterations], chains, dim, split ? ['--split-corners'] : []);
    chains.forEach((xy, k) => {
      const w = rtl.vectorize(xy, { dim, method, primitive, split, ...opts });
      const n = nat[k], what = `${dim}D ${method} ${primitive}${split ? '' : ' strict'} chain ${k}`;
      assert.equal(w.ok, n.ok, `${what}: ok`);
      assert.equal(w.count, n.count, `${what}: count`);
      assert.deepEqual(Array.from(w.indices), n.indices, `${what}: ranges`);
      assert.deepEqual(Array.from(w.polylineOffsets), n.polylineOffsets, `${what}: polylines`);
      sameNumbers(w.breaks.flatMap((b) => [b.boundary, b.crossingDistance, b.delta]), n.breaks, `${what}: breaks`);
      const f = w.failure ? [w.failure.boundary, w.failure.crossingDistance, w.failure.delta] : [];
      sameNumbers(f, n.failure, `${what}: failure`);
      sameNumbers(w.segments, n.segments, `${what}: segments`);
      sameNumbers(w.params, n.params, `${what}: params`);
      // rms = sqrt(mean squared residual): near zero the sqrt magnifies last-bit differences, so compare squares.
      sameNumbers(w.rms.map((r) => r * r), n.rms.map((r) => r * r), `${what}: rms^2`);
      sameNumbers(w.polygons.flatMap((p) => Array.from(p)), n.polygonPoints, `${what}: polygons`);
      compared++;
      if (!w.ok) failedBoth++;
      if (w.breaks.length) broken++;
    });
  }
  console.log(`# native vs wasm: ${compared} vectorizations (${failedBoth} ok=false in both, ${broken} split), ${stats.numbers} numbers, ` +
    `${stats.identical} bit-identical, max relative difference ${stats.maxDiff}`);
});
