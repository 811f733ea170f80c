// The module keeps its input buffer, vectorizers and segmenters between calls (wasm/src/kept.h): a call that reuses
// them (after a larger input, a different method or settings, a failure, releaseBuffers(), or an input above the
// kept limit) gives exactly the result of the same call on a fresh module.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import init from 'rtl-wasm';
import { wallRing as ring } from './helpers.mjs';

const used = await init();

function polyline(n, seed, dim = 2) {
  let s = seed;
  const rnd = () => ((s = (s * 1103515245 + 12345) % 2147483648) / 2147483648);
  const xy = new Float64Array(dim * n);
  let x = 0, y = 0, a = 0;
  for (let i = 0; i < n; i++) {
    if (i % 150 === 0) a += (rnd() - 0.5) * 2.5;
    x += 0.01 * Math.cos(a); y += 0.01 * Math.sin(a);
    xy[dim * i] = x + (rnd() - 0.5) * 0.01;
    xy[dim * i + 1] = y + (rnd() - 0.5) * 0.01;
    if (dim === 3) xy[dim * i + 2] = 0.3 * Math.sin(i * 0.002) + (rnd() - 0.5) * 0.01;
  }
  return xy;
}

const small2 = polyline(2000, 11), big2 = polyline(20_000, 12);
const small3 = polyline(2000, 13, 3), big3 = polyline(20_000, 14, 3);
const calls = [
  ['ftls', (r, p) => r.vectorize(p, { method: 'ftls', sigma: 0.01, delta: 0.2 }), small2, big2],
  ['ftls strict', (r, p) => r.vectorize(p, { method: 'ftls', sigma: 0.01, delta: 0.05, split: false }), small2, big2],
  ['aftls', (r, p) => r.vectorize(p, { method: 'aftls', sigma: 0.01, delta: 0.2 }), small2, big2],
  ['itls', (r, p) => r.vectorize(p, { method: 'itls', sigma: 0.01 }), small2, big2],
  ['dp', (r, p) => r.vectorize(p, { method: 'dp', epsilon: 0.02 }), small2, big2],
  ['dp segment', (r, p) => r.vectorize(p, { method: 'dp', epsilon: 0.02, distance: 'segment' }), small2, big2],
  ['rw', (r, p) => r.vectorize(p, { method: 'rw', epsilon: 0.02 }), small2, big2],
  ['ftls 3D', (r, p) => r.vectorize(p, { dim: 3, method: 'ftls', sigma: 0.01 }), small3, big3],
  ['aftls 3D', (r, p) => r.vectorize(p, { dim: 3, method: 'aftls', sigma: 0.01 }), small3, big3],
  ['itls 3D', (r, p) => r.vectorize(p, { dim: 3, method: 'itls', sigma: 0.01 }), small3, big3],
  ['dp 3D', (r, p) => r.vectorize(p, { dim: 3, method: 'dp', epsilon: 0.02 }), small3, big3],
  ['planes', (r, p) => r.vectorize(p, { dim: 3, method: 'aftls', primitive: 'plane', sigma: 0.02 }), small3, big3],
  ['segment step 3', (r, p) => r.segment(p, { step: 3, lowerBound: 0.05, upperBound: 0.3 }), ring(2000), ring(20_000)],
  ['segment step 10', (r, p) => r.segment(p, { step: 10, lowerBound: 0.01, upperBound: 0.1 }), ring(2000), ring(20_000)],
  ['simplify', (r, p) => r.simplify(p, 0.02), small2, big2],
];

test('every kept vectorizer and segmenter: a reused one gives the fresh module\'s result (after a larger input and other settings)', async () => {
  // Grow every kept object with the large inputs first, and run the others in between.
  for (const [, f, , big] of calls) f(used, big);
  for (const [name, f, small, big] of calls) {
    const fresh = await init();
    const expected = f(fresh, small);
    assert.deepEqual(f(used, small), expected, `${name}: reused after a larger input`);
    assert.deepEqual(f(used, big), f(fresh, big), `${name}: grown by the fresh module too`);
    assert.deepEqual(f(used, small), expected, `${name}: again`);
  }
});

test('a failing call, releaseBuffers() and an input above the kept limit leave the next results unchanged', async () => {
  const fresh = await init();
  const dp = (r, p) => r.vectorize(p, { method: 'dp', epsilon: 0.02 });
  const seg = (r, p) => r.segment(p, { step: 3 });
  const expected = [dp(fresh, small2), seg(fresh, ring(3000))];
  assert.throws(() => used.vectorize(new Float64Array([0, 0, 1, Infinity]), { method: 'dp' }), RangeError);
  assert.deepEqual([dp(used, small2), seg(used, ring(3000))], expected, 'after a failure');
  used.releaseBuffers();
  assert.deepEqual([dp(used, small2), seg(used, ring(3000))], expected, 'after releaseBuffers');
  // 2^21 + 1 points: above the kept limit (its own input block, buffers released after the call).
  const huge = new Float64Array(2 * (2 ** 21 + 1));
  for (let i = 0; i < huge.length / 2; i++) { huge[2 * i] = i * 1e-3; huge[2 * i + 1] = Math.sin(i * 1e-3); }
  const h = used.vectorize(huge, { method: 'dp', epsilon: 0.01 });
  assert.equal(h.indices[2 * h.count - 1], huge.length / 2);
  assert.ok(h.count > 10 && h.rms.every((r) => r <= 0.01));
  assert.deepEqual([dp(used, small2), seg(used, ring(3000))], expected, 'after an input above the kept limit');
});

test('results are copies: later calls (which reuse the module\'s result block) do not change an earlier result', () => {
  const results = calls.map(([name, f, , big]) => [name, f(used, big)]);
  const snapshots = results.map(([, r]) => structuredClone(r));
  for (const [, f, small] of calls) f(used, small);
  for (const [, f, , big] of [...calls].reverse()) f(used, big);
  results.forEach(([name, r], k) => assert.deepEqual(r, snapshots[k], `${name}: changed by later calls`));
});
