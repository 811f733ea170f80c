// The page's boot: loads the package (through the import map, /dist/index.js), builds the lesson menu from
// web/lessons/index.js, opens the lesson named by the URL hash, and connects it to the figure, the player and
// the export buttons. Test hook: window.__rtl = { ready, errors, lessons: [{ id, title, steps, step }], current,
// revision, finalState(), figureExtent(), clientPoint(x, y), exportArguments(), highlighted(), figureQuantities(),
// figureTitle(), lecture, link() }.
import init from 'rtl-wasm';
import { createData } from './data.js';
import { Figure } from './figure.js';
import { Player } from './player.js';
import { download, exportArguments, figureSvg, figureTikz } from './export.js';
import { wireLecture } from './lecture.js';
import { Predict } from './predict.js';
import { wireTextLink } from './text-link.js';
import { wireOpenData } from './open-data.js';
import { applyControls, formatHash, parseHash, readControls } from './link-state.js';
import LESSONS from './lessons/index.js';

const $ = (id) => document.getElementById(id);
const hook = (window.__rtl = {
  ready: false, errors: [], revision: 0, current: null,
  lessons: LESSONS.map(({ id, title }) => ({ id, title, steps: null, step: null })),
});
// Chromium reports a ResizeObserver that could not deliver every notification in one frame as an error event; it
// is a notice (the observers run again next frame), not a failure of the page.
window.addEventListener('error', (e) => { if (!/^ResizeObserver loop/.test(e.message)) hook.errors.push(String(e.message)); });
window.addEventListener('unhandledrejection', (e) => hook.errors.push(String(e.reason?.message ?? e.reason)));

const state = { rtl: null, data: null, lesson: null, instance: null, figure: null, player: null, opening: 0, written: null, source: null };

function setStatus(text, isError = false) {
  const el = $('status');
  el.textContent = text;
  el.classList.toggle('error', isError);
}

function entry(id) { return hook.lessons.find((l) => l.id === id); }

function buildMenu() {
  const nav = $('lesson-menu');
  nav.replaceChildren(...LESSONS.map((l) => {
    const a = document.createElement('a');
    a.href = `#${l.id}`;
    a.textContent = l.menu ?? l.title;
    a.dataset.lesson = l.id;
    a.title = l.summary;
    return a;
  }));
}

function showStep(k) {
  const { instance, lesson } = state;
  if (!instance) return;
  try {
    instance.show(k);
  } catch (e) {
    reportError(e);
  }
  const e = entry(lesson.id);
  e.step = k;
  state.predict?.stepped(k);
  writeLink();
  hook.revision += 1;
}

// The view's link: the open lesson, its form's parameters and the step (web/link-state.js). Written in place
// (replaceState), so stepping does not fill the history, and remembered so that our own write is not reopened.
function currentHash() {
  const { lesson, player } = state;
  const steps = entry(lesson.id).steps;
  return formatHash(lesson.id, readControls($('lesson-controls')), steps > 0 ? player.step + 1 : null, state.source, Boolean(hook.lecture?.on));
}
function writeLink() {
  if (!state.instance || !state.lesson) return;
  const hash = currentHash();
  if (hash === location.hash) return;
  state.written = hash;
  history.replaceState(history.state, '', hash);
}

async function copyLink() {
  writeLink();
  const url = location.href, out = $('link-status');
  try {
    await navigator.clipboard.writeText(url);
    out.textContent = `Link copied: it opens this lesson with these parameters at this step${hook.lecture.on ? ', in lecture mode' : ''}.`;
  } catch {
    // no clipboard (permission refused, insecure origin): show the link selected, ready for Ctrl+C
    out.replaceChildren('Copy this link: ');
    const field = Object.assign(document.createElement('input'), { type: 'text', readOnly: true, value: url, className: 'link-field' });
    field.setAttribute('aria-label', 'Link to this view');
    out.append(field);
    field.select();
  }
}

function reportError(e) {
  setStatus(`Error: ${e.message}`, true);
  hook.errors.push(String(e.message));
  console.error(e);
}

