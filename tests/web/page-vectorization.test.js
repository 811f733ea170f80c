// The demo page in headless Debian Chromium, vectorization: every method draws segments on their own clusters, and
// sigma / epsilon act as they should.
import { after, before, describe, test } from 'node:test';
import assert from 'node:assert/strict';
import { join } from 'node:path';
import init from 'rtl-wasm';
import { loadLog, openDemoPage, resultsDir, scanPoints } from './helpers.js';

describe('demo page (web/index.html) in Chromium: vectorization', { timeout: 240000 }, () => {
  let page, problems, state, revision, settled, settledWith, close;
  const scan = loadLog('intel')[0];

  before(async () => ({ page, problems, state, revision, settled, settledWith, close } = await openDemoPage()));
  after(() => close?.());

  test('the build has vectorize()', async () => {
    const r = await state();
    assert.deepEqual(r.errors, []);
    assert.equal(r.features.vectorize, true);
  });

  test('every vectorization method draws segments along their own clusters', async () => {
    for (const method of ['ftls', 'aftls', 'itls', 'dp', 'rw']) {
      const rev = await revision();
      await page.selectOption('#method', method);
      const r = await settled(rev);
      assert.equal(r.vectorization.method, method);
      assert.ok(r.vectorization.segmentCount >= 1, `${method}: no segments`);
      for (const [x1, y1, x2, y2, cluster] of r.vectorization.segments) {
        for (const [x, y] of [[x1, y1], [x2, y2]]) {
          let best = Infinity;
          r.segmentation.labels.forEach((l, i) => {
            if (l !== cluster) return;
            const px = scan.ranges[i] * Math.cos(scan.angles[i]), py = scan.ranges[i] * Math.sin(scan.angles[i]);
            best = Math.min(best, Math.hypot(px - x, py - y));
          });
          assert.ok(best < 0.5, `${method}: segment end (${x}, ${y}) is ${best} m from cluster ${cluster}`);
        }
      }
      assert.equal(await page.textContent('#vec-count'), String(r.vectorization.segmentCount));
      assert.ok((await page.textContent('#method-text')).length > 40, `${method}: explanation shown`);
      await page.screenshot({ path: join(resultsDir(), `page-${method}.png`) });
    }
  });

  test('the page draws the segments vectorize() computes in Node for each cluster', async () => {
    const rtl = await init();
    const points = scanPoints(scan);
    const seg = rtl.segment(points);
    for (const method of ['aftls', 'rw']) {
      const rev = await revision();
      await page.selectOption('#method', method);
      const r = await settled(rev);
      const expected = [], failed = [];
      seg.clusters.forEach((c, k) => {
        if (c.indices.length < 3) return;                    // the page's default smallest cluster drawn
        const xy = new Float64Array(2 * c.indices.length);
        c.indices.forEach((i, j) => { xy[2 * j] = points[2 * i]; xy[2 * j + 1] = points[2 * i + 1]; });
        const v = rtl.vectorize(xy, { method, sigma: 0.03, delta: 0.3, epsilon: 0.09 });
        if (!v.ok) failed.push(k);
        for (let q = 0; q < v.count; q++) expected.push([...v.segments.subarray(4 * q, 4 * q + 4), k]);
      });
      assert.equal(r.vectorization.segments.length, expected.length, method);
      assert.deepEqual(r.vectorization.failedClusters, failed, `${method}: clusters the vectorizer failed on`);
      r.vectorization.segments.forEach((sg, q) => sg.forEach((x, d) => assert.ok(Math.abs(x - expected[q][d]) < 1e-9, `${method} segment ${q}`)));
    }
  });

  test('the comparison table runs all five methods on the same clusters; a row click selects its method', async () => {
    const r = await state();
    const table = r.vectorization.comparison;
    assert.deepEqual(table.map((c) => c.method), ['ftls', 'aftls', 'itls', 'dp', 'rw']);
    const mine = table.find((c) => c.method === r.vectorization.method);
    assert.equal(mine.segmentCount, r.vectorization.segmentCount);
    assert.equal(mine.rmsMax, r.vectorization.rmsMax);
    for (const c of table) assert.ok(c.segmentCount >= 1, c.method);
    const rows = await page.$$eval('#compare-rows tr', (trs) => trs.map((tr) => [tr.dataset.method, tr.className, tr.children[1].textContent]));
    assert.deepEqual(rows.map(([m]) => m), table.map((c) => c.method));
    assert.deepEqual(rows.filter(([, cls]) => cls === 'current').map(([m]) => m), [r.vectorization.method]);
    rows.forEach(([, , count], k) => assert.equal(count, String(table[k].segmentCount)));
    const rev = await revision();
    await page.click('#compare-rows tr[data-method="itls"]');
    const after = await settled(rev);
    assert.equal(after.vectorization.method, 'itls');
    assert.equal(await page.inputValue('#method'), 'itls');
    assert.equal(after.vectorization.segmentCount, table.find((c) => c.method === 'itls').segmentCount);
    await page.screenshot({ path: join(resultsDir(), 'page-compare.png'), fullPage: true });
  });

  test('a smaller epsilon (DP) or sigma (FTLS) gives more segments; FTLS keeps every RMS under sigma', async () => {
    await page.selectOption('#method', 'dp');
    await page.fill('#epsilon', '0.3');
    const coarse = (await settledWith({ method: 'dp', epsilon: 0.3 })).vectorization.segmentCount;
    await page.fill('#epsilon', '0.01');
    const fine = (await settledWith({ method: 'dp', epsilon: 0.01 })).vectorization.segmentCount;
    assert.ok(fine > coarse, `DP: ${fine} segments at eps 1 cm vs ${coarse} at 30 cm`);

    await page.selectOption('#method', 'ftls');
    await page.fill('#sigma', '0.2');
    const loose = await settledWith({ method: 'ftls', sigma: 0.2 });
    await page.fill('#sigma', '0.01');
    const tight = await settledWith({ method: 'ftls', sigma: 0.01 });
    assert.ok(tight.vectorization.segmentCount > loose.vectorization.segmentCount,
      `FTLS: ${tight.vectorization.segmentCount} segments at sigma 1 cm vs ${loose.vectorization.segmentCount} at 20 cm`);
    assert.ok(tight.vectorization.rmsMax <= 0.01 + 1e-9, `FTLS sigma bound: max RMS ${tight.vectorization.rmsMax}`);
    await page.fill('#sigma', '0.03');
    await settledWith({ method: 'ftls', sigma: 0.03 });
  });

  test('no console errors, failed requests or page errors during the session', async () => {
    assert.deepEqual((await state()).errors, []);
    assert.deepEqual(problems, []);
  });
});
