// The API references: TypeDoc documents every export of the package's shipped declarations without a single
// warning (a warning fails the build, as doc_doxygen fails on any Doxygen warning), and `./run serve`'s server
// serves both references, built by docs/build-references.mjs as `./run serve` builds them, beside the page.
import { after, before, describe, test } from 'node:test';
import assert from 'node:assert/strict';
import { execFileSync } from 'node:child_process';
import { existsSync, mkdtempSync, readFileSync, rmSync, writeFileSync } from 'node:fs';
import { request } from 'node:http';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { fileURLToPath } from 'node:url';
import { buildJsReference } from '../../docs/build-references.mjs';
import { startServer } from '../web/helpers.js';

const ROOT = fileURLToPath(new URL('../..', import.meta.url));

// The declaration files TypeDoc documents, by the module name a user imports (docs/typedoc/module-names.mjs).
const MODULES = {
  'rtl-wasm': 'wasm/js/index.d.ts',
  'rtl-wasm/logs': 'wasm/js/ros/logs.d.ts',
  'rtl-wasm/ros': 'wasm/js/ros/messages.d.ts',
};
// TypeDoc's page folder for each kind of top-level export.
const FOLDERS = { function: 'functions', class: 'classes', interface: 'interfaces', type: 'types', const: 'variables' };

function topLevelExports(file) {
  const text = readFileSync(join(ROOT, file), 'utf8');
  return [...text.matchAll(/^export (?:declare )?(function|class|interface|type|const) (\w+)/gm)]
    .map(([, kind, name]) => ({ kind, name }));
}

describe('TypeDoc reference of the shipped declarations', () => {
  let tmp;
  before(() => { tmp = mkdtempSync(join(tmpdir(), 'rtl-typedoc-')); });
  after(() => rmSync(tmp, { recursive: true, force: true }));

  test('builds without a warning and has a page for every top-level export of the three modules', () => {
    const r = buildJsReference(join(tmp, 'js'));
    assert.deepEqual(r.problems, [], 'TypeDoc warnings or errors');
    assert.ok(r.ok);
    let pages = 0;
    for (const [module, file] of Object.entries(MODULES)) {
      const slug = module.replace('/', '_');
      assert.ok(existsSync(join(r.out, 'modules', `${slug}.html`)), `module page of ${module}`);
      const exports = topLevelExports(file);
      assert.ok(exports.length >= 3, `${file}: ${exports.length} exports found`);
      for (const { kind, name } of exports) {
        const page = join(r.out, FOLDERS[kind], `${slug}.${name}.html`);
        assert.ok(existsSync(page), `${module}: ${kind} ${name} has no page (${page})`);
        pages++;
      }
    }
    assert.ok(pages >= 60, `${pages} pages`);
    // The contract's prose reaches the page: init's documentation names the error it rejects with.
    assert.match(readFileSync(join(r.out, 'functions', 'rtl-wasm.init.html'), 'utf8'), /TypeError/);
  });

  test('a declaration with a broken {@link} fails the build and names it', () => {
    const bad = join(tmp, 'bad.d.ts');
    writeFileSync(bad, '/** Returns the answer; see {@link NoSuchThing}. */\nexport function answer(): number;\n');
    writeFileSync(join(tmp, 'tsconfig.json'), JSON.stringify({ compilerOptions: { strict: true, noEmit: true, types: [] }, files: [bad] }));
    const r = buildJsReference(join(tmp, 'bad'), ['--entryPoints', bad, '--tsconfig', join(tmp, 'tsconfig.json')]);
    assert.equal(r.ok, false);
    assert.ok(r.problems.some((p) => p.includes('NoSuchThing')), r.problems.join('\n'));
  });
});

// Raw GET, so that a path reaches the server exactly as written.
function get(port, path) {
  return new Promise((resolve, reject) => {
    const req = request({ host: '127.0.0.1', port, path }, (res) => {
      let body = '';
      res.setEncoding('utf8');
      res.on('data', (d) => { body += d; });
      res.on('end', () => resolve({ status: res.statusCode, type: res.headers['content-type'], headers: res.headers, body }));
    });
    req.on('error', reject);
    req.end();
  });
}

describe('./run serve: both references served beside the page', { timeout: 300_000 }, () => {
  let server;
  before(async () => {
    // As ./run serve does (build_docs): the script writes build/docs/js and build/docs/cpp and fails on warnings.
    execFileSync(process.execPath, [join(ROOT, 'docs', 'build-references.mjs')], { cwd: ROOT, encoding: 'utf8', stdio: 'pipe' });
    server = await startServer();
  });
  after(async () => { await server?.close(); });

  test('/docs/js/ is the TypeDoc index, with the modules and their pages', async () => {
    const index = await get(server.port, '/docs/js/');
    assert.equal(index.status, 200);
    assert.match(index.type, /^text\/html/);
    assert.match(index.body, /rtl-wasm: the JavaScript API reference/);   // docs/typedoc/index.md
    const modules = await get(server.port, '/docs/js/modules.html');
    for (const slug of ['rtl-wasm', 'rtl-wasm_logs', 'rtl-wasm_ros']) assert.ok(modules.body.includes(`modules/${slug}.html`), slug);
    const logs = await get(server.port, '/docs/js/modules/rtl-wasm_logs.html');
    assert.equal(logs.status, 200);
    assert.ok(logs.body.includes('openLog'));
    const css = await get(server.port, '/docs/js/assets/style.css');
    assert.equal(css.status, 200);
    assert.match(css.type, /^text\/css/);
  });

  test('/docs/cpp/ is the Doxygen index (the main page) with the class pages', async () => {
    const index = await get(server.port, '/docs/cpp/');
    assert.equal(index.status, 200);
    assert.match(index.body, /RTL C\+\+ API reference/);
    const vector = await get(server.port, '/docs/cpp/classrtl_1_1VectorND.html');
    assert.equal(vector.status, 200);
    assert.match(vector.body, /VectorND/);
  });

  test('without the slash it redirects; the repository\'s docs/ and the page are still served; nothing escapes', async () => {
    const bare = await get(server.port, '/docs/js');
    assert.equal(bare.status, 301);
    assert.equal(bare.headers.location, '/docs/js/');
    const notes = await get(server.port, '/docs/reference.md');
    assert.equal(notes.status, 200);
    assert.equal(notes.body, readFileSync(join(ROOT, 'docs', 'reference.md'), 'utf8'));
    assert.equal((await get(server.port, '/web/')).status, 200);
    // Encoded slashes survive URL parsing and are decoded afterwards: each reference is its own root.
    for (const path of ['/docs/js/..%2f..%2f..%2fpackage.json', '/docs/cpp/..%2fjs%2findex.html']) {
      assert.equal((await get(server.port, path)).status, 403, path);
    }
  });
});
