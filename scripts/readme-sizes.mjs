// Writes the wasm module sizes of the build in wasm/pkg into the READMEs (the parts table, "the
// six together", the npm README's `fisst/metrics` line): `node scripts/readme-sizes.mjs` after
// `make pkg`. KB = 1000 bytes, gzip level 9; tests/js/readme.test.mjs checks them within 2%.
import { readFileSync, writeFileSync } from 'node:fs';
import { gzipSync } from 'node:zlib';

const root = new URL('../', import.meta.url);
const size = (part) => readFileSync(new URL(`wasm/pkg/${part}_bg.wasm`, root));
const kb = (n) => Math.round(n / 1000);
let total = 0;
const readmePath = new URL('README.md', root);
let readme = readFileSync(readmePath, 'utf8').replace(
  /^(\| `fisst\/(\w+)` \|.*\| )\d+ KB \/ \d+ KB \|$/gm,
  (_, head, part) => {
    const bytes = size(part);
    total += bytes.length;
    return `${head}${kb(bytes.length)} KB / ${kb(gzipSync(bytes, { level: 9 }).length)} KB |`;
  },
);
const mb = (total / 1e6).toFixed(2);
readme = readme.replace(/the six together \([\d.]+ MB\)/, `the six together (${mb} MB)`);
writeFileSync(readmePath, readme);
const npmPath = new URL('wasm/npm/README.md', root);
const npm = readFileSync(npmPath, 'utf8').replace(
  /'fisst\/metrics'; \/\/ \d+ KB of wasm instead of [\d.]+ MB/,
  `'fisst/metrics'; // ${kb(size('metrics').length)} KB of wasm instead of ${mb} MB`,
);
writeFileSync(npmPath, npm);
console.log(`README sizes updated: six modules ${total} bytes`);
