// Every view is a link: the URL hash holds the lesson, its parameters and the step; "Copy link" puts it on the
// clipboard, and opening it in a new page restores exactly that view (the same finalState and step).
import { after, before, describe, test } from 'node:test';
import assert from 'node:assert/strict';
import { PAGE_TIMEOUT, openDemoPage, openLesson } from './helpers.js';

const stepOf = (page, id) => page.evaluate((h) => window.__rtl.lessons.find((l) => l.id === h).step, id);

// Sets a form input of the open lesson as a user would (value + its input event) and waits for the new trace.
async function setParam(page, name, value, check) {
  await page.evaluate(([n, v]) => { const i = document.querySelector(`#lesson-controls [name="${n}"]`); i.value = v; i.dispatchEvent(new Event('input', { bubbles: true })); }, [name, value]);
  await page.waitForFunction(check, null, { timeout: PAGE_TIMEOUT });
}

async function scrubTo(page, id, k) {
  await page.fill('#player [data-act="scrub"]', String(k + 1));
  await page.dispatchEvent('#player [data-act="scrub"]', 'input');
  await page.waitForFunction(([h, s]) => window.__rtl.lessons.find((l) => l.id === h).step === s, [id, k], { timeout: PAGE_TIMEOUT });
}

// Opens `url` in a new tab of the same browser and waits for the lesson to show a step.
async function openInNewPage(context, url) {
  const page = await context.newPage();
  const problems = [];
  page.on('pageerror', (e) => problems.push(e.message));
  page.on('console', (m) => { if (m.type() === 'error') problems.push(m.text()); });
  await page.goto(url);
  await page.waitForFunction(() => window.__rtl?.ready && window.__rtl.current &&
    window.__rtl.lessons.find((l) => l.id === window.__rtl.current).step !== null, null, { timeout: PAGE_TIMEOUT });
  return { page, problems };
}

describe('every view is a link', { timeout: 240000 }, () => {
  let page, problems, close, browser, server;
  before(async () => {
    ({ page, problems, close, browser, server } = await openDemoPage('/web/#ftls'));
    await browser.context.grantPermissions(['clipboard-read', 'clipboard-write'], { origin: server.origin });
    await page.setViewportSize({ width: 1280, height: 800 });
  });
  after(() => close?.());

  test('FTLS, δ = 0.05 m, split on, step 14: the copied link reopens that view in a new page', async () => {
    await openLesson(page, 'ftls');
    await setParam(page, 'delta', '0.05', () => window.__rtl.finalState()?.params?.delta === 0.05);
    await page.click('#lesson-controls [name="split"]');
    await page.waitForFunction(() => window.__rtl.finalState()?.params?.split === true, null, { timeout: PAGE_TIMEOUT });
    await scrubTo(page, 'ftls', 13);
    const before = await page.evaluate(() => window.__rtl.finalState());
    assert.equal(before.step, 13);
    await page.click('#copy-link');
    await page.waitForFunction(() => /Link copied/.test(document.querySelector('#link-status').textContent), null, { timeout: PAGE_TIMEOUT });
    const url = await page.evaluate(() => navigator.clipboard.readText());
    assert.match(url, /#ftls\?/);
    const q = new URLSearchParams(url.split('?')[1]);
    assert.equal(q.get('delta'), '0.05');
    assert.equal(q.get('split'), '1');
    assert.equal(q.get('at'), '14', 'the step as the player counts it');
    const other = await openInNewPage(browser.context, url);
    try {
      const after = await other.page.evaluate(() => window.__rtl.finalState());
      assert.deepEqual(after, before, 'the same replayed state, parameters and step');
      assert.equal(await other.page.textContent('#player .step-count'), await page.textContent('#player .step-count'));
      assert.equal(await other.page.textContent('#lesson-text'), await page.textContent('#lesson-text'));
      assert.equal(await other.page.inputValue('#lesson-controls [name="delta"]'), '0.05');
      assert.deepEqual(other.problems, []);
    } finally { await other.page.close(); }
  });

  test('the compare lesson: the chosen cluster and ε travel in the link', async () => {
    await openLesson(page, 'compare');
    const first = await page.evaluate(() => window.__rtl.finalState());
    const options = await page.$$eval('#cmp-cluster option', (os) => os.map((o) => o.value));
    const other = options.find((v) => Number(v) !== first.cluster);
    await setParam(page, 'cluster', other, () => true);
    await page.waitForFunction((c) => window.__rtl.finalState().cluster === Number(c), other, { timeout: PAGE_TIMEOUT });
    await setParam(page, 'epsilon', '0.1', () => window.__rtl.finalState()?.params?.epsilon === 0.1);
    await scrubTo(page, 'compare', 3);
    const before = await page.evaluate(() => window.__rtl.finalState());
    const url = await page.evaluate(() => window.__rtl.link());
    const view = await openInNewPage(browser.context, url);
    try {
      assert.deepEqual(await view.page.evaluate(() => window.__rtl.finalState()), before);
      assert.deepEqual(view.problems, []);
    } finally { await view.page.close(); }
  });

  test('stepping rewrites the URL in place (no history entry per step); a menu link opens the defaults', async () => {
    await openLesson(page, 'dp');
    const length = await page.evaluate(() => history.length);
    await scrubTo(page, 'dp', 2);
    await scrubTo(page, 'dp', 3);
    assert.equal(await page.evaluate(() => history.length), length);
    assert.match(await page.evaluate(() => location.hash), /^#dp\?epsilon=0\.05&at=4$/);
    await setParam(page, 'epsilon', '0.1', () => window.__rtl.finalState()?.params?.epsilon === 0.1);
    assert.match(await page.evaluate(() => location.hash), /epsilon=0\.1\b/);
    await page.click('#lesson-menu a[data-lesson="rw"]');
    await page.waitForFunction(() => window.__rtl.current === 'rw' && window.__rtl.lessons.find((l) => l.id === 'rw').step !== null, null, { timeout: PAGE_TIMEOUT });
    await page.click('#lesson-menu a[data-lesson="dp"]');
    await page.waitForFunction(() => window.__rtl.current === 'dp' && window.__rtl.finalState()?.params?.epsilon === 0.05, null, { timeout: PAGE_TIMEOUT });
  });

  test('a link with a parameter the lesson does not have opens the lesson and says which one', async () => {
    const url = `${server.origin}/web/#dp?epsilon=0.1&colour=red&at=2`;
    const view = await openInNewPage(browser.context, url);
    try {
      const s = await view.page.evaluate(() => window.__rtl.finalState());
      assert.equal(s.params.epsilon, 0.1);
      assert.equal(s.step, 1);
      assert.match(await view.page.textContent('#status'), /colour/);
      assert.deepEqual(view.problems, []);
    } finally { await view.page.close(); }
  });

  test('no console errors', async () => {
    assert.deepEqual(await page.evaluate(() => window.__rtl.errors), []);
    assert.deepEqual(problems, []);
  });
});
