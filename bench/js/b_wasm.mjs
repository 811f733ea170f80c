#!/usr/bin/env node
// rtl-wasm benchmarks (figures, not pass/fail; run by `./run bench`, or `node bench/js/b_wasm.mjs [--rounds=N] [--smoke]`):
//  1. wasm vs native at 100,000 and 1,000,000 points: FTLS, Douglas-Peucker and the batch (CAR) segmenter, in one
//     run, interleaved rounds (a native process call, then the wasm call), medians. Native = the same adapter code
//     (wasm/src/*_ops.h) in tests/tools/rtl_native ($RTL_NATIVE_BUILD_DIR/tools, default build/native) on objects
//     reused between its repetitions, its median of 3 calls per round; wasm = the library's own time of the call
//     (lastComputeMs: the kept objects are reused too) and the whole JS call.
//  2. time outside the library (argument checks, copy in, the C++ input check, results out) per function at
//     100,000 points, as a share of the library's time (the goal: under 10 %).
//  3. gzipped size of the .wasm and the JS.
// RTL_PACKAGE=dir: a package folder built by wasm/build.mjs with RTL_DIST_DIR, instead of dist/.
import { execFileSync } from 'node:child_process';
import { existsSync, mkdtempSync, readFileSync, rmSync, writeFileSync } from 'node:fs';
import { cpus, loadavg, tmpdir } from 'node:os';
import { join, resolve } from 'node:path';
import { fileURLToPath, pathToFileURL } from 'node:url';
import { gzipSync } from 'node:zlib';

const ROOT = fileURLToPath(new URL('../..', import.meta.url));
const PKG = resolve(ROOT, process.env.RTL_PACKAGE || 'dist');
const { default: init } = await import(pathToFileURL(join(PKG, 'index.node.mjs')).href);
const args = process.argv.slice(2);
const smoke = args.includes('--smoke');
const rounds = Number((args.find((a) => a.startsWith('--rounds=')) || '').slice(9)) || (smoke ? 1 : 7);
const SIZES = smoke ? [10_000] : [100_000, 1_000_000];
const N2 = smoke ? 10_000 : 100_000;
const TOOL = join(resolve(ROOT, process.env.RTL_NATIVE_BUILD_DIR || 'build/native'), 'tools', 'rtl_native');
const dir = mkdtempSync(join(tmpdir(), 'rtl-bench-'));
process.on('exit', () => rmSync(dir, { recursive: true, force: true }));
const load = () => `load ${loadavg().map((l) => l.toFixed(2)).join(' ')} on ${cpus().length} cores`;

const median = (a) => [...a].sort((x, y) => x - y)[Math.floor(a.length / 2)];
const fmt = (v, w = 9) => (Number.isFinite(v) ? v.toFixed(3) : '-').padStart(w);

// The paper's noisy semicircle (r 8, uniform noise 0.01) of n points, x and y interleaved.
function semicircle(n, seed = 1) {
  let s = seed >>> 0;
  const rnd = () => ((s = (Math.imul(s, 1664525) + 1013904223) >>> 0) / 4294967296);
  const xy = new Float64Array(2 * n);
  for (let i = 0; i < n; i++) {
    const a = (Math.PI * i) / (n - 1);
    xy[2 * i] = 8 * Math.cos(a) + 0.01 * (rnd() - 0.5);
    xy[2 * i + 1] = 8 * Math.sin(a) + 0.01 * (rnd() - 0.5);
  }
  return xy;
}
// A closed scan of n beams around the origin: walls at 2-12 m broken every 500 beams, 1% gaps.
function scan(n) {
  const xy = new Float64Array(2 * n);
  for (let i = 0; i < n; i++) {
    const a = (2 * Math.PI * i) / n, r = 2 + ((Math.floor(i / 500) * 7) % 11);
    const gap = i % 97 === 0;
    xy[2 * i] = gap ? NaN : r * Math.cos(a);
    xy[2 * i + 1] = gap ? NaN : r * Math.sin(a);
  }
  return xy;
}

function native(op, file, params) {
  const out = JSON.parse(execFileSync(TOOL, [op, file, '2', ...params.map(String), '--reps=3'], { encoding: 'utf8', maxBuffer: 1 << 30 }));
  return out.seconds * 1e3;
}

const rtl = await init();
console.log(`rtl-wasm ${rtl.version} benchmarks (${PKG}): ${rounds} interleaved rounds, medians, Node ${process.versions.node}${smoke ? ' (smoke)' : ''}`);

