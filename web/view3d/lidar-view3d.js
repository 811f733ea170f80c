// The 3D view of an organised LiDAR scan: rings coloured by cluster, their 3D line segments and fitted planes, in a
// WebGL canvas the user can orbit (three.js + OrbitControls). It only draws: every number it shows comes from the
// package (see lidar-scene.js). Coordinates are the sensor frame (x forward, y left, z up, metres).
import * as THREE from 'three';
import { OrbitControls } from 'three/addons/controls/OrbitControls.js';
import { palette } from 'rtl-wasm';

// The package's drawing palette: cluster k gets palette[k % palette.length] in every view.
export const PALETTE = palette;
// Points without a cluster: a lighter grey than the package's 2D unlabelled colour, so that in the shaded 3D view
// the many unclustered returns recede behind the coloured clusters.
export const UNLABELLED = '#9aa3af';
const SEGMENT_COLOUR = '#111111';
const LEVEL_PLANE = '#7fc97f', STEEP_PLANE = '#762A83';

// WebGL can be missing (old GPU, disabled, blocked); the view then says so instead of throwing from the renderer.
export function webglAvailable() {
  try {
    const c = document.createElement('canvas');
    return Boolean(c.getContext('webgl2') || c.getContext('webgl'));
  } catch {
    return false;
  }
}

// Interleaved xyz of the finite points only (three.js bounding spheres break on NaN) with their colours.
function pointCloud(rings, minClusterPoints) {
  const xyz = [], rgb = [];
  const colour = new THREE.Color();
  for (const ring of rings) {
    const sizes = new Map();
    for (const l of ring.labels) if (l >= 0) sizes.set(l, (sizes.get(l) || 0) + 1);
    for (let i = 0; i < ring.labels.length; i++) {
      const x = ring.points[3 * i], y = ring.points[3 * i + 1], z = ring.points[3 * i + 2];
      if (!Number.isFinite(x) || !Number.isFinite(y) || !Number.isFinite(z)) continue;
      const l = ring.labels[i];
      colour.set(l >= 0 && sizes.get(l) >= minClusterPoints ? PALETTE[l % PALETTE.length] : UNLABELLED);
      xyz.push(x, y, z);
      rgb.push(colour.r, colour.g, colour.b);
    }
  }
  const g = new THREE.BufferGeometry();
  g.setAttribute('position', new THREE.Float32BufferAttribute(xyz, 3));
  g.setAttribute('color', new THREE.Float32BufferAttribute(rgb, 3));
  return g;
}

function segmentGeometry(segments) {
  const parts = segments instanceof Float64Array || Array.isArray(segments) && typeof segments[0] === 'number'
    ? [segments] : segments;
  const xyz = [];
  for (const p of parts) for (let i = 0; i < p.length; i++) xyz.push(p[i]);
  const g = new THREE.BufferGeometry();
  g.setAttribute('position', new THREE.Float32BufferAttribute(xyz, 3));
  return g;
}

// A plane's polygon (the package's projected points of the fitted range) is drawn as the convex outline of those
// points inside the plane: a display choice, the plane itself is the package's.
function planeOutline(vertices, normal) {
  const n = new THREE.Vector3(normal[0], normal[1], normal[2]).normalize();
  const u = new THREE.Vector3(1, 0, 0);
  if (Math.abs(n.x) > 0.9) u.set(0, 1, 0);
  u.sub(n.clone().multiplyScalar(u.dot(n))).normalize();
  const v = new THREE.Vector3().crossVectors(n, u);
  const pts = [];
  for (let i = 0; i + 2 < vertices.length; i += 3) {
    const p = new THREE.Vector3(vertices[i], vertices[i + 1], vertices[i + 2]);
    pts.push({ p, a: p.dot(u), b: p.dot(v) });
  }
  pts.sort((s, t) => s.a - t.a || s.b - t.b);
  const cross = (o, s, t) => (s.a - o.a) * (t.b - o.b) - (s.b - o.b) * (t.a - o.a);
  const half = (list) => {
    const h = [];
    for (const q of list) {
      while (h.length >= 2 && cross(h[h.length - 2], h[h.length - 1], q) <= 0) h.pop();
      h.push(q);
    }
    h.pop();
    return h;
  };
  return [...half(pts), ...half([...pts].reverse())].map((q) => q.p);
}

function planeObjects(planes) {
  const group = new THREE.Group();
  planes.forEach((plane, k) => {
    const hull = planeOutline(plane.vertices, plane.normal);
    if (hull.length < 3) return;
    // colour by orientation, not by index: ground patches and steep surfaces (trunks, bushes, walls) read apart
    const level = Math.abs(plane.normal[2]) / Math.hypot(...plane.normal) > Math.cos(25 * Math.PI / 180);
    const colour = level ? LEVEL_PLANE : STEEP_PLANE;
    const fan = [];
    for (let i = 1; i + 1 < hull.length; i++) fan.push(...hull[0].toArray(), ...hull[i].toArray(), ...hull[i + 1].toArray());
    const g = new THREE.BufferGeometry();
    g.setAttribute('position', new THREE.Float32BufferAttribute(fan, 3));
    group.add(new THREE.Mesh(g, new THREE.MeshBasicMaterial({
      color: colour, transparent: true, opacity: level ? 0.22 : 0.4, side: THREE.DoubleSide, depthWrite: false,
    })));
    const outline = new THREE.BufferGeometry().setFromPoints(hull);
    group.add(new THREE.LineLoop(outline, new THREE.LineBasicMaterial({ color: colour, transparent: true, opacity: 0.5 })));
  });
  return group;
}

