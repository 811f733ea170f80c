// The tracker behind the "Tracking clusters" lesson: every algorithm is a package call. Each scan is segmented
// (segment(), CAR) in the sensor frame and moved into the map by the log's pose (TfTree); a cluster's centroid is the
// mean of its map points (presentation). Scan by scan, every track's constant-velocity KalmanFilter predicts to the
// scan's time, assign() (Munkres) pairs tracks with clusters on the distance from the predicted position, and a
// paired track is corrected with its cluster's centroid. The run records one plain-data snapshot per step and
// disposes of every filter before it returns (a filter lives exactly as long as its track).
import { buildTree } from './tf-tree.js';

export const DEFAULTS = Object.freeze({
  dataset: 'intel', first: 2, count: 10, gate: 1, sigma: 0.1, accel: 0.01, misses: 1,
  segment: Object.freeze({ step: 3, lowerBound: 0.1, upperBound: 0.5 }), minPoints: 5, initialSpeedSigma: 0.5,
});

// Constant velocity, state [x, y, vx, vy]: x ← A x over dt seconds; Q is the discrete white-noise acceleration model
// with spectral density q (m²/s³), so the position uncertainty a prediction adds grows with dt³.
export function transition(dt) { return [1, 0, dt, 0, 0, 1, 0, dt, 0, 0, 1, 0, 0, 0, 0, 1]; }
export function processNoise(dt, q) {
  const a = (q * dt ** 3) / 3, b = (q * dt ** 2) / 2, c = q * dt;
  return [a, 0, b, 0, 0, a, 0, b, b, 0, c, 0, 0, b, 0, c];
}
export const MEASUREMENT = [1, 0, 0, 0, 0, 1, 0, 0];     // the centroid measures the position only

// The clusters of one scan with at least minPoints points: indices, size and map-frame centroid; and the scan's
// points in the map frame.
export function scanClusters(rtl, scan, { segment, minPoints }) {
  const tree = buildTree(rtl, scan, { x: 0, y: 0, angle: 0 });
  let map;
  try { map = tree.transformPoints('sensor', 'map', scan.points); } finally { tree.dispose(); }
  const clusters = [];
  for (const c of rtl.segment(scan.points, segment).clusters) {
    const indices = Array.from(c.indices);
    if (indices.length < minPoints) continue;
    let sx = 0, sy = 0, n = 0;
    for (const i of indices) if (Number.isFinite(map[2 * i])) { sx += map[2 * i]; sy += map[2 * i + 1]; n++; }
    if (n) clusters.push({ indices, size: n, centroid: [sx / n, sy / n] });
  }
  return { map, clusters };
}

