// fromLaserScan / fromPointCloud2: the pure adapters, on hand-made messages whose points are known.
import test from 'node:test';
import assert from 'node:assert/strict';
import { fromLaserScan, fromPointCloud2 } from '../../wasm/js/ros/messages.js';

const near = (a, b, tol, what) => assert.ok(Math.abs(a - b) <= tol, `${what}: ${a} vs ${b}`);

function ros2Scan(over = {}) {
  return {
    header: { stamp: { sec: 12, nanosec: 500000000 }, frame_id: 'base_laser' },
    angle_min: -1, angle_max: 0.5, angle_increment: 0.25, time_increment: 0, scan_time: 0.1,
    range_min: 0.1, range_max: 30,
    ranges: Float32Array.of(1, NaN, Infinity, -Infinity, 0.05, 31, 2),
    intensities: new Float32Array(0), ...over,
  };
}

test('fromLaserScan: ROS 2 scan -> points per beam, NaN for NaN, +-inf and ranges outside [range_min, range_max]', () => {
  const s = fromLaserScan(ros2Scan());
  assert.equal(s.points.length, 14);
  assert.equal(s.angles.length, 7);
  for (let i = 0; i < 7; i++) near(s.angles[i], -1 + 0.25 * i, 1e-15, `angle ${i}`);
  near(s.points[0], Math.cos(-1), 1e-15, 'x0'); near(s.points[1], Math.sin(-1), 1e-15, 'y0');
  near(s.points[12], 2 * Math.cos(0.5), 1e-15, 'x6'); near(s.points[13], 2 * Math.sin(0.5), 1e-15, 'y6');
  for (let i = 1; i <= 5; i++) assert.ok(Number.isNaN(s.points[2 * i]) && Number.isNaN(s.points[2 * i + 1]), `beam ${i} is a gap`);
  assert.equal(s.maxRange, 30);
  near(s.stamp, 12.5, 1e-12, 'stamp');
  assert.equal(s.frameId, 'base_laser');
  assert.equal(s.intensities, undefined);
});

test('fromLaserScan: infinite ranges are gaps even when the bounds are infinite (found by the fuzz test)', () => {
  const s = fromLaserScan(ros2Scan({ range_min: -Infinity, range_max: Infinity, ranges: [-Infinity, Infinity, 3] }));
  assert.ok([0, 1, 2, 3].every((k) => Number.isNaN(s.points[k])));
  near(s.points[4], 3 * Math.cos(-0.5), 1e-15, 'finite range kept');
});

test('fromLaserScan: the range bounds are inclusive; plain arrays and intensities are accepted', () => {
  const s = fromLaserScan(ros2Scan({ ranges: [0.1, 30, 0.0999], intensities: [5, 6, 7] }));
  near(s.points[0], 0.1 * Math.cos(-1), 1e-15, 'range_min kept');
  near(s.points[2], 30 * Math.cos(-0.75), 1e-13, 'range_max kept');
  assert.ok(Number.isNaN(s.points[4]));
  assert.deepEqual([...s.intensities], [5, 6, 7]);
});

test('fromLaserScan: ROS 1 ({sec, nsec}) and roslib ({secs, nsecs}) stamps; a missing header', () => {
  near(fromLaserScan(ros2Scan({ header: { stamp: { sec: 3, nsec: 250000000 }, frame_id: 'a' } })).stamp, 3.25, 1e-12, 'ros1');
  near(fromLaserScan(ros2Scan({ header: { stamp: { secs: 4, nsecs: 1 }, frame_id: 'a' } })).stamp, 4 + 1e-9, 1e-12, 'roslib');
  const s = fromLaserScan(ros2Scan({ header: undefined }));
  assert.equal(s.stamp, undefined);
  assert.equal(s.frameId, '');
});

