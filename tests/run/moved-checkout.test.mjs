// ./run must work from any folder a checkout is copied or moved to: a build folder whose CMake cache names another
// source path is forgotten (CMake would refuse it), while build folders of this checkout are kept.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { execFileSync } from 'node:child_process';
import { cpSync, existsSync, mkdtempSync, mkdirSync, renameSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { fileURLToPath } from 'node:url';

const RUN = fileURLToPath(new URL('../../run', import.meta.url));
const sh = (cwd, script) => execFileSync('bash', ['-c', script], { cwd, encoding: 'utf8' });

test('a moved checkout reconfigures the build folders that name the old path, and keeps its own', () => {
  const tmp = mkdtempSync(join(tmpdir(), 'rtl-moved-'));
  try {
    const before = join(tmp, 'before');
    mkdirSync(join(before, 'project'), { recursive: true });
    cpSync(RUN, join(before, 'run'));
    writeFileSync(join(before, 'project', 'CMakeLists.txt'), 'cmake_minimum_required(VERSION 3.16)\nproject(p NONE)\n');
    sh(before, 'cmake -S project -B build/a >/dev/null');
    const after = join(tmp, 'after folder');   // a space in the path too
    renameSync(before, after);
    // CMake itself refuses the moved cache: this is what ./run has to deal with.
    assert.throws(() => sh(after, 'cmake -S project -B build/a 2>&1'), (e) => /does not match the source/.test(e.stdout));
    sh(after, 'source ./run && forget_moved_builds');
    assert.equal(existsSync(join(after, 'build', 'a')), false);
    sh(after, 'cmake -S project -B build/b >/dev/null');
    sh(after, 'source ./run && forget_moved_builds');
    assert.equal(existsSync(join(after, 'build', 'b', 'CMakeCache.txt')), true, 'a build folder of this checkout is kept');
    sh(after, 'cmake -S project -B build/a >/dev/null');   // and the forgotten one configures afresh
  } finally {
    rmSync(tmp, { recursive: true, force: true });
  }
});
