// The view as a link. The URL hash holds the lesson, every parameter of its form and the player's step:
//   #ftls?sigma=0.03&delta=0.05&split=0&at=14
// The lesson id comes first (so a plain `#dp` still opens a lesson with its defaults); then, as a query string, the
// value of every named input and select of the lesson's form (checkboxes as 1 / 0), and `at`, the step shown, counted
// from 1 as the player shows it. Parameters are whatever the lesson puts in its form: a lesson that offers a data
// set, a scan or a cluster as a field gets those into the link with no code of its own.
export const STEP_KEY = 'at';
// the data source when it is not the lesson's own excerpt: "dataset:scan" (a bundled log, or a file the user opened)
export const SOURCE_KEY = 'src';
// lecture mode (web/lecture.js) on: the link opens the figure full screen for a projector
export const LECTURE_KEY = 'lecture';

// { id, params: [[name, value], …] in URL order, at: 1-based step or null, src: { dataset, scan } or null,
//   lecture: true when the link asks for lecture mode } of a hash.
export function parseHash(hash) {
  const text = String(hash ?? '').replace(/^#/, '');
  const q = text.indexOf('?');
  const id = decodeURIComponent(q < 0 ? text : text.slice(0, q));
  const query = new URLSearchParams(q < 0 ? '' : text.slice(q + 1));
  const params = [];
  let at = null, src = null, lecture = false;
  for (const [k, v] of query) {
    if (k === STEP_KEY) { const n = Number(v); at = Number.isInteger(n) && n >= 1 ? n : null; }
    else if (k === LECTURE_KEY) lecture = v === '1';
    else if (k === SOURCE_KEY) { const m = v.match(/^([\w.-]+):(\d+)$/); src = m ? { dataset: m[1], scan: Number(m[2]) } : null; }
    else params.push([k, v]);
  }
  return { id, params, at, src, lecture };
}

// The hash (with its "#") of lesson `id`, its parameters ([[name, value], …]), the 1-based step `at` (null: none)
// the data source `src` ({ dataset, scan }, null: the lesson's own excerpt) and lecture mode (`lecture`: true adds
// lecture=1).
export function formatHash(id, params = [], at = null, src = null, lecture = false) {
  const query = new URLSearchParams(params);
  if (src) query.set(SOURCE_KEY, `${src.dataset}:${src.scan}`);
  if (lecture) query.set(LECTURE_KEY, '1');
  if (at !== null && at !== undefined) query.set(STEP_KEY, String(at));
  const q = query.toString();
  return `#${encodeURIComponent(id)}${q ? `?${q}` : ''}`;
}

// The named, enabled inputs and selects of a form that hold a parameter (buttons and file pickers hold none).
function parameterElements(form) {
  return [...form.querySelectorAll('input[name], select[name]')]
    .filter((el) => !el.disabled && !['button', 'submit', 'reset', 'file', 'image'].includes(el.type));
}

// [[name, value], …] of the form's parameters in document order (a name seen twice keeps its first element).
export function readControls(form) {
  const seen = new Set(), out = [];
  for (const el of parameterElements(form)) {
    if (seen.has(el.name)) continue;
    seen.add(el.name);
    out.push([el.name, el.type === 'checkbox' ? (el.checked ? '1' : '0') : el.value]);
  }
  return out;
}

// Sets the form's parameters from [[name, value], …] and fires each changed element's own `input` event, so the
// lesson's handlers (value labels, a cluster pick) run as if the user had set it. Returns the names it could not
// apply (no such field, or a value the field refuses, e.g. an option a select does not have).
export function applyControls(form, params) {
  const byName = new Map(parameterElements(form).map((el) => [el.name, el]));
  const refused = [];
  for (const [name, value] of params) {
    const el = byName.get(name);
    if (!el) { refused.push(name); continue; }
    if (el.type === 'checkbox') {
      const on = value === '1' || value === 'true';
      if (el.checked === on) continue;
      el.checked = on;
    } else {
      if (el.value === value) continue;
      el.value = value;
      if (el.value !== value && !(el.type === 'range' || el.type === 'number')) { refused.push(name); continue; }
    }
    el.dispatchEvent(new Event('input', { bubbles: true }));
  }
  return refused;
}
