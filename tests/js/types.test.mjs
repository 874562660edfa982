// The npm package's TypeScript declarations type-check a program that uses the contract
// (tests/js/types/usage.ts), under `strict`.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { execFileSync } from 'node:child_process';
import path from 'node:path';
import { fileURLToPath } from 'node:url';

const here = path.dirname(fileURLToPath(import.meta.url));

const tsc = (config) => {
  try {
    execFileSync(process.execPath, [path.join(here, 'node_modules/typescript/bin/tsc'), '-p', path.join(here, config)], { encoding: 'utf8' });
  } catch (e) {
    assert.fail(`tsc -p ${config} failed:\n${e.stdout}${e.stderr}`);
  }
};

test('TypeScript declarations', () => tsc('types/tsconfig.json'));

// Issue 26, point 3: a strict consumer with `lib: ["ES2022"]` only (no DOM, no Node types) and no
// `skipLibCheck` type-checks against the package's declarations.
test('TypeScript declarations under strict, lib ES2022, no skipLibCheck', () => tsc('types/tsconfig.es2022.json'));
