// pointBuffer(): the zero-copy input (a Float64Array on a block of wasm memory that vectorize, segment and simplify
// read in place). Results equal the copying path's; detached, foreign (on the module's memory outside the block)
// and too-short views are rejected with errors naming the function; 1000 calls on a view do not grow memory.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import init from 'rtl-wasm';
import { noisySemicircle, throwsWith, wallRing } from './helpers.mjs';

const rtl = await init();

// A noisy semicircle (r 8) of n points, and a scan with NaN gaps and steps between walls.
const semicircle = (n) => noisySemicircle(n, 7);
const scan = (n) => wallRing(n, 50, 37);
function helix(n) {
  const xyz = new Float64Array(3 * n);
  for (let i = 0; i < n; i++) xyz.set([Math.cos(i / 40), Math.sin(i / 40), i / 400], 3 * i);
  return xyz;
}
const viewOf = (a, dim = 2) => {
  const v = rtl.pointBuffer(a.length / dim, dim);
  v.set(a);
  return v;
};

const CALLS = [
  ['vectorize ftls', (p) => rtl.vectorize(p, { method: 'ftls', sigma: 0.03, delta: 3 }), () => semicircle(5000)],
  ['vectorize aftls', (p) => rtl.vectorize(p, { method: 'aftls', sigma: 0.03, delta: 3 }), () => semicircle(3000)],
  ['vectorize itls', (p) => rtl.vectorize(p, { method: 'itls', sigma: 0.03 }), () => semicircle(3000)],
  ['vectorize dp', (p) => rtl.vectorize(p, { method: 'dp', epsilon: 0.02 }), () => semicircle(5000)],
  ['vectorize dp segment distance', (p) => rtl.vectorize(p, { method: 'dp', epsilon: 0.02, distance: 'segment' }), () => semicircle(5000)],
  ['vectorize rw', (p) => rtl.vectorize(p, { method: 'rw', epsilon: 0.02 }), () => semicircle(5000)],
  ['vectorize ftls 3D', (p) => rtl.vectorize(p, { method: 'ftls', dim: 3, sigma: 0.01 }), () => helix(2000), 3],
  ['vectorize strict failure', (p) => rtl.vectorize(p, { method: 'ftls', sigma: 0.03, delta: 0.001, split: false }), () => semicircle(2000)],
  ['segment', (p) => rtl.segment(p, { step: 3, lowerBound: 0.1, upperBound: 0.5 }), () => scan(4000)],
  ['segment traced', (p) => rtl.segment(p, { step: 2, trace: true }), () => scan(500)],
  ['simplify', (p) => rtl.simplify(p, 0.02), () => semicircle(5000)],
  ['simplify highQuality 3D', (p) => rtl.simplify(p, 0.01, true, { dim: 3 }), () => helix(2000), 3],
];

test('a pointBuffer() view gives the results of the copying path', () => {
  for (const [name, f, make, dim = 2] of CALLS) {
    const a = make();
    const expected = f(a);
    assert.deepEqual(f(viewOf(a, dim)), expected, name);
    assert.deepEqual(f(viewOf(a, dim)), expected, `${name}, again`);
  }
});

test('a subarray of a view is read in place too, and views of a smaller pointBuffer() share the block', () => {
  const line = semicircle(3000), ring = scan(3000);
  const b = rtl.pointBuffer(6000, 2);
  b.set(line);
  b.set(ring, 6000);
  const dp = (p) => rtl.vectorize(p, { method: 'dp', epsilon: 0.02 });
  const car = (p) => rtl.segment(p, { step: 3 });
  assert.deepEqual(dp(b.subarray(0, 6000)), dp(line));
  assert.deepEqual(car(b.subarray(6000)), car(ring));
  const small = rtl.pointBuffer(10, 2);  // no larger than the block: the same memory
  assert.equal(small.byteOffset, b.byteOffset);
  assert.deepEqual(car(b.subarray(6000)), car(ring));
});

test('the input in the view is checked like a copied one', () => {
  const v = viewOf(semicircle(100));
  v[41] = NaN;
  throwsWith(() => rtl.vectorize(v, { method: 'dp' }), RangeError, /^vectorize: point 20 has a non-finite coordinate \(NaN\) at index 41$/);
  throwsWith(() => rtl.simplify(v, 1), RangeError, /^simplify: point 20 has a non-finite coordinate \(NaN\) at index 41$/);
  v[41] = 1e19;
  throwsWith(() => rtl.vectorize(v, { method: 'dp' }), RangeError, /^vectorize: point 20 has the coordinate 1e\+19 at index 41/);
  v[41] = Infinity;
  throwsWith(() => rtl.segment(v), RangeError, /^segment: point 20 has a non-finite coordinate \(Infinity\) at index 41$/);
});

test('too-short views: RangeError naming the function', () => {
  throwsWith(() => rtl.vectorize(rtl.pointBuffer(1, 2), { method: 'ftls' }), RangeError, /^vectorize: needs at least 2 points, got 1$/);
  throwsWith(() => rtl.vectorize(rtl.pointBuffer(0, 3), { method: 'dp', dim: 3 }), RangeError, /^vectorize: needs at least 2 points, got 0$/);
  const v = rtl.pointBuffer(10, 2).fill(1);
  throwsWith(() => rtl.segment(v.subarray(0, 5)), RangeError, /^segment: points has 5 numbers, not a multiple of dim 2/);
  throwsWith(() => rtl.simplify(v.subarray(0, 5), 1), RangeError, /^simplify: points has 5 numbers, not a multiple of dim 2/);
});