function disposeObject(obj) {
  obj.traverse((o) => {
    o.geometry?.dispose();
    o.material?.dispose();
  });
}

/**
 * Mounts the 3D view in `container` (an empty block element; the canvas fills its width, height from CSS or
 * options.height). scene = { rings: [{ points: Float64Array xyz (NaN gaps), labels: Int32Array }], segments:
 * Float64Array | Float64Array[] (x0,y0,z0,x1,y1,z1 per segment), planes: [{ vertices: Float64Array, normal: [3] }] }.
 * Returns { canvas, update(scene), setLayers({ points, segments, planes }), setView('orbit' | 'top'), cameraState(),
 * stats(), render(), dispose() }, or null (and a note in the container) without WebGL.
 */
export function createLidarView3D(container, scene, options = {}) {
  if (!(container instanceof HTMLElement)) throw new TypeError('createLidarView3D: container must be an HTMLElement');
  if (!scene || !Array.isArray(scene.rings)) throw new TypeError('createLidarView3D: scene.rings must be an array');
  const minClusterPoints = options.minClusterPoints ?? 1;
  if (!webglAvailable()) {
    const note = document.createElement('p');
    note.className = 'view3d-note';
    note.textContent = 'The 3D view needs WebGL, which this browser does not provide.';
    container.append(note);
    return null;
  }

  const renderer = new THREE.WebGLRenderer({ antialias: true, preserveDrawingBuffer: true });
  renderer.setPixelRatio(Math.min(window.devicePixelRatio || 1, 2));
  renderer.setClearColor(0xffffff, 1);
  const canvas = renderer.domElement;
  canvas.className = 'view3d-canvas';
  canvas.tabIndex = 0;
  canvas.setAttribute('role', 'img');
  canvas.setAttribute('aria-label', options.label ?? 'LiDAR scan in 3D: drag or Shift+arrow keys to orbit, wheel to zoom, arrow keys to pan');
  container.append(canvas);

  const camera = new THREE.PerspectiveCamera(50, 1, 0.1, 1000);
  camera.up.set(0, 0, 1);                         // sensor frame: z up
  const controls = new OrbitControls(camera, canvas);
  controls.listenToKeyEvents(canvas);
  controls.enableDamping = false;                 // render on demand only, no animation loop
  const world = new THREE.Scene();
  const layers = { points: true, segments: true, planes: true, ...options.layers };
  let objects = { points: null, segments: null, planes: null };
  let radius = 20;
  let counts = { points: 0, segments: 0, planes: 0 };

  const render = () => renderer.render(world, camera);
  controls.addEventListener('change', render);

  function setView(name) {
    const r = radius;
    if (name === 'top') camera.position.set(-0.001, 0, 2.4 * r);
    else camera.position.set(-1.1 * r, -0.6 * r, 0.8 * r);
    controls.target.set(0, 0, 0);
    camera.lookAt(0, 0, 0);
    controls.update();
    render();
  }

  function update(next) {
    for (const o of Object.values(objects)) if (o) { world.remove(o); disposeObject(o); }
    const pointSize = options.pointSize ?? 3;
    const pts = new THREE.Points(pointCloud(next.rings, minClusterPoints),
      new THREE.PointsMaterial({ size: pointSize, sizeAttenuation: false, vertexColors: true }));
    const segs = new THREE.LineSegments(segmentGeometry(next.segments ?? []),
      new THREE.LineBasicMaterial({ color: SEGMENT_COLOUR, transparent: true, opacity: 0.75 }));
    const planes = planeObjects(next.planes ?? []);
    objects = { points: pts, segments: segs, planes };
    for (const [k, o] of Object.entries(objects)) { o.visible = layers[k]; world.add(o); }
    counts = {
      points: pts.geometry.getAttribute('position').count,
      segments: segs.geometry.getAttribute('position').count / 2,
      planes: (next.planes ?? []).length,
    };
    // Frame the scene on the bulk of the points: the far returns of an outdoor scan would shrink everything else.
    const d = [];
    const pos = pts.geometry.getAttribute('position');
    for (let i = 0; i < pos.count; i++) d.push(Math.hypot(pos.getX(i), pos.getY(i)));
    d.sort((a, b) => a - b);
    radius = Math.max(2, d.length ? d[Math.floor(0.9 * (d.length - 1))] : 20);
    render();
  }

  function resize() {
    const w = Math.max(1, container.clientWidth);
    const h = options.height ?? Math.max(200, Math.round(Math.min(w * 0.75, 560)));
    renderer.setSize(w, h, true);
    camera.aspect = w / h;
    camera.updateProjectionMatrix();
    render();
  }
  const observer = new ResizeObserver(resize);
  observer.observe(container);

  update(scene);
  resize();
  setView(options.view ?? 'orbit');

  return {
    canvas,
    update,
    setView,
    render,
    setLayers(next) {
      Object.assign(layers, next);
      for (const [k, o] of Object.entries(objects)) if (o) o.visible = layers[k];
      render();
    },
    cameraState: () => ({ position: camera.position.toArray(), target: controls.target.toArray() }),
    stats: () => ({ ...counts, layers: { ...layers } }),
    dispose() {
      observer.disconnect();
      controls.dispose();
      for (const o of Object.values(objects)) if (o) disposeObject(o);
      renderer.dispose();
      renderer.forceContextLoss();   // browsers cap live WebGL contexts: reopening the lesson must not pile them up
      canvas.remove();
    },
  };
}
