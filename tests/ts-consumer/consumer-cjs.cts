// The same package from a CommonJS TypeScript file: `import init = require('rtl-wasm')` resolves through the
// "require" condition to dist/index.cjs and its types to dist/index.d.cts. tests/js/types.test.mjs type-checks this
// file with tsc --noEmit and also compiles and runs it.
import init = require('rtl-wasm');
import type { VectorizeResult } from 'rtl-wasm';

async function main(): Promise<{ rms: number; count: number; same: boolean; version: string }> {
  const rtl: init.RTL = await init();
  const viaDefault: init.RTL = await init.default();
  const viaNamed: init.RTL = await init.init({});
  const fit: init.LineFit2D = rtl.fitLine([0, 0, 1, 1, 2, 2.02]);
  const v: VectorizeResult = rtl.vectorize([0, 0, 1, 0, 2, 0, 3, 0], { method: 'dp', epsilon: 0.1 });
  const colours: readonly string[] = init.palette;
  const gray: string = init.unlabelledColour + colours.length + init.defaults.vectorize.sigma;
  void gray;
  const tree: init.TfTree = new rtl.TfTree('map');
  tree.dispose();
  // @ts-expect-error: method is required
  void (() => rtl.vectorize([0, 0, 1, 1], { sigma: 0.1 }));
  return { rms: fit.rms, count: v.count, same: viaDefault.version === viaNamed.version, version: rtl.version };
}
export = main;
