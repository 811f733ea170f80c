// The package's option defaults, in one place: the functions read them from here, and the package exports them
// (`defaults`) so that the command-line tool and the page need no copies. Where they differ from the C++ library's
// own defaults, and why: docs/package-defaults.md.

/** @type {import('./index.js').Defaults} */
export const defaults = Object.freeze({
  /** segment(): CAR segmentation of one scan. */
  segment: Object.freeze({ step: 2, lowerBound: 0.1, upperBound: 0.5 }),
  /** new StreamSegmenter(): IA segmentation of a stream. */
  streamSegmenter: Object.freeze({ step: 3, lowerBound: 0.1, upperBound: 0.5, scaling: 0.05 }),
  /** vectorize(): sigma (TLS methods), delta (FTLS/AFTLS corners), epsilon (Douglas-Peucker, Reumann-Witkam). */
  vectorize: Object.freeze({ sigma: 0.03, delta: 0.3, epsilon: 0.09, maxSize: 0, simplexShift: 1, maxIterations: 10000,
    split: true }),
  /** extractPolylines(): the vertex budget, the largest gap a polyline bridges, the cost of an unexplained beam. */
  extractPolylines: Object.freeze({ maxVertices: 50, maxGap: 1, unexplainedCost: 0.5 }),
});
