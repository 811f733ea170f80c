// readPcd: the PCD files PCL's own writer made (tests/data/pcd, see its README) in the three encodings, against
// the source records they were written from (the RELLIS-3D excerpts, parsed here with a DataView); errors.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import init from 'rtl-wasm';
import { throwsWith } from './helpers.mjs';

const rtl = await init();
const DATA = new URL('../data/', import.meta.url);
const pcd = (name) => readFileSync(new URL(`pcd/${name}.pcd`, DATA));
const ENCODINGS = ['ascii', 'binary', 'compressed'];

// Record (column c, beam b) of a column-major float32 x y z intensity excerpt with `beams` beams.
function record(buf, beams, c, b) {
  const dv = new DataView(buf.buffer, buf.byteOffset, buf.byteLength);
  const at = 16 * (c * beams + b);
  return [0, 4, 8, 12].map((o) => dv.getFloat32(at + o, true));
}
const noReturn = ([x, y, z]) => x === 0 && y === 0 && z === 0;

test('readPcd: organised (64 x 4, columns 1000-1063 of the 4-beam excerpt) in every encoding', () => {
  const bin = readFileSync(new URL('rellis3d-os1-4x2048.bin', DATA));
  for (const enc of ENCODINGS) {
    const cloud = rtl.readPcd(pcd(`organized.${enc}`));
    assert.equal(cloud.organized, true, enc);
    if (!cloud.organized) continue;
    assert.equal(cloud.width, 64);
    assert.equal(cloud.height, 4);
    assert.equal(cloud.beams, 4);
    assert.equal(cloud.columns, 64);
    assert.deepEqual([...cloud.viewpoint], [0, 0, 0, 1, 0, 0, 0]);
    assert.deepEqual(Object.keys(cloud.fields), ['intensity']);
    assert.ok(cloud.points instanceof Float64Array && cloud.intensity instanceof Float32Array);
    let gaps = 0;
    for (let c = 0; c < 64; c++) {
      for (let b = 0; b < 4; b++) {
        const r = record(bin, 4, 1000 + c, b), k = c * 4 + b;  // column-major, as readOrganizedLidar
        const p = cloud.points.subarray(3 * k, 3 * k + 3);
        if (noReturn(r)) {
          gaps++;
          assert.ok(p.every(Number.isNaN), `${enc} (${b}, ${c}): NaN expected`);
        } else {
          assert.deepEqual([...p], r.slice(0, 3), `${enc} (${b}, ${c})`);
        }
        assert.equal(cloud.intensity[k], r[3]);
        assert.equal(cloud.fields.intensity.values[k], r[3]);
      }
    }
    assert.equal(gaps, 32, enc);
    // The same cloud as the organised LiDAR reader's on those bytes, accessors included.
    const lidar = rtl.readOrganizedLidar(bin.subarray(1000 * 64, 1064 * 64), { beams: 4 });
    assert.deepEqual(cloud.points, lidar.points);
    assert.deepEqual(cloud.intensity, lidar.intensity);
    assert.deepEqual(cloud.ring(2), lidar.ring(2));
    assert.deepEqual(cloud.column(63), lidar.column(63));
  }
});

test('readPcd: unorganised (300 points with F 8 t and U 2 ring) in every encoding equals the source', () => {
  const bin = readFileSync(new URL('rellis3d-os1-16x2048.bin', DATA));
  const src = [];
  for (let c = 600; c < 680; c++) {
    for (let b = 0; b < 16; b++) {
      const r = record(bin, 16, c, b);
      if (!noReturn(r) && src.length < 300) src.push({ r, c, b });
    }
  }
  assert.equal(src.length, 300);
  for (const enc of ENCODINGS) {
    const cloud = rtl.readPcd(pcd(`unorganized.${enc}`), { fields: ['t', 'ring', 'intensity', 'absent'] });
    assert.equal(cloud.organized, false, enc);
    assert.equal(cloud.width, 300);
    assert.equal(cloud.height, 1);
    assert.deepEqual(Object.keys(cloud.fields), ['t', 'ring', 'intensity']);
    assert.equal(cloud.points.length, 900);
    src.forEach(({ r, c, b }, i) => {
      assert.deepEqual([...cloud.points.subarray(3 * i, 3 * i + 3)], r.slice(0, 3), `${enc} point ${i}`);
      assert.equal(cloud.fields.intensity.values[i], r[3]);
      assert.equal(cloud.fields.ring.values[i], 4 * b);
      assert.equal(cloud.fields.t.values[i], 10 + c / 64);
      assert.equal(cloud.fields.t.count, 1);
    });
    // Default fields: intensity and ring.
    assert.deepEqual(Object.keys(rtl.readPcd(pcd(`unorganized.${enc}`)).fields), ['intensity', 'ring']);
  }
});

// Bytes of `buf` up to and including the line starting `DATA`.
function headerLength(buf) {
  const at = buf.indexOf('DATA ');
  return buf.indexOf(10, at) + 1;
}

test('readPcd: a truncated binary file names the point and byte offset; heap and stack unchanged', () => {
  const full = pcd('unorganized.binary');
  const head = headerLength(full);
  const heap = rtl.heapInUse(), sp = rtl.stackPointer();
  // 10 whole records of 26 bytes (x y z intensity t ring) and 5 bytes of the 11th.
  throwsWith(() => rtl.readPcd(full.subarray(0, head + 26 * 10 + 5)), RangeError,
    new RegExp(`^readPcd: point 10 at byte offset ${head + 260}: `));
  throwsWith(() => rtl.readPcd(pcd('organized.compressed').subarray(0, 600)), RangeError, /^readPcd: .*byte offset \d+/);
  throwsWith(() => rtl.readPcd(full.subarray(0, 40)), RangeError, /^readPcd: /);
  assert.equal(rtl.heapInUse(), heap);
  assert.equal(rtl.stackPointer(), sp);
  assert.equal(rtl.readPcd(full).points.length, 900);  // the module works on
});

test('readPcd: a wrong point count names the line', () => {
  const text = pcd('organized.ascii').toString('latin1');
  // Header POINTS other than WIDTH x HEIGHT.
  throwsWith(() => rtl.readPcd(Buffer.from(text.replace('POINTS 256', 'POINTS 257'), 'latin1')), RangeError,
    /^readPcd: header line 10: POINTS 257 differs from WIDTH x HEIGHT/);
  // One data line missing: fewer lines than POINTS.
  const lines = text.split('\n');
  const short = [...lines.slice(0, 100), ...lines.slice(101)].join('\n');
  throwsWith(() => rtl.readPcd(Buffer.from(short, 'latin1')), RangeError, /^readPcd: .*point 255.*byte offset \d+/);
});

test('readPcd: argument errors are TypeError/RangeError starting with its name', () => {
  const b = pcd('organized.binary');
  throwsWith(() => rtl.readPcd('VERSION 0.7'), TypeError, /^readPcd: data must be/);
  throwsWith(() => rtl.readPcd(b, { field: ['x'] }), TypeError, /^readPcd: unknown option "field"/);
  throwsWith(() => rtl.readPcd(b, { fields: 'intensity' }), TypeError, /^readPcd: option fields must be an array/);
  throwsWith(() => rtl.readPcd(b, { fields: [7] }), TypeError, /^readPcd: option fields\[0\] must be a string/);
  throwsWith(() => rtl.readPcd(b, { fields: ['a b'] }), RangeError, /^readPcd: option fields\[0\]/);
});
