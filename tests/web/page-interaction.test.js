// The lesson page driven like a user in Chromium: one lesson run from the keyboard only, the comparison lesson
// (cluster picked from the keyboard, the text agrees with the table), and the SVG/TikZ export of exactly the view.
import { after, before, describe, test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import init from 'rtl-wasm';
import { PAGE_TIMEOUT, openDemoPage, openLesson } from './helpers.js';

const active = (page) => page.evaluate(() => {
  const a = document.activeElement;
  return { tag: a.tagName, lesson: a.dataset?.lesson ?? null, act: a.dataset?.act ?? null, name: a.getAttribute('name') };
});
async function tabTo(page, match, max = 60) {
  for (let i = 0; i < max; i++) {
    await page.keyboard.press('Tab');
    const a = await active(page);
    if (match(a)) return a;
  }
  throw new Error('focus never reached the element');
}

describe('lesson page interaction', { timeout: 240000 }, () => {
  let page, problems, close, rtl;
  before(async () => {
    rtl = await init();
    ({ page, problems, close } = await openDemoPage('/web/#car'));
    await page.setViewportSize({ width: 1280, height: 800 });
  });
  after(() => close?.());

  test('keyboard only: open Douglas–Peucker from the menu, change ε, step, jump to the end = the untraced result', async () => {
    await page.evaluate(() => document.activeElement?.blur());
    await tabTo(page, (a) => a.lesson === 'dp');
    const rev = await page.evaluate(() => window.__rtl.revision);
    await page.keyboard.press('Enter');
    await page.waitForFunction((r) => window.__rtl.current === 'dp' && window.__rtl.revision > r, rev, { timeout: PAGE_TIMEOUT });
    await tabTo(page, (a) => a.name === 'epsilon');
    await page.keyboard.press('ArrowRight');
    await page.keyboard.press('ArrowRight');
    await page.waitForFunction(() => Math.abs(window.__rtl.finalState().params?.epsilon - 0.06) < 1e-9, null, { timeout: PAGE_TIMEOUT });
    const s0 = await page.evaluate(() => window.__rtl.finalState());
    const traced = rtl.vectorize(new Float64Array(s0.chain), { method: 'dp', epsilon: 0.06, trace: true });
    assert.equal(s0.steps, traced.trace.length, 'steps = the package trace for ε = 0.06');
    await tabTo(page, (a) => a.act === 'forward');
    const before = (await page.evaluate(() => window.__rtl.lessons.find((l) => l.id === 'dp'))).step;
    await page.keyboard.press('Enter');
    await page.waitForFunction((b) => window.__rtl.lessons.find((l) => l.id === 'dp').step === b + 1, before, { timeout: PAGE_TIMEOUT });
    await tabTo(page, (a) => a.act === 'scrub');
    await page.keyboard.press('End');
    await page.waitForFunction(() => { const l = window.__rtl.lessons.find((x) => x.id === 'dp'); return l.step === l.steps - 1; }, null, { timeout: PAGE_TIMEOUT });
    const s = await page.evaluate(() => window.__rtl.finalState());
    const untraced = rtl.vectorize(new Float64Array(s.chain), { method: 'dp', epsilon: 0.06 });
    const keys = [...Array.from(untraced.indices).filter((_, i) => i % 2 === 0), untraced.indices[untraced.indices.length - 1] - 1];
    assert.deepEqual(s.replayed.vertices, keys);
    assert.match(await page.textContent('#lesson-text'), /Done: \d+ vertices/);
  });

  test('compare: a cluster picked from the keyboard recomputes all five methods, and the text agrees with the table', async () => {
    await openLesson(page, 'compare');
    const first = await page.evaluate(() => window.__rtl.finalState());
    await page.focus('#cmp-cluster');
    await page.keyboard.press('ArrowDown');
    await page.waitForFunction((c) => window.__rtl.finalState().cluster !== c, first.cluster, { timeout: PAGE_TIMEOUT });
    const s = await page.evaluate(() => window.__rtl.finalState());
    assert.equal(s.rows.length, 5);
    const table = await page.$$eval('#lesson-stage tbody tr', (trs) => trs.map((tr) => Array.from(tr.children, (td) => td.textContent)));
    s.rows.forEach((r, k) => assert.equal(table[k][1], r.ok ? String(r.segments) : 'failed'));
    const fewest = Math.min(...s.rows.filter((r) => r.ok).map((r) => r.segments));
    assert.match(s.verdict, new RegExp(`^Fewest segments: ${fewest}\\.`));
    // every method the text calls unbeaten is unbeaten in the table's numbers
    const list = s.verdict.split('less total squared residual): ')[1].split('. ')[0].split(', ');
    const named = s.rows.filter((r) => list.includes(r.name));
    assert.equal(named.length, list.length, `every name in "${list}" is a method`);
    assert.ok(named.length >= 1);
    const less = (a, b) => a < b - 1e-6 * Math.max(a, b);
    for (const r of named) assert.ok(!s.rows.some((o) => o.ok && o !== r && o.segments <= r.segments && less(o.ssr, r.ssr)), `${r.name} is not beaten`);
    // and every method left out is beaten by one in the table
    for (const r of s.rows.filter((x) => x.ok && !list.includes(x.name))) {
      assert.ok(s.rows.some((o) => o.ok && o !== r && o.segments <= r.segments && !less(r.ssr, o.ssr) && (o.segments < r.segments || less(o.ssr, r.ssr))), `${r.name} is beaten`);
    }
    // a table row picked with Enter selects its method in the player
    await page.focus('#lesson-stage tbody tr[data-k="3"]');
    await page.keyboard.press('Enter');
    await page.waitForFunction(() => window.__rtl.lessons.find((l) => l.id === 'compare').step === 3, null, { timeout: PAGE_TIMEOUT });
    assert.match(await page.textContent('#lesson-text'), /Douglas–Peucker/);
    assert.equal(await page.getAttribute('#lesson-stage tbody tr[data-k="3"]', 'class'), 'current');
  });

  test('SVG and TikZ export exactly the view: its title, its points, and fewer points when zoomed in', async () => {
    await openLesson(page, 'compare');
    const svgOf = async () => {
      const [dl] = await Promise.all([page.waitForEvent('download'), page.click('#dl-svg')]);
      return readFileSync(await dl.path(), 'utf8');
    };
    const s = await page.evaluate(() => window.__rtl.finalState());
    const whole = await svgOf();
    const shown = await page.evaluate(() => window.__rtl.lessons.find((l) => l.id === 'compare').step);
    const name = ['FTLS', 'AFTLS', 'ITLS', 'Douglas–Peucker', 'Reumann–Witkam'][shown];
    // the file is the package's toSvg of the figure's drawing, byte for byte (the same call in Node)
    const args = await page.evaluate(() => window.__rtl.exportArguments());
    assert.equal(whole, rtl.toSvg(args.drawing, args.svg));
    assert.equal(args.drawing.title, `Compare: ${name} on cluster ${s.cluster + 1} of Intel Research Lab, scan 17`);
    assert.ok(whole.includes(`>${args.drawing.title}</text>`), 'the figure title is drawn');
    const circles = (a) => a.drawing.points.length / 2;
    // the figure fits the chosen cluster: all of its points are in the view
    const clusterSize = (await page.evaluate(() => window.__rtl.finalState())).rows[0].n;
    assert.equal(circles(args), clusterSize, `one dot per point of cluster ${s.cluster + 1}`);
    await page.focus('#canvas');
    for (let i = 0; i < 4; i++) await page.keyboard.press('+');
    const zoomed = await svgOf(), zoomedArgs = await page.evaluate(() => window.__rtl.exportArguments());
    assert.equal(zoomed, rtl.toSvg(zoomedArgs.drawing, zoomedArgs.svg));
    assert.ok(circles(zoomedArgs) < circles(args), `zoomed export has ${circles(zoomedArgs)} of ${circles(args)} points`);
    // the exported extent is the view: its frame is the drawing's bounding box
    const e = await page.evaluate(() => window.__rtl.figureExtent());
    const ratio = (e.maxY - e.minY) / (e.maxX - e.minX);
    // (measured without the title: the SVG gives text above the data room of its own)
    const untitled = rtl.toSvg({ ...zoomedArgs.drawing, title: '' }, zoomedArgs.svg);
    const [, w, h] = untitled.match(/viewBox="0 0 ([\d.]+) ([\d.]+)"/).map(Number);
    assert.ok(Math.abs(h / w - ratio) < 0.02, `aspect ${h / w} vs view ${ratio}`);
    const [tex] = await Promise.all([page.waitForEvent('download'), page.click('#dl-tikz')]);
    const tikz = readFileSync(await tex.path(), 'utf8');
    assert.match(tikz, /\\begin\{tikzpicture\}/);
    assert.equal(tikz, rtl.toTikz(zoomedArgs.drawing));
    assert.equal((tikz.match(/\\Mark[A-Z]+\{/g) ?? []).length, circles(zoomedArgs), 'one TikZ mark per point in view');
    await page.keyboard.press('0');
  });

  test('CAR: clicking a point of the figure jumps to the first step about it', async () => {
    await openLesson(page, 'car');
    const s = await page.evaluate(() => window.__rtl.finalState());
    const at = await page.evaluate(([x, y]) => window.__rtl.clientPoint(x, y), [s.points[2 * 44], s.points[2 * 44 + 1]]);
    const before = (await page.evaluate(() => window.__rtl.lessons.find((l) => l.id === 'car'))).step;
    await page.mouse.click(at.x, at.y);
    await page.waitForFunction((b) => window.__rtl.lessons.find((l) => l.id === 'car').step !== b, before, { timeout: PAGE_TIMEOUT });
    const traced = rtl.segment(new Float64Array(s.points), { step: s.params.step, lowerBound: s.params.lowerBound, upperBound: s.params.upperBound, trace: true }).trace;
    const step = (await page.evaluate(() => window.__rtl.lessons.find((l) => l.id === 'car'))).step;
    assert.equal(step, traced.findIndex((e) => e.i === 44));
    assert.match(await page.textContent('#lesson-text'), /Point 44\b/);
  });

  test('no console errors', async () => {
    assert.deepEqual(await page.evaluate(() => window.__rtl.errors), []);
    assert.deepEqual(problems, []);
  });
});
