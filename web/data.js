// Loading the real scans through the package's readers, and cutting excerpts (a beam range or a cluster) out of
// them. Everything here is data plumbing: the algorithms run in the lessons, through the package.
export const DATASETS = {
  intel: { url: '/tests/data/intel.log', label: 'Intel Research Lab', unit: 'scan' },
  csail: { url: '/tests/data/csail.log', label: 'MIT CSAIL', unit: 'scan' },
  // 4 beams of an Ouster OS1 scan; ring b (one beam over 2048 columns) seen from above (x, y) as a 360° scan.
  rellis: { url: '/tests/data/rellis3d-os1-4x2048.bin', label: 'RELLIS-3D Ouster OS1', unit: 'ring', beams: 4 },
};

// Plain arrays of an organised cloud (as a worker posts them) in readOrganizedLidar's shape: ring(b) and column(c)
// gather their points (x,y,z; beam b of column c is point c * beams + b).
export function organizedCloud({ beams, columns, points, intensity }) {
  const ring = (b) => {
    if (!(Number.isInteger(b) && b >= 0 && b < beams)) throw new RangeError(`ring: beam must be an integer in 0..${beams - 1}, got ${b}`);
    const out = new Float64Array(3 * columns);
    for (let c = 0; c < columns; c++) out.set(points.subarray(3 * (c * beams + b), 3 * (c * beams + b) + 3), 3 * c);
    return out;
  };
  const column = (c) => {
    if (!(Number.isInteger(c) && c >= 0 && c < columns)) throw new RangeError(`column: c must be an integer in 0..${columns - 1}, got ${c}`);
    return points.slice(3 * c * beams, 3 * (c + 1) * beams);
  };
  return { beams, columns, points, intensity, ring, column };
}

export function createData(rtl) {
  const cache = new Map();
  const done = new Map();   // data sets read to the end: name -> scans (for synchronous use after load())

  // Every scan of a data set: { points (x,y interleaved, NaN = no return), x, y, theta } (robot frame + pose).
  async function load(name) {
    if (!DATASETS[name]) throw new RangeError(`data.load: unknown data set ${name}`);
    if (!cache.has(name)) cache.set(name, (async () => {
      const d = DATASETS[name];
      const res = await fetch(d.url);
      if (!res.ok) throw new Error(`cannot load ${d.url}: HTTP ${res.status}`);
      if (!d.beams) return rtl.readCarmenLog(await res.text());
      const cloud = rtl.readOrganizedLidar(await res.arrayBuffer(), { beams: d.beams, layout: 'column-major' });
      return Array.from({ length: cloud.beams }, (_, b) => {
        const ring = cloud.ring(b), points = new Float64Array(2 * cloud.columns);
        for (let c = 0; c < cloud.columns; c++) { points[2 * c] = ring[3 * c]; points[2 * c + 1] = ring[3 * c + 1]; }
        return { points, x: 0, y: 0, theta: 0, ring: b };
      });
    })().then((scans) => { done.set(name, scans); return scans; }));
    return cache.get(name);
  }

  // A data set read elsewhere (the user's own file, web/open-data.js): `scans` as load() gives them, and for an
  // organised 3D cloud (a PCD file) the cloud: { beams, columns, points (x,y,z column-major), intensity }, which
  // loadCloud() then gives in readOrganizedLidar's shape. Replaces an earlier one of the same name.
  function addDataset(name, { label, unit = 'scan', scans, cloud }) {
    DATASETS[name] = { label, unit, user: true, cloud: Boolean(cloud) };
    cache.set(name, Promise.resolve(scans));
    done.set(name, scans);
    if (cloud) cache.set(`${name}:cloud`, Promise.resolve(organizedCloud(cloud)));
    else cache.delete(`${name}:cloud`);
  }

  // The scans of a data set already read by load(), or null (not read yet).
  const loaded = (name) => done.get(name) ?? null;

  // The cloud itself (for the 3D view), read once; a user's data set has one only if it came with it.
  async function loadCloud(name = 'rellis') {
    if (DATASETS[name]?.user && !cache.has(`${name}:cloud`)) throw new RangeError(`data.loadCloud: ${DATASETS[name].label} is not an organised 3D cloud`);
    const key = `${name}:cloud`;
    if (!cache.has(key)) cache.set(key, (async () => {
      const d = DATASETS[name];
      const res = await fetch(d.url);
      if (!res.ok) throw new Error(`cannot load ${d.url}: HTTP ${res.status}`);
      return rtl.readOrganizedLidar(await res.arrayBuffer(), { beams: d.beams, layout: 'column-major' });
    })());
    return cache.get(key);
  }

  async function scan(name, index) {
    const scans = await load(name);
    if (!(index >= 0 && index < scans.length)) throw new RangeError(`data.scan: ${name} has no ${DATASETS[name].unit} ${index}`);
    return scans[index];
  }

  // Beams first..last (inclusive) of a scan's points, gaps kept (NaN).
  const beams = (points, first, last) => points.slice(2 * first, 2 * (last + 1));

  // The points at `indices`, in that order.
  function gather(points, indices) {
    const out = new Float64Array(2 * indices.length);
    indices.forEach((k, j) => { out[2 * j] = points[2 * k]; out[2 * j + 1] = points[2 * k + 1]; });
    return out;
  }

  // The finite points only, and the index of each in the input.
  function finite(points) {
    const xy = [], index = [];
    for (let i = 0; 2 * i + 1 < points.length; i++) {
      if (Number.isFinite(points[2 * i]) && Number.isFinite(points[2 * i + 1])) { xy.push(points[2 * i], points[2 * i + 1]); index.push(i); }
    }
    return { xy: new Float64Array(xy), index };
  }

  // Cluster number `k` (0-based, in the package's output order) of the scan segmented with `options`, as an
  // ordered chain of points, with its beam indices.
  function cluster(points, options, k) {
    const { clusters } = rtl.segment(points, options);
    if (!clusters[k]) throw new RangeError(`data.cluster: only ${clusters.length} clusters`);
    const indices = Array.from(clusters[k].indices);
    return { points: gather(points, indices), indices, clusters: clusters.length };
  }

  const describe = (name, index) => `${DATASETS[name].label}, ${DATASETS[name].unit} ${index}`;

  return { DATASETS, addDataset, load, loaded, loadCloud, scan, beams, gather, finite, cluster, describe };
}
