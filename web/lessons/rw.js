// Reumann–Witkam, step by step from the package's trace (events `start`, `keep`, `strip`, `exit`): the strip of
// half-width ε around the line from the key point through the next point, and each point that leaves it.
import { INK, Scene } from '../figure.js';
import { loadExcerpt, pt, vectorizerRun, explainNoSteps } from './common.js';
import { m } from './ui.js';
import { rwQuestions } from './predict-questions.js';

const EXCERPT = {
  dataset: 'intel', scan: 17, segment: { step: 3, lowerBound: 0.1, upperBound: 0.5 }, clusterAt: 0,
  why: 'The Douglas–Peucker lesson\'s corner, so the two can be compared: at ε = 0.05 m RW needs 6 segments where DP needs 5, because each strip is aimed by only two noisy points.',
};

function replay(trace, k) {
  const kept = [];
  let strip = null;
  for (let i = 0; i <= k && i < trace.length; i++) {
    const e = trace[i];
    if (e.kind === 'keep') kept.push(e.index);
    else if (e.kind === 'strip') strip = e;
  }
  return { kept, strip };
}

export default {
  id: 'rw',
  menu: 'RW',
  title: 'Reumann–Witkam',
  summary: 'Slide a strip of half-width ε along the points; where a point leaves it, the point before becomes a vertex.',
  async create(host) {
    const { chain, where } = await loadExcerpt(host, EXCERPT);
    const run = vectorizerRun(host, chain, { method: 'rw', key: 'epsilon', what: 'Reumann–Witkam',
      field: { label: 'ε: strip half-width', value: 0.05, min: 0.005, max: 0.4, step: 0.005, unit: 'm' } });
    host.figure.fitPoints(chain);
    return {
      predict: rwQuestions(run, chain),
      recompute: run.recompute,
      show(k) {
        const { params, untraced, trace, missing } = run;
        this.step = k;
        const s = new Scene(`Reumann–Witkam, ε = ${params?.epsilon ?? '–'} m: ${where}`);
        s.points(chain, { label: 0 });
        if (k < 0) { if (untraced) s.segments(untraced.segments, { colour: INK.segment, width: 2 }); host.figure.show(s); explainNoSteps(host, missing); return; }
        const e = trace[k], { kept, strip } = replay(trace, k);
        if (strip) {
          const [ax, ay] = pt(chain, strip.key), [bx, by] = pt(chain, strip.through);
          // the strip runs from the key point ahead, through the next point
          const l = Math.hypot(bx - ax, by - ay) || 1, far = 1000;
          s.strip(ax, ay, ax + ((bx - ax) / l) * far, ay + ((by - ay) / l) * far, strip.epsilon, { colour: INK.candidate, bounded: true, q: 'epsilon' });
          s.marker(ax, ay, { colour: INK.candidate, size: 8, q: 'key' });
          s.marker(bx, by, { colour: INK.candidate, size: 5, q: 'through' });
        }
        s.polyline(kept.flatMap((i) => pt(chain, i)), { colour: INK.segment, width: 2 });
        for (const i of kept) s.marker(...pt(chain, i), { colour: INK.segment, shape: 'dot', size: 6 });
        let html;
        const eps = (v) => `<span data-q="epsilon">ε = ${m(v)}</span>`;
        if (e.kind === 'start') html = `<p>${e.count} points, strip half-width ε = ${m(e.epsilon)}. Point 0 is the first key point.</p>`;
        else if (e.kind === 'keep') html = `<p>Point <b>${e.index}</b> is kept as a vertex${e.index === 0 ? ' (the first point)' : e.index === chain.length / 2 - 1 ? ' (the last point: the polyline ends there)' : ': it was the last point inside the strip'}.</p>`;
        else if (e.kind === 'strip') html = `<p>New strip: the line from <span data-q="key">key point <b>${e.key}</b></span> through <span data-q="through">point ${e.through}</span>, ${eps(e.epsilon)} on each side. The scan continues at point ${e.through + 1} while the points stay inside.</p>`;
        else if (e.kind === 'exit') {
          // the distance as a perpendicular from the leaving point to the strip's axis
          const [px, py] = pt(chain, e.index);
          if (strip) {
            const [ax, ay] = pt(chain, strip.key), [bx, by] = pt(chain, strip.through);
            const dx = bx - ax, dy = by - ay, t = ((px - ax) * dx + (py - ay) * dy) / (dx * dx + dy * dy || 1);
            s.segments([px, py, ax + t * dx, ay + t * dy], { colour: INK.fail, width: 2, q: 'distance' });
          }
          s.marker(px, py, { colour: INK.fail, shape: 'x', q: 'exit' });
          html = `<p>Point <b data-q="exit">${e.index}</b> lies <span data-q="distance">${m(e.distance)} from the strip's axis</span> &gt; ${eps(e.epsilon)}: it leaves the strip.</p><p class="why">So point ${e.index - 1}, the last one inside, becomes the next key point and a new strip starts there.</p>`;
        } else html = `<p>${e.kind}</p>`;
        if (k === trace.length - 1) html += `<p><b>Done:</b> ${kept.length} vertices, ${kept.length - 1} segments, as the package's untraced result (${untraced.count}). One pass, fast, but each strip is aimed by only two noisy points.</p>`;
        host.figure.show(s);
        host.text.innerHTML = html + '<p class="legend">Figure: blue band = the strip (ε each side) from its key point (large ring) through the next point (small ring); red × = the point that leaves it, red line = its distance from the axis; black = the polyline kept so far.</p>';
      },
      finalState() {
        const { params, untraced, trace } = run;
        const k = this.step ?? -1;
        const keys = untraced?.count ? [...Array.from(untraced.indices).filter((_, i) => i % 2 === 0), untraced.indices[untraced.indices.length - 1] - 1] : [];
        return { method: 'rw', chain: Array.from(chain), params, step: k, steps: trace.length,
          replayed: { vertices: replay(trace, k).kept }, untraced: { vertices: keys } };
      },
      dispose() {},
    };
  },
};
