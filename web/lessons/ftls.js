// FTLS: fast total least squares (see tls-lesson.js for what is drawn).
import { tlsLesson } from './tls-lesson.js';

export default tlsLesson({
  id: 'ftls', menu: 'FTLS', title: 'FTLS', method: 'ftls',
  summary: 'Grow each segment to the longest run whose TLS fit stays under σ (gallop, then bisection), then check that neighbouring lines meet within δ.',
  excerpt: { dataset: 'csail', scan: 11, segment: { step: 3, lowerBound: 0.1, upperBound: 0.5 }, clusterAt: 38, sigma: 0.03, delta: 0.1, split: false,
    why: 'A short wall with two bends: at δ = 0.1 m it closes with 3 segments; lower δ to 0.05 m and, in strict mode, the cluster fails — the text says at which corner and by how much.' },
});
