// A vertex budget: a whole real scan turned into polylines with at most J vertices (the package's extractPolylines),
// for every J from 2 to 60. The player and the J slider move through the budgets; the figure shows the map at the
// chosen J over the beams, every beam's radial residual along its own ray, the unexplained beams, and one beam at
// grazing incidence in a magnifier with its radial and orthogonal errors; the stage shows score, RMSE and f against J.
import { INK, Scene } from '../figure.js';
import { numberField, selectField, note, m, num } from './ui.js';
import { J_MIN, J_MAX, beamsOf, runBudgets, residuals, grazingBeam, newlyExplained, runsText, curveKnee } from './budget-run.js';
import { budgetChart } from './budget-chart.js';
import { budgetQuestions } from './predict-questions.js';
import { readParams, positive, explainNoSteps } from './common.js';

// The scans offered (bundled excerpts), the first by default: intel 21 explains 77 % of its beams at J = 20 and
// gains beams at 19 of the 59 budgets, so the budget visibly decides what is explained.
export const SCANS = [['intel:21', 'Intel, scan 21'], ['intel:25', 'Intel, scan 25'], ['csail:5', 'CSAIL, scan 5'], ['csail:16', 'CSAIL, scan 16']];
export const DEFAULT_J = 20;
const COST = 0.5;   // the package's default unexplained cost c (m): a beam it leaves unexplained counts as c²

// 1, 2, 5, 10, 20, … : the largest not above v (at least 1), for magnifications a student can read.
function niceFloor(v) {
  if (!(v >= 1)) return 1;
  const p = 10 ** Math.floor(Math.log10(v));
  return [5, 2, 1].map((s) => s * p).find((s) => s <= v);
}

// The part of the line through a with unit direction (tx, ty) inside the circle (c, R), as [x0, y0, x1, y1] or null.
function clipToCircle(ax, ay, tx, ty, cx, cy, R) {
  const dx = ax - cx, dy = ay - cy, b = dx * tx + dy * ty, disc = b * b - (dx * dx + dy * dy - R * R);
  if (disc <= 0) return null;
  const s0 = -b - Math.sqrt(disc), s1 = -b + Math.sqrt(disc);
  return [ax + s0 * tx, ay + s0 * ty, ax + s1 * tx, ay + s1 * ty];
}

