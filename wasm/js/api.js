// The thin JavaScript layer over the embind module: argument checks (TypeError for a wrong kind of value,
// RangeError for a bad value, both naming the function and argument), typed arrays in and out, and no C++ object
// ever handed to the caller except the two stateful classes, which free themselves (dispose / FinalizationRegistry).
// wasm/build.mjs emits this file twice: as ES module (api.mjs) and as CommonJS (api.cjs); keep the single
// `export { ... }` line at the end and no imports.

const VERSION = '__RTL_VERSION__';

// ------------------------------------------------------------------------------------------------ argument checks
function describe(v) {
  if (v === null) return 'null';
  if (Array.isArray(v)) return 'an Array';
  if (ArrayBuffer.isView(v)) return `a ${v.constructor.name}`;
  if (typeof v === 'object') return `an object (${Object.prototype.toString.call(v).slice(8, -1)})`;
  if (typeof v === 'string') return `a string ("${v.length > 20 ? v.slice(0, 20) + '...' : v}")`;
  if (typeof v === 'number') return `the number ${v}`;
  return `${typeof v === 'undefined' ? '' : 'a '}${typeof v}`;
}

function isNumericView(v) {
  return ArrayBuffer.isView(v) && !(v instanceof DataView) &&
    !(typeof BigInt64Array !== 'undefined' && (v instanceof BigInt64Array || v instanceof BigUint64Array));
}

// Points (or any number list) as a Float64Array: Float64Array as is, other numeric typed arrays and plain arrays
// (of numbers only) converted. Values are checked by the C++ side (NaN/Infinity rules depend on the function).
function toF64(v, fn, name) {
  if (v instanceof Float64Array) return v;
  if (isNumericView(v)) return new Float64Array(v);
  if (v !== null && typeof v === 'object' && !ArrayBuffer.isView(v) && typeof v.length === 'number' &&
      Number.isInteger(v.length) && v.length >= 0) {
    const out = new Float64Array(v.length);
    for (let i = 0; i < v.length; i++) {
      const x = v[i];
      if (typeof x !== 'number') throw new TypeError(`${fn}: ${name}[${i}] is ${describe(x)}, expected a number`);
      out[i] = x;
    }
    return out;
  }
  throw new TypeError(`${fn}: ${name} must be a Float64Array, a Float32Array or an array of numbers, got ${describe(v)}`);
}

function options(o, fn, known) {
  if (o === undefined || o === null) return {};
  if (typeof o !== 'object' || Array.isArray(o)) throw new TypeError(`${fn}: options must be an object, got ${describe(o)}`);
  for (const k of Object.keys(o)) {
    if (!known.includes(k)) throw new TypeError(`${fn}: unknown option "${k}" (known: ${known.join(', ')})`);
  }
  return o;
}

function num(o, key, fn, def, { min = -Infinity, max = Infinity, integer = false, exclusiveMin = false } = {}) {
  const v = o[key];
  if (v === undefined) return def;
  if (typeof v !== 'number') throw new TypeError(`${fn}: option ${key} must be a number, got ${describe(v)}`);
  if (!Number.isFinite(v)) throw new RangeError(`${fn}: option ${key} must be finite, got ${v}`);
  if (integer && !Number.isInteger(v)) throw new RangeError(`${fn}: option ${key} must be an integer, got ${v}`);
  if (exclusiveMin ? !(v > min) : v < min) throw new RangeError(`${fn}: option ${key} must be ${exclusiveMin ? '>' : '>='} ${min}, got ${v}`);
  if (v > max) throw new RangeError(`${fn}: option ${key} must be <= ${max}, got ${v}`);
  return v;
}

function dimOption(o, fn, allowed = [2, 3]) {
  const d = o.dim;
  if (d === undefined) return 2;
  if (typeof d !== 'number') throw new TypeError(`${fn}: option dim must be a number, got ${describe(d)}`);
  if (!allowed.includes(d)) throw new RangeError(`${fn}: option dim must be ${allowed.join(' or ')}, got ${d}`);
  return d;
}


function originOption(o, fn, dim) {
  if (o.origin === undefined) return [0, 0, 0];
  const a = toF64(o.origin, fn, 'option origin');
  if (a.length !== dim) throw new RangeError(`${fn}: option origin must have ${dim} numbers (dim ${dim}), got ${a.length}`);
  for (let i = 0; i < dim; i++) if (!Number.isFinite(a[i])) throw new RangeError(`${fn}: option origin[${i}] must be finite, got ${a[i]}`);
  return [a[0], a[1], dim === 3 ? a[2] : 0];
}

function boolOption(o, key, fn, def) {
  const v = o[key];
  if (v === undefined) return def;
  if (typeof v !== 'boolean') throw new TypeError(`${fn}: option ${key} must be a boolean, got ${describe(v)}`);
  return v;
}

// The C++ side's flat trace (wasm/src/trace_ops.h: names + numbers) as plain objects { kind, field: value, ... },
// one per event, in order. Field types: 0 number, 1 integer, 2 boolean.
function traceEvents(t) {
  const { names, data } = t;
  const out = [];
  for (let i = 0; i < data.length;) {
    const e = { kind: names[data[i]] };
    const fields = data[i + 1];
    i += 2;
    for (let k = 0; k < fields; k++, i += 3) e[names[data[i]]] = data[i + 1] === 2 ? data[i + 2] !== 0 : data[i + 2];
    out.push(e);
  }
  return out;
}

