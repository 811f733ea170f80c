// segment() and vectorize() with { view: true }: the result arrays are views on the module's result block in wasm
// memory instead of copies (the output counterpart of pointBuffer()). They equal the default results exactly, on
// copied and on pointBuffer() inputs, traced or not; they are valid until the next segment/vectorize/simplify call or
// releaseBuffers(), are detached by memory growth, and many view calls neither grow memory nor leak.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import init from 'rtl-wasm';
import { noisySemicircle, throwsWith } from './helpers.mjs';

const rtl = await init();

const semicircle = (n) => noisySemicircle(n, 5);
// A closed scan with NaN gaps and steps between walls (many clusters, one wrapping the seam).
function scan(n) {
  const xy = new Float64Array(2 * n);
  for (let i = 0; i < n; i++) {
    const a = (2 * Math.PI * i) / n, r = 2 + ((Math.floor((i + 20) / 60) * 7) % 11);
    xy[2 * i] = i % 41 === 0 ? NaN : r * Math.cos(a);
    xy[2 * i + 1] = i % 41 === 0 ? NaN : r * Math.sin(a);
  }
  return xy;
}
// 3D: rings of a cylinder-like scan with gaps (segment), a helix (lines), two walls (planes).
function scan3(n) {
  const xyz = new Float64Array(3 * n);
  for (let i = 0; i < n; i++) {
    const a = (2 * Math.PI * i) / n, r = 3 + ((Math.floor(i / 80) * 5) % 7);
    xyz.set(i % 53 === 0 ? [NaN, NaN, NaN] : [r * Math.cos(a), r * Math.sin(a), 0.2 * Math.sin(5 * a)], 3 * i);
  }
  return xyz;
}
function helix(n) {
  const xyz = new Float64Array(3 * n);
  for (let i = 0; i < n; i++) xyz.set([Math.cos(i / 40), Math.sin(i / 40), i / 400], 3 * i);
  return xyz;
}
function walls(n) {
  const xyz = new Float64Array(3 * n);
  for (let i = 0; i < n; i++) {
    const t = i / n, u = (i % 20) / 20;
    xyz.set(t < 0.5 ? [2 * t, 0, u] : [1, 2 * (t - 0.5), u], 3 * i);
  }
  return xyz;
}

// [name, call(points, extraOptions), input, dim]
const CALLS = [
  ['segment 2D', (p, o) => rtl.segment(p, { step: 3, lowerBound: 0.1, upperBound: 0.5, ...o }), scan(6000), 2],
  ['segment 2D step 1 (no clusters joined)', (p, o) => rtl.segment(p, { step: 1, ...o }), scan(500), 2],
  ['segment 3D', (p, o) => rtl.segment(p, { dim: 3, step: 3, origin: [0, 0, 0.1], ...o }), scan3(4000), 3],
  ['segment traced', (p, o) => rtl.segment(p, { step: 2, trace: true, ...o }), scan(400), 2],
  ['segment of only gaps', (p, o) => rtl.segment(p, o), new Float64Array(8).fill(NaN), 2],
  ['segment of no points', (p, o) => rtl.segment(p, o), new Float64Array(0), 2],
  ['vectorize ftls', (p, o) => rtl.vectorize(p, { method: 'ftls', sigma: 0.03, delta: 3, ...o }), semicircle(5000), 2],
  ['vectorize ftls split', (p, o) => rtl.vectorize(p, { method: 'ftls', sigma: 0.003, delta: 0.01, ...o }), semicircle(3000), 2],
  ['vectorize ftls strict failure', (p, o) => rtl.vectorize(p, { method: 'ftls', sigma: 0.03, delta: 0.001, split: false, ...o }), semicircle(2000), 2],
  ['vectorize aftls', (p, o) => rtl.vectorize(p, { method: 'aftls', sigma: 0.03, delta: 3, ...o }), semicircle(2000), 2],
  ['vectorize itls', (p, o) => rtl.vectorize(p, { method: 'itls', sigma: 0.03, ...o }), semicircle(3000), 2],
  ['vectorize dp', (p, o) => rtl.vectorize(p, { method: 'dp', epsilon: 0.02, ...o }), semicircle(5000), 2],
  ['vectorize dp segment distance', (p, o) => rtl.vectorize(p, { method: 'dp', epsilon: 0.02, distance: 'segment', ...o }), semicircle(5000), 2],
  ['vectorize rw', (p, o) => rtl.vectorize(p, { method: 'rw', epsilon: 0.02, ...o }), semicircle(5000), 2],
  ['vectorize dp traced', (p, o) => rtl.vectorize(p, { method: 'dp', epsilon: 0.05, trace: true, ...o }), semicircle(300), 2],
  ['vectorize ftls traced', (p, o) => rtl.vectorize(p, { method: 'ftls', sigma: 0.03, delta: 3, trace: true, ...o }), semicircle(300), 2],
  ['vectorize ftls 3D', (p, o) => rtl.vectorize(p, { method: 'ftls', dim: 3, sigma: 0.01, ...o }), helix(2000), 3],
  ['vectorize dp 3D', (p, o) => rtl.vectorize(p, { method: 'dp', dim: 3, epsilon: 0.01, ...o }), helix(2000), 3],
  ['vectorize planes', (p, o) => rtl.vectorize(p, { method: 'aftls', dim: 3, primitive: 'plane', sigma: 0.02, ...o }), walls(2000), 3],
];

