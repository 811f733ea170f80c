'use strict';
// rtl-wasm entry for require(): the CommonJS glue given the .wasm bytes (the 3.1.6 glue would otherwise fetch()
// them, which fails for file paths). init() starts both modules, the core and the extras.
const { readFile } = require('node:fs/promises');
const { join } = require('node:path');
const createRtlModule = require('./rtl.cjs');
const createRtlExtrasModule = require('./rtl-extras.cjs');
const { start, defaults, palette, unlabelledColour } = require('./api.cjs');

const parts = {
  extras: { create: async () => createRtlExtrasModule, binary: () => readFile(join(__dirname, 'rtl-extras.wasm')), atInit: true },
};

async function init(options) {
  return start(createRtlModule, options, () => readFile(join(__dirname, 'rtl.wasm')), parts);
}
module.exports = init;
module.exports.init = init;
module.exports.default = init;
module.exports.defaults = defaults;
module.exports.palette = palette;
module.exports.unlabelledColour = unlabelledColour;
