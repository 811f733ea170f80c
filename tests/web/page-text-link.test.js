// Text and figure linked both ways: hovering or focusing a quantity of the explanation highlights its element in the
// figure, and hovering that element in the figure lights up its words.
import { after, before, describe, test } from 'node:test';
import assert from 'node:assert/strict';
import init from 'rtl-wasm';
import { PAGE_TIMEOUT, openDemoPage, openLesson } from './helpers.js';

async function scrubTo(page, id, k) {
  await page.fill('#player [data-act="scrub"]', String(k + 1));
  await page.dispatchEvent('#player [data-act="scrub"]', 'input');
  await page.waitForFunction(([h, s]) => window.__rtl.lessons.find((l) => l.id === h).step === s, [id, k], { timeout: PAGE_TIMEOUT });
}
const highlighted = (page) => page.evaluate(() => window.__rtl.highlighted());

describe('text and figure linked', { timeout: 180000 }, () => {
  let page, problems, close, rtl;
  before(async () => {
    rtl = await init();
    ({ page, problems, close } = await openDemoPage('/web/#dp'));
    await page.setViewportSize({ width: 1280, height: 800 });
  });
  after(() => close?.());

  test('Douglas–Peucker: the farthest point\'s words light its marker, and the marker lights the words', async () => {
    await openLesson(page, 'dp');
    const s = await page.evaluate(() => window.__rtl.finalState());
    const { trace } = rtl.vectorize(new Float64Array(s.chain), { method: 'dp', epsilon: s.params.epsilon, trace: true });
    const k = trace.findIndex((e) => e.kind === 'range' && e.split);
    await scrubTo(page, 'dp', k);
    const e = trace[k];
    assert.equal(await page.textContent('#lesson-text [data-q="farthest"]'), String(e.farthest));
    assert.equal(await page.textContent('#lesson-text [data-q="distance"]'), `${e.distance.toFixed(3)} m`);
    assert.equal(await highlighted(page), null);
    await page.hover('#lesson-text [data-q="farthest"]');
    assert.equal(await highlighted(page), 'farthest');
    await page.hover('#lesson-title');
    assert.equal(await highlighted(page), null);
    // the keyboard reaches the quantities too
    await page.focus('#lesson-text [data-q="distance"]');
    assert.equal(await highlighted(page), 'distance');
    await page.focus('#copy-link');
    assert.equal(await highlighted(page), null);
    // the figure → the words
    const at = await page.evaluate(([x, y]) => window.__rtl.clientPoint(x, y), [s.chain[2 * e.farthest], s.chain[2 * e.farthest + 1]]);
    await page.mouse.move(at.x, at.y);
    await page.waitForFunction(() => document.querySelector('#lesson-text [data-q="farthest"]').classList.contains('hot'), null, { timeout: PAGE_TIMEOUT });
    assert.equal(await highlighted(page), 'farthest');
    assert.equal(await page.$$eval('#lesson-text .hot', (els) => els.length), 1, 'only its words');
    await page.mouse.move(5, 5);
    await page.waitForFunction(() => !document.querySelector('#lesson-text .hot'), null, { timeout: PAGE_TIMEOUT });
    assert.equal(await highlighted(page), null);
  });

  test('CAR: a comparison\'s threshold and distance', async () => {
    await openLesson(page, 'car');
    const s = await page.evaluate(() => window.__rtl.finalState());
    const { trace } = rtl.segment(new Float64Array(s.points), { step: s.params.step, lowerBound: s.params.lowerBound, upperBound: s.params.upperBound, trace: true });
    const k = trace.findIndex((e) => e.kind === 'compare' && e.i === 39 && e.j === 38);
    await scrubTo(page, 'car', k);
    await page.hover('#lesson-text [data-q="threshold"]');
    assert.equal(await highlighted(page), 'threshold');
    assert.equal(await page.textContent('#lesson-text [data-q="threshold"]'), `threshold ${trace[k].threshold.toFixed(3)} m`);
    // the compared pair's line, hovered at its middle, lights "distance"
    const [x, y] = [(s.points[78] + s.points[76]) / 2, (s.points[79] + s.points[77]) / 2];
    const at = await page.evaluate(([a, b]) => window.__rtl.clientPoint(a, b), [x, y]);
    await page.mouse.move(at.x, at.y);
    await page.waitForFunction(() => document.querySelector('#lesson-text [data-q="distance"]').classList.contains('hot'), null, { timeout: PAGE_TIMEOUT });
  });

  test('no console errors', async () => {
    assert.deepEqual(await page.evaluate(() => window.__rtl.errors), []);
    assert.deepEqual(problems, []);
  });
});
