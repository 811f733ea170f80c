// ROS scan messages -> the package's point arrays. Pure JavaScript with no dependency: the messages are the plain
// objects that the ecosystem's decoders (@foxglove/rosmsg2-serialization, @foxglove/rosmsg-serialization, roslib)
// produce, read by duck typing. Every function checks its argument and throws TypeError/RangeError whose message
// starts with the function's name; nothing here touches WebAssembly, so these run anywhere (workers included).

const TWO_32 = 4294967296;

function describe(v) {
  if (v === null) return 'null';
  if (Array.isArray(v)) return `an array of length ${v.length}`;
  if (ArrayBuffer.isView(v)) return `a ${v.constructor.name} of length ${v.length ?? v.byteLength}`;
  if (typeof v === 'object') return v.constructor && v.constructor !== Object ? `a ${v.constructor.name}` : 'an object';
  if (typeof v === 'string') return `the string '${v.length > 40 ? `${v.slice(0, 40)}...` : v}'`;
  return `${typeof v} ${String(v)}`;
}

function isObject(v) {
  return typeof v === 'object' && v !== null;
}

function number(fn, obj, key, { finite = false } = {}) {
  const v = obj[key];
  if (typeof v !== 'number') throw new TypeError(`${fn}: ${key} must be a number, got ${describe(v)}`);
  if (finite && !Number.isFinite(v)) throw new RangeError(`${fn}: ${key} must be finite, got ${v}`);
  return v;
}

function count(fn, obj, key, max = 2 ** 31 - 1) {
  const v = obj[key];
  if (typeof v !== 'number') throw new TypeError(`${fn}: ${key} must be a number, got ${describe(v)}`);
  if (!Number.isInteger(v) || v < 0 || v > max) throw new RangeError(`${fn}: ${key} must be an integer in [0, ${max}], got ${v}`);
  return v;
}

// A ROS time as seconds: { sec, nanosec } (ROS 2), { sec, nsec } (ROS 1 decoders, foxglove), { secs, nsecs } (roslib's
// ROS 1 JSON). Unsigned 32-bit seconds and nanoseconds below 1e9 (ROS 2's builtin_interfaces/Time has signed
// seconds: negative values are accepted). undefined when the message carries no time.
function stampOf(fn, where, t) {
  if (t === undefined || t === null) return undefined;
  if (!isObject(t)) throw new TypeError(`${fn}: ${where} must be a time object {sec, nanosec}, got ${describe(t)}`);
  const sec = t.sec ?? t.secs;
  const nsec = t.nanosec ?? t.nsec ?? t.nsecs ?? 0;
  if (typeof sec !== 'number' || typeof nsec !== 'number')
    throw new TypeError(`${fn}: ${where} must have numeric sec and nanosec (or nsec), got ${describe(sec)} and ${describe(nsec)}`);
  if (!Number.isInteger(sec) || sec < -(TWO_32 / 2) || sec >= TWO_32 || !Number.isInteger(nsec) || nsec < 0 || nsec >= 1e9)
    throw new RangeError(`${fn}: ${where} must have integer sec and nanosec in [0, 1e9), got ${sec} and ${nsec}`);
  return sec + nsec * 1e-9;
}

function frameOf(fn, where, f) {
  if (f === undefined || f === null) return '';
  if (typeof f !== 'string') throw new TypeError(`${fn}: ${where} must be a string, got ${describe(f)}`);
  return f;
}

// A numeric sequence (array of numbers or a typed array) as something indexable; its length is checked by the caller.
function numericArray(fn, key, v, { optional = false } = {}) {
  if (v === undefined && optional) return undefined;
  if (ArrayBuffer.isView(v) && !(v instanceof DataView) && typeof v.length === 'number' && !(v instanceof BigInt64Array) &&
      !(v instanceof BigUint64Array)) return v;
  if (Array.isArray(v)) {
    for (let i = 0; i < v.length; i++)
      if (typeof v[i] !== 'number') throw new TypeError(`${fn}: ${key}[${i}] must be a number, got ${describe(v[i])}`);
    return v;
  }
  throw new TypeError(`${fn}: ${key} must be an array of numbers or a typed array, got ${describe(v)}`);
}

const MAX_BEAMS = 1 << 24;

