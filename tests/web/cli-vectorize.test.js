// bin/rtl.js with the package's vectorizers: a known L shape into its two sides with every method, per-cluster
// vectorization of a real scan (the same segments as vectorize() called directly), and SVG/TikZ output.
import { after, before, describe, test } from 'node:test';
import assert from 'node:assert/strict';
import { mkdtempSync, readFileSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import init from 'rtl-wasm';
import { loadLog, runCli as rtl, scanPoints } from './helpers.js';

describe('rtl CLI: vectorization', { timeout: 120000 }, () => {
  let tmp, pkg;
  before(async () => { tmp = mkdtempSync(join(tmpdir(), 'rtl-cli-')); pkg = await init(); });
  after(() => rmSync(tmp, { recursive: true, force: true }));

  test('a noise-free L-shaped CSV becomes its two sides, meeting at the corner, with every method', () => {
    const rows = ['x,y'];
    for (let i = 0; i <= 20; i++) rows.push(`${(i * 0.1).toFixed(2)},0`);
    for (let i = 1; i <= 15; i++) rows.push(`2,${(i * 0.1).toFixed(2)}`);
    const csv = join(tmp, 'l.csv');
    writeFileSync(csv, rows.join('\n') + '\n');
    for (const method of ['ftls', 'aftls', 'dp', 'rw']) {
      const r = rtl([csv, '-m', method, '--sigma', '0.01', '--epsilon', '0.01']);
      assert.equal(r.code, 0, `${method}: ${r.err}`);
      const j = JSON.parse(r.out);
      assert.equal(j.vectorization.method, method);
      const segs = j.vectorization.segments;
      assert.equal(segs.length, 2, `${method}: ${JSON.stringify(segs)}`);
      const near = (a, b) => Math.hypot(a[0] - b[0], a[1] - b[1]) < 1e-6;
      assert.ok(near(segs[0].coordinates.slice(0, 2), [0, 0]), `${method} start ${segs[0].coordinates}`);
      assert.ok(near(segs[0].coordinates.slice(2, 4), [2, 0]), `${method} corner ${segs[0].coordinates}`);
      assert.ok(near(segs[1].coordinates.slice(0, 2), [2, 0]), `${method} corner ${segs[1].coordinates}`);
      assert.ok(near(segs[1].coordinates.slice(2, 4), [2, 1.5]), `${method} end ${segs[1].coordinates}`);
      for (const s of segs) assert.ok(s.rms < 1e-6, `${method}: rms ${s.rms}`);
      assert.equal(segs[0].cluster, null);
    }
  });

  test('-s -m vectorizes each cluster of a real scan exactly as vectorize() does', () => {
    const r = rtl(['tests/data/intel.log', '--scan', '12', '-s', '-m', 'ftls', '--sigma', '0.02', '--delta', '0.2']);
    assert.equal(r.code, 0, r.err);
    const j = JSON.parse(r.out);
    const { segments: got, failed: gotFailed, ...meta } = j.vectorization;
    assert.deepEqual(meta, { method: 'ftls', primitive: 'line', sigma: 0.02, delta: 0.2 });
    const scan = loadLog('intel')[12];
    const points = scanPoints(scan);
    const expected = [], failed = [];
    pkg.segment(points).clusters.forEach((c, k) => {
      if (c.indices.length < 3) return;
      const xy = new Float64Array(2 * c.indices.length);
      c.indices.forEach((i, q) => { xy[2 * q] = points[2 * i]; xy[2 * q + 1] = points[2 * i + 1]; });
      const v = pkg.vectorize(xy, { method: 'ftls', sigma: 0.02, delta: 0.2 });
      if (!v.ok) failed.push(k);
      for (let q = 0; q < v.count; q++) {
        expected.push({ cluster: k, coordinates: Array.from(v.segments.subarray(4 * q, 4 * q + 4)), rms: v.rms[q] });
      }
    });
    assert.deepEqual(gotFailed, failed);
    assert.ok(got.length >= 2);
    assert.equal(got.length, expected.length);
    got.forEach((s, q) => {
      assert.equal(s.cluster, expected[q].cluster);
      s.coordinates.forEach((x, d) => assert.ok(Math.abs(x - expected[q].coordinates[d]) < 1e-9));
      assert.ok(Math.abs(s.rms - expected[q].rms) < 1e-9);
      assert.ok(s.rms <= 0.02 + 1e-9, `sigma bound: ${s.rms}`);
      const members = j.segmentation.clusters[s.cluster];
      assert.ok(members.includes(s.indices[0]) && members.includes(s.indices[1]), 'index range inside its cluster');
    });
  });

  test('clusters the vectorizer reports failure on are listed, with a warning, not dropped silently', () => {
    const r = rtl(['tests/data/csail.log', '--scan', '12', '-s', '-m', 'aftls']);
    assert.equal(r.code, 0, r.err);
    const j = JSON.parse(r.out);
    const scan = loadLog('csail')[12];
    const points = scanPoints(scan);
    const failed = [];
    pkg.segment(points).clusters.forEach((c, k) => {
      if (c.indices.length < 3) return;
      const xy = new Float64Array(2 * c.indices.length);
      c.indices.forEach((i, q) => { xy[2 * q] = points[2 * i]; xy[2 * q + 1] = points[2 * i + 1]; });
      if (!pkg.vectorize(xy, { method: 'aftls' }).ok) failed.push(k);
    });
    assert.deepEqual(j.vectorization.failed, failed);
    for (const s of j.vectorization.segments) assert.ok(!failed.includes(s.cluster));
    if (failed.length) assert.match(r.err, new RegExp(`warning: aftls reported failure on ${failed.length} cluster\\(s\\)`));
    else assert.equal(r.err, '');
  });

  test('segments drawn as SVG (stdout) and as a standalone TikZ document (-o)', () => {
    let r = rtl(['tests/data/intel.log', '-s', '-m', 'dp', '--epsilon', '0.05', '-f', 'svg']);
    assert.equal(r.code, 0, r.err);
    const n = JSON.parse(rtl(['tests/data/intel.log', '-s', '-m', 'dp', '--epsilon', '0.05']).out).vectorization.segments.length;
    assert.match(r.out, /^<svg[\s>]/);
    assert.equal(r.out.match(/<line /g).length, n);
    const out = join(tmp, 'scan.tex');
    r = rtl(['tests/data/csail.log', '--scan', '1', '-m', 'itls', '-f', 'tikz', '--standalone', '-o', out]);
    assert.equal(r.code, 0, r.err);
    assert.equal(r.out, '');
    assert.match(readFileSync(out, 'utf8'), /^\\documentclass[\s\S]*\\begin\{tikzpicture\}[\s\S]*\\end\{document\}\s*$/);
  });

  test('3D: lines and planes through a LiDAR ring; planes need aftls', () => {
    const r = rtl(['tests/data/rellis3d-os1-4x2048.bin', '--beams', '4', '--ring', '0', '-s', '--upper', '1', '-m', 'ftls', '--sigma', '0.05']);
    assert.equal(r.code, 0, r.err);
    const j = JSON.parse(r.out);
    assert.equal(j.dim, 3);
    assert.ok(j.vectorization.segments.length >= 1);
    for (const s of j.vectorization.segments) assert.equal(s.coordinates.length, 6);
    // Planes (AFTLS) through one ring: unit normals, polygon vertices on their plane, ranges covering the ring in order.
    const p = rtl(['tests/data/rellis3d-os1-4x2048.bin', '--beams', '4', '--ring', '0', '-m', 'aftls', '--primitive', 'plane']);
    assert.equal(p.code, 0, p.err);
    const pj = JSON.parse(p.out);
    assert.equal(pj.vectorization.primitive, 'plane');
    const planes = pj.vectorization.planes;
    assert.ok(planes.length >= 1);
    let next = 0;
    for (const pl of planes) {
      const [a, b, c, d] = pl.params;
      assert.ok(Math.abs(Math.hypot(a, b, c) - 1) < 1e-9, 'unit normal');
      assert.ok(pl.polygon.length >= 9 && pl.polygon.length % 3 === 0);
      for (let i = 0; i < pl.polygon.length; i += 3) {
        assert.ok(Math.abs(a * pl.polygon[i] + b * pl.polygon[i + 1] + c * pl.polygon[i + 2] - d) < 1e-6, 'vertex on its plane');
      }
      assert.ok(pl.indices[0] >= next && pl.indices[1] >= pl.indices[0], `ranges in order: ${pl.indices}`);
      next = pl.indices[1];
      assert.ok(Number.isFinite(pl.rms) && pl.rms >= 0);
    }
    const bad = rtl(['tests/data/rellis3d-os1-4x2048.bin', '--beams', '4', '-m', 'dp', '--primitive', 'plane']);
    assert.equal(bad.code, 2);
    assert.match(bad.err, /--primitive plane needs --vectorize aftls/);
  });
});
