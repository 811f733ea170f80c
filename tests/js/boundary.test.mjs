// The wasm boundary by name (wasm/src/schema.h, wasm/js/schema.js): options are written in the C++ declaration's
// order, results read by their declared names and types, and any disagreement between the two sides fails loudly
// instead of shifting values. First on a stand-in module whose declaration the test controls, then on the real one.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import init from 'rtl-wasm';
import { boundaryOf } from '../../wasm/js/schema.js';

// A stand-in module: HEAPF64 over 64 doubles, the options block at byte 16 (4 doubles), and a declaration.
function standIn(calls, capacity = 8) {
  const HEAPF64 = new Float64Array(64);
  return { HEAPF64, boundarySchema: () => ({ calls, optionsBlock: 16, optionsCapacity: capacity }) };
}
const demo = {
  options: [['dim', 1], ['origin', 3], ['trace', 1], ['method', 1, ['ftls', 'dp', 'rw']], ['sigma', 1]],
  scalars: ['computeMs', 'count'],
  arrays: [['labels', 'Int32Array'], ['values', 'Float64Array']],
};

test('writeOptions: the declared order, booleans as 0/1, arrays element by element, a choice as its index', () => {
  const m = standIn({ demo });
  const c = boundaryOf(m).call('demo');
  const at = c.writeOptions({ sigma: 0.25, method: 'rw', trace: true, origin: [1, 2, 3], dim: 3 });
  assert.equal(at, 16);
  assert.deepEqual([...m.HEAPF64.subarray(2, 9)], [3, 1, 2, 3, 1, 2, 0.25]);
  c.writeOptions({ dim: 2, origin: [0, 0, 0], trace: false, method: 'ftls', sigma: 1 });
  assert.deepEqual([...m.HEAPF64.subarray(2, 9)], [2, 0, 0, 0, 0, 0, 1]);
});

test('writeOptions: a missing option, an undeclared one or an unknown choice is an Error naming the call', () => {
  const all = { dim: 2, origin: [0, 0, 0], trace: false, method: 'dp', sigma: 1 };
  assert.throws(() => boundaryOf(standIn({ demo })).call('demo').writeOptions({ ...all, sigma: undefined }),
    { name: 'Error', message: /^rtl-wasm: demo: option sigma not given/ });
  assert.throws(() => boundaryOf(standIn({ demo })).call('demo').writeOptions({ ...all, extra: 1 }),
    { name: 'Error', message: /^rtl-wasm: demo: the module declares no option extra/ });
  assert.throws(() => boundaryOf(standIn({ demo })).call('demo').writeOptions({ ...all, method: 'aftls' }),
    { name: 'Error', message: /^rtl-wasm: demo: option method aftls is none of ftls, dp, rw/ });
  // the same after a good call (the generated writer hands a bad value to the checking one)
  const warm = boundaryOf(standIn({ demo })).call('demo');
  warm.writeOptions(all);
  assert.throws(() => warm.writeOptions({ ...all, sigma: undefined }), { message: /^rtl-wasm: demo: option sigma not given/ });
  assert.throws(() => warm.writeOptions({ ...all, method: 'x' }), { message: /^rtl-wasm: demo: option method x is none/ });
  assert.throws(() => warm.writeOptions({ ...all, origin: undefined }), TypeError);
  assert.throws(() => boundaryOf(standIn({ demo })).call('other'), { message: /declares no call "other"/ });
  assert.throws(() => boundaryOf(standIn({ demo }, 6)).call('demo'), { message: /need 7 numbers, the block holds 6/ });
});

// A result block at byte 80: [S, scalars..., A, (address, length) per array], arrays after it.
function block(m, scalars, arrays) {
  const H = m.HEAPF64;
  let k = 10;
  H[k++] = scalars.length;
  for (const s of scalars) H[k++] = s;
  H[k++] = arrays.length;
  let at = 8 * 40;
  for (const a of arrays) {
    H[k++] = at;
    H[k++] = a.length;
    new a.constructor(H.buffer, at, a.length).set(a);
    at += 8 * Math.ceil(a.byteLength / 8);
  }
  return 80;
}

test('readResults: scalars and arrays by name with the declared types; copies, or views on the block', () => {
  const m = standIn({ demo });
  const c = boundaryOf(m).call('demo');
  const r = block(m, [1.5, 7], [new Int32Array([-1, 0, 4]), new Float64Array([0.5, 2])]);
  const copied = c.readResults(r);
  assert.deepEqual(copied.scalars, { computeMs: 1.5, count: 7 });
  assert.ok(copied.arrays.labels instanceof Int32Array && copied.arrays.values instanceof Float64Array);
  assert.deepEqual([...copied.arrays.labels], [-1, 0, 4]);
  assert.deepEqual([...copied.arrays.values], [0.5, 2]);
  assert.notEqual(copied.arrays.labels.buffer, m.HEAPF64.buffer);
  const viewed = c.readResults(r, true);
  assert.equal(viewed.arrays.values.buffer, m.HEAPF64.buffer);
  assert.deepEqual([...viewed.arrays.values], [0.5, 2]);
  const traced = c.readResults({ out: r, trace: 'events' });
  assert.equal(traced.trace, 'events');
  assert.equal(copied.trace, undefined);
});

