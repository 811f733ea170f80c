// rtl-wasm/logs and rtl-wasm/log-worker through a bundler (esbuild, from the lock file) with no plugin: the optional
// peers are imported by literal specifiers, so the bundle holds them and reads a log with nothing else installed
// beside it. The only options are the ones the peers' own files need of any bundler (@mcap/support's decompressors
// ship .wasm files that their Emscripten glue loads: a file loader; in a browser bundle their Node-only `require('fs')`
// and `require('path')` stay external). Also: the log worker, installed as a user installs the package (files, not a
// link to this checkout), resolves its bare 'rtl-wasm' import and processes a bag.
import test from 'node:test';
import assert from 'node:assert/strict';
import { cpSync, mkdirSync, mkdtempSync, readFileSync, rmSync, symlinkSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { fileURLToPath, pathToFileURL } from 'node:url';
import { Worker } from 'node:worker_threads';
import { build } from 'esbuild';
import init from 'rtl-wasm';
import { openLog } from 'rtl-wasm/logs';
import { laserScanOf, writeMcap } from './ros-fixtures.mjs';

const ROOT = fileURLToPath(new URL('../../', import.meta.url));
const DATA = join(ROOT, 'tests', 'data');
const PEERS = Object.keys(JSON.parse(readFileSync(join(ROOT, 'package.json'), 'utf8')).peerDependencies);
const rtl = await init();
const csail = rtl.readCarmenLog(readFileSync(join(DATA, 'csail.log'))).slice(0, 12);

const dir = mkdtempSync(join(tmpdir(), 'rtl-logs-bundle-'));
test.after(() => rmSync(dir, { recursive: true, force: true }));

// A user's entry importing the package's public subpath, bundled from the package root (esbuild resolves
// 'rtl-wasm/logs' through package.json's exports).
// For Node, CommonJS output: the decompressors' Emscripten glue reads its .wasm by its own name from __dirname, which
// an ES module bundle lacks (hence also assetNames: the .wasm files keep their names).
async function bundle(platform, contents, outdir) {
  const format = platform === 'node' ? 'cjs' : 'esm';
  return build({
    stdin: { contents, resolveDir: ROOT, sourcefile: 'user.mjs' }, bundle: true, format, platform, outdir,
    outExtension: { '.js': format === 'cjs' ? '.cjs' : '.mjs' }, assetNames: '[name]', metafile: true, logLevel: 'silent', loader: { '.wasm': 'file' },
    external: platform === 'browser' ? ['fs', 'path'] : [],
  });
}
// The bundle's one script (beside it: the decompressors' .wasm files).
const scriptOf = (result) => join(ROOT, Object.keys(result.metafile.outputs).find((f) => /\.[cm]js$/.test(f)));

// The bundle's inputs that come from a package's own files, as package names.
const packagesIn = (metafile) => new Set(Object.keys(metafile.inputs).map((p) => p.match(/node_modules\/((?:@[^/]+\/)?[^/]+)/)?.[1]).filter(Boolean));

test('rtl-wasm/logs bundled by esbuild with no plugin (Node): the peers are in the bundle; an lz4 and a zstd MCAP read as unbundled', async () => {
  const out = join(dir, 'node');
  const r = await bundle('node', "export { openLog } from 'rtl-wasm/logs';", out);
  assert.deepEqual(r.errors, []);
  const inside = packagesIn(r.metafile);
  for (const peer of PEERS) assert.ok(inside.has(peer), `${peer} is in the bundle`);
  const bundled = await import(pathToFileURL(scriptOf(r)).href);
  assert.notEqual(bundled.openLog, openLog);
  for (const compression of ['lz4', 'zstd']) {
    const file = join(dir, `csail-${compression}.mcap`);
    await writeMcap(file, [{ topic: '/scan', type: 'sensor_msgs/msg/LaserScan', messages: csail.map((s) => ({ time: s.timestamp, msg: laserScanOf(s) })) }],
                    { compression, chunkSize: 4096 });
    const read = async (open) => {
      const log = await open(file);
      const scans = [];
      for await (const s of log.scans('/scan')) scans.push(s);
      await log.close();
      return { topics: log.topics, scans };
    };
    const viaBundle = await read(bundled.openLog), direct = await read(openLog);
    assert.deepEqual(viaBundle.topics, [{ name: '/scan', type: 'sensor_msgs/msg/LaserScan', count: csail.length }]);
    assert.equal(viaBundle.scans.length, csail.length);
    assert.deepEqual(viaBundle, direct);
    // and the points are the CARMEN log's (where the beam returned)
    const s = viaBundle.scans[5], p = csail[5].points;
    for (let i = 0; i < p.length; i++) if (!Number.isNaN(s.points[i])) assert.ok(Math.abs(s.points[i] - p[i]) < 1e-5, `point ${i}`);
  }
  const bag = await bundled.openLog(join(DATA, 'ros1', 'intel-lz4.bag'));
  assert.equal(bag.format, 'bag');
  await bag.close();
});

test('rtl-wasm/logs and rtl-wasm/log-worker bundle for the browser with no plugin; the worker\'s bare rtl-wasm is the package\'s browser entry', async () => {
  const logs = await bundle('browser', "export { openLog } from 'rtl-wasm/logs';", join(dir, 'browser-logs'));
  assert.deepEqual(logs.errors, []);
  for (const peer of PEERS) assert.ok(packagesIn(logs.metafile).has(peer), `${peer} is in the browser bundle`);
  const text = readFileSync(scriptOf(logs), 'utf8');
  for (const peer of PEERS) assert.ok(!text.includes(`import("${peer}")`), `no import of ${peer} left to resolve at run time`);

  const worker = await bundle('browser', "import 'rtl-wasm/log-worker';", join(dir, 'browser-worker'));
  assert.deepEqual(worker.errors, []);
  const inputs = Object.keys(worker.metafile.inputs);
  assert.ok(inputs.some((p) => p.endsWith('dist/index.mjs')), 'rtl-wasm resolved to dist/index.mjs');
  assert.ok(inputs.some((p) => p.endsWith('dist/ros/logs.js')), 'the worker bundles the logs entry');
});

test('rtl-wasm/log-worker installed as a package (copied files, peers beside it) resolves rtl-wasm and processes a bag', async () => {
  const app = join(dir, 'app'), pkg = join(app, 'node_modules', 'rtl-wasm');
  mkdirSync(pkg, { recursive: true });
  cpSync(join(ROOT, 'package.json'), join(pkg, 'package.json'));
  cpSync(join(ROOT, 'dist'), join(pkg, 'dist'), { recursive: true });
  for (const scope of ['@mcap', '@foxglove']) symlinkSync(join(ROOT, 'node_modules', scope), join(app, 'node_modules', scope), 'dir');
  const w = new Worker(join(pkg, 'dist', 'ros', 'log-worker.js'));
  const msgs = await new Promise((resolve, reject) => {
    const got = [];
    w.on('error', reject);
    w.on('message', (m) => { got.push(m); if (m.type === 'done' || m.type === 'error') resolve(got); });
    w.postMessage({ type: 'open', source: join(DATA, 'ros1', 'intel-none.bag') });
  });
  await w.terminate();
  assert.deepEqual(msgs.at(-1), { type: 'done', done: 30, cancelled: false });
  const scans = msgs.filter((m) => m.type === 'scans').flatMap((m) => m.scans);
  const intel = rtl.readCarmenLog(readFileSync(join(DATA, 'intel.log')));
  assert.deepEqual(Array.from(scans[3].labels), Array.from(rtl.segment(intel[3].points).labels));
});

test('rtl-wasm/logs installed without a peer: opening a log that needs it is a LogError naming the missing package', async () => {
  const app = join(dir, 'app-no-mcap'), pkg = join(app, 'node_modules', 'rtl-wasm');
  mkdirSync(pkg, { recursive: true });
  cpSync(join(ROOT, 'package.json'), join(pkg, 'package.json'));
  cpSync(join(ROOT, 'dist', 'ros'), join(pkg, 'dist', 'ros'), { recursive: true });
  symlinkSync(join(ROOT, 'node_modules', '@foxglove'), join(app, 'node_modules', '@foxglove'), 'dir');   // no @mcap
  const { openLog: userOpenLog } = await import(pathToFileURL(join(pkg, 'dist', 'ros', 'logs.js')).href);
  const file = join(dir, 'magic-only.mcap');   // an MCAP's magic: enough to need @mcap/core
  writeFileSync(file, new Uint8Array([0x89, 0x4d, 0x43, 0x41, 0x50, 0x30, 0x0d, 0x0a]));
  await assert.rejects(userOpenLog(file), (e) => e.name === 'LogError' && e.code === 'MISSING_DEPENDENCY' && e.file === file &&
    e.message.startsWith(`openLog: ${file}: reading this log needs the optional peer dependency @mcap/core`));
});
