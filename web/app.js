// The demo page's logic. It uses only the public API of the npm package "rtl-wasm" (resolved by the import map to
// /dist/index.js), the same entry a user without a bundler would load. Results are exposed on window.__rtl so the
// browser tests can check the numbers the page shows.
import init from 'rtl-wasm';

const DATASETS = {
  intel: { url: '/tests/data/intel.log', label: 'Intel Research Lab', unit: 'scan' },
  csail: { url: '/tests/data/csail.log', label: 'MIT CSAIL', unit: 'scan' },
  // 4 beams of an Ouster OS1 scan; each ring (one beam over 2048 columns) is shown from above (x, y) as a 360° scan.
  rellis: { url: '/tests/data/rellis3d-os1-4x2048.bin', label: 'RELLIS-3D Ouster OS1', unit: 'ring', beams: 4 },
};

const METHOD_TEXT = {
  ftls: 'FTLS grows each segment over prefix sums to the longest run whose TLS fit stays under σ, then checks that neighbouring lines meet within δ; the corners are the lines\' intersections.',
  aftls: 'AFTLS runs FTLS, then moves the breakpoints with an integer Nelder–Mead search to reduce the total squared error, before the same continuity check with δ.',
  itls: 'Incremental TLS adds points one at a time and closes the segment just before the point that would lift its RMS distance to σ. Segments are trimmed fitted lines, so they need not touch.',
  dp: 'Douglas–Peucker keeps the point farthest from the chord and recurses while that distance exceeds ε. Vertices are measured points, so noise stays in the corners.',
  rw: 'Reumann–Witkam slides a strip of half-width ε along the polyline and keeps the point where the polyline leaves it. One pass, very fast, but order- and noise-sensitive.',
};

// Okabe–Ito palette (colour-blind safe) plus a few darker companions; clusters cycle through it.
const PALETTE = ['#0072B2', '#E69F00', '#009E73', '#D55E00', '#CC79A7', '#56B4E9', '#8C6D1F', '#1B7837', '#762A83', '#332288'];
const SMALL_CLUSTER = '#9aa3af';
const GAP_COLOUR = '#c9ced6';

const $ = (id) => document.getElementById(id);
const fmt = (v, d = 3) => (Number.isFinite(v) ? v.toFixed(d) : '–');
// Browsers coarsen performance.now() (to 0.1 ms in Chromium without cross-origin isolation): do not print 0.00 ms.
const fmtMs = (t) => (!Number.isFinite(t) ? '–' : t < 0.1 ? '< 0.1 ms' : `${t.toFixed(1)} ms`);

const state = {
  rtl: null,
  scans: {},          // dataset -> parsed scans (from the package's CARMEN reader)
  dataset: 'intel',
  scanIndex: 0,
  fitCluster: null,   // index of the clicked cluster, or null for the beam window
  result: null,       // last computed result (also exposed as window.__rtl)
  revision: 0,
  view: null,         // world -> canvas transform of the last draw
  zoom: null,         // user's view extents (wheel/drag), or null for the automatic extent
  features: null,     // which package functions this build provides (the page grows with the package)
  wholeScan: false,   // set the beam window to the whole scan at the next update
};

window.__rtl = { ready: false, revision: 0, errors: [] };
window.addEventListener('error', (e) => window.__rtl.errors.push(String(e.message)));
window.addEventListener('unhandledrejection', (e) => window.__rtl.errors.push(String(e.reason)));

function setStatus(text, isError = false) {
  const el = $('status');
  el.textContent = text;
  el.classList.toggle('error', isError);
}

// ---- reading the form ---------------------------------------------------------------------------------------------

function numberInput(id, fallback) {
  const v = Number($(id).value);
  return Number.isFinite(v) ? v : fallback;
}

// A setting the user has to correct (shown next to the status, not treated as a page error).
class SettingsError extends Error {}

function readSettings() {
  for (const el of $('controls').querySelectorAll('[aria-invalid]')) el.removeAttribute('aria-invalid');
  const s = readSettingsValues();
  if (state.features?.segment && s.upperBound < s.lowerBound) {
    $('seg-upper').setAttribute('aria-invalid', 'true');
    throw new SettingsError(`the upper bound (${s.upperBound} m) is below the lower bound (${s.lowerBound} m)`);
  }
  return s;
}

function readSettingsValues() {
  return {
    segmenter: $('segmenter').value,
    scaling: Math.max(0, numberInput('seg-scaling', 0.05)),
    step: Math.max(1, Math.round(numberInput('seg-step', 3))),
    lowerBound: Math.max(0, numberInput('seg-lower', 0.1)),
    upperBound: Math.max(0, numberInput('seg-upper', 0.5)),
    minPoints: Math.max(1, Math.round(numberInput('seg-min', 3))),
    method: $('method').value,
    sigma: numberInput('sigma', 0.03),
    delta: numberInput('delta', 0.3),
    epsilon: numberInput('epsilon', 0.09),
    fitFrom: Math.round(numberInput('fit-from', 0)),
    fitTo: Math.round(numberInput('fit-to', 0)),
    show: {
      points: $('show-points').checked,
      clusters: $('show-clusters').checked,
      segments: $('show-segments').checked,
      fit: $('show-fit').checked,
      residuals: $('show-residuals').checked,
    },
  };
}

function syncOutputs() {
  $('scan-out').textContent = $('scan').value;
  const ring = DATASETS[$('dataset').value].unit === 'ring';
  $('scan-label').textContent = ring ? 'Ring' : 'Scan';
  // Poses exist only in the CARMEN logs: the map frame is offered for them.
  $('map-frame-row').hidden = ring || !state.features?.tfTree;
  if (ring) $('map-frame').checked = false;
  $('seg-step-out').textContent = $('seg-step').value;
  $('ia-params').hidden = $('segmenter').value !== 'ia';
  $('sigma-out').textContent = Number($('sigma').value).toFixed(3);
  $('delta-out').textContent = Number($('delta').value).toFixed(2);
  $('epsilon-out').textContent = Number($('epsilon').value).toFixed(3);
  const method = $('method').value;
  for (const el of document.querySelectorAll('.param')) el.hidden = !el.dataset.for.split(' ').includes(method);
  $('method-text').textContent = METHOD_TEXT[method];
}

