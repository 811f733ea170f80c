// The lesson page in headless Chromium: every trace lesson's step count equals the length of the trace the
// package records in Node for the same excerpt and parameters, stepping to the end replays the untraced result,
// and no console errors. Screenshots of every lesson at 1280x800, 390x844 and 1920x1080 go to build/test-output/screenshots/.
import { after, before, describe, test } from 'node:test';
import assert from 'node:assert/strict';
import { mkdirSync } from 'node:fs';
import { join } from 'node:path';
import init from 'rtl-wasm';
import { PAGE_TIMEOUT, SCREENSHOTS as SHOTS, lastStep, openDemoPage, openLesson, streamClusters } from './helpers.js';
const TRACE_LESSONS = ['car', 'ia', 'ftls', 'aftls', 'itls', 'dp', 'rw'];

// The same call the lesson makes, in Node, traced and untraced.
function nodeRun(rtl, s) {
  const p = s.params;
  if (s.method === 'car') {
    const opts = { step: p.step, lowerBound: p.lowerBound, upperBound: p.upperBound };
    return { traced: rtl.segment(new Float64Array(s.points), { ...opts, trace: true }), untraced: rtl.segment(new Float64Array(s.points), opts) };
  }
  if (s.method === 'ia') {
    const opts = { dim: 2, step: p.step, lowerBound: p.lowerBound, upperBound: p.upperBound, scaling: p.scaling };
    const seg = new rtl.StreamSegmenter({ ...opts, trace: true });
    try {
      seg.addPoints(new Float64Array(s.points)); seg.flush();
      return { traced: { trace: seg.takeTrace() }, untraced: streamClusters(rtl, new Float64Array(s.points), opts) };
    } finally { seg.dispose(); }
  }
  const opts = { method: s.method, sigma: p.sigma, delta: p.delta, epsilon: p.epsilon, ...(p.split !== undefined ? { split: p.split } : {}) };
  return { traced: rtl.vectorize(new Float64Array(s.chain), { ...opts, trace: true }), untraced: rtl.vectorize(new Float64Array(s.chain), opts) };
}

