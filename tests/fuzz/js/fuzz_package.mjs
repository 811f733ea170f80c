// Fuzzes the package's exported functions and classes under Node: random arguments of random types and sizes.
// The contract (README, "Bad input"): a call either returns or throws a TypeError/RangeError whose message starts
// with the name of what was called ("segment: ...", "StreamSegmenter.addPoints: ..."); afterwards the wasm heap is
// back where it started, the wasm stack pointer has not moved, and the module still gives the same answers.
//   node tests/fuzz/js/fuzz_package.mjs [--seconds N] [--iterations N] [--seed S]
// The test command runs a fixed number of iterations with a fixed seed (tests/js/fuzz-package.test.mjs); a longer
// session is `node tests/fuzz/js/fuzz_package.mjs --seconds 600`. A finding prints the call and exits 1.
import { readFileSync, readdirSync } from 'node:fs';
import { fileURLToPath } from 'node:url';
import init from 'rtl-wasm';

// Deterministic generator (mulberry32), so that a finding can be replayed with its seed.
function generator(seed) {
  let s = seed >>> 0;
  const next = () => {
    s = (s + 0x6d2b79f5) >>> 0;
    let t = s;
    t = Math.imul(t ^ (t >>> 15), t | 1);
    t ^= t + Math.imul(t ^ (t >>> 7), t | 61);
    return ((t ^ (t >>> 14)) >>> 0) / 4294967296;
  };
  const int = (n) => Math.floor(next() * n);
  const pick = (a) => a[int(a.length)];
  return { next, int, pick };
}

// The option names the package checks, read from its own argument checks (`options(opts, fn, ['dim', ...])`), so
// that the fuzzer reaches options added later without being told.
function knownOptionNames() {
  const dist = fileURLToPath(new URL('../../../dist/', import.meta.url));
  const names = new Set(['dim', 'step', 'method', 'trace', 'split', 'width', 'height', 'rows', 'cols', 'maximize']);
  for (const f of readdirSync(dist).filter((f) => f.endsWith('.mjs') && !f.startsWith('rtl'))) {
    const src = readFileSync(dist + f, 'utf8');
    for (const m of src.matchAll(/options\([^,()]+,\s*[^,()]+,\s*\[([^\]]*)\]/g))
      for (const n of m[1].matchAll(/'([A-Za-z0-9_]+)'/g)) names.add(n[1]);
  }
  return [...names];
}

const SPECIAL_NUMBERS = [0, -0, 1, -1, 2, 3, 0.5, 1e-300, -1e-300, 1e18, -1e18, 1e300, 2 ** 31, 2 ** 32, 2 ** 53,
  -(2 ** 31), NaN, Infinity, -Infinity, Number.MAX_VALUE, Number.MIN_VALUE, 0.1, 10, 100, 1000, 65536];
const STRINGS = ['', 'x', 'ftls', 'aftls', 'itls', 'dp', 'rw', 'segment', 'line', 'column-major', 'row-major',
  'map', 'base', 'laser', '\u0000', '{}\\&%$#_^~', 'FLASER 3 1 1 1 0 0 0 0 0 0 1 h 1\n', 'PARAM laser_max_range 8\n'];

function randomValue(g, names, depth = 0) {
  const kind = g.int(depth > 1 ? 9 : 13);
  switch (kind) {
    case 0: return undefined;
    case 1: return null;
    case 2: return g.pick(SPECIAL_NUMBERS);
    case 3: return (g.next() - 0.5) * 10 ** g.int(8);
    case 4: return g.pick(STRINGS);
    case 5: return g.next() < 0.5;
    case 6: return randomTypedArray(g);
    case 7: return g.pick([Symbol('s'), 1n, () => 1, new Date(0), /re/]);
    case 8: return Array.from({ length: g.int(12) }, () => g.pick(SPECIAL_NUMBERS.concat([g.next() * 4])));
    case 9: return randomOptions(g, names, depth + 1);
    case 10: return Array.from({ length: g.int(5) }, () => randomValue(g, names, depth + 1));
    case 11: return new ArrayBuffer(g.int(64));
    default: return Array.from({ length: 1 + g.int(4) }, () => Array.from({ length: 1 + g.int(4) }, () => g.next() * 10));
  }
}

