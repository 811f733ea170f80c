// TypeScript: the hand-written dist/index.d.ts and its CommonJS twin dist/index.d.cts type-check an ESM and a
// CommonJS consumer (tests/ts-consumer) with tsc --noEmit in strict mode; the CommonJS one (`import init =
// require('rtl-wasm'); init()`) also compiles and runs; both declare every member the runtime module has.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { execFileSync } from 'node:child_process';
import { mkdirSync, readFileSync, rmSync } from 'node:fs';
import { join } from 'node:path';
import { fileURLToPath } from 'node:url';
import init from 'rtl-wasm';

const ROOT = fileURLToPath(new URL('../..', import.meta.url));
const tsc = fileURLToPath(new URL('../../node_modules/typescript/bin/tsc', import.meta.url));
const runTsc = (args) => {
  try {
    execFileSync(process.execPath, [tsc, ...args], { cwd: ROOT, encoding: 'utf8', stdio: 'pipe' });
  } catch (e) {
    assert.fail(`tsc ${args.join(' ')} failed:\n${e.stdout}${e.stderr}`);
  }
};

test('tsc --noEmit on tests/ts-consumer passes (ESM and CommonJS, strict, nodenext, @ts-expect-error on misuse)', { timeout: 120_000 }, () => {
  runTsc(['-p', 'tests/ts-consumer']);
});

// The package's own sources (wasm/js, ES modules bundled by wasm/build.mjs) against the declarations it ships: the
// instance API assembled in api.js must be an RTL of index.d.ts (segment, vectorize and simplify with its overloads),
// and every module must import each name it uses (an unresolved name fails the check).
test('tsc -p wasm/js: the package\'s ES modules type-check against index.d.ts (checkJs)', { timeout: 120_000 }, () => {
  runTsc(['-p', 'wasm/js']);
});

test('the CommonJS consumer compiled by tsc runs: import init = require(...); init()', { timeout: 120_000 }, () => {
  // Inside the repository, so that require('rtl-wasm') resolves to this package (self-reference).
  const out = join(ROOT, 'build', 'wasm', 'ts-consumer-run');
  rmSync(out, { recursive: true, force: true });
  mkdirSync(out, { recursive: true });
  try {
    runTsc(['-p', 'tests/ts-consumer', '--noEmit', 'false', '--outDir', out]);
    const r = JSON.parse(execFileSync(process.execPath, ['-e',
      `require(${JSON.stringify(join(out, 'consumer-cjs.cjs'))})().then((r) => console.log(JSON.stringify(r)))`],
    { cwd: ROOT, encoding: 'utf8' }));
    const pkg = JSON.parse(readFileSync(join(ROOT, 'package.json'), 'utf8'));
    assert.equal(r.version, pkg.version);
    assert.equal(r.count, 1, 'dp on 4 collinear points: one segment');
    assert.equal(r.same, true);
    // TLS RMS of (0,0) (1,1) (2,2.02): the square root of the smaller eigenvalue of the covariance matrix.
    const xs = [0, 1, 2], ys = [0, 1, 2.02], mx = 1, my = 3.02 / 3;
    const sxx = xs.reduce((a, x) => a + (x - mx) ** 2, 0) / 3, syy = ys.reduce((a, y) => a + (y - my) ** 2, 0) / 3;
    const sxy = xs.reduce((a, x, i) => a + (x - mx) * (ys[i] - my), 0) / 3;
    const lmin = (sxx + syy) / 2 - Math.sqrt(((sxx - syy) / 2) ** 2 + sxy ** 2);
    assert.ok(Math.abs(r.rms - Math.sqrt(lmin)) < 1e-12, `rms ${r.rms} vs ${Math.sqrt(lmin)}`);
  } finally {
    rmSync(out, { recursive: true, force: true });
  }
});

