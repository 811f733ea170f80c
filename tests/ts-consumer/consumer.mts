// A TypeScript consumer of the package's hand-written index.d.ts, checked with `tsc --noEmit` (tests/js/types.test.mjs).
// It uses every export the way the README shows; the @ts-expect-error lines check that misuse does not type-check.
import init, { init as namedInit, defaults, palette, unlabelledColour } from 'rtl-wasm';
import type {
  RTL, LineFit2D, LineFit3D, SegmentResult, VectorizeResult, CarmenScan, OrganizedCloud, Drawing, RigidTransform,
  StreamSegmenter, TfTree,
} from 'rtl-wasm';

const rtl: RTL = await init();
const other: RTL = await namedInit({ wasmBinary: new Uint8Array(8) });
const version: string = rtl.version + other.version;
// The drawings' colours, for pages that show clusters alike: read-only.
const clusterColour: string = palette[3 % palette.length]! + unlabelledColour;
const sigma: number = defaults.vectorize.sigma + defaults.segment.step;
// @ts-expect-error: the defaults are read-only
void (() => { defaults.segment.step = 3; });
// @ts-expect-error: the palette is read-only
void (() => { palette[0] = '#000000'; });

const xy = new Float64Array([0, 0, 1, 1, 2, 2]);
const f2: LineFit2D = rtl.fitLine(xy);
const f3: LineFit3D = rtl.fitLine([0, 0, 0, 1, 1, 1], { dim: 3 });
const nx: number = f2.normal[0]! + f2.offset + f2.rms + f3.direction[2]!;

const seg: SegmentResult = rtl.segment(new Float32Array(xy), { step: 3, lowerBound: 0.1, upperBound: 0.5, origin: [0, 0] });
const firstLabel: number = seg.labels[0]!;
const ranges: Uint32Array = seg.clusters[0]!.ranges;

const v: VectorizeResult = rtl.vectorize(xy, { method: 'aftls', sigma: 0.03, delta: 0.3, simplexShift: 1, maxIterations: 100 });
const planes = rtl.vectorize([0, 0, 0], { dim: 3, method: 'aftls', primitive: 'plane' });
const polys: Float64Array[] = planes.polygons;
const segs: Float64Array = v.segments;
const ok: boolean = v.ok && v.count === v.indices.length / 2 && v.stride > 0;

const drawing: Drawing = { points: xy, labels: seg.labels, segments: segs, title: 'scan' };
const svg: string = rtl.toSvg(drawing, { width: 400, height: 300, pointRadius: 1 });
const tex: string = rtl.toTikz(drawing, { standalone: false, width: 8 });

const scans: CarmenScan[] = rtl.readCarmenLog('FLASER ...');
const pose: number = scans[0]!.x + scans[0]!.theta;
const cloud: OrganizedCloud = rtl.readOrganizedLidar(new ArrayBuffer(64), { beams: 4, layout: 'row-major' });
const ring: Float64Array = cloud.ring(0);
const intensity: Float32Array = cloud.intensity;

{
  using stream: StreamSegmenter = new rtl.StreamSegmenter({ step: 3, scaling: 0.05 });
  stream.addPoints(xy, [0, 0]);
  const closed: Float64Array[] = stream.takeClosedClusters();
  const alive: number = stream.aliveClustersAvailable + closed.length;
  stream.flush();
}

const tree: TfTree = new rtl.TfTree('map', { dim: 2 });
tree.insert('robot', 'map', { angle: 0.5, translation: [1, 2] });
const t: RigidTransform = tree.tf('robot', 'map');
const moved: Float64Array = tree.transformPoints('robot', 'map', xy);
const m: number = t.matrix[0]! + t.rotation[0]! + moved[0]!;
tree.dispose();
const tree3: TfTree = new rtl.TfTree('world', { dim: 3 });
tree3.insert('cam', 'world', { quaternion: [1, 0, 0, 0], translation: [0, 0, 1] });
tree3.insert('lidar', 'cam', { angle: 0.1, axis: [0, 0, 1], translation: [0, 0, 0] });
tree3[Symbol.dispose]();

const diagnostics: number = rtl.heapInUse() + rtl.memoryBytes() + rtl.stackPointer();

// @ts-expect-error: method is required
rtl.vectorize(xy, { sigma: 0.1 });
// @ts-expect-error: unknown method
rtl.vectorize(xy, { method: 'spline' });
// @ts-expect-error: dim is 2 or 3
rtl.segment(xy, { dim: 4 });
// @ts-expect-error: points must be numbers
rtl.fitLine(["a", "b"]);
// @ts-expect-error: beams is required
rtl.readOrganizedLidar(new ArrayBuffer(16), {});
// @ts-expect-error: a 3D fit has no normal
rtl.fitLine(xy, { dim: 3 }).normal;

export { version, clusterColour, sigma, nx, firstLabel, ranges, polys, ok, svg, tex, pose, ring, intensity, m, diagnostics };

// Traces: discriminated unions narrow on kind.
const traced = rtl.segment(xy, { trace: true });
for (const e of traced.trace) {
  if (e.kind === 'compare') { const linked: boolean = e.linked; const d: number = e.distance - e.threshold; void linked; void d; }
  // @ts-expect-error: a cluster event has no distance
  if (e.kind === 'cluster') void e.distance;
}
const ft = rtl.vectorize(xy, { method: 'ftls', trace: true, split: false });
for (const e of ft.trace) if (e.kind === 'corner') { const ok: boolean = e.ok && e.crossingDistance <= e.delta; void ok; }
const failure: string | undefined = ft.failure?.message;
const offsets: Uint32Array = ft.polylineOffsets;
const dpTrace = rtl.vectorize(xy, { method: 'dp', trace: true }).trace;
for (const e of dpTrace) if (e.kind === 'range') { const f: number = e.farthest; void f; }
const s2 = new rtl.StreamSegmenter({ trace: true });
const iaEvents: { kind: string }[] = s2.takeTrace();
s2.dispose();
export { failure, offsets, iaEvents };
