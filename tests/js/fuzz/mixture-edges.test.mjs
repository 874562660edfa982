// The edges of the splitting / FoV / mixture / Bernoulli exports that the widened boundary
// fuzzer found (issue 26, point 7), each as a regression: a finite result where the value
// exists, a RangeError naming the field and its cap where the cost would be unbounded.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import * as fisst from 'fisst';
import { findNaN } from './harness.mjs';

const noNaN = (v) => assert.equal(findNaN(v), null, `NaN in ${JSON.stringify(v)}`);
const I2 = [[1, 0], [0, 1]];
const rho = [[1, 0.5], [0.5, 1]];
const spread = (i) => (i * 0.6180339887498949) % 1;
const comps = (n, d = 2) => Array.from({ length: n }, (_, i) => ({ weight: 1 / n, mean: Array.from({ length: d }, (_, k) => 10 * spread(i + k * 7919)), cov: d === 1 ? [[1]] : I2 }));
const rangeError = (prefix) => (e) => e instanceof RangeError && e.message.startsWith(prefix);
// CPU time of the call (as the fuzzer's watchdog counts it: test files run in parallel),
// bounded: the calls at a cap take 0.7–1.2 s on the machine these caps were set on and up to
// 3.5 s on a three times slower one (stop 43, where a 2 s bound failed with the package before
// and after that stop's changes alike); without the caps the same calls run for minutes to
// hours. The bound shows that a cap holds, not a speed (speed is measured in benches/).
const timed = (f, ms = 10_000) => {
  const t = process.cpuUsage();
  const r = f();
  const { user, system } = process.cpuUsage(t);
  assert.ok((user + system) / 1000 < ms, `${((user + system) / 1000).toFixed(0)} ms of CPU time`);
  return r;
};

test('splitForRegions-huge-corner: exactInside of a box corner at ±1e308 under a correlated Gaussian is finite', () => {
  // The bivariate normal's limits beyond ±1e37 are taken as infinite (their squares overflowed).
  for (const box of [{ min: [-1e308, -1e308], max: [0, 0] }, { min: [0, 0], max: [1e308, 1e308] }]) {
    const r = fisst.splitForRegions({ mixture: [{ weight: 1, mean: [0, 0], cov: rho }], regions: [{ box }], maxDepth: 0 });
    noNaN(r);
    assert.ok(Math.abs(r.exactInside - 1 / 3) < 1e-15, `${r.exactInside}`);
  }
});

test('fovCardinality-huge-corner: a FoV box at the largest doubles gives finite pmfs', () => {
  const fov = { box: { min: [0, 0], max: [1e308, 1e308] } };
  const mb = fisst.fovCardinality({ rfs: { multiBernoulli: [{ existence: 0.5, mean: [0, 0], cov: rho }] }, fov });
  noNaN(mb);
  assert.ok(Math.abs(mb.massInFov[0] - 1 / 3) < 1e-15);
  const poisson = fisst.fovCardinality({ rfs: { poisson: [{ weight: 1, mean: [0, 0], cov: rho }] }, fov });
  noNaN(poisson);
  assert.ok(Math.abs(poisson.mean - 1 / 3) < 1e-15);
});

test('mixtureDensityGrid-weight-overflow: a peak density past the largest double is a RangeError naming the weight', () => {
  const grid = { x: [0, 0, 1], y: [0, 0, 1] };
  assert.throws(
    () => fisst.mixtureDensityGrid({ mixture: [{ weight: 1e308, mean: [0, 0], cov: [[0.001, 0], [0, 0.001]] }], grid }),
    rangeError('options.mixture[0].weight'),
  );
  // Weight 1e308 with σ² = 1 peaks at 1.6e307: computed.
  const d = fisst.mixtureDensityGrid({ mixture: [{ weight: 1e308, mean: [0, 0], cov: I2 }], grid });
  assert.ok(Number.isFinite(d[0]));
});

test('mmucEstimate-huge-radius: particles at radius 1e308 give a finite centre', () => {
  const density = { particles: [[1e-53, 0], [1e308, 0], [0, 0]] };
  const m = fisst.mmucEstimate({ density, radius: 1e308 });
  noNaN(m);
  assert.equal(m.missProbability, 0);
  noNaN(fisst.bernoulliEstimate({ existence: 0.9, density, radius: 1e308, costs: 'mpe' }));
  noNaN(fisst.multiBernoulliPointEstimate({ components: [{ existence: 0.9, density }], radius: 1e308, costs: 'mpe' }));
});

test('reduceMixture caps: 5000 components (RangeError naming options.mixture beyond, before reading them), Runnalls 3000; each bounded', () => {
  assert.throws(() => fisst.reduceMixture({ mixture: comps(5001, 1), maxComponents: 1 }), rangeError('options.mixture has 5001 components, at most 5000 are supported'));
  const million = comps(1_000_000, 1);
  assert.throws(() => timed(() => fisst.reduceMixture({ mixture: million, maxComponents: 1_000_000, mergeDistance: 0 }), 100), rangeError('options.mixture has 1000000 components, at most 5000 are supported'));
  assert.throws(() => fisst.reduceMixture({ mixture: comps(3001), maxComponents: 1 }), rangeError('options.maxComponents: Runnalls\' reduction takes at most 3000 components'));
  assert.equal(timed(() => fisst.reduceMixture({ mixture: comps(3000), maxComponents: 1 })).length, 1);
  assert.equal(timed(() => fisst.reduceMixture({ mixture: comps(5000), mergeDistance: 0 })).length, 5000);
});

test('MMUC search caps: 100 mixture components, 1500 particles in 2+ dimensions; each bounded at the cap', () => {
  assert.throws(
    () => fisst.bernoulliEstimate({ existence: 0.5, density: { mixture: comps(101) }, radius: 1, costs: 'mpe' }),
    rangeError('options.density.mixture must have 1 to 100 components, got 101'),
  );
  assert.throws(
    () => fisst.multiBernoulliPointEstimate({ components: [{ existence: 0.5, density: { mixture: comps(101) } }], radius: 1, costs: 'mpe' }),
    rangeError('options.components[0].density.mixture'),
  );
  const points = (n) => Array.from({ length: n }, (_, i) => [100 * spread(2 * i), 100 * spread(2 * i + 1)]);
  assert.throws(() => fisst.mmucEstimate({ density: { particles: points(1501) }, radius: 1 }), rangeError('options.density.particles must have 1 to 1500 particles in 2 or more dimensions, got 1501'));
  noNaN(timed(() => fisst.bernoulliEstimate({ existence: 0.5, density: { mixture: comps(100) }, radius: 1, costs: 'mpe' })));
  // All 1500 within 2 r0 of each other: the 2D sweep's worst case.
  noNaN(timed(() => fisst.mmucEstimate({ density: { particles: points(1500) }, radius: 100 })));
  // 1D particles have no cap (a sort and a sweep).
  noNaN(timed(() => fisst.mmucEstimate({ density: { particles: Array.from({ length: 100_000 }, (_, i) => [spread(i)]) }, radius: 0.1 })));
});
