// simplify(): the drop-in for simplify-js keeps exactly simplify-js's points (the same objects), in both quality
// modes, on noisy semicircles, random walks and the real scans of tests/data, 10 to 1,000,000 points; 3D against
// simplify-js's 3D variant (the same code on x, y, z, written out below as the oracle); the typed-array form and
// vectorize({ method: 'dp', distance: 'segment' }) keep the same indices; argument errors.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { fileURLToPath } from 'node:url';
import simplifyJs from 'simplify-js';
import init from 'rtl-wasm';
import { throwsWith } from './helpers.mjs';

const DATA = fileURLToPath(new URL('../data/', import.meta.url));
const rtl = await init();

function rng(seed) {
  let s = seed >>> 0;
  return () => ((s = (Math.imul(s, 1664525) + 1013904223) >>> 0) / 4294967296);
}
// Noisy semicircle of radius 8 (the RTL paper's test curve), noise 0.01.
function semicircle(n, seed = 1, dim = 2) {
  const r = rng(seed);
  return Array.from({ length: n }, (_, i) => {
    const a = (Math.PI * i) / Math.max(n - 1, 1);
    const p = { x: 8 * Math.cos(a) + 0.01 * (r() - 0.5), y: 8 * Math.sin(a) + 0.01 * (r() - 0.5) };
    if (dim === 3) p.z = 0.5 * Math.sin(3 * a) + 0.01 * (r() - 0.5);
    return p;
  });
}
// Random walk: the chord's farthest point often projects outside the chord, where segment and line distance differ.
function walk(n, seed = 2, dim = 2) {
  const r = rng(seed);
  let x = 0, y = 0, z = 0;
  return Array.from({ length: n }, () => {
    x += r() - 0.5; y += r() - 0.5; z += r() - 0.5;
    return dim === 3 ? { x, y, z } : { x, y };
  });
}
// Every scan of the real logs as {x, y} polylines (gaps dropped).
const scans = ['intel.log', 'csail.log'].flatMap((f) => rtl.readCarmenLog(readFileSync(DATA + f, 'utf8')).map((s) => {
  const pts = [];
  for (let i = 0; i < s.points.length; i += 2) if (!Number.isNaN(s.points[i])) pts.push({ x: s.points[i], y: s.points[i + 1] });
  return pts;
}));

// simplify-js's 3D variant: its code with z added to both distances (the oracle for {x, y, z}).
function simplify3dReference(points, tolerance, highQuality) {
  if (points.length <= 2) return points;
  const sq = tolerance !== undefined ? tolerance * tolerance : 1;
  const d2 = (p, q) => { const dx = p.x - q.x, dy = p.y - q.y, dz = p.z - q.z; return dx * dx + dy * dy + dz * dz; };
  const seg2 = (p, p1, p2) => {
    let x = p1.x, y = p1.y, z = p1.z, dx = p2.x - x, dy = p2.y - y, dz = p2.z - z;
    if (dx !== 0 || dy !== 0 || dz !== 0) {
      const t = ((p.x - x) * dx + (p.y - y) * dy + (p.z - z) * dz) / (dx * dx + dy * dy + dz * dz);
      if (t > 1) { x = p2.x; y = p2.y; z = p2.z; } else if (t > 0) { x += dx * t; y += dy * t; z += dz * t; }
    }
    dx = p.x - x; dy = p.y - y; dz = p.z - z;
    return dx * dx + dy * dy + dz * dz;
  };
  let pts = points;
  if (!highQuality) {
    let prev = pts[0], point;
    const out = [prev];
    for (let i = 1; i < pts.length; i++) { point = pts[i]; if (d2(point, prev) > sq) { out.push(point); prev = point; } }
    if (prev !== point) out.push(point);
    pts = out;
  }
  const keep = [pts[0]];
  const step = (first, last) => {
    let max = sq, index;
    for (let i = first + 1; i < last; i++) { const d = seg2(pts[i], pts[first], pts[last]); if (d > max) { index = i; max = d; } }
    if (max > sq) {
      if (index - first > 1) step(first, index);
      keep.push(pts[index]);
      if (last - index > 1) step(index, last);
    }
  };
  step(0, pts.length - 1);
  keep.push(pts[pts.length - 1]);
  return keep;
}

