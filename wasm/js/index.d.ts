// rtl-wasm: hand-written TypeScript contract of the package (Emscripten 3.1.6 has no embind .d.ts generator).
// Everything returned is plain JS data (numbers, strings, typed arrays, arrays, objects): nothing needs .delete().
// Only the two stateful classes (StreamSegmenter, TfTree) own wasm memory; they have dispose() and [Symbol.dispose],
// and a FinalizationRegistry frees them if you forget.
//
// Points are interleaved coordinates: x0,y0,x1,y1,... (dim 2) or x0,y0,z0,... (dim 3), given as a Float64Array,
// a Float32Array or a plain array of numbers (converted). Point arrays the package returns are Float64Array.
// A point with a NaN coordinate is a gap (a laser beam without return) where a function says so.
//
// Errors: every function checks its arguments and throws TypeError (wrong type) or RangeError (bad value) with a
// message that starts with the function's name ("vectorize: ...", "TfTree.tf: ...", "readCarmenLog: line 7: ...")
// and names the argument; no C++ exception reaches JS and the module keeps working after any error.
// fitLine and vectorize accept coordinates within +-1e18 (RangeError beyond: their squares are summed).

export type PointArray = Float64Array | Float32Array | ArrayLike<number>;
export type Dim = 2 | 3;

export interface InitOptions {
  /** The module's .wasm bytes. Loaded automatically in Node and (via fetch) in browsers; pass it to override. */
  wasmBinary?: ArrayBuffer | Uint8Array;
  /** Where the .wasm lives when it is hosted somewhere else (a CDN). Do not pass it with a bundler. It is asked for
   *  rtl-extras.wasm too when the extras module is loaded. */
  locateFile?: (path: string, scriptDirectory: string) => string;
  /** Modules to load on demand that init() loads at once, as rtl.load(name) would (see RTL.load). */
  load?: ModuleName[];
}

/** Loads and instantiates the WebAssembly module. Each call makes an independent instance. A wasmBinary that is
 *  not a WebAssembly module, or not this package's, rejects with a TypeError whose message starts with "init:"
 *  (nothing is printed). */
export default function init(options?: InitOptions): Promise<RTL>;
export { init };

/** The colours of the package's drawings (toSvg, toTikz; CSS hex): cluster k is drawn in palette[k % 10], for pages
 *  that show clusters in the same colours. */
export const palette: readonly string[];
/** The colour of points without a cluster (label -1) in the package's drawings. */
export const unlabelledColour: string;
/** The defaults of the options of segment(), new StreamSegmenter() and vectorize() (frozen), for tools that show or
 *  pass them on. */
export const defaults: Defaults;
export interface Defaults {
  readonly segment: Readonly<Required<Pick<SegmentOptions, 'step' | 'lowerBound' | 'upperBound'>>>;
  readonly streamSegmenter: Readonly<Required<Pick<StreamSegmenterOptions, 'step' | 'lowerBound' | 'upperBound' | 'scaling'>>>;
  readonly vectorize: Readonly<Required<Pick<VectorizeOptions, 'sigma' | 'delta' | 'epsilon' | 'maxSize' | 'simplexShift' |
    'maxIterations' | 'split'>>>;
  readonly extractPolylines: Readonly<Required<ExtractPolylinesOptions>>;
}

// ---------------------------------------------------------------------------------------------- line fit (TLS)
export interface LineFitOptions { /** 2 (default) or 3 */ dim?: Dim }
export interface LineFit2D {
  dim: 2;
  /** unit normal (a, b) of the line a*x + b*y + c = 0; oriented so that c <= 0 (it points from the origin
   *  towards the line; for a line through the origin its first non-zero component is positive) */
  normal: Float64Array;
  /** c of a*x + b*y + c = 0 (-c >= 0 is the distance of the line from the origin) */
  offset: number;
  /** unit direction (b, -a), so that normal = (-direction.y, direction.x) */
  direction: Float64Array;
  /** centroid of the points (lies on the line) */
  centroid: Float64Array;
  /** root mean square orthogonal distance of the points from the line */
  rms: number;
  count: number;
}
export interface LineFit3D {
  dim: 3;
  /** unit direction (largest principal axis), first non-zero component positive */
  direction: Float64Array;
  /** centroid of the points (lies on the line) */
  centroid: Float64Array;
  rms: number;
  count: number;
}

// ---------------------------------------------------------------------------------------------- segmentation
export interface SegmentOptions {
  dim?: Dim;                 // default 2
  /** CAR step, integer >= 1; default 2. Step s compares each point with up to s - 1 previous points (cyclically
   *  across the seam): step 1 links nothing, step 2 (the default) links consecutive points. The threshold scales
   *  with it: t = clamp(s * 2 pi / N * |p - origin|, lowerBound, upperBound) for a scan of N points. */
  step?: number;
  /** lower bound of the adaptive distance threshold (m), >= 0; default 0.1 */
  lowerBound?: number;
  /** upper bound of the threshold (m), >= lowerBound; default 0.5 */
  upperBound?: number;
  /** sensor origin (dim numbers); default zeros */
  origin?: ArrayLike<number>;
  /** record the segmenter's steps (CarEvent[] in the result's `trace`); default false (the untraced C++ path) */
  trace?: boolean;
  /** return `labels` and every cluster's `indices` and `ranges` as views on the module's result block in wasm memory
   *  instead of copies (no copy out: the output counterpart of pointBuffer()); default false. Same numbers as the
   *  copies; with trace too. See RTL.pointBuffer for how long such views are valid. */
  view?: boolean;
}
export interface Cluster {
  /** point indices in the cluster's order (increasing; a cluster wrapping the seam lists its end-of-scan part first) */
  indices: Uint32Array;
  /** the same indices as contiguous half-open runs [begin0, end0, begin1, end1, ...] */
  ranges: Uint32Array;
}
export interface SegmentResult {
  /** cluster number per point, -1 for gaps (points with a NaN coordinate) */
  labels: Int32Array;
  /** clusters in the segmenter's output order; labels refer to this array */
  clusters: Cluster[];
  /** with { trace: true } only: every step of the CAR segmenter, in order (see CarEvent) */
  trace?: CarEvent[];
}

