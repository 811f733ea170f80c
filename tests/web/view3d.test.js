// The 3D view of the Ouster scan (web/view3d) in Chromium: a WebGL canvas with drawn pixels, orbiting moves the
// camera, the counts shown are those of the package run in Node on the same file, no console errors. Screenshots
// at 1280x800 and 390x844 into build/test-output/screenshots/.
import { after, before, describe, test } from 'node:test';
import assert from 'node:assert/strict';
import { mkdirSync, readFileSync } from 'node:fs';
import { join } from 'node:path';
import init from 'rtl-wasm';
import { DATA, PAGE_TIMEOUT, REPO, openDemoPage } from './helpers.js';
import { computeLidarScene } from '../../web/view3d/lidar-scene.js';

const PATH = '/web/view3d/dev/lidar3d.html';
const SHOTS = join(REPO, 'build', 'test-output', 'screenshots');

// Pixels of the WebGL canvas that differ from the white background (read back through a 2D copy in the page).
const inkedPixels = (page) => page.evaluate(() => {
  const src = document.querySelector('.lidar3d-3d canvas');
  const c = document.createElement('canvas');
  c.width = src.width; c.height = src.height;
  const g = c.getContext('2d');
  g.drawImage(src, 0, 0);
  const d = g.getImageData(0, 0, c.width, c.height).data;
  let n = 0;
  for (let i = 0; i < d.length; i += 4) if (d[i] < 235 || d[i + 1] < 235 || d[i + 2] < 235) n++;
  return { inked: n, total: d.length / 4 };
});

describe('3D view of the Ouster scan (web/view3d) in Chromium', { timeout: 240000 }, () => {
  let page, problems, close;
  before(async () => ({ page, problems, close } = await openDemoPage(PATH)));
  after(() => close?.());

  test('the page loaded the package and a WebGL canvas', async () => {
    assert.deepEqual(await page.evaluate(() => window.__rtl.errors), []);
    const gl = await page.evaluate(() => {
      const c = document.querySelector('.lidar3d-3d canvas');
      return Boolean(c && (c.getContext('webgl2') || c.getContext('webgl')));
    });
    assert.equal(gl, true);
  });

  test('the scene equals the package run in Node on the same 16-beam file', async () => {
    const rtl = await init();
    const cloud = rtl.readOrganizedLidar(readFileSync(join(DATA, 'rellis3d-os1-16x2048.bin')), { beams: 16 });
    const node = computeLidarScene(rtl, cloud);
    const shown = await page.evaluate(() => {
      const s = window.__lidar3d.scene();
      return { stats: window.__lidar3d.view.stats(), clusters: s.clusters, segments: s.segments.map((v) => Array.from(v)),
        planes: s.planes.map((p) => ({ normal: p.normal, d: p.d, count: p.count })), labels: s.rings.map((r) => Array.from(r.labels)) };
    });
    assert.equal(shown.clusters, node.clusters);
    assert.ok(node.clusters > 100, `clusters ${node.clusters}`);
    assert.deepEqual(shown.labels, node.rings.map((r) => Array.from(r.labels)));
    assert.equal(shown.segments.length, node.segments.length);
    shown.segments.forEach((s, k) => s.forEach((v, i) => assert.ok(Math.abs(v - node.segments[k][i]) < 1e-9)));
    assert.deepEqual(shown.planes.map((p) => p.count), node.planes.map((p) => p.count));
    assert.ok(node.planes.length >= 5, `planes ${node.planes.length}`);
    // the view draws every finite point, every segment and every plane
    const finite = node.rings.reduce((n, r) => n + r.labels.filter((l) => l >= 0).length, 0);
    assert.equal(shown.stats.points, finite);
    assert.equal(shown.stats.segments, node.segments.reduce((n, s) => n + s.length / 6, 0));
    assert.equal(shown.stats.planes, node.planes.length);
  });

  test('the canvas has drawn pixels and orbiting changes the camera and the picture', async () => {
    const { inked, total } = await inkedPixels(page);
    assert.ok(inked > 0.01 * total, `inked ${inked} of ${total}`);
    const before = await page.evaluate(() => window.__lidar3d.view.cameraState());
    const box = await page.locator('.lidar3d-3d canvas').boundingBox();
    const shot0 = await page.locator('.lidar3d-3d canvas').screenshot();
    await page.mouse.move(box.x + box.width / 2, box.y + box.height / 2);
    await page.mouse.down();
    await page.mouse.move(box.x + box.width / 2 + 120, box.y + box.height / 2 + 40, { steps: 8 });
    await page.mouse.up();
    const after = await page.evaluate(() => window.__lidar3d.view.cameraState());
    const moved = Math.hypot(...after.position.map((v, i) => v - before.position[i]));
    assert.ok(moved > 1, `camera moved ${moved} m`);
    // orbiting keeps the distance to the target
    const dist = (s) => Math.hypot(...s.position.map((v, i) => v - s.target[i]));
    assert.ok(Math.abs(dist(after) - dist(before)) < 1e-6 * dist(before));
    const shot1 = await page.locator('.lidar3d-3d canvas').screenshot();
    assert.notDeepEqual(shot0, shot1);
  });

  test('the keyboard orbits too: Shift+arrow keys on the focused view move the camera', async () => {
    const before = await page.evaluate(() => window.__lidar3d.view.cameraState());
    await page.focus('.lidar3d-3d canvas');
    for (let i = 0; i < 5; i++) await page.keyboard.press('Shift+ArrowLeft');
    const after = await page.evaluate(() => window.__lidar3d.view.cameraState());
    const moved = Math.hypot(...after.position.map((v, i) => v - before.position[i]));
    assert.ok(moved > 0.5, `camera moved ${moved} m`);
    assert.deepEqual(after.target, before.target, 'orbiting keeps the target');
  });

  test('the layer switches and the parameters recompute; an invalid σ is marked', async () => {
    await page.uncheck('input[data-layer="planes"]');
    assert.equal(await page.evaluate(() => window.__lidar3d.view.stats().layers.planes), false);
    await page.check('input[data-layer="planes"]');
    const n0 = await page.evaluate(() => window.__lidar3d.scene().planes.length);
    await page.fill('input[name="planeSigma"]', '0.2');
    await page.dispatchEvent('input[name="planeSigma"]', 'change');
    await page.waitForFunction(() => window.__lidar3d.settings().planeSigma === 0.2, null, { timeout: PAGE_TIMEOUT });
    const n1 = await page.evaluate(() => window.__lidar3d.scene().planes.length);
    assert.notEqual(n1, n0, 'a looser σ changes the planes');
    await page.fill('input[name="planeSigma"]', '-1');
    await page.dispatchEvent('input[name="planeSigma"]', 'change');
    assert.equal(await page.getAttribute('input[name="planeSigma"]', 'aria-invalid'), 'true');
    assert.match(await page.textContent('.lidar3d-error'), /planeSigma/);
    await page.fill('input[name="planeSigma"]', '0.05');
    await page.dispatchEvent('input[name="planeSigma"]', 'change');
  });

  test('screenshots at 1280x800 and 390x844; nothing scrolls sideways on the phone', async () => {
    mkdirSync(SHOTS, { recursive: true });
    await page.setViewportSize({ width: 1280, height: 800 });
    await page.click('button[data-view="orbit"]');
    await page.screenshot({ path: join(SHOTS, 'view3d-1280x800.png') });
    await page.setViewportSize({ width: 390, height: 844 });
    await page.waitForFunction(() => document.querySelector('.lidar3d-3d canvas').width <= 390 * 2, null, { timeout: PAGE_TIMEOUT });
    await page.screenshot({ path: join(SHOTS, 'view3d-390x844.png'), fullPage: true });
    assert.ok(await page.evaluate(() => document.documentElement.scrollWidth) <= 390);
    const { inked } = await inkedPixels(page);
    assert.ok(inked > 0);
  });

  test('no console errors', () => assert.deepEqual(problems, []));
});