// ---- computing ----------------------------------------------------------------------------------------------------

async function loadDataset(name) {
  if (state.scans[name]) return state.scans[name];
  const res = await fetch(DATASETS[name].url);
  if (!res.ok) throw new Error(`cannot load ${DATASETS[name].url}: HTTP ${res.status}`);
  if (DATASETS[name].beams) {
    // Organised LiDAR binary through the package's reader; ring b becomes a "scan" of x, y points (gaps stay NaN).
    const cloud = state.rtl.readOrganizedLidar(await res.arrayBuffer(), { beams: DATASETS[name].beams, layout: 'column-major' });
    state.scans[name] = Array.from({ length: cloud.beams }, (_, b) => {
      const ring = cloud.ring(b);
      const points = new Float64Array(2 * cloud.columns);
      for (let c = 0; c < cloud.columns; c++) { points[2 * c] = ring[3 * c]; points[2 * c + 1] = ring[3 * c + 1]; }
      return { points, x: 0, y: 0, theta: 0, ring: b, columns: cloud.columns };
    });
    return state.scans[name];
  }
  const text = await res.text();
  state.scans[name] = state.rtl.readCarmenLog(text);
  return state.scans[name];
}

// The streaming (IA) segmenter fed with the scan in beam order, then flushed. It hands clusters back as points, so
// they are mapped to beam indices by their exact coordinates (the package returns the doubles it was given).
function streamSegment(points, s) {
  const seg = new state.rtl.StreamSegmenter({ dim: 2, step: s.step, lowerBound: s.lowerBound, upperBound: s.upperBound, scaling: s.scaling });
  try {
    seg.addPoints(points);
    seg.flush();
    const where = new Map();
    for (let i = 0; i < points.length / 2; i++) {
      if (!Number.isFinite(points[2 * i]) || !Number.isFinite(points[2 * i + 1])) continue;
      const key = `${points[2 * i]},${points[2 * i + 1]}`;
      if (!where.has(key)) where.set(key, []);
      where.get(key).push(i);
    }
    const labels = new Int32Array(points.length / 2).fill(-1);
    const clusters = seg.takeClosedClusters().map((xy, k) => {
      const indices = [];
      for (let j = 0; j < xy.length; j += 2) {
        const i = where.get(`${xy[j]},${xy[j + 1]}`).shift();
        labels[i] = k;
        indices.push(i);
      }
      return { indices: Uint32Array.from(indices) };
    });
    return { labels, clusters };
  } finally {
    seg.dispose();
  }
}

// Interleaved x,y of the non-gap points, and the beam index of each.
function validPoints(points) {
  const n = points.length / 2;
  const xy = [];
  const beams = [];
  for (let i = 0; i < n; i++) {
    const x = points[2 * i], y = points[2 * i + 1];
    if (Number.isFinite(x) && Number.isFinite(y)) { xy.push(x, y); beams.push(i); }
  }
  return { xy: new Float64Array(xy), beams };
}

function gather(points, indices) {
  const out = new Float64Array(indices.length * 2);
  indices.forEach((k, j) => { out[2 * j] = points[2 * k]; out[2 * j + 1] = points[2 * k + 1]; });
  return out;
}

