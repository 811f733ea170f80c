// openLog on real MCAP files written by @mcap/core's McapWriter (ROS 2 CDR LaserScan from tests/data's CARMEN logs,
// PointCloud2 from the Ouster excerpt) at each chunk compression: the scans read back equal the package's own readers'
// points; bad input gives a LogError naming the file, topic and message index after every good scan before it.
import test from 'node:test';
import assert from 'node:assert/strict';
import { mkdtempSync, readFileSync, rmSync, writeFileSync } from 'node:fs';
import { open } from 'node:fs/promises';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { fileURLToPath } from 'node:url';
import init from 'rtl-wasm';
import { openLog, LogError } from 'rtl-wasm/logs';
import { McapIndexedReader } from '@mcap/core';
import { loadDecompressHandlers } from '@mcap/support';
import { laserScanOf, stampOf, writeMcap } from './ros-fixtures.mjs';

const DATA = fileURLToPath(new URL('../data/', import.meta.url));
const rtl = await init();
const intel = rtl.readCarmenLog(readFileSync(join(DATA, 'intel.log')));
const csail = rtl.readCarmenLog(readFileSync(join(DATA, 'csail.log')));
const ousterBin = readFileSync(join(DATA, 'rellis3d-os1-4x2048.bin'));
const ouster = rtl.readOrganizedLidar(ousterBin, { beams: 4 });
const dir = mkdtempSync(join(tmpdir(), 'rtl-ros-logs-'));
test.after(() => rmSync(dir, { recursive: true, force: true }));

// The Ouster excerpt as an organised PointCloud2 the way the Ouster ROS driver lays it out: one row per beam, x, y, z,
// intensity float32 and ring uint16 (point_step 20). The excerpt's records are column-major (column * 4 + beam).
function ousterCloud(t) {
  const beams = 4, cols = 2048, step = 20;
  const data = new Uint8Array(beams * cols * step);
  const out = new DataView(data.buffer), src = new DataView(ousterBin.buffer, ousterBin.byteOffset, ousterBin.byteLength);
  for (let c = 0; c < cols; c++) {
    for (let b = 0; b < beams; b++) {
      const from = (c * beams + b) * 16, to = (b * cols + c) * step;
      for (let k = 0; k < 4; k++) out.setFloat32(to + 4 * k, src.getFloat32(from + 4 * k, true), true);
      out.setUint16(to + 16, b, true);
    }
  }
  const f = (name, offset, datatype) => ({ name, offset, datatype, count: 1 });
  return { header: { stamp: stampOf(t), frame_id: 'os_sensor' }, height: beams, width: cols,
           fields: [f('x', 0, 7), f('y', 4, 7), f('z', 8, 7), f('intensity', 12, 7), f('ring', 16, 4)],
           is_bigendian: false, point_step: step, row_step: step * cols, data, is_dense: false };
}

const CHANNELS = () => [
  { topic: '/scan', type: 'sensor_msgs/msg/LaserScan', messages: intel.map((s) => ({ time: s.timestamp, msg: laserScanOf(s) })) },
  { topic: '/csail/scan', type: 'sensor_msgs/msg/LaserScan',
    messages: csail.map((s, i) => ({ time: intel[0].timestamp + 0.05 + i * 0.2, msg: laserScanOf(s) })) },
  { topic: '/os_cloud', type: 'sensor_msgs/msg/PointCloud2',
    messages: [0, 1, 2].map((k) => ({ time: intel[0].timestamp + 0.01 + k, msg: ousterCloud(100 + k) })) },
  { topic: '/chatter', type: 'std_msgs/msg/String', messages: [{ time: intel[0].timestamp, msg: { data: 'hello' } }] },
];

function assertScanEquals(got, carmen, what) {
  assert.equal(got.points.length, carmen.points.length, `${what}: beams`);
  for (let k = 0; k < carmen.points.length; k++) {
    const a = got.points[k], b = carmen.points[k];
    if (Number.isNaN(b)) assert.ok(Number.isNaN(a), `${what}: coordinate ${k} must be a gap, got ${a}`);
    // float32 ranges and angles in the message: a few micrometres at 80 m
    else assert.ok(Math.abs(a - b) <= 2e-5, `${what}: coordinate ${k}: ${a} vs ${b}`);
  }
  assert.ok(Math.abs(got.stamp - carmen.timestamp) < 1e-6, `${what}: stamp`);
}

// The chunk index of an MCAP, read with @mcap/core itself (to aim the damage at a chunk).
async function indexOf(bytes) {
  return McapIndexedReader.Initialize({
    readable: { size: async () => BigInt(bytes.length), read: async (o, n) => bytes.subarray(Number(o), Number(o + n)) },
    decompressHandlers: await loadDecompressHandlers() });
}

async function collect(iter) {
  const out = [];
  let error;
  try {
    for await (const s of iter) out.push(s);
  } catch (e) {
    error = e;
  }
  return { scans: out, error };
}

