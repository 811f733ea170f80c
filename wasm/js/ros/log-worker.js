// rtl-wasm/log-worker: a whole log processed off the main thread (a module Web Worker in browsers, a worker_threads
// Worker in Node). It opens the log (rtl-wasm/logs), runs segment() and, if asked, vectorize() per cluster on every
// scan of a topic, and posts results in batches with progress. Protocol (every message a plain object):
//   in:  { type: 'open', source: File | Blob | path, topic?, start?, end?, segment?: SegmentOptions,
//          vectorize?: VectorizeOptions (per cluster of >= minPoints points, default 3), ring?: number, batch?: number }
//        { type: 'cancel' }   stops after the current scan
//   out: { type: 'topics', file, format, topics }                  once the log is open
//        { type: 'scans', scans: [{ index, time, stamp, frameId, points, labels, segments }] }   typed arrays transferred
//        { type: 'progress', done, total }                         after each batch (total null when unknown)
//        { type: 'done', done, cancelled }                         the last message of a run
//        { type: 'error', error: { name, code, message, file, topic, index }, done }   after the scans before it
// Browser:  const w = new Worker(new URL('rtl-wasm/log-worker', import.meta.url), { type: 'module' });
//           w.postMessage({ type: 'open', source: file, topic: '/scan', vectorize: { method: 'ftls' } });
import init from 'rtl-wasm';
import { openLog } from './logs.js';

const node = typeof self === 'undefined' || typeof self.postMessage !== 'function';
// inside try: a browser bundle leaves this Node-only import alone (esbuild does not resolve it there)
async function nodePort() {
  try {
    return (await import('node:worker_threads')).parentPort;
  } catch (e) {
    throw new Error(`log-worker: neither a Web Worker nor a Node worker_threads Worker: ${e.message}`);
  }
}
const port = node ? await nodePort() : self;
const post = (msg, transfer = []) => port.postMessage(msg, transfer);
const listen = (fn) => (node ? port.on('message', fn) : port.addEventListener('message', (e) => fn(e.data)));

let cancelled = false;
let busy = false;
const rtlReady = init();

function chooseTopic(log, topic) {
  if (topic !== undefined) return topic;
  const lasers = log.topics.filter((t) => /LaserScan$/.test(t.type));
  const pick = lasers.length ? lasers : log.topics.filter((t) => /PointCloud2$/.test(t.type));
  if (pick.length !== 1) throw new RangeError(`log-worker: ${log.file}: pass topic (scan topics: ${pick.map((t) => t.name).join(', ') || 'none'})`);
  return pick[0].name;
}

function processScan(rtl, scan, req) {
  let points = scan.points, dim = 2;
  if (scan.beams !== undefined) { points = scan.ring(req.ring ?? 0); dim = 3; }
  else if (scan.angles === undefined) dim = 3;
  const seg = rtl.segment(points, { dim, ...(req.segment ?? {}) });
  const out = { index: scan.index, time: scan.time, stamp: scan.stamp, frameId: scan.frameId, points, labels: seg.labels };
  if (req.vectorize) {
    const { minPoints = 3, ...opts } = req.vectorize;
    const parts = [];
    for (const c of seg.clusters) {
      if (c.indices.length < minPoints) continue;
      const xy = new Float64Array(c.indices.length * dim);
      c.indices.forEach((k, j) => { for (let d = 0; d < dim; d++) xy[j * dim + d] = points[k * dim + d]; });
      parts.push(rtl.vectorize(xy, { dim, ...opts }).segments);
    }
    const segments = new Float64Array(parts.reduce((n, p) => n + p.length, 0));
    let at = 0;
    for (const p of parts) { segments.set(p, at); at += p.length; }
    out.segments = segments;
  }
  return out;
}

async function run(req) {
  const rtl = await rtlReady;
  let done = 0, log;
  try {
    log = await openLog(req.source);
    post({ type: 'topics', file: log.file, format: log.format, topics: log.topics });
    const topic = chooseTopic(log, req.topic);
    const total = log.topics.find((t) => t.name === topic)?.count ?? null;
    const batchSize = req.batch ?? 64;
    let batch = [];
    const flush = () => {
      if (batch.length === 0) return;
      post({ type: 'scans', scans: batch }, batch.flatMap((s) => [s.points.buffer, s.labels.buffer, ...(s.segments ? [s.segments.buffer] : [])]));
      batch = [];
      post({ type: 'progress', done, total });
    };
    for await (const scan of log.scans(topic, { start: req.start, end: req.end })) {
      batch.push(processScan(rtl, scan, req));
      done++;
      if (batch.length >= batchSize) flush();
      if (cancelled) break;
    }
    flush();
    post({ type: 'done', done, cancelled });
  } catch (e) {
    post({ type: 'error', done, error: { name: e.name, code: e.code, message: e.message, file: e.file, topic: e.topic, index: e.index } });
  } finally {
    await log?.close();
  }
}

listen((msg) => {
  if (msg?.type === 'cancel') { cancelled = true; return; }
  if (msg?.type !== 'open') {
    post({ type: 'error', done: 0, error: { name: 'TypeError', message: `log-worker: unknown message ${JSON.stringify(msg?.type)} (open, cancel)` } });
    return;
  }
  if (busy) {
    post({ type: 'error', done: 0, error: { name: 'Error', message: 'log-worker: a log is already being processed (one at a time)' } });
    return;
  }
  busy = true;
  cancelled = false;
  run(msg).finally(() => { busy = false; });
});