function randomTypedArray(g) {
  const n = g.pick([0, 1, 2, 3, 4, 5, 6, 7, 9, 12, 30, 64, 301, 1000, 2001]);
  const Type = g.pick([Float64Array, Float64Array, Float32Array, Int32Array, Uint8Array, Uint16Array]);
  const a = new Type(n);
  const style = g.int(5);
  for (let i = 0; i < n; ++i) {
    if (style === 0) a[i] = g.next() * 20 - 10;                                  // scattered
    else if (style === 1) a[i] = i % 2 ? Math.sin(i / 40) * 5 : i / 40;          // a smooth curve
    else if (style === 2) a[i] = Math.round(g.next() * 3);                      // many duplicates
    else if (style === 3) a[i] = g.pick(SPECIAL_NUMBERS);
    else a[i] = (i % 2 ? 1 : 0) + 1e-9 * g.next();                              // nearly collinear
  }
  return a;
}

function randomOptions(g, names, depth) {
  const o = {};
  for (let k = g.int(5); k > 0; --k) o[g.next() < 0.9 ? g.pick(names) : 'bogus'] = randomValue(g, names, depth + 1);
  return o;
}

class Finding extends Error {}

// True when `e` is an error the contract allows for a call named `name` ("segment", "TfTree.tf"): its message
// starts with that name, or with the class name for a constructor's checks; a method of a returned plain object
// (e.g. an organised cloud's column()) may name just itself (`alias`).
function allowed(e, name, alias) {
  if (!(e instanceof TypeError || e instanceof RangeError)) return false;
  return [name, alias].some((n) => n && (e.message.startsWith(n + ':') || e.message.startsWith(n + ' ')));
}

function describeCall(name, args) {
  const show = (v) => {
    if (ArrayBuffer.isView(v)) return `${v.constructor.name}(${v.length})`;
    if (typeof v === 'bigint' || typeof v === 'symbol' || typeof v === 'function') return String(v);
    try { return JSON.stringify(v, (k, x) => (ArrayBuffer.isView(x) ? `${x.constructor.name}(${x.length})` : typeof x === 'number' && !Number.isFinite(x) ? String(x) : x)); } catch { return String(v); }
  };
  return `${name}(${args.map(show).join(', ')})`;
}

function attempt(name, f, args, alias) {
  try {
    return { value: f(...args) };
  } catch (e) {
    if (!allowed(e, name, alias)) throw new Finding(`${describeCall(name, args)} threw ${e && e.constructor && e.constructor.name}: ${e && e.message}`);
    return { error: e };
  }
}

// A call whose answer must not change however the fuzzing went.
function fingerprint(rtl) {
  const pts = new Float64Array(200);
  for (let i = 0; i < 100; ++i) { pts[2 * i] = i * 0.05; pts[2 * i + 1] = i < 50 ? 0 : (i - 50) * 0.05; }
  const s = rtl.segment(pts);
  const v = rtl.vectorize(pts, { method: 'dp', epsilon: 0.01 });
  return JSON.stringify([s.clusters.length, Array.from(s.labels ?? []).slice(0, 5), v.segments?.length ?? v.polylines?.length]);
}

