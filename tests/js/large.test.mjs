// 10 million points: fitLine, segment and Douglas-Peucker on a 10M-point scan. The wasm memory grows from 16 MB to
// hundreds of MB during these calls; results must be complete and correct (no detached views) and the heap must
// return to where it was.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import init from 'rtl-wasm';
import { near } from './helpers.mjs';

test('10,000,000 points: fitLine, segment, vectorize (dp) with memory growth', { timeout: 120_000 }, () => {
  return init().then((rtl) => {
    const n = 10_000_000;
    const mem0 = rtl.memoryBytes();
    // A straight line y = 0.5 x - 3 with points moved +-0.01 along the normal in pairs, and a break every 1000
    // points (a 1 m jump across the line direction) so that segmentation has 10,000 clusters.
    const xy = new Float64Array(2 * n);
    const nx = -0.5 / Math.hypot(0.5, 1), ny = 1 / Math.hypot(0.5, 1);
    for (let i = 0; i < n; i++) {
      const t = Math.floor(i / 2) * 1e-4 + Math.floor(i / 1000) * 1.0;   // 1000 points span 0.05 m, then a 1 m jump
      const e = (i % 2 ? 0.01 : -0.01);
      xy[2 * i] = t + e * nx;
      xy[2 * i + 1] = 0.5 * t - 3 + e * ny;
    }
    const heap0 = rtl.heapInUse();
    const f = rtl.fitLine(xy);
    assert.equal(f.count, n);
    near(Math.abs(f.normal[0]), -nx, 1e-9, 'normal x');
    near(f.rms, 0.01, 1e-6, 'rms');
    assert.ok(rtl.memoryBytes() > 16 * n && mem0 < 16 * n, `memory grew (${mem0} -> ${rtl.memoryBytes()})`);

    const s = rtl.segment(xy, { step: 2, lowerBound: 0.1, upperBound: 0.5 });
    assert.equal(s.labels.length, n);
    assert.equal(s.clusters.length, 10_000);
    for (const k of [0, 1, 4999, 9999]) assert.deepEqual(Array.from(s.clusters[k].ranges), [1000 * k, 1000 * k + 1000], `cluster ${k}`);
    assert.equal(s.labels[n - 1], 9999);

    const v = rtl.vectorize(xy, { method: 'dp', epsilon: 0.05 });
    assert.equal(v.ok, true);
    assert.equal(v.indices[0], 0);
    assert.equal(v.indices[2 * v.count - 1], n);
    assert.equal(v.segments.length, 4 * v.count);
    for (let k = 0; k < v.count; k++) assert.ok(v.rms[k] <= 0.05, 'within epsilon');
    assert.equal(rtl.heapInUse(), heap0, 'every temporary freed');
    near(rtl.fitLine([0, 1, 1, 1]).offset, -1, 0, 'small call after growth');
  });
});
