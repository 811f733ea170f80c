// The transformation-tree lesson (web/lessons/tf-tree.js) in Chromium: the points it shows in each frame equal
// the package's TfTree in Node (and the pose formula R(theta) p + t), the mount parameters recompute at once and
// are validated, the four steps name their frames, no console errors. Screenshots at 1280x800 and 390x844.
import { after, before, describe, test } from 'node:test';
import assert from 'node:assert/strict';
import { mkdirSync, readFileSync } from 'node:fs';
import { join } from 'node:path';
import init from 'rtl-wasm';
import { DATA, PAGE_TIMEOUT, REPO, openDemoPage } from './helpers.js';

const PATH = '/web/#tf-tree';
const SHOTS = join(REPO, 'build', 'test-output', 'screenshots');
const lessonState = (page) => page.evaluate(() => window.__rtl.finalState());
const entryOf = (page) => page.evaluate(() => window.__rtl.lessons.find((l) => l.id === 'tf-tree'));
// the player's slider is 1-based
async function goStep(page, k) {
  await page.fill('[data-act="scrub"]', String(k + 1));
  await page.dispatchEvent('[data-act="scrub"]', 'input');
}

// The tree as a user of the package would build it: insert() takes parent -> child, the inverse of a pose.
function nodeTree(rtl, pose, mount) {
  const inv = ({ x, y, angle }) => {
    const c = Math.cos(angle), s = Math.sin(angle);
    return { angle: -angle, translation: [-(c * x + s * y), s * x - c * y] };
  };
  const tree = new rtl.TfTree('map', { dim: 2 });
  tree.insert('robot', 'map', inv({ x: pose.x, y: pose.y, angle: pose.theta }));
  tree.insert('sensor', 'robot', inv(mount));
  return tree;
}
const close3 = (a, b, tol, what) => {
  assert.equal(a.length, b.length, what);
  a.forEach((v, i) => {
    if (Number.isNaN(b[i])) assert.ok(v === null || Number.isNaN(v), `${what} ${i}: gap`);
    else assert.ok(Math.abs(v - b[i]) < tol, `${what} ${i}: ${v} vs ${b[i]}`);
  });
};

