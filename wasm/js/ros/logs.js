// Robot logs streamed scan by scan: MCAP (ROS 2 CDR, ROS 1 or JSON messages; chunks uncompressed, lz4 or zstd) and
// ROS 1 bags, from a path or a FileHandle in Node, a Blob/File in browsers, or bytes in memory. The formats are read
// by the ecosystem's maintained readers (@mcap/core, @mcap/support, @foxglove/rosbag, @foxglove/rosmsg*), which are
// optional peer dependencies loaded on first use; this module only adapts their messages with ./messages.js.
// Reads are indexed (a chunk at a time through read(offset, length)), so a log is never held in memory whole.
import { fromLaserScan, fromPointCloud2 } from './messages.js';

/** Every failure of a log (not of the arguments) is a LogError naming the file and, where it applies, the topic
 *  and the index of the message (0-based, counted on that topic from the start of the iteration) it stopped at.
 *  code: 'FORMAT' (not a log, or its index is unreadable), 'TRUNCATED', 'CORRUPT' (a chunk or record that does not
 *  parse or fails its CRC), 'DECODE' (a message that does not decode or adapt), 'UNKNOWN_TOPIC', 'WRONG_TYPE',
 *  'MISSING_DEPENDENCY'. Scans before the failing message have been delivered. */
export class LogError extends Error {
  constructor(code, message, { file, topic, index, cause } = {}) {
    super(message, cause === undefined ? undefined : { cause });
    this.name = 'LogError';
    this.code = code;
    this.file = file;
    this.topic = topic;
    this.index = index;
  }
}

const MCAP_MAGIC = [0x89, 0x4d, 0x43, 0x41, 0x50, 0x30, 0x0d, 0x0a];
const BAG_MAGIC = '#ROSBAG V2.0\n';

function describe(v) {
  if (v === null) return 'null';
  if (typeof v === 'object') return v.constructor && v.constructor !== Object ? `a ${v.constructor.name}` : 'an object';
  return `${typeof v} ${String(v)}`;
}

// The log's topics, one entry per topic name: the type of its first connection and the message count summed over
// all its connections (a topic recorded by several publishers has several).
function topicList(connections) {
  const byTopic = new Map();
  for (const { topic, type, count } of connections) {
    const entry = byTopic.get(topic) ?? { name: topic, type, count: 0 };
    entry.count += count;
    byTopic.set(topic, entry);
  }
  return [...byTopic.values()];
}
// A bag's topics from its connections (conn -> { topic, type }) and message counts per connection.
const bagTopics = (connections, counts) =>
  topicList([...connections.values()].map((c) => ({ topic: c.topic, type: c.type ?? '', count: counts.get(c.conn) ?? 0 })));

// The optional peers, each imported by a literal specifier so that bundlers (esbuild, Vite, webpack) follow them with
// no configuration; loaded on first use only, so the core package and logs that do not need a peer work without it.
const PEERS = {
  '@mcap/core': () => import('@mcap/core'),
  '@mcap/support': () => import('@mcap/support'),
  '@foxglove/rosmsg': () => import('@foxglove/rosmsg'),
  '@foxglove/rosmsg2-serialization': () => import('@foxglove/rosmsg2-serialization'),
  '@foxglove/rosmsg-serialization': () => import('@foxglove/rosmsg-serialization'),
  '@foxglove/rosbag': () => import('@foxglove/rosbag'),
  // the record classes of @foxglove/rosbag, for bags without an index (read record by record)
  '@foxglove/rosbag/record': () => import('@foxglove/rosbag/dist/cjs/record.js'),
  '@foxglove/rosbag/fields': () => import('@foxglove/rosbag/dist/cjs/fields.js'),
};

async function need(peer, file) {
  try {
    return await PEERS[peer]();
  } catch (e) {
    const pkg = peer.startsWith('@foxglove/rosbag/') ? '@foxglove/rosbag' : peer;
    throw new LogError('MISSING_DEPENDENCY', `openLog: ${file}: reading this log needs the optional peer dependency ${pkg} ` +
      `(npm install @mcap/core @mcap/support @foxglove/rosmsg @foxglove/rosmsg2-serialization @foxglove/rosmsg-serialization ` +
      `@foxglove/rosbag): ${e.message}`, { file, cause: e });
  }
}

