// The 2D figure: a canvas showing world coordinates (metres, y up, one scale for both axes) with zoom and pan.
// A lesson describes what to draw as a scene (a list of items in world units, see Scene below); the figure keeps
// the scene, so zoom, pan and resize redraw it without the lesson, and export.js turns the same scene into the
// package's SVG/TikZ (same view, colours and title).

import { palette, unlabelledColour } from 'rtl-wasm';

// The package's drawing palette: cluster k gets palette[k % palette.length] on screen and in the package's exports.
export const PALETTE = palette;
export const UNLABELLED = unlabelledColour;
export const clusterColour = (k) => (k >= 0 ? PALETTE[k % PALETTE.length] : UNLABELLED);
// Colours of the teaching overlays (not exported in colour: the package's SVG draws every segment black).
export const INK = { segment: '#111111', current: '#D55E00', candidate: '#0072B2', ok: '#009E73', fail: '#C0392B', muted: '#9aa3af' };

// A scene: items drawn in order. Every item is plain data in world units:
//   { type: 'points', xy, label?, colour?, radius? }      label: cluster number for the export colour (-1 grey)
//   { type: 'segments', xy (x0,y0,x1,y1,...), colour?, width?, dash? }
//   { type: 'polyline', xy, colour?, width?, dash? }
//   { type: 'circle', x, y, r, colour?, fill?, dash? }     r in metres
//   { type: 'strip', x0, y0, x1, y1, half, colour?, bounded? } the band of half-width `half` around the line through
//                                                         both points (bounded: only between them)
//   { type: 'marker', x, y, colour?, size?, shape? }       a highlighted point (size in CSS px), shape 'ring' | 'dot' | 'x'
//   { type: 'label', x, y, text, colour?, bold?, offset? }  offset: [dx, dy] CSS px from the point (default 6, -6)
// Any item may carry `q: name`, the quantity of the explanation it draws (web/text-link.js): the figure draws the
// items of its highlighted quantity over a halo.
// and optionally one `inset` chart in screen space: { title, xs, ys, ok (bool per value), hline, hlabel, xlabel, yformat }.
export class Scene {
  constructor(title = '') { this.title = title; this.items = []; this.inset = null; }
  add(item) { this.items.push(item); return this; }
  points(xy, opts = {}) { return this.add({ type: 'points', xy, ...opts }); }
  segments(xy, opts = {}) { return this.add({ type: 'segments', xy, ...opts }); }
  polyline(xy, opts = {}) { return this.add({ type: 'polyline', xy, ...opts }); }
  circle(x, y, r, opts = {}) { return this.add({ type: 'circle', x, y, r, ...opts }); }
  strip(x0, y0, x1, y1, half, opts = {}) { return this.add({ type: 'strip', x0, y0, x1, y1, half, ...opts }); }
  marker(x, y, opts = {}) { return this.add({ type: 'marker', x, y, ...opts }); }
  label(x, y, text, opts = {}) { return this.add({ type: 'label', x, y, text, ...opts }); }
  setInset(chart) { this.inset = chart; return this; }
}

// The same item, wider and in the halo colour, drawn under it when its quantity is highlighted.
const HALO = '#FFC400';
function haloOf(it) {
  const h = { ...it, colour: HALO, dash: false, width: (it.width ?? 1.5) + 6 };
  if (it.type === 'points') h.radius = (it.radius ?? 2.5) + 3.5;
  if (it.type === 'marker') { h.size = (it.size ?? 7) + 3; h.shape = it.shape === 'x' ? 'x' : 'dot'; }
  if (it.type === 'label') { h.bold = true; h.glow = true; }
  if (it.type === 'strip') h.colour = '#FFC400';
  if (it.type === 'circle') h.fill = undefined;
  return h;
}

// The two ends, far outside any view, of the line through (x0, y0) and (x1, y1) (for strips and unbounded lines).
export function lineThrough(x0, y0, x1, y1, reach) {
  const dx = x1 - x0, dy = y1 - y0, l = Math.hypot(dx, dy) || 1;
  return [x0 - (dx / l) * reach, y0 - (dy / l) * reach, x0 + (dx / l) * reach, y0 + (dy / l) * reach];
}

