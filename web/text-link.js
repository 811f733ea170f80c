// Text and figure linked both ways. A quantity in the explanation is an element with `data-q="name"` (e.g. the
// farthest point's distance); the figure's items that draw it carry `q: "name"` (web/figure.js). Hovering or focusing
// the words highlights those items; hovering such an item in the figure marks the words (class "hot").
const NEAR = 7;   // CSS px: how close the pointer must be to a point, a line or a circle's rim

// Squared distance (CSS px²) from (px, py) to the screen segment a–b.
function toSegment2(px, py, ax, ay, bx, by) {
  const dx = bx - ax, dy = by - ay, l2 = dx * dx + dy * dy;
  const t = l2 ? Math.max(0, Math.min(1, ((px - ax) * dx + (py - ay) * dy) / l2)) : 0;
  return (px - ax - t * dx) ** 2 + (py - ay - t * dy) ** 2;
}

// The quantity of the topmost item with a `q` under canvas point (px, py) (CSS px), or null.
export function quantityAt(figure, px, py) {
  const items = figure.scene.items, S = (x, y) => figure.toScreen(x, y), n2 = NEAR * NEAR;
  for (let k = items.length - 1; k >= 0; k--) {
    const it = items[k];
    if (!it.q) continue;
    let hit = false;
    if (it.type === 'points') {
      for (let i = 0; i + 1 < it.xy.length && !hit; i += 2) { const [x, y] = S(it.xy[i], it.xy[i + 1]); hit = (x - px) ** 2 + (y - py) ** 2 <= n2; }
    } else if (it.type === 'marker' || it.type === 'label') {
      const [x, y] = S(it.x, it.y); hit = (x - px) ** 2 + (y - py) ** 2 <= (NEAR + (it.size ?? 7)) ** 2;
    } else if (it.type === 'segments') {
      for (let i = 0; i + 3 < it.xy.length && !hit; i += 4) { const [ax, ay] = S(it.xy[i], it.xy[i + 1]), [bx, by] = S(it.xy[i + 2], it.xy[i + 3]); hit = toSegment2(px, py, ax, ay, bx, by) <= n2; }
    } else if (it.type === 'polyline') {
      for (let i = 0; i + 3 < it.xy.length && !hit; i += 2) { const [ax, ay] = S(it.xy[i], it.xy[i + 1]), [bx, by] = S(it.xy[i + 2], it.xy[i + 3]); hit = toSegment2(px, py, ax, ay, bx, by) <= n2; }
    } else if (it.type === 'circle') {
      const [x, y] = S(it.x, it.y), r = it.r * figure.view.scale / figure.view.dpr; hit = Math.abs(Math.hypot(x - px, y - py) - r) <= NEAR;
    } else if (it.type === 'strip') {
      const [ax, ay] = S(it.x0, it.y0), [bx, by] = S(it.x1, it.y1), half = it.half * figure.view.scale / figure.view.dpr;
      hit = toSegment2(px, py, ax, ay, bx, by) <= half * half;
    }
    if (hit) return it.q;
  }
  return null;
}

// Wires the explanation `text` and the figure `figure()` (the open lesson's) together; returns { current() } for tests.
export function wireTextLink(text, figure) {
  let fromFigure = null;
  const mark = (name) => {
    for (const el of text.querySelectorAll('[data-q]')) el.classList.toggle('hot', el.dataset.q === name);
  };
  const fromText = (ev) => {
    const el = ev.target.closest?.('[data-q]');
    figure()?.highlight(el ? el.dataset.q : null);
    mark(el ? el.dataset.q : null);
  };
  text.addEventListener('pointerover', fromText);
  text.addEventListener('focusin', fromText);
  text.addEventListener('pointerleave', () => { figure()?.highlight(null); mark(null); });
  text.addEventListener('focusout', () => { figure()?.highlight(null); mark(null); });
  // the figure: listen on the canvas box (the canvas is replaced per lesson)
  const box = document.getElementById('canvas-box');
  box.addEventListener('pointermove', (ev) => {
    const fig = figure();
    if (!fig?.view) return;
    const r = fig.canvas.getBoundingClientRect();
    const name = quantityAt(fig, ev.clientX - r.left, ev.clientY - r.top);
    if (name === fromFigure) return;
    fromFigure = name;
    fig.highlight(name);
    mark(name);
  });
  box.addEventListener('pointerleave', () => { fromFigure = null; figure()?.highlight(null); mark(null); });
  // new text (a new step): quantities are focusable, so the keyboard reaches them too
  new MutationObserver(() => {
    for (const el of text.querySelectorAll('[data-q]:not([tabindex])')) el.tabIndex = 0;
    if (fromFigure) mark(fromFigure);
  }).observe(text, { childList: true, subtree: true });
  return { current: () => figure()?.highlighted ?? null };
}
