// `./run serve` builds both API references (docs/build-references.mjs) after the package and before it starts the
// server that serves them. Checked on the script itself: its install and build steps are replaced by markers, and a
// `node` first on PATH records what it is asked to run instead of running it.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { execFileSync } from 'node:child_process';
import { chmodSync, mkdtempSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { fileURLToPath } from 'node:url';

const ROOT = fileURLToPath(new URL('../..', import.meta.url));

test('./run serve: apt, npm, the wasm package, then the references, then the server', () => {
  const bin = mkdtempSync(join(tmpdir(), 'rtl-run-serve-'));
  try {
    writeFileSync(join(bin, 'node'), '#!/bin/sh\necho "node $*"\n');
    chmodSync(join(bin, 'node'), 0o755);
    const script = [
      'source ./run',
      'apt_install() { echo apt; }; npm_install() { echo npm; }; forget_moved_builds() { :; }; build_wasm() { echo wasm; }',
      'log() { :; }',
      `PATH="${bin}:$PATH" cmd_serve`,
    ].join('\n');
    const out = execFileSync('bash', ['-c', script], { cwd: ROOT, encoding: 'utf8' }).trim().split('\n');
    assert.deepEqual(out, ['apt', 'npm', 'wasm', 'node docs/build-references.mjs', 'node web/serve.js']);
  } finally {
    rmSync(bin, { recursive: true, force: true });
  }
});