test('fromLaserScan: foxglove.LaserScan spreads the beams from start_angle to end_angle', () => {
  const s = fromLaserScan({ timestamp: { sec: 1, nsec: 0 }, frame_id: 'lidar', start_angle: 0, end_angle: Math.PI / 2,
                            ranges: [1, 2, NaN], intensities: [] });
  near(s.angles[1], Math.PI / 4, 1e-15, 'middle angle');
  near(s.points[2], 2 * Math.cos(Math.PI / 4), 1e-15, 'x1');
  assert.ok(Number.isNaN(s.points[4]) && Number.isNaN(s.points[5]), 'beam 2 (NaN) is a gap');
  near(s.points[0], 1, 0, 'x0');
  assert.equal(s.maxRange, Infinity);
  assert.equal(s.frameId, 'lidar');
  assert.equal(s.stamp, 1);
  assert.equal(fromLaserScan({ start_angle: 0.3, end_angle: 0.3, ranges: [1] }).angles[0], 0.3);
});

test('fromLaserScan: bad arguments throw TypeError/RangeError starting with its name', () => {
  const cases = [
    [undefined, TypeError], [null, TypeError], [42, TypeError], [{}, TypeError],
    [ros2Scan({ ranges: 'abc' }), TypeError], [ros2Scan({ ranges: [1, '2'] }), TypeError],
    [ros2Scan({ angle_min: NaN }), RangeError], [ros2Scan({ angle_increment: Infinity }), RangeError],
    [ros2Scan({ angle_increment: '0.1' }), TypeError], [ros2Scan({ range_min: 5, range_max: 1 }), RangeError],
    [ros2Scan({ range_max: NaN }), RangeError], [ros2Scan({ intensities: [1, 2] }), RangeError],
    [ros2Scan({ header: 5 }), TypeError], [ros2Scan({ header: { stamp: { sec: 1.5, nanosec: 0 } } }), RangeError],
    [ros2Scan({ header: { stamp: { sec: 1, nanosec: 2e9 } } }), RangeError], [ros2Scan({ header: { frame_id: 7 } }), TypeError],
    [{ start_angle: 0, end_angle: NaN, ranges: [] }, RangeError],
  ];
  for (const [msg, Type] of cases)
    assert.throws(() => fromLaserScan(msg), (e) => e instanceof Type && e.message.startsWith('fromLaserScan: '), JSON.stringify(msg));
});

// A PointCloud2 of the given points (rows x cols, row-major as drivers publish), with configurable layout.
function cloud(rows, cols, pts, { type = 7, big = false, xOff = 0, extra = 0, intensity, ring } = {}) {
  const size = type === 7 ? 4 : 8;
  const fields = ['x', 'y', 'z'].map((name, i) => ({ name, offset: xOff + i * size, datatype: type, count: 1 }));
  let step = xOff + 3 * size;
  if (intensity) { fields.push({ name: 'intensity', offset: step, datatype: 7, count: 1 }); step += 4; }
  if (ring) { fields.push({ name: 'ring', offset: step, datatype: 4, count: 1 }); step += 2; }
  step += extra;
  const rowStep = cols * step + 3;   // padded rows
  const data = new Uint8Array(rows * rowStep);
  const dv = new DataView(data.buffer);
  for (let r = 0; r < rows; r++) {
    for (let c = 0; c < cols; c++) {
      const at = r * rowStep + c * step, p = pts[r * cols + c];
      for (let a = 0; a < 3; a++) type === 7 ? dv.setFloat32(at + xOff + 4 * a, p[a], !big) : dv.setFloat64(at + xOff + 8 * a, p[a], !big);
      if (intensity) dv.setFloat32(at + 3 * size + xOff, intensity[r * cols + c], !big);
      if (ring) dv.setUint16(at + 3 * size + xOff + (intensity ? 4 : 0), ring[r * cols + c], !big);
    }
  }
  return { header: { stamp: { sec: 7, nanosec: 0 }, frame_id: 'os1' }, height: rows, width: cols, fields,
           is_bigendian: big, point_step: step, row_step: rowStep, data, is_dense: false };
}

const PTS = [[1, 2, 3], [0, 0, 0], [NaN, 1, 1], [4.5, -5.25, 6], [7, 8, Infinity], [-1, -2, -3]];

