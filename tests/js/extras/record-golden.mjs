// Records golden-cases.mjs's digests from a built package folder into extras-golden.json:
//   node tests/js/extras/record-golden.mjs <dist folder>
// Run once on the package before the extras module existed; the test compares the package against that file.
// cli-golden.json holds the CLI's outputs of the same time (bin/rtl.js on the tests/data logs, run from the
// repository root: the SHA-256 of stdout and stderr, the exit status and the output's length per argument list).
// A case whose output the library changes on purpose (the vertex budget's extractPolylines, when its defaults change)
// is re-recorded from the CLI alone; the split itself must leave every case as it was.
import { writeFileSync } from 'node:fs';
import { resolve } from 'node:path';
import { pathToFileURL } from 'node:url';
import { goldenDigests } from './golden-cases.mjs';

const dist = process.argv[2];
if (!dist) throw new Error('usage: node tests/js/extras/record-golden.mjs <dist folder>');
const { default: init } = await import(pathToFileURL(resolve(dist, 'index.node.mjs')).href);
const digests = goldenDigests(await init());
writeFileSync(new URL('extras-golden.json', import.meta.url), `${JSON.stringify(digests, null, 1)}\n`);
console.log(`${Object.keys(digests).length} digests recorded`);