export default {
  id: 'budget',
  menu: 'Budget',
  title: 'A vertex budget',
  summary: 'At most J vertices for a whole scan: where does the package spend them, and how far off is each beam along its own ray?',
  async create(host) {
    const src = host.source;
    let shown = -1;   // the step on screen
    const scanField = selectField(host.controls, { key: 'scan', label: 'scan', options: src ? [['', 'your chosen scan']] : SCANS, value: src ? '' : SCANS[0][0], onInput: host.onParamsChanged });
    if (src) scanField.input.disabled = true;   // the chosen scan travels in the link as its source
    const jField = numberField(host.controls, { key: 'J', label: 'J: vertex budget for the whole scan', value: DEFAULT_J, min: J_MIN, max: J_MAX, step: 1, digits: 0,
      onInput: () => {
        const J = jField.read();
        if (Number.isInteger(J)) host.goTo?.(J - J_MIN);
        // a pending "your turn" question holds the player: the slider goes back to the J shown
        if (run.snaps[shown]) jField.set(run.snaps[shown].J);
      } });
    const costField = numberField(host.controls, { key: 'c', label: 'c: unexplained cost (m)', kind: 'number', value: COST, min: 0.05, max: 5, step: 0.05,
      hint: 'a beam left unexplained counts as c²', onInput: host.onParamsChanged });
    note(host.controls, `${src ? `<strong>Your chosen scan</strong> (${host.data.describe(src.dataset, src.scan)}), whole. ` : ''}All numbers are the package's: <code>extractPolylines(points, { maxVertices: J, unexplainedCost: c })</code> for J = ${J_MIN} … ${J_MAX}, one per step of the player.`);
    const chart = budgetChart(host.stage, (k) => host.goTo?.(k));
    const run = { snaps: [], points: null, beams: null, where: '', size: 1 };
    // recompute() is synchronous: every scan it may switch to is read now
    if (src) await host.data.scan(src.dataset, src.scan);
    else await Promise.all([...new Set(SCANS.map(([v]) => v.split(':')[0]))].map((d) => host.data.load(d)));

    return {
      predict: budgetQuestions(run),
      recompute() {
        let dataset, scan;
        if (src) ({ dataset, scan } = src);
        else { const [d, s] = (scanField.read() || SCANS[0][0]).split(':'); dataset = d; scan = Number(s); }
        const scans = host.data.loaded(dataset);
        if (!scans?.[scan]) throw new RangeError(`budget: ${dataset} has no scan ${scan} loaded`);
        run.points = scans[scan].points;
        run.beams = beamsOf(run.points);
        run.where = host.data.describe(dataset, scan);
        const params = readParams({ c: costField }, ({ c }) => (positive(c) ? { c: positive(c) } : {}));
        if (!params) { run.snaps = []; chart.update([], -1); return { steps: 0 }; }
        run.cost = params.c;
        run.snaps = runBudgets(host.rtl, run.points, { unexplainedCost: run.cost });
        // the extent: every beam, the sensor and, beside them on the right, the magnifier (so that it hides nothing
        // and stays put while J changes); the larger side of the scan sets the size of the enlargements
        const xs = [0], ys = [0];
        for (let i = 0; i < run.beams.n; i++) if (Number.isFinite(run.beams.range[i])) { xs.push(run.points[2 * i]); ys.push(run.points[2 * i + 1]); }
        const box = { minX: Math.min(...xs), maxX: Math.max(...xs), minY: Math.min(...ys), maxY: Math.max(...ys) };
        run.size = Math.max(box.maxX - box.minX, box.maxY - box.minY, 1);
        // a wide canvas puts it on the right, a tall one (a phone) below, with room for its labels
        const c = host.figure.canvas, sized = c.clientWidth > 0 && c.clientHeight > 0, wide = !(c.clientHeight > 0) || c.clientWidth / c.clientHeight >= 1.2;
        // room above the scan for the figure's title (one line of 16 CSS px on a wide canvas, two on a phone's, times the
        // type scale of lecture mode), so that it covers no beam
        const titlePx = sized ? ((wide ? 1 : 2) * 16 + 8) * (Number(getComputedStyle(c).getPropertyValue('--figure-text-scale')) || 1) : 0;
        // the magnifier: a fifth of the scan's size, larger when a wide canvas has room beside the scan (a 1920 px screen:
        // the scan's height sets the scale and the width left over was empty): as large as the width allows at that
        // scale (5 % spare), at most as high as the scan (with its label under it: 2.6 R), so that the map is drawn no
        // smaller; the circle and its label centred on the scan's height
        const bw = box.maxX - box.minX, bh = box.maxY - box.minY;
        const room = wide && sized ? (0.95 * (c.clientWidth / (c.clientHeight - titlePx)) * bh - bw) / 2.7 : 0;
        const R = Math.max(0.2 * run.size, Math.min(room, bh / 2.6));
        run.lensAt = wide ? { R, x: box.maxX + 1.2 * R, y: (box.minY + box.maxY) / 2 + 0.3 * R } : { R, x: (box.minX + box.maxX) / 2, y: box.minY - 1.2 * R };
        const L = run.lensAt;
        const ext = [Math.min(box.minX, L.x - 1.5 * R), Math.min(box.minY, L.y - 1.6 * R), Math.max(box.maxX, L.x + 1.5 * R), Math.max(box.maxY, L.y + R)];
        if (sized) {
          const scale = Math.min(c.clientWidth / (ext[2] - ext[0]), (c.clientHeight - titlePx) / (ext[3] - ext[1]));
          if (scale > 0) ext[3] += titlePx / scale;
        }
        host.figure.setExtent(...ext);
        // the J slider holds the budget shown (show() keeps it current), so a new scan or c keeps J, also after a
        // parameter error emptied the player
        const J = jField.read(), k = Number.isInteger(J) ? Math.min(Math.max(J, J_MIN), J_MAX) - J_MIN : DEFAULT_J - J_MIN;
        return { steps: run.snaps.length, start: k, jump: k };
      },
      show(k) {
        this.step = shown = k;
        const snap = run.snaps[k];
        if (!snap) { host.figure.show(new Scene('A vertex budget')); explainNoSteps(host, null); return; }
        jField.set(snap.J);
        chart.update(run.snaps, k);
        host.figure.show(this.scene(snap));
        host.text.innerHTML = this.explain(k);
      },
      // The figure at one budget.
      scene(snap) {
        const { beams, points } = run;
        const res = residuals(beams, snap);
        const s = new Scene(`A vertex budget, J = ${snap.J} (${snap.vertexCount} used): ${run.where}`);
        const explained = [], unexplained = [];
        for (let i = 0; i < beams.n; i++) {
          if (!Number.isFinite(beams.range[i])) continue;
          (Number.isFinite(res[i]) ? explained : unexplained).push(points[2 * i], points[2 * i + 1]);
        }
        const D = run.size;
        // residuals enlarged so that a typical one (the median) shows as a stub while the large ones (the 95th
        // percentile) stay within a few per cent of the view; most radial errors are centimetres on a scan of metres
        const sorted = Array.from(res).filter(Number.isFinite).map(Math.abs).sort((a, b) => a - b);
        const at = (q) => (sorted.length ? sorted[Math.floor(q * (sorted.length - 1))] : 0);
        const p50 = at(0.5), p95 = at(0.95);
        const gain = p95 > 0 ? niceFloor(Math.min(p50 > 0 ? (0.008 * D) / p50 : Infinity, (0.08 * D) / p95)) : 1;
        const resXY = [];
        for (let i = 0; i < beams.n; i++) {
          if (!Number.isFinite(res[i])) continue;
          const x = points[2 * i], y = points[2 * i + 1];
          resXY.push(x, y, x - gain * res[i] * beams.ux[i], y - gain * res[i] * beams.uy[i]);
        }
        s.points(explained, { colour: '#5a6475', radius: 2, q: 'explained' });
        for (const p of snap.polylines) s.polyline(p, { colour: INK.segment, width: 2, q: 'map' });
        s.points(snap.polylines.flat(), { colour: INK.ok, radius: 3.5, q: 'vertices' });
        s.segments(resXY, { colour: INK.current, width: 2, q: 'residuals' });
        s.points(unexplained, { colour: INK.fail, radius: 3.5, q: 'unexplained' });
        s.marker(0, 0, { colour: INK.candidate, shape: 'x', size: 5, q: 'sensor' });
        // the beams this budget explains and one vertex fewer did not
        const before = run.snaps[snap.J - J_MIN - 1];
        run.gained = before ? newlyExplained(beams, before, snap) : [];
        for (const i of run.gained) s.marker(points[2 * i], points[2 * i + 1], { colour: INK.ok, size: 6, q: 'gained' });
        run.gain = gain;
        run.grazing = grazingBeam(beams, snap);
        if (run.grazing) this.lens(s, snap, run.grazing, D);
        return s;
      },
      // The grazing beam: its ray, and a magnifier beside its point with the line, r − r̂ along the ray and the
      // orthogonal distance to the line.
      lens(s, snap, g, D) {
        const { beams } = run, i = g.beam, r = beams.range[i], ux = beams.ux[i], uy = beams.uy[i];
        const px = r * ux, py = r * uy, { nx, ny } = g.line, off = px * nx + py * ny - g.line.r;
        s.segments([0, 0, px, py], { colour: INK.candidate, width: 1.5, dash: true, q: 'ray' });
        s.marker(px, py, { colour: INK.candidate, size: 6, q: 'ray' });
        const { R, x: cx, y: cy } = run.lensAt;
        const M = niceFloor((0.95 * R) / Math.max(g.radial, g.orthogonal, 1e-9));
        const T = (x, y) => [cx + M * (x - px), cy + M * (y - py)];
        const toP = Math.hypot(px - cx, py - cy) || 1;
        s.segments([cx + (R * (px - cx)) / toP, cy + (R * (py - cy)) / toP, px, py], { colour: INK.muted, width: 1 });
        s.circle(cx, cy, R, { colour: INK.muted, fill: '#ffffff', width: 1.5 });
        const rayIn = clipToCircle(cx, cy, ux, uy, cx, cy, R);
        if (rayIn) s.segments(rayIn, { colour: INK.candidate, width: 1.5, dash: true, q: 'ray' });
        const [fx, fy] = T(px - off * nx, py - off * ny);   // the foot of the perpendicular, magnified
        const lineIn = clipToCircle(fx, fy, -ny, nx, cx, cy, R);
        if (lineIn) s.segments(lineIn, { colour: INK.segment, width: 2.5, q: 'map' });
        const rh = snap.expected[i], [hx, hy] = T(rh * ux, rh * uy);
        s.segments([cx, cy, hx, hy], { colour: INK.current, width: 3, q: 'radial' });
        s.segments([cx, cy, fx, fy], { colour: INK.ok, width: 3, q: 'orthogonal' });
        s.label(hx, hy, 'radial', { colour: INK.current, q: 'radial' });
        s.label(fx, fy, 'orthogonal', { colour: INK.ok, q: 'orthogonal', offset: [6, 14] });
        s.marker(cx, cy, { colour: INK.candidate, shape: 'dot', size: 6, q: 'ray' });
        s.label(cx - R, cy - R, `beam ${i}, enlarged ×${M}`, { colour: INK.segment, bold: true, offset: [0, 16] });
        run.lens = { M, R, x: cx, y: cy };
      },
      explain(k) {
        const snap = run.snaps[k], prev = run.snaps[k - 1], g = run.grazing;
        const unexplained = snap.returned - snap.explainedBeams;
        let html = `<p><b>J = ${snap.J}</b>: the package spends <span data-q="vertices">${snap.vertexCount} vertices</span> on ` +
          `<span data-q="map">${snap.polylines.length} polyline${snap.polylines.length === 1 ? '' : 's'}</span>. They explain ` +
          `<span data-q="explained">${snap.explainedBeams} of the ${snap.returned} returned beams (f = ${num(snap.explained)})</span> with ` +
          `<span data-q="residuals">RMSE ${m(snap.rmse)}</span> along the beams; <span data-q="unexplained">${unexplained} beam${unexplained === 1 ? ' is' : 's are'} unexplained</span> ` +
          `and count as c = ${m(run.cost, 2)} each. Score f·RMSE² + (1 − f)·c² = <b>${num(snap.score, 4)} m²</b>.</p>`;
        // why a budget at all, and where this J sits on the curve under the figure (the package's scores)
        const knee = curveKnee(run.snaps);
        const side = !knee ? '' : snap.J < knee.J ? ` J = ${snap.J} is before the bend of the curve below (<span class="knee-j">J = ${knee.J}</span>, 90 % of the possible fall in score): vertices still pay here.`
          : snap.J === knee.J ? ` J = ${snap.J} is the bend of the curve below: 90 % of the possible fall in score is made, later vertices buy little.`
            : ` J = ${snap.J} is past the bend of the curve below (<span class="knee-j">J = ${knee.J}</span>): the ${snap.J - knee.J} vertices beyond it buy the last few per cent.`;
        html += `<p class="budget-why"><b>Why a budget?</b> A map is what a robot stores, sends and matches every scan against, and its size is its vertex count. ` +
          `Fixing J asks a fair question, the same for every method: with this many vertices, how well can the scan be explained?${side}</p>`;
        if (prev) {
          const d = snap.score - prev.score;
          const gained = run.gained.length ? ` <span data-q="gained">${run.gained.length} beam${run.gained.length === 1 ? '' : 's'} newly explained</span> (${runsText(run.gained)}, green rings).` : '';
          html += d < 0 ? `<p class="why">One vertex more than J = ${prev.J} lowered the score from ${num(prev.score, 4)} to ${num(snap.score, 4)} m².${gained}</p>`
            : d === 0 ? `<p class="why">One vertex more than J = ${prev.J} changes nothing: the best map within J is still the one of J − 1 (a single vertex does not pay here; a new polyline needs two).</p>`
              : `<p class="why">The score is <b>higher</b> than at J = ${prev.J} (${num(prev.score, 4)} m²): for each J the package refines the best plan of every budget up to J and keeps the one whose polylines explain their own stretches best; polylines of neighbouring stretches can overlap, which those costs leave out, so the final score can end slightly above the one at J − 1.${gained}</p>`;
        }
        if (g) {
          const ratio = g.orthogonal > 0 ? g.radial / g.orthogonal : Infinity;
          html += `<p><b>Why radial?</b> A range sensor errs along its beam, so each beam's error is <span data-q="residuals">r − r̂ along its own ray</span> (orange, drawn ×${run.gain}). ` +
            `A line fit measures the distance across the line instead. <span data-q="ray">Beam ${g.beam}</span> meets its line at ${num(g.incidence, 0)}° from the line's normal: its point is only ` +
            `<span data-q="orthogonal">${m(g.orthogonal)} from the line</span> (green), but <span data-q="radial">${m(g.radial)} from it along the beam</span> (orange), ` +
            `${Number.isFinite(ratio) ? `${num(ratio, 1)} times as far` : 'although it lies on the line\'s extension'}: orthogonal = radial × cos ${num(g.incidence, 0)}°. A beam meeting its wall head-on (0°) would have the two equal. ` +
            `The closer a beam grazes its wall, the more a small miss across the line costs along the beam, which is why the package moves the vertices to fit the radial errors after its line fits.</p>`;
        }
        html += `<p class="legend">Figure: black = the map, green dots = its vertices, grey = explained beams, red = unexplained beams, green rings = beams explained since J − 1, orange = each beam's r − r̂ ×${run.gain} toward where the map predicts it, blue = the example beam from the sensor (×), enlarged ×${run.lens?.M ?? 1} in the circle: its radial error (orange, along the beam) and orthogonal distance (green, across the line).</p>`;
        return html;
      },
      finalState() {
        const k = this.step ?? -1, snap = run.snaps[k];
        return { method: 'budget', where: run.where, cost: run.cost, step: k, steps: run.snaps.length, points: run.points && Array.from(run.points),
          J: snap?.J, vertexCount: snap?.vertexCount, polylines: snap?.polylines, rmse: snap?.rmse, explained: snap?.explained, score: snap?.score,
          expected: snap && Array.from(snap.expected),
          curve: run.snaps.map(({ J, vertexCount, rmse, explained, score }) => ({ J, vertexCount, rmse, explained, score })),
          lens: run.lens, gain: run.gain, gained: run.gained, grazing: run.grazing && { beam: run.grazing.beam, radial: run.grazing.radial, orthogonal: run.grazing.orthogonal, incidence: run.grazing.incidence } };
      },
      dispose() { chart.dispose(); },
    };
  },
};
