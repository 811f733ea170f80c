// Development stand-in for the page's 2D figure (web/figure.js), used only by the test pages in web/view3d/dev
// until the real figure is mounted: a canvas with a world extent (y up, equal scale) and world <-> screen mapping.
export function createStandinFigure(container) {
  const canvas = document.createElement('canvas');
  canvas.tabIndex = 0;
  canvas.className = 'standin-figure';
  container.append(canvas);
  const ctx = canvas.getContext('2d');
  let extent = [-1, -1, 1, 1], scale = 1, ox = 0, oy = 0;
  const fit = () => {
    const w = container.clientWidth || 600, h = Math.round(Math.min(w * 0.7, 480));
    canvas.width = w; canvas.height = h;
    const [x0, y0, x1, y1] = extent, pad = 24;
    scale = Math.min((w - 2 * pad) / Math.max(1e-9, x1 - x0), (h - 2 * pad) / Math.max(1e-9, y1 - y0));
    ox = w / 2 - scale * (x0 + x1) / 2; oy = h / 2 + scale * (y0 + y1) / 2;
  };
  return {
    canvas, ctx,
    setExtent(x0, y0, x1, y1) { extent = [x0, y0, x1, y1]; fit(); },
    clear() { fit(); ctx.fillStyle = '#fff'; ctx.fillRect(0, 0, canvas.width, canvas.height); },
    toScreen: (x, y) => [ox + scale * x, oy - scale * y],
    toWorld: (px, py) => [(px - ox) / scale, (oy - py) / scale],
    get scale() { return scale; },
  };
}
