// segment() (batch CAR segmenter) and StreamSegmenter (IA): known answers on synthetic scans, the seam, gaps, real
// CARMEN scans (complete merging, coverage), agreement of stream and batch, dispose / FinalizationRegistry, errors.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { execFileSync } from 'node:child_process';
import { readFileSync } from 'node:fs';
import { fileURLToPath } from 'node:url';
import init from 'rtl-wasm';
import { throwsWith } from './helpers.mjs';

const rtl = await init();

// 360 one-degree beams; arc k = beams 60k..60k+59 at radius radii[k].
function arcs(radii, dim = 2) {
  const out = [];
  for (let i = 0; i < 360; i++) {
    const a = i * Math.PI / 180, r = radii[Math.floor(i / 60)];
    out.push(r * Math.cos(a), r * Math.sin(a));
    if (dim === 3) out.push(0.5);
  }
  return new Float64Array(out);
}
const range = (b, e) => Array.from({ length: e - b }, (_, i) => b + i);

test('segment: six arcs -> six clusters with their index ranges; a gap stays unlabelled', () => {
  const xy = arcs([5, 3, 5, 3, 5, 3]);
  xy[2 * 10] = NaN;
  const s = rtl.segment(xy, { step: 3, lowerBound: 0.1, upperBound: 0.5 });
  assert.ok(s.labels instanceof Int32Array);
  assert.equal(s.labels.length, 360);
  assert.equal(s.clusters.length, 6);
  assert.equal(s.labels[10], -1);
  assert.deepEqual(Array.from(s.clusters[0].ranges), [0, 10, 11, 60]);
  assert.deepEqual(Array.from(s.clusters[0].indices), range(0, 60).filter((i) => i !== 10));
  for (let k = 1; k < 6; k++) {
    assert.deepEqual(Array.from(s.clusters[k].ranges), [60 * k, 60 * k + 60], `cluster ${k}`);
    assert.ok(s.clusters[k].indices instanceof Uint32Array);
  }
  for (let i = 0; i < 360; i++) if (i !== 10) assert.equal(s.labels[i], Math.floor(i / 60), `label ${i}`);
});

test('segment: +-Infinity in any coordinate is refused and NaN is a gap, at every position of short inputs', () => {
  // the check runs while the numbers are copied, four a step then one by one: every position of the step and of
  // the tail is covered
  for (const dim of [2, 3]) {
    for (let n = 1; n <= 7; n++) {
      const base = new Float64Array(dim * n).map((_, i) => 0.01 * i);
      for (let i = 0; i < dim * n; i++) {
        for (const bad of [Infinity, -Infinity]) {
          const xy = base.slice();
          xy[i] = bad;
          assert.throws(() => rtl.segment(xy, { dim }), (e) => e instanceof RangeError && e.message.includes(`at index ${i}`), `dim ${dim} n ${n} index ${i} ${bad}`);
        }
        const xy = base.slice();
        xy[i] = NaN;
        const s = rtl.segment(xy, { dim, lowerBound: 1, upperBound: 1 });
        const p = Math.floor(i / dim);
        assert.equal(s.labels[p], -1, `dim ${dim} n ${n} index ${i}: NaN makes point ${p} a gap`);
        for (let q = 0; q < n; q++) if (q !== p) assert.ok(s.labels[q] >= 0, `dim ${dim} n ${n}: point ${q} kept`);
      }
    }
  }
});

test('segment: a cluster across the seam starts with its end-of-scan part; 3D works the same', () => {
  for (const dim of [2, 3]) {
    const s = rtl.segment(arcs([5, 3, 5, 3, 5, 5], dim), { dim });
    assert.equal(s.clusters.length, 4, `dim ${dim}`);
    assert.deepEqual(Array.from(s.clusters[0].indices), [...range(240, 360), ...range(0, 60)]);
    assert.deepEqual(Array.from(s.clusters[0].ranges), [240, 360, 0, 60]);
    assert.equal(s.labels[359], 0);
    assert.equal(s.labels[60], 1);
  }
});

