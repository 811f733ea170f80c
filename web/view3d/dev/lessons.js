// Development harness for the lessons owned by web/view3d's engineer (tls-fit, tf-tree): the lesson contract of
// web/lessons/README.md with a stand-in figure, data loader and player. ?lesson=tls-fit | tf-tree
import init from 'rtl-wasm';
import { createStandinFigure } from './standin-figure.js';

const LESSONS = { 'tls-fit': '../../lessons/tls-fit.js', 'tf-tree': '../../lessons/tf-tree.js' };
window.__rtl = { ready: false, errors: [], lessons: [] };
window.addEventListener('error', (e) => window.__rtl.errors.push(String(e.message)));
window.addEventListener('unhandledrejection', (e) => window.__rtl.errors.push(String(e.reason)));
const $ = (id) => document.getElementById(id);

try {
  const id = new URLSearchParams(location.search).get('lesson') || 'tls-fit';
  const rtl = await init();
  const cache = {};
  const data = {
    carmen: async (name) => (cache[name] ??= rtl.readCarmenLog(await (await fetch(`/tests/data/${name}.log`)).text())),
  };
  const mod = (await import(LESSONS[id])).default;
  $('title').textContent = mod.title;
  const figure = createStandinFigure($('figure'));
  window.__figure = figure;
  let lesson, steps = 0, current = 0;
  const entry = { name: mod.id, title: mod.title, steps: 0, step: 0 };
  window.__rtl.lessons.push(entry);
  const show = (k) => {
    current = Math.max(0, Math.min(steps - 1, k));
    lesson.show(current);
    $('scrub').value = String(current);
    $('stepno').textContent = `${current + 1} / ${steps}`;
    entry.step = current;
  };
  const recompute = () => {
    ({ steps } = lesson.recompute());
    entry.steps = steps;
    $('scrub').max = String(steps - 1);
    show(Math.min(current, steps - 1));
    window.__rtl.revision = (window.__rtl.revision || 0) + 1;
  };
  const host = { rtl, data, figure, controls: $('controls'), text: $('text'), onParamsChanged: () => recompute() };
  lesson = await mod.create(host);
  window.__lesson = lesson;
  recompute();
  $('back').onclick = () => show(current - 1);
  $('next').onclick = () => show(current + 1);
  $('scrub').oninput = () => show(Number($('scrub').value));
  window.__rtl.ready = true;
} catch (e) {
  window.__rtl.errors.push(String(e?.stack || e));
}