function sameObjects(ours, theirs, what) {
  assert.equal(ours.length, theirs.length, `${what}: kept count`);
  for (let i = 0; i < theirs.length; i++) if (ours[i] !== theirs[i]) assert.fail(`${what}: kept point ${i} differs`);
}
const flat = (pts, dim) => {
  const a = new Float64Array(dim * pts.length);
  pts.forEach((p, i) => { a[dim * i] = p.x; a[dim * i + 1] = p.y; if (dim === 3) a[dim * i + 2] = p.z; });
  return a;
};

test('simplify keeps the same objects as simplify-js: semicircles and random walks, 10 to 1,000,000 points, both modes', () => {
  for (const n of [10, 100, 1000, 10_000, 100_000, 1_000_000]) {
    for (const [name, pts, tols] of [['semicircle', semicircle(n), [0.005, 0.05, 1]], ['walk', walk(n), [0.3, 2, 10]]]) {
      for (const tol of tols) {
        for (const hq of [false, true]) {
          const theirs = simplifyJs(pts, tol, hq);
          sameObjects(rtl.simplify(pts, tol, hq), theirs, `${name} n=${n} tol=${tol} hq=${hq}`);
          if (n === 1000 && tol !== tols[2]) assert.ok(theirs.length > 2 && theirs.length < n, `${name}: a non-trivial case (${theirs.length} kept)`);
        }
      }
    }
  }
});

test('simplify keeps the same objects as simplify-js on every real scan of tests/data (intel, csail)', () => {
  assert.ok(scans.length >= 50, `${scans.length} scans`);
  let kept = 0;
  for (const pts of scans) {
    for (const tol of [0.02, 0.1]) {
      for (const hq of [false, true]) {
        const theirs = simplifyJs(pts, tol, hq);
        sameObjects(rtl.simplify(pts, tol, hq), theirs, `scan tol=${tol} hq=${hq}`);
        kept += theirs.length;
      }
    }
  }
  assert.ok(kept > 4 * 2 * scans.length, 'scans keep more than their end points');
});

test('simplify-js defaults: tolerance 1, fast mode; 2 or fewer points come back as the same array', () => {
  const pts = walk(5000, 9);
  sameObjects(rtl.simplify(pts), simplifyJs(pts), 'defaults');
  sameObjects(rtl.simplify(pts, undefined, true), simplifyJs(pts, undefined, true), 'default tolerance, high quality');
  for (const few of [[], [{ x: 1, y: 2 }], [{ x: 1, y: 2 }, { x: 3, y: 4 }]]) assert.equal(rtl.simplify(few, 0.1), few);
  const dup = [{ x: 0, y: 0 }, { x: 0, y: 0 }, { x: 0, y: 0 }, { x: 1, y: 1 }, { x: 1, y: 1 }];
  for (const hq of [false, true]) sameObjects(rtl.simplify(dup, 0, hq), simplifyJs(dup, 0, hq), `duplicates, tolerance 0, hq=${hq}`);
  sameObjects(rtl.simplify(pts, Infinity), [pts[0], pts[pts.length - 1]], 'Infinity keeps the end points');
  const tagged = semicircle(300).map((p, i) => ({ ...p, id: i }));
  const out = rtl.simplify(tagged, 0.05);
  assert.ok(out.every((p) => p === tagged[p.id]), 'the caller\'s own objects, extra properties included');
});