describe('3D view mounted in the lesson page (web/#lidar-3d) in Chromium', { timeout: 180000 }, () => {
  let page, problems, close;
  before(async () => ({ page, problems, close } = await openDemoPage('/web/#lidar-3d')));
  after(() => close?.());

  test('the panel shows a drawn WebGL canvas next to the top view, at both sizes, without sideways scrolling', async () => {
    await page.waitForSelector('.lidar3d-3d canvas', { timeout: PAGE_TIMEOUT });
    mkdirSync(SHOTS, { recursive: true });
    for (const [width, height] of [[1280, 800], [390, 844]]) {
      await page.setViewportSize({ width, height });
      await page.waitForFunction((w) => document.querySelector('.lidar3d-3d canvas').getBoundingClientRect().width <= w, width, { timeout: PAGE_TIMEOUT });
      const { inked, total } = await inkedPixels(page);
      assert.ok(inked > 0.01 * total, `${width}: inked ${inked} of ${total}`);
      const top = await page.locator('.lidar3d-top').boundingBox();
      assert.ok(top && top.width > 100, 'the top view is shown');
      assert.ok(await page.evaluate(() => document.documentElement.scrollWidth) <= width);
      await page.screenshot({ path: join(SHOTS, `view3d-page-${width}x${height}.png`), fullPage: width < 500 });
    }
  });

  test('in lecture mode at 1920x1080 the top view\'s caption grows with the figure type (readable on a projector)', async () => {
    await page.setViewportSize({ width: 1280, height: 800 });
    await page.waitForFunction(() => document.querySelector('.lidar3d-top').dataset.captionPx === '12', null, { timeout: PAGE_TIMEOUT });
    await page.setViewportSize({ width: 1920, height: 1080 });
    await page.evaluate(() => window.__rtl.lecture.set(true));
    // the figure's text scale in lecture mode: the 2D figure's title and the top view's caption share it
    const scale = await page.evaluate(() => Number(getComputedStyle(document.documentElement).getPropertyValue('--figure-text-scale')));
    assert.ok(scale >= 1.5, `text scale ${scale}`);
    await page.waitForFunction((px) => Number(document.querySelector('.lidar3d-top').dataset.captionPx) === px, 12 * scale, { timeout: PAGE_TIMEOUT });
    await page.screenshot({ path: join(SHOTS, 'view3d-page-lecture-1920x1080.png') });
    await page.evaluate(() => window.__rtl.lecture.set(false));
    await page.waitForFunction(() => document.querySelector('.lidar3d-top').dataset.captionPx === '12', null, { timeout: PAGE_TIMEOUT });
  });

  test('no console errors', () => assert.deepEqual(problems, []));
});
