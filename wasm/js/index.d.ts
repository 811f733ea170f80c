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
  /** Where the .wasm lives when it is hosted somewhere else (a CDN). Do not pass it with a bundler. */
  locateFile?: (path: string, scriptDirectory: string) => string;
}

/** Loads and instantiates the WebAssembly module. Each call makes an independent instance. A wasmBinary that is
 *  not a WebAssembly module, or not this package's, rejects with a TypeError whose message starts with "init:"
 *  (nothing is printed). */
export default function init(options?: InitOptions): Promise<RTL>;
export { init };

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
   *  ranges their lines were fitted to (consecutive, covering the chain). dp/rw: [key_k, key_k+1 + 1), the span between
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
}

// ---------------------------------------------------------------------------------------------- drawings
export interface Drawing {
  /** 2D points (x,y interleaved); NaN points (gaps) are not drawn */
  points?: PointArray;
  /** cluster label per point (integer, -1 = no cluster): cluster k gets colour k % 10 of the Okabe-Ito based
   *  palette of the demo page (#0072B2, #E69F00, #009E73, #D55E00, #CC79A7, #56B4E9, #8C6D1F, #1B7837, #762A83,
   *  #332288), unlabelled points gray #808080; the same colours in SVG and TikZ */
  labels?: ArrayLike<number>;
  /** line segments x1,y1,x2,y2,... (finite) */
  segments?: PointArray;
  /** drawn above the picture (escaped for LaTeX / XML) */
  title?: string;
  /** toTikz: a complete LaTeX document (default) or a bare tikzpicture (false); the option wins if both are given */
  standalone?: boolean;
}
/** TikZ in the conventions of the C++ rtl::LaTeXTikz2D (minimal document + preview, StyleX/ColorX/MarkX names,
 *  picture in data units scaled to the size); unlike it, one uniform scale so that scans keep their shape. */
export interface TikzOptions {
  /** complete LaTeX document (default true) or only the tikzpicture */
  standalone?: boolean;
  /** picture size in cm (default 12 x 12; the data range is fitted inside, aspect kept) */
  width?: number;
  height?: number;
  /** point mark radius in cm (default 0.03) */
  markRadius?: number;
}
export interface SvgOptions {
  /** pixels (default 800 x 800; the data range is fitted inside, aspect kept, y axis up) */
  width?: number;
  height?: number;
  /** point radius in pixels (default 2) */
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
  /** removes and returns the closed clusters, in closing order, each as interleaved points in stream order */
  takeClosedClusters(): Float64Array[];
  /** current alive clusters (points that left the window, cluster not closed yet), not removed */
  aliveClusters(): Float64Array[];
  /** end of stream: every window point leaves the window, so every cluster closes */
  flush(): void;
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

// ---------------------------------------------------------------------------------------------- the module
export interface RTL {
  readonly version: string;
  fitLine(points: PointArray, options?: { dim?: 2 }): LineFit2D;
  fitLine(points: PointArray, options: { dim: 3 }): LineFit3D;
  fitLine(points: PointArray, options?: LineFitOptions): LineFit2D | LineFit3D;
  segment(points: PointArray, options?: SegmentOptions): SegmentResult;
  vectorize(points: PointArray, options: VectorizeOptions): VectorizeResult;
  toTikz(drawing: Drawing, options?: TikzOptions): string;
  toSvg(drawing: Drawing, options?: SvgOptions): string;
  /** every FLASER scan of a CARMEN log (the text, or the file's bytes); beams without a return (range <= 0,
   *  not finite, or >= maxRange, default 80 m) are NaN points. RangeError naming the line for a malformed line. */
  readCarmenLog(text: string | ArrayBuffer | ArrayBufferView, options?: { maxRange?: number }): CarmenScan[];
  /** alias of readCarmenLog */
  readCarmen(text: string | ArrayBuffer | ArrayBufferView, options?: { maxRange?: number }): CarmenScan[];
  readOrganizedLidar(data: ArrayBuffer | ArrayBufferView, options: OrganizedLidarOptions): OrganizedCloud;
  StreamSegmenter: new (options?: StreamSegmenterOptions) => StreamSegmenter;
  TfTree: new (root: string, options?: { dim?: Dim }) => TfTree;
  /** bytes of wasm heap currently allocated by malloc (diagnostics; used by the leak tests) */
  heapInUse(): number;
  /** bytes of wasm linear memory */
  memoryBytes(): number;
  /** milliseconds the last segment()/vectorize() call spent inside the C++ library (the rest of the call's time
   *  is argument checks and array transfer); diagnostics for benchmarks */
  readonly lastComputeMs: number;
  /** the wasm shadow-stack pointer (diagnostics: it is the same before and after every call, failing or not) */
  stackPointer(): number;
}
