// IA segmentation (incremental, adaptive), step by step from the package's trace (StreamSegmenter({ trace: true }),
// takeTrace(); events of rtl/seg/SegTrace.h: add, threshold, compare, link, merge, open, slide, alive, close): the
// window sliding over the stream, the threshold circle, comparisons, merges, and clusters closing.
import { INK, Scene } from '../figure.js';
import { fromSource, nonNegative, readParams, traced, explainNoSteps } from './common.js';
import { checkBounds, segFields } from './seg-common.js';
import { m, note, numberField } from './ui.js';
import { compareQuestions } from './predict-questions.js';

const EXCERPT = { dataset: 'intel', scan: 8, focusBeams: [26, 52], startAt: 36,
  why: 'The CAR lesson\'s scan and wall, fed point by point as the sensor delivers it: no seam, and a cluster closes as soon as none of its points is left in the window.' };

// Window, alive map and closed list after events 0..k (the SegTrace.h IA replay).
function replay(trace, k) {
  const window = new Map(), alive = new Map(), closed = [], clusterOf = new Map();
  for (let e = 0; e <= k && e < trace.length; e++) {
    const t = trace[e];
    if (t.kind === 'add') window.set(t.i, null);
    else if (t.kind === 'open' || t.kind === 'link') { window.set(t.i, t.cluster); clusterOf.set(t.i, t.cluster); }
    else if (t.kind === 'merge') {
      for (const [i, c] of window) if (c === t.from) window.set(i, t.into);
      for (const [i, c] of clusterOf) if (c === t.from) clusterOf.set(i, t.into);
      const a = alive.get(t.into) ?? [], b = alive.get(t.from) ?? [];
      alive.set(t.into, [...a, ...b].sort((x, y) => x - y));
      alive.delete(t.from);
    } else if (t.kind === 'slide') window.delete(t.i);
    else if (t.kind === 'alive') { if (!alive.has(t.cluster)) alive.set(t.cluster, []); alive.get(t.cluster).push(t.i); }
    else if (t.kind === 'close') { closed.push({ id: t.cluster, indices: alive.get(t.cluster) ?? [] }); alive.delete(t.cluster); }
  }
  return { window, alive, closed, clusterOf };
}

