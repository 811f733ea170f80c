// The FTLS and AFTLS lessons (one factory, two methods): the package's vectorize(…, { trace: true }) trace drawn
// event by event, and, for a cluster the vectorizer cannot close within δ, why it fails and what to change
// (strict mode: result.failure; split mode: result.breaks, see api.md / wasm/js/index.d.ts).
//
// Events are drawn from their fields, whatever their kind: a range [first, end) is highlighted, `rms` values of
// the run are plotted against `sigma`, a `crossingDistance` is drawn as the δ circle around point `boundary`, and
// the text names the event and its numbers. Kinds the lesson knows get a sentence of their own (KNOWN below).
import { INK, Scene } from '../figure.js';
import { explainNoSteps, loadExcerpt, pt, readParams, positive, slice, traced } from './common.js';
import { m, mm, numberField } from './ui.js';

const fmtField = (k, v) => (typeof v === 'boolean' ? `${k} ${v ? 'yes' : 'no'}` : Number.isInteger(v) ? `${k} ${v}`
  : /rms|sigma|distance|delta|error/i.test(k) ? `${k} ${mm(v)}` : `${k} ${v.toPrecision(4)}`);

// What the figure marks for a failure or a break: the boundary point, δ around it, and the text with the fix.
export function failureText(f, kind) {
  const finite = Number.isFinite(f.crossingDistance), over = finite && f.crossingDistance > f.delta;
  const raise = finite ? Math.ceil((f.crossingDistance + 0.005) * 100) / 100 : null;
  return `<p class="fail">${kind === 'break' ? 'Split' : 'Failed'} at the corner between points ${f.boundary - 1} and ${f.boundary}: the lines fitted on either side cross ` +
    `${finite ? `${m(f.crossingDistance, 2)} from that boundary (red circle)` : 'nowhere (they are parallel)'}, but δ = ${m(f.delta, 2)} (green circle).</p>` +
    `<p class="fix">Fix: ${over && raise <= 2 ? `<button type="button" class="small" data-fix="delta" data-value="${raise}">raise δ to ${raise.toFixed(2)} m</button> or ` : ''}` +
    (kind === 'break' ? 'keep the split there (split mode is on).' : '<button type="button" class="small" data-fix="split">split the polyline there</button>.') +
    ' A different σ also moves the boundary.</p>';
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
        const corner = (f) => {
          const [ax, ay] = pt(chain, Math.max(0, f.boundary - 1)), [bx, by] = pt(chain, f.boundary), c = [(ax + bx) / 2, (ay + by) / 2];
          s.circle(...c, f.delta, { colour: INK.ok, dash: true });
          if (Number.isFinite(f.crossingDistance)) s.circle(...c, f.crossingDistance, { colour: INK.fail, dash: true });
          s.marker(...c, { colour: INK.fail, shape: 'x', size: 9 });
        };
        for (const b of res.breaks ?? []) corner(b);
        if (res.failure) corner(res.failure);
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
          return { steps: trace.length };
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
          const e = trace[k];
          if (e.first !== undefined && e.end !== undefined) s.points(slice(chain, e.first, e.end), { label: -1, colour: e.fits === false || e.ok === false || e.pass === false ? INK.fail : INK.candidate, radius: 3.5 });
          if (e.boundary !== undefined && e.delta !== undefined) s.circle(...pt(chain, e.boundary), e.delta, { colour: e.crossingDistance > e.delta ? INK.fail : INK.ok, dash: true });
          if (e.index !== undefined) s.marker(...pt(chain, e.index), { colour: INK.current });
          // the RMS of the trials of this run (events with rms and the same first), against σ
          if (e.rms !== undefined && e.first !== undefined) {
            const run = trace.slice(0, k + 1).filter((t) => t.rms !== undefined && t.first === e.first && t.end !== undefined);
            if (run.length) s.setInset({ title: `RMS of trial ranges from point ${e.first}`, xs: run.map((t) => t.end - t.first), ys: run.map((t) => t.rms), ok: run.map((t) => t.rms < (t.sigma ?? params.sigma)), hline: params.sigma, hlabel: 'σ', xlabel: 'points in the trial range' });
          }
          const fieldsText = Object.entries(e).filter(([f]) => f !== 'kind').map(([f, v]) => fmtField(f, v)).join(', ');
          let html = `<p><b>${e.kind}</b>: ${fieldsText}.</p>`;
          if (k === trace.length - 1) { drawResult(s, untraced); html += resultText(untraced); }
          host.figure.show(s);
          host.text.innerHTML = html;
        },
        finalState() {
          return { method, chain: Array.from(chain), params: params && { ...params, split: split.checked }, step: this.step ?? -1, steps: trace.length,
            untraced: untraced && { ok: untraced.ok, count: untraced.count, indices: Array.from(untraced.indices), segments: Array.from(untraced.segments), failure: untraced.failure ?? null, breaks: untraced.breaks ?? [] } };
        },
        dispose() { host.text.removeEventListener('click', onFix); },
      };
    },
  };
}
