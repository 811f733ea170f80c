// AFTLS: FTLS, then an integer Nelder–Mead search over the breakpoints lowering the total squared error.
import { tlsLesson } from './tls-lesson.js';

export default tlsLesson({
  id: 'aftls', menu: 'AFTLS', title: 'AFTLS', method: 'aftls',
  summary: 'Start from FTLS, then move the breakpoints (integer Nelder–Mead) while the total squared error falls; the same δ check closes it.',
  excerpt: { dataset: 'intel', scan: 3, segment: { step: 3, lowerBound: 0.1, upperBound: 0.5 }, cluster: 0, sigma: 0.03, delta: 0.3,
    why: 'The FTLS lesson\'s wall: compare where the breakpoints end up.' },
});
