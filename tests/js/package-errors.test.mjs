// Packaging and error contract: every error message starts with the name of the function called;
// init() with a bad wasmBinary throws the package's own TypeError and prints nothing, from each entry; maxSize beyond
// what 2 GB of wasm memory can hold is a RangeError before any allocation, and a large valid one does not grow the
// memory; fitLine and vectorize reject coordinates whose squares would overflow and are exact near that limit.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { spawnSync } from 'node:child_process';
import { fileURLToPath } from 'node:url';
import init from 'rtl-wasm';
import { throwsWith } from './helpers.mjs';

const ROOT = fileURLToPath(new URL('../..', import.meta.url));
const rtl = await init();

test('C++ errors name the function called (readers, TfTree, no library labels)', () => {
  throwsWith(() => rtl.readCarmenLog('FLASER 2 1 1\n'), RangeError, /^readCarmenLog: line 1: /);
  throwsWith(() => rtl.readCarmenLog('# x\nFLASER 3 1 1 1 0 0 0 0 0 0 1 host 1\nFLASER 2 x y\n'), RangeError, /^readCarmenLog: line 3: /);
  throwsWith(() => rtl.readOrganizedLidar(new Uint8Array(20), { beams: 1 }), RangeError, /^readOrganizedLidar: truncated record/);
  const tree = new rtl.TfTree('map');
  throwsWith(() => tree.tf('map', 'nowhere'), RangeError, /^TfTree\.tf: unknown frame 'nowhere'$/);
  throwsWith(() => tree.transformPoints('nowhere', 'map', [0, 0]), RangeError, /^TfTree\.transformPoints: unknown frame 'nowhere'$/);
  tree.dispose();
  throwsWith(() => rtl.fitLine([1, 1, 1, 1]), RangeError, /^fitLine: all 2 points coincide/);
  throwsWith(() => rtl.vectorize([0, 0, NaN, 1], { method: 'ftls' }), RangeError, /^vectorize: point 1 has a non-finite/);
});

test('out of wasm memory names the function: an input larger than the 2 GB memory fails before any copy', () => {
  const heap = rtl.heapInUse(), mem = rtl.memoryBytes();
  const huge = new Float64Array(2 ** 28);  // 2 GB of zero pages, never touched
  throwsWith(() => rtl.fitLine(huge), RangeError, /^fitLine: out of wasm memory allocating 2147483648 bytes$/);
  throwsWith(() => rtl.segment(huge), RangeError, /^segment: out of wasm memory/);
  assert.equal(rtl.heapInUse(), heap);
  assert.equal(rtl.memoryBytes(), mem, 'nothing grew');
});

// ------------------------------------------------------------------------------------------------ init
const foreignModule = new Uint8Array([0, 97, 115, 109, 1, 0, 0, 0]);  // a valid, empty WebAssembly module
const ENTRIES = {
  esm: { ext: 'mjs', load: `const { default: init } = await import('rtl-wasm');` },
  cjs: { ext: 'cjs', load: `const init = require('rtl-wasm');` },
  browser: { ext: 'mjs', load: `const { default: init } = await import(${JSON.stringify(new URL('../../dist/index.js', import.meta.url).href)});` },
};
// Runs `body` (which may use init, bytes and report(value)) in a fresh Node process from the repository root, so
// that 'rtl-wasm' resolves to this package; returns the reported value and everything else the process printed.
function inChild(entry, body) {
  const { ext, load } = ENTRIES[entry];
  const wrapped = ext === 'cjs' ? `(async () => { ${load} ${body} })();` : `${load} ${body}`;
  const src = `const bytes = require_('fs').readFileSync(${JSON.stringify(fileURLToPath(new URL('../../dist/rtl.wasm', import.meta.url)))});
    const report = (v) => require_('fs').writeSync(3, JSON.stringify(v));
    ${wrapped}`;
  const prelude = ext === 'cjs' ? 'const require_ = require;' : `import { createRequire } from 'node:module'; const require_ = createRequire(${JSON.stringify(ROOT + '/')});`;
  const { status, stdout, stderr, output } = spawn(prelude + src, ext);
  return { status, stdout, stderr, value: output ? JSON.parse(output) : undefined };
}
function spawn(src, ext) {
  const r = spawnSync(process.execPath, [`--input-type=${ext === 'cjs' ? 'commonjs' : 'module'}`, '-e', src],
    { cwd: ROOT, encoding: 'utf8', stdio: ['ignore', 'pipe', 'pipe', 'pipe'] });
  return { status: r.status, stdout: r.stdout, stderr: r.stderr, output: r.output[3] };
}