// The association of one scan: distances from the predicted positions (rows: tracks) to the centroids (columns),
// the costs given to assign() (distances capped at the gate: a pair beyond it costs what leaving the track unpaired
// costs, so Munkres never prefers it, and such pairs are dropped), its result, and why each choice was made.
function associate(rtl, predicted, centroids, gate) {
  const rows = predicted.length, cols = centroids.length;
  const distances = new Float64Array(rows * cols), costs = new Float64Array(rows * cols);
  for (let i = 0; i < rows; i++) for (let j = 0; j < cols; j++) {
    const d = Math.hypot(predicted[i][0] - centroids[j][0], predicted[i][1] - centroids[j][1]);
    distances[i * cols + j] = d;
    costs[i * cols + j] = Math.min(d, gate);
  }
  let columns = new Int32Array(rows).fill(-1), total = 0;
  if (rows && cols) ({ columns, total } = rtl.assign(costs, { rows, cols }));
  const pairs = [];
  for (let i = 0; i < rows; i++) if (columns[i] >= 0 && distances[i * cols + columns[i]] <= gate) pairs.push([i, columns[i]]);
  const why = [];
  for (let i = 0; i < rows; i++) {
    let nearest = -1;
    for (let j = 0; j < cols; j++) if (nearest < 0 || distances[i * cols + j] < distances[i * cols + nearest]) nearest = j;
    const j = columns[i], paired = j >= 0 && distances[i * cols + j] <= gate;
    if (!paired) { why.push({ row: i, kind: 'unpaired', nearest, distance: nearest >= 0 ? distances[i * cols + nearest] : NaN }); continue; }
    if (j === nearest || distances[i * cols + nearest] === distances[i * cols + j]) {
      let rival = -1;     // another track that is nearer to this cluster
      for (let k = 0; k < rows; k++) if (k !== i && distances[k * cols + j] < distances[i * cols + j]) rival = k;
      why.push({ row: i, kind: rival < 0 ? 'mutual' : 'nearest', column: j, distance: distances[i * cols + j], rival });
      continue;
    }
    // its nearest cluster went to another track: the best assignment that gives it that cluster, from assign() on
    // the matrix without this row and that column, costs more than Munkres' optimum
    const sub = [];
    for (let k = 0; k < rows; k++) if (k !== i) for (let l = 0; l < cols; l++) if (l !== nearest) sub.push(costs[k * cols + l]);
    const rest = rows > 1 && cols > 1 ? rtl.assign(sub, { rows: rows - 1, cols: cols - 1 }).total : 0;
    why.push({ row: i, kind: 'global', column: j, distance: distances[i * cols + j], nearest,
      nearestDistance: distances[i * cols + nearest], alternative: costs[i * cols + nearest] + rest, total });
  }
  return { rows, cols, distances: Array.from(distances), costs: Array.from(costs), columns: Array.from(columns), total, pairs, why };
}

const positionSigma = (P) => Math.sqrt((P[0] + P[5]) / 2);
const trackView = (t, extra) => ({ id: t.id, state: t.state, P: t.P, sigma: positionSigma(t.P), misses: t.misses,
  trail: t.trail.slice(), born: t.born, ...extra });

