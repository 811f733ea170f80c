#!/usr/bin/env node
// Robot logs through the package in Node on one core (figures, not pass/fail):
//   node bench/js/b_logs.mjs [--scans=10000] [--big-mb=1024] [--rounds=3] [--clock=cpu|wall]
// 1. Throughput: MCAPs of N sensor_msgs/msg/LaserScan (360 beams: the first 360 of each CSAIL excerpt scan, cycled;
//    ROS 2 CDR written by @mcap/core's McapWriter, 1 MB chunks) at chunk compression none, lz4, zstd, at N/10 and N
//    scans, generated in a temp dir. Per round, in the same run and on the same file:
//      raw      @mcap/core's indexed reader alone (messages out, not decoded): the floor of any reading
//      read     openLog(...).scans(): raw + CDR decode + fromLaserScan
//      segment  read + segment()
//      pipeline read + segment() + vectorize(ftls) on each cluster of >= 3 points (the CLI's default pipeline)
//      batched  read + segmentAndVectorize(ftls, minPoints 3): the same work in one call into the module per scan
//               (what the CLI runs); its read share = read / batched, raw share = raw / batched
//    Scans/s of each, and the shares of the pipeline's time: reading (read / pipeline; raw / pipeline for the MCAP
//    reader alone) and segmenting ((segment - read) / pipeline); vectorizing is the rest. The cluster and segment totals are
//    checked equal across compressions and rounds (the same work). Medians over the rounds.
// 3. (after 2) Several logs: the CLI on --logs (default 2) MCAPs of --log-scans (default N) scans each (zstd), -m ftls,
//    --jobs 1 against --jobs K (K = the number of logs), wall time of the whole command (each worker's start, wasm
//    instantiation included), and the speed-up (ideal: min(K, idle cores)); also the commands' CPU time, and from it
//    the speed-up K idle cores would give at most. Outputs checked equal. --throughput=0 skips section 1.
// 2. Memory: a log of --big-mb MB (chunks uncompressed) read and processed by the batched pipeline; RSS sampled every 1000 scans after the
//    first 2000 (warm-up); growth = max - first sample. The file is deleted afterwards.
import { existsSync, mkdtempSync, readFileSync, rmSync, statSync, writeFileSync } from 'node:fs';
import { execFileSync } from 'node:child_process';
import { availableParallelism, loadavg } from 'node:os';
import { open } from 'node:fs/promises';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { fileURLToPath } from 'node:url';
import init from 'rtl-wasm';
import { openLog } from 'rtl-wasm/logs';
import { McapIndexedReader } from '@mcap/core';
import { loadDecompressHandlers } from '@mcap/support';
import { laserScanPayloads, writeLaserLog } from './laser_log.mjs';

const arg = (name, def) => Number(process.argv.find((a) => a.startsWith(`--${name}=`))?.split('=')[1] ?? def);
const N = arg('scans', 10000), BIG_MB = arg('big-mb', 1024), ROUNDS = arg('rounds', 3), LOGS = arg('logs', 2);
const THROUGHPUT = arg('throughput', 1), LOG_SCANS = arg('log-scans', N);
const DATA = fileURLToPath(new URL('../../tests/data/', import.meta.url));
const rtl = await init();
const csail = rtl.readCarmenLog(readFileSync(join(DATA, 'csail.log')));
const dir = mkdtempSync(join(tmpdir(), 'rtl-bench-logs-'));
process.on('exit', () => rmSync(dir, { recursive: true, force: true }));

// The CDR payloads of the 30 source scans (360 beams each), written once and repeated.
const payloads = laserScanPayloads(csail);
const writeLog = (path, count, compression) => writeLaserLog(path, payloads, count, compression);

async function raw(path) {
  const fh = await open(path, 'r');
  const { size } = await fh.stat();
  const reader = await McapIndexedReader.Initialize({
    readable: { size: async () => BigInt(size), read: async (o, n) => { const b = new Uint8Array(Number(n)); await fh.read(b, 0, Number(n), Number(o)); return b; } },
    decompressHandlers: await loadDecompressHandlers() });
  let n = 0;
  for await (const m of reader.readMessages({ topics: ['/scan'] })) n += m.data.byteLength > 0 ? 1 : 0;
  await fh.close();
  return { scans: n };
}

