// The demo page's map frame: every scan of the log placed by its pose through the package's transformation tree
// (TfTree). The drawn points must be R(theta) p + (x, y) of the robot-frame points, computed here independently.
import { after, before, describe, test } from 'node:test';
import assert from 'node:assert/strict';
import { join } from 'node:path';
import { PAGE_TIMEOUT as TIMEOUT, isReturn, loadLog, openDemoPage, resultsDir } from './helpers.js';

describe('demo page (web/index.html) in Chromium: map frame', { timeout: 180000 }, () => {
  let page, problems, state, close;
  const csail = loadLog('csail');

  before(async () => ({ page, problems, state, close } = await openDemoPage()));
  after(() => close?.());

  test('the build has TfTree and the page offers the map frame', async () => {
    const r = await state();
    assert.equal(r.features.tfTree, true);
    assert.equal(await page.isVisible('#map-frame'), true);
    assert.equal(r.frame, 'robot');
  });

  test('in the map frame each scan sits at its pose; the fit numbers stay those of the robot frame', async () => {
    await page.selectOption('#dataset', 'csail');
    await page.waitForFunction(() => window.__rtl.dataset === 'csail', null, { timeout: TIMEOUT });
    await page.fill('#scan', '20');
    await page.waitForFunction(() => window.__rtl.scanIndex === 20, null, { timeout: TIMEOUT });
    const robot = await state();
    await page.check('#map-frame');
    await page.waitForFunction(() => window.__rtl.frame === 'map', null, { timeout: TIMEOUT });
    const r = await state();
    const scan = csail[20];
    assert.deepEqual(r.sensor, { x: scan.x, y: scan.y, theta: scan.theta });
    const c = Math.cos(scan.theta), s = Math.sin(scan.theta);
    let returns = 0;
    scan.ranges.forEach((range, i) => {
      const [px, py] = [r.shownPoints[2 * i], r.shownPoints[2 * i + 1]];
      if (!isReturn(range)) { assert.ok(px === null || Number.isNaN(px), `gap ${i} stays a gap`); return; }
      returns++;
      const x = range * Math.cos(scan.angles[i]), y = range * Math.sin(scan.angles[i]);
      assert.ok(Math.abs(px - (c * x - s * y + scan.x)) < 1e-9 && Math.abs(py - (s * x + c * y + scan.y)) < 1e-9, `beam ${i}`);
    });
    assert.equal(returns, r.validCount);
    assert.equal(r.backgroundPoints, csail.reduce((n, sc, k) => n + (k === 20 ? 0 : sc.n), 0));
    assert.deepEqual(r.fit, robot.fit);
    assert.match(await page.textContent('#frame-text'), /^Map frame/);
    await page.screenshot({ path: join(resultsDir(), 'page-map-frame.png') });
  });

  test('clicking a cluster in the map frame fits that cluster', async () => {
    const r0 = await state();
    const largest = r0.segmentation.clusterSizes.indexOf(r0.segmentation.largest);
    const member = r0.segmentation.labels.indexOf(largest);
    const at = await page.evaluate((i) => window.__rtl.clientPoint(i), member);
    const rev = r0.revision;
    await page.mouse.click(at.x, at.y);
    await page.waitForFunction((v) => window.__rtl.revision > v, rev, { timeout: TIMEOUT });
    const r = await state();
    assert.equal(r.frame, 'map');
    assert.equal(r.fit.source, `cluster ${largest + 1}`);
  });

  test('back to the robot frame', async () => {
    await page.uncheck('#map-frame');
    await page.waitForFunction(() => window.__rtl.frame === 'robot', null, { timeout: TIMEOUT });
    const r = await state();
    assert.deepEqual(r.sensor, { x: 0, y: 0, theta: 0 });
    assert.equal(r.backgroundPoints, 0);
    assert.match(await page.textContent('#frame-text'), /^Robot frame/);
  });

  test('no console errors, failed requests or page errors during the session', async () => {
    assert.deepEqual((await state()).errors, []);
    assert.deepEqual(problems, []);
  });
});
