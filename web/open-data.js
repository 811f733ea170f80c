// Open your own data: a file picker and drag-and-drop anywhere on the page. A reader per file name ending turns the
// file into scans ({ points (x,y interleaved, NaN = no return), x, y, theta }); the scans become a data set of
// web/data.js, and a scan chooser makes one of them the source every 2D lesson runs on. Nothing leaves the browser.
//
// Readers are the extension point: registerReader({ test(name), label, read(file, progress) → { scans, unit? } }).
// CARMEN logs (.log, .log.gz) go to a Web Worker that reads them with the package and segments every scan;
// CSV of x,y is one scan, in file order. A bad file gets a message naming the file and the line; the page goes on.
const READERS = [];
export function registerReader(reader) { READERS.unshift(reader); }

const SEGMENT = { step: 3, lowerBound: 0.1, upperBound: 0.5 };   // for the chooser's cluster counts

// The file's bytes, gunzipped when its name ends in .gz (DecompressionStream: the browser's own gzip).
async function bytesOf(file) {
  if (!/\.gz$/i.test(file.name)) return file.arrayBuffer();
  try {
    return await new Response(file.stream().pipeThrough(new DecompressionStream('gzip'))).arrayBuffer();
  } catch (e) {
    throw new Error(`${file.name}: not a readable gzip file (${e.message})`);
  }
}

// CARMEN: readCarmenLog and segment in the worker, with its progress.
registerReader({
  label: 'CARMEN log (.log, .log.gz)',
  test: (name) => /\.(log|clf)(\.gz)?$/i.test(name),
  async read(file, progress) {
    const bytes = await bytesOf(file);
    const worker = new Worker(new URL('./data-worker.js', import.meta.url), { type: 'module' });
    try {
      return await new Promise((resolve, reject) => {
        worker.onmessage = ({ data }) => {
          if (data.error) reject(new Error(`${file.name}: ${data.error.replace(/^readCarmenLog: /, '')}`));
          else if (data.done) resolve({ scans: data.scans, unit: 'scan' });
          else progress(data.progress, data.phase);
        };
        worker.onerror = (e) => reject(new Error(`${file.name}: ${e.message || 'the reader stopped'}`));
        worker.postMessage({ bytes, name: file.name, segment: SEGMENT }, [bytes]);
      });
    } finally {
      worker.terminate();
    }
  },
});

// CSV of x,y: one point per line (comma, semicolon, tab or space between), an optional header line, # comments.
registerReader({
  label: 'CSV of x,y (.csv, .txt)',
  test: (name) => /\.(csv|txt)(\.gz)?$/i.test(name),
  async read(file, progress) {
    const text = new TextDecoder().decode(await bytesOf(file));
    const xy = [];
    const lines = text.split(/\r?\n/);
    lines.forEach((raw, i) => {
      const line = raw.trim();
      if (!line || line.startsWith('#')) return;
      const cells = line.split(/\s*[,;\t ]\s*/);
      const nums = cells.map(Number);
      if (cells.length >= 2 && cells.slice(0, 2).every((c) => c !== '') && Number.isFinite(nums[0]) && Number.isFinite(nums[1])) { xy.push(nums[0], nums[1]); return; }
      if (xy.length === 0 && i === lines.findIndex((l) => l.trim() && !l.trim().startsWith('#'))) return;   // a header
      throw new Error(`${file.name}: line ${i + 1}: expected two numbers x,y, found "${line.length > 40 ? `${line.slice(0, 40)}…` : line}"`);
    });
    if (xy.length < 4) throw new Error(`${file.name}: ${xy.length / 2} point${xy.length === 2 ? '' : 's'}; at least 2 are needed`);
    progress(1, 'read');
    return { scans: [{ points: new Float64Array(xy), x: 0, y: 0, theta: 0 }], unit: 'point set' };
  },
});

// Wires the picker (input[type=file]), the drop target (the whole page), the progress bar, the message and the scan
// chooser. onSource({ dataset, scan } | null) after a choice (null: the lessons' own excerpts).
export function wireOpenData({ data, input, progressBar, message, chooser, onSource }) {
  let serial = 0;
  const say = (text, isError = false) => { message.textContent = text; message.classList.toggle('error', isError); };

  async function openFile(file) {
    const reader = READERS.find((r) => r.test(file.name));
    if (!reader) { say(`${file.name}: not a format this page reads (${READERS.map((r) => r.label).join('; ')}).`, true); return; }
    progressBar.hidden = false;
    progressBar.value = 0;
    say(`Reading ${file.name}…`);
    try {
      const { scans, unit = 'scan' } = await reader.read(file, (p, phase) => { progressBar.value = p; say(`${file.name}: ${phase} ${Math.round(100 * p)} %`); });
      if (!scans.length) throw new Error(`${file.name}: no scan in the file`);
      const name = `file${++serial}`;
      data.addDataset(name, { label: file.name, unit, scans });
      const group = document.createElement('optgroup');
      group.label = file.name;
      scans.forEach((s, k) => {
        const o = document.createElement('option');
        o.value = `${name}:${k}`;
        const n = s.returns ?? s.points.length / 2;
        o.textContent = `${file.name}, ${unit} ${k}: ${n} points${s.clusters !== undefined ? `, ${s.clusters} clusters` : ''}`;
        group.append(o);
      });
      chooser.append(group);
      chooser.disabled = false;
      say(`${file.name}: ${scans.length} ${unit}${scans.length === 1 ? '' : 's'} read. The lessons now run on ${unit} 0; choose another in the list.`);
      chooser.value = `${name}:0`;
      onSource({ dataset: name, scan: 0 });
    } catch (e) {
      say(e.message.startsWith(file.name) ? e.message : `${file.name}: ${e.message}`, true);
    } finally {
      progressBar.hidden = true;
    }
  }

  input.addEventListener('change', () => { if (input.files[0]) openFile(input.files[0]); input.value = ''; });
  chooser.addEventListener('change', () => {
    const [dataset, scan] = chooser.value.split(':');
    onSource(dataset ? { dataset, scan: Number(scan) } : null);
  });
  window.addEventListener('dragover', (ev) => { if (ev.dataTransfer?.types?.includes('Files')) { ev.preventDefault(); document.documentElement.classList.add('dropping'); } });
  window.addEventListener('dragleave', (ev) => { if (!ev.relatedTarget) document.documentElement.classList.remove('dropping'); });
  window.addEventListener('drop', (ev) => {
    document.documentElement.classList.remove('dropping');
    const file = ev.dataTransfer?.files?.[0];
    if (!file) return;
    ev.preventDefault();
    openFile(file);
  });
  return { openFile };
}
