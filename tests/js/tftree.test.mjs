// TfTree: known 2D/3D answers, quaternion vs angle-axis, inverse round trips, erase of subtrees, transformPoints
// against a JS computation on 1M points, dispose and errors.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import init from 'rtl-wasm';
import { near, nearArray, throwsWith } from './helpers.mjs';

const rtl = await init();

test('TfTree 2D: tf(from, to) composes inverses up and node transformations down', () => {
  const t = new rtl.TfTree('map');
  assert.equal(t.dim, 2);
  assert.equal(t.size, 1);
  assert.equal(t.insert('robot', 'map', { angle: Math.PI / 2, translation: [1, 2] }), true);
  assert.equal(t.insert('laser', 'robot', { translation: [0.5, 0] }), true);
  assert.equal(t.insert('laser', 'map', { angle: 0 }), false, 'existing name');
  assert.equal(t.insert('x', 'nowhere', { angle: 0 }), false, 'unknown parent');
  assert.equal(t.size, 3);
  // Node tfs map parent -> child coordinates: p_robot = R90 p_map + (1,2); p_laser = p_robot + (0.5, 0).
  const down = t.tf('map', 'laser');
  nearArray(down.rotation, [0, -1, 1, 0], 1e-15, 'rotation');
  nearArray(down.translation, [1.5, 2], 1e-15, 'translation');
  nearArray(down.matrix, [0, -1, 1.5, 1, 0, 2, 0, 0, 1], 1e-15, 'matrix');
  const p = t.transformPoints('laser', 'map', [1, 0, NaN, NaN]);
  nearArray(p.subarray(0, 2), [-2, 0.5], 1e-15, 'laser (1,0) in the map');
  assert.ok(Number.isNaN(p[2]) && Number.isNaN(p[3]));
  t[Symbol.dispose]();
  assert.equal(t.disposed, true);
});

test('TfTree 3D: quaternion and angle-axis agree; tf(a,b) then tf(b,a) is the identity', () => {
  const t = new rtl.TfTree('world', { dim: 3 });
  const a = 0.7, axis = [1, 2, 2];
  t.insert('q', 'world', { quaternion: [Math.cos(a / 2), ...axis.map((v) => (v / 3) * Math.sin(a / 2))], translation: [1, 2, 3] });
  t.insert('aa', 'world', { angle: a, axis, translation: [1, 2, 3] });
  t.insert('cam', 'q', { quaternion: [2, 0, 0, 2], translation: [0, 0, 1] });   // normalised: 90 deg about z
  t.insert('lidar', 'aa', { angle: -0.3, axis: [0, 1, 0] });
  const q = t.tf('world', 'q'), aa = t.tf('world', 'aa');
  nearArray(q.matrix, aa.matrix, 1e-14, 'same frame either way');
  const m = t.tf('q', 'cam');
  nearArray(m.rotation, [0, -1, 0, 1, 0, 0, 0, 0, 1], 1e-15, '[2,0,0,2] is 90 degrees about z');
  nearArray(m.translation, [0, 0, 1], 0);
  const pts = new Float64Array([0.1, -2, 3, 4, 5, -6, NaN, 0, 0]);
  const there = t.transformPoints('lidar', 'cam', pts);
  const back = t.transformPoints('cam', 'lidar', there);
  nearArray(back.subarray(0, 6), pts.subarray(0, 6), 1e-12, 'round trip');
  assert.ok(Number.isNaN(back[6]), 'NaN stays NaN');
  t.dispose();
});

test('TfTree: erase removes the subtree; contains; 1M points match a JS computation', () => {
  const t = new rtl.TfTree('o');
  t.insert('a', 'o', { angle: 0.3, translation: [1, 0] });
  t.insert('b', 'a', { angle: -1.1, translation: [0, 2] });
  t.insert('c', 'b', { angle: 0.2, translation: [3, 3] });
  t.insert('d', 'o', { angle: 2, translation: [-1, -1] });
  const n = 1_000_000, pts = new Float64Array(2 * n).map((_, i) => Math.sin(i) * 50);
  const { rotation: R, translation: T } = t.tf('c', 'd');
  const out = t.transformPoints('c', 'd', pts);
  for (let i = 0; i < n; i += 9973) {
    near(out[2 * i], R[0] * pts[2 * i] + R[1] * pts[2 * i + 1] + T[0], 1e-9, `x ${i}`);
    near(out[2 * i + 1], R[2] * pts[2 * i] + R[3] * pts[2 * i + 1] + T[1], 1e-9, `y ${i}`);
  }
  assert.equal(t.erase('a'), true);
  assert.deepEqual(['o', 'a', 'b', 'c', 'd'].map((k) => t.contains(k)), [true, false, false, false, true]);
  assert.equal(t.size, 2);
  assert.equal(t.erase('o'), false, 'not the root');
  assert.equal(t.erase('zz'), false);
  t.dispose();
  assert.equal(t.disposed, true);
  throwsWith(() => t.size, TypeError, /TfTree\.size: the tree was disposed/);
});