// The radial pre-pass compares the last point with the last kept one by object identity (simplify-js's
// `prevPoint !== point`), not by index: an array holding one object several times must come out as simplify-js's.
test('simplify fast mode: repeated objects and a non-finite point the pre-pass would drop', () => {
  const a = { x: 0, y: 0 }, b = { x: 5, y: 0 }, c = { x: 5, y: 3 };
  const cases = [[a, a, a], [a, a, a, a, a], [a, b, b], [a, b, a], [a, b, c, b, b], [a, c, a, b, a, a], [b, a, c, a, a, b, b]];
  for (const pts of cases) {
    for (const tol of [0, 1, 10]) {
      sameObjects(rtl.simplify(pts, tol), simplifyJs(pts, tol), `${JSON.stringify(pts)} tol=${tol}`);
      sameObjects(rtl.simplify(pts, tol, true), simplifyJs(pts, tol, true), `${JSON.stringify(pts)} tol=${tol} hq`);
    }
  }
  assert.deepEqual(rtl.simplify([a, a, a], 1), [a, a], 'one object throughout: simplify-js returns it twice');
  // Long arrays ending with an object met before (the core's pre-pass learns which indices hold it), kept last or not.
  for (const k of [0, 1, 2, 17, 4990, 4997, 4998]) {
    const w = walk(5000, 11);
    w.push(w[k], w[k]);
    for (const tol of [0.1, 1, 3]) sameObjects(rtl.simplify(w, tol), simplifyJs(w, tol), `walk ending with point ${k} twice, tol ${tol}`);
  }
  // 0.001 from its predecessor: the pre-pass would drop it, the check still sees it (all modes, 2D and 3D)
  const near = [{ x: 0, y: 0 }, { x: 1, y: 0 }, { x: 1.001, y: NaN }, { x: 2, y: 0 }];
  for (const hq of [false, true]) {
    throwsWith(() => rtl.simplify(near, 0.5, hq), RangeError, /^simplify: point 2 has a non-finite coordinate \(NaN\) at index 5$/);
    throwsWith(() => rtl.simplify(near.map((p, i) => ({ ...p, z: i === 1 ? Infinity : 0 })), 0.5, hq), RangeError,
      /^simplify: point 1 has a non-finite coordinate \(Infinity\) at index 5$/);
  }
  // a wrong type after a non-finite number: the TypeError wins, as the check of the types comes first
  throwsWith(() => rtl.simplify([...near, { x: 'a', y: 0 }], 0.5), TypeError, /^simplify: points\[4\]\.x and \.y must be numbers/);
});

test('simplify {x, y, z}: the same objects as simplify-js\'s 3D variant (and dim 2 ignores z, as simplify-js)', () => {
  for (const n of [10, 1000, 100_000]) {
    for (const [name, pts, tol] of [['semicircle', semicircle(n, 3, 3), 0.02], ['walk', walk(n, 4, 3), 1]]) {
      for (const hq of [false, true]) {
        const theirs = simplify3dReference(pts, tol, hq);
        sameObjects(rtl.simplify(pts, tol, hq), theirs, `3D ${name} n=${n} hq=${hq}`);
        sameObjects(rtl.simplify(pts, tol, hq, { dim: 2 }), simplifyJs(pts, tol, hq), `${name} n=${n} hq=${hq} as 2D`);
        if (n === 1000) assert.notDeepEqual(theirs, simplifyJs(pts, tol, hq), `${name}: z matters`);
      }
    }
  }
});

