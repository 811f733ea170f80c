// The package's `rtl-wasm/logs` entry (the file its package.json exports as ./logs) and its optional peer
// dependencies bundled into one ES module for the browser, at serve time, with esbuild from node_modules: a module
// Web Worker sees no import map, so the bare names the entry imports must be resolved before the browser gets them.
// Nothing is fetched from a CDN.
//
// Two adaptations, both at bundle time, none in the package's files (the entry imports its peers by literal names,
// which esbuild follows by itself):
// - the decompressors (@foxglove/wasm-lz4, wasm-zstd, wasm-bz2) are Emscripten modules that `require` their .wasm
//   for a file URL; the bundle inlines each .wasm as a data: URL (application/wasm) that the worker fetches.
// - the lz4 and zstd decompressors copy their output with Node's Buffer: web/vendor-buffer.js stands in for it.
// Node built-ins the entry and the Emscripten glue reach only under Node (fs, path) stay out of the bundle.
import { promises as fs } from 'node:fs';
import { join } from 'node:path';
import { fileURLToPath } from 'node:url';

const BUFFER_SHIM = fileURLToPath(new URL('./vendor-buffer.js', import.meta.url));

export const LOGS_BUNDLE_PATH = '/vendor/rtl-wasm-logs.js';

const packageJson = async (root) => JSON.parse(await fs.readFile(join(root, 'package.json'), 'utf8'));

// The peers the entry may import by name (its package.json peerDependencies), so the table lists them statically.
export async function peerNames(root) {
  return Object.keys((await packageJson(root)).peerDependencies ?? {});
}

// The file the package's exports map gives its public subpath 'rtl-wasm/logs'.
export async function logsEntry(root) {
  const target = (await packageJson(root)).exports?.['./logs'];
  const file = typeof target === 'string' ? target : target?.browser ?? target?.import ?? target?.default;
  if (typeof file !== 'string') throw new Error('package.json has no export for ./logs');
  return join(root, file);
}

const cache = new Map();   // root -> { stamp, code }

/** The bundle's code for the package under `root` (its package.json's ./logs export and node_modules/), rebuilt when
 *  that entry or the shim changes. Throws when esbuild or a peer is missing (the server answers 503 with the reason). */
export async function bundleLogs(root) {
  const entry = await logsEntry(root);
  const stamp = `${(await fs.stat(entry)).mtimeMs}:${(await fs.stat(BUFFER_SHIM)).mtimeMs}`;
  const hit = cache.get(root);
  if (hit && hit.stamp === stamp) return hit.code;
  const { build } = await import('esbuild');
  const result = await build({
    entryPoints: [entry], bundle: true, format: 'esm', platform: 'browser', target: 'es2022', write: false,
    nodePaths: [join(root, 'node_modules')], absWorkingDir: root, logLevel: 'silent', legalComments: 'eof',
    loader: { '.wasm': 'dataurl' }, external: ['fs', 'path', 'crypto', 'node:*'],
    inject: [BUFFER_SHIM],
  });
  const code = result.outputFiles[0].text;
  cache.set(root, { stamp, code });
  return code;
}
