// The package's Emscripten modules: starting one (the core by init(), the others by load()), and the modules loaded
// on demand. 'extras' (rtl-extras.wasm: the TikZ/SVG/LaTeX writers, readPcd, assign, KalmanFilter) is kept out of
// the core so that what a browser loads first stays small (docs/package-modules.md). Its functions are the API's
// like any other (rtl.toSvg, ...): they only need the module started first, which the Node entries do in init().
import { describe } from './checks.js';
import { heapOf } from './heap.js';
import { boundaryOf } from './schema.js';

/** The modules load() knows, each with a binding it must have (a sign that the right .wasm came). */
const ON_DEMAND = { extras: 'drawScan2D' };

/**
 * Starts an Emscripten module with options o. It gets its own print/printErr/onAbort, so that a failed start prints
 * nothing (Emscripten would print "Aborted(...)" to stderr) and becomes an ErrorType whose message starts with
 * `what`; after a successful start they forward to the console.
 */
export async function startModule(createModule, o, binding, what, ErrorType = TypeError) {
  let started = false, reason = null;
  const say = (log) => (...a) => { if (started) log(...a); else reason ??= a.join(' '); };
  const opts = { ...o, print: say((...a) => console.log(...a)), printErr: say((...a) => console.error(...a)),
    onAbort: (/** @type {any} */ x) => { if (!started) reason ??= String(x); } };
  let module;
  try {
    module = await createModule(opts);
    if (typeof module[binding] !== 'function') throw new Error('the module has no rtl-wasm bindings');
  } catch (e) {
    throw new ErrorType(`${what}: the WebAssembly module could not be started: ${reason ?? (e && e.message) ?? e}`);
  }
  started = true;
  return module;
}

function moduleName(n, fn, what, core = false) {
  if (typeof n !== 'string') throw new TypeError(`${fn}: ${what} must be a module name (a string), got ${describe(n)}`);
  if (!(n in ON_DEMAND) && !(core && n === 'core'))
    throw new RangeError(`${fn}: ${what} "${n}" is not a module of the package (known: ${core ? 'core, ' : ''}${Object.keys(ON_DEMAND).join(', ')})`);
  return n;
}

/** init()'s option load: an array of module names. */
export function moduleNames(v, fn, what) {
  if (!Array.isArray(v)) throw new TypeError(`${fn}: ${what} must be an array of module names, got ${describe(v)}`);
  return v.map((n, i) => moduleName(n, fn, `${what}[${i}]`));
}

/**
 * The modules of one package instance beside its core module `core`. parts: how this entry gets each one,
 * {name: {create: () => Promise<factory>, binary?: () => Promise<bytes>}}; locateFile: init()'s, passed on.
 *   extras(fn): the started extras module's {m, withHeap, boundary, registry}, or an Error that starts with fn and
 *     says what to call;
 *   load(name, what): starts the module once (later calls get the same promise; a failed start may be retried);
 *   modules(fn, which): the Emscripten module named `which` ('core' or a started one), or without a name every
 *     started module beside the core.
 */
export function onDemandModules(core, { parts, locateFile }, registry) {
  /** @type {Record<string, {m: any, withHeap: any, boundary: any, registry: any}>} */
  const started = {};
  /** @type {Record<string, Promise<void>>} */
  const pending = {};

  function extras(fn) {
    const x = started.extras;
    if (x) return x;
    throw new Error(`${fn}: this function is in the package's extras module, which is not loaded: ` +
      "call await rtl.load('extras') first (or init({ load: ['extras'] }))");
  }

  async function startPart(name, what) {
    const part = parts[name];
    if (!part) throw new Error(`${what}: this entry of the package has no ${name} module`);
    const o = {};
    if (locateFile) o.locateFile = locateFile;
    if (part.binary) o.wasmBinary = await part.binary();
    const create = await part.create();
    const m = await startModule(create, o, ON_DEMAND[name], what, Error);
    started[name] = { m, withHeap: heapOf(m).withHeap, boundary: boundaryOf(m), registry };
  }

  function load(name, what = 'load') {
    moduleName(name, what, 'name');
    pending[name] ??= startPart(name, what).catch((e) => { delete pending[name]; throw e; });
    return pending[name];
  }

  function modules(fn, which) {
    if (which === undefined) return Object.values(started).map((x) => x.m);
    moduleName(which, fn, 'module', true);
    if (which === 'core') return core;
    if (!started[which]) throw new Error(`${fn}: the ${which} module is not loaded (rtl.load('${which}'))`);
    return started[which].m;
  }

  return { extras, load, modules };
}
