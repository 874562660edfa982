// The seeded slice of the boundary fuzzer that `make test` runs (at least 20,000 cases over
// every exported function; `make fuzz` runs 1,000,000 with a fresh seed).
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { fuzz } from './harness.mjs';

const CASES = 20_000;
const SEED = 20261201;

test(`boundary fuzz: ${CASES} seeded cases, no trap, typed errors naming a field, no NaN, module alive`, () => {
  const report = fuzz({ total: CASES, seed: SEED });
  const calls = report.reduce((a, r) => a + r.stats.calls, 0);
  const lines = report.map(({ name, stats }) => `${name}: ${stats.calls} (${stats.returned} returned, ${stats.typeErrors} TypeError, ${stats.rangeErrors} RangeError, slowest ${stats.slowestMs.toFixed(1)} ms)`);
  console.log(`# ${calls} calls\n# ${lines.join('\n# ')}`);
  const failures = report.filter((r) => r.failure).map(({ name, failure }) => `${name}: ${failure.message}\n    ${failure.input}`);
  assert.deepEqual(failures, [], failures.join('\n'));
  assert.ok(calls >= CASES, `${calls} calls`);
});
