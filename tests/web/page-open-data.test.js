// Open your own data: a CARMEN log dropped on the page, a gzipped one picked, and a CSV of x,y; the scan chooser
// makes a scan the source of every 2D lesson (checked against the package in Node on the same file); bad files get
// a message naming the file and the line, and the page keeps working.
import { after, before, describe, test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { join } from 'node:path';
import { gzipSync } from 'node:zlib';
import init from 'rtl-wasm';
import { DATA, PAGE_TIMEOUT, openDemoPage, openLesson } from './helpers.js';

const SEG = { step: 3, lowerBound: 0.1, upperBound: 0.5 };
const CHAIN_LESSONS = ['ftls', 'aftls', 'itls', 'dp', 'rw'];
const LESSONS_2D = ['car', 'ia', ...CHAIN_LESSONS, 'compare', 'overview'];

// Drops a file (name, text or bytes) on the page as a user dragging it from the desktop.
async function drop(page, name, content) {
  const bytes = Array.from(Buffer.from(content));
  const dt = await page.evaluateHandle(([n, b]) => { const t = new DataTransfer(); t.items.add(new File([new Uint8Array(b)], n)); return t; }, [name, bytes]);
  await page.dispatchEvent('body', 'drop', { dataTransfer: dt });
}
const message = (page) => page.textContent('#open-message');
const waitMessage = (page, re) => page.waitForFunction((src) => new RegExp(src).test(document.querySelector('#open-message').textContent), re.source, { timeout: PAGE_TIMEOUT });

// The largest cluster of a scan (the excerpt a chain lesson takes from the user's scan), as the package gives it.
function largestCluster(rtl, points) {
  const { clusters } = rtl.segment(points, SEG);
  const best = clusters.reduce((b, c) => (c.indices.length > b.indices.length ? c : b));
  return Array.from(best.indices).flatMap((i) => [points[2 * i], points[2 * i + 1]]);
}

// Every 2D lesson runs on `points` (the chosen scan): its excerpt is that scan (or its largest cluster) and its
// step count is the package's trace of it.
async function runEveryLesson(page, rtl, points, source) {
  for (const id of LESSONS_2D) {
    const entry = await openLesson(page, id);
    const s = await page.evaluate(() => window.__rtl.finalState());
    assert.deepEqual(await page.evaluate(() => window.__rtl.source()), source, `${id}: the source`);
    if (id === 'car') {
      assert.deepEqual(s.points, Array.from(points));
      assert.equal(entry.steps, rtl.segment(points, { step: s.params.step, lowerBound: s.params.lowerBound, upperBound: s.params.upperBound, trace: true }).trace.length);
    } else if (id === 'ia') {
      assert.deepEqual(s.points, Array.from(points));
      assert.ok(entry.steps > 1, 'ia steps');
    } else if (CHAIN_LESSONS.includes(id)) {
      const chain = largestCluster(rtl, points);
      assert.deepEqual(s.chain, chain, `${id}: the largest cluster of the chosen scan`);
      const p = s.params;
      const traced = rtl.vectorize(new Float64Array(chain), { method: id, sigma: p.sigma, delta: p.delta, epsilon: p.epsilon, ...(p.split !== undefined ? { split: p.split } : {}), trace: true });
      assert.equal(entry.steps, traced.trace.length, `${id}: steps`);
    } else if (id === 'compare') {
      assert.equal(s.rows.length, 5);
    } else {
      assert.equal(s.params.dataset, source.dataset);
      assert.equal(s.params.scan, source.scan);
      assert.equal(s.numbers.beams, points.length / 2);
    }
    assert.match(await page.textContent('#lesson-controls'), /Your chosen scan/, `${id}: says whose data`);
  }
}

describe('open your own data', { timeout: 400000 }, () => {
  let page, problems, close, rtl;
  before(async () => {
    rtl = await init();
    ({ page, problems, close } = await openDemoPage('/web/#dp'));
    await page.setViewportSize({ width: 1280, height: 800 });
  });
  after(() => close?.());

  test('a dropped CARMEN log: progress, the scan chooser, and every 2D lesson on scan 3', async () => {
    const text = readFileSync(join(DATA, 'csail.log'), 'utf8');
    const scans = rtl.readCarmenLog(text);
    await drop(page, 'my-run.log', text);
    await waitMessage(page, /my-run\.log: 30 scans read/);
    const options = await page.$$eval('#scan-chooser option', (os) => os.map((o) => [o.value, o.textContent]));
    assert.equal(options.length, 1 + scans.length);
    const seg3 = rtl.segment(scans[3].points, SEG).clusters.length;
    assert.ok(options[4][1].includes(`scan 3: `) && options[4][1].includes(`${seg3} clusters`), options[4][1]);
    const [dataset] = options[1][0].split(':');
    await page.selectOption('#scan-chooser', `${dataset}:3`);
    await page.waitForFunction(() => window.__rtl.source()?.scan === 3, null, { timeout: PAGE_TIMEOUT });
    await runEveryLesson(page, rtl, scans[3].points, { dataset, scan: 3 });
    // back to the lessons' own excerpts
    await page.selectOption('#scan-chooser', '');
    await page.waitForFunction(() => window.__rtl.source() === null, null, { timeout: PAGE_TIMEOUT });
    const ownDp = await openLesson(page, 'dp');
    assert.ok(ownDp.steps > 0);
    assert.match(await page.textContent('#lesson-controls'), /Intel Research Lab, scan 17/);
  });

  test('a gzipped log from the file picker', async () => {
    const text = readFileSync(join(DATA, 'intel.log'), 'utf8');
    await page.setInputFiles('#open-file', { name: 'intel-copy.log.gz', mimeType: 'application/gzip', buffer: gzipSync(Buffer.from(text)) });
    await waitMessage(page, /intel-copy\.log\.gz: \d+ scans read/);
    const scans = rtl.readCarmenLog(text);
    const src = await page.evaluate(() => window.__rtl.source());
    assert.equal(src.scan, 0);
    const s = await openLesson(page, 'car').then(() => page.evaluate(() => window.__rtl.finalState()));
    assert.deepEqual(s.points, Array.from(scans[0].points));
  });

  test('a CSV of x,y (a real cluster written out) runs every 2D lesson', async () => {
    const scan = rtl.readCarmenLog(readFileSync(join(DATA, 'intel.log'), 'utf8'))[17];
    const xy = [];
    for (let i = 0; i < scan.points.length; i += 2) if (Number.isFinite(scan.points[i])) xy.push([scan.points[i], scan.points[i + 1]]);
    const csv = `x,y\n${xy.map(([x, y]) => `${x},${y}`).join('\n')}\n`;
    await drop(page, 'room.csv', csv);
    await waitMessage(page, /room\.csv: 1 point set read/);
    const src = await page.evaluate(() => window.__rtl.source());
    await runEveryLesson(page, rtl, new Float64Array(xy.flat()), src);
  });

  test('bad files: the message names the file and the line; the page keeps working', async () => {
    const before = await page.evaluate(() => window.__rtl.source());
    await drop(page, 'broken.csv', 'x,y\n1,2\n3,4\n1.5,abc\n');
    await waitMessage(page, /broken\.csv: line 4: expected two numbers x,y, found "1\.5,abc"/);
    assert.equal(await page.getAttribute('#open-message', 'class'), 'open-message error');
    // a CARMEN log with a cut FLASER record: readCarmenLog's line, under the file's name
    const lines = readFileSync(join(DATA, 'intel.log'), 'utf8').split('\n');
    const k = lines.map((l, i) => (l.startsWith('FLASER') ? i : -1)).filter((i) => i >= 0)[2];   // the third scan
    lines[k] = lines[k].split(' ').slice(0, 50).join(' ');
    const bad = lines.join('\n');
    let expected;
    try { rtl.readCarmenLog(bad); } catch (e) { expected = e.message.replace(/^readCarmenLog: /, ''); }
    assert.ok(expected, 'the package rejects the cut record');
    assert.match(expected, new RegExp(`^line ${k + 1}:`));
    await drop(page, 'cut.log', bad);
    await waitMessage(page, /cut\.log: line/);
    assert.equal(await message(page), `cut.log: ${expected}`);
    await drop(page, 'notes.pdf', 'hello');
    await waitMessage(page, /notes\.pdf: not a format this page reads/);
    // nothing changed: the same source, and a lesson still runs
    assert.deepEqual(await page.evaluate(() => window.__rtl.source()), before);
    const e = await openLesson(page, 'rw');
    assert.ok(e.steps > 0);
  });

  test('no console errors', async () => {
    assert.deepEqual(await page.evaluate(() => window.__rtl.errors), []);
    assert.deepEqual(problems, []);
  });
});
