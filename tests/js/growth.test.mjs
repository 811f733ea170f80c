// The kept buffers' growth path: the module keeps its point vectors, vectorizers and segmenter between calls
// (wasm/src/kept.h), so a call larger than the one before grows them (and a smaller one leaves stale points
// beyond its end). Calls alternating small and large sizes must give exactly the results of a fresh module's first
// call on the same input, for segment (2D, 3D), vectorize (every method, 2D and 3D) and fitLine.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import init from 'rtl-wasm';
import { noisySemicircle } from './helpers.mjs';

// Small, large, small, larger, ... (the kept vectors shrink and grow again); each size has its own data.
const SIZES = [50, 20_000, 30, 60_000, 7, 100_000, 50, 60_000, 2, 20_000];

// A closed scan with NaN gaps and steps between walls (clusters, one over the seam); `shift` varies the data.
function scan(n, shift) {
  const xy = new Float64Array(2 * n);
  for (let i = 0; i < n; i++) {
    const a = (2 * Math.PI * i) / n, r = 2 + ((Math.floor((i + shift) / 40) * 7) % 11);
    const gap = (i + shift) % 97 === 0;
    xy[2 * i] = gap ? NaN : r * Math.cos(a);
    xy[2 * i + 1] = gap ? NaN : r * Math.sin(a);
  }
  return xy;
}
function helix(n, shift) {
  const xyz = new Float64Array(3 * n);
  for (let i = 0; i < n; i++) xyz.set([Math.cos(i / 40 + shift), Math.sin(i / 40 + shift), i / 400], 3 * i);
  return xyz;
}
function scan3(n, shift) {
  const xy = scan(n, shift), xyz = new Float64Array(3 * n);
  for (let i = 0; i < n; i++) xyz.set([xy[2 * i], xy[2 * i + 1], 0.5], 3 * i);
  return xyz;
}

const CALLS = [
  ['segment', (r, p) => r.segment(p, { step: 3 }), scan],
  ['segment step 1', (r, p) => r.segment(p, { step: 1, lowerBound: 0.05, upperBound: 0.2 }), scan],
  ['segment 3D', (r, p) => r.segment(p, { dim: 3, step: 3 }), scan3],
  ['vectorize ftls', (r, p) => r.vectorize(p, { method: 'ftls', sigma: 0.03, delta: 3 }), noisySemicircle],
  ['vectorize aftls', (r, p) => r.vectorize(p, { method: 'aftls', sigma: 0.03, delta: 3 }), noisySemicircle],
  ['vectorize itls', (r, p) => r.vectorize(p, { method: 'itls', sigma: 0.03 }), noisySemicircle],
  ['vectorize dp', (r, p) => r.vectorize(p, { method: 'dp', epsilon: 0.02 }), noisySemicircle],
  ['vectorize dp segment distance', (r, p) => r.vectorize(p, { method: 'dp', epsilon: 0.02, distance: 'segment' }), noisySemicircle],
  ['vectorize rw', (r, p) => r.vectorize(p, { method: 'rw', epsilon: 0.02 }), noisySemicircle],
  ['vectorize ftls 3D', (r, p) => r.vectorize(p, { method: 'ftls', dim: 3, sigma: 0.01 }), helix],
  ['vectorize dp 3D', (r, p) => r.vectorize(p, { method: 'dp', dim: 3, epsilon: 0.01 }), helix],
  ['fitLine', (r, p) => r.fitLine(p), noisySemicircle],
];

test('calls alternating small and large inputs equal a fresh module\'s first calls', async () => {
  // The expected results: for each size a fresh module, whose kept objects have never held another size.
  const inputs = CALLS.map(([, , make]) => SIZES.map((n, k) => make(n, k + 1)));
  const expected = CALLS.map(() => []);
  for (let k = 0; k < SIZES.length; k++) {
    const fresh = await init();
    CALLS.forEach(([, f], c) => expected[c].push(f(fresh, inputs[c][k])));
  }
  const rtl = await init();
  for (let round = 0; round < 2; round++) {  // the second round starts on buffers already grown to the largest size
    for (let k = 0; k < SIZES.length; k++) {
      CALLS.forEach(([name, f], c) => {
        assert.deepEqual(f(rtl, inputs[c][k]), expected[c][k], `${name}, ${SIZES[k]} points (call ${k}, round ${round})`);
      });
    }
  }
  // the data are not degenerate: the large calls found structure
  const large = SIZES.indexOf(100_000);
  assert.ok(expected[0][large].clusters.length > 10, 'segment: clusters');
  assert.ok(expected[3][large].count > 3 && expected[6][large].count > 10, 'vectorize: segments');
});