// ---------------------------------------------------------------------------------------------- vectorization
export type VectorizeMethod = 'ftls' | 'aftls' | 'itls' | 'dp' | 'rw';
/** Options a method does not use are checked and ignored, so one settings object can drive every method. */
export interface VectorizeOptions {
  dim?: Dim;                   // default 2
  method: VectorizeMethod;
  /** 'line' (default) or 'plane' (dim 3, method 'aftls' only) */
  primitive?: 'line' | 'plane';
  /** TLS methods: max RMS orthogonal distance of points from their line/plane (m), > 0; default 0.03 */
  sigma?: number;
  /** ftls/aftls 2D: corner (continuity) tolerance (m), > 0; default 0.3 */
  delta?: number;
  /** dp/rw: tolerance (m), > 0; default 0.09 */
  epsilon?: number;
  /** ftls/aftls/dp/rw: buffer reservation hint, integer >= 0 and at most the points 2 GB of wasm memory can hold
   *  (2^31 / (8 * dim): 134217728 in 2D, 89478485 in 3D; RangeError beyond, before any allocation). A call never
   *  reserves more than its own point count, so a large hint does not grow the memory. */
  maxSize?: number;
  /** aftls: initial simplex shift of the total-error optimizer, integer >= 1; default 1 */
  simplexShift?: number;
  /** aftls: iteration cap of the optimizer, integer >= 1; default 10000 */
  maxIterations?: number;
  /** ftls/aftls 2D: where a corner cannot be met within delta, break the polyline there, so that the result is
   *  several polylines covering the cluster (default true); false = RTL's strict behaviour: ok false, no segments,
   *  and `failure` names the corner */
  split?: boolean;
  /** record the vectorizer's steps in the result's `trace` (FtlsEvent for ftls/aftls, ItlsEvent, DpEvent, RwEvent);
   *  default false (the untraced C++ path). Not available for ftls/aftls/planes in 3D (RangeError). */
  trace?: boolean;
  /** dp: the distance a point is measured by: 'line' (default, RTL's: to the chord's infinite line) or 'segment'
   *  (to the chord segment, as simplify-js and Boost.Geometry: the same kept points as simplify(points, epsilon,
   *  true)). Checked and ignored by the other methods; not with trace (RangeError). */
  distance?: 'line' | 'segment';
  /** return the result's typed arrays (segments, polygons, indices, params, rms, polylineOffsets) as views on the
   *  module's result block in wasm memory instead of copies (no copy out); default false. Same numbers as the copies;
   *  with trace too. See RTL.pointBuffer for how long such views are valid. */
  view?: boolean;
}
// ---------------------------------------------------------------------------------------------- segment + vectorize
/** segmentAndVectorize(): segment() and vectorize() on each cluster, in one call into the module. */
export interface SegmentAndVectorizeOptions {
  dim?: Dim;                   // default 2
  /** clusters of fewer points are not vectorized; integer >= 2; default 3 */
  minPoints?: number;
  /** segment()'s options (trace and view are not available here) */
  segment?: Pick<SegmentOptions, 'step' | 'lowerBound' | 'upperBound' | 'origin'>;
  /** vectorize()'s options for every cluster: lines only (no primitive 'plane'), no trace or view */
  vectorize: Pick<VectorizeOptions, 'method' | 'sigma' | 'delta' | 'epsilon' | 'maxSize' | 'simplexShift' |
    'maxIterations' | 'split' | 'distance'>;
}
/** A vectorized cluster's failure (strict ftls/aftls): vectorize()'s failure on that cluster, message included. */
export interface SegmentAndVectorizeFailure extends VectorizeFailure {
  /** which vectorized cluster (j: cluster number vectorized[j]) */
  vectorized: number;
}
/**
 * segment()'s labels and clusters, then every vectorized cluster's vectorize() result back to back. V = the number of
 * vectorized clusters (those of at least minPoints points, in cluster order); cluster number vectorized[j]'s result
 * is sliced from the flat arrays by the offsets (each of V + 1 entries, the first 0); vectorizedCluster(r, j) gives it
 * in vectorize()'s shape. Every number equals segment() followed by vectorize() on each cluster's points exactly.
 */
export interface SegmentAndVectorizeResult extends SegmentResult {
  method: VectorizeMethod;
  dim: Dim;
  /** numbers per segment in params: 3 (2D line a, b, c) or 6 (3D point, direction) */
  stride: number;
  /** V: the cluster number of each vectorized cluster, ascending */
  vectorized: Uint32Array;
  /** V: vectorize()'s ok of each (1 or 0) */
  ok: Uint8Array;
  /** V + 1: vectorized cluster j has segments segmentOffsets[j] .. segmentOffsets[j + 1] - 1 */
  segmentOffsets: Uint32Array;
  /** 2 * dim numbers a segment (begin, end points) */
  segments: Float64Array;
  /** 2 numbers a segment: its half-open range of chain indices within its cluster (as vectorize()'s indices;
   *  chain index i is point clusters[vectorized[j]].indices[i]) */
  indices: Uint32Array;
  /** stride numbers a segment (as vectorize()'s params) */
  params: Float64Array;
  /** 1 number a segment (as vectorize()'s rms) */
  rms: Float64Array;
  /** V + 1: cluster j's polylineOffsets (vectorize()'s, cluster-local segment numbers) are
   *  polylineOffsets[polylineParts[j]] .. polylineOffsets[polylineParts[j + 1] - 1] */
  polylineParts: Uint32Array;
  polylineOffsets: Uint32Array;
  /** V + 1, counted in corners: cluster j's breaks are corners breakOffsets[j] .. breakOffsets[j + 1] - 1 */
  breakOffsets: Uint32Array;
  /** 3 numbers a corner: boundary, crossingDistance, delta (as vectorize()'s breaks) */
  breaks: Float64Array;
  /** the vectorized clusters whose vectorize() failed (strict ftls/aftls), in order; usually empty */
  failures: SegmentAndVectorizeFailure[];
}
/** A point of simplify-js's kind: {x, y}, or {x, y, z} for 3D. Other properties are kept (the objects are returned). */
export interface SimplifyPoint {
  x: number;
  y: number;
  z?: number;
}
/** A corner of an FTLS/AFTLS polyline that cannot be met within delta. */
export interface CornerReport {
  /** chain index of the first point of the range after the corner */
  boundary: number;
  /** how far the crossing of the two ranges' lines lies from the middle of points boundary - 1 and boundary
   *  (Infinity: the lines do not cross) */
  crossingDistance: number;
  delta: number;
}
export interface VectorizeFailure extends CornerReport {
  /** starts with "vectorize:"; names the corner and the numbers (strict mode; boundary 0: no partition within sigma
   *  at all) */
  message: string;
}
export interface VectorizeResult {
  method: VectorizeMethod;
  dim: Dim;
  primitive: 'line' | 'plane';
  /** false when the C++ vectorizer reported failure (then count is 0) */
  ok: boolean;
  /** number of segments (lines) or polygons (planes) */
  count: number;
  /** lines: count*2*dim numbers, segment k = (begin, end) points; planes: empty */
  segments: Float64Array;
  /** planes: polygon k's vertices (3 numbers each); lines: empty array */
  polygons: Float64Array[];
  /** half-open point-index range of each segment: [first0, end0, first1, end1, ...] (2*count). TLS methods: the
   *  ranges their lines were fitted to (consecutive, covering the chain; ftls/aftls in split mode, only on a chain that
   *  no partition into ranges within sigma fits, neighbouring ranges share one point). dp/rw: [key_k, key_k+1 + 1), the span between
   *  two kept points, both included (neighbouring spans share their kept point). */
  indices: Uint32Array;
  /**
   * fitted primitive of each range, `stride` numbers each:
   * 2D line: a, b, c of a*x + b*y + c = 0 (unit normal)   (stride 3)
   * 3D line: point (3) then unit direction (3)             (stride 6)
   * plane:   unit normal (3) then d of normal . p = d      (stride 4)
   */
  params: Float64Array;
  stride: number;
  /** RMS orthogonal distance of each range's points from its fitted primitive (for dp/rw: from the chord's line) */
  rms: Float64Array;
  /** segment index where each polyline starts, then the segment count: [0, count] for one polyline; with split,
   *  polyline p has segments polylineOffsets[p] .. polylineOffsets[p + 1] - 1 ([0, 0] when ok is false) */
  polylineOffsets: Uint32Array;
  /** ftls/aftls split mode: where the polyline broke (one entry between consecutive polylines); [] otherwise */
  breaks: CornerReport[];
  /** ftls/aftls, ok false: why (the corner that cannot be met); null otherwise and for other methods */
  failure: VectorizeFailure | null;
  /** with { trace: true } only: the vectorizer's steps, in order */
  trace?: FtlsEvent[] | ItlsEvent[] | DpEvent[] | RwEvent[];
}
/** The trace events of each method (vectorize with trace: true). */
export interface VectorizeEventByMethod { ftls: FtlsEvent; aftls: FtlsEvent; itls: ItlsEvent; dp: DpEvent; rw: RwEvent }

