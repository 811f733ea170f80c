// Whole-log processing off the page's thread: reads a CARMEN log with the package (readCarmenLog) and segments every
// scan (segment) for the scan chooser, posting progress as it goes. Nothing leaves the browser.
// In:  { bytes: ArrayBuffer, name, segment: { step, lowerBound, upperBound } }
// Out: { progress: 0..1, phase } …, then { done: true, scans: [{ points, x, y, theta, line, returns, clusters }] }
//      (points transferred) or { error: message } (readCarmenLog's own message: it names the line).
// A module worker does not see the page's import map: this is the path the map gives 'rtl-wasm' (web/index.html).
import init from '/dist/index.js';

let ready = null;
self.onmessage = async ({ data }) => {
  try {
    ready ??= init();
    const rtl = await ready;
    self.postMessage({ progress: 0, phase: 'reading' });
    const read = rtl.readCarmenLog(data.bytes);
    const scans = [];
    for (let k = 0; k < read.length; k++) {
      const s = read[k];
      const { clusters } = rtl.segment(s.points, data.segment);
      let returns = 0;
      for (let i = 0; i < s.points.length; i += 2) if (Number.isFinite(s.points[i])) returns++;
      scans.push({ points: new Float64Array(s.points), x: s.x, y: s.y, theta: s.theta, line: s.line, returns, clusters: clusters.length });
      if (k % 5 === 4 || k === read.length - 1) self.postMessage({ progress: (k + 1) / read.length, phase: 'segmenting' });
    }
    self.postMessage({ done: true, scans }, scans.map((s) => s.points.buffer));
  } catch (e) {
    self.postMessage({ error: String(e?.message ?? e) });
  }
};
