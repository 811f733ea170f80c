// The extras module (rtl-extras.wasm, loaded on demand; docs/package-modules.md): the calls that moved into it give
// byte-identical results to the package before the move (digests recorded from it: tests/js/extras/); the Node
// entries load it in init(); the browser entry loads it on rtl.load('extras') (or init({ load })), and before that
// each moved function throws the documented Error; load() checks its argument, is idempotent and can be retried
// after a failed fetch; the diagnostics cover both modules. The browser entry runs here in Node with the core's
// bytes given and a fetch() that serves dist/ (the glue fetches rtl-extras.wasm through locateFile's URL). The CLI
// (bin/rtl.js) writes the same JSON, SVG and TikZ bytes as before the split, on the tests/data logs.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { spawnSync } from 'node:child_process';
import { createHash } from 'node:crypto';
import { readFileSync } from 'node:fs';
import { createRequire } from 'node:module';
import { fileURLToPath } from 'node:url';
import init from 'rtl-wasm';
import { goldenDigests } from './extras/golden-cases.mjs';
import { throwsWith } from './helpers.mjs';

const DIST = new URL('../../dist/', import.meta.url);
const golden = JSON.parse(readFileSync(new URL('extras/extras-golden.json', import.meta.url), 'utf8'));
const rtl = await init();
const { default: initBrowser } = await import(new URL('index.js', DIST).href);
const coreBytes = readFileSync(new URL('rtl.wasm', DIST));

// The moved functions and a call of each that works once the module is loaded.
const MOVED = {
  toSvg: (r) => r.toSvg({ points: [0, 0, 1, 1, NaN, NaN, 2, 0], labels: [0, 0, -1, 1], segments: [0, 0, 1, 1], title: 'a & b' }),
  toTikz: (r) => r.toTikz({ points: [0, 0, 1, 1], segments: [0, 0, 1, 1] }, { width: 5, height: 4 }),
  toLatexTable: (r) => r.toLatexTable([['a_1', 2.5], null], { heading: ['x', 'y'] }),
  readPcd: (r) => JSON.stringify(Array.from(r.readPcd(readFileSync(new URL('../data/pcd/unorganized.ascii.pcd', import.meta.url))).points)),
  assign: (r) => JSON.stringify(r.assign([[4, 1, 3], [2, 0, 5], [3, 2, 2]])),
  KalmanFilter: (r) => { const k = new r.KalmanFilter({ stateDim: 2, measurementDim: 1 }); k.setMeasurementMatrix([1, 0]); k.correct([2]); const s = Array.from(k.state()); k.dispose(); return JSON.stringify(s); },
};

// A fetch() for the browser entry in Node: serves dist/ files under https://rtl.test/ and counts the requests.
function serveDist({ fail = false } = {}) {
  const requests = [];
  const saved = globalThis.fetch;
  globalThis.fetch = async (url) => {
    const path = new URL(String(url)).pathname.slice(1);
    requests.push(path);
    if (fail) return new Response('not found', { status: 404, statusText: 'Not Found' });
    return new Response(readFileSync(new URL(path, DIST)), { headers: { 'Content-Type': 'application/wasm' } });
  };
  return { requests, restore: () => { globalThis.fetch = saved; } };
}
const locateFile = (path) => `https://rtl.test/${path}`;

test('the moved calls give the bytes the package gave before the move (37 digests: SVG, TikZ 2D/3D, tables, PCD, assign, Kalman)', () => {
  const now = goldenDigests(rtl);
  assert.equal(Object.keys(golden).length, 37);
  assert.deepEqual(Object.keys(now), Object.keys(golden));
  for (const k of Object.keys(golden)) assert.equal(now[k], golden[k], k);
});

test('Node entries: init() loads the extras module; load() resolves at once to the same object', async () => {
  const fromCjs = await createRequire(import.meta.url)('rtl-wasm')();
  for (const r of [rtl, fromCjs]) {
    for (const [name, call] of Object.entries(MOVED)) assert.equal(call(r), call(rtl), `${name} works at once`);
    assert.equal(await r.load('extras'), r);
  }
  assert.equal(await (await init({ load: ['extras'] })).toLatexTable([['x']]), rtl.toLatexTable([['x']]));
});

test('browser entry: before load, each moved function throws an Error naming itself and the call that loads it', async () => {
  const r = await initBrowser({ wasmBinary: coreBytes, locateFile });
  assert.equal(r.fitLine([0, 2, 1, 2]).offset, -2, 'the core works without the extras');
  for (const name of Object.keys(MOVED)) {
    assert.throws(() => MOVED[name](r), (e) => e.constructor === Error &&
      e.message === `${name}: this function is in the package's extras module, which is not loaded: call await rtl.load('extras') first (or init({ load: ['extras'] }))`, name);
  }
  throwsWith(() => r.heapInUse('extras'), Error, /^heapInUse: the extras module is not loaded \(rtl\.load\('extras'\)\)$/);
  assert.equal(r.heapInUse(), r.heapInUse('core'), 'without the extras, the sum is the core\'s');
});

