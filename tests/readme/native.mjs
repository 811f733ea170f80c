// The README's C++ examples as a user builds them: against the INSTALLED CMake package (RTL_INSTALL_PREFIX, which
// `./run test` sets to its build/install, or a `cmake --install` of a fresh native configure into a temp prefix),
// with a CMakeLists.txt made of a minimal project line, the example as main.cpp and the README's find_package
// snippet, exactly as printed.
import { execFileSync } from 'node:child_process';
import { existsSync, mkdirSync, writeFileSync } from 'node:fs';
import { join } from 'node:path';
import { fileURLToPath } from 'node:url';

const ROOT = fileURLToPath(new URL('../..', import.meta.url));

function run(cmd, args, cwd) {
  try {
    return execFileSync(cmd, args, { cwd, encoding: 'utf8', stdio: ['ignore', 'pipe', 'pipe'], maxBuffer: 64 << 20 });
  } catch (e) {
    throw new Error(`${cmd} ${args.join(' ')} failed (exit ${e.status}):\n${e.stdout ?? ''}${e.stderr ?? ''}`);
  }
}

// The prefix holding lib/cmake/RTL (or share/...), installing one into `tmp` unless RTL_INSTALL_PREFIX names one.
export function installedPrefix(tmp) {
  if (process.env.RTL_INSTALL_PREFIX) {
    const prefix = process.env.RTL_INSTALL_PREFIX;
    if (!existsSync(join(prefix, 'include', 'rtl'))) throw new Error(`RTL_INSTALL_PREFIX=${prefix} holds no include/rtl`);
    return prefix;
  }
  const build = join(tmp, 'rtl-configure'), prefix = join(tmp, 'rtl-prefix');
  run('cmake', ['-S', ROOT, '-B', build, '-DCMAKE_BUILD_TYPE=Release', '-DRTL_BUILD_TESTS=OFF', '-DRTL_BUILD_EXAMPLES=OFF',
    '-DRTL_BUILD_BENCHMARKS=OFF', '-DRTL_BUILD_WASM=OFF', '-DRTL_INSTALL=ON'], tmp);
  run('cmake', ['--install', build, '--prefix', prefix], tmp);
  return prefix;
}

// Builds `code` as the executable `app` of a project using `snippet`; returns the executable's path.
export function buildProgram(dir, code, snippet, prefix) {
  mkdirSync(dir, { recursive: true });
  writeFileSync(join(dir, 'main.cpp'), code);
  writeFileSync(join(dir, 'CMakeLists.txt'),
    `cmake_minimum_required(VERSION 3.16)\nproject(readme_example LANGUAGES CXX)\nadd_executable(app main.cpp)\n${snippet}`);
  const build = join(dir, 'build');
  run('cmake', ['-S', dir, '-B', build, '-DCMAKE_BUILD_TYPE=Release', `-DCMAKE_PREFIX_PATH=${prefix}`], dir);
  run('cmake', ['--build', build], dir);
  return join(build, 'app');
}
