// Every recipe of docs/recipes/ runs as written against the built package and prints what its
// comments say it prints; docs/recipes/README.md lists every recipe (issue 26 point 2).
//
// The convention, as for the README snippet (readme.test.mjs): each `console.log(` line is
// followed by its expected output as a `// ` comment, on the same line (after the code) or on the
// comment lines right below it (one per printed line: a console.log in a loop is followed by one
// comment line per iteration). Lines are compared trimmed.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync, readdirSync, writeFileSync, rmSync } from 'node:fs';
import { spawnSync } from 'node:child_process';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { expectedOutput } from './expected_output.mjs';

const here = path.dirname(fileURLToPath(import.meta.url));
const dir = path.join(here, '../../docs/recipes');
const recipes = readdirSync(dir).filter((f) => f.endsWith('.mjs')).sort();
const LIMIT_MS = 10_000; // each recipe must run well under this, in CPU time (the machine may be loaded)
// Preloaded into the child: on exit, write its CPU time (user + system, µs) to stderr.
const CPU_PROBE = 'data:text/javascript,process.on("exit",()=>{const u=process.cpuUsage();process.stderr.write(`\\n@cpu ${u.user+u.system}\\n`)})';

test('docs/recipes holds the recipes', () => {
  assert.ok(recipes.length >= 7, `found ${recipes.join(', ')}`);
});

for (const name of recipes) {
  test(`recipe ${name} prints what its comments say`, (t) => {
    const code = readFileSync(path.join(dir, name), 'utf8');
    assert.match(code, /^import \* as fisst from 'fisst';$/m, 'the recipe imports the package as users do');
    const lines = code.trimEnd().split('\n').length;
    assert.ok(lines <= 60, `${name} has ${lines} lines: keep a recipe short`);
    // Run it from tests/js, where `fisst` resolves to the built package.
    const file = path.join(here, `.recipe-${name}`);
    writeFileSync(file, code);
    const t0 = performance.now();
    let run;
    try {
      run = spawnSync(process.execPath, ['--import', CPU_PROBE, file], { cwd: here, encoding: 'utf8', timeout: 6 * LIMIT_MS });
    } finally {
      rmSync(file, { force: true });
    }
    const wall = performance.now() - t0;
    assert.equal(run.status, 0, `${name} failed:\n${run.stderr}`);
    const cpu = Number(run.stderr.match(/@cpu (\d+)/)?.[1]) / 1000;
    const actual = run.stdout.trimEnd().split('\n').map((line) => line.trim());
    assert.deepEqual(actual, expectedOutput(code));
    assert.ok(cpu < LIMIT_MS, `${name} took ${(cpu / 1000).toFixed(1)} s of CPU`);
    t.diagnostic(`${name}: ${(cpu / 1000).toFixed(2)} s CPU, ${(wall / 1000).toFixed(2)} s wall`);
  });
}

test('docs/recipes/README.md lists every recipe, and only those', () => {
  const readme = readFileSync(path.join(dir, 'README.md'), 'utf8');
  const listed = [...new Set([...readme.matchAll(/\[`?([\w-]+\.mjs)`?\]\(\.\/\1\)/g)].map((m) => m[1]))].sort();
  assert.deepEqual(listed, recipes, 'README.md links each recipe as [name.mjs](./name.mjs)');
});
