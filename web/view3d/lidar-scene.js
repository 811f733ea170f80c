// What the 3D view shows, computed by the package only: each ring segmented (segment, dim 3), each cluster
// vectorized into 3D line segments (vectorize, dim 3) and the columns' surfaces fitted with planes (vectorize,
// primitive 'plane'). Plain data in, plain data out, so Node tests can compare with the page.

export const LIDAR_DEFAULTS = Object.freeze({
  step: 3,            // CAR step s: each point is compared with up to s-1 previous points of its ring
  lowerBound: 0.1,    // m
  upperBound: 0.5,    // m
  minPoints: 5,       // clusters smaller than this are grey and not vectorized
  sigma: 0.05,        // m, 3D line fits (FTLS)
  planeSigma: 0.05,   // m, plane fits (AFTLS plane mode)
  planeMinPoints: 24, // planes fitted to fewer points are not drawn (a patch of a few beams says little)
  planeMinWidth: 0.1, // m: planes whose points spread less than this across their main line are not drawn
  planeBlockColumns: 32, // width of the patches the plane chain runs through (columns; 2048 = 360 degrees)
});

// The points of a cloud as one ordered chain for plane fits: the columns are cut into blocks of `blockColumns`, and
// inside a block the chain runs along the first ring, back along the next, and so on (a boustrophedon). A range of
// it is then a patch of neighbouring rings and columns, so a plane fit is well posed: a single ring or a few
// columns lie nearly in one curve or one vertical plane through the sensor. Gaps are left out (the vectorizers
// need finite points).
export function patchChain(cloud, blockColumns = 32) {
  const out = [];
  for (let c0 = 0; c0 < cloud.columns; c0 += blockColumns) {
    const c1 = Math.min(cloud.columns, c0 + blockColumns);
    for (let b = 0; b < cloud.beams; b++) {
      for (let k = 0; k < c1 - c0; k++) {
        const c = b % 2 === 0 ? c0 + k : c1 - 1 - k;
        const i = 3 * (c * cloud.beams + b);
        const x = cloud.points[i], y = cloud.points[i + 1], z = cloud.points[i + 2];
        if (Number.isFinite(x) && Number.isFinite(y) && Number.isFinite(z)) out.push(x, y, z);
      }
    }
  }
  return new Float64Array(out);
}

function gather(points, indices) {
  const chain = new Float64Array(3 * indices.length);
  indices.forEach((i, k) => chain.set(points.subarray(3 * i, 3 * i + 3), 3 * k));
  return chain;
}

/**
 * rtl: the initialised package; cloud: rtl.readOrganizedLidar(...) result. Returns
 * { rings: [{ beam, points, labels, clusters }], segments: Float64Array[] (one per vectorized cluster),
 *   planes: [{ vertices, normal, d, rms, count }], settings }.
 */
export function computeLidarScene(rtl, cloud, options = {}) {
  const s = { ...LIDAR_DEFAULTS, ...options };
  const rings = [], segments = [];
  let clusterCount = 0, failed = 0;
  for (let b = 0; b < cloud.beams; b++) {
    const points = cloud.ring(b);
    const { labels, clusters } = rtl.segment(points, { dim: 3, step: s.step, lowerBound: s.lowerBound, upperBound: s.upperBound });
    rings.push({ beam: b, points, labels, clusters: clusters.length });
    for (const cluster of clusters) {
      if (cluster.indices.length < s.minPoints) continue;
      clusterCount++;
      const v = rtl.vectorize(gather(points, cluster.indices), { dim: 3, method: 'ftls', sigma: s.sigma });
      if (v.ok) segments.push(v.segments);
      else failed++;
    }
  }
  const planes = [];
  let degenerate = 0;
  const chain = patchChain(cloud, s.planeBlockColumns);
  if (chain.length >= 9) {
    const v = rtl.vectorize(chain, { dim: 3, method: 'aftls', primitive: 'plane', sigma: s.planeSigma });
    if (v.ok) {
      for (let k = 0; k < v.count; k++) {
        const count = v.indices[2 * k + 1] - v.indices[2 * k];
        if (count < s.planeMinPoints) continue;
        // A patch whose points lie nearly on one line (e.g. one column across far-apart rings) does not determine a
        // plane: the package's 3D line fit of its points measures how far they spread across that line.
        const across = rtl.fitLine(v.polygons[k], { dim: 3 }).rms;
        if (across < s.planeMinWidth) { degenerate++; continue; }
        planes.push({
          vertices: v.polygons[k], normal: Array.from(v.params.subarray(4 * k, 4 * k + 3)), d: v.params[4 * k + 3],
          rms: v.rms[k], count,
        });
      }
    }
  }
  return { rings, segments, planes, degenerate, clusters: clusterCount, failed, settings: s };
}