function compute() {
  const rtl = state.rtl;
  const scans = state.scans[state.dataset];
  const scan = scans[state.scanIndex];
  const s = readSettings();
  const points = scan.points;
  const beamCount = points.length / 2;

  const f = state.features;

  // Segmentation of the whole scan (gaps are marked by the segmenter).
  const t0 = performance.now();
  const seg = f.segment
    ? (s.segmenter === 'ia' && f.stream ? streamSegment(points, s)
      : rtl.segment(points, { dim: 2, step: s.step, lowerBound: s.lowerBound, upperBound: s.upperBound }))
    : null;
  const t1 = performance.now();
  const clusters = seg ? seg.clusters.map((c) => Array.from(c.indices)) : [];

  // Vectorization of each cluster big enough to be drawn as a cluster, by one method.
  const drawnClusters = clusters.map((idx, ci) => [idx, ci]).filter(([idx]) => idx.length >= Math.max(2, s.minPoints))
    .map(([idx, ci]) => ({ ci, idx, pts: gather(points, idx) }));
  const vectorizeAll = (method) => {
    const out = { method, segments: [], rmsSum: 0, rmsMax: 0, rmsCount: 0, vecPoints: 0, timeMs: 0, failed: [] };
    const t = performance.now();
    for (const { ci, idx, pts } of drawnClusters) {
      const v = rtl.vectorize(pts, { dim: 2, method, sigma: s.sigma, delta: s.delta, epsilon: s.epsilon });
      if (!v.ok) { out.failed.push(ci); continue; }   // the C++ vectorizer reported failure: no segments
      out.vecPoints += idx.length;
      for (let k = 0; k < v.count; k++) {
        const seg4 = v.segments.subarray(4 * k, 4 * k + 4);
        out.segments.push({ cluster: ci, x1: seg4[0], y1: seg4[1], x2: seg4[2], y2: seg4[3] });
        const r = v.rms[k];
        if (Number.isFinite(r)) { out.rmsSum += r; out.rmsMax = Math.max(out.rmsMax, r); out.rmsCount++; }
      }
    }
    out.timeMs = performance.now() - t;
    return out;
  };
  const t2 = performance.now();
  const chosen = f.vectorize ? vectorizeAll(s.method) : { segments: [], rmsSum: 0, rmsMax: 0, rmsCount: 0, vecPoints: 0, failed: [] };
  const t3 = performance.now();
  const { segments, rmsSum, rmsMax, rmsCount, vecPoints } = chosen;
  // The same clusters and parameters with every method, for the comparison table.
  const comparison = f.vectorize
    ? Object.keys(METHOD_TEXT).map((m) => (m === s.method ? chosen : vectorizeAll(m))).map((v) => ({
      method: v.method, segmentCount: v.segments.length, rmsMean: v.rmsCount ? v.rmsSum / v.rmsCount : NaN,
      rmsMax: v.rmsCount ? v.rmsMax : NaN, pointsPerSegment: v.segments.length ? v.vecPoints / v.segments.length : NaN,
      failed: v.failed.length, timeMs: v.timeMs,
    }))
    : null;

  // The TLS line: either the clicked cluster or the beam window [from, to].
  let fitIdx;
  let fitSource;
  if (state.fitCluster !== null && clusters[state.fitCluster]) {
    fitIdx = clusters[state.fitCluster];
    fitSource = `cluster ${state.fitCluster + 1}`;
  } else {
    state.fitCluster = null;
    const from = Math.min(Math.max(0, s.fitFrom), beamCount - 1);
    const to = Math.min(Math.max(from, s.fitTo), beamCount - 1);
    fitIdx = [];
    for (let i = from; i <= to; i++) if (Number.isFinite(points[2 * i]) && Number.isFinite(points[2 * i + 1])) fitIdx.push(i);
    fitSource = `beams ${from}–${to}`;
  }
  let fit = null;
  let fitError = null;
  if (fitIdx.length >= 2) {
    try {
      const line = rtl.fitLine(gather(points, fitIdx));
      fit = {
        normal: [line.normal[0], line.normal[1]], offset: line.offset, rms: line.rms, n: fitIdx.length,
        centroid: [line.centroid[0], line.centroid[1]],
      };
    } catch (e) {
      fitError = e.message;
    }
  } else {
    fitError = 'fewer than 2 valid points in the window';
  }

  const valid = validPoints(points);
  return {
    dataset: state.dataset,
    scanIndex: state.scanIndex,
    beams: beamCount,
    validCount: valid.beams.length,
    pose: { x: scan.x, y: scan.y, theta: scan.theta },
    points,
    labels: seg ? seg.labels : null,
    clusters,
    settings: s,
    fit,
    fitIdx,
    fitSource,
    fitError,
    segments,
    comparison,
    stats: {
      clusterCount: clusters.length,
      drawnClusters: clusters.filter((c) => c.length >= s.minPoints).length,
      largest: clusters.reduce((m, c) => Math.max(m, c.length), 0),
      gaps: beamCount - valid.beams.length,
      segTimeMs: t1 - t0,
      vecTimeMs: t3 - t2,
      segmentCount: segments.length,
      failedClusters: chosen.failed,
      vecPoints,
      rmsMean: rmsCount ? rmsSum / rmsCount : NaN,
      rmsMax: rmsCount ? rmsMax : NaN,
    },
  };
}

// ---- map frame (the package's transformation tree) -----------------------------------------------------------------

// One tree per log: root 'map', a frame 'scan k' per scan. insert() takes the transformation from the parent's
// coordinates to the child's, i.e. the inverse of the scan's pose (x, y, theta) in the map.
function treeFor(dataset) {
  state.trees ??= {};
  if (!state.trees[dataset]) {
    const tree = new state.rtl.TfTree('map', { dim: 2 });
    state.scans[dataset].forEach((s, k) => {
      const c = Math.cos(s.theta), sn = Math.sin(s.theta);
      tree.insert(`scan ${k}`, 'map', { angle: -s.theta, translation: [-(c * s.x + sn * s.y), sn * s.x - c * s.y] });
    });
    state.trees[dataset] = tree;
  }
  return state.trees[dataset];
}

// A copy of the result with everything drawn moved into the map frame by tree.transformPoints(scan -> map), plus the
// other scans of the log as background. The numbers shown (fit, clusters) stay those of the robot frame.
function inMapFrame(r) {
  const tree = treeFor(r.dataset);
  const frame = `scan ${r.scanIndex}`;
  const move = (pts) => tree.transformPoints(frame, 'map', pts);
  const scan = state.scans[r.dataset][r.scanIndex];
  const segs = move(r.segments.flatMap((g) => [g.x1, g.y1, g.x2, g.y2]));
  const out = {
    ...r,
    frame: 'map',
    points: move(r.points),
    segments: r.segments.map((g, k) => ({ ...g, x1: segs[4 * k], y1: segs[4 * k + 1], x2: segs[4 * k + 2], y2: segs[4 * k + 3] })),
    sensor: { x: scan.x, y: scan.y, theta: scan.theta },
    background: new Float64Array(state.scans[r.dataset].flatMap((s, k) => (k === r.scanIndex ? [] : Array.from(tree.transformPoints(`scan ${k}`, 'map', s.points))))),
  };
  if (r.fit) {
    // A line moves with its centroid and normal (rotate the normal: transform the normal's tip and the centroid).
    const [c0, c1, t0, t1] = move([r.fit.centroid[0], r.fit.centroid[1], r.fit.centroid[0] + r.fit.normal[0], r.fit.centroid[1] + r.fit.normal[1]]);
    const normal = [t0 - c0, t1 - c1];
    out.fit = { ...r.fit, centroid: [c0, c1], normal, offset: -(normal[0] * c0 + normal[1] * c1) };
  }
  return out;
}

// ---- drawing ------------------------------------------------------------------------------------------------------

function clusterColour(ci, size, s) {
  if (!s.show.clusters) return '#334155';
  if (size < s.minPoints) return SMALL_CLUSTER;
  return PALETTE[ci % PALETTE.length];
}

