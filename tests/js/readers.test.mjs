// Readers: the organised LiDAR binary of tests/data against an independent DataView parse; layouts; errors.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import init from 'rtl-wasm';
import { throwsWith } from './helpers.mjs';

const rtl = await init();
const DATA = new URL('../data/', import.meta.url);
const bin = readFileSync(new URL('rellis3d-os1-4x2048.bin', DATA));

// Independent parse: 16-byte little-endian float32 records x, y, z, intensity, record k = column * 4 + beam.
function parse(buf) {
  const dv = new DataView(buf.buffer, buf.byteOffset, buf.byteLength);
  const out = [];
  for (let k = 0; k < buf.byteLength / 16; k++) out.push([0, 4, 8, 12].map((o) => dv.getFloat32(16 * k + o, true)));
  return out;
}

test('readOrganizedLidar: the 4 x 2048 Ouster excerpt, column-major, gaps as NaN', () => {
  const ref = parse(bin);
  const cloud = rtl.readOrganizedLidar(bin, { beams: 4 });
  assert.equal(cloud.beams, 4);
  assert.equal(cloud.columns, 2048);
  assert.ok(cloud.points instanceof Float64Array && cloud.intensity instanceof Float32Array);
  assert.equal(cloud.points.length, 3 * 8192);
  let gaps = 0;
  for (let k = 0; k < ref.length; k++) {
    const [x, y, z, i] = ref[k];
    if (x === 0 && y === 0 && z === 0) {
      gaps++;
      assert.ok(Number.isNaN(cloud.points[3 * k]) && Number.isNaN(cloud.points[3 * k + 2]), `record ${k} is a gap`);
    } else {
      assert.deepEqual(Array.from(cloud.points.subarray(3 * k, 3 * k + 3)), [x, y, z], `record ${k}`);
    }
    assert.equal(cloud.intensity[k], i, `intensity ${k}`);
  }
  assert.ok(gaps < ref.length / 2, 'mostly returns');
  // ring(b): beam b of every column; column(c): the 4 beams of column c.
  const ring2 = cloud.ring(2);
  assert.equal(ring2.length, 3 * 2048);
  assert.deepEqual(Array.from(ring2.subarray(3 * 100, 3 * 101)), Array.from(cloud.points.subarray(3 * (100 * 4 + 2), 3 * (100 * 4 + 3))));
  const col = cloud.column(7);
  assert.deepEqual(Array.from(col), Array.from(cloud.points.subarray(3 * 28, 3 * 32)));
  // An ArrayBuffer and a DataView of the same bytes give the same cloud.
  const ab = bin.buffer.slice(bin.byteOffset, bin.byteOffset + bin.byteLength);
  assert.deepEqual(rtl.readOrganizedLidar(ab, { beams: 4 }).intensity, cloud.intensity);
  assert.deepEqual(rtl.readOrganizedLidar(new DataView(ab), { beams: 4, layout: 'column-major' }).intensity, cloud.intensity);
});

test('readOrganizedLidar: row-major files are reordered to column-major', () => {
  // 2 beams x 3 columns, row-major: ring 0 (columns 0..2), then ring 1. Point value = 10*beam + column + 1.
  const f = new Float32Array(6 * 4);
  for (let b = 0; b < 2; b++) for (let c = 0; c < 3; c++) f.set([10 * b + c + 1, 0, 0, b], 4 * (b * 3 + c));
  const cloud = rtl.readOrganizedLidar(f, { beams: 2, layout: 'row-major' });
  assert.equal(cloud.columns, 3);
  assert.deepEqual(Array.from(cloud.ring(1)).filter((_, i) => i % 3 === 0), [11, 12, 13]);
  assert.deepEqual(Array.from(cloud.column(2)).filter((_, i) => i % 3 === 0), [3, 13]);
  assert.deepEqual(Array.from(cloud.intensity), [0, 1, 0, 1, 0, 1]);
});

const ERRORS = [
  ['data a string', () => rtl.readOrganizedLidar('abc', { beams: 4 }), TypeError, /readOrganizedLidar: data must be an ArrayBuffer/],
  ['data an Array', () => rtl.readOrganizedLidar([1, 2], { beams: 4 }), TypeError, /got an Array/],
  ['no options', () => rtl.readOrganizedLidar(bin), TypeError, /options \{beams\} are required/],
  ['no beams', () => rtl.readOrganizedLidar(bin, {}), TypeError, /option beams is required/],
  ['beams 0', () => rtl.readOrganizedLidar(bin, { beams: 0 }), RangeError, /option beams must be >= 1, got 0/],
  ['beams 2.5', () => rtl.readOrganizedLidar(bin, { beams: 2.5 }), RangeError, /option beams must be an integer/],
  ['bad layout', () => rtl.readOrganizedLidar(bin, { beams: 4, layout: 'column' }), RangeError, /layout must be 'column-major' or 'row-major'/],
  ['truncated record', () => rtl.readOrganizedLidar(bin.subarray(0, 16 * 8 + 5), { beams: 4 }), RangeError,
    /^readOrganizedLidar: truncated record at byte offset 128 \(133 bytes is not a multiple of 16\)/],
  ['incomplete column', () => rtl.readOrganizedLidar(bin.subarray(0, 16 * 10), { beams: 4 }), RangeError,
    /incomplete column at byte offset 128 \(10 records is not a multiple of 4 beams\)/],
  ['ring out of range', () => rtl.readOrganizedLidar(bin, { beams: 4 }).ring(4), RangeError, /ring: beam must be an integer in \[0, 3\], got 4/],
  ['column out of range', () => rtl.readOrganizedLidar(bin, { beams: 4 }).column(-1), RangeError, /column: c must be an integer in \[0, 2047\]/],
];
for (const [name, f, type, re] of ERRORS) {
  test(`readOrganizedLidar error: ${name}`, () => {
    throwsWith(f, type, re);
    assert.equal(rtl.readOrganizedLidar(bin.subarray(0, 64), { beams: 4 }).columns, 1, 'works afterwards');
  });
}