test('typed-array form and vectorize distance segment keep the same points; distance line is the default', () => {
  for (const [dim, pts, tol] of [[2, walk(20_000, 5), 0.5], [2, semicircle(20_000, 6), 0.01], [3, walk(20_000, 7, 3), 0.5]]) {
    const ref = dim === 3 ? simplify3dReference(pts, tol, true) : simplifyJs(pts, tol, true);
    const xyz = flat(pts, dim);
    assert.deepEqual(rtl.simplify(xyz, tol, true, { dim }), flat(ref, dim), `dim ${dim}: Float64Array form`);
    const f32 = new Float32Array(xyz);
    assert.deepEqual(rtl.simplify(f32, tol, true, { dim }), rtl.simplify(new Float64Array(f32), tol, true, { dim }), 'Float32Array');
    const fast = dim === 3 ? simplify3dReference(pts, tol, false) : simplifyJs(pts, tol, false);
    assert.deepEqual(rtl.simplify(xyz, tol, false, { dim }), flat(fast, dim), `dim ${dim}: Float64Array form, fast mode`);
    const v = rtl.vectorize(xyz, { dim, method: 'dp', epsilon: tol, distance: 'segment' });
    const index = new Map(pts.map((p, i) => [p, i]));
    const kept = [0, ...Array.from({ length: v.count }, (_, k) => v.indices[2 * k + 1] - 1)];
    assert.deepEqual(kept, ref.map((p) => index.get(p)), `dim ${dim}: vectorize distance 'segment'`);
    assert.equal(v.segments.length, 2 * dim * v.count);
    const line = rtl.vectorize(xyz, { dim, method: 'dp', epsilon: tol, distance: 'line' });
    assert.deepEqual(rtl.vectorize(xyz, { dim, method: 'dp', epsilon: tol }), line, 'line is the default');
  }
  // On a random walk the chord's line and segment keep different points (simplify-js's vs RTL's distance).
  const w = flat(walk(20_000, 5), 2);
  assert.notDeepEqual(rtl.vectorize(w, { method: 'dp', epsilon: 0.5, distance: 'segment' }).indices,
    rtl.vectorize(w, { method: 'dp', epsilon: 0.5 }).indices);
  // A point beyond the chord's end: 1 from the segment, 0 from the line.
  const hook = new Float64Array([0, 0, 1, 0, 3, 0, 2, 0]);
  assert.equal(rtl.vectorize(hook, { method: 'dp', epsilon: 0.5, distance: 'segment' }).count, 2);
  assert.equal(rtl.vectorize(hook, { method: 'dp', epsilon: 0.5 }).count, 1);
});

// The radial pre-pass runs in steps of several points and detects a non-finite coordinate by the sum of the step's
// distances (an exact check follows only if that sum overflows): huge finite coordinates, whose squares and sums
// overflow, must follow simplify-js; a non-finite one anywhere (first, inside a step, in the tail, last) must throw.
test('simplify fast mode: huge finite coordinates follow simplify-js; a non-finite one anywhere throws naming it', () => {
  for (const scale of [1e150, 1e200]) {
    for (const n of [5, 9, 17, 1000]) {
      const pts = walk(n, 7).map((p) => ({ x: p.x * scale, y: p.y * scale }));
      for (const tol of [1, 3 * scale, 1e300]) {
        for (const hq of [false, true]) sameObjects(rtl.simplify(pts, tol, hq), simplifyJs(pts, tol, hq), `scale ${scale} n=${n} tol=${tol} hq=${hq}`);
      }
    }
  }
  const pts = walk(1003, 8);
  for (const at of [0, 1, 4, 8, 500, 999, 1000, 1001, 1002]) {
    for (const bad of [NaN, Infinity, -Infinity]) {
      for (const tol of [0.5, Infinity]) {
        const input = pts.map((p, i) => (i === at ? { x: p.x, y: bad } : p));
        throwsWith(() => rtl.simplify(input, tol), RangeError, new RegExp(`^simplify: point ${at} has a non-finite coordinate`));
      }
    }
  }
});

