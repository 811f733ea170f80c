// "Your turn": predict, then reveal. With the switch on (off by default), the player stops before each step the open
// lesson asks about, poses the question, and only after an answer plays the step and says whether the answer was
// right, with the trace's own numbers. The score counts the session's answers (sessionStorage: it survives changing
// lesson and reloading, and is gone with the tab).
//
// A lesson takes part by giving its instance `predict: { ask(k) }` (web/lessons/predict-questions.js builds these
// from a trace): ask(k) is null, or the question about step k, asked while step k - 1 is shown:
//   { prompt: HTML,
//     choices: [{ value, label }]            — answer with a button, or
//     points: [{ index, x, y }]              — answer by clicking one of these points of the figure,
//     check(given) → { right: bool, html },  — the verdict and why, from the trace's numbers;
//     marks?: [{ x, y }] }                   — points the question is about, ringed in the figure while it is asked.
// check's verdict may carry marks too: [{ x, y, kind: 'pick' | 'answer', text? }], drawn over the revealed step so
// that the figure shows the student's pick (a cross) apart from the right answer (a ring), each with its numbers.
const STORE = 'rtl-predict-score';

// The verdict's marks as figure items: the pick a vermilion cross, the answer a green ring, each labelled.
const VERDICT_INK = { pick: ['#D55E00', '#A63D00'], answer: ['#009E73', '#00704F'] };
export function verdictItems(marks) {
  const items = [];
  for (const m of marks) {
    const [mark, ink] = VERDICT_INK[m.kind];
    items.push(m.kind === 'pick'
      ? { type: 'marker', x: m.x, y: m.y, shape: 'x', colour: mark, size: 8, verdict: m.kind }
      : { type: 'marker', x: m.x, y: m.y, colour: mark, size: 11, verdict: m.kind });
    if (m.text) items.push({ type: 'label', x: m.x, y: m.y, text: m.text, colour: ink, bold: true, offset: [12, m.kind === 'pick' ? 18 : -12], verdict: m.kind });
  }
  return items;
}

export class Predict {
  // root: the question box; toggle: the "your turn" checkbox; player: the page's Player; figure(): the open figure.
  constructor({ root, toggle, player, figure }) {
    Object.assign(this, { root, toggle, player, figure });
    this.instance = null;
    this.pending = null;     // { step, question, savedPick }
    this.answered = new Set();
    this.score = this.loadScore();
    toggle.checked = false;
    toggle.addEventListener('change', () => { this.cancel(); this.render(); });
    player.gate = (from, to) => this.gate(from, to);
    root.addEventListener('click', (ev) => {
      const b = ev.target.closest('button[data-answer]');
      if (b && this.pending) this.answer(b.dataset.answer);
    });
    this.render();
  }

  get on() { return this.toggle.checked; }

  loadScore() {
    try { const s = JSON.parse(sessionStorage.getItem(STORE)); if (Number.isInteger(s?.right) && Number.isInteger(s?.asked)) return s; } catch { /* none yet */ }
    return { right: 0, asked: 0 };
  }

  // A new lesson (or a new trace of it): forget its answered steps.
  attach(instance) {
    this.cancel();
    this.instance = instance;
    this.answered.clear();
    // the switch only where the lesson asks questions (it keeps its state for the next lesson that does)
    const label = this.toggle.closest('label');
    if (instance && label) label.hidden = !instance.predict;
    this.render();
  }

  // The player asks before moving forward from `from` to `to`: the step it may go to.
  gate(from, to) {
    if (this.pending) return from;   // answer first (or step back, or turn the switch off)
    if (!this.on || !this.instance?.predict || to <= from) return to;
    for (let q = from + 1; q <= to; q++) {
      if (this.answered.has(q)) continue;
      const question = this.instance.predict.ask(q);
      if (question) { this.pose(q, question); return q - 1; }
    }
    return to;
  }

  pose(step, question) {
    this.player.pause();
    const fig = this.figure();
    this.pending = { step, question, fig, savedPick: fig.onPick };
    if (question.points) {
      fig.onPick = (x, y) => {
        let best = null, bd = (14 / fig.scale) ** 2;
        for (const p of question.points) { const d = (p.x - x) ** 2 + (p.y - y) ** 2; if (d < bd) { bd = d; best = p; } }
        if (best) this.answer(String(best.index));
      };
    }
    this.verdict = null;
    this.render();
    // ring the points asked about, once the player has drawn the step before (it draws after this gate returns)
    const rings = (question.marks ?? question.points ?? []).map((p) => ({ type: 'marker', x: p.x, y: p.y, colour: '#0072B2', size: 6 }));
    if (rings.length) queueMicrotask(() => { if (this.pending?.question === question) fig.setOverlay(rings); });
  }

  answer(given) {
    const { step, question } = this.pending;
    const verdict = question.check(given);
    this.cancel();
    this.answered.add(step);
    this.score = { right: this.score.right + (verdict.right ? 1 : 0), asked: this.score.asked + 1 };
    try { sessionStorage.setItem(STORE, JSON.stringify(this.score)); } catch { /* private mode: the score stays in memory */ }
    this.verdict = { step, ...verdict };
    this.player.go(step);
    // the revealed step is drawn: mark the pick and the answer over it (the next step's drawing clears them)
    if (verdict.marks?.length && this.verdict) this.figure().setOverlay(verdictItems(verdict.marks));
    this.render();
  }

  // Drops an unanswered question (the switch turned off, another lesson, a new trace) and gives the figure back.
  cancel() {
    if (this.pending) {
      if (this.pending.fig === this.figure()) this.pending.fig.onPick = this.pending.savedPick;
      this.pending = null;
    }
    this.verdict = null;
  }

  // After any move of the player: a question stays while its step is next, a verdict only on its own step.
  stepped(k) {
    if (this.pending && this.pending.step !== k + 1) { this.cancel(); this.render(); }
    else if (this.verdict && this.verdict.step !== k) { this.verdict = null; this.render(); }
  }

  render() {
    const r = this.root;
    const takesPart = Boolean(this.instance?.predict);
    r.hidden = !this.on;
    r.dataset.step = this.pending ? String(this.pending.step) : '';
    const score = `<p class="score">Score this session: <b>${this.score.right}</b> of ${this.score.asked}</p>`;
    if (!takesPart) { r.innerHTML = `<p>This lesson asks no questions; the player runs as usual.</p>${score}`; return; }
    if (this.pending) {
      const q = this.pending.question;
      const how = q.choices
        ? `<div class="answers">${q.choices.map((c) => `<button type="button" data-answer="${c.value}">${c.label}</button>`).join('')}</div>`
        : '<p class="how">Click the point in the figure.</p>';
      r.innerHTML = `<p class="ask"><b>Your turn (step ${this.pending.step + 1}):</b> ${q.prompt}</p>${how}${score}`;
      r.querySelector('button[data-answer]')?.focus({ preventScroll: true });
    } else if (this.verdict) {
      r.innerHTML = `<p class="${this.verdict.right ? 'right' : 'wrong'}"><b>${this.verdict.right ? 'Right.' : 'Not quite.'}</b> ${this.verdict.html}</p>${score}`;
    } else {
      r.innerHTML = `<p>Step forward: the player stops before each decisive step and asks you first.</p>${score}`;
    }
  }
}
