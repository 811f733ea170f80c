// What the two segmentation lessons share: their parameter fields (step, bounds) with the checks the package makes,
// and drawing the clusters of a replay.
import { numberField } from './ui.js';
import { nonNegative } from './common.js';

export function segFields(host, { step = 2, lowerBound = 0.1, upperBound = 0.5, stepLabel }) {
  return {
    step: numberField(host.controls, { key: 'step', label: stepLabel, value: step, min: 1, max: 8, step: 1, digits: 0, onInput: host.onParamsChanged }),
    lowerBound: numberField(host.controls, { key: 'lowerBound', label: 'lower bound (m)', kind: 'number', value: lowerBound, min: 0, max: 5, step: 0.01, onInput: host.onParamsChanged }),
    upperBound: numberField(host.controls, { key: 'upperBound', label: 'upper bound (m)', kind: 'number', value: upperBound, min: 0, max: 5, step: 0.01, onInput: host.onParamsChanged }),
  };
}

export function checkBounds({ lowerBound, upperBound }) {
  const out = {};
  if (nonNegative(lowerBound)) out.lowerBound = nonNegative(lowerBound);
  if (nonNegative(upperBound)) out.upperBound = nonNegative(upperBound);
  else if (!out.lowerBound && upperBound < lowerBound) out.upperBound = `must be ≥ the lower bound (${lowerBound} m)`;
  return out;
}

// Colour number per cluster label: the order of first appearance along the scan, so colours stay put while
// the clusters grow.
export function colourIndex(labels) {
  const order = new Map();
  for (const l of labels) if (l >= 0 && !order.has(l)) order.set(l, order.size);
  return order;
}

// Adds each cluster's points (labels: per point, -1 = none) to the scene in the package palette.
export function drawClusters(scene, points, labels) {
  const order = colourIndex(labels), groups = new Map();
  labels.forEach((l, i) => {
    if (!Number.isFinite(points[2 * i])) return;
    const c = l >= 0 ? order.get(l) : -1;
    if (!groups.has(c)) groups.set(c, []);
    groups.get(c).push(points[2 * i], points[2 * i + 1]);
  });
  for (const [c, xy] of groups) scene.points(xy, { label: c, radius: c < 0 ? 2 : 3 });
  return order;
}
