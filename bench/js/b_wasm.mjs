#!/usr/bin/env node
// rtl-wasm benchmarks (figures, not pass/fail; run by `./run bench`, or `node bench/js/b_wasm.mjs [--reps=N] [--smoke]`):
//  1. wasm vs native at 1M points: FTLS, Douglas-Peucker and the batch (CAR) segmenter. Native = the same adapter
//     code in tests/tools/rtl_native ($RTL_NATIVE_BUILD_DIR/tools, default build/native), timed inside the process;
//     wasm = the whole JS call (checks, copy in, compute, results out) and its compute part alone (lastComputeMs).
//  2. array transfer vs compute at 100,000 points (the share of a call not spent in the library).
//  3. Douglas-Peucker against simplify-js (highQuality = true, same tolerance, same polyline): same kept points?
//     speed at 100,000 points.
//  4. gzipped size of the .wasm and the JS.
import { execFileSync } from 'node:child_process';
import { existsSync, mkdtempSync, readFileSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join, resolve } from 'node:path';
import { fileURLToPath } from 'node:url';
import { gzipSync } from 'node:zlib';
import simplify from 'simplify-js';
import init from 'rtl-wasm';

const ROOT = fileURLToPath(new URL('../..', import.meta.url));
const args = process.argv.slice(2);
const smoke = args.includes('--smoke');
const reps = Number((args.find((a) => a.startsWith('--reps=')) || '').slice(7)) || (smoke ? 1 : 7);
const N = smoke ? 100_000 : 1_000_000;
const TOOL = join(resolve(ROOT, process.env.RTL_NATIVE_BUILD_DIR || 'build/native'), 'tools', 'rtl_native');
const dir = mkdtempSync(join(tmpdir(), 'rtl-bench-'));
process.on('exit', () => rmSync(dir, { recursive: true, force: true }));

const median = (a) => [...a].sort((x, y) => x - y)[Math.floor(a.length / 2)];
// Median time of f() after one warm-up call (tier-up, memory growth); with `compute`, also the median of what
// f() returns (the library's own time of that call).
function time(f, n = reps) {
  f();
  const t = [], c = [];
  for (let i = 0; i < n; i++) { const a = performance.now(); const r = f(); t.push(performance.now() - a); c.push(r); }
  const total = median(t);
  return Object.assign(new Number(total), { total, compute: median(c.map(Number)) });
}
const row = (name, ms, base, extra = '') =>
  console.log(`${name.padEnd(44)} ${ms.toFixed(3).padStart(10)} ms${base ? `  ${(ms / base).toFixed(2).padStart(6)}x` : '        '}  ${extra}`);

