// Fuzz of the ROS adapters with random messages: valid messages mutated field by field (wrong types, non-finite
// and out-of-range numbers, short or odd data, random field layouts). fromLaserScan / fromPointCloud2 either return
// a well-formed scan or throw TypeError/RangeError whose message starts with their name; every scan they return
// goes through segment() and vectorize(), and the wasm heap is the same before and after.
import test from 'node:test';
import assert from 'node:assert/strict';
import init from 'rtl-wasm';
import { fromLaserScan, fromPointCloud2 } from 'rtl-wasm/ros';

const rtl = await init();

function rng(seed) {
  let s = seed >>> 0;
  return () => ((s = (Math.imul(s, 1664525) + 1013904223) >>> 0) / 4294967296);
}

const ODD = [undefined, null, NaN, Infinity, -Infinity, -1, 0, 1.5, 2 ** 31, 2 ** 53, '3', true, {}, [], [1, 'a'],
  new Float32Array(3), new Uint8Array(5), 'AAAA', Symbol.iterator, 1n, () => 1];

function pick(r, list) { return list[Math.floor(r() * list.length)]; }

function randomScan(r) {
  const n = Math.floor(r() * 400);
  const ranges = new Float32Array(n).map(() => (r() < 0.1 ? pick(r, [NaN, Infinity, -Infinity, 0, -2, 1e30]) : r() * 40));
  const msg = r() < 0.8
    ? { header: { stamp: { sec: Math.floor(r() * 1e9), nanosec: Math.floor(r() * 1e9) }, frame_id: 'l' },
        angle_min: -Math.PI * r(), angle_max: Math.PI * r(), angle_increment: (r() - 0.3) * 0.05,
        range_min: r() * 0.5, range_max: 5 + r() * 50, ranges, intensities: r() < 0.5 ? [] : new Float32Array(n) }
    : { timestamp: { sec: 1, nsec: 2 }, frame_id: 'f', start_angle: -r() * 3, end_angle: r() * 3, ranges };
  return mutate(r, msg);
}

function randomCloud(r) {
  const height = Math.floor(r() * 4) + (r() < 0.5 ? 1 : 0), width = Math.floor(r() * 60);
  const type = r() < 0.5 ? 7 : 8, size = type === 7 ? 4 : 8;
  const pad = Math.floor(r() * 6);
  const names = ['x', 'y', 'z', ...(r() < 0.5 ? ['intensity'] : []), ...(r() < 0.5 ? ['ring'] : [])];
  const fields = names.map((name, i) => ({ name, offset: pad + i * size, datatype: name === 'ring' ? 4 : name === 'intensity' ? 7 : type, count: 1 }));
  const pointStep = pad + names.length * size + Math.floor(r() * 4);
  const rowStep = width * pointStep + Math.floor(r() * 8);
  const data = new Uint8Array(Math.max(0, height * rowStep)).map(() => Math.floor(r() * 256));
  const msg = { header: { stamp: { sec: 3, nanosec: 4 }, frame_id: 'c' }, height, width, fields, is_bigendian: r() < 0.5,
                point_step: pointStep, row_step: rowStep, data, is_dense: false };
  return mutate(r, msg);
}

// Replace, delete or truncate up to three fields (or nested fields) with odd values.
function mutate(r, msg) {
  const m = { ...msg };
  const times = r() < 0.3 ? 0 : 1 + Math.floor(r() * 3);
  for (let k = 0; k < times; k++) {
    const key = pick(r, Object.keys(m));
    const what = r();
    if (what < 0.4) m[key] = pick(r, ODD);
    else if (what < 0.5) delete m[key];
    else if (ArrayBuffer.isView(m[key])) m[key] = m[key].subarray(0, Math.floor(r() * m[key].length));
    else if (Array.isArray(m[key]) && m[key].length) m[key] = m[key].map((f) => (r() < 0.3 ? (typeof f === 'object' ? { ...f, [pick(r, Object.keys(f))]: pick(r, ODD) } : pick(r, ODD)) : f));
    else if (typeof m[key] === 'object' && m[key] !== null) m[key] = { ...m[key], stamp: pick(r, ODD) };
    else if (typeof m[key] === 'number') m[key] = pick(r, [m[key] * 1e9, -m[key], m[key] + 0.5, NaN]);
  }
  return m;
}

function check(fn, name, msg, stats) {
  let out;
  try {
    out = fn(msg);
  } catch (e) {
    assert.ok((e instanceof TypeError || e instanceof RangeError) && e.message.startsWith(`${name}: `), `${name} threw ${e?.name}: ${e?.message}`);
    stats.errors++;
    return undefined;
  }
  stats.ok++;
  assert.ok(out.points instanceof Float64Array);
  return out;
}

test('fuzz: random LaserScan / PointCloud2 messages give a scan or a typed error; the wasm heap stays flat', () => {
  const r = rng(20261204);
  const heap = rtl.heapInUse();
  const laser = { ok: 0, errors: 0 }, cloud = { ok: 0, errors: 0 };
  for (let i = 0; i < 3000; i++) {
    const s = check(fromLaserScan, 'fromLaserScan', randomScan(r), laser);
    if (s) {
      assert.equal(s.points.length, 2 * s.angles.length);
      const seg = rtl.segment(s.points);
      assert.equal(seg.labels.length, s.angles.length);
      const big = seg.clusters.find((c) => c.indices.length >= 3);
      if (big) rtl.vectorize(Float64Array.from([...big.indices].flatMap((k) => [s.points[2 * k], s.points[2 * k + 1]])), { method: 'ftls' });
    }
    const c = check(fromPointCloud2, 'fromPointCloud2', randomCloud(r), cloud);
    if (c) {
      assert.equal(c.points.length % 3, 0);
      for (let k = 0; k < c.points.length; k += 3) {
        const finite = Number.isFinite(c.points[k]) && Number.isFinite(c.points[k + 1]) && Number.isFinite(c.points[k + 2]);
        assert.ok(finite || (Number.isNaN(c.points[k]) && Number.isNaN(c.points[k + 1]) && Number.isNaN(c.points[k + 2])), 'all-or-nothing NaN');
      }
      if (c.points.length >= 9) rtl.segment(c.points, { dim: 3 });
    }
  }
  assert.equal(rtl.heapInUse(), heap, 'wasm heap in use');
  // both outcomes were exercised, many times
  for (const [what, s] of [['laser', laser], ['cloud', cloud]]) assert.ok(s.ok > 300 && s.errors > 300, `${what}: ${JSON.stringify(s)}`);
});
