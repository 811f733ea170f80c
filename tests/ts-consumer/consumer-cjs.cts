// The same package from a CommonJS TypeScript file (require through the "require" condition).
import init = require('rtl-wasm');

async function main(): Promise<number> {
  const rtl = await init.default();
  return rtl.fitLine([0, 0, 1, 1]).rms;
}
export = main;