// Proximity bounds of the segmenters: 0 <= lowerBound <= upperBound (upperBound may be Infinity).
function boundsOptions(o, fn, lowerDefault, upperDefault) {
  const lower = num(o, 'lowerBound', fn, lowerDefault, { min: 0 });
  let upper = upperDefault;
  if (o.upperBound === Infinity) upper = Infinity;
  else upper = num(o, 'upperBound', fn, upperDefault, { min: 0 });
  if (!(upper >= lower)) throw new RangeError(`${fn}: option upperBound (${upper}) must be >= lowerBound (${lower})`);
  return [lower, upper];
}


const ERRORS = { TypeError, RangeError, Error };
const MAX_MEMORY = 2 ** 31;  // -sMAXIMUM_MEMORY of wasm/CMakeLists.txt
const DISPOSE = Symbol.dispose ?? Symbol.for('Symbol.dispose');

// The C++ side returns {error, kind} instead of throwing (an exception crossing into JS leaks the wasm stack).
// Every message starts with the name of the function the caller called (fn).
function check(r, fn) {
  if (r !== null && typeof r === 'object' && typeof r.error === 'string') {
    const msg = r.error.startsWith(`${fn}:`) ? r.error : `${fn}: ${r.error}`;
    throw new (ERRORS[r.kind] || Error)(msg);
  }
  return r;
}


// ------------------------------------------------------------------------------------------------ drawings
// Cluster k is drawn in PALETTE[k % 10]: the Okabe-Ito colour-blind safe set plus darker companions, the same as
// the demo page (web/app.js), so exported figures match the screen. No pure red: that is kept for fitted lines.
// The TikZ export defines them with \definecolor{ColorX}{HTML}{...}; unlabelled points are gray.
const PALETTE = ['#0072B2', '#E69F00', '#009E73', '#D55E00', '#CC79A7', '#56B4E9', '#8C6D1F', '#1B7837', '#762A83', '#332288'];
const clusterColour = (k) => PALETTE[k % PALETTE.length];
const UNLABELLED = '#808080';

function fmt(v) {
  // Fixed precision without trailing zeros (both TikZ and SVG): 1e-4 of a unit is below any drawing's resolution.
  const s = (Math.round(v * 1e4) / 1e4).toFixed(4).replace(/\.?0+$/, '');
  return s === '-0' ? '0' : s;
}

// Checks a drawing and returns {xy, labels, segs, title, n}; nothing is drawn for NaN points (gaps).
function checkDrawing(d, fn) {
  if (d === null || typeof d !== 'object' || Array.isArray(d) || ArrayBuffer.isView(d))
    throw new TypeError(`${fn}: drawing must be an object {points, labels, segments, title}, got ${describe(d)}`);
  for (const k of Object.keys(d)) {
    if (!['points', 'labels', 'segments', 'title', 'standalone'].includes(k))
      throw new TypeError(`${fn}: unknown drawing field "${k}" (known: points, labels, segments, title, standalone)`);
  }
  const xy = d.points === undefined ? new Float64Array(0) : toF64(d.points, fn, 'drawing.points');
  if (xy.length % 2) throw new RangeError(`${fn}: drawing.points has ${xy.length} numbers, not a multiple of 2 (x,y interleaved)`);
  for (let i = 0; i < xy.length; i++) {
    if (!Number.isFinite(xy[i]) && !Number.isNaN(xy[i]))
      throw new RangeError(`${fn}: drawing.points[${i}] is ${xy[i]} (only finite numbers, or NaN for a gap)`);
  }
  const n = xy.length / 2;
  let labels = null;
  if (d.labels !== undefined) {
    labels = toF64(d.labels, fn, 'drawing.labels');
    if (labels.length !== n) throw new RangeError(`${fn}: drawing.labels has ${labels.length} entries for ${n} points`);
    for (let i = 0; i < n; i++) {
      if (!Number.isInteger(labels[i]) || labels[i] < -1)
        throw new RangeError(`${fn}: drawing.labels[${i}] is ${labels[i]}, expected an integer >= -1`);
    }
  }
  const segs = d.segments === undefined ? new Float64Array(0) : toF64(d.segments, fn, 'drawing.segments');
  if (segs.length % 4) throw new RangeError(`${fn}: drawing.segments has ${segs.length} numbers, not a multiple of 4 (x1,y1,x2,y2 per segment)`);
  for (let i = 0; i < segs.length; i++) {
    if (!Number.isFinite(segs[i])) throw new RangeError(`${fn}: drawing.segments[${i}] is ${segs[i]}, expected a finite number`);
  }
  if (d.title !== undefined && typeof d.title !== 'string') throw new TypeError(`${fn}: drawing.title must be a string, got ${describe(d.title)}`);
  if (d.standalone !== undefined && typeof d.standalone !== 'boolean')
    throw new TypeError(`${fn}: drawing.standalone must be a boolean, got ${describe(d.standalone)}`);
  // Data bounds over finite points and segment ends.
  let minX = Infinity, minY = Infinity, maxX = -Infinity, maxY = -Infinity;
  const grow = (x, y) => {
    if (!Number.isFinite(x) || !Number.isFinite(y)) return;
    if (x < minX) minX = x; if (x > maxX) maxX = x; if (y < minY) minY = y; if (y > maxY) maxY = y;
  };
  for (let i = 0; i < n; i++) grow(xy[2 * i], xy[2 * i + 1]);
  for (let i = 0; i < segs.length; i += 2) grow(segs[i], segs[i + 1]);
  if (minX > maxX) { minX = maxX = minY = maxY = 0; }
  return { xy, labels, segs, n, title: d.title, bounds: { minX, minY, maxX, maxY } };
}

// One uniform scale (a scan must not be distorted) that fits the data range into w x h.
function fitScale(b, w, h) {
  const rx = b.maxX - b.minX, ry = b.maxY - b.minY;
  const s = Math.min(rx > 0 ? w / rx : Infinity, ry > 0 ? h / ry : Infinity);
  return Number.isFinite(s) ? s : 1;
}

