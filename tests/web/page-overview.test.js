// The overview lesson is the opening screen: one Intel scan through the package (readCarmenLog, segment, vectorize)
// and a stretch of the log placed by its poses; its numbers are the package's own (checked in Node), and its links
// land in the CAR, Douglas–Peucker and transformation-tree lessons at the steps they name.
import { after, before, describe, test } from 'node:test';
import assert from 'node:assert/strict';
import { mkdirSync, readFileSync } from 'node:fs';
import { join } from 'node:path';
import init from 'rtl-wasm';
import { DATA, PAGE_TIMEOUT, SCREENSHOTS, openDemoPage, openLesson } from './helpers.js';

const lessonOf = (page, id) => page.evaluate((h) => window.__rtl.lessons.find((l) => l.id === h), id);
async function scrubTo(page, k) {
  await page.fill('#player [data-act="scrub"]', String(k + 1));
  await page.dispatchEvent('#player [data-act="scrub"]', 'input');
  await page.waitForFunction((s) => window.__rtl.current === 'overview' && window.__rtl.lessons[0].step === s, k, { timeout: PAGE_TIMEOUT });
}
// Clicks the explanation's link into lesson `id` (once the overview has measured it) and waits for that lesson to
// show a step; resolves with the step number the link's text names (1-based) and the lesson's entry.
async function follow(page, id) {
  const sel = `#lesson-text a[href^="#${id}"]`;
  await page.waitForSelector(sel, { timeout: PAGE_TIMEOUT });
  const text = await page.textContent(sel);
  const named = Number(text.match(/step (\d+)/)[1]);
  await page.click(sel);
  await page.waitForFunction((h) => window.__rtl.current === h && window.__rtl.lessons.find((l) => l.id === h).step !== null &&
    window.__rtl.lessons.find((l) => l.id === h).steps > 0, id, { timeout: PAGE_TIMEOUT });
  await page.waitForFunction(([h, n]) => window.__rtl.lessons.find((l) => l.id === h).step === n - 1, [id, named], { timeout: PAGE_TIMEOUT });
  return { named, entry: await lessonOf(page, id) };
}
// Back from a lesson the overview linked to: the overview reopens (from its link) at step k.
async function backToOverview(page, k) {
  const rev = await page.evaluate(() => window.__rtl.revision);
  await page.goBack();
  await page.waitForFunction(([r, s]) => window.__rtl.current === 'overview' && window.__rtl.revision > r &&
    window.__rtl.finalState()?.method === 'overview' && window.__rtl.finalState().step === s, [rev, k], { timeout: PAGE_TIMEOUT });
}