function fitCanvas(canvas) {
  const dpr = window.devicePixelRatio || 1;
  const w = Math.max(320, Math.round(canvas.clientWidth * dpr));
  const h = Math.round(w * 3 / 4);
  if (canvas.width !== w || canvas.height !== h) { canvas.width = w; canvas.height = h; }
  return dpr;
}

function autoExtent(points, cx = 0, cy = 0) {   // (cx, cy): the sensor
  const n = points.length / 2;
  const ranges = [];
  for (let i = 0; i < n; i++) {
    const x = points[2 * i], y = points[2 * i + 1];
    if (Number.isFinite(x) && Number.isFinite(y)) ranges.push(Math.hypot(x - cx, y - cy));
  }
  ranges.sort((a, b) => a - b);
  const limit = ranges.length ? 1.5 * ranges[Math.floor(0.9 * (ranges.length - 1))] : 1;
  let minX = cx, maxX = cx, minY = cy, maxY = cy;
  for (let i = 0; i < n; i++) {
    const x = points[2 * i], y = points[2 * i + 1];
    if (!Number.isFinite(x) || !Number.isFinite(y) || Math.hypot(x - cx, y - cy) > limit) continue;
    minX = Math.min(minX, x); maxX = Math.max(maxX, x); minY = Math.min(minY, y); maxY = Math.max(maxY, y);
  }
  const pad = 0.06 * Math.max(maxX - minX, maxY - minY, 1);
  return { minX: minX - pad, maxX: maxX + pad, minY: minY - pad, maxY: maxY + pad };
}

