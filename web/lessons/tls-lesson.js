// The FTLS and AFTLS lessons (one factory, two methods): the package's vectorize(…, { trace: true }) trace drawn
// event by event, and, for a cluster the vectorizer cannot close within δ, why it fails and what to change
// (strict mode: result.failure; split mode: result.breaks, see wasm/js/index.d.ts).
//
// Events are drawn from their fields, whatever their kind: a range [first, end) is highlighted, `rms` values of
// the run are plotted against `sigma`, a `crossingDistance` is drawn as the δ circle around point `boundary`, and
// the text names the event and its numbers. Kinds the lesson knows get a sentence of their own (KNOWN below).
import { INK, Scene } from '../figure.js';
import { explainNoSteps, loadExcerpt, pt, readParams, positive, slice, traced } from './common.js';
import { m, mm, numberField } from './ui.js';
import { cornerQuestions } from './predict-questions.js';

const fmtField = (k, v) => (typeof v === 'boolean' ? `${k} ${v ? 'yes' : 'no'}` : Number.isInteger(v) ? `${k} ${v}`
  : /rms|sigma|distance|delta|error/i.test(k) ? `${k} ${mm(v)}` : `${k} ${v.toPrecision(4)}`);

// What the figure marks for a failure or a break: the boundary point, δ around it, and the text with the fix.
export function failureText(f, kind) {
  const finite = Number.isFinite(f.crossingDistance), over = finite && f.crossingDistance > f.delta;
  const raise = finite ? Math.ceil((f.crossingDistance + 0.005) * 100) / 100 : null;
  return `<p class="fail">${kind === 'break' ? 'Split' : 'Failed'} at the corner between points ${f.boundary - 1} and ${f.boundary}: the lines fitted on either side cross ` +
    `${finite ? `<span data-q="crossing">${m(f.crossingDistance, 2)} from that boundary (red circle)</span>` : 'nowhere (they are parallel)'}, but <span data-q="delta">δ = ${m(f.delta, 2)} (green circle)</span>.</p>` +
    `<p class="fix">Fix: ${over && raise <= 2 ? `<button type="button" class="small" data-fix="delta" data-value="${raise}">raise δ to ${raise.toFixed(2)} m</button> or ` : ''}` +
    (kind === 'break' ? 'keep the split there (split mode is on).' : '<button type="button" class="small" data-fix="split">split the polyline there</button>.') +
    ' A different σ also moves the boundary.</p>';
}

const PHASE = ['Whole remainder', 'Gallop', 'Bisection', 'Tail adjustment'];
const REPAIR = { 1: 'move the boundary', 2: 'merge the two ranges', 3: 'three equal parts', 4: 're-partition a window', 5: 'exact search over the whole chain', 6: 'split-mode search', 7: 'unchecked bridge' };

// The partitions after events 0..k (the replay of rtl/vect/FtlsTrace.h): ranges[0] FTLS, ranges[1] AFTLS's
// optimized copy; result = the partition the call returns (empty after a strict `infeasible`).
export function replay(trace, k) {
  const ranges = [[], null];
  let kept = null, split = false, infeasible = false, into = 0;
  const segments = [];
  const branchOf = (b) => { if (b === 1 && !ranges[1]) ranges[1] = ranges[0].map((x) => x.slice()); return b; };
  const sortRanges = (b) => ranges[b].sort((x, y) => x[0] - y[0]);
  for (let i = 0; i <= k && i < trace.length; i++) {
    const e = trace[i];
    if (e.kind === 'start') split = e.split;
    else if (e.kind === 'range') { ranges[0] = ranges[0].filter((x) => x[1] <= e.first); ranges[0].push([e.first, e.end]); }
    else if (e.kind === 'repair') { const b = branchOf(e.branch); ranges[b] = ranges[b].filter((x) => x[1] <= e.first || x[0] >= e.end); into = b; infeasible = false; }
    else if (e.kind === 'repairRange') { ranges[into].push([e.first, e.end]); sortRanges(into); }
    else if (e.kind === 'move') { const b = branchOf(1); ranges[b][e.breakpoint - 1][1] = e.to; ranges[b][e.breakpoint][0] = e.to; }
    else if (e.kind === 'corner') branchOf(e.branch);
    else if (e.kind === 'choice') kept = e.kept;
    else if (e.kind === 'infeasible') infeasible = !split;
    else if (e.kind === 'segment') segments.push(e);
  }
  const result = infeasible ? [] : (ranges[kept ?? 0] ?? ranges[0]);
  return { ranges, kept, result, segments };
}

