// Lists the fuzz cases of one function that take longer than 500 ms (valid and malformed):
//   node fuzz/slowest.mjs <function> [cases = 300] [seed = 7]
import fc from 'fast-check';
import * as fisst from 'fisst';
import { specs } from './specs.mjs';
import { caseOf, show } from './harness.mjs';
const spec = specs.find((s) => s.name === process.argv[2]);
const samples = fc.sample(caseOf(spec), { numRuns: Number(process.argv[3] ?? 300), seed: Number(process.argv[4] ?? 7) });
let i = 0;
for (const { args, what } of samples) {
  const t = performance.now();
  let r;
  try { r = 'ok'; fisst[spec.name](...args); } catch (e) { r = e.name + ': ' + e.message.slice(0, 100); }
  const ms = performance.now() - t;
  if (ms > 500) console.log(i, ms.toFixed(0), 'ms', what, r, show(args).slice(0, 500));
  i++;
}
console.log('done', i);
