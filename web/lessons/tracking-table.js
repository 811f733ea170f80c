// The cost matrix of one association as a table for the teacher: rows = tracks (at their predicted positions),
// columns = the new scan's clusters, cells = distance in metres; cells beyond the gate are greyed (assign() gets the
// gate as their cost), the cells Munkres chose are marked once the association step is reached.
import { clusterColour } from '../figure.js';

export const trackColour = (id) => clusterColour(id - 1);

// The matrix and, beside it, `details` (the lesson's per-track list for the step).
export function costTable(parent) {
  const row = document.createElement('div');
  row.className = 'tracking-stage';
  const box = document.createElement('div');
  box.className = 'cost-matrix';
  box.innerHTML = '<p class="cost-caption"></p><div class="table-wrap"><table><thead></thead><tbody></tbody></table></div>';
  const details = document.createElement('div');
  details.className = 'tracking-details';
  details.setAttribute('aria-live', 'polite');
  row.append(box, details);
  parent.append(row);
  const caption = box.querySelector('.cost-caption'), head = box.querySelector('thead'), body = box.querySelector('tbody');
  const cell = (tag, text, cls) => { const c = document.createElement(tag); c.textContent = text; if (cls) c.className = cls; return c; };

  // step: the snapshot; chosen: whether Munkres' choice is shown (from the association step on)
  function show(step, gate, chosen) {
    const a = step.assoc;
    head.replaceChildren(); body.replaceChildren();
    if (!a) {
      caption.textContent = `Scan ${step.scan}: the first scan has nothing to associate. The cost matrix appears from the next scan on.`;
      return;
    }
    caption.textContent = a.rows && a.cols
      ? `Scan ${step.scan}: distance (m) from each track's prediction to each centroid. Grey: beyond the gate, cost ${gate.toFixed(2)} m.` +
        (chosen ? ` Outlined: Munkres' choice, total cost ${a.total.toFixed(2)} m, the least possible.` : ' Munkres has not chosen yet.')
      : `Scan ${step.scan}: ${a.rows ? 'no clusters' : 'no live tracks'}, nothing to associate.`;
    if (!a.rows || !a.cols) return;
    const hr = document.createElement('tr');
    hr.append(cell('th', 'track \\ cluster'));
    step.clusters.forEach((c) => { const th = cell('th', `C${c.index + 1}`); th.scope = 'col'; th.title = `${c.size} points`; hr.append(th); });
    head.append(hr);
    a.trackIds.forEach((id, i) => {
      const tr = document.createElement('tr');
      const th = cell('th', `T${id}`); th.scope = 'row'; th.style.color = trackColour(id);
      tr.append(th);
      for (let j = 0; j < a.cols; j++) {
        const d = a.distances[i * a.cols + j], gated = d > gate;
        const td = cell('td', d.toFixed(2), gated ? 'gated' : '');
        td.dataset.row = String(i); td.dataset.col = String(j);
        if (chosen && a.columns[i] === j) td.classList.add(gated ? 'dropped' : 'chosen');
        td.title = gated ? `${d.toFixed(3)} m, beyond the gate: cost ${gate.toFixed(2)} m` : `${d.toFixed(3)} m`;
        tr.append(td);
      }
      body.append(tr);
    });
  }
  return { show, details, element: row };
}
