#!/usr/bin/env node
// extractPolylines() in Node (the package's wasm) against rtl::ScanPolylines2D natively on PLE's benchmark scans, same
// inputs, same J, outputs checked equal (figures, not pass/fail):
//   node bench/js/b_polylines.mjs [--data=DIR] [--rounds=N] [--J=10,50] [--smoke]
// Inputs: b_vect_ple_budget --dump writes PLE's 20 intel and 20 csail scans (its protocol, bench/ple/README.md) as
// interleaved x, y doubles into a temporary folder; --smoke uses the tests/data excerpts (first 30 scans each).
// Native: tests/tools/polylines_native (in $RTL_NATIVE_BUILD_DIR/tools, default build/native) with a repetition count:
// the median thread CPU and wall-clock times of N + 1 calls (at least 3) on one object. It is started by a helper
// process, never by this one: every process start from Node forks it, and after a fork each page of its memory (wasm
// memory, the JS heap, array buffers) faults once more on its next write. Started from here before each scan's wasm calls, that
// made the JS layer's share 3-10x (intel J = 10 with /bin/true run in between: 10 -> 36-48 us at load 0.9, -> 100 us
// at load 5, where the library's time grew 1.5x too: a cost of this benchmark, not of the package). Wasm: the
// library's time of the call
// (lastComputeMs: wall clock inside the module) and the whole JS call, each the median of N calls in a row on the same
// module after one call that grows its buffers, after a first pass over every scan (V8 runs a wasm function with its
// baseline compiler first and swaps in optimised code, compiled in the background, once the function is hot: the
// first calls take 2-7x the steady time, see the "first pass" line; the table is the steady state, as natively).
// Per log and J: the medians over the scans, and the ratios of the wasm times to native wall clock (like for like;
// goal: wasm library / native <= 1.5), the median of the JS layer's share of a call (call - library: input copy,
// options, result arrays and objects), and the whole call on the same number of beams with no return at all (every
// coordinate NaN: the documented empty result, nearly no library work): the floor of the layers around the library
// (checks, input copy, the binding, the result's arrays) for that scan size, and the partition (offsets, vertex and explained-beam counts) checked identical, the score to 1e-7 relative (the
// package's test explains why not bit-identical). Both sides run on a shared machine: the load average is printed.
// RTL_PACKAGE=dir: a package folder built by wasm/build.mjs, instead of dist/.
import { execFileSync, spawn } from 'node:child_process';
import { mkdtempSync, readFileSync, readdirSync, rmSync } from 'node:fs';
import { loadavg, tmpdir } from 'node:os';
import { join, resolve } from 'node:path';
import { fileURLToPath, pathToFileURL } from 'node:url';
import { performance } from 'node:perf_hooks';

const ROOT = fileURLToPath(new URL('../..', import.meta.url));
const PKG = resolve(ROOT, process.env.RTL_PACKAGE || 'dist');
const BUILD = resolve(ROOT, process.env.RTL_NATIVE_BUILD_DIR || 'build/native');
const TOOL = join(BUILD, 'tools', 'polylines_native');
const DUMP = join(BUILD, 'bench', 'b_vect_ple_budget');
const arg = (name, fallback) => {
  const a = process.argv.find((s) => s.startsWith(`--${name}=`));
  return a ? a.slice(name.length + 3) : fallback;
};
const smoke = process.argv.includes('--smoke');
const rounds = Number(arg('rounds', smoke ? 1 : 5));
const budgets = arg('J', smoke ? '10,50' : '10,30,50').split(',').map(Number);
const dataArgs = arg('data') ? [`--data=${arg('data')}`] : [];

const { default: init } = await import(pathToFileURL(join(PKG, 'index.node.mjs')).href);
const rtl = await init();
const dir = mkdtempSync(join(tmpdir(), 'rtl-b-polylines-'));
process.on('exit', () => rmSync(dir, { recursive: true, force: true }));
execFileSync(DUMP, [...(smoke ? ['--smoke'] : dataArgs), `--dump=${dir}`], { stdio: ['ignore', 'ignore', 'inherit'] });

// The native runs' helper: runs the tool on request (IPC) and returns its output, so that this process forks only
// here and for the dump above, before the warm-up passes below rewrite its pages.
const runner = spawn(process.execPath, ['-e', `
  const { execFileSync } = require('node:child_process');
  process.on('message', ({ cmd, args }) => {
    try { process.send({ out: execFileSync(cmd, args, { encoding: 'utf8', maxBuffer: 1 << 26 }) }); }
    catch (e) { process.send({ error: String(e.message) }); }
  });`], { stdio: ['ignore', 'inherit', 'inherit', 'ipc'] });
