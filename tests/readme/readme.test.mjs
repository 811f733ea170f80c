// Every code block of README.md and of the guides it links (docs/guide-cpp.md, docs/guide-js.md) runs as written,
// where a user would run it:
//   ```js        an .mjs file (a `.cjs` one when its first line is `// CommonJS`) run with node in an empty project
//                where the `npm pack` tarball of this repository is installed with the optional peer dependencies that
//                read robot logs, next to copies of tests/data's intel.log, csail.log and rellis3d-os1-4x2048.bin and
//                robot.mcap (tests/data's Intel scans on /scan, written by @mcap/core's McapWriter); it must exit 0 (and
//                print nothing on stderr)
//   ```ts        type-checked with the repository's tsc (strict, nodenext) in that project
//   ```cpp       a complete program, compiled against the installed CMake package with a CMakeLists.txt that uses the
//                README's ```cmake find_package snippet, run in the data folder; it must exit 0
//   ```cmake     the find_package snippet is used by the C++ programs; the sub-project block is not run (it names a
//                path or URL of the user's)
//   ```bash      a block of `npx rtl ...` lines only: each line runs with the installed package's command in that project
//                (tests/data/ holds the logs and bags, points.csv a noisy line y = x/2 + 1, logs/ two MCAPs): exit 0,
//                the JSON (or each JSON line) parses, each SVG is one <svg> document, the --fit line is y = x/2 + 1;
//                other bash blocks (install/build) are not run
//   ```html      not run: the import map needs a page and a server
// A block that prints results says what with `// prints: <text>` comments; the output must contain each text, in order.
import { after, before, describe, test } from 'node:test';
import assert from 'node:assert/strict';
import { execFileSync, spawnSync } from 'node:child_process';
import { copyFileSync, cpSync, existsSync, mkdirSync, mkdtempSync, readdirSync, readFileSync, rmSync, symlinkSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { dirname, join } from 'node:path';
import { fileURLToPath } from 'node:url';
import { packAndInstall } from '../js/helpers.mjs';
import { laserScanOf, writeMcap } from '../js/ros-fixtures.mjs';
import { cliCommands, fencedBlocks, isCommonJs, KINDS, label, missingOutput, promisedOutput } from './blocks.mjs';
import { buildProgram, installedPrefix } from './native.mjs';

const ROOT = fileURLToPath(new URL('../..', import.meta.url));
const DATA_FILES = ['intel.log', 'csail.log', 'rellis3d-os1-4x2048.bin'];
const TSC = join(ROOT, 'node_modules', 'typescript', 'bin', 'tsc');

// The README and the guides whose examples moved out of it.
const DOCS = ['README.md', 'docs/guide-cpp.md', 'docs/guide-js.md'];
// rtl-wasm/logs's optional peer dependencies (the README's install line), linked from this repository's node_modules.
const LOG_PEERS = ['@mcap/core', '@mcap/support', '@foxglove/rosmsg', '@foxglove/rosmsg2-serialization',
  '@foxglove/rosmsg-serialization', '@foxglove/rosbag'];

const blocks = DOCS.flatMap((file) => fencedBlocks(readFileSync(join(ROOT, file), 'utf8'), file));
const fileName = (b, ext) => `${b.file.replace(/\W+/g, '-')}-${b.line}.${ext}`;
const ofKind = (kind) => blocks.filter((b) => KINDS[b.lang] === kind);

// One SVG document with the scan's points drawn.
function checkSvg(text, what) {
  assert.match(text, /^<\?xml [^>]*>\n<svg [^>]*>[^]*<\/svg>\n$/, `${what}: one SVG document`);
  assert.ok((text.match(/<use /g) ?? []).length >= 100, `${what}: the scan's points are drawn`);
}

// What the shell makes of a command-line argument with a `*` in its file name (`logs/*.mcap`), sorted as bash does.
function expandGlob(cwd, arg) {
  if (!arg.includes('*')) return [arg];
  const dir = dirname(arg), name = arg.slice(dir.length + 1);
  const pattern = new RegExp(`^${name.split('*').map((p) => p.replace(/[.+?^${}()|[\]\\]/g, '\\$&')).join('.*')}$`);
  const matches = readdirSync(join(cwd, dir)).filter((f) => pattern.test(f)).sort().map((f) => `${dir}/${f}`);
  assert.ok(matches.length > 0, `${arg} matches no file`);
  return matches;
}

function checkRun(b, r) {
  assert.equal(r.error, undefined, `${label(b)}: ${r.error}`);
  assert.equal(r.status, 0, `${label(b)} exited with ${r.status ?? r.signal}:\n${r.stdout}${r.stderr}`);
  assert.equal(r.stderr, '', `${label(b)} wrote to stderr`);
  const missing = missingOutput(r.stdout, promisedOutput(b.code));
  assert.equal(missing, null, `${label(b)} should print "${missing}" (after the texts promised before it); it printed:\n${r.stdout}`);
}

test('every code block of the README and the guides has a language this test knows what to do with', (t) => {
  assert.ok(blocks.length >= 8, `${blocks.length} blocks`);
  for (const b of blocks) assert.ok(b.lang in KINDS, `${label(b)}: untagged or unknown language; tag it (and teach this test)`);
  for (const kind of ['run', 'native', 'cmake']) assert.ok(ofKind(kind).length >= 1, `no ${kind} block`);
  assert.ok(ofKind('native').every((b) => promisedOutput(b.code).length >= 1), 'each C++ example says what it prints');
  assert.ok(ofKind('not run').some((b) => cliCommands(b.code)), 'the command-line block (npx rtl lines) is found');
  const notRun = [...ofKind('not run').filter((b) => !cliCommands(b.code)), ...ofKind('cmake').filter((b) => !/find_package\(RTL\b/.test(b.code))];
  t.diagnostic(`not run (install/build commands, a browser page, a sub-project path): ${notRun.map(label).join('; ')}`);
});

// GitHub's anchor of a heading: lower case, punctuation dropped, spaces to hyphens.
const slug = (heading) => heading.trim().toLowerCase().replace(/[^\p{L}\p{N}\s_-]/gu, '').replace(/\s/g, '-');

test('the README and the guides name files that exist: links (with their headings) and `path/file.ext` in code spans', () => {
  let checked = 0;
  for (const file of DOCS) {
    const text = readFileSync(join(ROOT, file), 'utf8');
    for (const [, target] of text.matchAll(/\]\(([^)\s]+)\)/g)) {
      if (/^[a-z]+:/.test(target)) continue;   // an absolute URL
      const [path, anchor] = target.split('#');
      const resolved = join(ROOT, dirname(file), path);
      assert.ok(existsSync(resolved), `${file}: link to ${target}: no ${path}`);
      if (anchor) {
        const headings = [...readFileSync(resolved, 'utf8').matchAll(/^#{1,6}\s+(.*)$/gm)].map((m) => slug(m[1]));
        assert.ok(headings.includes(anchor), `${file}: link to ${target}: no heading #${anchor} (${headings.join(', ')})`);
      }
      checked++;
    }
    // Code spans that name a file of the repository (`web/figure.js`, `rtl/io/Svg2D.h` under include/).
    for (const [, path] of text.matchAll(/`((?:docs|tests|web|wasm|bin|bench|examples|rtl)\/[\w./-]+\.\w+)`/g)) {
      assert.ok(existsSync(join(ROOT, path)) || existsSync(join(ROOT, 'include', path)), `${file}: \`${path}\` does not exist`);
      checked++;
    }
  }
  assert.ok(checked >= 40, `${checked} names checked`);
});

describe('README examples in a project with the packed tarball installed', { timeout: 600_000 }, () => {
  let tmp, app;
  before(async () => {
    tmp = mkdtempSync(join(tmpdir(), 'rtl-readme-'));
    ({ app } = packAndInstall(tmp));
    for (const f of DATA_FILES) copyFileSync(join(ROOT, 'tests', 'data', f), join(app, f));
    for (const peer of LOG_PEERS) {
      mkdirSync(dirname(join(app, 'node_modules', peer)), { recursive: true });
      symlinkSync(join(ROOT, 'node_modules', peer), join(app, 'node_modules', peer), 'dir');
    }
    // A user's MCAP: the Intel scans as sensor_msgs/msg/LaserScan on /scan; logs/ holds two more for the CLI's glob.
    const rtl = await (await import('rtl-wasm')).default();
    const intel = rtl.readCarmenLog(readFileSync(join(ROOT, 'tests', 'data', 'intel.log')));
    const scanChannel = (scans) => [{ topic: '/scan', type: 'sensor_msgs/msg/LaserScan',
      messages: scans.map((s) => ({ time: s.timestamp, msg: laserScanOf(s) })) }];
    await writeMcap(join(app, 'robot.mcap'), scanChannel(intel), { compression: 'lz4', chunkSize: 8 * 1024 });
    mkdirSync(join(app, 'logs'));
    await writeMcap(join(app, 'logs', 'a.mcap'), scanChannel(intel.slice(0, 10)), { compression: 'zstd' });
    await writeMcap(join(app, 'logs', 'b.mcap'), scanChannel(intel.slice(10)));
  });
  after(() => rmSync(tmp, { recursive: true, force: true }));

  for (const b of ofKind('run')) {
    test(`${label(b)} runs with node`, () => {
      const file = join(app, fileName(b, isCommonJs(b.code) ? 'cjs' : 'mjs'));
      writeFileSync(file, b.code);
      checkRun(b, spawnSync(process.execPath, [file], { cwd: app, encoding: 'utf8', timeout: 120_000 }));
    });
  }

  for (const b of ofKind('not run').filter((x) => cliCommands(x.code))) {
    test(`${label(b)}: every \`npx rtl\` line runs with the installed command`, () => {
      mkdirSync(join(app, 'tests', 'data'), { recursive: true });
      for (const f of DATA_FILES) copyFileSync(join(app, f), join(app, 'tests', 'data', f));
      cpSync(join(ROOT, 'tests', 'data', 'ros1'), join(app, 'tests', 'data', 'ros1'), { recursive: true });
      // A noisy line y = x/2 + 1 (deterministic noise of +-0.01).
      const csv = Array.from({ length: 50 }, (_, i) => `${(i * 0.1).toFixed(3)},${(0.05 * i + 1 + 0.01 * Math.sin(7 * i)).toFixed(5)}`);
      writeFileSync(join(app, 'points.csv'), `${csv.join('\n')}\n`);
      const rtlBin = join(app, 'node_modules', '.bin', 'rtl');
      for (const { args, output } of cliCommands(b.code)) {
        const line = `npx rtl ${args.join(' ')}${output ? ` > ${output}` : ''}`;
        const r = spawnSync(rtlBin, args.flatMap((arg) => expandGlob(app, arg)), { cwd: app, encoding: 'utf8', timeout: 120_000 });
        assert.equal(r.status, 0, `${label(b)}: \`${line}\` exited with ${r.status ?? r.signal}:\n${r.stderr}`);
        const outputOption = args.findIndex((arg) => arg === '-o' || arg === '--output');
        const written = outputOption >= 0 ? args[outputOption + 1] : null;
        const isSvg = args.includes('svg');
        if (written?.includes('%d')) {   // one file per scan: the log's 30 Intel scans
          const pattern = new RegExp(`^${written.replace('%d', '\\d+').replace(/\./g, '\\.')}$`);
          const files = readdirSync(app).filter((f) => pattern.test(f));
          assert.equal(files.length, 30, `${line}: ${files.length} pictures`);
          for (const f of files) checkSvg(readFileSync(join(app, f), 'utf8'), `${line}: ${f}`);
          continue;
        }
        const text = written ? readFileSync(join(app, written), 'utf8') : r.stdout;
        if (isSvg) {
          checkSvg(text, line);
          continue;
        }
        if ((written ?? output ?? '').endsWith('.jsonl')) {   // a log: one JSON line per scan, in log order
          const scans = text.trim().split('\n').map((l) => JSON.parse(l));
          assert.equal(scans.length, 30, `${line}: ${scans.length} scans`);
          for (const scan of scans) {
            assert.equal(scan.points, 180, `${line}: an Intel scan has 180 beams`);
            if (args.includes('-m')) assert.ok(scan.vectorization.segments.length >= 1, `${line}: scan ${scan.source.index} has segments`);
          }
          continue;
        }
        const json = JSON.parse(text);
        if (args.includes('--strict')) {
          const { failed } = json.vectorization;
          assert.ok(Array.isArray(failed) && failed.length >= 1, `${line}: lists the clusters strict AFTLS rejects`);
          assert.ok(failed.every((f) => typeof f.cluster === 'number' && f.crossingDistance > f.delta), `${line}: each failure names its cluster`);
        }
        if (args.includes('--fit')) {
          const [fit] = json.fits;
          assert.equal(fit.count, 50, line);
          assert.ok(Math.abs(fit.direction[1] / fit.direction[0] - 0.5) < 2e-3, `${line}: slope ${fit.direction[1] / fit.direction[0]}`);
          assert.ok(fit.rms < 0.01, `${line}: rms ${fit.rms}`);
        }
      }
    });
  }

  const ts = ofKind('typecheck');
  if (ts.length) {
    test(`the ${ts.length} TypeScript block(s) type-check (tsc --strict, nodenext)`, () => {
      const files = ts.map((b) => {
        const name = fileName(b, isCommonJs(b.code) ? 'cts' : 'mts');
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
        const exe = buildProgram(join(tmp, fileName(b, 'cpp')), b.code, snippet, prefix);
        checkRun(b, spawnSync(exe, [], { cwd: app, encoding: 'utf8', timeout: 120_000 }));
      });
    }
  });
});