describe('transformation-tree lesson in Chromium', { timeout: 180000 }, () => {
  let page, problems, close, rtl, scans;
  before(async () => {
    rtl = await init();
    scans = rtl.readCarmenLog(readFileSync(join(DATA, 'intel.log'), 'utf8'));
    ({ page, problems, close } = await openDemoPage(PATH));
  });
  after(() => close?.());

  const check = async (mount) => {
    const s = await lessonState(page);
    const scan = scans[s.excerpt.scan];
    assert.deepEqual(s.pose, { x: scan.x, y: scan.y, theta: scan.theta });
    for (const k of ['x', 'y', 'angle']) assert.ok(Math.abs(s.mount[k] - mount[k]) < 1e-12, `mount ${k}`);
    const tree = nodeTree(rtl, scan, mount);
    try {
      close3(s.sensor, Array.from(scan.points), 1e-12, 'sensor');
      close3(s.robot, Array.from(tree.transformPoints('sensor', 'robot', scan.points)), 1e-9, 'robot');
      close3(s.map, Array.from(tree.transformPoints('sensor', 'map', scan.points)), 1e-9, 'map');
      close3(s.chain, Array.from(tree.transformPoints('sensor', 'map', scan.points)), 1e-9, 'chain');
      close3(s.chainMatrix, Array.from(tree.tf('sensor', 'map').matrix), 1e-9, 'matrix');
      // and the formula: p_map = R(theta) (R(phi) p + m) + t
      const c = Math.cos(scan.theta), sn = Math.sin(scan.theta), ca = Math.cos(mount.angle), sa = Math.sin(mount.angle);
      for (let i = 0; i < scan.points.length; i += 2) {
        const px = scan.points[i], py = scan.points[i + 1];
        if (Number.isNaN(px)) continue;
        const rx = ca * px - sa * py + mount.x, ry = sa * px + ca * py + mount.y;
        assert.ok(Math.abs(s.map[i] - (c * rx - sn * ry + scan.x)) < 1e-9 && Math.abs(s.map[i + 1] - (sn * rx + c * ry + scan.y)) < 1e-9);
      }
    } finally {
      tree.dispose();
    }
    return s;
  };

  test('it starts on Intel scan 20 with the identity mount; every frame equals TfTree in Node', async () => {
    const s = await check({ x: 0, y: 0, angle: 0 });
    assert.equal(s.excerpt.scan, 20);
    assert.ok(Math.hypot(s.pose.x, s.pose.y) > 5 && Math.abs(s.pose.theta) > 0.5, 'a pose that visibly moves the scan');
  });

  test('the four steps show sensor, robot, map and the chain', async () => {
    const entry = await entryOf(page);
    assert.deepEqual([entry.id, entry.steps], ['tf-tree', 4]);
    const texts = [];
    for (let k = 0; k < 4; k++) {
      await goStep(page, k);
      texts.push(await page.textContent('#lesson-text'));
    }
    assert.match(texts[0], /sensor frame/);
    assert.match(texts[1], /sensor → robot/);
    assert.match(texts[2], /robot → map/);
    assert.match(texts[3], /tree\.tf\('sensor', 'map'\)/);
    const s = await lessonState(page);
    assert.ok(texts[2].includes(s.pose.x.toFixed(2)));
  });

  test('changing the mount recomputes at once; the result is again TfTree in Node', async () => {
    await page.fill('input[name="mountX"]', '0.3');
    await page.fill('input[name="mountY"]', '-0.1');
    await page.fill('input[name="mountAngle"]', '10');
    await page.dispatchEvent('input[name="mountAngle"]', 'input');
    await page.waitForFunction(() => window.__rtl.finalState().mount.angle > 0.17, null, { timeout: PAGE_TIMEOUT });
    await check({ x: 0.3, y: -0.1, angle: 10 * Math.PI / 180 });
    await goStep(page, 2);
    assert.match(await page.textContent('#lesson-text'), /no longer line up/);
  });

  test('an invalid mount offset is marked and explained, and the last valid mount stays', async () => {
    await page.fill('input[name="mountX"]', '9');
    assert.equal(await page.getAttribute('input[name="mountX"]', 'aria-invalid'), 'true');
    assert.match(await page.textContent('.field[data-key="mountX"] .field-error'), /from −5 to 5 m/);
    assert.ok(Math.abs((await lessonState(page)).mount.x - 0.3) < 1e-12);
    await page.fill('input[name="mountX"]', '0');
    await page.fill('input[name="mountY"]', '0');
    await page.fill('input[name="mountAngle"]', '0');
    await page.dispatchEvent('input[name="mountAngle"]', 'input');
    assert.equal(await page.getAttribute('input[name="mountX"]', 'aria-invalid'), null);
    await check({ x: 0, y: 0, angle: 0 });
  });

  test('screenshots at 1280x800 and 390x844', async () => {
    mkdirSync(SHOTS, { recursive: true });
    await page.setViewportSize({ width: 1280, height: 800 });
    await goStep(page, 2);
    await page.screenshot({ path: join(SHOTS, 'lesson-tf-tree-1280x800.png') });
    await page.setViewportSize({ width: 390, height: 844 });
    await page.dispatchEvent('[data-act="scrub"]', 'input');
    await page.screenshot({ path: join(SHOTS, 'lesson-tf-tree-390x844.png'), fullPage: true });
    assert.ok(await page.evaluate(() => document.documentElement.scrollWidth) <= 390);
  });

  test('the frames\' names never cover each other: every step, identity and a small mount, on a phone, a laptop and in lecture mode', async () => {
    for (const [width, height, lecture] of [[390, 844, false], [1280, 800, false], [1920, 1080, true]]) {
      await page.setViewportSize({ width, height });
      await page.evaluate((on) => window.__rtl.lecture.set(on), lecture);
      for (const angle of ['0', '5']) {
        // the field is hidden in lecture mode: set it as the slider would
        await page.evaluate((a) => { const i = document.querySelector('input[name="mountAngle"]'); i.value = a; i.dispatchEvent(new Event('input', { bubbles: true })); }, angle);
        await page.waitForFunction((a) => Math.abs(window.__rtl.finalState().mount.angle - a * Math.PI / 180) < 1e-9, Number(angle), { timeout: PAGE_TIMEOUT });
        for (let k = 0; k < 4; k++) {
          await goStep(page, k);
          const labels = await page.evaluate(() => window.__rtl.figureLabels());
          assert.ok(labels.length >= 2, `step ${k + 1}: ${labels.length} labels`);
          for (let i = 0; i < labels.length; i++) for (let j = 0; j < i; j++) {
            const a = labels[i], b = labels[j];
            const gap = 4;   // CSS px: a space between two names on one line, so they do not read as one
            const apart = a.x1 + gap <= b.x0 || a.x0 >= b.x1 + gap || a.y1 <= b.y0 || a.y0 >= b.y1;
            assert.ok(apart, `${width}x${height}${lecture ? ' lecture' : ''}, mount ${angle}°, step ${k + 1}: "${a.text}" covers "${b.text}"`);
            // side by side (no column in common) and nearer than one and a half type sizes across: half a type size
            // apart up or down, else the end of one reads on into the other ("map x" beside "robot = sensor" on a phone)
            const size = (a.y1 - a.y0) / 1.1, side = a.x1 <= b.x0 || a.x0 >= b.x1;
            const near = !(a.x1 + 1.5 * size <= b.x0 || a.x0 >= b.x1 + 1.5 * size);
            if (side && near) {
              const clear = Math.max(b.y0 - a.y1, a.y0 - b.y1);
              assert.ok(clear >= 0.5 * size - 0.01, `${width}x${height}${lecture ? ' lecture' : ''}, mount ${angle}°, step ${k + 1}: "${a.text}" and "${b.text}" side by side ${clear.toFixed(1)} px apart`);
            }
          }
          if (k >= 2) {
            // in the map frame the map's name sits under its origin, clear of its x axis (the line y = 0)
            const origin = await page.evaluate(() => { const p = window.__rtl.clientPoint(0, 0), r = document.querySelector('#canvas').getBoundingClientRect(); return p.y - r.top; });
            const map = labels.find((l) => l.text === 'map');
            assert.ok(map.y0 > origin + 1, `${width}x${height}${lecture ? ' lecture' : ''}, step ${k + 1}: "map" at ${map.y0}..${map.y1}, axis at ${origin}`);
          }
        }
        if (angle === '0' && width === 390) {
          await goStep(page, 2);
          await page.screenshot({ path: join(SHOTS, 'lesson-tf-tree-robot-map-390x844.png') });
        }
      }
    }
    await page.evaluate(() => window.__rtl.lecture.set(false));
    await page.fill('input[name="mountAngle"]', '0');
    await page.dispatchEvent('input[name="mountAngle"]', 'input');
  });

  test('no console errors', () => assert.deepEqual(problems, []));
});