async function read(path) {
  const log = await openLog(path);
  let n = 0;
  for await (const s of log.scans('/scan')) n += s.points.length === 720 ? 1 : 0;
  await log.close();
  return { scans: n };
}

async function segmentOnly(path) {
  const log = await openLog(path);
  let n = 0;
  for await (const s of log.scans('/scan')) n += rtl.segment(s.points).labels.length === 360 ? 1 : 0;
  await log.close();
  return { scans: n };
}

function pipelineScan(points, totals) {
  const seg = rtl.segment(points);
  totals.clusters += seg.clusters.length;
  for (const c of seg.clusters) {
    const idx = c.indices;
    if (idx.length < 3) continue;
    const xy = new Float64Array(2 * idx.length);
    for (let j = 0; j < idx.length; j++) { xy[2 * j] = points[2 * idx[j]]; xy[2 * j + 1] = points[2 * idx[j] + 1]; }
    totals.segments += rtl.vectorize(xy, { method: 'ftls' }).count;
  }
}

// The same work in one call into the module per scan (segmentAndVectorize: segment + every cluster's FTLS).
const batchOptions = { minPoints: 3, vectorize: { method: 'ftls' } };
function batchedScan(points, totals) {
  const r = rtl.segmentAndVectorize(points, batchOptions);
  totals.clusters += r.clusters.length;
  totals.segments += r.segmentOffsets[r.vectorized.length];
}

async function pipeline(path, onScan, scan = pipelineScan) {
  const log = await openLog(path);
  const totals = { scans: 0, clusters: 0, segments: 0 };
  for await (const s of log.scans('/scan')) {
    scan(s.points, totals);
    totals.scans++;
    onScan?.(totals.scans);
  }
  await log.close();
  return totals;
}

// --clock=cpu (default): the process's CPU time (user + system, process.cpuUsage), i.e. the rate on one core of its
// own, which a machine shared with other jobs does not distort as much as the wall clock (a load average of 12-17 on
// 2 cores made the same wall-clock figure vary 3-8x between rounds). --clock=wall: elapsed time.
const CLOCK = process.argv.find((a) => a.startsWith('--clock='))?.split('=')[1] ?? 'cpu';
if (CLOCK !== 'cpu' && CLOCK !== 'wall') throw new Error(`--clock must be cpu or wall, got ${CLOCK}`);
const now = CLOCK === 'wall' ? () => performance.now() : () => { const u = process.cpuUsage(); return (u.user + u.system) / 1000; };
async function timed(f) {
  const t = now();
  const r = await f();
  return { ms: now() - t, ...r };
}
const median = (a) => [...a].sort((x, y) => x - y)[Math.floor(a.length / 2)];

