// Test fixtures: ROS 2 message definitions and real MCAP files written by @mcap/core's McapWriter with CDR messages
// serialised by @foxglove/rosmsg2-serialization (the same writers ROS 2 tooling in JavaScript uses).
import { open } from 'node:fs/promises';
import { McapWriter } from '@mcap/core';
import { parse } from '@foxglove/rosmsg';
import { MessageWriter } from '@foxglove/rosmsg2-serialization';
import lz4 from 'lz4js';
import zstd from '@foxglove/wasm-zstd';

const SEP = '\n================================================================================\n';
const HEADER = `MSG: std_msgs/Header\nbuiltin_interfaces/Time stamp\nstring frame_id${SEP}MSG: builtin_interfaces/Time\nint32 sec\nuint32 nanosec`;

export const LASER_SCAN_DEF = `std_msgs/Header header
float32 angle_min
float32 angle_max
float32 angle_increment
float32 time_increment
float32 scan_time
float32 range_min
float32 range_max
float32[] ranges
float32[] intensities${SEP}${HEADER}`;

export const POINT_CLOUD2_DEF = `std_msgs/Header header
uint32 height
uint32 width
sensor_msgs/PointField[] fields
bool is_bigendian
uint32 point_step
uint32 row_step
uint8[] data
bool is_dense${SEP}${HEADER}${SEP}MSG: sensor_msgs/PointField
uint8 INT8=1
uint8 UINT8=2
uint8 INT16=3
uint8 UINT16=4
uint8 INT32=5
uint32 UINT32=6
uint8 FLOAT32=7
uint8 FLOAT64=8
string name
uint32 offset
uint8 datatype
uint32 count`;

export const STRING_DEF = 'string data';

export const TYPES = {
  'sensor_msgs/msg/LaserScan': LASER_SCAN_DEF,
  'sensor_msgs/msg/PointCloud2': POINT_CLOUD2_DEF,
  'std_msgs/msg/String': STRING_DEF,
};

const writers = new Map();
export function cdr(type, msg) {
  if (!writers.has(type)) writers.set(type, new MessageWriter(parse(TYPES[type], { ros2: true })));
  return writers.get(type).writeMessage(msg);
}

export const stampOf = (t) => ({ sec: Math.floor(t), nanosec: Math.round((t - Math.floor(t)) * 1e9) % 1e9 });

/** A sensor_msgs/msg/LaserScan from a CARMEN scan of readCarmenLog: beam i at -pi/2 + i * step, no-return beams
 *  (ranges >= the log's maxRange) beyond range_max. */
export function laserScanOf(scan, { frameId = 'laser' } = {}) {
  const n = scan.ranges.length;
  const step = n % 2 === 1 ? Math.PI / (n - 1) : Math.PI / n;
  return {
    header: { stamp: stampOf(scan.timestamp), frame_id: frameId },
    angle_min: -Math.PI / 2, angle_max: -Math.PI / 2 + (n - 1) * step, angle_increment: step,
    time_increment: 0, scan_time: 0, range_min: 0, range_max: scan.maxRange * (1 - 1e-6),
    ranges: Float32Array.from(scan.ranges), intensities: new Float32Array(0),
  };
}

await zstd.isLoaded;
export const COMPRESSIONS = {
  none: undefined,
  lz4: (data) => ({ compression: 'lz4', compressedData: new Uint8Array(lz4.compress(data)) }),
  zstd: (data) => ({ compression: 'zstd', compressedData: new Uint8Array(zstd.compress(data, 3)) }),
};

/** Writes an MCAP: channels [{ topic, type, messages: [{ time (s), msg }] }] (messages interleaved by time). */
export async function writeMcap(path, channels, { compression = 'none', chunkSize = 64 * 1024 } = {}) {
  const fh = await open(path, 'w');
  let pos = 0n;
  const writable = { position: () => pos, write: async (buf) => { await fh.write(buf); pos += BigInt(buf.byteLength); } };
  const w = new McapWriter({ writable, chunkSize, compressChunk: COMPRESSIONS[compression] });
  await w.start({ profile: 'ros2', library: 'rtl-wasm tests' });
  const all = [];
  for (const ch of channels) {
    const schemaId = await w.registerSchema({ name: ch.type, encoding: 'ros2msg', data: new TextEncoder().encode(TYPES[ch.type]) });
    const channelId = await w.registerChannel({ topic: ch.topic, schemaId, messageEncoding: 'cdr', metadata: new Map() });
    ch.messages.forEach((m, i) => all.push({ channelId, type: ch.type, i, ...m }));
  }
  all.sort((a, b) => a.time - b.time);
  let seq = 0;
  for (const m of all) {
    const t = BigInt(Math.round(m.time * 1e9));
    await w.addMessage({ channelId: m.channelId, sequence: seq++, logTime: t, publishTime: t, data: cdr(m.type, m.msg) });
  }
  await w.end();
  await fh.close();
}
