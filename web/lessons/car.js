// CAR segmentation (cyclic, adaptive, retroactive), step by step from the package's trace (segment(…, { trace:
// true }); events of rtl/seg/SegTrace.h: scan, gap, threshold, compare, link, merge, start, seam, cluster): the
// threshold circle around the current point, each comparison in its window, links, retroactive merges, the seam.
import { INK, Scene } from '../figure.js';
import { fromSource, readParams, traced, explainNoSteps } from './common.js';
import { checkBounds, drawClusters, segFields } from './seg-common.js';
import { m, note } from './ui.js';
import { compareQuestions } from './predict-questions.js';

// decisive: the comparison the note is about (the overview links to it)
export const EXCERPT = { dataset: 'intel', scan: 8, focusBeams: [26, 52], startAt: 36, decisive: { i: 39, j: 38 },
  why: 'The whole scan is segmented (the threshold depends on the beam count); the view shows a wall that, at step 2, breaks between beams 38 and 39: they are 0.132 m apart and the threshold there is the lower bound, 0.100 m. At step 3 the threshold grows with the step (0.135 m) and each point also looks two points back, so the wall stays one cluster (6 clusters of 3+ points become 4).' };

// Labels after events 0..k: start{i} labels i as i, link{i, cluster} gives i j's label, merge{from, into}
// relabels (the SegTrace.h replay).
function replay(trace, n, k) {
  const labels = new Int32Array(n).fill(-1);
  const clusters = [];
  for (let e = 0; e <= k && e < trace.length; e++) {
    const t = trace[e];
    if (t.kind === 'start') labels[t.i] = t.i;
    else if (t.kind === 'link') labels[t.i] = t.cluster;
    else if (t.kind === 'merge') { for (let i = 0; i < n; i++) if (labels[i] === t.from) labels[i] = t.into; }
    else if (t.kind === 'cluster') clusters.push(t);
  }
  return { labels, clusters };
}

// Partition of points as "smallest index of my cluster" (comparable between the replay and the untraced result).
export function canonical(labelsByCluster, n) {
  const out = new Array(n).fill(-1);
  for (const indices of labelsByCluster) { const min = Math.min(...indices); for (const i of indices) out[i] = min; }
  return out;
}