console.log(`# b_logs: Node ${process.version}, one thread; LaserScan 360 beams; ${ROUNDS} rounds, medians; ${CLOCK} time`);
console.log('scans   compression  file MB  raw scans/s  read scans/s  segment scans/s  pipeline scans/s  read share  raw share  segment share  batched scans/s  batched read share  batched raw share  clusters  segments');
let reference;
for (const count of THROUGHPUT ? [Math.round(N / 10), N] : []) {
  for (const compression of ['none', 'lz4', 'zstd']) {
    const path = join(dir, `scans-${count}-${compression}.mcap`);
    await writeLog(path, count, compression);
    const rs = [], rd = [], sg = [], pl = [], bt = [];
    let totals;
    for (let r = 0; r < ROUNDS; r++) {
      const a = await timed(() => raw(path)), b = await timed(() => read(path)), d = await timed(() => segmentOnly(path));
      const c = await timed(() => pipeline(path));
      const e = await timed(() => pipeline(path, undefined, batchedScan));
      if (a.scans !== count || b.scans !== count || c.scans !== count || d.scans !== count || e.scans !== count) throw new Error(`scan counts ${a.scans}/${b.scans}/${d.scans}/${c.scans}/${e.scans} != ${count}`);
      if (totals && (totals.clusters !== c.clusters || totals.segments !== c.segments)) throw new Error('pipeline totals differ between rounds');
      if (e.clusters !== c.clusters || e.segments !== c.segments) throw new Error(`batched totals ${e.clusters}/${e.segments} differ from per-cluster ${c.clusters}/${c.segments}`);
      totals = c;
      rs.push(a.ms); rd.push(b.ms); sg.push(d.ms); pl.push(c.ms); bt.push(e.ms);
    }
    if (count === N) {
      if (reference && (reference.clusters !== totals.clusters || reference.segments !== totals.segments)) throw new Error('pipeline totals differ between compressions');
      reference = totals;
    }
    const perS = (ms) => Math.round(count / (ms / 1000));
    console.log(`${String(count).padEnd(8)}${compression.padEnd(13)}${(statSync(path).size / 1e6).toFixed(1).padStart(7)}  ${String(perS(median(rs))).padStart(11)}  ${String(perS(median(rd))).padStart(12)}  ${String(perS(median(sg))).padStart(15)}  ${String(perS(median(pl))).padStart(16)}  ${(median(rd) / median(pl) * 100).toFixed(0).padStart(9)} %  ${(median(rs) / median(pl) * 100).toFixed(0).padStart(7)} %  ${((median(sg) - median(rd)) / median(pl) * 100).toFixed(0).padStart(11)} %  ${String(perS(median(bt))).padStart(15)}  ${(median(rd) / median(bt) * 100).toFixed(0).padStart(16)} %  ${(median(rs) / median(bt) * 100).toFixed(0).padStart(15)} %  ${String(totals.clusters).padStart(8)}  ${String(totals.segments).padStart(8)}`);
    rmSync(path);
  }
}

// The C++ floor of the compute: pipeline_native (tests/tools/pipeline_native.cpp: the same pipeline_ops.h code,
// natively, CPU time) on the same 30 scans cycled N times; totals checked equal to the batched pipeline's. Built by
// `cmake --build build/native --target pipeline_native`; skipped (with a note) when absent.
if (THROUGHPUT && reference) {
  const tool = fileURLToPath(new URL('../../build/native/tools/pipeline_native', import.meta.url));
  if (!existsSync(tool)) {
    console.log(`# native: ${tool} not built (cmake --build build/native --target pipeline_native); skipped`);
  } else {
    const file = join(dir, 'scans.f64');
    const pts = new Float64Array(csail.length * 720);
    // the 30 scans exactly as the pipeline gets them from the MCAP (fromLaserScan of the float32 ranges)
    const mcap = join(dir, 'native.mcap');
    await writeLog(mcap, csail.length, 'none');
    const log = await openLog(mcap);
    let k = 0;
    for await (const sc of log.scans('/scan')) pts.set(sc.points, 720 * k++);
    await log.close();
    writeFileSync(file, pts);
    const times = [];
    let res;
    for (let r = 0; r < ROUNDS; r++) {
      res = JSON.parse(execFileSync(tool, [file, '360', '2', String(N)], { encoding: 'utf8' }));
      times.push(res.seconds);
    }
    if (res.clusters !== reference.clusters || res.segments !== reference.segments)
      throw new Error(`native totals ${res.clusters}/${res.segments} differ from the package's ${reference.clusters}/${reference.segments}`);
    console.log(`# native (g++ -O3, CPU time): segment + FTLS per cluster on ${N} scans: ${Math.round(N / median(times))} scans/s ` +
                `(${(median(times) / N * 1e6).toFixed(1)} us a scan), the same ${res.clusters} clusters and ${res.segments} segments`);
  }
}