// Recomputes the open lesson's trace (after a parameter change) and reloads the player, keeping its place.
// keepAt: 'start' = the lesson's own first step (or its jump); { exact: k } = step k whatever the lesson says (a link).
function recompute(keepAt) {
  const { instance, lesson } = state;
  if (!instance) return;
  let steps = 0, start = 0, jump;
  try {
    ({ steps, start = 0, jump } = instance.recompute());
  } catch (e) {
    reportError(e);
  }
  entry(lesson.id).steps = steps;
  state.predict.attach(instance);   // a new trace: its questions start afresh
  const at = keepAt?.exact ?? (keepAt === 'start' ? jump ?? start : jump ?? keepAt ?? state.player.step);
  state.player.load(steps, at);
}

// Opens the lesson of a hash ("#dp", or a link "#dp?epsilon=0.06&at=5": its parameters and step restored).
async function open(hash) {
  const link = parseHash(hash);
  const lesson = LESSONS.find((l) => l.id === link.id) ?? LESSONS[0];
  // a link's data source: a bundled log, or a file opened in this page (a file cannot travel in a link)
  let sourceNote = '';
  if (link.src) {
    const d = state.data.DATASETS[link.src.dataset];
    if (d && d.unit === 'scan' || state.data.loaded(link.src.dataset)) state.source = link.src;
    else sourceNote = `This link's data (${link.src.dataset}) is a file opened in another page: open the file here to see it. `;
  }
  const ticket = ++state.opening;
  state.player.pause();
  if (state.instance) { try { state.instance.dispose(); } catch (e) { reportError(e); } }
  state.figure?.dispose();
  state.instance = null;
  state.predict.attach(null);
  // a link in lecture mode opens in it (a link without it, e.g. one in the text, leaves the mode as it is)
  if (link.lecture && !hook.lecture.on) hook.lecture.set(true);
  state.lesson = lesson;
  hook.current = lesson.id;
  for (const a of $('lesson-menu').querySelectorAll('a')) {
    if (a.dataset.lesson === lesson.id) a.setAttribute('aria-current', 'page'); else a.removeAttribute('aria-current');
  }
  $('lesson-title').textContent = lesson.title;
  $('lesson-summary').textContent = lesson.summary;
  document.title = `${lesson.title} · RTL lessons`;
  for (const el of [$('lesson-controls'), $('lesson-text'), $('lesson-stage')]) { el.replaceChildren(); el.className = el.className.replace(/ lidar3d\b/, ''); }
  $('figure').hidden = Boolean(lesson.noFigure);
  $('player').hidden = Boolean(lesson.noFigure);
  // A fresh canvas per lesson: its figure's listeners and zoom die with it.
  const canvas = document.createElement('canvas');
  Object.assign(canvas, { id: 'canvas', tabIndex: 0 });
  canvas.setAttribute('role', 'img');
  canvas.setAttribute('aria-label', `Figure of the lesson ${lesson.title}`);
  canvas.setAttribute('aria-describedby', 'lesson-text');
  $('canvas-box').replaceChildren(canvas);
  state.figure = new Figure(canvas);
  const host = {
    rtl: state.rtl, data: state.data, figure: state.figure, source: state.source,
    controls: $('lesson-controls'), text: $('lesson-text'), stage: $('lesson-stage'),
    onParamsChanged: () => { if (state.instance && state.lesson === lesson) recompute(); },
    goTo: (k) => { state.player.pause(); state.player.go(k); },
  };
  setStatus(`Loading ${lesson.title}…`);
  try {
    const instance = await lesson.create(host);
    if (ticket !== state.opening) { instance.dispose(); return; }
    // a link's parameters go into the form before the first trace (the lesson reads its form in recompute())
    const refused = applyControls(host.controls, link.params);
    state.instance = instance;
    recompute(link.at ? { exact: link.at - 1 } : 'start');
    setStatus(sourceNote + (refused.length ? `This link's ${refused.join(', ')} do not apply to this lesson; the defaults are shown.` : ''), Boolean(sourceNote));
  } catch (e) {
    reportError(e);
  }
  hook.ready = true;
  hook.revision += 1;
}

