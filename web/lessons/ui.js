// Small form helpers shared by the lessons: labelled inputs that can be marked invalid with the reason next to them,
// and number formatting.
let serial = 0;

// A labelled input in `parent`. kind 'range' shows its value next to the label; 'number' is a text field.
// Returns { input, read() (number, NaN when empty or not a number), setError(message | null) }.
export function numberField(parent, { key, label, value, min, max, step, kind = 'range', unit = '', hint = '', digits = 3, onInput }) {
  const id = `f-${key}-${++serial}`;
  const wrap = document.createElement('div');
  wrap.className = 'field';
  wrap.dataset.key = key;
  wrap.innerHTML = `<label for="${id}"></label><input id="${id}" name="${key}" type="${kind}">` +
    `<p class="hint" id="${id}-hint"></p><p class="field-error" id="${id}-error" role="alert" hidden></p>`;
  const [lab, input, hintEl, err] = [wrap.querySelector('label'), wrap.querySelector('input'), wrap.querySelector('.hint'), wrap.querySelector('.field-error')];
  lab.textContent = label;
  const out = document.createElement('output');
  out.setAttribute('for', id);
  if (kind === 'range') lab.append(' ', out);
  Object.assign(input, { min: String(min), max: String(max), step: String(step), value: String(value) });
  if (kind === 'number') input.inputMode = 'decimal';
  hintEl.textContent = hint;
  hintEl.hidden = !hint;
  input.setAttribute('aria-describedby', `${id}-hint ${id}-error`);
  const fmtOut = () => { out.textContent = `${Number(input.value).toFixed(digits)}${unit ? ` ${unit}` : ''}`; };
  fmtOut();
  input.addEventListener('input', () => { fmtOut(); onInput?.(); });
  parent.append(wrap);
  return {
    input,
    read: () => (input.value.trim() === '' ? NaN : Number(input.value)),
    set(v) { input.value = String(v); fmtOut(); },
    setError(message) {
      if (message) { input.setAttribute('aria-invalid', 'true'); err.textContent = message; err.hidden = false; }
      else { input.removeAttribute('aria-invalid'); err.textContent = ''; err.hidden = true; }
    },
  };
}

// A <select> field; returns { input, read(), set(v) }. It takes the form's whole width: a native drop-down cuts its
// text instead of wrapping it, and half the panel is too narrow for a data set's name.
export function selectField(parent, { key, label, options, value, onInput }) {
  const id = `f-${key}-${++serial}`;
  const wrap = document.createElement('div');
  wrap.className = 'field wide';
  wrap.innerHTML = `<label for="${id}"></label><select id="${id}" name="${key}"></select>`;
  wrap.querySelector('label').textContent = label;
  const sel = wrap.querySelector('select');
  for (const [v, text] of options) { const o = document.createElement('option'); o.value = v; o.textContent = text; sel.append(o); }
  sel.value = value;
  sel.addEventListener('input', () => onInput?.());
  parent.append(wrap);
  return { input: sel, read: () => sel.value, set(v) { sel.value = v; } };
}

// A paragraph in `parent` (for the excerpt note: which scan/cluster and why).
export function note(parent, html, cls = 'note') {
  const p = document.createElement('p');
  p.className = cls;
  p.innerHTML = html;
  parent.append(p);
  return p;
}

export const m = (v, d = 3) => (Number.isFinite(v) ? `${v.toFixed(d)} m` : '–');
export const mm = (v, d = 1) => (Number.isFinite(v) ? `${(v * 1000).toFixed(d)} mm` : '–');
export const num = (v, d = 3) => (Number.isFinite(v) ? v.toFixed(d) : '–');
