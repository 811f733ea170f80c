// Layout of the lesson page measured in Chromium: at 1280x800 the figure, the lesson's parameters and the player
// are on screen together without scrolling, and the comparison table fits beside the panel; at 390x844 nothing is
// wider than the screen and the comparison table keeps all its columns (it scrolls inside its box). Invalid inputs
// are marked and explained next to the field.
import { after, before, describe, test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { join } from 'node:path';
import { DATA, PAGE_TIMEOUT, openDemoPage, openLesson } from './helpers.js';

const LESSONS = ['overview', 'car', 'ia', 'ftls', 'aftls', 'itls', 'dp', 'rw', 'compare', 'tracking'];
const box = (page, sel) => page.locator(sel).first().boundingBox();

describe('lesson page layout', { timeout: 240000 }, () => {
  let page, problems, close;
  before(async () => ({ page, problems, close } = await openDemoPage('/web/')));
  after(() => close?.());

  test('1280x800: figure, parameters and player of every lesson visible together, no scrolling', async () => {
    await page.setViewportSize({ width: 1280, height: 800 });
    for (const id of LESSONS) {
      await openLesson(page, id);
      assert.equal(await page.evaluate(() => window.scrollY), 0);
      const fig = await box(page, '#canvas'), controls = await box(page, '#lesson-controls'), player = await box(page, '#player');
      for (const [name, b] of [['figure', fig], ['parameters', controls], ['player', player]]) {
        assert.ok(b && b.width > 0 && b.height > 0, `${id}: ${name} shown`);
        assert.ok(b.x >= 0 && b.y >= 0 && b.x + b.width <= 1280 + 0.5 && b.y + b.height <= 800 + 0.5,
          `${id}: ${name} inside the screen: ${JSON.stringify(b)}`);
      }
      assert.ok(fig.width >= 600 && fig.height >= 380, `${id}: figure big enough: ${fig.width}x${fig.height}`);
      assert.ok(controls.x + controls.width <= fig.x, `${id}: parameters beside the figure`);
      // every parameter input itself is on screen
      for (const b of await page.locator('#lesson-controls input, #lesson-controls select').evaluateAll((els) => els.map((e) => e.getBoundingClientRect().toJSON()))) {
        assert.ok(b.bottom <= 800 && b.top >= 0, `${id}: input at ${b.top}..${b.bottom}`);
      }
      assert.ok(await page.evaluate(() => document.documentElement.scrollWidth) <= 1280);
    }
  });

  test('1280x800: every drop-down of every lesson shows its chosen option whole (native <select> text is cut, not wrapped)', async () => {
    await page.setViewportSize({ width: 1280, height: 800 });
    await page.evaluate(() => { document.querySelector('#own-data').open = true; });
    const ids = await page.$$eval('#lesson-menu a[data-lesson]', (as) => as.map((a) => a.dataset.lesson));
    assert.ok(ids.length >= 14, `${ids.length} lessons`);
    let checked = 0;
    for (const id of ids) {
      await openLesson(page, id);
      // the selected option's text in the select's own font, against the room inside it (padding and the arrow)
      const cut = await page.evaluate(() => {
        const ctx = document.createElement('canvas').getContext('2d');
        return [...document.querySelectorAll('.panel select')].filter((s) => s.getClientRects().length).map((s) => {
          const css = getComputedStyle(s);
          ctx.font = `${css.fontWeight} ${css.fontSize} ${css.fontFamily}`;
          const text = s.selectedOptions[0]?.textContent ?? '';
          const room = s.clientWidth - parseFloat(css.paddingLeft) - parseFloat(css.paddingRight) - 20;
          return { name: s.name || s.id, text, need: ctx.measureText(text).width, room };
        });
      });
      for (const c of cut) assert.ok(c.need <= c.room, `${id}: "${c.text}" (${c.name}) needs ${c.need.toFixed(0)} px, has ${c.room.toFixed(0)}`);
      checked += cut.length;
    }
    assert.ok(checked >= ids.length, `${checked} drop-downs checked`);
    // a log opened: the scan chooser names the file, the scan and its counts
    const text = readFileSync(join(DATA, 'csail.log'), 'utf8');
    const dt = await page.evaluateHandle((b) => { const t = new DataTransfer(); t.items.add(new File([new Uint8Array(b)], 'csail-run-2003-a.log')); return t; }, Array.from(Buffer.from(text)));
    await page.dispatchEvent('body', 'drop', { dataTransfer: dt });
    await page.waitForFunction(() => window.__rtl.source()?.scan === 0, null, { timeout: PAGE_TIMEOUT });
    const chooser = await page.evaluate(() => {
      const s = document.querySelector('#scan-chooser'), css = getComputedStyle(s), ctx = document.createElement('canvas').getContext('2d');
      ctx.font = `${css.fontWeight} ${css.fontSize} ${css.fontFamily}`;
      return { text: s.selectedOptions[0].textContent, need: ctx.measureText(s.selectedOptions[0].textContent).width, room: s.clientWidth - parseFloat(css.paddingLeft) - parseFloat(css.paddingRight) - 20 };
    });
    assert.ok(chooser.need <= chooser.room, `scan chooser: "${chooser.text}" needs ${chooser.need.toFixed(0)} px, has ${chooser.room.toFixed(0)}`);
    // the file is named by the option's group (and in its tooltip with the scan)
    assert.equal(await page.$eval('#scan-chooser optgroup:last-of-type', (g) => g.label), 'csail-run-2003-a.log');
    assert.equal(await page.$eval('#scan-chooser', (s) => s.selectedOptions[0].title), `csail-run-2003-a.log, ${chooser.text}`);
    await page.selectOption('#scan-chooser', '');
    await page.waitForFunction(() => window.__rtl.source() === null, null, { timeout: PAGE_TIMEOUT });
    await page.evaluate(() => { document.querySelector('#own-data').open = false; });
  });

  test('1280 px: the comparison table shows all its columns without scrolling, even beside a page scrollbar', async () => {
    // 1265 px = 1280 px less a classic 15 px scrollbar (the page is taller than 800 px)
    for (const width of [1280, 1265]) {
      await page.setViewportSize({ width, height: 800 });
      await openLesson(page, 'compare');
      // the widest state: the longest method's row is the current one (bold)
      await page.fill('#player [data-act="scrub"]', '5');
      await page.dispatchEvent('#player [data-act="scrub"]', 'input');
      await page.waitForFunction(() => window.__rtl.lessons.find((l) => l.id === 'compare').step === 4, null, { timeout: PAGE_TIMEOUT });
      // the table is drawn with the step (under load it came a moment after the step's number)
      await page.waitForSelector('#lesson-stage .table-wrap', { timeout: PAGE_TIMEOUT });
      const t = await page.$eval('#lesson-stage .table-wrap', (el) => {
        const ths = [...el.querySelectorAll('thead th')], r = el.getBoundingClientRect();
        return { sw: el.scrollWidth, cw: el.clientWidth, right: r.right, last: ths.at(-1).getBoundingClientRect().right, n: ths.length };
      });
      assert.equal(t.n, 6);
      assert.ok(t.sw <= t.cw, `${width} px: the table scrolls (${t.sw} > ${t.cw})`);
      assert.ok(t.last <= t.right + 0.5, `${width} px: last column ends at ${t.last}, its box at ${t.right}`);
      const verdict = await box(page, '#lesson-stage .verdict');
      assert.ok(verdict.y + verdict.height <= 800, `${width} px: the verdict ends at ${verdict.y + verdict.height}`);
    }
    await page.setViewportSize({ width: 1280, height: 800 });
  });

  test('390x844: no sideways scrolling, the comparison table keeps its columns', async () => {
    await page.setViewportSize({ width: 390, height: 844 });
    for (const id of LESSONS) {
      await openLesson(page, id);
      const w = await page.evaluate(() => Math.max(document.documentElement.scrollWidth, document.body.scrollWidth));
      assert.ok(w <= 390, `${id}: document width ${w}`);
      const fig = await box(page, '#canvas');
      assert.ok(fig.width >= 300 && fig.x >= 0 && fig.x + fig.width <= 390, `${id}: figure ${JSON.stringify(fig)}`);
      // under the figure: the player and the explanation before the parameters (stepping needs no long scroll)
      const player = await box(page, '#player'), text = await box(page, '#lesson-text'), controls = await box(page, '#lesson-controls');
      if (player && controls && controls.height > 0) {
        assert.ok(fig.y + fig.height <= player.y && player.y < text.y && text.y + text.height <= controls.y + 1, `${id}: figure ${fig.y}, player ${player.y}, text ${text.y}, parameters ${controls.y}`);
      }
    }
    await openLesson(page, 'compare');
    const cols = await page.$$eval('#lesson-stage table thead th', (ths) => ths.map((th) => th.getBoundingClientRect().width));
    assert.equal(cols.length, 6);
    for (const c of cols) assert.ok(c > 20, `column width ${c}`);
    const cells = await page.$$eval('#lesson-stage table tbody tr', (trs) => trs.map((tr) => tr.children.length));
    assert.deepEqual(cells, [6, 6, 6, 6, 6]);
    const wrap = await page.$eval('#lesson-stage .table-wrap', (el) => ({ sw: el.scrollWidth, cw: el.clientWidth, right: el.getBoundingClientRect().right, ox: getComputedStyle(el).overflowX }));
    assert.ok(wrap.right <= 390, `table box ends at ${wrap.right}`);
    assert.equal(wrap.ox, 'auto');
    await page.setViewportSize({ width: 1280, height: 800 });
  });

  test('an upper bound below the lower bound is marked invalid and explained next to the field; fixing it recomputes', async () => {
    await openLesson(page, 'car');
    const upper = page.locator('#lesson-controls input[name="upperBound"]');
    const rev = await page.evaluate(() => window.__rtl.revision);
    await upper.fill('0.05');
    await page.waitForFunction((r) => window.__rtl.revision > r, rev, { timeout: PAGE_TIMEOUT });
    assert.equal(await upper.getAttribute('aria-invalid'), 'true');
    const err = page.locator('#lesson-controls .field[data-key="upperBound"] .field-error');
    assert.ok(await err.isVisible());
    assert.match(await err.textContent(), /lower bound \(0\.1 m\)/);
    // the message is tied to the input for screen readers
    const ids = (await upper.getAttribute('aria-describedby')).split(' ');
    assert.ok(ids.includes(await err.getAttribute('id')));
    assert.equal((await page.evaluate(() => window.__rtl.lessons.find((l) => l.id === 'car'))).steps, 0);
    assert.match(await page.textContent('#lesson-text'), /Fix the marked parameter/);
    await upper.fill('0.5');
    await page.waitForFunction(() => !document.querySelector('#lesson-controls input[name="upperBound"]').hasAttribute('aria-invalid'), null, { timeout: PAGE_TIMEOUT });
    assert.ok(!(await err.isVisible()));
  });

  test('an empty number field is invalid too', async () => {
    await openLesson(page, 'ia');
    const scaling = page.locator('#lesson-controls input[name="scaling"]');
    await scaling.fill('');
    await page.waitForFunction(() => document.querySelector('#lesson-controls input[name="scaling"]').getAttribute('aria-invalid') === 'true', null, { timeout: PAGE_TIMEOUT });
    assert.match(await page.textContent('#lesson-controls .field[data-key="scaling"] .field-error'), /number ≥ 0/);
    await scaling.fill('0.05');
  });

  test('no console errors', async () => {
    assert.deepEqual(await page.evaluate(() => window.__rtl.errors), []);
    assert.deepEqual(problems, []);
  });
});
