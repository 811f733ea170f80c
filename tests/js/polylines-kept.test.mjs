// extractPolylines keeps its extractor and result vectors between calls (wasm/src/polylines.cpp, kept.h): a call after
// other scans, budgets and settings, a failing call, releaseBuffers() or a scan above the kept limit gives exactly the
// result of the same call on a fresh module; results are copies that later calls leave alone.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import init from 'rtl-wasm';
import { wallRing as ring } from './helpers.mjs';

const used = await init();
const scans = used.readCarmenLog(readFileSync(new URL('../data/intel.log', import.meta.url))).map((s) => s.points);

// A scan of n beams around the sensor: walls at 2-12 m changing every 300 beams, a gap every 89 beams.

const cases = [
  [scans[3], { maxVertices: 10 }],
  [scans[3], { maxVertices: 50 }],
  [scans[17], { maxVertices: 30, maxGap: 0.4 }],
  [scans[17], { maxVertices: 30, unexplainedCost: 0.2 }],
  [scans[29], {}],
  [ring(1000), { maxVertices: 40 }],
];

test('extractPolylines: a reused extractor gives the fresh module\'s result, whatever ran before', async () => {
  // Grow and dirty the kept extractor: every scan at the largest budget, other settings, a larger scan.
  for (const p of scans) used.extractPolylines(p, { maxVertices: 60, maxGap: 2, unexplainedCost: 1 });
  used.extractPolylines(ring(2000), { maxVertices: 80 });
  const fresh = await init();
  for (const [k, [p, o]] of cases.entries()) {
    const expected = fresh.extractPolylines(p, o);
    assert.ok(expected.vertexCount >= 2, `case ${k}: the case extracts something`);
    assert.deepEqual(used.extractPolylines(p, o), expected, `case ${k}: reused after other calls`);
  }
  // in reverse order: each case right after another one
  for (const [k, [p, o]] of [...cases.entries()].reverse()) assert.deepEqual(used.extractPolylines(p, o), fresh.extractPolylines(p, o), `case ${k}: reversed`);
});

test('extractPolylines: a failing call, releaseBuffers() and a scan above the kept limit leave the next results unchanged', async () => {
  const fresh = await init();
  const expected = cases.map(([p, o]) => fresh.extractPolylines(p, o));
  const again = (what) => cases.forEach(([p, o], k) => assert.deepEqual(used.extractPolylines(p, o), expected[k], `case ${k}: ${what}`));
  assert.throws(() => used.extractPolylines([1, 2, Infinity, 3]), RangeError);
  again('after a failing call');
  used.releaseBuffers();
  again('after releaseBuffers');
  // 2049 beams: above the 2048 the kept extractor serves, so the call has its own; the same result as a fresh module
  const big = ring(2049);
  assert.deepEqual(used.extractPolylines(big, { maxVertices: 60 }), fresh.extractPolylines(big, { maxVertices: 60 }), 'above the kept limit');
  again('after a scan above the kept limit');
});

test('extractPolylines: results are copies: later calls (which reuse the result block) do not change an earlier one', () => {
  const results = cases.map(([p, o]) => used.extractPolylines(p, o));
  const snapshots = results.map((r) => structuredClone(r));
  for (const [p, o] of [...cases].reverse()) used.extractPolylines(p, { ...o, maxVertices: 12 });
  results.forEach((r, k) => assert.deepEqual(r, snapshots[k], `case ${k}: changed by later calls`));
  // the polylines are views on the result's own vertices
  for (const r of results) assert.ok(r.polylines.every((p) => p.buffer === r.vertices.buffer));
  // every other array its own ArrayBuffer of its own size, so that a worker can transfer them all (a transfer list
  // naming one buffer twice throws) and `new Float64Array(a.buffer)` reads exactly the array
  const arraysOf = (r) => [r.vertices, r.offsets, r.expectedRanges, ...Object.values(r.segments)];
  for (const [k, r] of results.entries()) {
    const arrays = arraysOf(r);
    assert.equal(arrays.length, 9);
    assert.equal(new Set(arrays.map((a) => a.buffer)).size, 9, `case ${k}: nine buffers`);
    for (const a of arrays) assert.equal(a.buffer.byteLength, a.byteLength, `case ${k}: a buffer of the array's size`);
    const moved = structuredClone(r, { transfer: arrays.map((a) => a.buffer) });
    assert.equal(moved.vertices.length, snapshots[k].vertices.length, `case ${k}: transferred`);
    assert.equal(r.vertices.byteLength, 0, `case ${k}: detached after the transfer`);
  }
});

test('extractPolylines: calls above the kept limit (their own extractor) leave the heap as it was', () => {
  const big = ring(3000);
  const round = () => { for (const [p, o] of cases) used.extractPolylines(p, o); used.extractPolylines(big, { maxVertices: 60 }); };
  round();  // warm-up: the kept extractor, input buffer and result block grow once
  const heap = used.heapInUse(), mem = used.memoryBytes();
  for (let k = 0; k < 3; k++) round();
  assert.equal(used.heapInUse(), heap, 'malloc heap in use');
  assert.equal(used.memoryBytes(), mem, 'wasm memory');
});
