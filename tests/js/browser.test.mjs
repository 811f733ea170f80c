// The whole API in headless Chromium (the browser entry dist/index.js, ES6 web glue, .wasm fetched by the glue):
// readers on fetched files, segment, vectorize, stateful classes with Symbol.dispose, SVG (after load('extras'),
// which fetches the extras module once), and error classes.
// Then the C++ writer's SVG of a real scan with clusters and segments (toSvg) is loaded as an SVG document, rendered
// and screenshot; the screenshot's pixels must show every cluster colour, the black segments and a white ground.
// Uses the page tests' server and browser helpers (tests/web/helpers.js).
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { mkdirSync, writeFileSync } from 'node:fs';
import { join } from 'node:path';
import { launchBrowser, SCREENSHOTS, startServer } from '../web/helpers.js';

// The cluster colours the writer documents (rtl::scan_palette: cluster k in PALETTE[k % 10]).
const PALETTE = ['0072B2', 'E69F00', '009E73', 'D55E00', 'CC79A7', '56B4E9', '8C6D1F', '1B7837', '762A83', '332288'];

// Runs body(page, errors, server) on a Chromium page of the test server (opened on a file of the checkout, so that
// /dist and /tests/data resolve), with the page's errors collected; the browser and the server are closed after it.
async function onPackagePage(body) {
  const server = await startServer();
  const browser = await launchBrowser();
  try {
    const page = browser.context.pages()[0] ?? await browser.context.newPage();
    const errors = [];
    page.on('pageerror', (e) => errors.push(e.message));
    await page.goto(`${server.origin}/tests/data/README.md`);
    await body(page, errors, server);
  } finally {
    await browser.close();
    await server.close();
  }
}

test('Chromium: every function of the package works from the browser entry', { timeout: 120_000 }, () => onPackagePage(async (page, errors) => {
  const r = await page.evaluate(async () => {
    const { default: init } = await import('/dist/index.js');
    const rtl = await init();
    const text = await (await fetch('/tests/data/intel.log')).text();
    const scans = rtl.readCarmenLog(text);
    const xy = scans[0].points;
    const seg = rtl.segment(xy, { step: 3, lowerBound: 0.1, upperBound: 0.5 });
    const c = seg.clusters.reduce((a, b) => (b.indices.length > a.indices.length ? b : a));
    const chain = Float64Array.from(Array.from(c.indices).flatMap((i) => [xy[2 * i], xy[2 * i + 1]]));
    const v = rtl.vectorize(chain, { method: 'aftls', sigma: 0.03, delta: 0.3 });
    const bin = await (await fetch('/tests/data/rellis3d-os1-4x2048.bin')).arrayBuffer();
    const cloud = rtl.readOrganizedLidar(bin, { beams: 4 });
    const s = new rtl.StreamSegmenter({ step: 3 });
    s.addPoints(xy);
    s.flush();
    const streamed = s.takeClosedClusters().length;
    s[Symbol.dispose]();
    const t = new rtl.TfTree('map');
    t.insert('robot', 'map', { angle: scans[0].theta, translation: [scans[0].x, scans[0].y] });
    const moved = t.transformPoints('robot', 'map', chain.subarray(0, 2));
    t.dispose();
    // toSvg is in the extras module, which the browser entry loads on demand: before load(), the documented Error
    let beforeLoad = null;
    try { rtl.toSvg({}); } catch (e) { beforeLoad = [e.constructor.name, e.message]; }
    const loaded = (await rtl.load('extras')) === rtl;
    const fetched = performance.getEntriesByType('resource').map((e) => new URL(e.name).pathname).filter((p) => p.startsWith('/dist/'));
    const svg = rtl.toSvg({ points: xy, labels: seg.labels, segments: v.segments });
    const heap = rtl.heapInUse();
    let kinds = new Set();
    for (let i = 0; i < 10000; i++) {
      try { i % 2 ? rtl.segment([0, 0, Infinity, 1]) : rtl.vectorize('x', { method: 'dp' }); } catch (e) { kinds.add(e.constructor.name); }
    }
    return {
      scans: scans.length, clusters: seg.clusters.length, labelled: seg.labels.filter((l) => l >= 0).length,
      returns: xy.filter((v2, i) => i % 2 === 0 && !Number.isNaN(v2)).length, ok: v.ok, segments: v.count,
      columns: cloud.columns, streamed, disposed: s.disposed, moved: Array.from(moved),
      // the C++ writer's document: an XML declaration, then an <svg> root that Chromium's XML parser accepts
      svg: svg.startsWith('<?xml') && (() => {
        const doc = new DOMParser().parseFromString(svg, 'image/svg+xml');
        return doc.documentElement.nodeName === 'svg' && doc.getElementsByTagName('parsererror').length === 0;
      })(),
      kinds: [...kinds].sort(), heapSame: rtl.heapInUse() === heap, beforeLoad, loaded, fetched,
    };
  });
  assert.deepEqual(errors, []);
  assert.equal(r.scans, 30);
  assert.ok(r.clusters > 5);
  assert.equal(r.labelled, r.returns, 'every return is in a cluster');
  assert.equal(r.ok, true);
  assert.ok(r.segments >= 1);
  assert.equal(r.columns, 2048);
  assert.ok(r.streamed >= r.clusters - 1, 'the stream segmenter closes about as many clusters as the batch one');
  assert.equal(r.disposed, true);
  assert.ok(r.moved.every(Number.isFinite));
  assert.equal(r.svg, true);
  assert.deepEqual(r.kinds, ['RangeError', 'TypeError']);
  assert.equal(r.heapSame, true, '10,000 failing calls leave the heap as it was');
  assert.deepEqual(r.beforeLoad, ['Error', "toSvg: this function is in the package's extras module, which is not loaded: call await rtl.load('extras') first (or init({ load: ['extras'] }))"]);
  assert.equal(r.loaded, true);
  for (const f of ['/dist/rtl.wasm', '/dist/rtl-extras.mjs', '/dist/rtl-extras.wasm'])
    assert.equal(r.fetched.filter((p) => p === f).length, 1, `${f} fetched once: ${r.fetched}`);
}));

