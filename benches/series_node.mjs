// Times the npm package's whole-scenario metrics (for gospa_vs_stonesoup.py):
// node series_node.mjs <gospa|ospa> <in.json> <repetitions> <out.json>  →  "median_seconds"
// and the series written to out.json with the native binary's field names. Exits with status
// 3 while the package has no `gospaSeries` / `ospaSeries` binding.
import { readFileSync, writeFileSync } from 'node:fs';
import * as fisst from '../wasm/pkg/node.js';

const [metric, file, repsText, out] = process.argv.slice(2);
const fn = metric === 'gospa' ? fisst.gospaSeries : fisst.ospaSeries;
if (typeof fn !== 'function') process.exit(3);
const { truths, estimates, c, p, alpha } = JSON.parse(readFileSync(file, 'utf8'));
const options = metric === 'gospa' ? { truths, estimates, c, p, alpha } : { truths, estimates, c, p };
const reps = Number(repsText);
fn(options); // warm-up
const times = [];
let s;
for (let i = 0; i < reps; i++) {
  const t0 = process.hrtime.bigint();
  s = fn(options);
  times.push(Number(process.hrtime.bigint() - t0) / 1e9);
}
times.sort((a, b) => a - b);
const series = metric === 'gospa'
  ? { distance: s.distance, localisation: s.localisation, missed: s.missed, false_targets: s.falseTargets }
  : { distance: s.distance, localisation: s.localisation, cardinality: s.cardinality };
writeFileSync(out, JSON.stringify(series));
console.log(`${times[Math.floor(reps / 2)]}`);
