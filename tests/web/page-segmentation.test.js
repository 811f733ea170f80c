// The demo page in headless Debian Chromium, segmentation: labels and gaps of a real scan, cluster colours on the
// canvas, the effect of the distance bounds, fitting a clicked cluster, and clusters in the SVG export.
import { after, before, describe, test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { join } from 'node:path';
import init from 'rtl-wasm';
import {
  PAGE_TIMEOUT as TIMEOUT, DATA, isReturn, loadLog, openDemoPage, resultsDir, sameLine, scanPoints, streamClusters,
  tlsFit, xyOf,
} from './helpers.js';

const PALETTE = [0x0072B2, 0xE69F00, 0x009E73, 0xD55E00, 0xCC79A7, 0x56B4E9, 0x8C6D1F, 0x1B7837, 0x762A83, 0x332288];

describe('demo page (web/index.html) in Chromium: segmentation', { timeout: 240000 }, () => {
  let page, problems, state, revision, settled, settledWith, close;
  const scan = loadLog('intel')[0];

  before(async () => ({ page, problems, state, revision, settled, settledWith, close } = await openDemoPage()));
  after(() => close?.());

  test('the build has segment()', async () => {
    const r = await state();
    assert.deepEqual(r.errors, []);
    assert.equal(r.features.segment, true);
  });

  test('segmentation labels every return, marks gaps, and colours the clusters on the canvas', async () => {
    const r = await state();
    const seg = r.segmentation;
    assert.equal(seg.labels.length, 180);
    seg.labels.forEach((l, i) => {
      if (isReturn(scan.ranges[i])) assert.ok(l >= 0 && l < seg.clusterCount, `beam ${i} labelled ${l}`);
      else assert.equal(l, -1, `gap beam ${i}`);
    });
    assert.equal(seg.clusterSizes.reduce((a, b) => a + b, 0), r.validCount);
    assert.ok(seg.clusterCount >= 2 && seg.clusterCount < r.validCount / 2, `${seg.clusterCount} clusters`);
    const colours = await page.evaluate(() => {
      const c = document.getElementById('canvas');
      const d = c.getContext('2d').getImageData(0, 0, c.width, c.height).data;
      const seen = new Map();
      for (let i = 0; i < d.length; i += 4) {
        const key = (d[i] << 16) | (d[i + 1] << 8) | d[i + 2];
        seen.set(key, (seen.get(key) ?? 0) + 1);
      }
      return [...seen.entries()];
    });
    // Points are drawn in their cluster's palette colour: the largest cluster's colour, and at least two colours
    // when two clusters have 10+ points (small clusters may hide under the segment lines).
    const painted = (c) => colours.some(([k, n]) => k === c && n >= 10);
    const largest = seg.clusterSizes.indexOf(seg.largest);
    assert.ok(painted(PALETTE[largest % PALETTE.length]), `largest cluster ${largest} painted`);
    const big = seg.clusterSizes.filter((n) => n >= 10).length;
    const drawn = PALETTE.filter(painted);
    assert.ok(drawn.length >= Math.min(2, big), `cluster colours on canvas: ${drawn.length}, clusters with 10+ points: ${big}`);
    assert.match(await page.textContent('#seg-count'), new RegExp(`^${seg.clusterCount} \\(`));
  });

  test('the page shows the same clusters as the package computes in Node for the same scan and settings', async () => {
    const rtl = await init();
    const points = scanPoints(scan);
    const ref = rtl.segment(points, { step: 3, lowerBound: 0.1, upperBound: 0.5 });
    const r = await state();
    assert.deepEqual(r.segmentation.labels, Array.from(ref.labels));
    assert.deepEqual(r.segmentation.clusterSizes, ref.clusters.map((c) => c.indices.length));
  });

  test('tighter distance bounds give more clusters; restoring them restores the result', async () => {
    const before = (await state()).segmentation.clusterCount;
    await page.fill('#seg-lower', '0.02');
    await page.fill('#seg-upper', '0.05');
    const strict = (await settledWith({ upperBound: 0.05, lowerBound: 0.02 })).segmentation.clusterCount;
    assert.ok(strict > before, `${strict} clusters with 2-5 cm bounds vs ${before} with defaults`);
    await page.screenshot({ path: join(resultsDir(), 'page-segmentation-strict.png') });
    // Bounds the wrong way round: the page says what to fix and keeps the last result.
    const rev = await revision();
    await page.fill('#seg-lower', '0.1');
    await page.waitForFunction(() => window.__rtl.inputError !== null && window.__rtl.inputError !== undefined, null, { timeout: TIMEOUT });
    assert.match(await page.textContent('#status'), /Check the settings: the upper bound \(0\.05 m\) is below the lower bound \(0\.1 m\)/);
    assert.equal(await page.getAttribute('#seg-upper', 'aria-invalid'), 'true');
    assert.equal(await revision(), rev);
    await page.fill('#seg-upper', '0.5');
    assert.equal((await settledWith({ upperBound: 0.5, lowerBound: 0.1 })).segmentation.clusterCount, before);
    assert.equal(await page.getAttribute('#seg-upper', 'aria-invalid'), null);
  });

  test('clicking a cluster fits its points', async () => {
    const r0 = await state();
    const largest = r0.segmentation.clusterSizes.indexOf(r0.segmentation.largest);
    const member = r0.segmentation.labels.indexOf(largest);
    const at = await page.evaluate((i) => window.__rtl.clientPoint(i), member);
    const rev = await revision();
    await page.mouse.click(at.x, at.y);
    const r = await settled(rev);
    assert.equal(r.fit.source, `cluster ${largest + 1}`);
    assert.deepEqual(r.fit.indices, r0.segmentation.labels.flatMap((l, i) => (l === largest ? [i] : [])));
    assert.ok(r.fit.rms < r0.fit.rms, `cluster fit rms ${r.fit.rms} below whole-scan ${r0.fit.rms}`);
    const ref = tlsFit(xyOf(scan, r.fit.indices));
    assert.ok(sameLine(r.fit, ref, 1e-6));
    assert.ok(Math.abs(r.fit.rms - ref.rms) < 1e-6);
    await page.screenshot({ path: join(resultsDir(), 'page-cluster-fit.png') });
  });

  test('the SVG export colours the clusters', async () => {
    const r = await state();
    const [svgDl] = await Promise.all([page.waitForEvent('download'), page.click('#dl-svg')]);
    const svg = readFileSync(await svgDl.path(), 'utf8');
    const groups = [...svg.matchAll(/<g class="cluster" data-cluster="(\d+)"/g)].map((m) => Number(m[1]));
    assert.deepEqual(groups, [...Array(r.segmentation.clusterCount).keys()]);
    // The export uses the page's cluster colours.
    const fills = [...svg.matchAll(/<g class="cluster" data-cluster="(\d+)" fill="(#[0-9a-fA-F]{6})"/g)];
    assert.equal(fills.length, groups.length);
    for (const [, k, fill] of fills) assert.equal(parseInt(fill.slice(1), 16), PALETTE[Number(k) % PALETTE.length], `cluster ${k}`);
    assert.equal(svg.match(/<circle /g).length, r.validCount);
  });

  test('the streaming (IA) segmenter gives the clusters StreamSegmenter gives in Node, as beam index sets', async () => {
    await page.selectOption('#segmenter', 'ia');
    await page.fill('#seg-scaling', '0.1');
    const r = await settledWith({ segmenter: 'ia', scaling: 0.1 });
    assert.equal(await page.isVisible('#seg-scaling'), true);
    const rtl = await init();
    const points = scanPoints(scan);
    const clusters = streamClusters(rtl, points, { step: 3, lowerBound: 0.1, upperBound: 0.5, scaling: 0.1 });
    assert.deepEqual(r.segmentation.clusterSizes, clusters.map((c) => c.length / 2));
    clusters.forEach((xy, k) => {
      const members = r.segmentation.labels.flatMap((l, i) => (l === k ? [i] : []));
      members.forEach((i, j) => {
        assert.ok(Math.abs(points[2 * i] - xy[2 * j]) < 1e-9 && Math.abs(points[2 * i + 1] - xy[2 * j + 1]) < 1e-9, `cluster ${k} point ${j}`);
      });
    });
    r.segmentation.labels.forEach((l, i) => assert.equal(l >= 0, isReturn(scan.ranges[i]), `beam ${i}`));
    await page.screenshot({ path: join(resultsDir(), 'page-ia-segmenter.png'), fullPage: true });
    await page.selectOption('#segmenter', 'car');
    await settledWith({ segmenter: 'car' });
    assert.equal(await page.isVisible('#seg-scaling'), false);
  });

  test('a LiDAR ring (RELLIS-3D, 360°) read by the package is segmented like segment() in Node on its x, y', async () => {
    await page.selectOption('#dataset', 'rellis');
    await page.waitForFunction(() => window.__rtl.dataset === 'rellis', null, { timeout: TIMEOUT });
    await page.fill('#scan', '2');
    await page.waitForFunction(() => window.__rtl.dataset === 'rellis' && window.__rtl.scanIndex === 2, null, { timeout: TIMEOUT });
    const r = await state();
    // Independent read of the binary: float32 x, y, z, intensity records, column-major, 4 beams; (0,0,0) = no return.
    const buf = readFileSync(join(DATA, 'rellis3d-os1-4x2048.bin'));
    const xy = new Float64Array(2 * 2048).fill(NaN);
    let returns = 0;
    for (let c = 0; c < 2048; c++) {
      const k = 16 * (c * 4 + 2);
      const [x, y, z] = [buf.readFloatLE(k), buf.readFloatLE(k + 4), buf.readFloatLE(k + 8)];
      if (x !== 0 || y !== 0 || z !== 0) { xy[2 * c] = x; xy[2 * c + 1] = y; returns++; }
    }
    assert.equal(r.beams, 2048);
    assert.equal(r.validCount, returns);
    assert.equal(await page.isVisible('#map-frame'), false, 'no poses, no map frame');
    const rtl = await init();
    assert.deepEqual(r.segmentation.labels, Array.from(rtl.segment(xy).labels));
    assert.match(await page.textContent('#status'), /^RELLIS-3D Ouster OS1, ring 2: \d+ clusters/);
    await page.screenshot({ path: join(resultsDir(), 'page-rellis-ring-2.png') });
  });

  test('no console errors, failed requests or page errors during the session', async () => {
    assert.deepEqual((await state()).errors, []);
    assert.deepEqual(problems, []);
  });
});