// `text` in lines no wider than `max` (measure(s) = its width), broken at spaces, at most `maxLines`; a last line
// that would not fit is shortened and ends with an ellipsis (so is a word wider than a line).
export function wrapText(text, measure, max, maxLines) {
  const words = String(text).split(' '), lines = [];
  let line = '';
  for (let i = 0; i < words.length; i++) {
    const next = line ? `${line} ${words[i]}` : words[i];
    if (measure(next) <= max || !line) { line = next; continue; }
    if (lines.length === maxLines - 1) { line = `${line} ${words.slice(i).join(' ')}`; break; }
    lines.push(line);
    line = words[i];
  }
  if (measure(line) > max) {
    while (line.length > 1 && measure(`${line}…`) > max) line = line.slice(0, -1);
    line = `${line.trimEnd()}…`;
  }
  lines.push(line);
  return lines;
}

export class Figure {
  constructor(canvas) {
    this.canvas = canvas;
    this.ctx = canvas.getContext('2d');
    this.scene = new Scene();
    this.home = { minX: -1, maxX: 1, minY: -1, maxY: 1 };   // the extent the lesson asked for
    this.zoom = null;                                           // the user's extent after zoom/pan, or null
    this.view = null;                                           // world <-> canvas transform of the last draw
    this.highlighted = null;                                    // the quantity (item.q) drawn with a halo
    this.overlay = [];                                          // items over the scene (setOverlay)
    this.wire();
    // redraw after layout, not inside the observer (a canvas resize there would re-enter the layout loop)
    this.resizeObserver = new ResizeObserver(() => requestAnimationFrame(() => this.render()));
    this.resizeObserver.observe(canvas);
  }

  // ---- extent and transforms ----------------------------------------------------------------------------------

  // The world rectangle to show (padded by 8 %); resets the user's zoom.
  setExtent(minX, minY, maxX, maxY) {
    const px = Math.max((maxX - minX) * 0.08, 0.05), py = Math.max((maxY - minY) * 0.08, 0.05);
    this.home = { minX: minX - px, maxX: maxX + px, minY: minY - py, maxY: maxY + py };
    this.zoom = null;
  }

  // The extent of the finite points of xy (interleaved), as setExtent.
  fitPoints(xy) {
    let minX = Infinity, maxX = -Infinity, minY = Infinity, maxY = -Infinity;
    for (let i = 0; i + 1 < xy.length; i += 2) {
      const x = xy[i], y = xy[i + 1];
      if (!Number.isFinite(x) || !Number.isFinite(y)) continue;
      minX = Math.min(minX, x); maxX = Math.max(maxX, x); minY = Math.min(minY, y); maxY = Math.max(maxY, y);
    }
    if (minX === Infinity) this.setExtent(-1, -1, 1, 1);
    else this.setExtent(minX, minY, maxX, maxY);
  }

  // The world rectangle on screen now (the requested one widened to the canvas' aspect).
  extent() {
    const v = this.view;
    return v ? { minX: v.minX, maxX: v.maxX, minY: v.minY, maxY: v.maxY } : { ...this.home };
  }

  toScreen(x, y) { const v = this.view; return [v.X(x) / v.dpr, v.Y(y) / v.dpr]; }     // CSS px in the canvas
  toWorld(px, py) { const v = this.view; return [v.minX + (px * v.dpr) / v.scale, v.maxY - (py * v.dpr) / v.scale]; }
  get scale() { return this.view ? this.view.scale / this.view.dpr : 1; }              // CSS px per metre

  // Client (CSS pixel) coordinates of a world point, for tests and pointer hit tests.
  clientPoint(x, y) {
    const r = this.canvas.getBoundingClientRect(), [sx, sy] = this.toScreen(x, y);
    return { x: r.left + sx, y: r.top + sy };
  }

  zoomAt(fx, fy, factor) {            // fx, fy: the fraction of the canvas that stays put
    const e = this.extent();
    const wx = e.minX + fx * (e.maxX - e.minX), wy = e.maxY - fy * (e.maxY - e.minY);
    this.zoom = { minX: wx - (wx - e.minX) * factor, maxX: wx + (e.maxX - wx) * factor,
      minY: wy - (wy - e.minY) * factor, maxY: wy + (e.maxY - wy) * factor };
    this.render();
  }

