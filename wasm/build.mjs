#!/usr/bin/env node
// Builds the rtl-wasm package into dist/: configures and builds wasm/ with emcmake (build dir build/wasm), checks
// that the ES6 and CommonJS links produced the same rtl.wasm, and assembles the JS entries and the .d.ts.
//   node wasm/build.mjs            (npm run build)     RTL_JOBS=n  parallel compile jobs (default: all cores)
import { execFileSync } from 'node:child_process';
import { copyFileSync, existsSync, mkdirSync, readFileSync, rmSync, writeFileSync } from 'node:fs';
import { availableParallelism } from 'node:os';
import { dirname, join, resolve } from 'node:path';
import { fileURLToPath } from 'node:url';

const ROOT = resolve(dirname(fileURLToPath(import.meta.url)), '..');
const BUILD = join(ROOT, 'build', 'wasm');
const DIST = join(ROOT, 'dist');
const JS = join(ROOT, 'wasm', 'js');

function fail(msg) {
  console.error(`wasm/build.mjs: ${msg}`);
  process.exit(1);
}

function run(cmd, args) {
  console.log(`$ ${cmd} ${args.join(' ')}`);
  try {
    execFileSync(cmd, args, { cwd: ROOT, stdio: 'inherit' });
  } catch (e) {
    fail(`${cmd} failed (${e.status ?? e.message})`);
  }
}

function hasCommand(cmd) {
  try {
    execFileSync('sh', ['-c', `command -v ${cmd}`], { stdio: 'ignore' });
    return true;
  } catch {
    return false;
  }
}

if (!hasCommand('emcmake')) fail('emcmake not found: install Emscripten (apt-get install emscripten)');

const pkg = JSON.parse(readFileSync(join(ROOT, 'package.json'), 'utf8'));
const jobs = String(Number(process.env.RTL_JOBS) || availableParallelism());

// Configure (cheap when nothing changed). Eigen3_DIR: find_package fails under emcmake without it; the emulator
// override: emcmake's default passes a flag Node 20 rejects.
run('emcmake', ['cmake', '-S', '.', '-B', BUILD, '-DCMAKE_BUILD_TYPE=Release', '-DEigen3_DIR=/usr/share/eigen3/cmake',
  '-DCMAKE_CROSSCOMPILING_EMULATOR=/usr/bin/node', '-DRTL_BUILD_WASM=ON', '-DRTL_INSTALL=OFF']);
run('cmake', ['--build', BUILD, '-j', jobs, '--target', 'rtl_wasm_es', 'rtl_wasm_node']);

const es = join(BUILD, 'wasm', 'es');
const node = join(BUILD, 'wasm', 'node');
for (const f of [join(es, 'rtl.mjs'), join(es, 'rtl.wasm'), join(node, 'rtl.cjs'), join(node, 'rtl.wasm')]) {
  if (!existsSync(f)) fail(`missing build output ${f}`);
}
if (!readFileSync(join(es, 'rtl.wasm')).equals(readFileSync(join(node, 'rtl.wasm'))))
  fail('the ES6 and CommonJS links produced different rtl.wasm files; dist/ ships only one');

rmSync(DIST, { recursive: true, force: true });
mkdirSync(DIST, { recursive: true });
copyFileSync(join(es, 'rtl.mjs'), join(DIST, 'rtl.mjs'));
copyFileSync(join(node, 'rtl.cjs'), join(DIST, 'rtl.cjs'));
copyFileSync(join(es, 'rtl.wasm'), join(DIST, 'rtl.wasm'));

// api.js is written once, as an ES module whose last statement is `export { ... };`; derive the CommonJS twin.
const api = readFileSync(join(JS, 'api.js'), 'utf8').replaceAll('__RTL_VERSION__', pkg.version);
const exportLine = /^export \{([^}]*)\};\s*$/m;
if (!exportLine.test(api)) fail('wasm/js/api.js must end with a single `export { ... };` line');
writeFileSync(join(DIST, 'api.mjs'), api);
writeFileSync(join(DIST, 'api.cjs'), `'use strict';\n${api.replace(exportLine, 'module.exports = {$1};')}`);

copyFileSync(join(JS, 'index.mjs'), join(DIST, 'index.mjs'));
copyFileSync(join(JS, 'index.mjs'), join(DIST, 'index.js'));  // the demo page's import map points here
copyFileSync(join(JS, 'index.node.mjs'), join(DIST, 'index.node.mjs'));
copyFileSync(join(JS, 'index.cjs'), join(DIST, 'index.cjs'));
copyFileSync(join(JS, 'index.d.ts'), join(DIST, 'index.d.ts'));

console.log(`dist/ ready (rtl-wasm ${pkg.version}): rtl.wasm ${readFileSync(join(DIST, 'rtl.wasm')).length} bytes`);
