// make test's short leak soak: 10,000 calls of every exported function (valid and malformed
// inputs), then no growth of wasm memory, held JS values or JS heap after the warm-up.
// `make soak` runs 100,000 per function (soak.mjs).
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { grew, soak } from './soak.mjs';

test('no leak: wasm memory, externrefs and JS heap stop growing (10,000 calls per function)', async () => {
  const results = await soak({ calls: 10_000 });
  const grown = results.filter(grew).map((r) => `${r.name}: wasm ${r.before.wasmBytes} → ${r.after.wasmBytes}, externrefs ${r.before.externrefs} → ${r.after.externrefs}, heap ${(r.before.heap / 2 ** 20).toFixed(1)} → ${(r.after.heap / 2 ** 20).toFixed(1)} MiB`);
  for (const r of results) console.log(`# ${r.name}: ${((r.ms * 1000) / (r.calls * 0.8)).toFixed(1)} µs/call, wasm ${r.after.wasmBytes} B, externrefs ${r.after.externrefs}`);
  assert.deepEqual(grown, []);
});
