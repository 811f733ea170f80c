// The rtl command's pipeline on one scan: reading the single-scan inputs (CARMEN, organised binary, CSV), segmenting,
// fitting/vectorizing (run), and drawing (render). Shared by bin/rtl.js and the log workers (bin/log-job.js).
import { readFileSync } from 'node:fs';
import { basename } from 'node:path';
import { UsageError } from './options.js';

class InputError extends Error {}
class MissingFeature extends Error {}

// The package grows function by function; say clearly when this build lacks one instead of failing obscurely.
function need(rtl, name, what) {
  if (typeof rtl[name] !== 'function') {
    throw new MissingFeature(`${what} needs ${name}(), which this build of rtl-wasm (${rtl.version ?? 'unknown version'}) does not have`);
  }
  return rtl[name].bind(rtl);
}

const inputName = (file) => (file === '-' ? 'stdin' : file);

function readInput(file, binary) {
  try {
    const buf = readFileSync(file === '-' ? 0 : file);
    return binary ? buf : buf.toString('utf8');
  } catch (e) {
    throw new InputError(`cannot read "${file}": ${e.code === 'ENOENT' ? 'no such file' : e.message}`);
  }
}

// CSV: x,y or x,y,z per line. A first line that is not numeric is a header. Empty/NaN coordinates are gaps.
function parseCsv(text, name = 'input') {
  const rows = [];
  let dim = 0;
  const lines = text.split(/\r?\n/);
  lines.forEach((raw, li) => {
    const line = raw.replace(/#.*/, '').trim();
    if (!line) return;
    const fields = line.split(/\s*[,;\t ]\s*/);
    const vals = fields.map((f) => (f === '' || /^nan$/i.test(f) ? NaN : Number(f)));
    const bad = fields.findIndex((f, k) => Number.isNaN(vals[k]) && !(f === '' || /^nan$/i.test(f)));
    if (bad >= 0) {
      if (rows.length === 0 && dim === 0 && fields.every((f) => Number.isNaN(Number(f)))) { dim = -1; return; } // header
      throw new InputError(`${name}:${li + 1}: "${fields[bad]}" is not a number`);
    }
    if (fields.length < 2 || fields.length > 3) throw new InputError(`${name}:${li + 1}: expected 2 or 3 coordinates, got ${fields.length}`);
    if (dim <= 0) dim = fields.length;
    else if (fields.length !== dim) throw new InputError(`${name}:${li + 1}: expected ${dim} coordinates like the lines before, got ${fields.length}`);
    rows.push(vals.map((x) => (Number.isFinite(x) ? x : NaN)));
  });
  if (rows.length === 0) throw new InputError(`${name}: no points found`);
  const out = new Float64Array(rows.length * dim);
  rows.forEach((r, i) => out.set(r, i * dim));
  return { points: out, dim };
}

async function loadPoints(rtl, opts) {
  const name = inputName(opts.file);
  if (opts.type === 'csv') {
    const { points, dim } = parseCsv(readInput(opts.file, false), name);
    return { points, dim, source: { type: 'csv', file: opts.file } };
  }
  if (opts.type === 'carmen') {
    const text = readInput(opts.file, false);
    let scans;
    try {
      scans = need(rtl, 'readCarmenLog', 'a CARMEN log')(text, opts.maxRange === undefined ? undefined : { maxRange: opts.maxRange });
    } catch (e) {
      if (e instanceof MissingFeature) throw e;
      throw new InputError(`${name}: ${e.message}`);
    }
    if (scans.length === 0) throw new InputError(`${name}: no laser scans (FLASER lines) found`);
    if (opts.scan >= scans.length) throw new InputError(`${name}: --scan ${opts.scan} is out of range, the log has ${scans.length} scans (0..${scans.length - 1})`);
    const s = scans[opts.scan];
    return {
      points: Float64Array.from(s.points), dim: 2,
      source: {
        type: 'carmen', file: opts.file, scan: opts.scan, scans: scans.length, line: s.line,
        // The no-return value used (ranges >= it are gaps) and where it came from (the option, the log, ...).
        ...(s.maxRange !== undefined ? { maxRange: round(s.maxRange) } : {}),
        ...(s.maxRangeSource !== undefined ? { maxRangeSource: s.maxRangeSource } : {}),
        pose: { x: s.x, y: s.y, theta: s.theta },
      },
    };
  }
  const buf = readInput(opts.file, true);
  const layout = opts.layout === 'row' ? 'row-major' : 'column-major';
  const read = need(rtl, 'readOrganizedLidar', 'a binary scan');
  let cloud;
  try {
    cloud = read(buf, { beams: opts.beams, layout });
  } catch (e) {
    throw new InputError(`${name}: ${e.message}`);
  }
  let points, what;
  if (opts.column !== undefined) {
    if (opts.column >= cloud.columns) throw new InputError(`${name}: --column ${opts.column} is out of range, the scan has ${cloud.columns} columns`);
    points = cloud.column(opts.column); what = { column: opts.column };
  } else {
    const ring = opts.ring ?? 0;
    if (ring >= cloud.beams) throw new InputError(`${name}: --ring ${ring} is out of range, the scan has ${cloud.beams} beams`);
    points = cloud.ring(ring); what = { ring };
  }
  return { points, dim: 3, source: { type: 'bin', file: opts.file, beams: cloud.beams, columns: cloud.columns, ...what } };
}

function gather(points, dim, indices) {
  const out = new Float64Array(indices.length * dim);
  indices.forEach((k, j) => { for (let d = 0; d < dim; d++) out[j * dim + d] = points[k * dim + d]; });
  return out;
}

// The streaming (IA) segmenter fed in point order and flushed; its clusters come back as points, mapped to point
// indices by their exact coordinates (the package returns the doubles it was given).
function streamSegment(rtl, points, dim, opts) {
  if (typeof rtl.StreamSegmenter !== 'function') {
    throw new MissingFeature(`--segmenter ia needs StreamSegmenter, which this build of rtl-wasm (${rtl.version}) does not have`);
  }
  const seg = new rtl.StreamSegmenter({ dim, step: opts.step, lowerBound: opts.lower, upperBound: opts.upper, scaling: opts.scaling });
  try {
    seg.addPoints(points);
    seg.flush();
    const where = new Map();
    for (const i of validIndices(points, dim)) {
      const key = Array.from(points.subarray(i * dim, (i + 1) * dim)).join(',');
      if (!where.has(key)) where.set(key, []);
      where.get(key).push(i);
    }
    const labels = new Int32Array(points.length / dim).fill(-1);
    const clusters = seg.takeClosedClusters().map((xyz, k) => {
      const indices = [];
      for (let j = 0; j < xyz.length; j += dim) {
        const i = where.get(Array.from(xyz.subarray(j, j + dim)).join(',')).shift();
        labels[i] = k;
        indices.push(i);
      }
      return { indices };
    });
    return { labels, clusters };
  } finally {
    seg.dispose();
  }
}

function validIndices(points, dim) {
  const idx = [];
  for (let i = 0; i < points.length / dim; i++) {
    let ok = true;
    for (let d = 0; d < dim; d++) ok &&= Number.isFinite(points[i * dim + d]);
    if (ok) idx.push(i);
  }
  return idx;
}

const round = (x) => (Number.isFinite(x) ? Number(x.toPrecision(12)) : null);
const plain = (a) => Array.from(a, round);
const usesSplit = (opts, dim) => ['ftls', 'aftls'].includes(opts.method) && dim === 2 && opts.primitive === 'line';

// Segments of one vectorized chain in the JSON shape; indices stay the API's half-open chain indices.
function segmentsOf(v, cluster, dim) {
  const offsets = v.polylineOffsets ?? [0, v.count];
  const polylineOf = (k) => { let p = 0; while (p + 2 < offsets.length && k >= offsets[p + 1]) p++; return p; };
  const out = [];
  if (v.primitive === 'plane') {
    v.polygons.forEach((poly, k) => out.push({
      cluster, indices: [v.indices[2 * k], v.indices[2 * k + 1]], polygon: plain(poly),
      params: plain(v.params.subarray(k * v.stride, (k + 1) * v.stride)), rms: round(v.rms[k]),
    }));
    return out;
  }
  const width = 2 * dim;
  for (let k = 0; k < v.count; k++) {
    out.push({
      cluster, polyline: polylineOf(k), indices: [v.indices[2 * k], v.indices[2 * k + 1]],
      coordinates: plain(v.segments.subarray(k * width, (k + 1) * width)),
      params: plain(v.params.subarray(k * v.stride, (k + 1) * v.stride)),
      rms: round(v.rms[k]),
    });
  }
  return out;
}

const crossing = (b) => ({ boundary: b.boundary, crossingDistance: round(b.crossingDistance), delta: round(b.delta) });

// segmentAndVectorize() for a scan the CLI segments with CAR and vectorizes into lines, when the package has it;
// undefined otherwise (the per-cluster calls then). Its vectorized clusters are `big` below, in the same order.
function batched(rtl, opts, points, dim) {
  if (opts.segmenter === 'ia' || !opts.method || opts.primitive !== 'line' || typeof rtl.segmentAndVectorize !== 'function') return undefined;
  return rtl.segmentAndVectorize(points, {
    dim, minPoints: opts.minPoints,
    segment: { step: opts.step, lowerBound: opts.lower, upperBound: opts.upper },
    vectorize: {
      method: opts.method, sigma: opts.sigma, delta: opts.delta, epsilon: opts.epsilon, simplexShift: opts.simplexShift,
      maxIterations: opts.maxIterations, ...(usesSplit(opts, dim) ? { split: !opts.strict } : {}),
    },
  });
}

function run(rtl, opts, input) {
  const { points, dim } = input;
  const returns = validIndices(points, dim);
  const result = { source: input.source, dim, points: points.length / dim, returns: returns.length };
  if (opts.maxVertices !== undefined) {
    if (dim !== 2) throw new InputError(`${inputName(input.source.file)}: --max-vertices needs 2D points (a scan's beams in the sensor frame)`);
    const r = need(rtl, 'extractPolylines', '--max-vertices')(points, { maxVertices: opts.maxVertices });
    result.budget = {
      maxVertices: opts.maxVertices, vertexCount: r.vertexCount, returned: r.returned, explained: round(r.explained),
      rmse: round(r.rmse), score: round(r.score),
      polylines: r.polylines.map((p) => plain(p)),
      segments: Array.from(r.segments.r, (_, k) => ({
        polyline: r.segments.polyline[k], beams: [r.segments.firstBeam[k], r.segments.lastBeam[k]],
        r: round(r.segments.r[k]), theta: round(r.segments.theta[k]),
        covariance: plain(r.segments.covariance.subarray(4 * k, 4 * k + 4)),
      })),
    };
    return result;
  }
  let groups, batch;
  if (opts.segment) {
    // CAR then lines on every cluster: one call for the whole scan (segmentAndVectorize), the same numbers as
    // segment() and a vectorize() per cluster, which cost a crossing into the module per cluster.
    batch = batched(rtl, opts, points, dim);
    const seg = batch ?? (opts.segmenter === 'ia'
      ? streamSegment(rtl, points, dim, opts)
      : need(rtl, 'segment', 'segmentation')(points, { dim, step: opts.step, lowerBound: opts.lower, upperBound: opts.upper }));
    result.segmentation = {
      segmenter: opts.segmenter, step: opts.step, lowerBound: opts.lower, upperBound: opts.upper,
      ...(opts.segmenter === 'ia' ? { scaling: opts.scaling } : {}),
      labels: Array.from(seg.labels),
      clusters: seg.clusters.map((c) => Array.from(c.indices)),
    };
    groups = result.segmentation.clusters.map((idx, cluster) => ({ cluster, idx }));
    result.labels = seg.labels;
  } else {
    result.chain = returns;
    groups = [{ cluster: null, idx: returns }];
  }
  const big = groups.filter((g) => g.idx.length >= opts.minPoints);
  if (opts.fit) {
    const fitLine = need(rtl, 'fitLine', '--fit');
    if (big.length === 0) throw new InputError(`${inputName(input.source.file)}: no ${opts.segment ? 'cluster' : 'chain'} of at least ${opts.minPoints} points to fit a line to`);
    result.fits = big.map((g) => {
      const f = fitLine(gather(points, dim, g.idx), { dim });
      return {
        cluster: g.cluster, count: f.count, first: g.idx[0], last: g.idx[g.idx.length - 1],
        ...(dim === 2 ? { normal: plain(f.normal), offset: round(f.offset) } : {}),
        direction: plain(f.direction), centroid: plain(f.centroid), rms: round(f.rms),
      };
    });
  }
  if (opts.method) {
    const vectorize = need(rtl, 'vectorize', '--vectorize');
    const split = usesSplit(opts, dim);
    const params = {
      dim, method: opts.method, sigma: opts.sigma, delta: opts.delta, epsilon: opts.epsilon,
      simplexShift: opts.simplexShift, maxIterations: opts.maxIterations, primitive: opts.primitive,
      ...(split ? { split: !opts.strict } : {}),
    };
    const out = [], failed = [], breaks = [];
    for (const [j, g] of big.entries()) {
      let v;
      try {
        v = batch ? rtl.vectorizedCluster(batch, j) : vectorize(gather(points, dim, g.idx), params);
      } catch (e) {
        if (/unknown option "split"/.test(e.message)) throw new MissingFeature(`--vectorize ${opts.method} needs vectorize()'s split option, which this build of rtl-wasm (${rtl.version}) does not have`);
        throw e;
      }
      // Strict FTLS/AFTLS (and the 3D vectorizers) can report failure (ok = false, no segments): say where and why.
      if (!v.ok) {
        failed.push({ cluster: g.cluster, ...(v.failure ? { ...crossing(v.failure), message: v.failure.message } : {}) });
        continue;
      }
      for (const b of v.breaks ?? []) breaks.push({ cluster: g.cluster, ...crossing(b) });
      out.push(...segmentsOf(v, g.cluster, dim));
    }
    result.vectorization = {
      method: opts.method, primitive: opts.primitive,
      ...(['dp', 'rw'].includes(opts.method) ? { epsilon: opts.epsilon } : { sigma: opts.sigma }),
      ...(['ftls', 'aftls'].includes(opts.method) ? { delta: opts.delta } : {}),
      ...(split ? { mode: opts.strict ? 'strict' : 'split' } : {}),
      [opts.primitive === 'plane' ? 'planes' : 'segments']: out,
      failed,
      breaks,
    };
    if (failed.length) {
      const what = failed.length === 1 && failed[0].cluster === null ? 'the chain' : `${failed.length} cluster(s)`;
      process.stderr.write(`rtl: warning: ${opts.method} found no segments for ${what} ("failed" in the JSON)\n`);
    }
  }
  return result;
}

const metres = (x) => `${round(x)} m`;

// What the figure shows, for its title: the scan, the segmentation, the method and their parameters, the extent.
function titleOf(opts, input, result) {
  const s = input.source;
  const parts = [];
  let what = basename(inputName(s.file));
  if (s.type === 'carmen') what += ` scan ${s.scan}${opts.maxRange !== undefined ? `, max range ${metres(opts.maxRange)}` : ''}`;
  if (s.type === 'bin') what += s.column !== undefined ? ` column ${s.column}` : ` ring ${s.ring}`;
  if (s.type === 'log') what += ` ${s.topic} scan ${s.index}${s.ring !== undefined ? ` ring ${s.ring}` : s.column !== undefined ? ` column ${s.column}` : ''}`;
  parts.push(what);
  if (result.budget) {
    parts.push(`${result.budget.vertexCount} of ${result.budget.maxVertices} vertices, RMSE ${metres(result.budget.rmse ?? NaN)}, explained ${result.budget.explained}`);
  } else if (result.segmentation) {
    const g = result.segmentation;
    parts.push(`${g.segmenter.toUpperCase()} step ${g.step}, bounds ${g.lowerBound}-${metres(g.upperBound)}${g.segmenter === 'ia' ? `, scaling ${g.scaling}` : ''}`);
  } else {
    parts.push('not segmented');
  }
  if (result.vectorization) {
    const v = result.vectorization;
    const p = v.epsilon !== undefined ? [`epsilon ${metres(v.epsilon)}`] : [`sigma ${metres(v.sigma)}`];
    if (v.delta !== undefined) p.push(`delta ${metres(v.delta)}`);
    if (v.mode) p.push(v.mode);
    parts.push(`${v.method.toUpperCase()} ${p.join(', ')}`);
  }
  if (result.fits) parts.push(`TLS line fit, min ${opts.minPoints} points`);
  const xs = [], ys = [];
  for (let i = 0; i < input.points.length; i += 2) {
    if (Number.isFinite(input.points[i]) && Number.isFinite(input.points[i + 1])) { xs.push(input.points[i]); ys.push(input.points[i + 1]); }
  }
  if (xs.length) {
    const span = (a) => Math.max(...a) - Math.min(...a);
    parts.push(`${span(xs).toFixed(1)} x ${span(ys).toFixed(1)} m`);
  }
  return parts.join('; ');
}

function render(rtl, opts, input, result) {
  if (opts.format === 'json') {
    const { labels, ...rest } = result;
    // Indented objects, but arrays of numbers on one line each (labels, clusters, coordinates).
    return JSON.stringify(rest, null, 1)
      .replace(/\[\s+([^[\]{}"]*?)\s+\]/g, (m, inner) => `[${inner.replace(/,\s+/g, ', ')}]`) + '\n';
  }
  if (opts.dim === 3) return render3D(rtl, opts, input, result);
  if (input.dim !== 2) throw new UsageError(`--format ${opts.format} draws 2D data only; use --format json or --format tikz --dim 3 for 3D points`);
  const segments = (result.vectorization?.segments ?? []).flatMap((s) => s.coordinates);
  // The budget's polylines, segment by segment.
  for (const p of result.budget?.polylines ?? []) for (let k = 0; k + 3 < p.length; k += 2) segments.push(p[k], p[k + 1], p[k + 2], p[k + 3]);
  // A fitted line is drawn as the segment between the projections of its first and last point.
  for (const f of result.fits ?? []) {
    const [dx, dy] = f.direction, [cx, cy] = f.centroid;
    const t = (k) => (input.points[2 * k] - cx) * dx + (input.points[2 * k + 1] - cy) * dy;
    const [t0, t1] = [t(f.first), t(f.last)];
    segments.push(cx + t0 * dx, cy + t0 * dy, cx + t1 * dx, cy + t1 * dy);
  }
  const drawing = {
    points: input.points,
    ...(result.labels ? { labels: result.labels } : {}),
    segments: new Float64Array(segments),
    title: titleOf(opts, input, result),
  };
  return opts.format === 'svg'
    ? need(rtl, 'toSvg', '--format svg')(drawing)
    : need(rtl, 'toTikz', '--format tikz')(drawing, { standalone: opts.standalone });
}

// The 3D picture: the same package call as the page's 3D export, toTikz({dim: 3, ...}, {camera}).
function render3D(rtl, opts, input, result) {
  if (input.dim !== 3) throw new InputError(`${inputName(input.source.file)}: --dim 3 draws 3D points, the input has 2D points`);
  const v = result.vectorization;
  const drawing = {
    dim: 3,
    points: input.points,
    ...(result.labels ? { labels: result.labels } : {}),
    segments: new Float64Array((v?.segments ?? []).flatMap((s) => s.coordinates)),
    ...(v?.planes ? { planes: v.planes.map((p) => p.polygon) } : {}),
  };
  return need(rtl, 'toTikz', '--format tikz')(drawing, { standalone: opts.standalone, ...(opts.camera ? { camera: opts.camera } : {}) });
}

// The package's checks of option values it cannot take (e.g. a step beyond what the segmenter holds) are bad usage
// of this command: name the command-line option, not the package's.
const FLAG_OF = {
  step: 'step', lowerBound: 'lower', upperBound: 'upper', scaling: 'scaling', sigma: 'sigma', delta: 'delta',
  epsilon: 'epsilon', simplexShift: 'simplex-shift', maxIterations: 'max-iterations', maxRange: 'max-range',
};
function asUsageError(e) {
  const m = /^[\w.]+: option (\w+) (must .*)$/.exec(e.message ?? '');
  return (e instanceof RangeError || e instanceof TypeError) && m && FLAG_OF[m[1]] ? new UsageError(`--${FLAG_OF[m[1]]} ${m[2]}`) : e;
}

export { InputError, MissingFeature, need, inputName, readInput, parseCsv, loadPoints, gather, streamSegment, validIndices, round, plain, usesSplit, segmentsOf, crossing, run, metres, titleOf, render, render3D, FLAG_OF, asUsageError };
