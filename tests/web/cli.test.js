// bin/rtl.js, the package's command-line tool: real scans in, JSON out, and clear errors with distinct exit codes
// (1 = bad data, 2 = bad usage). Numbers are checked against an independent plain-JavaScript TLS fit.
import { after, before, describe, test } from 'node:test';
import assert from 'node:assert/strict';
import { spawnSync } from 'node:child_process';
import { copyFileSync, mkdtempSync, readFileSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { packAndInstall } from '../js/helpers.mjs';
import { DATA, loadLog, REPO, returnsOf, runCli as rtl, sameLine, tlsFit, xyOf } from './helpers.js';

// Little-endian float32 x,y,z,intensity records of the organised binary scan, read independently of the package.
function binaryPoint(buf, k) {
  return [buf.readFloatLE(16 * k), buf.readFloatLE(16 * k + 4), buf.readFloatLE(16 * k + 8)];
}

describe('rtl CLI (bin/rtl.js)', { timeout: 120000 }, () => {
  let tmp;
  before(() => { tmp = mkdtempSync(join(tmpdir(), 'rtl-cli-')); });
  after(() => rmSync(tmp, { recursive: true, force: true }));

  test('--help describes the options and exits 0', () => {
    const r = rtl(['--help']);
    assert.equal(r.code, 0, r.err);
    assert.match(r.out, /^Usage: rtl \[options\] <file>/);
    for (const opt of ['--fit', '--segment', '--no-segment', '--raw', '--vectorize', '--sigma', '--epsilon', '--step', '--beams',
      '--format', '--output', '--max-range', '--strict']) {
      assert.ok(r.out.includes(opt), opt);
    }
    // The documented conventions: CAR's window, the default step, the JSON's half-open chain indices, split mode.
    assert.match(r.out, /up to N-1 previous points\s+\(default 2: consecutive points are linked/);
    assert.match(r.out, /"indices": \[begin, end\),\s+half-open\s+indices into its cluster's chain/);
    assert.match(r.out, /Default \(split mode\): the polyline breaks/);
  });

  test('the command works installed from the npm pack tarball (npx rtl; every file of bin/ is shipped)', { timeout: 120000 }, () => {
    const dir = mkdtempSync(join(tmpdir(), 'rtl-cli-pack-'));
    try {
      const { app } = packAndInstall(dir);
      copyFileSync(join(DATA, 'intel.log'), join(app, 'intel.log'));
      const r = spawnSync('npx', ['--offline', 'rtl', 'intel.log', '--scan', '5', '-m', 'dp', '-f', 'svg'], { cwd: app, encoding: 'utf8', timeout: 60000 });
      assert.equal(r.status, 0, r.stderr);
      assert.match(r.stdout, /^<\?xml[^>]*>\n<svg[\s\S]*>intel\.log scan 5; CAR step 2, bounds 0\.1-0\.5 m; DP epsilon 0\.09 m; /);
      assert.equal(r.stdout, rtl(['tests/data/intel.log', '--scan', '5', '-m', 'dp', '-f', 'svg']).out, 'the same figure as from the checkout');
    } finally {
      rmSync(dir, { recursive: true, force: true });
    }
  });

  test('--version prints the package version', () => {
    const pkg = JSON.parse(readFileSync(join(REPO, 'package.json'), 'utf8'));
    const r = rtl(['--version']);
    assert.equal(r.code, 0);
    assert.equal(r.out.trim(), pkg.version);
  });

  test('--no-segment --fit on a CARMEN scan: the TLS line of its returns (the raw chain), as an independent fit finds it', () => {
    const r = rtl(['tests/data/intel.log', '--scan', '4', '--no-segment', '--fit']);
    assert.equal(r.code, 0, r.err);
    const j = JSON.parse(r.out);
    const scans = loadLog('intel');
    const scan = scans[4];
    // (maxRange, the no-return value the reader used, is checked in cli-vectorize.test.js)
    const { maxRange, maxRangeSource, ...source } = j.source;
    assert.deepEqual(source, { type: 'carmen', file: 'tests/data/intel.log', scan: 4, scans: scans.length, line: scan.line, pose: { x: scan.x, y: scan.y, theta: scan.theta } });
    assert.equal(j.dim, 2);
    assert.equal(j.points, 180);
    const beams = returnsOf(scan);
    assert.equal(j.returns, beams.length);
    assert.deepEqual(j.chain, beams, 'the raw chain: the returns in scan order');
    assert.equal(j.fits.length, 1);
    const f = j.fits[0];
    const ref = tlsFit(xyOf(scan, beams));
    assert.equal(f.count, beams.length);
    assert.equal(f.cluster, null);
    assert.equal(f.first, beams[0]);
    assert.equal(f.last, beams[beams.length - 1]);
    assert.ok(sameLine(f, ref, 1e-9), `${JSON.stringify(f)} vs ${JSON.stringify(ref)}`);
    assert.ok(Math.abs(f.rms - ref.rms) < 1e-9);
    assert.ok(Math.abs(f.centroid[0] - ref.centroid[0]) < 1e-9 && Math.abs(f.centroid[1] - ref.centroid[1]) < 1e-9);
    assert.equal(j.segmentation, undefined);
    assert.equal(j.vectorization, undefined);
  });

  test('--fit on a CSV wall with alternating noise recovers the wall and the noise level exactly', () => {
    // y = 2 with +-1 cm alternating along x = 0..3 (symmetric, uncorrelated with x): line y = 2, RMS 1 cm.
    const rows = ['x,y  # header and comments are allowed'];
    [[0, 0.01], [1, -0.01], [2, -0.01], [3, 0.01]].forEach(([x, e]) => rows.push(`${x},${2 + e}`));
    rows.push('4,nan', '');
    const csv = join(tmp, 'wall.csv');
    writeFileSync(csv, rows.join('\n'));
    const r = rtl([csv, '--raw', '--fit', '-o', join(tmp, 'wall.json')]);
    assert.equal(r.code, 0, r.err);
    assert.equal(r.out, '');
    const j = JSON.parse(readFileSync(join(tmp, 'wall.json'), 'utf8'));
    assert.equal(j.points, 5);
    assert.equal(j.returns, 4, 'the NaN row is a gap');
    const f = j.fits[0];
    assert.ok(sameLine(f, { normal: [0, 1], offset: -2 }, 1e-9), JSON.stringify(f));
    assert.ok(Math.abs(f.rms - 0.01) < 1e-9, `rms ${f.rms}`);
  });

  test('--fit on one ring of the organised binary scan (3D): direction and centroid of its returns', () => {
    const buf = readFileSync(join(DATA, 'rellis3d-os1-4x2048.bin'));
    const r = rtl(['tests/data/rellis3d-os1-4x2048.bin', '--beams', '4', '--ring', '1', '--no-segment', '--fit']);
    assert.equal(r.code, 0, r.err);
    const j = JSON.parse(r.out);
    assert.equal(j.dim, 3);
    assert.equal(j.points, 2048);
    assert.deepEqual(j.source, { type: 'bin', file: 'tests/data/rellis3d-os1-4x2048.bin', beams: 4, columns: 2048, ring: 1 });
    const pts = [];
    for (let c = 0; c < 2048; c++) {
      const p = binaryPoint(buf, c * 4 + 1);
      if (p.some((v) => v !== 0)) pts.push(p);
    }
    assert.equal(j.returns, pts.length);
    const f = j.fits[0];
    assert.equal(f.count, pts.length);
    const mean = [0, 1, 2].map((d) => pts.reduce((s, p) => s + p[d], 0) / pts.length);
    mean.forEach((m, d) => assert.ok(Math.abs(f.centroid[d] - m) < 1e-6, `centroid ${f.centroid} vs ${mean}`));
    assert.ok(Math.abs(Math.hypot(...f.direction) - 1) < 1e-9);
    // The direction is the principal axis: no other unit direction has a larger spread (checked on a few).
    const spread = (u) => pts.reduce((s, p) => s + ((p[0] - mean[0]) * u[0] + (p[1] - mean[1]) * u[1] + (p[2] - mean[2]) * u[2]) ** 2, 0);
    const best = spread(f.direction);
    for (const u of [[1, 0, 0], [0, 1, 0], [0, 0, 1], [Math.SQRT1_2, Math.SQRT1_2, 0], [Math.SQRT1_2, -Math.SQRT1_2, 0]]) {
      assert.ok(best >= spread(u) * (1 - 1e-9), `spread along ${u}`);
    }
    // A column is a vertical profile of 4 points.
    const col = JSON.parse(rtl(['tests/data/rellis3d-os1-4x2048.bin', '--beams', '4', '--column', '100', '--no-segment', '--fit', '--min-points', '2']).out);
    assert.equal(col.points, 4);
    assert.equal(col.source.column, 100);
  });

  test('--fit as SVG (stdout) and as TikZ (a tikzpicture, or a standalone document with -o)', () => {
    let r = rtl(['tests/data/csail.log', '--scan', '3', '--no-segment', '--fit', '-f', 'svg']);
    assert.equal(r.code, 0, r.err);
    const scan = loadLog('csail')[3];
    assert.match(r.out, /^<\?xml[^>]*>\n<svg[\s>]/);
    assert.match(r.out, /<\/svg>\s*$/);
    // The title names the scan and what was done, not the file's path.
    assert.match(r.out, />csail\.log scan 3; not segmented; TLS line fit, min 3 points; \d+\.\d x \d+\.\d m<\/text>/);
    assert.equal((r.out.match(/<use href="#Mark[A-Z]+"/g) ?? []).length, returnsOf(scan).length, 'one dot per return');
    assert.equal(r.out.match(/<line /g).length, 1, 'the fitted line');
    r = rtl(['tests/data/csail.log', '--scan', '3', '--no-segment', '--fit', '-f', 'tikz']);
    assert.equal(r.code, 0, r.err);
    assert.doesNotMatch(r.out, /\\documentclass/);
    assert.match(r.out, /\\begin\{tikzpicture\}[\s\S]*\\end\{tikzpicture\}\s*$/);
    const out = join(tmp, 'fit.tex');
    r = rtl(['tests/data/csail.log', '--scan', '3', '--no-segment', '--fit', '-f', 'tikz', '--standalone', '-o', out]);
    assert.equal(r.code, 0, r.err);
    assert.equal(r.out, '');
    assert.match(readFileSync(out, 'utf8'), /^\\documentclass[\s\S]*\\begin\{tikzpicture\}[\s\S]*\\end\{document\}\s*$/);
  });

  test('reads points from standard input with --type', () => {
    const r = rtl(['-', '--type', 'csv', '--no-segment', '--fit'], '0 0\n1 1\n2 2\n3 3\n');
    assert.equal(r.code, 0, r.err);
    const f = JSON.parse(r.out).fits[0];
    assert.ok(sameLine(f, { normal: [Math.SQRT1_2, -Math.SQRT1_2], offset: 0 }, 1e-12), JSON.stringify(f));
    assert.ok(f.rms < 1e-12);
  });

  // Each bad invocation: exit code, and a message naming the problem; nothing on stdout.
  const bad = [
    [[], 2, /missing input file/],
    [['tests/data/intel.log', '--bogus'], 2, /^rtl: unknown option --bogus\n/],
    [['tests/data/intel.log', '--scna', '3'], 2, /^rtl: unknown option --scna \(did you mean --scan\?\)/],
    [['tests/data/intel.log', '-x'], 2, /^rtl: unknown option -x\n/],
    [['tests/data/intel.log', '--scan', '-1'], 2, /^rtl: --scan must be >= 0, got "-1"/],
    [['tests/data/intel.log', '--scan'], 2, /^rtl: --scan needs a value/],
    [['tests/data/intel.log', '--scan', '--fit'], 2, /^rtl: --scan needs a value/],
    [['tests/data/intel.log', '-m'], 2, /^rtl: -m \(--vectorize\) needs a value/],
    [['tests/data/intel.log', '--fit=yes'], 2, /^rtl: --fit takes no value/],
    [['tests/data/intel.log', '--scan', '1', '--scan', '2'], 2, /^rtl: --scan is given more than once/],
    [['tests/data/intel.log', '--max-range', 'far'], 2, /^rtl: --max-range must be a number, got "far"/],
    [['tests/data/intel.log', '--max-range', '0'], 2, /^rtl: --max-range must be > 0/],
    [['tests/data/intel.log', '--no-segment'], 2, /^rtl: --no-segment needs --fit or --vectorize/],
    [['tests/data/intel.log', '--raw', '--step', '3', '--fit'], 2, /^rtl: --step applies to segmentation, not with --raw/],
    [['tests/data/intel.log', '-s', '--no-segment', '--fit'], 2, /^rtl: --segment and --no-segment contradict each other/],
    [['tests/data/intel.log', '--strict'], 2, /^rtl: --strict applies to --vectorize ftls or aftls only/],
    [['tests/data/intel.log', '--strict', '-m', 'dp'], 2, /^rtl: --strict applies to --vectorize ftls or aftls only/],
    [['pts.csv', '--max-range', '5', '--fit'], 2, /^rtl: --max-range applies to CARMEN logs only/],
    [['tests/data/intel.log', '--step', 'NaN'], 2, /^rtl: --step must be a number, got "NaN"/],
    // Values only the package can bound (what its segmenters and optimizer hold) name the command's option too.
    [['tests/data/intel.log', '--step', '1e12'], 2, /^rtl: --step must be <= \d+, got 1000000000000\n/],
    [['tests/data/intel.log', '--segmenter', 'ia', '--step', '1e9'], 2, /^rtl: --step must be <= \d+, got 1000000000\n/],
    [['tests/data/intel.log', '-m', 'aftls', '--max-iterations', '1e20'], 2, /^rtl: --max-iterations must be <= \d+/],
    [['tests/data/intel.log', '--sigma', '1e999', '-m', 'itls'], 2, /^rtl: --sigma must be a number, got "1e999"/],
    [['a.csv', 'b.csv'], 2, /expected one input file, got 2/],
    [['tests/data/intel.log', '-m', 'magic'], 2, /--vectorize must be one of ftls, aftls, itls, dp, rw/],
    [['tests/data/intel.log', '--sigma=-1', '-m', 'ftls'], 2, /--sigma must be > 0, got "-1"/],
    [['tests/data/intel.log', '--epsilon', '0', '-m', 'dp'], 2, /--epsilon must be > 0/],
    [['tests/data/intel.log', '--step', 'two'], 2, /--step must be a number/],
    [['tests/data/intel.log', '--step', '1.5'], 2, /--step must be an integer/],
    [['tests/data/intel.log', '--lower', '2', '--upper', '1'], 2, /--lower .* must not exceed --upper/],
    [['tests/data/intel.log', '-f', 'pdf'], 2, /--format must be one of json, svg, tikz/],
    [['tests/data/intel.log', '--beams', '4'], 2, /--beams applies to binary scans only/],
    [['tests/data/intel.log', '--standalone'], 2, /--standalone applies to --format tikz only/],
    [['tests/data/rellis3d-os1-4x2048.bin', '--beams', '4', '--fit', '-f', 'svg'], 2, /--format svg draws 2D data only/],
    [['points.dat'], 2, /cannot tell the input type.*--type/],
    [['tests/data/rellis3d-os1-4x2048.bin'], 2, /needs --beams/],
    [['tests/data/rellis3d-os1-4x2048.bin', '--beams', '4', '--ring', '1', '--column', '2'], 2, /either --ring or --column/],
    [['tests/data/no-such-file.log', '--fit'], 1, /cannot read "tests\/data\/no-such-file.log": no such file/],
    [['tests/data/intel.log', '--scan', '99', '--fit'], 1, /--scan 99 is out of range, the log has 30 scans/],
    [['tests/data/rellis3d-os1-4x2048.bin', '--beams', '4', '--ring', '4', '--fit'], 1, /--ring 4 is out of range, the scan has 4 beams/],
    [['tests/data/rellis3d-os1-4x2048.bin', '--beams', '3', '--fit'], 1, /3 beams/],
  ];
  for (const [args, code, message] of bad) {
    test(`fails clearly: rtl ${args.join(' ') || '(no arguments)'}`, () => {
      const r = rtl(args);
      assert.equal(r.code, code, r.err);
      assert.match(r.err, message);
      assert.match(r.err, /^rtl: /, 'the package\'s own message');
      if (code === 2) assert.match(r.err, /\nTry 'rtl --help' for more information\.\n$/);
      assert.equal(r.out, '');
      assert.ok(!/\n\s+at .*:\d+:\d+/.test(r.err), `no stack trace: ${r.err}`);
    });
  }

  test('fails with exit 1 on a corrupt CARMEN line, naming the line', () => {
    const f = join(tmp, 'bad.log');
    writeFileSync(f, '# comment\nFLASER 180 1.0 1.1 oops\n');
    const r = rtl([f, '--fit']);
    assert.equal(r.code, 1, r.err);
    assert.match(r.err, /line 2/);
  });

  test('fails with exit 1 on a CSV with a non-number or a ragged row, naming the line', () => {
    const f = join(tmp, 'bad.csv');
    writeFileSync(f, 'x,y\n0,0\n1,zero\n');
    let r = rtl([f, '--fit']);
    assert.equal(r.code, 1);
    assert.match(r.err, /bad\.csv:3: "zero" is not a number/);
    writeFileSync(f, '0,0\n1,1\n2,2,2\n');
    r = rtl([f, '--fit']);
    assert.equal(r.code, 1);
    assert.match(r.err, /bad\.csv:3: expected 2 coordinates like the lines before, got 3/);
  });

  test('fails with exit 1 on a truncated binary scan', () => {
    const f = join(tmp, 'short.bin');
    writeFileSync(f, Buffer.alloc(16 * 4 * 3 + 5));
    const r = rtl([f, '--beams', '4', '--fit']);
    assert.equal(r.code, 1);
    assert.match(r.err, /short\.bin/);
    assert.ok(!/\n\s+at .*:\d+:\d+/.test(r.err), `message without a stack trace: ${r.err}`);
  });
});
