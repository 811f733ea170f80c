// The opening screen: what the library is for. One real scan goes from raw beams to points, clusters (segment) and
// line segments (vectorize, Douglas–Peucker); then a short stretch of the log, each scan treated the same way and
// placed by its pose (TfTree), builds a small map. One player step per stage, then one per scan of the stretch. Each
// stage names its numbers and links into its lesson, at the step of that lesson where the stage's decisive moment
// happens (the link is the lesson's URL state: web/link-state.js).
import { INK, Scene } from '../figure.js';
import { formatHash } from '../link-state.js';
import { readParams, positive } from './common.js';
import { checkBounds, drawClusters, segFields } from './seg-common.js';
import { MIN_CLUSTER, carMoment, dpMoment, mapStretch, scanPipeline } from './overview-pipeline.js';
import { m, note, numberField, selectField } from './ui.js';

const STAGES = ['beams', 'points', 'clusters', 'segments'];
// Intel scan 17: a room corner with a door frame and a corridor; the stretch 12–21 turns through the room.
const DEFAULT = { dataset: 'intel', scan: 17, stretch: 10 };
const TF_POSE_STEP = 3;   // the tf-tree lesson's step "robot → map"

const link = (id, params, at, text) => `<a class="lesson-link" href="${formatHash(id, Object.entries(params).map(([k, v]) => [k, String(v)]), at)}">${text}</a>`;
const q = (name, value, text = value) => `<span class="qty" data-q="${name}">${text}</span>`;

