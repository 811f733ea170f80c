#!/usr/bin/env node
// Per-call time of small calls, where the wasm boundary (argument checks, the options block, the result object) is
// most of the time: fitLine on 10 points, readCarmenLog on a one-scan log, TfTree.insert + erase. The package in
// dist/ (or RTL_PACKAGE=dir) against a baseline package (RTL_BASELINE=dir: another build's dist/, e.g. of the
// commit before a boundary change; without it, the package against a second instance of itself, which shows the
// noise of the machine). Both in one Node process, after 3 s of calls to both (their wasm tiers up in the
// background), in interleaved rounds whose order alternates; the minimum per call over the rounds is reported,
// and the ratio package / baseline. The results of both are checked equal first.
//   [RTL_PACKAGE=dir] [RTL_BASELINE=dir] node bench/js/b_boundary_calls.mjs [--rounds=N] [--smoke]
import assert from 'node:assert/strict';
import { resolve } from 'node:path';
import { pathToFileURL } from 'node:url';

const root = new URL('../../', import.meta.url);
const entry = (dir) => pathToFileURL(resolve(dir, 'index.node.mjs')).href;
const smoke = process.argv.includes('--smoke');
const roundsArg = process.argv.find((a) => a.startsWith('--rounds='));
const ROUNDS = smoke ? 3 : Number(roundsArg ? roundsArg.slice(9) : 201);

const pkgDir = process.env.RTL_PACKAGE || new URL('dist', root).pathname;
const A = await (await import(entry(pkgDir))).init();
const B = await (await import(entry(process.env.RTL_BASELINE || pkgDir))).init();

const pts = new Float64Array(20);
for (let i = 0; i < 10; i++) { pts[2 * i] = i; pts[2 * i + 1] = 0.5 * i + (i % 2) * 0.01; }
const log = 'FLASER 5 1.0 1.5 2.0 2.5 3.0 0 0 0 0 0 0 0.1 host 0.1\n';
const trees = new Map();
const cases = [
  ['fitLine, 10 points', 2000, (r) => r.fitLine(pts)],
  ['readCarmenLog, 1 scan of 5 beams', 100, (r) => r.readCarmenLog(log)],
  ['TfTree.insert + erase', 2000, (r) => {
    let t = trees.get(r);
    if (!t) trees.set(r, t = new r.TfTree('w', { dim: 3 }));
    const ok = t.insert('a', 'w', { angle: 0.3, axis: [0, 0, 1], translation: [1, 2, 3] });
    const tf = t.tf('w', 'a');
    t.erase('a');
    return [ok, tf];
  }],
];

for (const [name, , f] of cases) assert.deepEqual(f(A), f(B), `${name}: the same result from both packages`);
for (const t0 = Date.now(); Date.now() - t0 < (smoke ? 100 : 3000);) for (const [, , f] of cases) { f(A); f(B); }

console.log(`per-call minimum over ${ROUNDS} interleaved rounds: package ${pkgDir} / baseline ${process.env.RTL_BASELINE || '(itself)'}`);
for (const [name, n, f] of cases) {
  const best = [Infinity, Infinity];
  for (let r = 0; r < ROUNDS; r++) {
    for (const i of r % 2 ? [1, 0] : [0, 1]) {
      const R = i ? B : A;
      const t0 = process.hrtime.bigint();
      for (let k = 0; k < n; k++) f(R);
      best[i] = Math.min(best[i], Number(process.hrtime.bigint() - t0) / n / 1000);
    }
  }
  console.log(`${name.padEnd(34)} package ${best[0].toFixed(3)} us  baseline ${best[1].toFixed(3)} us  ratio ${(best[0] / best[1]).toFixed(3)}`);
}
for (const t of trees.values()) t.dispose();