// Every typed array of a result (labels, cluster indices and ranges; vectorize's arrays and polygons).
function arraysOf(r) {
  if (r.labels) return [r.labels, ...r.clusters.flatMap((c) => [c.indices, c.ranges])];
  return [r.segments, r.indices, r.params, r.rms, r.polylineOffsets, ...r.polygons];
}

test('view results equal the default results exactly, on copied and on pointBuffer() inputs, 2D and 3D', () => {
  for (const [name, f, a, dim] of CALLS) {
    const expected = f(a, {});
    const got = f(a, { view: true });
    assert.deepEqual(got, expected, `${name}: copied input`);
    const buf = rtl.pointBuffer(a.length / dim, dim);
    buf.set(a);
    const inPlace = f(buf, { view: true });
    assert.deepEqual(inPlace, expected, `${name}: pointBuffer input`);
    // the views are on the module's memory (the buffer pointBuffer()'s view is on), the copies are not
    for (const x of arraysOf(inPlace)) assert.equal(x.buffer, buf.buffer, `${name}: a view on wasm memory`);
    for (const x of arraysOf(f(buf, {}))) assert.notEqual(x.buffer, buf.buffer, `${name}: a copy`);
  }
});

test('a view stays valid across calls that do not fill the result block', () => {
  const ring = scan(3000);
  const expected = rtl.segment(ring, { step: 3 });
  const got = rtl.segment(ring, { step: 3, view: true });
  rtl.fitLine(semicircle(100));
  rtl.toSvg({ points: ring.subarray(0, 200), labels: got.labels.subarray(0, 100) });
  rtl.pointBuffer(3000, 2).set(ring);
  const s = new rtl.StreamSegmenter();
  s.addPoints(ring);
  s.dispose();
  assert.deepEqual(got, expected);
});

test('the next call\'s results do not depend on what was written into an earlier view', () => {
  const ring = scan(3000), line = semicircle(3000);
  const seg = rtl.segment(ring, { step: 3 }), vec = rtl.vectorize(line, { method: 'dp', epsilon: 0.02 });
  for (let k = 0; k < 3; k++) {
    const a = rtl.segment(ring, { step: 3, view: true });
    for (const x of arraysOf(a)) x.fill(7);
    const b = rtl.vectorize(line, { method: 'dp', epsilon: 0.02, view: true });
    for (const x of arraysOf(b)) x.fill(7);
    assert.deepEqual(rtl.segment(ring, { step: 3 }), seg);
    assert.deepEqual(rtl.vectorize(line, { method: 'dp', epsilon: 0.02, view: true }), vec);
  }
});

test('after the next call a view no longer holds its result (a slice() taken before it does)', () => {
  // vectorize's arrays live in the result block, which the next call of the same layout refills in place: an old
  // view then shows the new call's numbers (in general: anything, see index.d.ts).
  const line = semicircle(4000), moved = line.map((v, i) => (i % 2 ? v : v + 1));
  const expected = rtl.vectorize(line, { method: 'dp', epsilon: 0.05 });
  const first = rtl.vectorize(line, { method: 'dp', epsilon: 0.05, view: true });
  const kept = first.segments.slice();
  const second = rtl.vectorize(moved, { method: 'dp', epsilon: 0.05, view: true });
  assert.equal(second.count, first.count);
  assert.equal(first.segments.byteOffset, second.segments.byteOffset, 'the same place in the block');
  assert.deepEqual(first.segments, second.segments, 'the old view shows the new numbers');
  assert.equal(second.segments[0], kept[0] + 1);
  assert.deepEqual(kept, expected.segments, 'the slice is the first result');
});

