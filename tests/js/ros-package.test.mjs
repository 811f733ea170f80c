// fromLaserScan / fromPointCloud2 through the built package (rtl.fromLaserScan, rtl.fromPointCloud2): messages made
// from tests/data's real scans give the points the package's own readers give, and feed its algorithms.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import init from 'rtl-wasm';
import * as ros from '../../wasm/js/ros/messages.js';

const rtl = await init();
const DATA = new URL('../data/', import.meta.url);

test('rtl.fromLaserScan: a LaserScan of an intel.log scan gives readCarmenLog\'s points and the same polylines', () => {
  assert.equal(typeof rtl.fromLaserScan, 'function');
  const scan = rtl.readCarmenLog(readFileSync(new URL('intel.log', DATA)))[5];
  const n = scan.ranges.length;
  const msg = {
    header: { stamp: { sec: 1, nanosec: 0 }, frame_id: 'laser' },
    // CARMEN's beam layout (rtl/io/CarmenLog.h): intel's 180 beams at -90 + i degrees
    angle_min: -Math.PI / 2, angle_max: -Math.PI / 2 + (n - 1) * Math.PI / n, angle_increment: Math.PI / n,
    range_min: 1e-9, range_max: scan.maxRange * (1 - 1e-12), ranges: Float32Array.from(scan.ranges),
  };
  const s = rtl.fromLaserScan(msg);
  assert.deepEqual(s, ros.fromLaserScan(msg));  // the package's copy is the source module's adapter
  assert.equal(s.points.length, scan.points.length);
  let gaps = 0;
  for (let i = 0; i < scan.points.length; i++) {
    if (Number.isNaN(scan.points[i])) { gaps++; assert.ok(Number.isNaN(s.points[i]), `coordinate ${i}: gap expected`); continue; }
    // float32 ranges (as a LaserScan carries them): within float precision of the log's ranges
    assert.ok(Math.abs(s.points[i] - scan.points[i]) <= 1e-6 * 80, `coordinate ${i}: ${s.points[i]} vs ${scan.points[i]}`);
  }
  assert.ok(gaps < scan.points.length);
  const a = rtl.extractPolylines(s.points, { maxVertices: 20 });
  const b = rtl.extractPolylines(scan.points, { maxVertices: 20 });
  assert.equal(a.vertexCount, b.vertexCount);
  assert.ok(Math.abs(a.score - b.score) <= 1e-4, `${a.score} vs ${b.score}`);
});

test('rtl.fromPointCloud2: a PointCloud2 of the organised PCD gives readPcd\'s cloud', () => {
  const cloud = rtl.readPcd(readFileSync(new URL('pcd/organized.binary.pcd', DATA)));
  assert.ok(cloud.organized);
  if (!cloud.organized) return;
  const { width, height } = cloud;
  // Row-major float32 records x, y, z, intensity, as a ROS driver publishes an organised cloud.
  const data = new Uint8Array(16 * width * height), dv = new DataView(data.buffer);
  for (let r = 0; r < height; r++) {
    for (let c = 0; c < width; c++) {
      const k = c * height + r, at = 16 * (r * width + c);  // k: column-major index in readPcd's result
      for (let a = 0; a < 3; a++) dv.setFloat32(at + 4 * a, cloud.points[3 * k + a], true);
      dv.setFloat32(at + 12, cloud.intensity[k], true);
    }
  }
  const fields = ['x', 'y', 'z', 'intensity'].map((name, i) => ({ name, offset: 4 * i, datatype: 7, count: 1 }));
  const msg = { header: { stamp: { sec: 3, nanosec: 0 }, frame_id: 'os1' }, height, width, fields, is_bigendian: false,
    point_step: 16, row_step: 16 * width, data, is_dense: false };
  const p = rtl.fromPointCloud2(msg);
  assert.ok('beams' in p);
  if (!('beams' in p)) return;
  assert.equal(p.beams, cloud.beams);
  assert.equal(p.columns, cloud.columns);
  assert.deepEqual(p.points, cloud.points);
  assert.deepEqual(p.intensity, cloud.intensity);
  assert.deepEqual(p.ring(1), cloud.ring(1));
  assert.equal(p.frameId, 'os1');
});
