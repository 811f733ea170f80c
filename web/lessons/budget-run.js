// The vertex-budget lesson's data: one extractPolylines() call per budget J (J_MIN..J_MAX), kept as plain data, and
// what the text and figure read off each result (a beam's range, its predicted range, the line that predicted it).
// Nothing here extracts lines: every map, expected range and score is the package's.
export const J_MIN = 2, J_MAX = 60;

// The returned beams of a scan (points in the sensor frame, NaN = no return): per beam its range and direction.
export function beamsOf(points) {
  const n = points.length / 2, range = new Float64Array(n).fill(NaN), ux = new Float64Array(n), uy = new Float64Array(n);
  for (let i = 0; i < n; i++) {
    const x = points[2 * i], y = points[2 * i + 1], r = Math.hypot(x, y);
    if (Number.isFinite(r) && r > 0) { range[i] = r; ux[i] = x / r; uy[i] = y / r; }
  }
  return { n, range, ux, uy };
}

// The package's result at one budget, as plain data (copies: nothing points into wasm memory afterwards).
function snapshot(J, r) {
  const s = r.segments;
  return {
    J, vertexCount: r.vertexCount, returned: r.returned, explainedBeams: r.explainedBeams,
    rmse: r.rmse, explained: r.explained, score: r.score,
    polylines: r.polylines.map((p) => Array.from(p)),
    expected: Float64Array.from(r.expectedRanges),
    segments: { r: Array.from(s.r), theta: Array.from(s.theta), firstBeam: Array.from(s.firstBeam), lastBeam: Array.from(s.lastBeam) },
  };
}

// extractPolylines at every J of J_MIN..J_MAX: [snapshot], index k is J = J_MIN + k.
export function runBudgets(rtl, points, options) {
  const out = [];
  for (let J = J_MIN; J <= J_MAX; J++) out.push(snapshot(J, rtl.extractPolylines(points, { ...options, maxVertices: J })));
  return out;
}

// Per beam of a snapshot: r − r̂ (NaN where the map explains no return there).
export function residuals(beams, snap) {
  const out = new Float64Array(beams.n).fill(NaN);
  for (let i = 0; i < beams.n; i++) if (Number.isFinite(beams.range[i]) && Number.isFinite(snap.expected[i])) out[i] = beams.range[i] - snap.expected[i];
  return out;
}

// The segment whose line holds beam i's predicted point r̂·u (the package places r̂ on the line of the segment that
// explains the beam): { k, nx, ny, r } with the line x·nx + y·ny = r, or null. Among segments through that point, the
// one fitted to beam i's own range of beams comes first.
export function lineOf(beams, snap, i) {
  const rh = snap.expected[i];
  if (!Number.isFinite(rh)) return null;
  const { r, theta, firstBeam, lastBeam } = snap.segments;
  let best = null, bestKey = Infinity;
  for (let k = 0; k < r.length; k++) {
    const nx = Math.cos(theta[k]), ny = Math.sin(theta[k]);
    const off = Math.abs(rh * (beams.ux[i] * nx + beams.uy[i] * ny) - r[k]);
    if (off > 1e-6 * Math.max(1, rh)) continue;
    const key = (i >= firstBeam[k] && i <= lastBeam[k] ? 0 : 1) + off;
    if (key < bestKey) { bestKey = key; best = { k, nx, ny, r: r[k] }; }
  }
  return best;
}

// Beam i against its line: the radial error |r − r̂| (along the beam), the orthogonal distance of its point to the
// line, and the incidence (degrees between the beam and the line's normal). orthogonal = radial · cos(incidence).
export function beamErrors(beams, snap, i) {
  const line = lineOf(beams, snap, i);
  if (!line) return null;
  const x = beams.range[i] * beams.ux[i], y = beams.range[i] * beams.uy[i];
  const cos = Math.abs(beams.ux[i] * line.nx + beams.uy[i] * line.ny);
  return { beam: i, line, radial: Math.abs(beams.range[i] - snap.expected[i]), orthogonal: Math.abs(x * line.nx + y * line.ny - line.r),
    incidence: (Math.acos(Math.min(1, cos)) * 180) / Math.PI };
}

// The lesson's example of grazing incidence: of the explained beams whose radial error is typical or larger (at least
// half the RMSE, so the error is not rounding noise) and not an outlier (at most three times the RMSE), the one that
// meets its line at the largest incidence up to 75° (beyond, the ray runs almost along the line and the picture of
// the two distances is unreadable). null when no beam qualifies.
// minRange: beams nearer the sensor are passed over (the magnifier sits between sensor and point) unless no other
// beam qualifies.
export function grazingBeam(beams, snap, minRange = 0) {
  let best = null;
  for (let i = 0; i < beams.n; i++) {
    if (!(beams.range[i] >= minRange)) continue;
    const e = beamErrors(beams, snap, i);
    if (!e || e.radial < 0.5 * snap.rmse || e.radial > 3 * snap.rmse || e.incidence > 75) continue;
    if (!best || e.incidence > best.incidence) best = e;
  }
  return best ?? (minRange > 0 ? grazingBeam(beams, snap) : null);
}

// The returned beams explained in `snap` but not in `before` (the beams a larger budget newly explains).
export function newlyExplained(beams, before, snap) {
  const out = [];
  for (let i = 0; i < beams.n; i++) if (Number.isFinite(beams.range[i]) && Number.isFinite(snap.expected[i]) && !Number.isFinite(before.expected[i])) out.push(i);
  return out;
}

// Runs of consecutive beam indices, as "a–b" text ("12–30, 41").
export function runsText(indices) {
  const parts = [];
  for (let j = 0; j < indices.length;) {
    let e = j;
    while (e + 1 < indices.length && indices[e + 1] === indices[e] + 1) e++;
    parts.push(e > j ? `${indices[j]}–${indices[e]}` : `${indices[j]}`);
    j = e + 1;
  }
  return parts.join(', ');
}

// Where the score curve bends: the smallest budget whose score has come `share` (default 90 %) of the whole way down
// from the smallest budget's score to the best score of any budget. Past it, further vertices buy little. Reads the
// package's scores only. { J, score, first: { J, score }, best: { J, score }, share }, or null without a finite score.
export function curveKnee(snaps, share = 0.9) {
  const scored = snaps.filter((s) => Number.isFinite(s.score));
  if (!scored.length) return null;
  const first = scored[0], best = scored.reduce((b, s) => (s.score < b.score ? s : b), first);
  const target = best.score + (1 - share) * (first.score - best.score);
  const knee = scored.find((s) => s.score <= target);
  return { J: knee.J, score: knee.score, first: { J: first.J, score: first.score }, best: { J: best.J, score: best.score }, share };
}