function draw(r) {
  const canvas = $('canvas');
  const dpr = fitCanvas(canvas);
  const ctx = canvas.getContext('2d');
  const W = canvas.width, H = canvas.height;
  ctx.setTransform(1, 0, 0, 1, 0, 0);
  ctx.fillStyle = '#fbfcfd';
  ctx.fillRect(0, 0, W, H);

  // View: by default the bulk of the scan (points up to 1.5x the 90th-percentile range, so a few far returns
  // through a door do not shrink the room to a corner) plus the sensor; the user can zoom (wheel) and pan (drag).
  const n = r.points.length / 2;
  const sensor = r.sensor ?? { x: 0, y: 0, theta: 0 };
  const view = state.zoom ?? autoExtent(r.points, sensor.x, sensor.y);
  let { minX, maxX, minY, maxY } = view;
  const scale = Math.min(W / (maxX - minX), H / (maxY - minY));
  const ox = (W - scale * (maxX - minX)) / 2, oy = (H - scale * (maxY - minY)) / 2;
  minX -= ox / scale; maxX += ox / scale; minY -= oy / scale; maxY += oy / scale;
  const X = (x) => (x - minX) * scale;
  const Y = (y) => H - (y - minY) * scale;
  state.view = { X, Y, scale, dpr, minX, maxX, minY, maxY, W, H };

  // Metre grid with labels every metre (every 5 m when zoomed out).
  // Grid spacing: the smallest 1-2-5 step that leaves at least 45 CSS pixels between lines.
  const stepM = [0.1, 0.2, 0.5, 1, 2, 5, 10, 20, 50, 100].find((m) => (m * scale) / dpr >= 45) ?? 100;
  ctx.lineWidth = 1;
  ctx.strokeStyle = '#e6e9ee';
  ctx.fillStyle = '#8a94a3';
  ctx.font = `${11 * dpr}px system-ui, sans-serif`;
  const label = (v) => `${Number(v.toFixed(1))} m`;
  for (let k = Math.ceil(minX / stepM); k * stepM <= maxX; k++) {   // integer counter: no accumulated rounding
    const gx = k * stepM;
    ctx.beginPath(); ctx.moveTo(X(gx), 0); ctx.lineTo(X(gx), H); ctx.stroke();
    ctx.fillText(label(gx), X(gx) + 3 * dpr, H - 4 * dpr);
  }
  for (let k = Math.ceil(minY / stepM); k * stepM <= maxY; k++) {
    const gy = k * stepM;
    ctx.beginPath(); ctx.moveTo(0, Y(gy)); ctx.lineTo(W, Y(gy)); ctx.stroke();
    ctx.fillText(label(gy), 3 * dpr, Y(gy) - 3 * dpr);
  }

  const s = r.settings;

  // Map frame: the other scans of the log, faint, where their poses put them.
  if (r.background) {
    ctx.fillStyle = 'rgba(90, 100, 117, 0.35)';
    const b = r.background, rad = 1.1 * dpr;
    for (let i = 0; i < b.length; i += 2) {
      if (Number.isFinite(b[i])) ctx.fillRect(X(b[i]) - rad, Y(b[i + 1]) - rad, 2 * rad, 2 * rad);
    }
  }

  // Beams of the fitted points, faint, to show which measurements the fit uses.
  if (s.show.fit && r.fit) {
    ctx.strokeStyle = 'rgba(31, 95, 191, 0.10)';
    ctx.lineWidth = 1 * dpr;
    ctx.beginPath();
    for (const k of r.fitIdx) { ctx.moveTo(X(sensor.x), Y(sensor.y)); ctx.lineTo(X(r.points[2 * k]), Y(r.points[2 * k + 1])); }
    ctx.stroke();
  }

  // Vectorized segments under the points: a wide translucent band in the cluster colour, then a dark core line.
  if (s.show.segments) {
    ctx.lineCap = 'round';
    for (const sg of r.segments) {
      ctx.strokeStyle = s.show.clusters ? PALETTE[sg.cluster % PALETTE.length] + '55' : 'rgba(28, 35, 48, 0.2)';
      ctx.lineWidth = 7 * dpr;
      ctx.beginPath(); ctx.moveTo(X(sg.x1), Y(sg.y1)); ctx.lineTo(X(sg.x2), Y(sg.y2)); ctx.stroke();
    }
  }

  // Points, coloured by cluster.
  if (s.show.points) {
    const sizeOf = r.clusters.map((c) => c.length);
    const rad = Math.max(1.8, Math.min(3.2, scale / (70 * dpr))) * dpr;
    for (let i = 0; i < n; i++) {
      const x = r.points[2 * i], y = r.points[2 * i + 1];
      if (!Number.isFinite(x) || !Number.isFinite(y)) continue;
      const ci = r.labels ? r.labels[i] : null;
      ctx.fillStyle = ci === null ? '#334155' : ci >= 0 ? clusterColour(ci, sizeOf[ci], s) : GAP_COLOUR;
      ctx.beginPath(); ctx.arc(X(x), Y(y), rad, 0, 2 * Math.PI); ctx.fill();
    }
  }

  if (s.show.segments) {
    ctx.strokeStyle = '#1c2330';
    ctx.lineWidth = 1.6 * dpr;
    ctx.beginPath();
    for (const sg of r.segments) { ctx.moveTo(X(sg.x1), Y(sg.y1)); ctx.lineTo(X(sg.x2), Y(sg.y2)); }
    ctx.stroke();
    ctx.fillStyle = '#1c2330';
    for (const sg of r.segments) {
      for (const [x, y] of [[sg.x1, sg.y1], [sg.x2, sg.y2]]) { ctx.beginPath(); ctx.arc(X(x), Y(y), 2.4 * dpr, 0, 2 * Math.PI); ctx.fill(); }
    }
  }

  // The TLS line: dashed across the view, solid between the projections of the fitted points.
  if (s.show.fit && r.fit) {
    const [nx, ny] = r.fit.normal; const c = r.fit.offset;
    const dx = -ny, dy = nx;                                   // direction
    const px = -c * nx, py = -c * ny;                          // foot of the origin on the line
    let tMin = Infinity, tMax = -Infinity;
    for (const k of r.fitIdx) {
      const t = (r.points[2 * k] - px) * dx + (r.points[2 * k + 1] - py) * dy;
      tMin = Math.min(tMin, t); tMax = Math.max(tMax, t);
    }
    const far = 2 * Math.hypot(maxX - minX, maxY - minY) + Math.hypot(px, py);
    ctx.strokeStyle = 'rgba(200, 30, 60, 0.55)'; ctx.lineWidth = 1.3 * dpr; ctx.setLineDash([6 * dpr, 5 * dpr]);
    ctx.beginPath(); ctx.moveTo(X(px - far * dx), Y(py - far * dy)); ctx.lineTo(X(px + far * dx), Y(py + far * dy)); ctx.stroke();
    ctx.setLineDash([]);
    ctx.strokeStyle = '#c81e3c'; ctx.lineWidth = 2.6 * dpr;
    ctx.beginPath(); ctx.moveTo(X(px + tMin * dx), Y(py + tMin * dy)); ctx.lineTo(X(px + tMax * dx), Y(py + tMax * dy)); ctx.stroke();
    // Orthogonal residuals: what TLS minimises (the sum of their squares), drawn from each point to its foot.
    if (s.show.residuals) {
      ctx.strokeStyle = 'rgba(200, 30, 60, 0.7)'; ctx.lineWidth = 1 * dpr;
      ctx.beginPath();
      for (const k of r.fitIdx) {
        const x = r.points[2 * k], y = r.points[2 * k + 1], d = nx * x + ny * y + c;
        ctx.moveTo(X(x), Y(y)); ctx.lineTo(X(x - d * nx), Y(y - d * ny));
      }
      ctx.stroke();
    }
    // The centroid, through which every TLS line passes.
    ctx.fillStyle = '#c81e3c';
    ctx.beginPath(); ctx.arc(X(r.fit.centroid[0]), Y(r.fit.centroid[1]), 4.5 * dpr, 0, 2 * Math.PI); ctx.fill();
  }

  // The sensor: a triangle pointing along the robot's heading (+x in the robot frame).
  const sz = 9 * dpr, hc = Math.cos(sensor.theta), hs = Math.sin(sensor.theta);
  const corner = (u, v) => [X(sensor.x) + (u * hc - v * hs) * sz, Y(sensor.y) - (u * hs + v * hc) * sz];
  ctx.fillStyle = '#1c2330';
  ctx.beginPath(); ctx.moveTo(...corner(1, 0)); ctx.lineTo(...corner(-0.6, -0.6)); ctx.lineTo(...corner(-0.6, 0.6)); ctx.closePath(); ctx.fill();

  $('frame-text').textContent = r.frame === 'map'
    ? `Map frame: ${DATASETS[r.dataset].unit} ${r.scanIndex} in colour and the other ${DATASETS[r.dataset].unit}s in grey, each placed by its pose through the package's transformation tree; the triangle is the robot, facing its heading.`
    : 'Robot frame: the sensor is the triangle at the origin, facing +x.';
  canvas.setAttribute('aria-label', `${DATASETS[r.dataset].label} ${DATASETS[r.dataset].unit} ${r.scanIndex}: ${r.validCount} points` +
    (r.labels ? ` in ${r.stats.clusterCount} clusters` : '') +
    (state.features.vectorize ? `, ${r.stats.segmentCount} line segments (${s.method.toUpperCase()})` : '') +
    (r.fit ? `, fitted line RMS ${fmt(r.fit.rms * 1000, 1)} mm` : ''));
}

// ---- numbers and exposure -----------------------------------------------------------------------------------------

