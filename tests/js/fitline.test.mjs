// The package from ES modules: loading through the package name, the TLS line fit against known answers, every
// error case, and 100,000 failing calls that leave the wasm heap, memory and stack where they were.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import init, { init as namedInit } from 'rtl-wasm';
import { memoryProbe, near, nearArray, offsetLinePoints, throwsWith } from './helpers.mjs';

const pkg = JSON.parse(readFileSync(new URL('../../package.json', import.meta.url), 'utf8'));
const rtl = await init();

test('ESM: default and named init load independent instances', async () => {
  assert.equal(typeof init, 'function');
  assert.equal(namedInit, init);
  assert.equal(rtl.version, pkg.version);
  const other = await namedInit();
  assert.notEqual(other, rtl);
  assert.equal(other.fitLine([0, 0, 1, 0]).offset, 0);
});

test('init: the wasm bytes can be passed in; bad options are TypeErrors', async () => {
  const bytes = readFileSync(new URL('../../dist/rtl.wasm', import.meta.url));
  const r = await init({ wasmBinary: new Uint8Array(bytes) });
  near(r.fitLine([0, 1, 2, 1]).offset, -1, 0);
  await assert.rejects(init('x'), (e) => e instanceof TypeError && /init: options must be an object/.test(e.message));
  await assert.rejects(init({ wasmBinary: 'x' }), (e) => e instanceof TypeError && /wasmBinary must be an ArrayBuffer/.test(e.message));
  await assert.rejects(init({ wasm: 1 }), (e) => e instanceof TypeError && /unknown option "wasm"/.test(e.message));
});

test('fitLine 2D: known line, normal, offset, rms, centroid', () => {
  const ref = offsetLinePoints(0.05);
  const f = rtl.fitLine(ref.xy);
  assert.equal(f.dim, 2);
  assert.equal(f.count, 20);
  assert.ok(f.normal instanceof Float64Array && f.direction instanceof Float64Array && f.centroid instanceof Float64Array);
  nearArray(f.normal, ref.normal, 1e-12, 'normal');
  near(f.offset, ref.offset, 1e-12, 'offset');
  near(f.rms, ref.rms, 1e-12, 'rms');
  nearArray(f.centroid, ref.centroid, 1e-12, 'centroid');
  nearArray(f.direction, [f.normal[1], -f.normal[0]], 0, 'direction');
  // The same points from a Float32Array (converted) and from a plain array.
  const f32 = rtl.fitLine(new Float32Array(ref.xy));
  nearArray(f32.normal, ref.normal, 1e-6, 'normal (Float32Array)');
  near(f32.rms, ref.rms, 1e-6, 'rms (Float32Array)');
  const arr = rtl.fitLine(Array.from(ref.xy));
  nearArray(arr.normal, f.normal, 0, 'normal (Array)');
});

test('fitLine 2D: orientation convention, axis-aligned lines, far from the origin', () => {
  // y = 3: the normal points from the origin to the line, c <= 0.
  let f = rtl.fitLine([0, 3, 1, 3, 2, 3]);
  nearArray(f.normal, [0, 1], 0, 'normal');
  near(f.offset, -3, 1e-15, 'offset');
  assert.ok(!Object.is(f.normal[0], -0), 'no negative zero');
  // x = -2: normal (-1, 0), c = -2.
  f = rtl.fitLine([-2, 5, -2, 6, -2, 9]);
  nearArray(f.normal, [-1, 0], 0, 'normal');
  near(f.offset, -2, 1e-15, 'offset');
  // Through the origin: first non-zero component positive.
  f = rtl.fitLine([-1, 1, 1, -1]);
  near(f.normal[0], Math.SQRT1_2, 1e-15, 'normal x');
  near(f.normal[1], Math.SQRT1_2, 1e-15, 'normal y');
  near(f.offset, 0, 1e-15, 'offset');
  // A scan 1 km away: two-pass centring keeps full precision.
  const ref = offsetLinePoints(0.01);
  const far = ref.xy.map((v, i) => v + (i % 2 ? 1000 : -1000));
  f = rtl.fitLine(far);
  nearArray(f.normal, ref.normal, 1e-9, 'normal far');
  near(f.rms, 0.01, 1e-9, 'rms far');
});

test('fitLine 3D: direction, centroid, rms', () => {
  // Along (1,2,2)/3 through (1,1,1), moved +-0.1 along (0,1,-1)/sqrt2 (perpendicular).
  const d = [1 / 3, 2 / 3, 2 / 3];
  const q = [0, Math.SQRT1_2, -Math.SQRT1_2];
  const xyz = [];
  for (let t = -3; t <= 3; t++) for (const k of [0.1, -0.1]) xyz.push(...[0, 1, 2].map((j) => 1 + t * d[j] + k * q[j]));
  const f = rtl.fitLine(xyz, { dim: 3 });
  assert.equal(f.dim, 3);
  assert.equal(f.count, 14);
  nearArray(f.direction, d, 1e-12, 'direction');
  nearArray(f.centroid, [1, 1, 1], 1e-12, 'centroid');
  near(f.rms, 0.1, 1e-12, 'rms');
});