test('a declared name that is not an identifier is refused before any code is made from it', () => {
  const bad = { ...demo, scalars: ['computeMs', 'a-b'] };
  assert.throws(() => boundaryOf(standIn({ bad })).call('bad'), { message: /declares the name "a-b", not an identifier/ });
});

test('readResults: a block with other counts than the declaration is an Error, not shifted values', () => {
  const m = standIn({ demo });
  const c = boundaryOf(m).call('demo');
  assert.throws(() => c.readResults(block(m, [1], [new Int32Array(1), new Float64Array(1)])),
    { message: /^rtl-wasm: demo returned 1 scalars, its schema declares 2/ });
  assert.throws(() => c.readResults(block(m, [1, 2], [new Int32Array(1)])),
    { message: /^rtl-wasm: demo returned 1 arrays, its schema declares 2/ });
});

test('the module declares segment, vectorize and simplify; their results arrive with the declared types', async () => {
  const rtl = await init();
  const xy = new Float64Array([0, 0, 0.05, 0, 0.1, 0, 5, 5, 5.05, 5, 5.1, 5]);
  const s = rtl.segment(xy);
  assert.ok(s.labels instanceof Int32Array);
  assert.deepEqual([...s.labels], [0, 0, 0, 1, 1, 1]);
  assert.ok(s.clusters[1].indices instanceof Uint32Array && s.clusters[1].ranges instanceof Uint32Array);
  assert.deepEqual([...s.clusters[1].ranges], [3, 6]);
  const v = rtl.vectorize(xy.subarray(0, 6), { method: 'ftls' });
  assert.ok(v.segments instanceof Float64Array && v.indices instanceof Uint32Array && v.rms instanceof Float64Array);
  assert.equal(v.count, 1);
  assert.deepEqual([...v.indices], [0, 3]);
  const kept = rtl.simplify([{ x: 0, y: 0 }, { x: 1, y: 0.001 }, { x: 2, y: 0 }], 0.1, true);
  assert.equal(kept.length, 2);
});

test('fitLine, the readers and TfTree cross by the declared names: the module declares every option, no positions', async () => {
  const { default: createRtlModule } = await import('../../dist/rtl.mjs');
  const { readFile } = await import('node:fs/promises');
  const m = await createRtlModule({ wasmBinary: await readFile(new URL('../../dist/rtl.wasm', import.meta.url)) });
  const { calls } = m.boundarySchema();
  assert.deepEqual(calls.fitLine.options, [['dim', 1]]);
  assert.deepEqual(calls.readCarmenLog.options, [['maxRange', 1]]);
  assert.deepEqual(calls.readOrganizedLidar.options, [['beams', 1], ['layout', 1, ['column-major', 'row-major']]]);
  assert.deepEqual(calls.tfCreate.options, [['dim', 1]]);
  assert.deepEqual(calls.tfInsert.options, [['rotation', 4], ['translation', 3]]);
  for (const name of ['fitLine', 'readCarmenLog', 'readOrganizedLidar', 'tfCreate', 'tfInsert'])
    assert.deepEqual([calls[name].scalars, calls[name].arrays], [[], []], name);  // objects built in C++
  // The bindings take the options block, not numbers: one argument fewer than the positional ones had.
  const b = boundaryOf(m);
  // 4 numbers with dim 3: the shape check, before any number is read, names the dim the options block gave.
  assert.match(m.fitLine(0, 4, b.call('fitLine').writeOptions({ dim: 3 })).error, /not a multiple of dim 3/);
  assert.match(m.fitLine(0, 3, b.call('fitLine').writeOptions({ dim: 2 })).error, /not a multiple of dim 2/);
  const rtl = await init();
  const tree = new rtl.TfTree('w', { dim: 3 });
  tree.insert('a', 'w', { angle: Math.PI / 2, axis: [0, 0, 2], translation: [1, 2, 3] });
  const t = tree.tf('w', 'a');  // the node's transformation: parent -> child coordinates
  assert.deepEqual([...t.translation], [1, 2, 3]);
  [0, -1, 0, 1, 0, 0, 0, 0, 1].forEach((r, i) => assert.ok(Math.abs(t.rotation[i] - r) < 1e-12, `rotation[${i}]`));
  assert.deepEqual([...tree.transformPoints('w', 'a', [1, 0, 0])].map((x) => Math.round(x * 1e12) / 1e12), [1, 3, 3]);
  tree.dispose();
});
