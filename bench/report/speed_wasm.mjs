#!/usr/bin/env node
// The paper's speed figure, package side: the calls of speed_native.cpp through rtl-wasm (dist/, built
// by `npm run build`) on the same points, which speed_native wrote with --points=DIR: FTLS (sigma 0.03, delta 3,
// strict as RTL), incremental TLS (sigma 0.03), Douglas-Peucker and Reumann-Witkam (epsilon 0.09) on the
// semicircle; segment() (CAR, step 10, bounds 0.01-0.1) and a StreamSegmenter (IA, step 9 with CAR step 10's
// scaling: the same neighbours) on the scan. The floor is speed_native's, written in JavaScript over the
// Float64Array: one pass of squared distances to the chord and their maximum.
//
// Timing as in speed_native: interleaved rounds, each a batch of calls covering --batch points but taking no more
// than about 5 ms of CPU time, medians
// over the rounds of the whole call (what a user waits for: checks, copy in, compute, results out) in the
// process's CPU time (process.cpuUsage: this single-threaded work, plus whatever V8's helper threads do) and in
// wall time, and of the library's part in CPU time (estimated from rtl.lastComputeMs, the library's wall time:
// the call's CPU time times the library's share of its wall time; StreamSegmenter reports none: '-').
//
// Usage: node bench/report/speed_wasm.mjs --points=DIR [--smoke] [--rounds=R] [--batch=P] [--sizes=10,100,...]
//        [--out=FILE.tsv] [--no-header]   (speed_native's columns, impl "wasm"; --no-header appends to --out)
import { appendFileSync, readFileSync, writeFileSync } from 'node:fs';
import { join } from 'node:path';
import init from 'rtl-wasm';

const args = Object.fromEntries(process.argv.slice(2).map((a) => {
  const m = /^--([a-z-]+)(?:=(.*))?$/.exec(a);
  if (!m) { console.error(`speed_wasm: unknown argument '${a}'`); process.exit(2); }
  return [m[1], m[2] ?? true];
}));
const smoke = args.smoke === true;
let sizes = smoke ? [10, 100, 1000] : [10, 30, 100, 300, 1000, 3000, 10000, 30000, 100000, 300000, 1000000];
if (typeof args.sizes === 'string') sizes = args.sizes.split(',').map(Number).filter((n) => n >= 2);
const rounds = Math.max(1, Number(args.rounds) || (smoke ? 1 : 11));
const batch = Math.max(1, Number(args.batch) || (smoke ? 1000 : 200_000));
if (typeof args.points !== 'string') { console.error('speed_wasm: --points=DIR (written by speed_native) is required'); process.exit(2); }

const read = (stem, n) => {
  const b = readFileSync(join(args.points, `${stem}_${n}.f64`));
  if (b.length !== 16 * n) throw new Error(`speed_wasm: ${stem}_${n}.f64 holds ${b.length} bytes, not ${16 * n}`);
  return new Float64Array(b.buffer.slice(b.byteOffset, b.byteOffset + b.length));
};
const median = (a) => [...a].sort((x, y) => x - y)[Math.floor(a.length / 2)];

const rtl = await init();

