// The "Tracking clusters" lesson (web/lessons/tracking.js) in Chromium, on the real Intel scans: every association
// it shows is what the package's assign() returns in Node for the displayed matrix (and the outlined cells are those
// columns), the matrix is the distances from the predicted positions to the centroids (the centroids recomputed here
// from the log with the package's segment() and the log's pose), every Kalman estimate is the one an independent
// constant-velocity filter written here gives for the same measurements, the numbers are plausible for fixed objects
// seen from a robot turning on the spot, stepping changes the state, the wasm heap does not grow, no console errors.
// Screenshots at 1280x800 and 390x844.
import { after, before, describe, test } from 'node:test';
import assert from 'node:assert/strict';
import { mkdirSync, readFileSync } from 'node:fs';
import { join } from 'node:path';
import init from 'rtl-wasm';
import { PAGE_TIMEOUT, SCREENSHOTS, loadLog, openDemoPage, scanPoints } from './helpers.js';

const state = (page) => page.evaluate(() => window.__rtl.finalState());
const entry = (page) => page.evaluate(() => window.__rtl.lessons.find((l) => l.id === 'tracking'));
async function goStep(page, k) {
  const before = await page.evaluate(() => window.__rtl.revision);
  await page.fill('#player [data-act="scrub"]', String(k + 1));
  await page.dispatchEvent('#player [data-act="scrub"]', 'input');
  await page.waitForFunction(([r, want]) => window.__rtl.revision > r || window.__rtl.lessons.find((l) => l.id === 'tracking').step === want, [before, k], { timeout: PAGE_TIMEOUT });
}
async function setField(page, name, value) {
  const rev = await page.evaluate(() => window.__rtl.revision);
  await page.evaluate(([n, v]) => { const i = document.querySelector(`#lesson-controls input[name="${n}"]`); i.value = String(v); i.dispatchEvent(new Event('input')); }, [name, value]);
  await page.waitForFunction((r) => window.__rtl.revision > r, rev, { timeout: PAGE_TIMEOUT });
}

// Plain constant-velocity Kalman filter (state x, y, vx, vy; position measured), standard form.
const mul = (A, B, n, k, mm) => { const C = new Array(n * mm).fill(0); for (let i = 0; i < n; i++) for (let j = 0; j < mm; j++) for (let l = 0; l < k; l++) C[i * mm + j] += A[i * k + l] * B[l * mm + j]; return C; };
const tr = (A, n, mm) => { const T = new Array(n * mm); for (let i = 0; i < n; i++) for (let j = 0; j < mm; j++) T[j * n + i] = A[i * mm + j]; return T; };
function referenceTrack(updates, p) {
  let x = [updates[0].z[0], updates[0].z[1], 0, 0];
  const s2 = p.sigma ** 2, v2 = p.initialSpeedSigma ** 2;
  let P = [s2, 0, 0, 0, 0, s2, 0, 0, 0, 0, v2, 0, 0, 0, 0, v2];
  const states = [x.slice()];
  for (const u of updates.slice(1)) {
    const dt = u.dt, q = p.accel;
    const A = [1, 0, dt, 0, 0, 1, 0, dt, 0, 0, 1, 0, 0, 0, 0, 1];
    const a = (q * dt ** 3) / 3, b = (q * dt ** 2) / 2, c = q * dt;
    const Q = [a, 0, b, 0, 0, a, 0, b, b, 0, c, 0, 0, b, 0, c];
    x = mul(A, x, 4, 4, 1);
    P = mul(mul(A, P, 4, 4, 4), tr(A, 4, 4), 4, 4, 4).map((v, i) => v + Q[i]);
    if (u.z) {
      const S = [P[0] + s2, P[1], P[4], P[5] + s2], det = S[0] * S[3] - S[1] * S[2];
      const Si = [S[3] / det, -S[1] / det, -S[2] / det, S[0] / det];
      const PHt = [0, 1, 2, 3].flatMap((i) => [P[i * 4], P[i * 4 + 1]]);      // 4x2
      const K = mul(PHt, Si, 4, 2, 2);
      const r = [u.z[0] - x[0], u.z[1] - x[1]];
      x = x.map((v, i) => v + K[2 * i] * r[0] + K[2 * i + 1] * r[1]);
      const KH = [0, 1, 2, 3].flatMap((i) => [K[2 * i], K[2 * i + 1], 0, 0]);
      P = mul(KH.map((v, i) => (i % 5 === 0 ? 1 : 0) - v), P, 4, 4, 4);
    }
    states.push(x.slice());
  }
  return states;
}

