// The lessons in menu order; the first opens when the URL names none. Each module default-exports { id, title, summary, create(host) } (see README.md).
import overview from './overview.js';
import tlsFit from './tls-fit.js';
import car from './car.js';
import ia from './ia.js';
import ftls from './ftls.js';
import aftls from './aftls.js';
import itls from './itls.js';
import dp from './dp.js';
import rw from './rw.js';
import budget from './budget.js';
import compare from './compare.js';
import tfTree from './tf-tree.js';
import tracking from './tracking.js';
import lidar3d from './lidar3d.js';

export default [overview, tlsFit, car, ia, ftls, aftls, itls, dp, rw, budget, compare, tfTree, tracking, lidar3d];
