// rtl on robot logs (MCAP, ROS 1 bags): every scan of a topic through the same pipeline as a single scan (segment,
// then fit/vectorize), written as JSON Lines (one scan a line) or one SVG/TikZ file per scan. Scans are written as
// they are done, so Ctrl-C or a corrupt message leaves complete output for the scans before it; the message says
// where it stopped. Several logs run in worker threads (--jobs), each log's lines written whole by the main thread.
import { closeSync, openSync, writeSync } from 'node:fs';
import { basename, extname } from 'node:path';
import { Worker } from 'node:worker_threads';

export class LogStop extends Error {}

const isLaser = (type) => /LaserScan$/.test(type);
const isCloud = (type) => /PointCloud2$/.test(type);

/** Which topic to read: --topic, or the log's only LaserScan (else only PointCloud2) topic. */
export function chooseTopic(log, wanted) {
  if (wanted !== undefined) return wanted;   // openLog's scans() names the file and lists the topics if it is not there
  const list = log.topics.map((t) => `${t.name} [${t.type}]`).join(', ') || 'none';
  const lasers = log.topics.filter((t) => isLaser(t.type));
  const clouds = log.topics.filter((t) => isCloud(t.type));
  const pick = lasers.length ? lasers : clouds;
  if (pick.length !== 1) throw new LogStop(`${log.file}: ${pick.length ? 'several' : 'no'} scan topics; pass --topic (topics: ${list})`);
  return pick[0].name;
}

/** A scan of the log -> the pipeline's input { points, dim, source }. Clouds give a ring (default 0) or a column. */
export function inputOf(scan, file, opts) {
  const source = { type: 'log', file, topic: scan.topic, index: scan.index, time: scan.time,
                   ...(scan.stamp !== undefined ? { stamp: scan.stamp } : {}), frameId: scan.frameId };
  if (scan.angles) return { points: scan.points, dim: 2, source: { ...source, maxRange: Number.isFinite(scan.maxRange) ? scan.maxRange : null } };
  if (scan.beams === undefined) return { points: scan.points, dim: 3, source };
  if (opts.column !== undefined) {
    if (opts.column >= scan.columns) throw new LogStop(`${file}: --column ${opts.column} is out of range, the cloud has ${scan.columns} columns`);
    return { points: scan.column(opts.column), dim: 3, source: { ...source, beams: scan.beams, columns: scan.columns, column: opts.column } };
  }
  const ring = opts.ring ?? 0;
  if (ring >= scan.beams) throw new LogStop(`${file}: --ring ${ring} is out of range, the cloud has ${scan.beams} beams`);
  return { points: scan.ring(ring), dim: 3, source: { ...source, beams: scan.beams, columns: scan.columns, ring } };
}

/** The JSON line of one scan: run()'s result on one line (no labels array twice). */
export function jsonLine(result) {
  const { labels, ...rest } = result;
  void labels;
  return `${JSON.stringify(rest)}\n`;
}

/** The file of one scan's picture: --output with %d -> the scan index, %f -> the log's name without extension. */
export function pictureFile(pattern, file, index) {
  return pattern.replaceAll('%f', basename(file, extname(file))).replaceAll('%d', String(index));
}

function progressBar(file, done, total) {
  const width = 30;
  const f = total ? Math.min(1, done / total) : 0;
  const bar = '#'.repeat(Math.round(f * width)).padEnd(width, '.');
  return `\r[${bar}] ${done}${total ? `/${total}` : ''} scans  ${basename(file)}`;
}

/**
 * Processes one log: opens it, runs `process(scan) -> { line?, picture? }` on every scan and hands each output to
 * `emit`. Returns { file, topic, scans }. Stops cleanly when `stopped()` turns true (Ctrl-C). A LogError or a bad
 * scan ends it with a LogStop saying how many scans were written and where it stopped.
 */