describe('tracking lesson in Chromium', { timeout: 300000 }, () => {
  let page, problems, close, rtl, scans;
  before(async () => {
    rtl = await init();
    scans = loadLog('intel');
    ({ page, problems, close } = await openDemoPage('/web/#tracking'));
    await page.setViewportSize({ width: 1280, height: 800 });
    await page.waitForFunction(() => window.__rtl.lessons.find((l) => l.id === 'tracking').steps > 0, null, { timeout: PAGE_TIMEOUT });
  });
  after(() => close?.());

  test('it opens on the first association of Intel scans 2-11: 1 + 3 x 9 steps', async () => {
    const e = await entry(page), s = await state(page);
    assert.deepEqual([s.params.first, s.params.count], [2, 10]);
    assert.equal(e.steps, 28);
    assert.deepEqual(s.kinds.slice(0, 4), ['start', 'predict', 'associate', 'correct']);
    assert.equal(e.step, 2);
    assert.equal(s.kind, 'associate');
    assert.equal(await page.textContent('#player .step-count'), 'step 3 of 28');
  });

  test("the centroids are the package's clusters of the log's scans placed by the log's pose", async () => {
    await goStep(page, 0);
    const s = await state(page);
    const sc = scans[s.scan], pts = scanPoints(sc);
    const { clusters } = rtl.segment(pts, s.params.segment);
    const c = Math.cos(sc.theta), sn = Math.sin(sc.theta);
    const want = clusters.map((k) => Array.from(k.indices)).filter((ix) => ix.length >= s.params.minPoints).map((ix) => {
      let x = 0, y = 0;
      for (const i of ix) { x += sc.x + c * pts[2 * i] - sn * pts[2 * i + 1]; y += sc.y + sn * pts[2 * i] + c * pts[2 * i + 1]; }
      return [x / ix.length, y / ix.length];
    });
    assert.equal(s.clusters.length, want.length);
    assert.ok(want.length >= 2, `${want.length} clusters`);
    s.clusters.forEach((k, j) => {
      assert.ok(Math.hypot(k.centroid[0] - want[j][0], k.centroid[1] - want[j][1]) < 1e-9, `C${j + 1}: ${k.centroid} vs ${want[j]}`);
      assert.equal(s.tracks[j].id, j + 1);
      assert.deepEqual(s.tracks[j].state.slice(0, 2), k.centroid);
    });
  });

  test('every association shown is assign() on the displayed matrix, and the outlined cells are its columns', async () => {
    const { kinds } = await state(page);
    let checked = 0, paired = 0, gatedSeen = 0;
    for (let k = 0; k < kinds.length; k++) {
      if (kinds[k] !== 'associate') continue;
      await goStep(page, k);
      const s = await state(page), a = s.association;
      // the costs are the distances from the predicted positions to the centroids, capped at the gate
      const pred = a.trackIds.map((id) => s.tracks.find((t) => t.id === id).predicted);
      for (let i = 0; i < a.rows; i++) for (let j = 0; j < a.cols; j++) {
        const d = Math.hypot(pred[i][0] - s.clusters[j].centroid[0], pred[i][1] - s.clusters[j].centroid[1]);
        assert.ok(Math.abs(a.distances[i * a.cols + j] - d) < 1e-12);
        assert.equal(a.costs[i * a.cols + j], Math.min(d, s.params.gate));
        if (d > s.params.gate) gatedSeen++;
      }
      const r = rtl.assign(new Float64Array(a.costs), { rows: a.rows, cols: a.cols });
      assert.deepEqual(Array.from(r.columns), a.columns, `scan ${s.scan}`);
      assert.ok(Math.abs(r.total - a.total) < 1e-12);
      // the table shows the same matrix and marks exactly the chosen cells within the gate
      const cells = await page.$$eval('#lesson-stage .cost-matrix td', (tds) => tds.map((td) => ({ i: Number(td.dataset.row), j: Number(td.dataset.col), text: td.textContent, cls: td.className })));
      assert.equal(cells.length, a.rows * a.cols);
      for (const c of cells) {
        const d = a.distances[c.i * a.cols + c.j];
        assert.equal(c.text, d.toFixed(2));
        assert.equal(/\bgated\b/.test(c.cls), d > s.params.gate);
        const chosen = a.columns[c.i] === c.j && d <= s.params.gate;
        assert.equal(/\bchosen\b/.test(c.cls), chosen, `cell ${c.i},${c.j} of scan ${s.scan}`);
        if (chosen) paired++;
      }
      assert.equal(a.pairs.length, cells.filter((c) => /\bchosen\b/.test(c.cls)).length);
      checked++;
    }
    assert.equal(checked, 9);
    assert.ok(paired >= 20, `${paired} pairs over 9 scans`);
    assert.ok(gatedSeen > 0, 'some pairs lie beyond the gate');
  });

  test('every Kalman estimate is the independent constant-velocity filter on the same measurements', async () => {
    const s = await state(page);
    let compared = 0;
    for (const t of s.log) {
      const ref = referenceTrack(t.updates, s.params);
      t.updates.forEach((u, k) => {
        for (let i = 0; i < 4; i++) assert.ok(Math.abs(u.state[i] - ref[k][i]) < 1e-9, `T${t.id} update ${k} state[${i}]: ${u.state[i]} vs ${ref[k][i]}`);
        compared++;
      });
    }
    assert.ok(compared >= 40, `${compared} estimates`);
  });

  test('the numbers are plausible: fixed objects give long, slow tracks that stay near their centroids', async () => {
    const s = await state(page);
    const long = s.log.filter((t) => t.updates.filter((u) => u.z).length >= 6);
    assert.ok(long.length >= 2, `${long.length} tracks measured in 6+ scans`);
    for (const t of s.log) {
      for (const u of t.updates.slice(1)) {
        if (!u.z) continue;
        const est = Math.hypot(u.state[0] - u.z[0], u.state[1] - u.z[1]), pre = Math.hypot(u.predicted[0] - u.z[0], u.predicted[1] - u.z[1]);
        assert.ok(pre <= s.params.gate + 1e-12, `T${t.id}: paired within the gate`);
        assert.ok(est <= pre + 1e-12, `T${t.id}: the correction moves towards the centroid (${est} vs ${pre})`);
        assert.ok(est < 0.5, `T${t.id}: estimate ${est} m from its centroid`);
      }
    }
    // the objects the turning robot keeps seeing (small, fixed): the estimate stays within 0.1 m of the centroid
    for (const t of long) {
      const last = t.updates.filter((u) => u.z).at(-1);
      assert.ok(Math.hypot(last.state[0] - last.z[0], last.state[1] - last.z[1]) < 0.15, `T${t.id} final estimate near its centroid`);
    }
    const still = long.filter((t) => { const u = t.updates.at(-1); return Math.hypot(u.state[2], u.state[3]) < 0.1; });
    assert.ok(still.length >= 1, 'at least one long track is (nearly) still');
    // tracks alive per scan: between 1 and 12
    for (let k = 0; k < s.kinds.length; k++) if (s.kinds[k] === 'correct' || s.kinds[k] === 'start') {
      await goStep(page, k);
      const n = (await state(page)).tracks.filter((t) => t.status !== 'ended').length;
      assert.ok(n >= 1 && n <= 12, `step ${k}: ${n} tracks`);
    }
  });

  test('stepping changes the state, the figure title and the text', async () => {
    await goStep(page, 2);
    const a = await state(page), textA = await page.textContent('#lesson-text');
    await page.click('#player [data-act="forward"]');
    await page.waitForFunction(() => window.__rtl.lessons.find((l) => l.id === 'tracking').step === 3, null, { timeout: PAGE_TIMEOUT });
    const b = await state(page), textB = await page.textContent('#lesson-text');
    assert.deepEqual([a.kind, b.kind], ['associate', 'correct']);
    assert.notEqual(textA, textB);
    assert.match(textA, /rtl\.assign/);
    assert.match(textB, /corrects/);
    const moved = b.tracks.filter((t) => t.status === 'corrected');
    assert.ok(moved.length > 0);
    for (const t of moved) assert.ok(Math.hypot(t.state[0] - t.predicted[0], t.state[1] - t.predicted[1]) > 1e-6, `T${t.id} moved from its prediction`);
  });

  test("the SVG and TikZ exports are the package's, of the figure as shown: its title, one dot per point in view", async () => {
    await goStep(page, 2);
    const s = await state(page), e = await page.evaluate(() => window.__rtl.figureExtent());
    const sc = scans[s.scan], pts = scanPoints(sc), c = Math.cos(sc.theta), sn = Math.sin(sc.theta);
    let inView = 0;
    for (let i = 0; i < pts.length / 2; i++) {
      if (!Number.isFinite(pts[2 * i])) continue;
      const x = sc.x + c * pts[2 * i] - sn * pts[2 * i + 1], y = sc.y + sn * pts[2 * i] + c * pts[2 * i + 1];
      if (x >= e.minX && x <= e.maxX && y >= e.minY && y <= e.maxY) inView++;
    }
    assert.ok(inView > 20, `${inView} points in view`);
    const download = async (id) => { const [dl] = await Promise.all([page.waitForEvent('download'), page.click(id)]); return readFileSync(await dl.path(), 'utf8'); };
    const svg = await download('#dl-svg'), tikz = await download('#dl-tikz');
    const args = await page.evaluate(() => window.__rtl.exportArguments());
    // the files are the package's calls on the figure's drawing, byte for byte
    assert.equal(svg, rtl.toSvg(args.drawing, args.svg));
    assert.equal(tikz, rtl.toTikz(args.drawing));
    const title = `Tracking, scan ${s.scan} (associate): Intel Research Lab, scans 2–11, map frame`;
    assert.equal(args.drawing.title, title);
    assert.ok(svg.includes(`>${title}</text>`), 'the SVG draws the figure title');
    assert.equal(args.drawing.points.length / 2, inView, 'one dot per point in view');
    // coloured as on screen: the paired clusters' points in their tracks' colours, the rest grey
    const labels = new Set(args.drawing.labels);
    for (const c of s.clusters) if (c.track !== null) assert.ok(labels.has(c.track - 1), `T${c.track}'s colour`);
    assert.ok(labels.has(-1));
    assert.match(tikz, /\\begin\{tikzpicture\}/);
    assert.equal((tikz.match(/\\Mark[A-Z]+\{/g) ?? []).length, inView);
  });

  test("why: driving (scans 18-29), a track paired with a cluster that is not its nearest is explained with assign()'s numbers", async () => {
    await setField(page, 'first', 18);
    await setField(page, 'count', 12);
    const { kinds } = await state(page);
    let explained = 0;
    for (let k = 0; k < kinds.length; k++) {
      if (kinds[k] !== 'associate') continue;
      await goStep(page, k);
      const s = await state(page), a = s.association, text = await page.textContent('#lesson-stage .tracking-details');
      for (const w of a.why) {
        const id = a.trackIds[w.row];
        if (w.kind === 'mutual') {
          // each is the other's nearest
          for (let j = 0; j < a.cols; j++) assert.ok(a.distances[w.row * a.cols + j] >= w.distance);
          for (let i = 0; i < a.rows; i++) assert.ok(a.distances[i * a.cols + w.column] >= w.distance);
        }
        if (w.kind !== 'global') continue;
        // the best assignment that gives this track its nearest cluster, computed here from assign() on the rest
        const sub = [];
        for (let i = 0; i < a.rows; i++) if (i !== w.row) for (let j = 0; j < a.cols; j++) if (j !== w.nearest) sub.push(a.costs[i * a.cols + j]);
        const rest = rtl.assign(new Float64Array(sub), { rows: a.rows - 1, cols: a.cols - 1 }).total;
        const alternative = a.costs[w.row * a.cols + w.nearest] + rest;
        assert.ok(Math.abs(alternative - w.alternative) < 1e-12);
        assert.ok(alternative > a.total, `T${id}: ${alternative} > ${a.total}`);
        assert.ok(w.nearestDistance < w.distance);
        assert.ok(text.includes(`T${id} → C${w.column + 1} (${w.distance.toFixed(2)} m), not its nearest C${w.nearest + 1} (${w.nearestDistance.toFixed(2)} m)`), text);
        assert.ok(text.includes(`costs ${alternative.toFixed(2)} m, more than Munkres' ${a.total.toFixed(2)} m`), text);
        explained++;
      }
    }
    assert.ok(explained >= 1, `${explained} non-nearest pairs explained`);
    await setField(page, 'first', 2);
    await setField(page, 'count', 10);
  });

  test('clicking a track in the figure goes back to the step where it started', async () => {
    await goStep(page, 15);
    const s = await state(page);
    const t = s.tracks.find((x) => x.id === 5);
    assert.equal(t.status, 'corrected');
    const at = await page.evaluate(([x, y]) => window.__rtl.clientPoint(x, y), [t.state[0], t.state[1]]);
    await page.mouse.click(at.x, at.y);
    await page.waitForFunction(() => window.__rtl.lessons.find((l) => l.id === 'tracking').step !== 15, null, { timeout: PAGE_TIMEOUT });
    const b = await state(page);
    assert.equal(b.kind, 'correct');
    assert.equal(b.tracks.find((x) => x.id === 5)?.status, 'new');
    assert.ok(s.log.find((x) => x.id === 5).born === b.scan, `T5 was born in scan ${b.scan}`);
  });

  test('a smaller gate leaves more pairs unassigned; an impossible excerpt is marked', async () => {
    const wide = await state(page);
    await setField(page, 'gate', 0.1);
    const narrow = await state(page);
    const pairs = (s) => s.log.reduce((n, t) => n + t.updates.filter((u) => u.z).length - 1, 0);
    assert.ok(pairs(narrow) < pairs(wide), `${pairs(narrow)} < ${pairs(wide)} pairs`);
    assert.ok(narrow.log.length > wide.log.length, 'more tracks start');
    await setField(page, 'gate', 1);
    await setField(page, 'count', 29);
    assert.equal(await page.getAttribute('#lesson-controls input[name="count"]', 'aria-invalid'), 'true');
    assert.match(await page.textContent('#lesson-controls .field[data-key="count"] .field-error'), /≤ 30/);
    assert.equal((await entry(page)).steps, 0);
    await setField(page, 'count', 10);
    assert.equal((await entry(page)).steps, 28);
  });

  test('no wasm heap growth over many steps and recomputations', async () => {
    await goStep(page, 0);
    const before = (await state(page)).heapInUse;
    for (let r = 0; r < 3; r++) {
      await setField(page, 'gate', 0.5 + r * 0.25);
      for (let k = 0; k < 28; k += 3) await goStep(page, k);
    }
    await setField(page, 'gate', 1);
    await goStep(page, 0);
    const after = (await state(page)).heapInUse;
    assert.ok(Number.isFinite(before) && before > 0);
    assert.equal(after, before, `heap ${before} -> ${after} bytes`);
  });

  test('screenshots at 1280x800 and 390x844', async () => {
    mkdirSync(SCREENSHOTS, { recursive: true });
    await goStep(page, 5);
    await page.waitForTimeout(150);
    await page.screenshot({ path: join(SCREENSHOTS, 'lesson-tracking-1280x800.png') });
    await page.setViewportSize({ width: 390, height: 844 });
    await goStep(page, 5);
    await page.waitForTimeout(150);
    await page.screenshot({ path: join(SCREENSHOTS, 'lesson-tracking-390x844.png'), fullPage: true });
    assert.ok(await page.evaluate(() => document.documentElement.scrollWidth) <= 390);
    await page.setViewportSize({ width: 1280, height: 800 });
  });

  test('no console errors', async () => {
    assert.deepEqual(await page.evaluate(() => window.__rtl.errors), []);
    assert.deepEqual(problems, []);
  });
});
