// The step player: play / pause / back / forward / first / last and a scrub slider over a trace of N steps.
// It owns the current step (0 .. N-1) and calls onStep(k) whenever it changes. Keyboard: every control is a
// native button or range input; in the player, Space plays or pauses, Home/End jump, ←/→ step (the slider's own).
const SPEEDS = { slow: 700, normal: 280, fast: 60 };

export class Player {
  constructor(root, onStep) {
    this.root = root;
    this.onStep = onStep;
    this.steps = 0;
    this.step = 0;
    this.timer = null;
    this.gate = null;   // (from, to) => the step a forward move may reach (web/predict.js)
    root.classList.add('player');
    root.innerHTML = `
      <div class="player-buttons">
        <button type="button" data-act="first" aria-label="First step" title="First step (Home)">|◀◀</button>
        <button type="button" data-act="back" aria-label="Step back" title="Step back (←)">◀ Back</button>
        <button type="button" data-act="play" class="play" aria-label="Play" title="Play / pause (Space)">▶ Play</button>
        <button type="button" data-act="forward" aria-label="Step forward" title="Step forward (→)">Step ▶</button>
        <button type="button" data-act="last" aria-label="Last step" title="Last step (End)">▶▶|</button>
      </div>
      <label class="scrub"><span class="visually-hidden">Step</span>
        <input type="range" min="1" max="1" value="1" step="1" data-act="scrub" aria-label="Step of the trace">
      </label>
      <div class="player-status"><output class="step-count" aria-live="off">step 0 of 0</output>
        <label class="speed">speed <select data-act="speed" aria-label="Playback speed">
          <option value="slow">slow</option><option value="normal" selected>normal</option><option value="fast">fast</option>
        </select></label></div>`;
    this.el = (act) => root.querySelector(`[data-act="${act}"]`);
    this.slider = this.el('scrub');
    this.count = root.querySelector('.step-count');
    root.addEventListener('click', (ev) => {
      const act = ev.target.closest('button')?.dataset.act;
      if (act === 'first') this.go(0);
      else if (act === 'back') this.go(this.step - 1);
      else if (act === 'forward') this.go(this.step + 1);
      else if (act === 'last') this.go(this.steps - 1);
      else if (act === 'play') this.toggle();
    });
    this.slider.addEventListener('input', () => { this.pause(); this.go(Number(this.slider.value) - 1); });
    this.el('speed').addEventListener('change', () => { if (this.timer) { this.pause(); this.play(); } });
    root.addEventListener('keydown', (ev) => {
      if (ev.target.tagName === 'SELECT') return;
      if (ev.key === ' ' && ev.target !== this.slider && ev.target.tagName !== 'BUTTON') { ev.preventDefault(); this.toggle(); }
      else if (ev.key === ' ' && ev.target === this.slider) { ev.preventDefault(); this.toggle(); }
      else if (ev.key === 'Home' && ev.target !== this.slider) { ev.preventDefault(); this.go(0); }
      else if (ev.key === 'End' && ev.target !== this.slider) { ev.preventDefault(); this.go(this.steps - 1); }
    });
  }

  // A new trace of n steps; keeps the step index when it still exists (so a parameter change keeps the place).
  load(n, keepAt = this.step) {
    this.pause();
    this.steps = n;
    this.slider.max = String(Math.max(1, n));
    this.slider.disabled = n <= 1;
    this.go(Math.min(Math.max(0, keepAt), Math.max(0, n - 1)), true);
  }

  go(k, force = false) {
    if (this.steps === 0) { this.step = 0; this.render(); this.onStep(-1); return; }
    let next = Math.min(Math.max(0, k), this.steps - 1);
    // a forward move asks the gate first (the "your turn" mode stops before a step it asks about)
    if (!force && this.gate && next > this.step) next = this.gate(this.step, next);
    if (next === this.step && !force) return;
    this.step = next;
    this.render();
    this.onStep(next);
    if (this.step >= this.steps - 1) this.pause();
  }

  render() {
    this.slider.value = String(this.step + 1);
    const text = this.steps ? `step ${this.step + 1} of ${this.steps}` : 'no steps';
    this.count.textContent = text;
    this.slider.setAttribute('aria-valuetext', text);
    this.el('back').disabled = this.el('first').disabled = this.step <= 0;
    this.el('forward').disabled = this.el('last').disabled = this.step >= this.steps - 1;
    this.el('play').disabled = this.steps <= 1;
  }

  play() {
    if (this.timer || this.steps <= 1) return;
    if (this.step >= this.steps - 1) this.go(0);
    this.timer = setInterval(() => this.go(this.step + 1), SPEEDS[this.el('speed').value]);
    const b = this.el('play');
    b.textContent = '⏸ Pause'; b.setAttribute('aria-label', 'Pause');
  }

  pause() {
    if (!this.timer) return;
    clearInterval(this.timer);
    this.timer = null;
    const b = this.el('play');
    b.textContent = '▶ Play'; b.setAttribute('aria-label', 'Play');
  }

  toggle() { if (this.timer) this.pause(); else this.play(); }
  get playing() { return Boolean(this.timer); }
  dispose() { this.pause(); }
}
