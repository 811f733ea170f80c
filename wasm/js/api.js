// The package's JavaScript layer over the embind module, assembled from one module per concern: argument checks
// (TypeError for a wrong kind of value, RangeError for a bad value, both naming the function and argument), typed
// arrays in and out, and no C++ object ever handed to the caller except the stateful classes, which free
// themselves (dispose / FinalizationRegistry). wasm/build.mjs bundles this entry with esbuild into dist/api.mjs
// (ES module) and dist/api.cjs (CommonJS); the entries index.mjs, index.node.mjs and index.cjs call start().
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
import { simplifyApi } from './simplify.js';
import { polylinesApi } from './polylines.js';
import { fromLaserScan, fromPointCloud2 } from './ros/messages.js';

export { palette, unlabelledColour } from './palette.js';
export { defaults } from './defaults.js';

/** The package's version, written in by wasm/build.mjs. */
const VERSION = '__RTL_VERSION__';

/** @typedef {import('./index.js').RTL} RTL */

/**
 * The package's API on one started Emscripten module m. tsc checks the object against index.d.ts's RTL
 * (tests/js/types.test.mjs); lastComputeMs, a getter added below, is the one member the literal leaves out.
 * @returns {RTL}
 */
function wrap(m) {
  let lastComputeMs = NaN;  // time spent in the C++ library by the last segment()/vectorize()/simplify() call
  // Stateful objects own a C++ object behind an integer handle: dispose() frees it, and if the caller forgets,
  // the FinalizationRegistry frees it after the wrapper is garbage collected (the held value does not reference
  // the wrapper, so it does not keep it alive).
  const registry = typeof FinalizationRegistry === 'function' ? new FinalizationRegistry((free) => free()) : null;
  const heap = heapOf(m);
  // What the functions of this instance share: the module, its memory functions, the calls' options and results by
  // name (schema.js), the registry and the timing.
  const ctx = { m, ...heap, boundary: boundaryOf(m), registry, setComputeMs: (ms) => { lastComputeMs = ms; } };
  const { release } = heap;
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
    ...simplifyApi(ctx),
    ...polylinesApi(ctx),
    // The ROS message adapters (pure JS, also the subpath export rtl-wasm/ros).
    fromLaserScan,
    fromPointCloud2,
    // Frees the input buffer, vectorizers and segmenters kept between calls (they grow back on the next call).
    // Also pointBuffer()'s block: its views must not be used afterwards.
    releaseBuffers: release,
    // Malloc heap in use once the kept buffers are released: equal figures before and after calls mean no leak.
    heapInUse: () => { release(); return m.heapInUse(); },
    pointBuffer: heap.pointBuffer,
    memoryBytes: () => m.memoryBytes(),
    stackPointer: () => m.stackPointer(),
  };
  Object.defineProperty(api, 'lastComputeMs', { get: () => lastComputeMs, enumerable: false });
  return /** @type {RTL} */ (api);
}

// Checks init()'s options and returns the ones handed to the Emscripten factory.
function initOptions(o) {
  if (o === undefined || o === null) return {};
  if (typeof o !== 'object' || Array.isArray(o)) throw new TypeError(`init: options must be an object, got ${describe(o)}`);
  const out = {};
  for (const k of Object.keys(o)) {
    if (k === 'wasmBinary') {
      const b = o.wasmBinary;
      if (!(b instanceof ArrayBuffer || b instanceof Uint8Array))
        throw new TypeError(`init: wasmBinary must be an ArrayBuffer or a Uint8Array, got ${describe(b)}`);
      out.wasmBinary = b;
    } else if (k === 'locateFile') {
      if (typeof o.locateFile !== 'function') throw new TypeError(`init: locateFile must be a function, got ${describe(o.locateFile)}`);
      out.locateFile = o.locateFile;
    } else {
      throw new TypeError(`init: unknown option "${k}" (known: wasmBinary, locateFile)`);
    }
  }
  return out;
}

/**
 * Starts the Emscripten module and wraps it, the same way for the three entries (Node ESM, CommonJS, browsers).
 * The module gets its own print/printErr/onAbort, so that a failed start prints nothing (Emscripten would print
 * "Aborted(...)" to stderr) and becomes the package's TypeError; after a successful start they forward to the console.
 * @returns {Promise<RTL>}
 */
export async function start(createModule, options, loadDefaultBinary) {
  const o = initOptions(options);
  if (o.wasmBinary !== undefined) {
    const bytes = o.wasmBinary instanceof ArrayBuffer ? new Uint8Array(o.wasmBinary) : o.wasmBinary;
    if (!WebAssembly.validate(bytes)) throw new TypeError(`init: wasmBinary is not a valid WebAssembly module (${bytes.length} bytes)`);
  } else if (loadDefaultBinary) {
    o.wasmBinary = await loadDefaultBinary();
  }
  let started = false, reason = null;
  const say = (log) => (...a) => { if (started) log(...a); else reason ??= a.join(' '); };
  o.print = say((...a) => console.log(...a));
  o.printErr = say((...a) => console.error(...a));
  o.onAbort = (what) => { if (!started) reason ??= String(what); };
  let module;
  try {
    module = await createModule(o);
    if (typeof module.fitLine !== 'function') throw new Error('the module has no rtl-wasm bindings');
  } catch (e) {
    throw new TypeError(`init: the WebAssembly module could not be started: ${reason ?? (e && e.message) ?? e}`);
  }
  started = true;
  return wrap(module);
}