// ---------------------------------------------------------------------------------------------- traces
// With { trace: true }, segment(), vectorize() and StreamSegmenter record the steps the C++ algorithm takes, as plain
// objects { kind, ...fields } in order (the C++ event structs of rtl/seg/SegTrace.h, rtl/vect/FtlsTrace.h and
// rtl/vect/SimplifyTrace.h, converted generically: field names are the C++ names). Indices are point indices of the
// input (CAR: scan index; IA: stream index counted from the segmenter's first point; vectorizers: chain index);
// ranges are half-open [first, end). Distances, RMS values and errors are in the points' units. A replay from the
// first event to the last ends in the returned result (rules below); the same call always gives the same events.

/** CAR (segment). Replay: start with no point in a cluster; `start` puts i in a new cluster labelled i; `link` puts
 *  i in cluster `cluster`; `merge` relabels every point of cluster `from` as `into`. The `cluster` events at the end
 *  list the returned clusters in order (clusters[index]); labels are the smallest scan index of each cluster. */
export type CarEvent =
  /** loadData starts: scan size, step, window = step - 1 previous points compared, threshold scaling
   *  step * 2 pi / size and the bounds it is clamped to */
  | { kind: 'scan'; size: number; step: number; window: number; scaling: number; lowerBound: number; upperBound: number }
  /** point i has a non-finite coordinate: a gap, in no cluster, never compared */
  | { kind: 'gap'; i: number }
  /** point i's threshold: range = |p_i - origin|, raw = scaling * range, threshold = raw clamped to the bounds (the
   *  radius of the circle around p_i within which an earlier point is close) */
  | { kind: 'threshold'; i: number; range: number; raw: number; threshold: number }
  /** point i compared with the earlier point j of its window (1 <= i - j <= step - 1); linked = distance <= threshold */
  | { kind: 'compare'; i: number; j: number; distance: number; threshold: number; linked: boolean }
  /** point i joins the cluster `cluster` of j (its first linked comparison) */
  | { kind: 'link'; i: number; j: number; cluster: number }
  /** i, already in a cluster, is linked to j of another: cluster `from` merges into `into` (into < from), also
   *  after a linked seam comparison */
  | { kind: 'merge'; i: number; j: number; from: number; into: number }
  /** point i is close to no earlier point of its window: a new cluster labelled i */
  | { kind: 'start'; i: number }
  /** seam pass after the whole scan: i among the first points compared with j among the last (at most step - 1
   *  places apart across the seam), with i's threshold; linked = distance <= threshold */
  | { kind: 'seam'; i: number; j: number; distance: number; threshold: number; linked: boolean }
  /** returned cluster number `index`: its label, its first point (the end-of-scan part first for a cluster that
   *  wraps the seam) and its size */
  | { kind: 'cluster'; index: number; label: number; first: number; size: number };

/** IA (StreamSegmenter). Replay: `add` puts i in the window; `open`/`link` give it a cluster; `merge` renames
 *  `from` to `into` and merges the alive lists in stream order; `slide` removes i from the window; `alive` appends i
 *  to its cluster's alive list; `close` moves the cluster's alive list to the end of the closed queue. The replayed
 *  alive lists equal aliveClusters() and the closed queue takeClosedClusters(), in order. */
export type IaEvent =
  /** point i enters the window; gap: non-finite, takes a window place but joins no cluster */
  | { kind: 'add'; i: number; gap: boolean }
  /** the new point's threshold: range = |p_i - origin|, raw = scaling * range, threshold = raw clamped */
  | { kind: 'threshold'; i: number; range: number; raw: number; threshold: number }
  /** the new point i compared with window point j (the window holds the `step` previous points); linked =
   *  distance <= threshold */
  | { kind: 'compare'; i: number; j: number; distance: number; threshold: number; linked: boolean }
  /** i joins cluster `cluster` (j's): its first linked comparison */
  | { kind: 'link'; i: number; j: number; cluster: number }
  /** i, already in a cluster, is linked to j of another: cluster `from` merges into `into` (the older id) */
  | { kind: 'merge'; i: number; j: number; from: number; into: number }
  /** i is close to no window point: it opens cluster `cluster` (ids grow from 0) */
  | { kind: 'open'; i: number; cluster: number }
  /** the oldest window point i leaves the window (a valid point is followed by `alive`) */
  | { kind: 'slide'; i: number; gap: boolean }
  /** i, out of the window, is appended to its cluster's alive list */
  | { kind: 'alive'; i: number; cluster: number }
  /** cluster `cluster` has no point left in the window: it closes with `size` points */
  | { kind: 'close'; cluster: number; size: number };

