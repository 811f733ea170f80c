// The vertex-budget lesson's curves, in the stage under the figure: the score and, beside it, RMSE and the explained
// fraction f against J, one point per extractPolylines() call, the chosen J marked. Clicking a J chooses it. Each
// panel is H user units high and as wide as its box allows at its CSS height (the viewBox follows the box), so that
// on a wide screen the curves spread over the panel while the text keeps its size.
import { curveKnee } from './budget-run.js';

const NS = 'http://www.w3.org/2000/svg';
const MIN_W = 300, H = 180, PAD = { l: 44, r: 34, t: 22, b: 38 };
const COLOUR = { score: '#111111', rmse: '#D55E00', f: '#0072B2', rise: '#C0392B', chosen: '#FFC400' };

const el = (name, attrs = {}, text) => {
  const e = document.createElementNS(NS, name);
  for (const [k, v] of Object.entries(attrs)) e.setAttribute(k, String(v));
  if (text !== undefined) e.textContent = text;
  return e;
};

// Tick values 0..top at a 1-2-5 step, about 4 of them.
function ticks(top) {
  const raw = top / 4, p = 10 ** Math.floor(Math.log10(raw || 1));
  const step = [1, 2, 5, 10].map((m) => m * p).find((s) => s >= raw) ?? p;
  const out = [];
  for (let v = 0; v <= top * (1 + 1e-9); v += step) out.push(Number(v.toPrecision(6)));
  return out;
}
const label = (v) => (v === 0 ? '0' : Math.abs(v) < 0.01 ? v.toExponential(0) : String(Number(v.toPrecision(3))));

// One panel (an svg of its own, so that narrow screens stack them): series [{ name, ys, colour, axis: 'left' |
// 'right', top, dots? (colour per point) }] against xs; knee: the J where the score curve bends, dashed, or null.
function panel(W, title, xs, series, chosen, knee = null) {
  const g = el('svg', { viewBox: `0 0 ${W} ${H}`, role: 'img' });
  const pw = W - PAD.l - PAD.r, ph = H - PAD.t - PAD.b, xMin = xs[0], xMax = xs[xs.length - 1];
  const X = (x) => PAD.l + ((x - xMin) / (xMax - xMin)) * pw;
  g.append(el('text', { x: PAD.l - 36, y: 13, class: 'chart-title' }, title));
  g.append(el('line', { x1: X(chosen), x2: X(chosen), y1: PAD.t, y2: PAD.t + ph, stroke: COLOUR.chosen, 'stroke-width': 5, class: 'chosen-j' }));
  g.append(el('path', { d: `M${PAD.l},${PAD.t}V${PAD.t + ph}H${PAD.l + pw}${series.some((s) => s.axis === 'right') ? `V${PAD.t}` : ''}`, fill: 'none', stroke: '#5a6475' }));
  if (knee !== null) {
    g.append(el('line', { x1: X(knee), x2: X(knee), y1: PAD.t, y2: PAD.t + ph, stroke: '#5a6475', 'stroke-width': 1, 'stroke-dasharray': '3 3', class: 'knee' }));
    // its name beside it at the top of the plot, on the side with room
    const right = X(knee) < PAD.l + 0.6 * pw;
    g.append(el('text', { x: X(knee) + (right ? 4 : -4), y: PAD.t + 11, 'text-anchor': right ? 'start' : 'end', class: 'tick knee-label' }, `90 % by J = ${knee}`));
  }
  for (const J of [xMin, 10, 20, 30, 40, 50, xMax]) {
    g.append(el('text', { x: X(J), y: PAD.t + ph + 17, 'text-anchor': 'middle', class: 'tick' }, String(J)));
  }
  g.append(el('text', { x: PAD.l + pw / 2, y: H - 3, 'text-anchor': 'middle', class: 'tick' }, 'J (vertex budget)'));
  for (const s of series) {
    const Y = (y) => PAD.t + ph - (Math.min(y, s.top) / s.top) * ph;
    for (const t of ticks(s.top)) {
      const right = s.axis === 'right';
      g.append(el('text', { x: right ? PAD.l + pw + 5 : PAD.l - 5, y: Y(t) + 3, 'text-anchor': right ? 'start' : 'end', class: 'tick', style: `fill: ${s.colour}` }, label(t)));
    }
    let d = '';
    xs.forEach((x, i) => { if (Number.isFinite(s.ys[i])) d += `${d ? 'L' : 'M'}${X(x).toFixed(1)},${Y(s.ys[i]).toFixed(1)}`; });
    g.append(el('path', { d, fill: 'none', stroke: s.colour, 'stroke-width': 1.6, class: `series-${s.name}` }));
    xs.forEach((x, i) => {
      if (!Number.isFinite(s.ys[i]) || !(s.dots?.[i] || x === chosen)) return;
      g.append(el('circle', { cx: X(x), cy: Y(s.ys[i]), r: x === chosen ? 3.5 : 3, fill: s.dots?.[i] ?? s.colour }));
    });
  }
  // one transparent column per J: clicking chooses it
  xs.forEach((x, i) => {
    const half = pw / (xs.length - 1) / 2;
    const hit = el('rect', { x: X(x) - half, y: PAD.t, width: 2 * half, height: ph, fill: 'transparent', 'data-k': i, class: 'pick' });
    hit.append(el('title', {}, `J = ${x}`));
    g.append(hit);
  });
  return g;
}