// source -> { name, size, read(offset: number, length: number): Promise<Uint8Array>, close() }
async function byteSource(source, name) {
  const fn = 'openLog';
  if (typeof source === 'string') {
    if (source === '') throw new RangeError(`${fn}: path must not be empty`);
    // inside try: a browser bundle leaves this Node-only import alone (esbuild does not resolve it there)
    let fs;
    try {
      fs = await import('node:fs/promises');
    } catch (e) {
      throw new TypeError(`${fn}: a path needs Node's file system (in a browser, pass a File or Blob): ${e.message}`);
    }
    const handle = await fs.open(source, 'r');
    try {
      return { ...(await handleSource(handle, name ?? source)), close: () => handle.close() };
    } catch (e) {
      await handle.close();
      throw e;
    }
  }
  if (typeof Blob !== 'undefined' && source instanceof Blob) {
    return {
      name: name ?? (typeof source.name === 'string' && source.name !== '' ? source.name : 'blob'),
      size: source.size,
      read: async (offset, length) => new Uint8Array(await source.slice(offset, offset + length).arrayBuffer()),
      close: async () => {},
    };
  }
  if (source instanceof ArrayBuffer || ArrayBuffer.isView(source)) {
    const bytes = source instanceof ArrayBuffer ? new Uint8Array(source) : new Uint8Array(source.buffer, source.byteOffset, source.byteLength);
    return {
      name: name ?? 'bytes', size: bytes.byteLength,
      read: async (offset, length) => bytes.subarray(offset, offset + length),
      close: async () => {},
    };
  }
  if (typeof source === 'object' && source !== null && typeof source.read === 'function' && typeof source.stat === 'function')
    return { ...(await handleSource(source, name ?? 'file handle')), close: async () => {} };   // the caller's to close
  throw new TypeError(`${fn}: source must be a path, a FileHandle (fs.promises.open), a Blob/File or bytes, got ${describe(source)}`);
}

async function handleSource(handle, name) {
  const { size } = await handle.stat();
  return {
    name, size,
    async read(offset, length) {
      const out = new Uint8Array(length);
      let got = 0;
      while (got < length) {
        const { bytesRead } = await handle.read(out, got, length - got, offset + got);
        if (bytesRead === 0) break;
        got += bytesRead;
      }
      return got === length ? out : out.subarray(0, got);
    },
  };
}

// Time bounds: seconds (number) or nanoseconds (bigint) -> bigint nanoseconds, or undefined
function timeBound(v, key) {
  const fn = 'scans';
  if (v === undefined) return undefined;
  if (typeof v === 'bigint') {
    if (v < 0n) throw new RangeError(`${fn}: ${key} must be >= 0, got ${v}`);
    return v;
  }
  if (typeof v !== 'number') throw new TypeError(`${fn}: ${key} must be seconds (number) or nanoseconds (bigint), got ${describe(v)}`);
  if (!Number.isFinite(v) || v < 0) throw new RangeError(`${fn}: ${key} must be a finite number of seconds >= 0, got ${v}`);
  return BigInt(Math.round(v * 1e9));
}

function scanKind(type) {
  if (/(^|[/.])LaserScan$/.test(type)) return 'laser';
  if (/(^|[/.])PointCloud2$/.test(type)) return 'cloud';
  return undefined;
}

const ADAPT = { laser: fromLaserScan, cloud: fromPointCloud2 };

/**
 * Opens a log: { format: 'mcap' | 'bag', file, topics: [{ name, type, count }], scans(topic, { start, end }),
 * close() }. scans() checks its arguments at once (TypeError/RangeError starting "scans:"; a topic the log does not
 * have or whose type is neither LaserScan nor PointCloud2: LogError) and returns an async iterator of
 * { index, topic, logTime (bigint ns), time (s), ...fromLaserScan or fromPointCloud2 of the message } in log-time
 * order, start <= logTime <= end (seconds as numbers, or bigint nanoseconds). count is null when an MCAP has no
 * statistics. A path is opened and closed here; a FileHandle or Blob stays the caller's. options.name names the
 * source in errors.
 */
