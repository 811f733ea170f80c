// The package's option defaults (the `defaults` export, wasm/js/defaults.js) are the ones its functions use: a call
// without an option gives exactly what the same call with the exported default gives, on a real scan; a different
// value changes the result (so the comparison can fail). CommonJS gives the same object (tests/js/load.test.cjs).
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import init, { defaults } from 'rtl-wasm';

const rtl = await init();
const log = readFileSync(new URL('../data/intel.log', import.meta.url), 'utf8');
const scans = rtl.readCarmenLog(log).slice(0, 6);
const finite = (xy) => xy.filter((_, i) => Number.isFinite(xy[i - (i % 2)]) && Number.isFinite(xy[i - (i % 2) + 1]));

test('defaults: frozen, every level', () => {
  assert.ok(Object.isFrozen(defaults));
  for (const k of Object.keys(defaults)) assert.ok(Object.isFrozen(defaults[k]), k);
  assert.deepEqual(Object.keys(defaults).sort(), ['extractPolylines', 'segment', 'streamSegmenter', 'vectorize']);
});

test('segment(): no options = defaults.segment; another upperBound differs', () => {
  let differs = 0;
  for (const s of scans) {
    const plain = rtl.segment(s.points);
    assert.deepEqual(rtl.segment(s.points, { ...defaults.segment }), plain);
    const other = rtl.segment(s.points, { ...defaults.segment, upperBound: defaults.segment.upperBound / 5 });
    if (other.clusters.length !== plain.clusters.length) differs++;
  }
  assert.ok(differs > 0, 'upperBound / 5 changes some scan\'s clusters');
});

test('vectorize(): no options but method = method + defaults.vectorize, every method; another sigma differs', () => {
  for (const method of ['ftls', 'aftls', 'itls', 'dp', 'rw']) {
    let differs = 0;
    for (const s of scans.slice(0, 3)) {
      const xy = finite(s.points);
      const plain = rtl.vectorize(xy, { method });
      assert.deepEqual(rtl.vectorize(xy, { method, ...defaults.vectorize }), plain, method);
      const other = rtl.vectorize(xy, { method, ...defaults.vectorize, sigma: 4 * defaults.vectorize.sigma, epsilon: 4 * defaults.vectorize.epsilon });
      if (other.count !== plain.count) differs++;
    }
    assert.ok(differs > 0, `${method}: 4x sigma / epsilon changes some scan's segment count`);
  }
});

test('extractPolylines(): no options = defaults.extractPolylines; a smaller budget differs', () => {
  let differs = 0;
  for (const s of scans) {
    const plain = rtl.extractPolylines(s.points);
    assert.ok(plain.vertexCount > 0 && plain.vertexCount <= defaults.extractPolylines.maxVertices);
    assert.deepEqual(rtl.extractPolylines(s.points, { ...defaults.extractPolylines }), plain);
    const other = rtl.extractPolylines(s.points, { ...defaults.extractPolylines, maxVertices: defaults.extractPolylines.maxVertices / 5 });
    if (other.vertexCount !== plain.vertexCount) differs++;
  }
  assert.ok(differs > 0, 'a fifth of the vertex budget changes some scan\'s polylines');
});

test('new StreamSegmenter(): no options = defaults.streamSegmenter', () => {
  const clusters = (opts) => {
    const seg = new rtl.StreamSegmenter(opts);
    try {
      const out = [];
      for (const s of scans) { seg.addPoints(s.points); out.push(...seg.takeClosedClusters().map((c) => Array.from(c))); }
      seg.flush();
      out.push(...seg.takeClosedClusters().map((c) => Array.from(c)));
      return out;
    } finally {
      seg.dispose();
    }
  };
  const plain = clusters();
  assert.ok(plain.length > 10);
  assert.deepEqual(clusters({ ...defaults.streamSegmenter }), plain);
  assert.notDeepEqual(clusters({ ...defaults.streamSegmenter, scaling: defaults.streamSegmenter.scaling / 10 }), plain);
});
