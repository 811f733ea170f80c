// Shared helpers for the page, Vite and CLI tests: a server on a free port, a headless Debian Chromium, the demo page
// opened in it, the CLI run as a child process, and an independent (pure JavaScript, no wasm) CARMEN parser and
// total-least-squares fit to check the page's numbers against.
import { spawn, spawnSync } from 'node:child_process';
import { mkdirSync, mkdtempSync, readFileSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { dirname, join, resolve } from 'node:path';
import { fileURLToPath } from 'node:url';

export const REPO = resolve(dirname(fileURLToPath(import.meta.url)), '..', '..');
export const DATA = join(REPO, 'tests', 'data');
export const RESULTS = join(REPO, 'test-results');
export const CHROMIUM = process.env.RTL_CHROMIUM || '/usr/bin/chromium';

// Headless flags for CI: no sandbox (root in CI), no GPU, no network chatter or updates.
export const CHROMIUM_ARGS = ['--headless', '--no-sandbox', '--disable-gpu', '--disable-quic', '--no-first-run',
  '--disable-background-networking', '--disable-component-update', '--disable-sync'];

export function resultsDir() {
  mkdirSync(RESULTS, { recursive: true });
  return RESULTS;
}

// Starts web/serve.js on a free port (PORT=0) and resolves with its URL once it printed it; close() kills it by PID.
export function startServer({ root } = {}) {
  const env = { ...process.env, PORT: '0' };
  if (root) env.RTL_SERVE_ROOT = root;
  else delete env.RTL_SERVE_ROOT;
  const child = spawn(process.execPath, [join(REPO, 'web', 'serve.js')], { env, stdio: ['ignore', 'pipe', 'pipe'] });
  let stderr = '';
  child.stderr.on('data', (d) => { stderr += d; });
  const close = () => new Promise((res) => {
    if (child.exitCode !== null || child.signalCode !== null) return res();
    child.once('exit', () => res());
    child.kill('SIGTERM');
  });
  return new Promise((res, rej) => {
    let out = '';
    const timer = setTimeout(() => { close(); rej(new Error(`serve.js did not start: ${stderr}`)); }, 10000);
    child.stdout.on('data', (d) => {
      out += d;
      const m = out.match(/^(http:\/\/127\.0\.0\.1:(\d+))(\/\S*)\n/);
      if (m) {
        clearTimeout(timer);
        res({ origin: m[1], port: Number(m[2]), pageUrl: m[1] + m[3], pid: child.pid, close });
      }
    });
    child.once('exit', (code) => { clearTimeout(timer); rej(new Error(`serve.js exited with ${code}: ${stderr}`)); });
  });
}

// A fresh headless Chromium with its own temporary profile; close() removes the profile too.
export async function launchBrowser() {
  const { chromium } = await import('playwright-core');
  const profile = mkdtempSync(join(tmpdir(), 'rtl-chromium-'));
  const context = await chromium.launchPersistentContext(profile, {
    executablePath: CHROMIUM, headless: true, args: CHROMIUM_ARGS, viewport: { width: 1400, height: 1000 },
    acceptDownloads: true,
  });
  return {
    context,
    async close() {
      try { await context.close(); } finally { rmSync(profile, { recursive: true, force: true }); }
    },
  };
}

// Records console errors and uncaught page errors; tests assert the list stays empty.
export function watchConsole(page) {
  const problems = [];
  page.on('console', (m) => { if (m.type() === 'error') problems.push(`console.error: ${m.text()}`); });
  page.on('pageerror', (e) => problems.push(`pageerror: ${e.message}`));
  page.on('requestfailed', (r) => problems.push(`request failed: ${r.url()} ${r.failure()?.errorText}`));
  page.on('response', (r) => { if (r.status() >= 400) problems.push(`HTTP ${r.status()}: ${r.url()}`); });
  return problems;
}

export const PAGE_TIMEOUT = 30000;

// Serves the repository, opens the demo page (`path` below the server's origin, else the URL serve.js prints) in a
// fresh Chromium and waits until the page has loaded the package or reported an error. The accessors read the page's
// test hook window.__rtl; close() stops the browser, then the server.
export async function openDemoPage(path) {
  const server = await startServer();
  let browser;
  const close = async () => {
    try { if (browser) await browser.close(); } finally { await server.close(); }
  };
  try {
    browser = await launchBrowser();
    const page = browser.context.pages()[0] ?? await browser.context.newPage();
    const problems = watchConsole(page);
    await page.goto(path ? server.origin + path : server.pageUrl);
    await page.waitForFunction(() => window.__rtl && (window.__rtl.ready || window.__rtl.errors.length > 0), null,
      { timeout: PAGE_TIMEOUT });
    const state = () => page.evaluate(() => window.__rtl);
    const revision = () => page.evaluate(() => window.__rtl.revision);
    // The state once the page has recomputed after `previousRevision`.
    const settled = async (previousRevision) => {
      await page.waitForFunction((r) => window.__rtl.revision > r, previousRevision, { timeout: PAGE_TIMEOUT });
      return state();
    };
    // The state once the page shows a result computed with all of the given settings.
    const settledWith = async (settings) => {
      await page.waitForFunction((want) => window.__rtl.settings &&
        Object.entries(want).every(([k, v]) => window.__rtl.settings[k] === v), settings, { timeout: PAGE_TIMEOUT });
      return state();
    };
    return { server, browser, page, problems, state, revision, settled, settledWith, close };
  } catch (e) {
    await close();
    throw e;
  }
}

// Runs bin/rtl.js from the repository root.
export function runCli(args, input) {
  const r = spawnSync(process.execPath, [join(REPO, 'bin', 'rtl.js'), ...args],
    { cwd: REPO, encoding: 'utf8', input, timeout: 60000 });
  return { code: r.status, out: r.stdout, err: r.stderr };
}

// ---- independent reference computations (no wasm) -----------------------------------------------------------------

// FLASER n r_1..r_n x y theta odom_x odom_y odom_theta ipc_timestamp host logger_timestamp; beam i at
// -pi/2 + i*pi/n (n = 180) or -pi/2 + i*pi/(n-1) (n = 361: 0.5 degree steps, last beam at +pi/2).
export function parseCarmen(text) {
  const scans = [];
  text.split('\n').forEach((line, li) => {
    const t = line.trim().split(/\s+/);
    if (t[0] !== 'FLASER') return;
    const n = Number(t[1]);
    const ranges = t.slice(2, 2 + n).map(Number);
    const step = n % 2 === 1 ? Math.PI / (n - 1) : Math.PI / n;
    const angles = ranges.map((_, i) => -Math.PI / 2 + i * step);
    scans.push({ line: li + 1, n, ranges, angles, x: Number(t[2 + n]), y: Number(t[3 + n]), theta: Number(t[4 + n]) });
  });
  return scans;
}

// A CARMEN log of tests/data by name ('intel', 'csail'), parsed as above.
export const loadLog = (name) => parseCarmen(readFileSync(join(DATA, `${name}.log`), 'utf8'));

// In these logs a beam without return reads the sensor's maximum (81.83 m Intel, 81.91 m CSAIL); real returns in the
// excerpts are all below 20 m, so any cut between the two gives the same gaps.
export const isReturn = (r) => r > 0 && r < 80;

// Indices of the beams with a return in [from, to] (inclusive), and their robot-frame x,y.
export function returnsOf(scan, from = 0, to = scan.n - 1) {
  const beams = [];
  for (let i = from; i <= to; i++) if (isReturn(scan.ranges[i])) beams.push(i);
  return beams;
}
export function xyOf(scan, beams) {
  return beams.flatMap((i) => [scan.ranges[i] * Math.cos(scan.angles[i]), scan.ranges[i] * Math.sin(scan.angles[i])]);
}

// The whole scan as the package takes it: x,y of every beam in the robot frame, NaN for beams without a return.
export function scanPoints(scan) {
  const points = new Float64Array(2 * scan.n).fill(NaN);
  scan.ranges.forEach((r, i) => {
    if (isReturn(r)) { points[2 * i] = r * Math.cos(scan.angles[i]); points[2 * i + 1] = r * Math.sin(scan.angles[i]); }
  });
  return points;
}

// The clusters the package's StreamSegmenter closes for `points` fed at once and flushed (x,y arrays, in order).
export function streamClusters(pkg, points, options) {
  const seg = new pkg.StreamSegmenter(options);
  try {
    seg.addPoints(points);
    seg.flush();
    return seg.takeClosedClusters();
  } finally {
    seg.dispose();
  }
}

// Plain two-pass TLS in double precision: centroid, covariance, smaller eigenvalue and its eigenvector.
export function tlsFit(xy) {
  const n = xy.length / 2;
  let mx = 0, my = 0;
  for (let i = 0; i < n; i++) { mx += xy[2 * i]; my += xy[2 * i + 1]; }
  mx /= n; my /= n;
  let sxx = 0, sxy = 0, syy = 0;
  for (let i = 0; i < n; i++) {
    const dx = xy[2 * i] - mx, dy = xy[2 * i + 1] - my;
    sxx += dx * dx; sxy += dx * dy; syy += dy * dy;
  }
  sxx /= n; sxy /= n; syy /= n;
  // Angle of the major axis; the normal is perpendicular to it (robust for axis-aligned sets too).
  const phi = 0.5 * Math.atan2(2 * sxy, sxx - syy);
  const normal = [-Math.sin(phi), Math.cos(phi)];
  const offset = -(normal[0] * mx + normal[1] * my);
  let ss = 0;
  for (let i = 0; i < n; i++) { const d = normal[0] * xy[2 * i] + normal[1] * xy[2 * i + 1] + offset; ss += d * d; }
  return { normal, offset, rms: Math.sqrt(ss / n), centroid: [mx, my], n };
}

// The line n.p + c = 0 is the same as (-n).p - c = 0: compare up to that sign.
export function sameLine(a, b, tol) {
  const s = Math.sign(a.normal[0] * b.normal[0] + a.normal[1] * b.normal[1]) || 1;
  return Math.abs(a.normal[0] - s * b.normal[0]) < tol && Math.abs(a.normal[1] - s * b.normal[1]) < tol &&
    Math.abs(a.offset - s * b.offset) < tol;
}

// ---- the lesson page ------------------------------------------------------------------------------------------------

// Opens lesson `id` by its URL hash (if it is not open yet) and waits until it has computed and shown a step.
export async function openLesson(page, id) {
  const rev = await page.evaluate(() => window.__rtl.revision);
  const already = await page.evaluate((h) => window.__rtl.current === h, id);
  if (!already) {
    await page.evaluate((h) => { location.hash = h; }, id);
    await page.waitForFunction(([h, r]) => window.__rtl.current === h && window.__rtl.revision > r &&
      window.__rtl.lessons.find((l) => l.id === h).steps !== null, [id, rev], { timeout: PAGE_TIMEOUT });
  }
  return page.evaluate((h) => window.__rtl.lessons.find((l) => l.id === h), id);
}

// Moves the player of the open lesson to its last step with the "last step" button; resolves with finalState().
export async function lastStep(page, id) {
  const { steps } = await page.evaluate((h) => window.__rtl.lessons.find((l) => l.id === h), id);
  if (steps > 1) await page.click('#player [data-act="last"]');
  await page.waitForFunction(([h, n]) => window.__rtl.lessons.find((l) => l.id === h).step === n - 1, [id, steps], { timeout: PAGE_TIMEOUT });
  return page.evaluate(() => window.__rtl.finalState());
}

export const SCREENSHOTS = join(REPO, 'build', 'test-output', 'screenshots');
