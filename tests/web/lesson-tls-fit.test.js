// The TLS line-fit lesson (web/lessons/tls-fit.js) in Chromium: its numbers are the package's fitLine on the points
// it shows (checked in Node), moving a point with the keyboard changes the fit, the steps walk centroid -> RMS,
// an invalid σ is marked; a scan the user opened (a dropped CARMEN log, a CSV) gives the lesson a straight run of that
// scan, checked against the package in Node, and its text names the file; a scan with no such run falls back to the
// bundled wall and says so; no console errors. Screenshots at 1280x800 and 390x844.
import { after, before, describe, test } from 'node:test';
import assert from 'node:assert/strict';
import { mkdirSync, readFileSync } from 'node:fs';
import { join } from 'node:path';
import init from 'rtl-wasm';
import { DATA, PAGE_TIMEOUT, REPO, loadLog, openDemoPage, openLesson, returnsOf, xyOf } from './helpers.js';

const PATH = '/web/#tls-fit';
const SHOTS = join(REPO, 'build', 'test-output', 'screenshots');
const lessonState = (page) => page.evaluate(() => window.__rtl.finalState());
const entryOf = (page) => page.evaluate(() => window.__rtl.lessons.find((l) => l.id === 'tls-fit'));
// the player's slider is 1-based
async function goStep(page, k) {
  await page.fill('[data-act="scrub"]', String(k + 1));
  await page.dispatchEvent('[data-act="scrub"]', 'input');
}

// Drops a file (name, text) on the page as a user dragging it from the desktop.
async function drop(page, name, content) {
  const bytes = Array.from(Buffer.from(content));
  const dt = await page.evaluateHandle(([n, b]) => { const t = new DataTransfer(); t.items.add(new File([new Uint8Array(b)], n)); return t; }, [name, bytes]);
  await page.dispatchEvent('body', 'drop', { dataTransfer: dt });
}
const SEG = { step: 3, lowerBound: 0.1, upperBound: 0.5 };

// The lesson's points on a chosen scan (`points`, the package's reading of it): consecutive points of one of the
// package's clusters, exactly the scan's coordinates, within σ of the package's own line, and as long as the longest
// range FTLS fits on that scan (up to the lesson's 12).
function checkRun(rtl, points, s) {
  const n = s.indices.length;
  assert.ok(n >= 4 && n <= 12, `${n} points`);
  assert.equal(s.points.length, 2 * n);
  s.indices.forEach((k, i) => {
    assert.equal(s.points[2 * i], points[2 * k]);
    assert.equal(s.points[2 * i + 1], points[2 * k + 1]);
  });
  const cluster = rtl.segment(points, SEG).clusters.find((c) => c.indices.includes(s.indices[0]));
  const at = Array.from(cluster.indices).indexOf(s.indices[0]);
  assert.deepEqual(Array.from(cluster.indices.slice(at, at + n)), s.indices, 'consecutive in one cluster');
  const f = rtl.fitLine(new Float64Array(s.points));
  assert.ok(f.rms < 0.03, `a line fits them: rms ${f.rms}`);
  assert.ok(Math.abs(s.fit.rms - f.rms) < 1e-12);
  const r = rtl.segmentAndVectorize(points, { minPoints: 4, segment: SEG, vectorize: { method: 'ftls', sigma: 0.03 } });
  let longest = 0;
  for (let j = 0; j < r.indices.length; j += 2) longest = Math.max(longest, r.indices[j + 1] - r.indices[j]);
  assert.equal(n, Math.min(12, longest), 'the longest fitted range');
}

