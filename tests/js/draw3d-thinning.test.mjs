// toTikz({dim: 3}) of a scene beyond pdflatex's memory: LaTeXTikz3D writes every k-th mark and a note
// (rtl/io/TikzBudget.h, default limit 8,000 mark equivalents), byte for byte as the native library; within the
// limit every mark is written and there is no note.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import init from 'rtl-wasm';
import { nativeTool } from './helpers.mjs';

const rtl = await init();
const drawScan = nativeTool('draw_scan');

// n points on a helix, 50 points per cluster, every 11th cluster unlabelled.
function helix(n) {
  const points = new Float64Array(3 * n), labels = new Float64Array(n);
  for (let i = 0; i < n; i++) {
    const a = (8 * Math.PI * i) / n;
    points.set([Math.cos(a), Math.sin(a), i / n], 3 * i);
    labels[i] = Math.floor(i / 50) % 11 === 10 ? -1 : Math.floor(i / 50);
  }
  return { dim: 3, points, labels };
}
const marks = (tex) => (tex.match(/^\\Mark[A-Z]+\{/gm) || []).length;
const native = (d) => drawScan('tikz3d', d.points, d.labels, [], [], [], [], [], 'nan', 0, 0, -1, 12, 12, 0.03);

test('toTikz 3D: 8,000 marks are all written, 8,001 and 12,000 are thinned 1 in 2 with the note', () => {
  const at = rtl.toTikz(helix(8000));
  assert.equal(marks(at), 8000);
  assert.ok(!at.includes('Thinned'), 'no note within the limit');
  for (const [n, kept] of [[8001, 4001], [12000, 6000]]) {
    const tex = rtl.toTikz(helix(n));
    assert.equal(marks(tex), kept, `${n} points`);
    assert.ok(tex.includes(`{Thinned for pdflatex's memory: 1 in 2 marks drawn (${kept} of ${n} marks).};\n`), `${n}: the note`);
    assert.ok(tex.endsWith('\\end{tikzpicture}\n\\end{document}\n'));
  }
});

test('toTikz 3D: the thinned scene is byte-identical to the native rtl::drawScene3D + LaTeXTikz3D', () => {
  const d = helix(12000);
  assert.equal(rtl.toTikz(d), native(d));
});