const ERRORS = [
  ['root not a string', () => new rtl.TfTree(3), TypeError, /TfTree: root must be a string/],
  ['empty root', () => new rtl.TfTree(''), RangeError, /TfTree: root must not be empty/],
  ['dim 4', () => new rtl.TfTree('r', { dim: 4 }), RangeError, /option dim must be 2 or 3/],
];
for (const [name, f, type, re] of ERRORS) test(`TfTree error: ${name}`, () => throwsWith(f, type, re));

test('TfTree errors on a live tree, which keeps working', () => {
  const t = new rtl.TfTree('r', { dim: 3 });
  throwsWith(() => t.insert('a', 'r', 'x'), TypeError, /TfTree\.insert: the transformation must be an object/);
  throwsWith(() => t.insert('a', 'r', { angle: 1 }), TypeError, /angle needs an axis in 3D/);
  throwsWith(() => t.insert('a', 'r', { angle: 1, axis: [0, 0, 0] }), RangeError, /axis must not be the zero vector/);
  throwsWith(() => t.insert('a', 'r', { quaternion: [0, 0, 0, 0] }), RangeError, /quaternion must not be zero/);
  throwsWith(() => t.insert('a', 'r', { quaternion: [1, 0, 0], translation: [0, 0, 0] }), RangeError, /quaternion must have 4 numbers, got 3/);
  throwsWith(() => t.insert('a', 'r', { translation: [0, NaN, 0] }), RangeError, /translation\[1\] must be finite/);
  throwsWith(() => t.insert('a', 'r', { quaternion: [1, 0, 0, 0], angle: 1, axis: [1, 0, 0] }), TypeError, /either quaternion or angle \+ axis/);
  throwsWith(() => t.insert('a', 'r', { rotation: 1 }), TypeError, /unknown option "rotation"/);
  throwsWith(() => t.insert(5, 'r', {}), TypeError, /TfTree\.insert: name must be a string/);
  throwsWith(() => t.tf('r', 'nope'), RangeError, /^TfTree\.tf: unknown frame 'nope'$/);
  throwsWith(() => t.transformPoints('r', 'r', [1, 2]), RangeError, /TfTree\.transformPoints: points has 2 numbers, not a multiple of dim 3/);
  throwsWith(() => t.transformPoints('r', 'r', [1, 2, Infinity]), RangeError, /non-finite coordinate \(Infinity\)/);
  assert.equal(t.insert('a', 'r', { translation: [1, 2, 3] }), true);
  nearArray(t.transformPoints('r', 'a', [0, 0, 0]), [1, 2, 3], 0);
  t.dispose();
});

test('TfTree: forgotten trees are freed by the FinalizationRegistry (child process, --expose-gc)', { timeout: 60_000 }, async () => {
  const { execFileSync } = await import('node:child_process');
  const { fileURLToPath } = await import('node:url');
  const script = `
    import init from 'rtl-wasm';
    const rtl = await init();
    const make = () => { for (let i = 0; i < 100; i++) { const t = new rtl.TfTree('root', { dim: 3 });
      for (let k = 0; k < 50; k++) t.insert('f' + k, k ? 'f' + (k - 1) : 'root', { angle: 0.1, axis: [0, 0, 1], translation: [k, 0, 0] }); } };
    const settle = async () => { for (let k = 0; k < 4; k++) { globalThis.gc(); await new Promise((r) => setTimeout(r, 30)); } };
    make(); await settle();
    const base = rtl.heapInUse();
    make();
    const grown = rtl.heapInUse();
    for (let k = 0; k < 10 && rtl.heapInUse() > base; k++) await settle();
    console.log(JSON.stringify({ base, grown, after: rtl.heapInUse() }));`;
  const out = execFileSync(process.execPath, ['--expose-gc', '--input-type=module', '-e', script],
    { cwd: fileURLToPath(new URL('../..', import.meta.url)), encoding: 'utf8' });
  const { base, grown, after } = JSON.parse(out);
  assert.ok(grown > base + 100 * 50 * 100, `100 live trees of 50 frames hold memory (${base} -> ${grown})`);
  assert.ok(after <= base, `all freed after GC: ${after} <= ${base}`);
});
