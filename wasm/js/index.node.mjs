// rtl-wasm entry for Node ESM: the 3.1.6 glue would fetch() the .wasm (which fails on file URLs), so hand it the bytes.
import { readFile } from 'node:fs/promises';
import createRtlModule from './rtl.mjs';
import { start } from './api.mjs';

export { defaults, palette, unlabelledColour } from './api.mjs';

export async function init(options) {
  return start(createRtlModule, options, () => readFile(new URL('./rtl.wasm', import.meta.url)));
}
export default init;