for (const entry of Object.keys(ENTRIES)) {
  test(`init (${entry} entry): a bad wasmBinary is the package's TypeError, printing nothing`, { timeout: 60_000 }, () => {
    const r = inChild(entry, `
      const out = [];
      for (const b of [new Uint8Array([1, 2, 3]), new Uint8Array(${JSON.stringify(Array.from(foreignModule))}), new ArrayBuffer(16)]) {
        try { await init({ wasmBinary: b }); out.push('resolved'); } catch (e) { out.push([e.constructor.name, e.message]); }
      }
      const good = await init({ wasmBinary: bytes });
      out.push(good.fitLine([0, 2, 1, 2]).offset);
      report(out);`);
    assert.equal(r.status, 0, r.stderr);
    assert.equal(r.stdout, '', 'nothing on stdout');
    assert.equal(r.stderr, '', 'nothing on stderr');
    const [garbage, foreign, empty, offset] = r.value;
    assert.deepEqual(garbage, ['TypeError', 'init: wasmBinary is not a valid WebAssembly module (3 bytes)']);
    assert.equal(foreign[0], 'TypeError');
    assert.match(foreign[1], /^init: the WebAssembly module could not be started: /);
    assert.deepEqual(empty, ['TypeError', 'init: wasmBinary is not a valid WebAssembly module (16 bytes)']);
    assert.equal(offset, -2, 'a good binary still starts after the failures');
  });
}

test('init: the three entries give the same results on the same calls', { timeout: 60_000 }, () => {
  const body = `const r = await init(${'{ wasmBinary: bytes }'}); const f = r.fitLine([0, 0, 1, 1.01, 2, 1.98]);
    const v = r.vectorize([0, 0, 1, 0, 2, 0, 3, 0.5, 4, 1], { method: 'ftls', sigma: 0.05, delta: 0.5 });
    let err; try { r.segment('x'); } catch (e) { err = [e.constructor.name, e.message]; }
    report({ f: [...f.normal, f.offset, f.rms], v: [...v.segments, ...v.indices], err, version: r.version, keys: Object.keys(r) });`;
  const results = Object.keys(ENTRIES).map((e) => inChild(e, body));
  for (const r of results) assert.equal(r.stderr, '');
  assert.deepEqual(results[1].value, results[0].value, 'CommonJS = ESM');
  assert.deepEqual(results[2].value, results[0].value, 'browser entry = ESM');
});

// ------------------------------------------------------------------------------------------------ maxSize
test('vectorize: maxSize beyond 2 GB of points is a RangeError before any allocation; 1e8 does not grow memory', () => {
  const xy = new Float64Array([0, 0, 1, 0, 2, 0, 2, 1, 2, 2]);
  const mem = rtl.memoryBytes(), heap = rtl.heapInUse();
  throwsWith(() => rtl.vectorize(xy, { method: 'ftls', maxSize: 2 ** 27 + 1 }), RangeError, /^vectorize: option maxSize must be <= 134217728, got 134217729$/);
  throwsWith(() => rtl.vectorize([0, 0, 0, 1, 1, 1], { dim: 3, method: 'dp', maxSize: 89478486 }), RangeError, /^vectorize: option maxSize must be <= 89478485, got 89478486$/);
  assert.equal(rtl.memoryBytes(), mem);
  const plain = rtl.vectorize(xy, { method: 'ftls', sigma: 0.01, delta: 0.5 });
  for (const method of ['ftls', 'aftls', 'dp', 'rw']) {
    const big = rtl.vectorize(xy, { method, sigma: 0.01, delta: 0.5, maxSize: 1e8 });
    if (method === 'ftls') assert.deepEqual(big, plain, 'same result with the hint');
    assert.ok(big.ok && big.count === 2, method);
    assert.ok(rtl.vectorize(xy, { method, sigma: 0.01, delta: 0.5, maxSize: 2 ** 27 }).ok, `${method}: the largest accepted hint`);
  }
  assert.equal(rtl.memoryBytes(), mem, 'memory did not grow for a reservation no call can use');
  assert.equal(rtl.heapInUse(), heap);
});