test('Chromium renders the C++ writer\'s SVG of a scan: a screenshot shows every cluster colour and the segments', { timeout: 120_000 }, () => onPackagePage(async (page, errors, server) => {
  // Scan 3 of the Intel log: CAR clusters (step 3, 0.1-0.5 m), ITLS segments of each cluster of >= 5 points.
  const d = await page.evaluate(async () => {
    const { default: init } = await import('/dist/index.js');
    const rtl = await init();
    await rtl.load('extras');  // toSvg
    const xy = rtl.readCarmenLog(await (await fetch('/tests/data/intel.log')).text())[3].points;
    const seg = rtl.segment(xy, { step: 3, lowerBound: 0.1, upperBound: 0.5 });
    const segments = [];
    for (const c of seg.clusters) {
      if (c.indices.length < 5) continue;
      const chain = Float64Array.from(Array.from(c.indices).flatMap((i) => [xy[2 * i], xy[2 * i + 1]]));
      segments.push(...rtl.vectorize(chain, { method: 'itls', sigma: 0.03 }).segments);
    }
    const svg = rtl.toSvg({ points: xy, labels: seg.labels, segments, title: 'intel.log scan 3' }, { width: 800, height: 800, pointRadius: 3 });
    return { svg, labels: Array.from(seg.labels), segments: segments.length / 4 };
  });
  // Served as image/svg+xml: Chromium parses it as an XML document and renders it.
  await page.route('**/scan.svg', (route) => route.fulfill({ contentType: 'image/svg+xml', body: d.svg }));
  await page.goto(`${server.origin}/scan.svg`);
  const size = await page.evaluate(() => {
    const r = document.documentElement.getBoundingClientRect();
    return { root: document.documentElement.nodeName, width: Math.round(r.width), height: Math.round(r.height) };
  });
  assert.equal(size.root, 'svg');
  // The scan's extent fitted into 800 x 800 px (plus the margin and the title): the longer side about 800.
  assert.ok(Math.max(size.width, size.height) > 750 && Math.max(size.width, size.height) < 900 &&
    Math.min(size.width, size.height) > 100, JSON.stringify(size));
  const png = await page.screenshot({ clip: { x: 0, y: 0, width: size.width, height: size.height } });
  mkdirSync(SCREENSHOTS, { recursive: true });
  writeFileSync(join(SCREENSHOTS, 'browser-scan-svg.png'), png);

  // Pixel counts of the screenshot, decoded by the browser: near each palette colour (the dots' centres), near
  // black (segments, the title), near white (the ground).
  await page.goto(`${server.origin}/tests/data/README.md`);
  const px = await page.evaluate(async ([b64, palette]) => {
    const img = new Image();
    img.src = `data:image/png;base64,${b64}`;
    await img.decode();
    const c = document.createElement('canvas');
    c.width = img.width; c.height = img.height;
    const g = c.getContext('2d');
    g.drawImage(img, 0, 0);
    const data = g.getImageData(0, 0, c.width, c.height).data;
    const rgb = palette.map((h) => [0, 2, 4].map((k) => parseInt(h.slice(k, k + 2), 16)));
    const near = (i, [r, gr, b], tol) => Math.abs(data[i] - r) <= tol && Math.abs(data[i + 1] - gr) <= tol && Math.abs(data[i + 2] - b) <= tol;
    const colour = palette.map(() => 0);
    let white = 0, black = 0;
    for (let i = 0; i < data.length; i += 4) {
      if (near(i, [255, 255, 255], 8)) white++;
      else if (near(i, [0, 0, 0], 60)) black++;
      rgb.forEach((v, k) => { if (near(i, v, 12)) colour[k]++; });
    }
    return { total: data.length / 4, white, black, colour };
  }, [png.toString('base64'), PALETTE]);

  assert.deepEqual(errors, []);
  const used = new Set(d.labels.filter((l) => l >= 0).map((l) => l % 10));
  assert.ok(used.size >= 5, `clusters use ${used.size} palette colours`);
  assert.ok(d.segments >= 5, `segments: ${d.segments}`);
  // Mostly white ground, neither blank nor black.
  assert.ok(px.white > 0.6 * px.total && px.white < 0.995 * px.total, `white ${px.white} of ${px.total}`);
  // Black: the title's glyphs and the segments' cores (thin lines are mostly anti-aliased grey).
  assert.ok(px.black > 150 && px.black < 0.1 * px.total, `black ${px.black} of ${px.total}`);
  // Every colour of a cluster shows (a dot of radius 3 px has ~20 pixels of its colour, fewer where dots overlap); unused ones do not.
  const dots = (k) => d.labels.filter((l) => l >= 0 && l % 10 === k).length;
  for (let k = 0; k < 10; k++) {
    if (used.has(k)) assert.ok(px.colour[k] >= 6 * Math.min(dots(k), 20), `colour ${PALETTE[k]}: ${px.colour[k]} px for ${dots(k)} points`);
    else assert.ok(px.colour[k] < 20, `unused colour ${PALETTE[k]}: ${px.colour[k]} px`);
  }
}));