/** FTLS / AFTLS 2D (vectorize, method 'ftls' or 'aftls'). branch: 0 = the FTLS partition, 1 = AFTLS's optimized
 *  one (AFTLS keeps both until `choice`). Replay: ranges[0] = []; each `range` drops the ranges that end after its
 *  first, then appends [first, end); after extraction AFTLS copies ranges[0] to ranges[1]; a `repair` replaces, in
 *  ranges[branch], the ranges inside [first, end) by the `inserted` repairRange events after it; a `move` moves
 *  boundary `breakpoint` of branch 1 from `from` to `to`; `choice` names the branch kept (none: ranges[0]); an
 *  `infeasible` ends a strict call with no result (in split mode a repair of branch 0 with method 6, or 8, follows and
 *  gives the polylines). The `segment` events at the end equal indices, polylineOffsets and segments exactly. */
export type FtlsEvent =
  /** a call begins: point count, sigma, delta; aftls: the optimizer runs; split: split mode */
  | { kind: 'start'; count: number; sigma: number; delta: number; aftls: boolean; split: boolean }
  /** the extractor tried [first, end): meanSquaredError of its TLS fit against sigma^2; pass = end - first == 2 or
   *  meanSquaredError < sigma^2. phase: 0 whole remainder, 1 gallop (lengths 4, 8, 16, ...), 2 bisection, 3 tail */
  | { kind: 'trial'; first: number; end: number; phase: 0 | 1 | 2 | 3; meanSquaredError: number; sigma: number; pass: boolean }
  /** the extractor accepted [first, end) */
  | { kind: 'range'; first: number; end: number }
  /** continuity check of the corner between ranges index and index + 1 of `branch`, at chain index boundary: the
   *  lines cross crossingDistance from the middle of points boundary - 1 and boundary (Infinity: parallel);
   *  ok = crossingDistance <= delta */
  | { kind: 'corner'; branch: 0 | 1; index: number; boundary: number; crossingDistance: number; delta: number; ok: boolean }
  /** a repair of `branch` replaced the ranges inside [first, end) by the next `inserted` repairRange events.
   *  method: 1 move the boundary, 2 merge, 3 three equal parts, 4 re-partition a window, 5 exact search over the
   *  whole chain, 6 split-mode search, 7 unchecked bridge, 8 split-mode cover whose ranges may share a point (only
   *  after `infeasible`, when no partition within sigma exists) */
  | { kind: 'repair'; branch: 0 | 1; method: 1 | 2 | 3 | 4 | 5 | 6 | 7 | 8; first: number; end: number; inserted: number }
  /** one range inserted by the preceding repair */
  | { kind: 'repairRange'; first: number; end: number }
  /** AFTLS optimizer: boundary `breakpoint` moved from `from` to `to`; totalError = total squared residual after it */
  | { kind: 'move'; breakpoint: number; from: number; to: number; totalError: number }
  /** AFTLS: total squared residuals of both branches (Infinity: no valid result) and the branch kept */
  | { kind: 'choice'; ftlsError: number; aftlsError: number; kept: 0 | 1 }
  /** strict mode found no valid partition: the corner that cannot be met (= the result's failure) */
  | { kind: 'infeasible'; boundary: number; crossingDistance: number; delta: number }
  /** final segment number index = range [first, end) of polyline `polyline`, from (x0, y0) to (x1, y1) */
  | { kind: 'segment'; index: number; first: number; end: number; polyline: number; x0: number; y0: number; x1: number; y1: number };

/** ITLS (vectorize, method 'itls', 2D and 3D). Replay: ranges = []; each `close` appends [first, end); a `tail`
 *  truncates the list to `kept` ranges and the `tailRange` events after it append the new last ranges. The `segment`
 *  events at the end equal indices and segments exactly. */
export type ItlsEvent =
  /** a call begins: point count, the RMS bound sigma */
  | { kind: 'start'; count: number; sigma: number }
  /** point `index` joined the running range that starts at `first` (now `count` points); rms of their fit; ranges
   *  of 3 and more points are tested (fits = !tested || rms < sigma); a point that does not fit is taken out again
   *  and a `close` follows */
  | { kind: 'add'; index: number; first: number; count: number; rms: number; sigma: number; tested: boolean; fits: boolean }
  /** range [first, end) closed with RMS rms: the next point would lift it to rmsWithNext >= sigma, or the chain
   *  ended (atEnd, rmsWithNext NaN) */
  | { kind: 'close'; first: number; end: number; rms: number; rmsWithNext: number; sigma: number; atEnd: boolean }
  /** the single last point `index` is placed by method (0 left out, 1 appended to the last range, 2 the last range
   *  gives up its last point, 3 the previous range takes a point, 4 the previous range gives up a point, 5 the last
   *  ranges re-partitioned): the first `kept` ranges stay, the next tailRange events replace the rest */
  | { kind: 'tail'; index: number; kept: number; method: 0 | 1 | 2 | 3 | 4 | 5 }
  /** a range of the repaired tail, with its RMS */
  | { kind: 'tailRange'; first: number; end: number; rms: number }
  /** final range number `range` = [first, end) and its segment from (x0, y0[, z0]) to (x1, y1[, z1]) (z in 3D only) */
  | { kind: 'segment'; range: number; first: number; end: number; x0: number; y0: number; z0?: number; x1: number; y1: number; z1?: number };

/** Douglas-Peucker (vectorize, method 'dp'). Replay: kept = {0, count - 1}; each `range` with split adds
 *  `farthest`; sorted, kept lists the polyline vertices. */
export type DpEvent =
  /** a call begins: point count, tolerance epsilon; the end points are kept */
  | { kind: 'start'; count: number; epsilon: number }
  /** range [first, last] (inclusive, in the recursion's order, depth first, left part first): `farthest` is the
   *  first interior point farthest from the line through points first and last, at `distance`; split = distance >
   *  epsilon: farthest is kept and [first, farthest], [farthest, last] come next */
  | { kind: 'range'; first: number; last: number; farthest: number; distance: number; epsilon: number; split: boolean };

