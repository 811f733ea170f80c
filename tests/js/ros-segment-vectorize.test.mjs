// segmentAndVectorize(): a scan segmented and every cluster vectorized in one call equals segment() followed by
// vectorize() on each cluster's points, number for number, on the real scans of tests/data (CARMEN logs in 2D,
// Ouster rings in 3D), for every method, both FTLS modes and several minPoints; bad arguments are typed errors
// naming the function; repeated calls leave the wasm heap and memory as they were.
import test from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { join } from 'node:path';
import { fileURLToPath } from 'node:url';
import init from 'rtl-wasm';

const DATA = fileURLToPath(new URL('../data/', import.meta.url));
const rtl = await init();
const csail = rtl.readCarmenLog(readFileSync(join(DATA, 'csail.log')));
const intel = rtl.readCarmenLog(readFileSync(join(DATA, 'intel.log')));
const ouster = rtl.readOrganizedLidar(readFileSync(join(DATA, 'rellis3d-os1-4x2048.bin')), { beams: 4 });

const gather = (points, dim, idx) => {
  const out = new Float64Array(idx.length * dim);
  idx.forEach((k, j) => { for (let d = 0; d < dim; d++) out[j * dim + d] = points[k * dim + d]; });
  return out;
};

// The reference: segment(), then vectorize() on each cluster of >= minPoints points; compared field by field.
function compare(points, dim, seg, vec, minPoints, what) {
  const r = rtl.segmentAndVectorize(points, { dim, minPoints, segment: seg, vectorize: vec });
  const s = rtl.segment(points, { dim, ...seg });
  assert.deepEqual(r.labels, s.labels, `${what}: labels`);
  assert.deepEqual(r.clusters, s.clusters, `${what}: clusters`);
  const big = s.clusters.map((c, k) => [c, k]).filter(([c]) => c.indices.length >= minPoints);
  assert.deepEqual(Array.from(r.vectorized), big.map(([, k]) => k), `${what}: vectorized clusters`);
  let segments = 0, failures = 0;
  big.forEach(([c], j) => {
    const v = rtl.vectorize(gather(points, dim, c.indices), { dim, ...vec });
    const b = rtl.vectorizedCluster(r, j);
    for (const key of ['method', 'dim', 'primitive', 'ok', 'count', 'stride', 'breaks', 'failure'])
      assert.deepEqual(b[key], v[key], `${what}: cluster ${j}: ${key}`);
    for (const key of ['segments', 'indices', 'params', 'rms', 'polylineOffsets'])
      assert.deepEqual(Array.from(b[key]), Array.from(v[key]), `${what}: cluster ${j}: ${key}`);
    segments += v.count;
    if (v.failure) failures++;
  });
  assert.equal(r.failures.length, failures, `${what}: failures`);
  assert.equal(r.segmentOffsets.at(-1), segments, `${what}: segment total`);
  return { clusters: big.length, segments, failures };
}

const METHODS = [
  { method: 'ftls' }, { method: 'ftls', split: false }, { method: 'ftls', sigma: 0.01, delta: 0.05, split: false },
  { method: 'aftls' }, { method: 'itls' }, { method: 'dp' }, { method: 'dp', distance: 'segment', epsilon: 0.05 },
  { method: 'rw', epsilon: 0.05 },
];

test('segmentAndVectorize equals segment() + vectorize() per cluster on the CARMEN logs (every method, 2D)', () => {
  let clusters = 0, segments = 0, failures = 0;
  for (const [name, log] of [['csail', csail], ['intel', intel]]) {
    for (const [i, scan] of log.entries()) {
      for (const vec of METHODS) {
        for (const minPoints of [2, 3, 8]) {
          const t = compare(scan.points, 2, { step: 2 }, vec, minPoints, `${name} scan ${i} ${JSON.stringify(vec)} minPoints ${minPoints}`);
          clusters += t.clusters; segments += t.segments; failures += t.failures;
        }
      }
    }
  }
  // the comparison covered real work, strict failures included
  assert.ok(clusters > 5000 && segments > 5000, `${clusters} clusters, ${segments} segments`);
  assert.ok(failures > 0, 'no strict-mode failure was compared');
});

test('segmentAndVectorize equals segment() + vectorize() per cluster on Ouster rings (3D) and with other segment options', () => {
  for (let ring = 0; ring < ouster.beams; ring++) {
    const pts = ouster.ring(ring);
    for (const vec of [{ method: 'ftls' }, { method: 'aftls' }, { method: 'itls' }, { method: 'dp' }, { method: 'rw' }])
      compare(pts, 3, { step: 3, lowerBound: 0.2, upperBound: 1 }, vec, 3, `ring ${ring} ${vec.method}`);
  }
  const s = csail[0].points;
  compare(s, 2, { step: 4, lowerBound: 0.05, upperBound: Infinity, origin: [0.3, -0.2] }, { method: 'ftls', sigma: 0.05 }, 3, 'csail 0, step 4');
  compare(new Float64Array(0), 2, {}, { method: 'ftls' }, 3, 'no points');
  compare(new Float64Array([NaN, NaN, 1, 1]), 2, {}, { method: 'dp' }, 2, 'a gap and one point');
});

