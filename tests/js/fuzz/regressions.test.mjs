// Every failure the boundary fuzzer found, as a named test with its shrunk input (the fix is
// named beside each).
import { test } from 'node:test';
import assert from 'node:assert/strict';
import * as fisst from 'fisst';
import { findNaN } from './harness.mjs';

const noNaN = (v) => assert.equal(findNaN(v), null, `NaN in ${JSON.stringify(v)}`);

test('fuzz #1: mixtureDensityGrid far from an astronomically distant component is 0, not NaN', () => {
  // Gaussian::mahalanobis_sq stops at +∞ before an ∞·0 appears.
  const d = fisst.mixtureDensityGrid({
    mixture: [
      { weight: 1, mean: [0, 0], cov: [[1, 0], [0, 1]] },
      { weight: 5e-324, mean: [-1e308, 1.6e-215], cov: [[0.002, 0], [0, 0.002]] },
    ],
    grid: { x: [0, 1, 3], y: [0, 1, 3] },
  });
  noNaN(d);
  assert.ok(Math.abs(d[0] - 1 / (2 * Math.PI)) < 1e-15);
});

test('fuzz #2: mbOptimalEstimate with c^p overflowing (p = 1e308) gives 0 or Infinity, not NaN', () => {
  const e = fisst.mbOptimalEstimate({ existence: [], metric: 'gospa', c: 1.0000000000000002, p: 1e308 });
  assert.equal(e.meanSquareError, 0);
  const m = fisst.mbMeanSquareError({ existence: [0.5], report: [true], metric: 'ospa', c: 2, p: 1e308 });
  assert.equal(m, Infinity);
});

test('fuzz #3: gospa, ospa and uospa with a huge cut-off (c^p overflows) are not NaN', () => {
  for (const c of [1e300, 1e308]) {
    assert.equal(fisst.gospa([], [], { c }).distance, 0);
    assert.equal(fisst.ospa([[0, 0, 0]], [[0, 0, 0]], { c }).distance, 0);
    assert.equal(fisst.uospa([[0, 0, 0]], [[0, 0, 0]], { c }).distance, 0);
    // The metrics are exact to rounding relative to c (as on every path: a distance whose
    // p-th power underflows next to c^p counts as 0), so 5 next to c = 1e300 may come out as
    // any value within 1e-15·c of 5, but finite, never NaN, with the right counts.
    const g = fisst.gospa([[0, 0]], [[3, 4]], { c });
    assert.ok(Number.isFinite(g.distance) && Math.abs(g.distance - 5) <= 1e-15 * c);
    assert.equal(g.missed, 0);
    assert.equal(g.falseTargets, 0);
    // One missed point: the distance is c / 2^(1/p) even though c^p overflows.
    assert.ok(Math.abs(fisst.gospa([[0, 0]], [], { c }).distance / (c / Math.SQRT2) - 1) < 1e-15);
    assert.ok(Math.abs(fisst.ospa([[0]], [], { c, p: 2 }).distance / c - 1) < 1e-15);
  }
});

test('fuzz #4: a Bernoulli estimate of a mixture with a Dirac-like 3D component returns promptly', () => {
  const t = performance.now();
  const e = fisst.bernoulliEstimate({
    existence: 0,
    density: {
      mixture: [
        { weight: 5.70661873585501e-200, mean: [-4.78e-93, -5.1e-99, -0.01838381426331513], cov: [1e-4, 0, 0, 0, 1e-4, 0, 0, 0, 1e-4] },
        { weight: 1.1389912030382942e-200, mean: [1.3e-20, 1, 2], cov: [[1e-150, 0, 0], [0, 1e-150, 4.25e-265], [0, 4.25e-265, 1e-150]] },
      ],
    },
    radius: 0.06485315108916177,
    costs: 'mpe',
  });
  const ms = performance.now() - t;
  noNaN(e);
  assert.equal(e.declare, false);
  assert.ok(ms < 5000, `took ${ms.toFixed(0)} ms`);
});