const native = (args) => new Promise((res, rej) => {
  runner.once('message', (r) => (r.error === undefined ? res(r.out) : rej(new Error(`polylines_native: ${r.error}`))));
  runner.send({ cmd: TOOL, args });
});

const median = (v) => { const s = [...v].sort((a, b) => a - b); return s[Math.floor(s.length / 2)]; };
const files = readdirSync(dir).filter((f) => f.endsWith('.f64')).sort();
const read = (f) => { const b = readFileSync(join(dir, f)); return new Float64Array(b.buffer, b.byteOffset, b.byteLength / 8); };
console.log(`extractPolylines (wasm, ${PKG}) vs native; ${files.length} scans, ${rounds} calls each; load average ${loadavg().map((v) => v.toFixed(1)).join(' ')}`);
// The first pass (cold: baseline code until V8's optimised code is ready), then the same pass again (warm).
const all = files.map(read), Jmax = Math.max(...budgets);
const pass = () => { const t0 = performance.now(); for (const p of all) rtl.extractPolylines(p, { maxVertices: Jmax }); return performance.now() - t0; };
const cold = pass(), warm = pass();
console.log(`first pass over the ${all.length} scans at J = ${Jmax}: ${cold.toFixed(1)} ms cold, ${warm.toFixed(1)} ms the same pass warm (${(cold / warm).toFixed(2)}x)`);
// Untimed: three more passes at every budget, with the empty calls, so that the JS layer's functions are optimised too
// before the first row (after the two passes above alone, the first row's calls took 10-20 us more than the others').
const none = all.map((p) => new Float64Array(p.length).fill(NaN));
for (let r = 0; r < 3; r++) for (const J of budgets) all.forEach((p, i) => { rtl.extractPolylines(p, { maxVertices: J }); rtl.extractPolylines(none[i], { maxVertices: J }); });
console.log('log    J   scans  native cpu / wall med us  wasm lib med us  wasm call med us  JS share med us  empty call med us  lib/native  call/native  partitions equal  max score diff');
for (const log of ['intel', 'csail']) {
  const mine = files.filter((f) => f.startsWith(`${log}_`));
  for (const J of budgets) {
    const nat = [], natCpu = [], lib = [], call = [], share = [], empty = [];
    let equal = 0, maxDiff = 0;
    for (const f of mine) {
      const file = join(dir, f);
      const points = read(f);
      // at least 3 native calls: the median of 2 (--smoke) was the first, cold one (its buffers allocated and faulted in)
      const n = JSON.parse(await native([file, J, 1, 0.5, Math.max(3, rounds + 1)].map(String)));
      let w;
      const libMs = [], callMs = [];
      rtl.extractPolylines(points, { maxVertices: J });   // first call: the module's buffers grow
      for (let k = 0; k < rounds; k++) {
        const t0 = performance.now();
        w = rtl.extractPolylines(points, { maxVertices: J });
        callMs.push(performance.now() - t0);
        libMs.push(rtl.lastComputeMs);
      }
      const none = new Float64Array(points.length).fill(NaN), emptyMs = [];
      rtl.extractPolylines(none, { maxVertices: J });
      for (let k = 0; k < rounds; k++) {
        const t0 = performance.now();
        rtl.extractPolylines(none, { maxVertices: J });
        emptyMs.push(performance.now() - t0);
      }
      empty.push(1000 * median(emptyMs));
      nat.push(n.wallUs); natCpu.push(n.timeUs); lib.push(1000 * median(libMs)); call.push(1000 * median(callMs));
      share.push(1000 * median(callMs.map((t, k) => t - libMs[k])));
      const same = JSON.stringify([...w.offsets]) === JSON.stringify(n.offsets) && w.vertexCount === n.vertexCount
        && w.explainedBeams === n.explainedBeams;
      equal += same ? 1 : 0;
      maxDiff = Math.max(maxDiff, Math.abs(w.score - n.score) / Math.max(1e-300, Math.abs(n.score)));
    }
    const mn = median(nat), ml = median(lib), mc = median(call);
    console.log(`${log.padEnd(6)} ${String(J).padStart(2)}  ${String(mine.length).padStart(5)}  ${`${median(natCpu).toFixed(1)} / ${mn.toFixed(1)}`.padStart(24)}  ${ml.toFixed(1).padStart(15)}  ${mc.toFixed(1).padStart(16)}  ${median(share).toFixed(1).padStart(15)}  ${median(empty).toFixed(1).padStart(17)}  ${(ml / mn).toFixed(2).padStart(10)}  ${(mc / mn).toFixed(2).padStart(11)}  ${`${equal} of ${mine.length}`.padStart(16)}  ${maxDiff.toExponential(1).padStart(14)}`);
  }
}
runner.disconnect();