test('segmentAndVectorize: typed errors starting with its name, the module keeps working', () => {
  const p = csail[0].points;
  const cases = [
    [() => rtl.segmentAndVectorize(p), TypeError, /^segmentAndVectorize: options/],
    [() => rtl.segmentAndVectorize(p, {}), TypeError, /^segmentAndVectorize: option vectorize/],
    [() => rtl.segmentAndVectorize(p, { vectorize: { method: 'x' } }), RangeError, /^segmentAndVectorize: option method/],
    [() => rtl.segmentAndVectorize(p, { vectorize: { method: 'ftls', primitive: 'plane' } }), TypeError, /^segmentAndVectorize: unknown option "primitive"/],
    [() => rtl.segmentAndVectorize(p, { vectorize: { method: 'ftls' }, minPoints: 1 }), RangeError, /^segmentAndVectorize: option minPoints must be >= 2/],
    [() => rtl.segmentAndVectorize(p, { vectorize: { method: 'ftls' }, segment: { step: 0 } }), RangeError, /^segmentAndVectorize: option step/],
    [() => rtl.segmentAndVectorize(p, { vectorize: { method: 'ftls', sigma: -1 } }), RangeError, /^segmentAndVectorize: option sigma/],
    [() => rtl.segmentAndVectorize('x', { vectorize: { method: 'ftls' } }), TypeError, /^segmentAndVectorize: points/],
    [() => rtl.segmentAndVectorize([1, 2, 3], { vectorize: { method: 'ftls' } }), RangeError, /^segmentAndVectorize: points has 3 numbers/],
    [() => rtl.segmentAndVectorize([0, 0, 1, Infinity], { vectorize: { method: 'ftls' } }), RangeError, /^segmentAndVectorize: point 1 has a non-finite/],
    [() => rtl.segmentAndVectorize([0, 0, 1, 2e18], { vectorize: { method: 'ftls' } }), RangeError, /^segmentAndVectorize: point 1 has the coordinate 2e\+18/],
    [() => rtl.vectorizedCluster({}, 0), TypeError, /^vectorizedCluster: r must be/],
    [() => rtl.vectorizedCluster(rtl.segmentAndVectorize(p, { vectorize: { method: 'ftls' } }), 1e6), RangeError, /^vectorizedCluster: j must be/],
  ];
  for (const [f, type, re] of cases) assert.throws(f, (e) => e instanceof type && re.test(e.message), String(re));
  compare(p, 2, {}, { method: 'ftls' }, 3, 'after the errors');
});

test('segmentAndVectorize: repeated calls leave the wasm heap and memory as they were', () => {
  const run = () => { for (const s of csail) rtl.segmentAndVectorize(s.points, { vectorize: { method: 'ftls' } }); };
  run();
  const heap = rtl.heapInUse(), memory = rtl.memoryBytes();
  for (let k = 0; k < 20; k++) run();
  assert.equal(rtl.heapInUse(), heap);
  assert.equal(rtl.memoryBytes(), memory);
});

test('segmentAndVectorize: random points and options give results or typed errors only, the heap stays flat', () => {
  let seed = 7;
  const rand = () => ((seed = (seed * 1103515245 + 12345) % 2 ** 31) / 2 ** 31);
  const pick = (a) => a[Math.floor(rand() * a.length)];
  const heap = rtl.heapInUse();
  let results = 0, errors = 0;
  for (let k = 0; k < 400; k++) {
    const dim = pick([2, 3, 2, 3, 2, 4]);
    const n = Math.floor(rand() * 60);
    const pts = Array.from({ length: n * (dim === 4 ? 2 : dim) + (rand() < 0.05 ? 1 : 0) },
      () => (rand() < 0.004 ? pick([NaN, Infinity, 1e19, -0]) : (rand() - 0.5) * 10));
    const opts = {
      dim, minPoints: pick([2, 3, 5, 3, 3, 1, 2.5]),
      segment: pick([{}, { step: pick([1, 2, 3, 2, 0]) }, { lowerBound: rand() * 0.3, upperBound: pick([0.5, Infinity, 2, -1]) }]),
      vectorize: { method: pick(['ftls', 'aftls', 'itls', 'dp', 'rw', 'ftls', 'x']), sigma: pick([0.01, 0.03, 0.5, 0.03, 0]), split: pick([true, false]) },
    };
    try {
      const r = rtl.segmentAndVectorize(pts, opts);
      assert.equal(r.segmentOffsets.length, r.vectorized.length + 1);
      for (let j = 0; j < r.vectorized.length; j++) rtl.vectorizedCluster(r, j);
      results++;
    } catch (e) {
      assert.ok((e instanceof TypeError || e instanceof RangeError) && e.message.startsWith('segmentAndVectorize: '), `${e.name}: ${e.message}`);
      errors++;
    }
  }
  assert.ok(results > 50 && errors > 50, `${results} results, ${errors} errors`);
  assert.equal(rtl.heapInUse(), heap);
});

test('segmentAndVectorize: a result stays as it was after later calls (the module refills its kept output arrays)', () => {
  const snapshot = (r) => JSON.stringify(r, (k, v) => (ArrayBuffer.isView(v) ? Array.from(v) : v));
  const first = rtl.segmentAndVectorize(csail[3].points, { vectorize: { method: 'ftls' } });
  const before = snapshot(first);
  assert.ok(first.vectorized.length > 5 && first.segmentOffsets.at(-1) > 10, 'a scan with real work');
  // larger, smaller, 3D and other-method scans in between
  for (const s of [intel[0], csail[0], csail[7]]) rtl.segmentAndVectorize(s.points, { vectorize: { method: 'dp' }, minPoints: 2 });
  rtl.segmentAndVectorize(ouster.ring(1), { dim: 3, vectorize: { method: 'itls' } });
  assert.equal(snapshot(first), before);
  assert.equal(snapshot(rtl.segmentAndVectorize(csail[3].points, { vectorize: { method: 'ftls' } })), before);
});
