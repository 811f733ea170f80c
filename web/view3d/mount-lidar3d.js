// Mounts the whole "LiDAR in 3D" panel: reads the 16-beam Ouster excerpt with the package, computes the scene
// (lidar-scene.js) and shows it in the orbitable 3D view (lidar-view3d.js) next to a top view of the same points,
// with layer toggles and the segmentation / fit parameters, which recompute at once.
import { computeLidarScene, LIDAR_DEFAULTS } from './lidar-scene.js';
import { createLidarView3D, PALETTE, UNLABELLED } from './lidar-view3d.js';

export const LIDAR_URL = '/tests/data/rellis3d-os1-16x2048.bin';
export const LIDAR_BEAMS = 16;

// The top view: every ring from above (x forward = up on screen), the same colours; a plain 2D canvas.
function drawTopView(canvas, scene, minPoints) {
  const w = canvas.clientWidth || 400, h = canvas.clientHeight || 400;
  canvas.width = w; canvas.height = h;
  const ctx = canvas.getContext('2d');
  ctx.fillStyle = '#fff'; ctx.fillRect(0, 0, w, h);
  const range = 25;                                   // m shown around the sensor (the bulk of the returns)
  const s = Math.min(w, h) / (2 * range);
  const toScreen = (x, y) => [w / 2 - s * y, h / 2 - s * x];
  for (const ring of scene.rings) {
    const sizes = new Map();
    for (const l of ring.labels) if (l >= 0) sizes.set(l, (sizes.get(l) || 0) + 1);
    for (let i = 0; i < ring.labels.length; i++) {
      const x = ring.points[3 * i], y = ring.points[3 * i + 1];
      if (!Number.isFinite(x)) continue;
      const l = ring.labels[i];
      ctx.fillStyle = l >= 0 && sizes.get(l) >= minPoints ? PALETTE[l % PALETTE.length] : UNLABELLED;
      const [sx, sy] = toScreen(x, y);
      ctx.fillRect(sx - 1, sy - 1, 2, 2);
    }
  }
  ctx.strokeStyle = '#111'; ctx.lineWidth = 1.2;
  ctx.beginPath();
  for (const seg of scene.segments) for (let i = 0; i + 5 < seg.length; i += 6) {
    ctx.moveTo(...toScreen(seg[i], seg[i + 1])); ctx.lineTo(...toScreen(seg[i + 3], seg[i + 4]));
  }
  ctx.stroke();
  ctx.fillStyle = '#000'; ctx.beginPath(); ctx.arc(w / 2, h / 2, 4, 0, 2 * Math.PI); ctx.fill();
  // the caption grows with the page's figure type (--figure-text-scale: large in lecture mode, as the 2D figure's)
  const px = 12 * (Number(getComputedStyle(canvas).getPropertyValue('--figure-text-scale')) || 1);
  const text = `top view · ${2 * range} m across · x up`;
  ctx.font = `${px}px system-ui, sans-serif`;
  ctx.fillStyle = 'rgba(255,255,255,0.85)'; ctx.fillRect(0, 0, ctx.measureText(text).width + px, 1.5 * px);
  ctx.fillStyle = '#1c2330'; ctx.fillText(text, px / 2, 1.1 * px);
  canvas.dataset.captionPx = String(px);              // the caption's size as drawn (tests read it)
}

/**
 * mountLidar3D(container, rtl, { url, beams }) → Promise<{ view, scene(), settings(), recompute(), dispose() }>
 * container: an empty element; the panel fills it. rtl: the initialised package.
 */