function showNumbers(r) {
  const scan = state.scans[r.dataset][r.scanIndex];
  $('scan-info').textContent = scan.ring !== undefined
    ? `ring ${scan.ring}: ${scan.columns} columns (360°), ${r.validCount} returns, seen from above (x, y)`
    : `${r.beams} beams, ${r.validCount} returns, pose (${fmt(scan.x, 2)}, ${fmt(scan.y, 2)}) m, ` +
      `${fmt(scan.theta * 180 / Math.PI, 1)}° · log line ${scan.line ?? '–'}`;
  if (r.fit) {
    $('fit-n').textContent = `${r.fit.n} (${r.fitSource})`;
    $('fit-normal').textContent = `(${fmt(r.fit.normal[0], 4)}, ${fmt(r.fit.normal[1], 4)})`;
    $('fit-offset').textContent = `${fmt(r.fit.offset, 4)} m`;
    $('fit-rms').textContent = `${fmt(r.fit.rms * 1000, 1)} mm`;
    $('fit-centroid').textContent = `(${fmt(r.fit.centroid[0], 3)}, ${fmt(r.fit.centroid[1], 3)}) m`;
  } else {
    $('fit-n').textContent = r.fitError ?? '–';
    for (const id of ['fit-normal', 'fit-offset', 'fit-rms', 'fit-centroid']) $(id).textContent = '–';
  }
  $('seg-gaps').textContent = `${r.stats.gaps} beams`;
  if (state.features.segment) {
    $('seg-count').textContent = `${r.stats.clusterCount} (${r.stats.drawnClusters} with ≥ ${r.settings.minPoints} pts)`;
    $('seg-largest').textContent = `${r.stats.largest} points`;
    $('seg-time').textContent = fmtMs(r.stats.segTimeMs);
  }
  if (state.features.vectorize) {
    $('vec-count').textContent = String(r.stats.segmentCount);
    $('vec-failed').textContent = r.stats.failedClusters.length ? `${r.stats.failedClusters.length} (no segments)` : 'none';
    $('vec-ratio').textContent = r.stats.segmentCount ? fmt(r.stats.vecPoints / r.stats.segmentCount, 1) : '–';
    $('vec-rms').textContent = Number.isFinite(r.stats.rmsMean) ? `${fmt(r.stats.rmsMean * 1000, 1)} / ${fmt(r.stats.rmsMax * 1000, 1)} mm` : '–';
    $('vec-time').textContent = fmtMs(r.stats.vecTimeMs);
  }
  $('compare').hidden = !r.comparison;
  if (r.comparison) {
    $('compare-rows').replaceChildren(...r.comparison.map((c) => {
      const tr = document.createElement('tr');
      tr.dataset.method = c.method;
      tr.tabIndex = 0;
      if (c.method === r.settings.method) { tr.className = 'current'; tr.setAttribute('aria-current', 'true'); }
      const cells = [c.method.toUpperCase(), String(c.segmentCount), fmt(c.pointsPerSegment, 1),
        `${fmt(c.rmsMean * 1000, 1)} mm`, `${fmt(c.rmsMax * 1000, 1)} mm`, String(c.failed), fmtMs(c.timeMs)];
      for (const text of cells) { const td = document.createElement('td'); td.textContent = text; tr.append(td); }
      return tr;
    }));
  }
}

function expose(r, shown = r) {
  state.revision += 1;
  window.__rtl = {
    ready: true,
    revision: state.revision,
    inputError: null,
    errors: window.__rtl.errors,
    dataset: r.dataset,
    scanIndex: r.scanIndex,
    beams: r.beams,
    validCount: r.validCount,
    settings: { ...r.settings, show: { ...r.settings.show } },
    fit: r.fit && { ...r.fit, source: r.fitSource, indices: r.fitIdx.slice() },
    fitError: r.fitError,
    features: { ...state.features },
    version: state.rtl.version,
    segmentation: r.labels && {
      clusterCount: r.stats.clusterCount,
      drawnClusters: r.stats.drawnClusters,
      largest: r.stats.largest,
      clusterSizes: r.clusters.map((c) => c.length),
      labels: Array.from(r.labels),
      timeMs: r.stats.segTimeMs,
    },
    // What the figure shows: the frame, the sensor pose and the points in that frame.
    frame: shown.frame ?? 'robot',
    sensor: shown.sensor ?? { x: 0, y: 0, theta: 0 },
    shownPoints: Array.from(shown.points),
    backgroundPoints: shown.background ? shown.background.length / 2 : 0,
    // The world rectangle the figure shows now (zoom and pan change it without recomputing).
    viewExtent() {
      const v = state.view;
      return { minX: v.minX, maxX: v.maxX, minY: v.minY, maxY: v.maxY };
    },
    // Client (CSS pixel) coordinates of point i in the figure, for tests that click on the drawing.
    clientPoint(i) {
      const v = state.view, rect = $('canvas').getBoundingClientRect();
      return { x: rect.left + v.X(shown.points[2 * i]) * rect.width / v.W, y: rect.top + v.Y(shown.points[2 * i + 1]) * rect.height / v.H };
    },
    vectorization: state.features.vectorize ? {
      method: r.settings.method,
      segmentCount: r.stats.segmentCount,
      failedClusters: r.stats.failedClusters.slice(),
      segments: r.segments.map((s) => [s.x1, s.y1, s.x2, s.y2, s.cluster]),
      rmsMean: r.stats.rmsMean,
      rmsMax: r.stats.rmsMax,
      timeMs: r.stats.vecTimeMs,
      comparison: r.comparison.map(({ timeMs, ...c }) => c),
    } : null,
  };
}