  panBy(dxCss, dyCss) {
    const e = this.extent(), dx = dxCss / this.scale, dy = dyCss / this.scale;
    this.zoom = { minX: e.minX - dx, maxX: e.maxX - dx, minY: e.minY + dy, maxY: e.maxY + dy };
    this.render();
  }

  resetView() { this.zoom = null; this.render(); }

  // Pans (same zoom) so that world point (x, y) is in the view, when it is not: a stepped-to point stays visible.
  ensureVisible(x, y) {
    if (!Number.isFinite(x) || !Number.isFinite(y)) return;
    if (!this.view) this.layout();
    const e = this.extent(), mx = (e.maxX - e.minX) * 0.05, my = (e.maxY - e.minY) * 0.05;
    if (x >= e.minX + mx && x <= e.maxX - mx && y >= e.minY + my && y <= e.maxY - my) return;
    const hw = (e.maxX - e.minX) / 2, hh = (e.maxY - e.minY) / 2;
    this.zoom = { minX: x - hw, maxX: x + hw, minY: y - hh, maxY: y + hh };
  }

  // ---- drawing --------------------------------------------------------------------------------------------------

  show(scene) { this.scene = scene; this.overlay = []; this.render(); }

  // Items drawn over the scene until the next show() (a question's candidate points, web/predict.js).
  setOverlay(items) { this.overlay = items; this.render(); }

  // Draws the items of quantity `name` (item.q) over a halo; null: none.
  highlight(name) {
    if (name === this.highlighted) return;
    this.highlighted = name;
    this.render();
  }

  layout() {
    const c = this.canvas, dpr = window.devicePixelRatio || 1;
    const W = Math.max(1, Math.round(c.clientWidth * dpr)), H = Math.max(1, Math.round(c.clientHeight * dpr));
    if (c.width !== W || c.height !== H) { c.width = W; c.height = H; }
    const e = this.zoom ?? this.home;
    const scale = Math.min(W / Math.max(e.maxX - e.minX, 1e-9), H / Math.max(e.maxY - e.minY, 1e-9));
    const cx = (e.minX + e.maxX) / 2, cy = (e.minY + e.maxY) / 2;
    const minX = cx - W / scale / 2, maxX = cx + W / scale / 2, minY = cy - H / scale / 2, maxY = cy + H / scale / 2;
    // text size: CSS decides (--figure-text-scale, e.g. larger in lecture mode); t = pixels per CSS px of text
    // and marks (points, markers, line widths): --figure-mark-scale; m = pixels per CSS px of a mark
    const css = getComputedStyle(c);
    const textScale = Number(css.getPropertyValue('--figure-text-scale')) || 1, markScale = Number(css.getPropertyValue('--figure-mark-scale')) || 1;
    this.view = { W, H, dpr, t: dpr * textScale, m: dpr * markScale, scale, minX, maxX, minY, maxY, X: (x) => (x - minX) * scale, Y: (y) => (maxY - y) * scale };
  }

  render() {
    if (!this.canvas.isConnected) return;
    this.layout();
    const { ctx } = this, v = this.view;
    ctx.setTransform(1, 0, 0, 1, 0, 0);
    ctx.fillStyle = '#ffffff';
    ctx.fillRect(0, 0, v.W, v.H);
    this.drawScale();
    this.labels = [];
    for (const item of this.scene.items) {
      const at = item.type === 'label' ? this.placeLabel(item) : null;
      if (this.highlighted && item.q === this.highlighted) this.drawItem(haloOf(item), at);
      this.drawItem(item, at);
    }
    for (const item of this.overlay) this.drawItem(item, item.type === 'label' ? this.placeLabel(item) : null);
    const title = this.titleLayout();
    if (this.scene.inset) this.drawInset(this.scene.inset, title.height);
    this.drawTitle(title);
  }

  // The scene's title on top, as in the exported SVG/TikZ: wrapped at spaces onto up to three lines when it is wider
  // than the canvas (large type in lecture mode, a phone's narrow figure), the last line shortened with an ellipsis.
  // { lines, width, height (device px) } of the title as drawTitle draws it.
  titleLayout() {
    const { ctx } = this, v = this.view, d = v.t, t = this.scene.title;
    if (!t) return { lines: [], width: 0, height: 0 };
    ctx.font = `${12 * d}px system-ui, sans-serif`;
    const lines = wrapText(t, (s) => ctx.measureText(s).width, v.W - 16 * d, 3);
    return { lines, width: Math.max(...lines.map((l) => ctx.measureText(l).width)), height: (lines.length * 16 + 5) * d };
  }

