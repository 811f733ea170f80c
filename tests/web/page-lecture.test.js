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
  let page, problems, close;
  before(async () => {
    mkdirSync(SCREENSHOTS, { recursive: true });
    ({ page, problems, close } = await openDemoPage('/web/#dp'));
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
