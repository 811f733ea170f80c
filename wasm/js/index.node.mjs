// rtl-wasm entry for Node ESM: the 3.1.6 glue would fetch() the .wasm (which fails on file URLs), so hand it the bytes.
// init() starts both modules, the core and the extras (rtl.load('extras') is then a no-op).
import { readFile } from 'node:fs/promises';
import createRtlModule from './rtl.mjs';
import createRtlExtrasModule from './rtl-extras.mjs';
import { start } from './api.mjs';

export { defaults, palette, unlabelledColour } from './api.mjs';

const parts = {
  extras: { create: async () => createRtlExtrasModule, binary: () => readFile(new URL('./rtl-extras.wasm', import.meta.url)), atInit: true },
};

export async function init(options) {
  return start(createRtlModule, options, () => readFile(new URL('./rtl.wasm', import.meta.url)), parts);
}
export default init;