for (const compression of ['none', 'lz4', 'zstd']) {
  const path = join(dir, `robot-${compression}.mcap`);
  test(`openLog (MCAP, ${compression} chunks): topics, and LaserScans equal to readCarmenLog's points`, async () => {
    await writeMcap(path, CHANNELS(), { compression, chunkSize: 16 * 1024 });
    const log = await openLog(path);
    try {
      assert.equal(log.format, 'mcap');
      assert.deepEqual(log.topics.map((t) => [t.name, t.type, t.count]).sort(), [
        ['/chatter', 'std_msgs/msg/String', 1], ['/csail/scan', 'sensor_msgs/msg/LaserScan', 30],
        ['/os_cloud', 'sensor_msgs/msg/PointCloud2', 3], ['/scan', 'sensor_msgs/msg/LaserScan', 30]]);
      for (const [topic, carmen] of [['/scan', intel], ['/csail/scan', csail]]) {
        const { scans, error } = await collect(log.scans(topic));
        assert.equal(error, undefined);
        assert.equal(scans.length, carmen.length);
        scans.forEach((s, i) => {
          assert.equal(s.index, i);
          assert.equal(s.topic, topic);
          assert.equal(s.frameId, 'laser');
          assertScanEquals(s, carmen[i], `${topic} scan ${i}`);
        });
      }
    } finally {
      await log.close();
    }
  });

  test(`openLog (MCAP, ${compression} chunks): organised PointCloud2 equal to readOrganizedLidar's cloud`, async () => {
    const log = await openLog(path);
    const { scans, error } = await collect(log.scans('/os_cloud'));
    await log.close();
    assert.equal(error, undefined);
    assert.equal(scans.length, 3);
    for (const c of scans) {
      assert.equal(c.beams, 4); assert.equal(c.columns, 2048);
      assert.deepEqual(c.points, ouster.points);
      assert.deepEqual(c.intensity, ouster.intensity);
      assert.deepEqual(c.ring(2), ouster.ring(2));
      assert.deepEqual([...c.rings.subarray(0, 8)], [0, 1, 2, 3, 0, 1, 2, 3]);
    }
    assert.deepEqual(scans.map((c) => c.stamp), [100, 101, 102]);
  });
}

test('openLog: a Blob, a FileHandle and bytes read the same scans as the path; start/end select by log time', async () => {
  const path = join(dir, 'robot-zstd.mcap');
  const bytes = readFileSync(path);
  const fh = await open(path, 'r');
  const fromHandle = await openLog(fh, { name: 'handle.mcap' });
  const fromBlob = await openLog(new Blob([bytes]));
  const fromBytes = await openLog(new Uint8Array(bytes));
  for (const log of [fromHandle, fromBlob, fromBytes]) {
    const { scans } = await collect(log.scans('/scan'));
    assert.equal(scans.length, 30);
    scans.forEach((s, i) => assertScanEquals(s, intel[i], `${log.file} scan ${i}`));
    const t5 = scans[5].logTime, t9 = scans[9].logTime;
    const part = (await collect(log.scans('/scan', { start: t5, end: t9 }))).scans;
    assert.deepEqual(part.map((s) => s.logTime), scans.slice(5, 10).map((s) => s.logTime));
    const bySeconds = (await collect(log.scans('/scan', { start: Number(t5) / 1e9 - 1e-4, end: Number(t9) / 1e9 + 1e-4 }))).scans;
    assert.equal(bySeconds.length, 5);
    await log.close();
  }
  assert.equal(fromHandle.file, 'handle.mcap');
  await fh.stat();   // still open: a caller's handle is the caller's to close
  await fh.close();
});

test('the read scans run through the pipeline: segment and vectorize give the same result as on readCarmenLog points', async () => {
  const log = await openLog(join(dir, 'robot-lz4.mcap'));
  let n = 0, segments = 0;
  try {
    for await (const s of log.scans('/csail/scan')) {
      const a = rtl.segment(s.points), b = rtl.segment(csail[s.index].points);
      assert.deepEqual(a.labels, b.labels, `scan ${s.index}: segmentation`);
      for (let c = 0; c < b.clusters.length; c++) {
        const idx = b.clusters[c].indices;
        if (idx.length < 3) continue;
        const pick = (pts) => Float64Array.from(Array.from(idx, (i) => [pts[2 * i], pts[2 * i + 1]]).flat());
        const va = rtl.vectorize(pick(s.points), { method: 'ftls' }), vb = rtl.vectorize(pick(csail[s.index].points), { method: 'ftls' });
        assert.equal(va.count, vb.count, `scan ${s.index} cluster ${c}: segments`);
        for (let k = 0; k < vb.segments.length; k++)
          assert.ok(Math.abs(va.segments[k] - vb.segments[k]) < 1e-3, `scan ${s.index} cluster ${c}: coordinate ${k}`);
        segments += vb.count;
      }
      n++;
    }
  } finally {
    await log.close();
  }
  assert.equal(n, 30);
  assert.ok(segments > 30 * 5, `${segments} segments`);
});

