// vectorize() split mode: FTLS/AFTLS break the polyline where a corner cannot be met within delta
// (the JS default), so real clusters never come back empty; split: false is RTL's strict behaviour, whose failure
// names the corner. polylineOffsets/breaks/failure for every method; drawings with several polylines per cluster.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import init from 'rtl-wasm';
import { near, throwsWith } from './helpers.mjs';

const rtl = await init();
const L = [0, 0, 1, 0, 2, 0, 3, 0, 3, 1, 3, 2, 3, 3];  // noise-free L: fails in strict mode at the defaults

test('split (default): the noise-free L gives two polylines, the break at the corner with its numbers', () => {
  for (const method of ['ftls', 'aftls']) {
    const v = rtl.vectorize(L, { method });
    assert.equal(v.ok, true, method);
    assert.equal(v.count, 2);
    assert.deepEqual(Array.from(v.indices), [0, 3, 3, 7]);
    assert.deepEqual(Array.from(v.polylineOffsets), [0, 1, 2], 'two polylines of one segment');
    assert.ok(v.polylineOffsets instanceof Uint32Array);
    // Lines y = 0 (points 0-2) and x = 3 (points 3-6) cross at (3, 0), 0.5 from the middle (2.5, 0) of points 2, 3.
    assert.equal(v.breaks.length, 1);
    assert.equal(v.breaks[0].boundary, 3);
    near(v.breaks[0].crossingDistance, 0.5, 1e-12, 'crossing distance');
    assert.equal(v.breaks[0].delta, 0.3);
    assert.equal(v.failure, null);
    assert.deepEqual(Array.from(v.segments).map((x) => Math.round(x * 1e9) / 1e9), [0, 0, 2, 0, 3, 0, 3, 3]);
  }
});

test('split: false is strict: no segments, and failure names the corner (message starts with vectorize:)', () => {
  for (const method of ['ftls', 'aftls']) {
    const v = rtl.vectorize(L, { method, split: false });
    assert.equal(v.ok, false);
    assert.equal(v.count, 0);
    assert.deepEqual(Array.from(v.polylineOffsets), [0, 0]);
    assert.deepEqual(v.breaks, []);
    assert.ok(v.failure && Number.isInteger(v.failure.boundary) && v.failure.boundary > 0 && v.failure.boundary < 7);
    assert.ok(v.failure.crossingDistance > v.failure.delta, 'the corner is missed by more than delta');
    assert.equal(v.failure.delta, 0.3);
    assert.match(v.failure.message, new RegExp(`^vectorize: no polyline within sigma 0.03 meets delta 0.3 at chain index ${v.failure.boundary}: `));
    // A delta above the crossing distance meets it: strict mode then succeeds with one polyline.
    const ok = rtl.vectorize(L, { method, split: false, delta: 0.6 });
    assert.equal(ok.ok, true);
    assert.equal(ok.failure, null);
    assert.deepEqual(Array.from(ok.polylineOffsets), [0, ok.count]);
  }
});

test('other methods: one polyline, no breaks, no failure; split is checked', () => {
  for (const [dim, method] of [[2, 'itls'], [2, 'dp'], [2, 'rw'], [3, 'ftls'], [3, 'aftls'], [3, 'itls'], [3, 'dp']]) {
    const pts = dim === 2 ? L : L.flatMap((v, i) => (i % 2 ? [v, 0] : [v]));
    const v = rtl.vectorize(pts, { dim, method, sigma: 0.01, epsilon: 0.01 });
    assert.ok(v.ok, `${dim}D ${method}`);
    assert.deepEqual(Array.from(v.polylineOffsets), [0, v.count], `${dim}D ${method}`);
    assert.deepEqual(v.breaks, []);
    assert.equal(v.failure, null);
  }
  throwsWith(() => rtl.vectorize(L, { method: 'ftls', split: 1 }), TypeError, /^vectorize: option split must be a boolean, got the number 1$/);
});

// Every cluster of >= 3 points of every CARMEN scan in tests/data, at the package's defaults.
const chains = [];
for (const f of ['intel.log', 'csail.log']) {
  for (const scan of rtl.readCarmenLog(readFileSync(new URL(`../data/${f}`, import.meta.url)))) {
    for (const c of rtl.segment(scan.points).clusters) {
      if (c.indices.length < 3) continue;
      chains.push(Float64Array.from(Array.from(c.indices).flatMap((i) => [scan.points[2 * i], scan.points[2 * i + 1]])));
    }
  }
}