// ------------------------------------------------------------------------------------------------ magnitudes
test('fitLine and vectorize reject coordinates beyond +-1e18 (squares would overflow), naming the limit', () => {
  throwsWith(() => rtl.fitLine([1e200, 0, 2e200, 1e200]), RangeError, /^fitLine: point 0 has the coordinate 1e\+200 at index 0; coordinates must be within \+-1e18/);
  throwsWith(() => rtl.fitLine([0, 0, 1, -1.0000000001e18]), RangeError, /^fitLine: point 1 .* at index 3; coordinates must be within \+-1e18/);
  for (const method of ['ftls', 'aftls', 'itls', 'dp', 'rw']) {
    throwsWith(() => rtl.vectorize([0, 0, 1e200, 1e200, 2e200, 0], { method }), RangeError, /^vectorize: point 1 has the coordinate 1e\+200 .*within \+-1e18/);
    throwsWith(() => rtl.vectorize([0, 0, 0, 1, 1, 1, 2, 2, -2e18], { dim: 3, method }), RangeError, /^vectorize: point 2 .*within \+-1e18/);
  }
  assert.equal(rtl.fitLine([0, 0, 1e18, -1e18]).count, 2, 'the limit itself is accepted');
});

// Near the limit the results are those of the same shape at unit scale, scaled: 2^59 = 5.8e17 is a power of two,
// so every coordinate, sum and square scales exactly, and a fit that does not overflow gives the same digits.
const S = 2 ** 59;
const shape2 = [];
for (let i = 0; i <= 40; i++) shape2.push(i * 0.025, 0.002 * Math.sin(i));          // along x
for (let i = 1; i <= 40; i++) shape2.push(1 + 0.002 * Math.cos(i), i * 0.025);      // up
for (let i = 1; i <= 30; i++) shape2.push(1 - i * 0.02, 1 + i * 0.015);             // back, diagonal
const shape3 = [];
for (let k = 0; k < shape2.length / 2; k++) shape3.push(shape2[2 * k], shape2[2 * k + 1], 0.5 * shape2[2 * k] - 0.2);

function scaledNear(big, small, tol, what) {
  assert.equal(big.length, small.length, `${what}: length`);
  for (let i = 0; i < small.length; i++) {
    const d = Math.abs(big[i] / S - small[i]);
    assert.ok(d <= tol * Math.max(1, Math.abs(small[i])), `${what}[${i}]: ${big[i] / S} vs ${small[i]}`);
  }
}

test('fitLine near the limit (|x| ~ 5.8e17) equals the unit-scale fit, scaled', () => {
  for (const dim of [2, 3]) {
    const pts = dim === 2 ? shape2 : shape3;
    const small = rtl.fitLine(pts, { dim });
    const big = rtl.fitLine(pts.map((v) => v * S), { dim });
    if (dim === 2) {
      assert.deepEqual(Array.from(big.normal), Array.from(small.normal), 'normal');
      assert.ok(Math.abs(big.offset / S - small.offset) <= 1e-15, 'offset');
    }
    assert.deepEqual(Array.from(big.direction), Array.from(small.direction), `dim ${dim} direction`);
    scaledNear(big.centroid, small.centroid, 1e-15, `dim ${dim} centroid`);
    assert.ok(Math.abs(big.rms / S - small.rms) <= 1e-15, `dim ${dim} rms ${big.rms / S} vs ${small.rms}`);
    assert.ok(Number.isFinite(big.rms) && big.rms > 0);
  }
});

test('vectorize near the limit equals the unit-scale result, scaled, for every method (2D, 3D, planes)', () => {
  const runs = [];
  for (const method of ['ftls', 'aftls', 'itls', 'dp', 'rw']) runs.push([2, method, 'line'], [3, method, 'line']);
  runs.push([3, 'aftls', 'plane']);
  for (const [dim, method, primitive] of runs) {
    const pts = dim === 2 ? shape2 : shape3;
    const o = { dim, method, primitive, sigma: 0.01, delta: 0.2, epsilon: 0.01 };
    const small = rtl.vectorize(pts, o);
    const big = rtl.vectorize(pts.map((v) => v * S), { ...o, sigma: o.sigma * S, delta: o.delta * S, epsilon: o.epsilon * S });
    const what = `${dim}D ${method} ${primitive}`;
    assert.equal(big.ok, small.ok, `${what}: ok`);
    assert.ok(small.ok && small.count >= (primitive === 'plane' ? 1 : 3), `${what}: the shape needs several segments`);
    assert.deepEqual(Array.from(big.indices), Array.from(small.indices), `${what}: ranges`);
    scaledNear(big.segments, small.segments, 1e-12, `${what}: segments`);
    scaledNear(big.rms, small.rms, 1e-12, `${what}: rms`);
    for (const v of big.params) assert.ok(Number.isFinite(v), `${what}: finite parameters`);
    for (let k = 0; k < big.polygons.length; k++) scaledNear(big.polygons[k], small.polygons[k], 1e-12, `${what}: polygon ${k}`);
  }
});
