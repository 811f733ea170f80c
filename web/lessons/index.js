// The lessons in menu order. Each module default-exports { id, title, summary, create(host) } (see README.md).
import car from './car.js';
import ia from './ia.js';
import ftls from './ftls.js';
import aftls from './aftls.js';
import itls from './itls.js';
import dp from './dp.js';
import rw from './rw.js';
import compare from './compare.js';

export default [car, ia, ftls, aftls, itls, dp, rw, compare];
