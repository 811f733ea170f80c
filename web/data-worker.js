// Whole-file processing off the page's thread, with the package only; posts progress as it goes. Nothing leaves
// the browser. One worker per opened file; every message names its kind:
//   { kind: 'carmen', bytes: ArrayBuffer, segment }  readCarmenLog, then segment every scan
//   { kind: 'pcd', bytes: ArrayBuffer, segment }     readPcd: an organised cloud's rings, or an unorganised cloud
//   { kind: 'log-open', file: File }                 openLog (rtl-wasm/logs: MCAP or ROS 1 bag) -> its topics
//   { kind: 'log-read', topic, segment }             every scan of a topic of the open log, segmented
// Out: { progress: 0..1 | null (total unknown), phase } …, then { done: true, scans, ... } (typed arrays
//      transferred) or { error: message, scans? (those read before the failure) }. A scan is
//      { points (x,y interleaved, NaN = no return), x, y, theta, returns, clusters, line?, time?, ring? }.
// A module worker does not see the page's import map: '/dist/index.js' is the path the map gives 'rtl-wasm'
// (web/index.html), and '/vendor/rtl-wasm-logs.js' is the package's 'rtl-wasm/logs' with its peers, bundled by
// web/serve.js (web/vendor-logs.js); it is loaded only when a log is opened.
import init from '/dist/index.js';

let ready = null;
let log = null;       // the open log of a 'log-open'

const post = (msg, transfer = []) => self.postMessage(msg, transfer);
const transferOf = (scans) => scans.map((s) => s.points.buffer);

// A 2D scan for the chooser: its points, returns and cluster count (segment, the chooser's settings).
function summarise(rtl, points, segment, extra) {
  let returns = 0;
  for (let i = 0; i < points.length; i += 2) if (Number.isFinite(points[i]) && Number.isFinite(points[i + 1])) returns++;
  const clusters = returns ? rtl.segment(points, segment).clusters.length : 0;
  return { points, x: 0, y: 0, theta: 0, returns, clusters, ...extra };
}

// x, y of x, y, z points (a cloud seen from above, as the 2D lessons take a ring of a 3D scan).
function fromAbove(xyz) {
  const out = new Float64Array(2 * Math.floor(xyz.length / 3));
  for (let i = 0, j = 0; j < out.length; i += 3, j += 2) { out[j] = xyz[i]; out[j + 1] = xyz[i + 1]; }
  return out;
}

// The ring of an organised cloud the 2D lessons see: the one with the most returns (the middle one on a tie).
function bestRing(cloud) {
  let best = Math.floor(cloud.beams / 2), most = -1;
  for (let b = 0; b < cloud.beams; b++) {
    const ring = cloud.ring(b);
    let n = 0;
    for (let i = 0; i < ring.length; i += 3) if (Number.isFinite(ring[i])) n++;
    if (n > most || (n === most && b === Math.floor(cloud.beams / 2))) { most = n; best = b; }
  }
  return best;
}

function readCarmen(rtl, data) {
  post({ progress: 0, phase: 'reading' });
  const read = rtl.readCarmenLog(data.bytes);
  const scans = [];
  for (let k = 0; k < read.length; k++) {
    const s = read[k];
    scans.push({ ...summarise(rtl, new Float64Array(s.points), data.segment), x: s.x, y: s.y, theta: s.theta, line: s.line });
    if (k % 5 === 4 || k === read.length - 1) post({ progress: (k + 1) / read.length, phase: 'segmenting' });
  }
  post({ done: true, scans, unit: 'scan' }, transferOf(scans));
}

function readPcd(rtl, data) {
  post({ progress: 0, phase: 'reading' });
  const cloud = rtl.readPcd(data.bytes);
  if (!cloud.organized) {
    const points = fromAbove(cloud.points);
    const scans = [summarise(rtl, points, data.segment)];
    post({ progress: 1, phase: 'segmenting' });
    post({ done: true, scans, unit: 'point set', organized: false, count: points.length / 2 }, transferOf(scans));
    return;
  }
  const scans = [];
  for (let b = 0; b < cloud.beams; b++) {
    scans.push(summarise(rtl, fromAbove(cloud.ring(b)), data.segment, { ring: b }));
    post({ progress: (b + 1) / cloud.beams, phase: 'segmenting rings' });
  }
  const xyz = new Float64Array(cloud.points), intensity = new Float32Array(cloud.intensity);
  post({ done: true, scans, unit: 'ring', organized: true, cloud: { beams: cloud.beams, columns: cloud.columns, points: xyz, intensity } },
       [...transferOf(scans), xyz.buffer, intensity.buffer]);
}

async function openLog(data) {
  let open;
  try {
    ({ openLog: open } = await import('/vendor/rtl-wasm-logs.js'));
  } catch (e) {
    throw new Error(`reading MCAP files and ROS bags needs the page served by web/serve.js, which bundles rtl-wasm/logs for the browser (${e.message})`);
  }
  await log?.close();
  log = await open(data.file, { name: data.file.name });
  post({ done: true, format: log.format, topics: log.topics });
}

// The scans of one topic: a LaserScan as it is, a PointCloud2 seen from above (an organised one: its ring with the
// most returns). The scans before a failure are delivered with the error.
async function readTopic(rtl, data) {
  const total = log.topics.find((t) => t.name === data.topic)?.count ?? null;
  const scans = [];
  post({ progress: total ? 0 : null, phase: 'reading' });
  try {
    for await (const s of log.scans(data.topic)) {
      let points, extra = { time: s.time };
      if (s.angles !== undefined) points = new Float64Array(s.points);
      else if (s.beams !== undefined) { const b = bestRing(s); points = fromAbove(s.ring(b)); extra.ring = b; }
      else points = fromAbove(s.points);
      scans.push(summarise(rtl, points, data.segment, extra));
      if (scans.length % 5 === 0) post({ progress: total ? Math.min(1, scans.length / total) : null, phase: 'segmenting', count: scans.length });
    }
  } catch (e) {
    post({ error: String(e?.message ?? e), scans, unit: 'scan' }, transferOf(scans));
    return;
  }
  post({ progress: 1, phase: 'segmenting', count: scans.length });
  post({ done: true, scans, unit: 'scan' }, transferOf(scans));
}

self.onmessage = async ({ data }) => {
  try {
    ready ??= init();
    const rtl = await ready;
    if (data.kind === 'carmen') readCarmen(rtl, data);
    else if (data.kind === 'pcd') readPcd(await rtl.load('extras'), data);  // readPcd: in the extras module
    else if (data.kind === 'log-open') await openLog(data);
    else if (data.kind === 'log-read') await readTopic(rtl, data);
    else throw new TypeError(`data-worker: unknown message kind ${data.kind}`);
  } catch (e) {
    post({ error: String(e?.message ?? e) });
  }
};
