// bin/rtl.js with the package's vectorizers: the scan is segmented first (unless --no-segment), each cluster is
// vectorized exactly as vectorize() does it, the JSON's indices are vectorize()'s half-open chain indices per cluster,
// FTLS/AFTLS run in split mode (breaks listed) unless --strict (failures listed with their numbers), and SVG/TikZ
// titles name the scan, the method and its parameters.
import { after, before, describe, test } from 'node:test';
import assert from 'node:assert/strict';
import { mkdtempSync, readFileSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import init from 'rtl-wasm';
import { DATA, loadLog, runCli as rtl, scanPoints } from './helpers.js';

// The chain of a cluster: its points in cluster order (x,y interleaved), as the CLI hands it to vectorize().
function chainOf(points, members, dim = 2) {
  const xy = new Float64Array(dim * members.length);
  members.forEach((i, q) => { for (let d = 0; d < dim; d++) xy[dim * q + d] = points[dim * i + d]; });
  return xy;
}

// RMS distance of chain points [begin, end) from the line a x + b y + c = 0.
function rmsFromLine(xy, [begin, end], [a, b, c]) {
  let s = 0;
  for (let q = begin; q < end; q++) s += (a * xy[2 * q] + b * xy[2 * q + 1] + c) ** 2;
  return Math.sqrt(s / (end - begin));
}

const csvOf = (xy) => ['x,y', ...Array.from({ length: xy.length / 2 }, (_, q) => `${xy[2 * q]},${xy[2 * q + 1]}`)].join('\n') + '\n';

describe('rtl CLI: vectorization', { timeout: 180000 }, () => {
  let tmp, pkg;
  before(async () => { tmp = mkdtempSync(join(tmpdir(), 'rtl-cli-')); pkg = await init(); });
  after(() => rmSync(tmp, { recursive: true, force: true }));

  test('an L-shaped CSV is segmented first (one cluster), then becomes its two sides with every method', () => {
    const xy = [];
    for (let i = 0; i <= 40; i++) xy.push(i * 0.05, 0);
    for (let i = 1; i <= 30; i++) xy.push(2, i * 0.05);
    const csv = join(tmp, 'l.csv');
    writeFileSync(csv, csvOf(xy));
    for (const method of ['ftls', 'aftls', 'dp', 'rw']) {
      // sigma 1 mm: a range that takes in the first point past the corner (5 cm off its line) misses it.
      const r = rtl([csv, '-m', method, '--sigma', '0.001', '--epsilon', '0.01']);
      assert.equal(r.code, 0, `${method}: ${r.err}`);
      const j = JSON.parse(r.out);
      assert.deepEqual(j.segmentation.clusters, [Array.from({ length: 71 }, (_, i) => i)], 'one cluster: the default segments first');
      assert.equal(j.vectorization.method, method);
      const segs = j.vectorization.segments;
      assert.equal(segs.length, 2, `${method}: ${JSON.stringify(segs)}`);
      const near = (a, b) => Math.hypot(a[0] - b[0], a[1] - b[1]) < 1e-6;
      assert.ok(near(segs[0].coordinates.slice(0, 2), [0, 0]), `${method} start ${segs[0].coordinates}`);
      assert.ok(near(segs[0].coordinates.slice(2, 4), [2, 0]), `${method} corner ${segs[0].coordinates}`);
      assert.ok(near(segs[1].coordinates.slice(0, 2), [2, 0]), `${method} corner ${segs[1].coordinates}`);
      assert.ok(near(segs[1].coordinates.slice(2, 4), [2, 1.5]), `${method} end ${segs[1].coordinates}`);
      // Half-open chain indices: the first range starts at 0, the last ends at the chain's length (71 points);
      // TLS ranges are consecutive, dp/rw spans share their kept point; every indexed point lies on its line.
      assert.equal(segs[0].indices[0], 0);
      assert.equal(segs[1].indices[1], 71);
      assert.equal(segs[1].indices[0], segs[0].indices[1] - (['dp', 'rw'].includes(method) ? 1 : 0), `${method}: ${segs.map((s) => s.indices)}`);
      for (const s of segs) {
        assert.equal(s.cluster, 0);
        assert.ok(rmsFromLine(xy, s.indices, s.params) < 1e-6, `${method}: points ${s.indices} on their line`);
        assert.ok(s.rms < 1e-6, `${method}: rms ${s.rms}`);
      }
      // --no-segment: the raw chain (here the same points) as one unnamed cluster, the same segments.
      const raw = JSON.parse(rtl([csv, '--no-segment', '-m', method, '--sigma', '0.001', '--epsilon', '0.01']).out);
      assert.equal(raw.segmentation, undefined);
      assert.deepEqual(raw.chain, j.segmentation.clusters[0]);
      assert.deepEqual(raw.vectorization.segments, segs.map((s) => ({ ...s, cluster: null })));
    }
  });

  test('each cluster of a real scan is vectorized exactly as vectorize() does it (segments, indices, polylines, breaks)', () => {
    for (const method of ['ftls', 'aftls', 'itls']) {
      const r = rtl(['tests/data/intel.log', '--scan', '12', '-m', method, '--sigma', '0.02', '--delta', '0.2']);
      assert.equal(r.code, 0, r.err);
      const j = JSON.parse(r.out);
      const { segments: got, failed, breaks, ...meta } = j.vectorization;
      const tls2 = method !== 'itls';
      assert.deepEqual(meta, { method, primitive: 'line', sigma: 0.02, ...(tls2 ? { delta: 0.2, mode: 'split' } : {}) });
      const points = scanPoints(loadLog('intel')[12]);
      const seg = pkg.segment(points, { step: 2, lowerBound: 0.1, upperBound: 0.5 });
      assert.deepEqual(j.segmentation.clusters, seg.clusters.map((c) => Array.from(c.indices)));
      const expected = [], expectedBreaks = [], expectedFailed = [];
      let vectorized = 0;
      seg.clusters.forEach((c, k) => {
        if (c.indices.length < 3) return;
        vectorized++;
        const v = pkg.vectorize(chainOf(points, c.indices), { method, sigma: 0.02, delta: 0.2 });
        if (!v.ok) expectedFailed.push({ cluster: k, boundary: v.failure.boundary, delta: v.failure.delta, message: v.failure.message });
        for (const b of v.breaks) expectedBreaks.push({ cluster: k, boundary: b.boundary, crossingDistance: b.crossingDistance, delta: b.delta });
        for (let q = 0; q < v.count; q++) {
          expected.push({ cluster: k, indices: [v.indices[2 * q], v.indices[2 * q + 1]], coordinates: Array.from(v.segments.subarray(4 * q, 4 * q + 4)), rms: v.rms[q] });
        }
      });
      // Split mode fails only where no partition into ranges within sigma exists at all (the package's report).
      assert.deepEqual(failed.map(({ crossingDistance, ...f }) => f), expectedFailed);
      assert.ok(failed.length < vectorized, `${method}: ${failed.length} of ${vectorized} clusters failed`);
      if (failed.length) assert.match(r.err, new RegExp(`^rtl: warning: ${method} found no segments for ${failed.length} cluster\\(s\\)`));
      else assert.equal(r.err, '');
      assert.equal(got.length, expected.length);
      got.forEach((s, q) => {
        assert.equal(s.cluster, expected[q].cluster);
        assert.deepEqual(s.indices, expected[q].indices, `${method} segment ${q}: the API's indices`);
        s.coordinates.forEach((x, d) => assert.ok(Math.abs(x - expected[q].coordinates[d]) < 1e-9));
        assert.ok(Math.abs(s.rms - expected[q].rms) < 1e-9);
        assert.ok(s.rms <= 0.02 + 1e-9, `sigma bound: ${s.rms}`);
        // The indices address the cluster's chain: its points [begin, end) are the ones fitted (the same RMS).
        const chain = chainOf(points, j.segmentation.clusters[s.cluster]);
        // (compared squared: the library's mean squared residual comes from prefix sums, exact to ~1e-14 m^2, so
        // the RMS of an exactly fitted 2-point range can read 1e-7 m where the direct sum gives 1e-14 m)
        assert.ok(Math.abs(rmsFromLine(chain, s.indices, s.params) ** 2 - s.rms ** 2) < 1e-12, `${method} segment ${q}: rms of chain ${s.indices}`);
      });
      assert.equal(breaks.length, expectedBreaks.length);
      breaks.forEach((b, q) => {
        assert.equal(b.cluster, expectedBreaks[q].cluster);
        assert.equal(b.boundary, expectedBreaks[q].boundary);
        assert.ok(Math.abs(b.crossingDistance - expectedBreaks[q].crossingDistance) < 1e-9);
        assert.ok(b.crossingDistance > b.delta, 'a break is a corner that could not be met within delta');
      });
      if (tls2) {
        // A new polyline starts at each break (segment numbering per cluster).
        const perCluster = new Map();
        for (const s of got) perCluster.set(s.cluster, Math.max(perCluster.get(s.cluster) ?? 0, s.polyline));
        for (const [k, last] of perCluster) assert.equal(last, breaks.filter((b) => b.cluster === k).length, `cluster ${k} polylines`);
      }
    }
  });

  test('--strict: clusters FTLS/AFTLS cannot vectorize within delta are listed with boundary, crossing distance and delta', () => {
    for (const [log, scan, method] of [['csail', 12, 'aftls'], ['intel', 12, 'ftls']]) {
      const r = rtl([`tests/data/${log}.log`, '--scan', String(scan), '-m', method, '--strict']);
      assert.equal(r.code, 0, r.err);
      const j = JSON.parse(r.out);
      assert.equal(j.vectorization.mode, 'strict');
      const points = scanPoints(loadLog(log)[scan]);
      const failed = [];
      j.segmentation.clusters.forEach((c, k) => {
        if (c.length < 3) return;
        const v = pkg.vectorize(chainOf(points, c), { method, split: false });
        if (!v.ok) failed.push({ cluster: k, ...v.failure });
      });
      assert.equal(j.vectorization.failed.length, failed.length);
      j.vectorization.failed.forEach((f, q) => {
        assert.equal(f.cluster, failed[q].cluster);
        assert.equal(f.boundary, failed[q].boundary);
        if (failed[q].crossingDistance === Infinity) assert.equal(f.crossingDistance, null, 'parallel lines: null (JSON has no Infinity)');
        else assert.ok(Math.abs(f.crossingDistance - failed[q].crossingDistance) < 1e-9 && f.crossingDistance > f.delta);
        assert.equal(f.delta, 0.3);
        assert.match(f.message, /^vectorize:/);
      });
      for (const s of j.vectorization.segments) assert.ok(!failed.some((f) => f.cluster === s.cluster));
      assert.deepEqual(j.vectorization.breaks, []);
      assert.match(r.err, new RegExp(`^rtl: warning: ${method} found no segments for ${failed.length} cluster\\(s\\)`));
      // The default (split mode) vectorizes every one whose failing corner has crossing lines: it breaks there.
      const split = JSON.parse(rtl([`tests/data/${log}.log`, '--scan', String(scan), '-m', method]).out).vectorization;
      const crossing = failed.filter((f) => Number.isFinite(f.crossingDistance));
      assert.ok(crossing.length >= 1, `${log} scan ${scan}: ${crossing.length} failures at a crossing corner`);
      for (const f of crossing) {
        assert.ok(split.segments.some((s) => s.cluster === f.cluster), `cluster ${f.cluster} has segments`);
        assert.ok(split.breaks.some((b) => b.cluster === f.cluster), `cluster ${f.cluster} breaks`);
        assert.ok(!split.failed.some((g) => g.cluster === f.cluster));
      }
    }
  });

  test("the issue's noise-free L that strict FTLS rejects: split mode covers it, --strict names the failing corner", () => {
    const csv = join(tmp, 'issue-l.csv');
    writeFileSync(csv, csvOf([0, 0, 1, 0, 2, 0, 3, 0, 3, 1, 3, 2, 3, 3]));
    for (const method of ['ftls', 'aftls']) {
      const r = rtl([csv, '--raw', '-m', method]);
      assert.equal(r.code, 0, r.err);
      const v = JSON.parse(r.out).vectorization;
      assert.deepEqual(v.failed, []);
      assert.ok(v.segments.length >= 1);
      assert.equal(v.segments[0].indices[0], 0);
      assert.equal(v.segments.at(-1).indices[1], 7, 'the segments cover the whole chain');
      const s = rtl([csv, '--raw', '-m', method, '--strict']);
      assert.equal(s.code, 0, s.err);
      const f = JSON.parse(s.out).vectorization;
      assert.deepEqual(f.segments, []);
      assert.equal(f.failed.length, 1);
      assert.equal(f.failed[0].cluster, null);
      assert.ok(f.failed[0].boundary > 0 && f.failed[0].boundary < 7, `boundary ${f.failed[0].boundary}`);
      assert.ok(f.failed[0].crossingDistance > 0.3);
      assert.match(s.err, new RegExp(`warning: ${method} found no segments for the chain`));
    }
  });

  test('--max-range: ranges at or beyond it are gaps; by default the log\'s own no-return value (reported in "source")', () => {
    const text = readFileSync(join(DATA, 'csail.log'), 'utf8');
    const scans = loadLog('csail');
    const { maxRange: detected, maxRangeSource } = pkg.readCarmenLog(text)[5];
    assert.ok(Number.isFinite(detected) && detected > 0);
    const def = JSON.parse(rtl(['tests/data/csail.log', '--scan', '5']).out);
    assert.ok(Math.abs(def.source.maxRange - detected) < 1e-9, `${def.source.maxRange} vs ${detected}`);
    assert.equal(def.source.maxRangeSource, maxRangeSource);
    const returns = scans[5].ranges.filter((x) => x > 0 && x < detected).length;
    assert.equal(def.returns, returns);
    const r = rtl(['tests/data/csail.log', '--scan', '5', '--max-range', '4', '-m', 'dp', '-f', 'svg']);
    assert.equal(r.code, 0, r.err);
    assert.match(r.out, />csail\.log scan 5, max range 4 m; CAR step 2/);
    const j = JSON.parse(rtl(['tests/data/csail.log', '--scan', '5', '--max-range', '4']).out);
    assert.equal(j.source.maxRange, 4);
    assert.equal(j.source.maxRangeSource, pkg.readCarmenLog(text, { maxRange: 4 })[5].maxRangeSource);
    assert.notEqual(j.source.maxRangeSource, maxRangeSource);
    const near = scans[5].ranges.map((x) => x > 0 && x < 4);
    assert.equal(j.returns, near.filter(Boolean).length);
    assert.ok(j.returns < def.returns, `${j.returns} < ${def.returns}`);
    j.segmentation.labels.forEach((l, i) => assert.equal(l >= 0, near[i], `beam ${i}`));
  });

  test('segments drawn as SVG (stdout) and as a standalone TikZ document (-o), titled with scan, method and parameters', () => {
    let r = rtl(['tests/data/intel.log', '-m', 'dp', '--epsilon', '0.05', '-f', 'svg']);
    assert.equal(r.code, 0, r.err);
    const n = JSON.parse(rtl(['tests/data/intel.log', '-m', 'dp', '--epsilon', '0.05']).out).vectorization.segments.length;
    assert.match(r.out, /^<\?xml[^>]*>\n<svg[\s>]/);
    assert.equal(r.out.match(/<line /g).length, n);
    assert.match(r.out, />intel\.log scan 0; CAR step 2, bounds 0\.1-0\.5 m; DP epsilon 0\.05 m; \d+\.\d x \d+\.\d m<\/text>/);
    const out = join(tmp, 'scan.tex');
    r = rtl(['tests/data/csail.log', '--scan', '1', '-m', 'aftls', '--sigma', '0.02', '-f', 'tikz', '--standalone', '-o', out]);
    assert.equal(r.code, 0, r.err);
    assert.equal(r.out, '');
    const tex = readFileSync(out, 'utf8');
    assert.match(tex, /^\\documentclass[\s\S]*\\begin\{tikzpicture\}[\s\S]*\\end\{document\}\s*$/);
    assert.match(tex, /csail\.log scan 1; CAR step 2, bounds 0\.1-0\.5 m; AFTLS sigma 0\.02 m, delta 0\.3 m, split; /);
    assert.doesNotMatch(tex, /tests\/data/, 'the title names the scan, not the path');
    r = rtl(['tests/data/csail.log', '--scan', '1', '--no-segment', '-m', 'itls', '-f', 'svg']);
    assert.match(r.out, />csail\.log scan 1; not segmented; ITLS sigma 0\.03 m; /);
  });

  test('3D: lines per cluster of a LiDAR ring; planes (aftls only) through the raw ring with consecutive chain ranges', () => {
    const r = rtl(['tests/data/rellis3d-os1-4x2048.bin', '--beams', '4', '--ring', '0', '--upper', '1', '-m', 'ftls', '--sigma', '0.05']);
    assert.equal(r.code, 0, r.err);
    const j = JSON.parse(r.out);
    assert.equal(j.dim, 3);
    assert.ok(j.vectorization.segments.length >= 1);
    for (const s of j.vectorization.segments) {
      assert.equal(s.coordinates.length, 6);
      assert.ok(s.indices[0] < s.indices[1] && s.indices[1] <= j.segmentation.clusters[s.cluster].length, `${s.indices}`);
    }
    const p = rtl(['tests/data/rellis3d-os1-4x2048.bin', '--beams', '4', '--ring', '0', '--no-segment', '-m', 'aftls', '--primitive', 'plane']);
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
      assert.equal(pl.indices[0], next, `consecutive ranges: ${pl.indices}`);
      assert.ok(pl.indices[1] > pl.indices[0]);
      next = pl.indices[1];
      assert.ok(Number.isFinite(pl.rms) && pl.rms >= 0);
    }
    assert.equal(next, pj.chain.length, 'the planes cover the chain');
    const bad = rtl(['tests/data/rellis3d-os1-4x2048.bin', '--beams', '4', '-m', 'dp', '--primitive', 'plane']);
    assert.equal(bad.code, 2);
    assert.match(bad.err, /--primitive plane needs --vectorize aftls/);
  });
});
