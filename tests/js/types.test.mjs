// TypeScript: the hand-written dist/index.d.ts type-checks a consumer (tests/ts-consumer, ESM and CJS) with
// tsc --noEmit in strict mode, and declares every member the runtime module has.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { execFileSync } from 'node:child_process';
import { readFileSync } from 'node:fs';
import { fileURLToPath } from 'node:url';
import init from 'rtl-wasm';

const ROOT = fileURLToPath(new URL('../..', import.meta.url));

test('tsc --noEmit on tests/ts-consumer passes (strict, nodenext, @ts-expect-error on misuse)', { timeout: 120_000 }, () => {
  const tsc = fileURLToPath(new URL('../../node_modules/typescript/bin/tsc', import.meta.url));
  try {
    execFileSync(process.execPath, [tsc, '-p', 'tests/ts-consumer'], { cwd: ROOT, encoding: 'utf8', stdio: 'pipe' });
  } catch (e) {
    assert.fail(`tsc failed:\n${e.stdout}${e.stderr}`);
  }
});

test('index.d.ts declares every member of the runtime module', async () => {
  const dts = readFileSync(new URL('../../dist/index.d.ts', import.meta.url), 'utf8');
  const body = dts.slice(dts.indexOf('export interface RTL {'));
  const declared = new Set([...body.matchAll(/^ {2}(?:readonly )?([A-Za-z]+)[(:?]/gm)].map((m) => m[1]));
  const rtl = await init();
  for (const k of Object.keys(rtl)) assert.ok(declared.has(k), `${k} is declared in interface RTL`);
});