// A deterministic polyline like a long laser chain: straight runs with corners and 5 mm noise (x, y interleaved).
function polyline(n, seed = 1) {
  let s = seed;
  const rnd = () => ((s = (s * 1103515245 + 12345) % 2147483648) / 2147483648);
  const xy = new Float64Array(2 * n);
  let x = 0, y = 0, a = 0;
  for (let i = 0; i < n; i++) {
    if (i % 200 === 0) a += (rnd() - 0.5) * 2.5;
    x += 0.01 * Math.cos(a); y += 0.01 * Math.sin(a);
    xy[2 * i] = x + (rnd() - 0.5) * 0.01;
    xy[2 * i + 1] = y + (rnd() - 0.5) * 0.01;
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

function native(op, xy, params) {
  const f = join(dir, 'pts.f64');
  writeFileSync(f, xy);
  const out = JSON.parse(execFileSync(TOOL, [op, f, '2', ...params.map(String), `--reps=${reps}`], { encoding: 'utf8', maxBuffer: 1 << 30 }));
  return out.seconds * 1e3;
}

const rtl = await init();
console.log(`rtl-wasm ${rtl.version} benchmarks: median of ${reps} runs, Node ${process.versions.node}${smoke ? ' (smoke)' : ''}\n`);

// ---- 1. wasm vs native at 1M points
console.log(`1. wasm vs native, ${N.toLocaleString('en')} points (ratio: wasm / native compute)`);
const line = polyline(N), ring = scan(N);
const cases = [
  ['FTLS (sigma 0.03, delta 0.3)', line, () => rtl.vectorize(line, { method: 'ftls', sigma: 0.03, delta: 0.3 }), 'vectorize', [0, 0, 0.03, 0.3, 0.09, 1, 10000]],
  ['Douglas-Peucker (epsilon 0.03)', line, () => rtl.vectorize(line, { method: 'dp', epsilon: 0.03 }), 'vectorize', [3, 0, 0.03, 0.3, 0.03, 1, 10000]],
  ['batch segmenter CAR (step 3, 0.1-0.5)', ring, () => rtl.segment(ring, { step: 3, lowerBound: 0.1, upperBound: 0.5 }), 'segment', [3, 0.1, 0.5]],
];
const haveNative = existsSync(TOOL);
if (!haveNative) console.log(`   (native tool ${TOOL} not built: native column skipped)`);
for (const [name, xy, f, op, params] of cases) {
  const nat = haveNative ? native(op, xy, params) : NaN;
  const { total, compute } = time(() => { f(); return rtl.lastComputeMs; });
  if (haveNative) row(`   native ${name}`, nat, 0);
  row(`   wasm   ${name}: compute`, compute, haveNative ? nat : 0);
  row(`   wasm   ${name}: whole call`, total, haveNative ? nat : 0);
}

// ---- 2. transfer vs compute at 100,000 points
console.log('\n2. array transfer (checks, copy in, results out) vs compute, 100,000 points');
for (const [name, xy, f] of [
  ['FTLS', polyline(100_000), (p) => rtl.vectorize(p, { method: 'ftls' })],
  ['Douglas-Peucker', polyline(100_000), (p) => rtl.vectorize(p, { method: 'dp', epsilon: 0.03 })],
  ['segmenter', scan(100_000), (p) => rtl.segment(p)],
]) {
  const { total, compute } = time(() => { f(xy); return rtl.lastComputeMs; }, reps * 3);
  row(`   ${name}: whole call`, total, 0);
  row(`   ${name}: transfer share`, total - compute, total, `(${(100 * (total - compute) / total).toFixed(1)} % of the call)`);
}

// ---- 3. simplify-js
// Its Douglas-Peucker measures the distance to the chord *segment*; rtl's (rtl-api 6.8) to the chord's infinite
// line. They keep the same points unless the farthest point projects outside its chord, which a profile (x
// increasing) never does and a wandering polyline rarely does: both are reported.
console.log('\n3. Douglas-Peucker vs simplify-js (highQuality = true), tolerance 0.03, 100,000 points');
function profile(n) {
  const xy = new Float64Array(2 * n);
  for (let i = 0; i < n; i++) { xy[2 * i] = i * 0.01; xy[2 * i + 1] = Math.sin(i * 0.003) * 2 + Math.sin(i * 0.05) * 0.05 + ((i * 7919) % 13) * 0.001; }
  return xy;
}
for (const [label, xy] of [['profile (x increasing)', profile(100_000)], ['wandering polyline', polyline(100_000, 7)]]) {
  const objs = Array.from({ length: xy.length / 2 }, (_, i) => ({ x: xy[2 * i], y: xy[2 * i + 1] }));
  const ours = rtl.vectorize(xy, { method: 'dp', epsilon: 0.03 });
  const kept = [0, ...Array.from({ length: ours.count }, (_, k) => ours.indices[2 * k + 1] - 1)];
  const index = new Map(objs.map((o, i) => [o, i]));
  const theirKept = simplify(objs, 0.03, true).map((o) => index.get(o));
  const theirSet = new Set(theirKept);
  const common = kept.filter((i) => theirSet.has(i)).length;
  const same = kept.length === theirKept.length && common === kept.length;
  console.log(`   ${label}: kept rtl-wasm ${kept.length}, simplify-js ${theirKept.length}, in common ${common}: ${same ? 'identical' : 'differ'}`);
  const tJs = time(() => simplify(objs, 0.03, true), reps * 3).total;
  const tW = time(() => rtl.vectorize(xy, { method: 'dp', epsilon: 0.03 }), reps * 3).total;
  row('     simplify-js (array of {x, y})', tJs, 0);
  row('     rtl-wasm vectorize dp (Float64Array)', tW, tJs, `-> ${(tJs / tW).toFixed(1)}x faster`);
}

// ---- 4. size
console.log('\n4. package size (gzip -9)');
const gz = (f) => gzipSync(readFileSync(join(ROOT, 'dist', f)), { level: 9 }).length;
const wasmGz = gz('rtl.wasm'), jsGz = gz('rtl.mjs') + gz('api.mjs') + gz('index.mjs');
console.log(`   rtl.wasm ${readFileSync(join(ROOT, 'dist', 'rtl.wasm')).length} B -> ${wasmGz} B gz; browser JS (rtl.mjs + api.mjs + index.mjs) ${jsGz} B gz; together ${((wasmGz + jsGz) / 1024).toFixed(1)} KiB`);
