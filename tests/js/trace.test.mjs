// Traces: segment(points, { trace: true }), vectorize(points, { ..., trace: true }) and the stream
// segmenter's { trace: true } + takeTrace() return the steps the C++ algorithms took, as plain objects. On every
// scan in tests/data: the traced result equals the untraced one, a replay of the trace ends in the returned
// result, and the same call gives the same trace (deterministic step counts).
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import init from 'rtl-wasm';
import { throwsWith } from './helpers.mjs';

const rtl = await init();
const DATA = new URL('../data/', import.meta.url);
const scans2 = ['intel.log', 'csail.log'].flatMap((f) => rtl.readCarmenLog(readFileSync(new URL(f, DATA))).map((s) => s.points));
const cloud = rtl.readOrganizedLidar(readFileSync(new URL('rellis3d-os1-4x2048.bin', DATA)), { beams: 4 });
const scans3 = [0, 1, 2, 3].map((b) => cloud.ring(b));
const withoutTrace = ({ trace, ...rest }) => rest;
const gather = (xy, idx, dim) => Float64Array.from(Array.from(idx).flatMap((i) => Array.from(xy.subarray(dim * i, dim * i + dim))));

// CAR replay (SegTrace.h): start/link/merge build the labels; the cluster events list the returned clusters.
function replayCar(events, n) {
  const label = new Array(n).fill(-1);
  for (const e of events) {
    if (e.kind === 'start') label[e.i] = e.i;
    else if (e.kind === 'link') label[e.i] = e.cluster;
    else if (e.kind === 'merge') for (let k = 0; k < n; k++) if (label[k] === e.from) label[k] = e.into;
  }
  return { label, clusters: events.filter((e) => e.kind === 'cluster') };
}

const clusters = { 2: [], 3: [] };
test('segment trace: equals the untraced result and replays to it, on every real scan (2D and 3D), deterministic', { timeout: 120_000 }, () => {
  let events = 0;
  for (const [dim, scans] of [[2, scans2], [3, scans3]]) {
    for (const step of [1, 2, 3, 5]) {
      scans.forEach((xy, s) => {
        const what = `dim ${dim} scan ${s} step ${step}`;
        const o = { dim, step, lowerBound: 0.1, upperBound: 0.5 };
        const plain = rtl.segment(xy, o);
        assert.equal('trace' in plain, false, 'no trace unless asked');
        const traced = rtl.segment(xy, { ...o, trace: true });
        assert.deepEqual(withoutTrace(traced), plain, `${what}: same result`);
        const t = traced.trace;
        assert.ok(Array.isArray(t) && t.every((e) => typeof e.kind === 'string'));
        assert.deepEqual(t[0], { kind: 'scan', size: xy.length / dim, step, window: step - 1, scaling: t[0].scaling, lowerBound: 0.1, upperBound: 0.5 });
        const n = xy.length / dim;
        const { label, clusters: cl } = replayCar(t, n);
        // The replayed partition is the returned one: same groups, labelled by their smallest index.
        assert.equal(cl.length, plain.clusters.length, `${what}: cluster count`);
        plain.clusters.forEach((c, k) => {
          assert.deepEqual(cl[k], { kind: 'cluster', index: k, label: Math.min(...c.indices), first: c.indices[0], size: c.indices.length }, `${what}: cluster ${k}`);
          for (const i of c.indices) assert.equal(label[i], cl[k].label, `${what}: point ${i} replayed into cluster ${k}`);
        });
        for (let i = 0; i < n; i++) if (plain.labels[i] < 0) assert.equal(label[i], -1, `${what}: gap ${i}`);
        for (const e of t) if (e.kind === 'compare' || e.kind === 'seam') {
          assert.equal(e.linked, e.distance <= e.threshold, `${what}: linked = distance <= threshold`);
          assert.ok(e.kind === 'seam' || (e.i - e.j >= 1 && e.i - e.j <= step - 1), `${what}: window of step - 1`);
        }
        if (s % 7 === 0) assert.deepEqual(rtl.segment(xy, { ...o, trace: true }).trace, t, `${what}: deterministic`);
        events += t.length;
        if (step === 2) for (const c of plain.clusters) if (c.indices.length >= 2) clusters[dim].push(gather(xy, c.indices, dim));
      });
    }
  }
  assert.ok(clusters[2].length > 300 && clusters[3].length > 20);
  console.log(`# segment traces: ${events} events`);
});

