// 100,000 failing calls spread over every function, most of them failing inside C++ (caught there and returned
// as data): every one throws a TypeError or RangeError, and the wasm heap, memory size and stack pointer are
// exactly where they were afterwards; the module still computes correctly.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import init from 'rtl-wasm';
import { memoryProbe } from './helpers.mjs';

test('100,000 failing calls over all functions: no leak, no stack drift, module intact', { timeout: 120_000 }, async () => {
  const rtl = await init();
  const tree = new rtl.TfTree('map');
  tree.insert('robot', 'map', { angle: 0.1, translation: [1, 0] });
  const stream = new rtl.StreamSegmenter();
  const inf = new Float64Array([0, 0, 1, Infinity]);
  const calls = [
    () => rtl.fitLine(new Float64Array([1, 1, 1, 1])),                          // C++: coincident points
    () => rtl.segment(inf),                                                       // C++: Infinity
    () => rtl.segment([0, 0, 1], {}),                                             // C++: odd length
    () => rtl.vectorize([0, 0, NaN, 1], { method: 'ftls' }),                      // C++: NaN
    () => rtl.vectorize([0, 0], { method: 'dp' }),                                // C++: one point
    () => rtl.readCarmenLog('FLASER 2 1 1\n'),                                    // C++ reader: short line
    () => rtl.readOrganizedLidar(new Uint8Array(20), { beams: 1 }),               // C++ reader: truncated record
    () => rtl.readPcd(new TextEncoder().encode('FIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nPOINTS 2\nDATA ascii\n1 2 3\n')),  // C++ PCD reader: too few lines
    () => rtl.extractPolylines([1, 2, 3, Infinity]),                              // C++: Infinity
    () => tree.tf('robot', 'nowhere'),                                            // C++: unknown frame
    () => tree.transformPoints('map', 'robot', inf),                              // C++: Infinity
    () => stream.addPoints(inf),                                                  // C++: Infinity
    () => rtl.toSvg({ points: [1] }),                                             // JS
    () => rtl.segment('x'),                                                       // JS
  ];
  // Warm-up: the first failure of each kind may allocate lazily initialised state.
  for (const f of calls) assert.throws(f, (e) => e instanceof RangeError || e instanceof TypeError);
  const memory = memoryProbe(rtl);
  let thrown = 0;
  for (let i = 0; i < 100_000; i++) {
    try {
      calls[i % calls.length]();
    } catch (e) {
      if (e instanceof RangeError || e instanceof TypeError) thrown++;
      else throw e;
    }
  }
  assert.equal(thrown, 100_000);
  memory.unchanged();
  // Still computing: a fit, a segmentation, a vectorization and a transformation.
  assert.equal(rtl.fitLine([0, 2, 1, 2]).offset, -2);
  assert.equal(rtl.segment([0, 0, 0.01, 0]).clusters.length, 1);
  assert.equal(rtl.vectorize([0, 0, 1, 0, 2, 0], { method: 'dp' }).count, 1);
  assert.ok(Math.abs(tree.transformPoints('map', 'robot', [0, 0])[0] - 1) < 1e-12);
  tree.dispose();
  stream.dispose();
});

// The input check runs block-wise (256 numbers at a time) before it looks for the culprit: a bad number in any
// block, first or last position included, is found and named; good inputs of every length pass.
test('the input check finds a bad number in any block and names its point and index', async () => {
  const rtl = await init();
  const line = (n) => Float64Array.from({ length: 2 * n }, (_, i) => (i % 2 ? 0.001 * (i % 7) : 0.01 * (i >> 1)));
  for (const n of [2, 128, 129, 1000]) {
    assert.equal(rtl.vectorize(line(n), { method: 'dp' }).ok, true);
    assert.equal(rtl.segment(line(n)).labels.length, n);
    for (const at of [0, 255, 256, 257, 2 * n - 1]) {
      if (at >= 2 * n) continue;
      const where = `point ${at >> 1} has`;
      for (const [bad, text] of [[NaN, 'a non-finite coordinate \\(NaN\\)'], [Infinity, 'a non-finite coordinate \\(Infinity\\)'],
        [-Infinity, 'a non-finite coordinate \\(-Infinity\\)'], [2e18, 'the coordinate 2e\\+18']]) {
        const xy = line(n);
        xy[at] = bad;
        assert.throws(() => rtl.vectorize(xy, { method: 'ftls' }), (e) => e instanceof RangeError &&
          new RegExp(`^vectorize: ${where} ${text} at index ${at}`).test(e.message), `vectorize n=${n} at=${at} ${bad}`);
        if (Number.isNaN(bad)) {
          assert.equal(rtl.segment(xy).labels[at >> 1], -1, `segment: a NaN point is a gap (n=${n} at=${at})`);
        } else if (!Number.isFinite(bad)) {
          assert.throws(() => rtl.segment(xy), (e) => e instanceof RangeError &&
            new RegExp(`^segment: ${where} ${text} at index ${at}$`).test(e.message), `segment n=${n} at=${at} ${bad}`);
        }
        if (!Number.isFinite(bad))
          assert.throws(() => rtl.simplify(xy, 0.1, true), (e) => e instanceof RangeError &&
            new RegExp(`^simplify: ${where} ${text} at index ${at}$`).test(e.message), `simplify n=${n} at=${at} ${bad}`);
      }
    }
  }
});
