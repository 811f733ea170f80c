// rtl-wasm/log-worker in a worker_threads Worker (the same module a browser runs as a module Web Worker): a whole log
// processed off the main thread with progress; results equal the main thread's segment(); errors after the good scans.
import test from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { join } from 'node:path';
import { fileURLToPath } from 'node:url';
import { createRequire } from 'node:module';
import { Worker } from 'node:worker_threads';
import init from 'rtl-wasm';

const DATA = fileURLToPath(new URL('../data/', import.meta.url));
const WORKER = createRequire(import.meta.url).resolve('rtl-wasm/log-worker');
const rtl = await init();
const intel = rtl.readCarmenLog(readFileSync(join(DATA, 'intel.log')));

// Runs one request; resolves with every message the worker posted up to 'done' or 'error'.
function runWorker(request, { cancelAfterFirstBatch = false } = {}) {
  const w = new Worker(WORKER);
  const got = [];
  return new Promise((resolve, reject) => {
    w.on('error', reject);
    w.on('message', (m) => {
      got.push(m);
      if (m.type === 'scans' && cancelAfterFirstBatch) w.postMessage({ type: 'cancel' });
      if (m.type === 'done' || m.type === 'error') { w.terminate(); resolve(got); }
    });
    w.postMessage(request);
  });
}

test('log-worker: a bag processed in the worker, in batches with progress; labels equal segment() on readCarmenLog points', async () => {
  for (const source of [join(DATA, 'ros1', 'intel-bz2.bag'), new Blob([readFileSync(join(DATA, 'ros1', 'intel-bz2.bag'))])]) {
    const msgs = await runWorker({ type: 'open', source, vectorize: { method: 'ftls' }, batch: 8 });
    assert.equal(msgs[0].type, 'topics');
    assert.ok(msgs[0].topics.some((t) => t.name === '/base_scan' && t.count === 30));
    const scans = msgs.filter((m) => m.type === 'scans').flatMap((m) => m.scans);
    assert.deepEqual(msgs.filter((m) => m.type === 'scans').map((m) => m.scans.length), [8, 8, 8, 6]);
    assert.deepEqual(msgs.filter((m) => m.type === 'progress').map((m) => [m.done, m.total]), [[8, 30], [16, 30], [24, 30], [30, 30]]);
    assert.deepEqual(msgs.at(-1), { type: 'done', done: 30, cancelled: false });
    scans.forEach((s, i) => {
      assert.equal(s.index, i);
      assert.deepEqual(s.labels, rtl.segment(intel[i].points).labels, `scan ${i} labels`);
      assert.ok(s.segments instanceof Float64Array && s.segments.length > 0 && s.segments.length % 4 === 0);
    });
  }
});

test('log-worker: cancel stops after the current scan; a topic of another type or an unknown request ends with a typed error', async () => {
  const cancelled = await runWorker({ type: 'open', source: join(DATA, 'ros1', 'intel-none.bag'), batch: 4 }, { cancelAfterFirstBatch: true });
  const end = cancelled.at(-1);
  assert.equal(end.type, 'done');
  assert.equal(end.cancelled, true);
  assert.ok(end.done < 30 && end.done >= 4, `${end.done} scans`);
  const msgs = await runWorker({ type: 'open', source: join(DATA, 'ros1', 'intel-none.bag'), topic: '/chatter' });
  assert.equal(msgs.at(-1).type, 'error');
  assert.equal(msgs.at(-1).error.code, 'WRONG_TYPE');
  const bad = await runWorker({ type: 'frobnicate' });
  assert.equal(bad.at(-1).type, 'error');
  assert.match(bad.at(-1).error.message, /^log-worker: unknown message/);
});
