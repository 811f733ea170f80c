// Helpers shared by the lessons: the excerpt a lesson starts on, the trace of a package call, and the replay of a
// trace prefix. Nothing here knows an algorithm: replays only fold the package's own events.
import { note, numberField } from './ui.js';

// The excerpt: cluster `cluster` of `scan` of `dataset` segmented with `segment` (the package's segment()), or the
// beams `beams: [first, last]` of that scan. Adds the lesson's note (which excerpt and why) to host.controls.
export async function loadExcerpt(host, ex) {
  ex = fromSource(host, ex);
  const { scan, chain, indices, where } = await excerptChain(host, ex);
  note(host.controls, `<strong>Excerpt:</strong> ${where}. ${ex.why}`);
  return { scan, chain, indices, where };
}

// The excerpt's chain of points without the note: { scan, chain, indices, where } (the overview measures the lessons'
// own excerpts with it to name the step its links land on).
export async function excerptChain(host, ex) {
  const scan = await host.data.scan(ex.dataset, ex.scan);
  let chain, indices;
  if (ex.beams) {
    const [first, last] = ex.beams;
    const f = host.data.finite(host.data.beams(scan.points, first, last));
    chain = f.xy;
    indices = f.index.map((i) => i + first);
  } else {
    // the cluster holding beam `clusterAt` when the scan is segmented with `segment`
    const { clusters } = host.rtl.segment(scan.points, ex.segment);
    if (!clusters.length) throw new RangeError(`${host.data.describe(ex.dataset, ex.scan)} has no cluster (no point with a return)`);
    // no clusterAt (the user's own scan): the largest cluster
    const k = ex.clusterAt === undefined
      ? clusters.reduce((best, c, i) => (c.indices.length > clusters[best].indices.length ? i : best), 0)
      : clusters.findIndex((c) => c.indices.includes(ex.clusterAt));
    indices = Array.from(clusters[k].indices);
    chain = host.data.gather(scan.points, indices);
    ex = { ...ex, cluster: k };
  }
  const seg = ex.segment ? `, segmented with step ${ex.segment.step}, bounds ${ex.segment.lowerBound}–${ex.segment.upperBound} m` : '';
  const where = `${host.data.describe(ex.dataset, ex.scan)}, ` +
    (ex.beams ? `beams ${ex.beams[0]}–${ex.beams[1]}` : `cluster ${ex.cluster + 1}${seg}`) + ` (${chain.length / 2} points, beams ${indices[0]}–${indices[indices.length - 1]})`;
  return { scan, chain, indices, where };
}

// The lesson's excerpt, or the scan the user chose (host.source: { dataset, scan }, e.g. their own file): then the
// scan's largest cluster (a chain lesson) or the whole scan (a segmentation lesson) is the excerpt.
export function fromSource(host, ex) {
  const src = host.source;
  if (!src) return ex;
  return { ...ex, dataset: src.dataset, scan: src.scan, beams: undefined, clusterAt: undefined, focusBeams: null, startAt: null,
    decisive: undefined, segment: ex.segment ?? { step: 3, lowerBound: 0.1, upperBound: 0.5 },
    why: ex.segment || ex.beams || ex.clusterAt !== undefined ? 'Your chosen scan: its largest cluster.' : 'Your chosen scan, whole.' };
}

// The trace of a traced package call: { trace, missing }. missing is the reason when this build of the package
// does not record that trace yet (an older dist/: the option is unknown, or the result has no trace); then trace = [].
export function traced(call, what) {
  let result;
  try {
    result = call();
  } catch (e) {
    if ((e instanceof RangeError || e instanceof TypeError) && /unknown option "trace"/.test(e.message)) return { trace: [], missing: missingText(what) };
    throw e;
  }
  const trace = Array.isArray(result.trace) ? result.trace : result;
  return Array.isArray(trace) ? { trace, missing: null } : { trace: [], missing: missingText(what) };
}
const missingText = (what) => `No step-by-step trace: this build of rtl-wasm does not record ${what} traces yet (a newer "npm run build" will). The figure shows the result.`;

// Point i of an interleaved chain.
export const pt = (xy, i) => [xy[2 * i], xy[2 * i + 1]];

// The chain points i in [first, end) as a new array.
export const slice = (xy, first, end) => xy.slice(2 * first, 2 * end);

// A numbered list of equal values, e.g. for "same as untraced" comparisons.
export const sameArrays = (a, b) => a.length === b.length && a.every((v, i) => v === b[i]);

// No step to show: the explanation says why (no trace in this build, or a parameter to fix).
export function explainNoSteps(host, missing) {
  host.text.innerHTML = '';
  const p = document.createElement('p');
  p.className = missing ? 'why' : 'fail';
  p.textContent = missing ?? 'Fix the marked parameter to see the steps.';
  host.text.append(p);
}

// Reads the parameters of `fields` ({ key: field }) through `check(values)` → { key: message } of invalid ones;
// marks the fields and returns the values, or null when any is invalid.
export function readParams(fields, check) {
  const values = Object.fromEntries(Object.entries(fields).map(([k, f]) => [k, f.read()]));
  const problems = check(values);
  for (const [k, f] of Object.entries(fields)) f.setError?.(problems[k] ?? null);
  return Object.keys(problems).length ? null : values;
}

export const positive = (v) => (Number.isFinite(v) && v > 0 ? null : 'must be a number above 0');
export const nonNegative = (v) => (Number.isFinite(v) && v >= 0 ? null : 'must be a number ≥ 0');

// The one-parameter vectorizer lessons (DP, RW, ITLS): the parameter's field (`field`: numberField's options without
// key and onInput) and recompute(), which makes the package's untraced result and the same call traced. show() and
// finalState() read run.params, run.untraced, run.trace and run.missing (what traced() says when there is no trace).
export function vectorizerRun(host, chain, { method, key, field, what }) {
  const fields = { [key]: numberField(host.controls, { key, ...field, onInput: host.onParamsChanged }) };
  const run = { params: null, untraced: null, trace: [], missing: null };
  run.recompute = () => {
    run.params = readParams(fields, (v) => (positive(v[key]) ? { [key]: positive(v[key]) } : {}));
    if (!run.params) { Object.assign(run, { trace: [], missing: null, untraced: null }); return { steps: 0 }; }
    const options = { method, [key]: run.params[key] };
    run.untraced = host.rtl.vectorize(chain, options);
    Object.assign(run, traced(() => host.rtl.vectorize(chain, { ...options, trace: true }), what));
    return { steps: run.trace.length };
  };
  return run;
}
