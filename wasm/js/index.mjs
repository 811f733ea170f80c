// rtl-wasm entry for browsers and bundlers: the ES6 glue finds rtl.wasm next to itself
// (new URL('rtl.wasm', import.meta.url), which Vite and other bundlers rewrite).
import createRtlModule from './rtl.mjs';
import { start } from './api.mjs';

export { defaults, palette, unlabelledColour } from './api.mjs';

export async function init(options) {
  return start(createRtlModule, options);
}
export default init;
