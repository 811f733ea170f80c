// Lesson: the total-least-squares line fit, on real points of a wall: its bundled excerpt, or a straight run of the
// scan the user chose (tls-fit-source.js). The fit (centroid, normal, offset, RMS) is the package's fitLine; the
// ordinary-least-squares line is a teaching comparison computed here (two formulas). Points can be dragged with the
// mouse, or picked with [ / ] and moved with the arrow keys (Shift: 10 cm).
import { Scene, lineThrough } from '../figure.js';
import { note, numberField, selectField } from './ui.js';
import { EXCERPT, tlsFitPoints } from './tls-fit-source.js';

export { EXCERPT };

const STEPS = ['centroid', 'spread', 'normal', 'residuals', 'rms'];
const NUDGE = 0.01;   // m per arrow key press

const f3 = (v) => (Number.isFinite(v) ? v.toFixed(3) : '–');
// where and why name the user's file: text, never markup, in the note and the explanation.
const escapeHtml = (t) => t.replace(/[&<>"]/g, (c) => ({ '&': '&amp;', '<': '&lt;', '>': '&gt;', '"': '&quot;' })[c]);
const mm = (v) => (Number.isFinite(v) ? `${(v * 1000).toFixed(1)} mm` : '–');
// The wall's angle to the x axis (from the package's direction) and what it does to vertical residuals: the bundled
// wall runs at 84°, where they are about nine times the orthogonal ones.
const steepness = (direction, olsRms, tlsRms) => {
  const deg = Math.atan2(Math.abs(direction[1]), Math.abs(direction[0])) * 180 / Math.PI, r = olsRms / tlsRms;
  return `This wall runs at ${deg.toFixed(1)}° to the x axis: OLS vertical RMS ${mm(olsRms)} against the orthogonal ${mm(tlsRms)}, ${r.toFixed(1)} times` +
    (r >= 2 ? ', so measuring errors vertically is the wrong model here.' : '; the steeper a wall, the further the two part.');
};

// Teaching comparison, not the package: OLS regresses y on x (vertical residuals), y = slope * x + intercept.
export function olsLine(xy) {
  const n = xy.length / 2;
  let mx = 0, my = 0;
  for (let i = 0; i < n; i++) { mx += xy[2 * i]; my += xy[2 * i + 1]; }
  mx /= n; my /= n;
  let sxx = 0, sxy = 0;
  for (let i = 0; i < n; i++) { sxx += (xy[2 * i] - mx) ** 2; sxy += (xy[2 * i] - mx) * (xy[2 * i + 1] - my); }
  const slope = sxy / sxx;
  return { slope, intercept: my - slope * mx };
}

export default {
  id: 'tls-fit',
  title: 'TLS line fit',
  summary: 'Fit a line to a wall by total least squares: centroid, covariance, the normal, orthogonal residuals; compared with ordinary least squares.',
  async create(host) {
    const run = await tlsFitPoints(host);
    const original = run.points;
    const label = (i) => `${run.word} ${run.indices[i]}`;
    let points = original.slice();
    let selected = 0;
    let step = 0;
    let fit = null, ols = null, spread = null;

    // ---- controls: σ, the selected point, reset
    const controls = host.controls;
    const changed = () => { host.onParamsChanged(); };
    const sigmaField = numberField(controls, { key: 'sigma', label: 'σ: max RMS distance', value: 0.03, min: 0.005, max: 1,
      step: 0.005, kind: 'number', unit: 'm', hint: 'FTLS accepts a run of points as one segment while its RMS stays below σ.', onInput: changed });
    const pointField = selectField(controls, { key: 'point', label: 'Point to move (arrow keys on the figure)',
      options: Array.from({ length: original.length / 2 }, (_, i) => [String(i), label(i)]), value: '0',
      onInput: () => { selected = Number(pointField.read()); lesson.show(step); } });
    const pointSelect = pointField.input;
    const reset = document.createElement('button');
    Object.assign(reset, { type: 'button', className: 'small wide', textContent: 'Reset the points' });
    reset.dataset.act = 'reset-points';
    controls.append(reset);
    note(controls, `<strong>Excerpt:</strong> ${escapeHtml(run.where)}. ${escapeHtml(run.why)} Drag a point, or focus the figure and use [ ] to pick one and the arrow keys to move it (Shift: 10 cm).`);
    let sigma = 0.03, sigmaOk = true;
    const readSigma = () => {
      const v = sigmaField.read();
      sigmaOk = v > 0 && v <= 1;
      sigmaField.setError(sigmaOk ? null : 'σ must be a number above 0 and at most 1 m.');
      if (sigmaOk) sigma = v;
    };
    reset.addEventListener('click', () => { points = original.slice(); fig.setExtent(...view); changed(); });

    // ---- interaction on the figure
    const fig = host.figure;
    const canvas = fig.canvas;
    const nearest = (px, py) => {
      let best = -1, bd = Infinity;
      for (let i = 0; i < points.length / 2; i++) {
        const [sx, sy] = fig.toScreen(points[2 * i], points[2 * i + 1]);
        const d = Math.hypot(sx - px, sy - py);
        if (d < bd) { bd = d; best = i; }
      }
      return bd < 16 ? best : -1;
    };
    const local = (e) => { const r = canvas.getBoundingClientRect(); return [e.clientX - r.left, e.clientY - r.top]; };
    // The figure pans on drag and on arrow keys; on a point (or with a point selected for the keys) the lesson takes
    // the event first (capture phase on the canvas) and keeps it from the figure.
    let dragging = -1;
    const onDown = (e) => {
      const i = nearest(...local(e));
      if (i < 0) return;
      dragging = selected = i;
      pointSelect.value = String(i);
      canvas.setPointerCapture?.(e.pointerId);
      e.preventDefault();
      e.stopImmediatePropagation();
    };
    const onMove = (e) => {
      if (dragging < 0) return;
      e.stopImmediatePropagation();
      const [x, y] = fig.toWorld(...local(e));
      points[2 * dragging] = x; points[2 * dragging + 1] = y;
      changed();
    };
    const onUp = (e) => { if (dragging >= 0) e.stopImmediatePropagation(); dragging = -1; };
    const onKey = (e) => {
      const n = points.length / 2;
      if (e.key === '[' || e.key === ']') {
        selected = (selected + (e.key === ']' ? 1 : n - 1)) % n;
        pointSelect.value = String(selected);
        lesson.show(step);
        e.preventDefault();
        e.stopImmediatePropagation();
        return;
      }
      const d = { ArrowLeft: [-1, 0], ArrowRight: [1, 0], ArrowUp: [0, 1], ArrowDown: [0, -1] }[e.key];
      if (!d) return;
      const k = e.shiftKey ? 10 * NUDGE : NUDGE;
      points[2 * selected] += d[0] * k; points[2 * selected + 1] += d[1] * k;
      e.preventDefault();
      e.stopImmediatePropagation();
      changed();
    };
    canvas.addEventListener('pointerdown', onDown, true);
    canvas.addEventListener('pointermove', onMove, true);
    canvas.addEventListener('pointerup', onUp, true);
    canvas.addEventListener('keydown', onKey, true);

    // The view: the original excerpt with a margin, fixed while dragging so the points do not jump.
    const view = (() => {
      let x0 = Infinity, y0 = Infinity, x1 = -Infinity, y1 = -Infinity;
      for (let i = 0; i < original.length; i += 2) {
        x0 = Math.min(x0, original[i]); x1 = Math.max(x1, original[i]);
        y0 = Math.min(y0, original[i + 1]); y1 = Math.max(y1, original[i + 1]);
      }
      const m = 0.35 * Math.max(x1 - x0, y1 - y0);
      return [x0 - m, y0 - m, x1 + m, y1 + m];
    })();

    fig.setExtent(...view);
    const reach = 2 * Math.max(view[2] - view[0], view[3] - view[1]);
    const lineItem = (scene, x, y, dx, dy, opts) => scene.segments(lineThrough(x, y, x + dx, y + dy, reach), opts);

    const lesson = {
      recompute() {
        readSigma();
        if (!sigmaOk) return { steps: 0 };
        fit = host.rtl.fitLine(new Float64Array(points));
        ols = olsLine(points);
        // The spread the text talks about: the covariance entries (display), whose smaller eigenvalue is fitLine's rms².
        const n = points.length / 2, [cx, cy] = fit.centroid;
        let sxx = 0, sxy = 0, syy = 0;
        for (let i = 0; i < n; i++) {
          const dx = points[2 * i] - cx, dy = points[2 * i + 1] - cy;
          sxx += dx * dx; sxy += dx * dy; syy += dy * dy;
        }
        spread = { sxx: sxx / n, sxy: sxy / n, syy: syy / n };
        return { steps: STEPS.length };
      },
      show(k) {
        if (k < 0 || !fit) {
          host.text.textContent = 'Correct σ (marked) to see the fit.';
          fig.show(new Scene('TLS line fit').points(points, { colour: '#222', radius: 4 }));
          return;
        }
        step = Math.max(0, Math.min(STEPS.length - 1, k));
        const [cx, cy] = fit.centroid, [a, b] = fit.normal, c = fit.offset, [dx, dy] = fit.direction;
        const n = points.length / 2;
        const name = STEPS[step];
        const scene = new Scene(`TLS line fit, ${run.where}: ${name}`);
        // line and residuals first, points on top
        if (step >= 2) lineItem(scene, cx, cy, dx, dy, { colour: '#0072B2', width: 2.5, q: 'line' });
        if (step >= 3) {
          lineItem(scene, cx, ols.slope * cx + ols.intercept, 1, ols.slope, { colour: '#D55E00', width: 1.5, dash: true, q: 'ols' });
          const orth = [], vert = [];
          for (let i = 0; i < n; i++) {
            const x = points[2 * i], y = points[2 * i + 1], d = a * x + b * y + c;
            orth.push(x, y, x - d * a, y - d * b);
            vert.push(x, y, x, ols.slope * x + ols.intercept);
          }
          scene.segments(vert, { colour: '#D55E00', width: 1, dash: true, q: 'vertical' });
          scene.segments(orth, { colour: '#0072B2', width: 1.5, q: 'residuals' });
        }
        if (step === 1 || step === 2) {
          // principal axes of the spread, along the package's direction and normal, half-lengths 2√λ (display)
          const lmin = fit.rms ** 2, lmax = spread.sxx + spread.syy - lmin;
          const L = 2 * Math.sqrt(lmax), S = 2 * Math.sqrt(lmin);
          scene.segments([cx - L * dx, cy - L * dy, cx + L * dx, cy + L * dy], { colour: '#009E73', width: 2, q: 'major' });
          scene.segments([cx - S * a, cy - S * b, cx + S * a, cy + S * b], { colour: '#CC79A7', width: 3, q: 'minor' });
        }
        if (step === 2) {
          const len = 0.2 * (view[2] - view[0]);
          scene.segments([cx, cy, cx + len * a, cy + len * b], { colour: '#CC79A7', width: 2.5, q: 'normal' });
          scene.marker(cx + len * a, cy + len * b, { shape: 'dot', colour: '#CC79A7', size: 8, q: 'normal' });
          scene.label(cx + len * a, cy + len * b, 'normal n', { colour: '#762A83', q: 'normal' });
        }
        scene.points(points, { colour: '#222', radius: 4 });
        scene.marker(points[2 * selected], points[2 * selected + 1], { colour: '#E69F00', size: 9 });
        scene.marker(cx, cy, { shape: 'x', colour: '#000', size: 7, q: 'centroid' });
        scene.label(cx, cy, 'centroid', { q: 'centroid' });
        if (step === 1) {
          // the axes' names, over the centroid's mark: the short axis is a few pixels long, so its label stands off it
          const off = 0.08 * (view[2] - view[0]), lmin = fit.rms ** 2, L = 2 * Math.sqrt(spread.sxx + spread.syy - lmin);
          scene.label(cx + L * dx, cy + L * dy, 'λmax', { colour: '#00704F', q: 'major' });
          scene.segments([cx, cy, cx + off * a, cy + off * b], { colour: '#CC79A7', width: 1, dash: true, q: 'minor' });
          scene.label(cx + off * a, cy + off * b, 'λmin (across)', { colour: '#8E3B73', q: 'minor', offset: [6, 16] });   // below, apart from "centroid"
        }
        if (step === 4) {
          // each point's orthogonal distance against σ (the quantities whose mean square the RMS is)
          const xs = [], ys = [], ok = [];
          for (let i = 0; i < n; i++) {
            const d = Math.abs(a * points[2 * i] + b * points[2 * i + 1] + c);
            xs.push(run.indices[i]); ys.push(d); ok.push(d < sigma);
          }
          scene.setInset({ title: `|orthogonal residual| per ${run.word}, RMS ${mm(fit.rms)}`, xs, ys, ok, hline: sigma, hlabel: 'σ', xlabel: run.word, yformat: (y) => mm(y) });
        }
        fig.show(scene);

        const olsRms = Math.sqrt(points.reduce((s, v, i) => (i % 2 ? s + (v - ols.slope * points[i - 1] - ols.intercept) ** 2 : s), 0) / n);
        const lmin = fit.rms ** 2, lmax = spread.sxx + spread.syy - lmin;
        const text = {
          centroid: `Step 1 of 5 · centroid. The ${n} points are ${escapeHtml(run.where)}, ${run.origin === 'source' ? 'a straight run of your chosen scan' : 'a wall'} in the robot frame. The best line in the total-least-squares sense always passes through <span data-q="centroid">their centroid (×) = (${f3(cx)}, ${f3(cy)}) m</span>, so only its direction is left to find.`,
          spread: `Step 2 of 5 · spread. Around the centroid the points spread as the covariance matrix [[${spread.sxx.toExponential(2)}, ${spread.sxy.toExponential(2)}], [${spread.sxy.toExponential(2)}, ${spread.syy.toExponential(2)}]] m². Its eigenvectors are the axes drawn: <span data-q="major">the long green one along the wall (λ = ${lmax.toExponential(2)} m²)</span>, <span data-q="minor">the short pink one across it (λ = ${lmin.toExponential(2)} m²)</span>.`,
          normal: `Step 3 of 5 · normal. The normal of the fitted line is the eigenvector of the smaller eigenvalue: <span data-q="normal">n = (${f3(a)}, ${f3(b)})</span>, so <span data-q="line">the line is ${f3(a)}·x + ${f3(b)}·y ${c < 0 ? '−' : '+'} ${f3(Math.abs(c))} = 0</span> (package fitLine). Turning the line any other way around the centroid would increase the sum of squared orthogonal distances.`,
          residuals: `Step 4 of 5 · residuals. TLS measures <span data-q="residuals">each point's orthogonal distance to the line (solid blue)</span>. Ordinary least squares (dashed orange, a teaching comparison computed in this page, not by the package) measures <span data-q="vertical">vertical distances</span>: <span data-q="ols">y = ${f3(ols.slope)}·x ${ols.intercept < 0 ? '−' : '+'} ${f3(Math.abs(ols.intercept))}</span>. ${steepness(fit.direction, olsRms, fit.rms)} Vertical residuals depend on how the axes happen to lie, which a wall does not care about.`,
          rms: `Step 5 of 5 · RMS against σ. The RMS <span data-q="residuals">orthogonal distance</span> is √λmin = ${mm(fit.rms)} (package fitLine), against σ = ${mm(sigma)}: ${fit.rms < sigma ? 'below σ, so FTLS would accept these points as one segment.' : 'above σ, so FTLS would not accept these points as one segment and would split them.'} Drag a point away from the wall and watch both the RMS and the OLS line react.`,
        }[name];
        host.text.innerHTML = `<p>${text}</p>`;
      },
      finalState() {
        return {
          excerpt: { dataset: run.dataset, scan: run.scan, firstBeam: run.firstBeam, lastBeam: run.lastBeam }, origin: run.origin,
          indices: run.indices.slice(), points: points.slice(), selected, sigma, step,
          fit: { normal: Array.from(fit.normal), offset: fit.offset, centroid: Array.from(fit.centroid), rms: fit.rms, count: fit.count },
          ols: { ...ols }, accepted: fit.rms < sigma,
        };
      },
      dispose() {
        canvas.removeEventListener('pointerdown', onDown, true);
        canvas.removeEventListener('pointermove', onMove, true);
        canvas.removeEventListener('pointerup', onUp, true);
        canvas.removeEventListener('keydown', onKey, true);
        controls.replaceChildren();
      },
    };
    return lesson;
  },
};
