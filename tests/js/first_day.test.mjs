// A user's first day (issue 26, Checks): the package is packed (`npm pack` of wasm/pkg), the
// tarball installed into a fresh project without the network, and there the npm README's snippet
// runs as written, every recipe of docs/recipes/ runs and prints what its comments say, and a
// strict TypeScript consumer (tests/js/types/usage.ts: strict, lib ES2022 only, no skipLibCheck,
// Node's module resolution through the package's exports map) type-checks against the INSTALLED
// declarations. Unlike readme.test.mjs and recipes.test.mjs, nothing here resolves `fisst`
// through tests/js/node_modules (a link to wasm/pkg): a file missing from package.json's `files`,
// a broken exports map or a dependency on the repository shows up here.
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { mkdtempSync, mkdirSync, readFileSync, readdirSync, writeFileSync, copyFileSync, rmSync } from 'node:fs';
import { execFileSync, spawnSync } from 'node:child_process';
import os from 'node:os';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { expectedOutput } from './expected_output.mjs';

const here = path.dirname(fileURLToPath(import.meta.url));
const root = path.join(here, '../..');
const recipesDir = path.join(root, 'docs/recipes');
const recipes = readdirSync(recipesDir).filter((f) => f.endsWith('.mjs')).sort();
const tsc = path.join(here, 'node_modules/typescript/bin/tsc'); // not downloaded: tests/js's own
const npm = process.platform === 'win32' ? 'npm.cmd' : 'npm';

let tmp; // holds the tarball and the fresh project `app/`
let app;

before(() => {
  tmp = mkdtempSync(path.join(os.tmpdir(), 'fisst-first-day-'));
  const packed = execFileSync(npm, ['pack', path.join(root, 'wasm/pkg'), '--pack-destination', tmp, '--silent'], { encoding: 'utf8' });
  const tarball = path.join(tmp, packed.trim().split('\n').pop());
  app = path.join(tmp, 'app');
  mkdirSync(app);
  writeFileSync(path.join(app, 'package.json'), JSON.stringify({ name: 'first-day', private: true, type: 'module' }, null, 2));
  // --offline: the tarball must install without the network (it has no dependencies).
  execFileSync(npm, ['install', tarball, '--offline', '--no-audit', '--no-fund', '--loglevel=error'], { cwd: app, encoding: 'utf8' });
});

after(() => {
  if (tmp) rmSync(tmp, { recursive: true, force: true });
});

/** Runs `code` as `name` inside the fresh project; returns its stdout lines, trimmed. */
function runInApp(name, code) {
  const file = path.join(app, name);
  writeFileSync(file, code);
  const run = spawnSync(process.execPath, [file], { cwd: app, encoding: 'utf8', timeout: 60_000 });
  assert.equal(run.status, 0, `${name} failed in the fresh project:\n${run.stderr}`);
  return run.stdout.trimEnd().split('\n').map((line) => line.trim());
}

test('the tarball installs offline, alone: no dependencies, only the package in node_modules', () => {
  const manifest = JSON.parse(readFileSync(path.join(app, 'node_modules/fisst/package.json'), 'utf8'));
  for (const key of ['dependencies', 'peerDependencies', 'optionalDependencies', 'bundleDependencies']) {
    assert.equal(manifest[key], undefined, `package.json has ${key}`);
  }
  const installed = readdirSync(path.join(app, 'node_modules')).filter((n) => !n.startsWith('.'));
  assert.deepEqual(installed, ['fisst']);
  for (const f of ['README.md', 'LICENSE-MIT', 'LICENSE-APACHE', 'CHANGELOG.md']) {
    assert.ok(readdirSync(path.join(app, 'node_modules/fisst')).includes(f), `the package ships ${f}`);
  }
  // The recipes ship too (an npm user has no repository to read them in), the same files.
  assert.deepEqual(readdirSync(path.join(app, 'node_modules/fisst/recipes')).sort(), [...recipes, 'README.md'].sort());
  for (const name of recipes) {
    assert.equal(
      readFileSync(path.join(app, 'node_modules/fisst/recipes', name), 'utf8'),
      readFileSync(path.join(recipesDir, name), 'utf8'),
      `recipes/${name} is docs/recipes/${name}`,
    );
  }
});

test("the npm README's Node snippet runs as written and prints what it says", () => {
  const readme = readFileSync(path.join(root, 'wasm/npm/README.md'), 'utf8');
  const m = readme.match(/<!-- readme-test: node -->\s*```js\n([\s\S]*?)```/);
  assert.ok(m, 'wasm/npm/README.md has a marked Node snippet');
  assert.deepEqual(runInApp('readme-snippet.mjs', m[1]), expectedOutput(m[1]));
});

test('docs/recipes holds the recipes', () => {
  assert.ok(recipes.length >= 7, `found ${recipes.join(', ')}`);
});

for (const name of recipes) {
  test(`recipe ${name} runs against the installed package`, () => {
    const code = readFileSync(path.join(recipesDir, name), 'utf8');
    assert.deepEqual(runInApp(name, code), expectedOutput(code));
  });
}

test('a strict TypeScript consumer (lib ES2022, no skipLibCheck) type-checks against the installed package', () => {
  const types = path.join(here, 'types');
  const config = JSON.parse(readFileSync(path.join(types, 'tsconfig.es2022.json'), 'utf8'));
  const opts = config.compilerOptions;
  // The settings this check is about, whatever types/tsconfig.es2022.json becomes.
  assert.equal(opts.strict, true);
  assert.equal(opts.skipLibCheck, false);
  assert.deepEqual(opts.lib.map((l) => l.toLowerCase()), ['es2022']);
  assert.match(opts.moduleResolution, /^(nodenext|node16|bundler)$/i, 'a resolution that reads the exports map');
  const dir = path.join(app, 'ts');
  mkdirSync(dir);
  for (const f of config.files) copyFileSync(path.join(types, f), path.join(dir, f));
  copyFileSync(path.join(types, 'package.json'), path.join(dir, 'package.json'));
  writeFileSync(path.join(dir, 'tsconfig.json'), JSON.stringify(config, null, 2));
  let listed;
  try {
    listed = execFileSync(process.execPath, [tsc, '-p', dir, '--listFiles'], { cwd: dir, encoding: 'utf8' });
  } catch (e) {
    assert.fail(`tsc failed in the fresh project:\n${e.stdout}${e.stderr}`);
  }
  // `fisst` resolved to the installed copy, not to the repository's wasm/pkg.
  const decls = listed.split('\n').filter((f) => /fisst_wasm\.d\.ts$/.test(f));
  assert.equal(decls.length, 1, listed);
  assert.ok(path.resolve(decls[0]).startsWith(path.resolve(app, 'node_modules/fisst')), decls[0]);
});