// The beam angles with their cosines and sines, kept for the last geometry seen: a log's scans share one geometry,
// and the trigonometry is most of the adapter's time otherwise. Read-only once built.
let lastTable = { first: NaN, step: NaN, n: -1 };
function beamTable(first, step, n) {
  const t = lastTable;
  if (t.first === first && t.step === step && t.n === n) return t;
  const angles = new Float64Array(n), cos = new Float64Array(n), sin = new Float64Array(n);
  for (let i = 0; i < n; i++) {
    const a = first + i * step;
    angles[i] = a;
    cos[i] = Math.cos(a);
    sin[i] = Math.sin(a);
  }
  lastTable = { first, step, n, angles, cos, sin };
  return lastTable;
}

/**
 * sensor_msgs/LaserScan (ROS 1 or ROS 2) or foxglove.LaserScan -> { points, angles, maxRange, stamp, frameId,
 * intensities }. Beam i lies at angle_min + i * angle_increment (foxglove: start_angle + i * (end_angle -
 * start_angle) / (n - 1)); its point is (r cos a, r sin a) in the sensor frame, or NaN, NaN (a gap) when r is NaN,
 * +-inf or outside [range_min, range_max] (foxglove: not finite or negative). O(n) for n beams.
 */
export function fromLaserScan(msg) {
  const fn = 'fromLaserScan';
  if (!isObject(msg)) throw new TypeError(`${fn}: msg must be a LaserScan message object, got ${describe(msg)}`);
  let first, step, rangeMin, rangeMax, stamp, frameId;
  const ros = 'angle_min' in msg;
  if (!ros && !('start_angle' in msg))
    throw new TypeError(`${fn}: msg must be a sensor_msgs/LaserScan (angle_min, angle_increment, range_min, range_max, ranges) ` +
                        'or a foxglove.LaserScan (start_angle, end_angle, ranges)');
  const ranges = numericArray(fn, 'ranges', msg.ranges);
  const n = ranges.length;
  if (n > MAX_BEAMS) throw new RangeError(`${fn}: ranges has ${n} beams, more than ${MAX_BEAMS}`);
  if (ros) {
    first = number(fn, msg, 'angle_min', { finite: true });
    number(fn, msg, 'angle_max');
    step = number(fn, msg, 'angle_increment', { finite: true });
    rangeMin = number(fn, msg, 'range_min');
    rangeMax = number(fn, msg, 'range_max');
    if (Number.isNaN(rangeMin) || Number.isNaN(rangeMax) || rangeMin > rangeMax)
      throw new RangeError(`${fn}: range_min and range_max must be ordered numbers, got ${rangeMin} and ${rangeMax}`);
    if (msg.header !== undefined && !isObject(msg.header)) throw new TypeError(`${fn}: header must be an object, got ${describe(msg.header)}`);
    stamp = stampOf(fn, 'header.stamp', msg.header?.stamp);
    frameId = frameOf(fn, 'header.frame_id', msg.header?.frame_id);
  } else {
    first = number(fn, msg, 'start_angle', { finite: true });
    const last = number(fn, msg, 'end_angle', { finite: true });
    step = n > 1 ? (last - first) / (n - 1) : 0;
    rangeMin = 0;
    rangeMax = Infinity;
    stamp = stampOf(fn, 'timestamp', msg.timestamp);
    frameId = frameOf(fn, 'frame_id', msg.frame_id);
  }
  const inten = numericArray(fn, 'intensities', msg.intensities, { optional: true });
  if (inten !== undefined && inten.length !== 0 && inten.length !== n)
    throw new RangeError(`${fn}: intensities must be empty or have one value per beam (${n}), got ${inten.length}`);

  const points = new Float64Array(2 * n);
  const t = beamTable(first, step, n);
  const angles = t.angles.slice();
  const cos = t.cos, sin = t.sin;
  for (let i = 0; i < n; i++) {
    const r = ranges[i];
    if (r >= rangeMin && r <= rangeMax && Number.isFinite(r)) {
      points[2 * i] = r * cos[i];
      points[2 * i + 1] = r * sin[i];
    } else {
      points[2 * i] = NaN;
      points[2 * i + 1] = NaN;
    }
  }
  const out = { points, angles, maxRange: rangeMax, stamp, frameId };
  if (inten !== undefined && inten.length === n && n > 0) out.intensities = Float32Array.from(inten);
  return out;
}

