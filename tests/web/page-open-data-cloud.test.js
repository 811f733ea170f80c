// An organised PCD opened on the page reaches web/data.js as plain arrays (a worker cannot post functions): the
// data set's loadCloud() gives it back in readOrganizedLidar's shape, ring by ring and column by column equal to the
// package's own cloud of the same file. A user's data set without a cloud says so.
import test from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { join } from 'node:path';
import init from 'rtl-wasm';
import { createData, organizedCloud } from '../../web/data.js';
import { DATA } from './helpers.js';

const rtl = await init();

test('organizedCloud: rings and columns of PCL\'s organised PCD equal the package\'s, in all three encodings', () => {
  for (const encoding of ['ascii', 'binary', 'compressed']) {
    const cloud = rtl.readPcd(readFileSync(join(DATA, 'pcd', `organized.${encoding}.pcd`)));
    assert.equal(cloud.organized, true);
    const plain = organizedCloud({ beams: cloud.beams, columns: cloud.columns, points: new Float64Array(cloud.points), intensity: new Float32Array(cloud.intensity) });
    assert.deepEqual([plain.beams, plain.columns], [4, 64]);
    for (let b = 0; b < 4; b++) assert.deepEqual(plain.ring(b), cloud.ring(b), `${encoding}: ring ${b}`);
    for (const c of [0, 17, 63]) assert.deepEqual(plain.column(c), cloud.column(c), `${encoding}: column ${c}`);
    assert.throws(() => plain.ring(4), (e) => e instanceof RangeError && /^ring: /.test(e.message));
    assert.throws(() => plain.column(-1), (e) => e instanceof RangeError && /^column: /.test(e.message));
  }
});

test('addDataset with a cloud: loadCloud gives it; without one: a RangeError naming the data set', async () => {
  const data = createData(rtl);
  const cloud = rtl.readPcd(readFileSync(join(DATA, 'pcd', 'organized.binary.pcd')));
  const scans = [{ points: new Float64Array([1, 2, 3, 4]), x: 0, y: 0, theta: 0 }];
  data.addDataset('file1', { label: 'organized.binary.pcd', unit: 'ring', scans,
    cloud: { beams: cloud.beams, columns: cloud.columns, points: new Float64Array(cloud.points), intensity: new Float32Array(cloud.intensity) } });
  const got = await data.loadCloud('file1');
  assert.deepEqual(got.ring(3), cloud.ring(3));
  assert.equal(data.DATASETS.file1.cloud, true);
  assert.equal(await data.scan('file1', 0), scans[0]);
  data.addDataset('file1', { label: 'room.csv', unit: 'point set', scans });   // the same name, now without a cloud
  await assert.rejects(data.loadCloud('file1'), (e) => e instanceof RangeError && e.message === 'data.loadCloud: room.csv is not an organised 3D cloud');
});