export default {
  id: 'overview',
  menu: 'Overview',
  title: 'From a scan to a map',
  summary: 'One laser scan becomes points, clusters and walls; a few scans placed by their poses become a map. Press play, or step.',
  async create(host) {
    // the bundled 2D logs and every file the user opened (a CSV is one 'point set')
    const datasets = Object.entries(host.data.DATASETS).filter(([, d]) => d.unit === 'scan' || d.user);
    const source = selectField(host.controls, { key: 'dataset', label: 'log', options: datasets.map(([k, d]) => [k, d.label]), value: host.source?.dataset ?? DEFAULT.dataset, onInput: host.onParamsChanged });
    const scanField = numberField(host.controls, { key: 'scan', label: 'scan', kind: 'number', value: host.source?.scan ?? DEFAULT.scan, min: 0, max: 1000, step: 1, digits: 0, onInput: host.onParamsChanged });
    const fields = {
      ...segFields(host, { step: 3, stepLabel: 'segment: step s' }),
      epsilon: numberField(host.controls, { key: 'epsilon', label: 'ε: Douglas–Peucker', value: 0.05, min: 0.005, max: 0.4, step: 0.005, unit: 'm', onInput: host.onParamsChanged }),
    };
    if (host.source) note(host.controls, `<strong>Your chosen scan:</strong> ${host.data.describe(host.source.dataset, host.source.scan)} (set the log and scan here to look at others).`);
    note(host.controls, 'Every number below comes from the package: <code>readCarmenLog</code>, <code>segment</code>, <code>vectorize</code>, <code>TfTree</code>. The links open each lesson at the step where its stage is decided.');
    let run = null;   // { params, scans, one, map, car, dp, dataset, scan }
    let ticket = 0;

    const lesson = {
      // every log the source field offers is read once up front (data.load caches it), so that recompute() and a
      // link's data set need no wait
      prepare: () => Promise.all(datasets.map(([k]) => host.data.load(k))),
      recompute() {
        const params = readParams(fields, (v) => ({ ...checkBounds(v), ...(positive(v.epsilon) ? { epsilon: positive(v.epsilon) } : {}), ...(Number.isInteger(v.step) && v.step >= 1 ? {} : { step: 'must be a whole number ≥ 1' }) }));
        const name = source.read(), scans = host.data.loaded(name);
        const k = scanField.read();
        const scanOk = scans && Number.isInteger(k) && k >= 0 && k < scans.length;
        scanField.setError(scanOk || !scans ? null : `must be a whole number from 0 to ${scans.length - 1}`);
        if (!params || !scanOk) { run = null; return { steps: 0 }; }
        const first = Math.max(0, Math.min(k - Math.floor(DEFAULT.stretch / 2), scans.length - DEFAULT.stretch));
        const last = Math.min(scans.length - 1, first + DEFAULT.stretch - 1);
        run = { params, name, k, one: scanPipeline(host.rtl, scans[k], params), map: mapStretch(host.rtl, scans, first, last, params), car: null, dp: null };
        // the links' steps need the lessons' own excerpts (read asynchronously); the text updates when they arrive
        const mine = ++ticket, at = run;
        Promise.all([carMoment(host, params), dpMoment(host, params)]).then(([car, dp]) => {
          if (mine !== ticket) return;
          at.car = car; at.dp = dp;
          if (lesson.step !== undefined) lesson.show(lesson.step);
        }, (e) => { host.text.insertAdjacentHTML('beforeend', `<p class="fail">Could not measure the lessons' steps: ${e.message}</p>`); });
        return { steps: STAGES.length + run.map.length };
      },
      show(k) {
        this.step = k;
        if (k < 0 || !run) { host.figure.show(new Scene('From a scan to a map')); host.text.innerHTML = '<p class="fail">Fix the marked parameter to see the pipeline.</p>'; return; }
        const { one, params, name, k: idx } = run;
        const where = `${host.data.DATASETS[name].label}, scan ${idx}`;
        const stage = STAGES[k] ?? 'map';
        const s = new Scene(stage === 'map' ? `Map of ${host.data.DATASETS[name].label}, scans ${run.map[0].index}–${run.map.at(-1).index}` : `${where}: ${stage}`);
        const stageList = `<ol class="stages">${['raw beams', 'points', 'clusters', 'line segments', 'map'].map((t, i) => `<li${i === Math.min(k, 4) ? ' aria-current="step"' : ''}>${t}</li>`).join('')}</ol>`;
        let html = '';
        if (stage !== 'map') host.figure.fitPoints(one.points);
        if (stage === 'beams') {
          const rays = [];
          for (let i = 0; i < one.beams; i++) if (Number.isFinite(one.points[2 * i])) rays.push(0, 0, one.points[2 * i], one.points[2 * i + 1]);
          s.segments(rays, { colour: '#b8c7dc', width: 0.6, q: 'beams' });
          s.marker(0, 0, { colour: INK.current, shape: 'x', size: 6 });
          html = `<p>The laser turns and measures ${q('beams', one.beams)} ranges, one per beam, from −90° to +90°. ${q('returns', one.returns)} hit something; <b>${one.gaps}</b> saw nothing within the sensor's range (gaps).</p>` +
            '<p class="why">Each ray is one range reading, drawn from the sensor (the cross) to what it hit.</p>';
        } else if (stage === 'points') {
          s.points(one.points, { label: -1, colour: INK.segment, radius: 2.4, q: 'returns' });
          s.marker(0, 0, { colour: INK.current, shape: 'x', size: 6 });
          html = `<p>Each return becomes a point (r cos a, r sin a) in the robot's frame: ${q('returns', one.returns)} points, in beam order. ` +
            'Nothing says yet which points belong together.</p>';
        } else if (stage === 'clusters') {
          drawClusters(s, one.points, one.labels);
          const big = one.clusters.filter((c) => c.indices.length >= MIN_CLUSTER).length;
          html = `<p><code>segment</code> (CAR, step ${params.step}, threshold between ${m(params.lowerBound, 2)} and ${m(params.upperBound, 2)}) cuts the scan into <b>${one.clusters.length}</b> clusters (${big} of ${MIN_CLUSTER}+ points): ` +
            'neighbouring points closer than a range-dependent threshold belong together.</p>' +
            (run.car ? `<p class="why">Decided in the CAR lesson at ${link('car', { step: params.step, lowerBound: params.lowerBound, upperBound: params.upperBound }, run.car.at, `step ${run.car.at}`)}: ${run.car.what}.</p>` : '<p class="why">Measuring the CAR lesson…</p>');
        } else if (stage === 'segments') {
          drawClusters(s, one.points, one.labels);
          for (const l of one.lines) s.segments(l.segments, { colour: INK.segment, width: 2.2, q: 'segments' });
          html = `<p><code>vectorize</code> (Douglas–Peucker, ε = ${m(params.epsilon)}) turns each cluster of ${MIN_CLUSTER}+ points into a polyline: ${q('segments', one.segmentCount)} line segments stand for ${q('returns', one.returns)} points.</p>` +
            (run.dp ? `<p class="why">Decided in the Douglas–Peucker lesson at ${link('dp', { epsilon: params.epsilon }, run.dp.at, `step ${run.dp.at}`)}: ${run.dp.what}. Other methods fit lines instead: ${link('ftls', {}, null, 'FTLS')}, ${link('compare', { epsilon: params.epsilon }, null, 'compare them')}.</p>` : '<p class="why">Measuring the Douglas–Peucker lesson…</p>');
        } else {
          const upto = run.map.slice(0, k - STAGES.length + 1), cur = upto.at(-1);
          // the view follows the map as it grows (the scans placed so far), so that it fills the figure at every step
          // rather than waiting in a corner of the whole stretch's extent
          host.figure.fitPoints(upto.flatMap((r) => [...r.segments, r.pose.x, r.pose.y]));
          // the map grows: the scans placed so far, their points faint under their segments
          for (const r of upto) s.points(r.points, { colour: '#c9d3e0', radius: 1.3 });
          for (const r of upto) s.segments(r.segments, { colour: r === cur ? INK.candidate : INK.segment, width: r === cur ? 2.2 : 1.6, q: 'mapSegments' });
          s.polyline(upto.flatMap((r) => [r.pose.x, r.pose.y]), { colour: INK.current, width: 1.5, dash: true, q: 'travelled' });
          for (const r of upto) {
            const a = r.pose.theta, l = 0.45;
            s.segments([r.pose.x, r.pose.y, r.pose.x + l * Math.cos(a), r.pose.y + l * Math.sin(a)], { colour: INK.current, width: 2 });
            s.marker(r.pose.x, r.pose.y, { colour: INK.current, shape: 'dot', size: 4, q: 'scans' });
          }
          const total = upto.reduce((a, r) => a + r.segmentCount, 0);
          let travelled = 0;
          for (let i = 1; i < upto.length; i++) travelled += Math.hypot(upto[i].pose.x - upto[i - 1].pose.x, upto[i].pose.y - upto[i - 1].pose.y);
          html = `<p>Scan ${cur.index} at its pose (${cur.pose.x.toFixed(2)}, ${cur.pose.y.toFixed(2)}) m, heading ${(cur.pose.theta * 180 / Math.PI).toFixed(0)}°: a <code>TfTree</code> (map → robot) moves its ${cur.segmentCount} segments into the map (blue). ` +
            `So far ${q('scans', upto.length)} scans, ${q('mapSegments', total)} segments, ${q('travelled', travelled.toFixed(2))} m travelled (orange: the poses).</p>` +
            `<p class="why">How a frame moves points: the ${link('tf-tree', {}, TF_POSE_STEP, `transformation tree lesson, step ${TF_POSE_STEP}`)}. The walls of successive scans fall on each other because the log's poses are corrected.</p>`;
        }
        host.figure.show(s);
        host.text.innerHTML = stageList + html;
      },
      finalState() {
        if (!run) return { method: 'overview', step: this.step ?? -1, steps: 0, params: null };
        const { one } = run;
        return {
          method: 'overview', step: this.step ?? -1, steps: STAGES.length + run.map.length,
          params: { ...run.params, dataset: run.name, scan: run.k },
          numbers: { beams: one.beams, returns: one.returns, gaps: one.gaps, clusters: one.clusters.length, segments: one.segmentCount, mapScans: run.map.map((r) => r.index) },
          links: { car: run.car, dp: run.dp },
        };
      },
      dispose() { ticket++; },
    };
    await lesson.prepare();
    return lesson;
  },
};