// Each case: one call returning [output size, library ms or NaN].
function cases(xy, ring) {
  const n = xy.length / 2;
  const vect = (opts) => () => { const r = rtl.vectorize(xy, opts); return [r.ok ? r.count : 0, rtl.lastComputeMs]; };
  return [
    ['floor', () => {
      const ax = xy[0], ay = xy[1], ux = xy[2 * n - 2] - ax, uy = xy[2 * n - 1] - ay;
      let m = 0;
      for (let i = 0; i < 2 * n; i += 2) {
        const c = (xy[i] - ax) * uy - (xy[i + 1] - ay) * ux;
        if (c * c > m) m = c * c;
      }
      return [m > 0 ? 1 : 0, NaN];
    }],
    ['FTLS', vect({ method: 'ftls', sigma: 0.03, delta: 3, split: false })],
    ['ITLS', vect({ method: 'itls', sigma: 0.03 })],
    // kept points = segments + 1, as speed_native counts them
    ['DP', () => { const r = rtl.vectorize(xy, { method: 'dp', epsilon: 0.09 }); return [r.count + 1, rtl.lastComputeMs]; }],
    ['RW', () => { const r = rtl.vectorize(xy, { method: 'rw', epsilon: 0.09 }); return [r.count + 1, rtl.lastComputeMs]; }],
    ['CAR', () => { const r = rtl.segment(ring, { step: 10, lowerBound: 0.01, upperBound: 0.1 }); return [r.clusters.length, rtl.lastComputeMs]; }],
    ['IA', () => {
      const s = new rtl.StreamSegmenter({ step: 9, lowerBound: 0.01, upperBound: 0.1, scaling: (2 * Math.PI * 10) / n });
      try {
        s.addPoints(ring);
        s.flush();
        return [s.takeClosedClusters().length, NaN];
      } finally {
        s.dispose();
      }
    }],
  ];
}

const cpuMs = (since) => { const u = process.cpuUsage(since); return (u.user + u.system) / 1000; };
// Calls per timed batch: enough to cover `batch` points, but no more than take about 5 ms. Before
// that, 30 ms of calls let V8 compile the JavaScript around the call to its optimised tier; then doubling the
// calls until they take 1 ms tells the time of one. That time is the least of three tries in wall time (the
// process's CPU time also counts V8's compiler and GC threads; one wait for a core does not hit all three).
function batchCalls(run, n) {
  const byPoints = Math.max(1, Math.ceil(batch / n));
  for (const t0 = performance.now(); performance.now() - t0 < (smoke ? 1 : 30);) run();
  for (let k = 1; ; k *= 2) {
    let t = Infinity;
    for (let trial = 0; trial < 3; trial++) {
      const t0 = performance.now();
      for (let i = 0; i < k; i++) run();
      t = Math.min(t, performance.now() - t0);
    }
    if (t >= 1 || k >= byPoints) return Math.min(byPoints, Math.max(1, Math.ceil((5 * k) / Math.max(t, 1e-3))));
  }
}

const rows = args['no-header'] ? [] : ['impl\tcase\tpoints\trounds\tcalls\tcpu_ns_per_point\twall_ns_per_point\tlibrary_ns_per_point\toutput'];
const g = (v) => (Number.isFinite(v) ? Number(v.toPrecision(6)).toString() : '-');
for (const n of sizes) {
  const cs = cases(read('semicircle', n), read('scan', n)).map(([name, run]) => ({ name, run, cpu: [], wall: [], lib: [], output: run()[0] }));
  for (const c of cs) c.calls = batchCalls(c.run, n);
  for (let r = 0; r < rounds; r++) {
    for (const c of cs) {
      const { calls } = c;
      let lib = 0;
      const t0 = performance.now(), c0 = process.cpuUsage();
      for (let k = 0; k < calls; k++) lib += c.run()[1];
      const cpu = cpuMs(c0) / calls, wall = (performance.now() - t0) / calls;
      c.cpu.push(cpu);
      c.wall.push(wall);
      // The library's CPU time, estimated as the call's CPU time times the library's share of its wall time
      // (lastComputeMs is wall time: alone it would count the waits for a core).
      c.lib.push((cpu * lib) / calls / wall);
    }
  }
  for (const c of cs)
    rows.push(['wasm', c.name, n, rounds, c.calls, ...[c.cpu, c.wall, c.lib].map((v) => g((median(v) / n) * 1e6)), c.output].join('\t'));
  const car = cs.find((c) => c.name === 'CAR').output, ia = cs.find((c) => c.name === 'IA').output;
  if (car !== ia) { console.error(`speed_wasm: CAR found ${car} clusters, IA ${ia} at ${n} points`); process.exit(1); }
  console.error(`speed_wasm: ${n} points done`);
}
const tsv = rows.map((r) => r + '\n').join('');
if (typeof args.out === 'string') (args['no-header'] ? appendFileSync : writeFileSync)(args.out, tsv);
else process.stdout.write(tsv);
