// Lesson: tracking the clusters of consecutive scans. The tracker (tracking-run.js) runs once per parameter change,
// through the package only (segment, TfTree, assign, KalmanFilter); the player replays its snapshots: the first scan
// starts the tracks, then per scan the filters predict, Munkres associates, the filters correct.
import { INK, Scene } from '../figure.js';
import { readParams } from './common.js';
import { DEFAULTS, runTracker } from './tracking-run.js';
import { costTable, trackColour } from './tracking-table.js';
import { m, note, numberField } from './ui.js';

const PHASE = { start: 'tracks start', predict: 'predict', associate: 'associate', correct: 'correct' };
const xy = (p) => `(${p[0].toFixed(2)}, ${p[1].toFixed(2)})`;
const speed = (s) => Math.hypot(s[2], s[3]);

function checkParams(v, scanCount) {
  const out = {};
  const int = (x, lo, hi) => Number.isInteger(x) && x >= lo && x <= hi;
  if (!int(v.first, 0, scanCount - 2)) out.first = `must be a whole number from 0 to ${scanCount - 2}`;
  if (!int(v.count, 2, scanCount)) out.count = `must be a whole number from 2 to ${scanCount}`;
  else if (!out.first && v.first + v.count > scanCount) out.count = `first scan + scans must be ≤ ${scanCount} (the excerpt has ${scanCount} scans)`;
  for (const k of ['gate', 'sigma', 'accel']) if (!(Number.isFinite(v[k]) && v[k] > 0)) out[k] = 'must be a number above 0';
  if (!int(v.misses, 0, 5)) out.misses = 'must be a whole number from 0 to 5';
  return out;
}

// Why each pair was chosen (or not), from the association's own numbers.
function whyList(st, p) {
  const a = st.assoc, T = (i) => `T${a.trackIds[i]}`, C = (j) => `C${j + 1}`, items = [];
  for (const w of a.why) {
    if (w.kind === 'mutual') items.push(`<b>${T(w.row)} → ${C(w.column)}</b> (${m(w.distance, 2)}): each is the other's nearest.`);
    else if (w.kind === 'nearest') items.push(`<b>${T(w.row)} → ${C(w.column)}</b> (${m(w.distance, 2)}): its nearest cluster; ${T(w.rival)} is nearer to ${C(w.column)}, but giving it to ${T(w.rival)} would not lower the total.`);
    else if (w.kind === 'global') items.push(`<b>${T(w.row)} → ${C(w.column)}</b> (${m(w.distance, 2)}), not its nearest ${C(w.nearest)} (${m(w.nearestDistance, 2)}): with ${C(w.nearest)} the best for all tracks costs ${m(w.alternative, 2)}, more than Munkres' ${m(w.total, 2)}.`);
    else items.push(`<b>${T(w.row)}</b>: ${w.nearest < 0 ? 'no cluster in this scan' : `no cluster within the gate (nearest ${C(w.nearest)} at ${m(w.distance, 2)})`}: it coasts on its prediction.`);
  }
  const paired = new Set(a.pairs.map(([, j]) => j));
  st.clusters.forEach((c, j) => {
    if (paired.has(j)) return;
    let best = -1;
    for (let i = 0; i < a.rows; i++) if (best < 0 || a.distances[i * a.cols + j] < a.distances[best * a.cols + j]) best = i;
    const d = best < 0 ? NaN : a.distances[best * a.cols + j];
    items.push(`<b>${C(j)}</b> (${c.size} points): ${best < 0 ? 'no track to pair with' : d > p.gate ? `no track within the gate (nearest ${T(best)} at ${m(d, 2)})` : `${T(best)} is within the gate (${m(d, 2)}) but has a better pair`}: it starts a new track.`);
  });
  return `<ul>${items.map((t) => `<li>${t}</li>`).join('')}</ul>`;
}