export async function openLog(source, options = {}) {
  const fn = 'openLog';
  if (typeof options !== 'object' || options === null) throw new TypeError(`${fn}: options must be an object, got ${describe(options)}`);
  if (options.name !== undefined && typeof options.name !== 'string') throw new TypeError(`${fn}: options.name must be a string, got ${describe(options.name)}`);
  const src = await byteSource(source, options.name);
  try {
    const head = await src.read(0, Math.min(src.size, 16));
    if (MCAP_MAGIC.every((b, i) => head[i] === b)) return await openMcap(src);
    if (new TextDecoder().decode(head.subarray(0, BAG_MAGIC.length)) === BAG_MAGIC) return await openBag(src);
    throw new LogError('FORMAT', `${fn}: ${src.name}: not an MCAP file or a ROS 1 bag (V2.0)`, { file: src.name });
  } catch (e) {
    await src.close();
    throw e;
  }
}

function checkTopic(log, topic, opts) {
  const fn = 'scans';
  if (typeof topic !== 'string') throw new TypeError(`${fn}: topic must be a string, got ${describe(topic)}`);
  if (opts === null || typeof opts !== 'object') throw new TypeError(`${fn}: options must be an object, got ${describe(opts)}`);
  const start = timeBound(opts.start, 'start'), end = timeBound(opts.end, 'end');
  if (start !== undefined && end !== undefined && end < start) throw new RangeError(`${fn}: end must be >= start`);
  const entry = log.topics.find((t) => t.name === topic);
  if (entry === undefined)
    throw new LogError('UNKNOWN_TOPIC', `${fn}: ${log.file}: no topic ${topic} (topics: ${log.topics.map((t) => `${t.name} [${t.type}]`).join(', ') || 'none'})`,
                       { file: log.file, topic });
  const kind = scanKind(entry.type);
  if (kind === undefined)
    throw new LogError('WRONG_TYPE', `${fn}: ${log.file}: topic ${topic} has type ${entry.type}, not LaserScan or PointCloud2`, { file: log.file, topic });
  return { start, end, kind };
}

// Wraps a reader's message stream into adapted scans, turning every failure into a LogError at the right index.
async function* adapt(file, topic, kind, messages, decode) {
  let index = 0;
  const it = messages[Symbol.asyncIterator]();
  for (;;) {
    let next;
    try {
      next = await it.next();
    } catch (e) {
      if (e instanceof LogError) throw e;
      const truncated = /truncat|end of (file|data)|past end|not enough|too short/i.test(e.message);
      const err = new LogError(truncated ? 'TRUNCATED' : 'CORRUPT', `scans: ${file}: topic ${topic}: message ${index}: ${e.message}`,
                               { file, topic, index, cause: e });
      if (typeof e.position === 'number') err.position = e.position;   // the byte offset a stream reader stopped at
      throw err;
    }
    if (next.done) return;
    const { logTime } = next.value;
    let scan;
    try {
      scan = ADAPT[kind](decode(next.value));
    } catch (e) {
      throw new LogError('DECODE', `scans: ${file}: topic ${topic}: message ${index} (log time ${logTime} ns): ${e.message}`,
                         { file, topic, index, cause: e });
    }
    yield { index, topic, logTime, time: Number(logTime) / 1e9, ...scan };
    index++;
  }
}

// ------------------------------------------------------------------------------------------------------------ MCAP