  drawTitle({ lines, width, height }) {
    if (!lines.length) return;
    const { ctx } = this, d = this.view.t;
    ctx.font = `${12 * d}px system-ui, sans-serif`;
    ctx.fillStyle = 'rgba(255,255,255,0.85)';
    ctx.fillRect(0, 0, Math.min(this.view.W, width + 16 * d), height);
    ctx.fillStyle = '#1c2330';
    lines.forEach((l, i) => ctx.fillText(l, 8 * d, (14 + 16 * i) * d));
  }

  // Where label `it` is drawn (device px, the text's baseline start): at its offset from its point, or, when that
  // would cover a label drawn before it in this render (frames that nearly coincide, names of nearby points on a
  // phone's small figure), the nearest of a few places one line below or above that covers none. Records the box.
  placeLabel(it) {
    const { ctx } = this, v = this.view, d = v.m, size = (it.bold ? 13 : 12) * v.t;
    ctx.font = `${it.bold ? '600 ' : ''}${size}px system-ui, sans-serif`;
    const w = ctx.measureText(it.text).width, line = 1.2 * size;
    const dx = (it.offset?.[0] ?? 6) * d, y0 = v.Y(it.y) + (it.offset?.[1] ?? -6) * d;
    // a label that would run off the right edge goes to the left of its point instead (as far as the left edge allows)
    let x = v.X(it.x) + dx;
    if (x + w > v.W) x = Math.max(0, Math.min(v.X(it.x) - Math.abs(dx) - w, v.W - w));
    const box = (y) => ({ x0: x, x1: x + w, y0: y - 0.85 * size, y1: y + 0.25 * size });
    // names on one line stay a clear gap apart, so that two never read as one ("map x robot = sensor"); so do names
    // side by side half a line apart (the end of one beside the start of the other reads as one name too); names
    // stacked in one column need only not overlap
    const gap = 1.5 * size;
    const free = (b) => this.labels.every((o) => {
      if (b.x1 + gap <= o.x0 || b.x0 >= o.x1 + gap) return true;
      const side = b.x1 <= o.x0 || b.x0 >= o.x1, clear = side ? 0.5 * size : 0;
      return b.y1 + clear <= o.y0 || b.y0 >= o.y1 + clear;
    });
    let y = y0;
    for (const k of [0, 1, -1, 2, -2, 3, -3]) if (free(box(y0 + k * line))) { y = y0 + k * line; break; }
    this.labels.push({ ...box(y), text: it.text });
    return [x, y];
  }

  // The labels of the last render as drawn: { text, x0, y0, x1, y1 } in CSS px of the canvas (tests check overlaps).
  labelBoxes() {
    const r = this.view?.dpr ?? 1;
    return (this.labels ?? []).map((b) => ({ text: b.text, x0: b.x0 / r, y0: b.y0 / r, x1: b.x1 / r, y1: b.y1 / r }));
  }

