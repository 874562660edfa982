// The JS boundary's conversion cost, serde (this tree's wasm/pkg) against the hand-written
// converters it replaced (the package built from git revision BASELINE_REV, by
// benches/boundary_baseline.sh), on the same inputs in one Node process. Ratios < 1 mean the
// serde boundary is faster.
//
//   benches/boundary_baseline.sh && node benches/boundary_node.mjs
import { readdirSync, readFileSync } from 'node:fs';
import { gzipSync } from 'node:zlib';
import path from 'node:path';
import { fileURLToPath } from 'node:url';

const here = path.dirname(fileURLToPath(import.meta.url));
const pkgNew = path.join(here, '../wasm/pkg');
const pkgOld = path.join(here, '.baseline/pkg');

const serde = await import(path.join(pkgNew, 'node.js'));
const hand = await import(path.join(pkgOld, 'node.js'));

function lcg(seed) {
  let s = seed >>> 0;
  return () => (s = (1664525 * s + 1013904223) >>> 0) / 2 ** 32;
}
const rand = lcg(42);
const gauss = () => Math.sqrt(-2 * Math.log(rand() + 1e-300)) * Math.cos(2 * Math.PI * rand());

// GOSPA, 1,000 × 1,000 points: a sparse scene (truths uniform in [0, 1000]², estimates within
// σ = 1, c = 5) and the same points with c = 0.001 (no pair closer than c: conversion-bound).
const truth = Array.from({ length: 1000 }, () => [1000 * rand(), 1000 * rand()]);
const estimate = truth.map(([x, y]) => [x + gauss(), y + gauss()]);
// FoV variance map: the placement page's scene (100 components, 121 × 121 centres).
const scene = serde.placementScene({ count: 100, seed: 1 }).multiBernoulli;
const mapOpts = { multiBernoulli: scene, fovSize: [1, 1], grid: { x: [-3, 3, 121], y: [-3, 3, 121] } };
// splitForRegions with 1,000 components (4D states), most away from the region's boundary.
const mixture = Array.from({ length: 1000 }, (_, i) => ({
  weight: 1 / 1000,
  mean: [20 * rand() - 10, 20 * rand() - 10, gauss(), gauss()],
  cov: [[0.05, 0, 0, 0], [0, 0.05, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]],
}));
const splitOpts = { mixture, regions: [{ box: { min: [-2, -2], max: [2, 2] } }] };
// Reading alone: a 10,000-component multi-Bernoulli through fovCardinality with a tiny box.
const many = Array.from({ length: 10000 }, () => ({ existence: rand(), mean: [10 * rand(), 10 * rand()], cov: [[0.1, 0], [0, 0.1]] }));
const fovOpts = { rfs: { multiBernoulli: many }, fov: { box: { min: [0, 0], max: [0.1, 0.1] } } };

const cases = [
  ['gospa 1000×1000, c = 5 (sparse scene)', (f) => f.gospa(truth, estimate, { c: 5 })],
  ['gospa 1000×1000, c = 0.001 (conversion-bound)', (f) => f.gospa(truth, estimate, { c: 0.001 })],
  ['fovVarianceMap 100 components × 121²', (f) => f.fovVarianceMap(mapOpts)],
  ['splitForRegions 1000 components (4D)', (f) => f.splitForRegions(splitOpts)],
  ['fovCardinality 10,000 Bernoulli components', (f) => f.fovCardinality(fovOpts)],
];

function time(fn, minMs = 400) {
  fn();
  const samples = [];
  const start = performance.now();
  while (performance.now() - start < minMs || samples.length < 5) {
    const t = performance.now();
    fn();
    samples.push(performance.now() - t);
  }
  samples.sort((a, b) => a - b);
  return samples[Math.floor(samples.length / 2)];
}

console.log('boundary conversion: serde (this tree) vs hand-written (baseline), Node, medians');
console.log(`${'case'.padEnd(48)}${'hand-written ms'.padStart(16)}${'serde ms'.padStart(12)}${'ratio'.padStart(9)}`);
const rows = [];
for (const [name, run] of cases) {
  // Alternate to share the machine's state fairly.
  const a1 = time(() => run(hand));
  const b1 = time(() => run(serde));
  const a2 = time(() => run(hand));
  const b2 = time(() => run(serde));
  const hw = Math.min(a1, a2);
  const sd = Math.min(b1, b2);
  rows.push({ name, hw, sd });
  console.log(`${name.padEnd(48)}${hw.toFixed(2).padStart(16)}${sd.toFixed(2).padStart(12)}${(sd / hw).toFixed(2).padStart(9)}`);
}
for (const [label, dir] of [['hand-written', pkgOld], ['serde', pkgNew]]) {
  // One module before the package was split into parts, one per part after (summed).
  const files = readdirSync(dir).filter((f) => f.endsWith('_bg.wasm'));
  const wasm = files.map((f) => readFileSync(path.join(dir, f)));
  const raw = wasm.reduce((n, w) => n + w.length, 0);
  const gz = wasm.reduce((n, w) => n + gzipSync(w, { level: 9 }).length, 0);
  console.log(`${label} wasm: ${raw} bytes raw, ${gz} gzipped (${files.length} module${files.length > 1 ? 's' : ''})`);
}
