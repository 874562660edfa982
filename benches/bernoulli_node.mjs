// Times the npm package's Bernoulli functions in Node (for bernoulli_vs_scipy.py), on the
// job format of benches/src/bin/bernoulli_timing.rs:
//   node bernoulli_node.mjs <in.json> <out.json>
// mode "q": probabilityOutsideBall at every centre; mode "mmuc": mmucEstimate. Writes
// { results: [{ seconds (median per call), q: [...], center? }] }.
import { readFileSync, writeFileSync } from 'node:fs';
import * as fisst from '../wasm/pkg/node.js';

const [file, out] = process.argv.slice(2);
const { cases } = JSON.parse(readFileSync(file, 'utf8'));

function medianTime(reps, f) {
  const times = [];
  let result;
  for (let i = 0; i < reps; i++) {
    const t0 = process.hrtime.bigint();
    result = f();
    times.push(Number(process.hrtime.bigint() - t0) / 1e9);
  }
  times.sort((a, b) => a - b);
  return [times[Math.floor(reps / 2)], result];
}

const results = cases.map(({ mode, density, centers, radius, reps }) => {
  if (mode === 'q') {
    let seconds = 0;
    const q = centers.map((center) => {
      const [t, value] = medianTime(reps, () => fisst.probabilityOutsideBall({ density, center, radius }));
      seconds += t;
      return value;
    });
    return { seconds: seconds / centers.length, q };
  }
  if (mode === 'mmuc') {
    const [t, m] = medianTime(reps, () => fisst.mmucEstimate({ density, radius }));
    return { seconds: t, q: [m.missProbability], center: m.center };
  }
  throw new Error(`mode must be q or mmuc, got ${mode}`);
});
writeFileSync(out, JSON.stringify({ results }));