export default {
  id: 'car',
  menu: 'CAR',
  title: 'CAR segmentation',
  summary: 'Cut a scan into clusters: each point is compared with up to step − 1 previous points, with a threshold that grows with range.',
  async create(host) {
    const ex = fromSource(host, EXCERPT);
    const scan = await host.data.scan(ex.dataset, ex.scan);
    const points = scan.points, n = points.length / 2;
    note(host.controls, `<strong>Excerpt:</strong> ${host.data.describe(ex.dataset, ex.scan)} (${n} beams). ${ex.why}`);
    const fields = segFields(host, { step: 2, stepLabel: 'step s (compares up to s − 1 previous points)' });
    host.figure.fitPoints(ex.focusBeams ? host.data.beams(points, ...ex.focusBeams) : points);
    let missing = null, trace = [], untraced = null, params = null;
    const first = new Map();   // point -> first event about it (clicking a point jumps there)
    host.figure.onPick = (x, y) => {
      let best = -1, bd = (12 / host.figure.scale) ** 2;
      for (let i = 0; i < n; i++) { const d = (points[2 * i] - x) ** 2 + (points[2 * i + 1] - y) ** 2; if (d < bd) { bd = d; best = i; } }
      if (best >= 0 && first.has(best)) host.goTo?.(first.get(best));
    };
    return {
      predict: compareQuestions({ get trace() { return trace; } }, points),
      recompute() {
        params = readParams(fields, (v) => checkBounds(v));
        if (!params) { trace = []; missing = null; untraced = null; return { steps: 0 }; }
        const opts = { step: params.step, lowerBound: params.lowerBound, upperBound: params.upperBound };
        untraced = host.rtl.segment(points, opts);
        ({ trace, missing } = traced(() => host.rtl.segment(points, { ...opts, trace: true }), 'CAR segmentation'));
        first.clear();
        trace.forEach((e, k) => { if (e.i !== undefined && !first.has(e.i)) first.set(e.i, k); });
        return { steps: trace.length, start: first.get(ex.startAt) ?? 0 };
      },
      show(k) {
        this.step = k;
        const s = new Scene(`CAR segmentation, step ${params?.step ?? '–'}, bounds ${params?.lowerBound ?? '–'}–${params?.upperBound ?? '–'} m: ${host.data.describe(ex.dataset, ex.scan)}`);
        if (k < 0) { if (untraced) drawClusters(s, points, Array.from(untraced.labels)); else s.points(points, { label: -1 }); host.figure.show(s); explainNoSteps(host, missing); return; }
        const e = trace[k], { labels, clusters } = replay(trace, n, k);
        drawClusters(s, points, labels);
        s.marker(0, 0, { colour: INK.muted, shape: 'x', size: 5 });
        const P = (i) => [points[2 * i], points[2 * i + 1]];
        const scanEv = trace.find((t) => t.kind === 'scan');
        const w = scanEv ? scanEv.window : params.step - 1;
        let html = '';
        // the current point's threshold (its latest threshold event)
        let thr = null;
        if (e.i !== undefined) for (let q = k; q >= 0; q--) if (trace[q].kind === 'threshold' && trace[q].i === e.i) { thr = trace[q]; break; }
        if (thr && ['threshold', 'compare', 'link', 'merge', 'start', 'seam'].includes(e.kind)) {
          s.circle(...P(thr.i), thr.threshold, { colour: INK.candidate, dash: true, q: 'threshold' });
          for (let d = 1; d <= w; d++) { const j = (thr.i - d + n) % n; if (Number.isFinite(points[2 * j])) s.marker(...P(j), { colour: INK.muted, size: 5 }); }
        }
        switch (e.kind) {
          case 'scan':
            html = `<p>${e.size} points, step ${e.step}: each point is compared with up to <b>${e.window}</b> previous point${e.window === 1 ? '' : 's'}${e.window === 0 ? ' (none: every point is its own cluster)' : ''}.</p>` +
              `<p class="why">Threshold of point i = clamp(${e.step}·2π/${e.size} · range, ${m(e.lowerBound, 2)}, ${m(e.upperBound, 2)}) = clamp(${e.scaling.toFixed(4)} · range, …): neighbouring beams fan out with range.</p>`;
            break;
          case 'gap': html = `<p>Beam <b>${e.i}</b> has no return (a gap): it joins no cluster and is never compared.</p>`; break;
          case 'threshold':
            html = `<p>Point <b data-q="current">${e.i}</b> at range ${m(e.range, 2)}: ${e.raw < e.threshold ? `scaling · range = ${m(e.raw)} is below the lower bound, so <span data-q="threshold">the threshold is ${m(e.threshold)}</span>` : e.raw > e.threshold ? `scaling · range = ${m(e.raw)} is above the upper bound, so <span data-q="threshold">the threshold is ${m(e.threshold)}</span>` : `<span data-q="threshold">threshold = scaling · range = ${m(e.threshold)}</span>`}.</p><p class="why">The dashed circle has that radius: an earlier point of the window (grey rings) inside it is close.</p>`;
            break;
          case 'compare': case 'seam':
            s.segments([...P(e.i), ...P(e.j)], { colour: e.linked ? INK.ok : INK.fail, width: 2.5, q: 'distance' });
            html = `<p>${e.kind === 'seam' ? 'Seam pass: point' : 'Point'} <b data-q="current">${e.i}</b> vs point ${e.j}${e.kind === 'seam' ? ' across the end of the scan' : ` (${e.i - e.j} back)`}: <span data-q="distance">distance ${m(e.distance)}</span> ${e.linked ? '≤' : '>'} <span data-q="threshold">threshold ${m(e.threshold)}</span>.</p>` +
              `<p class="why">${e.linked ? 'Close: they belong to the same cluster.' : 'Too far: no link from this comparison.'}</p>`;
            break;
          case 'link': html = `<p>Point <b>${e.i}</b> joins the cluster of point ${e.j} (label ${e.cluster}).</p>`; break;
          case 'start': html = `<p>Point <b>${e.i}</b> is close to no earlier point of its window: it starts a new cluster.</p>`; break;
          case 'merge':
            s.segments([...P(e.i), ...P(e.j)], { colour: INK.ok, width: 3 });
            html = `<p>Point <b>${e.i}</b> also links to point ${e.j} of another cluster: the clusters merge <i>retroactively</i> (label ${e.from} becomes ${e.into}).</p><p class="why">This is why a stray return between two wall points does not cut the wall, when step ≥ 3.</p>`;
            break;
          case 'cluster': html = `<p>Result: cluster ${e.index + 1} starts at point ${e.first} and has ${e.size} point${e.size === 1 ? '' : 's'}.</p>`; break;
          default: html = `<p>${e.kind}</p>`;
        }
        // the current point's ring on top of its comparison line, so that hovering it names the point
        if (thr && ['threshold', 'compare', 'link', 'merge', 'start', 'seam'].includes(e.kind)) s.marker(...P(thr.i), { colour: INK.current, q: 'current' });
        if (k === trace.length - 1) html += `<p><b>Done:</b> ${clusters.length} clusters, as the package's untraced segment() (${untraced.clusters.length}).</p>`;
        if (e.i !== undefined) host.figure.ensureVisible(points[2 * e.i], points[2 * e.i + 1]);
        host.figure.show(s);
        host.text.innerHTML = html + '<p class="legend">Figure: orange ring = current point, dashed circle = its threshold, grey rings = the earlier points of its window, green / red line = a comparison that links / does not; colours = clusters so far.</p>';
      },
      finalState() {
        const k = this.step ?? -1, { labels } = replay(trace, n, k);
        const groups = new Map();
        labels.forEach((l, i) => { if (l >= 0) { if (!groups.has(l)) groups.set(l, []); groups.get(l).push(i); } });
        return { method: 'car', points: Array.from(points), params, step: k, steps: trace.length,
          replayed: { partition: canonical([...groups.values()], n), clusters: groups.size },
          untraced: untraced && { partition: canonical(untraced.clusters.map((c) => Array.from(c.indices)), n), clusters: untraced.clusters.length } };
      },
      dispose() {},
    };
  },
};
