// The package from CommonJS: require('rtl-wasm') resolves to dist/index.cjs (the node CommonJS glue).
const { test } = require('node:test');
const assert = require('node:assert/strict');

test('CJS: require() gives init (also as .init and .default); fitLine and errors work', async () => {
  const init = require('rtl-wasm');
  assert.equal(typeof init, 'function');
  assert.equal(init.init, init);
  assert.equal(init.default, init);
  const esm = await import('rtl-wasm');  // the drawings' colours: the same constants as the ES module's
  assert.deepEqual([...init.palette, init.unlabelledColour], [...esm.palette, esm.unlabelledColour]);
  assert.deepEqual(init.defaults, esm.defaults);
  assert.equal(init.palette.length, 10);
  assert.match(require.resolve('rtl-wasm'), /dist[\\/]index\.cjs$/);
  const rtl = await init();
  assert.equal(rtl.version, require('../../package.json').version);
  const f = rtl.fitLine(new Float64Array([0, 3, 1, 3, 2, 3]));
  assert.deepEqual(Array.from(f.normal), [0, 1]);
  assert.equal(f.offset, -3);
  assert.equal(f.rms, 0);
  assert.throws(() => rtl.fitLine([1, 2, 3]), (e) => e instanceof RangeError && /not a multiple of dim 2/.test(e.message));
  assert.throws(() => rtl.fitLine('x'), (e) => e instanceof TypeError && /points must be/.test(e.message));
  assert.throws(() => rtl.fitLine([0, 0, 1, NaN]), (e) => e instanceof RangeError && /NaN/.test(e.message));
  assert.equal(rtl.fitLine([0, 1, 1, 1]).offset, -1);
});
