// Douglas–Peucker, step by step from the package's trace (events `start`, `range`; wasm/js/index.d.ts): each range's
// chord, its farthest interior point and that point's distance against ε, and the vertices kept so far.
import { INK, Scene } from '../figure.js';
import { loadExcerpt, pt, vectorizerRun, explainNoSteps } from './common.js';
import { m } from './ui.js';
import { dpQuestions } from './predict-questions.js';

export const EXCERPT = {
  dataset: 'intel', scan: 17, segment: { step: 3, lowerBound: 0.1, upperBound: 0.5 }, clusterAt: 0,
  why: 'A room corner with a door frame: ε = 0.02 m keeps 8 segments, 0.05 m 5, 0.2 m only 2, so ε visibly decides which bends are corners.',
};

// kept vertices (sorted) after events 0..k, as the SimplifyTrace.h replay says: start keeps 0 and count-1, each
// range with split = true keeps its farthest point.
function keptAfter(trace, k) {
  const kept = new Set();
  for (let i = 0; i <= k && i < trace.length; i++) {
    const e = trace[i];
    if (e.kind === 'start') { kept.clear(); kept.add(0); kept.add(e.count - 1); }
    else if (e.kind === 'range' && e.split) kept.add(e.farthest);
  }
  return [...kept].sort((a, b) => a - b);
}

const polylineOf = (xy, keys) => keys.flatMap((i) => pt(xy, i));

export default {
  id: 'dp',
  menu: 'DP',
  title: 'Douglas–Peucker',
  summary: 'Keep the point farthest from the chord while it is farther than ε, and recurse on both halves.',
  async create(host) {
    const { chain, where } = await loadExcerpt(host, EXCERPT);
    const run = vectorizerRun(host, chain, { method: 'dp', key: 'epsilon', what: 'Douglas–Peucker',
      field: { label: 'ε: max distance from the chord', value: 0.05, min: 0.005, max: 0.4, step: 0.005, unit: 'm' } });
    host.figure.fitPoints(chain);
    return {
      predict: dpQuestions(run, chain),
      recompute: run.recompute,
      show(k) {
        const { params, untraced, trace, missing } = run;
        const s = new Scene(`Douglas–Peucker, ε = ${params?.epsilon ?? '–'} m: ${where}`);
        s.points(chain, { label: 0 });
        if (k < 0) { if (untraced) s.segments(untraced.segments, { colour: INK.segment, width: 2 }); host.figure.show(s); explainNoSteps(host, missing); return; }
        const e = trace[k], kept = keptAfter(trace, k);
        let html;
        if (e.kind === 'range') {
          const [ax, ay] = pt(chain, e.first), [bx, by] = pt(chain, e.last), [fx, fy] = pt(chain, e.farthest);
          s.strip(ax, ay, bx, by, e.epsilon, { colour: e.split ? INK.fail : INK.ok, bounded: true, q: 'epsilon' });
          s.segments([ax, ay, bx, by], { colour: INK.candidate, width: 2.5, q: 'chord' });
          // the distance as a perpendicular from the farthest point to the chord's line
          const dx = bx - ax, dy = by - ay, l2 = dx * dx + dy * dy || 1, t = ((fx - ax) * dx + (fy - ay) * dy) / l2;
          s.segments([fx, fy, ax + t * dx, ay + t * dy], { colour: INK.current, width: 2, q: 'distance' });
          s.marker(fx, fy, { colour: INK.current, q: 'farthest' });
          html = `<p>Range <b>${e.first}–${e.last}</b> (${e.last - e.first - 1} interior point${e.last - e.first - 1 === 1 ? '' : 's'}): <span data-q="chord">the chord joins points ${e.first} and ${e.last}</span>. ` +
            `The farthest interior point is <b data-q="farthest">${e.farthest}</b>, <span data-q="distance">${m(e.distance)}</span> from the chord's line; <span data-q="epsilon">ε = ${m(e.epsilon)}</span>.</p>` +
            (e.split
              ? `<p class="why">${m(e.distance)} &gt; ε: point ${e.farthest} is kept as a vertex, and the two halves ${e.first}–${e.farthest} and ${e.farthest}–${e.last} are examined next (left first).</p>`
              : `<p class="why">${m(e.distance)} ≤ ε: every point of the range lies inside the band of half-width ε around the chord, so the chord becomes one segment.</p>`);
        } else {
          html = `<p>Douglas–Peucker starts with the two end points 0 and ${e.count - 1} of the ${e.count} points and examines the chord between them.</p>`;
        }
        if (k === trace.length - 1) {
          html += `<p><b>Done:</b> ${kept.length} vertices, ${kept.length - 1} segments, the same as the package's untraced result (${untraced.count} segments). Vertices are measured points, so their noise stays in the corners.</p>`;
        }
        s.polyline(polylineOf(chain, kept), { colour: INK.segment, width: 2 });
        s.points(polylineOf(chain, kept), { label: -1, radius: 4, colour: INK.segment });
        host.figure.show(s);
        host.text.innerHTML = html + '<p class="legend">Figure: blue line = the chord, band = ε on each side of it (red: the farthest point is outside, so it splits), orange = the farthest point and its distance; black = the polyline kept so far.</p>';
        this.step = k;
      },
      finalState() {
        const { params, untraced, trace } = run;
        const k = this.step ?? -1, kept = keptAfter(trace, k);
        // The untraced result's vertices: dp spans are [key_k, key_k+1 + 1) (index.d.ts).
        const keys = untraced ? [...Array.from(untraced.indices).filter((_, i) => i % 2 === 0), untraced.indices[untraced.indices.length - 1] - 1] : [];
        return { method: 'dp', chain: Array.from(chain), params, step: k, steps: trace.length,
          replayed: { vertices: kept }, untraced: { vertices: untraced?.count ? keys : [], segments: Array.from(untraced?.segments ?? []) } };
      },
      dispose() {},
    };
  },
};