export default {
  id: 'ia',
  menu: 'IA',
  title: 'IA segmentation (streaming)',
  summary: 'Segment a stream point by point: each new point is compared with the last s points; a cluster closes when no point of it is left in that window.',
  async create(host) {
    const ex = fromSource(host, EXCERPT);
    const scan = await host.data.scan(ex.dataset, ex.scan);
    const points = scan.points, n = points.length / 2;
    note(host.controls, `<strong>Excerpt:</strong> ${host.data.describe(ex.dataset, ex.scan)} (${n} beams, fed in beam order). ${ex.why}`);
    const fields = {
      ...segFields(host, { step: 3, stepLabel: 'step s (window of the last s points)' }),
      scaling: numberField(host.controls, { key: 'scaling', label: 'scaling (threshold = scaling · range)', kind: 'number', value: 0.05, min: 0, max: 1, step: 0.005, onInput: host.onParamsChanged }),
    };
    host.figure.fitPoints(ex.focusBeams ? host.data.beams(points, ...ex.focusBeams) : points);
    let missing = null, trace = [], untraced = [], params = null;
    const run = (opts, withTrace) => {
      const seg = new host.rtl.StreamSegmenter(withTrace ? { ...opts, trace: true } : opts);
      try {
        seg.addPoints(points);
        seg.flush();
        return withTrace ? { trace: seg.takeTrace?.(), clusters: seg.takeClosedClusters() } : seg.takeClosedClusters();
      } finally { seg.dispose(); }
    };
    return {
      predict: compareQuestions({ get trace() { return trace; } }, points),
      recompute() {
        params = readParams(fields, (v) => { const out = checkBounds(v); if (nonNegative(v.scaling)) out.scaling = nonNegative(v.scaling); return out; });
        if (!params) { trace = []; missing = null; untraced = []; return { steps: 0 }; }
        const opts = { dim: 2, step: params.step, lowerBound: params.lowerBound, upperBound: params.upperBound, scaling: params.scaling };
        untraced = run(opts, false);
        ({ trace, missing } = traced(() => run(opts, true), 'streaming (IA) segmentation'));
        const start = trace.findIndex((e) => e.i === ex.startAt);
        return { steps: trace.length, start: Math.max(0, start) };
      },
      show(k) {
        this.step = k;
        const s = new Scene(`IA segmentation, step ${params?.step ?? '–'}, scaling ${params?.scaling ?? '–'}: ${host.data.describe(ex.dataset, ex.scan)}`);
        const P = (i) => [points[2 * i], points[2 * i + 1]];
        if (k < 0) { s.points(points, { label: -1 }); host.figure.show(s); explainNoSteps(host, missing); return; }
        const e = trace[k], { window, alive, closed } = replay(trace, k);
        const seen = new Set();
        const group = (indices, label, opts = {}) => { s.points(indices.flatMap(P), { label, radius: 3, ...opts }); indices.forEach((i) => seen.add(i)); };
        closed.forEach((c, q) => group(c.indices, q));
        for (const [, idx] of alive) group(idx, -1, { colour: INK.candidate });
        const rest = [];
        for (let i = 0; i < n; i++) if (!seen.has(i) && !window.has(i)) rest.push(i);
        s.points(rest.flatMap(P), { label: -1, radius: 1.6 });
        for (const [i] of window) if (Number.isFinite(points[2 * i])) s.marker(...P(i), { colour: INK.muted, size: 5 });
        let html = '';
        const i = e.i;
        let thr = null;
        if (i !== undefined) for (let q = k; q >= 0; q--) if (trace[q].kind === 'threshold' && trace[q].i === i) { thr = trace[q]; break; }
        if (thr && ['threshold', 'compare', 'link', 'merge', 'open'].includes(e.kind)) {
          s.circle(...P(i), thr.threshold, { colour: INK.candidate, dash: true, q: 'threshold' });
        }
        switch (e.kind) {
          case 'add': html = `<p>Point <b>${e.i}</b> arrives and enters the window${e.gap ? ' — a gap (no return): it takes a window place but joins nothing' : ''}.</p>`; break;
          case 'threshold':
            html = `<p>The threshold of point <b data-q="current">${e.i}</b>: scaling · range = ${params.scaling} · ${m(e.range, 2)} = ${m(e.raw)}${e.raw !== e.threshold ? `, clamped to <span data-q="threshold">${m(e.threshold)}</span>` : ` = <span data-q="threshold">threshold ${m(e.threshold)}</span>`}.</p>`; break;
          case 'compare':
            s.segments([...P(e.i), ...P(e.j)], { colour: e.linked ? INK.ok : INK.fail, width: 2.5, q: 'distance' });
            html = `<p>Point <b data-q="current">${e.i}</b> vs window point ${e.j}: <span data-q="distance">distance ${m(e.distance)}</span> ${e.linked ? '≤' : '>'} <span data-q="threshold">threshold ${m(e.threshold)}</span> — ${e.linked ? 'close' : 'too far'}.</p>`; break;
          case 'link': html = `<p>Point <b>${e.i}</b> joins cluster #${e.cluster} (the cluster of point ${e.j}).</p>`; break;
          case 'open': html = `<p>Point <b>${e.i}</b> is close to no window point: it opens cluster #${e.cluster}.</p>`; break;
          case 'merge': html = `<p>Point <b>${e.i}</b> links two clusters: #${e.from} merges into #${e.into} (the older one survives).</p>`; break;
          case 'slide': html = `<p>The window is full: the oldest point <b>${e.i}</b> leaves it${e.gap ? ' (a gap)' : ''}.</p>`; break;
          case 'alive': html = `<p>Point <b>${e.i}</b> is now out of the window and stays in its cluster #${e.cluster} (blue: alive, the cluster can still grow).</p>`; break;
          case 'close': html = `<p>Cluster #${e.cluster} has no point left in the window: it <b>closes</b> with ${e.size} point${e.size === 1 ? '' : 's'}.</p><p class="why">A streaming segmenter can hand it on now, before the scan ends.</p>`; break;
          default: html = `<p>${e.kind}</p>`;
        }
        // the new point's ring on top of its comparison line, so that hovering it names the point
        if (thr && ['threshold', 'compare', 'link', 'merge', 'open'].includes(e.kind)) s.marker(...P(i), { colour: INK.current, q: 'current' });
        if (k === trace.length - 1) html += `<p><b>Done:</b> ${closed.length} closed clusters, as the untraced StreamSegmenter (${untraced.length}).</p>`;
        if (e.i !== undefined) host.figure.ensureVisible(points[2 * e.i], points[2 * e.i + 1]);
        host.figure.show(s);
        host.text.innerHTML = html + '<p class="legend">Figure: orange ring = the new point, dashed circle = its threshold, grey rings = the window, green / red line = a comparison that links / does not; blue = alive clusters, colours = closed clusters.</p>';
      },
      finalState() {
        const k = this.step ?? -1, { closed } = replay(trace, k);
        return { method: 'ia', points: Array.from(points), params, step: k, steps: trace.length,
          replayed: { clusters: closed.map((c) => c.indices.flatMap((i) => [points[2 * i], points[2 * i + 1]])) },
          untraced: { clusters: untraced.map((c) => Array.from(c)) } };
      },
      dispose() {},
    };
  },
};
