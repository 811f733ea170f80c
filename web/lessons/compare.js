// The five vectorizers side by side on one cluster (the player steps through the methods): segments, vertices,
// RMS per segment and the total squared residual against the segment count, with a text computed from the same
// table (no method is called better unless it has fewer or as many segments AND less residual).
import { INK, Scene } from '../figure.js';
import { readParams, positive } from './common.js';
import { mm, note, numberField } from './ui.js';

const METHODS = [['ftls', 'FTLS'], ['aftls', 'AFTLS'], ['itls', 'ITLS'], ['dp', 'Douglas–Peucker'], ['rw', 'Reumann–Witkam']];
const SCAN = { dataset: 'intel', scan: 17, segment: { step: 3, lowerBound: 0.1, upperBound: 0.5 }, minPoints: 10, start: 0 };

function measure(chain, v) {
  const n = chain.length / 2;
  let ssr = 0, covered = 0;
  const rms = Array.from(v.rms);
  for (let k = 0; k < v.count; k++) {
    const c = v.indices[2 * k + 1] - v.indices[2 * k];
    if (Number.isFinite(rms[k])) { ssr += rms[k] ** 2 * c; covered += c; }
  }
  const ends = new Set();
  for (let i = 0; i < v.segments.length; i += 2) ends.add(`${v.segments[i]},${v.segments[i + 1]}`);
  return { segments: v.count, vertices: ends.size, rmsMean: rms.length ? rms.reduce((a, b) => a + b, 0) / rms.length : NaN,
    rmsMax: rms.length ? Math.max(...rms) : NaN, ssr, rmsAll: covered ? Math.sqrt(ssr / covered) : NaN, ok: v.ok, n };
}

