// The package's JavaScript layer over the embind module, assembled from one module per concern: argument checks
// (TypeError for a wrong kind of value, RangeError for a bad value, both naming the function and argument), typed
// arrays in and out, and no C++ object ever handed to the caller except the stateful classes, which free
// themselves (dispose / FinalizationRegistry). wasm/build.mjs bundles this entry with esbuild into dist/api.mjs
// (ES module) and dist/api.cjs (CommonJS); the entries index.mjs, index.node.mjs and index.cjs call start().
// The package is two Emscripten modules (docs/package-modules.md): the core, started by init(), and the extras
// (drawing writers, readPcd, assign, KalmanFilter), started by load('extras') (modules.js) or, in Node, by init().
import { describe } from './checks.js';
import { heapOf } from './heap.js';
import { boundaryOf } from './schema.js';
import { fitLineApi } from './fitline.js';
import { segmentApi } from './segment.js';
import { vectorizeApi } from './vectorize.js';
import { pipelineApi } from './pipeline.js';
import { streamApi } from './stream.js';
import { tfTreeApi } from './tftree.js';
import { drawingApi } from './draw.js';
import { algorithmsApi } from './alg.js';
import { readersApi } from './readers.js';
import { pcdApi } from './pcd.js';
import { moduleNames, onDemandModules, startModule } from './modules.js';
import { simplifyApi } from './simplify.js';
import { polylinesApi } from './polylines.js';
import { fromLaserScan, fromPointCloud2 } from './ros/messages.js';

export { palette, unlabelledColour } from './palette.js';
export { defaults } from './defaults.js';

/** The package's version, written in by wasm/build.mjs. */
const VERSION = '__RTL_VERSION__';

/** @typedef {import('./index.js').RTL} RTL */

// Each instance's module loader, for init({load}) (its errors start with "init:").
const loaders = new WeakMap();

/**
 * The package's API on one started core module m, with the modules loaded on demand (onDemand: {parts, locateFile},
 * see start() and modules.js). tsc checks the object against index.d.ts's RTL
 * (tests/js/types.test.mjs); lastComputeMs, a getter added below, is the one member the literal leaves out.
 * @returns {RTL}
 */
function wrap(m, onDemand) {
  let lastComputeMs = NaN;  // time spent in the C++ library by the last segment()/vectorize()/simplify() call
  // Stateful objects own a C++ object behind an integer handle: dispose() frees it, and if the caller forgets,
  // the FinalizationRegistry frees it after the wrapper is garbage collected (the held value does not reference
  // the wrapper, so it does not keep it alive).
  const registry = typeof FinalizationRegistry === 'function' ? new FinalizationRegistry((free) => free()) : null;
  const heap = heapOf(m);
  // What the functions of this instance share: the module, its memory functions, the calls' options and results by
  // name (schema.js), the registry and the timing.
  // extras(fn): the extras module's {m, withHeap, boundary, registry}, or an Error naming fn and the call that loads it.
  const { extras, load, modules } = onDemandModules(m, onDemand, registry);
  const ctx = { m, ...heap, boundary: boundaryOf(m), registry, extras, setComputeMs: (ms) => { lastComputeMs = ms; } };
  const { release } = heap;
  // A diagnostic of one module ('core', 'extras') or, without a name, the sum over the loaded ones (equal figures
  // before and after calls still mean no leak in any of them).
  const each = (fn, which, read) => {
    if (which !== undefined) return read(modules(fn, which));
    let sum = read(m);
    for (const x of modules(fn)) sum += read(x);
    return sum;
  };
  /** @type {Omit<RTL, 'lastComputeMs'>} */
  const api = {
    version: VERSION,
    ...fitLineApi(ctx),
    ...segmentApi(ctx),
    ...vectorizeApi(ctx),
    ...pipelineApi(ctx),
    ...streamApi(ctx),
    ...tfTreeApi(ctx),
    ...drawingApi(ctx),
    ...algorithmsApi(ctx),
    ...readersApi(ctx),
    ...pcdApi(ctx),
    ...simplifyApi(ctx),
    ...polylinesApi(ctx),
    // The ROS message adapters (pure JS, also the subpath export rtl-wasm/ros).
    fromLaserScan,
    fromPointCloud2,
    // Frees the input buffer, vectorizers and segmenters kept between calls (they grow back on the next call).
    // Also pointBuffer()'s block: its views must not be used afterwards.
    releaseBuffers: release,
    // Malloc heap in use once the kept buffers are released: equal figures before and after calls mean no leak.
    heapInUse: (which) => { release(); return each('heapInUse', which, (x) => x.heapInUse()); },
    pointBuffer: heap.pointBuffer,
    memoryBytes: (which) => each('memoryBytes', which, (x) => x.memoryBytes()),
    stackPointer: (which) => each('stackPointer', which, (x) => x.stackPointer()),
    // Starts a module loaded on demand ('extras'); idempotent; resolves to this object (a bad name rejects too).
    load: async (name) => { await load(name); return /** @type {RTL} */ (api); },
  };
  Object.defineProperty(api, 'lastComputeMs', { get: () => lastComputeMs, enumerable: false });
  loaders.set(api, load);
  return /** @type {RTL} */ (api);
}