/** Reumann-Witkam (vectorize, method 'rw'). Replay: the `keep` indices, in order, are the polyline vertices. */
export type RwEvent =
  /** a call begins: point count, strip half-width epsilon */
  | { kind: 'start'; count: number; epsilon: number }
  /** point `index` is kept (a polyline vertex): point 0, each key point, the last point */
  | { kind: 'keep'; index: number }
  /** a strip of half-width epsilon around the line from key point `key` through point `through`; the scan continues
   *  at through + 1 */
  | { kind: 'strip'; key: number; through: number; epsilon: number }
  /** point `index` lies outside the strip of key point `key`, at distance > epsilon from its axis; point index - 1
   *  becomes the next key */
  | { kind: 'exit'; index: number; key: number; distance: number; epsilon: number };

// ---------------------------------------------------------------------------------------------- drawings
export interface Drawing {
  /** 2 (default) */
  dim?: 2;
  /** 2D points (x,y interleaved); NaN points (gaps) are not drawn */
  points?: PointArray;
  /** cluster label per point (integer, -1 = no cluster): cluster k gets colour palette[k % 10] of the package's
   *  `palette` export (the Okabe-Ito based #0072B2, #E69F00, #009E73, #D55E00, #CC79A7, #56B4E9, #8C6D1F, #1B7837,
   *  #762A83, #332288), unlabelled points `unlabelledColour` (gray #808080); the same colours in SVG and TikZ */
  labels?: ArrayLike<number>;
  /** line segments x1,y1,x2,y2,... (finite) */
  segments?: PointArray;
  /** drawn above the picture (escaped for LaTeX / XML) */
  title?: string;
  /** toTikz: a complete LaTeX document (default) or a bare tikzpicture (false); the option wins if both are given */
  standalone?: boolean;
}
/** Faces of a 3D drawing: `vertices` x,y,z per vertex, all faces one after the other, `counts` the number of
 *  vertices of each face (>= 3, summing to vertices.length / 3). An array of flat vertex arrays (one per face, as
 *  vectorize's `polygons`) is accepted too. */
export type Faces = { vertices: PointArray; counts: ArrayLike<number> } | PointArray[];
/** A 3D scene for toTikz, rendered by the C++ rtl::LaTeXTikz3D (depth order, faces split where they cross). */
export interface Drawing3D {
  dim: 3;
  /** 3D points (x,y,z interleaved) drawn as dots; NaN points (gaps) are not drawn */
  points?: PointArray;
  /** cluster label per point, colours as Drawing.labels */
  labels?: ArrayLike<number>;
  /** line segments x1,y1,z1,x2,y2,z2,... (finite), black */
  segments?: PointArray;
  /** filled faces: face k in palette colour k % 10 (lighter from behind), outlined */
  planes?: Faces;
  /** outlines only (black), hidden where a plane is in front */
  polygons?: Faces;
  standalone?: boolean;
}
/** TikZ written by the C++ library (wasm/src/scan_drawing.h through rtl::LaTeXTikz2D; 3D: rtl::LaTeXTikz3D): minimal
 *  document + preview, StyleX/ColorX/MarkX names, the picture in data units with unit vectors x=..cm, y=..cm (no
 *  TeX dimension overflow for large coordinates); one uniform scale so that scans keep their shape. pdflatex's
 *  default memory holds about 15,000 marks: larger drawings are written in full; compile them with lualatex or pass
 *  fewer points. An empty 3D drawing gives "" (as LaTeXTikz3D::writeTEX). */
export interface TikzOptions {
  /** complete LaTeX document (default true) or only the tikzpicture */
  standalone?: boolean;
  /** picture size in cm (default 12 x 12, at most 400 so that the picture with its margins stays within TeX's
   *  dimensions; 2D: the data range is fitted inside, aspect kept; 3D: the picture) */
  width?: number;
  height?: number;
  /** point mark radius in cm (default 0.03; 3D: at the scene's centre, perspective-scaled elsewhere) */
  markRadius?: number;
  /** 3D only: field of view in degrees (default 60, in (0, 179]) and viewing direction (world, default [0, 0, -1];
   *  world +z stays up); the camera is placed so the scene just fits. Without it, LaTeXTikz3D's default view. */
  camera?: { fov?: number; direction?: ArrayLike<number> };
}
export interface LatexTableOptions {
  /** heading row */
  heading?: Array<string | number>;
  /** \caption text (none if empty) */
  caption?: string;
  /** escape every cell and the caption as plain text (default true); false: cells are LaTeX, written as given */
  escape?: boolean;
  /** tabular column specification (rtl::LaTeXTable::setColumnStyle, e.g. "l|r"); default one "c" per column */
  columns?: string;
}
/** SVG written by the C++ library (wasm/src/scan_drawing.h through rtl::writeSvg: the same drawing as toTikz's): an XML
 *  document whose width/height and viewBox are in cm, y axis up, points as <use> of one mark per cluster colour. */
export interface SvgOptions {
  /** CSS pixels, 96 per inch (default 800 x 800): the data range is fitted inside with one scale (aspect kept), the
   *  document adds a small margin (border and marks) */
  width?: number;
  height?: number;
  /** point radius in CSS pixels (default 2) */
  pointRadius?: number;
}

// ---------------------------------------------------------------------------------------------- readers
export interface CarmenScan {
  /** robot-frame points, one per beam in beam order (beam i at -pi/2 + i*pi/n, or i*pi/(n-1) for odd n);
   *  no-return beams are NaN points (gaps) */
  points: Float64Array;
  ranges: Float64Array;
  /** corrected pose in the map frame */
  x: number; y: number; theta: number;
  timestamp: number;
  /** 1-based line of the FLASER record in the log */
  line: number;
  /** the no-return value used (the same for every scan of a log): ranges >= it are gaps */
  maxRange: number;
  /** where maxRange came from: the option, a PARAM line of the log (e.g. robot_front_laser_max), the top range many
   *  beams of the log hit exactly, or 80 m when the log gives no evidence */
  maxRangeSource: 'explicit' | 'parameter' | 'recurring' | 'default';
}
export interface CarmenOptions {
  /** ranges >= maxRange are gaps (> 0; Infinity keeps every finite positive range). Default: detected from the
   *  log itself (its PARAM lines, or the maximum range that recurs in it) */
  maxRange?: number;
}
export type OrganizedLayout = 'column-major' | 'row-major';
export interface OrganizedLidarOptions {
  /** beams (rings) per column, integer >= 1 */
  beams: number;
  /** 'column-major' (Ouster: point k is beam k % beams of column k / beams; default) or 'row-major' */
  layout?: OrganizedLayout;
}
export interface OrganizedCloud {
  beams: number;
  columns: number;
  /** x,y,z per point, column-major whatever the file layout: beam b of column c is point c * beams + b;
   *  no-return points (0,0,0 in the file) are NaN */
  points: Float64Array;
  /** per point, in the same order as points */
  intensity: Float32Array;
  /** the points of one beam over all columns (x,y,z interleaved) */
  ring(beam: number): Float64Array;
  /** the points of one column, top to bottom */
  column(c: number): Float64Array;
}

