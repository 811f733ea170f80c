// web/serve.js: the dev server the README's `./run serve` starts. It must send the MIME types browsers insist on,
// never serve files outside the repository, and stop when its PID is signalled.
import { after, before, describe, test } from 'node:test';
import assert from 'node:assert/strict';
import { request } from 'node:http';
import { mkdirSync, mkdtempSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { startServer } from './helpers.js';

// Raw GET so that '..' and encoded segments reach the server exactly as written (fetch would normalise them).
function get(port, path, method = 'GET') {
  return new Promise((resolve, reject) => {
    const req = request({ host: '127.0.0.1', port, path, method }, (res) => {
      let body = '';
      res.setEncoding('latin1');
      res.on('data', (d) => { body += d; });
      res.on('end', () => resolve({ status: res.statusCode, type: res.headers['content-type'], headers: res.headers, body }));
    });
    req.on('error', reject);
    req.end();
  });
}

describe('web/serve.js', () => {
  let server, root;

  before(async () => {
    // A private root with one file of each type, and a secret next to (outside) it.
    const base = mkdtempSync(join(tmpdir(), 'rtl-serve-'));
    root = join(base, 'site');
    mkdirSync(join(root, 'web'), { recursive: true });
    mkdirSync(join(root, 'dist'));
    writeFileSync(join(base, 'secret.txt'), 'top secret');
    writeFileSync(join(root, 'web', 'index.html'), '<!doctype html><title>t</title>');
    writeFileSync(join(root, 'web', 'app.js'), 'export {};');
    writeFileSync(join(root, 'dist', 'm.mjs'), 'export {};');
    writeFileSync(join(root, 'dist', 'm.wasm'), Buffer.from([0, 0x61, 0x73, 0x6d, 1, 0, 0, 0]));
    writeFileSync(join(root, 'dist', 's.css'), 'p{}');
    writeFileSync(join(root, 'dist', 'd.json'), '{}');
    writeFileSync(join(root, 'dist', 'f.svg'), '<svg/>');
    server = await startServer({ root });
  });

  after(async () => {
    if (server) await server.close();
    rmSync(join(root, '..'), { recursive: true, force: true });
  });

  test('prints the page URL on 127.0.0.1 with the chosen free port', () => {
    assert.match(server.origin, /^http:\/\/127\.0\.0\.1:\d+$/);
    assert.ok(server.port > 0);
  });

  test('serves files with the right MIME types', async () => {
    const cases = {
      '/web/index.html': 'text/html; charset=utf-8',
      '/web/app.js': 'text/javascript; charset=utf-8',
      '/dist/m.mjs': 'text/javascript; charset=utf-8',
      '/dist/m.wasm': 'application/wasm',
      '/dist/s.css': 'text/css; charset=utf-8',
      '/dist/d.json': 'application/json; charset=utf-8',
      '/dist/f.svg': 'image/svg+xml',
    };
    for (const [path, type] of Object.entries(cases)) {
      const r = await get(server.port, path);
      assert.equal(r.status, 200, path);
      assert.equal(r.type, type, path);
    }
    const wasm = await get(server.port, '/dist/m.wasm');
    assert.equal(wasm.body.slice(0, 4), '\0asm');
    assert.equal(wasm.headers['content-length'], '8');
  });

  test('a directory serves its index.html, and gets a trailing slash first', async () => {
    const redirect = await get(server.port, '/web');
    assert.equal(redirect.status, 301);
    assert.equal(redirect.headers.location, '/web/');
    const page = await get(server.port, '/web/');
    assert.equal(page.status, 200);
    assert.match(page.body, /<title>t<\/title>/);
  });

  test('HEAD has headers only; other methods are refused; missing files are 404', async () => {
    const head = await get(server.port, '/web/app.js', 'HEAD');
    assert.equal(head.status, 200);
    assert.equal(head.body, '');
    assert.equal((await get(server.port, '/web/app.js', 'POST')).status, 405);
    assert.equal((await get(server.port, '/nope.js')).status, 404);
  });

  test('never serves anything outside its root', async () => {
    for (const path of ['/../secret.txt', '/web/../../secret.txt', '/%2e%2e/secret.txt', '/web/..%2f..%2fsecret.txt',
      '/..%5csecret.txt', '/%2e%2e%2fsecret.txt', '/web/%00', '/%E0%A4%A']) {
      const r = await get(server.port, path);
      assert.ok([400, 403, 404].includes(r.status), `${path}: ${r.status}`);
      assert.doesNotMatch(r.body, /top secret/, path);
    }
  });

  test('stops when its PID gets SIGTERM', async () => {
    const other = await startServer({ root });
    assert.equal((await get(other.port, '/web/app.js')).status, 200);
    process.kill(other.pid, 'SIGTERM');
    await other.close();
    await assert.rejects(get(other.port, '/web/app.js'));
  });
});