test('segment: thresholds follow the options (adaptive bound, origin)', () => {
  // Two returns 0.3 apart at range 20 in a 360-beam scan (the rest gaps): at step 2 the adaptive threshold is
  // 2 * 2pi/360 * 20 = 0.698, clamped to [lowerBound, upperBound].
  const pts = new Float64Array(720).fill(NaN);
  pts.set([20, 0, 20, 0.3]);
  const clusters = (o) => rtl.segment(pts, { step: 2, ...o }).clusters.length;
  assert.equal(clusters({ lowerBound: 0.1, upperBound: 0.5 }), 1);
  assert.equal(clusters({ lowerBound: 0.1, upperBound: 0.2 }), 2);
  assert.equal(clusters({ lowerBound: 0.1, upperBound: Infinity }), 1);
  assert.equal(clusters({ lowerBound: 0.31, upperBound: 0.31 }), 1);
  assert.equal(clusters({ lowerBound: 0.29, upperBound: 0.29 }), 2);
  // Origin next to the points: the adaptive part vanishes, the lower bound 0.1 decides -> split.
  assert.equal(clusters({ lowerBound: 0.1, upperBound: 0.5, origin: [20, 0.15] }), 2);
  // Step 1 threshold 0.349 would join them, but step 1 compares no previous point: one cluster per point.
  assert.equal(rtl.segment(pts, { step: 1, lowerBound: 0.1, upperBound: 0.5 }).clusters.length, 2);
  assert.deepEqual(rtl.segment([], {}).clusters, []);
  assert.deepEqual(Array.from(rtl.segment([NaN, NaN, NaN, 1]).labels), [-1, -1]);
});

test('segment: step s compares each point with up to s - 1 previous points; the default step 2 links neighbours', () => {
  // Points 0.05 apart along x at range ~10 in a 360-beam scan, with gaps (NaN) at 3 and at 6, 7.
  const pts = new Float64Array(720).fill(NaN);
  for (const i of [0, 1, 2, 4, 5, 8, 9]) pts.set([10 + 0.05 * i, 0], 2 * i);
  const runs = (o) => rtl.segment(pts, { lowerBound: 0.1, upperBound: 0.5, ...o }).clusters.map((c) => Array.from(c.indices));
  assert.deepEqual(runs({}), [[0, 1, 2], [4, 5], [8, 9]], 'default: consecutive points linked, a one-beam gap splits');
  assert.deepEqual(runs({ step: 2 }), runs({}), 'the default is step 2');
  assert.deepEqual(runs({ step: 1 }), [[0], [1], [2], [4], [5], [8], [9]], 'step 1 links nothing');
  assert.deepEqual(runs({ step: 3 }), [[0, 1, 2, 4, 5], [8, 9]], 'step 3 reaches across one gap, not two');
  assert.deepEqual(runs({ step: 4 }), [[0, 1, 2, 4, 5, 8, 9]], 'step 4 reaches across two');
});

// FLASER lines of a CARMEN log -> points (beam i at -pi/2 + i*res), max-range beams as NaN.
function carmenScans(name) {
  const text = readFileSync(new URL(`../data/${name}`, import.meta.url), 'utf8');
  return text.split('\n').filter((l) => l.startsWith('FLASER')).map((l) => {
    const t = l.trim().split(/\s+/).map(Number);
    const n = t[1], res = n % 2 ? Math.PI / (n - 1) : Math.PI / n;
    const xy = new Float64Array(2 * n);
    for (let i = 0; i < n; i++) {
      const r = t[2 + i], a = -Math.PI / 2 + i * res;
      const ok = r > 0 && r < 80;
      xy[2 * i] = ok ? r * Math.cos(a) : NaN;
      xy[2 * i + 1] = ok ? r * Math.sin(a) : NaN;
    }
    return xy;
  });
}

test('segment: real scans (intel, csail): every return in one cluster, complete merging, no close pair split', () => {
  for (const name of ['intel.log', 'csail.log']) {
    for (const [xy, step] of carmenScans(name).flatMap((scan) => [[scan, 2], [scan, 3]])) {
      const n = xy.length / 2, lower = 0.1, upper = 0.5;
      const s = rtl.segment(xy, { step, lowerBound: lower, upperBound: upper });
      const seen = new Uint8Array(n);
      s.clusters.forEach((c, k) => { for (const i of c.indices) { assert.equal(s.labels[i], k); seen[i]++; } });
      for (let i = 0; i < n; i++) assert.equal(seen[i], Number.isNaN(xy[2 * i]) ? 0 : 1, `${name}: point ${i} in exactly one cluster`);
      // The criterion (same formula as the C++ header): i joins j = i-k (k <= step - 1, cyclic) if
      // |pi-pj|^2 <= t(pi)^2 with t(pi) = clamp(step * 2pi/N * |pi|, lower, upper).
      const scaling = step * 2 * Math.PI / n;
      for (let i = 0; i < n; i++) {
        if (Number.isNaN(xy[2 * i])) continue;
        const t = Math.min(Math.max(scaling * Math.hypot(xy[2 * i], xy[2 * i + 1]), lower), upper);
        for (let k = 1; k < step; k++) {
          const j = (i - k + n) % n;
          if (Number.isNaN(xy[2 * j])) continue;
          const d2 = (xy[2 * i] - xy[2 * j]) ** 2 + (xy[2 * i + 1] - xy[2 * j + 1]) ** 2;
          if (d2 < t * t * (1 - 1e-12)) assert.equal(s.labels[i], s.labels[j], `${name}: close pair ${j},${i} split`);
        }
      }
    }
  }
});