async function channelDecoder(file, schema, channel) {
  const enc = channel.messageEncoding;
  if (enc === 'json') {
    const td = new TextDecoder();
    return (data) => JSON.parse(td.decode(data));
  }
  if (schema === undefined) throw new Error(`channel ${channel.topic} (${enc}) has no schema`);
  const text = new TextDecoder().decode(schema.data);
  const { parse } = await need('@foxglove/rosmsg', file);
  if (enc === 'cdr' && schema.encoding === 'ros2msg') {
    const { MessageReader } = await need('@foxglove/rosmsg2-serialization', file);
    const reader = new MessageReader(parse(text, { ros2: true }));
    return (data) => reader.readMessage(data);
  }
  if (enc === 'ros1' && schema.encoding === 'ros1msg') {
    const { MessageReader } = await need('@foxglove/rosmsg-serialization', file);
    const reader = new MessageReader(parse(text));
    return (data) => reader.readMessage(data);
  }
  throw new Error(`unsupported message encoding ${enc} with schema encoding ${schema.encoding}`);
}

async function openMcap(src) {
  const file = src.name;
  const { McapIndexedReader } = await need('@mcap/core', file);
  const { loadDecompressHandlers } = await need('@mcap/support', file);
  const decompressHandlers = await loadDecompressHandlers();
  const readable = {
    size: async () => BigInt(src.size),
    read: async (offset, length) => {
      const out = await src.read(Number(offset), Number(length));
      if (out.byteLength !== Number(length))
        throw new Error(`read past end of file (${length} bytes at offset ${offset}, file size ${src.size})`);
      return out;
    },
  };
  let reader;
  try {
    reader = await McapIndexedReader.Initialize({ readable, decompressHandlers });
  } catch (e) {
    // No usable index (typically a recording that was cut off before its summary was written): read it as a stream.
    return openMcapStream(src, decompressHandlers, e);
  }
  const counts = reader.statistics?.channelMessageCounts;
  const byTopic = new Map();
  for (const ch of reader.channelsById.values()) {
    const schema = reader.schemasById.get(ch.schemaId);
    const entry = byTopic.get(ch.topic) ?? { name: ch.topic, type: schema?.name ?? '', count: counts ? 0 : null, channels: [] };
    if (counts) entry.count += Number(counts.get(ch.id) ?? 0n);
    entry.channels.push(ch);
    byTopic.set(ch.topic, entry);
  }
  const topics = [...byTopic.values()].map(({ name, type, count }) => ({ name, type, count }));
  const log = {
    format: 'mcap', file, topics,
    scans(topic, opts = {}) {
      const { start, end, kind } = checkTopic(log, topic, opts);
      const decoders = new Map();
      async function* messages() {
        for await (const m of reader.readMessages({ topics: [topic], startTime: start, endTime: end })) {
          if (!decoders.has(m.channelId)) {
            const ch = reader.channelsById.get(m.channelId);
            decoders.set(m.channelId, await channelDecoder(file, reader.schemasById.get(ch.schemaId), ch).catch((e) => e));
          }
          yield m;
        }
      }
      const decode = (m) => {
        const d = decoders.get(m.channelId);
        if (d instanceof Error) throw d;
        return d(m.data);
      };
      return adapt(file, topic, kind, messages(), decode);
    },
    close: () => src.close(),
  };
  log[Symbol.asyncDispose] = log.close;
  return log;
}

const STREAM_BLOCK = 1 << 20;

// The records of an MCAP front to back (McapStreamReader, one block of the file in memory at a time); throws at a
// truncation or a corrupt record, after yielding every record before it.
async function* mcapRecords(src, decompressHandlers, McapStreamReader) {
  const stream = new McapStreamReader({ decompressHandlers, validateCrcs: true });
  for (let offset = 0; offset < src.size;) {
    const block = await src.read(offset, Math.min(STREAM_BLOCK, src.size - offset));
    offset += block.byteLength;
    stream.append(block);
    for (let rec; (rec = stream.nextRecord()) !== undefined;) yield rec;
  }
  if (!stream.done()) throw new Error(`truncated: the file ends at byte ${src.size} inside a record or before its footer`);
}