// `cloud` (readOrganizedLidar's shape, e.g. a user's organised PCD) and its `label` replace the bundled scan.
export async function mountLidar3D(container, rtl, { url = LIDAR_URL, beams = LIDAR_BEAMS, cloud: given, label } = {}) {
  if (!(container instanceof HTMLElement)) throw new TypeError('mountLidar3D: container must be an HTMLElement');
  let cloud = given;
  if (!cloud) {
    const res = await fetch(url);
    if (!res.ok) throw new Error(`mountLidar3D: ${url}: HTTP ${res.status}`);
    cloud = rtl.readOrganizedLidar(new Uint8Array(await res.arrayBuffer()), { beams });
  }

  container.classList.add('lidar3d');
  container.innerHTML = `
    <div class="lidar3d-controls" role="group" aria-label="3D view settings">
      <label><input type="checkbox" data-layer="points" checked> points by cluster</label>
      <label><input type="checkbox" data-layer="segments" checked> 3D line segments</label>
      <label><input type="checkbox" data-layer="planes" checked> planes</label>
      <label>step <input type="number" name="step" min="1" max="10" step="1" value="${LIDAR_DEFAULTS.step}"></label>
      <label>σ lines (m) <input type="number" name="sigma" min="0.005" max="1" step="0.01" value="${LIDAR_DEFAULTS.sigma}"></label>
      <label>σ planes (m) <input type="number" name="planeSigma" min="0.005" max="1" step="0.01" value="${LIDAR_DEFAULTS.planeSigma}"></label>
      <button type="button" data-view="orbit">perspective</button>
      <button type="button" data-view="top">from above</button>
    </div>
    <p class="lidar3d-error" aria-live="polite"></p>
    <div class="lidar3d-views">
      <div class="lidar3d-3d"></div>
      <canvas class="lidar3d-top" role="img" aria-label="Top view of the same rings"></canvas>
    </div>
    <p class="lidar3d-caption" aria-live="polite"></p>`;
  const q = (s) => container.querySelector(s);
  const error = q('.lidar3d-error'), caption = q('.lidar3d-caption'), top = q('.lidar3d-top');
  let settings = { ...LIDAR_DEFAULTS };
  let scene = computeLidarScene(rtl, cloud, settings);
  const view = createLidarView3D(q('.lidar3d-3d'), scene, { minClusterPoints: settings.minPoints });

  const describe = () => {
    const nSeg = scene.segments.reduce((s, v) => s + v.length / 6, 0);
    caption.textContent = `${label ? `${label}, ${cloud.beams} rings` : `RELLIS-3D, one Ouster OS1-64 scan, ${cloud.beams} of its 64 beams (every 4th)`} × ${cloud.columns} columns: ` +
      `${scene.clusters} clusters of ≥ ${settings.minPoints} points (segment, dim 3, step ${settings.step}), ${nSeg} line segments ` +
      `(vectorize FTLS 3D, σ ${settings.sigma} m${scene.failed ? `, ${scene.failed} clusters failed` : ''}) and ${scene.planes.length} planes ` +
      `(AFTLS plane mode, σ ${settings.planeSigma} m, on a chain that runs back and forth along the rings in blocks of ${settings.planeBlockColumns} columns; light green: planes within 25° of level ground, violet: steeper; ${scene.degenerate} more patches lie nearly on a line and do not determine a plane). Drag (or focus the view and press Shift+arrow keys) to orbit, wheel to zoom, right-drag or arrow keys to pan.`;
  };
  const recompute = () => {
    const next = { ...settings };
    let bad = '';
    for (const input of container.querySelectorAll('input[name]')) {
      const v = Number(input.value), min = Number(input.min), max = Number(input.max);
      const ok = input.value.trim() !== '' && Number.isFinite(v) && v >= min && v <= max && (input.name !== 'step' || Number.isInteger(v));
      if (ok) { input.removeAttribute('aria-invalid'); next[input.name] = v; } else {
        input.setAttribute('aria-invalid', 'true');
        bad = `${input.name === 'step' ? 'step must be an integer' : `${input.name} must be a number`} from ${min} to ${max}.`;
      }
    }
    error.textContent = bad;
    if (bad) return;
    settings = next;
    scene = computeLidarScene(rtl, cloud, settings);
    view?.update(scene);
    drawTopView(top, scene, settings.minPoints);
    describe();
  };
  for (const box of container.querySelectorAll('input[data-layer]')) {
    box.addEventListener('change', () => view?.setLayers({ [box.dataset.layer]: box.checked }));
  }
  for (const input of container.querySelectorAll('input[name]')) input.addEventListener('change', recompute);
  for (const b of container.querySelectorAll('button[data-view]')) b.addEventListener('click', () => view?.setView(b.dataset.view));
  const topObserver = new ResizeObserver(() => drawTopView(top, scene, settings.minPoints));
  topObserver.observe(top);
  describe();
  drawTopView(top, scene, settings.minPoints);

  return {
    view,
    cloud,
    scene: () => scene,
    settings: () => ({ ...settings }),
    recompute,
    dispose() { topObserver.disconnect(); view?.dispose(); container.replaceChildren(); },
  };
}
