// Development page of the 3D view: mounts the panel alone and exposes it on window.__rtl for the browser tests.
import init from 'rtl-wasm';
import { mountLidar3D } from '../mount-lidar3d.js';

window.__rtl = { ready: false, errors: [] };
window.addEventListener('error', (e) => window.__rtl.errors.push(String(e.message)));
window.addEventListener('unhandledrejection', (e) => window.__rtl.errors.push(String(e.reason)));
try {
  const rtl = await init();
  const panel = await mountLidar3D(document.getElementById('lidar3d'), rtl);
  window.__lidar3d = panel;
  window.__rtl.ready = true;
} catch (e) {
  window.__rtl.errors.push(String(e?.stack || e));
}
