// `make fuzz`: the boundary fuzzer at full size (default 1,000,000 cases; `--cases N`,
// `--seed S`, `--only gospa,ospa`), then every input at the size caps (specs.mjs, `largeCases`),
// each in a child process under the watchdog (`--large 0` skips them, `--large only` runs only
// them; `--sweep 0` skips the sweep of every number through every extreme; `--cpu-limit MS` and `--watchdog MS` set when the watchdog kills a runaway call, in CPU
// and wall time: default the 2 s bound + 0.5 s, and 60 s). Prints the count per function and
// every failure with its shrunk input; failures that are known edges (known-edges.mjs) are listed
// apart. Exits non-zero when any other check failed.
import { fuzz, runLarge, show, sweepExtremes } from './harness.mjs';
import { knownEdges } from './known-edges.mjs';
import { largeCases } from './specs.mjs';

const arg = (name, fallback) => {
  const i = process.argv.indexOf(`--${name}`);
  return i >= 0 ? process.argv[i + 1] : fallback;
};
const total = Number(arg('cases', 1_000_000));
const seed = Number(arg('seed', Date.now() % 1_000_000));
const only = arg('only', '') ? arg('only', '').split(',') : null;
const large = arg('large', '1');
const cpuLimitMs = arg('cpu-limit', undefined) === undefined ? undefined : Number(arg('cpu-limit'));
const watchdogMs = Number(arg('watchdog', 60_000));

const pad = (s, n) => String(s).padEnd(n);
const start = Date.now();
let failed = 0;
const knownSeen = [];

if (large !== 'only') {
  console.log(`fuzzing the npm package: ${total} cases, seed ${seed}${only ? `, only ${only.join(', ')}` : ''}`);
  const report = fuzz({ total, seed, only, known: knownEdges, progress: (r) => process.stderr.write(`  ${r.name}: ${r.stats.calls} calls${r.failure ? ' FAIL' : ''} (${((Date.now() - start) / 1000).toFixed(1)} s)\n`) });
  console.log(`\n${pad('function', 30)}${pad('cases', 9)}${pad('returned', 10)}${pad('TypeError', 11)}${pad('RangeError', 12)}${pad('slowest ms', 12)}result`);
  let cases = 0;
  for (const { name, stats, failure } of report) {
    cases += stats.calls;
    console.log(`${pad(name, 30)}${pad(stats.calls, 9)}${pad(stats.returned, 10)}${pad(stats.typeErrors, 11)}${pad(stats.rangeErrors, 12)}${pad(stats.slowestMs.toFixed(1), 12)}${failure ? 'FAIL' : 'ok'}`);
    if (failure) failed++;
    for (const [id, k] of Object.entries(stats.known)) knownSeen.push(`${id} (${k.count} cases): ${k.message}\n  ${k.input}`);
  }
  for (const { name, failure } of report.filter((r) => r.failure)) {
    console.log(`\nFAIL ${name} (shrunk ${failure.shrinks} times): ${failure.message}\n  ${failure.input}`);
  }
  console.log(`\n${cases} calls in ${((Date.now() - start) / 1000).toFixed(1)} s`);
}

if (large !== 'only' && arg('sweep', '1') !== '0') {
  console.log('\nevery number of 2 valid inputs per function, replaced in turn by every extreme value:');
  const rows = sweepExtremes({ seed, only, known: knownEdges });
  for (const r of rows) {
    console.log(`  ${r.failures.length ? 'FAIL ' : 'ok   '} ${r.name}: ${r.calls} calls${Object.keys(r.known).length ? `; known ${Object.entries(r.known).map(([id, n]) => `${id} ×${n}`).join(', ')}` : ''}`);
    for (const f of r.failures) console.log(`        ${f.message}\n          ${f.input}`);
    if (r.failures.length) failed++;
  }
}

if (large !== '0') {
  console.log('\ninputs at the size caps (each in a child process under the watchdog):');
  const rows = await runLarge({
    labels: only ? largeCases.filter((c) => only.includes(c.name)).map((c) => c.label) : undefined,
    known: knownEdges,
    cpuLimitMs,
    watchdogMs,
    progress: (r) => console.log(`  ${r.failure ? 'FAIL ' : r.known ? 'known' : 'ok   '} ${r.label}: ${r.failure ?? r.knownFailure ?? r.outcome} (${r.call ?? ''} ${r.wallMs?.toFixed(0) ?? '?'} ms wall, ${r.cpuMs?.toFixed(0) ?? '?'} ms CPU)`),
  });
  const bad = rows.filter((r) => r.failure);
  failed += bad.length;
  for (const r of rows.filter((x) => x.known)) knownSeen.push(`${r.known}: ${r.knownFailure}\n  ${r.label}`);
}

if (knownSeen.length) console.log(`\nknown edges (known-edges.mjs), not counted as failures:\n${knownSeen.map((k) => `  ${k}`).join('\n')}`);
console.log(`\n${((Date.now() - start) / 1000).toFixed(1)} s; ${failed} failure(s) (seed ${seed})`);
void show;
process.exit(failed ? 1 : 0);