describe('TLS line-fit lesson in Chromium', { timeout: 180000 }, () => {
  let page, problems, close, rtl;
  before(async () => { rtl = await init(); ({ page, problems, close } = await openDemoPage(PATH)); });
  after(() => close?.());

  test('it starts on Intel scan 28, beams 124-131, read independently here', async () => {
    const s = await lessonState(page);
    assert.deepEqual(s.excerpt, { dataset: 'intel', scan: 28, firstBeam: 124, lastBeam: 131 });
    const scan = loadLog('intel')[28];
    const xy = xyOf(scan, returnsOf(scan, 124, 131));
    assert.equal(s.points.length, 16);
    s.points.forEach((v, i) => assert.ok(Math.abs(v - xy[i]) < 1e-4, `coordinate ${i}: ${v} vs ${xy[i]}`));
  });

  test("the lesson's fit is the package's fitLine in Node on the same points", async () => {
    const s = await lessonState(page);
    const f = rtl.fitLine(new Float64Array(s.points));
    assert.ok(Math.abs(s.fit.rms - f.rms) < 1e-12);
    assert.ok(Math.abs(s.fit.offset - f.offset) < 1e-12);
    [0, 1].forEach((i) => {
      assert.ok(Math.abs(s.fit.normal[i] - f.normal[i]) < 1e-12);
      assert.ok(Math.abs(s.fit.centroid[i] - f.centroid[i]) < 1e-12);
    });
    assert.ok(s.fit.rms > 0.005 && s.fit.rms < 0.03, `a real wall: rms ${s.fit.rms}`);
    // the OLS comparison is vertical: its slope is the y-on-x regression of the same points
    const n = 8, mx = s.points.filter((_, i) => i % 2 === 0).reduce((a, b) => a + b) / n;
    const my = s.points.filter((_, i) => i % 2 === 1).reduce((a, b) => a + b) / n;
    let sxx = 0, sxy = 0;
    for (let i = 0; i < n; i++) { sxx += (s.points[2 * i] - mx) ** 2; sxy += (s.points[2 * i] - mx) * (s.points[2 * i + 1] - my); }
    assert.ok(Math.abs(s.ols.slope - sxy / sxx) < 1e-9 * Math.abs(sxy / sxx));
  });

  test('stepping shows centroid, spread, normal, residuals, RMS vs σ with the numbers of the fit', async () => {
    const entry = await entryOf(page);
    assert.deepEqual([entry.id, entry.steps], ['tls-fit', 5]);
    const s = await lessonState(page);
    const texts = [];
    for (let k = 0; k < 5; k++) {
      if (k > 0) await page.click('[data-act="forward"]');
      texts.push(await page.textContent('#lesson-text'));
    }
    assert.match(texts[0], /centroid/);
    assert.ok(texts[0].includes(s.fit.centroid[0].toFixed(3)));
    assert.match(texts[1], /covariance/);
    assert.match(texts[2], /normal/);
    assert.ok(texts[2].includes(s.fit.normal[0].toFixed(3)));
    assert.match(texts[3], /Ordinary least squares/);
    // the bundled wall: steep in the frame, vertical residuals many times the orthogonal ones
    const deg = Math.atan2(Math.abs(s.fit.normal[0]), Math.abs(s.fit.normal[1])) * 180 / Math.PI;
    assert.ok(texts[3].includes(`runs at ${deg.toFixed(1)}° to the x axis`), texts[3]);
    assert.match(texts[3], /wrong model/);
    assert.ok(texts[4].includes(`${(s.fit.rms * 1000).toFixed(1)} mm`));
    assert.match(texts[4], /below σ/);
    assert.equal((await lessonState(page)).step, 4);
  });

  test('moving a point with the keyboard changes the fit, again equal to fitLine', async () => {
    const before = await lessonState(page);
    await page.focus('#canvas');
    await page.keyboard.press(']');                                  // select the second point
    for (let i = 0; i < 4; i++) await page.keyboard.press('Shift+ArrowRight');   // 4 x 10 cm off the wall
    const s = await lessonState(page);
    assert.equal(s.selected, 1);
    assert.ok(Math.abs(s.points[2] - (before.points[2] + 0.4)) < 1e-9);
    assert.ok(s.fit.rms > 2 * before.fit.rms, `rms ${before.fit.rms} -> ${s.fit.rms}`);
    const f = rtl.fitLine(new Float64Array(s.points));
    assert.ok(Math.abs(s.fit.rms - f.rms) < 1e-12 && Math.abs(s.fit.offset - f.offset) < 1e-12);
    assert.match(await page.textContent('#lesson-text'), /above σ/);
    await page.click('[data-act="reset-points"]');
    assert.deepEqual((await lessonState(page)).points, before.points);
  });

  test('dragging a point with the mouse moves it', async () => {
    const before = await lessonState(page);
    const { x, y } = await page.evaluate(([px, py]) => window.__rtl.clientPoint(px, py), [before.points[0], before.points[1]]);
    await page.mouse.move(x, y);
    await page.mouse.down();
    await page.mouse.move(x - 30, y, { steps: 4 });
    await page.mouse.up();
    const s = await lessonState(page);
    assert.ok(s.points[0] < before.points[0] - 0.01, `x ${before.points[0]} -> ${s.points[0]}`);
    await page.click('[data-act="reset-points"]');
  });

  test('an invalid σ is marked and explained', async () => {
    await page.fill('input[name="sigma"]', '0');
    assert.equal(await page.getAttribute('input[name="sigma"]', 'aria-invalid'), 'true');
    assert.match(await page.textContent('.field[data-key="sigma"] .field-error'), /σ must be/);
    await page.fill('input[name="sigma"]', '0.005');
    assert.equal(await page.getAttribute('input[name="sigma"]', 'aria-invalid'), null);
    assert.equal((await lessonState(page)).accepted, false);
    await page.fill('input[name="sigma"]', '0.03');
  });

  test('screenshots at 1280x800 and 390x844', async () => {
    mkdirSync(SHOTS, { recursive: true });
    await page.setViewportSize({ width: 1280, height: 800 });
    await page.focus('#canvas');
    await page.keyboard.press('Shift+ArrowRight');
    await goStep(page, 4);
    await page.screenshot({ path: join(SHOTS, 'lesson-tls-fit-1280x800.png') });
    await page.setViewportSize({ width: 390, height: 844 });
    await page.dispatchEvent('[data-act="scrub"]', 'input');
    await page.screenshot({ path: join(SHOTS, 'lesson-tls-fit-390x844.png'), fullPage: true });
    assert.ok(await page.evaluate(() => document.documentElement.scrollWidth) <= 390);
    await page.waitForFunction(() => window.__rtl.ready, null, { timeout: PAGE_TIMEOUT });
  });

  test('a dropped CARMEN log: a straight run of the chosen scan, named in the text', async () => {
    const text = readFileSync(join(DATA, 'csail.log'), 'utf8');
    const scans = rtl.readCarmenLog(text);
    const excerpt = (await lessonState(page)).points;
    await drop(page, 'my-run.log', text);
    await page.waitForFunction(() => window.__rtl.source()?.scan === 0, null, { timeout: PAGE_TIMEOUT });
    const { dataset } = await page.evaluate(() => window.__rtl.source());
    for (const k of [0, 7]) {
      if (k) {
        await page.selectOption('#scan-chooser', `${dataset}:${k}`);
        await page.waitForFunction((want) => window.__rtl.source()?.scan === want, k, { timeout: PAGE_TIMEOUT });
      }
      await openLesson(page, 'tls-fit');
      await page.waitForFunction((want) => window.__rtl.finalState()?.excerpt.scan === want, k, { timeout: PAGE_TIMEOUT });
      const s = await lessonState(page);
      assert.equal(s.origin, 'source');
      assert.deepEqual([s.excerpt.dataset, s.excerpt.scan], [dataset, k]);
      assert.notDeepEqual(s.points, excerpt);
      checkRun(rtl, scans[k].points, s);
      const where = `my-run.log, scan ${k}, beams ${s.indices[0]}–${s.indices[s.indices.length - 1]}`;
      const controls = await page.textContent('#lesson-controls');
      assert.ok(controls.includes(where), controls);
      assert.match(controls, /Your chosen scan/);
      assert.doesNotMatch(controls, /Intel/);
      await goStep(page, 0);
      const first = await page.textContent('#lesson-text');
      assert.ok(first.includes(`The ${s.indices.length} points are ${where}`), first);
      assert.doesNotMatch(first, /Intel/);
      assert.equal(await page.textContent('select[name="point"] option:last-child'), `beam ${s.indices[s.indices.length - 1]}`);
      await goStep(page, 3);
      const deg = Math.atan2(Math.abs(s.fit.normal[0]), Math.abs(s.fit.normal[1])) * 180 / Math.PI;
      assert.ok((await page.textContent('#lesson-text')).includes(`This wall runs at ${deg.toFixed(1)}° to the x axis`));
    }
  });

  test('a CSV: its run; a CSV with no straight run of 4 points: the bundled wall, and the note says why', async () => {
    const scan = rtl.readCarmenLog(readFileSync(join(DATA, 'intel.log'), 'utf8'))[17];
    const xy = [];
    for (let i = 0; i < scan.points.length; i += 2) if (Number.isFinite(scan.points[i])) xy.push([scan.points[i], scan.points[i + 1]]);
    await drop(page, 'room.csv', `x,y\n${xy.map(([x, y]) => `${x},${y}`).join('\n')}\n`);
    await page.waitForFunction(() => /room\.csv: 1 point set read/.test(document.querySelector('#open-message').textContent), null, { timeout: PAGE_TIMEOUT });
    await openLesson(page, 'tls-fit');
    await page.waitForFunction(() => window.__rtl.finalState()?.origin === 'source' && window.__rtl.finalState().excerpt.dataset !== 'intel' &&
      document.querySelector('#lesson-controls').textContent.includes('room.csv'), null, { timeout: PAGE_TIMEOUT });
    const s = await lessonState(page);
    checkRun(rtl, new Float64Array(xy.flat()), s);
    assert.ok((await page.textContent('#lesson-controls')).includes(`room.csv, point set 0, points ${s.indices[0]}–`));
    assert.equal(await page.textContent('select[name="point"] option'), `point ${s.indices[0]}`);

    // three points a few metres apart: no cluster, no run; the lesson keeps its own wall and says so
    await drop(page, 'sparse.csv', 'x,y\n1,0\n3,2\n5,-1\n');
    await page.waitForFunction(() => document.querySelector('#lesson-controls').textContent.includes('sparse.csv'), null, { timeout: PAGE_TIMEOUT });
    const f = await lessonState(page);
    assert.equal(f.origin, 'fallback');
    assert.deepEqual(f.excerpt, { dataset: 'intel', scan: 28, firstBeam: 124, lastBeam: 131 });
    const note = await page.textContent('#lesson-controls');
    assert.match(note, /sparse\.csv, point set 0 has no straight run of 4 or more points/);
    assert.match(note, /Intel Research Lab, scan 28, beams 124–131/);
    await page.selectOption('#scan-chooser', '');
    await page.waitForFunction(() => window.__rtl.source() === null, null, { timeout: PAGE_TIMEOUT });
  });

  test('no console errors', () => assert.deepEqual(problems, []));
});
