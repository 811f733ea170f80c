#!/usr/bin/env node
// rtl: the rtl-wasm package's command-line tool. Reads a scan (CARMEN log, organised LiDAR binary or CSV), fits
// total-least-squares lines, segments and/or vectorizes it with the package's WebAssembly build, and writes JSON, SVG
// or TikZ. Exit codes: 0 ok, 1 bad input data, 2 bad usage, 3 a function this build of the package does not have.
import { readFileSync, writeFileSync } from 'node:fs';
import { extname } from 'node:path';
import { parseArgs } from 'node:util';
import init from 'rtl-wasm';

const HELP = `Usage: rtl [options] <file>      (use - to read standard input)

Reads ordered 2D/3D points, cuts them into clusters with the batch segmenter and/or
turns them into line segments (or planes), fits total-least-squares lines, and
writes JSON, SVG or TikZ (rtl-wasm package).

Input
  -t, --type TYPE        carmen | bin | csv; default from the extension
                         (.log .carmen -> carmen, .bin -> bin, .csv .txt .xyz -> csv)
      --scan N           scan of a CARMEN log, 0-based (default 0)
      --beams N          beams (rings) of an organised binary scan (required for bin)
      --layout L         column | row: point order of the binary scan (default column)
      --ring K           take ring K of the binary scan (default 0)
      --column C         take column C of the binary scan instead of a ring
  CSV: one point per line, x,y or x,y,z (comma, semicolon or blanks); '#' comments;
       an optional header line; empty, NaN or non-finite coordinates mark gaps.

Line fit
      --fit              total-least-squares line through the points (with --segment:
                         through each cluster of at least --min-points points)

Segmentation
  -s, --segment          run the batch segmenter (the default when neither --vectorize
                         nor --fit is given)
      --segmenter S      car (batch, the scan as a closed loop; default) | ia (streaming)
      --step N           neighbours compared, >= 1 (default 3)
      --lower M          lower bound of the distance threshold in metres (default 0.1)
      --upper M          upper bound in metres (default 0.5)
      --scaling K        ia: threshold = K * range, clamped to the bounds (default 0.05)

Vectorization
  -m, --vectorize METHOD ftls | aftls | itls | dp | rw (with --segment: each cluster)
      --sigma M          max RMS distance of points from a line (TLS methods, default 0.03)
      --delta M          corner tolerance of FTLS/AFTLS (default 0.3)
      --epsilon M        tolerance of Douglas-Peucker / Reumann-Witkam (default 0.09)
      --simplex-shift N  AFTLS optimizer start simplex shift (default 1)
      --max-iterations N AFTLS optimizer iteration cap (default 10000)
      --primitive P      line | plane, for 3D points (default line; plane needs aftls)
      --min-points N     clusters with fewer points are not vectorized (default 3)
                         Clusters the vectorizer reports failure on (ok = false) are listed
                         in the JSON as "failed" (cluster numbers; null = all points).

Output
  -f, --format FMT       json | svg | tikz (default json)
      --standalone       TikZ: a complete LaTeX document instead of a tikzpicture
  -o, --output FILE      write to FILE instead of standard output
  -h, --help             show this help
      --version          show the package version

Exit status: 0 on success, 1 when the input cannot be read or parsed, 2 on bad options,
3 when this build of rtl-wasm lacks a function the options need.

Examples
  rtl tests/data/intel.log --scan 3 -m ftls --sigma 0.02 -f svg -o scan3.svg
  rtl tests/data/rellis3d-os1-4x2048.bin --beams 4 --ring 1 -s --upper 0.8
  rtl points.csv -m dp --epsilon 0.05
  rtl points.csv --fit
`;

class UsageError extends Error {}
class InputError extends Error {}
class MissingFeature extends Error {}

// The package grows function by function; say clearly when this build lacks one instead of failing obscurely.
function need(rtl, name, what) {
  if (typeof rtl[name] !== 'function') {
    throw new MissingFeature(`${what} needs ${name}(), which this build of rtl-wasm (${rtl.version ?? 'unknown version'}) does not have`);
  }
  return rtl[name].bind(rtl);
}

const METHODS = ['ftls', 'aftls', 'itls', 'dp', 'rw'];
const FORMATS = ['json', 'svg', 'tikz'];
const TYPES = ['carmen', 'bin', 'csv'];

