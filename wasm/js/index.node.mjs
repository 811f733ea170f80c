// rtl-wasm entry for Node ESM: the 3.1.6 glue would fetch() the .wasm (which fails on file URLs), so hand it the bytes.
import { readFile } from 'node:fs/promises';
import createRtlModule from './rtl.mjs';
import { wrap, initOptions } from './api.mjs';

export async function init(options) {
  const o = initOptions(options);
  if (o.wasmBinary === undefined) o.wasmBinary = await readFile(new URL('./rtl.wasm', import.meta.url));
  return wrap(await createRtlModule(o));
}
export default init;
