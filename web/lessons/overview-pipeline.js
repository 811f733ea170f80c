// The overview's computations, all package calls: one scan segmented (segment) and each cluster simplified
// (vectorize, Douglas–Peucker), then a short stretch of the log's scans, each treated the same way and placed in the
// map by its pose (TfTree). Also the step at which each linked lesson reaches its decisive moment, read from the
// trace of the same call that lesson makes on its own excerpt. Plain data out; every package object is freed here.
import { buildTree } from './tf-tree.js';
import { excerptChain } from './common.js';
import { EXCERPT as CAR_EXCERPT } from './car.js';
import { EXCERPT as DP_EXCERPT } from './dp.js';

// Clusters with fewer points are left out of the line segments (one or two returns are no wall).
export const MIN_CLUSTER = 3;

// One scan through the pipeline: { points, ranges, returns, gaps, clusters: [{ indices }], labels, lines: [{ cluster,
// segments (x0,y0,x1,y1,…), count }], segmentCount }.
export function scanPipeline(rtl, scan, p) {
  const n = scan.points.length / 2;
  let returns = 0;
  for (let i = 0; i < n; i++) if (Number.isFinite(scan.points[2 * i])) returns++;
  const seg = rtl.segment(scan.points, { step: p.step, lowerBound: p.lowerBound, upperBound: p.upperBound });
  const clusters = seg.clusters.map((c) => ({ indices: Array.from(c.indices) }));
  const lines = [];
  clusters.forEach((c, k) => {
    if (c.indices.length < MIN_CLUSTER) return;
    const chain = new Float64Array(2 * c.indices.length);
    c.indices.forEach((i, j) => { chain[2 * j] = scan.points[2 * i]; chain[2 * j + 1] = scan.points[2 * i + 1]; });
    const v = rtl.vectorize(chain, { method: 'dp', epsilon: p.epsilon });
    lines.push({ cluster: k, segments: Array.from(v.segments), count: v.count });
  });
  return {
    points: scan.points, ranges: scan.ranges, beams: n, returns, gaps: n - returns, labels: Array.from(seg.labels),
    clusters, lines, segmentCount: lines.reduce((a, l) => a + l.count, 0),
    pose: { x: scan.x, y: scan.y, theta: scan.theta },
  };
}

// The scans first..last of a log, each one's line segments and points moved into the map frame through a TfTree
// holding its pose (the log's laser sits at the robot's origin): [{ index, pose, segments, points }].
export function mapStretch(rtl, scans, first, last, p) {
  const out = [];
  for (let k = first; k <= last; k++) {
    const one = scanPipeline(rtl, scans[k], p);
    const tree = buildTree(rtl, scans[k], { x: 0, y: 0, angle: 0 });
    try {
      const ends = one.lines.flatMap((l) => l.segments);
      out.push({
        index: k, pose: one.pose, segmentCount: one.segmentCount,
        segments: ends.length ? Array.from(tree.transformPoints('robot', 'map', ends)) : [],
        points: Array.from(tree.transformPoints('robot', 'map', scans[k].points)),
      });
    } finally {
      tree.dispose();
    }
  }
  return out;
}

// Where the CAR lesson, with these segmentation parameters, shows its decisive moment on its own excerpt: the
// comparison of the wall's two points its note is about (EXCERPT.decisive), linked or not. { at (1-based), what }.
export async function carMoment(host, p) {
  const scan = await host.data.scan(CAR_EXCERPT.dataset, CAR_EXCERPT.scan);
  const { trace } = host.rtl.segment(scan.points, { step: p.step, lowerBound: p.lowerBound, upperBound: p.upperBound, trace: true });
  const { i, j } = CAR_EXCERPT.decisive;
  const k = trace.findIndex((e) => e.kind === 'compare' && e.i === i && e.j === j);
  if (k < 0) return { at: 1, what: `points ${i} and ${j} are never compared with step ${p.step}` };
  const e = trace[k];
  return { at: k + 1, what: `points ${i} and ${j} of a wall are ${e.distance.toFixed(3)} m apart, ${e.linked ? 'within' : 'beyond'} the threshold ${e.threshold.toFixed(3)} m: ${e.linked ? 'the wall stays one cluster' : 'the wall breaks in two'}` };
}

// Where the Douglas–Peucker lesson, with this ε, shows its decisive moment on its own excerpt: the first range whose
// farthest point is farther than ε (the first split). { at (1-based), what }.
export async function dpMoment(host, p) {
  const { chain } = await excerptChain(host, DP_EXCERPT);
  const { trace } = host.rtl.vectorize(chain, { method: 'dp', epsilon: p.epsilon, trace: true });
  const k = trace.findIndex((e) => e.kind === 'range' && e.split);
  if (k < 0) return { at: trace.length, what: 'no point is farther than ε: one segment' };
  const e = trace[k];
  return { at: k + 1, what: `point ${e.farthest} is ${e.distance.toFixed(3)} m from the chord ${e.first}–${e.last}, more than ε, and becomes a corner` };
}
