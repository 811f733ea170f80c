// Shared helpers of the package tests (tests/js): tolerant comparisons and reference data.
import assert from 'node:assert/strict';
import { execFileSync } from 'node:child_process';
import { existsSync, mkdirSync, mkdtempSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join, resolve } from 'node:path';
import { fileURLToPath } from 'node:url';

export function near(actual, expected, tol, what = 'value') {
  assert.ok(Math.abs(actual - expected) <= tol, `${what}: ${actual} differs from ${expected} by more than ${tol}`);
}

export function nearArray(actual, expected, tol, what = 'array') {
  assert.equal(actual.length, expected.length, `${what}: length`);
  for (let i = 0; i < expected.length; i++) near(actual[i], expected[i], tol, `${what}[${i}]`);
}

// Points on the line y = 2x + 1, each one moved by +d and -d along the unit normal: the TLS line is exactly
// -2x + y - 1 = 0 (normalised), the RMS orthogonal residual exactly d, the centroid (0, 1).
export function offsetLinePoints(d = 0.05) {
  const s = Math.sqrt(5);
  const n = [-2 / s, 1 / s];
  const xy = [];
  for (let t = -4.5; t <= 4.5; t += 1) {
    for (const k of [1, -1]) xy.push(t + k * d * n[0], 2 * t + 1 + k * d * n[1]);
  }
  return { xy: new Float64Array(xy), normal: n, offset: -1 / s, rms: d, centroid: [0, 1] };
}

// The paper's noisy semicircle (radius 8, uniform noise of width 0.01 per coordinate) of n points, x and y
// interleaved; the noise comes from a linear congruential generator started at `seed`, so a seed names a data set.
export function noisySemicircle(n, seed) {
  let s = seed >>> 0;
  const rnd = () => ((s = (Math.imul(s, 1664525) + 1013904223) >>> 0) / 4294967296);
  const xy = new Float64Array(2 * n);
  for (let i = 0; i < n; i++) {
    const a = (Math.PI * i) / (n - 1);
    xy[2 * i] = 8 * Math.cos(a) + 0.01 * (rnd() - 0.5);
    xy[2 * i + 1] = 8 * Math.sin(a) + 0.01 * (rnd() - 0.5);
  }
  return xy;
}

// The module's memory now: malloc heap in use, linear memory size and stack pointer. unchanged() asserts all three are
// where they were (a call that leaks, grows memory or leaves the stack moved fails). Take it after a warm-up call of
// each kind, since a first call may allocate lazily initialised state.
export function memoryProbe(rtl) {
  const heap = rtl.heapInUse(), mem = rtl.memoryBytes(), sp = rtl.stackPointer();
  return {
    unchanged() {
      assert.equal(rtl.heapInUse(), heap, 'malloc heap in use');
      assert.equal(rtl.memoryBytes(), mem, 'linear memory size');
      assert.equal(rtl.stackPointer(), sp, 'stack pointer');
    },
  };
}

// Assert that f() throws an error of class `type` whose message matches `re`.
export function throwsWith(f, type, re) {
  assert.throws(f, (e) => {
    assert.equal(e.constructor, type, `expected ${type.name}, got ${e.constructor.name}: ${e.message}`);
    assert.match(e.message, re);
    return true;
  });
}

// `npm pack` of this repository into `dir`, then an offline `npm install` of the tarball into the empty project
// `dir/app` (the package has no dependencies), as a user would install it. Returns { app, tarball, pack }, where
// pack is npm's JSON report of the tarball (files, version).
export function packAndInstall(dir) {
  const root = fileURLToPath(new URL('../..', import.meta.url));
  const npm = (args, cwd) => execFileSync('npm', args, { cwd, encoding: 'utf8', stdio: ['ignore', 'pipe', 'pipe'] });
  const [pack] = JSON.parse(npm(['pack', '--json', '--pack-destination', dir], root));
  const app = join(dir, 'app');
  mkdirSync(app);
  writeFileSync(join(app, 'package.json'), JSON.stringify({ name: 'app', version: '1.0.0', private: true }));
  const tarball = join(dir, pack.filename);
  npm(['install', '--no-audit', '--no-fund', '--offline', tarball], app);
  return { app, tarball, pack };
}

// A native helper program of tests/tools ($RTL_NATIVE_BUILD_DIR/tools, default build/native) as a function of its
// arguments: arrays and typed arrays go in temporary .f64 files (empty ones as '-'), other values as text; returns
// the program's stdout.
export function nativeTool(name) {
  const root = fileURLToPath(new URL('../..', import.meta.url));
  const tool = join(resolve(root, process.env.RTL_NATIVE_BUILD_DIR || 'build/native'), 'tools', name);
  assert.ok(existsSync(tool), `${tool} missing: build the native tree (cmake --build <dir> --target ${name})`);
  const dir = mkdtempSync(join(tmpdir(), `rtl-${name}-`));
  process.on('exit', () => rmSync(dir, { recursive: true, force: true }));
  let files = 0;
  const arg = (a) => {
    if (typeof a !== 'object' || a === null) return String(a);
    if (a.length === 0) return '-';
    const f = join(dir, `a${files++}.f64`);
    writeFileSync(f, Float64Array.from(a));
    return f;
  };
  return (...args) => execFileSync(tool, args.map(arg), { encoding: 'utf8', maxBuffer: 1 << 28 });
}

// One scan as the CLI and the page draw it: segmented by the package (defaults), every cluster of at least 3 points
// simplified by Douglas–Peucker; { points, labels, segments, title } for toSvg / toTikz.
export function scanDrawing(rtl, points, title) {
  const seg = rtl.segment(points);
  const segments = [];
  for (const c of seg.clusters) {
    if (c.indices.length < 3) continue;
    const xy = new Float64Array(2 * c.indices.length);
    c.indices.forEach((i, j) => { xy[2 * j] = points[2 * i]; xy[2 * j + 1] = points[2 * i + 1]; });
    segments.push(...rtl.vectorize(xy, { method: 'dp' }).segments);
  }
  return { points, labels: seg.labels, segments, title };
}

/** A scan of n beams around the sensor: walls at 2-12 m that change every `wallBeams` beams, no return (NaN) every
 * `gapEvery` beams; interleaved x, y. */
export function wallRing(n, wallBeams = 300, gapEvery = 89) {
  const xy = new Float64Array(2 * n);
  for (let i = 0; i < n; i++) {
    const a = (2 * Math.PI * i) / n, r = 2 + ((Math.floor(i / wallBeams) * 7) % 11);
    xy[2 * i] = i % gapEvery === 0 ? NaN : r * Math.cos(a);
    xy[2 * i + 1] = i % gapEvery === 0 ? NaN : r * Math.sin(a);
  }
  return xy;
}
