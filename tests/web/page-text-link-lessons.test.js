// Text and figure linked both ways in every 2D lesson whose text names a number the figure draws (IA, FTLS, AFTLS,
// ITLS, RW, the TLS fit, compare, CAR's threshold step; DP and CAR's comparison: page-text-link.test.js). For each lesson, at steps found in the
// package's own trace (recomputed here in Node from the lesson's chain and parameters): the text's quantities are
// the expected ones and carry the trace's numbers; hovering each lights the figure item(s) of that name; hovering
// such an item in the figure marks exactly those words.
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
const words = (page) => page.$$eval('#lesson-text [data-q]', (els) => [...new Set(els.map((e) => e.dataset.q))].sort());
const textOf = (page, q) => page.textContent(`#lesson-text [data-q="${q}"]`);

// World points on an item where the pointer is on it (the figure's hit test: on a point, a line, a rim, a strip).
function candidates(it) {
  const out = [];
  if (it.type === 'points') for (let i = 0; i + 1 < it.xy.length; i += 2) out.push([it.xy[i], it.xy[i + 1]]);
  if (it.type === 'marker' || it.type === 'label') out.push([it.x, it.y]);
  if (it.type === 'segments') {
    for (let i = 0; i + 3 < it.xy.length; i += 4) {
      const [x0, y0, x1, y1] = it.xy.slice(i, i + 4), l = Math.hypot(x1 - x0, y1 - y0) || 1, mx = (x0 + x1) / 2, my = (y0 + y1) / 2;
      for (const t of [0.5, 0.3, 0.7]) out.push([x0 + t * (x1 - x0), y0 + t * (y1 - y0)]);
      // a line drawn far beyond the view: places near its middle
      for (const d of [0.1, 0.2, 0.4, 0.7, 1, 1.5].flatMap((v) => [v, -v])) if (Math.abs(d) < l / 2) out.push([mx + d * (x1 - x0) / l, my + d * (y1 - y0) / l]);
    }
  }
  if (it.type === 'circle') for (let a = 0; a < 16; a++) out.push([it.x + it.r * Math.cos(a * Math.PI / 8), it.y + it.r * Math.sin(a * Math.PI / 8)]);
  if (it.type === 'strip') {
    const l = Math.hypot(it.x1 - it.x0, it.y1 - it.y0);
    for (const d of [0.05, 0.1, 0.2, 0.3, 0.5]) if (d < l) out.push([it.x0 + (it.x1 - it.x0) * d / l, it.y0 + (it.y1 - it.y0) * d / l]);
  }
  return out;
}

// Both directions for every quantity of the text at the current step; `expected`: the names the text must link.
async function checkBothWays(page, label, expected) {
  assert.deepEqual(await words(page), [...expected].sort(), `${label}: linked quantities`);
  const items = await page.evaluate(() => window.__rtl.figureQuantities());
  const canvas = await page.locator('#canvas').boundingBox();
  for (const q of expected) {
    const mine = items.filter((it) => it.q === q);
    assert.ok(mine.length > 0, `${label}: the figure draws "${q}"`);
    // text → figure
    await page.hover(`#lesson-text [data-q="${q}"]`);
    assert.equal(await highlighted(page), q, `${label}: hovering the words of "${q}"`);
    await page.mouse.move(2, 2);
    assert.equal(await highlighted(page), null);
    // figure → text: the first place on the item (inside the canvas) that the hit test gives to this quantity
    let hit = false;
    for (const [x, y] of mine.flatMap(candidates)) {
      const at = await page.evaluate(([a, b]) => window.__rtl.clientPoint(a, b), [x, y]);
      if (at.x < canvas.x + 2 || at.y < canvas.y + 2 || at.x > canvas.x + canvas.width - 2 || at.y > canvas.y + canvas.height - 2) continue;
      await page.mouse.move(at.x, at.y);
      if (await highlighted(page) !== q) continue;
      const hot = await page.$$eval('#lesson-text .hot', (els) => [...new Set(els.map((e) => e.dataset.q))]);
      assert.deepEqual(hot, [q], `${label}: hovering "${q}" in the figure marks its words only`);
      hit = true;
      break;
    }
    assert.ok(hit, `${label}: "${q}" can be hovered in the figure`);
    await page.mouse.move(2, 2);
    await page.waitForFunction(() => !document.querySelector('#lesson-text .hot'), null, { timeout: PAGE_TIMEOUT });
  }
}

