// AFTLS: FTLS, then an integer Nelder–Mead search over the breakpoints lowering the total squared error.
import { tlsLesson } from './tls-lesson.js';

export default tlsLesson({
  id: 'aftls', menu: 'AFTLS', title: 'AFTLS', method: 'aftls',
  summary: 'Start from FTLS, then move the breakpoints (integer Nelder–Mead) while the total squared error falls; the same δ check closes it.',
  excerpt: { dataset: 'csail', scan: 18, segment: { step: 3, lowerBound: 0.1, upperBound: 0.5 }, clusterAt: 322, sigma: 0.03, delta: 0.3, split: false,
    why: 'A corner seen at a grazing angle: 4 segments at δ = 0.3 m; at δ = 0.1 m a corner cannot be met and the strict vectorizer fails.' },
});
