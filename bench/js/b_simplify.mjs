#!/usr/bin/env node
// rtl-wasm's simplify() against simplify-js, each used as its users use it: the same array of {x, y} objects in,
// an array of the same objects out, in one Node process, interleaved rounds (simplify-js, rtl-wasm, simplify-js,
// ...), medians. Both quality modes, a noisy semicircle (r 8, noise 0.01) and a random walk, 100,000 and 1,000,000
// points; the kept points are checked identical before timing. Also the typed-array form and the share of
// rtl-wasm's call spent in the library (lastComputeMs), i.e. the {x, y} -> wasm transfer.
//   node bench/js/b_simplify.mjs [--rounds=N] [--smoke]
import simplifyJs from 'simplify-js';
import init from 'rtl-wasm';

const args = process.argv.slice(2);
const smoke = args.includes('--smoke');
const rounds = Number((args.find((a) => a.startsWith('--rounds=')) || '').slice(9)) || (smoke ? 1 : 9);
const SIZES = smoke ? [10_000] : [100_000, 1_000_000];
const median = (a) => [...a].sort((x, y) => x - y)[Math.floor(a.length / 2)];

function rng(seed) {
  let s = seed >>> 0;
  return () => ((s = (Math.imul(s, 1664525) + 1013904223) >>> 0) / 4294967296);
}
function semicircle(n) {
  const r = rng(1);
  return Array.from({ length: n }, (_, i) => {
    const a = (Math.PI * i) / (n - 1);
    return { x: 8 * Math.cos(a) + 0.01 * (r() - 0.5), y: 8 * Math.sin(a) + 0.01 * (r() - 0.5) };
  });
}
function walk(n) {
  const r = rng(2);
  let x = 0, y = 0;
  return Array.from({ length: n }, () => ({ x: (x += r() - 0.5), y: (y += r() - 0.5) }));
}

const rtl = await init();
console.log(`simplify: rtl-wasm ${rtl.version} vs simplify-js, Node ${process.versions.node}, ${rounds} interleaved rounds, medians (ms)${smoke ? ' (smoke)' : ''}`);
console.log('case'.padEnd(34), 'kept'.padStart(8), 'simplify-js'.padStart(12), 'rtl {x,y}'.padStart(10), 'speed-up'.padStart(9),
  'rtl f64'.padStart(9), 'library'.padStart(9), 'transfer %'.padStart(11));
for (const n of SIZES) {
  for (const [name, pts, tol] of [['semicircle', semicircle(n), 0.01], ['random walk', walk(n), 1]]) {
    const xy = new Float64Array(2 * n);
    pts.forEach((p, i) => { xy[2 * i] = p.x; xy[2 * i + 1] = p.y; });
    for (const hq of [false, true]) {
      const theirs = simplifyJs(pts, tol, hq), ours = rtl.simplify(pts, tol, hq);
      if (ours.length !== theirs.length || ours.some((p, i) => p !== theirs[i])) throw new Error(`${name} ${n}: kept points differ`);
      const tJs = [], tObj = [], tF64 = [], tLib = [];
      for (let r = 0; r < rounds + 1; r++) {  // round 0 warms up (tier-up, memory growth) and is dropped
        let a = performance.now(); simplifyJs(pts, tol, hq); const js = performance.now() - a;
        a = performance.now(); rtl.simplify(pts, tol, hq); const obj = performance.now() - a; const lib = rtl.lastComputeMs;
        a = performance.now(); rtl.simplify(xy, tol, hq); const f64 = performance.now() - a;
        if (r) { tJs.push(js); tObj.push(obj); tLib.push(lib); tF64.push(f64); }
      }
      const js = median(tJs), obj = median(tObj), lib = median(tLib);
      console.log(`${name} ${n.toLocaleString('en')}${hq ? ' hq' : ''}`.padEnd(34), String(ours.length).padStart(8), js.toFixed(2).padStart(12),
        obj.toFixed(2).padStart(10), `${(js / obj).toFixed(2)}x`.padStart(9), median(tF64).toFixed(2).padStart(9), lib.toFixed(2).padStart(9),
        (100 * (obj - lib) / obj).toFixed(1).padStart(11));
    }
  }
}
