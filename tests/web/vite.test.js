// The package in a bundler: `npm pack` the repository, install the tarball into a fresh copy of the consumer app in
// tests/vite-app/, build it with `vite build` (no plugins), serve the output and run it in headless Chromium; then the
// same app under the Vite dev server with the one setting docs/guide-js.md gives (optimizeDeps.exclude).
import { after, before, describe, test } from 'node:test';
import assert from 'node:assert/strict';
import { spawn, spawnSync } from 'node:child_process';
import { createServer } from 'node:net';
import { cpSync, mkdirSync, mkdtempSync, readFileSync, readdirSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { REPO, launchBrowser, resultsDir, startServer, watchConsole } from './helpers.js';

const NPM_ENV = { ...process.env, npm_config_audit: 'false', npm_config_fund: 'false', npm_config_update_notifier: 'false' };

const VITE = join(REPO, 'node_modules', 'vite', 'bin', 'vite.js');

function freePort() {
  return new Promise((res, rej) => {
    const srv = createServer().once('error', rej).listen(0, '127.0.0.1', () => {
      const { port } = srv.address();
      srv.close(() => res(port));
    });
  });
}

// Opens the app, waits for its result and checks it: the known line, the error path, the SVG, no console errors.
async function checkApp(browser, url, shot) {
  const page = await browser.context.newPage();
  const problems = [];
  page.on('console', (m) => { if (m.type() === 'error') problems.push(`console.error: ${m.text()}`); });
  page.on('pageerror', (e) => problems.push(`pageerror: ${e.message}`));
  const wasmResponses = [];
  page.on('response', (r) => { if (r.url().endsWith('.wasm')) wasmResponses.push(`${/rtl-extras[^/]*\.wasm$/.test(r.url()) ? 'extras' : 'core'} ${r.status()} ${r.headers()['content-type']}`); });
  await page.goto(url);
  await page.waitForFunction(() => window.__result !== undefined, null, { timeout: 60000 });
  const r = await page.evaluate(() => window.__result);
  // the C++ SVG writer draws each point as a <use> of one mark per colour
  const svgUses = await page.evaluate(() => document.querySelectorAll('#figure svg use').length);
  await page.screenshot({ path: join(resultsDir(), shot) });
  await page.close();
  assert.equal(r.failure, undefined, r.failure);
  const s5 = Math.sqrt(5);
  const sign = Math.sign(r.normal[1]);             // the normal's sign is free: compare with (-1, 2)/sqrt(5)
  assert.ok(Math.abs(sign * r.normal[0] + 1 / s5) < 1e-12, `normal ${r.normal}`);
  assert.ok(Math.abs(sign * r.normal[1] - 2 / s5) < 1e-12, `normal ${r.normal}`);
  // n . (1, 1.5) + c = 0  ->  c = -(-1 + 3)/sqrt(5)
  assert.ok(Math.abs(sign * r.offset + 2 / s5) < 1e-12, `offset ${r.offset}`);
  assert.ok(Math.abs(r.rms - 0.05) < 1e-12, `rms ${r.rms}`);
  assert.equal(r.count, 4);
  assert.equal(r.error?.name, 'RangeError');
  assert.match(r.error.message, /fitLine/);
  assert.equal(r.againRms, r.rms);
  assert.deepEqual(r.clusterSizes, [36, 1]);
  assert.equal(r.segments.length, 8, `two segments: ${r.segments}`);
  [[0, 0], [2, 0], [2, 0], [2, 1.5]].forEach(([x, y], k) => {
    assert.ok(Math.hypot(r.segments[2 * k] - x, r.segments[2 * k + 1] - y) < 1e-9, `end ${k}: ${r.segments}`);
  });
  assert.equal(svgUses, 4);
  assert.equal(r.svgCircles, 1, 'one mark, the unlabelled points\' colour');
  assert.equal(r.svgLines, 1);
  assert.deepEqual(wasmResponses, ['core 200 application/wasm', 'extras 200 application/wasm'],
    'one streaming-compilable .wasm request per module: the core at init(), the extras at load()');
  assert.deepEqual(problems, []);
  assert.equal(r.version, JSON.parse(readFileSync(join(REPO, 'package.json'), 'utf8')).version);
}

function run(cmd, args, cwd) {
  const r = spawnSync(cmd, args, { cwd, env: NPM_ENV, encoding: 'utf8', timeout: 180000 });
  assert.equal(r.status, 0, `${cmd} ${args.join(' ')} failed (${r.status ?? r.signal}):\n${r.stdout}\n${r.stderr}`);
  return r.stdout;
}

describe('packed tarball in a consumer folder: the rtl command, and tests/vite-app built by Vite and run in Chromium', { timeout: 300000 }, () => {
  let tmp, app, server, browser;

  before(() => {
    tmp = mkdtempSync(join(tmpdir(), 'rtl-vite-'));
    app = join(tmp, 'app');
    const packed = JSON.parse(run('npm', ['pack', '--json', '--pack-destination', tmp], REPO));
    mkdirSync(app);
    for (const f of ['index.html', 'main.js', 'vite.config.js']) cpSync(join(REPO, 'tests', 'vite-app', f), join(app, f));
    writeFileSync(join(app, 'package.json'), JSON.stringify({ name: 'rtl-vite-consumer', private: true, type: 'module' }));
    run('npm', ['install', '--offline', '--ignore-scripts', '--no-package-lock', join(tmp, packed[0].filename)], app);
    // Vite itself comes from the repository's dev dependencies; the app only has the package.
    run(process.execPath, [VITE, 'build'], app);
  });

  after(async () => {
    try { if (browser) await browser.close(); } finally {
      if (server) await server.close();
      if (tmp) rmSync(tmp, { recursive: true, force: true });
    }
  });

  test('the build emits the package\'s two .wasm unchanged as hashed assets, the extras glue as a chunk of its own', () => {
    const assets = readdirSync(join(app, 'dist', 'assets'));
    const wasm = assets.filter((f) => f.endsWith('.wasm'));
    assert.equal(wasm.length, 2, `assets: ${assets.join(', ')}`);
    const core = wasm.find((f) => !f.startsWith('rtl-extras-')), extras = wasm.find((f) => f.startsWith('rtl-extras-'));
    assert.ok(core && extras, `assets: ${assets.join(', ')}`);
    assert.match(core, /^rtl-[\w-]+\.wasm$/);
    assert.ok(readFileSync(join(app, 'dist', 'assets', core)).equals(readFileSync(join(REPO, 'dist', 'rtl.wasm'))));
    assert.ok(readFileSync(join(app, 'dist', 'assets', extras)).equals(readFileSync(join(REPO, 'dist', 'rtl-extras.wasm'))));
    const js = assets.filter((f) => f.endsWith('.js'));
    assert.ok(js.length >= 2);
    const text = (f) => readFileSync(join(app, 'dist', 'assets', f), 'utf8');
    const coreJs = js.filter((f) => text(f).includes(core)), extrasJs = js.filter((f) => text(f).includes(extras));
    assert.equal(coreJs.length, 1, 'one bundle refers to the hashed core .wasm');
    assert.equal(extrasJs.length, 1, 'one chunk refers to the hashed extras .wasm');
    assert.notEqual(coreJs[0], extrasJs[0], 'the extras glue is a chunk of its own, fetched on load(\'extras\')');
  });

  test('the installed tarball provides the rtl command (package bin), which runs from the consumer folder', () => {
    const bin = join(app, 'node_modules', '.bin', 'rtl');
    let r = spawnSync(bin, ['--version'], { cwd: app, encoding: 'utf8' });
    assert.equal(r.status, 0, r.stderr);
    assert.equal(r.stdout.trim(), JSON.parse(readFileSync(join(REPO, 'package.json'), 'utf8')).version);
    // Points 10 cm apart: the command segments first, and these are close enough to form one cluster.
    writeFileSync(join(app, 'wall.csv'), '0,1\n0.1,1\n0.2,1\n0.3,1\n');
    r = spawnSync(bin, ['wall.csv', '--fit', '-f', 'svg'], { cwd: app, encoding: 'utf8' });
    assert.equal(r.status, 0, r.stderr);
    assert.match(r.stdout, /^<\?xml[^>]*>\n<svg[\s>][\s\S]*<line [\s\S]*<\/svg>\s*$/);
    r = spawnSync(bin, ['wall.csv', '-m', 'magic'], { cwd: app, encoding: 'utf8' });
    assert.equal(r.status, 2);
    assert.match(r.stderr, /^rtl: --vectorize must be one of/);
  });

  test('the built app loads the module in Chromium and fits the known line', async () => {
    server = await startServer({ root: join(app, 'dist') });
    browser = await launchBrowser();
    await checkApp(browser, server.pageUrl, 'vite-app-build.png');
  });

  test('the same app works under the Vite dev server (optimizeDeps.exclude from docs/guide-js.md)', async () => {
    const port = await freePort();
    // Started with node directly (npx would leave a child running); stopped by PID below.
    const dev = spawn(process.execPath, [VITE, '--host', '127.0.0.1', '--port', String(port), '--strictPort'],
      { cwd: app, stdio: ['ignore', 'pipe', 'pipe'] });
    let log = '';
    dev.stdout.on('data', (d) => { log += d; });
    dev.stderr.on('data', (d) => { log += d; });
    const stopped = new Promise((res) => dev.once('exit', res));
    try {
      const url = `http://127.0.0.1:${port}/`;
      const deadline = Date.now() + 60000;
      for (;;) {
        try { if ((await fetch(url)).ok) break; } catch { /* not listening yet */ }
        assert.ok(Date.now() < deadline && dev.exitCode === null, `vite dev server did not start:\n${log}`);
        await new Promise((r) => setTimeout(r, 200));
      }
      browser ??= await launchBrowser();
      await checkApp(browser, url, 'vite-app-dev.png');
    } finally {
      dev.kill('SIGTERM');
      await stopped;
    }
  });
});
