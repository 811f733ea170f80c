// "Your turn": off by default; switched on, the player stops before a decisive step and asks; the answer is judged
// with the package's trace numbers (checked here against the same call in Node), and the session keeps the score.
import { after, before, describe, test } from 'node:test';
import assert from 'node:assert/strict';
import { mkdirSync } from 'node:fs';
import { join } from 'node:path';
import init from 'rtl-wasm';
import { PAGE_TIMEOUT, SCREENSHOTS, openDemoPage, openLesson } from './helpers.js';

const predictState = (page) => page.evaluate(() => window.__rtl.predict());
const stepOf = (page, id) => page.evaluate((h) => window.__rtl.lessons.find((l) => l.id === h).step, id);

// The player's first step (the button is disabled when it is there already).
async function toFirst(page, id) {
  if (await stepOf(page, id) > 0) await page.click('#player [data-act="first"]');
  await page.waitForFunction((h) => window.__rtl.lessons.find((l) => l.id === h).step === 0, id, { timeout: PAGE_TIMEOUT });
}

// Presses "Step ▶" until the page asks a question; resolves with the question's step (0-based).
async function forwardToQuestion(page, max = 80) {
  for (let i = 0; i < max; i++) {
    const q = (await predictState(page)).step;
    if (q !== null) return q;
    await page.click('#player [data-act="forward"]');
  }
  throw new Error('no question within reach');
}