test('package.json types conditions point at the ESM and the CommonJS declarations', () => {
  const pkg = JSON.parse(readFileSync(join(ROOT, 'package.json'), 'utf8'));
  assert.equal(pkg.exports['.'].import.types, './dist/index.d.ts');
  assert.equal(pkg.exports['.'].require.types, './dist/index.d.cts');
  const cts = readFileSync(join(ROOT, 'dist', 'index.d.cts'), 'utf8');
  assert.match(cts, /^export = init;$/m);
});

for (const file of ['index.d.ts', 'index.d.cts']) {
  test(`${file} declares every member of the runtime module`, async () => {
    const dts = readFileSync(new URL(`../../dist/${file}`, import.meta.url), 'utf8');
    const body = dts.slice(dts.indexOf('export interface RTL {'));
    const declared = new Set([...body.matchAll(/^ *(?:readonly )?([A-Za-z][A-Za-z0-9]*)[(:?]/gm)].map((m) => m[1]));
    const rtl = await init();
    for (const k of Object.keys(rtl)) assert.ok(declared.has(k), `${k} is declared in interface RTL`);
  });
}

// The trace event unions of index.d.ts (CarEvent, IaEvent, FtlsEvent, ItlsEvent, DpEvent, RwEvent) declare exactly
// the kinds and fields the package returns: the page's lessons are built from that file.
function declaredEvents(dts, name) {
  const start = dts.indexOf(`export type ${name} =`);
  const body = dts.slice(start, dts.indexOf(';\n\n', start));
  const kinds = new Map();
  for (const m of body.matchAll(/\| \{ kind: '(\w+)';([^}]*)\}/g)) {
    const fields = [...m[2].matchAll(/(\w+)(\??):/g)].map((f) => [f[1], f[2] === '?']);
    kinds.set(m[1], fields);
  }
  return kinds;
}
test('index.d.ts: the trace event unions match the events the package returns (kinds and fields)', async () => {
  const dts = readFileSync(new URL('../../dist/index.d.ts', import.meta.url), 'utf8');
  const rtl = await init();
  const data = new URL('../data/', import.meta.url);
  const scan = rtl.readCarmenLog(readFileSync(new URL('intel.log', data)))[3].points;
  const L = [0, 0, 1, 0, 2, 0, 3, 0, 3, 1, 3, 2, 3, 3, 2.5, 3.5, 2, 4];
  const L3 = L.flatMap((v, i) => (i % 2 ? [v, 0.1 * i] : [v]));
  const stream = new rtl.StreamSegmenter({ trace: true, step: 2 });
  stream.addPoints(scan);
  stream.flush();
  const runs = [
    ['CarEvent', rtl.segment(scan, { step: 3, trace: true }).trace],
    ['IaEvent', stream.takeTrace()],
    ['FtlsEvent', [...rtl.vectorize(L, { method: 'aftls', trace: true }).trace, ...rtl.vectorize(L, { method: 'ftls', split: false, trace: true }).trace]],
    ['ItlsEvent', [...rtl.vectorize(L, { method: 'itls', sigma: 0.01, trace: true }).trace, ...rtl.vectorize(L3, { dim: 3, method: 'itls', trace: true }).trace]],
    ['DpEvent', rtl.vectorize(L, { method: 'dp', trace: true }).trace],
    ['RwEvent', rtl.vectorize(L, { method: 'rw', trace: true }).trace],
  ];
  stream.dispose();
  for (const [name, events] of runs) {
    const declared = declaredEvents(dts, name);
    assert.ok(declared.size >= 2, `${name} is declared`);
    const seen = new Set();
    for (const e of events) {
      assert.ok(declared.has(e.kind), `${name}: kind '${e.kind}' is declared`);
      seen.add(e.kind);
      const fields = declared.get(e.kind);
      const keys = Object.keys(e).filter((k) => k !== 'kind');
      for (const k of keys) assert.ok(fields.some(([f]) => f === k), `${name} '${e.kind}': field ${k} is declared`);
      for (const [f, optional] of fields) if (!optional) assert.ok(f in e, `${name} '${e.kind}': declared field ${f} is present`);
    }
    assert.ok(seen.size >= 2, `${name}: the sample covers several kinds (${[...seen]})`);
  }
});