async function openMcapStream(src, decompressHandlers, indexError) {
  const file = src.name;
  const { McapStreamReader } = await need('@mcap/core', file);
  const schemas = new Map(), channels = new Map(), counts = new Map();
  let stop;
  try {
    for await (const rec of mcapRecords(src, decompressHandlers, McapStreamReader)) {
      if (rec.type === 'Schema') schemas.set(rec.id, rec);
      else if (rec.type === 'Channel') channels.set(rec.id, rec);
      else if (rec.type === 'Message') counts.set(rec.channelId, (counts.get(rec.channelId) ?? 0) + 1);
    }
  } catch (e) {
    stop = e;
  }
  if (channels.size === 0)
    throw new LogError(stop ? 'TRUNCATED' : 'FORMAT', `openLog: ${file}: unreadable MCAP (index: ${indexError.message}` +
                       `${stop ? `; stream: ${stop.message}` : ''})`, { file, cause: stop ?? indexError });
  const log = {
    format: 'mcap', file,
    topics: topicList([...channels.values()].map((ch) => ({ topic: ch.topic, type: schemas.get(ch.schemaId)?.name ?? '', count: counts.get(ch.id) ?? 0 }))),
    /** the log has no usable index and is read front to back: why, and what stopped the first pass (if anything) */
    unindexed: { reason: indexError.message, stoppedBy: stop?.message },
    scans(topic, opts = {}) {
      const { start, end, kind } = checkTopic(log, topic, opts);
      const decoders = new Map();
      async function* messages() {
        for await (const rec of mcapRecords(src, decompressHandlers, McapStreamReader)) {
          if (rec.type !== 'Message' || channels.get(rec.channelId)?.topic !== topic) continue;
          if ((start !== undefined && rec.logTime < start) || (end !== undefined && rec.logTime > end)) continue;
          if (!decoders.has(rec.channelId)) {
            const ch = channels.get(rec.channelId);
            decoders.set(rec.channelId, await channelDecoder(file, schemas.get(ch.schemaId), ch).catch((e) => e));
          }
          yield rec;
        }
      }
      const decode = (m) => {
        const d = decoders.get(m.channelId);
        if (d instanceof Error) throw d;
        return d(m.data);
      };
      return adapt(file, topic, kind, messages(), decode);
    },
    close: () => src.close(),
  };
  log[Symbol.asyncDispose] = log.close;
  return log;
}

// ------------------------------------------------------------------------------------------------------ ROS 1 bag

async function openBag(src) {
  const file = src.name;
  const { Bag } = await need('@foxglove/rosbag', file);
  const { loadDecompressHandlers } = await need('@mcap/support', file);
  const handlers = await loadDecompressHandlers();
  const decompress = {
    lz4: (buffer, size) => handlers.lz4(buffer, BigInt(size)),
    bz2: (buffer, size) => handlers.bz2(buffer, BigInt(size)),
  };
  const filelike = {
    size: () => src.size,
    read: async (offset, length) => {
      const out = await src.read(offset, length);
      if (out.byteLength !== length) throw new Error(`read past end of file (${length} bytes at offset ${offset}, file size ${src.size})`);
      return out;
    },
  };
  const bag = new Bag(filelike, { decompress, parse: true });
  try {
    await bag.open();
  } catch (e) {
    // No usable index (typically a recording cut off before its index was written): read it record by record.
    return openBagStream(src, decompress, e);
  }
  const counts = new Map();
  for (const info of bag.chunkInfos) for (const { conn, count } of info.connections) counts.set(conn, (counts.get(conn) ?? 0) + count);
  const log = {
    format: 'bag', file, topics: bagTopics(bag.connections, counts),
    scans(topic, opts = {}) {
      const { start, end, kind } = checkTopic(log, topic, opts);
      const toTime = (ns) => ({ sec: Number(ns / 1000000000n), nsec: Number(ns % 1000000000n) });
      async function* messages() {
        const it = bag.messageIterator({ topics: [topic], start: start === undefined ? undefined : toTime(start) });
        for await (const ev of it) {
          const logTime = BigInt(ev.timestamp.sec) * 1000000000n + BigInt(ev.timestamp.nsec);
          if (end !== undefined && logTime > end) return;
          yield { logTime, message: ev.message, data: ev.data };
        }
      }
      return adapt(file, topic, kind, messages(), (ev) => ev.message);
    },
    close: () => src.close(),
  };
  log[Symbol.asyncDispose] = log.close;
  return log;
}

