// bin/rtl.js --max-vertices J: the whole scan within a vertex budget (the package's extractPolylines) instead of
// segment + vectorize; the JSON equals the package call on the same scan, the budget holds, SVG draws the polylines,
// and contradicting options are usage errors.
import { after, before, describe, test } from 'node:test';
import assert from 'node:assert/strict';
import { mkdtempSync, readFileSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import init from 'rtl-wasm';
import { DATA, runCli as rtl } from './helpers.js';
import { laserScanOf, writeMcap } from '../js/ros-fixtures.mjs';

describe('rtl CLI: --max-vertices', { timeout: 120000 }, () => {
  let tmp, pkg, scans;
  before(async () => {
    tmp = mkdtempSync(join(tmpdir(), 'rtl-cli-budget-'));
    pkg = await init();
    scans = pkg.readCarmenLog(readFileSync(join(DATA, 'intel.log'), 'utf8'));
  });
  after(() => rmSync(tmp, { recursive: true, force: true }));

  test('JSON: the polylines, segments and score of extractPolylines on the scan', () => {
    for (const [scan, J] of [[3, 20], [12, 10]]) {
      const r = rtl([join(DATA, 'intel.log'), '--scan', String(scan), '--max-vertices', String(J)]);
      assert.equal(r.code, 0, r.err);
      const out = JSON.parse(r.out);
      assert.equal(out.segmentation, undefined);
      assert.equal(out.vectorization, undefined);
      const ref = pkg.extractPolylines(scans[scan].points, { maxVertices: J });
      const b = out.budget;
      assert.equal(b.maxVertices, J);
      assert.equal(b.vertexCount, ref.vertexCount);
      assert.ok(b.vertexCount <= J);
      assert.equal(b.polylines.flat().length, 2 * b.vertexCount);
      assert.equal(b.polylines.length, ref.polylines.length);
      b.polylines.forEach((p, k) => p.forEach((v, i) => assert.ok(Math.abs(v - ref.polylines[k][i]) <= 1e-9, `polyline ${k}[${i}]`)));
      assert.equal(b.segments.length, ref.segments.r.length);
      assert.ok(Math.abs(b.rmse - ref.rmse) <= 1e-9 && Math.abs(b.score - ref.score) <= 1e-9 && Math.abs(b.explained - ref.explained) <= 1e-9);
      assert.deepEqual(b.segments[0].beams, [ref.segments.firstBeam[0], ref.segments.lastBeam[0]]);
    }
  });

  test('SVG: one line per polyline segment, the budget in the title', () => {
    const file = join(tmp, 'b.svg');
    const r = rtl([join(DATA, 'intel.log'), '--scan', '3', '--max-vertices', '12', '-f', 'svg', '-o', file]);
    assert.equal(r.code, 0, r.err);
    const svg = readFileSync(file, 'utf8');
    const ref = pkg.extractPolylines(scans[3].points, { maxVertices: 12 });
    assert.match(svg, new RegExp(`${ref.vertexCount} of 12 vertices`));
    const lines = (svg.match(/<line /g) ?? []).length;
    assert.ok(lines >= ref.vertexCount - ref.polylines.length, `${lines} <line> elements`);
  });

  test('a log: one JSON line per LaserScan, each within the budget, as the CARMEN scan it was made from', async () => {
    const log = join(tmp, 'intel.mcap');
    await writeMcap(log, [{ topic: '/scan', type: 'sensor_msgs/msg/LaserScan',
      messages: scans.map((s) => ({ time: s.timestamp, msg: laserScanOf(s) })) }], { compression: 'lz4', chunkSize: 8 * 1024 });
    const r = rtl([log, '--topic', '/scan', '--max-vertices', '20']);
    assert.equal(r.code, 0, r.err);
    const got = r.out.split('\n').filter((l) => l !== '').map((l) => JSON.parse(l));
    assert.equal(got.length, 30);
    for (const [i, line] of got.entries()) {
      assert.ok(line.budget.vertexCount <= 20, `scan ${i}`);
      // float32 ranges in the message: the same map up to float rounding
      const ref = pkg.extractPolylines(scans[i].points, { maxVertices: 20 });
      assert.ok(Math.abs(line.budget.score - ref.score) <= 1e-4, `scan ${i}: ${line.budget.score} vs ${ref.score}`);
    }
  });

  test('bad and contradicting options are usage errors (exit 2)', () => {
    for (const args of [['--max-vertices', '1'], ['--max-vertices', '2.5'], ['--max-vertices', '10', '-m', 'ftls'],
      ['--max-vertices', '10', '--fit'], ['--max-vertices', '10', '--no-segment']]) {
      const r = rtl([join(DATA, 'intel.log'), ...args]);
      assert.equal(r.code, 2, `${args.join(' ')}: ${r.err}`);
      assert.match(r.err, /max-vertices/);
    }
  });
});