// sensor_msgs/PointField datatypes: [bytes, DataView getter]
const FIELD_TYPES = {
  1: [1, 'getInt8'], 2: [1, 'getUint8'], 3: [2, 'getInt16'], 4: [2, 'getUint16'],
  5: [4, 'getInt32'], 6: [4, 'getUint32'], 7: [4, 'getFloat32'], 8: [8, 'getFloat64'],
};

function bytesOf(fn, data) {
  if (data instanceof Uint8Array) return data;
  if (ArrayBuffer.isView(data)) return new Uint8Array(data.buffer, data.byteOffset, data.byteLength);
  if (data instanceof ArrayBuffer) return new Uint8Array(data);
  if (typeof data === 'string') {   // roslib's JSON carries uint8[] as base64
    let bin;
    try {
      bin = atob(data);
    } catch {
      throw new RangeError(`${fn}: data is a string but not base64`);
    }
    const u8 = new Uint8Array(bin.length);
    for (let i = 0; i < bin.length; i++) u8[i] = bin.charCodeAt(i);
    return u8;
  }
  if (Array.isArray(data)) {
    const u8 = new Uint8Array(data.length);
    for (let i = 0; i < data.length; i++) {
      const b = data[i];
      if (typeof b !== 'number' || !Number.isInteger(b) || b < 0 || b > 255)
        throw new RangeError(`${fn}: data[${i}] must be a byte (integer in [0, 255]), got ${describe(b)}`);
      u8[i] = b;
    }
    return u8;
  }
  throw new TypeError(`${fn}: data must be a Uint8Array (or base64 string), got ${describe(data)}`);
}

function fieldsOf(fn, fields, pointStep) {
  if (!Array.isArray(fields)) throw new TypeError(`${fn}: fields must be an array of PointField, got ${describe(fields)}`);
  const byName = new Map();
  fields.forEach((f, i) => {
    if (!isObject(f)) throw new TypeError(`${fn}: fields[${i}] must be a PointField object, got ${describe(f)}`);
    if (typeof f.name !== 'string') throw new TypeError(`${fn}: fields[${i}].name must be a string, got ${describe(f.name)}`);
    const offset = count(fn, f, 'offset');
    const datatype = f.datatype;
    if (typeof datatype !== 'number') throw new TypeError(`${fn}: fields[${i}].datatype must be a number, got ${describe(datatype)}`);
    const type = FIELD_TYPES[datatype];
    if (type === undefined) throw new RangeError(`${fn}: fields[${i}] ('${f.name}') has unknown datatype ${datatype} (1..8)`);
    const n = f.count === undefined ? 1 : count(fn, f, 'count');
    if (offset + type[0] * Math.max(n, 1) > pointStep)
      throw new RangeError(`${fn}: field '${f.name}' (offset ${offset}, ${type[0]} bytes x ${n}) does not fit in point_step ${pointStep}`);
    if (!byName.has(f.name)) byName.set(f.name, { offset, datatype, size: type[0], get: type[1] });
  });
  return byName;
}

/**
 * sensor_msgs/PointCloud2 (ROS 1 or ROS 2) -> points. x, y, z may be float32 or float64 at any offset, in either
 * endianness. A point with a non-finite coordinate, or at (0, 0, 0) (how drivers such as Ouster's mark no return),
 * is a NaN point. Organised clouds (height > 1: row r is beam r, top first, as Ouster and Velodyne drivers publish
 * them) give readOrganizedLidar's shape: { beams: height, columns: width, points column-major (beam b of column c is
 * point c * beams + b), intensity (NaN when the cloud has no intensity field), ring(b), column(c) }; unorganised
 * clouds (height 1) give { points, count, intensity? } in message order. A 'ring' field, when present, is returned
 * per point as rings (Int32Array, same order as points). Both carry stamp and frameId. O(width * height).
 */