// ---- 1. wasm vs native
const haveNative = existsSync(TOOL);
console.log(`\n1. wasm vs native (library call; native ${haveNative ? TOOL : 'tool not built: column skipped'}) (${load()})`);
console.log(`${'case'.padEnd(40)} ${'native'.padStart(9)} ${'wasm lib'.padStart(9)} ${'wasm/nat'.padStart(9)} ${'whole'.padStart(9)} ${'whole/nat'.padStart(9)} ${'min ratio'.padStart(9)}  (ms)`);
const CASES = [
  ['FTLS (sigma 0.03, delta 3)', semicircle, (p) => rtl.vectorize(p, { method: 'ftls', sigma: 0.03, delta: 3 }), 'vectorize', [0, 0, 0.03, 3, 0.09, 1, 10000]],
  ['Douglas-Peucker (epsilon 0.09)', semicircle, (p) => rtl.vectorize(p, { method: 'dp', epsilon: 0.09 }), 'vectorize', [3, 0, 0.03, 3, 0.09, 1, 10000]],
  ['CAR (step 3, 0.1-0.5)', scan, (p) => rtl.segment(p, { step: 3, lowerBound: 0.1, upperBound: 0.5 }), 'segment', [3, 0.1, 0.5]],
];
for (const n of SIZES) {
  for (const [name, make, f, op, params] of CASES) {
    const xy = make(n), file = join(dir, `${op}-${n}.f64`);
    writeFileSync(file, xy);
    f(xy);  // warm-up: tier-up, memory growth, the kept objects
    const t = { nat: [], lib: [], whole: [] };
    for (let r = 0; r < rounds; r++) {
      if (haveNative) t.nat.push(native(op, file, params));
      const a = performance.now(); f(xy); t.whole.push(performance.now() - a); t.lib.push(rtl.lastComputeMs);
    }
    const nat = haveNative ? median(t.nat) : NaN, lib = median(t.lib), whole = median(t.whole);
    // min ratio: the fastest wasm call over the fastest native one, the least disturbed pair on a loaded machine
    const minRatio = Math.min(...t.lib) / (haveNative ? Math.min(...t.nat) : NaN);
    console.log(`${`${name} ${n.toLocaleString('en')}`.padEnd(40)} ${fmt(nat)} ${fmt(lib)} ${fmt(lib / nat)} ${fmt(whole)} ${fmt(whole / nat)} ${fmt(minRatio)}`);
  }
}

// ---- 2. time outside the library per function
console.log(`\n2. time outside the library call (checks, copy in, input check, results out), ${N2.toLocaleString('en')} points (${load()})`);
console.log(`${'function'.padEnd(40)} ${'whole'.padStart(9)} ${'library'.padStart(9)} ${'outside'.padStart(9)} ${'% of lib'.padStart(9)} ${'min out'.padStart(9)} ${'min lib'.padStart(9)}  (ms)`);
const line2 = semicircle(N2), ring2 = scan(N2);
const OUT = [
  ['vectorize ftls', () => rtl.vectorize(line2, { method: 'ftls', sigma: 0.03, delta: 3 })],
  ['vectorize aftls', () => rtl.vectorize(line2, { method: 'aftls', sigma: 0.03, delta: 3 })],
  ['vectorize itls', () => rtl.vectorize(line2, { method: 'itls', epsilon: 0.09 })],
  ['vectorize dp', () => rtl.vectorize(line2, { method: 'dp', epsilon: 0.09 })],
  ['vectorize dp, distance segment', () => rtl.vectorize(line2, { method: 'dp', epsilon: 0.09, distance: 'segment' })],
  ['vectorize rw', () => rtl.vectorize(line2, { method: 'rw', epsilon: 0.09 })],
  ['segment (CAR, step 3)', () => rtl.segment(ring2, { step: 3, lowerBound: 0.1, upperBound: 0.5 })],
  ['simplify (Float64Array)', () => rtl.simplify(line2, 0.09, true)],
];
const T = OUT.map(() => ({ whole: [], lib: [] }));
for (const [, f] of OUT) f();
for (let r = 0; r < 3 * rounds; r++) {  // interleaved: one call of each function per round
  OUT.forEach(([, f], k) => { const a = performance.now(); f(); T[k].whole.push(performance.now() - a); T[k].lib.push(rtl.lastComputeMs); });
}
OUT.forEach(([name], k) => {
  // the per-round difference, then its median: both parts of one call saw the same machine state
  const outside = median(T[k].whole.map((w, i) => w - T[k].lib[i])), lib = median(T[k].lib);
  const outs = T[k].whole.map((w, i) => w - T[k].lib[i]);
  console.log(`${name.padEnd(40)} ${fmt(median(T[k].whole))} ${fmt(lib)} ${fmt(outside)} ${(100 * outside / lib).toFixed(1).padStart(9)} ${fmt(Math.min(...outs))} ${fmt(Math.min(...T[k].lib))}`);
});

// ---- 3. size
console.log('\n3. package size (gzip -9)');
const gz = (f) => gzipSync(readFileSync(join(PKG, f)), { level: 9 }).length;
const wasmGz = gz('rtl.wasm'), jsGz = gz('rtl.mjs') + gz('api.mjs') + gz('index.mjs');
console.log(`   rtl.wasm ${readFileSync(join(PKG, 'rtl.wasm')).length} B -> ${wasmGz} B gz; browser JS (rtl.mjs + api.mjs + index.mjs) ${jsGz} B gz; together ${((wasmGz + jsGz) / 1024).toFixed(1)} KiB`);
console.log(`\n${load()}`);