  drawItem(it, at = null) {
    const { ctx } = this, v = this.view, d = v.m;
    ctx.setLineDash(it.dash ? [5 * d, 4 * d] : []);
    ctx.lineWidth = (it.width ?? 1.5) * d;
    ctx.strokeStyle = it.colour ?? INK.segment;
    switch (it.type) {
      case 'points': {
        ctx.fillStyle = it.colour ?? clusterColour(it.label ?? -1);
        const r = (it.radius ?? 2.5) * d;
        for (let i = 0; i + 1 < it.xy.length; i += 2) {
          const x = it.xy[i], y = it.xy[i + 1];
          if (!Number.isFinite(x) || !Number.isFinite(y)) continue;
          ctx.beginPath(); ctx.arc(v.X(x), v.Y(y), r, 0, 2 * Math.PI); ctx.fill();
        }
        break;
      }
      case 'segments':
        ctx.beginPath();
        for (let i = 0; i + 3 < it.xy.length; i += 4) { ctx.moveTo(v.X(it.xy[i]), v.Y(it.xy[i + 1])); ctx.lineTo(v.X(it.xy[i + 2]), v.Y(it.xy[i + 3])); }
        ctx.stroke();
        break;
      case 'polyline':
        ctx.beginPath();
        for (let i = 0; i + 1 < it.xy.length; i += 2) (i ? ctx.lineTo : ctx.moveTo).call(ctx, v.X(it.xy[i]), v.Y(it.xy[i + 1]));
        ctx.stroke();
        break;
      case 'circle':
        ctx.beginPath(); ctx.arc(v.X(it.x), v.Y(it.y), Math.max(it.r * v.scale, 0.5), 0, 2 * Math.PI);
        if (it.fill) { ctx.fillStyle = it.fill; ctx.fill(); }
        ctx.stroke();
        break;
      case 'strip': {
        const reach = (v.maxX - v.minX) + (v.maxY - v.minY);
        const dx = it.x1 - it.x0, dy = it.y1 - it.y0, l = Math.hypot(dx, dy) || 1, nx = -dy / l * it.half, ny = dx / l * it.half;
        // bounded: only between the two points (a DP chord); else the whole line (an RW strip runs ahead)
        const [a, b, c, e] = it.bounded ? [it.x0, it.y0, it.x1, it.y1] : lineThrough(it.x0, it.y0, it.x1, it.y1, reach);
        ctx.fillStyle = (it.colour ?? INK.candidate) + '22';
        ctx.beginPath();
        ctx.moveTo(v.X(a + nx), v.Y(b + ny)); ctx.lineTo(v.X(c + nx), v.Y(e + ny));
        ctx.lineTo(v.X(c - nx), v.Y(e - ny)); ctx.lineTo(v.X(a - nx), v.Y(b - ny)); ctx.closePath();
        ctx.fill();
        ctx.setLineDash([5 * d, 4 * d]);
        ctx.beginPath();
        ctx.moveTo(v.X(a + nx), v.Y(b + ny)); ctx.lineTo(v.X(c + nx), v.Y(e + ny));
        ctx.moveTo(v.X(a - nx), v.Y(b - ny)); ctx.lineTo(v.X(c - nx), v.Y(e - ny));
        ctx.stroke();
        ctx.setLineDash([]);
        ctx.lineWidth = 1 * d;
        ctx.beginPath(); ctx.moveTo(v.X(a), v.Y(b)); ctx.lineTo(v.X(c), v.Y(e)); ctx.stroke();
        break;
      }
      case 'marker': {
        const s = (it.size ?? 7) * d, X = v.X(it.x), Y = v.Y(it.y);
        ctx.lineWidth = 2 * d;
        ctx.beginPath();
        if (it.shape === 'x') { ctx.moveTo(X - s, Y - s); ctx.lineTo(X + s, Y + s); ctx.moveTo(X + s, Y - s); ctx.lineTo(X - s, Y + s); ctx.stroke(); }
        else if (it.shape === 'dot') { ctx.fillStyle = it.colour ?? INK.current; ctx.arc(X, Y, s * 0.6, 0, 2 * Math.PI); ctx.fill(); }
        else { ctx.arc(X, Y, s, 0, 2 * Math.PI); ctx.stroke(); }
        break;
      }
      case 'label':
        ctx.font = `${it.bold ? '600 ' : ''}${(it.bold ? 13 : 12) * v.t}px system-ui, sans-serif`;
        ctx.fillStyle = it.colour ?? INK.segment;
        {
          const [x, y] = at ?? [v.X(it.x) + (it.offset?.[0] ?? 6) * d, v.Y(it.y) + (it.offset?.[1] ?? -6) * d];
          // a white edge keeps a name readable where it crosses a line or points (an axis, a scan); a highlighted
          // name's halo is a wider glow in the halo colour, drawn first, so it shows outside that edge
          ctx.save();
          ctx.strokeStyle = it.glow ? HALO : 'rgba(255,255,255,0.9)'; ctx.lineWidth = (it.glow ? 7 : 3) * v.t; ctx.lineJoin = 'round';
          ctx.strokeText(it.text, x, y);
          ctx.restore();
          ctx.fillText(it.text, x, y);
        }
        break;
      default:
        throw new TypeError(`Figure: unknown item type ${it.type}`);
    }
    ctx.setLineDash([]);
  }

