#!/usr/bin/env node
// rtl-wasm benchmarks (figures, not pass/fail; run by `./run bench`, or `node bench/js/b_wasm.mjs [--rounds=N] [--smoke]`):
//  1. wasm vs native at 100,000 and 1,000,000 points: FTLS, Douglas-Peucker and the batch (CAR) segmenter, in one
//     run, interleaved rounds (a native process call, then the wasm call), medians and minima. Native = the same
//     adapter code (wasm/src/*_ops.h) in tests/tools/rtl_native ($RTL_NATIVE_BUILD_DIR/tools, default build/native)
//     with the JS defaults (FTLS split at corners), the median of 5 calls per round on objects reused between them
//     (the first, cold call is the slowest and never the median); wasm = the library's own time of the call
//     (lastComputeMs: the kept objects are reused too), also the median of 5 calls in a row per round. (Why five:
//     docs/bench.md, "Measuring wasm against native".) Two ratios per case, each with its goal:
//     wasm library / native (<= 1.25) and time outside the library / library (< 10 % at 100k), the outside time
//     being the whole JS call minus its library time, per round. The kept counts (segments, clusters) of both
//     sides are checked equal. The native tool is one process for the whole run (see native() below). "faults":
//     the minor page faults of a wasm call (median). CAR returns its per-point arrays (8 bytes a point) in new
//     ArrayBuffers, whose pages fault in whenever the C allocator under it hands out fresh memory (a fresh mmap, or
//     the heap grown again after freed buffers were trimmed off its top), ~10 us a page on this VM: 200 pages at
//     100k points, ~2-7 ms. Calls in a row (this section) meet that state, interleaved calls (section 2) mostly
//     reuse pages. "floor": new ArrayBuffers of the same sizes, filled, timed after each round's calls: it meets
//     the same state, so outside - floor is the package's own share.
//  1b. a 100k-point call right after a 50-point call against the steady state (CAR, DP, FTLS; wasm and native).
//  2. time outside the library (argument checks, copy in, the C++ input check, results out) per function at
//     100,000 points, as a share of the library's time (the goal: under 10 %); ", pointBuffer" rows: the input is
//     an rtl.pointBuffer() view, read in place (no copy in); ", pointBuffer + view" rows: also { view: true }, the
//     results as views on the module's result block (no copy out).
//  2b. segment()'s outside time by parts at 100,000 points, against its floor (two new ArrayBuffers of 4 bytes a
//     point, filled: the two per-point arrays segment() returns as owned copies), and the same call with a pointBuffer()
//     input and { view: true }, which has neither the copy in nor that floor.
//  3. gzipped size of the .wasm and the JS.
// RTL_PACKAGE=dir: a package folder built by wasm/build.mjs with RTL_DIST_DIR, instead of dist/.
import { spawn } from 'node:child_process';
import { existsSync, mkdtempSync, readFileSync, rmSync, writeFileSync } from 'node:fs';
import { cpus, loadavg, tmpdir } from 'node:os';
import { join, resolve } from 'node:path';
import { fileURLToPath, pathToFileURL } from 'node:url';
import { createInterface } from 'node:readline';
import { gzipSync } from 'node:zlib';
import { noisySemicircle } from '../../tests/js/helpers.mjs';

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

// The paper's noisy semicircle (tests/js/helpers.mjs), seed 1.
const semicircle = (n) => noisySemicircle(n, 1);
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

// The native tool: one process for the whole run (--serve: a command a line, an answer a line), started before
// the first wasm call. A process started per round forks this one each time, and a fork write-protects all of
// its memory: every page the following wasm calls wrote faulted once more. --summary: only the time and the
// count, not the results (1.4 MB of JSON for CAR at 100k points, parsed between the timed calls).
let server = null, answers = null;
function startNative() {
  server = spawn(TOOL, ['--serve'], { stdio: ['pipe', 'pipe', 'inherit'] });
  answers = createInterface({ input: server.stdout })[Symbol.asyncIterator]();
}
async function native(op, file, params, reps = REPS) {
  server.stdin.write(`${[op, file, '2', ...params.map(String), `--reps=${reps}`, '--summary'].join(' ')}\n`);
  const { value, done } = await answers.next();
  const out = done ? { error: true } : JSON.parse(value);
  if (out.error) throw new Error(`rtl_native failed on ${op} ${file}`);
  return { ms: out.seconds * 1e3, count: out.count };
}
// Minor page faults of this process so far (the kernel's count): a fresh ArrayBuffer's pages fault on first write.
const faults = () => process.resourceUsage().minorPageFault;