let scheduled = false;
function update() {
  if (scheduled) return;
  scheduled = true;
  requestAnimationFrame(async () => {
    scheduled = false;
    try {
      syncOutputs();
      state.dataset = $('dataset').value;
      await loadDataset(state.dataset);
      const scans = state.scans[state.dataset];
      $('scan').max = String(scans.length - 1);
      state.scanIndex = Math.min(Number($('scan').value), scans.length - 1);
      // The beam window spans the whole scan after a data set change (the beam count can differ).
      const lastBeam = scans[state.scanIndex].points.length / 2 - 1;
      $('fit-from').max = $('fit-to').max = String(lastBeam);
      if (state.wholeScan) { $('fit-from').value = '0'; $('fit-to').value = String(lastBeam); state.wholeScan = false; }
      const r = compute();
      const shown = state.features.tfTree && $('map-frame').checked ? inMapFrame(r) : r;
      state.result = shown;
      draw(shown);
      showNumbers(r);
      expose(r, shown);
      const f = state.features;
      setStatus(`${DATASETS[r.dataset].label}, ${DATASETS[r.dataset].unit} ${r.scanIndex}: ` + (f.segment
        ? `${r.stats.clusterCount} clusters, ` + (f.vectorize ? `${r.stats.segmentCount} segments by ${r.settings.method.toUpperCase()} ` : '') +
          `in ${fmtMs(r.stats.segTimeMs + r.stats.vecTimeMs)}.`
        : `${r.validCount} returns` + (r.fit ? `, TLS line through ${r.fit.n} points, RMS ${fmt(r.fit.rms * 1000, 1)} mm.` : '.')));
    } catch (e) {
      // Bad settings (ours, or a RangeError from the package naming the option) are the user's to fix.
      if (e instanceof SettingsError || e instanceof RangeError) {
        setStatus(`Check the settings: ${e.message}.`, true);
        window.__rtl.inputError = e.message;
        return;
      }
      setStatus(`Error: ${e.message}`, true);
      window.__rtl.errors.push(String(e.message));
      console.error(e);
    }
  });
}

// ---- export -------------------------------------------------------------------------------------------------------

function drawing(r) {
  const s = r.settings;
  const segs = r.segments.flatMap((g) => [g.x1, g.y1, g.x2, g.y2]);
  // The fitted line, as drawn: between the projections of its first and last point.
  if (r.fit && s.show.fit) {
    const [nx, ny] = r.fit.normal, [cx, cy] = r.fit.centroid, dx = -ny, dy = nx;
    let tMin = Infinity, tMax = -Infinity;
    for (const k of r.fitIdx) {
      const t = (r.points[2 * k] - cx) * dx + (r.points[2 * k + 1] - cy) * dy;
      tMin = Math.min(tMin, t); tMax = Math.max(tMax, t);
    }
    segs.push(cx + tMin * dx, cy + tMin * dy, cx + tMax * dx, cy + tMax * dy);
  }
  const parts = [`${DATASETS[r.dataset].label} ${DATASETS[r.dataset].unit} ${r.scanIndex}`];
  if (r.labels) parts.push(`${r.clusters.filter((c) => c.length >= s.minPoints).length} clusters`);
  if (state.features.vectorize) parts.push(`${r.segments.length} segments (${s.method.toUpperCase()})`);
  if (r.fit && s.show.fit) parts.push(`TLS line through ${r.fit.n} points, RMS ${fmt(r.fit.rms * 1000, 1)} mm`);
  return {
    points: r.points,
    ...(r.labels && s.show.clusters ? { labels: r.labels } : {}),
    segments: new Float64Array(segs),
    title: parts.join(', '),
  };
}

function download(name, type, text) {
  const url = URL.createObjectURL(new Blob([text], { type }));
  const a = document.createElement('a');
  a.href = url; a.download = name;
  document.body.append(a); a.click(); a.remove();
  setTimeout(() => URL.revokeObjectURL(url), 1000);
}

// ---- wiring -------------------------------------------------------------------------------------------------------

// Current view extents in world metres (what autoExtent or the user's zoom chose, after aspect padding).
function currentExtent() {
  const v = state.view;
  return { minX: v.minX, maxX: v.maxX, minY: v.minY, maxY: v.maxY };
}

function zoomAt(fx, fy, factor) {          // fx, fy: fraction of the canvas (0..1) that stays put
  if (!state.view) return;
  const e = currentExtent();
  const wx = e.minX + fx * (e.maxX - e.minX), wy = e.maxY - fy * (e.maxY - e.minY);
  state.zoom = {
    minX: wx - (wx - e.minX) * factor, maxX: wx + (e.maxX - wx) * factor,
    minY: wy - (wy - e.minY) * factor, maxY: wy + (e.maxY - wy) * factor,
  };
  draw(state.result);
}

function panBy(dxPx, dyPx) {               // canvas pixels
  const v = state.view;
  if (!v) return;
  const dx = dxPx / v.scale, dy = dyPx / v.scale, e = currentExtent();
  state.zoom = { minX: e.minX - dx, maxX: e.maxX - dx, minY: e.minY + dy, maxY: e.maxY + dy };
  draw(state.result);
}

function resetView() {
  state.zoom = null;
  if (state.result) draw(state.result);
}

function wireCanvas(canvas) {
  canvas.addEventListener('wheel', (ev) => {
    ev.preventDefault();
    const rect = canvas.getBoundingClientRect();
    zoomAt((ev.clientX - rect.left) / rect.width, (ev.clientY - rect.top) / rect.height, Math.exp(ev.deltaY * 0.0015));
  }, { passive: false });
  let drag = null;
  canvas.addEventListener('pointerdown', (ev) => {
    drag = { x: ev.clientX, y: ev.clientY, moved: false };
    canvas.setPointerCapture(ev.pointerId);
  });
  canvas.addEventListener('pointermove', (ev) => {
    if (!drag) return;
    const rect = canvas.getBoundingClientRect(), k = state.view.W / rect.width;
    const dx = ev.clientX - drag.x, dy = ev.clientY - drag.y;
    if (!drag.moved && Math.hypot(dx, dy) < 4) return;
    drag.moved = true;
    panBy(dx * k, dy * k);
    drag.x = ev.clientX; drag.y = ev.clientY;
  });
  canvas.addEventListener('pointerup', (ev) => {
    const wasClick = drag && !drag.moved;
    drag = null;
    if (wasClick) onCanvasClick(ev);
  });
  canvas.addEventListener('dblclick', resetView);
  // Keyboard: + and - zoom, arrows pan, 0 resets the view.
  canvas.addEventListener('keydown', (ev) => {
    const step = 40 * (state.view?.dpr ?? 1);
    const actions = {
      '+': () => zoomAt(0.5, 0.5, 0.8), '=': () => zoomAt(0.5, 0.5, 0.8), '-': () => zoomAt(0.5, 0.5, 1.25),
      '0': resetView, ArrowLeft: () => panBy(step, 0), ArrowRight: () => panBy(-step, 0),
      ArrowUp: () => panBy(0, step), ArrowDown: () => panBy(0, -step),
    };
    if (actions[ev.key]) { ev.preventDefault(); actions[ev.key](); }
  });
}