// The records of a bag front to back with @foxglove/rosbag's record classes, one record in memory at a time (a
// chunk decompressed whole): { conn, time, data } of every message and { connection } of every connection record, in
// file order. Throws at a truncation or a record that does not parse, after yielding every complete one before it
// (an uncompressed chunk cut off yields its complete messages too); the error's `position` is the byte offset of
// the record (or, inside a chunk cut off, of the message record) it stopped at.
const BAG_OP = { message: 2, header: 3, chunk: 5, connection: 7 };
const BAG_HEADER_AT = 13;   // after the magic line
const BAG_PARTIAL_MAX = 64 << 20;
async function* bagRecords(src, decompress, rec) {
  const stopAt = (position, why) => Object.assign(new Error(`${why} at byte ${position} (file size ${src.size})`), { position });
  const view = (b) => new DataView(b.buffer, b.byteOffset, b.byteLength);
  // One record at byte `at` of `bytes` (whole, or `complete` false: it runs past the end): its op, fields and data.
  const parse = (bytes, at) => {
    if (at + 4 > bytes.byteLength) return { complete: false };
    const headerLength = view(bytes).getUint32(at, true);
    if (at + 8 + headerLength > bytes.byteLength) return { complete: false };
    const fields = rec.extractFields(bytes.subarray(at + 4, at + 4 + headerLength));
    const dataLength = view(bytes).getUint32(at + 4 + headerLength, true);
    const end = at + 8 + headerLength + dataLength;
    if (end > bytes.byteLength) return { complete: false };
    if (fields.op === undefined || fields.op.byteLength !== 1) throw new Error('a record without its op field');
    return { complete: true, op: fields.op[0], fields, data: bytes.subarray(at + 8 + headerLength, end), end };
  };
  const inner = function* (bytes, base, partial) {
    for (let at = 0; at < bytes.byteLength;) {
      let r;
      try {
        r = parse(bytes, at);
      } catch (e) {
        throw stopAt(base + at, `a corrupt record inside a chunk (${e.message})`);
      }
      if (!r.complete) {
        if (partial) throw stopAt(base + at, 'truncated: the file ends inside a message record');
        throw stopAt(base + at, 'a chunk\'s records overrun its data');
      }
      if (r.op === BAG_OP.connection) {
        const c = new rec.Connection(r.fields);
        c.parseData(r.data);
        yield { connection: c };
      } else if (r.op === BAG_OP.message) {
        const m = new rec.MessageData(r.fields);
        yield { conn: m.conn, time: m.time, data: r.data };
      }
      at = r.end;
    }
  };
  const HEAD = 4096;
  let indexAt = 0;   // the bag header's index_pos: the file must reach it (a recording cut off ends before)
  for (let at = BAG_HEADER_AT; at < src.size;) {
    // the record's lengths first, then the whole record
    const head = await src.read(at, Math.min(HEAD, src.size - at));
    let size;
    try {
      if (head.byteLength < 4) throw stopAt(at, 'truncated: the file ends inside a record');
      const headerLength = view(head).getUint32(0, true);
      if (8 + headerLength > src.size - at) throw stopAt(at, 'truncated: the file ends inside a record');
      const h = 8 + headerLength <= head.byteLength ? head : await src.read(at, 8 + headerLength);
      size = 8 + headerLength + view(h).getUint32(4 + headerLength, true);
    } catch (e) {
      throw e.position !== undefined ? e : stopAt(at, `a corrupt record (${e.message})`);
    }
    // a record running past the end is read (for an uncompressed chunk's complete messages) only up to 64 MB: a
    // corrupt length must not pull the rest of a large file into memory
    if (size > src.size - at && src.size - at > BAG_PARTIAL_MAX) throw stopAt(at, 'truncated: the file ends inside a record');
    const bytes = size <= head.byteLength ? head.subarray(0, size) : await src.read(at, Math.min(size, src.size - at));
    let r;
    try {
      r = parse(bytes, 0);
    } catch (e) {
      throw stopAt(at, `a corrupt record (${e.message})`);
    }
    if (!r.complete) {
      // a chunk cut off: its complete messages are still readable when it is not compressed (its header is whole:
      // checked above)
      const headerLength = view(bytes).getUint32(0, true);
      const fields = rec.extractFields(bytes.subarray(4, 4 + headerLength));
      if (fields.op?.[0] === BAG_OP.chunk && new rec.Chunk(fields).compression === 'none')
        yield* inner(bytes.subarray(8 + headerLength), at + 8 + headerLength, true);
      throw stopAt(at, 'truncated: the file ends inside a record');
    }
    if (r.op === BAG_OP.header) {
      indexAt = Number(new rec.BagHeader(r.fields).indexPosition);
    } else if (r.op === BAG_OP.chunk) {
      const chunk = new rec.Chunk(r.fields);
      let data = r.data;
      try {
        if (chunk.compression !== 'none') {
          const d = decompress[chunk.compression];
          if (d === undefined) throw new Error(`unsupported chunk compression ${chunk.compression}`);
          data = d(data, chunk.size);
        }
      } catch (e) {
        throw stopAt(at, `a chunk that does not decompress (${e.message})`);
      }
      yield* inner(data, at, false);
    } else if (r.op === BAG_OP.connection) {
      const c = new rec.Connection(r.fields);
      c.parseData(r.data);
      yield { connection: c };
    } else if (r.op === BAG_OP.message) {
      const m = new rec.MessageData(r.fields);
      yield { conn: m.conn, time: m.time, data: r.data };
    }
    at += size;
  }
  if (indexAt === 0 || indexAt >= src.size) throw stopAt(src.size, 'truncated: the file ends before the bag\'s index');
}

