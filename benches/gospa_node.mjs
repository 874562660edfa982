// Times the npm package's GOSPA on point sets from a JSON file (for gospa_vs_scipy.py):
// node gospa_node.mjs <file.json> <repetitions>  →  "median_seconds distance"
// Untimed warm-up calls first (at least 5 and 0.3 s), so that the median measures the
// optimised wasm code rather than V8's baseline compiler.
import { readFileSync } from 'node:fs';
const fisst = await import(process.env.FISST_NODE_ENTRY ?? '../wasm/pkg/node.js');

const [file, repsText] = process.argv.slice(2);
const { truth, estimate, c, p } = JSON.parse(readFileSync(file, 'utf8'));
const reps = Number(repsText);
const warmUntil = process.hrtime.bigint() + 300_000_000n;
for (let i = 0; i < 5 || process.hrtime.bigint() < warmUntil; i++) {
  fisst.gospa(truth, estimate, { c, p });
}
const times = [];
let distance = 0;
for (let i = 0; i < reps; i++) {
  const t0 = process.hrtime.bigint();
  distance = fisst.gospa(truth, estimate, { c, p }).distance;
  times.push(Number(process.hrtime.bigint() - t0) / 1e9);
}
times.sort((a, b) => a - b);
console.log(`${times[Math.floor(reps / 2)]} ${distance}`);
