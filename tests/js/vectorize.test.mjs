// vectorize(): every method in 2D and 3D, planes, known answers on noise-free shapes, Douglas-Peucker against an
// independent JS implementation on real scans, residual bounds, option checks and errors.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import init from 'rtl-wasm';
import { near, nearArray, throwsWith } from './helpers.mjs';

const rtl = await init();

// L-shape: (0,0) -> (1,0) -> (1,1), 0.01 apart: 101 + 100 points, corner at index 100.
const L = [];
for (let i = 0; i <= 100; i++) L.push(i * 0.01, 0);
for (let i = 1; i <= 100; i++) L.push(1, i * 0.01);
const L2 = new Float64Array(L);
const L3 = new Float64Array(L.flatMap((v, i) => (i % 2 ? [v, 0.25] : [v])));  // z = 0.25

function sameLineParams(p, [a, b, c], tol, what) {
  const s = Math.sign(p[0] * a + p[1] * b) || 1;
  nearArray([p[0], p[1], p[2]], [s * a, s * b, s * c], tol, what);
}

test('vectorize 2D: aftls, dp and rw find the exact L (segments, ranges, line parameters, zero residuals)', () => {
  // RW's epsilon 0.005, not 0.01: the first point after the corner lies exactly 0.01 from y = 0, on the strip's edge,
  // where the result depends on the last bit of epsilon (the decimal 0.01 lies between float(0.01) and double(0.01)).
  for (const [method, o] of [['aftls', { sigma: 0.005 }], ['dp', { epsilon: 0.01 }], ['rw', { epsilon: 0.005 }]]) {
    const v = rtl.vectorize(L2, { method, ...o });
    assert.equal(v.method, method);
    assert.equal(v.dim, 2);
    assert.equal(v.primitive, 'line');
    assert.equal(v.ok, true, method);
    assert.equal(v.count, 2, method);
    assert.ok(v.segments instanceof Float64Array && v.indices instanceof Uint32Array && v.params instanceof Float64Array);
    nearArray(v.segments, [0, 0, 1, 0, 1, 0, 1, 1], 1e-12, `${method} segments`);
    assert.deepEqual(Array.from(v.indices), method === 'aftls' ? [0, 101, 101, 201] : [0, 101, 100, 201], `${method} ranges`);
    assert.equal(v.stride, 3);
    sameLineParams(v.params.subarray(0, 3), [0, 1, 0], 1e-12, `${method} line 0: y = 0`);
    sameLineParams(v.params.subarray(3, 6), [1, 0, -1], 1e-12, `${method} line 1: x = 1`);
    nearArray(v.rms, [0, 0], 1e-9, `${method} rms`);
    assert.deepEqual(v.polygons, []);
  }
});

test('vectorize 2D: ftls and itls split near the corner within sigma; the ranges cover the chain', () => {
  for (const method of ['ftls', 'itls']) {
    for (const sigma of [0.03, 0.005]) {
      const v = rtl.vectorize(L2, { method, sigma });
      assert.equal(v.ok, true);
      assert.equal(v.count, 2, `${method} sigma ${sigma}`);
      assert.equal(v.indices[0], 0);
      assert.equal(v.indices[3], 201);
      assert.equal(v.indices[1], v.indices[2], 'consecutive ranges');
      assert.ok(Math.abs(v.indices[1] - 101) <= 20, `split near the corner: ${v.indices[1]}`);
      for (const r of v.rms) assert.ok(r <= sigma * (1 + 1e-9), `${method}: rms ${r} <= sigma ${sigma}`);
      nearArray(v.segments.subarray(6, 8), [1, 1], 1e-3, `${method} ends at the last point`);
    }
  }
});