export async function processLog(file, opts, { openLog, process: step, emit, stopped = () => false, progress }) {
  const log = await openLog(file);
  let done = 0, topic;
  try {
    topic = chooseTopic(log, opts.topic);
    const total = log.topics.find((t) => t.name === topic)?.count ?? null;
    const range = { ...(opts.start !== undefined ? { start: opts.start } : {}), ...(opts.end !== undefined ? { end: opts.end } : {}) };
    let scans;
    try {
      scans = log.scans(topic, range);
    } catch (e) {
      throw new LogStop(e.message.replace(/^scans: /, ''));
    }
    try {
      for await (const scan of scans) {
        emit(step(scan, log.file), scan);
        done++;
        progress?.(file, done, total);
        if (stopped()) return { file, topic, scans: done, interrupted: true, next: scan.index + 1 };
      }
    } catch (e) {
      if (e.code === 'EPIPE') throw e;   // the reader of our output has gone (e.g. `| head`): nothing to report
      const where = e.index !== undefined ? `at message ${e.index}` : `at scan ${done}`;
      throw new LogStop(`${e.message.replace(/^scans: /, '')}\nrtl: ${file}: stopped ${where} of ${topic}; the output holds the ${done} scans before it`);
    }
    return { file, topic, scans: done };
  } finally {
    await log.close();
  }
}

/** Output sink: JSON lines to a file descriptor (stdout or --output), written whole with writeSync. */
export function lineSink(output) {
  const fd = output ? openSync(output, 'w') : 1;
  return {
    write(text) {
      for (let off = 0; off < text.length;) {
        try {
          off += writeSync(fd, Buffer.from(text.slice(off)));
          break;
        } catch (e) {
          if (e.code !== 'EAGAIN') throw e;
        }
      }
    },
    close() { if (fd !== 1) closeSync(fd); },
  };
}

export const progressWriter = (enabled) => {
  if (!enabled) return { update: undefined, end() {} };
  let shown = false;
  return {
    update(file, done, total) { shown = true; process.stderr.write(progressBar(file, done, total)); },
    end() { if (shown) process.stderr.write('\n'); },
  };
};

/** Several logs on `jobs` worker threads (bin/log-job.js), one log per worker at a time; lines reach `sink` whole. */
export async function processLogsInWorkers(files, opts, jobs, sink, { onDone, onError, stopped, progress }) {
  const queue = [...files];
  // progress over all logs: scans done / scans announced by the logs started so far
  const counts = new Map();
  const report = () => {
    let done = 0, total = 0;
    for (const c of counts.values()) { done += c.done; total += c.total ?? 0; }
    progress?.(`${files.length} logs`, done, total);
  };
  const workerUrl = new URL('./log-job.js', import.meta.url);
  const runOne = (file) => new Promise((resolve) => {
    const w = new Worker(workerUrl, { workerData: { file, opts } });
    let settled = false;
    const finish = (r) => { if (!settled) { settled = true; resolve(r); } };
    w.on('message', (m) => {
      if (m.lines) sink.write(m.lines);
      if (m.progress) { counts.set(file, m.progress); report(); }
      if (m.done) finish({ ok: true, ...m.done });
      if (m.error) finish({ ok: false, file, message: m.error });
    });
    w.on('error', (e) => finish({ ok: false, file, message: `${file}: ${e.message}` }));
    w.on('exit', () => finish({ ok: false, file, message: `${file}: worker ended unexpectedly` }));
    const poll = setInterval(() => { if (stopped()) { w.postMessage('stop'); clearInterval(poll); } }, 50);
    w.on('exit', () => clearInterval(poll));
  });
  let failures = 0;
  await Promise.all(Array.from({ length: Math.min(jobs, files.length) }, async () => {
    while (queue.length && !stopped()) {
      const r = await runOne(queue.shift());
      if (r.ok) onDone(r); else { failures++; onError(r.message); }
    }
  }));
  return failures;
}
