// toSvg, toTikz (2D and 3D) and toLatexTable: the C++ core draws and writes (wasm/src/scan_drawing.h, Drawing2D,
// Svg2D, LaTeXTikz3D, LaTeXTable); the package's output is byte-identical to the native library's on real scans
// (tests/tools/draw_scan.cpp in $RTL_NATIVE_BUILD_DIR/tools); structure, numbers, escaping, errors, no leaks;
// the TikZ documents compile with pdflatex.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { execFileSync } from 'node:child_process';
import { existsSync, mkdtempSync, readFileSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join, resolve } from 'node:path';
import { fileURLToPath } from 'node:url';
import init, { palette, unlabelledColour } from 'rtl-wasm';
import { memoryProbe, near, scanDrawing, throwsWith } from './helpers.mjs';

const rtl = await init();
const ROOT = fileURLToPath(new URL('../..', import.meta.url));
const TOOL = join(resolve(ROOT, process.env.RTL_NATIVE_BUILD_DIR || 'build/native'), 'tools', 'draw_scan');
const DATA = new URL('../data/', import.meta.url);
const dir = mkdtempSync(join(tmpdir(), 'rtl-draw-'));
process.on('exit', () => rmSync(dir, { recursive: true, force: true }));
let files = 0;
const f64 = (a) => { if (!a || a.length === 0) return '-'; const f = join(dir, `a${files++}.f64`); writeFileSync(f, Float64Array.from(a)); return f; };
const text = (s) => { if (!s) return '-'; const f = join(dir, `t${files++}.txt`); writeFileSync(f, s); return f; };
const native = (args) => execFileSync(TOOL, args.map(String), { encoding: 'utf8', maxBuffer: 1 << 28 });

// pdflatex in a fresh directory; returns the log (throws if no PDF came out).
function pdflatex(tex) {
  const d = mkdtempSync(join(dir, 'tex-'));
  writeFileSync(join(d, 'doc.tex'), tex);
  try {
    execFileSync('pdflatex', ['-interaction=nonstopmode', '-halt-on-error', 'doc.tex'], { cwd: d, stdio: 'ignore', timeout: 100_000 });
  } catch { /* judged by the PDF and the log below */ }
  const log = readFileSync(join(d, 'doc.log'), 'latin1');
  assert.ok(existsSync(join(d, 'doc.pdf')), `pdflatex made no PDF:\n${log.split('\n').filter((l) => l.startsWith('!')).join('\n')}`);
  assert.ok(!/^! /m.test(log), 'no LaTeX errors');
  return log;
}

// Four points in two clusters, a gap and an unlabelled point, one segment.
const drawing = {
  points: [0, 0, 1, 0, NaN, NaN, 2, 1, 4, 2],
  labels: [0, 0, -1, 1, -1],
  segments: [0, 0, 4, 2],
  title: 'scan <1> & "x"',
};

