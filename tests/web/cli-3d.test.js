// bin/rtl.js --dim 3: the 3D TikZ export of a real organised LiDAR scan through the package's toTikz({dim: 3}) with
// its camera option. The CLI's bytes must be exactly the package call's on the drawing its own JSON describes (the
// clusters, the segments or planes), so the command and a script (or the page) making that call agree; the
// standalone document compiles with pdflatex; bad combinations are usage errors.
import { after, before, describe, test } from 'node:test';
import assert from 'node:assert/strict';
import { spawnSync } from 'node:child_process';
import { mkdtempSync, readFileSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import init from 'rtl-wasm';
import { DATA, runCli as rtl } from './helpers.js';

const BIN = ['tests/data/rellis3d-os1-4x2048.bin', '--beams', '4'];

describe('rtl CLI --dim 3 (3D TikZ)', { timeout: 120000 }, () => {
  let pkg, cloud, tmp;
  before(async () => {
    pkg = await init();
    cloud = pkg.readOrganizedLidar(readFileSync(join(DATA, 'rellis3d-os1-4x2048.bin')), { beams: 4 });
    tmp = mkdtempSync(join(tmpdir(), 'rtl-cli-3d-'));
  });
  after(() => rmSync(tmp, { recursive: true, force: true }));

  // The drawing the CLI's JSON describes: the input points, the segmentation's labels, the segments or planes.
  const drawingOf = (json, points) => ({
    dim: 3, points, labels: Int32Array.from(json.segmentation.labels),
    segments: new Float64Array((json.vectorization.segments ?? []).flatMap((s) => s.coordinates)),
    ...(json.vectorization.planes ? { planes: json.vectorization.planes.map((p) => p.polygon) } : {}),
  });

  test('a ring with ITLS segments from a camera: the bytes of toTikz({dim: 3}, {camera})', () => {
    const args = [...BIN, '--ring', '1', '-m', 'itls'];
    const json = JSON.parse(rtl(args).out);
    const r = rtl([...args, '-f', 'tikz', '--dim', '3', '--camera', '50,1,-1,-1']);
    assert.equal(r.code, 0, r.err);
    const points = cloud.ring(1);
    assert.ok(json.vectorization.segments.length >= 5, `segments: ${json.vectorization.segments.length}`);
    const expected = pkg.toTikz(drawingOf(json, points), { standalone: false, camera: { fov: 50, direction: [1, -1, -1] } });
    assert.equal(r.out, expected);
    assert.match(r.out, /^\\begin\{tikzpicture\}[\s\S]*\\end\{tikzpicture\}\s*$/);
    // One dot per return of the ring, in the colours of its clusters (10 palette colours at most).
    const returns = json.returns;
    assert.ok(returns > 1000, `returns: ${returns}`);
    assert.equal((r.out.match(/^\\Mark[A-Z]+\{/gm) ?? []).length, returns);
    const colours = new Set(json.segmentation.labels.filter((l) => l >= 0).map((l) => l % 10)).size;
    assert.equal((r.out.match(/\\definecolor\{Color[A-Z]+\}\{HTML\}/g) ?? []).length, colours);
    // The camera is applied: the default view writes other coordinates, a field of view alone yet others.
    const plain = rtl([...args, '-f', 'tikz', '--dim', '3']).out;
    assert.equal(plain, pkg.toTikz(drawingOf(json, points), { standalone: false }));
    assert.notEqual(plain, r.out);
    const fov = rtl([...args, '-f', 'tikz', '--dim', '3', '--camera', '30']).out;
    assert.equal(fov, pkg.toTikz(drawingOf(json, points), { standalone: false, camera: { fov: 30 } }));
    assert.notEqual(fov, plain);
  });

  test('AFTLS planes of a column as a standalone document that pdflatex compiles', () => {
    const args = [...BIN, '--column', '5', '-m', 'aftls', '--primitive', 'plane'];
    const json = JSON.parse(rtl(args).out);
    assert.ok(json.vectorization.planes.length >= 1);
    const out = join(tmp, 'planes.tex');
    const r = rtl([...args, '-f', 'tikz', '--dim', '3', '--standalone', '--camera', '60,0,1,-1', '-o', out]);
    assert.equal(r.code, 0, r.err);
    const tex = readFileSync(out, 'utf8');
    assert.equal(tex, pkg.toTikz(drawingOf(json, cloud.column(5)), { camera: { fov: 60, direction: [0, 1, -1] } }));
    assert.match(tex, /^\\documentclass[\s\S]*\\end\{document\}\s*$/);
    assert.match(tex, /fill=Color[A-Z]+!45/, 'a plane is a filled face');
    const c = spawnSync('pdflatex', ['-interaction=nonstopmode', '-halt-on-error', 'planes.tex'], { cwd: tmp, encoding: 'utf8', timeout: 60000 });
    assert.equal(c.status, 0, c.stdout.slice(-1500));
    assert.match(readFileSync(join(tmp, 'planes.log'), 'utf8'), /Output written on planes\.pdf \(1 page/);
  });

  const bad = [
    [[...BIN, '--fit', '-f', 'svg', '--dim', '3'], 2, /--dim 3 draws TikZ only: pass --format tikz/],
    [[...BIN, '--fit', '--dim', '3'], 2, /--dim 3 draws TikZ only/],
    [[...BIN, '--fit', '-f', 'tikz', '--dim', '4'], 2, /--dim must be 2 or 3, got "4"/],
    [[...BIN, '--fit', '-f', 'tikz', '--camera', '60'], 2, /--camera applies to --dim 3 only/],
    [[...BIN, '--fit', '-f', 'tikz', '--dim', '3', '--camera', '0'], 2, /field of view must be in \(0, 179\]/],
    [[...BIN, '--fit', '-f', 'tikz', '--dim', '3', '--camera', '60,0,0,0'], 2, /direction must not be zero/],
    [[...BIN, '--fit', '-f', 'tikz', '--dim', '3', '--camera', '60,1'], 2, /--camera must be FOV or FOV,DX,DY,DZ/],
    [[...BIN, '--fit', '-f', 'tikz', '--dim', '3', '--camera', '60,x,1,1'], 2, /--camera must be FOV or FOV,DX,DY,DZ/],
    [['tests/data/intel.log', '--fit', '-f', 'tikz', '--dim', '3'], 1, /intel\.log: --dim 3 draws 3D points, the input has 2D points/],
    [[...BIN, '--fit', '-f', 'tikz'], 2, /draws 2D data only; use --format json or --format tikz --dim 3/],
  ];
  for (const [args, code, message] of bad) {
    test(`fails clearly: rtl ${args.join(' ')}`, () => {
      const r = rtl(args);
      assert.equal(r.code, code, r.err);
      assert.match(r.err, message);
      assert.equal(r.out, '');
    });
  }

  test('--help documents --dim and --camera', () => {
    const r = rtl(['--help']);
    assert.match(r.out, /--dim D +2 \(default\) \| 3/);
    assert.match(r.out, /--camera F\[,X,Y,Z\]/);
  });

  test('a CSV of x,y,z points draws in 3D too', () => {
    const f = join(tmp, 'wall.csv');
    const rows = [];
    for (let i = 0; i < 40; i++) rows.push(`${(i * 0.05).toFixed(2)},${i % 2 ? 0.01 : -0.01},${(1 + 0.02 * i).toFixed(2)}`);
    writeFileSync(f, rows.join('\n') + '\n');
    const json = JSON.parse(rtl([f, '-m', 'itls']).out);
    const r = rtl([f, '-m', 'itls', '-f', 'tikz', '--dim', '3']);
    assert.equal(r.code, 0, r.err);
    const points = new Float64Array(rows.flatMap((l) => l.split(',').map(Number)));
    assert.equal(r.out, pkg.toTikz(drawingOf(json, points), { standalone: false }));
    assert.equal((r.out.match(/^\\Mark[A-Z]+\{/gm) ?? []).length, 40);
  });
});
