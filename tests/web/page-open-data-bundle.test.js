// The browser's copy of rtl-wasm/logs (web/vendor-logs.js, served by web/serve.js at /vendor/rtl-wasm-logs.js): one
// self-contained ES module, its optional peers inside it (no bare name left for a worker that has no import map), the
// decompressors' wasm inlined, no Node built-in reachable outside Node's branches; served with a JavaScript type.
// Without a built package the server answers 503 with the reason.
import test from 'node:test';
import assert from 'node:assert/strict';
import { mkdtempSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { LOGS_BUNDLE_PATH, bundleLogs, peerNames } from '../../web/vendor-logs.js';
import { REPO, startServer } from './helpers.js';

test('bundleLogs: the peers are inside, nothing is left to resolve by name', async () => {
  const code = await bundleLogs(REPO);
  assert.deepEqual((await peerNames(REPO)).sort(), ['@foxglove/rosbag', '@foxglove/rosmsg', '@foxglove/rosmsg-serialization',
    '@foxglove/rosmsg2-serialization', '@mcap/core', '@mcap/support']);
  assert.doesNotMatch(code, /\bimport\s*\(\s*["'`]@/, 'no dynamic import of a package name');
  assert.doesNotMatch(code, /^\s*import\s[^;]*from\s*["'](?![./])/m, 'no static import of a package name');
  assert.doesNotMatch(code, /\bimport\((pkg|name)\)/, 'the entry\'s import(name) goes through the table');
  assert.match(code, /export\s*\{[^}]*\bopenLog\b/);
  assert.match(code, /export\s*\{[^}]*\bLogError\b/);
  assert.equal((code.match(/data:application\/wasm;base64,/g) ?? []).length, 3, 'lz4, zstd and bz2 inlined');
  assert.equal(await bundleLogs(REPO), code, 'cached');
});

test('serve.js: the bundle with a JavaScript type; without a package a 503 that says why', async () => {
  const server = await startServer();
  try {
    const res = await fetch(server.origin + LOGS_BUNDLE_PATH);
    assert.equal(res.status, 200);
    assert.match(res.headers.get('content-type'), /^text\/javascript/);
    assert.match(await res.text(), /\bopenLog\b/);
  } finally {
    await server.close();
  }
  const empty = mkdtempSync(join(tmpdir(), 'rtl-serve-empty-'));
  const bare = await startServer({ root: empty });
  try {
    const res = await fetch(bare.origin + LOGS_BUNDLE_PATH);
    assert.equal(res.status, 503);
    assert.match(await res.text(), /^\/vendor\/rtl-wasm-logs\.js: .*package\.json/);
  } finally {
    await bare.close();
    rmSync(empty, { recursive: true, force: true });
  }
});
