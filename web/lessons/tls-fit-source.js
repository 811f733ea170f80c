// The points the TLS line-fit lesson fits: its bundled wall (EXCERPT), or, when the user chose a scan (host.source), a
// straight run of that scan. The run is found by the package alone: segmentAndVectorize() cuts the scan into clusters
// and fits each cluster's FTLS lines within σ; the longest fitted range (most points) is the run, so every point of
// it is consecutive in one cluster and the package's own line fits it. Nothing here fits or segments anything.

// Intel Research Lab, scan 28, beams 124-131: a wall about 4.3 m away seen nearly edge-on (83.9 degrees in the robot
// frame). Its orthogonal residuals are ~1.5 cm, but its vertical ones are about nine times larger: the case where
// measuring errors vertically (OLS) is the wrong model.
export const EXCERPT = Object.freeze({ dataset: 'intel', scan: 28, firstBeam: 124, lastBeam: 131 });

// How a chosen scan is cut and vectorized: the chain lessons' segmentation of a chosen scan, FTLS at the lesson's
// default σ. A run needs MIN_RUN points to show a spread; a longer one is cut to its middle MAX_RUN points, which
// stay consecutive and on the package's line, so that every point can still be picked and dragged.
export const SOURCE_SEGMENT = Object.freeze({ step: 3, lowerBound: 0.1, upperBound: 0.5 });
export const SOURCE_SIGMA = 0.03;
export const MIN_RUN = 4;
export const MAX_RUN = 12;

// What a point of this data set is called: a beam of a scan or ring, else a point of a point set.
const wordFor = (data, dataset) => (['scan', 'ring'].includes(data.DATASETS[dataset]?.unit) ? 'beam' : 'point');

// The bundled excerpt's points, as the package reads the log (robot frame, gaps skipped).
async function bundled(host) {
  const scans = await host.data.load(EXCERPT.dataset);
  const p = scans[EXCERPT.scan].points;
  const points = [], indices = [];
  for (let i = EXCERPT.firstBeam; i <= EXCERPT.lastBeam; i++) {
    if (Number.isFinite(p[2 * i]) && Number.isFinite(p[2 * i + 1])) { points.push(p[2 * i], p[2 * i + 1]); indices.push(i); }
  }
  return { ...EXCERPT, points, indices, word: 'beam', origin: 'excerpt',
    where: `Intel Research Lab, scan ${EXCERPT.scan}, beams ${EXCERPT.firstBeam}–${EXCERPT.lastBeam}`,
    why: 'A wall seen nearly edge-on, so vertical and orthogonal residuals differ by a factor of about nine.' };
}

// The longest FTLS range of the scan: { cluster, first, end } in the cluster's chain indices, or null when no range
// has MIN_RUN points. Ties go to the smaller RMS (the straighter run).
function longestRange(result) {
  let best = null;
  for (let j = 0; j < result.vectorized.length; j++) {
    if (!result.ok[j]) continue;
    for (let s = result.segmentOffsets[j]; s < result.segmentOffsets[j + 1]; s++) {
      const first = result.indices[2 * s], end = result.indices[2 * s + 1], n = end - first, rms = result.rms[s];
      if (n < MIN_RUN) continue;
      if (!best || n > best.n || (n === best.n && rms < best.rms)) best = { cluster: result.vectorized[j], first, end, n, rms };
    }
  }
  return best;
}

// { dataset, scan, firstBeam, lastBeam, points, indices, word, origin, where, why } (where, why: plain text, naming the
// user's file): origin 'excerpt' (no source),
// 'source' (the chosen scan's run) or 'fallback' (the chosen scan has no run: the excerpt, and why says so).
export async function tlsFitPoints(host) {
  const src = host.source;
  if (!src) return bundled(host);
  const scan = await host.data.scan(src.dataset, src.scan);
  const name = host.data.describe(src.dataset, src.scan);
  const result = host.rtl.segmentAndVectorize(scan.points,
    { minPoints: MIN_RUN, segment: SOURCE_SEGMENT, vectorize: { method: 'ftls', sigma: SOURCE_SIGMA } });
  const run = longestRange(result);
  if (!run) {
    const own = await bundled(host);
    return { ...own, origin: 'fallback',
      why: `${name} has no straight run of ${MIN_RUN} or more points (FTLS, σ = ${SOURCE_SIGMA * 100} cm, finds none), so the lesson shows its own ` +
        `excerpt, ${own.where}. ${own.why}` };
  }
  const cut = Math.max(0, Math.floor((run.n - MAX_RUN) / 2));
  const first = run.first + cut, end = Math.min(run.end, first + MAX_RUN);
  const indices = Array.from(result.clusters[run.cluster].indices.subarray(first, end));
  const points = Array.from(host.data.gather(scan.points, indices));
  const word = wordFor(host.data, src.dataset);
  const whole = run.n > end - first ? `; the middle ${end - first} of its ${run.n} points` : '';
  return { dataset: src.dataset, scan: src.scan, firstBeam: indices[0], lastBeam: indices[indices.length - 1], points, indices,
    word, origin: 'source', where: `${name}, ${word}s ${indices[0]}–${indices[indices.length - 1]}`,
    why: `Your chosen scan: its straightest long run, the longest range that the package's FTLS fits within σ = ${SOURCE_SIGMA * 100} cm ` +
      `(cluster ${run.cluster + 1} of the scan segmented with step ${SOURCE_SEGMENT.step}, bounds ${SOURCE_SEGMENT.lowerBound}–${SOURCE_SEGMENT.upperBound} m${whole}).` };
}
