// SVG / TikZ of exactly what the figure shows, through the package's toSvg / toTikz: the scene's points (in their
// cluster colours) and every line it draws (segments, polylines, circles, strips, markers as short strokes),
// clipped to the visible world rectangle, whose frame is drawn too so that the exported extent is the view. The
// title is the figure's title. (The package draws every line black; on screen the final segments are black too.)
import { lineThrough } from './figure.js';

// Liang-Barsky: the part of segment (x0,y0)-(x1,y1) inside the rectangle, or null.
function clip(x0, y0, x1, y1, e) {
  let t0 = 0, t1 = 1;
  const dx = x1 - x0, dy = y1 - y0;
  for (const [p, q] of [[-dx, x0 - e.minX], [dx, e.maxX - x0], [-dy, y0 - e.minY], [dy, e.maxY - y0]]) {
    if (p === 0) { if (q < 0) return null; continue; }
    const t = q / p;
    if (p < 0) { if (t > t1) return null; if (t > t0) t0 = t; } else { if (t < t0) return null; if (t < t1) t1 = t; }
  }
  return [x0 + t0 * dx, y0 + t0 * dy, x0 + t1 * dx, y0 + t1 * dy];
}

function polygon(cx, cy, r, sides = 48) {
  const out = [];
  for (let k = 0; k < sides; k++) {
    const a = (2 * Math.PI * k) / sides, b = (2 * Math.PI * (k + 1)) / sides;
    out.push(cx + r * Math.cos(a), cy + r * Math.sin(a), cx + r * Math.cos(b), cy + r * Math.sin(b));
  }
  return out;
}

// The package Drawing of a scene as seen through extent e ({minX, maxX, minY, maxY}); pxPerMetre sizes markers.
export function sceneDrawing(scene, e, pxPerMetre = 100) {
  const xy = [], labels = [], lines = [];
  const inside = (x, y) => x >= e.minX && x <= e.maxX && y >= e.minY && y <= e.maxY;
  const line = (x0, y0, x1, y1) => { const c = clip(x0, y0, x1, y1, e); if (c) lines.push(...c); };
  const lineList = (arr) => { for (let i = 0; i + 3 < arr.length; i += 4) line(arr[i], arr[i + 1], arr[i + 2], arr[i + 3]); };
  const reach = (e.maxX - e.minX) + (e.maxY - e.minY);
  for (const it of scene.items) {
    switch (it.type) {
      case 'points':
        for (let i = 0; i + 1 < it.xy.length; i += 2) {
          if (!inside(it.xy[i], it.xy[i + 1])) continue;
          xy.push(it.xy[i], it.xy[i + 1]);
          labels.push(it.label ?? -1);
        }
        break;
      case 'segments': lineList(it.xy); break;
      case 'polyline': for (let i = 0; i + 3 < it.xy.length; i += 2) line(it.xy[i], it.xy[i + 1], it.xy[i + 2], it.xy[i + 3]); break;
      case 'circle': lineList(polygon(it.x, it.y, it.r)); break;
      case 'strip': {
        const dx = it.x1 - it.x0, dy = it.y1 - it.y0, l = Math.hypot(dx, dy) || 1, nx = (-dy / l) * it.half, ny = (dx / l) * it.half;
        const [a, b, c, d] = it.bounded ? [it.x0, it.y0, it.x1, it.y1] : lineThrough(it.x0, it.y0, it.x1, it.y1, reach);
        line(a + nx, b + ny, c + nx, d + ny); line(a - nx, b - ny, c - nx, d - ny); line(a, b, c, d);
        break;
      }
      case 'marker': lineList(polygon(it.x, it.y, (it.size ?? 7) / pxPerMetre, 16)); break;
      default: break;   // labels are screen text only
    }
  }
  lines.push(e.minX, e.minY, e.maxX, e.minY, e.maxX, e.minY, e.maxX, e.maxY,
    e.maxX, e.maxY, e.minX, e.maxY, e.minX, e.maxY, e.minX, e.minY);
  return { points: new Float64Array(xy), labels: Int32Array.from(labels), segments: new Float64Array(lines), title: scene.title };
}

// The package calls' arguments for what `figure` shows now: the drawing and the SVG size (800 px wide, the view's
// aspect). The page passes them to toSvg / toTikz unchanged, so a script making the same calls gets the same bytes.
export function exportArguments(figure) {
  const e = figure.extent(), h = Math.round((800 * (e.maxY - e.minY)) / (e.maxX - e.minX));
  return { drawing: sceneDrawing(figure.scene, e, figure.scale), svg: { width: 800, height: Math.min(Math.max(h, 100), 4000) } };
}

// SVG and TikZ texts of what `figure` shows now (the writers are in the package's extras module, loaded on first use).
export async function figureSvg(rtl, figure) {
  await rtl.load('extras');
  const { drawing, svg } = exportArguments(figure);
  return rtl.toSvg(drawing, svg);
}
export async function figureTikz(rtl, figure) {
  await rtl.load('extras');
  return rtl.toTikz(exportArguments(figure).drawing);
}

export function download(name, type, text) {
  const url = URL.createObjectURL(new Blob([text], { type }));
  const a = document.createElement('a');
  a.href = url; a.download = name;
  document.body.append(a); a.click(); a.remove();
  setTimeout(() => URL.revokeObjectURL(url), 1000);
}