function escapeXml(s) {
  return s.replace(/[<>&"']/g, (c) => ({ '<': '&lt;', '>': '&gt;', '&': '&amp;', '"': '&quot;', "'": '&apos;' })[c]);
}

// LaTeX escaping as rtl::LaTeX::escapeLaTeXCharacters (rtl-api 4.2).
function escapeLatex(s) {
  let out = '';
  for (const c of s) {
    if ('&%$#_{}'.includes(c)) out += '\\' + c;
    else if (c === '~') out += '\\textasciitilde ';
    else if (c === '^') out += '\\textasciicircum ';
    else if (c === '\\') out += '\\textbackslash ';
    else if (c === '<' || c === '>') out += (out.endsWith('$') ? ' ' : '') + '$' + c + '$';
    else out += c;
  }
  return out;
}

function toSvg(drawing, opts) {
  const fn = 'toSvg';
  const o = options(opts, fn, ['width', 'height', 'pointRadius']);
  const W = num(o, 'width', fn, 800, { min: 1, max: 100000 });
  const H = num(o, 'height', fn, 800, { min: 1, max: 100000 });
  const r = num(o, 'pointRadius', fn, 2, { min: 0, max: 1000 });
  const d = checkDrawing(drawing, fn);
  const margin = Math.max(r, 1) + 4;
  const top = d.title ? 24 : 0;
  const b = d.bounds;
  const s = fitScale(b, Math.max(W - 2 * margin, 1), Math.max(H - 2 * margin - top, 1));
  const ox = (W - (b.maxX - b.minX) * s) / 2, oy = top + (H - top + (b.maxY - b.minY) * s) / 2;
  const X = (x) => fmt(ox + (x - b.minX) * s), Y = (y) => fmt(oy - (y - b.minY) * s);  // SVG y points down
  const out = [`<svg xmlns="http://www.w3.org/2000/svg" width="${W}" height="${H}" viewBox="0 0 ${W} ${H}">`];
  if (d.title) out.push(`<title>${escapeXml(d.title)}</title>`,
    `<text x="${fmt(W / 2)}" y="18" text-anchor="middle" font-family="sans-serif" font-size="14">${escapeXml(d.title)}</text>`);
  // Points grouped by colour: one <g fill> per cluster.
  const groups = new Map();
  for (let i = 0; i < d.n; i++) {
    const x = d.xy[2 * i], y = d.xy[2 * i + 1];
    if (Number.isNaN(x) || Number.isNaN(y)) continue;
    const k = d.labels ? d.labels[i] : -1;
    if (!groups.has(k)) groups.set(k, []);
    groups.get(k).push(`<circle cx="${X(x)}" cy="${Y(y)}" r="${fmt(r)}"/>`);
  }
  for (const k of [...groups.keys()].sort((a, b2) => a - b2)) {
    const colour = k < 0 ? UNLABELLED : clusterColour(k);
    out.push(`<g class="${k < 0 ? 'points' : 'cluster'}"${k < 0 ? '' : ` data-cluster="${k}"`} fill="${colour}">`, ...groups.get(k), '</g>');
  }
  if (d.segs.length) {
    out.push('<g class="segments" stroke="#000000" stroke-width="1.5" stroke-linecap="round">');
    for (let i = 0; i < d.segs.length; i += 4) {
      out.push(`<line x1="${X(d.segs[i])}" y1="${Y(d.segs[i + 1])}" x2="${X(d.segs[i + 2])}" y2="${Y(d.segs[i + 3])}"/>`);
    }
    out.push('</g>');
  }
  out.push('</svg>');
  return out.join('\n') + '\n';
}

// Generated names as in rtl::LaTeXTikz2D: the 0-based index with its decimal digits as letters (0 -> A, 11 -> BB).
function latexName(prefix, i) { return prefix + String(i).replace(/[0-9]/g, (c) => 'ABCDEFGHIJ'[c]); }

// TikZ with the conventions of rtl::LaTeXTikz2D (rtl/io/LaTeXTikz2D.h): minimal document with xcolor[rgb], tikz and
// preview[active,tightpage]; the picture in data units scaled by xscale/yscale to the requested size; StyleX/.style
// keys in the picture options; \definecolor{ColorX}{HTML}{...}; \pgfmathsetmacro \MaxX \MinX \MaxY \MinY
// \MarkGlobalScaleX/Y \MarkRadius; points as \MarkX{x}{y}{rotation} dots of \MarkRadius cm whatever the scaling.
// One difference: a single (uniform) scale, so that a scan keeps its shape.
function toTikz(drawing, opts) {
  const fn = 'toTikz';
  const o = options(opts, fn, ['standalone', 'width', 'height', 'markRadius']);
  if (o.standalone !== undefined && typeof o.standalone !== 'boolean')
    throw new TypeError(`${fn}: option standalone must be a boolean, got ${describe(o.standalone)}`);
  const W = num(o, 'width', fn, 12, { min: 0, exclusiveMin: true, max: 500 });
  const H = num(o, 'height', fn, 12, { min: 0, exclusiveMin: true, max: 500 });
  const markRadius = num(o, 'markRadius', fn, 0.03, { min: 0, max: 10 });
  const d = checkDrawing(drawing, fn);
  const standalone = o.standalone ?? drawing.standalone ?? true;
  const b = d.bounds;
  const sc = fitScale(b, W, H);

  const styles = [], colours = [], marks = [], body = [];
  const colourIndex = new Map();
  const colour = (hex) => {
    const key = `{HTML}{${hex.slice(1).toUpperCase()}}`;
    if (!colourIndex.has(key)) { colourIndex.set(key, latexName('Color', colours.length)); colours.push(`\\definecolor{${colourIndex.get(key)}}${key}`); }
    return colourIndex.get(key);
  };
  const style = (text) => { const name = latexName('Style', styles.length); styles.push(`${name}/.${text}`); return name; };
  const mark = (styleName) => {
    const name = '\\' + latexName('Mark', marks.length);
    marks.push(`\\newcommand{${name}}[3]{\\begin{scope}[shift={(#1,#2)}, xscale=\\MarkGlobalScaleX, yscale=\\MarkGlobalScaleY, rotate=#3, scale=1] \\filldraw[${styleName}] (0,0) circle (\\MarkRadius); \\end{scope}}`);
    return name;
  };

  const byLabel = new Map();
  for (let i = 0; i < d.n; i++) {
    const x = d.xy[2 * i], y = d.xy[2 * i + 1];
    if (Number.isNaN(x) || Number.isNaN(y)) continue;
    const k = d.labels ? d.labels[i] : -1;
    if (!byLabel.has(k)) byLabel.set(k, []);
    byLabel.get(k).push(`{${fmt(x)}}{${fmt(y)}}{0}`);
  }
  for (const k of [...byLabel.keys()].sort((a, c) => a - c)) {
    const c = colour(k < 0 ? UNLABELLED : clusterColour(k));
    const m = mark(style(`style={draw=${c},fill=${c},line width=0.1pt}`));
    body.push(`% ${k < 0 ? 'points' : `cluster ${k}`}`, ...byLabel.get(k).map((a) => m + a));
  }
  if (d.segs.length) {
    const st = style('style={draw=black,line width=0.6pt,line cap=round}');
    body.push('% segments');
    for (let i = 0; i < d.segs.length; i += 4) {
      body.push(`\\draw[${st}] (${fmt(d.segs[i])},${fmt(d.segs[i + 1])}) -- (${fmt(d.segs[i + 2])},${fmt(d.segs[i + 3])});`);
    }
  }
  if (d.title) body.push(`\\node[anchor=south] at (${fmt((b.minX + b.maxX) / 2)},${fmt(b.maxY)}) {${escapeLatex(d.title)}};`);

  const pic = [
    `\\begin{tikzpicture}[xscale=${fmt(sc)}, yscale=${fmt(sc)}${styles.map((t) => `,\n\t${t}`).join('')}]`,
    ...colours,
    `\\pgfmathsetmacro{\\MaxX}{${fmt(b.maxX)}}`, `\\pgfmathsetmacro{\\MinX}{${fmt(b.minX)}}`,
    `\\pgfmathsetmacro{\\MaxY}{${fmt(b.maxY)}}`, `\\pgfmathsetmacro{\\MinY}{${fmt(b.minY)}}`,
    `\\pgfmathsetmacro{\\MarkGlobalScaleX}{${1 / sc}}`, `\\pgfmathsetmacro{\\MarkGlobalScaleY}{${1 / sc}}`,
    `\\pgfmathsetmacro{\\MarkRadius}{${fmt(markRadius)}}`,
    ...marks, ...body, '\\end{tikzpicture}',
  ].join('\n') + '\n';
  if (!standalone) return pic;
  return '\\documentclass{minimal}\n\\usepackage[rgb]{xcolor}\n\\usepackage{tikz}\n' +
    '\\usepackage[active,tightpage]{preview}\n\\PreviewEnvironment{tikzpicture}\n' +
    '\\setlength\\PreviewBorder{0.1cm}\n\n\\begin{document}\n' + pic + '\\end{document}\n';
}

// ------------------------------------------------------------------------------------------------ the module
function wrap(m) {
  let lastComputeMs = NaN;  // time spent in the C++ library by the last segment()/vectorize() call
  // Copies `arrays` (Float64Array or Uint8Array) into the wasm heap, calls f(ptr0, len0, ptr1, len1, ...) with lengths
  // in elements, frees them again. HEAP* views are read after every _malloc: memory growth replaces the buffer and
  // detaches older views.
  function withHeap(fn, arrays, f) {
    const ptrs = [];
    try {
      for (const a of arrays) {
        const p = m._malloc(Math.max(8, a.byteLength));
        if (!p) throw new RangeError(`${fn}: out of wasm memory allocating ${a.byteLength} bytes`);
        ptrs.push(p);
      }
      const args = [];
      arrays.forEach((a, i) => {
        if (a instanceof Float64Array) m.HEAPF64.set(a, ptrs[i] / 8);
        else m.HEAPU8.set(a, ptrs[i]);
        args.push(ptrs[i], a.length);
      });
      return check(f(...args), fn);
    } finally {
      for (const p of ptrs) m._free(p);
    }
  }

  // Writes `len` numbers into the module's kept input buffer (wasm/src/adapter.h; fill(HEAPF64, index) writes them
  // from index on, straight into wasm memory) and returns check(f(ptr, len)). Inputs beyond the buffer's limit get
  // a block of their own, freed after the call.
  function withInputOf(fn, len, fill, f) {
    let p = m.inputBuffer(len), own = 0;
    if (!p) {
      own = p = m._malloc(Math.max(8, 8 * len));
      if (!p) throw new RangeError(`${fn}: out of wasm memory allocating ${8 * len} bytes`);
    }
    try {
      fill(m.HEAPF64, p / 8);  // read after inputBuffer/_malloc: growth detaches older views
      return check(f(p, len), fn);
    } finally {
      if (own) m._free(own);
    }
  }
  const withInput = (fn, a, f) => withInputOf(fn, a.length, (heap, at) => heap.set(a, at), f);

  function fitLine(points, opts) {
    const fn = 'fitLine';
    const o = options(opts, fn, ['dim']);
    const dim = dimOption(o, fn);
    const xy = toF64(points, fn, 'points');
    return withHeap(fn, [xy], (p, n) => m.fitLine(p, n, dim));
  }

  function segment(points, opts) {
    const fn = 'segment';
    const o = options(opts, fn, ['dim', 'step', 'lowerBound', 'upperBound', 'origin', 'trace']);
    const dim = dimOption(o, fn);
    const trace = boolOption(o, 'trace', fn, false);
    // Default 2: CAR compares each point with up to step - 1 previous points, so 2 links consecutive points.
    const step = num(o, 'step', fn, 2, { min: 1, integer: true, max: 2 ** 31 });
    const [lower, upper] = boundsOptions(o, fn, 0.1, 0.5);
    const origin = originOption(o, fn, dim);
    const xyz = toF64(points, fn, 'points');
    const r = withInput(fn, xyz, (p, n) => m.segment(p, n, dim, step, lower, upper, origin[0], origin[1], origin[2], trace));
    lastComputeMs = r.computeMs;
    const clusters = [];
    for (let k = 0; k + 1 < r.offsets.length; k++) {
      const indices = r.indices.subarray(r.offsets[k], r.offsets[k + 1]);
      clusters.push({ indices, ranges: r.runs.subarray(r.runOffsets[k], r.runOffsets[k + 1]) });
    }
    return trace ? { labels: r.labels, clusters, trace: traceEvents(r.trace) } : { labels: r.labels, clusters };
  }

  const METHODS = ['ftls', 'aftls', 'itls', 'dp', 'rw'];
  function vectorize(points, opts) {
    const fn = 'vectorize';
    if (opts === undefined) throw new TypeError(`${fn}: options {method} are required (method: ${METHODS.join(', ')})`);
    const o = options(opts, fn, ['dim', 'method', 'primitive', 'sigma', 'delta', 'epsilon', 'maxSize', 'simplexShift',
      'maxIterations', 'split', 'trace', 'distance']);
    const dim = dimOption(o, fn);
    if (o.method === undefined) throw new TypeError(`${fn}: option method is required (${METHODS.join(', ')})`);
    if (typeof o.method !== 'string') throw new TypeError(`${fn}: option method must be a string, got ${describe(o.method)}`);
    const method = o.method;
    if (!METHODS.includes(method)) throw new RangeError(`${fn}: option method must be one of ${METHODS.join(', ')}, got '${method}'`);
    // Options a method does not use (e.g. epsilon for 'ftls') are still checked, then ignored, so that one
    // settings object can drive every method.
    const primitive = o.primitive ?? 'line';
    if (primitive !== 'line' && primitive !== 'plane') throw new RangeError(`${fn}: option primitive must be 'line' or 'plane', got ${describe(primitive)}`);
    if (primitive === 'plane' && (dim !== 3 || method !== 'aftls'))
      throw new RangeError(`${fn}: primitive 'plane' needs dim 3 and method 'aftls'`);
    const sigma = num(o, 'sigma', fn, 0.03, { min: 0, exclusiveMin: true });
    const delta = num(o, 'delta', fn, 0.3, { min: 0, exclusiveMin: true });
    const epsilon = num(o, 'epsilon', fn, 0.09, { min: 0, exclusiveMin: true });
    // maxSize is a reservation hint: 2 GB of wasm memory (the module's maximum) cannot hold more points than this.
    const maxSize = num(o, 'maxSize', fn, 0, { min: 0, integer: true, max: Math.floor(MAX_MEMORY / (8 * dim)) });
    const simplexShift = num(o, 'simplexShift', fn, 1, { min: 1, integer: true, max: 2 ** 32 - 1 });
    const maxIterations = num(o, 'maxIterations', fn, 10000, { min: 1, integer: true, max: 2 ** 32 - 1 });
    // split (FTLS/AFTLS 2D): break the polyline where a corner cannot be met within delta (default), or RTL's
    // strict behaviour (false: no result then, and `failure` says why).
    const split = boolOption(o, 'split', fn, true);
    const trace = boolOption(o, 'trace', fn, false);
    if (trace && dim === 3 && (method === 'ftls' || method === 'aftls'))
      throw new RangeError(`${fn}: option trace is not available for method '${method}' in 3D (only itls, dp and rw trace in 3D)`);
    // distance (dp): to the chord's line (RTL's, default) or to the chord segment (simplify-js's).
    const distance = o.distance ?? 'line';
    if (distance !== 'line' && distance !== 'segment') throw new RangeError(`${fn}: option distance must be 'line' or 'segment', got ${describe(distance)}`);
    const segmentDistance = method === 'dp' && distance === 'segment';
    if (trace && segmentDistance) throw new RangeError(`${fn}: option trace is not available with distance 'segment'`);
    const xyz = toF64(points, fn, 'points');
    const r = withInput(fn, xyz, (p, n) => m.vectorize(p, n, dim, METHODS.indexOf(method), primitive === 'plane',
      sigma, delta, epsilon, maxSize, simplexShift, maxIterations, split, trace, segmentDistance));
    lastComputeMs = r.computeMs;
    const corner = (b, k) => ({ boundary: b[k], crossingDistance: b[k + 1], delta: b[k + 2] });
    const breaks = [];
    for (let k = 0; k < r.breaks.length; k += 3) breaks.push(corner(r.breaks, k));
    let failure = null;
    if (r.failure) {
      const f = corner(r.failure, 0);
      const n = xyz.length / dim;
      f.message = f.boundary === 0
        ? `${fn}: no partition of the ${n} points into ranges within sigma ${sigma} exists`
        : `${fn}: no polyline within sigma ${sigma} meets delta ${f.delta} at chain index ${f.boundary}: the lines of the ` +
          `ranges before and after it ${Number.isFinite(f.crossingDistance)
            ? `cross ${Number(f.crossingDistance.toPrecision(4))} from the middle of points ${f.boundary - 1} and ${f.boundary}`
            : 'do not cross'}${split ? '' : ' (raise delta, or use split: true to break the polyline there)'}`;
      failure = f;
    }
    const polygons = [];
    for (let k = 0; k + 1 < r.polygonOffsets.length; k++) polygons.push(r.polygonPoints.slice(r.polygonOffsets[k], r.polygonOffsets[k + 1]));
    return {
      method, dim, primitive, ok: r.ok, count: r.count, segments: r.segments, polygons,
      indices: r.indices, params: r.params, stride: r.stride, rms: r.rms,
      polylineOffsets: r.polylineOffsets, breaks, failure,
      ...(trace ? { trace: traceEvents(r.trace) } : {}),
    };
  }

  // Stateful objects own a C++ object behind an integer handle: dispose() frees it, and if the caller forgets,
  // the FinalizationRegistry frees it after the wrapper is garbage collected (the held value does not reference
  // the wrapper, so it does not keep it alive).
  const registry = typeof FinalizationRegistry === 'function' ? new FinalizationRegistry((free) => free()) : null;

  function splitClusters(r, dim) {
    const out = [];
    for (let k = 0; k + 1 < r.offsets.length; k++) out.push(r.points.slice(dim * r.offsets[k], dim * r.offsets[k + 1]));
    return out;
  }

  class StreamSegmenter {
    #h = 0;
    #dim;
    #traced;
    constructor(opts) {
      const fn = 'StreamSegmenter';
      const o = options(opts, fn, ['dim', 'step', 'lowerBound', 'upperBound', 'scaling', 'trace']);
      this.#dim = dimOption(o, fn);
      this.#traced = boolOption(o, 'trace', fn, false);
      const step = num(o, 'step', fn, 3, { min: 1, integer: true, max: 1 << 24 });
      const [lower, upper] = boundsOptions(o, fn, 0.1, 0.5);
      const scaling = num(o, 'scaling', fn, 0.05, { min: 0 });
      const h = check(m.streamCreate(this.#dim, step, lower, upper, scaling, this.#traced), fn);
      this.#h = h;
      registry?.register(this, () => m.streamDestroy(h), this);
    }
    #handle(fn) {
      if (this.#h === 0) throw new TypeError(`StreamSegmenter.${fn}: the segmenter was disposed`);
      return this.#h;
    }
    get dim() { return this.#dim; }
    get disposed() { return this.#h === 0; }
    addPoints(points, origin) {
      const fn = 'StreamSegmenter.addPoints';
      const h = this.#handle('addPoints');
      const o = originOption(origin === undefined ? {} : { origin }, fn, this.#dim);
      const xyz = toF64(points, fn, 'points');
      withHeap(fn, [xyz], (p, n) => m.streamAdd(h, p, n, this.#dim, o[0], o[1], o[2]));
    }
    get closedClustersAvailable() { return m.streamClosed(this.#handle('closedClustersAvailable')); }
    get aliveClustersAvailable() { return m.streamAlive(this.#handle('aliveClustersAvailable')); }
    takeClosedClusters() { return splitClusters(check(m.streamTakeClosed(this.#handle('takeClosedClusters')), 'StreamSegmenter.takeClosedClusters'), this.#dim); }
    aliveClusters() { return splitClusters(check(m.streamAliveClusters(this.#handle('aliveClusters')), 'StreamSegmenter.aliveClusters'), this.#dim); }
    flush() { check(m.streamFlush(this.#handle('flush')), 'StreamSegmenter.flush'); }
    get traced() { return this.#traced; }
    // The steps recorded since the last call (the segmenter was made with { trace: true }), then forgotten.
    takeTrace() {
      const fn = 'StreamSegmenter.takeTrace';
      const h = this.#handle('takeTrace');
      if (!this.#traced) throw new TypeError(`${fn}: the segmenter was made without { trace: true }`);
      return traceEvents(check(m.streamTakeTrace(h), fn));
    }
    dispose() {
      if (this.#h === 0) return;
      registry?.unregister(this);
      m.streamDestroy(this.#h);
      this.#h = 0;
    }
    [DISPOSE]() { this.dispose(); }
  }

  function frameName(v, fn, what) {
    if (typeof v !== 'string') throw new TypeError(`${fn}: ${what} must be a string, got ${describe(v)}`);
    if (v.length === 0) throw new RangeError(`${fn}: ${what} must not be empty`);
    return v;
  }
  function vector(v, fn, what, n) {
    const a = toF64(v, fn, what);
    if (a.length !== n) throw new RangeError(`${fn}: ${what} must have ${n} numbers, got ${a.length}`);
    for (let i = 0; i < n; i++) if (!Number.isFinite(a[i])) throw new RangeError(`${fn}: ${what}[${i}] must be finite, got ${a[i]}`);
    return a;
  }

  // A transformation {angle, translation} (2D) or {quaternion | angle + axis, translation} (3D) -> [q0..q3, t0..t2]
  // with a unit quaternion [w, x, y, z] in 3D.
  function rigid(tf, fn, dim) {
    if (tf === null || typeof tf !== 'object' || Array.isArray(tf) || ArrayBuffer.isView(tf))
      throw new TypeError(`${fn}: the transformation must be an object, got ${describe(tf)}`);
    const known = dim === 2 ? ['angle', 'translation'] : ['quaternion', 'angle', 'axis', 'translation'];
    const o = options(tf, fn, known);
    const t = o.translation === undefined ? new Float64Array(dim) : vector(o.translation, fn, 'translation', dim);
    if (dim === 2) return [num(o, 'angle', fn, 0), 0, 0, 0, t[0], t[1], 0];
    let q;
    if (o.quaternion !== undefined) {
      if (o.angle !== undefined || o.axis !== undefined) throw new TypeError(`${fn}: give either quaternion or angle + axis, not both`);
      q = Array.from(vector(o.quaternion, fn, 'quaternion', 4));
    } else if (o.angle !== undefined || o.axis !== undefined) {
      const angle = num(o, 'angle', fn, 0);
      if (o.axis === undefined) throw new TypeError(`${fn}: angle needs an axis in 3D`);
      const axis = vector(o.axis, fn, 'axis', 3);
      const len = Math.hypot(axis[0], axis[1], axis[2]);
      if (!(len > 0)) throw new RangeError(`${fn}: axis must not be the zero vector`);
      const s = Math.sin(angle / 2) / len;
      q = [Math.cos(angle / 2), axis[0] * s, axis[1] * s, axis[2] * s];
    } else {
      q = [1, 0, 0, 0];
    }
    const qn = Math.hypot(...q);
    if (!(qn > 0)) throw new RangeError(`${fn}: quaternion must not be zero`);
    return [q[0] / qn, q[1] / qn, q[2] / qn, q[3] / qn, t[0], t[1], t[2]];
  }

  class TfTree {
    #h = 0;
    #dim;
    constructor(root, opts) {
      const fn = 'TfTree';
      frameName(root, fn, 'root');
      const o = options(opts, fn, ['dim']);
      this.#dim = dimOption(o, fn);
      const h = check(m.tfCreate(this.#dim, root), fn);
      this.#h = h;
      registry?.register(this, () => m.tfDestroy(h), this);
    }
    #handle(fn) {
      if (this.#h === 0) throw new TypeError(`TfTree.${fn}: the tree was disposed`);
      return this.#h;
    }
    get dim() { return this.#dim; }
    get disposed() { return this.#h === 0; }
    get size() { return m.tfSize(this.#handle('size')); }
    insert(name, parent, tf) {
      const fn = 'TfTree.insert';
      const h = this.#handle('insert');
      frameName(name, fn, 'name');
      frameName(parent, fn, 'parent');
      return check(m.tfInsert(h, name, parent, ...rigid(tf, fn, this.#dim)), fn);
    }
    erase(name) { return m.tfErase(this.#handle('erase'), frameName(name, 'TfTree.erase', 'name')); }
    contains(name) { return m.tfContains(this.#handle('contains'), frameName(name, 'TfTree.contains', 'name')); }
    tf(from, to) {
      const fn = 'TfTree.tf';
      const h = this.#handle('tf');
      return check(m.tfGet(h, frameName(from, fn, 'from'), frameName(to, fn, 'to')), fn);
    }
    transformPoints(from, to, points) {
      const fn = 'TfTree.transformPoints';
      const h = this.#handle('transformPoints');
      frameName(from, fn, 'from');
      frameName(to, fn, 'to');
      const xyz = toF64(points, fn, 'points');
      return withHeap(fn, [xyz], (p, n) => m.tfApply(h, from, to, p, n, this.#dim));
    }
    dispose() {
      if (this.#h === 0) return;
      registry?.unregister(this);
      m.tfDestroy(this.#h);
      this.#h = 0;
    }
    [DISPOSE]() { this.dispose(); }
  }

  // CARMEN logs: every FLASER line is a scan; beams without a return (range <= 0, non-finite or >= maxRange) are NaN
  // points; maxRange is the log's own no-return value unless given. Text as a string (UTF-8 encoded here) or bytes.
  function readCarmenLog(text, opts) {
    const fn = 'readCarmenLog';
    let u8;
    if (typeof text === 'string') u8 = new TextEncoder().encode(text);
    else if (text instanceof ArrayBuffer) u8 = new Uint8Array(text);
    else if (ArrayBuffer.isView(text)) u8 = new Uint8Array(text.buffer, text.byteOffset, text.byteLength);
    else throw new TypeError(`${fn}: text must be a string, an ArrayBuffer or a typed array of the file, got ${describe(text)}`);
    const o = options(opts, fn, ['maxRange']);
    // Default: detected from the log (NaN to the C++ reader); Infinity keeps every finite positive range.
    const maxRange = o.maxRange === Infinity ? Infinity : num(o, 'maxRange', fn, NaN, { min: 0, exclusiveMin: true });
    const r = withHeap(fn, [u8], (p, n) => m.readCarmenLog(p, n, maxRange));
    const scans = [];
    for (let k = 0; k + 1 < r.offsets.length; k++) {
      const b = r.offsets[k], e = r.offsets[k + 1];
      scans.push({
        points: r.points.slice(2 * b, 2 * e), ranges: r.ranges.slice(b, e),
        x: r.x[k], y: r.y[k], theta: r.theta[k], timestamp: r.timestamp[k], line: r.line[k],
        maxRange: r.maxRange, maxRangeSource: r.maxRangeSource,
      });
    }
    return scans;
  }

  // Organised LiDAR: 16-byte little-endian float32 records x, y, z, intensity; (0,0,0) = no return (NaN point).
  // The cloud is stored column-major whatever the file layout: beam b of column c is point c * beams + b.
  function readOrganizedLidar(data, opts) {
    const fn = 'readOrganizedLidar';
    let u8;
    if (data instanceof ArrayBuffer) u8 = new Uint8Array(data);
    else if (ArrayBuffer.isView(data)) u8 = new Uint8Array(data.buffer, data.byteOffset, data.byteLength);
    else throw new TypeError(`${fn}: data must be an ArrayBuffer or a typed array / DataView / Buffer, got ${describe(data)}`);
    if (opts === undefined) throw new TypeError(`${fn}: options {beams} are required`);
    const o = options(opts, fn, ['beams', 'layout']);
    if (o.beams === undefined) throw new TypeError(`${fn}: option beams is required`);
    const beams = num(o, 'beams', fn, 0, { min: 1, integer: true, max: 1 << 20 });
    const layout = o.layout ?? 'column-major';
    if (typeof layout !== 'string') throw new TypeError(`${fn}: option layout must be a string, got ${describe(layout)}`);
    if (layout !== 'column-major' && layout !== 'row-major')
      throw new RangeError(`${fn}: option layout must be 'column-major' or 'row-major', got '${layout}'`);
    const r = withHeap(fn, [u8], (p, n) => m.readOrganizedLidar(p, n, beams, layout === 'row-major' ? 1 : 0));
    const { columns, points } = r;
    return {
      beams, columns, points, intensity: r.intensity,
      ring(b) {
        if (typeof b !== 'number') throw new TypeError(`ring: beam must be a number, got ${describe(b)}`);
        if (!Number.isInteger(b) || b < 0 || b >= beams) throw new RangeError(`ring: beam must be an integer in [0, ${beams - 1}], got ${b}`);
        const out = new Float64Array(3 * columns);
        for (let c = 0; c < columns; c++) out.set(points.subarray(3 * (c * beams + b), 3 * (c * beams + b) + 3), 3 * c);
        return out;
      },
      column(c) {
        if (typeof c !== 'number') throw new TypeError(`column: c must be a number, got ${describe(c)}`);
        if (!Number.isInteger(c) || c < 0 || c >= columns) throw new RangeError(`column: c must be an integer in [0, ${columns - 1}], got ${c}`);
        return points.slice(3 * c * beams, 3 * (c + 1) * beams);
      },
    };
  }

  const api = {
    version: VERSION,
    fitLine,
    segment,
    vectorize,
    StreamSegmenter,
    TfTree,
    toSvg,
    toTikz,
    ...algorithmsApi(m, withHeap, registry),
    readCarmenLog,
    readCarmen: readCarmenLog,
    readOrganizedLidar,
    simplify: makeSimplify(m, withInputOf, (ms) => { lastComputeMs = ms; }),
    // Frees the input buffer, vectorizers and segmenters kept between calls (they grow back on the next call).
    releaseBuffers: () => m.releaseBuffers(),
    // Malloc heap in use once the kept buffers are released: equal figures before and after calls mean no leak.
    heapInUse: () => { m.releaseBuffers(); return m.heapInUse(); },
    memoryBytes: () => m.memoryBytes(),
    stackPointer: () => m.stackPointer(),
  };
  Object.defineProperty(api, 'lastComputeMs', { get: () => lastComputeMs, enumerable: false });
  return api;
}

// Checks init()'s options and returns the ones handed to the Emscripten factory.
function initOptions(o) {
  if (o === undefined || o === null) return {};
  if (typeof o !== 'object' || Array.isArray(o)) throw new TypeError(`init: options must be an object, got ${describe(o)}`);
  const out = {};
  for (const k of Object.keys(o)) {
    if (k === 'wasmBinary') {
      const b = o.wasmBinary;
      if (!(b instanceof ArrayBuffer || b instanceof Uint8Array))
        throw new TypeError(`init: wasmBinary must be an ArrayBuffer or a Uint8Array, got ${describe(b)}`);
      out.wasmBinary = b;
    } else if (k === 'locateFile') {
      if (typeof o.locateFile !== 'function') throw new TypeError(`init: locateFile must be a function, got ${describe(o.locateFile)}`);
      out.locateFile = o.locateFile;
    } else {
      throw new TypeError(`init: unknown option "${k}" (known: wasmBinary, locateFile)`);
    }
  }
  return out;
}

// Starts the Emscripten module and wraps it, the same way for the three entries (Node ESM, CommonJS, browsers).
// The module gets its own print/printErr/onAbort, so that a failed start prints nothing (Emscripten would print
// "Aborted(...)" to stderr) and becomes the package's TypeError; after a successful start they forward to the console.
async function start(createModule, options, loadDefaultBinary) {
  const o = initOptions(options);
  if (o.wasmBinary !== undefined) {
    const bytes = o.wasmBinary instanceof ArrayBuffer ? new Uint8Array(o.wasmBinary) : o.wasmBinary;
    if (!WebAssembly.validate(bytes)) throw new TypeError(`init: wasmBinary is not a valid WebAssembly module (${bytes.length} bytes)`);
  } else if (loadDefaultBinary) {
    o.wasmBinary = await loadDefaultBinary();
  }
  let started = false, reason = null;
  const say = (log) => (...a) => { if (started) log(...a); else reason ??= a.join(' '); };
  o.print = say((...a) => console.log(...a));
  o.printErr = say((...a) => console.error(...a));
  o.onAbort = (what) => { if (!started) reason ??= String(what); };
  let module;
  try {
    module = await createModule(o);
    if (typeof module.fitLine !== 'function') throw new Error('the module has no rtl-wasm bindings');
  } catch (e) {
    throw new TypeError(`init: the WebAssembly module could not be started: ${reason ?? (e && e.message) ?? e}`);
  }
  started = true;
  return wrap(module);
}

export { start };
