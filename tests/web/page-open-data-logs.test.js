// Open your own robot's files: an MCAP written at test time by @mcap/core's McapWriter (ROS 2 CDR LaserScans from a
// CARMEN log, an organised PointCloud2 from the Ouster excerpt), the ROS 1 bags of tests/data/ros1 (written by the
// rosbag Python package) and PCL's PCD files of tests/data/pcd, dropped or picked in real Chromium. Each opens: the
// topic chooser lists the log's topics with their counts, the progress bar reaches 100 %, a chosen scan runs the 2D
// lessons on the points the package gives in Node for the same file (to the last bit of a cosine); bad files (a
// truncated bag, a corrupt MCAP, a PCD with points missing or miscounted, a file of another kind) get the package's
// message under the file's name, and the page keeps working; an MCAP without statistics reads with an unknown count.
// Screenshots of the chooser at 1280x800 and 390x844 go to test-results/.
import { after, before, describe, test } from 'node:test';
import assert from 'node:assert/strict';
import { mkdtempSync, readFileSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import init from 'rtl-wasm';
import { openLog } from 'rtl-wasm/logs';
import { McapIndexedReader, McapWriter } from '@mcap/core';
import { loadDecompressHandlers } from '@mcap/support';
import { TYPES, cdr, laserScanOf, stampOf, writeMcap } from '../js/ros-fixtures.mjs';
import { DATA, PAGE_TIMEOUT, openDemoPage, openLesson, resultsDir } from './helpers.js';

const SEG = { step: 3, lowerBound: 0.1, upperBound: 0.5 };
const LESSONS_2D = ['car', 'ia', 'ftls', 'aftls', 'itls', 'dp', 'rw', 'compare', 'overview'];
const rtl = await init();
const intel = rtl.readCarmenLog(readFileSync(join(DATA, 'intel.log')));
const ousterBin = readFileSync(join(DATA, 'rellis3d-os1-4x2048.bin'));
const dir = mkdtempSync(join(tmpdir(), 'rtl-page-logs-'));

// The Ouster excerpt as an organised PointCloud2 laid out as the Ouster ROS driver does: a row per beam, x, y, z,
// intensity float32 (point_step 16); the excerpt's records are column-major (column * 4 + beam, 16 bytes each).
function ousterCloud(t) {
  const beams = 4, cols = 2048, step = 16;
  const data = new Uint8Array(beams * cols * step);
  const out = new DataView(data.buffer), src = new DataView(ousterBin.buffer, ousterBin.byteOffset, ousterBin.byteLength);
  for (let c = 0; c < cols; c++) for (let b = 0; b < beams; b++)
    for (let k = 0; k < 4; k++) out.setFloat32((b * cols + c) * step + 4 * k, src.getFloat32((c * beams + b) * 16 + 4 * k, true), true);
  const f = (name, offset) => ({ name, offset, datatype: 7, count: 1 });
  return { header: { stamp: stampOf(t), frame_id: 'os_sensor' }, height: beams, width: cols,
           fields: [f('x', 0), f('y', 4), f('z', 8), f('intensity', 12)], is_bigendian: false, point_step: step,
           row_step: step * cols, data, is_dense: false };
}

async function robotMcap(chunkSize = 16 * 1024) {
  const path = join(dir, 'robot.mcap');
  await writeMcap(path, [
    { topic: '/scan', type: 'sensor_msgs/msg/LaserScan', messages: intel.map((s) => ({ time: s.timestamp, msg: laserScanOf(s) })) },
    { topic: '/os_cloud', type: 'sensor_msgs/msg/PointCloud2', messages: [0, 1].map((k) => ({ time: intel[0].timestamp + 0.01 + k, msg: ousterCloud(100 + k) })) },
    { topic: '/chatter', type: 'std_msgs/msg/String', messages: [{ time: intel[0].timestamp, msg: { data: 'hello' } }] },
  ], { compression: 'zstd', chunkSize });
  return new Uint8Array(readFileSync(path));
}

// Every scan of a topic as the package gives it in Node, and the error that stopped them (if any).
async function nodeScans(bytes, name, topic) {
  const log = await openLog(bytes, { name });
  const scans = [];
  let error;
  try {
    for await (const s of log.scans(topic)) scans.push(s);
  } catch (e) {
    error = e;
  } finally {
    await log.close();
  }
  return { scans, error, topics: log.topics };
}

const message = (page) => page.textContent('#open-message');
const waitMessage = (page, re) => page.waitForFunction((src) => new RegExp(src).test(document.querySelector('#open-message').textContent) &&
  document.querySelector('#open-progress').hidden, re.source, { timeout: PAGE_TIMEOUT });
async function drop(page, name, bytes) {
  const dt = await page.evaluateHandle(([n, b]) => { const t = new DataTransfer(); t.items.add(new File([new Uint8Array(b)], n)); return t; }, [name, Array.from(bytes)]);
  await page.dispatchEvent('body', 'drop', { dataTransfer: dt });
}
const pick = (page, name, bytes) => page.setInputFiles('#open-file', { name, mimeType: 'application/octet-stream', buffer: Buffer.from(bytes) });
// The scan chooser's options of the newest group: [value, text].
const lastGroup = (page) => page.$$eval('#scan-chooser optgroup:last-of-type option', (os) => os.map((o) => [o.value, o.textContent]));
const topicOptions = (page) => page.$$eval('#topic-chooser option', (os) => os.map((o) => [o.textContent, o.disabled]));

// The car lesson's points are the chosen scan's (x, y as the package gives them in Node: the same gaps, the same
// numbers but for the last bit of a cosine, which Chromium's and Node's engines may round apart), and its steps are
// the package's trace of them (with the lesson's parameters).
async function carRunsOn(page, points) {
  await openLesson(page, 'car');
  const s = await page.evaluate(() => window.__rtl.finalState());
  assert.equal(s.points.length, points.length, 'coordinates');
  for (let i = 0; i < points.length; i++) {
    if (Number.isNaN(points[i])) assert.ok(Number.isNaN(s.points[i]), `coordinate ${i} must be a gap, got ${s.points[i]}`);
    else assert.ok(Math.abs(s.points[i] - points[i]) <= 1e-12 * Math.max(1, Math.abs(points[i])), `coordinate ${i}: ${s.points[i]} vs ${points[i]}`);
  }
  const entry = await page.evaluate(() => window.__rtl.lessons.find((l) => l.id === 'car'));
  const { step, lowerBound, upperBound } = s.params;
  assert.equal(entry.steps, rtl.segment(new Float64Array(s.points), { step, lowerBound, upperBound, trace: true }).trace.length);
}

const xyOf = (xyz) => Float64Array.from({ length: (2 * xyz.length) / 3 }, (_, j) => xyz[3 * Math.floor(j / 2) + (j % 2)]);

describe('open your own robot files: MCAP, ROS 1 bags, PCD', { timeout: 400000 }, () => {
  let page, problems, close;
  before(async () => {
    ({ page, problems, close } = await openDemoPage('/web/#car'));
    await page.setViewportSize({ width: 1280, height: 800 });
    // every text the message shows, to see the progress go by
    await page.evaluate(() => {
      window.__messages = [];
      const el = document.querySelector('#open-message');
      new MutationObserver(() => window.__messages.push(el.textContent)).observe(el, { childList: true, characterData: true, subtree: true });
    });
  });
  after(async () => { await close?.(); rmSync(dir, { recursive: true, force: true }); });

  test('an MCAP (zstd chunks): topics with counts, progress to 100 %, every 2D lesson on the chosen scan, then the cloud topic', async () => {
    const bytes = await robotMcap();
    const node = await nodeScans(bytes, 'robot.mcap', '/scan');
    assert.equal(node.scans.length, intel.length);
    await page.evaluate(() => { window.__messages.length = 0; });
    await drop(page, 'robot.mcap', bytes);
    await waitMessage(page, /robot\.mcap \/scan: 30 scans read \(an MCAP file\)/);
    assert.deepEqual(await topicOptions(page), [
      ['/scan · LaserScan · 30 messages', false], ['/os_cloud · PointCloud2 · 2 messages', false], ['/chatter · String · 1 message', true]]);
    assert.equal(await page.inputValue('#topic-chooser'), '/scan');
    const seen = await page.evaluate(() => window.__messages);
    const percents = seen.map((m) => m.match(/^robot\.mcap: segmenting (\d+) %$/)?.[1]).filter(Boolean).map(Number);
    assert.ok(percents.length >= 5, seen.join(' | '));
    assert.deepEqual(percents, [...percents].sort((a, b) => a - b), 'progress only grows');
    assert.equal(percents.at(-1), 100);
    const options = await lastGroup(page);
    assert.equal(options.length, 30);
    const k = 7, pts = node.scans[k].points;
    assert.equal(await page.$eval('#scan-chooser optgroup:last-of-type', (g) => g.label), 'robot.mcap /scan', 'the group names the file and topic');
    assert.equal(options[k][1], `scan ${k}: ${pts.filter((v, i) => i % 2 === 0 && Number.isFinite(v)).length} points, ${rtl.segment(pts, SEG).clusters.length} clusters`);
    await page.selectOption('#scan-chooser', options[k][0]);
    const [dataset] = options[k][0].split(':');
    await page.waitForFunction((d) => window.__rtl.source()?.dataset === d && window.__rtl.source()?.scan === 7, dataset, { timeout: PAGE_TIMEOUT });
    for (const id of LESSONS_2D) {
      const entry = await openLesson(page, id);
      assert.ok(entry.steps > 0 || id === 'overview' || id === 'compare', `${id}: steps`);
      assert.match(await page.textContent('#lesson-controls'), /Your chosen scan/, `${id}: says whose data`);
      assert.deepEqual(await page.evaluate(() => window.__rtl.source()), { dataset, scan: 7 });
    }
    await carRunsOn(page, pts);

    // screenshots of the chooser, as a student sees it
    await page.evaluate(() => document.querySelector('#own-data').scrollIntoView({ block: 'start' }));
    await page.screenshot({ path: join(resultsDir(), 'open-data-mcap-1280x800.png') });
    await page.setViewportSize({ width: 390, height: 844 });
    await page.evaluate(() => document.querySelector('#own-data').scrollIntoView({ block: 'start' }));
    await page.screenshot({ path: join(resultsDir(), 'open-data-mcap-390x844.png') });
    await page.setViewportSize({ width: 1280, height: 800 });

    // the cloud topic: each message seen from above, its ring with the most returns
    const clouds = (await nodeScans(bytes, 'robot.mcap', '/os_cloud')).scans;
    await page.selectOption('#topic-chooser', '/os_cloud');
    await waitMessage(page, /robot\.mcap \/os_cloud: 2 scans read/);
    const cloudOptions = await lastGroup(page);
    assert.equal(cloudOptions.length, 2);
    const returns = Array.from({ length: 4 }, (_, b) => { const r = clouds[1].ring(b); let n = 0; for (let i = 0; i < r.length; i += 3) if (Number.isFinite(r[i])) n++; return n; });
    const best = returns.indexOf(Math.max(...returns));
    assert.match(cloudOptions[1][1], new RegExp(`^scan 1 \\(ring ${best}\\): ${returns[best]} points, `));
    await page.selectOption('#scan-chooser', cloudOptions[1][0]);
    await page.waitForFunction(() => window.__rtl.source()?.scan === 1, null, { timeout: PAGE_TIMEOUT });
    await carRunsOn(page, xyOf(clouds[1].ring(best)));
  });

  test('an MCAP without statistics: the topic\'s count is unknown ("?"), the progress bar runs without a total, then ends at 100 %', async () => {
    const chunks = [];
    let pos = 0n;
    const w = new McapWriter({ writable: { position: () => pos, write: async (b) => { chunks.push(b.slice()); pos += BigInt(b.byteLength); } },
                               useStatistics: false, chunkSize: 8 * 1024 });
    await w.start({ profile: 'ros2', library: 'rtl-wasm tests' });
    const type = 'sensor_msgs/msg/LaserScan';
    const schemaId = await w.registerSchema({ name: type, encoding: 'ros2msg', data: new TextEncoder().encode(TYPES[type]) });
    const channelId = await w.registerChannel({ topic: '/front/scan', schemaId, messageEncoding: 'cdr', metadata: new Map() });
    for (const [i, s] of intel.slice(0, 12).entries()) {
      const t = BigInt(Math.round(s.timestamp * 1e9));
      await w.addMessage({ channelId, sequence: i, logTime: t, publishTime: t, data: cdr(type, laserScanOf(s)) });
    }
    await w.end();
    const bytes = new Uint8Array(Buffer.concat(chunks));
    const node = await nodeScans(bytes, 'nostats.mcap', '/front/scan');
    assert.deepEqual(node.topics, [{ name: '/front/scan', type, count: null }]);
    await page.evaluate(() => { window.__messages.length = 0; });
    await drop(page, 'nostats.mcap', bytes);
    await waitMessage(page, /nostats\.mcap \/front\/scan: 12 scans read/);
    assert.deepEqual(await topicOptions(page), [['/front/scan · LaserScan · ? messages', false]]);
    const seen = await page.evaluate(() => window.__messages);
    assert.ok(seen.includes('nostats.mcap: segmenting, 10 so far'), seen.join(' | '));
    assert.ok(seen.includes('nostats.mcap: segmenting 100 %'), seen.join(' | '));
    const options = await lastGroup(page);
    await page.selectOption('#scan-chooser', options[11][0]);
    await page.waitForFunction(() => window.__rtl.source()?.scan === 11, null, { timeout: PAGE_TIMEOUT });
    await carRunsOn(page, node.scans[11].points);
  });

  for (const compression of ['none', 'lz4', 'bz2']) {
    test(`a ROS 1 bag (${compression} chunks) from the file picker: its topics, its 30 scans, the car lesson on scan 12`, async () => {
      const bytes = readFileSync(join(DATA, 'ros1', `intel-${compression}.bag`));
      const name = `intel-${compression}.bag`;
      const node = await nodeScans(new Uint8Array(bytes), name, '/base_scan');
      await pick(page, name, bytes);
      await waitMessage(page, new RegExp(`${name.replace('.', '\\.')} /base_scan: 30 scans read \\(a ROS 1 bag\\)`));
      assert.deepEqual((await topicOptions(page)).sort(), [
        ['/base_scan · LaserScan · 30 messages', false], ['/chatter · String · 1 message', true], ['/os_cloud · PointCloud2 · 2 messages', false]]);
      const options = await lastGroup(page);
      assert.equal(options.length, 30);
      await page.selectOption('#scan-chooser', options[12][0]);
      await page.waitForFunction(() => window.__rtl.source()?.scan === 12, null, { timeout: PAGE_TIMEOUT });
      await carRunsOn(page, node.scans[12].points);
    });
  }

  test('PCD: an organised cloud gives its rings, an unorganised one its points, seen from above', async () => {
    const organised = readFileSync(join(DATA, 'pcd', 'organized.binary.pcd'));
    const cloud = rtl.readPcd(organised);
    await drop(page, 'organized.binary.pcd', organised);
    await waitMessage(page, /organized\.binary\.pcd: 4 rings read \(an organised cloud of 4 rings × 64 columns/);
    assert.equal(await page.isHidden('.topic-chooser'), true, 'no topic chooser for a PCD');
    const rings = await lastGroup(page);
    assert.equal(rings.length, 4);
    await page.selectOption('#scan-chooser', rings[2][0]);
    await page.waitForFunction(() => window.__rtl.source()?.scan === 2, null, { timeout: PAGE_TIMEOUT });
    await carRunsOn(page, xyOf(cloud.ring(2)));
    // the 3D lesson shows the opened cloud instead of the bundled Ouster scan
    await openLesson(page, 'lidar-3d');
    await page.waitForFunction(() => /organized\.binary\.pcd, 4 rings × 64 columns: \d+ clusters/.test(document.querySelector('.lidar3d-caption')?.textContent ?? ''),
      null, { timeout: PAGE_TIMEOUT });

    const unorganised = readFileSync(join(DATA, 'pcd', 'unorganized.compressed.pcd'));
    const points = rtl.readPcd(unorganised).points;
    await pick(page, 'unorganized.compressed.pcd', unorganised);
    await waitMessage(page, /unorganized\.compressed\.pcd: 1 point set read \(an unorganised cloud of 300 points/);
    await carRunsOn(page, xyOf(points));
  });

  test('bad files: the package\'s message under the file\'s name; the scans before a corrupt chunk stay; the page keeps working', async () => {
    // a corrupt chunk in the middle of the MCAP: the scans before it are offered, the message names topic and message
    const bytes = await robotMcap(4096);
    const reader = await McapIndexedReader.Initialize({
      readable: { size: async () => BigInt(bytes.length), read: async (o, n) => bytes.subarray(Number(o), Number(o + n)) },
      decompressHandlers: await loadDecompressHandlers() });
    const t15 = BigInt(Math.round(intel[15].timestamp * 1e9));
    const victim = reader.chunkIndexes.find((c) => c.messageStartTime <= t15 && t15 <= c.messageEndTime);
    for (let k = Number(victim.chunkStartOffset) + 60; k < Number(victim.chunkStartOffset + victim.chunkLength) - 8; k += 7) bytes[k] ^= 0x5a;
    const node = await nodeScans(bytes, 'corrupt.mcap', '/scan');
    assert.ok(node.error && node.scans.length >= 5 && node.scans.length <= 15, `${node.scans.length} scans, ${node.error}`);
    const expected = node.error.message.replace(/^scans: /, '');
    assert.match(expected, /^corrupt\.mcap: topic \/scan: message \d+/);
    await drop(page, 'corrupt.mcap', bytes);
    await waitMessage(page, /^corrupt\.mcap: topic/);
    assert.equal(await message(page), `${expected}. The ${node.scans.length} scans before it can be chosen in the list.`);
    assert.equal(await page.getAttribute('#open-message', 'class'), 'open-message error');
    assert.equal((await lastGroup(page)).length, node.scans.length);
    await carRunsOn(page, node.scans[0].points);
    await page.selectOption('#scan-chooser', (await lastGroup(page)).at(-1)[0]);
    await carRunsOn(page, node.scans.at(-1).points);

    // a bag cut at 70 %: its index is gone; the package reads it record by record, so the complete scans before the
    // cut are offered and the message says where it stopped
    const bag = readFileSync(join(DATA, 'ros1', 'intel-none.bag'));
    const cut = new Uint8Array(bag.subarray(0, Math.floor(bag.length * 0.7)));
    const cutNode = await nodeScans(cut, 'cut.bag', '/base_scan');
    assert.ok(cutNode.error && cutNode.scans.length > 0 && cutNode.scans.length <= 30, `${cutNode.scans.length} scans, ${cutNode.error}`);
    const cutExpected = cutNode.error.message.replace(/^scans: /, '');
    assert.match(cutExpected, /^cut\.bag: /);
    await drop(page, 'cut.bag', cut);
    await waitMessage(page, /^cut\.bag: /);
    assert.equal(await message(page), `${cutExpected}. The ${cutNode.scans.length} scans before it can be chosen in the list.`);
    assert.equal((await lastGroup(page)).length, cutNode.scans.length);
    await carRunsOn(page, cutNode.scans[0].points);
    const before = await page.evaluate(() => window.__rtl.source());

    // a PCD whose POINTS promise more than its data holds
    const lines = readFileSync(join(DATA, 'pcd', 'organized.ascii.pcd'), 'utf8').split('\n');
    const short = lines.slice(0, lines.length - 21).join('\n') + '\n';
    let pcdError;
    try { rtl.readPcd(new TextEncoder().encode(short)); } catch (e) { pcdError = e.message.replace(/^readPcd: /, ''); }
    assert.ok(pcdError, 'the package rejects the short file');
    await pick(page, 'short.pcd', Buffer.from(short));
    await waitMessage(page, /^short\.pcd: /);
    assert.equal(await message(page), `short.pcd: ${pcdError}`);

    // a PCD whose POINTS disagrees with WIDTH x HEIGHT
    const miscount = readFileSync(join(DATA, 'pcd', 'organized.ascii.pcd'), 'utf8').replace(/^POINTS 256$/m, 'POINTS 250');
    assert.notEqual(miscount, lines.join('\n'));
    let countError;
    try { rtl.readPcd(new TextEncoder().encode(miscount)); } catch (e) { countError = e.message.replace(/^readPcd: /, ''); }
    assert.ok(countError, 'the package rejects the count');
    await drop(page, 'miscount.pcd', Buffer.from(miscount));
    await waitMessage(page, /^miscount\.pcd: /);
    assert.equal(await message(page), `miscount.pcd: ${countError}`);

    // a file of another kind under a log's name
    await drop(page, 'notes.mcap', Buffer.from('these are my notes, not a log\n'));
    await waitMessage(page, /^notes\.mcap: /);
    assert.equal(await message(page), 'notes.mcap: not an MCAP file or a ROS 1 bag (V2.0)');

    // nothing changed: the same source, and a lesson still runs on it
    assert.deepEqual(await page.evaluate(() => window.__rtl.source()), before);
    const e = await openLesson(page, 'dp');
    assert.ok(e.steps > 0);
  });

  test('no console errors', async () => {
    assert.deepEqual(await page.evaluate(() => window.__rtl.errors), []);
    assert.deepEqual(problems, []);
  });
});