async function openBagStream(src, decompress, indexError) {
  const file = src.name;
  const rec = { ...(await need('@foxglove/rosbag/record', file)), ...(await need('@foxglove/rosbag/fields', file)) };
  const { parse } = await need('@foxglove/rosmsg', file);
  const { MessageReader } = await need('@foxglove/rosmsg-serialization', file);
  const connections = new Map(), counts = new Map();
  let stop;
  try {
    for await (const r of bagRecords(src, decompress, rec)) {
      if (r.connection) connections.set(r.connection.conn, r.connection);
      else counts.set(r.conn, (counts.get(r.conn) ?? 0) + 1);
    }
  } catch (e) {
    stop = e;
  }
  if (connections.size === 0)
    throw new LogError(stop ? 'TRUNCATED' : 'FORMAT', `openLog: ${file}: unreadable ROS bag (index: ${indexError.message}` +
                       `${stop ? `; records: ${stop.message}` : ''})`, { file, cause: stop ?? indexError });
  const log = {
    format: 'bag', file, topics: bagTopics(connections, counts),
    /** the bag has no usable index and is read front to back (messages in file order): why, and what stopped the
     *  first pass (if anything) */
    unindexed: { reason: indexError.message, stoppedBy: stop?.message },
    scans(topic, opts = {}) {
      const { start, end, kind } = checkTopic(log, topic, opts);
      const readers = new Map();
      async function* messages() {
        const conns = new Map();
        for await (const r of bagRecords(src, decompress, rec)) {
          if (r.connection) { conns.set(r.connection.conn, r.connection); continue; }
          const c = conns.get(r.conn) ?? connections.get(r.conn);
          if (c?.topic !== topic) continue;
          const logTime = BigInt(r.time.sec) * 1000000000n + BigInt(r.time.nsec);
          if ((start !== undefined && logTime < start) || (end !== undefined && logTime > end)) continue;
          yield { logTime, conn: c, data: r.data };
        }
      }
      const decode = (m) => {
        if (!readers.has(m.conn.conn)) readers.set(m.conn.conn, new MessageReader(parse(m.conn.messageDefinition)));
        return readers.get(m.conn.conn).readMessage(m.data);
      };
      return adapt(file, topic, kind, messages(), decode);
    },
    close: () => src.close(),
  };
  log[Symbol.asyncDispose] = log.close;
  return log;
}
