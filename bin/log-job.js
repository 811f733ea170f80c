// A worker thread of `rtl --jobs N` on several logs: processes one log (workerData { file, opts }) with the same
// pipeline as the main thread and posts its JSON lines to it in batches; 'stop' (Ctrl-C in the main thread) ends
// it after the current scan.
import { parentPort, workerData } from 'node:worker_threads';
import init from 'rtl-wasm';
import { openLog } from 'rtl-wasm/logs';
import { scanStep } from './log-run.js';
import { processLog } from './logs.js';

const { file, opts } = workerData;
let stop = false;
parentPort.on('message', (m) => { if (m === 'stop') stop = true; });
let pending = '', progress = null;
const flush = () => {
  if (pending || progress) parentPort.postMessage({ lines: pending, progress });
  pending = '';
  progress = null;
};
try {
  const rtl = await init();
  const step = scanStep(rtl, opts);
  const done = await processLog(file, opts, {
    openLog, process: step, stopped: () => stop,
    progress: (f, done, total) => { progress = { done, total }; if (done % 64 === 0) flush(); },
    emit: (line) => { if (line) { pending += line; if (pending.length > 1 << 16) flush(); } },
  });
  flush();
  parentPort.postMessage({ done });
} catch (e) {
  flush();
  parentPort.postMessage({ error: e.message });
}
parentPort.close();