export async function fuzzPackage({ seed = 1, iterations = Infinity, seconds = Infinity, log = () => {} } = {}) {
  const rtl = await init();
  const g = generator(seed);
  const names = knownOptionNames();
  const functions = Object.keys(rtl).filter((k) => typeof rtl[k] === 'function' && !/^[A-Z]/.test(k) &&
    !['heapInUse', 'memoryBytes', 'stackPointer'].includes(k));
  const classes = Object.keys(rtl).filter((k) => typeof rtl[k] === 'function' && /^[A-Z]/.test(k));
  // The first calls may allocate what the module keeps for later calls; the baseline is taken after them.
  // Buffers the module keeps between calls are handed back first (releaseBuffers), so that they do not count.
  const release = () => rtl.releaseBuffers?.();
  const answer = fingerprint(rtl);
  release();
  const before = { heap: rtl.heapInUse(), sp: rtl.stackPointer(), answer };
  const deadline = Date.now() + seconds * 1000;
  const calls = {};
  let i = 0;
  for (; i < iterations && Date.now() < deadline; ++i) {
    const useClass = classes.length && g.next() < 0.3;
    const args = Array.from({ length: g.int(4) }, () => randomValue(g, names));
    if (!useClass) {
      const name = g.pick(functions);
      calls[name] = (calls[name] ?? 0) + 1;
      // An alias (readCarmen = readCarmenLog) reports under the function's own name.
      const own = functions.find((k) => rtl[k] === rtl[name]);
      const r = attempt(name, rtl[name], args, own);
      // An async call (load) rejects instead of throwing: its rejection obeys the same rule.
      if (r.value instanceof Promise) {
        await r.value.catch((e) => {
          if (!allowed(e, name, own)) throw new Finding(`${describeCall(name, args)} rejected with ${e && e.constructor && e.constructor.name}: ${e && e.message}`);
        });
        continue;
      }
      // Objects returned with methods (e.g. an organised cloud) get their methods fuzzed too.
      if (r.value && typeof r.value === 'object')
        for (const [k, f] of Object.entries(r.value)) if (typeof f === 'function') attempt(`${name}.${k}`, f.bind(r.value), [randomValue(g, names)], k);
      continue;
    }
    const cls = g.pick(classes);
    calls[cls] = (calls[cls] ?? 0) + 1;
    const made = attempt(cls, (...a) => new rtl[cls](...a), g.next() < 0.5 ? [] : args);
    if (!made.value) continue;
    const obj = made.value;
    const methods = Object.getOwnPropertyNames(Object.getPrototypeOf(obj))
      .filter((k) => k !== 'constructor' && k !== 'dispose' && typeof Object.getOwnPropertyDescriptor(Object.getPrototypeOf(obj), k).value === 'function');
    for (let k = g.int(8); k > 0 && methods.length; --k) {
      const m = g.pick(methods);
      attempt(`${cls}.${m}`, obj[m].bind(obj), Array.from({ length: g.int(4) }, () => randomValue(g, names)));
    }
    if (typeof obj.dispose === 'function') {
      obj.dispose();
      if (methods.length) {   // use after dispose is a TypeError naming the method, never a crash
        const m = g.pick(methods);
        const r = attempt(`${cls}.${m}`, obj[m].bind(obj), []);
        if (!r.error && m !== 'toString') throw new Finding(`${cls}.${m}() after dispose() did not throw`);
      }
    }
  }
  release();
  const after = { heap: rtl.heapInUse(), sp: rtl.stackPointer(), answer: fingerprint(rtl) };
  if (after.sp !== before.sp) throw new Finding(`the wasm stack pointer moved: ${before.sp} -> ${after.sp}`);
  if (after.heap !== before.heap) throw new Finding(`the wasm heap grew by ${after.heap - before.heap} bytes over ${i} iterations`);
  if (after.answer !== before.answer) throw new Finding(`the module answers differently after fuzzing: ${before.answer} -> ${after.answer}`);
  log(`fuzz_package: seed ${seed}, ${i} iterations, calls ${JSON.stringify(calls)}, heap ${after.heap} bytes (unchanged)`);
  return { iterations: i, calls };
}

if (process.argv[1] === fileURLToPath(import.meta.url)) {
  const arg = (k, d) => { const j = process.argv.indexOf(k); return j > 0 ? Number(process.argv[j + 1]) : d; };
  const seconds = arg('--seconds', process.argv.includes('--iterations') ? Infinity : 60);
  try {
    await fuzzPackage({ seed: arg('--seed', Date.now() % 1e9), iterations: arg('--iterations', Infinity), seconds, log: console.log });
  } catch (e) {
    console.error(e instanceof Finding ? `FINDING: ${e.message}` : e);
    process.exit(1);
  }
}
