// toSvg and toTikz: structure, coordinates, colours, escaping, errors; the TikZ document compiles with pdflatex.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { execFileSync } from 'node:child_process';
import { existsSync, mkdtempSync, readFileSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import init from 'rtl-wasm';
import { near, throwsWith } from './helpers.mjs';

const rtl = await init();

// Four points in two clusters, a gap and an unlabelled point, one segment.
const drawing = {
  points: [0, 0, 1, 0, NaN, NaN, 2, 1, 4, 2],
  labels: [0, 0, -1, 1, -1],
  segments: [0, 0, 4, 2],
  title: 'scan <1> & "x"',
};

test('toSvg: circles per cluster in the palette colours, y up, uniform scale, segments, escaped title', () => {
  const svg = rtl.toSvg(drawing, { width: 420, height: 300, pointRadius: 3 });
  assert.match(svg, /^<svg xmlns="http:\/\/www\.w3\.org\/2000\/svg" width="420" height="300" viewBox="0 0 420 300">/);
  assert.ok(svg.trimEnd().endsWith('</svg>'));
  assert.equal((svg.match(/<circle /g) || []).length, 4, 'the NaN point is not drawn');
  // cluster 0: #0072B2, cluster 1: #E69F00 (the page's palette); unlabelled gray
  assert.match(svg, /<g class="cluster" data-cluster="0" fill="#0072B2">\n<circle [^\n]*\n<circle [^\n]*\n<\/g>/);
  assert.match(svg, /<g class="cluster" data-cluster="1" fill="#E69F00">\n<circle [^\n]*\n<\/g>/);
  assert.match(svg, /<g class="points" fill="#808080">\n<circle [^\n]*\n<\/g>/);
  assert.match(svg, /<title>scan &lt;1&gt; &amp; &quot;x&quot;<\/title>/);
  // Geometry: data x in [0,4], y in [0,2]; margin 7, title 24 -> scale min((420-14)/4, (300-14-24)/2) = 101.5.
  const line = svg.match(/<line x1="([\d.]+)" y1="([\d.]+)" x2="([\d.]+)" y2="([\d.]+)"\/>/);
  assert.ok(line, 'one segment line');
  const [x1, y1, x2, y2] = line.slice(1).map(Number);
  near(x2 - x1, 4 * 101.5, 1e-3, 'segment width');
  near(y1 - y2, 2 * 101.5, 1e-3, 'segment height (y up)');
  near((x1 + x2) / 2, 210, 1e-3, 'centred horizontally');
  const c0 = svg.match(/data-cluster="0" fill="#0072B2">\n<circle cx="([\d.]+)" cy="([\d.]+)" r="3"\/>/);
  assert.deepEqual([Number(c0[1]), Number(c0[2])], [x1, y1], 'point (0,0) at the segment start');
  const gray = svg.match(/<g class="points" fill="#808080">\n<circle cx="([\d.]+)" cy="([\d.]+)"/);
  assert.deepEqual([Number(gray[1]), Number(gray[2])], [x2, y2], 'unlabelled point (4,2) at the segment end');
});

test('toSvg: empty drawing and defaults', () => {
  const svg = rtl.toSvg({});
  assert.match(svg, /width="800" height="800"/);
  assert.ok(!svg.includes('<circle'));
});

test('toTikz: LaTeXTikz2D conventions (preamble, StyleX, ColorX, MarkX, macros), bare picture', () => {
  const tex = rtl.toTikz(drawing, { width: 8, height: 8 });
  assert.ok(tex.startsWith('\\documentclass{minimal}\n\\usepackage[rgb]{xcolor}\n\\usepackage{tikz}\n\\usepackage[active,tightpage]{preview}\n\\PreviewEnvironment{tikzpicture}\n'));
  assert.ok(tex.endsWith('\\end{tikzpicture}\n\\end{document}\n'));
  assert.match(tex, /\\begin\{tikzpicture\}\[xscale=2, yscale=2,\n\tStyleA\/\.style=\{draw=ColorA,fill=ColorA/);
  assert.match(tex, /\\definecolor\{ColorA\}\{HTML\}\{808080\}/, 'unlabelled (drawn first, beneath)');
  assert.match(tex, /\\definecolor\{ColorB\}\{HTML\}\{0072B2\}/, 'cluster 0');
  assert.match(tex, /\\definecolor\{ColorC\}\{HTML\}\{E69F00\}/, 'cluster 1');
  assert.match(tex, /\\pgfmathsetmacro\{\\MarkGlobalScaleX\}\{0\.5\}/);
  for (const m of ['MaxX}{4}', 'MinX}{0}', 'MaxY}{2}', 'MinY}{0}']) assert.ok(tex.includes(`\\pgfmathsetmacro{\\${m}`), m);
  assert.match(tex, /\\newcommand\{\\MarkA\}\[3\]\{\\begin\{scope\}\[shift=\{\(#1,#2\)\}, xscale=\\MarkGlobalScaleX/);
  assert.equal((tex.match(/^\\Mark[A-J]+\{/gm) || []).length, 4, 'one mark per drawn point');
  assert.ok(tex.includes('% cluster 0\n\\MarkB{0}{0}{0}\n\\MarkB{1}{0}{0}\n'));
  assert.match(tex, /\\draw\[Style[A-J]+\] \(0,0\) -- \(4,2\);/);
  assert.ok(tex.includes('{scan $<$1$>$ \\& "x"}'), 'title escaped for LaTeX');
  const bare = rtl.toTikz({ ...drawing, standalone: false });
  assert.ok(bare.startsWith('\\begin{tikzpicture}') && !bare.includes('\\documentclass'));
  assert.ok(rtl.toTikz({ ...drawing, standalone: false }, { standalone: true }).startsWith('\\documentclass'));
});

test('toTikz: a 361-beam scan with 6 clusters compiles with pdflatex', { timeout: 60_000 }, () => {
  const pts = [], labels = [];
  for (let i = 0; i < 361; i++) {
    const a = -Math.PI / 2 + i * Math.PI / 360;
    const r = 4 + (Math.floor(i / 60) % 2);
    pts.push(r * Math.cos(a), r * Math.sin(a));
    labels.push(Math.floor(i / 60));
  }
  const dir = mkdtempSync(join(tmpdir(), 'rtl-tikz-'));
  try {
    writeFileSync(join(dir, 'scan.tex'), rtl.toTikz({ points: pts, labels, segments: [0, -4, 4, 0], title: 'scan_1' }));
    execFileSync('pdflatex', ['-interaction=nonstopmode', '-halt-on-error', 'scan.tex'], { cwd: dir, stdio: 'ignore', timeout: 50_000 });
    assert.ok(existsSync(join(dir, 'scan.pdf')));
    assert.ok(!/^! /m.test(readFileSync(join(dir, 'scan.log'), 'latin1')), 'no LaTeX errors');
  } finally {
    rmSync(dir, { recursive: true, force: true });
  }
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
test('toTikz error: standalone not a boolean', () => {
  throwsWith(() => rtl.toTikz({}, { standalone: 1 }), TypeError, /toTikz: option standalone must be a boolean/);
  throwsWith(() => rtl.toTikz({ standalone: 'no' }), TypeError, /drawing\.standalone must be a boolean/);
});