describe('text and figure linked in every 2D lesson', { timeout: 300000 }, () => {
  let page, problems, close, rtl;
  before(async () => {
    rtl = await init();
    ({ page, problems, close } = await openDemoPage('/web/#ia'));
    await page.setViewportSize({ width: 1280, height: 800 });
  });
  after(() => close?.());

  test('IA: a comparison\'s current point, distance and threshold', async () => {
    await openLesson(page, 'ia');
    const s = await page.evaluate(() => window.__rtl.finalState());
    const seg = new rtl.StreamSegmenter({ dim: 2, step: s.params.step, lowerBound: s.params.lowerBound, upperBound: s.params.upperBound, scaling: s.params.scaling, trace: true });
    let trace;
    try { seg.addPoints(new Float64Array(s.points)); seg.flush(); trace = seg.takeTrace(); } finally { seg.dispose(); }
    const k = trace.findIndex((e) => e.kind === 'compare' && e.i >= 36);
    assert.ok(k >= 0);
    await scrubTo(page, 'ia', k);
    const e = trace[k];
    assert.equal(await textOf(page, 'distance'), `distance ${e.distance.toFixed(3)} m`);
    assert.equal(await textOf(page, 'threshold'), `threshold ${e.threshold.toFixed(3)} m`);
    assert.equal(await textOf(page, 'current'), String(e.i));
    const circle = (await page.evaluate(() => window.__rtl.figureQuantities())).find((it) => it.q === 'threshold');
    assert.ok(Math.abs(circle.r - e.threshold) < 1e-12 && circle.x === s.points[2 * e.i] && circle.y === s.points[2 * e.i + 1]);
    await checkBothWays(page, 'IA compare', ['current', 'distance', 'threshold']);
    const t = trace.findIndex((x) => x.kind === 'threshold');
    await scrubTo(page, 'ia', t);
    await checkBothWays(page, 'IA threshold', ['current', 'threshold']);
  });

  test('CAR: a point\'s threshold event names the point and its threshold', async () => {
    await openLesson(page, 'car');
    const s = await page.evaluate(() => window.__rtl.finalState());
    const { trace } = rtl.segment(new Float64Array(s.points), { step: s.params.step, lowerBound: s.params.lowerBound, upperBound: s.params.upperBound, trace: true });
    const k = trace.findIndex((e) => e.kind === 'threshold' && e.i === 38);
    await scrubTo(page, 'car', k);
    assert.equal(await textOf(page, 'threshold'), `the threshold is ${trace[k].threshold.toFixed(3)} m`);
    await checkBothWays(page, 'CAR threshold', ['current', 'threshold']);
    const c = trace.findIndex((e) => e.kind === 'compare' && e.i === 39 && e.j === 38);
    await scrubTo(page, 'car', c);
    await checkBothWays(page, 'CAR compare', ['current', 'distance', 'threshold']);
  });

  for (const id of ['ftls', 'aftls']) {
    test(`${id.toUpperCase()}: a trial range, a corner's crossing against δ`, async () => {
      await openLesson(page, id);
      const s = await page.evaluate(() => window.__rtl.finalState());
      const { trace } = rtl.vectorize(new Float64Array(s.chain), { method: id, sigma: s.params.sigma, delta: s.params.delta, split: s.params.split, trace: true });
      const trial = trace.findIndex((e) => e.kind === 'trial');
      await scrubTo(page, id, trial);
      const e = trace[trial];
      assert.match(await textOf(page, 'trial'), new RegExp(`^points ${e.first}–${e.end - 1} \\(${e.end - e.first} points\\)$`));
      const pts = (await page.evaluate(() => window.__rtl.figureQuantities())).find((it) => it.q === 'trial');
      assert.deepEqual(pts.xy, s.chain.slice(2 * e.first, 2 * e.end));
      await checkBothWays(page, `${id} trial`, ['trial']);
      const corner = trace.findIndex((c) => c.kind === 'corner' && Number.isFinite(c.crossingDistance));
      assert.ok(corner >= 0, 'the excerpt has a corner check');
      await scrubTo(page, id, corner);
      const c = trace[corner];
      assert.equal(await textOf(page, 'crossing'), `${c.crossingDistance.toFixed(3)} m from there`);
      const circles = (await page.evaluate(() => window.__rtl.figureQuantities())).filter((it) => it.type === 'circle');
      assert.deepEqual(circles.map((it) => [it.q, it.r]), [['delta', c.delta], ['crossing', c.crossingDistance]]);
      await checkBothWays(page, `${id} corner`, ['boundary', 'crossing', 'delta']);
    });
  }

  test('FTLS, strict mode and δ too small: the failure\'s crossing and δ circles', async () => {
    await page.evaluate(() => { location.hash = 'ftls?delta=0.05&split=0'; });
    await page.waitForFunction(() => window.__rtl.finalState()?.params?.delta === 0.05 && window.__rtl.finalState().untraced?.failure, null, { timeout: PAGE_TIMEOUT });
    const s = await page.evaluate(() => window.__rtl.finalState());
    const { trace } = rtl.vectorize(new Float64Array(s.chain), { method: 'ftls', sigma: s.params.sigma, delta: 0.05, split: false, trace: true });
    const k = trace.findIndex((e) => e.kind === 'infeasible');
    assert.ok(k >= 0);
    await scrubTo(page, 'ftls', k);
    assert.equal(await textOf(page, 'crossing'), `${trace[k].crossingDistance.toFixed(2)} m from that boundary (red circle)`);
    await checkBothWays(page, 'ftls failure', ['crossing', 'delta']);
  });

  test('ITLS: the point added to the run, and the point that closes it', async () => {
    await openLesson(page, 'itls');
    const s = await page.evaluate(() => window.__rtl.finalState());
    const { trace } = rtl.vectorize(new Float64Array(s.chain), { method: 'itls', sigma: s.params.sigma, trace: true });
    const add = trace.findIndex((e) => e.kind === 'add' && e.tested && e.fits);
    await scrubTo(page, 'itls', add);
    assert.equal(await textOf(page, 'added'), String(trace[add].index));
    await checkBothWays(page, 'itls add', ['added', 'run']);
    const close = trace.findIndex((e) => e.kind === 'close' && !e.atEnd);
    await scrubTo(page, 'itls', close);
    assert.equal(await textOf(page, 'next'), `point ${trace[close].end}`);
    const next = (await page.evaluate(() => window.__rtl.figureQuantities())).find((it) => it.q === 'next');
    assert.deepEqual([next.x, next.y], s.chain.slice(2 * trace[close].end, 2 * trace[close].end + 2));
    await checkBothWays(page, 'itls close', ['next', 'run']);
    const seg = trace.findIndex((e) => e.kind === 'segment');
    await scrubTo(page, 'itls', seg);
    await checkBothWays(page, 'itls segment', ['segment']);
  });

  test('RW: the strip\'s key point, its ε, and the distance of the point that leaves it', async () => {
    await openLesson(page, 'rw');
    const s = await page.evaluate(() => window.__rtl.finalState());
    const { trace } = rtl.vectorize(new Float64Array(s.chain), { method: 'rw', epsilon: s.params.epsilon, trace: true });
    const strip = trace.findIndex((e) => e.kind === 'strip');
    await scrubTo(page, 'rw', strip);
    await checkBothWays(page, 'rw strip', ['epsilon', 'key', 'through']);
    const exit = trace.findIndex((e) => e.kind === 'exit');
    await scrubTo(page, 'rw', exit);
    const e = trace[exit];
    assert.equal(await textOf(page, 'distance'), `${e.distance.toFixed(3)} m from the strip's axis`);
    // the drawn distance is as long as the trace says
    const d = (await page.evaluate(() => window.__rtl.figureQuantities())).find((it) => it.q === 'distance').xy;
    assert.ok(Math.abs(Math.hypot(d[2] - d[0], d[3] - d[1]) - e.distance) < 1e-9, `drawn ${Math.hypot(d[2] - d[0], d[3] - d[1])}, traced ${e.distance}`);
    await checkBothWays(page, 'rw exit', ['distance', 'epsilon', 'exit']);
  });

  test('TLS fit: centroid, axes, normal, residuals', async () => {
    await openLesson(page, 'tls-fit');
    const want = [['centroid'], ['major', 'minor'], ['line', 'normal'], ['ols', 'residuals', 'vertical'], ['residuals']];
    for (let k = 0; k < want.length; k++) {
      await scrubTo(page, 'tls-fit', k);
      await checkBothWays(page, `tls-fit step ${k + 1}`, want[k]);
    }
    const s = await page.evaluate(() => window.__rtl.finalState());
    const fit = rtl.fitLine(new Float64Array(s.points));
    await scrubTo(page, 'tls-fit', 0);
    assert.equal(await textOf(page, 'centroid'), `their centroid (×) = (${fit.centroid[0].toFixed(3)}, ${fit.centroid[1].toFixed(3)}) m`);
  });

  test('compare: the method\'s segments and vertices', async () => {
    await openLesson(page, 'compare');
    for (const k of [0, 3]) {
      await scrubTo(page, 'compare', k);
      const s = await page.evaluate(() => window.__rtl.finalState());
      assert.equal(await textOf(page, 'vertices'), `${s.rows[k].vertices} vertices`);
      const markers = (await page.evaluate(() => window.__rtl.figureQuantities())).filter((it) => it.q === 'vertices');
      assert.equal(new Set(markers.map((it) => `${it.x},${it.y}`)).size, s.rows[k].vertices);
      await checkBothWays(page, `compare ${s.rows[k].method}`, ['segments', 'vertices']);
    }
  });

  test('no console errors', async () => {
    assert.deepEqual(await page.evaluate(() => window.__rtl.errors), []);
    assert.deepEqual(problems, []);
  });
});
