// bin/rtl.js with the package's segmenter: clusters of a CARMEN scan and of a LiDAR ring, the same as segment()
// called directly, the bounds' effect, per-cluster line fits, and coloured clusters in the SVG.
import { after, before, describe, test } from 'node:test';
import assert from 'node:assert/strict';
import { mkdtempSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import init from 'rtl-wasm';
import { isReturn, loadLog, returnsOf, runCli as rtl, sameLine, scanPoints, streamClusters, tlsFit, xyOf } from './helpers.js';

describe('rtl CLI: segmentation', { timeout: 120000 }, () => {
  let tmp, pkg;
  const scans = loadLog('intel');
  before(async () => { tmp = mkdtempSync(join(tmpdir(), 'rtl-cli-')); pkg = await init(); });
  after(() => rmSync(tmp, { recursive: true, force: true }));

  test('segments a CARMEN scan (the default action): clusters cover every return, gaps stay unlabelled', () => {
    const r = rtl(['tests/data/intel.log', '--scan', '2']);
    assert.equal(r.code, 0, r.err);
    const j = JSON.parse(r.out);
    const scan = scans[2];
    assert.equal(j.points, 180);
    const { labels, clusters, ...params } = j.segmentation;
    assert.deepEqual(params, { segmenter: 'car', step: 2, lowerBound: 0.1, upperBound: 0.5 });
    assert.equal(labels.length, 180);
    assert.equal(clusters.flat().length, j.returns);
    labels.forEach((l, i) => assert.equal(l >= 0, isReturn(scan.ranges[i]), `beam ${i}`));
    clusters.forEach((c, ci) => c.forEach((i) => assert.equal(labels[i], ci)));
    assert.ok(clusters.length > 1);
    assert.equal(j.vectorization, undefined);
    assert.equal(j.fits, undefined);
    // The same labels as segment() called directly on the scan's points.
    const points = scanPoints(scan);
    assert.deepEqual(labels, Array.from(pkg.segment(points, { step: 2, lowerBound: 0.1, upperBound: 0.5 }).labels));
  });

  test('the default step (2) links consecutive points; step 1 links nothing (CAR compares up to step-1 previous points)', () => {
    for (const [log, k] of [['intel', 7], ['csail', 4]]) {
      const scan = loadLog(log)[k];
      const points = scanPoints(scan);
      const { labels, clusters } = JSON.parse(rtl([`tests/data/${log}.log`, '--scan', String(k)]).out).segmentation;
      let linked = 0;
      for (let i = 0; i + 1 < scan.n; i++) {
        if (!isReturn(scan.ranges[i]) || !isReturn(scan.ranges[i + 1])) continue;
        // Closer than the lower bound of the threshold: always the same cluster.
        if (Math.hypot(points[2 * i + 2] - points[2 * i], points[2 * i + 3] - points[2 * i + 1]) < 0.1) {
          assert.equal(labels[i + 1], labels[i], `${log} scan ${k}: beams ${i} and ${i + 1}`);
          linked++;
        }
      }
      assert.ok(linked > 50, `${log}: ${linked} close consecutive pairs`);
      assert.ok(clusters.length < linked, `${clusters.length} clusters`);
      const one = JSON.parse(rtl([`tests/data/${log}.log`, '--scan', String(k), '--step', '1']).out).segmentation;
      assert.equal(one.clusters.length, returnsOf(scan).length, 'step 1: every return is its own cluster');
      assert.ok(one.clusters.every((c) => c.length === 1));
    }
  });

  test('--segmenter ia: the clusters of StreamSegmenter fed with the scan, as point index sets', () => {
    const r = rtl(['tests/data/csail.log', '--scan', '6', '--segmenter', 'ia', '--scaling', '0.08', '--step', '4']);
    assert.equal(r.code, 0, r.err);
    const j = JSON.parse(r.out);
    const { labels, clusters, ...params } = j.segmentation;
    assert.deepEqual(params, { segmenter: 'ia', step: 4, lowerBound: 0.1, upperBound: 0.5, scaling: 0.08 });
    const scan = loadLog('csail')[6];
    const points = scanPoints(scan);
    const ref = streamClusters(pkg, points, { step: 4, lowerBound: 0.1, upperBound: 0.5, scaling: 0.08 });
    assert.deepEqual(clusters.map((c) => c.length), ref.map((c) => c.length / 2));
    clusters.forEach((c, k) => c.forEach((i, q) => {
      assert.equal(labels[i], k);
      assert.ok(Math.abs(points[2 * i] - ref[k][2 * q]) < 1e-9 && Math.abs(points[2 * i + 1] - ref[k][2 * q + 1]) < 1e-9, `cluster ${k} point ${q}`);
    }));
    assert.equal(clusters.flat().length, j.returns, 'after the flush every return is in a closed cluster');
    const bad = rtl(['tests/data/csail.log', '--scaling', '0.1']);
    assert.equal(bad.code, 2);
    assert.match(bad.err, /--scaling applies to --segmenter ia only/);
  });

  test('tighter bounds cut more clusters, a larger step fewer', () => {
    const base = JSON.parse(rtl(['tests/data/intel.log', '--scan', '2']).out).segmentation.clusters.length;
    const strict = JSON.parse(rtl(['tests/data/intel.log', '--scan', '2', '--lower', '0.02', '--upper', '0.05']).out);
    assert.deepEqual([strict.segmentation.lowerBound, strict.segmentation.upperBound], [0.02, 0.05]);
    assert.ok(strict.segmentation.clusters.length > base, `${strict.segmentation.clusters.length} vs ${base}`);
    const step4 = JSON.parse(rtl(['tests/data/intel.log', '--scan', '2', '--step', '4']).out);
    assert.ok(step4.segmentation.clusters.length < base, `${step4.segmentation.clusters.length} vs ${base}`);
  });

  test('--fit segments first and fits each cluster of at least --min-points points (-s changes nothing)', () => {
    const r = rtl(['tests/data/intel.log', '--scan', '5', '--fit', '--min-points', '10']);
    assert.equal(rtl(['tests/data/intel.log', '--scan', '5', '-s', '--fit', '--min-points', '10']).out, r.out);
    assert.equal(r.code, 0, r.err);
    const j = JSON.parse(r.out);
    const big = j.segmentation.clusters.map((c, k) => [c, k]).filter(([c]) => c.length >= 10);
    assert.ok(big.length >= 1);
    assert.deepEqual(j.fits.map((f) => f.cluster), big.map(([, k]) => k));
    for (const f of j.fits) {
      const members = j.segmentation.clusters[f.cluster];
      assert.equal(f.count, members.length);
      const ref = tlsFit(xyOf(scans[5], members));
      assert.ok(sameLine(f, ref, 1e-9), `cluster ${f.cluster}`);
      assert.ok(Math.abs(f.rms - ref.rms) < 1e-9);
    }
  });

  test('segments one ring of the organised binary scan (3D)', () => {
    const r = rtl(['tests/data/rellis3d-os1-4x2048.bin', '--beams', '4', '--ring', '1', '--upper', '1']);
    assert.equal(r.code, 0, r.err);
    const j = JSON.parse(r.out);
    assert.equal(j.dim, 3);
    assert.equal(j.segmentation.labels.length, 2048);
    assert.equal(j.segmentation.clusters.flat().length, j.returns);
    assert.ok(j.segmentation.clusters.length >= 1);
  });

  test('SVG of a segmented scan: one colour per cluster (the palette of 10 repeats), one dot per return', () => {
    const r = rtl(['tests/data/intel.log', '--scan', '2', '-f', 'svg']);
    assert.equal(r.code, 0, r.err);
    const j = JSON.parse(rtl(['tests/data/intel.log', '--scan', '2']).out), n = j.segmentation.clusters.length;
    assert.ok(n > 1);
    // the C++ writer defines one mark per colour and draws each point as a <use> of its cluster's mark
    assert.equal([...r.out.matchAll(/<g id="Mark[A-Z]+"><circle /g)].length, Math.min(n, 10));
    assert.equal((r.out.match(/<use href="#Mark[A-Z]+"/g) ?? []).length, j.returns);
    assert.match(r.out, />intel\.log scan 2; CAR step 2, bounds 0\.1-0\.5 m; \d+\.\d x \d+\.\d m<\/text>/);
    const ia = rtl(['tests/data/intel.log', '--scan', '2', '--segmenter', 'ia', '--step', '4', '--upper', '0.8', '-f', 'tikz']);
    assert.equal(ia.code, 0, ia.err);
    assert.match(ia.out, /intel\.log scan 2; IA step 4, bounds 0\.1-0\.8 m, scaling 0\.05;/);
  });
});