const haveNative = existsSync(TOOL);
if (haveNative) startNative();
const rtl = await init();
console.log(`rtl-wasm ${rtl.version} benchmarks (${PKG}): ${rounds} interleaved rounds, medians, Node ${process.versions.node}${smoke ? ' (smoke)' : ''}`);

// ---- 1. wasm vs native
console.log(`\n1. wasm vs native (library call; native ${haveNative ? TOOL : 'tool not built: column skipped'}) (${load()})`);
console.log(`${'case'.padEnd(36)} ${'native'.padStart(8)} ${'wasm lib'.padStart(8)} ${'lib/nat'.padStart(8)} ${'min l/n'.padStart(8)} ${'outside'.padStart(8)} ${'out/lib'.padStart(8)} ${'min o/l'.padStart(8)} ${'whole'.padStart(8)} ${'faults'.padStart(7)} ${'floor'.padStart(8)} ${'faults'.padStart(7)}  (ms; ratios: medians, then minima; faults: minor page faults per call, median; floor: new ArrayBuffers of the call's per-point results, filled)`);
const CASES = [
  ['FTLS (sigma 0.03, delta 3)', semicircle, (p) => rtl.vectorize(p, { method: 'ftls', sigma: 0.03, delta: 3 }), 'vectorize', [0, 0, 0.03, 3, 0.09, 1, 10000, '--split-corners']],
  ['Douglas-Peucker (epsilon 0.09)', semicircle, (p) => rtl.vectorize(p, { method: 'dp', epsilon: 0.09 }), 'vectorize', [3, 0, 0.03, 3, 0.09, 1, 10000]],
  ['CAR (step 3, 0.1-0.5)', scan, (p) => rtl.segment(p, { step: 3, lowerBound: 0.1, upperBound: 0.5 }), 'segment', [3, 0.1, 0.5], 8],
];
// The floor of a call's time outside the library when it returns per-point arrays as owned copies (CAR: labels and
// indices, 4 + 4 bytes a point): two new ArrayBuffers of those sizes, filled. Timed after each round's wasm calls, the same
// number of times: it meets the allocator in the state they left (fresh pages or reused ones).
function floorMs(bytes, src) {
  const f0 = faults(), a = performance.now();
  const b = new Uint8Array(bytes / 2), c = new Uint8Array(bytes / 2);  // two arrays, as segment() returns
  b.set(src.subarray(0, bytes / 2));
  c.set(src.subarray(bytes / 2));
  return [performance.now() - a, faults() - f0, b[0] + c[0]];
}
const pct = (v, w = 8) => (Number.isFinite(v) ? `${(100 * v).toFixed(1)}%` : '-').padStart(w);
for (const n of SIZES) {
  for (const [name, make, f, op, params, bytesPerPoint = 0] of CASES) {
    const xy = make(n), file = join(dir, `${op}-${n}.f64`);
    const floorSrc = new Uint8Array(bytesPerPoint * n).fill(1);
    writeFileSync(file, xy);
    const first = f(xy);  // warm-up: tier-up, memory growth, the kept objects
    const count = op === 'segment' ? first.clusters.length : first.count;
    const t = { nat: [], lib: [], whole: [], out: [], faults: [], floor: [], floorFaults: [] };
    for (let r = 0; r < rounds; r++) {
      if (haveNative) {
        const nat = await native(op, file, params);
        if (nat.count !== count) throw new Error(`${name} ${n}: native kept ${nat.count}, wasm ${count}`);
        t.nat.push(nat.ms);
      }
      // The wasm side under the native side's protocol: REPS calls in a row, their median (the first call after
      // the native process ran starts on cold caches, as the native tool's first call does).
      const c = { whole: [], lib: [], out: [], faults: [] };
      for (let k = 0; k < REPS; k++) {
        const f0 = faults(), a = performance.now(); f(xy); const w = performance.now() - a;
        c.whole.push(w); c.lib.push(rtl.lastComputeMs); c.out.push(w - rtl.lastComputeMs); c.faults.push(faults() - f0);
      }
      t.whole.push(median(c.whole)); t.lib.push(median(c.lib)); t.out.push(median(c.out)); t.faults.push(median(c.faults));
      if (bytesPerPoint) {
        const fl = Array.from({ length: REPS }, () => floorMs(bytesPerPoint * n, floorSrc));
        t.floor.push(median(fl.map((x) => x[0]))); t.floorFaults.push(median(fl.map((x) => x[1])));
      }
    }
    const nat = haveNative ? median(t.nat) : NaN, lib = median(t.lib), out = median(t.out);
    // minima: the least disturbed call of each kind on a loaded machine
    const minNat = haveNative ? Math.min(...t.nat) : NaN, minLib = Math.min(...t.lib), minOut = Math.min(...t.out);
    console.log(`${`${name} ${n.toLocaleString('en')}`.padEnd(36)} ${fmt(nat, 8)} ${fmt(lib, 8)} ${fmt(lib / nat, 8)} ${fmt(minLib / minNat, 8)} ${fmt(out, 8)} ${pct(out / lib)} ${pct(minOut / minLib)} ${fmt(median(t.whole), 8)} ${String(median(t.faults)).padStart(7)} ${fmt(bytesPerPoint ? median(t.floor) : NaN, 8)} ${(bytesPerPoint ? String(median(t.floorFaults)) : '-').padStart(7)}`);
  }
}