// The step's explanation (for the panel) and its per-track list (beside the matrix).
function explain(st, p) {
  const n = st.clusters.length, at = `Scan ${st.scan} (t = ${st.time.toFixed(1)} s)`, ul = (items) => `<ul>${items.map((t) => `<li>${t}</li>`).join('')}</ul>`;
  if (st.kind === 'start') {
    return {
      text: `<p>${at}: CAR segmentation (step ${p.segment.step}, bounds ${p.segment.lowerBound}–${p.segment.upperBound} m) gives ${n} cluster${n === 1 ? '' : 's'} of ${p.minPoints}+ points, placed in the map by the log's pose. Each centroid starts a track with its own Kalman filter.</p>`,
      details: ul(st.tracks.map((t) => `<b>T${t.id}</b> starts at ${xy(t.state)}, velocity 0 ± ${p.initialSpeedSigma} m/s, σ ${m(p.sigma, 2)}`)),
    };
  }
  if (st.kind === 'predict') {
    return {
      text: `<p>${at}, Δt = ${st.dt.toFixed(1)} s later. Each filter <b>predicts</b> (constant velocity): x ← A x moves the position by v·Δt, P ← A P Aᵀ + Q grows its uncertainty (dashed circles: 1σ).</p><p class="why">The new scan has ${n} cluster${n === 1 ? '' : 's'} (crosses), not associated yet.</p>`,
      details: ul(st.tracks.map((t) => `<b>T${t.id}</b>: ${xy(t.previous.state)} → ${xy(t.predicted)}, σ ${m(Math.sqrt((t.previous.P[0] + t.previous.P[5]) / 2), 2)} → ${m(t.sigma, 2)}`)) +
        '<p class="why">estimate → prediction, position σ before → after</p>',
    };
  }
  if (st.kind === 'associate') {
    const a = st.assoc;
    return {
      text: `<p>${at}: <b>rtl.assign</b> (Munkres) pairs tracks with clusters at the least total distance (the ${a.rows} × ${a.cols} matrix below): ${a.pairs.length} pair${a.pairs.length === 1 ? '' : 's'}, total cost ${m(a.total, 2)}. Pairs beyond the gate (${m(p.gate, 2)}, dashed circles) stay unassigned.</p><p class="why">Why each choice: with the matrix.</p>`,
      details: whyList(st, p),
    };
  }
  const rows = st.tracks.map((t) => {
    if (t.status === 'corrected') {
      // how far along the way from its prediction to its centroid the estimate went (the gain, seen on the map)
      const way = Math.hypot(t.measured[0] - t.predicted[0], t.measured[1] - t.predicted[1]);
      const went = way > 0 ? Math.hypot(t.state[0] - t.predicted[0], t.state[1] - t.predicted[1]) / way : 1;
      return `<b>T${t.id}</b>: ${xy(t.predicted)} → ${xy(t.state)}, ${Math.round(went * 100)} % of the way to C${t.cluster + 1}; ${speed(t.state).toFixed(2)} m/s, σ ${m(t.sigma, 2)}`;
    }
    if (t.status === 'coasting') return `<b>T${t.id}</b>: missed (${t.misses} of ${p.misses} allowed), keeps its prediction`;
    if (t.status === 'ended') return `<b>T${t.id}</b> ends: missed ${t.misses} scan${t.misses === 1 ? '' : 's'} in a row (more than ${p.misses}); its filter is disposed`;
    return `<b>T${t.id}</b> starts at C${t.cluster + 1} ${xy(t.state)}`;
  });
  return {
    text: `<p>${at}: each paired filter <b>corrects</b> with its centroid, x ← x + K (z − H x): the estimate (dot) lands between the prediction (ring) and the centroid (cross), nearer to whichever is less uncertain.</p><p class="why">Beside the matrix: prediction → estimate, and how far the gain K moved it towards the centroid.</p>`,
    details: ul(rows),
  };
}

