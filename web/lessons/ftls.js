// FTLS: fast total least squares (see tls-lesson.js for what is drawn).
import { tlsLesson } from './tls-lesson.js';

export default tlsLesson({
  id: 'ftls', menu: 'FTLS', title: 'FTLS', method: 'ftls',
  summary: 'Grow each segment to the longest run whose TLS fit stays under σ (gallop, then bisection), then check that neighbouring lines meet within δ.',
  excerpt: { dataset: 'intel', scan: 3, segment: { step: 3, lowerBound: 0.1, upperBound: 0.5 }, cluster: 0, sigma: 0.03, delta: 0.3,
    why: 'A wall with a bend: σ decides where the runs end, δ whether their lines may meet at the bend.' },
});