test('browser entry: load() fetches rtl-extras.wasm once; then every moved call equals the Node entry\'s bytes', async () => {
  const r = await initBrowser({ wasmBinary: coreBytes, locateFile });
  const net = serveDist();
  try {
    const [a, b] = await Promise.all([r.load('extras'), r.load('extras')]);
    assert.equal(a, r);
    assert.equal(b, r);
    assert.equal(await r.load('extras'), r);
    assert.deepEqual(net.requests, ['rtl-extras.wasm'], 'one fetch for three load() calls');
  } finally {
    net.restore();
  }
  for (const [name, call] of Object.entries(MOVED)) assert.equal(call(r), call(rtl), name);
  // init({ load }) does the same before it resolves
  const net2 = serveDist();
  try {
    const r2 = await initBrowser({ wasmBinary: coreBytes, locateFile, load: ['extras'] });
    assert.deepEqual(net2.requests, ['rtl-extras.wasm']);
    assert.equal(MOVED.toSvg(r2), MOVED.toSvg(rtl));
  } finally {
    net2.restore();
  }
});

test('browser entry: a failed fetch rejects load() with an Error starting "load:", printing nothing; a new load() retries', async (t) => {
  const r = await initBrowser({ wasmBinary: coreBytes, locateFile });
  const printed = [];
  for (const k of ['log', 'error', 'warn']) t.mock.method(console, k, (...a) => printed.push(a.join(' ')));
  const net = serveDist({ fail: true });
  try {
    await assert.rejects(r.load('extras'), (e) => e.constructor === Error && /^load: the WebAssembly module could not be started: /.test(e.message));
  } finally {
    net.restore();
  }
  assert.deepEqual(printed, []);
  throwsWith(() => MOVED.assign(r), Error, /^assign: this function is in the package's extras module, which is not loaded/);
  const again = serveDist();
  try {
    assert.equal(await r.load('extras'), r);
  } finally {
    again.restore();
  }
  assert.equal(MOVED.assign(r), MOVED.assign(rtl));
  // init({ load }) with a failed fetch: init rejects, naming itself
  const down = serveDist({ fail: true });
  try {
    await assert.rejects(initBrowser({ wasmBinary: coreBytes, locateFile, load: ['extras'] }), /^Error: init: the WebAssembly module could not be started: /);
  } finally {
    down.restore();
  }
});

test('load and init({ load }): TypeError / RangeError for a bad module name', async () => {
  await assert.rejects(rtl.load(), (e) => e instanceof TypeError && /^load: name must be a module name \(a string\), got undefined/.test(e.message));
  await assert.rejects(rtl.load('core'), (e) => e instanceof RangeError && e.message === 'load: name "core" is not a module of the package (known: extras)');
  await assert.rejects(init({ load: 'extras' }), (e) => e instanceof TypeError && /^init: option load must be an array of module names/.test(e.message));
  await assert.rejects(init({ load: ['extras', 'draw'] }), (e) => e instanceof RangeError && e.message === 'init: option load[1] "draw" is not a module of the package (known: extras)');
  throwsWith(() => rtl.heapInUse('all'), RangeError, /^heapInUse: module "all" is not a module of the package \(known: core, extras\)$/);
  throwsWith(() => rtl.stackPointer(2), TypeError, /^stackPointer: module must be a module name/);
});

test('diagnostics of both modules: the sums, and each module\'s heap unchanged by the moved calls, failing or not', () => {
  assert.equal(rtl.heapInUse(), rtl.heapInUse('core') + rtl.heapInUse('extras'));
  assert.equal(rtl.memoryBytes(), rtl.memoryBytes('core') + rtl.memoryBytes('extras'));
  assert.equal(rtl.stackPointer(), rtl.stackPointer('core') + rtl.stackPointer('extras'));
  for (const [name, call] of Object.entries(MOVED)) call(rtl);  // warm up
  const heap = rtl.heapInUse('extras'), core = rtl.heapInUse('core'), sp = rtl.stackPointer('extras');
  for (let i = 0; i < 50; i++) {
    for (const call of Object.values(MOVED)) call(rtl);
    assert.throws(() => rtl.readPcd(new Uint8Array([80, 67, 68])), RangeError);
    assert.throws(() => rtl.assign([[1, 2], [3]]), RangeError);
  }
  assert.equal(rtl.heapInUse('extras'), heap, 'extras heap');
  assert.equal(rtl.heapInUse('core'), core, 'core heap');
  assert.equal(rtl.stackPointer('extras'), sp, 'extras stack pointer');
});

test('esbuild bundles the browser entry: the extras glue becomes a chunk of its own, loaded by the dynamic import', async () => {
  const esbuild = await import('esbuild');
  const out = await esbuild.build({ entryPoints: [new URL('index.mjs', DIST).pathname], bundle: true, splitting: true,
    format: 'esm', platform: 'browser', write: false, outdir: '/out', logLevel: 'silent' });
  assert.deepEqual(out.errors, []);
  const files = out.outputFiles.map((f) => [f.path, f.text]);
  const entry = files.find(([p]) => p.endsWith('/index.js'));
  const chunks = files.filter(([p]) => p !== entry[0]);
  assert.ok(entry[1].includes("new URL(\"rtl.wasm\", import.meta.url)"), 'the core glue, in the entry bundle');
  assert.ok(!entry[1].includes('rtl-extras.wasm'), 'the extras glue is not in the entry bundle');
  const extrasChunk = chunks.filter(([, t]) => t.includes("new URL(\"rtl-extras.wasm\", import.meta.url)"));
  assert.equal(extrasChunk.length, 1, 'one chunk holds the extras glue, which finds rtl-extras.wasm beside itself');
  assert.match(entry[1], /import\("\.\/[\w-]+\.js"\)/, 'the entry imports it on demand');
});

test('each module reports its own boundary schema: the moved calls\' option structs are the extras module\'s', async () => {
  const { default: createCore } = await import(new URL('rtl.mjs', DIST).href);
  const { default: createExtras } = await import(new URL('rtl-extras.mjs', DIST).href);
  const core = await createCore({ wasmBinary: coreBytes });
  const extras = await createExtras({ wasmBinary: readFileSync(new URL('rtl-extras.wasm', DIST)) });
  const calls = extras.boundarySchema().calls;
  assert.deepEqual(Object.keys(calls).sort(), ['assign', 'drawScan2D', 'drawTikz3D', 'kalmanCreate']);
  assert.deepEqual(calls.drawScan2D.options, [['width', 1], ['height', 1], ['markRadius', 1], ['format', 1, ['tikz', 'tikzpicture', 'svg']]]);
  assert.deepEqual(calls.drawTikz3D.options, [['fov', 1], ['direction', 3], ['width', 1], ['height', 1], ['markRadius', 1], ['standalone', 1]]);
  assert.deepEqual(calls.assign.options, [['rows', 1], ['cols', 1], ['maximize', 1]]);
  assert.deepEqual(calls.kalmanCreate.options.map(([n]) => n), ['stateDim', 'measurementDim', 'controlDim', 'processNoise', 'observationNoise']);
  for (const c of Object.values(calls)) assert.deepEqual([c.scalars, c.arrays], [[], []], 'results built in C++ (NamedObjectResult)');
  const coreCalls = Object.keys(core.boundarySchema().calls);
  assert.ok(coreCalls.includes('segment') && coreCalls.includes('simplify'));
  for (const k of Object.keys(calls)) assert.ok(!coreCalls.includes(k), `${k} is not in the core`);
  for (const f of ['drawScan2D', 'readPcd', 'assign', 'kalmanCreate']) assert.equal(typeof core[f], 'undefined', `the core has no ${f}`);
  assert.equal(typeof extras.segment, 'undefined', 'the extras module has no segment');
});

test('the CLI writes the same bytes as before the split: JSON, SVG, TikZ 2D/3D on the tests/data logs, a bag, a budget', { timeout: 180_000 }, () => {
  const sha = (b) => createHash('sha256').update(b).digest('hex');
  const root = fileURLToPath(new URL('../..', import.meta.url));
  const cases = JSON.parse(readFileSync(new URL('extras/cli-golden.json', import.meta.url), 'utf8'));
  assert.equal(cases.length, 27);
  for (const c of cases) {
    const r = spawnSync(process.execPath, ['bin/rtl.js', ...c.args], { cwd: root, maxBuffer: 1 << 26 });
    const what = `rtl ${c.args.join(' ')}`;
    assert.equal(r.status, c.status, `${what}: exit status (${r.stderr})`);
    assert.equal(r.stdout.length, c.bytes, `${what}: output length`);
    assert.equal(sha(r.stdout), c.stdout, `${what}: output bytes`);
    assert.equal(sha(r.stderr), c.stderr, `${what}: stderr`);
  }
});
