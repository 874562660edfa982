// `make fuzz`: the boundary fuzzer at full size (default 1,000,000 cases; `--cases N`,
// `--seed S`, `--only gospa,ospa`). Prints the count per function and every failure with its
// shrunk input; exits non-zero when any check failed.
import { fuzz, show } from './harness.mjs';

const arg = (name, fallback) => {
  const i = process.argv.indexOf(`--${name}`);
  return i >= 0 ? process.argv[i + 1] : fallback;
};
const total = Number(arg('cases', 1_000_000));
const seed = Number(arg('seed', Date.now() % 1_000_000));
const only = arg('only', '') ? arg('only', '').split(',') : null;

console.log(`fuzzing the npm package: ${total} cases, seed ${seed}${only ? `, only ${only.join(', ')}` : ''}`);
const start = Date.now();
const report = fuzz({ total, seed, only, progress: (r) => process.stderr.write(`  ${r.name}: ${r.stats.calls} calls${r.failure ? ' FAIL' : ''} (${((Date.now() - start) / 1000).toFixed(1)} s)\n`) });
const pad = (s, n) => String(s).padEnd(n);
console.log(`\n${pad('function', 30)}${pad('cases', 9)}${pad('returned', 10)}${pad('TypeError', 11)}${pad('RangeError', 12)}${pad('slowest ms', 12)}result`);
let failed = 0;
let cases = 0;
for (const { name, stats, failure } of report) {
  cases += stats.calls;
  console.log(`${pad(name, 30)}${pad(stats.calls, 9)}${pad(stats.returned, 10)}${pad(stats.typeErrors, 11)}${pad(stats.rangeErrors, 12)}${pad(stats.slowestMs.toFixed(1), 12)}${failure ? 'FAIL' : 'ok'}`);
  if (failure) failed++;
}
for (const { name, failure } of report.filter((r) => r.failure)) {
  console.log(`\nFAIL ${name} (shrunk ${failure.shrinks} times): ${failure.message}\n  ${failure.input}`);
}
console.log(`\n${cases} calls in ${((Date.now() - start) / 1000).toFixed(1)} s; ${failed} function(s) failed (seed ${seed})`);
void show;
process.exit(failed ? 1 : 0);