if (BIG_MB > 0) {
  const per = payloads[0].byteLength + 40;   // payload + message record overhead, roughly
  const count = Math.round((BIG_MB * 1e6) / per);
  const path = join(dir, 'big.mcap');
  const tw = performance.now();
  await writeLog(path, count, 'none');
  const mb = statSync(path).size / 1e6;
  console.log(`# memory: ${count} scans, ${mb.toFixed(0)} MB MCAP (chunks uncompressed) written in ${((performance.now() - tw) / 1000).toFixed(0)} s`);
  let base, peak = 0;
  const quarters = [];   // RSS at each quarter of the log: a leak rises steadily, a heap settling does not
  const t = await timed(() => pipeline(path, (n) => {
    if (n % 1000 !== 0 || n < 2000) return;
    const rss = process.memoryUsage().rss;
    base ??= rss;
    peak = Math.max(peak, rss);
    if (quarters.length < 4 && n >= ((quarters.length + 1) * count) / 4 - 1000) quarters.push(rss);
  }, batchedScan));
  rmSync(path);
  console.log(`# memory: pipeline over the whole log at ${Math.round(count / (t.ms / 1000))} scans/s; RSS after warm-up ${(base / 1e6).toFixed(0)} MB, ` +
              `peak ${(peak / 1e6).toFixed(0)} MB, growth ${((peak - base) / 1e6).toFixed(1)} MB (goal < 50 MB); at each quarter of the log ` +
              `${quarters.map((q) => (q / 1e6).toFixed(0)).join(', ')} MB`);
}

if (LOGS > 1) {
  const files = [];
  for (let k = 0; k < LOGS; k++) {
    files.push(join(dir, `log-${k}.mcap`));
    await writeLog(files[k], LOG_SCANS, 'zstd');
  }
  const cli = fileURLToPath(new URL('../../bin/rtl.js', import.meta.url));
  // The CPU time of the finished children (Linux: /proc/self/stat's cutime + cstime, in clock ticks of 10 ms): the
  // CLI and its worker threads. On a shared machine the wall clock says little; the CPU time of --jobs K against
  // --jobs 1 says what running K at once costs (each worker's start-up, contention), hence the speed-up K idle cores
  // would give at most: K x cpu(1) / cpu(K), for K logs of equal size.
  const childCpuMs = () => {
    if (!existsSync('/proc/self/stat')) return NaN;
    const stat = readFileSync('/proc/self/stat', 'utf8'), f = stat.slice(stat.lastIndexOf(')') + 2).split(' ');
    return (Number(f[13]) + Number(f[14])) * 10;
  };
  const run = (jobs) => {
    const t = performance.now(), c = childCpuMs();
    execFileSync(process.execPath, [cli, ...files, '--topic', '/scan', '-m', 'ftls', '--jobs', String(jobs), '-o', join(dir, `out-${jobs}.jsonl`)]);
    return { wall: performance.now() - t, cpu: childCpuMs() - c };
  };
  const one = [], many = [];
  for (let r = 0; r < ROUNDS; r++) { one.push(run(1)); many.push(run(LOGS)); }
  const lines = (jobs) => readFileSync(join(dir, `out-${jobs}.jsonl`), 'utf8').split('\n').filter(Boolean).sort();
  const [out1, outK] = [lines(1), lines(LOGS)];
  if (out1.length !== LOGS * LOG_SCANS || out1.join('\n') !== outK.join('\n')) throw new Error(`--jobs outputs differ: ${out1.length} vs ${outK.length} lines`);
  const m = (a, k) => median(a.map((x) => x[k])) / 1000;
  console.log(`# --jobs: ${LOGS} logs x ${LOG_SCANS} scans, rtl -m ftls, outputs equal: wall --jobs 1 ${m(one, 'wall').toFixed(1)} s, --jobs ${LOGS} ` +
              `${m(many, 'wall').toFixed(1)} s, speed-up ${(m(one, 'wall') / m(many, 'wall')).toFixed(2)} (${availableParallelism()} cores on this machine, ` +
              `load average ${loadavg()[0].toFixed(1)}); CPU --jobs 1 ${m(one, 'cpu').toFixed(1)} s, --jobs ${LOGS} ${m(many, 'cpu').toFixed(1)} s: ` +
              `at most ${(LOGS * m(one, 'cpu') / m(many, 'cpu')).toFixed(2)} on ${LOGS} idle cores`);
}
