#!/usr/bin/env node
// The simplify-js comparison of b_simplify.mjs in headless Chromium (playwright-core, $RTL_CHROMIUM or
// /usr/bin/chromium): the package's browser entry (dist/index.js, .wasm fetched by the glue) and simplify-js's own
// file, served by web/serve.js; same cases, rounds and table (bench/js/simplify_cases.mjs), wall time
// (performance.now(); a page has no CPU clock).
//   [RTL_PACKAGE=dir] node bench/js/b_simplify_browser.mjs [--rounds=N] [--warmup-ms=N] [--smoke]   (dir: a package folder inside
//   the repository built by wasm/build.mjs with RTL_DIST_DIR, instead of dist/)
import { cpus, loadavg } from 'node:os';
import { relative, resolve } from 'node:path';
import { REPO, launchBrowser, startServer } from '../../tests/web/helpers.js';
import { WARMUP_MS, formatRows } from './simplify_cases.mjs';

const args = process.argv.slice(2);
const smoke = args.includes('--smoke');
const rounds = Number((args.find((a) => a.startsWith('--rounds=')) || '').slice(9)) || (smoke ? 1 : 9);
const sizes = smoke ? [10_000] : [100_000, 1_000_000];
// Untimed warm-up per case (simplify_cases.mjs); --warmup-ms=0 measures the start-up instead (round 0 dropped).
// Chromium 156 needed longer than Node: after 400 ms its first case (semicircle 100k fast) still took 1.3 ms for
// rtl and 2.3 ms for simplify-js, 0.3 and 0.5 ms after 2000 ms.
const warmArg = args.find((a) => a.startsWith('--warmup-ms='));
const warmupMs = warmArg ? Number(warmArg.slice(12)) : (smoke ? 0 : 2 * WARMUP_MS);
const entry = `/${relative(REPO, resolve(process.env.RTL_PACKAGE || resolve(REPO, 'dist')))}/index.js`;
const load = () => `load ${loadavg().map((l) => l.toFixed(2)).join(' ')} on ${cpus().length} cores`;

const server = await startServer();
const browser = await launchBrowser();
try {
  const page = browser.context.pages()[0] ?? await browser.context.newPage();
  const errors = [];
  page.on('pageerror', (e) => errors.push(e.message));
  await page.goto(`${server.origin}/tests/data/README.md`);
  await page.addScriptTag({ url: '/node_modules/simplify-js/simplify.js' });  // UMD: sets window.simplify
  console.log(`simplify in Chromium ${browser.context.browser()?.version() ?? ''}: ${rounds} interleaved rounds after ${warmupMs} ms of warm-up per case, medians (ms, wall)${smoke ? ' (smoke)' : ''} (${load()})`);
  const rows = await page.evaluate(async ({ sizes, rounds, entry, warmupMs }) => {
    const { default: init } = await import(entry);
    const { runSimplifyBench } = await import('/bench/js/simplify_cases.mjs');
    const rtl = await init();
    return runSimplifyBench({ rtl, simplifyJs: window.simplify, sizes, rounds, clock: () => performance.now(), warmupMs });
  }, { sizes, rounds, entry, warmupMs });
  if (errors.length) throw new Error(`page errors: ${errors.join('; ')}`);
  console.log(formatRows(rows));
  console.log(`\nspeed-up = simplify-js / rtl {x,y}; ${load()}`);
} finally {
  await browser.close();
  await server.close();
}
