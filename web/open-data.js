// Open your own data: a file picker and drag-and-drop anywhere on the page. A reader per file name ending turns the
// file into scans ({ points (x,y interleaved, NaN = no return), x, y, theta }); the scans become a data set of
// web/data.js, and a scan chooser makes one of them the source every 2D lesson runs on. Nothing leaves the browser.
//
// Readers are the extension point: registerReader({ test(name), label, accept, read(file, progress) → { scans, unit?,
// note?, cloud?, topics? } }). CARMEN logs (.log, .log.gz), robot logs (.mcap: ROS 2; .bag: ROS 1) and PCD clouds
// go to a Web Worker (web/data-worker.js) that reads them with the package (readCarmenLog, rtl-wasm/logs, readPcd)
// and segments every scan; CSV of x,y is one scan, in file order. A log also gives `topics`: its topic list and
// read(topic, progress) for the topic chooser. A bad file gets a message naming the file and the place; the page
// goes on.
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

// The package's own error messages start with the function's name; the page's start with the file's.
const PACKAGE_PREFIX = /^(readCarmenLog|readPcd|openLog|scans): /;

function newWorker() {
  return new Worker(new URL('./data-worker.js', import.meta.url), { type: 'module' });
}

// One request to a worker: resolves with its { done } message, rejects at its { error } (the error carries the
// scans read before the failure, if any); progress(p, phase, count) on the way (p null: total unknown).
function ask(worker, file, message, transfer, progress) {
  return new Promise((resolve, reject) => {
    worker.onmessage = ({ data }) => {
      if (data.error !== undefined) {
        const msg = data.error.replace(PACKAGE_PREFIX, '');
        const err = new Error(msg.startsWith(`${file.name}: `) ? msg : `${file.name}: ${msg}`);
        err.scans = data.scans;
        reject(err);
      } else if (data.done) resolve(data);
      else progress(data.progress, data.phase, data.count);
    };
    worker.onerror = (e) => reject(new Error(`${file.name}: ${e.message || 'the reader stopped'}`));
    worker.abandon = () => reject(new Error(`${file.name}: closed before the end`));   // terminate() answers nothing
    worker.postMessage(message, transfer);
  });
}

// CARMEN: readCarmenLog and segment in the worker, with its progress.
registerReader({
  label: 'CARMEN log (.log, .log.gz)',
  accept: '.log,.clf,.gz',
  test: (name) => /\.(log|clf)(\.gz)?$/i.test(name),
  async read(file, progress) {
    const bytes = await bytesOf(file);
    const worker = newWorker();
    try {
      const { scans } = await ask(worker, file, { kind: 'carmen', bytes, segment: SEGMENT }, [bytes], progress);
      return { scans, unit: 'scan' };
    } finally {
      worker.terminate();
    }
  },
});

// PCD (PCL's ascii, binary, binary_compressed): readPcd in the worker. An organised cloud: its rings, each seen from
// above as a 2D scan, and the cloud itself for the 3D view; an unorganised one: its points from above, one set.
registerReader({
  label: 'PCD point cloud (.pcd)',
  accept: '.pcd',
  test: (name) => /\.pcd$/i.test(name),
  async read(file, progress) {
    const bytes = await file.arrayBuffer();
    const worker = newWorker();
    try {
      const r = await ask(worker, file, { kind: 'pcd', bytes, segment: SEGMENT }, [bytes], progress);
      const note = r.organized
        ? `an organised cloud of ${r.cloud.beams} rings × ${r.cloud.columns} columns; each ring, seen from above, is a scan of the 2D lessons`
        : `an unorganised cloud of ${r.count} points, seen from above as one point set (its order is the file's)`;
      return { scans: r.scans, unit: r.unit, note, cloud: r.cloud };
    } finally {
      worker.terminate();
    }
  },
});

