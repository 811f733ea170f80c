// Fuzz of openLog with damaged logs: real files (an MCAP written by McapWriter at each compression, the committed
// ROS 1 bags) with random bytes flipped, ranges zeroed or cut. Opening and reading every scan either succeeds or
// fails with a LogError naming the file (never another error, a hang or a crash), and every scan delivered is
// well formed.
import test from 'node:test';
import assert from 'node:assert/strict';
import { mkdtempSync, readFileSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { fileURLToPath } from 'node:url';
import init from 'rtl-wasm';
import { openLog, LogError } from 'rtl-wasm/logs';
import { laserScanOf, writeMcap } from './ros-fixtures.mjs';

const DATA = fileURLToPath(new URL('../data/', import.meta.url));
const rtl = await init();
const intel = rtl.readCarmenLog(readFileSync(join(DATA, 'intel.log')));
const dir = mkdtempSync(join(tmpdir(), 'rtl-ros-fuzz-'));
test.after(() => rmSync(dir, { recursive: true, force: true }));

function rng(seed) {
  let s = seed >>> 0;
  return () => ((s = (Math.imul(s, 1664525) + 1013904223) >>> 0) / 4294967296);
}

function damage(r, bytes) {
  const b = new Uint8Array(bytes);
  const kind = r();
  if (kind < 0.5) {
    for (let k = 0, n = 1 + Math.floor(r() * 8); k < n; k++) b[Math.floor(r() * b.length)] ^= 1 << Math.floor(r() * 8);
  } else if (kind < 0.75) {
    const at = Math.floor(r() * b.length);
    b.fill(r() < 0.5 ? 0 : 0xff, at, Math.min(b.length, at + 1 + Math.floor(r() * 64)));
  } else {
    return b.subarray(0, Math.floor(r() * b.length));
  }
  return b;
}

async function readAll(bytes, topic, name) {
  const log = await openLog(bytes, { name });
  let n = 0;
  try {
    for (const t of log.topics) assert.equal(typeof t.name, 'string');
    for await (const s of log.scans(topic)) {
      assert.ok(s.points instanceof Float64Array && s.points.length === 2 * s.angles.length);
      n++;
    }
  } finally {
    await log.close();
  }
  return n;
}

test('fuzz: damaged MCAP files and ROS 1 bags give scans or a LogError naming the file', async () => {
  const sources = [];
  for (const compression of ['none', 'lz4', 'zstd']) {
    const path = join(dir, `fuzz-${compression}.mcap`);
    await writeMcap(path, [{ topic: '/scan', type: 'sensor_msgs/msg/LaserScan',
      messages: intel.slice(0, 12).map((s) => ({ time: s.timestamp, msg: laserScanOf(s) })) }], { compression, chunkSize: 4096 });
    sources.push({ bytes: readFileSync(path), topic: '/scan' });
  }
  for (const c of ['none', 'lz4', 'bz2']) sources.push({ bytes: readFileSync(join(DATA, 'ros1', `intel-${c}.bag`)), topic: '/base_scan' });
  const r = rng(35);
  const outcome = { ok: 0, logError: 0 };
  for (let i = 0; i < 600; i++) {
    const src = sources[i % sources.length];
    const name = `damaged-${i}`;
    try {
      await readAll(damage(r, src.bytes), src.topic, name);
      outcome.ok++;
    } catch (e) {
      assert.ok(e instanceof LogError, `case ${i}: ${e?.name}: ${e?.message}`);
      assert.ok(e.message.includes(name), `case ${i}: the message names the file: ${e.message}`);
      outcome.logError++;
    }
  }
  assert.ok(outcome.ok > 50 && outcome.logError > 50, JSON.stringify(outcome));
});
