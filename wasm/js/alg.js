// assign (Munkres / Hungarian assignment) and KalmanFilter: argument checks and typed arrays only; the algorithms
// are the C++ core's (rtl/alg/munkres/Assignment.h, rtl/alg/kalman/KalmanX.h via wasm/src/alg.cpp).
import { boolOption, check, num, options, toF64 } from './checks.js';
import { CppObject, HANDLE } from './owned.js';

/** assign and the KalmanFilter class of one package instance: ctx.extras(fn) gives the extras module's {m, withHeap,
 *  registry} (modules.js; see owned.js), or throws when it is not loaded. */
export function algorithmsApi({ extras }) {
  // A cost matrix as [row-major Float64Array, rows, cols]: an array of equal-length rows (rows/cols inferred,
  // given ones must agree), or a flat array / typed array with options rows and cols.
  function costMatrix(costs, o, fn) {
    const given = (k) => (o[k] === undefined ? undefined : num(o, k, fn, 0, { min: 0, integer: true, max: 2 ** 32 - 1 }));
    let rows = given('rows'), cols = given('cols');
    let flat;
    if (Array.isArray(costs) && costs.length > 0 && typeof costs[0] === 'object' && costs[0] !== null) {
      const c0 = costs[0].length;
      if (rows !== undefined && rows !== costs.length) throw new RangeError(`${fn}: option rows is ${rows}, costs has ${costs.length} rows`);
      if (cols !== undefined && cols !== c0) throw new RangeError(`${fn}: option cols is ${cols}, costs[0] has ${c0} entries`);
      rows = costs.length;
      cols = c0;
      flat = new Float64Array(rows * cols);
      costs.forEach((row, i) => {
        const r = toF64(row, fn, `costs[${i}]`);
        if (r.length !== cols) throw new RangeError(`${fn}: costs[${i}] has ${r.length} entries, costs[0] has ${cols} (rows must have equal length)`);
        flat.set(r, i * cols);
      });
    } else {
      flat = toF64(costs, fn, 'costs');
      if (rows === undefined && cols === undefined) {
        const s = Math.round(Math.sqrt(flat.length));
        if (s * s !== flat.length) throw new TypeError(`${fn}: options rows and cols are required for a flat cost array of ${flat.length} numbers (not a square)`);
        rows = cols = s;
      } else if (rows === undefined) {
        if (cols === 0 || flat.length % cols) throw new RangeError(`${fn}: ${flat.length} costs do not fill rows of ${cols} columns`);
        rows = flat.length / cols;
      } else if (cols === undefined) {
        if (rows === 0 || flat.length % rows) throw new RangeError(`${fn}: ${flat.length} costs do not fill ${rows} rows`);
        cols = flat.length / rows;
      }
      if (rows * cols !== flat.length) throw new RangeError(`${fn}: costs has ${flat.length} numbers, a ${rows} x ${cols} matrix needs ${rows * cols}`);
    }
    for (let k = 0; k < flat.length; k++) {
      if (!Number.isFinite(flat[k])) throw new RangeError(`${fn}: the cost at row ${Math.floor(k / cols)}, column ${k % cols} is ${flat[k]}, expected a finite number`);
    }
    return [flat, rows, cols];
  }

  // Optimal assignment of rows to distinct columns (min(rows, cols) pairs) with the least (or, maximize, greatest)
  // total cost; columns[i] = -1 for the rows left out when rows > cols.
  function assign(costs, opts) {
    const fn = 'assign';
    const { m, withHeap, boundary } = extras(fn);
    const o = options(opts, fn, ['rows', 'cols', 'maximize']);
    const maximize = boolOption(o, 'maximize', fn, false);
    const [flat, rows, cols] = costMatrix(costs, o, fn);
    return withHeap(fn, [flat], (p, n) => m.assign(p, n, boundary.call('assign').writeOptions({ rows, cols, maximize })));
  }

  class KalmanFilter extends CppObject {
    #n; #m; #c; #x;
    constructor(opts) {
      const fn = 'KalmanFilter';
      const x = extras(fn), { m } = x;
      if (opts === undefined) throw new TypeError(`${fn}: options {stateDim, measurementDim} are required`);
      const o = options(opts, fn, ['stateDim', 'measurementDim', 'controlDim', 'processNoise', 'observationNoise']);
      for (const k of ['stateDim', 'measurementDim']) if (o[k] === undefined) throw new TypeError(`${fn}: option ${k} is required`);
      const n = num(o, 'stateDim', fn, 0, { min: 1, integer: true, max: 4096 });
      const md = num(o, 'measurementDim', fn, 0, { min: 1, integer: true, max: 4096 });
      const c = num(o, 'controlDim', fn, 0, { min: 0, integer: true, max: 4096 });
      const q = num(o, 'processNoise', fn, 1);
      const r = num(o, 'observationNoise', fn, 1);
      const created = { stateDim: n, measurementDim: md, controlDim: c, processNoise: q, observationNoise: r };
      super(check(m.kalmanCreate(x.boundary.call('kalmanCreate').writeOptions(created)), fn), (h) => m.kalmanDestroy(h), x.registry, fn, 'filter');
      this.#x = x;
      this.#n = n;
      this.#m = md;
      this.#c = c;
    }
    get stateDim() { return this.#n; }
    get measurementDim() { return this.#m; }
    get controlDim() { return this.#c; }
    // Row-major values of matrix `which` (0 x, 1 A, 2 B, 3 P, 4 H, 5 Q, 6 R; see wasm/src/alg.cpp), rows x cols, finite.
    #set(method, which, rows, cols, v) {
      const fn = `KalmanFilter.${method}`;
      const h = this[HANDLE](method);
      const a = toF64(v, fn, 'values');
      if (a.length !== rows * cols)
        throw new RangeError(`${fn}: expected ${rows * cols} numbers (${rows} x ${cols}${cols > 1 ? ', row-major' : ''}), got ${a.length}`);
      for (let i = 0; i < a.length; i++) if (!Number.isFinite(a[i])) throw new RangeError(`${fn}: values[${i}] is ${a[i]}, expected a finite number`);
      const { m, withHeap } = this.#x;
      withHeap(fn, [a], (p, n) => m.kalmanSet(h, which, p, n));
    }
    setState(x) { this.#set('setState', 0, this.#n, 1, x); }
    setTransitionMatrix(A) { this.#set('setTransitionMatrix', 1, this.#n, this.#n, A); }
    setControlMatrix(B) { this.#set('setControlMatrix', 2, this.#n, this.#c, B); }
    setCovarianceMatrix(P) { this.#set('setCovarianceMatrix', 3, this.#n, this.#n, P); }
    setMeasurementMatrix(H) { this.#set('setMeasurementMatrix', 4, this.#m, this.#n, H); }
    setProcessNoiseCovariance(Q) { this.#set('setProcessNoiseCovariance', 5, this.#n, this.#n, Q); }
    setMeasurementNoiseCovariance(R) { this.#set('setMeasurementNoiseCovariance', 6, this.#m, this.#m, R); }
    #vector(fn, v, len, what) {
      const a = toF64(v, fn, what);
      if (a.length !== len) throw new RangeError(`${fn}: ${what} must have ${len} numbers, got ${a.length}`);
      for (let i = 0; i < len; i++) if (!Number.isFinite(a[i])) throw new RangeError(`${fn}: ${what}[${i}] is ${a[i]}, expected a finite number`);
      return a;
    }
    // x = A x + B u, P = A P A^T + Q; the control u defaults to zeros.
    predict(control) {
      const fn = 'KalmanFilter.predict';
      const h = this[HANDLE]('predict');
      const u = control === undefined ? new Float64Array(this.#c) : this.#vector(fn, control, this.#c, 'control');
      const { m, withHeap } = this.#x;
      withHeap(fn, [u], (p, n) => m.kalmanPredict(h, p, n));
    }
    // The correction with measurement z through H and R (Joseph form).
    correct(measurement) {
      const fn = 'KalmanFilter.correct';
      const h = this[HANDLE]('correct');
      if (measurement === undefined) throw new TypeError(`${fn}: measurement is required`);
      const z = this.#vector(fn, measurement, this.#m, 'measurement');
      const { m, withHeap } = this.#x;
      withHeap(fn, [z], (p, n) => m.kalmanCorrect(h, p, n));
    }
    state() { return this.#x.m.kalmanState(this[HANDLE]('state')); }
    covariance() { return this.#x.m.kalmanCovariance(this[HANDLE]('covariance')); }
  }
  return { assign, KalmanFilter };
}