export interface PcdOptions {
  /** further fields to read by name (default ['intensity', 'ring']); a name the file lacks is left out of `fields` */
  fields?: string[];
}
export interface PcdField {
  /** values per point (the field's COUNT) */
  count: number;
  /** count values per point, in the same order as points */
  values: Float64Array;
}
interface PcdCommon {
  /** the file's WIDTH and HEIGHT */
  width: number;
  height: number;
  /** VIEWPOINT: translation tx, ty, tz, then the orientation quaternion qw, qx, qy, qz */
  viewpoint: Float64Array;
  /** the requested fields that the file has, by name */
  fields: Record<string, PcdField>;
}
/** an organised PCD (height > 1) in readOrganizedLidar's shape: beams = height (rows, top to bottom), columns = width,
 *  column-major; NaN points (PCL's no return) stay NaN; intensity from the "intensity" field, else NaN */
export interface PcdOrganizedCloud extends OrganizedCloud, PcdCommon {
  organized: true;
}
/** an unorganised PCD (height 1): x, y, z per point in file order */
export interface PcdPointCloud extends PcdCommon {
  organized: false;
  points: Float64Array;
}
export type PcdCloud = PcdOrganizedCloud | PcdPointCloud;

export interface ExtractPolylinesOptions {
  /** vertices over the whole scan (a polyline of k segments has k + 1), integer >= 2; default 50 */
  maxVertices?: number;
  /** neighbouring beams farther apart (m) never share a polyline; finite, > 0; default 1 */
  maxGap?: number;
  /** radial error (m) beyond which a beam is better left unexplained; finite, > 0; default 0.5 */
  unexplainedCost?: number;
}
export interface ScanSegments {
  /** index of each segment's polyline */
  polyline: Uint32Array;
  /** first and last beam (inclusive) each segment was fitted to */
  firstBeam: Uint32Array;
  lastBeam: Uint32Array;
  /** the segment's line x cos(theta) + y sin(theta) = r, r >= 0 */
  r: Float64Array;
  theta: Float64Array;
  /** 2x2 covariance of (r, theta) per segment, row-major (4 numbers each) */
  covariance: Float64Array;
}
export interface ExtractPolylinesResult {
  /** each polyline's vertices (x, y interleaved): views on `vertices` */
  polylines: Float64Array[];
  /** every vertex, polyline after polyline; polyline k is vertices offsets[k] .. offsets[k + 1] - 1 */
  vertices: Float64Array;
  offsets: Uint32Array;
  /** r-hat per input beam: the range the polylines predict along the beam; NaN where no segment crosses it or the
   *  beam has no return */
  expectedRanges: Float64Array;
  segments: ScanSegments;
  /** total vertices (<= maxVertices) */
  vertexCount: number;
  /** beams with a return; 0 gives the empty result (no polylines, expectedRanges all NaN, rmse/explained/score NaN) */
  returned: number;
  explainedBeams: number;
  /** root mean square radial error over the explained beams (NaN when none) */
  rmse: number;
  /** explained beams / returned beams */
  explained: number;
  /** mean per returned beam of the squared radial error, or unexplainedCost squared for an unexplained beam */
  score: number;
}

// ---------------------------------------------------------------------------------------------- stateful classes
export interface StreamSegmenterOptions {
  dim?: Dim;          // default 2
  /** sliding window length: each new point is compared with up to `step` previous points (IA), integer >= 1;
   *  default 3. IA step s corresponds to segment()'s (CAR) step s + 1 with scaling (s + 1) * 2 pi / N. */
  step?: number;
  /** lower bound of the distance threshold (m), >= 0; default 0.1 */
  lowerBound?: number;
  /** upper bound (m), >= lowerBound, may be Infinity; default 0.5 */
  upperBound?: number;
  /** threshold = scaling * |p - origin| clamped to [lowerBound, upperBound]; >= 0, default 0.05
   *  ((step + 1) * 2 pi / N gives segment()'s criterion at CAR step step + 1 for a scan of N beams) */
  scaling?: number;
  /** record every step (IaEvent), handed out by takeTrace(); default false (the untraced C++ path) */
  trace?: boolean;
}
/** Streaming (IA) segmenter over rtl::IA_Segmenter. Construct it through the module: `new rtl.StreamSegmenter(options)`.
 *  It owns wasm memory: call dispose() (or use `using`); a FinalizationRegistry frees it if you forget. */
export interface StreamSegmenter {
  readonly dim: Dim;
  /** feeds points in stream order (origin: dim finite numbers, default zeros); a NaN point is a gap: it takes a
   *  window place but joins no cluster */
  addPoints(points: PointArray, origin?: ArrayLike<number>): void;
  readonly closedClustersAvailable: number;
  readonly aliveClustersAvailable: number;
  /** removes and returns the closed clusters, in closing order, each as interleaved points in stream order; the
   *  clusters of one call are views on one new Float64Array (take `.slice()` of a cluster to keep it apart) */
  takeClosedClusters(): Float64Array[];
  /** current alive clusters (points that left the window, cluster not closed yet), not removed; views on one new
   *  Float64Array per call, as takeClosedClusters() */
  aliveClusters(): Float64Array[];
  /** end of stream: every window point leaves the window, so every cluster closes */
  flush(): void;
  /** whether it was made with { trace: true } */
  readonly traced: boolean;
  /** the steps recorded since the last call (IaEvent, in order), then forgotten; TypeError unless made with
   *  { trace: true } */
  takeTrace(): IaEvent[];
  dispose(): void;
  [Symbol.dispose](): void;
  readonly disposed: boolean;
}

export interface Transform2D {
  /** rotation angle (rad), counter-clockwise; default 0 */
  angle?: number;
  /** default [0, 0] */
  translation?: ArrayLike<number>;
}
export interface Transform3D {
  /** rotation as a quaternion [w, x, y, z] (normalised for you); or give angle + axis; default identity */
  quaternion?: ArrayLike<number>;
  angle?: number;
  axis?: ArrayLike<number>;
  /** default [0, 0, 0] */
  translation?: ArrayLike<number>;
}
/** v -> rotation * v + translation */
export interface RigidTransform {
  dim: Dim;
  /** rotation matrix, row-major dim x dim */
  rotation: Float64Array;
  translation: Float64Array;
  /** homogeneous (dim+1) x (dim+1) matrix, row-major */
  matrix: Float64Array;
}
/** A tree of named frames holding rigid transformations, over rtl::TfTree<std::string, RigidTfND<dim, double>>.
 *  Construct it through the module: `new rtl.TfTree(rootName, { dim })`. It owns wasm memory: call dispose()
 *  (or use `using`); a FinalizationRegistry frees it if you forget. */