async function main() {
  buildMenu();
  state.player = new Player($('player'), showStep);
  state.predict = new Predict({ root: $('predict'), toggle: $('your-turn'), player: state.player, figure: () => state.figure });
  hook.predict = () => ({ on: state.predict.on, step: state.predict.pending ? state.predict.pending.step : null, score: { ...state.predict.score } });
  try {
    state.rtl = await init();
  } catch (e) {
    setStatus(`Could not load the WebAssembly module: ${e.message}. Run "npm run build" first.`, true);
    hook.errors.push(String(e.message));
    return;
  }
  state.data = createData(state.rtl);
  hook.version = state.rtl.version;
  hook.finalState = () => state.instance?.finalState() ?? null;
  hook.figureExtent = () => state.figure?.extent() ?? null;
  hook.clientPoint = (x, y) => state.figure.clientPoint(x, y);
  // the export buttons' package-call arguments as plain data (tests repeat the calls in Node)
  hook.exportArguments = () => {
    const { drawing, svg } = exportArguments(state.figure);
    return { drawing: { ...drawing, points: Array.from(drawing.points), labels: Array.from(drawing.labels), segments: Array.from(drawing.segments) }, svg };
  };
  const name = () => `rtl-${state.lesson.id}-step${state.player.step + 1}`;
  $('dl-svg').addEventListener('click', async () => download(`${name()}.svg`, 'image/svg+xml', await figureSvg(state.rtl, state.figure)));
  $('dl-tikz').addEventListener('click', async () => download(`${name()}.tex`, 'text/x-tex', await figureTikz(state.rtl, state.figure)));
  $('reset-view').addEventListener('click', () => state.figure?.resetView());
  $('copy-link').addEventListener('click', copyLink);
  // the user's own data: the lesson reopens (its defaults) on the chosen scan
  wireOpenData({
    data: state.data, input: $('open-file'), progressBar: $('open-progress'), message: $('open-message'), chooser: $('scan-chooser'),
    onSource: (src) => { state.source = src; $('own-data').open = true; const hash = formatHash(state.lesson.id, [], null, src); state.written = hash; history.pushState(null, '', hash); open(hash); },
  });
  hook.source = () => state.source && { ...state.source };
  const textLink = wireTextLink($('lesson-text'), () => state.figure);
  hook.highlighted = () => textLink.current();
  // the figure's title as the scene names it, and the lines the canvas shows of it (wrapped, maybe shortened)
  hook.figureLabels = () => state.figure?.labelBoxes() ?? [];
  // the items drawn over the scene (the "your turn" rings and verdict marks), as plain data
  hook.figureOverlay = () => (state.figure?.overlay ?? []).map((it) => ({ ...it }));
  hook.figureTitle = () => state.figure && { title: state.figure.scene.title, lines: state.figure.titleLayout().lines };
  // the figure's items that draw a quantity of the text, as plain data (tests hover them)
  hook.figureQuantities = () => (state.figure?.scene.items ?? []).filter((it) => it.q)
    .map((it) => ({ ...it, ...(it.xy ? { xy: Array.from(it.xy) } : {}) }));
  hook.lecture = wireLecture({ player: state.player, button: $('lecture'), onChange: () => { state.figure?.render(); writeLink(); } });
  // a parameter the lesson redraws without a new trace (a selected point) changes the link too
  $('lesson-controls').addEventListener('input', () => queueMicrotask(writeLink));
  hook.link = () => { writeLink(); return location.href; };
  // a new hash (a link, the menu, Back/Forward over our replaced entries) opens its view; our own writes do not
  const navigate = () => { if (location.hash !== state.written) { state.written = location.hash; open(location.hash); } };
  window.addEventListener('hashchange', navigate);
  window.addEventListener('popstate', navigate);
  await open(location.hash);
}

main();