export default {
  id: 'tracking',
  menu: 'Tracking',
  title: 'Tracking clusters',
  summary: 'Follow the clusters of consecutive scans: Munkres pairs each track with a cluster, a Kalman filter smooths each track.',
  async create(host) {
    await host.rtl.load('extras');  // assign and KalmanFilter are in the package's extras module
    const p0 = DEFAULTS;
    const scans = await host.data.load(p0.dataset);
    note(host.controls, `<strong>Excerpt:</strong> ${host.data.DATASETS[p0.dataset].label}, scans 2–11 of ${scans.length}, in the map by the log's poses: the robot turns on the spot, fixed objects keep still. From scan 18 on it drives, and Munkres sometimes pairs a track with a cluster that is not its nearest.`);
    const field = (key, label, o) => numberField(host.controls, { key, label, onInput: host.onParamsChanged, ...o });
    const fields = {
      first: field('first', 'first scan', { value: p0.first, min: 0, max: scans.length - 2, step: 1, digits: 0 }),
      count: field('count', 'scans', { value: p0.count, min: 2, max: scans.length, step: 1, digits: 0 }),
      gate: field('gate', 'gate', { value: p0.gate, min: 0.1, max: 3, step: 0.05, unit: 'm', digits: 2 }),
      sigma: field('sigma', 'centroid σ', { value: p0.sigma, min: 0.01, max: 1, step: 0.01, unit: 'm', digits: 2 }),
      accel: field('accel', 'accel. noise q (m²/s³)', { kind: 'number', value: p0.accel, min: 0.001, max: 10, step: 0.005 }),
      misses: field('misses', 'misses before a track ends', { value: p0.misses, min: 0, max: 5, step: 1, digits: 0 }),
    };
    const table = costTable(host.stage);
    // an older build of the package (before assign and KalmanFilter) says so instead of failing
    const missing = typeof host.rtl.assign === 'function' && typeof host.rtl.KalmanFilter === 'function' ? null
      : 'This build of rtl-wasm has no assign() or KalmanFilter yet (a newer "npm run build" will): nothing to track.';
    let run = { steps: [], tracks: [] }, params = null, fitted = null, shown = -1;
    // clicking a track (its dot or ring) goes back to the step where it started
    const drawnAt = (st, t) => (st.kind === 'predict' || st.kind === 'associate' ? t.predicted : t.state);
    host.figure.onPick = (x, y) => {
      const st = run.steps[shown];
      if (!st) return;
      let best = null, bd = (14 / host.figure.scale) ** 2;
      for (const t of st.tracks) { const [px, py] = drawnAt(st, t), d = (px - x) ** 2 + (py - y) ** 2; if (d < bd) { bd = d; best = t; } }
      if (!best) return;
      const born = run.steps.findIndex((b) => b.tracks.some((t) => t.id === best.id));
      if (born >= 0) host.goTo?.(born);
    };
    return {
      recompute() {
        if (missing) return { steps: 0 };
        const v = readParams(fields, (x) => checkParams(x, scans.length));
        if (!v) { params = null; run = { steps: [], tracks: [] }; return { steps: 0 }; }
        params = { ...p0, ...v };
        run = runTracker(host.rtl, scans, params);
        const range = `${params.first}:${params.count}`;
        if (fitted !== range) {       // a new excerpt: fit the view to every centroid of the run
          fitted = range;
          host.figure.fitPoints(run.steps.flatMap((st) => st.clusters.flatMap((c) => c.centroid)));
        }
        const firstAssoc = run.steps.findIndex((st) => st.kind === 'associate');
        return { steps: run.steps.length, start: Math.max(0, firstAssoc) };
      },
      show(k) {
        this.step = shown = k;
        const st = run.steps[k];
        if (!st) {
          host.figure.show(new Scene('Tracking clusters'));
          host.text.innerHTML = `<p class="${missing ? 'why' : 'fail'}">${missing ?? 'Fix the marked parameter to see the steps.'}</p>`;
          table.show({ scan: '–', clusters: [], assoc: { rows: 0, cols: 0 } }, 0, false);
          table.details.innerHTML = '';
          return;
        }
        const s = new Scene(`Tracking, scan ${st.scan} (${PHASE[st.kind]}): ${host.data.DATASETS[params.dataset].label}, scans ${params.first}–${params.first + params.count - 1}, map frame`);
        const labelOf = new Int32Array(st.map.length / 2).fill(-1);
        const associated = st.kind !== 'predict';
        for (const c of st.clusters) if (associated && c.track !== null) for (const i of c.indices) labelOf[i] = c.track - 1;
        const groups = new Map();
        labelOf.forEach((l, i) => { if (!groups.has(l)) groups.set(l, []); groups.get(l).push(st.map[2 * i], st.map[2 * i + 1]); });
        for (const [l, pts] of groups) s.points(pts, { label: l, radius: l < 0 ? 1.6 : 2.6 });
        s.marker(st.pose[0], st.pose[1], { colour: INK.muted, shape: 'x', size: 5 });
        s.label(st.pose[0], st.pose[1], 'robot', { colour: INK.muted });
        for (const t of st.tracks) if (t.trail.length > 1) s.polyline(t.trail.flat(), { colour: trackColour(t.id), width: 1.5 });
        for (const c of st.clusters) {
          s.marker(c.centroid[0], c.centroid[1], { colour: INK.segment, shape: 'x', size: 5 });
          if (st.kind !== 'start') s.label(c.centroid[0], c.centroid[1], `C${c.index + 1}`, { colour: INK.segment, offset: [6, 16] });
        }
        for (const t of st.tracks) {
          const colour = trackColour(t.id);
          if (st.kind === 'predict') {
            s.segments([t.previous.state[0], t.previous.state[1], ...t.predicted], { colour, dash: true });
            s.circle(t.predicted[0], t.predicted[1], t.sigma, { colour, dash: true });
            s.marker(t.predicted[0], t.predicted[1], { colour, size: 6 });
          } else if (st.kind === 'associate') {
            s.circle(t.predicted[0], t.predicted[1], params.gate, { colour: INK.muted, dash: true });
            s.marker(t.predicted[0], t.predicted[1], { colour, size: 6 });
            if (t.measured) s.segments([...t.predicted, ...t.measured], { colour: INK.ok, width: 3 });
          } else {
            if (t.predicted && t.status !== 'new') s.marker(t.predicted[0], t.predicted[1], { colour, size: 6 });
            if (t.status !== 'ended') s.marker(t.state[0], t.state[1], { colour, shape: 'dot', size: 9 });
          }
          const at = drawnAt(st, t);
          s.label(at[0], at[1], `T${t.id}${t.status === 'ended' ? ' ends' : t.status === 'new' && st.kind !== 'start' ? ' new' : ''}`, { colour, bold: true });
        }
        host.figure.show(s);
        const { text, details } = explain(st, params);
        table.details.innerHTML = details;
        host.text.innerHTML = text +
          '<p class="legend">Figure (map frame): crosses = cluster centroids C1…, rings = predicted positions, dots = Kalman estimates, lines = each track\'s estimates so far; colours = tracks, grey = points in no track. Click a track to go to the step where it started.</p>';
        table.show(st, params.gate, st.kind === 'associate' || st.kind === 'correct');
      },
      finalState() {
        const k = this.step ?? -1, st = run.steps[k];
        return {
          method: 'tracking', params, step: k, steps: run.steps.length, kind: st?.kind ?? null, scan: st?.scan ?? null,
          tracks: st ? st.tracks.map(({ id, state, P, predicted, measured, status, sigma }) => ({ id, state, P, predicted, measured, status, sigma })) : [],
          association: st?.assoc ? (({ rows, cols, costs, distances, columns, total, trackIds, pairs, why }) => ({ rows, cols, costs, distances, columns, total, trackIds, pairs, why }))(st.assoc) : null,
          clusters: st ? st.clusters.map(({ index, size, centroid, track }) => ({ index, size, centroid, track })) : [],
          kinds: run.steps.map((x) => x.kind), log: run.tracks, heapInUse: host.rtl.heapInUse(),
        };
      },
      dispose() { run = { steps: [], tracks: [] }; },
    };
  },
};