// Robot logs: MCAP (ROS 2, ROS 1 or JSON messages) and ROS 1 bags, through the package's rtl-wasm/logs in the
// worker, which stays alive while the topic chooser may ask for another topic (close() ends it).
const isScanTopic = (t) => /(^|[/.])(LaserScan|PointCloud2)$/.test(t.type);
registerReader({
  label: 'ROS log (.mcap, .bag)',
  accept: '.mcap,.bag',
  test: (name) => /\.(mcap|bag)$/i.test(name),
  async read(file, progress) {
    const worker = newWorker();
    try {
      progress(null, 'opening');
      const { format, topics } = await ask(worker, file, { kind: 'log-open', file }, [], progress);
      const scanTopics = topics.filter(isScanTopic);
      if (!scanTopics.length)
        throw new Error(`${file.name}: no LaserScan or PointCloud2 topic (topics: ${topics.map((t) => `${t.name} [${t.type}]`).join(', ') || 'none'})`);
      const readTopic = async (topic, onProgress) => {
        const r = await ask(worker, file, { kind: 'log-read', topic, segment: SEGMENT }, [], onProgress);
        return { scans: r.scans, unit: 'scan' };
      };
      const first = scanTopics.find((t) => /LaserScan$/.test(t.type) && t.count !== 0) ?? scanTopics.find((t) => t.count !== 0) ?? scanTopics[0];
      const { scans } = await readTopic(first.name, progress);
      return {
        scans, unit: 'scan', note: format === 'bag' ? 'a ROS 1 bag' : 'an MCAP file',
        topics: { list: topics, current: first.name, read: readTopic }, close: () => { worker.terminate(); worker.abandon(); },
      };
    } catch (e) {
      worker.terminate();
      throw e;
    }
  },
});

