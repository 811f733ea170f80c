// The vertex-budget lesson's data helpers (web/lessons/budget-run.js) in Node against the package: the snapshots are
// the package's results, the line a beam is explained by holds its predicted point, orthogonal = radial · cos, and the
// newly explained beams are those whose expected range became finite.
import { before, describe, test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { join } from 'node:path';
import init from 'rtl-wasm';
import { DATA } from './helpers.js';
import { J_MIN, J_MAX, beamsOf, runBudgets, residuals, lineOf, beamErrors, grazingBeam, newlyExplained, runsText, curveKnee } from '../../web/lessons/budget-run.js';

describe('budget-run.js', () => {
  let rtl, points, beams, snaps;
  before(async () => {
    rtl = await init();
    points = rtl.readCarmenLog(readFileSync(join(DATA, 'intel.log'), 'utf8'))[21].points;
    beams = beamsOf(points);
    snaps = runBudgets(rtl, points, {});
  });

  test('one snapshot per J, each the package\'s result copied out of wasm memory', () => {
    assert.equal(snaps.length, J_MAX - J_MIN + 1);
    for (const J of [2, 9, 20, 60]) {
      const s = snaps[J - J_MIN], r = rtl.extractPolylines(points, { maxVertices: J });
      assert.equal(s.J, J);
      assert.equal(s.vertexCount, r.vertexCount);
      assert.deepEqual(s.polylines, r.polylines.map((p) => Array.from(p)));
      assert.deepEqual(Array.from(s.expected, String), Array.from(r.expectedRanges, String));
      assert.ok(s.expected instanceof Float64Array && s.expected.buffer !== r.expectedRanges.buffer);
    }
  });

  test('beams: ranges and unit directions of the returned beams, NaN for the others', () => {
    let returned = 0;
    for (let i = 0; i < beams.n; i++) {
      if (!Number.isFinite(points[2 * i])) { assert.ok(Number.isNaN(beams.range[i])); continue; }
      returned++;
      assert.ok(Math.abs(beams.range[i] * beams.ux[i] - points[2 * i]) < 1e-12 && Math.abs(beams.range[i] * beams.uy[i] - points[2 * i + 1]) < 1e-12);
      assert.ok(Math.abs(Math.hypot(beams.ux[i], beams.uy[i]) - 1) < 1e-12);
    }
    assert.equal(returned, snaps[0].returned);
  });

  test('every explained beam has a line through its predicted point; orthogonal = radial · cos(incidence)', () => {
    const snap = snaps[20 - J_MIN], res = residuals(beams, snap);
    let explained = 0, sq = 0;
    for (let i = 0; i < beams.n; i++) {
      const line = lineOf(beams, snap, i);
      assert.equal(line !== null, Number.isFinite(snap.expected[i]), `beam ${i}`);
      if (!line) continue;
      explained++;
      sq += res[i] ** 2;
      const rh = snap.expected[i];
      assert.ok(Math.abs(rh * (beams.ux[i] * line.nx + beams.uy[i] * line.ny) - line.r) < 1e-6);
      const e = beamErrors(beams, snap, i);
      assert.ok(Math.abs(e.radial - Math.abs(res[i])) < 1e-12);
      assert.ok(Math.abs(e.orthogonal - e.radial * Math.cos((e.incidence * Math.PI) / 180)) < 1e-9, `beam ${i}`);
      assert.ok(e.orthogonal <= e.radial + 1e-12);
    }
    assert.equal(explained, snap.explainedBeams);
    assert.ok(Math.abs(Math.sqrt(sq / explained) - snap.rmse) < 1e-9, 'the residuals give the package\'s RMSE');
  });

  test('the grazing example: a typical error at the largest incidence up to 75°', () => {
    const snap = snaps[20 - J_MIN], g = grazingBeam(beams, snap);
    assert.ok(g.incidence > 45 && g.incidence <= 75, JSON.stringify(g));
    assert.ok(g.radial >= 0.5 * snap.rmse && g.radial <= 3 * snap.rmse);
    for (let i = 0; i < beams.n; i++) {
      const e = beamErrors(beams, snap, i);
      if (e && e.radial >= 0.5 * snap.rmse && e.radial <= 3 * snap.rmse && e.incidence <= 75) assert.ok(e.incidence <= g.incidence);
    }
    const none = { ...snap, expected: new Float64Array(beams.n).fill(NaN) };
    assert.equal(grazingBeam(beams, none), null);
  });

  test('newly explained beams and their runs as text', () => {
    const before = snaps[4], after = snaps[5];
    const gained = newlyExplained(beams, before, after);
    for (let i = 0; i < beams.n; i++) {
      const want = Number.isFinite(beams.range[i]) && !Number.isFinite(before.expected[i]) && Number.isFinite(after.expected[i]);
      assert.equal(gained.includes(i), want, `beam ${i}`);
    }
    assert.equal(runsText([3, 4, 5, 9, 11, 12]), '3–5, 9, 11–12');
    assert.equal(runsText([]), '');
  });

  test('the knee of the score curve: the first J within 10 % of the way from J = 2\'s score to the best, from the package\'s scores', () => {
    const scores = [];
    for (let J = J_MIN; J <= J_MAX; J++) scores.push(rtl.extractPolylines(points, { maxVertices: J }).score);
    const k = curveKnee(snaps);
    const best = Math.min(...scores), bound = best + 0.1 * (scores[0] - best);
    assert.equal(k.first.J, 2);
    assert.equal(k.first.score, scores[0]);
    assert.equal(k.best.score, best);
    assert.ok(k.score <= bound && k.score === scores[k.J - J_MIN]);
    for (let J = J_MIN; J < k.J; J++) assert.ok(scores[J - J_MIN] > bound, `J = ${J} is already within the bound`);
    // on this scan the curve bends well inside the range offered, not at either end
    assert.ok(k.J > 10 && k.J < 50, `knee at J = ${k.J}`);
    assert.equal(curveKnee(snaps, 0.5).J <= k.J, true, 'half the way comes no later than 90 %');
    assert.equal(curveKnee([]), null);
    assert.equal(curveKnee([{ J: 2, score: NaN }]), null);
  });
});