test('releaseBuffers() frees the result block: the views pin no memory', async () => {
  const r = await init();
  const h0 = r.heapInUse();
  const ring = scan(5000), line = semicircle(5000);
  const a = r.segment(ring, { step: 3, view: true });
  const b = r.vectorize(line, { method: 'ftls', sigma: 0.03, delta: 3, view: true });
  assert.ok(a.labels.length === 5000 && b.count > 0);
  assert.equal(r.heapInUse(), h0, 'released with views alive');
  const expected = r.segment(ring, { step: 3 });  // first: the next call invalidates a view
  assert.deepEqual(r.segment(ring, { step: 3, view: true }), expected);
});

test('memory growth detaches the views (length 0)', async () => {
  const r = await init();
  const seg = r.segment(scan(3000), { step: 3, view: true });
  const vec = r.vectorize(walls(2000), { method: 'aftls', dim: 3, primitive: 'plane', sigma: 0.02, view: true });
  assert.ok(seg.labels.length === 3000 && seg.clusters.length > 1 && vec.polygons.length > 0);
  const before = r.memoryBytes();
  r.pointBuffer(1_500_000, 2);  // 24 MB: memory grows
  assert.ok(r.memoryBytes() > before);
  for (const x of [...arraysOf(seg), ...arraysOf(vec)]) assert.equal(x.length, 0, 'detached');
  for (const x of [...arraysOf(seg), ...arraysOf(vec)]) assert.equal(x.byteLength, 0, 'detached');
});

test('a view result passed back as input is rejected (the call would overwrite it): TypeError', () => {
  const v = rtl.vectorize(semicircle(500), { method: 'dp', epsilon: 0.02, view: true });
  throwsWith(() => rtl.vectorize(v.segments, { method: 'dp' }), TypeError, /^vectorize: points is a view on wasm memory outside the current pointBuffer\(\) block$/);
  throwsWith(() => rtl.segment(v.params), TypeError, /^segment: points is a view on wasm memory outside/);
  // a copy of it is an ordinary input
  assert.equal(rtl.vectorize(v.segments.slice(), { method: 'dp' }).ok, true);
});

test('bad view option values: TypeError naming the function; undefined and false give copies', () => {
  const line = semicircle(100), ring = scan(100);
  for (const bad of [1, 0, 'true', null, {}, [true]]) {
    throwsWith(() => rtl.segment(ring, { view: bad }), TypeError, /^segment: option view must be a boolean, got /);
    throwsWith(() => rtl.vectorize(line, { method: 'dp', view: bad }), TypeError, /^vectorize: option view must be a boolean, got /);
  }
  throwsWith(() => rtl.segment(ring, { view: 1 }), TypeError, /^segment: option view must be a boolean, got the number 1$/);
  const mem = rtl.pointBuffer(0).buffer;
  for (const view of [undefined, false]) {
    for (const x of arraysOf(rtl.segment(ring, { view }))) assert.notEqual(x.buffer, mem);
    for (const x of arraysOf(rtl.vectorize(line, { method: 'dp', view }))) assert.notEqual(x.buffer, mem);
  }
  // a failing call with view: true leaves the module working
  throwsWith(() => rtl.segment(new Float64Array([0, 0, Infinity, 1]), { view: true }), RangeError, /^segment: point 1 has a non-finite coordinate \(Infinity\)/);
  const expected = rtl.segment(ring);
  assert.deepEqual(rtl.segment(ring, { view: true }), expected);
});

test('1000 view calls: memory does not grow, the input view stays attached, nothing leaks', async () => {
  const r = await init();
  const h0 = r.heapInUse();
  const line = semicircle(3000), ring = scan(3000), xyz = scan3(2000);
  const b = r.pointBuffer(6000, 2);
  b.set(line);
  b.set(ring, 6000);
  const lineV = b.subarray(0, 6000), ringV = b.subarray(6000);
  const calls = [
    (o) => r.segment(ringV, { step: 3, ...o }),
    (o) => r.vectorize(lineV, { method: 'ftls', sigma: 0.03, delta: 3, ...o }),
    (o) => r.vectorize(lineV, { method: 'dp', epsilon: 0.02, ...o }),
    (o) => r.segment(xyz, { dim: 3, step: 3, ...o }),
    (o) => r.vectorize(lineV, { method: 'dp', epsilon: 0.05, trace: true, ...o }),
  ];
  const expected = calls.map((f) => f({}));
  const mem = r.memoryBytes();
  for (let i = 0; i < 1000; i++) {
    const k = i % calls.length, got = calls[k]({ view: true });
    if (i < 2 * calls.length) assert.deepEqual(got, expected[k]);
  }
  assert.equal(r.memoryBytes(), mem);
  assert.equal(b.length, 12000, 'not detached');
  calls.forEach((f, k) => assert.deepEqual(f({ view: true }), expected[k]));
  assert.equal(r.heapInUse(), h0);
});
