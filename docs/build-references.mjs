#!/usr/bin/env node
// Builds the two API references that `./run serve` serves beside the page (web/serve.js maps /docs/js/ and
// /docs/cpp/ to them):
//   build/docs/js   TypeDoc from the package's shipped declarations (wasm/js/index.d.ts, ros/logs.d.ts,
//                   ros/messages.d.ts; configuration in docs/typedoc/)
//   build/docs/cpp  Doxygen from the headers' contracts (docs/Doxyfile)
// Both fail on any warning: a reference with a broken link or a malformed comment is not published.
//   node docs/build-references.mjs [js|cpp ...] [--out DIR]   (default: both, into build/docs)
// The functions are exported for the tests (tests/docs/).
import { spawnSync } from 'node:child_process';
import { existsSync, mkdirSync, readFileSync, rmSync } from 'node:fs';
import { join, resolve } from 'node:path';
import { fileURLToPath } from 'node:url';

const ROOT = fileURLToPath(new URL('..', import.meta.url));
const TYPEDOC_DIR = join(ROOT, 'docs', 'typedoc');
// TypeDoc sits in its own folder with the TypeScript release it supports (docs/typedoc/package.json says why);
// the root lock file installs it there.
const TYPEDOC_BIN = join(TYPEDOC_DIR, 'node_modules', 'typedoc', 'bin', 'typedoc');

/** Result of one build: the folder written, whether it succeeded, and every warning or error line. */
function result(out, status, problems) {
  return { out, ok: status === 0 && problems.length === 0, problems };
}

/**
 * TypeDoc into `out`. `overrides` are further command-line options (the tests document another declaration file
 * with them). TypeDoc's `treatWarningsAsErrors` (docs/typedoc/typedoc.json) makes any warning fail the build.
 */
export function buildJsReference(out, overrides = []) {
  if (!existsSync(TYPEDOC_BIN)) {
    return result(out, 1, [`TypeDoc is not installed (${TYPEDOC_BIN}); run npm ci in the repository root`]);
  }
  rmSync(out, { recursive: true, force: true });
  // The tsconfig is given here rather than in typedoc.json, so that `overrides` can replace it.
  const tsconfig = overrides.includes('--tsconfig') ? [] : ['--tsconfig', join(TYPEDOC_DIR, 'tsconfig.json')];
  const r = spawnSync(process.execPath, [TYPEDOC_BIN, '--options', join(TYPEDOC_DIR, 'typedoc.json'), ...tsconfig,
    '--out', out, '--logLevel', 'Warn', ...overrides], { cwd: ROOT, encoding: 'utf8', env: { ...process.env, NO_COLOR: '1' } });
  const problems = `${r.stdout ?? ''}${r.stderr ?? ''}`.split('\n').map((l) => l.trim()).filter(Boolean);
  if (r.error) problems.push(`typedoc: ${r.error.message}`);
  if (r.status === 0 && !existsSync(join(out, 'index.html'))) problems.push(`typedoc wrote no ${join(out, 'index.html')}`);
  return result(out, r.status, problems);
}

/** Doxygen with docs/Doxyfile, its HTML written to `out` itself (not to out/html). */
export function buildCppReference(out) {
  rmSync(out, { recursive: true, force: true });
  mkdirSync(out, { recursive: true });
  const warnings = join(out, 'doxygen-warnings.log');
  const config = `${readFileSync(join(ROOT, 'docs', 'Doxyfile'), 'utf8')}\n` +
    `OUTPUT_DIRECTORY = "${resolve(out, '..')}"\nHTML_OUTPUT = "${out}"\nWARN_LOGFILE = "${warnings}"\n`;
  const r = spawnSync('doxygen', ['-'], { cwd: ROOT, input: config, encoding: 'utf8' });
  if (r.error) return result(out, 1, [`doxygen: ${r.error.message} (apt-get install doxygen)`]);
  const problems = `${existsSync(warnings) ? readFileSync(warnings, 'utf8') : ''}${r.stderr ?? ''}`
    .split('\n').map((l) => l.trim()).filter(Boolean);
  rmSync(warnings, { force: true });  // not part of the served reference
  if (r.status === 0 && !existsSync(join(out, 'index.html'))) problems.push(`doxygen wrote no ${join(out, 'index.html')}`);
  return result(out, r.status, problems);
}

export const BUILDERS = { js: buildJsReference, cpp: buildCppReference };

const isMain = process.argv[1] && resolve(process.argv[1]) === fileURLToPath(import.meta.url);
if (isMain) {
  const args = process.argv.slice(2);
  const at = args.indexOf('--out');
  const outRoot = resolve(at >= 0 ? args.splice(at, 2)[1] ?? '' : join(ROOT, 'build', 'docs'));
  const which = args.length ? args : Object.keys(BUILDERS);
  let failed = false;
  for (const name of which) {
    if (!(name in BUILDERS)) {
      console.error(`build-references: unknown reference "${name}" (js or cpp)`);
      process.exit(2);
    }
    const r = BUILDERS[name](join(outRoot, name));
    if (r.ok) console.log(`${name} reference: ${join(r.out, 'index.html')}`);
    else {
      failed = true;
      console.error(`${name} reference failed:\n  ${r.problems.join('\n  ')}`);
    }
  }
  process.exit(failed ? 1 : 0);
}