/**
 * Checks init()'s options and returns them: the ones handed to the Emscripten factory, and load.
 * @returns {{wasmBinary?: any, locateFile?: Function, load?: string[]}}
 */
function initOptions(o) {
  if (o === undefined || o === null) return {};
  if (typeof o !== 'object' || Array.isArray(o)) throw new TypeError(`init: options must be an object, got ${describe(o)}`);
  /** @type {{wasmBinary?: any, locateFile?: Function, load?: string[]}} */
  const out = {};
  for (const k of Object.keys(o)) {
    if (k === 'wasmBinary') {
      const b = o.wasmBinary;
      if (!(b instanceof ArrayBuffer || b instanceof Uint8Array))
        throw new TypeError(`init: wasmBinary must be an ArrayBuffer or a Uint8Array, got ${describe(b)}`);
      out.wasmBinary = b;
    } else if (k === 'load') {
      out.load = moduleNames(o.load, 'init', 'option load');
    } else if (k === 'locateFile') {
      if (typeof o.locateFile !== 'function') throw new TypeError(`init: locateFile must be a function, got ${describe(o.locateFile)}`);
      out.locateFile = o.locateFile;
    } else {
      throw new TypeError(`init: unknown option "${k}" (known: wasmBinary, locateFile, load)`);
    }
  }
  return out;
}

/**
 * Starts the core module and wraps it, the same way for the three entries (Node ESM, CommonJS, browsers). parts:
 * the modules loaded on demand, {extras: {create: () => Promise<factory>, binary?: () => Promise<bytes>, atInit?}}
 * (atInit: started by init() too, as the Node entries do); init({load}) starts the named ones as well.
 * @returns {Promise<RTL>}
 */
export async function start(createModule, options, loadDefaultBinary, parts = {}) {
  const { load = [], ...o } = initOptions(options);
  if (o.wasmBinary !== undefined) {
    const bytes = o.wasmBinary instanceof ArrayBuffer ? new Uint8Array(o.wasmBinary) : o.wasmBinary;
    if (!WebAssembly.validate(bytes)) throw new TypeError(`init: wasmBinary is not a valid WebAssembly module (${bytes.length} bytes)`);
  } else if (loadDefaultBinary) {
    o.wasmBinary = await loadDefaultBinary();
  }
  const module = await startModule(createModule, o, 'fitLine', 'init');
  const api = wrap(module, { parts, locateFile: o.locateFile });
  for (const name of new Set([...load, ...Object.keys(parts).filter((k) => parts[k].atInit)])) await loaders.get(api)(name, 'init');
  return api;
}
