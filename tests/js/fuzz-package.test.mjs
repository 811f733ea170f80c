// The package's exported functions under random arguments (tests/fuzz/js/fuzz_package.mjs): a fixed seed and a
// fixed number of calls here, so that the test does the same work every run; longer sessions run the script itself.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { fuzzPackage } from '../fuzz/js/fuzz_package.mjs';

for (const seed of [1, 2, 3]) {
  test(`random calls (seed ${seed}): only TypeError/RangeError naming the call, heap and stack unchanged`, async () => {
    const { iterations, calls } = await fuzzPackage({ seed, iterations: 1500 });
    assert.equal(iterations, 1500);
    assert.ok(Object.keys(calls).length >= 8, `every export is reached: ${Object.keys(calls)}`);
  });
}