// Runs the tracker over scans[first .. first + count - 1] with the lesson's parameters; returns { steps, tracks }:
// steps[k] the snapshot after step k (0: the first scan starts the tracks; then per scan: predict, associate,
// correct), tracks the log of every track (born/ended and each update: scan number, dt, centroid z or null when
// missed, prediction, estimate; for checks).
export function runTracker(rtl, scans, p) {
  const live = [], log = [], steps = [];
  let nextId = 1;
  const P0 = [p.sigma ** 2, 0, 0, 0, 0, p.sigma ** 2, 0, 0, 0, 0, p.initialSpeedSigma ** 2, 0, 0, 0, 0, p.initialSpeedSigma ** 2];
  const R = [p.sigma ** 2, 0, 0, p.sigma ** 2];
  const start = (c, s) => {
    const kf = new rtl.KalmanFilter({ stateDim: 4, measurementDim: 2 });
    const t = { id: nextId++, kf, misses: 0, born: p.first + s, trail: [c.centroid.slice()], state: [c.centroid[0], c.centroid[1], 0, 0], P: P0 };
    live.push(t);
    try {
      kf.setState(t.state); kf.setCovarianceMatrix(P0); kf.setMeasurementMatrix(MEASUREMENT); kf.setMeasurementNoiseCovariance(R);
    } catch (e) { kf.dispose(); live.pop(); throw e; }
    log.push({ id: t.id, born: p.first + s, ended: null, updates: [{ scan: p.first + s, dt: 0, z: c.centroid.slice(), state: t.state.slice() }] });
    c.track = t.id;
    return t;
  };
  const read = (t) => { t.state = Array.from(t.kf.state()); t.P = Array.from(t.kf.covariance()); };
  try {
    let prev = null;
    for (let s = 0; s < p.count; s++) {
      const scan = scans[p.first + s], here = scanClusters(rtl, scan, p);
      const clusters = here.clusters.map((c, j) => ({ index: j, size: c.size, centroid: c.centroid, indices: c.indices, track: null }));
      const base = { scan: p.first + s, position: s, time: scan.timestamp, pose: [scan.x, scan.y, scan.theta], map: here.map };
      if (s === 0) {
        for (const c of clusters) start(c, s);
        steps.push({ ...base, kind: 'start', dt: 0, clusters, tracks: live.map((t, j) => trackView(t, { status: 'new', cluster: j })), ended: [] });
        prev = scan;
        continue;
      }
      const dt = scan.timestamp - prev.timestamp;
      prev = scan;
      const before = new Map(live.map((t) => [t.id, { state: t.state, P: t.P }]));
      for (const t of live) {
        t.kf.setTransitionMatrix(transition(dt));
        t.kf.setProcessNoiseCovariance(processNoise(dt, p.accel));
        t.kf.predict();
        read(t);
      }
      const predicted = live.map((t) => [t.state[0], t.state[1]]);
      const assoc = associate(rtl, predicted, clusters.map((c) => c.centroid), p.gate);
      assoc.trackIds = live.map((t) => t.id);
      const views = (status) => live.map((t, i) => trackView(t, { status: status(t, i), predicted: predicted[i], previous: before.get(t.id) }));
      steps.push({ ...base, kind: 'predict', dt, clusters: clusters.map((c) => ({ ...c })), assoc, tracks: views(() => 'predicted'), ended: [] });
      const pairedOf = new Map(assoc.pairs.map(([i, j]) => [i, j]));
      const assocClusters = clusters.map((c) => ({ ...c, track: null }));
      for (const [i, j] of assoc.pairs) assocClusters[j].track = live[i].id;
      steps.push({ ...base, kind: 'associate', dt, clusters: assocClusters, assoc,
        tracks: views((t, i) => (pairedOf.has(i) ? 'paired' : 'unpaired')).map((v, i) => ({ ...v, measured: pairedOf.has(i) ? clusters[pairedOf.get(i)].centroid : null })), ended: [] });
      // correct the paired tracks, count the misses of the others, end the tracks missed too often, start new ones
      const ended = [], status = new Map(), measured = new Map();
      live.forEach((t, i) => {
        const entry = log.find((l) => l.id === t.id);
        if (pairedOf.has(i)) {
          const c = clusters[pairedOf.get(i)];
          t.kf.correct(c.centroid);
          read(t);
          t.misses = 0;
          c.track = t.id;
          status.set(t.id, 'corrected');
          measured.set(t.id, c.centroid);
          entry.updates.push({ scan: p.first + s, dt, z: c.centroid.slice(), predicted: predicted[i], state: t.state.slice() });
        } else {
          t.misses++;
          status.set(t.id, t.misses > p.misses ? 'ended' : 'coasting');
          entry.updates.push({ scan: p.first + s, dt, z: null, predicted: predicted[i], state: t.state.slice() });
        }
        t.trail.push([t.state[0], t.state[1]]);
      });
      const views2 = live.map((t, i) => trackView(t, { status: status.get(t.id), predicted: predicted[i], measured: measured.get(t.id) ?? null, cluster: pairedOf.get(i) ?? null }));
      for (let i = live.length - 1; i >= 0; i--) {
        const t = live[i];
        if (status.get(t.id) !== 'ended') continue;
        ended.push(t.id);
        log.find((l) => l.id === t.id).ended = p.first + s;
        t.kf.dispose();
        live.splice(i, 1);
      }
      for (const c of clusters) if (c.track === null) { start(c, s); views2.push(trackView(live[live.length - 1], { status: 'new', cluster: c.index })); }
      steps.push({ ...base, kind: 'correct', dt, clusters, assoc, tracks: views2, ended: ended.reverse() });
    }
  } finally {
    for (const t of live) t.kf.dispose();
    live.length = 0;
  }
  return { steps, tracks: log };
}
