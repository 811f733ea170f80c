// The C++ input check (wasm/src/adapter.h checkPoints: a vector pass over blocks of 256 numbers, then a scalar
// tail): a bad number at every lane and block position is found, with the index in the message; what a function
// allows (NaN gaps in segment, any finite magnitude in simplify) passes at the same positions.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import init from 'rtl-wasm';
import { throwsWith } from './helpers.mjs';

const rtl = await init();
const N = 300;  // 600 numbers: two full blocks of 256 and a tail of 88
const POSITIONS = [0, 1, 2, 3, 254, 255, 256, 257, 511, 512, 513, 598, 599];
function line(bad, at) {
  const xy = new Float64Array(2 * N);
  for (let i = 0; i < N; i++) { xy[2 * i] = i * 0.01; xy[2 * i + 1] = 0.5 * Math.sin(i * 0.05); }
  if (bad !== undefined) xy[at] = bad;
  return xy;
}

test('vectorize refuses NaN, +-Infinity and |v| > 1e18 at every block position', () => {
  for (const at of POSITIONS) {
    for (const [bad, re] of [[NaN, /non-finite coordinate \(NaN\)/], [Infinity, /\(Infinity\)/], [-Infinity, /\(-Infinity\)/], [-2e18, /coordinate -2e\+18/]]) {
      throwsWith(() => rtl.vectorize(line(bad, at), { method: 'dp', epsilon: 0.01 }), RangeError,
        new RegExp(`^vectorize: point ${at >> 1} has .*${re.source}.* at index ${at}`));
    }
    assert.equal(rtl.vectorize(line(1e18, at), { method: 'dp', epsilon: 0.01 }).ok, true, `1e18 at ${at}`);
  }
});

test('segment takes NaN as a gap and refuses +-Infinity at every block position', () => {
  for (const at of POSITIONS) {
    const r = rtl.segment(line(NaN, at), { step: 3, lowerBound: 0, upperBound: 0.5 });
    assert.equal(r.labels[at >> 1], -1, `NaN at ${at} is a gap`);
    for (const bad of [Infinity, -Infinity])
      throwsWith(() => rtl.segment(line(bad, at)), RangeError, new RegExp(`^segment: point ${at >> 1} has a non-finite coordinate .* at index ${at}$`));
  }
});

test('simplify accepts any finite magnitude and refuses NaN at every block position', () => {
  for (const at of POSITIONS) {
    assert.ok(rtl.simplify(line(1e300, at), 0.01, true).length >= 2, `1e300 at ${at}`);
    throwsWith(() => rtl.simplify(line(NaN, at), 0.01, true), RangeError, new RegExp(`^simplify: point ${at >> 1} has a non-finite coordinate \\(NaN\\) at index ${at}$`));
  }
});
