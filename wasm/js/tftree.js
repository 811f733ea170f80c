// TfTree: a tree of named coordinate frames (rtl::TfTree, wasm/src/tftree.cpp), a stateful object that owns a C++
// tree behind an integer handle.
import { check, describe, dimOption, num, options, toF64, vector } from './checks.js';
import { CppObject, HANDLE } from './owned.js';

function frameName(v, fn, what) {
  if (typeof v !== 'string') throw new TypeError(`${fn}: ${what} must be a string, got ${describe(v)}`);
  if (v.length === 0) throw new RangeError(`${fn}: ${what} must not be empty`);
  return v;
}

// A transformation {angle, translation} (2D) or {quaternion | angle + axis, translation} (3D) -> the options of
// m.tfInsert: {rotation: [angle, 0, 0, 0] (2D) or a unit quaternion [w, x, y, z] (3D), translation: [x, y, z]}
// (z 0 in 2D).
function rigid(tf, fn, dim) {
  if (tf === null || typeof tf !== 'object' || Array.isArray(tf) || ArrayBuffer.isView(tf))
    throw new TypeError(`${fn}: the transformation must be an object, got ${describe(tf)}`);
  const known = dim === 2 ? ['angle', 'translation'] : ['quaternion', 'angle', 'axis', 'translation'];
  const o = options(tf, fn, known);
  const t = o.translation === undefined ? new Float64Array(dim) : vector(o.translation, fn, 'translation', dim);
  if (dim === 2) return { rotation: [num(o, 'angle', fn, 0), 0, 0, 0], translation: [t[0], t[1], 0] };
  let q;
  if (o.quaternion !== undefined) {
    if (o.angle !== undefined || o.axis !== undefined) throw new TypeError(`${fn}: give either quaternion or angle + axis, not both`);
    q = Array.from(vector(o.quaternion, fn, 'quaternion', 4));
  } else if (o.angle !== undefined || o.axis !== undefined) {
    const angle = num(o, 'angle', fn, 0);
    if (o.axis === undefined) throw new TypeError(`${fn}: angle needs an axis in 3D`);
    const axis = vector(o.axis, fn, 'axis', 3);
    const len = Math.hypot(axis[0], axis[1], axis[2]);
    if (!(len > 0)) throw new RangeError(`${fn}: axis must not be the zero vector`);
    const s = Math.sin(angle / 2) / len;
    q = [Math.cos(angle / 2), axis[0] * s, axis[1] * s, axis[2] * s];
  } else {
    q = [1, 0, 0, 0];
  }
  const qn = Math.hypot(...q);
  if (!(qn > 0)) throw new RangeError(`${fn}: quaternion must not be zero`);
  return { rotation: [q[0] / qn, q[1] / qn, q[2] / qn, q[3] / qn], translation: [t[0], t[1], t[2]] };
}

/** The TfTree class of one module instance: ctx = {m, withHeap, boundary, registry} (api.js; see owned.js). */
export function tfTreeApi({ m, withHeap, boundary, registry }) {
  // The options of m.tfCreate and m.tfInsert by name, as wasm/src/tftree.cpp declares them (schema.js).
  const createCall = boundary.call('tfCreate'), insertCall = boundary.call('tfInsert');
  class TfTree extends CppObject {
    #dim;
    constructor(root, opts) {
      const fn = 'TfTree';
      frameName(root, fn, 'root');
      const o = options(opts, fn, ['dim']);
      const dim = dimOption(o, fn);
      super(check(m.tfCreate(root, createCall.writeOptions({ dim })), fn), (h) => m.tfDestroy(h), registry, fn, 'tree');
      this.#dim = dim;
    }
    get dim() { return this.#dim; }
    get size() { return m.tfSize(this[HANDLE]('size')); }
    insert(name, parent, tf) {
      const fn = 'TfTree.insert';
      const h = this[HANDLE]('insert');
      frameName(name, fn, 'name');
      frameName(parent, fn, 'parent');
      return check(m.tfInsert(h, name, parent, insertCall.writeOptions(rigid(tf, fn, this.#dim))), fn);
    }
    erase(name) { return m.tfErase(this[HANDLE]('erase'), frameName(name, 'TfTree.erase', 'name')); }
    contains(name) { return m.tfContains(this[HANDLE]('contains'), frameName(name, 'TfTree.contains', 'name')); }
    tf(from, to) {
      const fn = 'TfTree.tf';
      const h = this[HANDLE]('tf');
      return check(m.tfGet(h, frameName(from, fn, 'from'), frameName(to, fn, 'to')), fn);
    }
    transformPoints(from, to, points) {
      const fn = 'TfTree.transformPoints';
      const h = this[HANDLE]('transformPoints');
      frameName(from, fn, 'from');
      frameName(to, fn, 'to');
      const xyz = toF64(points, fn, 'points');
      return withHeap(fn, [xyz], (p, n) => m.tfApply(h, from, to, p, n));
    }
  }
  return { TfTree };
}