export interface TfTree {
  readonly dim: Dim;
  /** number of frames, the root included */
  readonly size: number;
  /** adds frame `name` under `parent`; `tf` maps coordinates of `parent` to coordinates of `name` (as in
   *  rtl::TfTree). false (nothing changed) if the parent is unknown or the name exists */
  insert(name: string, parent: string, tf: Transform2D | Transform3D): boolean;
  /** removes the frame and its subtree; false for the root or an unknown name */
  erase(name: string): boolean;
  contains(name: string): boolean;
  /** the transformation that maps coordinates of frame `from` to frame `to` (RangeError for an unknown frame) */
  tf(from: string, to: string): RigidTransform;
  /** applies tf(from, to) to every point (dim numbers each; NaN points stay NaN) */
  transformPoints(from: string, to: string, points: PointArray): Float64Array;
  dispose(): void;
  [Symbol.dispose](): void;
  readonly disposed: boolean;
}

// ---------------------------------------------------------------------------------------------- algorithms
export interface AssignOptions { rows?: number; cols?: number; /** default false */ maximize?: boolean }
export interface AssignResult { columns: Int32Array; total: number }
export interface KalmanFilterOptions {
  stateDim: number;
  measurementDim: number;
  /** default 0 */
  controlDim?: number;
  /** Q = I * processNoise (default 1) */
  processNoise?: number;
  /** R = I * observationNoise (default 1) */
  observationNoise?: number;
}
/** Linear Kalman filter over rtl::KalmanX<double> (RTL's defaults: x = 0, A = I, B = 0, P = I, H = 0). Matrices are
 *  row-major (rows x cols numbers: A, P, Q n x n; B n x controlDim; H measurementDim x n; R measurementDim^2).
 *  Construct it through the module: `new rtl.KalmanFilter(options)`. It owns wasm memory: call dispose() (or use
 *  `using`); a FinalizationRegistry frees it if you forget. Calls after dispose() throw TypeError. */
export interface KalmanFilter {
  readonly stateDim: number;
  readonly measurementDim: number;
  readonly controlDim: number;
  setState(x: PointArray): void;
  setTransitionMatrix(A: PointArray): void;
  setControlMatrix(B: PointArray): void;
  setCovarianceMatrix(P: PointArray): void;
  setMeasurementMatrix(H: PointArray): void;
  setProcessNoiseCovariance(Q: PointArray): void;
  setMeasurementNoiseCovariance(R: PointArray): void;
  /** x = A x + B u, P = A P A^T + Q (control u: controlDim numbers, default zeros) */
  predict(control?: PointArray): void;
  /** K = P H^T (H P H^T + R)^-1, x += K (z - H x), P in Joseph form */
  correct(measurement: PointArray): void;
  /** copies of x and P (row-major) */
  state(): Float64Array;
  covariance(): Float64Array;
  dispose(): void;
  [Symbol.dispose](): void;
  readonly disposed: boolean;
}