test('simplify argument errors name the function; the module keeps working and the heap does not grow', () => {
  const ok = [{ x: 0, y: 0 }, { x: 1, y: 1 }, { x: 2, y: 0 }];
  throwsWith(() => rtl.simplify('x'), TypeError, /^simplify: points must be an array of \{x, y\} objects or a typed array/);
  throwsWith(() => rtl.simplify([{ x: 0, y: 0 }, null, { x: 1, y: 1 }]), TypeError, /^simplify: points\[1\] is null, expected an object \{x, y\}$/);
  throwsWith(() => rtl.simplify([{ x: 0, y: 0 }, { x: '1', y: 1 }, { x: 1, y: 1 }]), TypeError, /^simplify: points\[1\]\.x and \.y must be numbers, got a string/);
  throwsWith(() => rtl.simplify([{ x: 0, y: 0, z: 0 }, { x: 1, y: 1 }, { x: 1, y: 1, z: 1 }]), TypeError, /^simplify: points\[1\]\.z must be a number \(dim 3\)/);
  throwsWith(() => rtl.simplify([1, 2, 3, 4]), TypeError, /^simplify: points\[0\] is the number 1, expected an object/);
  // Checked in the copy loop without an object test per point: null, undefined and primitives anywhere are named,
  // and an error thrown by a getter of the caller's comes through unchanged.
  throwsWith(() => rtl.simplify([{ x: 0, y: 0 }, { x: 1, y: 1 }, undefined]), TypeError, /^simplify: points\[2\] is undefined, expected an object \{x, y\}$/);
  throwsWith(() => rtl.simplify([{ x: 0, y: 0, z: 0 }, { x: 1, y: 1, z: 1 }, null]), TypeError, /^simplify: points\[2\] is null, expected an object \{x, y, z\}$/);
  throwsWith(() => rtl.simplify([{ x: 0, y: 0 }, 'ab', { x: 1, y: 1 }]), TypeError, /^simplify: points\[1\] is a string/);
  throwsWith(() => rtl.simplify([{ x: 0, y: 0 }, () => 0, { x: 1, y: 1 }]), TypeError, /^simplify: points\[1\] is a function/);
  const boom = new Error('boom');
  assert.throws(() => rtl.simplify([{ x: 0, y: 0 }, { get x() { throw boom; }, y: 1 }, { x: 1, y: 1 }]), (e) => e === boom);
  throwsWith(() => rtl.simplify(ok, '1'), TypeError, /^simplify: tolerance must be a number, got a string/);
  throwsWith(() => rtl.simplify(ok, -1), RangeError, /^simplify: tolerance must be >= 0 \(or Infinity\), got -1$/);
  throwsWith(() => rtl.simplify(ok, NaN), RangeError, /^simplify: tolerance must be >= 0 \(or Infinity\), got NaN$/);
  throwsWith(() => rtl.simplify(ok, 1, 1), TypeError, /^simplify: highQuality must be a boolean, got the number 1$/);
  throwsWith(() => rtl.simplify(ok, 1, false, { dims: 3 }), TypeError, /^simplify: unknown option "dims"/);
  throwsWith(() => rtl.simplify(ok, 1, false, { dim: 4 }), RangeError, /^simplify: option dim must be 2 or 3, got 4$/);
  throwsWith(() => rtl.simplify([{ x: 0, y: 0 }, { x: NaN, y: 1 }, { x: 1, y: 1 }]), RangeError, /^simplify: point 1 has a non-finite coordinate \(NaN\) at index 2$/);
  throwsWith(() => rtl.simplify([{ x: 0, y: 0 }, { x: 1, y: -Infinity }]), RangeError, /^simplify: point 1 has a non-finite coordinate \(-Infinity\)/);
  throwsWith(() => rtl.simplify(new Float64Array(5), 1, false, { dim: 2 }), RangeError, /^simplify: points has 5 numbers, not a multiple of dim 2/);
  throwsWith(() => rtl.vectorize(flat(ok, 2), { method: 'dp', distance: 'chord' }), RangeError, /^vectorize: option distance must be 'line' or 'segment', got a string \("chord"\)$/);
  throwsWith(() => rtl.vectorize(flat(ok, 2), { method: 'dp', distance: 'segment', trace: true }), RangeError, /^vectorize: option trace is not available with distance 'segment'$/);
  const pts = semicircle(2000);
  rtl.simplify(pts, 0.01);
  const heap = rtl.heapInUse(), sp = rtl.stackPointer();
  for (let i = 0; i < 2000; i++) {
    assert.throws(() => rtl.simplify([{ x: 0, y: 0 }, { x: NaN, y: 1 }, { x: 1, y: 1 }]), RangeError);
    rtl.simplify(pts, 0.01 * (1 + (i % 5)), i % 2 === 0);
  }
  assert.equal(rtl.heapInUse(), heap, 'heap');
  assert.equal(rtl.stackPointer(), sp, 'stack pointer');
  sameObjects(rtl.simplify(pts, 0.01), simplifyJs(pts, 0.01), 'still exact');
});
