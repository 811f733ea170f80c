// rtl-wasm entry for browsers and bundlers: the ES6 glue finds rtl.wasm next to itself
// (new URL('rtl.wasm', import.meta.url), which Vite and other bundlers rewrite). init() starts the core module only;
// rtl.load('extras') (or init({ load: ['extras'] })) fetches rtl-extras.mjs and rtl-extras.wasm the same way.
import createRtlModule from './rtl.mjs';
import { start } from './api.mjs';

export { defaults, palette, unlabelledColour } from './api.mjs';

const parts = { extras: { create: () => import('./rtl-extras.mjs').then((x) => x.default) } };

export async function init(options) {
  return start(createRtlModule, options, undefined, parts);
}
export default init;