export default {
  id: 'compare',
  menu: 'Compare',
  title: 'Compare the methods',
  summary: 'The same cluster and tolerances for all five vectorizers: how many segments each needs, and how well they fit.',
  async create(host) {
    const SRC = host.source ?? SCAN;
    const scan = await host.data.scan(SRC.dataset, SRC.scan);
    const { clusters } = host.rtl.segment(scan.points, SCAN.segment);
    const all = clusters.map((c, k) => ({ k, indices: Array.from(c.indices) }));
    // a small scan of the user's may have no cluster of minPoints: then every cluster of 3 or more
    let big = all.filter((c) => c.indices.length >= SCAN.minPoints);
    if (!big.length) big = all.filter((c) => c.indices.length >= 3);
    if (!big.length) throw new RangeError(`${host.data.describe(SRC.dataset, SRC.scan)} has no cluster of 3 or more points`);
    note(host.controls, `<strong>Excerpt:</strong> ${host.data.describe(SRC.dataset, SRC.scan)}, segmented with step 3, bounds 0.1–0.5 m; pick a cluster (list, or click it in the figure). ${host.source ? 'Your chosen scan.' : 'The room corner of beams 0–32 starts selected: it has bends, so the methods disagree (on a straight wall they all give one segment).'}`);
    const wrap = document.createElement('div');
    wrap.className = 'field wide';
    wrap.innerHTML = '<label for="cmp-cluster">cluster</label><select id="cmp-cluster" name="cluster"></select>';
    const select = wrap.querySelector('select');
    for (const c of big) { const o = document.createElement('option'); o.value = String(c.k); o.textContent = `cluster ${c.k + 1}: ${c.indices.length} points, beams ${c.indices[0]}–${c.indices[c.indices.length - 1]}`; select.append(o); }
    select.value = String((big.find((c) => c.indices[0] === SCAN.start) ?? big[0]).k);
    select.addEventListener('input', () => { pickCluster(); host.onParamsChanged(); });
    host.controls.append(wrap);
    const fields = {
      sigma: numberField(host.controls, { key: 'sigma', label: 'σ (FTLS, AFTLS, ITLS)', value: 0.03, min: 0.005, max: 0.2, step: 0.005, unit: 'm', onInput: host.onParamsChanged }),
      delta: numberField(host.controls, { key: 'delta', label: 'δ (FTLS, AFTLS)', value: 0.3, min: 0.01, max: 2, step: 0.01, unit: 'm', digits: 2, onInput: host.onParamsChanged }),
      epsilon: numberField(host.controls, { key: 'epsilon', label: 'ε (DP, RW)', value: 0.03, min: 0.005, max: 0.4, step: 0.005, unit: 'm', onInput: host.onParamsChanged }),
    };
    let chain = null, rows = [], results = [], params = null;
    const pickCluster = () => {
      const c = big.find((b) => String(b.k) === select.value);
      chain = host.data.gather(scan.points, c.indices);
      host.figure.fitPoints(chain);
    };
    pickCluster();
    host.figure.onPick = (x, y) => {
      let best = null, bd = (12 / host.figure.scale) ** 2;
      for (const c of big) for (const i of c.indices) { const d = (scan.points[2 * i] - x) ** 2 + (scan.points[2 * i + 1] - y) ** 2; if (d < bd) { bd = d; best = c; } }
      if (best) { select.value = String(best.k); pickCluster(); host.onParamsChanged(); }
    };
    const table = document.createElement('div');
    table.className = 'table-wrap';
    table.innerHTML = `<table><caption class="visually-hidden">The five methods on the selected cluster</caption><thead><tr><th scope="col">method</th><th scope="col">segments</th><th scope="col">vertices</th>
      <th scope="col">RMS per segment<br>(mean / max)</th><th scope="col">total squared<br>residual</th><th scope="col">RMS over<br>all points</th></tr></thead><tbody></tbody></table>`;
    const verdict = document.createElement('p');
    verdict.className = 'verdict';
    host.stage.append(table, verdict);
    table.querySelector('tbody').addEventListener('click', (ev) => { const tr = ev.target.closest('tr'); if (tr) host.goTo(Number(tr.dataset.k)); });
    table.querySelector('tbody').addEventListener('keydown', (ev) => { if (ev.key === 'Enter' || ev.key === ' ') { const tr = ev.target.closest('tr'); if (tr) { ev.preventDefault(); host.goTo(Number(tr.dataset.k)); } } });

    function writeVerdict() {
      const ok = rows.filter((r) => r.ok && r.segments > 0);
      // Pareto front: no other method has <= segments and < residual (or < segments and <= residual).
      // residuals equal to 1 part in 1e6 count as equal (the same partition fitted in a different order)
      const less = (a, b) => a < b - 1e-6 * Math.max(a, b), leq = (a, b) => !less(b, a);
      const front = ok.filter((r) => !ok.some((o) => o !== r && o.segments <= r.segments && leq(o.ssr, r.ssr) && (o.segments < r.segments || less(o.ssr, r.ssr))));
      const failed = rows.filter((r) => !r.ok).map((r) => r.name);
      verdict.textContent = `Fewest segments: ${ok.length ? Math.min(...ok.map((r) => r.segments)) : '–'}. ` +
        `Not beaten on both counts (fewer or as many segments and less total squared residual): ${front.map((r) => r.name).join(', ') || '–'}. ` +
        'A lower RMS bought with more segments is not a better fit, only a finer one.' + (failed.length ? ` Failed on this cluster: ${failed.join(', ')} (see their lessons for why).` : '');
    }

    return {
      recompute() {
        params = readParams(fields, (v) => Object.fromEntries(Object.entries(v).map(([k, x]) => [k, positive(x)]).filter(([, e]) => e)));
        if (!params) { rows = []; return { steps: 0 }; }
        results = METHODS.map(([method]) => host.rtl.vectorize(chain, { method, sigma: params.sigma, delta: params.delta, epsilon: params.epsilon }));
        rows = results.map((v, k) => ({ method: METHODS[k][0], name: METHODS[k][1], ...measure(chain, v) }));
        table.querySelector('tbody').replaceChildren(...rows.map((r, k) => {
          const tr = document.createElement('tr');
          tr.dataset.k = String(k);
          tr.tabIndex = 0;
          for (const t of [r.name, r.ok ? String(r.segments) : 'failed', r.ok ? String(r.vertices) : '–', `${mm(r.rmsMean)} / ${mm(r.rmsMax)}`, `${(r.ssr * 1e6).toFixed(0)} mm²`, mm(r.rmsAll)]) {
            const td = document.createElement('td'); td.textContent = t; tr.append(td);
          }
          return tr;
        }));
        writeVerdict();
        return { steps: METHODS.length };
      },
      show(k) {
        this.step = k;
        const s = new Scene(`Compare: ${METHODS[Math.max(k, 0)][1]} on cluster ${Number(select.value) + 1} of ${host.data.describe(SRC.dataset, SRC.scan)}`);
        s.points(chain, { label: 0 });
        if (k >= 0) {
          s.segments(results[k].segments, { colour: INK.segment, width: 2.5, q: 'segments' });
          // the segments' end points, as markers (screen only: the export keeps the cluster's points alone)
          const seg = results[k].segments;
          for (let i = 0; i + 1 < seg.length; i += 2) s.marker(seg[i], seg[i + 1], { colour: INK.current, shape: 'dot', size: 6, q: 'vertices' });
        }
        host.figure.show(s);
        for (const tr of table.querySelectorAll('tbody tr')) tr.classList.toggle('current', Number(tr.dataset.k) === k);
        const r = rows[k];
        host.text.innerHTML = r ? `<p><b>${r.name}</b>: ${r.ok ? `<span data-q="segments">${r.segments} segments</span>, <span data-q="vertices">${r.vertices} vertices</span>, total squared residual ${(r.ssr * 1e6).toFixed(0)} mm² (RMS over all points ${mm(r.rmsAll)})` : 'failed on this cluster'}.</p><p class="why">Step through the methods (or pick a table row); the table below the figure compares them all.</p>` : '';
      },
      finalState() { return { method: 'compare', rows: rows.map((r) => ({ ...r })), verdict: verdict.textContent, params, cluster: Number(select.value), step: this.step ?? -1, steps: rows.length ? METHODS.length : 0 }; },
      dispose() {},
    };
  },
};
