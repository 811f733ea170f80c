// toTikz, toSvg, toLatexTable: argument checks and typed arrays only. The pictures are drawn by the C++ core
// (the package's scan drawing: palette, point marks, segments, title; wasm/src/draw*.cpp) and written by the
// library's TikZ/SVG/table writers, so the package's output is the C++ library's byte for byte.
import { boolOption, check, describe, num, options, toF64 } from './checks.js';

const DRAWING_2D = ['dim', 'points', 'labels', 'segments', 'title', 'standalone'];
const DRAWING_3D = ['dim', 'points', 'labels', 'segments', 'planes', 'polygons', 'standalone'];

/** toTikz, toSvg and toLatexTable of one package instance: ctx.extras(fn) gives the extras module's {m, withHeap}
 *  (modules.js), or throws when it is not loaded. */
export function drawingApi({ extras }) {
  // Points (NaN = gap, never drawn), labels (integers >= -1) and segments of a 2D or 3D drawing.
  function checkDrawing(d, fn) {
    if (d === null || typeof d !== 'object' || Array.isArray(d) || ArrayBuffer.isView(d))
      throw new TypeError(`${fn}: drawing must be an object {points, labels, segments, title}, got ${describe(d)}`);
    let dim = 2;
    if (d.dim !== undefined) {
      if (typeof d.dim !== 'number') throw new TypeError(`${fn}: drawing.dim must be a number, got ${describe(d.dim)}`);
      if (d.dim !== 2 && d.dim !== 3) throw new RangeError(`${fn}: drawing.dim must be 2 or 3, got ${d.dim}`);
      dim = d.dim;
    }
    const known = dim === 2 ? DRAWING_2D : DRAWING_3D;
    for (const k of Object.keys(d)) {
      if (!known.includes(k)) throw new TypeError(`${fn}: unknown drawing field "${k}" (known for dim ${dim}: ${known.join(', ')})`);
    }
    const xy = d.points === undefined ? new Float64Array(0) : toF64(d.points, fn, 'drawing.points');
    if (xy.length % dim) throw new RangeError(`${fn}: drawing.points has ${xy.length} numbers, not a multiple of ${dim} (${dim === 2 ? 'x,y' : 'x,y,z'} interleaved)`);
    for (let i = 0; i < xy.length; i++) {
      if (!Number.isFinite(xy[i]) && !Number.isNaN(xy[i]))
        throw new RangeError(`${fn}: drawing.points[${i}] is ${xy[i]} (only finite numbers, or NaN for a gap)`);
    }
    const n = xy.length / dim;
    let labels = /** @type {Float64Array} */ (new Float64Array(0));
    if (d.labels !== undefined) {
      labels = toF64(d.labels, fn, 'drawing.labels');
      if (labels.length !== n) throw new RangeError(`${fn}: drawing.labels has ${labels.length} entries for ${n} points`);
      for (let i = 0; i < n; i++) {
        if (!Number.isInteger(labels[i]) || labels[i] < -1 || labels[i] > 2 ** 31 - 1)
          throw new RangeError(`${fn}: drawing.labels[${i}] is ${labels[i]}, expected an integer >= -1`);
      }
    }
    const per = 2 * dim;
    const segs = d.segments === undefined ? new Float64Array(0) : toF64(d.segments, fn, 'drawing.segments');
    if (segs.length % per) throw new RangeError(`${fn}: drawing.segments has ${segs.length} numbers, not a multiple of ${per} (${dim === 2 ? 'x1,y1,x2,y2' : 'x1,y1,z1,x2,y2,z2'} per segment)`);
    for (let i = 0; i < segs.length; i++) {
      if (!Number.isFinite(segs[i])) throw new RangeError(`${fn}: drawing.segments[${i}] is ${segs[i]}, expected a finite number`);
    }
    if (d.title !== undefined && typeof d.title !== 'string') throw new TypeError(`${fn}: drawing.title must be a string, got ${describe(d.title)}`);
    if (d.standalone !== undefined && typeof d.standalone !== 'boolean')
      throw new TypeError(`${fn}: drawing.standalone must be a boolean, got ${describe(d.standalone)}`);
    return { dim, xy, labels, segs, title: d.title ?? '' };
  }

  // Planes / polygons of a 3D drawing: { vertices (x,y,z per vertex), counts (vertices per face) } or an array of
  // flat vertex arrays (as vectorize's `polygons`), as [vertices: Float64Array, counts: Float64Array].
  function faces(v, fn, name) {
    if (v === undefined) return [new Float64Array(0), new Float64Array(0)];
    let vertices, counts;
    if (Array.isArray(v)) {
      const parts = v.map((f, k) => toF64(f, fn, `drawing.${name}[${k}]`));
      vertices = new Float64Array(parts.reduce((s, p) => s + p.length, 0));
      let at = 0;
      counts = new Float64Array(parts.length);
      parts.forEach((p, k) => {
        if (p.length % 3) throw new RangeError(`${fn}: drawing.${name}[${k}] has ${p.length} numbers, not a multiple of 3 (x,y,z per vertex)`);
        vertices.set(p, at);
        at += p.length;
        counts[k] = p.length / 3;
      });
    } else if (v !== null && typeof v === 'object' && !ArrayBuffer.isView(v)) {
      options(v, fn, ['vertices', 'counts']);
      if (v.vertices === undefined || v.counts === undefined) throw new TypeError(`${fn}: drawing.${name} needs vertices and counts`);
      vertices = toF64(v.vertices, fn, `drawing.${name}.vertices`);
      counts = toF64(v.counts, fn, `drawing.${name}.counts`);
      if (vertices.length % 3) throw new RangeError(`${fn}: drawing.${name}.vertices has ${vertices.length} numbers, not a multiple of 3 (x,y,z per vertex)`);
    } else {
      throw new TypeError(`${fn}: drawing.${name} must be {vertices, counts} or an array of vertex arrays, got ${describe(v)}`);
    }
    let sum = 0;
    for (let k = 0; k < counts.length; k++) {
      if (!Number.isInteger(counts[k]) || counts[k] < 3)
        throw new RangeError(`${fn}: drawing.${name} face ${k} has ${counts[k]} vertices, expected an integer >= 3`);
      sum += counts[k];
    }
    if (sum * 3 !== vertices.length) throw new RangeError(`${fn}: drawing.${name}: the counts add up to ${sum} vertices, the vertices hold ${vertices.length / 3}`);
    for (let i = 0; i < vertices.length; i++) {
      if (!Number.isFinite(vertices[i])) throw new RangeError(`${fn}: drawing.${name} vertex coordinate ${i} is ${vertices[i]}, expected a finite number`);
    }
    return [vertices, counts];
  }

  function camera(c, fn) {
    if (c === undefined) return [NaN, 0, 0, -1];  // LaTeXTikz3D's own view: looking down -z, auto-fitted
    if (c === null || typeof c !== 'object' || Array.isArray(c)) throw new TypeError(`${fn}: option camera must be an object {fov, direction}, got ${describe(c)}`);
    const o = options(c, `${fn}: camera`, ['fov', 'direction']);
    const fov = num(o, 'fov', `${fn}: camera`, 60, { min: 0, exclusiveMin: true, max: 179 });
    let dir = [0, 0, -1];
    if (o.direction !== undefined) {
      const a = toF64(o.direction, fn, 'camera.direction');
      if (a.length !== 3) throw new RangeError(`${fn}: camera.direction must have 3 numbers, got ${a.length}`);
      if (!a.every(Number.isFinite) || !(Math.hypot(a[0], a[1], a[2]) > 0))
        throw new RangeError(`${fn}: camera.direction must be a finite non-zero vector`);
      dir = Array.from(a);
    }
    return [fov, ...dir];
  }

  // At most 400 cm: with its margins (2D: 5 % overrun per side, marks, border; 3D: 1.1 x the picture) the picture
  // stays within the writers' 500 cm limit below TeX's largest dimension (575 cm), which they refuse beyond.
  function sizeOptions(o, fn, width, height, radius) {
    return [num(o, 'width', fn, width, { min: 0, exclusiveMin: true, max: 400 }),
      num(o, 'height', fn, height, { min: 0, exclusiveMin: true, max: 400 }),
      num(o, radius, fn, 0.03, { min: 0, max: 10 })];
  }

  // Standalone pdflatex document (default) or the bare tikzpicture. 2D: one uniform scale, the data range fitted
  // into width x height cm; 3D: LaTeXTikz3D's picture of width x height cm from the camera.
  function toTikz(drawing, opts) {
    const fn = 'toTikz';
    const { m, withHeap, boundary } = extras(fn);
    const o = options(opts, fn, ['standalone', 'width', 'height', 'markRadius', 'camera']);
    const standaloneOpt = boolOption(o, 'standalone', fn, undefined);
    const [W, H, r] = sizeOptions(o, fn, 12, 12, 'markRadius');
    const d = checkDrawing(drawing, fn);
    const standalone = standaloneOpt ?? drawing.standalone ?? true;
    if (d.dim === 2) {
      if (o.camera !== undefined) throw new TypeError(`${fn}: option camera needs a 3D drawing (dim: 3)`);
      return withHeap(fn, [d.xy, d.labels, d.segs], (p, np, l, nl, s, ns) =>
        m.drawScan2D(p, np, l, nl, s, ns, d.title, boundary.call('drawScan2D').writeOptions(
          { width: W, height: H, markRadius: r, format: standalone ? 'tikz' : 'tikzpicture' })));
    }
    const [fov, ...direction] = camera(o.camera, fn);
    const [pv, pc] = faces(drawing.planes, fn, 'planes');
    const [qv, qc] = faces(drawing.polygons, fn, 'polygons');
    return withHeap(fn, [d.xy, d.labels, d.segs, pv, pc, qv, qc], (p, np, l, nl, s, ns, a, na, b, nb, e, ne, f, nf) =>
      m.drawTikz3D(p, np, l, nl, s, ns, a, na, b, nb, e, ne, f, nf, boundary.call('drawTikz3D').writeOptions(
        { fov, direction, width: W, height: H, markRadius: r, standalone })));
  }

  // The same 2D picture as SVG (rtl::writeSvg, a document in cm). Sizes are CSS pixels (96 per inch), so that the
  // picture shows at that size on screen; the data range is fitted into width x height, plus a small margin.
  const CM_PER_PX = 2.54 / 96;
  function toSvg(drawing, opts) {
    const fn = 'toSvg';
    const { m, withHeap, boundary } = extras(fn);
    const o = options(opts, fn, ['width', 'height', 'pointRadius']);
    const W = num(o, 'width', fn, 800, { min: 0, exclusiveMin: true, max: 100000 });
    const H = num(o, 'height', fn, 800, { min: 0, exclusiveMin: true, max: 100000 });
    const r = num(o, 'pointRadius', fn, 2, { min: 0, max: 1000 });
    const d = checkDrawing(drawing, fn);
    if (d.dim !== 2) throw new RangeError(`${fn}: only 2D drawings (3D: toTikz with dim 3)`);
    return withHeap(fn, [d.xy, d.labels, d.segs], (p, np, l, nl, s, ns) =>
      m.drawScan2D(p, np, l, nl, s, ns, d.title, boundary.call('drawScan2D').writeOptions(
        { width: W * CM_PER_PX, height: H * CM_PER_PX, markRadius: r * CM_PER_PX, format: 'svg' })));
  }

  // rows: arrays of cells (strings, or numbers written with String()); a null row is a horizontal rule.
  function toLatexTable(rows, opts) {
    const fn = 'toLatexTable';
    const { m } = extras(fn);
    const o = options(opts, fn, ['heading', 'caption', 'escape', 'columns']);
    const escape = boolOption(o, 'escape', fn, true);
    const cells = (row, what) => {
      if (!Array.isArray(row)) throw new TypeError(`${fn}: ${what} must be an array of cells, got ${describe(row)}`);
      return row.map((c, j) => {
        if (typeof c === 'string') return c;
        if (typeof c === 'number') return String(c);
        throw new TypeError(`${fn}: ${what}[${j}] is ${describe(c)}, expected a string or a number`);
      });
    };
    if (!Array.isArray(rows)) throw new TypeError(`${fn}: rows must be an array of rows, got ${describe(rows)}`);
    const body = rows.map((r, i) => (r === null ? null : cells(r, `rows[${i}]`)));
    const heading = o.heading === undefined ? [] : cells(o.heading, 'option heading');
    for (const k of ['caption', 'columns']) {
      if (o[k] !== undefined && typeof o[k] !== 'string') throw new TypeError(`${fn}: option ${k} must be a string, got ${describe(o[k])}`);
    }
    return check(m.latexTable(body, heading, o.caption ?? '', o.columns ?? '', escape), fn);
  }

  return { toTikz, toSvg, toLatexTable };
}
