// readCarmenLog's no-return value: detected from the log by default (PARAM lines, or the top range that
// recurs), an explicit maxRange overrides it, and every scan reports the value used and where it came from.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import init from 'rtl-wasm';
import { throwsWith } from './helpers.mjs';

const rtl = await init();
const read = (f) => readFileSync(new URL(`../data/${f}`, import.meta.url), 'utf8');
const rangesOf = (text) => text.split('\n').filter((l) => l.startsWith('FLASER')).map((l) => {
  const t = l.trim().split(/\s+/);
  return t.slice(2, 2 + Number(t[1])).map(Number);
});
const gaps = (scans) => scans.reduce((a, s) => a + s.points.filter((v, i) => i % 2 === 0 && Number.isNaN(v)).length, 0);

test('intel: the recurring 81.83 is detected; its 481 beams are gaps; every scan reports it', () => {
  const text = read('intel.log');
  const scans = rtl.readCarmenLog(text);
  assert.equal(scans.length, 30);
  for (const s of scans) {
    assert.equal(s.maxRange, 81.83);
    assert.equal(s.maxRangeSource, 'recurring');
  }
  const raw = rangesOf(text).flat();
  assert.equal(raw.filter((r) => r >= 81.83).length, 481);
  assert.equal(gaps(scans), raw.filter((r) => !(r > 0 && r < 81.83)).length);
  // Explicit values override: Infinity keeps the 81.83 beams as points, 5 m makes more gaps.
  const all = rtl.readCarmenLog(text, { maxRange: Infinity });
  assert.equal(all[0].maxRange, Infinity);
  assert.equal(all[0].maxRangeSource, 'explicit');
  assert.equal(gaps(all), raw.filter((r) => !(r > 0)).length);
  const near = rtl.readCarmenLog(text, { maxRange: 5 });
  assert.equal(near[7].maxRange, 5);
  assert.equal(gaps(near), raw.filter((r) => !(r > 0 && r < 5)).length);
});

test('csail: the log\'s robot_front_laser_max PARAM (50 m) is the no-return value', () => {
  const text = read('csail.log');
  const scans = rtl.readCarmenLog(text);
  assert.equal(scans[0].maxRange, 50);
  assert.equal(scans[0].maxRangeSource, 'parameter');
  const raw = rangesOf(text).flat();
  assert.equal(gaps(scans), raw.filter((r) => !(r > 0 && r < 50)).length);
});

test('a log with no evidence keeps 80 m; aces-like 50.0 no-returns become gaps', () => {
  const beams = (rs) => `FLASER ${rs.length} ${rs.join(' ')} 1 2 0.5 1 2 0.5 10.5 host 10.6`;
  const plain = rtl.readCarmenLog(beams([1, 2, 3]) + '\n');
  assert.equal(plain[0].maxRange, 80);
  assert.equal(plain[0].maxRangeSource, 'default');
  const lines = [];
  for (let k = 0; k < 20; k++) lines.push(beams([1, 50, 2, 50, 3.5, 50]));
  const aces = rtl.readCarmenLog(lines.join('\n') + '\n');
  assert.equal(aces[0].maxRange, 50);
  assert.equal(gaps(aces), 60, 'the recurring 50.0 beams are gaps, not points 50 m away');
  const param = rtl.readCarmenLog(`PARAM robot_front_laser_max 3.0 host 1\n${beams([1, 2, 3, 4])}\n`);
  assert.equal(param[0].maxRange, 3);
  assert.equal(gaps(param), 2);
});

test('readCarmenLog options and malformed lines: errors start with readCarmenLog', () => {
  throwsWith(() => rtl.readCarmenLog('', { maxRange: 0 }), RangeError, /^readCarmenLog: option maxRange must be > 0, got 0$/);
  throwsWith(() => rtl.readCarmenLog('', { maxRange: NaN }), RangeError, /^readCarmenLog: option maxRange must be finite/);
  throwsWith(() => rtl.readCarmenLog('', { maxRange: '50' }), TypeError, /^readCarmenLog: option maxRange must be a number/);
  throwsWith(() => rtl.readCarmenLog('FLASER 2 1 1 nan 0 0 0 0 0 1 h 2\n'), RangeError, /^readCarmenLog: line 1: /);
  throwsWith(() => rtl.readCarmenLog('# c\nFLASER 2 1 1 0 0 0 0 0 0 inf h 2\n'), RangeError, /^readCarmenLog: line 2: /);
});
