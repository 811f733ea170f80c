#!/usr/bin/env node
// rtl-wasm's simplify() against simplify-js, each used as its users use it: the same array of {x, y} objects in,
// an array of the same objects out, in one Node process, interleaved rounds, medians (bench/js/simplify_cases.mjs).
// Both quality modes, a noisy semicircle (r 8, noise 0.01, tolerance 0.01) and a random walk (tolerance 1),
// 100,000 and 1,000,000 points; the kept points are checked identical before timing. Floor: reading the {x, y}
// array once. Timed twice: process CPU time (less disturbed by other processes on a loaded machine) and wall time.
// Rows where simplify-js itself takes less than 3 floors get a line stating that bound (js/floor): no {x, y}
// reader can be 3x faster there (fast mode on the 1M semicircle, where simplify-js keeps 1 point in ~650).
// The same cases in Chromium: bench/js/b_simplify_browser.mjs.
//   [RTL_PACKAGE=dir] node bench/js/b_simplify.mjs [--rounds=N] [--warmup-ms=N] [--smoke] [--wall-only]
import { cpus, loadavg } from 'node:os';
import { resolve } from 'node:path';
import { pathToFileURL } from 'node:url';
import simplifyJs from 'simplify-js';
import { WARMUP_MS, formatRows, runSimplifyBench } from './simplify_cases.mjs';

const args = process.argv.slice(2);
const smoke = args.includes('--smoke');
const rounds = Number((args.find((a) => a.startsWith('--rounds=')) || '').slice(9)) || (smoke ? 1 : 9);
const sizes = smoke ? [10_000] : [100_000, 1_000_000];
// Untimed warm-up per case (simplify_cases.mjs); --warmup-ms=0 measures the start-up instead (round 0 dropped).
const warmArg = args.find((a) => a.startsWith('--warmup-ms='));
const warmupMs = warmArg ? Number(warmArg.slice(12)) : (smoke ? 0 : WARMUP_MS);

// RTL_PACKAGE=dir: a package folder built elsewhere (e.g. RTL_DIST_DIR of wasm/build.mjs) instead of dist/.
const { default: init } = await import(process.env.RTL_PACKAGE ? pathToFileURL(resolve(process.env.RTL_PACKAGE, 'index.node.mjs')).href : 'rtl-wasm');
const rtl = await init();
const cpuMs = () => { const u = process.cpuUsage(); return (u.user + u.system) / 1000; };
const load = () => `load ${loadavg().map((l) => l.toFixed(2)).join(' ')} on ${cpus().length} cores`;
console.log(`simplify: rtl-wasm ${rtl.version} vs simplify-js, Node ${process.versions.node}, ${rounds} interleaved rounds after ${warmupMs} ms of warm-up per case, medians (ms)${smoke ? ' (smoke)' : ''}`);
for (const [label, clock] of [['CPU time', cpuMs], ['wall time', () => performance.now()]]) {
  if (label === 'CPU time' && args.includes('--wall-only')) continue;
  console.log(`\n${label} (${load()})`);
  console.log(formatRows(runSimplifyBench({ rtl, simplifyJs, sizes, rounds, clock, warmupMs })));
}
console.log(`\nspeed-up = simplify-js / rtl {x,y}; library = rtl's own time in the call (lastComputeMs, wall); ${load()}`);