test('openLog: an unknown topic or one of another type is a LogError naming the file and topic', async () => {
  const path = join(dir, 'robot-none.mcap');
  const log = await openLog(path);
  assert.throws(() => log.scans('/nope'), (e) => e instanceof LogError && e.code === 'UNKNOWN_TOPIC' && e.topic === '/nope' &&
                e.file === path && e.message.includes(path) && e.message.includes('/nope') && e.message.includes('/scan'));
  assert.throws(() => log.scans('/chatter'), (e) => e instanceof LogError && e.code === 'WRONG_TYPE' && e.message.includes('std_msgs/msg/String'));
  assert.throws(() => log.scans(5), (e) => e instanceof TypeError && e.message.startsWith('scans: '));
  assert.throws(() => log.scans('/scan', { start: NaN }), (e) => e instanceof RangeError && e.message.startsWith('scans: '));
  assert.throws(() => log.scans('/scan', { start: 5, end: 4 }), RangeError);
  assert.throws(() => log.scans('/scan', null), TypeError);
  await log.close();
  await assert.rejects(openLog(42), (e) => e instanceof TypeError && e.message.startsWith('openLog: '));
  await assert.rejects(openLog(path, { name: 3 }), TypeError);
  await assert.rejects(openLog(new Uint8Array(100)), (e) => e instanceof LogError && e.code === 'FORMAT');
  await assert.rejects(openLog(join(dir, 'missing.mcap')), (e) => e.code === 'ENOENT');
});

for (const compression of ['none', 'lz4', 'zstd']) {
  test(`openLog (MCAP, ${compression}): a truncated file delivers every complete scan, then a LogError at the first missing one`, async () => {
    const bytes = readFileSync(join(dir, `robot-${compression}.mcap`));
    const reader = await indexOf(bytes);
    // cut inside the last chunk: the reader can only fall back to streaming, and gets every chunk before it
    const last = reader.chunkIndexes[reader.chunkIndexes.length - 1];
    const cut = Number(last.chunkStartOffset + last.chunkLength / 2n);
    const complete = reader.chunkIndexes.filter((c) => Number(c.chunkStartOffset + c.chunkLength) <= cut);
    const lastTime = complete.reduce((t, c) => (c.messageEndTime > t ? c.messageEndTime : t), -1n);
    const expected = intel.filter((s) => BigInt(Math.round(s.timestamp * 1e9)) <= lastTime).length;
    assert.ok(expected > 3 && expected < 30, `${expected} scans before the cut`);
    const path = join(dir, `truncated-${compression}.mcap`);
    writeFileSync(path, bytes.subarray(0, cut));
    const log = await openLog(path);
    assert.ok(log.unindexed, 'read without an index');
    const { scans, error } = await collect(log.scans('/scan'));
    await log.close();
    assert.equal(scans.length, expected);
    scans.forEach((s, i) => assertScanEquals(s, intel[i], `scan ${i}`));
    assert.ok(error instanceof LogError, String(error));
    assert.equal(error.code, 'TRUNCATED');
    assert.equal(error.index, expected);
    assert.equal(error.topic, '/scan');
    assert.ok(error.message.includes(path) && error.message.includes(`message ${expected}`), error.message);
  });

  test(`openLog (MCAP, ${compression}): a corrupt chunk delivers every scan before it, then a LogError naming the index`, async () => {
    const bytes = new Uint8Array(readFileSync(join(dir, `robot-${compression}.mcap`)));
    const reader = await indexOf(bytes);
    assert.ok(reader.chunkIndexes.length >= 4, `${reader.chunkIndexes.length} chunks`);
    const victim = reader.chunkIndexes[Math.floor(reader.chunkIndexes.length / 2)];
    const from = Number(victim.chunkStartOffset) + 60, to = Number(victim.chunkStartOffset + victim.chunkLength) - 8;
    for (let k = from; k < to; k += 7) bytes[k] ^= 0x5a;
    const path = join(dir, `corrupt-${compression}.mcap`);
    writeFileSync(path, bytes);
    const expected = intel.filter((s) => BigInt(Math.round(s.timestamp * 1e9)) < victim.messageStartTime).length;
    const log = await openLog(path);
    const { scans, error } = await collect(log.scans('/scan'));
    await log.close();
    assert.equal(scans.length, expected);
    scans.forEach((s, i) => assertScanEquals(s, intel[i], `scan ${i}`));
    assert.ok(error instanceof LogError, String(error));
    assert.ok(error.code === 'CORRUPT' || error.code === 'DECODE', error.code);
    assert.equal(error.index, expected);
    assert.ok(error.message.includes(path) && error.message.includes('/scan') && error.message.includes(`message ${expected}`), error.message);
  });
}