test('vectorize 3D: lines with every method; planes with aftls', () => {
  for (const method of ['ftls', 'aftls', 'itls', 'dp', 'rw']) {
    const v = rtl.vectorize(L3, { dim: 3, method, ...(method === 'dp' || method === 'rw' ? { epsilon: 0.01 } : { sigma: 0.005 }) });
    assert.equal(v.ok, true, method);
    assert.equal(v.count, 2, method);
    assert.equal(v.segments.length, 12);
    assert.equal(v.stride, 6);
    assert.equal(v.params.length, 12);
    for (let k = 0; k < 2; k++) near(Math.hypot(...v.params.subarray(6 * k + 3, 6 * k + 6)), 1, 1e-12, `${method} unit direction`);
    near(Math.abs(v.params[3]), 1, 1e-3, `${method} first line along x`);
    near(Math.abs(v.params[10]), 1, 1e-3, `${method} second line along y`);
    for (let i = 2; i < 12; i += 3) near(v.segments[i], 0.25, 1e-9, `${method} z`);
  }
  // A 10 x 10 grid in the plane z = 0.5: one polygon, normal (0,0,+-1), d = +-0.5, zero residual.
  const grid = [];
  for (let i = 0; i < 10; i++) for (let j = 0; j < 10; j++) grid.push(i * 0.1, j * 0.1, 0.5);
  const p = rtl.vectorize(grid, { dim: 3, method: 'aftls', primitive: 'plane', sigma: 0.01, simplexShift: 2, maxIterations: 50 });
  assert.equal(p.ok, true);
  assert.equal(p.primitive, 'plane');
  assert.equal(p.count, 1);
  assert.equal(p.stride, 4);
  const s = Math.sign(p.params[2]);
  nearArray(p.params, [0, 0, s, 0.5 * s], 1e-12, 'plane');
  near(p.rms[0], 0, 1e-12);
  assert.equal(p.segments.length, 0);
  assert.equal(p.polygons.length, 1);
  assert.ok(p.polygons[0] instanceof Float64Array && p.polygons[0].length >= 9 && p.polygons[0].length % 3 === 0);
  for (let i = 2; i < p.polygons[0].length; i += 3) near(p.polygons[0][i], 0.5, 1e-12, 'polygon in the plane');
  assert.deepEqual(Array.from(p.indices), [0, 100]);
});

// Independent Douglas-Peucker (recursive): keep the farthest point from the infinite line through the ends
// (distance to the point when the ends coincide; the first one on ties) while it is > epsilon.
function douglasPeucker(xy, eps) {
  const n = xy.length / 2, keep = new Uint8Array(n);
  keep[0] = keep[n - 1] = 1;
  const stack = [[0, n - 1]];
  while (stack.length) {
    const [a, b] = stack.pop();
    const ax = xy[2 * a], ay = xy[2 * a + 1], dx = xy[2 * b] - ax, dy = xy[2 * b + 1] - ay, len = Math.hypot(dx, dy);
    let best = -1, bi = -1;
    for (let i = a + 1; i < b; i++) {
      const px = xy[2 * i] - ax, py = xy[2 * i + 1] - ay;
      const d = len > 0 ? Math.abs(px * dy - py * dx) / len : Math.hypot(px, py);
      if (d > best) { best = d; bi = i; }
    }
    if (bi >= 0 && best > eps) { keep[bi] = 1; stack.push([a, bi], [bi, b]); }
  }
  return Array.from(keep.keys()).filter((i) => keep[i]);
}

