// Every code block of README.md runs as written (issue 12.3), where a user would run it:
//   ```js        an .mjs file (a `.cjs` one when its first line is `// CommonJS`) run with node in an empty project
//                where the `npm pack` tarball of this repository is installed, next to copies of tests/data's intel.log,
//                csail.log and rellis3d-os1-4x2048.bin; it must exit 0 (and print nothing on stderr)
//   ```ts        type-checked with the repository's tsc (strict, nodenext) in that project
//   ```cpp       a complete program, compiled against the installed CMake package with a CMakeLists.txt that uses the
//                README's ```cmake find_package snippet, run in the data folder; it must exit 0
//   ```cmake     the find_package snippet is used by the C++ programs; the sub-project block is not run (it names a
//                path or URL of the user's)
//   ```bash, ```html  not run: install/build commands would modify the machine; the import map needs a page and a server
// A block that prints results says what with `// prints: <text>` comments; the output must contain each text, in order.
import { after, before, describe, test } from 'node:test';
import assert from 'node:assert/strict';
import { execFileSync, spawnSync } from 'node:child_process';
import { copyFileSync, mkdtempSync, readFileSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { fileURLToPath } from 'node:url';
import { packAndInstall } from '../js/helpers.mjs';
import { fencedBlocks, isCommonJs, KINDS, label, missingOutput, promisedOutput } from './blocks.mjs';
import { buildProgram, installedPrefix } from './native.mjs';

const ROOT = fileURLToPath(new URL('../..', import.meta.url));
const DATA_FILES = ['intel.log', 'csail.log', 'rellis3d-os1-4x2048.bin'];
const TSC = join(ROOT, 'node_modules', 'typescript', 'bin', 'tsc');

const blocks = fencedBlocks(readFileSync(join(ROOT, 'README.md'), 'utf8'));
const ofKind = (kind) => blocks.filter((b) => KINDS[b.lang] === kind);

function checkRun(b, r) {
  assert.equal(r.error, undefined, `${label(b)}: ${r.error}`);
  assert.equal(r.status, 0, `${label(b)} exited with ${r.status ?? r.signal}:\n${r.stdout}${r.stderr}`);
  assert.equal(r.stderr, '', `${label(b)} wrote to stderr`);
  const missing = missingOutput(r.stdout, promisedOutput(b.code));
  assert.equal(missing, null, `${label(b)} should print "${missing}" (after the texts promised before it); it printed:\n${r.stdout}`);
}

test('every README code block has a language this test knows what to do with', (t) => {
  assert.ok(blocks.length >= 8, `${blocks.length} blocks`);
  for (const b of blocks) assert.ok(b.lang in KINDS, `${label(b)}: untagged or unknown language; tag it (and teach this test)`);
  for (const kind of ['run', 'native', 'cmake']) assert.ok(ofKind(kind).length >= 1, `no ${kind} block`);
  assert.ok(ofKind('native').every((b) => promisedOutput(b.code).length >= 1), 'each C++ example says what it prints');
  const notRun = [...ofKind('not run'), ...ofKind('cmake').filter((b) => !/find_package\(RTL\b/.test(b.code))];
  t.diagnostic(`not run (install/build commands, a browser page, a sub-project path): ${notRun.map(label).join('; ')}`);
});

describe('README examples in a project with the packed tarball installed', { timeout: 600_000 }, () => {
  let tmp, app;
  before(() => {
    tmp = mkdtempSync(join(tmpdir(), 'rtl-readme-'));
    ({ app } = packAndInstall(tmp));
    for (const f of DATA_FILES) copyFileSync(join(ROOT, 'tests', 'data', f), join(app, f));
  });
  after(() => rmSync(tmp, { recursive: true, force: true }));

  for (const b of ofKind('run')) {
    test(`${label(b)} runs with node`, () => {
      const file = join(app, `readme-${b.line}.${isCommonJs(b.code) ? 'cjs' : 'mjs'}`);
      writeFileSync(file, b.code);
      checkRun(b, spawnSync(process.execPath, [file], { cwd: app, encoding: 'utf8', timeout: 120_000 }));
    });
  }

  const ts = ofKind('typecheck');
  if (ts.length) {
    test(`the ${ts.length} TypeScript block(s) type-check (tsc --strict, nodenext)`, () => {
      const files = ts.map((b) => {
        const name = `readme-${b.line}.${isCommonJs(b.code) ? 'cts' : 'mts'}`;
        writeFileSync(join(app, name), b.code);
        return name;
      });
      writeFileSync(join(app, 'tsconfig.json'), JSON.stringify({
        compilerOptions: {
          target: 'es2022', lib: ['es2022', 'esnext.disposable', 'dom'], module: 'nodenext', moduleResolution: 'nodenext',
          strict: true, noEmit: true, skipLibCheck: false, types: [],
        },
        files,
      }));
      try {
        execFileSync(process.execPath, [TSC, '-p', 'tsconfig.json'], { cwd: app, encoding: 'utf8', stdio: 'pipe' });
      } catch (e) {
        assert.fail(`tsc on ${ts.map(label).join(', ')}:\n${e.stdout}${e.stderr}`);
      }
    });
  }

  describe('C++ blocks: complete programs against the installed CMake package', () => {
    let prefix, snippet;
    before(() => {
      const cmake = ofKind('cmake').filter((b) => /find_package\(RTL\b/.test(b.code));
      assert.equal(cmake.length, 1, 'the README has one ```cmake find_package snippet');
      snippet = cmake[0].code;
      prefix = installedPrefix(tmp);
    });
    for (const b of ofKind('native')) {
      test(`${label(b)} compiles, runs in the data folder and prints what it says`, () => {
        const exe = buildProgram(join(tmp, `cpp-${b.line}`), b.code, snippet, prefix);
        checkRun(b, spawnSync(exe, [], { cwd: app, encoding: 'utf8', timeout: 120_000 }));
      });
    }
  });
});
