// bin/rtl.js on robot logs: MCAP files written by @mcap/core's McapWriter (ROS 2 CDR LaserScan from the CARMEN
// excerpts, PointCloud2 from the Ouster excerpt). JSON Lines equal the single-scan CLI on the CARMEN log; per-scan
// SVG; several logs with --jobs; a truncated log and Ctrl-C leave complete lines and say where they stopped.
import { after, before, describe, test } from 'node:test';
import assert from 'node:assert/strict';
import { spawn } from 'node:child_process';
import { existsSync, mkdtempSync, readFileSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import init from 'rtl-wasm';
import { DATA, REPO, runCli as rtl } from './helpers.js';
import { laserScanOf, writeMcap } from '../js/ros-fixtures.mjs';

const lines = (out) => out.split('\n').filter((l) => l !== '').map((l) => JSON.parse(l));

describe('rtl CLI on logs (.mcap)', { timeout: 180000 }, () => {
  let tmp, intel, csail, robot, single;
  before(async () => {
    tmp = mkdtempSync(join(tmpdir(), 'rtl-cli-logs-'));
    const r = await init();
    intel = r.readCarmenLog(readFileSync(join(DATA, 'intel.log')));
    csail = r.readCarmenLog(readFileSync(join(DATA, 'csail.log')));
    robot = join(tmp, 'robot.mcap');
    single = join(tmp, 'single.mcap');
    const t0 = intel[0].timestamp;
    const bin = readFileSync(join(DATA, 'rellis3d-os1-4x2048.bin'));
    // the Ouster excerpt as an unorganised-by-rows copy is not needed here: one organised cloud, rows = beams
    const data = new Uint8Array(4 * 2048 * 16);
    for (let c = 0; c < 2048; c++) for (let b = 0; b < 4; b++) data.set(bin.subarray((c * 4 + b) * 16, (c * 4 + b) * 16 + 16), (b * 2048 + c) * 16);
    const f = (name, offset) => ({ name, offset, datatype: 7, count: 1 });
    const cloud = { header: { stamp: { sec: 5, nanosec: 0 }, frame_id: 'os' }, height: 4, width: 2048,
      fields: [f('x', 0), f('y', 4), f('z', 8), f('intensity', 12)], is_bigendian: false, point_step: 16, row_step: 16 * 2048, data, is_dense: false };
    await writeMcap(robot, [
      { topic: '/scan', type: 'sensor_msgs/msg/LaserScan', messages: intel.map((s) => ({ time: s.timestamp, msg: laserScanOf(s) })) },
      { topic: '/csail/scan', type: 'sensor_msgs/msg/LaserScan', messages: csail.map((s, i) => ({ time: t0 + 0.05 + i * 0.2, msg: laserScanOf(s) })) },
      { topic: '/os_cloud', type: 'sensor_msgs/msg/PointCloud2', messages: [{ time: t0 + 0.01, msg: cloud }] },
    ], { compression: 'lz4', chunkSize: 8 * 1024 });
    await writeMcap(single, [{ topic: '/scan', type: 'sensor_msgs/msg/LaserScan',
      messages: intel.map((s) => ({ time: s.timestamp, msg: laserScanOf(s) })) }], { compression: 'zstd', chunkSize: 8 * 1024 });
  });
  after(() => rmSync(tmp, { recursive: true, force: true }));

  test('rtl robot.mcap --topic /scan -m ftls: one JSON line per scan, equal to rtl intel.log --scan i', () => {
    const r = rtl([robot, '--topic', '/scan', '-m', 'ftls']);
    assert.equal(r.code, 0, r.err);
    const got = lines(r.out);
    assert.equal(got.length, 30);
    got.forEach((l, i) => {
      assert.equal(l.source.index, i);
      assert.equal(l.source.topic, '/scan');
      assert.equal(l.source.file, robot);
    });
    for (const i of [0, 11, 29]) {
      const ref = JSON.parse(rtl([join(DATA, 'intel.log'), '--scan', String(i), '-m', 'ftls']).out);
      assert.deepEqual(got[i].segmentation.clusters, ref.segmentation.clusters, `scan ${i}: clusters`);
      assert.equal(got[i].returns, ref.returns);
      assert.equal(got[i].vectorization.segments.length, ref.vectorization.segments.length, `scan ${i}: segments`);
      got[i].vectorization.segments.forEach((s, k) => {
        assert.deepEqual(s.indices, ref.vectorization.segments[k].indices);
        s.coordinates.forEach((x, j) => assert.ok(Math.abs(x - ref.vectorization.segments[k].coordinates[j]) < 1e-3, `scan ${i} segment ${k}`));
      });
    }
  });

  test('rtl on a ROS 1 bag (tests/data/ros1, written by rosbag): the same clusters as rtl intel.log --scan i', () => {
    const r = rtl([join(DATA, 'ros1', 'intel-lz4.bag'), '--topic', '/base_scan']);
    assert.equal(r.code, 0, r.err);
    const got = lines(r.out);
    assert.equal(got.length, 30);
    for (const i of [0, 17]) {
      const ref = JSON.parse(rtl([join(DATA, 'intel.log'), '--scan', String(i)]).out);
      assert.deepEqual(got[i].segmentation.clusters, ref.segmentation.clusters, `scan ${i}`);
      assert.equal(got[i].source.maxRange, 50);
    }
  });

  test('the topic: the only LaserScan topic by default; several -> exit 1 listing them; a PointCloud2 topic by ring', () => {
    assert.equal(lines(rtl([single]).out).length, 30);
    const r = rtl([robot]);
    assert.equal(r.code, 1);
    assert.match(r.err, /several scan topics; pass --topic/);
    assert.match(r.err, /\/csail\/scan \[sensor_msgs\/msg\/LaserScan\]/);
    const unknown = rtl([robot, '--topic', '/nope']);
    assert.equal(unknown.code, 1);
    assert.ok(unknown.err.includes(robot) && unknown.err.includes('no topic /nope'), unknown.err);
    const c = rtl([robot, '--topic', '/os_cloud', '--ring', '2']);
    assert.equal(c.code, 0, c.err);
    const [l] = lines(c.out);
    assert.equal(l.dim, 3);
    assert.equal(l.points, 2048);
    assert.equal(l.source.ring, 2);
    assert.ok(l.segmentation.clusters.length > 10);
  });

  test('--format svg writes one file per scan (%d); usage errors exit 2', () => {
    const r = rtl([single, '-m', 'dp', '-f', 'svg', '-o', join(tmp, 'scan-%d.svg')]);
    assert.equal(r.code, 0, r.err);
    for (const i of [0, 29]) assert.match(readFileSync(join(tmp, `scan-${i}.svg`), 'utf8'), /^<\?xml|<svg/);
    assert.ok(!existsSync(join(tmp, 'scan-30.svg')));
    for (const args of [[single, '-f', 'svg'], [single, '-f', 'svg', '-o', 'x.svg'], [single, '--beams', '4'], [single, '--scan', '2'],
      [join(DATA, 'intel.log'), '--topic', '/scan'], [single, '--jobs', '0'], [single, join(DATA, 'intel.log')],
      [single, single, '-f', 'svg', '-o', 'a-%d.svg']]) {
      const u = rtl(args);
      assert.equal(u.code, 2, `${args.join(' ')}: ${u.err}`);
      assert.match(u.err, /^rtl: /);
    }
  });

  test('a truncated log: complete lines for every scan before the cut, then exit 1 naming file, topic and message', () => {
    const bytes = readFileSync(single);
    const cut = join(tmp, 'cut.mcap');
    writeFileSync(cut, bytes.subarray(0, Math.floor(bytes.length * 0.6)));
    const r = rtl([cut, '-o', join(tmp, 'cut.jsonl')]);
    assert.equal(r.code, 1);
    const got = lines(readFileSync(join(tmp, 'cut.jsonl'), 'utf8'));
    assert.ok(got.length > 0 && got.length < 30, `${got.length} lines`);
    got.forEach((l, i) => assert.equal(l.source.index, i));
    assert.ok(r.err.includes(cut) && r.err.includes('/scan') && r.err.includes(`message ${got.length}`), r.err);
    assert.match(r.err, new RegExp(`the output holds the ${got.length} scans before it`));
  });

  test('a truncated ROS 1 bag (its index lost): the lines of every complete scan, equal to the whole bag\'s, then exit 1 naming file, message and byte', () => {
    const whole = rtl([join(DATA, 'ros1', 'intel-none.bag'), '--topic', '/base_scan', '-m', 'ftls']);
    assert.equal(whole.code, 0, whole.err);
    const bytes = readFileSync(join(DATA, 'ros1', 'intel-none.bag'));
    const cut = join(tmp, 'cut.bag');
    writeFileSync(cut, bytes.subarray(0, Math.floor(bytes.length * 0.5)));
    const r = rtl([cut, '--topic', '/base_scan', '-m', 'ftls']);
    assert.equal(r.code, 1, r.err);
    const got = r.out.split('\n').filter(Boolean), all = whole.out.split('\n').filter(Boolean);
    assert.ok(got.length > 5 && got.length < 30, `${got.length} lines`);
    got.forEach((l, i) => assert.equal(l.replaceAll(cut, 'F'), all[i].replaceAll(join(DATA, 'ros1', 'intel-none.bag'), 'F'), `scan ${i}`));
    assert.ok(r.err.includes(cut) && r.err.includes('/base_scan') && r.err.includes(`message ${got.length}`) && /truncated: .* at byte \d+/.test(r.err), r.err);
    assert.match(r.err, new RegExp(`the output holds the ${got.length} scans before it`));
  });

  test('several logs with --jobs 2: every scan of each, each line naming its log; --progress draws a bar', () => {
    const r = rtl([single, robot, '--topic', '/scan', '--jobs', '2']);
    assert.equal(r.code, 0, r.err);
    const got = lines(r.out);
    assert.equal(got.filter((l) => l.source.file === single).length, 30);
    assert.equal(got.filter((l) => l.source.file === robot).length, 30);
    const p = rtl([single, '--progress']);
    assert.equal(p.code, 0);
    assert.match(p.err, /\[#{30}\] 30\/30 scans {2}single\.mcap/);
    assert.equal(rtl([single]).err, '');   // not a terminal: no bar
    const pj = rtl([single, robot, '--topic', '/scan', '--jobs', '2', '--progress']);
    assert.equal(pj.code, 0, pj.err);
    assert.match(pj.err, /\[#{30}\] 60\/60 scans {2}2 logs\n$/);
  });

  test('Ctrl-C: the scans done are complete lines, and it says where it stopped (exit 130)', async () => {
    const big = join(tmp, 'big.mcap');
    const messages = [];
    for (let k = 0; k < 400; k++) intel.forEach((s, i) => messages.push({ time: 1 + (k * 30 + i) * 0.1, msg: laserScanOf(s) }));
    await writeMcap(big, [{ topic: '/scan', type: 'sensor_msgs/msg/LaserScan', messages }], { compression: 'zstd', chunkSize: 256 * 1024 });
    const child = spawn(process.execPath, [join(REPO, 'bin', 'rtl.js'), big, '-m', 'ftls'], { cwd: REPO });
    let out = '', err = '';
    child.stderr.on('data', (d) => { err += d; });
    child.stdout.on('data', (d) => {
      if (out === '') setTimeout(() => child.kill('SIGINT'), 100);
      out += d;
    });
    const code = await new Promise((res) => child.on('exit', (c) => res(c)));
    assert.equal(code, 130, err);
    assert.ok(out.endsWith('\n'));
    const got = lines(out);
    assert.ok(got.length > 0 && got.length < 12000, `${got.length} lines`);
    const m = /interrupted: .*big\.mcap: \/scan: wrote (\d+) scans; the next is message (\d+)/.exec(err);
    assert.ok(m, err);
    assert.equal(Number(m[1]), got.length);
    assert.equal(Number(m[2]), got.length);
  });
});