test('readOrganizedLidar: 20,000 failing reads leave the heap and stack where they were', () => {
  const bad = bin.subarray(0, 16 * 10);
  throwsWith(() => rtl.readOrganizedLidar(bad, { beams: 4 }), RangeError, /incomplete column/);
  const heap = rtl.heapInUse(), mem = rtl.memoryBytes(), sp = rtl.stackPointer();
  for (let i = 0; i < 20_000; i++) {
    try { rtl.readOrganizedLidar(bad, { beams: 4 }); } catch (e) { if (!(e instanceof RangeError)) throw e; }
  }
  assert.equal(rtl.heapInUse(), heap);
  assert.equal(rtl.memoryBytes(), mem);
  assert.equal(rtl.stackPointer(), sp);
});

// ---- CARMEN logs
function parseCarmen(text) {
  const scans = [];
  text.split('\n').forEach((l, li) => {
    const t = l.trim().split(/\s+/);
    if (t[0] !== 'FLASER') return;
    const n = Number(t[1]), res = n % 2 ? Math.PI / (n - 1) : Math.PI / n;
    const ranges = t.slice(2, 2 + n).map(Number);
    scans.push({ line: li + 1, n, ranges, res, x: Number(t[2 + n]), y: Number(t[3 + n]), theta: Number(t[4 + n]), ts: Number(t[8 + n]) });
  });
  return scans;
}

test('readCarmenLog: intel (180 beams) and csail (361 beams) against an independent parse', () => {
  for (const [name, beams] of [['intel.log', 180], ['csail.log', 361]]) {
    const text = readFileSync(new URL(name, DATA), 'utf8');
    const ref = parseCarmen(text);
    const scans = rtl.readCarmenLog(text);
    assert.equal(scans.length, 30, name);
    assert.equal(ref.length, 30);
    scans.forEach((s, k) => {
      const r = ref[k];
      assert.equal(s.line, r.line);
      assert.equal(s.x, r.x);
      assert.equal(s.y, r.y);
      assert.equal(s.theta, r.theta);
      assert.equal(s.timestamp, r.ts);
      assert.ok(s.points instanceof Float64Array && s.ranges instanceof Float64Array);
      assert.equal(s.ranges.length, beams);
      assert.deepEqual(Array.from(s.ranges), r.ranges);
      for (let i = 0; i < beams; i++) {
        const range = r.ranges[i], a = -Math.PI / 2 + i * r.res;
        if (range > 0 && range < 80) {
          assert.ok(Math.abs(s.points[2 * i] - range * Math.cos(a)) < 1e-12 && Math.abs(s.points[2 * i + 1] - range * Math.sin(a)) < 1e-12, `${name} scan ${k} beam ${i}`);
        } else {
          assert.ok(Number.isNaN(s.points[2 * i]) && Number.isNaN(s.points[2 * i + 1]), `${name} scan ${k} beam ${i} is a gap`);
        }
      }
    });
    // The bytes of the file give the same scans; readCarmen is the same function.
    const fromBytes = rtl.readCarmen(readFileSync(new URL(name, DATA)));
    assert.deepEqual(fromBytes[29].points, scans[29].points);
    // maxRange: with 5 m every return beyond 5 m becomes a gap.
    const near5 = rtl.readCarmenLog(text, { maxRange: 5 })[0];
    for (let i = 0; i < beams; i++) if (ref[0].ranges[i] >= 5) assert.ok(Number.isNaN(near5.points[2 * i]));
  }
});

const CARMEN_ERRORS = [
  ['not text', () => rtl.readCarmenLog(42), TypeError, /readCarmenLog: text must be a string, an ArrayBuffer or a typed array/],
  ['bad number', () => rtl.readCarmenLog('# c\nFLASER 2 1.0 x1 0 0 0 0 0 0 1 h 2\n'), RangeError, /^readCarmenLog: line 2: bad range 2 'x1'/],
  ['short line', () => rtl.readCarmenLog('FLASER 3 1 2 3 0 0\n'), RangeError, /line 1: FLASER with 3 beams needs 14 fields, found 7/],
  ['bad beam count', () => rtl.readCarmenLog('FLASER -2 1\n'), RangeError, /line 1: bad beam count '-2'/],
  ['unknown record', () => rtl.readCarmenLog('ODOM 1 2 3\nhello world\n'), RangeError, /line 2: unknown record 'hello'/],
  ['maxRange 0', () => rtl.readCarmenLog('', { maxRange: 0 }), RangeError, /option maxRange must be > 0/],
];
for (const [name, f, type, re] of CARMEN_ERRORS) {
  test(`readCarmenLog error: ${name}`, () => {
    throwsWith(f, type, re);
    assert.equal(rtl.readCarmenLog('FLASER 2 1 1 0 0 0 0 0 0 1 h 2\n')[0].ranges.length, 2, 'works afterwards');
  });
}