describe('your turn: predict, then reveal', { timeout: 240000 }, () => {
  let page, problems, close, rtl;
  before(async () => {
    rtl = await init();
    mkdirSync(SCREENSHOTS, { recursive: true });
    ({ page, problems, close } = await openDemoPage('/web/#dp'));
    await page.setViewportSize({ width: 1280, height: 800 });
    await page.evaluate(() => sessionStorage.clear());
  });
  after(() => close?.());

  test('off by default: the player steps through without asking', async () => {
    await openLesson(page, 'dp');
    assert.equal(await page.isChecked('#your-turn'), false);
    assert.equal(await page.isVisible('#predict'), false);
    await toFirst(page, 'dp');
    for (let i = 0; i < 6; i++) await page.click('#player [data-act="forward"]');
    assert.equal(await stepOf(page, 'dp'), 6);
    assert.equal((await predictState(page)).step, null);
  });

  test('Douglas–Peucker: the right point, then a wrong one; the verdicts quote the trace', async () => {
    await page.click('#your-turn');
    await toFirst(page, 'dp');
    const s = await page.evaluate(() => window.__rtl.finalState());
    const { trace } = rtl.vectorize(new Float64Array(s.chain), { method: 'dp', epsilon: s.params.epsilon, trace: true });
    let q = await forwardToQuestion(page);
    assert.equal(trace[q].kind, 'range');
    assert.equal(trace[q].split, true);
    assert.equal(await stepOf(page, 'dp'), q - 1, 'stopped before the split');
    await page.screenshot({ path: join(SCREENSHOTS, 'predict-dp-question-1280x800.png') });
    // forward is held until the answer
    await page.click('#player [data-act="forward"]');
    assert.equal(await stepOf(page, 'dp'), q - 1);
    const click = async (i) => {
      const at = await page.evaluate(([x, y]) => window.__rtl.clientPoint(x, y), [s.chain[2 * i], s.chain[2 * i + 1]]);
      await page.mouse.click(at.x, at.y);
    };
    await click(trace[q].farthest);
    await page.waitForFunction((k) => window.__rtl.lessons.find((l) => l.id === 'dp').step === k, q, { timeout: PAGE_TIMEOUT });
    let verdict = await page.textContent('#predict');
    await page.screenshot({ path: join(SCREENSHOTS, 'predict-dp-right-1280x800.png') });
    assert.match(verdict, /^Right\./);
    assert.ok(verdict.includes(`${trace[q].distance.toFixed(3)} m`), verdict);
    const right = (await page.evaluate(() => window.__rtl.figureOverlay())).filter((m) => m.verdict);
    assert.deepEqual(right.map((m) => [m.type, m.verdict]), [['marker', 'answer'], ['label', 'answer']], 'a right pick: one ring, no cross');
    assert.deepEqual((await predictState(page)).score, { right: 1, asked: 1 });

    q = await forwardToQuestion(page);
    const e = trace[q];
    assert.equal(e.split, true);
    // a wrong interior point, far enough from the right one to be clicked alone
    const wrong = e.farthest - e.first > e.last - e.farthest ? e.first + 1 : e.last - 1;
    assert.notEqual(wrong, e.farthest);
    await click(wrong);
    await page.waitForFunction((k) => window.__rtl.lessons.find((l) => l.id === 'dp').step === k, q, { timeout: PAGE_TIMEOUT });
    verdict = await page.textContent('#predict');
    assert.match(verdict, /^Not quite\./);
    // how far the pick was from the answer, in metres (the chain's own coordinates)
    const off = Math.hypot(s.chain[2 * wrong] - s.chain[2 * e.farthest], s.chain[2 * wrong + 1] - s.chain[2 * e.farthest + 1]);
    assert.ok(off > 0.01, `the wrong pick is a distinct point (${off} m away)`);
    assert.ok(verdict.includes(`You picked point ${wrong}, ${off.toFixed(3)} m from point ${e.farthest}.`), verdict);
    assert.ok(verdict.includes(`point ${e.farthest} farthest from the chord ${e.first}–${e.last}, at ${e.distance.toFixed(3)} m`), verdict);
    // the figure marks the pick (a cross) and the right answer (a ring) apart, the answer with the trace's distance
    const marks = await page.evaluate(() => window.__rtl.figureOverlay());
    const of = (kind, type) => marks.filter((m) => m.verdict === kind && m.type === type);
    assert.equal(of('pick', 'marker').length, 1);
    assert.equal(of('pick', 'marker')[0].shape, 'x');
    assert.deepEqual([of('pick', 'marker')[0].x, of('pick', 'marker')[0].y], [s.chain[2 * wrong], s.chain[2 * wrong + 1]]);
    assert.equal(of('answer', 'marker').length, 1);
    assert.notEqual(of('answer', 'marker')[0].shape, 'x');
    assert.deepEqual([of('answer', 'marker')[0].x, of('answer', 'marker')[0].y], [s.chain[2 * e.farthest], s.chain[2 * e.farthest + 1]]);
    assert.equal(of('pick', 'label')[0].text, `your pick: ${wrong}, ${off.toFixed(3)} m from point ${e.farthest}`);
    assert.equal(of('answer', 'label')[0].text, `farthest: ${e.farthest}, ${e.distance.toFixed(3)} m > ε`);
    const labels = await page.evaluate(() => window.__rtl.figureLabels());
    assert.ok(labels.some((l) => l.text === `your pick: ${wrong}, ${off.toFixed(3)} m from point ${e.farthest}`) && labels.some((l) => l.text.startsWith(`farthest: ${e.farthest}`)), 'both drawn');
    await page.screenshot({ path: join(SCREENSHOTS, 'predict-dp-wrong-1280x800.png') });
    // the next step's drawing clears them
    await page.click('#player [data-act="forward"]');
    await page.waitForFunction(() => !window.__rtl.figureOverlay().some((m) => m.verdict), null, { timeout: PAGE_TIMEOUT });
    assert.deepEqual((await predictState(page)).score, { right: 1, asked: 2 });
  });

  test('Reumann–Witkam: a wrong pick says how far it lies from the first point outside the strip', async () => {
    await openLesson(page, 'rw');
    await toFirst(page, 'rw');
    const s = await page.evaluate(() => window.__rtl.finalState());
    const { trace } = rtl.vectorize(new Float64Array(s.chain), { method: 'rw', epsilon: s.params.epsilon, trace: true });
    const q = await forwardToQuestion(page);
    const e = trace[q];
    assert.equal(e.kind, 'exit');
    const n = s.chain.length / 2;
    // a point after the exit (else the one before it), clicked where it is drawn
    const wrong = e.index + 2 < n ? e.index + 2 : e.index - 1;
    const at = await page.evaluate(([x, y]) => window.__rtl.clientPoint(x, y), [s.chain[2 * wrong], s.chain[2 * wrong + 1]]);
    await page.mouse.click(at.x, at.y);
    await page.waitForFunction((k) => window.__rtl.lessons.find((l) => l.id === 'rw').step === k, q, { timeout: PAGE_TIMEOUT });
    const verdict = await page.textContent('#predict');
    assert.match(verdict, /^Not quite\./);
    const off = Math.hypot(s.chain[2 * wrong] - s.chain[2 * e.index], s.chain[2 * wrong + 1] - s.chain[2 * e.index + 1]);
    assert.ok(off > 0.01, `a distinct point (${off} m away)`);
    assert.ok(verdict.includes(`You picked point ${wrong}, ${off.toFixed(3)} m from point ${e.index}.`), verdict);
    const label = (await page.evaluate(() => window.__rtl.figureOverlay())).find((m) => m.verdict === 'pick' && m.type === 'label');
    assert.equal(label.text, `your pick: ${wrong} (${wrong < e.index ? 'inside the strip' : 'after the exit'}), ${off.toFixed(3)} m from point ${e.index}`);
    const score = (await predictState(page)).score;
    assert.equal(score.asked - score.right, 2, 'two wrong answers so far (DP\'s and this one)');
  });

  test('CAR: "do these two points link?" answered wrong, with the distance and the threshold', async () => {
    await openLesson(page, 'car');
    assert.equal(await page.isChecked('#your-turn'), true, 'the switch stays on across lessons');
    const s = await page.evaluate(() => window.__rtl.finalState());
    const { trace } = rtl.segment(new Float64Array(s.points), { step: s.params.step, lowerBound: s.params.lowerBound, upperBound: s.params.upperBound, trace: true });
    const q = await forwardToQuestion(page);
    const e = trace[q];
    assert.equal(e.kind, 'compare');
    await page.click(`#predict button[data-answer="${e.linked ? 'no' : 'yes'}"]`);
    await page.waitForFunction((k) => window.__rtl.lessons.find((l) => l.id === 'car').step === k, q, { timeout: PAGE_TIMEOUT });
    const verdict = await page.textContent('#predict');
    assert.match(verdict, /^Not quite\./);
    assert.ok(verdict.includes(`${e.distance.toFixed(3)} m apart`) && verdict.includes(`threshold ${e.threshold.toFixed(3)} m`), verdict);
    const label = (await page.evaluate(() => window.__rtl.figureOverlay())).find((m) => m.verdict === 'answer' && m.type === 'label');
    assert.equal(label.text, `${e.linked ? 'link' : 'no link'}: ${e.distance.toFixed(3)} m ${e.linked ? '≤' : '>'} ${e.threshold.toFixed(3)} m`);
    assert.deepEqual((await predictState(page)).score, { right: 1, asked: 4 });
  });

  test('FTLS: "does this corner meet within δ?" answered right', async () => {
    await openLesson(page, 'ftls');
    const s = await page.evaluate(() => window.__rtl.finalState());
    const { trace } = rtl.vectorize(new Float64Array(s.chain), { method: 'ftls', sigma: s.params.sigma, delta: s.params.delta, split: s.params.split, trace: true });
    await toFirst(page, 'ftls');
    const q = await forwardToQuestion(page, 200);
    const e = trace[q];
    assert.equal(e.kind, 'corner');
    await page.click(`#predict button[data-answer="${e.ok ? 'yes' : 'no'}"]`);
    await page.waitForFunction((k) => window.__rtl.lessons.find((l) => l.id === 'ftls').step === k, q, { timeout: PAGE_TIMEOUT });
    const verdict = await page.textContent('#predict');
    assert.match(verdict, /^Right\./);
    assert.ok(verdict.includes(`δ = ${e.delta.toFixed(3)} m`), verdict);
    assert.deepEqual((await predictState(page)).score, { right: 2, asked: 5 });
  });

  test('the score lasts the session (a reload keeps it), the switch starts off again', async () => {
    await page.reload();
    await page.waitForFunction(() => window.__rtl?.ready, null, { timeout: PAGE_TIMEOUT });
    assert.deepEqual((await predictState(page)).score, { right: 2, asked: 5 });
    assert.equal(await page.isChecked('#your-turn'), false);
  });

  test('the switch is offered only in lessons that ask questions', async () => {
    for (const [id, asks] of [['compare', false], ['tls-fit', false], ['dp', true], ['itls', false], ['rw', true]]) {
      await openLesson(page, id);
      assert.equal(await page.isVisible('#your-turn'), asks, id);
    }
  });

  test('no console errors', async () => {
    assert.deepEqual(await page.evaluate(() => window.__rtl.errors), []);
    assert.deepEqual(problems, []);
  });
});
