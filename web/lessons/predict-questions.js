// The "your turn" questions (web/predict.js) of each trace lesson, read off the package's trace: which event is
// decisive, what the right answer is and why, in the trace's own numbers. Nothing is computed here that the trace
// does not already say. Each function returns `predict` for a lesson instance: { ask(k) → question | null }.
import { newlyExplained, runsText } from './budget-run.js';

const f3 = (v) => (Number.isFinite(v) ? `${v.toFixed(3)} m` : 'infinitely far (the lines are parallel)');
const YES_NO = [{ value: 'yes', label: 'Yes' }, { value: 'no', label: 'No' }];

// The points of a chain with these indices, for a question answered by clicking one.
const pointsOf = (xy, indices) => indices.map((index) => ({ index, x: xy[2 * index], y: xy[2 * index + 1] }));
// A verdict's marks (web/predict.js draws them): point i of a chain, the student's pick, the middle of two points.
const at = (xy, i) => ({ x: xy[2 * i], y: xy[2 * i + 1] });
const pick = (xy, i, text) => ({ ...at(xy, i), kind: 'pick', text });
const between = (xy, i, j) => ({ x: (xy[2 * i] + xy[2 * j]) / 2, y: (xy[2 * i + 1] + xy[2 * j + 1]) / 2 });
// How far a wrong pick lies from the right answer, in the figure's metres: ", 0.431 m from point 17" (nearest of several).
const apart = (xy, i, answers, noun) => {
  const d = (j) => Math.hypot(xy[2 * i] - xy[2 * j], xy[2 * i + 1] - xy[2 * j + 1]);
  const j = answers.reduce((b, a) => (d(a) < d(b) ? a : b), answers[0]);
  return `, ${f3(d(j))} from ${noun} ${j}`;
};

// Douglas–Peucker: before each range that splits, "click the point where it splits".
export function dpQuestions(run, chain) {
  return {
    ask(k) {
      const e = run.trace[k];
      if (!e || e.kind !== 'range' || !e.split) return null;
      const interior = Array.from({ length: e.last - e.first - 1 }, (_, j) => e.first + 1 + j);
      return {
        prompt: `Douglas–Peucker examines points ${e.first}–${e.last} next (ringed), and this range splits (ε = ${f3(e.epsilon)}). Which point does it keep as the new corner?`,
        points: pointsOf(chain, interior),
        check(given) {
          const p = Number(given);
          const answer = { ...at(chain, e.farthest), kind: 'answer', text: `farthest: ${e.farthest}, ${f3(e.distance)} > ε` };
          return p === e.farthest
            ? { right: true, marks: [{ ...answer, text: `your pick ${p}: ${f3(e.distance)} > ε` }], html: `Point ${e.farthest} is the interior point farthest from the chord ${e.first}–${e.last}: ${f3(e.distance)}, more than ε = ${f3(e.epsilon)}, so it becomes a corner.` }
            : { right: false, marks: [pick(chain, p, `your pick: ${p}${apart(chain, p, [e.farthest], 'point')}`), answer], html: `You picked point ${p}${apart(chain, p, [e.farthest], 'point')}. The package measured point ${e.farthest} farthest from the chord ${e.first}–${e.last}, at ${f3(e.distance)} (more than ε = ${f3(e.epsilon)}): the split is there, and no other point of the range is that far.` };
        },
      };
    },
  };
}

// Reumann–Witkam: before a point leaves the strip, "click the first point outside the strip".
export function rwQuestions(run, chain) {
  return {
    ask(k) {
      const e = run.trace[k];
      if (!e || e.kind !== 'exit') return null;
      const strip = run.trace.slice(0, k).reverse().find((t) => t.kind === 'strip' && t.key === e.key);
      const after = Array.from({ length: chain.length / 2 - 1 - (strip?.through ?? e.key) }, (_, j) => (strip?.through ?? e.key) + 1 + j);
      return {
        prompt: `The strip of half-width ε = ${f3(e.epsilon)} runs from key point ${e.key}${strip ? ` through point ${strip.through}` : ''}. Which point is the first to leave it?`,
        points: pointsOf(chain, after),
        check(given) {
          const p = Number(given);
          const answer = { ...at(chain, e.index), kind: 'answer', text: `first outside: ${e.index}, ${f3(e.distance)} > ε` };
          return p === e.index
            ? { right: true, marks: [{ ...answer, text: `your pick ${p}: ${f3(e.distance)} > ε` }], html: `Point ${e.index} is ${f3(e.distance)} from the strip's axis, more than ε: point ${e.index - 1} becomes the next key.` }
            : { right: false, marks: [pick(chain, p, `your pick: ${p} (${p < e.index ? 'inside the strip' : 'after the exit'})${apart(chain, p, [e.index], 'point')}`), answer], html: `You picked point ${p}${apart(chain, p, [e.index], 'point')}. The first point outside is ${e.index}, ${f3(e.distance)} from the axis (ε = ${f3(e.epsilon)})${p < e.index ? `; point ${p} comes before it and is still inside` : `; the scan stops at ${e.index} before reaching ${p}`}.` };
        },
      };
    },
  };
}