test('fromPointCloud2: an organised cloud comes out column-major, NaN for no return (0,0,0) and non-finite points', () => {
  for (const opts of [{}, { type: 8 }, { big: true }, { type: 8, big: true, xOff: 4, extra: 5 }]) {
    const c = fromPointCloud2(cloud(2, 3, PTS, { ...opts, intensity: [1, 2, 3, 4, 5, 6], ring: [0, 0, 0, 1, 1, 1] }));
    assert.equal(c.beams, 2); assert.equal(c.columns, 3);
    // column c, beam b = point c * 2 + b = source row b, column c
    const expect = (k) => { const b = k % 2, col = (k - b) / 2; return PTS[b * 3 + col]; };
    for (let k = 0; k < 6; k++) {
      const p = expect(k);
      const gap = !p.every(Number.isFinite) || p.every((v) => v === 0);
      for (let a = 0; a < 3; a++) {
        if (gap) assert.ok(Number.isNaN(c.points[3 * k + a]), `point ${k} gap (${JSON.stringify(opts)})`);
        else assert.equal(c.points[3 * k + a], p[a], `point ${k} axis ${a} (${JSON.stringify(opts)})`);
      }
    }
    assert.deepEqual([...c.intensity], [1, 4, 2, 5, 3, 6]);
    assert.deepEqual([...c.rings], [0, 1, 0, 1, 0, 1]);
    assert.deepEqual([...c.ring(1)].slice(0, 3), [4.5, -5.25, 6]);
    assert.deepEqual([...c.column(0)], [1, 2, 3, 4.5, -5.25, 6]);
    assert.equal(c.stamp, 7); assert.equal(c.frameId, 'os1');
  }
});

test('fromPointCloud2: an unorganised cloud keeps message order; intensity absent when the cloud has none', () => {
  const c = fromPointCloud2(cloud(1, 6, PTS));
  assert.equal(c.count, 6);
  assert.deepEqual([...c.points.subarray(9, 12)], [4.5, -5.25, 6]);
  assert.ok(Number.isNaN(c.points[3]));
  assert.equal(c.intensity, undefined);
  assert.equal(c.rings, undefined);
  const empty = fromPointCloud2({ ...cloud(1, 6, PTS), width: 0, height: 0 });
  assert.equal(empty.points.length, 0);
});

test('fromPointCloud2: roslib base64 data and plain byte arrays', () => {
  const m = cloud(1, 6, PTS);
  const b64 = Buffer.from(m.data).toString('base64');
  assert.deepEqual(fromPointCloud2({ ...m, data: b64 }).points, fromPointCloud2(m).points);
  assert.deepEqual(fromPointCloud2({ ...m, data: [...m.data] }).points, fromPointCloud2(m).points);
});

test('fromPointCloud2: bad arguments throw TypeError/RangeError starting with its name', () => {
  const m = cloud(2, 3, PTS);
  const noZ = { ...m, fields: m.fields.filter((f) => f.name !== 'z') };
  const intX = { ...m, fields: m.fields.map((f) => (f.name === 'x' ? { ...f, datatype: 5 } : f)) };
  const cases = [
    [undefined, TypeError], ['cloud', TypeError], [{ ...m, height: -1 }, RangeError], [{ ...m, width: 1.5 }, RangeError],
    [{ ...m, width: '3' }, TypeError], [{ ...m, data: m.data.subarray(0, 10) }, RangeError], [{ ...m, data: {} }, TypeError],
    [{ ...m, data: [256] }, RangeError], [{ ...m, data: '!!notbase64' }, RangeError], [{ ...m, fields: 'xyz' }, TypeError],
    [noZ, RangeError], [intX, RangeError], [{ ...m, fields: [...m.fields, { name: 'q', offset: 0, datatype: 9 }] }, RangeError],
    [{ ...m, fields: [...m.fields, { name: 'q', offset: m.point_step, datatype: 2 }] }, RangeError],
    [{ ...m, row_step: 1 }, RangeError], [{ ...m, is_bigendian: 'no' }, TypeError], [{ ...m, fields: [null] }, TypeError],
  ];
  for (const [msg, Type] of cases)
    assert.throws(() => fromPointCloud2(msg), (e) => e instanceof Type && e.message.startsWith('fromPointCloud2: '), String(Object.keys(msg ?? {})));
  const c = fromPointCloud2(m);
  assert.throws(() => c.ring(2), RangeError);
  assert.throws(() => c.column('0'), TypeError);
});
