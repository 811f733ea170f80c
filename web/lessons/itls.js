// Incremental TLS, step by step from the package's trace (events `start`, `add`, `close`, `tail`, `tailRange`,
// `segment`): the run growing point by point, its RMS as a curve against σ, each close, the tail repair and the
// final trimmed segments.
import { INK, Scene } from '../figure.js';
import { loadExcerpt, pt, slice, vectorizerRun, explainNoSteps } from './common.js';
import { mm } from './ui.js';

const EXCERPT = {
  dataset: 'intel', scan: 17, segment: { step: 3, lowerBound: 0.1, upperBound: 0.5 }, clusterAt: 0,
  why: 'A room corner with a door frame: σ = 0.01 m gives 4 runs, 0.03 m 3, 0.08 m swallows the corner in 1.',
};
const TAIL = ['left out (no partition of the tail within σ)', 'appended to the last range', 'paired with the last range\'s last point',
  'taken by the previous range', 'given a point by the previous range', 'placed by re-partitioning the last ranges'];

// Ranges and segments after events 0..k (the replay of rtl/vect/SimplifyTrace.h).
function replay(trace, k) {
  let ranges = [];
  const segments = [];
  for (let i = 0; i <= k && i < trace.length; i++) {
    const e = trace[i];
    if (e.kind === 'close') ranges.push([e.first, e.end]);
    else if (e.kind === 'tail') ranges = ranges.slice(0, e.kept);
    else if (e.kind === 'tailRange') ranges.push([e.first, e.end]);
    else if (e.kind === 'segment') segments.push([e.first, e.end, e.x0, e.y0, e.x1, e.y1]);
  }
  return { ranges, segments };
}

export default {
  id: 'itls',
  menu: 'ITLS',
  title: 'Incremental TLS',
  summary: 'Add points one by one to a running line fit; close the run just before the point that lifts its RMS to σ.',
  async create(host) {
    const { chain, where } = await loadExcerpt(host, EXCERPT);
    const run = vectorizerRun(host, chain, { method: 'itls', key: 'sigma', what: 'incremental TLS',
      field: { label: 'σ: max RMS distance', value: 0.03, min: 0.005, max: 0.2, step: 0.005, unit: 'm' } });
    host.figure.fitPoints(chain);
    return {
      recompute: run.recompute,
      show(k) {
        const { params, untraced, trace, missing } = run;
        this.step = k;
        const s = new Scene(`Incremental TLS, σ = ${params?.sigma ?? '–'} m: ${where}`);
        if (k < 0) { s.points(chain, { label: -1 }); if (untraced) s.segments(untraced.segments, { colour: INK.segment, width: 2 }); host.figure.show(s); explainNoSteps(host, missing); return; }
        const e = trace[k], { ranges, segments } = replay(trace, k);
        const covered = new Uint8Array(chain.length / 2);
        ranges.forEach(([a, b], r) => { s.points(slice(chain, a, b), { label: r }); covered.fill(1, a, b); });
        for (let i = 0; i < covered.length; i++) if (!covered[i]) s.points(slice(chain, i, i + 1), { label: -1 });
        let html;
        if (e.kind === 'add') {
          // the run so far, its RMS history (this run's add events) as a curve against σ
          s.points(slice(chain, e.first, e.index + 1), { label: -1, colour: INK.candidate, radius: 3.5, q: 'run' });
          s.marker(...pt(chain, e.index), { colour: e.fits ? INK.ok : INK.fail, q: 'added' });
          const run = [];
          for (let i = k; i >= 0 && trace[i].kind === 'add' && trace[i].first === e.first; i--) run.unshift(trace[i]);
          s.setInset({ title: `RMS of the run from point ${e.first}`, xs: run.map((a) => a.count), ys: run.map((a) => a.rms), ok: run.map((a) => a.fits), hline: e.sigma, hlabel: 'σ', xlabel: 'points in the run', yformat: (y) => mm(y) });
          html = `<p>Point <b data-q="added">${e.index}</b> joins <span data-q="run">the run that starts at point ${e.first} (now ${e.count} points)</span>.</p>` +
            (!e.tested ? `<p class="why">One or two points always fit a line exactly, so nothing is tested yet.</p>`
              : e.fits ? `<p class="why"><span data-q="run">The run's TLS line has RMS ${mm(e.rms)}</span> &lt; σ = ${mm(e.sigma)}: the point stays.</p>`
                : `<p class="why">The RMS would rise to ${mm(e.rms)} ≥ σ = ${mm(e.sigma)}: <span data-q="added">the point</span> is taken out again and the run is closed before it.</p>`);
        } else if (e.kind === 'close') {
          s.points(slice(chain, e.first, e.end), { label: -1, colour: INK.ok, radius: 3.5, q: 'run' });
          if (!e.atEnd && e.end < chain.length / 2) s.marker(...pt(chain, e.end), { colour: INK.fail, q: 'next' });
          html = `<p><span data-q="run">Run <b>${e.first}–${e.end - 1}</b></span> is closed with RMS ${mm(e.rms)}.</p><p class="why">` +
            (e.atEnd ? 'The chain ended.' : `With <span data-q="next">point ${e.end}</span> its RMS would be ${mm(e.rmsWithNext)} ≥ σ = ${mm(e.sigma)}; point ${e.end} starts the next run.`) + '</p>';
        } else if (e.kind === 'tail') {
          s.marker(...pt(chain, e.index), { colour: INK.current, q: 'tail' });
          html = `<p>The last point <b data-q="tail">${e.index}</b> was left alone when the chain ended: it is ${TAIL[e.method] ?? `placed (method ${e.method})`}. The first ${e.kept} ranges stay.</p>`;
        } else if (e.kind === 'tailRange') {
          html = `<p>Repaired tail: range <b>${e.first}–${e.end - 1}</b>, RMS ${mm(e.rms)}.</p>`;
        } else if (e.kind === 'segment') {
          html = `<p><span data-q="segment">Segment ${e.range + 1}</span>: the fitted line of points ${e.first}–${e.end - 1}, trimmed at the projections of its first and last point.</p>`;
        } else {
          html = `<p>${e.count} points, σ = ${mm(e.sigma)}: the first run starts at point 0.</p>`;
        }
        s.segments(segments.flatMap((g) => g.slice(2)), { colour: INK.segment, width: 2.5 });
        if (e.kind === 'segment') s.segments([e.x0, e.y0, e.x1, e.y1], { colour: INK.current, width: 3, q: 'segment' });
        if (k === trace.length - 1) html += `<p><b>Done:</b> ${segments.length} segments, as the package's untraced result (${untraced.count}). Segments are trimmed fitted lines, so they need not touch.</p>`;
        host.figure.show(s);
        host.text.innerHTML = html + '<p class="legend">Figure: large blue points = the run being grown, green/red ring = the point just added fits / does not; colours = closed runs; inset = the RMS of the run against σ.</p>';
      },
      finalState() {
        const { params, untraced, trace } = run;
        const k = this.step ?? -1, r = replay(trace, k);
        return { method: 'itls', chain: Array.from(chain), params, step: k, steps: trace.length,
          replayed: { ranges: r.ranges.flat(), segments: r.segments.flatMap((g) => g.slice(2)) },
          untraced: { ranges: Array.from(untraced?.indices ?? []), segments: Array.from(untraced?.segments ?? []) } };
      },
      dispose() {},
    };
  },
};
