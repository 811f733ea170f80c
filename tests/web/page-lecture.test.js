// Lecture mode at 1920x1080: L turns it on, the figure fills the screen's height beside the explanation in large
// type, menus and parameters are hidden, and the keyboard alone steps, plays, jumps and leaves.
import { after, before, describe, test } from 'node:test';
import assert from 'node:assert/strict';
import { mkdirSync } from 'node:fs';
import { join } from 'node:path';
import { PAGE_TIMEOUT, SCREENSHOTS, openDemoPage, openLesson } from './helpers.js';

const stepOf = (page) => page.evaluate(() => window.__rtl.lessons.find((l) => l.id === window.__rtl.current).step);
const waitStep = (page, k) => page.waitForFunction((s) => window.__rtl.lessons.find((l) => l.id === window.__rtl.current).step === s, k, { timeout: PAGE_TIMEOUT });

describe('lecture mode', { timeout: 240000 }, () => {
  let page, problems, close, browser;
  before(async () => {
    mkdirSync(SCREENSHOTS, { recursive: true });
    ({ page, problems, close, browser } = await openDemoPage('/web/#dp'));
    await page.setViewportSize({ width: 1920, height: 1080 });
  });
  after(() => close?.());

  test('L: figure full height in large type, no menu or parameters; keys step, play and leave', async () => {
    await openLesson(page, 'dp');
    await page.click('#lesson-title');
    await page.keyboard.press('l');
    assert.equal(await page.evaluate(() => document.documentElement.classList.contains('lecture')), true);
    assert.equal(await page.getAttribute('#lecture', 'aria-pressed'), 'true');
    await page.waitForTimeout(100);
    const fig = await page.locator('#canvas').boundingBox();
    assert.ok(fig.height >= 1000 && fig.width >= 1250, `figure ${fig.width}x${fig.height}`);
    for (const sel of ['.top', '#lesson-controls', 'figcaption']) assert.equal(await page.isVisible(sel), false, `${sel} hidden`);
    const px = await page.$eval('#lesson-text', (el) => parseFloat(getComputedStyle(el).fontSize));
    assert.ok(px >= 21, `explanation at ${px} px`);
    assert.equal(await page.$eval('#canvas', (el) => getComputedStyle(el).getPropertyValue('--figure-text-scale').trim()), '1.8');
    // the explanation and the player are on screen beside the figure
    for (const sel of ['#lesson-text', '#player']) {
      const b = await page.locator(sel).boundingBox();
      assert.ok(b.x >= fig.x + fig.width && b.y + b.height <= 1080, `${sel} at ${JSON.stringify(b)}`);
    }
    const k0 = await stepOf(page);
    await page.keyboard.press('ArrowRight'); await waitStep(page, k0 + 1);
    await page.keyboard.press('ArrowRight'); await waitStep(page, k0 + 2);
    await page.keyboard.press('ArrowLeft'); await waitStep(page, k0 + 1);
    // the arrows step even when the figure (whose arrows pan outside lecture mode) has the focus
    await page.focus('#canvas');
    await page.keyboard.press('ArrowRight'); await waitStep(page, k0 + 2);
    await page.keyboard.press('Home'); await waitStep(page, 0);
    await page.keyboard.press(' ');
    await page.waitForFunction(() => document.querySelector('#player [data-act="play"]').getAttribute('aria-label') === 'Pause', null, { timeout: PAGE_TIMEOUT });
    await page.keyboard.press(' ');
    await page.waitForFunction(() => document.querySelector('#player [data-act="play"]').getAttribute('aria-label') === 'Play', null, { timeout: PAGE_TIMEOUT });
    await page.keyboard.press('End');
    const steps = await page.evaluate(() => window.__rtl.lessons.find((l) => l.id === 'dp').steps);
    await waitStep(page, steps - 1);
    await page.screenshot({ path: join(SCREENSHOTS, 'lecture-dp-1920x1080.png') });
    await page.keyboard.press('Escape');
    assert.equal(await page.evaluate(() => document.documentElement.classList.contains('lecture')), false);
    await page.keyboard.press('L');
    assert.equal(await page.evaluate(() => document.documentElement.classList.contains('lecture')), true);
    await page.keyboard.press('L');
    assert.equal(await page.evaluate(() => document.documentElement.classList.contains('lecture')), false);
    assert.equal(await page.isVisible('.top'), true);
  });

  test('the figure\'s title is whole at 1920x1080 in lecture mode (wrapped, not cut)', async () => {
    for (const id of ['dp', 'ftls', 'car']) {
      await openLesson(page, id);
      await page.keyboard.press('l');
      await page.waitForFunction(() => document.documentElement.classList.contains('lecture'), null, { timeout: PAGE_TIMEOUT });
      await page.waitForTimeout(100);
      const { title, lines } = await page.evaluate(() => window.__rtl.figureTitle());
      assert.equal(lines.join(' '), title, `${id}: ${JSON.stringify(lines)}`);
      if (id === 'dp') assert.ok(lines.length >= 2, `${id}: its long title wraps in large type (${lines.length} line)`);
      for (const l of lines) assert.ok(!l.endsWith('…'), `${id}: ${l}`);
      await page.screenshot({ path: join(SCREENSHOTS, `lecture-${id}-title-1920x1080.png`) });
      await page.keyboard.press('Escape');
    }
  });

  test('lecture mode is in the link: a link with it opens in it, copy link keeps it', async () => {
    await openLesson(page, 'dp');
    await page.evaluate(() => window.__rtl.lecture.set(false));
    await page.click('#lesson-title');
    await page.keyboard.press('l');
    const url = await page.evaluate(() => window.__rtl.link());
    assert.match(url, /[?&]lecture=1(&|$)/);
    // the copy link button is there in lecture mode, and its link keeps the mode
    assert.equal(await page.isVisible('#copy-link'), true);
    await page.keyboard.press('Escape');
    assert.doesNotMatch(await page.evaluate(() => window.__rtl.link()), /lecture=/);
    // a link with lecture mode, parameters and step, opened in a fresh page
    const link = url.replace(/#.*/, '#dp?epsilon=0.06&lecture=1&at=3');
    const other = await browser.context.newPage();
    try {
      await other.setViewportSize({ width: 1920, height: 1080 });
      await other.goto(link);
      await other.waitForFunction(() => window.__rtl?.ready && window.__rtl.lessons.find((l) => l.id === 'dp').step === 2, null, { timeout: PAGE_TIMEOUT });
      assert.equal(await other.evaluate(() => document.documentElement.classList.contains('lecture')), true);
      assert.equal(await other.getAttribute('#lecture', 'aria-pressed'), 'true');
      assert.equal((await other.evaluate(() => window.__rtl.finalState())).params.epsilon, 0.06);
      assert.match(await other.evaluate(() => location.hash), /^#dp\?epsilon=0\.06&lecture=1&at=3$/);
      // a link in the text (no lecture key) keeps the mode
      await other.evaluate(() => { location.hash = 'rw'; });
      await other.waitForFunction(() => window.__rtl.current === 'rw' && window.__rtl.lessons.find((l) => l.id === 'rw').step !== null, null, { timeout: PAGE_TIMEOUT });
      assert.equal(await other.evaluate(() => document.documentElement.classList.contains('lecture')), true);
      assert.match(await other.evaluate(() => location.hash), /lecture=1/);
    } finally { await other.close(); }
  });

  test('typing L into a parameter field does not toggle the mode', async () => {
    await openLesson(page, 'ia');
    await page.focus('#lesson-controls input[name="scaling"]');
    await page.keyboard.press('l');
    assert.equal(await page.evaluate(() => document.documentElement.classList.contains('lecture')), false);
  });

  test('no console errors', async () => {
    assert.deepEqual(await page.evaluate(() => window.__rtl.errors), []);
    assert.deepEqual(problems, []);
  });
});