// CSV of x,y: one point per line (comma, semicolon, tab or space between), an optional header line, # comments.
registerReader({
  label: 'CSV of x,y (.csv, .txt)',
  accept: '.csv,.txt',
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

// Wires the picker (input[type=file]), the drop target (the whole page), the progress bar, the message, the topic
// chooser (made here, before the scan chooser, shown for a log) and the scan chooser. onSource({ dataset, scan } |
// null) after a choice (null: the lessons' own excerpts).
export function wireOpenData({ data, input, progressBar, message, chooser, onSource }) {
  let serial = 0;
  let openLog = null;   // the last log opened: { file, close(), read(topic), read topics: Map topic -> data set }
  const say = (text, isError = false) => { message.textContent = text; message.classList.toggle('error', isError); };
  input.accept = [...new Set(READERS.flatMap((r) => (r.accept ?? '').split(',').filter(Boolean)))].join(',');

  const topicLabel = document.createElement('label');
  topicLabel.className = 'chooser topic-chooser';
  topicLabel.hidden = true;
  const topicChooser = document.createElement('select');
  topicChooser.id = 'topic-chooser';
  topicLabel.append('Topic ', topicChooser);
  (chooser.closest('label') ?? chooser).before(topicLabel);

  const showProgress = (file, what) => (p, phase, count) => {
    if (p === null || p === undefined) progressBar.removeAttribute('value'); else progressBar.value = p;
    const done = p === null || p === undefined ? (count ? `, ${count} so far` : '') : ` ${Math.round(100 * p)} %`;
    say(`${file.name}${what ? ` ${what}` : ''}: ${phase}${done}`);
  };

  // Adds scans as a new data set with its group of the scan chooser, and makes its first scan the source.
  function addScans(file, { scans, unit = 'scan', cloud }, caption) {
    const name = `file${++serial}`;
    data.addDataset(name, { label: caption, unit, scans, cloud });
    const group = document.createElement('optgroup');
    group.label = caption;
    scans.forEach((s, k) => {
      const o = document.createElement('option');
      o.value = `${name}:${k}`;
      const n = s.returns ?? s.points.length / 2;
      // the file is the group's label: the option itself stays short, since a closed drop-down cuts what does not fit
      o.textContent = `${unit} ${k}${unit !== 'ring' && s.ring !== undefined ? ` (ring ${s.ring})` : ''}: ${n} points${s.clusters !== undefined ? `, ${s.clusters} cluster${s.clusters === 1 ? '' : 's'}` : ''}`;
      o.title = `${caption}, ${o.textContent}`;
      group.append(o);
    });
    chooser.append(group);
    chooser.disabled = false;
    chooser.value = `${name}:0`;
    onSource({ dataset: name, scan: 0 });
    return name;
  }

  const readMessage = (caption, scans, unit, note) =>
    `${caption}: ${scans.length} ${unit}${scans.length === 1 ? '' : 's'} read${note ? ` (${note})` : ''}. The lessons now run on ${unit} 0; choose another in the list.`;

  // A failure after some scans: they are kept (a data set) and the message says both.
  function failed(file, e, caption) {
    const msg = e.message.startsWith(file.name) ? e.message : `${file.name}: ${e.message}`;
    if (e.scans?.length) {
      addScans(file, { scans: e.scans, unit: 'scan' }, caption);
      say(`${msg}. The ${e.scans.length} scan${e.scans.length === 1 ? '' : 's'} before it can be chosen in the list.`, true);
    } else {
      say(msg, true);
    }
  }

  function showTopics(file, topics) {
    topicChooser.replaceChildren(...topics.list.map((t) => {
      const o = document.createElement('option');
      o.value = t.name;
      o.textContent = `${t.name} · ${t.type.replace(/^.*[/.]/, '')} · ${t.count ?? '?'} message${t.count === 1 ? '' : 's'}`;
      o.disabled = !isScanTopic(t);
      return o;
    }));
    topicChooser.value = topics.current;
    topicLabel.hidden = false;
  }

  async function chooseTopic(topic) {
    const log = openLog;
    if (!log) return;
    if (log.datasets.has(topic)) { const name = log.datasets.get(topic); chooser.value = `${name}:0`; onSource({ dataset: name, scan: 0 }); return; }
    const caption = `${log.file.name} ${topic}`;
    progressBar.hidden = false;
    progressBar.value = 0;
    topicChooser.disabled = true;
    try {
      const r = await log.topics.read(topic, showProgress(log.file, topic));
      if (openLog !== log) return;   // another file was opened meanwhile
      if (!r.scans.length) throw new Error(`${log.file.name}: topic ${topic} has no scan`);
      log.datasets.set(topic, addScans(log.file, r, caption));
      say(readMessage(caption, r.scans, 'scan'));
    } catch (e) {
      if (openLog === log) failed(log.file, e, caption);
    } finally {
      if (openLog === log) progressBar.hidden = true;
      topicChooser.disabled = false;
    }
  }

  async function openFile(file) {
    const reader = READERS.find((r) => r.test(file.name));
    if (!reader) { say(`${file.name}: not a format this page reads (${READERS.map((r) => r.label).join('; ')}).`, true); return; }
    openLog?.close();   // the topic chooser is the last log's; another file ends it
    openLog = null;
    topicLabel.hidden = true;
    progressBar.hidden = false;
    progressBar.value = 0;
    say(`Reading ${file.name}…`);
    let caption = file.name;
    try {
      const r = await reader.read(file, showProgress(file));
      const { scans, unit = 'scan' } = r;
      if (r.topics) caption = `${file.name} ${r.topics.current}`;
      if (!scans.length) throw new Error(`${file.name}: no scan in the file`);
      const name = addScans(file, r, caption);
      if (r.topics) {
        openLog = { file, topics: r.topics, close: r.close, datasets: new Map([[r.topics.current, name]]) };
        showTopics(file, r.topics);
      }
      say(readMessage(caption, scans, unit, r.note));
    } catch (e) {
      failed(file, e, caption);
    } finally {
      progressBar.hidden = true;
    }
  }

  input.addEventListener('change', () => { if (input.files[0]) openFile(input.files[0]); input.value = ''; });
  chooser.addEventListener('change', () => {
    const [dataset, scan] = chooser.value.split(':');
    onSource(dataset ? { dataset, scan: Number(scan) } : null);
  });
  topicChooser.addEventListener('change', () => chooseTopic(topicChooser.value));
  window.addEventListener('dragover', (ev) => { if (ev.dataTransfer?.types?.includes('Files')) { ev.preventDefault(); document.documentElement.classList.add('dropping'); } });
  window.addEventListener('dragleave', (ev) => { if (!ev.relatedTarget) document.documentElement.classList.remove('dropping'); });
  window.addEventListener('drop', (ev) => {
    document.documentElement.classList.remove('dropping');
    const file = ev.dataTransfer?.files?.[0];
    if (!file) return;
    ev.preventDefault();
    openFile(file);
  });
  return { openFile, chooseTopic };
}