  // A scale bar (bottom left) so that circles and strips can be read in metres.
  drawScale() {
    const { ctx } = this, v = this.view, d = v.dpr;
    const target = (v.W * 0.18) / v.scale, p = 10 ** Math.floor(Math.log10(target));
    const len = [1, 2, 5, 10].map((m) => m * p).filter((l) => l <= target).pop() ?? p;
    const x = 12 * d, y = v.H - 12 * d;
    ctx.strokeStyle = '#5a6475'; ctx.fillStyle = '#5a6475'; ctx.lineWidth = 2 * d;
    ctx.beginPath(); ctx.moveTo(x, y); ctx.lineTo(x + len * v.scale, y); ctx.stroke();
    ctx.font = `${11 * v.t}px system-ui, sans-serif`;
    ctx.fillText(len >= 1 ? `${len} m` : `${Math.round(len * 1000)} mm`, x, y - 5 * d);
  }

  // A small chart in a corner: values against their index, with a horizontal limit line, its value, and the range of
  // both axes (yformat(v) writes a value, e.g. in mm). Sized in text units, so it grows with the type (lecture mode).
  // titleHeight: the title's height (device px); the chart's top corners sit below it.
  drawInset(ch, titleHeight = 20 * this.view.dpr) {
    const { ctx } = this, v = this.view, d = v.t;
    const fmt = ch.yformat ?? ((y) => String(Number(y.toPrecision(2))));
    const w = Math.min(270 * d, v.W * 0.45), h = Math.min(140 * d, v.H * 0.38), below = titleHeight + 6 * v.dpr;
    // the corner that hides the fewest points of the scene
    const corners = [[v.W - w - 8 * v.dpr, below], [8 * v.dpr, below], [v.W - w - 8 * v.dpr, v.H - h - 8 * v.dpr], [8 * v.dpr, v.H - h - 30 * v.t]];
    const hidden = corners.map(([cx, cy]) => {
      let n = 0;
      for (const it of this.scene.items) {
        if (it.type !== 'points') continue;
        for (let i = 0; i + 1 < it.xy.length; i += 2) {
          const X = v.X(it.xy[i]), Y = v.Y(it.xy[i + 1]);
          if (X >= cx && X <= cx + w && Y >= cy && Y <= cy + h) n++;
        }
      }
      return n;
    });
    const [x0, y0] = corners[hidden.indexOf(Math.min(...hidden))];
    ctx.fillStyle = 'rgba(255,255,255,0.93)'; ctx.strokeStyle = '#b7c0cd'; ctx.lineWidth = 1 * v.dpr;
    ctx.fillRect(x0, y0, w, h); ctx.strokeRect(x0, y0, w, h);
    ctx.font = `${11 * d}px system-ui, sans-serif`; ctx.fillStyle = '#1c2330'; ctx.textAlign = 'left';
    ctx.fillText(ch.title, x0 + 6 * d, y0 + 13 * d, w - 12 * d);
    const finite = ch.ys.filter(Number.isFinite);
    const top = Math.max(ch.hline ?? 0, ...finite, 1e-9) * 1.15;
    ctx.font = `${10 * d}px system-ui, sans-serif`;
    const left = Math.max(ctx.measureText(fmt(top)).width, ctx.measureText('0').width) + 10 * d;
    const px = x0 + left, py = y0 + 22 * d, pw = w - left - 10 * d, ph = h - 42 * d;
    const xsMin = Math.min(...ch.xs), xsMax = Math.max(...ch.xs, xsMin + 1);
    const X = (x) => px + ((x - xsMin) / (xsMax - xsMin)) * pw, Y = (y) => py + ph - (Math.min(y, top) / top) * ph;
    ctx.strokeStyle = '#5a6475'; ctx.beginPath(); ctx.moveTo(px, py); ctx.lineTo(px, py + ph); ctx.lineTo(px + pw, py + ph); ctx.stroke();
    // the axes' ranges: 0 and the top value on the left, the first and last index below
    ctx.fillStyle = '#5a6475';
    ctx.textAlign = 'right';
    ctx.fillText(fmt(top), px - 4 * d, py + 8 * d);
    ctx.fillText('0', px - 4 * d, py + ph);
    ctx.textAlign = 'left';
    ctx.fillText(String(xsMin), px, py + ph + 12 * d);
    ctx.textAlign = 'right';
    ctx.fillText(String(xsMax), px + pw, py + ph + 12 * d);
    ctx.textAlign = 'center';
    ctx.fillText(ch.xlabel ?? '', px + pw / 2, py + ph + 12 * d, pw - 2 * ctx.measureText(String(xsMax)).width - 8 * d);
    ctx.textAlign = 'left';
    if (ch.hline !== undefined) {
      ctx.strokeStyle = INK.fail; ctx.lineWidth = 1 * v.dpr; ctx.setLineDash([4 * d, 3 * d]);
      ctx.beginPath(); ctx.moveTo(px, Y(ch.hline)); ctx.lineTo(px + pw, Y(ch.hline)); ctx.stroke(); ctx.setLineDash([]);
      ctx.fillStyle = INK.fail; ctx.textAlign = 'right';
      ctx.fillText(`${ch.hlabel ?? ''} = ${fmt(ch.hline)}`, px + pw, Y(ch.hline) - 3 * d);
      ctx.textAlign = 'left';
    }
    ctx.strokeStyle = INK.candidate; ctx.lineWidth = 1.5 * v.m; ctx.beginPath();
    let started = false;
    ch.xs.forEach((x, i) => {
      if (!Number.isFinite(ch.ys[i])) return;
      (started ? ctx.lineTo : ctx.moveTo).call(ctx, X(x), Y(ch.ys[i])); started = true;
    });
    ctx.stroke();
    ch.xs.forEach((x, i) => {
      if (!Number.isFinite(ch.ys[i])) return;
      ctx.fillStyle = ch.ok && !ch.ok[i] ? INK.fail : INK.ok;
      ctx.beginPath(); ctx.arc(X(x), Y(ch.ys[i]), (i === ch.xs.length - 1 ? 4 : 2.5) * v.m, 0, 2 * Math.PI); ctx.fill();
    });
  }

