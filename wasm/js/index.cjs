'use strict';
// rtl-wasm entry for require(): CommonJS glue (ENVIRONMENT=node) given the .wasm bytes (the 3.1.6 glue would
// otherwise fetch() them, which fails for file paths).
const { readFileSync } = require('node:fs');
const { join } = require('node:path');
const createRtlModule = require('./rtl.cjs');
const { wrap, initOptions } = require('./api.cjs');

async function init(options) {
  const o = initOptions(options);
  if (o.wasmBinary === undefined) o.wasmBinary = readFileSync(join(__dirname, 'rtl.wasm'));
  return wrap(await createRtlModule(o));
}
module.exports = init;
module.exports.init = init;
module.exports.default = init;
