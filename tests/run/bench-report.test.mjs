// The speed report of ./run bench (bench/report/make_report.sh) works end to end on tiny sizes: the native and wasm
// TSVs hold every case at every size with the same outputs, the figures are SVG that an XML parser accepts and
// TikZ that pdflatex compiles, and report.md has the figures, tables and machine. No timing is asserted.
// Needs the native build with speed_native and speed_figure ($RTL_NATIVE_BUILD_DIR, default build/native), dist/,
// pdflatex and Chromium (all installed and built by ./run test before the JavaScript tests).
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { execFileSync } from 'node:child_process';
import { existsSync, mkdtempSync, readFileSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join, resolve } from 'node:path';
import { fileURLToPath } from 'node:url';
import { launchBrowser } from '../web/helpers.js';

const ROOT = fileURLToPath(new URL('../..', import.meta.url));
const BUILD = resolve(ROOT, process.env.RTL_NATIVE_BUILD_DIR || 'build/native');
const CASES = ['floor', 'FTLS', 'ITLS', 'DP', 'RW', 'CAR', 'IA'];
const SIZES = [10, 100, 1000];

function readTsv(file) {
  const [head, ...lines] = readFileSync(file, 'utf8').trim().split('\n');
  const cols = head.split('\t');
  assert.deepEqual(cols, ['impl', 'case', 'points', 'rounds', 'calls', 'cpu_ns_per_point', 'wall_ns_per_point', 'library_ns_per_point', 'output']);
  return lines.map((l) => Object.fromEntries(l.split('\t').map((v, i) => [cols[i], v])));
}

test('make_report.sh --smoke writes the TSVs, both figures as SVG and PDF, and report.md', { timeout: 300_000 }, async () => {
  assert.ok(existsSync(join(BUILD, 'bench', 'report', 'speed_native')), `speed_native is not built in ${BUILD}`);
  const out = mkdtempSync(join(tmpdir(), 'rtl-bench-report-'));
  try {
    execFileSync(join(ROOT, 'bench', 'report', 'make_report.sh'), ['--build', BUILD, '--out', out, '--smoke'],
      { cwd: ROOT, stdio: ['ignore', 'ignore', 'pipe'] });

    // Every case at every size, on both sides, with positive times and the same outputs.
    const rows = { native: readTsv(join(out, 'native.tsv')), wasm: readTsv(join(out, 'wasm.tsv')) };
    const output = {};
    for (const [impl, rs] of Object.entries(rows)) {
      assert.deepEqual(rs.map((r) => `${r.case}@${r.points}`), SIZES.flatMap((n) => CASES.map((c) => `${c}@${n}`)), impl);
      for (const r of rs) {
        assert.equal(r.impl, impl);
        assert.ok(Number(r.cpu_ns_per_point) > 0 && Number(r.wall_ns_per_point) > 0, `${impl} ${r.case} ${r.points}: ${r.cpu_ns_per_point}`);
        output[`${impl} ${r.case} ${r.points}`] = Number(r.output);
      }
    }
    for (const n of SIZES)
      for (const c of CASES) assert.equal(output[`wasm ${c} ${n}`], output[`native ${c} ${n}`], `${c} at ${n} points`);
    // The scan's beams are 6 m apart at 10 points and 0.6 m at 100 (over the upper bound 0.1: one cluster each),
    // 6 cm at 1000: its 10 walls.
    assert.deepEqual(SIZES.map((n) => [output[`native CAR ${n}`], output[`native IA ${n}`]]), [[10, 10], [100, 100], [10, 10]]);
    // Douglas-Peucker keeps both ends and, at epsilon 0.09 on a radius of 8, more than 10 points of 1000.
    assert.ok(output['native DP 1000'] > 10 && output['native DP 1000'] < 100, `DP kept ${output['native DP 1000']}`);

    const report = readFileSync(join(out, 'report.md'), 'utf8');
    for (const s of ['## Figures', '## Tables', '## Machine', '![', 'speed_vectorizers.svg', 'speed_segmenters.pdf',
      'identical at every size and case', 'load before', 'nproc'])
      assert.ok(report.includes(s), `report.md lacks "${s}"`);
    // The native table: one row per size, 8 columns (n, floor, six cases), each case "ns (ratio×)".
    const table = report.split('\n').filter((l) => /^\| (10|100|1000) \| [0-9.]+ \|( [0-9.]+ \([0-9.]+×\) \|){6}$/.test(l));
    assert.equal(table.length, 2 * SIZES.length, 'native and wasm rows with a ratio to the floor per case');

    for (const f of ['speed_vectorizers', 'speed_segmenters']) {
      assert.ok(readFileSync(join(out, `${f}.pdf`)).subarray(0, 5).toString() === '%PDF-', `${f}.pdf`);
      const tex = readFileSync(join(out, `${f}.tex`), 'utf8');
      assert.match(tex, /\\begin\{tikzpicture\}[\s\S]*\\end\{tikzpicture\}/);
      assert.ok(tex.includes('number of points n') && tex.includes('native (C++)'));
    }
    const browser = await launchBrowser();
    try {
      const page = await browser.context.newPage();
      for (const [f, names] of [['speed_vectorizers', ['FTLS', 'ITLS', 'DP', 'RW']], ['speed_segmenters', ['CAR', 'IA']]]) {
        const svg = readFileSync(join(out, `${f}.svg`), 'utf8');
        const parsed = await page.evaluate((s) => {
          const doc = new DOMParser().parseFromString(s, 'image/svg+xml');
          return {
            error: doc.getElementsByTagName('parsererror').length,
            root: doc.documentElement.nodeName,
            texts: [...doc.getElementsByTagName('text')].map((t) => t.textContent),
            dashed: [...doc.getElementsByTagName('polyline')].filter((p) => p.getAttribute('stroke-dasharray')).length,
            solid: [...doc.getElementsByTagName('polyline')].filter((p) => !p.getAttribute('stroke-dasharray')).length,
          };
        }, svg);
        assert.equal(parsed.error, 0, `${f}.svg does not parse`);
        assert.equal(parsed.root, 'svg');
        for (const t of [...names, 'native (C++)', 'wasm (Node)', 'number of points n']) assert.ok(parsed.texts.includes(t), `${f}.svg: "${t}"`);
        // One curve per case and implementation (floor included) plus one legend sample per case and per line style.
        assert.equal(parsed.dashed, names.length + 1 + 1, `${f}.svg dashed polylines`);
        assert.equal(parsed.solid, 2 * (names.length + 1) + 1, `${f}.svg solid polylines`);
      }
    } finally {
      await browser.close();
    }
  } finally {
    rmSync(out, { recursive: true, force: true });
  }
});