// ---- 1b. a large call right after a small one: the kept point vectors and the library's buffers grow again (the
// small call shrank them) on every large call. Per round and side: a 50-point call, the large call ("after small"),
// then the large call twice more, the last one "steady"; medians over the rounds, native with one call per figure.
// (Until the link-order fix in wasm/CMakeLists.txt the growth ran -Oz copies of std::vector::__append: CAR 13.5 vs
// 0.34 ms, DP 8.0 vs 0.70, FTLS 6.7 vs 0.16 at 100k.) Goal: after small within ~1.3x of steady. Native shows
// 1.2-1.4x too here: the large call's data are cold in the caches after the small call and the other side's calls.
{
  const n = N2;
  console.log(`\n1b. ${n.toLocaleString('en')} points right after a 50-point call vs steady (library call, ms; ${rounds} rounds, medians) (${load()})`);
  console.log(`${'case'.padEnd(36)} ${'nat st'.padStart(8)} ${'nat aft'.padStart(8)} ${'aft/st'.padStart(7)} ${'wasm st'.padStart(8)} ${'wasm aft'.padStart(8)} ${'aft/st'.padStart(7)} ${'aft/nat'.padStart(7)}`);
  for (const [name, make, f, op, params] of CASES) {
    const big = make(n), small = make(50), bigFile = join(dir, `${op}-after-${n}.f64`), smallFile = join(dir, `${op}-small.f64`);
    writeFileSync(bigFile, big);
    writeFileSync(smallFile, small);
    f(big);
    const t = { natSt: [], natAft: [], st: [], aft: [] };
    for (let r = 0; r < rounds; r++) {
      if (haveNative) {
        await native(op, smallFile, params, 1);
        t.natAft.push((await native(op, bigFile, params, 1)).ms);
        await native(op, bigFile, params, 1);
        t.natSt.push((await native(op, bigFile, params, 1)).ms);
      }
      f(small);
      f(big); t.aft.push(rtl.lastComputeMs);
      f(big);
      f(big); t.st.push(rtl.lastComputeMs);
    }
    const [ns, na, ws, wa] = [t.natSt, t.natAft, t.st, t.aft].map((a) => (a.length ? median(a) : NaN));
    console.log(`${`${name} ${n.toLocaleString('en')}`.padEnd(36)} ${fmt(ns, 8)} ${fmt(na, 8)} ${fmt(na / ns, 7)} ${fmt(ws, 8)} ${fmt(wa, 8)} ${fmt(wa / ws, 7)} ${fmt(wa / na, 7)}`);
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
let views, hasView = false;
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
  // ... and their results as views on the module's result block ({ view: true }: no copy out), if the package has it.
  try { rtl.segment(new Float64Array(4), { view: true }); hasView = true; } catch { /* an older package */ }
  if (hasView) {
    OUT.push(...[
      ['vectorize ftls, pointBuffer + view', () => rtl.vectorize(views.line, { method: 'ftls', sigma: 0.03, delta: 3, view: true })],
      ['vectorize dp, pointBuffer + view', () => rtl.vectorize(views.line, { method: 'dp', epsilon: 0.09, view: true })],
      ['segment (CAR, step 3), pointBuffer + view', () => rtl.segment(views.ring, { step: 3, lowerBound: 0.1, upperBound: 0.5, view: true })],
    ]);
  }
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

// ---- 2b. segment()'s outside time by parts, with its floor: segment() returns owned copies of two per-point arrays
// (labels, indices: 8 bytes a point) in new ArrayBuffers, so no call can spend less outside than allocating and
// filling 8 bytes a point. Interleaved rounds; the page faults are the kernel's count per call (median): on this
// class of virtual machine a fault costs ~10 us, and a fresh ArrayBuffer's 200 pages at 100k points cost ~2 ms
// whenever the allocator hands out new pages instead of freed ones.
console.log(`\n2b. segment() (CAR, step 3) outside the library by parts, ${N2.toLocaleString('en')} points (${load()})`);
console.log(`${'part'.padEnd(58)} ${'median'.padStart(9)} ${'min'.padStart(9)} ${'% of lib'.padStart(9)} ${'faults'.padStart(7)}  (ms)`);
{
  const opts = { step: 3, lowerBound: 0.1, upperBound: 0.5 };
  const ref = rtl.segment(ring2, opts);
  const perPoint = new Uint8Array(8 * N2).fill(1), copyIn = new Float64Array(2 * N2);
  const labels = ref.labels, indices = new Uint32Array(N2);
  const offsets = [0], runs = [], runOffsets = [0];
  for (const c of ref.clusters) { offsets.push(offsets.at(-1) + c.indices.length); runs.push(...c.ranges); runOffsets.push(runs.length); }
  const offs = Uint32Array.from(offsets), rns = Uint32Array.from(runs), roffs = Uint32Array.from(runOffsets);
  let sink = 0;
  const PARTS = [
    ['segment(): whole call - library', () => { const a = performance.now(); rtl.segment(ring2, opts); return performance.now() - a - rtl.lastComputeMs; }],
    ['floor: two new ArrayBuffers of 4 B/point, filled', () => { const [ms, , v] = floorMs(8 * N2, perPoint); sink += v; return ms; }],
    ...(hasView ? [['segment(), pointBuffer + view: whole call - library', () => {
      const a = performance.now(); rtl.segment(views.ring, { ...opts, view: true }); return performance.now() - a - rtl.lastComputeMs;
    }]] : []),
    ['part: copy in (16 B/point into an existing array)', () => { const a = performance.now(); copyIn.set(ring2); return performance.now() - a; }],
    ['part: cluster objects and their views (as segment() makes them)', () => {
      const a = performance.now(), count = offs.length - 1, clusters = new Array(count);
      const ib = indices.buffer, io = indices.byteOffset, rb = rns.buffer, ro = rns.byteOffset;
      for (let k = 0; k < count; k++) {
        clusters[k] = { indices: new Uint32Array(ib, io + 4 * offs[k], offs[k + 1] - offs[k]), ranges: new Uint32Array(rb, ro + 4 * roffs[k], roffs[k + 1] - roffs[k]) };
      }
      sink += clusters.length + labels[0];
      return performance.now() - a;
    }],
  ];
  const P = PARTS.map(() => ({ t: [], f: [] })), libs = [];
  for (let r = 0; r < 3 * rounds; r++) {
    PARTS.forEach(([, f], k) => { const f0 = faults(); P[k].t.push(f()); P[k].f.push(faults() - f0); if (k === 0) libs.push(rtl.lastComputeMs); });
  }
  const lib = median(libs);
  PARTS.forEach(([name], k) => console.log(`${name.padEnd(58)} ${fmt(median(P[k].t))} ${fmt(Math.min(...P[k].t))} ${(100 * median(P[k].t) / lib).toFixed(1).padStart(9)} ${String(median(P[k].f)).padStart(7)}`));
  console.log(`${'(library time of those segment() calls, median)'.padEnd(58)} ${fmt(lib)}${sink < 0 ? ' ' : ''}`);
}

// ---- 3. size
console.log('\n3. package size (gzip -9)');
const gz = (f) => gzipSync(readFileSync(join(PKG, f)), { level: 9 }).length;
const wasmGz = gz('rtl.wasm'), jsGz = gz('rtl.mjs') + gz('api.mjs') + gz('index.mjs');
console.log(`   rtl.wasm ${readFileSync(join(PKG, 'rtl.wasm')).length} B -> ${wasmGz} B gz; browser JS (rtl.mjs + api.mjs + index.mjs) ${jsGz} B gz; together ${((wasmGz + jsGz) / 1024).toFixed(1)} KiB`);
console.log(`\n${load()}`);
if (server) server.stdin.end();
