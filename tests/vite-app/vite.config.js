// A consumer's Vite config, exactly as docs/guide-js.md recommends. `vite build` needs nothing; the dev server needs
// the package excluded from dependency pre-bundling, or the glue's `new URL('*.wasm', import.meta.url)` points into
// node_modules/.vite/deps/ and the .wasm request gets index.html back.
export default {
  optimizeDeps: { exclude: ['rtl-wasm'] },
  build: { target: 'es2022' },
  logLevel: 'warn',
};
