// `npm pack` gives a tarball that installs into an empty folder and works there from ESM and CommonJS.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { execFileSync } from 'node:child_process';
import { mkdtempSync, readFileSync, readdirSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join, resolve } from 'node:path';
import { fileURLToPath } from 'node:url';

const ROOT = resolve(fileURLToPath(new URL('../..', import.meta.url)));
const npm = (args, cwd) => execFileSync('npm', args, { cwd, encoding: 'utf8', stdio: ['ignore', 'pipe', 'pipe'] });

test('npm pack -> npm install into an empty folder -> import and require work', { timeout: 120_000 }, () => {
  const dir = mkdtempSync(join(tmpdir(), 'rtl-pack-'));
  try {
    const out = JSON.parse(npm(['pack', '--json', '--pack-destination', dir], ROOT));
    const files = out[0].files.map((f) => f.path);
    for (const f of ['package.json', 'LICENSE', 'dist/NOTICE.md', 'dist/index.mjs', 'dist/index.node.mjs', 'dist/index.cjs',
      'dist/index.d.ts', 'dist/index.d.cts', 'dist/rtl.wasm', 'dist/rtl.mjs', 'dist/rtl.cjs', 'dist/api.mjs', 'dist/api.cjs',
      'dist/rtl-extras.wasm', 'dist/rtl-extras.mjs', 'dist/rtl-extras.cjs']) {
      assert.ok(files.includes(f), `tarball contains ${f}`);
    }
    assert.ok(!files.some((f) => f.startsWith('wasm/') || f.startsWith('tests/') || f.startsWith('include/')),
      'tarball holds only the package files');
    const app = join(dir, 'app');
    execFileSync('mkdir', [app]);
    writeFileSync(join(app, 'package.json'), JSON.stringify({ name: 'app', version: '1.0.0', private: true }));
    npm(['install', '--no-audit', '--no-fund', '--offline', join(dir, out[0].filename)], app);
    assert.ok(readdirSync(join(app, 'node_modules', 'rtl-wasm', 'dist')).includes('rtl.wasm'));
    const installed = join(app, 'node_modules', 'rtl-wasm');
    assert.match(readFileSync(join(installed, 'LICENSE'), 'utf8'), /^MIT License\n/);
    const notice = readFileSync(join(installed, 'dist', 'NOTICE.md'), 'utf8');
    for (const s of ['Intel Research Lab', 'MIT CSAIL', 'Radish', 'Schaefer et al., IROS 2018', 'RELLIS-3D', 'Jiang et al., 2021'])
      assert.ok(notice.includes(s), `NOTICE.md attributes ${s}`);
    writeFileSync(join(app, 'esm.mjs'), `import init from 'rtl-wasm';
      const r = await init(); const f = r.fitLine(new Float64Array([0, 2, 1, 2, 5, 2]));
      console.log(JSON.stringify({ n: Array.from(f.normal), c: f.offset, v: r.version }));
      try { r.fitLine([1]); } catch (e) { console.log(e.constructor.name); }`);
    writeFileSync(join(app, 'cjs.cjs'), `require('rtl-wasm')().then((r) => {
      const f = r.fitLine([0, 2, 1, 2, 5, 2]);
      console.log(JSON.stringify({ n: Array.from(f.normal), c: f.offset, v: r.version }));
      try { r.fitLine('x'); } catch (e) { console.log(e.constructor.name); } });`);
    for (const [file, err] of [['esm.mjs', 'RangeError'], ['cjs.cjs', 'TypeError']]) {
      const lines = execFileSync(process.execPath, [file], { cwd: app, encoding: 'utf8' }).trim().split('\n');
      assert.deepEqual(JSON.parse(lines[0]), { n: [0, 1], c: -2, v: out[0].version }, file);
      assert.equal(lines[1], err, file);
    }
  } finally {
    rmSync(dir, { recursive: true, force: true });
  }
});

// The size budget: what a browser loads for the core package (rtl.wasm, the ES glue rtl.mjs, api.mjs, index.mjs)
// stays within 350,000 bytes gzipped, each file compressed with `gzip -9` on its own. Past that, rarely used parts
// move into a module loaded on demand (as the log readers of rtl-wasm/logs are, and the extras module
// rtl-extras.wasm + rtl-extras.mjs, fetched by rtl.load('extras'), not counted here) rather than being dropped.
test('the shipped JS + wasm is within 350,000 bytes gzipped', () => {
  const sizes = {};
  for (const f of ['rtl.wasm', 'rtl.mjs', 'api.mjs', 'index.mjs'])
    sizes[f] = execFileSync('gzip', ['-9', '-c', join(ROOT, 'dist', f)], { maxBuffer: 1 << 26 }).length;
  const total = Object.values(sizes).reduce((a, b) => a + b, 0);
  assert.ok(total <= 350_000, `gzipped total ${total} B: ${JSON.stringify(sizes)}`);
});