// Whether the chain splits into consecutive ranges of >= 2 points, each with a TLS RMS below sigma (2 points always).
function partitionExists(xy, sigma) {
  const n = xy.length / 2, ok = new Array(n + 1).fill(false);
  ok[0] = true;
  for (let e = 2; e <= n; e++) {
    for (let b = 0; b + 2 <= e && !ok[e]; b++) {
      if (ok[b] && (e - b === 2 || rtl.fitLine(xy.subarray(2 * b, 2 * e)).rms < sigma)) ok[e] = true;
    }
  }
  return ok[n];
}

test('real scans: split mode never comes back empty; polylines cover the chain; strict results are kept as they are', { timeout: 120_000 }, () => {
  assert.ok(chains.length > 300, `${chains.length} clusters`);
  let strictFailed = 0, broken = 0, noPartition = 0;
  for (const method of ['ftls', 'aftls']) {
    chains.forEach((xy, k) => {
      const what = `${method} chain ${k}`;
      const v = rtl.vectorize(xy, { method });
      const strict = rtl.vectorize(xy, { method, split: false });
      const n = xy.length / 2;
      // Split mode never comes back empty: a valid chain always gets segments.
      assert.equal(v.ok, true, `${what}: split mode has a result (${n} points)`);
      assert.equal(v.failure, null, `${what}: no failure in split mode`);
      const noPartitionHere = !strict.ok && n <= 9 && !partitionExists(xy, 0.03);
      const off = Array.from(v.polylineOffsets);
      assert.equal(off[0], 0);
      assert.equal(off[off.length - 1], v.count);
      for (let p = 1; p < off.length; p++) assert.ok(off[p] > off[p - 1], `${what}: polylines are not empty`);
      assert.equal(v.breaks.length, off.length - 2, `${what}: one break between polylines`);
      v.breaks.forEach((b, p) => {
        assert.equal(b.boundary, v.indices[2 * off[p + 1]], `${what}: break ${p} is where polyline ${p + 1} starts`);
        assert.ok(b.crossingDistance > b.delta && b.delta === 0.3, `${what}: a break only where delta cannot be met`);
      });
      // Ranges in order and covering the chain: consecutive where a partition exists; where none does (an odd chain
      // whose triples do not fit sigma, checked exhaustively with fitLine), neighbouring ranges may share one point.
      assert.equal(v.indices[0], 0);
      assert.equal(v.indices[2 * v.count - 1], n);
      let shared = 0;
      for (let s = 1; s < v.count; s++) {
        const gap = v.indices[2 * s - 1] - v.indices[2 * s];
        assert.ok(gap === 0 || (gap === 1 && noPartitionHere), `${what}: range ${s} starts at the previous end (or shares its last point only where no partition exists)`);
        shared += gap;
      }
      if (noPartitionHere) { assert.ok(shared >= 1, `${what}: no partition exists, so ranges share a point`); noPartition++; }
      for (let p = 0; p + 1 < off.length; p++) {
        for (let s = off[p] + 1; s < off[p + 1]; s++) {
          assert.deepEqual([v.segments[4 * s], v.segments[4 * s + 1]], [v.segments[4 * s - 2], v.segments[4 * s - 1]], `${what}: polyline ${p} is connected`);
        }
      }
      for (const r of v.rms) assert.ok(r < 0.03, `${what}: rms ${r} within sigma`);
      if (strict.ok) {
        assert.deepEqual(v, strict, `${what}: where strict mode succeeds, split mode gives the same result`);
      } else {
        strictFailed++;
        assert.ok(v.breaks.length >= 1 || noPartitionHere, `${what}: strict failed at a corner, so the split result breaks somewhere`);
        assert.ok(strict.failure && strict.failure.message.startsWith('vectorize: '), `${what}: strict failure explained`);
        assert.equal(strict.count, 0);
      }
      if (v.breaks.length) broken++;
    });
  }
  console.log(`# ${chains.length} clusters x 2 methods: strict failed on ${strictFailed}, split broke ${broken}, ` +
    `no partition within sigma at all (covered with a shared point): ${noPartition}`);
  assert.ok(strictFailed > 0 && noPartition > 0, 'the real scans exercise both a break and a shared-point cover');
});

test('toSvg/toTikz draw several polylines per cluster: one line per segment, nothing across a break', () => {
  const v = rtl.vectorize(L, { method: 'ftls' });
  const svg = rtl.toSvg({ points: L, labels: new Array(7).fill(0), segments: v.segments });
  assert.equal((svg.match(/<line /g) || []).length, v.count);
  const tikz = rtl.toTikz({ points: L, segments: v.segments }, { standalone: false });
  const draws = [...tikz.matchAll(/\\draw\[[^\]]*\] \(([-\d.]+),([-\d.]+)\) -- \(([-\d.]+),([-\d.]+)\);/g)].map((m) => m.slice(1).map(Number));
  assert.deepEqual(draws, [[0, 0, 2, 0], [3, 0, 3, 3]], 'the two polylines, not joined from (2,0) to (3,0)');
});