test('fitLine: 1,000,000 points (memory growth; results read after it)', () => {
  const n = 1_000_000;
  const xy = new Float64Array(2 * n);
  for (let i = 0; i < n; i++) {
    const t = Math.floor(i / 2) / n * 200;  // each t twice, moved +e and -e: the TLS line is exact
    const e = (i % 2 ? 1 : -1) * 0.02;
    xy[2 * i] = t - 0.6 * e;  // line y = 0.75 x + 2: normal (-0.6, 0.8), c = -1.6
    xy[2 * i + 1] = 0.75 * t + 2 + 0.8 * e;
  }
  const f = rtl.fitLine(xy);
  nearArray(f.normal, [-0.6, 0.8], 1e-9, 'normal');
  near(f.offset, -1.6, 1e-8, 'offset');
  near(f.rms, 0.02, 1e-9, 'rms');
  assert.ok(rtl.memoryBytes() > 16 * 1024 * 1024 && rtl.memoryBytes() >= 8 * 2 * n, 'memory grew to hold the points');
  // The module still works after growth (cached heap views would be detached).
  near(rtl.fitLine([0, 3, 1, 3]).offset, -3, 1e-15, 'small fit after growth');
});

const ERROR_CASES = [
  ['odd length', () => rtl.fitLine([1, 2, 3]), RangeError, /fitLine: points has 3 numbers, not a multiple of dim 2/],
  ['not a multiple of 3', () => rtl.fitLine([1, 2, 3, 4], { dim: 3 }), RangeError, /not a multiple of dim 3/],
  ['one point', () => rtl.fitLine(new Float64Array([1, 2])), RangeError, /fitLine: needs at least 2 points, got 1/],
  ['empty', () => rtl.fitLine([]), RangeError, /needs at least 2 points, got 0/],
  ['NaN', () => rtl.fitLine([0, 0, 1, NaN, 2, 2]), RangeError, /point 1 has a non-finite coordinate \(NaN\) at index 3/],
  ['Infinity', () => rtl.fitLine(new Float32Array([0, 0, Infinity, 1])), RangeError, /point 1 has a non-finite coordinate \(Infinity\)/],
  ['-Infinity', () => rtl.fitLine([-Infinity, 0, 1, 1]), RangeError, /point 0 .*\(-Infinity\) at index 0/],
  ['coincident points', () => rtl.fitLine([1, 1, 1, 1, 1, 1]), RangeError, /all 3 points coincide/],
  ['a string', () => rtl.fitLine('0,0,1,1'), TypeError, /fitLine: points must be a Float64Array, a Float32Array or an array of numbers, got a string/],
  ['a number', () => rtl.fitLine(42), TypeError, /got the number 42/],
  ['undefined', () => rtl.fitLine(), TypeError, /points must be .* got undefined/],
  ['null', () => rtl.fitLine(null), TypeError, /got null/],
  ['an object', () => rtl.fitLine({ x: 1 }), TypeError, /got an object/],
  ['a BigInt64Array', () => rtl.fitLine(new BigInt64Array(4)), TypeError, /got a BigInt64Array/],
  ['a string element', () => rtl.fitLine([0, 0, '1', 1]), TypeError, /points\[2\] is a string \("1"\), expected a number/],
  ['options not an object', () => rtl.fitLine([0, 0, 1, 1], 2), TypeError, /options must be an object/],
  ['unknown option', () => rtl.fitLine([0, 0, 1, 1], { dims: 2 }), TypeError, /unknown option "dims"/],
  ['dim not a number', () => rtl.fitLine([0, 0, 1, 1], { dim: '2' }), TypeError, /option dim must be a number/],
  ['dim 4', () => rtl.fitLine([0, 0, 0, 0, 1, 1, 1, 1], { dim: 4 }), RangeError, /option dim must be 2 or 3, got 4/],
];

for (const [name, f, type, re] of ERROR_CASES) {
  test(`fitLine error: ${name} -> ${type.name}, and the module keeps working`, () => {
    throwsWith(f, type, re);
    near(rtl.fitLine([0, 1, 1, 1]).offset, -1, 0, 'fit after the error');
  });
}

test('100,000 failing calls leave heap, memory and stack pointer where they were', () => {
  assert.throws(() => rtl.fitLine(new Float64Array(64)), RangeError);  // warm-up of the error path (coincident points)
  const memory = memoryProbe(rtl);
  const nan = new Float64Array([0, 0, 1, NaN]);
  const odd = new Float64Array([0, 0, 1]);
  const same = new Float64Array([2, 2, 2, 2]);
  let caught = 0;
  for (let i = 0; i < 100_000; i++) {
    try {
      // Most failures are raised in C++ (caught there and returned), some in JS before the call.
      switch (i % 4) {
        case 0: rtl.fitLine(nan); break;
        case 1: rtl.fitLine(odd); break;
        case 2: rtl.fitLine(same); break;
        default: rtl.fitLine('x');
      }
    } catch (e) {
      if (e instanceof RangeError || e instanceof TypeError) caught++;
    }
  }
  assert.equal(caught, 100_000);
  memory.unchanged();
  nearArray(rtl.fitLine(offsetLinePoints(0.05).xy).normal, offsetLinePoints().normal, 1e-12, 'fit afterwards');
});