  // ---- input: wheel / drag / keyboard zoom and pan; clicks go to onPick ------------------------------------------

  wire() {
    const c = this.canvas;
    c.addEventListener('wheel', (ev) => {
      ev.preventDefault();
      const r = c.getBoundingClientRect();
      this.zoomAt((ev.clientX - r.left) / r.width, (ev.clientY - r.top) / r.height, Math.exp(ev.deltaY * 0.0015));
    }, { passive: false });
    let drag = null;
    c.addEventListener('pointerdown', (ev) => { drag = { x: ev.clientX, y: ev.clientY, moved: false }; c.setPointerCapture(ev.pointerId); });
    c.addEventListener('pointermove', (ev) => {
      if (!drag) return;
      const dx = ev.clientX - drag.x, dy = ev.clientY - drag.y;
      if (!drag.moved && Math.hypot(dx, dy) < 4) return;
      drag.moved = true;
      this.panBy(dx, dy);
      drag.x = ev.clientX; drag.y = ev.clientY;
    });
    c.addEventListener('pointerup', (ev) => {
      const click = drag && !drag.moved;
      drag = null;
      if (click && this.onPick) {
        const r = c.getBoundingClientRect();
        this.onPick(...this.toWorld(ev.clientX - r.left, ev.clientY - r.top));
      }
    });
    c.addEventListener('dblclick', () => this.resetView());
    c.addEventListener('keydown', (ev) => {
      const actions = {
        '+': () => this.zoomAt(0.5, 0.5, 0.8), '=': () => this.zoomAt(0.5, 0.5, 0.8), '-': () => this.zoomAt(0.5, 0.5, 1.25),
        0: () => this.resetView(), ArrowLeft: () => this.panBy(40, 0), ArrowRight: () => this.panBy(-40, 0),
        ArrowUp: () => this.panBy(0, 40), ArrowDown: () => this.panBy(0, -40),
      };
      if (actions[ev.key]) { ev.preventDefault(); actions[ev.key](); }
    });
  }

  dispose() { this.resizeObserver.disconnect(); this.onPick = null; }
}
