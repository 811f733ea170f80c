// The demo page in headless Debian Chromium, first slice: it loads the package through the import map, reads a real
// scan and fits a total-least-squares line; the numbers must match an independent fit done here in plain JavaScript.
import { after, before, describe, test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { join } from 'node:path';
import {
  PAGE_TIMEOUT as TIMEOUT, loadLog, openDemoPage, resultsDir, returnsOf, sameLine, tlsFit, xyOf,
} from './helpers.js';

describe('demo page (web/index.html) in Chromium: scans and the TLS line fit', { timeout: 180000 }, () => {
  let page, problems, settledWith, close;
  const intel = loadLog('intel');
  const csail = loadLog('csail');

  // The file itself, as issue 2 asks (/web/ serves it too).
  before(async () => ({ page, problems, settledWith, close } = await openDemoPage('/web/index.html')));
  after(() => close?.());

  test('loads the package and shows Intel scan 0 without errors', async () => {
    const r = await page.evaluate(() => window.__rtl);
    assert.deepEqual(r.errors, [], 'page errors');
    assert.equal(r.ready, true);
    assert.equal(r.features.fitLine, true);
    assert.equal(typeof r.version, 'string');
    assert.equal(r.dataset, 'intel');
    assert.equal(r.scanIndex, 0);
    assert.equal(r.beams, 180);
    assert.equal(r.validCount, returnsOf(intel[0]).length);
    assert.match(await page.textContent('#status'), /Intel Research Lab, scan 0/);
    await page.screenshot({ path: join(resultsDir(), 'page-initial.png'), fullPage: true });
  });

  test('the whole-scan TLS line matches an independent fit of the same beams', async () => {
    const r = await page.evaluate(() => window.__rtl);
    const beams = returnsOf(intel[0]);
    assert.ok(beams.length > 100, 'scan 0 has enough returns');
    assert.deepEqual(r.fit.indices, beams);
    const ref = tlsFit(xyOf(intel[0], beams));
    assert.equal(r.fit.n, beams.length);
    assert.ok(Math.abs(Math.hypot(...r.fit.normal) - 1) < 1e-9, 'unit normal');
    assert.ok(sameLine(r.fit, ref, 1e-6), `page ${JSON.stringify(r.fit.normal)} ${r.fit.offset} vs ref ${JSON.stringify(ref.normal)} ${ref.offset}`);
    assert.ok(Math.abs(r.fit.rms - ref.rms) < 1e-6, `rms ${r.fit.rms} vs ${ref.rms}`);
    assert.ok(Math.hypot(r.fit.centroid[0] - ref.centroid[0], r.fit.centroid[1] - ref.centroid[1]) < 1e-9, 'centroid');
    // The numbers shown to the user are the same ones.
    assert.equal(await page.textContent('#fit-rms'), `${(ref.rms * 1000).toFixed(1)} mm`);
    assert.equal(await page.textContent('#fit-n'), `${beams.length} (beams 0–179)`);
    // The residuals (what TLS minimises) can be drawn: more red pixels on the canvas than without them.
    const redPixels = () => page.evaluate(() => {
      const c = document.getElementById('canvas');
      const d = c.getContext('2d').getImageData(0, 0, c.width, c.height).data;
      let n = 0;
      for (let i = 0; i < d.length; i += 4) if (d[i] > 150 && d[i + 1] < 110 && d[i + 2] < 130) n++;
      return n;
    });
    const without = await redPixels();
    const rev = (await page.evaluate(() => window.__rtl)).revision;
    await page.check('#show-residuals');
    await page.waitForFunction((v) => window.__rtl.revision > v && window.__rtl.settings.show.residuals, rev, { timeout: TIMEOUT });
    const withResiduals = await redPixels();
    assert.ok(withResiduals > without * 1.05, `red pixels ${withResiduals} with residuals vs ${without}`);
    await page.screenshot({ path: join(resultsDir(), 'page-residuals.png') });
    await page.uncheck('#show-residuals');
    await page.waitForFunction(() => !window.__rtl.settings.show.residuals, null, { timeout: TIMEOUT });
  });

  test('a beam window fits just those beams, and "Whole scan" restores the full fit', async () => {
    const whole = (await page.evaluate(() => window.__rtl)).fit;
    await page.fill('#fit-from', '10');
    await page.fill('#fit-to', '60');
    const r = await settledWith({ fitFrom: 10, fitTo: 60 });
    const beams = returnsOf(intel[0], 10, 60);
    assert.deepEqual(r.fit.indices, beams);
    const ref = tlsFit(xyOf(intel[0], beams));
    assert.ok(sameLine(r.fit, ref, 1e-6));
    assert.ok(Math.abs(r.fit.rms - ref.rms) < 1e-6);
    assert.ok(!sameLine(r.fit, whole, 1e-3), 'a different line than the whole scan');
    await page.screenshot({ path: join(resultsDir(), 'page-window-10-60.png') });
    await page.click('#fit-all');
    const r2 = await settledWith({ fitFrom: 0, fitTo: 179 });
    assert.equal(r2.fit.source, 'beams 0–179');
    assert.ok(sameLine(r2.fit, whole, 1e-12));
  });

  test('the figure zooms and pans with the keyboard and the wheel, and resets', async () => {
    const extent = () => page.evaluate(() => window.__rtl.viewExtent());
    const width = (e) => e.maxX - e.minX;
    const start = await extent();
    await page.focus('#canvas');
    await page.keyboard.press('+');
    const zoomed = await extent();
    assert.ok(Math.abs(width(zoomed) / width(start) - 0.8) < 1e-9, `zoom in: ${width(zoomed)} vs ${width(start)}`);
    await page.keyboard.press('ArrowLeft');
    const panned = await extent();
    assert.ok(panned.minX < zoomed.minX && Math.abs(width(panned) - width(zoomed)) < 1e-9, 'pan keeps the size');
    await page.keyboard.press('0');
    assert.deepEqual(await extent(), start);
    const box = await page.locator('#canvas').boundingBox();
    await page.mouse.move(box.x + box.width / 2, box.y + box.height / 2);
    await page.mouse.wheel(0, 200);                               // wheel down: zoom out around the cursor
    await page.waitForFunction((w) => { const e = window.__rtl.viewExtent(); return e.maxX - e.minX > w; }, width(start), { timeout: TIMEOUT });
    await page.click('#reset-view');
    assert.deepEqual(await extent(), start);
  });

  test('switching to CSAIL (361 beams) and moving the scan slider recomputes', async () => {
    await page.selectOption('#dataset', 'csail');
    await page.waitForFunction(() => window.__rtl.dataset === 'csail', null, { timeout: TIMEOUT });
    let r = await page.evaluate(() => window.__rtl);
    assert.equal(r.beams, 361);
    assert.equal(r.scanIndex, 0);
    await page.fill('#scan', '7');
    await page.waitForFunction(() => window.__rtl.dataset === 'csail' && window.__rtl.scanIndex === 7, null, { timeout: TIMEOUT });
    r = await page.evaluate(() => window.__rtl);
    const beams = returnsOf(csail[7]);
    assert.deepEqual(r.fit.indices, beams);
    const ref = tlsFit(xyOf(csail[7], beams));
    assert.ok(sameLine(r.fit, ref, 1e-6));
    assert.ok(Math.abs(r.fit.rms - ref.rms) < 1e-6);
    assert.match(await page.textContent('#scan-info'), new RegExp(`361 beams, ${beams.length} returns`));
    await page.screenshot({ path: join(resultsDir(), 'page-csail-7.png'), fullPage: true });
  });

  test('SVG and TikZ downloads of the figure come from the package exporters', async () => {
    const r = await page.evaluate(() => window.__rtl);       // CSAIL scan 7 after the previous test
    const [svgDl] = await Promise.all([page.waitForEvent('download'), page.click('#dl-svg')]);
    assert.equal(svgDl.suggestedFilename(), 'rtl-csail-7.svg');
    const svg = readFileSync(await svgDl.path(), 'utf8');
    assert.match(svg, /^<svg[\s>]/);
    assert.match(svg, /<\/svg>\s*$/);
    assert.match(svg, /<title>MIT CSAIL scan 7, [^<]*TLS line through \d+ points/);
    assert.equal(svg.match(/<circle /g).length, r.validCount, 'one dot per return');
    assert.equal(svg.match(/<line /g).length, (r.vectorization?.segmentCount ?? 0) + 1, 'the segments and the fitted line');
    const [texDl] = await Promise.all([page.waitForEvent('download'), page.click('#dl-tikz')]);
    assert.equal(texDl.suggestedFilename(), 'rtl-csail-7.tex');
    const tex = readFileSync(await texDl.path(), 'utf8');
    assert.match(tex, /\\documentclass/);
    assert.match(tex, /\\begin\{tikzpicture\}[\s\S]*\\end\{tikzpicture\}[\s\S]*\\end\{document\}/);
  });

  test('no console errors, failed requests or page errors during the session', async () => {
    const r = await page.evaluate(() => window.__rtl);
    assert.deepEqual(r.errors, []);
    assert.deepEqual(problems, []);
  });
});