// CAR and IA: "do these two points link?" at the close calls, the comparisons whose distance is within a factor 2
// of the threshold (clear cases would only slow the player down).
export function compareQuestions(run, points) {
  return {
    ask(k) {
      const e = run.trace[k];
      if (!e || (e.kind !== 'compare' && e.kind !== 'seam')) return null;
      if (!(e.distance >= e.threshold / 2 && e.distance <= 2 * e.threshold)) return null;
      return {
        prompt: `Point ${e.i} is compared with point ${e.j} (ringed). Do they link (the same cluster)? Point ${e.i}'s threshold is ${f3(e.threshold)}.`,
        marks: pointsOf(points, [e.i, e.j]),
        choices: YES_NO,
        check(given) {
          const right = (given === 'yes') === e.linked;
          const why = `they are ${f3(e.distance)} apart, ${e.linked ? 'within' : 'beyond'} the threshold ${f3(e.threshold)}`;
          const marks = [{ ...between(points, e.i, e.j), kind: 'answer', text: `${e.linked ? 'link' : 'no link'}: ${f3(e.distance)} ${e.linked ? '≤' : '>'} ${f3(e.threshold)}` }];
          return { right, marks, html: right ? `They ${e.linked ? 'link' : 'do not link'}: ${why}.` : `They ${e.linked ? 'do link' : 'do not link'}: ${why}.` };
        },
      };
    },
  };
}

// FTLS / AFTLS: before each corner check, "does this corner meet within δ?"
export function cornerQuestions(run, chain) {
  return {
    ask(k) {
      const e = run.trace[k];
      if (!e || e.kind !== 'corner') return null;
      return {
        prompt: `The lines of the ranges on each side of the corner between points ${e.boundary - 1} and ${e.boundary} (ringed) are fitted. Do they meet within δ = ${f3(e.delta)} of that corner?`,
        marks: pointsOf(chain, [e.boundary - 1, e.boundary]),
        choices: YES_NO,
        check(given) {
          const right = (given === 'yes') === e.ok;
          const why = `the two lines cross ${f3(e.crossingDistance)} from the middle of points ${e.boundary - 1} and ${e.boundary}, ${e.ok ? 'within' : 'beyond'} δ = ${f3(e.delta)}`;
          const marks = [{ ...between(chain, e.boundary - 1, e.boundary), kind: 'answer', text: `${e.ok ? 'meets' : 'misses'}: ${f3(e.crossingDistance)} ${e.ok ? '≤' : '>'} δ` }];
          return { right, marks, html: `${e.ok ? 'It meets' : 'It does not meet'}: ${why}${e.ok ? '' : ', so the partition must be repaired there'}.` };
        },
      };
    },
  };
}

// The vertex budget: when one more vertex explains beams that were unexplained, "click a beam the bigger budget will
// explain" among those unexplained now (ringed). run = { snaps (extractPolylines results per J), points, beams
// (budget-run.js) }; only the package's expected ranges say which beams are explained (r̂ finite) and by how much
// they miss.
export function budgetQuestions(run) {
  const unexplainedIn = (snap) => {
    const out = [];
    for (let i = 0; i < run.beams.n; i++) if (Number.isFinite(run.beams.range[i]) && !Number.isFinite(snap.expected[i])) out.push(i);
    return out;
  };
  return {
    ask(k) {
      const before = run.snaps[k - 1], after = run.snaps[k];
      if (!before || !after) return null;
      const was = unexplainedIn(before), gained = newlyExplained(run.beams, before, after);
      // a real choice: several beams newly explained, others that stay unexplained
      if (gained.length < 3 || gained.length === was.length) return null;
      const range = (i) => run.beams.range[i];
      const change = `the score went from ${before.score.toFixed(4)} to ${after.score.toFixed(4)} m²`;
      return {
        prompt: `The budget grows from J = ${before.J} to J = ${after.J}. ${was.length} beams are unexplained now (ringed). The package spends the budget where the score falls most: click one beam it will explain at J = ${after.J}.`,
        points: pointsOf(run.points, was),
        check(given) {
          const p = Number(given), where = `beams ${runsText(gained)} (${gained.length} beams)`;
          const mid = gained[Math.floor(gained.length / 2)];
          const answers = gained.map((i) => ({ ...at(run.points, i), kind: 'answer', text: i === mid ? `explained at J = ${after.J}: beams ${runsText(gained)}` : undefined }));
          if (Number.isFinite(after.expected[p])) {
            return { right: true, marks: [...answers, { ...at(run.points, p), kind: 'answer', text: `your pick ${p}: misses by ${f3(Math.abs(range(p) - after.expected[p]))}` }], html: `Beam ${p} is explained at J = ${after.J}: it misses the map by ${f3(Math.abs(range(p) - after.expected[p]))} along its ray instead of counting as the unexplained cost. The budget went to ${where}; ${change}.` };
          }
          return { right: false, marks: [...answers, pick(run.points, p, `your pick: ${p} (unexplained)${apart(run.points, p, gained, 'beam')}`)], html: `You picked beam ${p}${apart(run.points, p, gained, 'beam')} (the nearest it explains): it stays unexplained at J = ${after.J}. The package spent the budget on ${where}, a stretch that lines explain well; ${change}.` };
        },
      };
    },
  };
}