function parseCommandLine(argv) {
  let parsed;
  try {
    parsed = parseArgs({
      args: argv,
      allowPositionals: true,
      strict: true,
      options: {
        type: { type: 'string', short: 't' },
        scan: { type: 'string' },
        beams: { type: 'string' },
        layout: { type: 'string' },
        ring: { type: 'string' },
        column: { type: 'string' },
        fit: { type: 'boolean' },
        segment: { type: 'boolean', short: 's' },
        segmenter: { type: 'string' },
        scaling: { type: 'string' },
        step: { type: 'string' },
        lower: { type: 'string' },
        upper: { type: 'string' },
        vectorize: { type: 'string', short: 'm' },
        sigma: { type: 'string' },
        delta: { type: 'string' },
        epsilon: { type: 'string' },
        'simplex-shift': { type: 'string' },
        'max-iterations': { type: 'string' },
        primitive: { type: 'string' },
        'min-points': { type: 'string' },
        format: { type: 'string', short: 'f' },
        standalone: { type: 'boolean' },
        output: { type: 'string', short: 'o' },
        help: { type: 'boolean', short: 'h' },
        version: { type: 'boolean' },
      },
    });
  } catch (e) {
    throw new UsageError(e.message.replace(/\. To specify a positional argument.*$/s, '.'));
  }
  const v = parsed.values;
  if (v.help || v.version) return { help: v.help, version: v.version };
  if (parsed.positionals.length !== 1) {
    throw new UsageError(parsed.positionals.length === 0 ? 'missing input file' : `expected one input file, got ${parsed.positionals.length}: ${parsed.positionals.join(' ')}`);
  }

  const num = (name, def, { min = -Infinity, integer = false, positive = false } = {}) => {
    if (v[name] === undefined) return def;
    const text = v[name].trim();
    const x = Number(text);
    if (text === '' || !Number.isFinite(x)) throw new UsageError(`--${name} must be a number, got "${v[name]}"`);
    if (integer && !Number.isInteger(x)) throw new UsageError(`--${name} must be an integer, got "${v[name]}"`);
    if (positive && !(x > 0)) throw new UsageError(`--${name} must be > 0, got "${v[name]}"`);
    if (x < min) throw new UsageError(`--${name} must be >= ${min}, got "${v[name]}"`);
    return x;
  };
  const oneOf = (name, list, def) => {
    if (v[name] === undefined) return def;
    const x = v[name].toLowerCase();
    if (!list.includes(x)) throw new UsageError(`--${name} must be one of ${list.join(', ')}, got "${v[name]}"`);
    return x;
  };

  const file = parsed.positionals[0];
  let type = oneOf('type', TYPES, undefined);
  if (!type) {
    const ext = extname(file).toLowerCase();
    if (ext === '.log' || ext === '.carmen' || ext === '.clf') type = 'carmen';
    else if (ext === '.bin') type = 'bin';
    else if (ext === '.csv' || ext === '.txt' || ext === '.xyz') type = 'csv';
    else throw new UsageError(`cannot tell the input type of "${file}" from its extension; pass --type carmen|bin|csv`);
  }
  const opts = {
    file,
    type,
    scan: num('scan', 0, { min: 0, integer: true }),
    beams: num('beams', undefined, { integer: true, positive: true }),
    layout: oneOf('layout', ['column', 'row'], 'column'),
    ring: num('ring', undefined, { min: 0, integer: true }),
    column: num('column', undefined, { min: 0, integer: true }),
    fit: Boolean(v.fit),
    segment: Boolean(v.segment),
    segmenter: oneOf('segmenter', ['car', 'ia'], 'car'),
    scaling: num('scaling', 0.05, { min: 0 }),
    step: num('step', 3, { min: 1, integer: true }),
    lower: num('lower', 0.1, { min: 0 }),
    upper: num('upper', 0.5, { min: 0 }),
    method: oneOf('vectorize', METHODS, undefined),
    sigma: num('sigma', 0.03, { positive: true }),
    delta: num('delta', 0.3, { positive: true }),
    epsilon: num('epsilon', 0.09, { positive: true }),
    simplexShift: num('simplex-shift', 1, { min: 1, integer: true }),
    maxIterations: num('max-iterations', 10000, { min: 1, integer: true }),
    primitive: oneOf('primitive', ['line', 'plane'], 'line'),
    minPoints: num('min-points', 3, { min: 2, integer: true }),
    format: oneOf('format', FORMATS, 'json'),
    standalone: Boolean(v.standalone),
    output: v.output,
  };
  if (opts.lower > opts.upper) throw new UsageError(`--lower (${opts.lower}) must not exceed --upper (${opts.upper})`);
  if (!opts.method && !opts.fit) opts.segment = true;
  if (opts.type !== 'bin') {
    for (const k of ['beams', 'ring', 'column']) if (opts[k] !== undefined) throw new UsageError(`--${k} applies to binary scans only`);
    if (v.layout !== undefined) throw new UsageError('--layout applies to binary scans only');
  } else {
    if (opts.beams === undefined) throw new UsageError('a binary scan needs --beams N (the number of rings)');
    if (opts.ring !== undefined && opts.column !== undefined) throw new UsageError('pass either --ring or --column, not both');
  }
  if (opts.type !== 'carmen' && v.scan !== undefined) throw new UsageError('--scan applies to CARMEN logs only');
  if (v.scaling !== undefined && opts.segmenter !== 'ia') throw new UsageError('--scaling applies to --segmenter ia only');
  if (opts.primitive === 'plane' && opts.method !== 'aftls') throw new UsageError('--primitive plane needs --vectorize aftls');
  if (opts.standalone && opts.format !== 'tikz') throw new UsageError('--standalone applies to --format tikz only');
  return opts;
}

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
  const name = opts.file === '-' ? 'stdin' : opts.file;
  if (opts.type === 'csv') {
    const { points, dim } = parseCsv(readInput(opts.file, false), name);
    return { points, dim, source: { type: 'csv', file: opts.file } };
  }
  if (opts.type === 'carmen') {
    const text = readInput(opts.file, false);
    let scans;
    try {
      scans = need(rtl, 'readCarmenLog', 'a CARMEN log')(text);
    } catch (e) {
      if (e instanceof MissingFeature) throw e;
      throw new InputError(`${name}: ${e.message}`);
    }
    if (scans.length === 0) throw new InputError(`${name}: no laser scans (FLASER lines) found`);
    if (opts.scan >= scans.length) throw new InputError(`${name}: --scan ${opts.scan} is out of range, the log has ${scans.length} scans (0..${scans.length - 1})`);
    const s = scans[opts.scan];
    return {
      points: Float64Array.from(s.points), dim: 2,
      source: { type: 'carmen', file: opts.file, scan: opts.scan, scans: scans.length, line: s.line, pose: { x: s.x, y: s.y, theta: s.theta } },
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

function run(rtl, opts, input) {
  const { points, dim } = input;
  const result = { source: input.source, dim, points: points.length / dim, returns: validIndices(points, dim).length };
  let groups = [{ cluster: null, idx: validIndices(points, dim) }];
  if (opts.segment) {
    const seg = opts.segmenter === 'ia'
      ? streamSegment(rtl, points, dim, opts)
      : need(rtl, 'segment', '--segment')(points, { dim, step: opts.step, lowerBound: opts.lower, upperBound: opts.upper });
    result.segmentation = {
      segmenter: opts.segmenter, step: opts.step, lowerBound: opts.lower, upperBound: opts.upper,
      ...(opts.segmenter === 'ia' ? { scaling: opts.scaling } : {}),
      labels: Array.from(seg.labels),
      clusters: seg.clusters.map((c) => Array.from(c.indices)),
    };
    groups = result.segmentation.clusters.map((idx, cluster) => ({ cluster, idx }));
    result.labels = seg.labels;
  }
  const big = groups.filter((g) => g.idx.length >= opts.minPoints);
  if (opts.fit) {
    const fitLine = need(rtl, 'fitLine', '--fit');
    const name = input.source.file === '-' ? 'stdin' : input.source.file;
    if (big.length === 0) throw new InputError(`${name}: no ${opts.segment ? 'cluster' : 'set'} of at least ${opts.minPoints} points to fit a line to`);
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
    const params = {
      dim, method: opts.method, sigma: opts.sigma, delta: opts.delta, epsilon: opts.epsilon,
      simplexShift: opts.simplexShift, maxIterations: opts.maxIterations, primitive: opts.primitive,
    };
    const out = [];
    const failed = [];
    for (const g of big) {
      const v = vectorize(gather(points, dim, g.idx), params);
      // The C++ vectorizer can report failure (ok = false, no segments); say so instead of dropping it silently.
      if (!v.ok) { failed.push(g.cluster); continue; }
      if (v.primitive === 'plane') {
        v.polygons.forEach((poly, k) => out.push({
          cluster: g.cluster, polygon: plain(poly),
          indices: [g.idx[v.indices[2 * k]], g.idx[Math.max(v.indices[2 * k], v.indices[2 * k + 1] - 1)]],
          params: plain(v.params.subarray(k * v.stride, (k + 1) * v.stride)), rms: round(v.rms[k]),
        }));
        continue;
      }
      const width = 2 * dim;
      for (let k = 0; k < v.count; k++) {
        const from = v.indices[2 * k], to = v.indices[2 * k + 1];
        out.push({
          cluster: g.cluster,
          coordinates: plain(v.segments.subarray(k * width, (k + 1) * width)),
          indices: [g.idx[from], g.idx[Math.max(from, to - 1)]],
          params: plain(v.params.subarray(k * v.stride, (k + 1) * v.stride)),
          rms: round(v.rms[k]),
        });
      }
    }
    result.vectorization = {
      method: opts.method, primitive: opts.primitive,
      ...(['dp', 'rw'].includes(opts.method) ? { epsilon: opts.epsilon } : { sigma: opts.sigma }),
      ...(['ftls', 'aftls'].includes(opts.method) ? { delta: opts.delta } : {}),
      [opts.primitive === 'plane' ? 'planes' : 'segments']: out,
      failed,
    };
    if (failed.length) {
      const what = failed.length === 1 && failed[0] === null ? 'the points' : `${failed.length} cluster(s)`;
      process.stderr.write(`rtl: warning: ${opts.method} reported failure on ${what}; no segments for them ("failed" in the JSON)\n`);
    }
  }
  return result;
}

function render(rtl, opts, input, result) {
  if (opts.format === 'json') {
    const { labels, ...rest } = result;
    // Indented objects, but arrays of numbers on one line each (labels, clusters, coordinates).
    return JSON.stringify(rest, null, 1)
      .replace(/\[\s+([^[\]{}"]*?)\s+\]/g, (m, inner) => `[${inner.replace(/,\s+/g, ', ')}]`) + '\n';
  }
  if (input.dim !== 2) throw new UsageError(`--format ${opts.format} draws 2D data only; use --format json for 3D points`);
  const segments = (result.vectorization?.segments ?? []).flatMap((s) => s.coordinates);
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
    title: input.source.file === '-' ? 'stdin' : input.source.file,
  };
  return opts.format === 'svg'
    ? need(rtl, 'toSvg', '--format svg')(drawing)
    : need(rtl, 'toTikz', '--format tikz')(drawing, { standalone: opts.standalone });
}

async function main(argv) {
  let opts;
  try {
    opts = parseCommandLine(argv);
  } catch (e) {
    if (e instanceof UsageError) {
      process.stderr.write(`rtl: ${e.message}\nTry 'rtl --help' for more information.\n`);
      return 2;
    }
    throw e;
  }
  if (opts.help) { process.stdout.write(HELP); return 0; }
  if (opts.version) {
    const pkg = JSON.parse(readFileSync(new URL('../package.json', import.meta.url), 'utf8'));
    process.stdout.write(`${pkg.version}\n`);
    return 0;
  }
  try {
    const rtl = await init();
    const input = await loadPoints(rtl, opts);
    const result = run(rtl, opts, input);
    const text = render(rtl, opts, input, result);
    if (opts.output) {
      try {
        writeFileSync(opts.output, text);
      } catch (e) {
        throw new InputError(`cannot write "${opts.output}": ${e.message}`);
      }
    } else {
      process.stdout.write(text);
    }
    return 0;
  } catch (e) {
    process.stderr.write(`rtl: ${e.message}\n`);
    if (e instanceof UsageError) return 2;
    if (e instanceof MissingFeature) return 3;
    // Data errors: our own, or a TypeError/RangeError from the package naming what was wrong.
    return 1;
  }
}

process.exitCode = await main(process.argv.slice(2));