test('toSvg: marks per cluster in the palette colours, y up, one scale from CSS pixels, segment, escaped title', () => {
  const svg = rtl.toSvg(drawing, { width: 420, height: 300, pointRadius: 3 });
  assert.ok(svg.startsWith('<?xml version="1.0" encoding="UTF-8"?>\n<svg xmlns="http://www.w3.org/2000/svg"'));
  assert.ok(svg.trimEnd().endsWith('</svg>'));
  assert.equal((svg.match(/<use href="#Mark/g) || []).length, 4, 'the NaN point is not drawn');
  // unlabelled gray first, then cluster 0 #0072B2, cluster 1 #E69F00; mark radius 3 px in cm
  assert.match(svg, /<g id="MarkA"><circle r="0.0793750?" stroke="#808080" fill="#808080"/);
  assert.match(svg, /<g id="MarkB"><circle r="[\d.]+" stroke="#0072b2" fill="#0072b2"/);
  assert.match(svg, /<g id="MarkC"><circle r="[\d.]+" stroke="#e69f00" fill="#e69f00"/);
  assert.match(svg, />scan &lt;1&gt; &amp; &quot;x&quot;<\/text>/);
  // Data x in [0,4], y in [0,2] into 420 x 300 px = 11.1125 x 7.9375 cm: one scale min(11.1125/4, 7.9375/2) cm/unit.
  const s = Math.min(420 / 4, 300 / 2) * 2.54 / 96;
  const line = svg.match(/<line x1="([-\d.]+)" y1="([-\d.]+)" x2="([-\d.]+)" y2="([-\d.]+)"/);
  assert.ok(line, 'one segment line');
  const [x1, y1, x2, y2] = line.slice(1).map(Number);
  near(x2 - x1, 4 * s, 1e-4, 'segment width');
  near(y1 - y2, 2 * s, 1e-4, 'segment height (y up)');
  const w = Number(svg.match(/ width="([\d.]+)cm"/)[1]), h = Number(svg.match(/ height="([\d.]+)cm"/)[1]);
  assert.ok(w >= 4 * s && w < 4 * s + 1, `picture width ${w} cm: the data width plus a margin`);
  assert.ok(h >= 2 * s && h < 2 * s + 1, `picture height ${h} cm`);
  const first = svg.match(/<use href="#MarkB" transform="translate\(([-\d.]+),([-\d.]+)\)"/);
  assert.deepEqual([Number(first[1]), Number(first[2])], [x1, y1], 'point (0,0) at the segment start');
});

test('toSvg: empty drawing', () => {
  const svg = rtl.toSvg({});
  assert.match(svg, /<svg [^>]*width="[\d.]+cm"/);
  assert.ok(!svg.includes('<use'));
});

test('toTikz: LaTeXTikz2D conventions (unit vectors, StyleX, ColorX, MarkX, macros), bare picture', () => {
  const tex = rtl.toTikz(drawing, { width: 8, height: 8 });
  assert.ok(tex.startsWith('\\documentclass{minimal}\n\\usepackage[rgb]{xcolor}\n\\usepackage{tikz}\n\\usepackage[active,tightpage]{preview}\n\\PreviewEnvironment{tikzpicture}\n'));
  assert.ok(tex.endsWith('\\end{tikzpicture}\n\\end{document}\n'));
  // one scale: min(8/4, 8/2) = 2 cm per unit on both axes
  assert.match(tex, /\\begin\{tikzpicture\}\[x=2cm, y=2cm,\n\tStyleA\/\.style=\{draw=ColorA,fill=ColorA/);
  assert.match(tex, /\\definecolor\{ColorA\}\{HTML\}\{808080\}/, 'unlabelled (drawn first, beneath)');
  assert.match(tex, /\\definecolor\{ColorB\}\{HTML\}\{0072B2\}/, 'cluster 0');
  assert.match(tex, /\\definecolor\{ColorC\}\{HTML\}\{E69F00\}/, 'cluster 1');
  assert.match(tex, /\\pgfmathsetmacro\{\\MarkGlobalScaleX\}\{0\.5\}/);
  for (const m of ['MaxX}{4}', 'MinX}{0}', 'MaxY}{2}', 'MinY}{0}']) assert.ok(tex.includes(`\\pgfmathsetmacro{\\${m}`), m);
  assert.equal((tex.match(/^\\Mark[A-J]+\{/gm) || []).length, 4, 'one mark per drawn point');
  assert.ok(tex.includes('\\MarkB{0}{0}{0}\n\\MarkB{1}{0}{0}\n'), 'cluster 0 marks');
  assert.match(tex, /\\draw\[Style[A-J]+\] \(0,0\) -- \(4,2\);/);
  assert.ok(tex.includes('{scan $<$1$>$ \\& "x"}'), 'title escaped for LaTeX');
  const bare = rtl.toTikz({ ...drawing, standalone: false });
  assert.ok(bare.startsWith('\\begin{tikzpicture}') && !bare.includes('\\documentclass'));
  assert.ok(rtl.toTikz({ ...drawing, standalone: false }, { standalone: true }).startsWith('\\documentclass'));
});

// Real scans: 4 scans spread over each of intel.log and csail.log, segmented, clusters of >= 3 points vectorized.
function realDrawings() {
  const out = [];
  for (const name of ['intel.log', 'csail.log']) {
    const scans = rtl.readCarmenLog(readFileSync(new URL(name, DATA)));
    for (let k = 0; k < scans.length; k += Math.max(1, Math.ceil(scans.length / 4))) {
      out.push(scanDrawing(rtl, scans[k].points, `${name} scan ${k} _&%`));
    }
  }
  return out;
}

test('toTikz and toSvg equal the native C++ library byte for byte on real scans with clusters and segments', () => {
  const drawings = realDrawings();
  assert.ok(drawings.length >= 4);
  let segmentsDrawn = 0;
  for (const d of drawings) {
    const args = [f64(d.points), f64(d.labels), f64(d.segments), text(d.title)];
    assert.equal(rtl.toTikz(d, { width: 10, height: 7, markRadius: 0.02 }), native(['tikz', ...args, 10, 7, 0.02]));
    assert.equal(rtl.toTikz({ ...d, standalone: false }), native(['tikz-bare', ...args, 12, 12, 0.03]));
    const px = 2.54 / 96;
    assert.equal(rtl.toSvg(d, { width: 640, height: 480 }), native(['svg', ...args, 640 * px, 480 * px, 2 * px]));
    segmentsDrawn += d.segments.length / 4;
  }
  assert.ok(segmentsDrawn > 20, `segments drawn: ${segmentsDrawn}`);
});

test('toTikz: a real scan in the map frame (millimetres, around x 1000-2000) compiles with pdflatex', { timeout: 120_000 }, () => {
  const d = realDrawings()[1];
  const mm = (a) => Float64Array.from(a, (v) => 1000 * v + 1500);
  pdflatex(rtl.toTikz({ ...d, points: mm(d.points), segments: mm(d.segments) }));
});

test('toTikz: 15,000 points are thinned for pdflatex with a note, byte for byte as the native library', () => {
  // A scan in the map frame, clusters of 60 points, one segment per cluster (as tests/io/t_tikz2d_budget.cpp).
  const n = 15000, points = new Float64Array(2 * n), labels = new Int32Array(n), segments = [];
  for (let i = 0; i < n; i++) {
    const a = (2 * Math.PI * i) / n, r = 20 + 5 * Math.sin(7 * a);
    points[2 * i] = 1500 + r * Math.cos(a);
    points[2 * i + 1] = 800 + r * Math.sin(a);
    labels[i] = Math.floor(i / 60) % 7 === 6 ? -1 : Math.floor(i / 60);
    if (i % 60 === 59) segments.push(points[2 * (i - 59)], points[2 * (i - 59) + 1], points[2 * i], points[2 * i + 1]);
  }
  const d = { points, labels, segments, title: 'big' };
  const tex = rtl.toTikz({ ...d, standalone: false });
  assert.ok(tex.includes("{Thinned for pdflatex's memory: 1 in 2 marks and line points drawn (7500 of 15000 marks).};\n\\end{tikzpicture}"));
  assert.equal(tex.match(/^\\Mark[A-Z]+\{/gm).length, 7500);
  assert.equal(tex, native(['tikz-bare', f64(points), f64(labels), f64(segments), text('big'), 12, 12, 0.03]));
  // The SVG has no such limit: every point is drawn.
  assert.equal(rtl.toSvg(d).match(/<use /g).length, n);
});

// A unit cube's floor (plane), one wall outline, points on a line, a segment.
const scene = {
  dim: 3,
  points: [0, 0, 1, 0.5, 0.5, 1, NaN, NaN, NaN, 1, 1, 1],
  labels: [0, 0, -1, 2],
  segments: [0, 0, 0, 1, 1, 1],
  planes: { vertices: [0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0], counts: [4] },
  polygons: [[0, 0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1]],
};

test('toTikz 3D: LaTeXTikz3D scene (marks, faces, lines), equal to the native library, compiles', { timeout: 120_000 }, () => {
  const camera = { fov: 50, direction: [-1, -2, -1] };
  const tex = rtl.toTikz(scene, { camera, width: 9, height: 6 });
  assert.ok(tex.startsWith('\\documentclass{minimal}'));
  assert.equal((tex.match(/^\\Mark[A-J]+\{/gm) || []).length, 3, 'three marks (the NaN point is a gap)');
  assert.match(tex, /fill=Color[A-J]+!45/, 'the plane filled in its palette colour');
  assert.match(tex, /\\definecolor\{Color[A-J]+\}\{HTML\}\{009E73\}/, 'label 2 colour');
  const pv = scene.planes.vertices, qv = scene.polygons[0];
  const expected = native(['tikz3d', f64(scene.points), f64(scene.labels), f64(scene.segments), f64(pv), f64([4]), f64(qv), f64([4]),
    50, -1, -2, -1, 9, 6, 0.03]);
  assert.equal(tex, expected, 'byte-identical to rtl::drawScene3D + LaTeXTikz3D');
  // the flat layout and the array-of-faces layout are the same drawing
  assert.equal(rtl.toTikz({ ...scene, planes: [pv], polygons: { vertices: qv, counts: [4] } }, { camera, width: 9, height: 6 }), tex);
  // default view: LaTeXTikz3D's own
  assert.equal(rtl.toTikz(scene), native(['tikz3d', f64(scene.points), f64(scene.labels), f64(scene.segments), f64(pv), f64([4]),
    f64(qv), f64([4]), 'nan', 0, 0, -1, 12, 12, 0.03]));
  assert.equal(rtl.toTikz({ dim: 3 }), '', 'an empty scene writes nothing (LaTeXTikz3D::writeTEX)');
  pdflatex(tex);
});

test('toLatexTable: rtl::LaTeXTable layout, escaping by default, LaTeX cells with escape: false, rules', () => {
  const t = rtl.toLatexTable([['a_1', 2.5], null, ['50%', 'x&y']], { heading: ['name', 'value'], caption: 'Costs & #' });
  assert.equal(t, '\\begin{table}\n\\begin{center}\n\\begin{tabular}{cc}\n\tname & value\\\\\n\ta\\_1 & 2.5\\\\\n\t\\hline\n' +
    '\t50\\% & x\\&y\\\\\n\\end{tabular}\n\\end{center}\n\\caption{Costs \\& \\#}\n\\end{table}\n\n');
  const raw = rtl.toLatexTable([['$10^{3}$']], { escape: false, columns: 'l' });
  assert.ok(raw.includes('\\begin{tabular}{l}\n\t$10^{3}$\\\\\n'), raw);
  assert.ok(!raw.includes('\\caption'), 'no caption when none is given');
});

test('toLatexTable: a table of every special character compiles with pdflatex', { timeout: 120_000 }, () => {
  const nasty = '& % $ # _ { } ~ ^ \\ < > é ü \u0007';
  pdflatex('\\documentclass{article}\n\\usepackage[T1]{fontenc}\n\\usepackage[utf8]{inputenc}\n\\begin{document}\n' +
    rtl.toLatexTable([[nasty, 1]], { heading: ['text', 'n'], caption: nasty }) + '\\end{document}\n');
});

const ERRORS = [
  ['drawing not an object', (f) => f('x'), TypeError, /drawing must be an object/],
  ['drawing an array', (f) => f([1, 2]), TypeError, /drawing must be an object/],
  ['unknown field', (f) => f({ pts: [] }), TypeError, /unknown drawing field "pts"/],
  ['odd points', (f) => f({ points: [1, 2, 3] }), RangeError, /drawing\.points has 3 numbers, not a multiple of 2/],
  ['Infinity point', (f) => f({ points: [1, Infinity] }), RangeError, /drawing\.points\[1\] is Infinity/],
  ['points a string', (f) => f({ points: 'a' }), TypeError, /drawing\.points must be a Float64Array/],
  ['labels length', (f) => f({ points: [1, 2], labels: [0, 1] }), RangeError, /drawing\.labels has 2 entries for 1 points/],
  ['label -2', (f) => f({ points: [1, 2], labels: [-2] }), RangeError, /drawing\.labels\[0\] is -2, expected an integer >= -1/],
  ['label 0.5', (f) => f({ points: [1, 2], labels: [0.5] }), RangeError, /drawing\.labels\[0\] is 0\.5/],
  ['segments length', (f) => f({ segments: [1, 2, 3] }), RangeError, /drawing\.segments has 3 numbers, not a multiple of 4/],
  ['segment NaN', (f) => f({ segments: [0, 0, NaN, 1] }), RangeError, /drawing\.segments\[2\] is NaN/],
  ['title a number', (f) => f({ title: 3 }), TypeError, /drawing\.title must be a string/],
  ['dim 4', (f) => f({ dim: 4 }), RangeError, /drawing\.dim must be 2 or 3/],
  ['unknown option', (f) => f({}, { colour: 'red' }), TypeError, /unknown option "colour"/],
  ['width 0', (f) => f({}, { width: 0 }), RangeError, /option width must be/],
  ['height NaN', (f) => f({}, { height: NaN }), RangeError, /option height must be finite/],
  ['height a string', (f) => f({}, { height: '9' }), TypeError, /option height must be a number/],
];
for (const [name, call, type, re] of ERRORS) {
  test(`toSvg/toTikz error: ${name}`, () => {
    throwsWith(() => call(rtl.toSvg), type, new RegExp('^toSvg: ' + re.source));
    throwsWith(() => call(rtl.toTikz), type, new RegExp('^toTikz: ' + re.source));
  });
}
// width/height up to 400 cm (markRadius up to 10): with its margins the picture stays within the writers' 500 cm
// limit below TeX's largest dimension (575 cm), so every size toTikz accepts compiles; above, the option is refused.
test('toTikz: the largest sizes compile with pdflatex, beyond them a RangeError', { timeout: 120_000 }, () => {
  const opts = { width: 400, height: 400, markRadius: 10 };
  pdflatex(rtl.toTikz(drawing, opts));
  pdflatex(rtl.toTikz(scene, { ...opts, camera: { fov: 50, direction: [-1, -2, -1] } }));
  for (const key of ['width', 'height']) {
    throwsWith(() => rtl.toTikz(drawing, { ...opts, [key]: 401 }), RangeError, new RegExp(`^toTikz: option ${key} must be <= 400, got 401`));
    throwsWith(() => rtl.toTikz(scene, { [key]: 401 }), RangeError, new RegExp(`^toTikz: option ${key} must be <= 400, got 401`));
  }
});

const MORE_ERRORS = [
  ['standalone not a boolean', () => rtl.toTikz({}, { standalone: 1 }), TypeError, /^toTikz: option standalone must be a boolean/],
  ['drawing.standalone not a boolean', () => rtl.toTikz({ standalone: 'no' }), TypeError, /^toTikz: drawing\.standalone must be a boolean/],
  ['camera in 2D', () => rtl.toTikz({}, { camera: {} }), TypeError, /^toTikz: option camera needs a 3D drawing/],
  ['camera fov 0', () => rtl.toTikz({ dim: 3 }, { camera: { fov: 0 } }), RangeError, /^toTikz: camera: option fov must be > 0/],
  ['camera direction zero', () => rtl.toTikz({ dim: 3 }, { camera: { direction: [0, 0, 0] } }), RangeError, /^toTikz: camera\.direction must be a finite non-zero vector/],
  ['3D points not xyz', () => rtl.toTikz({ dim: 3, points: [1, 2] }), RangeError, /^toTikz: drawing\.points has 2 numbers, not a multiple of 3/],
  ['3D segment of 4 numbers', () => rtl.toTikz({ dim: 3, segments: [1, 2, 3, 4] }), RangeError, /^toTikz: drawing\.segments has 4 numbers, not a multiple of 6/],
  ['3D title', () => rtl.toTikz({ dim: 3, title: 'x' }), TypeError, /^toTikz: unknown drawing field "title"/],
  ['face of 2 vertices', () => rtl.toTikz({ dim: 3, planes: [[0, 0, 0, 1, 1, 1]] }), RangeError, /^toTikz: drawing\.planes face 0 has 2 vertices/],
  ['counts do not add up', () => rtl.toTikz({ dim: 3, polygons: { vertices: [0, 0, 0, 1, 0, 0, 0, 1, 0], counts: [4] } }), RangeError, /^toTikz: drawing\.polygons: the counts add up to 4 vertices, the vertices hold 3/],
  ['planes a number', () => rtl.toTikz({ dim: 3, planes: 3 }), TypeError, /^toTikz: drawing\.planes must be \{vertices, counts\}/],
  ['svg of 3D', () => rtl.toSvg({ dim: 3 }), RangeError, /^toSvg: only 2D drawings/],
  ['table rows not an array', () => rtl.toLatexTable('x'), TypeError, /^toLatexTable: rows must be an array of rows/],
  ['table cell an object', () => rtl.toLatexTable([[{}]]), TypeError, /^toLatexTable: rows\[0\]\[0\] is an object/],
  ['table caption a number', () => rtl.toLatexTable([], { caption: 1 }), TypeError, /^toLatexTable: option caption must be a string/],
  ['table escape a string', () => rtl.toLatexTable([], { escape: 'yes' }), TypeError, /^toLatexTable: option escape must be a boolean/],
];
for (const [name, f, type, re] of MORE_ERRORS) test(`drawing error: ${name}`, () => throwsWith(f, type, re));

test('drawings leave the wasm heap, memory and stack as they were (calls and failures)', () => {
  const calls = () => {
    rtl.toTikz(drawing);
    rtl.toSvg(drawing);
    rtl.toTikz(scene);
    rtl.toLatexTable([['a', 1]]);
    try { rtl.toTikz({ dim: 3, planes: [[0, 0, 0]] }); } catch { /* expected */ }
  };
  calls();
  const memory = memoryProbe(rtl);
  for (let i = 0; i < 300; i++) calls();
  memory.unchanged();
});

// The package's palette export is the one its drawings use (the C++ side that draws holds the same list): TikZ
// defines the colours in the order it first meets them, unlabelled points first, then clusters 0, 1, ...; cluster 10
// wraps around to palette[0] (SVG: the mark of its point has palette[0]'s colour).
test('palette / unlabelledColour: the colours toTikz and toSvg draw clusters and unlabelled points in', () => {
  assert.equal(palette.length, 10);
  assert.ok(Object.isFrozen(palette));
  for (const c of [...palette, unlabelledColour]) assert.match(c, /^#[0-9A-F]{6}$/);
  const points = [], labels = [];
  for (let k = -1; k <= 10; k++) { points.push(k, k * k); labels.push(k); }
  const tikz = rtl.toTikz({ points, labels });
  const defined = [...tikz.matchAll(/\\definecolor\{\w+\}\{HTML\}\{([0-9A-F]{6})\}/g)].map((m) => `#${m[1]}`);
  assert.deepEqual(defined, [unlabelledColour, ...palette]);
  const svg = rtl.toSvg({ points, labels });
  const markColour = new Map([...svg.matchAll(/<g id="(\w+)"><circle [^>]*fill="(#[0-9a-f]{6})"/g)].map((m) => [m[1], m[2]]));
  const used = [...svg.matchAll(/<use href="#(\w+)"/g)].map((m) => markColour.get(m[1]).toUpperCase());
  assert.deepEqual(used, [unlabelledColour, ...palette, palette[0]], 'one mark per point, in label order -1..10');
});
