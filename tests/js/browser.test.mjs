// The whole API in headless Chromium (the browser entry dist/index.js, ES6 web glue, .wasm fetched by the glue):
// readers on fetched files, segment, vectorize, stateful classes with Symbol.dispose, SVG, and error classes.
// Uses the page tests' server and browser helpers (tests/web/helpers.js).
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { launchBrowser, startServer } from '../web/helpers.js';

test('Chromium: every function of the package works from the browser entry', { timeout: 120_000 }, async () => {
  const server = await startServer();
  const browser = await launchBrowser();
  try {
    const page = browser.context.pages()[0] ?? await browser.context.newPage();
    const errors = [];
    page.on('pageerror', (e) => errors.push(e.message));
    await page.goto(`${server.origin}/tests/data/README.md`);
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
        kinds: [...kinds].sort(), heapSame: rtl.heapInUse() === heap,
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
  } finally {
    await browser.close();
    await server.close();
  }
});