// Replays of the vectorizers' traces (SimplifyTrace.h, FtlsTrace.h) -> ranges as [first, end) pairs.
function replayItls(t) {
  let ranges = [];
  for (const e of t) {
    if (e.kind === 'close') ranges.push([e.first, e.end]);
    else if (e.kind === 'tail') ranges = ranges.slice(0, e.kept);
    else if (e.kind === 'tailRange') ranges.push([e.first, e.end]);
  }
  return ranges;
}
function replayKept(t, method) {
  if (method === 'rw') return t.filter((e) => e.kind === 'keep').map((e) => e.index);
  const start = t.find((e) => e.kind === 'start');
  const kept = start ? [0, start.count - 1] : [];
  for (const e of t) if (e.kind === 'range' && e.split) kept.push(e.farthest);
  return kept.sort((a, b) => a - b);
}

test('vectorize trace: equals the untraced result and its final events reproduce it, every method on every real cluster', { timeout: 300_000 }, () => {
  const runs = [];
  for (const method of ['ftls', 'aftls', 'itls', 'dp', 'rw']) runs.push([2, method]);
  for (const method of ['itls', 'dp', 'rw']) runs.push([3, method]);
  const counts = {};
  for (const [dim, method] of runs) {
    let events = 0;
    clusters[dim].forEach((xy, k) => {
      const what = `${dim}D ${method} cluster ${k}`;
      const o = { dim, method, sigma: 0.03, delta: 0.3, epsilon: 0.05 };
      const plain = rtl.vectorize(xy, o);
      assert.equal('trace' in plain, false);
      const traced = rtl.vectorize(xy, { ...o, trace: true });
      assert.deepEqual(withoutTrace(traced), plain, `${what}: same result`);
      const t = traced.trace;
      const idx = Array.from(plain.indices);
      const pairs = [];
      for (let s = 0; s < plain.count; s++) pairs.push([idx[2 * s], idx[2 * s + 1]]);
      if (method === 'dp' || method === 'rw') {
        const kept = replayKept(t, method);
        assert.deepEqual(kept, plain.count ? [...pairs.map((p) => p[0]), pairs.at(-1)[1] - 1] : kept, `${what}: kept points`);
      } else {
        const segs = t.filter((e) => e.kind === 'segment');
        assert.equal(segs.length, plain.count, `${what}: one segment event per segment`);
        segs.forEach((e, s) => {
          assert.deepEqual([e.first, e.end], pairs[s], `${what}: segment ${s} range`);
          const want = Array.from(plain.segments.subarray(2 * dim * s, 2 * dim * s + 2 * dim));
          const got = dim === 2 ? [e.x0, e.y0, e.x1, e.y1] : [e.x0, e.y0, e.z0, e.x1, e.y1, e.z1];
          assert.deepEqual(got, want, `${what}: segment ${s} end points`);
          if (method !== 'itls') {
            const off = Array.from(plain.polylineOffsets);
            assert.equal(off[e.polyline] <= s && s < off[e.polyline + 1], true, `${what}: segment ${s} in polyline ${e.polyline}`);
          }
        });
        if (method === 'itls') assert.deepEqual(replayItls(t), pairs, `${what}: close/tail/tailRange replay`);
        if (method !== 'itls') {
          assert.equal(t[0].kind, 'start');
          assert.equal(t[0].split, true);
          assert.equal(t[0].aftls, method === 'aftls');
          for (const e of t) {
            if (e.kind === 'trial') assert.equal(typeof e.pass, 'boolean');
            if (e.kind === 'corner') assert.equal(e.ok, e.crossingDistance <= e.delta, `${what}: corner ok = crossing <= delta`);
          }
        }
      }
      if (k % 25 === 0) assert.deepEqual(rtl.vectorize(xy, { ...o, trace: true }).trace, t, `${what}: deterministic`);
      events += t.length;
    });
    counts[`${dim}D ${method}`] = events;
  }
  console.log(`# vectorize trace events: ${JSON.stringify(counts)}`);
});