// The first scans of a CARMEN log: all beams (NaN gaps), or only the returns as one chain.
function scans(name, count) {
  const text = readFileSync(new URL(`../data/${name}`, import.meta.url), 'utf8');
  return text.split('\n').filter((l) => l.startsWith('FLASER')).slice(0, count).map((l) => {
    const t = l.trim().split(/\s+/).map(Number);
    const n = t[1], res = n % 2 ? Math.PI / (n - 1) : Math.PI / n, out = new Float64Array(2 * n);
    for (let i = 0; i < n; i++) {
      const r = t[2 + i], a = -Math.PI / 2 + i * res, ok = r > 0 && r < 80;
      out[2 * i] = ok ? r * Math.cos(a) : NaN;
      out[2 * i + 1] = ok ? r * Math.sin(a) : NaN;
    }
    return out;
  });
}
function chains(name, count) {
  const text = readFileSync(new URL(`../data/${name}`, import.meta.url), 'utf8');
  return text.split('\n').filter((l) => l.startsWith('FLASER')).slice(0, count).map((l) => {
    const t = l.trim().split(/\s+/).map(Number);
    const n = t[1], res = n % 2 ? Math.PI / (n - 1) : Math.PI / n, out = [];
    for (let i = 0; i < n; i++) {
      const r = t[2 + i], a = -Math.PI / 2 + i * res;
      if (r > 0 && r < 80) out.push(r * Math.cos(a), r * Math.sin(a));
    }
    return new Float64Array(out);
  });
}

test('vectorize dp: the same kept points as an independent Douglas-Peucker on real scans', () => {
  for (const xy of [...chains('intel.log', 10), ...chains('csail.log', 10)]) {
    for (const eps of [0.02, 0.09, 0.3]) {
      const v = rtl.vectorize(xy, { method: 'dp', epsilon: eps });
      const kept = [0];
      for (let k = 0; k < v.count; k++) kept.push(v.indices[2 * k + 1] - 1);
      assert.deepEqual(kept, douglasPeucker(xy, eps), `epsilon ${eps}`);
      for (let k = 0; k < v.count; k++) {
        const i = v.indices[2 * k], j = v.indices[2 * k + 1] - 1;
        nearArray(v.segments.subarray(4 * k, 4 * k + 4), [xy[2 * i], xy[2 * i + 1], xy[2 * j], xy[2 * j + 1]], 0, 'kept points');
        assert.ok(v.rms[k] <= eps, 'every point of a span within epsilon of its chord, so the rms too');
      }
    }
  }
});

// The clusters (>= 2 points) of the first scans of a log, as gap-free chains.
function clusters(name, count) {
  const out = [];
  for (const xy of scans(name, count)) {
    for (const c of rtl.segment(xy).clusters) {
      if (c.indices.length >= 2) out.push(Float64Array.from(Array.from(c.indices).flatMap((i) => [xy[2 * i], xy[2 * i + 1]])));
    }
  }
  return out;
}

test('vectorize on real scan clusters: valid ranges, unit normals, rms <= sigma (TLS); success rates', () => {
  const tally = {};
  for (const xy of [...clusters('intel.log', 10), ...clusters('csail.log', 10)]) {
    const n = xy.length / 2;
    for (const method of ['ftls', 'aftls', 'itls', 'dp', 'rw']) {
      const v = rtl.vectorize(xy, { method, sigma: 0.03, delta: 0.3, epsilon: 0.09 });
      tally[method] ??= { ok: 0, all: 0 };
      tally[method].all++;
      if (!v.ok) {
        assert.equal(v.count, 0);
        continue;
      }
      tally[method].ok++;
      assert.ok(v.count >= 1, method);
      assert.equal(v.indices[0], 0, `${method} starts at 0`);
      assert.equal(v.indices[2 * v.count - 1], n, `${method} ends at the last point`);
      for (let k = 0; k < v.count; k++) assert.ok(v.indices[2 * k] < v.indices[2 * k + 1], `${method} non-empty range`);
      for (let k = 0; k + 1 < v.count; k++) assert.ok(v.indices[2 * k + 2] <= v.indices[2 * k + 1], `${method} ranges in order, no holes`);
      assert.equal(v.rms.length, v.count);
      assert.equal(v.params.length, 3 * v.count);
      for (let k = 0; k < v.count; k++) near(Math.hypot(v.params[3 * k], v.params[3 * k + 1]), 1, 1e-9, 'unit normal');
      if (method === 'ftls' || method === 'aftls' || method === 'itls')
        for (const r of v.rms) assert.ok(r <= 0.03 * (1 + 1e-9), `${method}: rms ${r} <= sigma`);
    }
  }
  for (const m of ['itls', 'dp', 'rw']) assert.equal(tally[m].ok, tally[m].all, `${m} always succeeds`);
  // Published RTL defect 4 (docs/reference.md, "Vectorization defects fixed here"): FTLS/AFTLS may fail when the
  // continuity repair cannot split a short pair.
  for (const m of ['ftls', 'aftls']) assert.ok(tally[m].ok >= 0.9 * tally[m].all, `${m}: ${tally[m].ok} of ${tally[m].all}`);
});

