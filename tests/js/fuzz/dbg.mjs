import fc from 'fast-check';
import * as fisst from 'fisst';
import { specs } from './specs.mjs';
import { show } from './harness.mjs';
const spec = specs.find((s) => s.name === process.argv[2]);
const samples = fc.sample(spec.args, { numRuns: 150, seed: 7 });
const times = [];
for (const args of samples) {
  const t = performance.now();
  try { fisst[spec.name](...args); } catch (e) {}
  const ms = performance.now() - t;
  times.push([ms, args]);
}
times.sort((a, b) => b[0] - a[0]);
for (const [ms, args] of times.slice(0, 5)) console.log(ms.toFixed(1), show(args).slice(0, 400));