// ---------------------------------------------------------------------------------------------- the module
export interface RTL {
  readonly version: string;
  fitLine(points: PointArray, options?: { dim?: 2 }): LineFit2D;
  fitLine(points: PointArray, options: { dim: 3 }): LineFit3D;
  fitLine(points: PointArray, options?: LineFitOptions): LineFit2D | LineFit3D;
  segment(points: PointArray, options: SegmentOptions & { trace: true }): SegmentResult & { trace: CarEvent[] };
  segment(points: PointArray, options?: SegmentOptions): SegmentResult;
  vectorize<M extends VectorizeMethod>(points: PointArray, options: VectorizeOptions & { method: M; trace: true }):
    VectorizeResult & { trace: VectorizeEventByMethod[M][] };
  vectorize(points: PointArray, options: VectorizeOptions): VectorizeResult;
  /** segment() and then vectorize() on every cluster of at least minPoints points, in ONE call into the module (a
   *  scan of 360 beams has ~20 clusters: one call instead of ~21). Same numbers as those calls, laid out flat with
   *  offsets (SegmentAndVectorizeResult). Coordinates: NaN is a gap, every other within +-1e18 (RangeError). Errors:
   *  TypeError/RangeError starting "segmentAndVectorize:". The module's memory does not grow across repeated calls
   *  of one size. */
  segmentAndVectorize(points: PointArray, options: SegmentAndVectorizeOptions): SegmentAndVectorizeResult;
  /** vectorized cluster j (0 <= j < r.vectorized.length) of a segmentAndVectorize() result in vectorize()'s shape,
   *  its arrays views on r's (TypeError/RangeError starting "vectorizedCluster:") */
  vectorizedCluster(r: SegmentAndVectorizeResult, j: number): VectorizeResult;
  toTikz(drawing: Drawing | Drawing3D, options?: TikzOptions): string;
  /** a LaTeX table (rtl::LaTeXTable: table/center/tabular, cells joined by " & "); rows are arrays of cells
   *  (numbers written with String()), a null row is a \hline */
  toLatexTable(rows: ReadonlyArray<ReadonlyArray<string | number> | null>, options?: LatexTableOptions): string;
  /** optimal assignment (Munkres / Hungarian, rtl::solveAssignment) of rows to distinct columns: min(rows, cols)
   *  pairs with the least (maximize: greatest) total cost. costs: row-major rows*cols numbers (rows/cols options;
   *  a square matrix needs neither) or an array of equal-length rows. columns[i]: the column of row i, -1 for rows
   *  left out (rows > cols); total: the sum of the assigned costs. */
  assign(costs: PointArray | ReadonlyArray<PointArray>, options?: AssignOptions): AssignResult;
  KalmanFilter: new (options: KalmanFilterOptions) => KalmanFilter;
  /** Drop-in for simplify-js's simplify(points, tolerance, highQuality): keeps exactly the points simplify-js
   *  keeps (its radial-distance pre-pass unless highQuality, then Douglas-Peucker on the squared distance to the
   *  chord segment), computed in C++ (rtl/vect/SimplifyCompatible.h). Objects form: returns a new array of the
   *  caller's own objects (or `points` itself when it has 2 or fewer, as simplify-js does); 3D when options.dim is
   *  3 or the first point has a numeric z (every point then needs one). Typed-array form: interleaved coordinates
   *  (options.dim, default 2) in, the kept points' coordinates out as a Float64Array. tolerance: default 1, >= 0
   *  (Infinity keeps the end points only); highQuality: default false. TypeError for a wrong kind of value,
   *  RangeError for a negative or NaN tolerance or a non-finite coordinate. */
  simplify<P extends SimplifyPoint>(points: P[], tolerance?: number, highQuality?: boolean, options?: { dim?: Dim }): P[];
  simplify(points: Float64Array | Float32Array, tolerance?: number, highQuality?: boolean, options?: { dim?: Dim }): Float64Array;
  /** frees the input buffer, vectorizers and segmenters the module keeps between calls (so that a repeated call
   *  neither allocates nor zero-fills; inputs above 2^21 points release theirs after the call anyway); they grow
   *  back on the next call */
  releaseBuffers(): void;
  /** zero-copy input: a Float64Array of n * dim numbers (dim 2 or 3, default 2) on a block of wasm memory the
   *  module keeps. Fill it with interleaved coordinates and pass it (or a subarray of it) as the points of
   *  vectorize, segment or simplify: they read it in place instead of copying it in. Calls never move the block;
   *  a later pointBuffer() may (same or smaller size: same block), releaseBuffers() and heapInUse() free it, and
   *  wasm memory growth detaches the view (length 0): check `view.length` and take a new one. A view on the module's
   *  memory outside the current block, or a detached one, is rejected with a TypeError.
   *
   *  Zero-copy output, its counterpart: segment() and vectorize() with { view: true } return their typed arrays as
   *  views on the module's result block. Such a view is valid until the next segment(), vectorize() or simplify()
   *  call, releaseBuffers() or heapInUse(): these refill or free the block, after which the view may show another
   *  call's numbers or freed memory, and must be neither read nor written (writing can corrupt the module's heap).
   *  Until then, writing into it changes nothing the module uses. Other calls leave it as it is, unless they grow
   *  wasm memory, which detaches it (length 0) as it does pointBuffer()'s views. Keep a result with `.slice()`; a
   *  Float64Array view passed back as points is rejected with a TypeError (the call would overwrite it). */
  pointBuffer(n: number, dim?: Dim): Float64Array;
  toSvg(drawing: Drawing, options?: SvgOptions): string;
  /** every FLASER scan of a CARMEN log (the text, or the file's bytes); beams without a return (range <= 0, not
   *  finite, or >= maxRange: the log's own no-return value unless given) are NaN points. RangeError starting
   *  "readCarmenLog: line N:" for a malformed line, a non-finite pose or timestamp. */
  readCarmenLog(text: string | ArrayBuffer | ArrayBufferView, options?: CarmenOptions): CarmenScan[];
  /** alias of readCarmenLog */
  readCarmen(text: string | ArrayBuffer | ArrayBufferView, options?: CarmenOptions): CarmenScan[];
  readOrganizedLidar(data: ArrayBuffer | ArrayBufferView, options: OrganizedLidarOptions): OrganizedCloud;
  /** a PCD file (PCL's format: ascii, binary or binary_compressed) read by the C++ core (rtl/io/PcdFile.h).
   *  RangeError starting "readPcd: " for a malformed file, naming the header or data line, the point and the byte
   *  offset (e.g. "readPcd: point 15 at byte offset 593: truncated data: ..."). */
  readPcd(data: ArrayBuffer | ArrayBufferView, options?: PcdOptions): PcdCloud;
  /** whole-scan polylines within a vertex budget (rtl::ScanPolylines2D): points are the scan's beams in the sensor
   *  frame (sensor at the origin), x, y interleaved, in beam order, NaN for no return. Within maxVertices the
   *  polylines minimise the mean per returned beam of the squared radial error (or unexplainedCost squared for a
   *  beam left unexplained). TypeError/RangeError starting "extractPolylines: " for bad arguments. */
  extractPolylines(points: PointArray, options?: ExtractPolylinesOptions): ExtractPolylinesResult;
  /** sensor_msgs/LaserScan or foxglove.LaserScan -> the scan's points (also rtl-wasm/ros) */
  fromLaserScan: typeof import('./ros/messages.js').fromLaserScan;
  /** sensor_msgs/PointCloud2 -> readOrganizedLidar's shape (organised) or points (also rtl-wasm/ros) */
  fromPointCloud2: typeof import('./ros/messages.js').fromPointCloud2;
  StreamSegmenter: new (options?: StreamSegmenterOptions) => StreamSegmenter;
  TfTree: new (root: string, options?: { dim?: Dim }) => TfTree;
  /** bytes of wasm heap allocated by malloc once the buffers kept between calls are released (releaseBuffers():
   *  equal figures before and after a series of calls mean nothing leaked; diagnostics, used by the leak tests).
   *  Without a module name: the sum over the core and every loaded module; with one, that module's. */
  heapInUse(module?: PackageModule): number;
  /** bytes of wasm linear memory (without a module name: the sum over the loaded modules) */
  memoryBytes(module?: PackageModule): number;
  /** milliseconds the last segment()/vectorize()/simplify()/extractPolylines() call spent inside the C++ library (the rest of the call's time
   *  is argument checks and array transfer); diagnostics for benchmarks */
  readonly lastComputeMs: number;
  /** the wasm shadow-stack pointer (diagnostics: it is the same before and after every call, failing or not);
   *  without a module name, the sum over the loaded modules' */
  stackPointer(module?: PackageModule): number;
  // ---- modules loaded on demand (the extras module)
  /** Loads a module of the package on demand and resolves to this object. 'extras' (rtl-extras.wasm + its glue)
   *  holds toSvg, toTikz, toLatexTable, readPcd, assign and KalmanFilter. The Node entries (import in Node,
   *  require) load it in init(), so there this resolves at once; the browser entry loads it here (or in
   *  init({ load: ['extras'] })). Idempotent: later calls get the same promise (after a failed load, a new try).
   *  Calling one of its functions before it is loaded throws an Error whose message starts with the function's
   *  name and says to call `await rtl.load('extras')`. TypeError/RangeError starting "load: " for a bad name;
   *  an Error starting "load: " when the module cannot be fetched or started. */
  load(name: ModuleName): Promise<RTL>;
  // ---- end of the modules loaded on demand
}

// ---- modules loaded on demand (the extras module)
/** A module of the package loaded on demand (RTL.load). */
export type ModuleName = 'extras';
/** A module of the package, for the diagnostics (heapInUse, memoryBytes, stackPointer): the core or a loaded one. */
export type PackageModule = 'core' | ModuleName;
// ---- end of the modules loaded on demand
