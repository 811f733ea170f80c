#!/usr/bin/env node
// rtl-wasm benchmarks (figures, not pass/fail; run by `./run bench`, or `node bench/js/b_wasm.mjs [--rounds=N] [--smoke]`):
//  1. wasm vs native at 100,000 and 1,000,000 points: FTLS, Douglas-Peucker and the batch (CAR) segmenter, in one
//     run, interleaved rounds (a native process call, then the wasm call), medians and minima. Native = the same
//     adapter code (wasm/src/*_ops.h) in tests/tools/rtl_native ($RTL_NATIVE_BUILD_DIR/tools, default build/native)
//     with the JS defaults (FTLS split at corners), the median of 5 calls per round on objects reused between them
//     (the first, cold call is the slowest and never the median); wasm = the library's own time of the call
//     (lastComputeMs: the kept objects are reused too), also the median of 5 calls in a row per round. (Until
//     issue 17's stop 26 the wasm side made one call per round, right after the native process had run: on cold
//     caches, against the native side's warm median, e.g. DP at 100k 1.63x native that way, 1.2x with both warm.) Two ratios per case (issue 17 item 4's goals):
//     wasm library / native (<= 1.25) and time outside the library / library (< 10 % at 100k), the outside time
//     being the whole JS call minus its library time, per round. The kept counts (segments, clusters) of both
//     sides are checked equal.
//  2. time outside the library (argument checks, copy in, the C++ input check, results out) per function at
//     100,000 points, as a share of the library's time (the goal: under 10 %); ", pointBuffer" rows: the input is
//     an rtl.pointBuffer() view, read in place (no copy in).
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
const rounds = Number((args.find((a) => a.startsWith('--rounds=')) || '').slice(9)) || (smoke ? 1 : 15);
const SIZES = smoke ? [10_000] : [100_000, 1_000_000];
const N2 = smoke ? 10_000 : 100_000;
const REPS = 5;  // section 1: calls per round on each side, their median is the round's figure
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
  const out = JSON.parse(execFileSync(TOOL, [op, file, '2', ...params.map(String), `--reps=${REPS}`], { encoding: 'utf8', maxBuffer: 1 << 30 }));
  return { ms: out.seconds * 1e3, count: op === 'segment' ? out.offsets.length - 1 : out.count };
}

const rtl = await init();
console.log(`rtl-wasm ${rtl.version} benchmarks (${PKG}): ${rounds} interleaved rounds, medians, Node ${process.versions.node}${smoke ? ' (smoke)' : ''}`);

// ---- 1. wasm vs native
const haveNative = existsSync(TOOL);
console.log(`\n1. wasm vs native (library call; native ${haveNative ? TOOL : 'tool not built: column skipped'}) (${load()})`);
console.log(`${'case'.padEnd(36)} ${'native'.padStart(8)} ${'wasm lib'.padStart(8)} ${'lib/nat'.padStart(8)} ${'min l/n'.padStart(8)} ${'outside'.padStart(8)} ${'out/lib'.padStart(8)} ${'min o/l'.padStart(8)} ${'whole'.padStart(8)}  (ms; ratios: medians, then minima)`);
const CASES = [
  ['FTLS (sigma 0.03, delta 3)', semicircle, (p) => rtl.vectorize(p, { method: 'ftls', sigma: 0.03, delta: 3 }), 'vectorize', [0, 0, 0.03, 3, 0.09, 1, 10000, '--split-corners']],
  ['Douglas-Peucker (epsilon 0.09)', semicircle, (p) => rtl.vectorize(p, { method: 'dp', epsilon: 0.09 }), 'vectorize', [3, 0, 0.03, 3, 0.09, 1, 10000]],
  ['CAR (step 3, 0.1-0.5)', scan, (p) => rtl.segment(p, { step: 3, lowerBound: 0.1, upperBound: 0.5 }), 'segment', [3, 0.1, 0.5]],
];
const pct = (v, w = 8) => (Number.isFinite(v) ? `${(100 * v).toFixed(1)}%` : '-').padStart(w);
for (const n of SIZES) {
  for (const [name, make, f, op, params] of CASES) {
    const xy = make(n), file = join(dir, `${op}-${n}.f64`);
    writeFileSync(file, xy);
    const first = f(xy);  // warm-up: tier-up, memory growth, the kept objects
    const count = op === 'segment' ? first.clusters.length : first.count;
    const t = { nat: [], lib: [], whole: [], out: [] };
    for (let r = 0; r < rounds; r++) {
      if (haveNative) {
        const nat = native(op, file, params);
        if (nat.count !== count) throw new Error(`${name} ${n}: native kept ${nat.count}, wasm ${count}`);
        t.nat.push(nat.ms);
      }
      // The wasm side under the native side's protocol: REPS calls in a row, their median (the first call after
      // the native process ran starts on cold caches, as the native tool's first call does).
      const c = { whole: [], lib: [], out: [] };
      for (let k = 0; k < REPS; k++) {
        const a = performance.now(); f(xy); const w = performance.now() - a;
        c.whole.push(w); c.lib.push(rtl.lastComputeMs); c.out.push(w - rtl.lastComputeMs);
      }
      t.whole.push(median(c.whole)); t.lib.push(median(c.lib)); t.out.push(median(c.out));
    }
    const nat = haveNative ? median(t.nat) : NaN, lib = median(t.lib), out = median(t.out);
    // minima: the least disturbed call of each kind on a loaded machine
    const minNat = haveNative ? Math.min(...t.nat) : NaN, minLib = Math.min(...t.lib), minOut = Math.min(...t.out);
    console.log(`${`${name} ${n.toLocaleString('en')}`.padEnd(36)} ${fmt(nat, 8)} ${fmt(lib, 8)} ${fmt(lib / nat, 8)} ${fmt(minLib / minNat, 8)} ${fmt(out, 8)} ${pct(out / lib)} ${pct(minOut / minLib)} ${fmt(median(t.whole), 8)}`);
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
// The same calls on rtl.pointBuffer() views (zero-copy input: the numbers are read in place, not copied in): one
// block holds both inputs, each function gets the subarray it reads.
for (const [, f] of OUT) f();  // warm-up first: memory growth now would detach the views
let views;
const takeViews = () => {
  const b = rtl.pointBuffer(2 * N2, 2);
  b.set(line2); b.set(ring2, 2 * N2);
  views = { line: b.subarray(0, 2 * N2), ring: b.subarray(2 * N2) };
};
if (rtl.pointBuffer) {
  takeViews();
  OUT.push(...[
    ['vectorize ftls, pointBuffer', () => rtl.vectorize(views.line, { method: 'ftls', sigma: 0.03, delta: 3 })],
    ['vectorize dp, pointBuffer', () => rtl.vectorize(views.line, { method: 'dp', epsilon: 0.09 })],
    ['segment (CAR, step 3), pointBuffer', () => rtl.segment(views.ring, { step: 3, lowerBound: 0.1, upperBound: 0.5 })],
    ['simplify (Float64Array), pointBuffer', () => rtl.simplify(views.line, 0.09, true)],
  ]);
  // Warm-up again until no call grows memory (growth detaches the views: the next call on them throws).
  for (let t = 0; t < 4; t++) {
    try { for (const [, f] of OUT) f(); } catch { /* detached */ }
    takeViews();
  }
}
const T = OUT.map(() => ({ whole: [], lib: [] }));
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
