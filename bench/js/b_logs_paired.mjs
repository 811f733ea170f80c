#!/usr/bin/env node
// Two builds of the package in one process, interleaved on the same MCAP (figures, not pass/fail): the way to compare
// a change on a shared machine, where absolute rates move several-fold between runs but a paired ratio does not.
//   node bench/js/b_logs_paired.mjs --before=DIR [--scans=10000] [--rounds=5]
// DIR is a copy of an earlier dist/ (e.g. `git stash; npm run build; cp -r dist build/dist-before; git stash pop;
// npm run build`). Per round and build, in alternating order, CPU time (process.cpuUsage) of:
//   read     openLog(...).scans() over the whole log (MCAP reader + CDR decode + fromLaserScan)
//   compute  segmentAndVectorize(ftls, minPoints 3) on the log's scans already in memory
//   batched  read + segmentAndVectorize per scan: what the CLI runs
// Medians over the rounds, and after/before ratios of the medians. Every scan's result is checked equal between the
// builds (every array of segmentAndVectorize's result, and the read scans' points and angles). The builds alternate
// every 100 scans within a round (see paired()).
import { mkdtempSync, readFileSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join, resolve } from 'node:path';
import { fileURLToPath, pathToFileURL } from 'node:url';
import { laserScanPayloads, writeLaserLog } from './laser_log.mjs';

const flag = (name, def) => process.argv.find((a) => a.startsWith(`--${name}=`))?.split('=')[1] ?? def;
const N = Number(flag('scans', 10000)), ROUNDS = Number(flag('rounds', 5));
const ROOT = fileURLToPath(new URL('../../', import.meta.url));
const BEFORE = flag('before', undefined);
if (BEFORE === undefined) throw new Error('--before=DIR (a copy of an earlier dist/) is required');

async function build(dir) {
  const init = (await import(pathToFileURL(join(dir, 'index.node.mjs')).href)).default;
  const { openLog } = await import(pathToFileURL(join(dir, 'ros', 'logs.js')).href);
  return { rtl: await init(), openLog };
}
const builds = { before: await build(resolve(BEFORE)), after: await build(join(ROOT, 'dist')) };

// The bench's log (b_logs.mjs): N 360-beam LaserScans from the CSAIL excerpt, cycled, 1 MB uncompressed chunks.
const csail = builds.after.rtl.readCarmenLog(readFileSync(join(ROOT, 'tests', 'data', 'csail.log')));
const dir = mkdtempSync(join(tmpdir(), 'rtl-bench-paired-'));
process.on('exit', () => rmSync(dir, { recursive: true, force: true }));
const path = join(dir, 'scans.mcap');
await writeLaserLog(path, laserScanPayloads(csail), N);

const OPTIONS = { minPoints: 3, vectorize: { method: 'ftls' } };
const cpuMs = () => { const u = process.cpuUsage(); return (u.user + u.system) / 1000; };

// The same scans read by both builds, and their results, checked equal once before timing.
const equalArrays = (a, b) => a.length === b.length && a.every((x, i) => Object.is(x, b[i]));
function sameResult(a, b) {
  if (a.clusters.length !== b.clusters.length) return false;
  for (let k = 0; k < a.clusters.length; k++)
    if (!equalArrays(a.clusters[k].indices, b.clusters[k].indices) || !equalArrays(a.clusters[k].ranges, b.clusters[k].ranges)) return false;
  for (const key of Object.keys(a)) {
    if (key === 'clusters') continue;
    const x = a[key], y = b[key];
    if (ArrayBuffer.isView(x) ? !equalArrays(x, y) : JSON.stringify(x) !== JSON.stringify(y)) return false;
  }
  return Object.keys(a).join() === Object.keys(b).join();
}
const scansOf = async (b) => {
  const log = await b.openLog(path), out = [];
  for await (const s of log.scans('/scan')) out.push(s);
  await log.close();
  return out;
};
const inMemory = {};
{
  const [sa, sb] = [await scansOf(builds.before), await scansOf(builds.after)];
  for (let i = 0; i < N; i++) {
    if (!equalArrays(sa[i].points, sb[i].points) || !equalArrays(sa[i].angles, sb[i].angles) || sa[i].time !== sb[i].time)
      throw new Error(`scan ${i} reads differently`);
    if (!sameResult(builds.before.rtl.segmentAndVectorize(sa[i].points, OPTIONS), builds.after.rtl.segmentAndVectorize(sb[i].points, OPTIONS)))
      throw new Error(`scan ${i}: segmentAndVectorize results differ`);
  }
  inMemory.before = sa.map((s) => s.points);
  inMemory.after = sb.map((s) => s.points);
}

// Each part runs on both builds in slices of SLICE scans, alternating (before, after, after, before, ...), each
// slice timed on its own: both see the same load, to within a few milliseconds.
const SLICE = 100;
async function paired(part) {
  const state = {};
  for (const name of ['before', 'after']) state[name] = { ms: 0, check: 0, ...(await part.start(builds[name], name)) };
  for (let at = 0, k = 0; at < N; at += SLICE, k++) {
    for (const name of k % 2 === 0 ? ['before', 'after'] : ['after', 'before']) {
      const st = state[name], t = cpuMs();
      st.check += await part.slice(builds[name], st, at, Math.min(N, at + SLICE));
      st.ms += cpuMs() - t;
    }
  }
  for (const name of ['before', 'after']) await state[name].end?.();
  if (state.before.check !== state.after.check) throw new Error(`${part.name}: ${state.before.check} != ${state.after.check}`);
  return { before: state.before.ms, after: state.after.ms };
}
// A log's scans through an async iterator, SLICE at a time; f(scan) per scan.
const logPart = (name, f) => ({
  name,
  async start(b) {
    const log = await b.openLog(path);
    return { it: log.scans('/scan')[Symbol.asyncIterator](), end: () => log.close() };
  },
  async slice(b, st, from, to) {
    let n = 0;
    for (let i = from; i < to; i++) n += f(b, (await st.it.next()).value);
    return n;
  },
});
const parts = [
  logPart('read', (b, s) => s.points.length),
  { name: 'compute', start: (b, name) => ({ points: inMemory[name] }),
    slice(b, st, from, to) {
      let n = 0;
      for (let i = from; i < to; i++) n += b.rtl.segmentAndVectorize(st.points[i], OPTIONS).vectorized.length;
      return n;
    } },
  logPart('batched', (b, s) => b.rtl.segmentAndVectorize(s.points, OPTIONS).vectorized.length),
];

const times = {};
for (let r = 0; r < ROUNDS; r++) {
  for (const part of parts) {
    const t = await paired(part);
    for (const name of ['before', 'after']) ((times[part.name] ??= {})[name] ??= []).push(t[name]);
  }
}
const median = (a) => [...a].sort((x, y) => x - y)[Math.floor(a.length / 2)];
console.log(`# b_logs_paired: Node ${process.version}, ${N} scans (360 beams), ${ROUNDS} rounds interleaved, CPU time; results equal`);
console.log('part      before us/scan  after us/scan  after/before  before scans/s  after scans/s');
for (const [part, t] of Object.entries(times)) {
  const b = median(t.before) / N * 1000, a = median(t.after) / N * 1000;
  console.log(`${part.padEnd(10)}${b.toFixed(1).padStart(14)}${a.toFixed(1).padStart(15)}${(a / b).toFixed(3).padStart(14)}` +
              `${String(Math.round(1e6 / b)).padStart(16)}${String(Math.round(1e6 / a)).padStart(15)}`);
}