describe('the overview lesson', { timeout: 240000 }, () => {
  let page, problems, close, rtl, scans;
  before(async () => {
    rtl = await init();
    scans = rtl.readCarmenLog(readFileSync(join(DATA, 'intel.log'), 'utf8'));
    ({ page, problems, close } = await openDemoPage('/web/'));
    await page.setViewportSize({ width: 1280, height: 800 });
  });
  after(() => close?.());

  test('opens first, on Intel scan 17, with the package\'s numbers', async () => {
    await page.waitForFunction(() => window.__rtl.current === 'overview' && window.__rtl.lessons[0].step !== null, null, { timeout: PAGE_TIMEOUT });
    assert.equal(await page.getAttribute('#lesson-menu a:first-child', 'data-lesson'), 'overview');
    const s = await page.evaluate(() => window.__rtl.finalState());
    assert.deepEqual(s.params, { step: 3, lowerBound: 0.1, upperBound: 0.5, epsilon: 0.05, dataset: 'intel', scan: 17 });
    const scan = scans[17];
    const returns = Array.from({ length: scan.points.length / 2 }, (_, i) => Number.isFinite(scan.points[2 * i])).filter(Boolean).length;
    assert.equal(s.numbers.beams, scan.points.length / 2);
    assert.equal(s.numbers.returns, returns);
    const seg = rtl.segment(scan.points, { step: 3, lowerBound: 0.1, upperBound: 0.5 });
    assert.equal(s.numbers.clusters, seg.clusters.length);
    let segments = 0;
    for (const c of seg.clusters) {
      if (c.indices.length < 3) continue;
      const chain = new Float64Array(Array.from(c.indices).flatMap((i) => [scan.points[2 * i], scan.points[2 * i + 1]]));
      segments += rtl.vectorize(chain, { method: 'dp', epsilon: 0.05 }).count;
    }
    assert.equal(s.numbers.segments, segments);
    assert.deepEqual(s.numbers.mapScans, [12, 13, 14, 15, 16, 17, 18, 19, 20, 21]);
    assert.equal(s.steps, 4 + 10);
    assert.match(await page.textContent('#lesson-text'), new RegExp(`${scan.points.length / 2} ranges`));
  });

  test('screenshots of every stage at 1280x800', async () => {
    mkdirSync(SCREENSHOTS, { recursive: true });
    for (const k of [0, 1, 2, 3, 13]) {
      await scrubTo(page, k);
      await page.waitForTimeout(100);
      await page.screenshot({ path: join(SCREENSHOTS, `overview-stage${k + 1}-1280x800.png`) });
    }
  });

  test('the clusters stage links into CAR at the comparison that keeps the wall whole', async () => {
    await scrubTo(page, 2);
    assert.match(await page.textContent('#lesson-text'), /cuts the scan into \d+ clusters/);
    const { named, entry } = await follow(page, 'car');
    const car = await page.evaluate(() => window.__rtl.finalState());
    assert.equal(car.params.step, 3, 'the overview\'s step s travels with the link');
    const { trace } = rtl.segment(new Float64Array(car.points), { step: 3, lowerBound: 0.1, upperBound: 0.5, trace: true });
    // the wall's boundary the CAR lesson is about: 39 against 38, linked at step 3 (0.132 m within 0.135 m)
    const k = trace.findIndex((e) => e.kind === 'compare' && e.i === 39 && e.j === 38);
    assert.equal(named - 1, k);
    assert.equal(trace[k].linked, true);
    assert.equal(entry.step, named - 1);
    assert.match(await page.textContent('#lesson-text'), /Point 39 vs point 38 \(1 back\): distance 0\.132 m ≤ threshold 0\.135 m/);
    await backToOverview(page, 2);
  });

  test('the segments stage links into Douglas–Peucker at its first split, with the overview\'s ε', async () => {
    await page.evaluate(() => { const i = document.querySelector('#lesson-controls [name="epsilon"]'); i.value = '0.1'; i.dispatchEvent(new Event('input', { bubbles: true })); });
    await page.waitForFunction(() => window.__rtl.finalState()?.params?.epsilon === 0.1, null, { timeout: PAGE_TIMEOUT });
    await scrubTo(page, 3);
    const { named } = await follow(page, 'dp');
    const dp = await page.evaluate(() => window.__rtl.finalState());
    assert.equal(dp.params.epsilon, 0.1);
    const { trace } = rtl.vectorize(new Float64Array(dp.chain), { method: 'dp', epsilon: 0.1, trace: true });
    const k = trace.findIndex((e) => e.kind === 'range' && e.split);
    assert.equal(named - 1, k);
    assert.ok(trace[k].distance > 0.1);
    assert.match(await page.textContent('#lesson-text'), new RegExp(`farthest interior point is ${trace[k].farthest}\\b`));
    await backToOverview(page, 3);
  });

  test('the map stage places the stretch by its poses and links into the transformation tree at robot → map', async () => {
    await scrubTo(page, 13);
    const text = await page.textContent('#lesson-text');
    assert.match(text, /So far 10 scans/);
    const last = scans[21];
    assert.ok(text.includes(`Scan 21 at its pose (${last.x.toFixed(2)}, ${last.y.toFixed(2)}) m`), text);
    await follow(page, 'tf-tree');
    assert.match(await page.textContent('#lesson-text'), /Step 3 of 4 · robot → map/);
  });

  test('the map fills the figure at every map step, on a phone and in lecture mode (the view follows the map)', async () => {
    await openLesson(page, 'overview');
    for (const [width, height, lecture] of [[390, 844, false], [1920, 1080, true], [1280, 800, false]]) {
      await page.setViewportSize({ width, height });
      await page.evaluate((on) => window.__rtl.lecture.set(on), lecture);
      for (let k = 4; k < 14; k++) {
        await scrubTo(page, k);
        // the placed scans' segments and poses as drawn, against the world rectangle the figure shows
        const items = (await page.evaluate(() => window.__rtl.figureQuantities())).filter((it) => it.q === 'mapSegments' || it.q === 'scans');
        const xs = [], ys = [];
        for (const it of items) {
          if (it.xy) for (let i = 0; i < it.xy.length; i += 2) { xs.push(it.xy[i]); ys.push(it.xy[i + 1]); }
          else { xs.push(it.x); ys.push(it.y); }
        }
        const e = await page.evaluate(() => window.__rtl.figureExtent());
        const fw = (Math.max(...xs) - Math.min(...xs)) / (e.maxX - e.minX), fh = (Math.max(...ys) - Math.min(...ys)) / (e.maxY - e.minY);
        const at = `${width}x${height}${lecture ? ' lecture' : ''}, step ${k + 1}`;
        assert.ok(Math.max(fw, fh) > 0.8, `${at}: the map spans ${fw.toFixed(2)} x ${fh.toFixed(2)} of the figure`);
        const cx = (Math.max(...xs) + Math.min(...xs)) / 2, cy = (Math.max(...ys) + Math.min(...ys)) / 2;
        assert.ok(Math.abs(cx - (e.minX + e.maxX) / 2) < 0.1 * (e.maxX - e.minX) && Math.abs(cy - (e.minY + e.maxY) / 2) < 0.1 * (e.maxY - e.minY), `${at}: centred`);
      }
      await scrubTo(page, 6);
      await page.screenshot({ path: join(SCREENSHOTS, `overview-map-step7-${lecture ? 'lecture-' : ''}${width}x${height}.png`), fullPage: width < 500 });
    }
    await page.evaluate(() => window.__rtl.lecture.set(false));
  });

  test('no console errors', async () => {
    assert.deepEqual(await page.evaluate(() => window.__rtl.errors), []);
    assert.deepEqual(problems, []);
  });
});