test('vectorize trace: strict FTLS that fails ends in an infeasible event naming the reported corner', () => {
  const L = [0, 0, 1, 0, 2, 0, 3, 0, 3, 1, 3, 2, 3, 3];
  for (const method of ['ftls', 'aftls']) {
    const v = rtl.vectorize(L, { method, split: false, trace: true });
    assert.equal(v.ok, false);
    const inf = v.trace.filter((e) => e.kind === 'infeasible');
    assert.deepEqual(inf, [{ kind: 'infeasible', boundary: v.failure.boundary, crossingDistance: v.failure.crossingDistance, delta: 0.3 }]);
    assert.equal(v.trace.filter((e) => e.kind === 'segment').length, 0);
  }
});

// IA replay (SegTrace.h): window, alive lists, closed queue.
function replayIa(events) {
  const alive = new Map(), closed = [];
  for (const e of events) {
    if (e.kind === 'alive') { if (!alive.has(e.cluster)) alive.set(e.cluster, []); alive.get(e.cluster).push(e.i); }
    else if (e.kind === 'merge') {
      const from = alive.get(e.from) || [], into = alive.get(e.into) || [];
      alive.set(e.into, [...into, ...from].sort((a, b) => a - b));
      alive.delete(e.from);
    } else if (e.kind === 'close') { closed.push(alive.get(e.cluster) || []); alive.delete(e.cluster); }
  }
  return closed;
}

test('StreamSegmenter trace: takeTrace() returns and clears the steps; replay = the closed clusters; untraced unchanged', () => {
  for (const [dim, xy] of [[2, scans2[3]], [2, scans2[40]], [3, scans3[1]]]) {
    const o = { dim, step: 3, lowerBound: 0.1, upperBound: 0.5, scaling: 0.05 };
    const plain = new rtl.StreamSegmenter(o);
    const traced = new rtl.StreamSegmenter({ ...o, trace: true });
    assert.equal(traced.traced, true);
    assert.equal(plain.traced, false);
    const events = [];
    const n = xy.length / dim;
    for (let b = 0; b < n; b += 97) {
      const chunk = xy.subarray(dim * b, dim * Math.min(n, b + 97));
      plain.addPoints(chunk);
      traced.addPoints(chunk);
      events.push(...traced.takeTrace());
      assert.deepEqual(traced.takeTrace(), [], 'takeTrace clears');
    }
    plain.flush();
    traced.flush();
    events.push(...traced.takeTrace());
    const a = plain.takeClosedClusters(), b = traced.takeClosedClusters();
    assert.deepEqual(b, a, 'same clusters traced and untraced');
    const replayed = replayIa(events);
    assert.equal(replayed.length, a.length);
    replayed.forEach((idx, k) => assert.deepEqual(gather(xy, idx, dim), a[k], `closed cluster ${k}`));
    assert.equal(events.filter((e) => e.kind === 'add').length, n, 'one add per point');
    throwsWith(() => plain.takeTrace(), TypeError, /^StreamSegmenter\.takeTrace: the segmenter was made without \{ trace: true \}$/);
    plain.dispose();
    traced.dispose();
    throwsWith(() => traced.takeTrace(), TypeError, /^StreamSegmenter\.takeTrace: the segmenter was disposed/);
  }
});

test('trace options are checked', () => {
  throwsWith(() => rtl.segment([0, 0], { trace: 1 }), TypeError, /^segment: option trace must be a boolean, got the number 1$/);
  throwsWith(() => rtl.vectorize([0, 0, 1, 1], { method: 'dp', trace: 'yes' }), TypeError, /^vectorize: option trace must be a boolean/);
  throwsWith(() => rtl.vectorize([0, 0, 0, 1, 1, 1], { dim: 3, method: 'ftls', trace: true }), RangeError, /^vectorize: option trace is not available for method 'ftls' in 3D/);
  throwsWith(() => new rtl.StreamSegmenter({ trace: null }), TypeError, /^StreamSegmenter: option trace must be a boolean, got null$/);
  const heap = rtl.heapInUse();
  for (let i = 0; i < 200; i++) rtl.vectorize(scans2[0].subarray(0, 40), { method: 'aftls', trace: true });
  assert.equal(rtl.heapInUse(), heap, 'traced calls leave the heap as it was');
});