function onCanvasClick(ev) {
  const r = state.result, v = state.view;
  if (!r || !v || !r.labels) return;
  const rect = ev.currentTarget.getBoundingClientRect();
  const cx = (ev.clientX - rect.left) * (v.W / rect.width), cy = (ev.clientY - rect.top) * (v.H / rect.height);
  let best = -1, bestD = (12 * v.dpr) ** 2;
  const n = r.points.length / 2;
  for (let i = 0; i < n; i++) {
    const x = r.points[2 * i], y = r.points[2 * i + 1];
    if (!Number.isFinite(x)) continue;
    const d = (v.X(x) - cx) ** 2 + (v.Y(y) - cy) ** 2;
    if (d < bestD && r.labels[i] >= 0) { bestD = d; best = i; }
  }
  if (best < 0) return;
  const ci = r.labels[best];
  state.fitCluster = ci;
  const idx = r.clusters[ci];
  $('fit-from').value = String(idx[0]);
  $('fit-to').value = String(idx[idx.length - 1]);
  update();
}

function resetFitWindow() {
  state.fitCluster = null;
  state.wholeScan = true;   // update() sets the window to the beams of the scan it shows
}

// The page follows the package: parts whose functions this build lacks are disabled and say so.
function applyFeatures() {
  const rtl = state.rtl;
  const has = (name) => typeof rtl[name] === 'function';
  state.features = {
    reader: has('readCarmenLog') || has('readCarmen'),
    fitLine: has('fitLine'),
    segment: has('segment'),
    vectorize: has('vectorize'),
    svg: has('toSvg'),
    tikz: has('toTikz'),
    tfTree: typeof rtl.TfTree === 'function',
    stream: typeof rtl.StreamSegmenter === 'function',
  };
  const f = state.features;
  const missing = (fieldset, what) => {
    fieldset.disabled = true;
    const note = document.createElement('p');
    note.className = 'hint missing';
    note.textContent = `${what} is not in this build of rtl-wasm (${rtl.version ?? 'unknown version'}).`;
    fieldset.append(note);
  };
  if (!f.segment) missing($('seg-step').closest('fieldset'), 'Segmentation');
  if (!f.vectorize) missing($('method').closest('fieldset'), 'Vectorization');
  $('dl-svg').disabled = !f.svg;
  $('dl-tikz').disabled = !f.tikz;
  $('show-clusters').disabled = !f.segment;
  $('show-segments').disabled = !f.vectorize;
  $('fit-tip').hidden = !f.segment;
  if (!f.stream) $('segmenter').closest('fieldset').querySelector('option[value=ia]').remove();
  $('map-frame-row').hidden = !f.tfTree;
  if (typeof rtl.readOrganizedLidar !== 'function') $('dataset').querySelector('option[value=rellis]').remove();
}

async function main() {
  syncOutputs();
  try {
    state.rtl = await init();
  } catch (e) {
    setStatus(`Could not load the WebAssembly module: ${e.message}. Run "npm run build" first.`, true);
    window.__rtl.errors.push(String(e.message));
    return;
  }
  applyFeatures();
  for (const el of $('controls').querySelectorAll('input, select')) {
    el.addEventListener('input', () => {
      // A clicked cluster is a cluster of this segmentation: new clusters or another scan forget it (the beam window
      // still holds its first and last beam).
      if (['fit-from', 'fit-to', 'segmenter', 'seg-step', 'seg-lower', 'seg-upper', 'seg-scaling', 'scan', 'dataset'].includes(el.id)) {
        state.fitCluster = null;
      }
      update();
    });
  }
  $('dataset').addEventListener('change', () => { $('scan').value = '0'; state.zoom = null; resetFitWindow(); update(); });
  $('fit-all').addEventListener('click', () => { resetFitWindow(); update(); });
  // A row of the comparison table selects its method (mouse or Enter/Space).
  const pickRow = (ev) => {
    const tr = ev.target.closest('tr[data-method]');
    if (!tr || tr.dataset.method === $('method').value) return;
    $('method').value = tr.dataset.method;
    update();
  };
  $('compare-rows').addEventListener('click', pickRow);
  $('compare-rows').addEventListener('keydown', (ev) => { if (ev.key === 'Enter' || ev.key === ' ') { ev.preventDefault(); pickRow(ev); } });
  $('map-frame').addEventListener('change', () => { state.zoom = null; });
  wireCanvas($('canvas'));
  $('reset-view').addEventListener('click', resetView);
  $('dl-svg').addEventListener('click', () => {
    const r = state.result; if (!r) return;
    download(`rtl-${r.dataset}-${r.scanIndex}.svg`, 'image/svg+xml', state.rtl.toSvg(drawing(r)));
  });
  $('dl-tikz').addEventListener('click', () => {
    const r = state.result; if (!r) return;
    download(`rtl-${r.dataset}-${r.scanIndex}.tex`, 'text/x-tex', state.rtl.toTikz(drawing(r)));
  });
  window.addEventListener('resize', () => { if (state.result) draw(state.result); });
  update();
}

main();
