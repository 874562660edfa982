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

// The sizes the READMEs quote (KB = 1000 bytes, MB = 10^6) are those of the build at hand, within
// 2%: the parts table (raw / gzip -9), the six together, and the npm README's `fisst/metrics` line.
test('README module sizes match the built package within 2%', async () => {
  const { gzipSync } = await import('node:zlib');
  const pkgDir = path.join(here, '../../wasm/pkg');
  const close = (quoted, bytes, what) => {
    const rel = Math.abs(quoted - bytes) / bytes;
    assert.ok(rel <= 0.02, `${what}: the README says ${quoted} bytes, the build has ${bytes} (${(100 * rel).toFixed(1)}% off)`);
  };
  const readme = readFileSync(path.join(here, '../../README.md'), 'utf8');
  const rows = [...readme.matchAll(/^\| `fisst\/(\w+)` \|.*\| (\d+) KB \/ (\d+) KB \|$/gm)];
  assert.equal(rows.length, 6, 'the README lists six parts with their sizes');
  let total = 0;
  for (const [, part, raw, gz] of rows) {
    const bytes = readFileSync(path.join(pkgDir, `${part}_bg.wasm`));
    total += bytes.length;
    close(Number(raw) * 1000, bytes.length, `${part} raw`);
    close(Number(gz) * 1000, gzipSync(bytes, { level: 9 }).length, `${part} gzipped`);
  }
  const six = readme.match(/the six together \(([\d.]+) MB\)/);
  assert.ok(six, 'the README gives the size of the six together');
  close(Number(six[1]) * 1e6, total, 'the six together');
  const npm = readFileSync(path.join(here, '../../wasm/npm/README.md'), 'utf8');
  const line = npm.match(/'fisst\/metrics'; \/\/ (\d+) KB of wasm instead of ([\d.]+) MB/);
  assert.ok(line, 'the npm README quotes the metrics part and the whole package');
  close(Number(line[1]) * 1000, readFileSync(path.join(pkgDir, 'metrics_bg.wasm')).length, 'npm README metrics');
  close(Number(line[2]) * 1e6, total, 'npm README total');
});