describe('lesson page: traces, final states, screenshots', { timeout: 300000 }, () => {
  let page, problems, close, rtl;
  before(async () => {
    rtl = await init();
    mkdirSync(SHOTS, { recursive: true });
    ({ page, problems, close } = await openDemoPage('/web/'));
    await page.setViewportSize({ width: 1280, height: 800 });
  });
  after(() => close?.());

  test('the menu lists every lesson and the hash opens it', async () => {
    const ids = await page.$$eval('#lesson-menu a', (as) => as.map((a) => a.dataset.lesson));
    for (const id of [...TRACE_LESSONS, 'compare']) assert.ok(ids.includes(id), `menu has ${id}`);
    const hook = await page.evaluate(() => window.__rtl.lessons.map((l) => l.id));
    assert.deepEqual(hook, ids);
    await openLesson(page, 'dp');
    assert.equal(await page.getAttribute('#lesson-menu a[data-lesson="dp"]', 'aria-current'), 'page');
    assert.equal(await page.textContent('#lesson-title'), 'Douglas–Peucker');
  });

  for (const id of TRACE_LESSONS) {
    test(`${id}: the step count is the package's trace length, and the last step is the untraced result`, async () => {
      const entry = await openLesson(page, id);
      const s0 = await page.evaluate(() => window.__rtl.finalState());
      const { traced, untraced } = nodeRun(rtl, s0);
      assert.ok(Array.isArray(traced.trace), `the package records a ${id} trace`);
      assert.ok(traced.trace.length > 1, 'more than one step');
      assert.equal(entry.steps, traced.trace.length);
      assert.equal(await page.textContent('#player .step-count'), `step ${entry.step + 1} of ${traced.trace.length}`);
      const s = await lastStep(page, id);
      assert.equal(s.step, traced.trace.length - 1);
      if (id === 'car') {
        const n = s.points.length / 2, canon = new Array(n).fill(-1);
        for (const c of untraced.clusters) { const ix = Array.from(c.indices), m = Math.min(...ix); for (const i of ix) canon[i] = m; }
        assert.deepEqual(s.replayed.partition, canon);
        assert.equal(s.replayed.clusters, untraced.clusters.length);
      } else if (id === 'ia') {
        assert.deepEqual(s.replayed.clusters, untraced.map((c) => Array.from(c)));
      } else if (id === 'dp' || id === 'rw') {
        const keys = [...Array.from(untraced.indices).filter((_, i) => i % 2 === 0), untraced.indices[untraced.indices.length - 1] - 1];
        assert.deepEqual(s.replayed.vertices, keys);
      } else if (id === 'itls') {
        assert.deepEqual(s.replayed.ranges, Array.from(untraced.indices));
        s.replayed.segments.forEach((v, i) => assert.ok(Math.abs(v - untraced.segments[i]) < 1e-9, `segment coordinate ${i}`));
        assert.equal(s.replayed.segments.length, untraced.segments.length);
      } else {
        // FTLS / AFTLS: the replayed partition and segments are the untraced call's
        assert.deepEqual(s.replayed.ranges, Array.from(untraced.indices));
        assert.equal(s.replayed.segments.length, untraced.segments.length);
        s.replayed.segments.forEach((v, i) => assert.ok(Math.abs(v - untraced.segments[i]) < 1e-9, `segment coordinate ${i}`));
      }
      assert.match(await page.textContent('#lesson-text'), /Done|segments|failure|Failed/);
    });
  }

  test('why a cluster fails: FTLS strict mode at δ = 0.05 m names the corner and the package\'s numbers, and the fix works', async () => {
    await openLesson(page, 'ftls');
    const rev = await page.evaluate(() => window.__rtl.revision);
    await page.evaluate(() => { const i = document.querySelector('#lesson-controls input[name="delta"]'); i.value = '0.05'; i.dispatchEvent(new Event('input')); });
    await page.waitForFunction((r) => window.__rtl.revision > r && window.__rtl.finalState().params?.delta === 0.05, rev, { timeout: PAGE_TIMEOUT });
    const s = await page.evaluate(() => window.__rtl.finalState());
    const v = rtl.vectorize(new Float64Array(s.chain), { method: 'ftls', sigma: 0.03, delta: 0.05, split: false });
    assert.equal(v.ok, false, 'the excerpt fails at δ = 0.05 m');
    assert.ok(v.failure && v.failure.crossingDistance > 0.05);
    assert.deepEqual(s.untraced.failure && [s.untraced.failure.boundary, s.untraced.failure.crossingDistance], [v.failure.boundary, v.failure.crossingDistance]);
    const text = await page.textContent('#lesson-text');
    assert.ok(text.includes(`corner between points ${v.failure.boundary - 1} and ${v.failure.boundary}`), text);
    assert.ok(text.includes(`cross ${v.failure.crossingDistance.toFixed(2)} m from that boundary`), text);
    assert.ok(text.includes('δ = 0.05 m'), text);
    await page.click('#lesson-text [data-fix="delta"]');
    await page.waitForFunction(() => window.__rtl.finalState().params.delta > 0.05, null, { timeout: PAGE_TIMEOUT });
    const fixed = await page.evaluate(() => window.__rtl.finalState());
    assert.ok(fixed.params.delta > v.failure.crossingDistance);
    assert.equal(fixed.untraced.ok, rtl.vectorize(new Float64Array(s.chain), { method: 'ftls', sigma: 0.03, delta: fixed.params.delta, split: false }).ok);
  });

  test('screenshots of every lesson at 1280x800, 390x844 and 1920x1080 (and in lecture mode there): nothing sideways, titles whole', async () => {
    const ids = await page.evaluate(() => window.__rtl.lessons.map((l) => l.id));
    for (const [w, h, lecture] of [[1280, 800], [390, 844], [1920, 1080], [1920, 1080, true]]) {
      await page.setViewportSize({ width: w, height: h });
      await page.evaluate((on) => window.__rtl.lecture.set(on), Boolean(lecture));
      for (const id of ids) {
        const e = await openLesson(page, id);
        // a few steps after the one the lesson opens at shows the algorithm at work
        if (e.steps > 2) {
          await page.fill('#player [data-act="scrub"]', String(e.step + 1 + Math.min(6, e.steps - 1 - e.step)));
          await page.dispatchEvent('#player [data-act="scrub"]', 'input');
        }
        await page.waitForTimeout(150);
        await page.screenshot({ path: join(SHOTS, `${lecture ? 'lecture-' : ''}${id}-${w}x${h}.png`), fullPage: w < 500 });
        const width = await page.evaluate(() => Math.max(document.documentElement.scrollWidth, document.body.scrollWidth));
        assert.ok(width <= w, `${id} at ${w}x${h}: the page is ${width} px wide`);
        const t = await page.evaluate(() => window.__rtl.figureTitle());
        if (t && t.title && await page.isVisible('#canvas')) assert.equal(t.lines.join(' '), t.title, `${id} at ${w}x${h}${lecture ? ' (lecture)' : ''}: the figure's title is whole`);
      }
    }
    await page.evaluate(() => window.__rtl.lecture.set(false));
    await page.setViewportSize({ width: 1280, height: 800 });
  });

  test('no console errors, failed requests or page errors', async () => {
    assert.deepEqual(await page.evaluate(() => window.__rtl.errors), []);
    assert.deepEqual(problems, []);
  });
});