test('foreign views on the module memory and views after releaseBuffers(): TypeError naming the function', () => {
  rtl.releaseBuffers();  // the block then holds exactly the 200 numbers of v
  const v = viewOf(semicircle(100));
  const foreign = new Float64Array(v.buffer, 0, 200);  // on wasm memory, not in the block
  throwsWith(() => rtl.vectorize(foreign, { method: 'dp' }), TypeError, /^vectorize: points is a view on wasm memory outside/);
  throwsWith(() => rtl.segment(foreign), TypeError, /^segment: points is a view on wasm memory outside/);
  throwsWith(() => rtl.simplify(foreign, 1), TypeError, /^simplify: points is a view on wasm memory outside/);
  const beyond = new Float64Array(v.buffer, v.byteOffset, v.length + 2);  // runs past the block
  throwsWith(() => rtl.segment(beyond), TypeError, /^segment: points is a view on wasm memory outside/);
  rtl.releaseBuffers();  // frees the block: its views must not be read any more
  assert.ok(v.length > 0, 'freeing does not shrink memory: the view is still attached');
  throwsWith(() => rtl.vectorize(v, { method: 'dp' }), TypeError, /^vectorize: points is a view on wasm memory outside/);
  // a view of another instance's memory is just an array to this one: copied in
  return init().then((other) => {
    const w = other.pointBuffer(100, 2);
    w.set(semicircle(100));
    assert.deepEqual(rtl.vectorize(w, { method: 'dp' }), rtl.vectorize(semicircle(100), { method: 'dp' }));
  });
});

test('a view detached by memory growth: TypeError naming the function', async () => {
  const r = await init();
  const v = r.pointBuffer(100, 2);
  v.set(semicircle(100));
  const before = r.memoryBytes();
  r.vectorize(semicircle(1_500_000), { method: 'dp' });  // 24 MB copied in: memory grows
  assert.ok(r.memoryBytes() > before);
  assert.equal(v.length, 0, 'detached');
  throwsWith(() => r.vectorize(v, { method: 'dp' }), TypeError, /^vectorize: points is a detached view/);
  throwsWith(() => r.segment(v), TypeError, /^segment: points is a detached view/);
  throwsWith(() => r.simplify(v, 1), TypeError, /^simplify: points is a detached view/);
  assert.equal(r.pointBuffer(100, 2).length, 200, 'a new view is attached');
});

test('memory growth during a call on a view: the results are still right', async () => {
  const a = semicircle(200_000);
  const expected = rtl.simplify(a, 0.01);
  const r = await init();
  const v = r.pointBuffer(200_000, 2);
  v.set(a);
  assert.deepEqual(r.simplify(v, 0.01), expected);
  const w = r.pointBuffer(200_000, 2);
  w.set(a);
  const e2 = rtl.vectorize(a, { method: 'ftls', sigma: 0.001, delta: 0.0001, split: false });
  assert.deepEqual(r.vectorize(w, { method: 'ftls', sigma: 0.001, delta: 0.0001, split: false }), e2);
});

test('pointBuffer() argument errors', () => {
  throwsWith(() => rtl.pointBuffer('10'), TypeError, /^pointBuffer: n must be a number, got a string/);
  throwsWith(() => rtl.pointBuffer(-1), RangeError, /^pointBuffer: n must be an integer >= 0, got -1$/);
  throwsWith(() => rtl.pointBuffer(1.5), RangeError, /^pointBuffer: n must be an integer >= 0, got 1.5$/);
  throwsWith(() => rtl.pointBuffer(10, 4), RangeError, /^pointBuffer: option dim must be 2 or 3, got 4$/);
  throwsWith(() => rtl.pointBuffer(2 ** 40, 2), RangeError, /^pointBuffer: /);
  assert.equal(rtl.pointBuffer(10, 3).length, 30);
  assert.equal(rtl.pointBuffer(10).length, 20);
});

test('1000 calls on a view: memory does not grow, the view stays attached, nothing leaks', async () => {
  const r = await init();
  const h0 = r.heapInUse();
  const line = semicircle(2000), ring = scan(2000);
  const b = r.pointBuffer(4000, 2);
  b.set(line);
  b.set(ring, 4000);
  const lineV = b.subarray(0, 4000), ringV = b.subarray(4000);
  const calls = [
    () => r.vectorize(lineV, { method: 'ftls', sigma: 0.03, delta: 3 }),
    () => r.vectorize(lineV, { method: 'dp', epsilon: 0.02 }),
    () => r.segment(ringV, { step: 3 }),
    () => r.simplify(lineV, 0.02),
  ];
  const first = calls.map((f) => f());
  const mem = r.memoryBytes();
  for (let i = 0; i < 1000; i++) calls[i % 4]();
  assert.equal(r.memoryBytes(), mem);
  assert.equal(b.length, 8000, 'not detached');
  assert.deepEqual(calls.map((f) => f()), first);
  assert.equal(r.heapInUse(), h0);
});
