// The README's Node quick start runs as written against the built package and prints what the
// README says it prints.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync, writeFileSync, rmSync } from 'node:fs';
import { execFileSync } from 'node:child_process';
import path from 'node:path';
import { fileURLToPath } from 'node:url';

const here = path.dirname(fileURLToPath(import.meta.url));

test('README Node quick start', () => {
  const readme = readFileSync(path.join(here, '../../README.md'), 'utf8');
  const m = readme.match(/<!-- readme-test: node -->\s*```js\n([\s\S]*?)```/);
  assert.ok(m, 'README has a marked Node snippet');
  const code = m[1];
  const file = path.join(here, '.readme-snippet.mjs');
  writeFileSync(file, code);
  let out;
  try {
    out = execFileSync(process.execPath, [file], { cwd: here, encoding: 'utf8' });
  } finally {
    rmSync(file, { force: true });
  }
  // Each `console.log` is followed by a comment with its expected output (same line or next).
  const expected = [];
  const lines = code.split('\n');
  lines.forEach((line, i) => {
    if (!line.includes('console.log')) return;
    const same = line.match(/\/\/ (.*)$/);
    const next = lines[i + 1]?.match(/^\/\/ (.*)$/);
    expected.push((same ?? next)[1].trim());
  });
  const actual = out.trim().split('\n').map((s) => s.trim());
  assert.deepEqual(actual, expected);
});
