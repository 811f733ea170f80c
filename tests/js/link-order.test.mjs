// The package's link order (wasm/CMakeLists.txt): an inline function or template instantiated in several objects is
// kept from the first object that defines it, so an object compiled for size (-Oz) must not come before the -O3
// objects with its own copy of a function they run. When readers.cpp (-Oz) came first, the hot bindings grew their
// kept point vectors through its std::vector<VectorND>::__append, whose zero-fill called non-inlined Eigen
// constructors: a 100k-point call right after a small one took 10-40x its steady time. Checked on the objects of the
// core module's link (the extras module, rtl-extras.wasm, runs no hot loop: draw.cpp, pcd.cpp and alg.cpp at -Oz,
// and module.cpp's diagnostics) in the wasm build folder (RTL_WASM_BUILD_DIR, default build/wasm) with llvm-nm;
// skipped only without a wasm build.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { execFileSync } from 'node:child_process';
import { existsSync, readFileSync } from 'node:fs';
import { join, resolve } from 'node:path';
import { fileURLToPath } from 'node:url';

const ROOT = fileURLToPath(new URL('../..', import.meta.url));
const WASM = join(resolve(ROOT, process.env.RTL_WASM_BUILD_DIR || 'build/wasm'), 'wasm');
const LINK = join(WASM, 'CMakeFiles', 'rtl_wasm_es.dir', 'objects1');
const FLAGS = join(WASM, 'CMakeFiles', 'rtl_wasm_objects.dir', 'flags.make');
// Debian's emscripten brings llvm-14 (llvm-nm-14); a plain llvm-nm comes only with the llvm package.
const NM = ['llvm-nm', 'llvm-nm-14', '/usr/lib/llvm-14/bin/llvm-nm'].find((nm) => {
  try {
    execFileSync(nm, ['--version'], { stdio: 'ignore' });
    return true;
  } catch {
    return false;
  }
});
// Without a wasm build (a package tested from its dist alone) there are no objects to check; with one, a missing
// llvm-nm is a failure, not a skip.
const skip = !existsSync(LINK) || !existsSync(FLAGS) ? `no wasm build in ${WASM}` : false;

// Weak (COMDAT) function symbols an object defines, mangled.
const weakFunctions = (obj) => new Set(execFileSync(NM, ['--defined-only', join(WASM, obj)], { encoding: 'utf8', maxBuffer: 64 << 20 })
  .split('\n').map((l) => l.trim().split(/\s+/)).filter((f) => f[1] === 'W').map((f) => f[2]));
// Code the numeric bindings run: the library's and Eigen's functions and std::vector's members (not its throw helpers).
const hot = (sym) => /3rtl|5Eigen|NSt3__26vectorI/.test(sym) && !/__throw/.test(sym);

// [symbol, -Oz object that supplies it, -O3 object that loses its copy] for every hot symbol an -Oz object defines
// before an -O3 object does.
export function sizeObjectsFirst(objects, sizeObjects, symbolsOf) {
  const first = new Map(), found = [];
  for (const obj of objects) {
    for (const sym of symbolsOf(obj)) {
      if (!hot(sym)) continue;
      if (!first.has(sym)) first.set(sym, obj);
      else if (sizeObjects.has(first.get(sym)) && !sizeObjects.has(obj)) found.push([sym, first.get(sym), obj]);
    }
  }
  return found;
}

test('no -Oz object supplies a function the -O3 objects run (link order)', { skip }, () => {
  assert.ok(NM, 'llvm-nm not found (tried llvm-nm, llvm-nm-14, /usr/lib/llvm-14/bin/llvm-nm)');
  const objects = readFileSync(LINK, 'utf8').trim().split(/\s+/);
  // CMake's record of per-source options: "# Custom options: <dir>/src/x.cpp.o_OPTIONS = -Oz"
  const sizeObjects = new Set([...readFileSync(FLAGS, 'utf8').matchAll(/^# Custom options: \S*?(CMakeFiles\/\S+\.o)_OPTIONS = .*-O[sz]\b/gm)]
    .map((m) => m[1]));
  assert.ok(sizeObjects.size > 0, `no -Oz/-Os object recorded in ${FLAGS}`);
  const symbols = new Map(objects.map((o) => [o, weakFunctions(o)]));
  const found = sizeObjectsFirst(objects, sizeObjects, (o) => symbols.get(o));
  assert.deepEqual(found.map(([sym, from, to]) => `${sym} from ${from} (not ${to})`), []);
  // the check sees the case it guards: readers.cpp before segment.cpp would supply vector<VectorND<2>>::__append
  const readers = objects.find((o) => o.endsWith('/readers.cpp.o')), segment = objects.find((o) => o.endsWith('/segment.cpp.o'));
  const swapped = [readers, ...objects.filter((o) => o !== readers)];
  assert.ok(sizeObjectsFirst(swapped, sizeObjects, (o) => symbols.get(o))
    .some(([sym, from, to]) => /vectorIN3rtl8VectorNDILi2EdEE.*8__appendEm/.test(sym) && from === readers && to === segment));
});