export function tlsLesson({ id, menu, title, summary, method, excerpt, extra = () => ({}) }) {
  return {
    id, menu, title, summary,
    async create(host) {
      const { chain, where } = await loadExcerpt(host, excerpt);
      const fields = {
        sigma: numberField(host.controls, { key: 'sigma', label: 'σ: max RMS distance', value: excerpt.sigma ?? 0.03, min: 0.005, max: 0.2, step: 0.005, unit: 'm', onInput: host.onParamsChanged }),
        delta: numberField(host.controls, { key: 'delta', label: 'δ: corner tolerance', value: excerpt.delta ?? 0.3, min: 0.01, max: 2, step: 0.01, unit: 'm', digits: 2, onInput: host.onParamsChanged }),
      };
      const splitWrap = document.createElement('label');
      splitWrap.className = 'check wide';
      splitWrap.innerHTML = '<input type="checkbox" name="split"> split where a corner fails (off: RTL\'s strict mode, the whole cluster fails)';
      const split = splitWrap.querySelector('input');
      split.checked = excerpt.split ?? false;
      split.addEventListener('input', host.onParamsChanged);
      host.controls.append(splitWrap);
      host.figure.fitPoints(chain);
      let missing = null, trace = [], untraced = null, params = null;
      const options = () => ({ method, sigma: params.sigma, delta: params.delta, split: split.checked, ...extra(params) });
      const hasSplit = () => untraced && 'failure' in untraced;

      const drawResult = (s, res) => {
        s.segments(res.segments, { colour: INK.segment, width: 2.5 });
        // a failed corner: δ around the boundary point (allowed) and the circle on which the crossing lies
        // (the package measures the crossing from the midpoint of points boundary - 1 and boundary)
        for (const b of res.breaks ?? []) failedCorner(s, b);
        if (res.failure) failedCorner(s, res.failure);
      };
      const failedCorner = (s, f) => {
        const [ax, ay] = pt(chain, Math.max(0, f.boundary - 1)), [bx, by] = pt(chain, f.boundary), c = [(ax + bx) / 2, (ay + by) / 2];
        s.circle(...c, f.delta, { colour: INK.ok, dash: true, q: 'delta' });
        if (Number.isFinite(f.crossingDistance)) s.circle(...c, f.crossingDistance, { colour: INK.fail, dash: true, q: 'crossing' });
        s.marker(...c, { colour: INK.fail, shape: 'x', size: 9 });
      };
      const resultText = (res) => {
        let html = res.ok ? `<p>${res.count} segments${res.polylineOffsets && res.polylineOffsets.length > 2 ? ` in ${res.polylineOffsets.length - 1} polylines` : ''}, RMS ${Array.from(res.rms).map((r) => mm(r)).join(', ')}.</p>` : '<p class="fail">The vectorizer reports failure: no segments for this cluster.</p>';
        if (res.failure) html += failureText(res.failure, 'failure');
        for (const b of res.breaks ?? []) html += failureText(b, 'break');
        if (!hasSplit()) html += '<p class="why">(This build of the package does not report failure reasons or split mode yet.)</p>';
        return html;
      };

      const onFix = (ev) => {
        const b = ev.target.closest('[data-fix]');
        if (!b) return;
        if (b.dataset.fix === 'delta') fields.delta.set(Number(b.dataset.value)); else split.checked = true;
        host.onParamsChanged();
      };
      host.text.addEventListener('click', onFix);
      return {
        predict: cornerQuestions({ get trace() { return trace; } }, chain),
        recompute() {
          params = readParams(fields, ({ sigma, delta }) => {
            const out = {};
            if (positive(sigma)) out.sigma = positive(sigma);
            if (positive(delta)) out.delta = positive(delta);
            return out;
          });
          if (!params) { trace = []; missing = null; untraced = null; return { steps: 0 }; }
          let opts = options();
          try { untraced = host.rtl.vectorize(chain, opts); } catch (e) {
            if (!/unknown option "split"/.test(e.message)) throw e;
            delete opts.split;                       // an older package: strict mode only
            untraced = host.rtl.vectorize(chain, opts);
          }
          ({ trace, missing } = traced(() => host.rtl.vectorize(chain, { ...opts, trace: true }), title));
          // a failed cluster: show the step where it fails (the reason and the fix are there)
          const failedAt = trace.findIndex((t) => t.kind === 'infeasible');
          return { steps: trace.length, ...(untraced.failure && failedAt >= 0 ? { jump: failedAt } : {}) };
        },
        show(k) {
          this.step = k;
          const s = new Scene(`${title}, σ = ${params?.sigma ?? '–'} m, δ = ${params?.delta ?? '–'} m: ${where}`);
          s.points(chain, { label: 0 });
          if (k < 0 || !untraced) {
            if (untraced) drawResult(s, untraced);
            host.figure.show(s);
            host.text.innerHTML = untraced ? resultText(untraced) : '';
            if (missing || !params) { const p = document.createElement('div'); host.text.prepend(p); explainNoSteps({ text: p }, missing); }
            return;
          }
          const e = trace[k], r = replay(trace, k);
          // the ranges of the branch this step works on, coloured by range
          const branch = e.branch ?? (e.kind === 'move' ? 1 : r.kept ?? 0);
          (r.ranges[branch] ?? r.ranges[0]).forEach(([a, b], q) => s.points(slice(chain, a, b), { label: q + 1 }));
          s.segments(r.segments.flatMap((g) => [g.x0, g.y0, g.x1, g.y1]), { colour: INK.segment, width: 2.5 });
          const mid = (b) => { const [ax, ay] = pt(chain, Math.max(0, b - 1)), [bx, by] = pt(chain, b); return [(ax + bx) / 2, (ay + by) / 2]; };
          let html;
          switch (e.kind) {
            case 'start':
              html = `<p>${e.count} points, σ = ${mm(e.sigma)}, δ = ${m(e.delta, 2)}${e.aftls ? '; AFTLS: after FTLS an optimizer moves the breakpoints (branch 1) and the better partition is kept' : ''}${e.split ? '; split mode: an impossible corner breaks the polyline' : '; strict mode: an impossible corner fails the cluster'}.</p>`;
              break;
            case 'trial': {
              const rms = Math.sqrt(e.meanSquaredError);
              s.points(slice(chain, e.first, e.end), { label: -1, colour: e.pass ? INK.ok : INK.fail, radius: 3.5, q: 'trial' });
              const run = trace.slice(0, k + 1).filter((t) => t.kind === 'trial' && t.first === e.first);
              s.setInset({ title: `RMS of trial ranges from point ${e.first}`, xs: run.map((t) => t.end - t.first), ys: run.map((t) => Math.sqrt(t.meanSquaredError)), ok: run.map((t) => t.pass), hline: e.sigma, hlabel: 'σ', xlabel: 'points in the trial range', yformat: (y) => mm(y) });
              html = `<p>${PHASE[e.phase] ?? 'Trial'}: <span data-q="trial">points <b>${e.first}–${e.end - 1}</b> (${e.end - e.first} points)</span> fitted with one line: RMS ${mm(rms)} ${e.pass ? '&lt;' : '≥'} σ = ${mm(e.sigma)} — ${e.pass ? 'pass' : 'fail'}.</p>` +
                `<p class="why">${e.phase === 1 ? 'Doubling the length finds, in a few fits, a range that is too long.' : e.phase === 2 ? 'Halving the interval between the last passing and the first failing end finds the longest passing range.' : e.phase === 0 ? 'If the whole rest of the chain fits one line, the search is over.' : 'A single point left at the end is joined to its neighbour range.'} Each fit costs O(1) from prefix sums.</p>`;
              break;
            }
            case 'range':
              s.points(slice(chain, e.first, e.end), { label: -1, colour: INK.ok, radius: 3.5, q: 'range' });
              html = `<p><span data-q="range">Range <b>${e.first}–${e.end - 1}</b></span> is accepted: the longest run from point ${e.first} whose fit stays under σ. The next run starts at point ${e.end}.</p>`;
              break;
            case 'corner': {
              const c = mid(e.boundary);
              s.circle(...c, e.delta, { colour: INK.ok, dash: true, q: 'delta' });
              if (Number.isFinite(e.crossingDistance)) s.circle(...c, e.crossingDistance, { colour: e.ok ? INK.candidate : INK.fail, dash: true, q: 'crossing' });
              s.marker(...c, { colour: e.ok ? INK.ok : INK.fail, shape: 'x', q: 'boundary' });
              html = `<p>Continuity check of the corner between ranges ${e.index + 1} and ${e.index + 2}${branch ? ' (AFTLS branch)' : ''}, at <span data-q="boundary">points ${e.boundary - 1}|${e.boundary}</span>: the two lines cross ${Number.isFinite(e.crossingDistance) ? `<span data-q="crossing">${m(e.crossingDistance)} from there</span>` : 'nowhere (parallel)'}, <span data-q="delta">δ = ${m(e.delta, 2)}</span> — ${e.ok ? 'ok, the crossing becomes a vertex' : 'too far: this corner needs a repair'}.</p>`;
              break;
            }
            case 'repair':
              s.points(slice(chain, e.first, e.end), { label: -1, colour: INK.current, radius: 3.5 });
              html = `<p>Repair (${REPAIR[e.method] ?? `method ${e.method}`}): the ranges inside points ${e.first}–${e.end - 1} are replaced by ${e.inserted} new range${e.inserted === 1 ? '' : 's'}.</p>`;
              break;
            case 'repairRange': html = `<p>New range <b>${e.first}–${e.end - 1}</b> from the repair.</p>`; break;
            case 'move': {
              const moves = trace.slice(0, k + 1).filter((t) => t.kind === 'move');
              s.setInset({ title: 'total squared residual after each move', xs: moves.map((_, q) => q + 1), ys: moves.map((t) => t.totalError), xlabel: 'optimizer moves', yformat: (y) => `${(y * 1e6).toFixed(0)} mm²` });
              s.marker(...pt(chain, e.to), { colour: INK.current, q: 'moved' });
              html = `<p>Optimizer: breakpoint ${e.breakpoint} moves from point ${e.from} to <b data-q="moved">${e.to}</b>; total squared residual now ${(e.totalError * 1e6).toFixed(0)} mm².</p>`;
              break;
            }
            case 'choice':
              html = `<p>AFTLS compares both partitions: FTLS ${Number.isFinite(e.ftlsError) ? `${(e.ftlsError * 1e6).toFixed(0)} mm²` : 'no valid result'}, optimized ${Number.isFinite(e.aftlsError) ? `${(e.aftlsError * 1e6).toFixed(0)} mm²` : 'no valid result'} — it keeps ${e.kept ? 'the optimized one' : 'FTLS\'s'}.</p>`;
              break;
            case 'infeasible':
              failedCorner(s, e);
              html = failureText(e, 'failure');
              break;
            case 'segment':
              s.segments([e.x0, e.y0, e.x1, e.y1], { colour: INK.current, width: 3, q: 'segment' });
              html = `<p><span data-q="segment">Segment ${e.index + 1}</span> (points ${e.first}–${e.end - 1}${r.segments.some((g) => g.polyline > 0) ? `, polyline ${e.polyline + 1}` : ''}): between the crossings with its neighbours' lines.</p>`; break;
            default: html = `<p><b>${e.kind}</b>: ${Object.entries(e).filter(([f]) => f !== 'kind').map(([f, v]) => fmtField(f, v)).join(', ')}.</p>`;
          }
          if (k === trace.length - 1) { drawResult(s, untraced); html += resultText(untraced); }
          host.figure.show(s);
          host.text.innerHTML = html + '<p class="legend">Figure: colours = the current ranges, green/red points = a trial that passes/fails, circles at a corner: δ (green) and where the lines cross (blue ok, red too far); inset = RMS against σ.</p>';
        },
        finalState() {
          const r = replay(trace, this.step ?? -1);
          return { method, chain: Array.from(chain), params: params && { ...params, split: split.checked }, step: this.step ?? -1, steps: trace.length,
            replayed: { ranges: r.result.flat(), segments: r.segments.flatMap((g) => [g.x0, g.y0, g.x1, g.y1]), polylines: r.segments.map((g) => g.polyline) },
            untraced: untraced && { ok: untraced.ok, count: untraced.count, indices: Array.from(untraced.indices), segments: Array.from(untraced.segments), failure: untraced.failure ?? null, breaks: untraced.breaks ?? [] } };
        },
        dispose() { host.text.removeEventListener('click', onFix); },
      };
    },
  };
}