const SEG_ERRORS = [
  ['points a string', () => rtl.segment('1,2'), TypeError, /segment: points must be/],
  ['odd length', () => rtl.segment([1, 2, 3]), RangeError, /segment: points has 3 numbers, not a multiple of dim 2/],
  ['Infinity', () => rtl.segment([1, 2, Infinity, 3]), RangeError, /segment: point 1 has a non-finite coordinate \(Infinity\)/],
  ['step 0', () => rtl.segment([1, 2], { step: 0 }), RangeError, /option step must be >= 1, got 0/],
  ['step 1.5', () => rtl.segment([1, 2], { step: 1.5 }), RangeError, /option step must be an integer/],
  ['negative lowerBound', () => rtl.segment([1, 2], { lowerBound: -1 }), RangeError, /option lowerBound must be >= 0/],
  ['upper < lower', () => rtl.segment([1, 2], { lowerBound: 0.4, upperBound: 0.2 }), RangeError, /upperBound \(0\.2\) must be >= lowerBound \(0\.4\)/],
  ['origin length', () => rtl.segment([1, 2], { origin: [0, 0, 0] }), RangeError, /option origin must have 2 numbers/],
  ['origin NaN', () => rtl.segment([1, 2], { origin: [0, NaN] }), RangeError, /option origin\[1\] must be finite/],
  ['origin a string', () => rtl.segment([1, 2], { origin: 'o' }), TypeError, /option origin must be a Float64Array/],
  ['unknown option', () => rtl.segment([1, 2], { steps: 2 }), TypeError, /unknown option "steps"/],
  ['dim 1', () => rtl.segment([1, 2], { dim: 1 }), RangeError, /option dim must be 2 or 3/],
];
for (const [name, f, type, re] of SEG_ERRORS) {
  test(`segment error: ${name}`, () => {
    throwsWith(f, type, re);
    assert.equal(rtl.segment([0, 0, 0.01, 0]).clusters.length, 1, 'works afterwards');
  });
}

test('StreamSegmenter: a stream of arcs closes clusters in order; flush closes the rest; nothing is lost', () => {
  const xy = arcs([5, 3, 5, 3, 5, 3]);
  const s = new rtl.StreamSegmenter({ step: 3, lowerBound: 0.1, upperBound: 0.5, scaling: 3 * 2 * Math.PI / 360 });
  assert.equal(s.dim, 2);
  assert.equal(s.disposed, false);
  const closed = [];
  for (let i = 0; i < 360; i += 45) {   // arbitrary chunks
    s.addPoints(xy.subarray(2 * i, 2 * (i + 45)));
    closed.push(...s.takeClosedClusters());
  }
  assert.equal(s.closedClustersAvailable, 0);
  assert.equal(closed.length, 5);
  assert.equal(s.aliveClustersAvailable, 1);
  assert.equal(s.aliveClusters()[0].length, 2 * 57, 'the last arc minus the 3 window points');
  s.flush();
  closed.push(...s.takeClosedClusters());
  assert.equal(closed.length, 6);
  closed.forEach((c, k) => {
    assert.ok(c instanceof Float64Array);
    assert.deepEqual(Array.from(c), Array.from(xy.subarray(120 * k, 120 * k + 120)), `cluster ${k} = arc ${k} in stream order`);
  });
  s.dispose();
  assert.equal(s.disposed, true);
  s.dispose();  // idempotent
});

test('StreamSegmenter: one call\'s clusters are disjoint views on one array; 3D coordinates exact; later calls leave them intact', () => {
  const pts = [1, 0, 0, 1, 0.01, 0, 8, 8, 8, 8, 8, 8.01, 20, 0, 1, 20, 0.01, 1, 20, 0.02, 1];
  const s = new rtl.StreamSegmenter({ dim: 3, step: 2 });
  s.addPoints(pts);
  s.flush();
  const taken = s.takeClosedClusters();
  assert.deepEqual(taken.map((c) => Array.from(c)), [pts.slice(0, 6), pts.slice(6, 12), pts.slice(12)]);
  assert.ok(taken.every((c) => c.buffer === taken[0].buffer), 'one buffer per call');
  assert.deepEqual(taken.map((c) => c.byteOffset), [0, 48, 96], 'consecutive, not overlapping');
  s.addPoints([5, 5, 5, 5, 5, 5.01, 5, 5, 5.02]);
  assert.deepEqual(s.aliveClusters().map((c) => Array.from(c)), [[5, 5, 5]], 'the point that left the 2-point window');
  s.flush();
  const next = s.takeClosedClusters();
  assert.deepEqual(next.map((c) => Array.from(c)), [[5, 5, 5, 5, 5, 5.01, 5, 5, 5.02]]);
  assert.notEqual(next[0].buffer, taken[0].buffer);
  assert.deepEqual(Array.from(taken[2]), pts.slice(12), 'an earlier call\'s cluster is unchanged');
  s.dispose();
});

