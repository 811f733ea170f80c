// openLog on ROS 1 bags written by ROS's own rosbag writer (tests/data/ros1/make_bags.py: the Intel excerpt as
// sensor_msgs/LaserScan, part of the Ouster excerpt as PointCloud2) at each chunk compression (none, lz4, bz2).
import test from 'node:test';
import assert from 'node:assert/strict';
import { mkdtempSync, readFileSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { fileURLToPath } from 'node:url';
import init from 'rtl-wasm';
import { openLog, LogError } from 'rtl-wasm/logs';
import { Bag } from '@foxglove/rosbag';

const DATA = fileURLToPath(new URL('../data/', import.meta.url));
const rtl = await init();
const intel = rtl.readCarmenLog(readFileSync(join(DATA, 'intel.log')));
const ouster64 = rtl.readOrganizedLidar(readFileSync(join(DATA, 'rellis3d-os1-4x2048.bin')).subarray(0, 64 * 4 * 16), { beams: 4 });
const dir = mkdtempSync(join(tmpdir(), 'rtl-ros-bag-'));
test.after(() => rmSync(dir, { recursive: true, force: true }));

async function collect(iter) {
  const scans = [];
  let error;
  try {
    for await (const s of iter) scans.push(s);
  } catch (e) {
    error = e;
  }
  return { scans, error };
}

function assertScanEquals(got, carmen, what) {
  assert.equal(got.points.length, carmen.points.length, `${what}: beams`);
  for (let k = 0; k < carmen.points.length; k++) {
    const a = got.points[k], b = carmen.points[k];
    if (Number.isNaN(b)) assert.ok(Number.isNaN(a), `${what}: coordinate ${k} must be a gap, got ${a}`);
    else assert.ok(Math.abs(a - b) <= 2e-5, `${what}: coordinate ${k}: ${a} vs ${b}`);
  }
  assert.ok(Math.abs(got.stamp - carmen.timestamp) < 1e-6, `${what}: stamp`);
}

for (const compression of ['none', 'lz4', 'bz2']) {
  const path = join(DATA, 'ros1', `intel-${compression}.bag`);

  test(`openLog (ROS 1 bag, ${compression}): topics, LaserScans equal to readCarmenLog's, clouds to readOrganizedLidar's`, async () => {
    const log = await openLog(path);
    try {
      assert.equal(log.format, 'bag');
      assert.deepEqual(log.topics.map((t) => [t.name, t.type, t.count]).sort(), [
        ['/base_scan', 'sensor_msgs/LaserScan', 30], ['/chatter', 'std_msgs/String', 1], ['/os_cloud', 'sensor_msgs/PointCloud2', 2]]);
      const { scans, error } = await collect(log.scans('/base_scan'));
      assert.equal(error, undefined);
      assert.equal(scans.length, 30);
      scans.forEach((s, i) => {
        assert.equal(s.index, i);
        assert.equal(s.maxRange, 50);
        assertScanEquals(s, intel[i], `scan ${i}`);
      });
      const clouds = (await collect(log.scans('/os_cloud'))).scans;
      assert.deepEqual(clouds.map((c) => c.stamp), [1000, 1001]);
      for (const c of clouds) {
        assert.equal(c.beams, 4); assert.equal(c.columns, 64);
        assert.deepEqual(c.points, ouster64.points);
        assert.deepEqual(c.intensity, ouster64.intensity);
      }
      const part = (await collect(log.scans('/base_scan', { start: intel[3].timestamp - 1e-4, end: intel[6].timestamp + 1e-4 }))).scans;
      assert.equal(part.length, 4);
      part.forEach((s, k) => assert.ok(Math.abs(s.stamp - intel[3 + k].timestamp) < 1e-6, `window scan ${k}`));
      assert.throws(() => log.scans('/chatter'), (e) => e instanceof LogError && e.code === 'WRONG_TYPE' && e.message.includes(path));
      assert.throws(() => log.scans('/scan'), (e) => e instanceof LogError && e.code === 'UNKNOWN_TOPIC' && e.message.includes('/base_scan'));
    } finally {
      await log.close();
    }
  });
}

test('openLog (ROS 1 bag): a Blob reads the same as the path', async () => {
  const bytes = readFileSync(join(DATA, 'ros1', 'intel-lz4.bag'));
  const log = await openLog(new Blob([bytes]));
  const { scans } = await collect(log.scans('/base_scan'));
  scans.forEach((s, i) => assertScanEquals(s, intel[i], `blob scan ${i}`));
  assert.equal(scans.length, 30);
});

// Where each /base_scan message of a whole bag becomes readable when the file is cut: the end of its message record
// in an uncompressed chunk, the end of its chunk record in a compressed one (from the bag's own index, read by
// @foxglove/rosbag's Bag).
async function messageEnds(bytes) {
  const bag = new Bag({ read: async (o, n) => bytes.subarray(o, o + n), size: () => bytes.length });
  await bag.open();
  const conn = [...bag.connections.values()].find((c) => c.topic === '/base_scan').conn;
  const { loadDecompressHandlers } = await import('@mcap/support');
  const h = await loadDecompressHandlers();
  const decompress = { lz4: (b, n) => h.lz4(b, BigInt(n)), bz2: (b, n) => h.bz2(b, BigInt(n)) };
  const ends = [];
  for (const info of [...bag.chunkInfos].sort((a, b) => a.chunkPosition - b.chunkPosition)) {
    const { chunk, indices } = await bag.reader.readChunk(info, decompress);
    for (const { offset } of indices.find((x) => x.conn === conn)?.indices ?? []) {
      const view = new DataView(chunk.data.buffer, chunk.data.byteOffset + offset);
      const header = view.getUint32(0, true), length = 8 + header + view.getUint32(4 + header, true);
      ends.push(chunk.compression === 'none' ? chunk.dataOffset + offset + length : chunk.end);
    }
  }
  return ends;
}

for (const compression of ['none', 'lz4', 'bz2']) {
  test(`openLog (ROS 1 bag, ${compression}): a bag cut at several offsets delivers every complete scan, then a TRUNCATED LogError naming the file, message and byte`, async () => {
    const bytes = new Uint8Array(readFileSync(join(DATA, 'ros1', `intel-${compression}.bag`)));
    const ends = await messageEnds(bytes);
    assert.equal(ends.length, 30);
    // through the chunks (mid-chunk, at a chunk's end) and into the index at the end of the file
    const cuts = [0.3, 0.45, 0.6, 0.75, 0.9, 0.99].map((f) => Math.floor(bytes.length * f));
    cuts.push(ends[15], ends[15] - 1, bytes.length - 1);
    let partial = 0;
    for (const cut of cuts) {
      const path = join(dir, `cut-${compression}-${cut}.bag`);
      writeFileSync(path, bytes.subarray(0, cut));
      const expected = ends.filter((e) => e <= cut).length;
      if (expected > 0 && expected < 30) partial++;
      const log = await openLog(path);
      try {
        assert.ok(log.unindexed, `cut at ${cut}: read front to back`);
        assert.equal(log.topics.find((t) => t.name === '/base_scan').count, expected, `cut at ${cut}: count`);
        const { scans, error } = await collect(log.scans('/base_scan'));
        assert.equal(scans.length, expected, `cut at ${cut}: scans`);
        scans.forEach((s, i) => { assert.equal(s.index, i); assertScanEquals(s, intel[i], `cut at ${cut}: scan ${i}`); });
        assert.ok(error instanceof LogError && error.code === 'TRUNCATED', `cut at ${cut}: ${error}`);
        assert.equal(error.index, expected);
        assert.equal(error.file, path);
        assert.ok(error.position >= 13 && error.position <= cut, `cut at ${cut}: position ${error.position}`);
        for (const part of [path, '/base_scan', `message ${expected}`, `byte ${error.position}`])
          assert.ok(error.message.includes(part), `cut at ${cut}: "${part}" in ${error.message}`);
      } finally {
        await log.close();
      }
    }
    assert.ok(partial >= 4, `${partial} cuts left part of the scans`);
  });
}

test('openLog (ROS 1 bag): a bag cut inside its header record is a TRUNCATED LogError naming the file', async () => {
  const bytes = readFileSync(join(DATA, 'ros1', 'intel-none.bag'));
  const path = join(dir, 'cut-header.bag');
  writeFileSync(path, bytes.subarray(0, 2000));
  await assert.rejects(openLog(path), (e) => e instanceof LogError && e.code === 'TRUNCATED' && e.message.includes(path) && e.message.includes('byte 13'));
});

for (const compression of ['lz4', 'bz2']) {
  test(`openLog (ROS 1 bag, ${compression}): a corrupt chunk delivers every scan before it, then a LogError naming the index`, async () => {
    const bytes = new Uint8Array(readFileSync(join(DATA, 'ros1', `intel-${compression}.bag`)));
    const bag = new Bag({ read: async (o, n) => bytes.subarray(o, o + n), size: () => bytes.length });
    await bag.open();
    const chunks = [...bag.chunkInfos].sort((a, b) => a.chunkPosition - b.chunkPosition);
    assert.ok(chunks.length >= 3, `${chunks.length} chunks`);
    const victim = chunks[Math.floor(chunks.length / 2)], next = chunks[Math.floor(chunks.length / 2) + 1];
    // damage the compressed body (past the chunk record's header, before the next record)
    for (let k = victim.chunkPosition + 80; k < next.chunkPosition - 200; k += 5) bytes[k] ^= 0xa5;
    const expected = intel.filter((s) => s.timestamp < victim.startTime.sec + victim.startTime.nsec * 1e-9 - 1e-6).length;
    const path = join(dir, `corrupt-${compression}.bag`);
    writeFileSync(path, bytes);
    const log = await openLog(path);
    const { scans, error } = await collect(log.scans('/base_scan'));
    await log.close();
    assert.equal(scans.length, expected);
    scans.forEach((s, i) => assertScanEquals(s, intel[i], `scan ${i}`));
    assert.ok(error instanceof LogError, String(error));
    assert.equal(error.index, expected);
    assert.ok(error.message.includes(path) && error.message.includes('/base_scan') && error.message.includes(`message ${expected}`), error.message);
  });
}