// The viewBox width that fills a panel box of clientWidth × its max-height (CSS px) at the height H: at least MIN_W
// (narrower boxes scale the whole drawing down, as before).
function widthFor(svg) {
  const w = svg?.clientWidth, h = svg ? parseFloat(getComputedStyle(svg).maxHeight) : NaN;
  return w > 0 && h > 0 ? Math.max(MIN_W, Math.round((H * w) / h)) : MIN_W;
}

// Mounts the chart in `parent`; returns { update(snaps, k), dispose() }. onPick(k) when a J column is clicked.
export function budgetChart(parent, onPick) {
  const box = document.createElement('div');
  box.className = 'budget-chart';
  const svg = document.createElement('div');
  svg.className = 'panels';
  svg.setAttribute('role', 'group');
  const legend = document.createElement('p');
  legend.className = 'legend';
  box.append(svg, legend);
  parent.append(box);
  svg.addEventListener('click', (ev) => {
    const k = ev.target.closest?.('[data-k]')?.dataset.k;
    if (k !== undefined) onPick(Number(k));
  });
  let shown = null, W = MIN_W;   // the last update()'s arguments; the viewBox width drawn
  const render = () => {
    const [snaps, k] = shown;
    if (!snaps.length) { svg.replaceChildren(); legend.textContent = ''; return; }
    const xs = snaps.map((s) => s.J), chosen = snaps[k]?.J ?? xs[0];
    const score = snaps.map((s) => s.score), rmse = snaps.map((s) => s.rmse), f = snaps.map((s) => s.explained);
    // a budget whose score is above the one before it (more vertices, a worse map) is marked
    const rises = score.map((v, i) => (i > 0 && v > score[i - 1] ? COLOUR.rise : null));
    const top = (ys) => Math.max(1e-9, ...ys.filter(Number.isFinite)) * 1.08;
    const knee = curveKnee(snaps);
    svg.replaceChildren(
      panel(W, 'score (m²): lower is better', xs, [{ name: 'score', ys: score, colour: COLOUR.score, axis: 'left', top: top(score), dots: rises }], chosen, knee?.J ?? null),
      panel(W, 'RMSE (m, left) and f (right)', xs, [
        { name: 'rmse', ys: rmse, colour: COLOUR.rmse, axis: 'left', top: top(rmse) },
        { name: 'f', ys: f, colour: COLOUR.f, axis: 'right', top: 1 }], chosen));
    svg.firstChild.setAttribute('aria-label', `Score for J = ${xs[0]} to ${xs[xs.length - 1]}; J = ${chosen}: ${score[k]?.toFixed(4)} m².`);
    svg.lastChild.setAttribute('aria-label', `RMSE and explained fraction for J = ${xs[0]} to ${xs[xs.length - 1]}; J = ${chosen} is marked: score ${score[k]?.toFixed(4)} m², RMSE ${rmse[k]?.toFixed(3)} m, f ${f[k]?.toFixed(3)}.`);
    const nRises = rises.filter(Boolean).length;
    const m2 = (v) => `${v.toFixed(4)} m²`;
    const reading = knee ? `<b>Reading the curve:</b> the score falls from <span class="knee-first">${m2(knee.first.score)}</span> at J = ${knee.first.J} to ` +
      `<span class="knee-best">${m2(knee.best.score)}</span> at best (J = ${knee.best.J}); by <span class="knee-j">J = ${knee.J}</span> (dashed) it has come 90 % of that way. ` +
      `Past the bend, more vertices make the map bigger and slower to match against while it barely improves: for this scan a budget near ${knee.J} is enough. ` : '';
    // lecture mode shows the reading only (the projector's height; the teacher says the rest)
    legend.innerHTML = reading + `<span class="chart-help">` +
      `<span style="color:${COLOUR.f}">f</span> is the fraction of returned beams the map explains (a segment crosses the beam); ` +
      `<span style="color:${COLOUR.rmse}">RMSE</span> is the root mean square of r − r̂ over those beams only, so it can grow while f grows (the map takes on harder beams): the score weighs both. ` +
      `One extractPolylines() call per J; the yellow bar is the J shown (click the chart to choose another).` +
      (nRises ? ` <span style="color:${COLOUR.rise}">Red dots</span>: ${nRises} budget${nRises === 1 ? '' : 's'} where the score is higher than one vertex fewer.` : '') + '</span>';
  };
  // drawn once to lay the panels out, then again at the width their boxes give (and whenever that changes: a new
  // window size, lecture mode)
  const fit = () => {
    const want = widthFor(svg.firstChild);
    if (shown && want !== W) { W = want; render(); }
  };
  const resize = new ResizeObserver(() => requestAnimationFrame(fit));
  resize.observe(svg);
  return {
    update(snaps, k) {
      shown = [snaps, k];
      render();
      fit();
    },
    dispose() { resize.disconnect(); },
  };
}