export function fromPointCloud2(msg) {
  const fn = 'fromPointCloud2';
  if (!isObject(msg)) throw new TypeError(`${fn}: msg must be a PointCloud2 message object, got ${describe(msg)}`);
  const height = count(fn, msg, 'height');
  const width = count(fn, msg, 'width');
  const pointStep = count(fn, msg, 'point_step');
  const rowStep = count(fn, msg, 'row_step');
  const big = msg.is_bigendian;
  if (big !== undefined && typeof big !== 'boolean') throw new TypeError(`${fn}: is_bigendian must be a boolean, got ${describe(big)}`);
  const data = bytesOf(fn, msg.data);
  const fields = fieldsOf(fn, msg.fields, pointStep);
  for (const axis of ['x', 'y', 'z']) {
    const f = fields.get(axis);
    if (f === undefined) throw new RangeError(`${fn}: the cloud has no '${axis}' field (fields: ${[...fields.keys()].join(', ') || 'none'})`);
    if (f.datatype !== 7 && f.datatype !== 8)
      throw new RangeError(`${fn}: field '${axis}' must be FLOAT32 (7) or FLOAT64 (8), got datatype ${f.datatype}`);
  }
  const n = width * height;
  if (n > 0) {
    if (rowStep < width * pointStep) throw new RangeError(`${fn}: row_step ${rowStep} is less than width * point_step = ${width * pointStep}`);
    const need = (height - 1) * rowStep + width * pointStep;
    if (data.byteLength < need) throw new RangeError(`${fn}: data has ${data.byteLength} bytes, the cloud needs ${need} (height ${height}, row_step ${rowStep}, width ${width}, point_step ${pointStep})`);
  }
  if (n > 2 ** 28) throw new RangeError(`${fn}: ${n} points are more than ${2 ** 28}`);
  if (msg.header !== undefined && !isObject(msg.header)) throw new TypeError(`${fn}: header must be an object, got ${describe(msg.header)}`);
  const stamp = stampOf(fn, 'header.stamp', msg.header?.stamp);
  const frameId = frameOf(fn, 'header.frame_id', msg.header?.frame_id);

  const view = new DataView(data.buffer, data.byteOffset, data.byteLength);
  const le = !big;
  const fx = fields.get('x'), fy = fields.get('y'), fz = fields.get('z');
  const fi = fields.get('intensity'), fr = fields.get('ring');
  const organised = height > 1;
  const points = new Float64Array(3 * n);
  const intensity = fi || organised ? new Float32Array(n) : undefined;
  const rings = fr ? new Int32Array(n) : undefined;
  for (let r = 0; r < height; r++) {
    for (let c = 0; c < width; c++) {
      const at = r * rowStep + c * pointStep;
      const k = organised ? c * height + r : c;   // column-major for organised clouds
      const x = view[fx.get](at + fx.offset, le), y = view[fy.get](at + fy.offset, le), z = view[fz.get](at + fz.offset, le);
      if (Number.isFinite(x) && Number.isFinite(y) && Number.isFinite(z) && (x !== 0 || y !== 0 || z !== 0)) {
        points[3 * k] = x; points[3 * k + 1] = y; points[3 * k + 2] = z;
      } else {
        points[3 * k] = NaN; points[3 * k + 1] = NaN; points[3 * k + 2] = NaN;
      }
      if (intensity) intensity[k] = fi ? view[fi.get](at + fi.offset, le) : NaN;
      if (rings) rings[k] = view[fr.get](at + fr.offset, le);
    }
  }
  if (!organised) {
    const out = { points, count: n, stamp, frameId };
    if (intensity) out.intensity = intensity;
    if (rings) out.rings = rings;
    return out;
  }
  const beams = height, columns = width;
  const cloud = {
    beams, columns, points, intensity, stamp, frameId,
    ring(b) {
      if (typeof b !== 'number') throw new TypeError(`ring: beam must be a number, got ${describe(b)}`);
      if (!Number.isInteger(b) || b < 0 || b >= beams) throw new RangeError(`ring: beam must be an integer in [0, ${beams - 1}], got ${b}`);
      const out = new Float64Array(3 * columns);
      for (let c = 0; c < columns; c++) out.set(points.subarray(3 * (c * beams + b), 3 * (c * beams + b) + 3), 3 * c);
      return out;
    },
    column(c) {
      if (typeof c !== 'number') throw new TypeError(`column: c must be a number, got ${describe(c)}`);
      if (!Number.isInteger(c) || c < 0 || c >= columns) throw new RangeError(`column: c must be an integer in [0, ${columns - 1}], got ${c}`);
      return points.slice(3 * c * beams, 3 * (c + 1) * beams);
    },
  };
  if (rings) cloud.rings = rings;
  return cloud;
}