const ERRORS = [
  ['no options', () => rtl.vectorize(L2), TypeError, /vectorize: options \{method\} are required/],
  ['no method', () => rtl.vectorize(L2, { sigma: 0.1 }), TypeError, /option method is required/],
  ['method a number', () => rtl.vectorize(L2, { method: 1 }), TypeError, /option method must be a string/],
  ['unknown method', () => rtl.vectorize(L2, { method: 'spline' }), RangeError, /method must be one of ftls, aftls, itls, dp, rw, got 'spline'/],
  ['unknown option', () => rtl.vectorize(L2, { method: 'dp', epsylon: 0.1 }), TypeError, /unknown option "epsylon"/],
  ['an unused option is still checked', () => rtl.vectorize(L2, { method: 'dp', sigma: -1 }), RangeError, /option sigma must be > 0/],
  ['plane in 2D', () => rtl.vectorize(L2, { method: 'aftls', primitive: 'plane' }), RangeError, /primitive 'plane' needs dim 3 and method 'aftls'/],
  ['plane with ftls', () => rtl.vectorize(L3, { dim: 3, method: 'ftls', primitive: 'plane' }), RangeError, /needs dim 3 and method 'aftls'/],
  ['bad primitive', () => rtl.vectorize(L3, { dim: 3, method: 'aftls', primitive: 'surface' }), RangeError, /primitive must be 'line' or 'plane'/],
  ['sigma 0', () => rtl.vectorize(L2, { method: 'ftls', sigma: 0 }), RangeError, /option sigma must be > 0, got 0/],
  ['sigma NaN', () => rtl.vectorize(L2, { method: 'itls', sigma: NaN }), RangeError, /option sigma must be finite/],
  ['epsilon negative', () => rtl.vectorize(L2, { method: 'rw', epsilon: -1 }), RangeError, /option epsilon must be > 0/],
  ['simplexShift 0', () => rtl.vectorize(L2, { method: 'aftls', simplexShift: 0 }), RangeError, /option simplexShift must be >= 1/],
  ['maxIterations 1.5', () => rtl.vectorize(L2, { method: 'aftls', maxIterations: 1.5 }), RangeError, /option maxIterations must be an integer/],
  ['maxSize -1', () => rtl.vectorize(L2, { method: 'dp', maxSize: -1 }), RangeError, /option maxSize must be >= 0/],
  ['one point', () => rtl.vectorize([1, 2], { method: 'ftls' }), RangeError, /vectorize: needs at least 2 points, got 1/],
  ['NaN point', () => rtl.vectorize([0, 0, NaN, 1, 2, 2], { method: 'dp' }), RangeError, /vectorize: point 1 has a non-finite coordinate \(NaN\)/],
  ['odd length', () => rtl.vectorize([0, 0, 1], { method: 'dp' }), RangeError, /not a multiple of dim 2/],
  ['points an object', () => rtl.vectorize({}, { method: 'dp' }), TypeError, /vectorize: points must be/],
];
for (const [name, f, type, re] of ERRORS) {
  test(`vectorize error: ${name}`, () => {
    throwsWith(f, type, re);
    assert.equal(rtl.vectorize(L2, { method: 'dp', epsilon: 0.01 }).count, 2, 'works afterwards');
  });
}