// IA's window holds `step` points, CAR's step - 1: IA step s is CAR step s + 1 with the threshold scaling of CAR
// step s + 1, (s + 1) * 2pi / N.
test('StreamSegmenter: same clusters as segment() at step + 1 on real scans, scaling (step + 1) * 2pi / N (away from the seam)', () => {
  const xy = carmenScans('intel.log')[5];
  const n = xy.length / 2, step = 3;
  const batch = rtl.segment(xy, { step: step + 1, lowerBound: 0.1, upperBound: 0.5 });
  const s = new rtl.StreamSegmenter({ step, lowerBound: 0.1, upperBound: 0.5, scaling: (step + 1) * 2 * Math.PI / n });
  s.addPoints(xy);
  s.flush();
  const stream = s.takeClosedClusters().map((c) => Array.from(c).join(',')).sort();
  s.dispose();
  const wraps = batch.clusters.some((c) => c.ranges.length > 2 && c.ranges[0] > c.ranges[c.ranges.length - 1]);
  if (!wraps) {
    const expected = batch.clusters.map((c) => Array.from(c.indices).flatMap((i) => [xy[2 * i], xy[2 * i + 1]]).join(',')).sort();
    assert.deepEqual(stream, expected);
  } else {
    assert.ok(stream.length >= batch.clusters.length);
  }
});

test('StreamSegmenter: using Symbol.dispose; use after dispose is a TypeError; 3D; errors', () => {
  let leaked;
  {
    const s = new rtl.StreamSegmenter({ dim: 3 });
    s[Symbol.dispose]();
    leaked = s;
  }
  assert.equal(leaked.disposed, true);
  throwsWith(() => leaked.addPoints([0, 0, 0]), TypeError, /StreamSegmenter\.addPoints: the segmenter was disposed/);
  throwsWith(() => leaked.closedClustersAvailable, TypeError, /disposed/);
  const s = new rtl.StreamSegmenter({ dim: 3, step: 2 });
  s.addPoints([1, 0, 0, 1, 0.01, 0, 8, 8, 8, 8, 8, 8.01], [0, 0, 0]);
  s.flush();
  assert.deepEqual(s.takeClosedClusters().map((c) => c.length), [6, 6]);
  throwsWith(() => s.addPoints([1, 2]), RangeError, /StreamSegmenter\.addPoints: points has 2 numbers, not a multiple of dim 3/);
  throwsWith(() => s.addPoints([1, 2, 3], [0, 0]), RangeError, /option origin must have 3 numbers/);
  throwsWith(() => s.addPoints({}), TypeError, /StreamSegmenter\.addPoints: points must be/);
  s.dispose();
  throwsWith(() => new rtl.StreamSegmenter({ step: -1 }), RangeError, /StreamSegmenter: option step must be >= 1/);
  throwsWith(() => new rtl.StreamSegmenter({ scaling: NaN }), RangeError, /option scaling must be finite/);
  throwsWith(() => new rtl.StreamSegmenter('x'), TypeError, /StreamSegmenter: options must be an object/);
});

test('StreamSegmenter: forgotten segmenters are freed by the FinalizationRegistry (child process, --expose-gc)', { timeout: 60_000 }, () => {
  const script = `
    import init from 'rtl-wasm';
    const rtl = await init();
    const pts = new Float64Array(2000).map((_, i) => i * 0.001);
    const make = () => { for (let i = 0; i < 200; i++) { const s = new rtl.StreamSegmenter({ step: 50 }); s.addPoints(pts); } };
    make(); globalThis.gc(); await new Promise((r) => setTimeout(r, 50)); globalThis.gc(); await new Promise((r) => setTimeout(r, 50));
    const base = rtl.heapInUse();
    make();
    const grown = rtl.heapInUse();
    for (let k = 0; k < 10 && rtl.heapInUse() > base; k++) { globalThis.gc(); await new Promise((r) => setTimeout(r, 50)); }
    console.log(JSON.stringify({ base, grown, after: rtl.heapInUse() }));`;
  const out = execFileSync(process.execPath, ['--expose-gc', '--input-type=module', '-e', script],
    { cwd: fileURLToPath(new URL('../..', import.meta.url)), encoding: 'utf8' });
  const { base, grown, after } = JSON.parse(out);
  assert.ok(grown > base + 200 * 1000, `200 live segmenters hold memory (${base} -> ${grown})`);
  assert.ok(after <= base, `all freed after GC: ${after} <= ${base}`);
});
