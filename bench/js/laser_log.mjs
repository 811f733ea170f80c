// The robot log the log benches read (b_logs.mjs, b_logs_paired.mjs): sensor_msgs/msg/LaserScan messages of 360 beams
// (the first 360 of each CSAIL excerpt scan, cycled), ROS 2 CDR, written by @mcap/core's McapWriter in 1 MB chunks,
// one message every 25 ms (40 Hz). One writer, so that both benches time the same file.
import { open } from 'node:fs/promises';
import { McapWriter } from '@mcap/core';
import { COMPRESSIONS, LASER_SCAN_DEF, cdr } from '../../tests/js/ros-fixtures.mjs';

// The CDR payloads of CARMEN scans (readCarmenLog's, 361 beams over 180°): the first 360 beams of each, half a degree
// apart from -90°; range_max just under the log's maximum range, so that a no-return beam stays one.
export function laserScanPayloads(scans) {
  return scans.map((s) => {
    const n = 360, step = Math.PI / 360;
    return cdr('sensor_msgs/msg/LaserScan', {
      header: { stamp: { sec: 0, nanosec: 0 }, frame_id: 'laser' },
      angle_min: -Math.PI / 2, angle_max: -Math.PI / 2 + (n - 1) * step, angle_increment: step, time_increment: 0, scan_time: 0,
      range_min: 0, range_max: s.maxRange * (1 - 1e-6), ranges: Float32Array.from(s.ranges.subarray(0, n)), intensities: new Float32Array(0),
    });
  });
}

// Writes `count` messages on /scan, payload i % payloads.length for message i, chunks compressed by `compression`
// ('none', 'lz4' or 'zstd').
export async function writeLaserLog(path, payloads, count, compression = 'none') {
  const fh = await open(path, 'w');
  try {
    let pos = 0n;
    const w = new McapWriter({ writable: { position: () => pos, write: async (b) => { await fh.write(b); pos += BigInt(b.byteLength); } },
      chunkSize: 1 << 20, compressChunk: COMPRESSIONS[compression] });
    await w.start({ profile: 'ros2', library: 'rtl-wasm bench' });
    const schemaId = await w.registerSchema({ name: 'sensor_msgs/msg/LaserScan', encoding: 'ros2msg', data: new TextEncoder().encode(LASER_SCAN_DEF) });
    const channelId = await w.registerChannel({ topic: '/scan', schemaId, messageEncoding: 'cdr', metadata: new Map() });
    for (let i = 0; i < count; i++) {
      const t = BigInt(i) * 25000000n + 1000000000n;
      await w.addMessage({ channelId, sequence: i, logTime: t, publishTime: t, data: payloads[i % payloads.length] });
    }
    await w.end();
  } finally {
    await fh.close();
  }
}
