// `rtl` on robot logs: the per-scan step (pipeline + output) and the driver over one or several logs, with the
// progress bar, Ctrl-C handling and --jobs. See bin/logs.js for the log side.
import { writeFileSync } from 'node:fs';
import { availableParallelism } from 'node:os';
import { render, run } from './pipeline.js';
import { inputOf, jsonLine, lineSink, LogStop, pictureFile, processLog, processLogsInWorkers, progressWriter } from './logs.js';

/** scan -> its JSON line (json), or writes its picture file and returns undefined (svg, tikz). */
export function scanStep(rtl, opts) {
  return (scan, file) => {
    const input = inputOf(scan, file, opts);
    const result = run(rtl, opts, input);
    if (opts.format === 'json') return jsonLine(result);
    writeFileSync(pictureFile(opts.output, file, scan.index), render(rtl, opts, input, result));
    return undefined;
  };
}

/** Runs the logs of opts.files; returns the exit code (0, 1 when a log stopped on bad data, 130 on Ctrl-C). */
export async function runLogs(rtl, opts) {
  const { openLog } = await import('rtl-wasm/logs');
  const progress = progressWriter(opts.progress ?? Boolean(process.stderr.isTTY));
  let interrupted = false;
  const onSigint = () => { interrupted = true; };
  process.on('SIGINT', onSigint);
  const sink = opts.format === 'json' ? lineSink(opts.output) : { write() {}, close() {} };
  const say = (text) => { progress.end(); process.stderr.write(`rtl: ${text}\n`); };
  let failures = 0;
  try {
    const jobs = Math.min(opts.jobs ?? availableParallelism(), opts.files.length);
    if (jobs > 1) {
      failures = await processLogsInWorkers(opts.files, opts, jobs, sink, {
        stopped: () => interrupted, progress: progress.update,
        onDone: (r) => { if (r.interrupted) say(`interrupted: ${r.file}: ${r.topic}: wrote ${r.scans} scans; the next is message ${r.next}`); },
        onError: (message) => say(message),
      });
    } else {
      const step = scanStep(rtl, opts);
      for (const file of opts.files) {
        if (interrupted) break;
        try {
          const r = await processLog(file, opts, {
            openLog, process: step, stopped: () => interrupted, progress: progress.update,
            emit: (line) => { if (line) sink.write(line); },
          });
          if (r.interrupted) say(`interrupted: ${file}: ${r.topic}: wrote ${r.scans} scans; the next is message ${r.next}`);
        } catch (e) {
          if (e.code === 'EPIPE') break;
          if (!(e instanceof LogStop) && e.name !== 'LogError' && e.code !== 'ENOENT') throw e;
          failures++;
          say(e.code === 'ENOENT' ? `cannot read "${file}": no such file` : e.message.replace(/^openLog: /, ''));
        }
      }
    }
  } finally {
    progress.end();
    sink.close();
    process.off('SIGINT', onSigint);
  }
  if (interrupted) return 130;
  return failures ? 1 : 0;
}
