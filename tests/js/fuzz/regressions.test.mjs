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

test('fuzz #5: a filter class names the config, not the scan, for an update error about the config', () => {
  // GmBernoulliFilter/ParticleBernoulliFilter.update put every core error under `reports`
  // ("reports.exclusions …", "reports.clutter.rate …"); now only the scan's own fields are
  // (wasm/src/bernoulli_filters.rs, scan_error).
  const prior = { weight: 1, mean: [0, 0], cov: [[1, 0], [0, 1]] };
  const base = { existence: 0.5, mixture: [prior], transition: { F: [[1, 0], [0, 1]], Q: [[0.1, 0], [0, 0.1]] }, detection: { probability: 0.9 }, particles: 50, seed: 1 };
  const two = [{ disc: { center: [0, 0], radius: 1 } }, { disc: { center: [1, 0], radius: 1 } }];
  const wall = { exclusions: [{ box: { min: [-1e3, -1e3], max: [1e3, 1e3] } }] };
  for (const C of [fisst.GmBernoulliFilter, fisst.ParticleBernoulliFilter]) {
    const f = new C({ ...base, clutter: { rate: 0, density: 0.1 } });
    const g = new C({ ...base, clutter: { rate: 0.25, density: 0.1 }, ...wall });
    try {
      assert.throws(() => f.update(two), (e) => e instanceof RangeError && e.message.startsWith('config.clutter.rate'), C.name);
      assert.throws(() => g.update([]), (e) => e instanceof RangeError && e.message.startsWith('config.exclusions'), C.name);
      assert.throws(() => f.update([{ disc: { center: [0, 0, 0], radius: 1 } }]), (e) => e instanceof RangeError && e.message.startsWith('reports[0]'), C.name);
      assert.throws(() => f.update({ measurements: [[0, 0]] }), (e) => e instanceof RangeError && /^(config|reports)\b/.test(e.message), C.name);
      assert.equal(f.existence, 0.5);
    } finally {
      f.free();
      g.free();
    }
  }
});

test('fuzz #6: a filter estimate with components or particles 1e300 apart is ±Infinity or finite, not NaN', () => {
  // The MMSE covariance took 0 · ∞ (a weightless component far away) and ∞ − ∞ (particles
  // spread beyond f64 in both signs); core/src/filters/estimate.rs (spread_cov) scales by
  // powers of two and skips weightless terms.
  const eye = [[1, 0], [0, 1]];
  const gm = new fisst.GmBernoulliFilter({
    existence: 0.5, mixture: [{ weight: 1 - 3e-9, mean: [0, 0], cov: eye }, { weight: 3e-9, mean: [1e300, 0], cov: eye }],
    transition: { F: [[3e-80, 0], [0, 4e-74]], Q: [[5, 0], [0, 1]] }, detection: { probability: 1 - 1e-16 },
    reduction: { maxComponents: 2 }, clutter: { rate: 1, density: 1e-300 }, likelihood: { H: eye, R: eye },
  });
  const pf = new fisst.ParticleBernoulliFilter({
    existence: 0, mixture: [{ weight: 1, mean: [0, 0, 0, 0], cov: [[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]] }],
    transition: { F: [[1, 0, 1, 0], [0, 1, 0, 1], [0, 0, 1, 0], [0, 0, 0, 1]], Q: [[1 / 3, 0, 0.5, 0], [0, 1 / 3, 0, 0.5], [0.5, 0, 1, 0], [0, 0.5, 0, 1]] },
    birth: { probability: 1 - 1e-16, mixture: [{ weight: 0.5, mean: [0, 0, 0, 0], cov: [[1e150, 0, 0, 0], [0, 1e150, 0, 0], [0, 0, 1e150, 0], [0, 0, 0, 1e150]] }, { weight: 0.5, mean: [0, 1e300, 0, 0], cov: [[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]] }] },
    detection: { probability: 0 }, clutter: { rate: 0, density: 0 }, particles: 3, birthParticles: 12, seed: 0,
  });
  try {
    gm.predict();
    gm.update({ measurements: [[0, 0], [0, 0], [0, 0]] });
    noNaN(gm.estimate());
    pf.predict();
    pf.update([]);
    noNaN(pf.estimate());
    // In range the covariance is unchanged: one Gaussian's own.
    const one = new fisst.GmBernoulliFilter({ existence: 0.5, mixture: [{ weight: 1, mean: [1, 2], cov: [[2, 0.5], [0.5, 1]] }], transition: { F: eye, Q: [[0, 0], [0, 0]] }, detection: { probability: 0.5 }, clutter: { rate: 0, density: 0 } });
    assert.deepEqual(one.estimate().cov, [[2, 0.5], [0.5, 1]]);
    one.free();
  } finally {
    gm.free();
    pf.free();
  }
});

test('fuzz #7: a covariance entry near f64::MAX gives finite particles, not infinite ones', () => {
  // Gaussian::new symmetrised as (A + Aᵀ)/2: 1e308 + 1e308 = ∞, so the Cholesky factor and
  // every sample were infinite (the particle filter's mean then NaN); now A/2 + Aᵀ/2
  // (core/src/gaussian/density.rs).
  const pf = new fisst.ParticleBernoulliFilter({
    existence: 0, mixture: [{ weight: 1, mean: [0, 0], cov: [[1, 0], [0, 1e308]] }],
    transition: { F: [[-5.8e-101, 3e-323], [1.3e-268, -1.5e-302]], Q: [[1e150, 0], [0, 1e150]] },
    detection: { probability: 0 }, clutter: { rate: 0, density: 0 }, particles: 1, seed: 0,
  });
  try {
    assert.ok(pf.particles.flat().every(Number.isFinite), JSON.stringify(pf.particles));
    pf.predict();
    pf.update([]);
    noNaN(pf.estimate());
  } finally {
    pf.free();
  }
});

// Not fixed (found through GmBernoulliFilter.estimate({ radius, costs })): the MMUC search of
// core/src/bernoulli/mmuc.rs runs its local searches to steps of 1e-7 · min(r0, σ_min), so one
// component with σ = 1e-75 makes a 5-component 2D mixture take 22 s in Node (2026-12-02).
// Skipped so that the suite stays fast; un-skip it to check a fix.
test('fuzz #8: bernoulliEstimate of a mixture with one near-degenerate component returns promptly', () => {
  const wide = (weight, y) => ({ weight, mean: [-0.1, y], cov: [[0.00041340382013338505, 0], [0, 0.001]] });
  const t0 = performance.now();
  const e = fisst.bernoulliEstimate({
    existence: 0.5, radius: 0.2508888387473499, costs: 'mpe',
    density: { mixture: [{ weight: 0.5, mean: [0, -1], cov: [[1e-150, 0], [0, 1.0000014426379469e-150]] }, wide(0.0435, 0.1), wide(0.2065, 0.2), wide(0.2065, 0.3), wide(0.0435, 0.4)] },
  });
  noNaN(e);
  assert.ok(performance.now() - t0 < 2000);
});

test('fuzz #9: a particle prediction that overflows f64 is an error naming config.transition, not a NaN estimate', () => {
  // F = [[0, 1e308], …] sends the particles to ±∞; estimate() now throws (core/src/filters/
  // estimate.rs, particle_estimate) instead of returning NaN means.
  const pf = new fisst.ParticleBernoulliFilter({
    existence: 0, mixture: [{ weight: 1, mean: [0, -2], cov: [[1, 0], [0, 1]] }],
    transition: { F: [[0, 1e308], [-0.86, 0]], Q: [[1e-150, 0], [0, 1e-150]] }, survival: 0,
    detection: { probability: 0 }, clutter: { rate: 1, density: 0.1 }, particles: 1, birthParticles: 0, mcmcMoves: 0, seed: 0,
  });
  try {
    pf.predict();
    pf.update([{ disc: { center: [0, 0], radius: 1e-9 } }]);
    assert.throws(() => pf.estimate(), (e) => e instanceof RangeError && e.message.startsWith('config.transition'));
  } finally {
    pf.free();
  }
});

test('fuzz #10: jdeBound with a negligible gain (hᵀPh subnormal) returns promptly: no gain, not seconds of quadrature', () => {
  // vector_bound treats h as zero when σ_s² = hᵀPh is not a normal number (it took 11 s).
  const cx = { model: 'II', existence: 0, prior: { multivariateGaussian: { mean: [0, 0], cov: [[5.978381385528621e-208, 3.8677176674982933e-280], [3.8677176674982933e-280, 1.4682132801569165e-223]] } }, observation: { detectionProbability: 6.6620561364315225e-68, gain: [[-6.433072886419347e-59, -5.972398038515846e-107]], offset: [6.028765786271736e-221], noiseCov: [[1.0009999999999998e+150]] }, falseAlarmError: 1.10051691993192e-191, missError: 6.4e-323, dims: 2, clutter: { rate: 2.4757454418458292e-113, density: { gaussian: { mean: 0, variance: 25 } } }, samples: 200, seed: 1, quadratureCardinality: 1 };
  const t = performance.now();
  assert.throws(() => fisst.jdeBound(cx), (e) => e instanceof RangeError && e.message.startsWith('options.observation.gain'));
  const out = fisst.jdeBound({ ...cx, clutter: undefined, samples: undefined, seed: undefined });
  noNaN(out);
  assert.equal(out.cardinalities[0].method, 'closed-form');
  assert.ok(performance.now() - t < 1000, `${performance.now() - t} ms`);
});

test('fuzz #11: jdeBound with a subnormal prior variance is a RangeError naming it, not 37 s of quadrature', () => {
  // Found by the helper that wrote the vector bounds: variance 5e-324, model II, λ = 0.5 took
  // 37 s. Density variances must now be normal floats (≥ 2.2e-308).
  const base = {
    model: 'II', existence: 0.5, observation: { detectionProbability: 0.9, gain: 1, noiseVariance: 1 },
    clutter: { rate: 0.5, density: { gaussian: { mean: 0, variance: 25 } } }, falseAlarmError: 1, missError: 1, samples: 200, seed: 1,
  };
  const t = performance.now();
  for (const variance of [5e-324, 1e-310]) {
    assert.throws(
      () => fisst.jdeBound({ ...base, prior: { gaussian: { mean: 0, variance } } }),
      (e) => e instanceof RangeError && e.message.startsWith('options.prior.gaussian.variance'),
    );
  }
  assert.throws(
    () => fisst.jdeBound({ ...base, prior: { gaussian: { mean: 0, variance: 1 } }, observation: { ...base.observation, noiseVariance: 5e-324 } }),
    (e) => e instanceof RangeError && e.message.startsWith('options.observation.noiseVariance'),
  );
  assert.ok(performance.now() - t < 1000, `${performance.now() - t} ms`);
  // A tiny normal variance is computed, or refused by name where the integrals cannot resolve
  // that scale: never NaN.
  noNaN(fisst.jdeBound({ ...base, prior: { gaussian: { mean: 0, variance: 1e-6 } } }));
  assert.throws(
    () => fisst.jdeBound({ ...base, prior: { gaussian: { mean: 0, variance: 1e-300 } } }),
    (e) => e instanceof RangeError && e.message.startsWith('options.prior'),
  );
});

test('fuzz #12: mmucEstimate over a mixture with a nearly degenerate 3-D component stops at its search budget', () => {
  // Found by `node fuzz/run.mjs --cases 1000000` (seed 602302): each evaluation of q was
  // within its own budget, but the search evaluated q some 1,600 times (2.6 s). The whole
  // search now has one budget (core MMUC_SEARCH_BUDGET, 10^7 evaluations); the watchdog of
  // the fuzz slice holds the time, this test the answer: a centre at the heavy component's
  // mean (its covariance is tiny) and q the light component's tail.
  const e = fisst.mmucEstimate({
    density: {
      mixture: [
        { weight: 1.5943428659959995e-127, mean: [-1.4035815575359678e-285, -4.5651984964795094e-178, -2.9309333900897442e-173], cov: [[0.001, 0, 0], [0, 0.001, 0], [0, 0, 0.001]] },
        { weight: 1, mean: [1.3842930252453666e-130, -1.3556882110795213e-61, -9.471772948376036e-132], cov: [[1.1150655654625976e-11, -5.173865028903137e-271, -2.9191461212067335e-110], [-5.173865028903137e-271, 1.8461991266345536e-292, 1.3789151307041794e-249], [-2.9191461212067335e-110, 1.3789151307041794e-249, 8.405850856824145e-9]] },
      ],
    },
    radius: 0.2503930865808104,
  });
  noNaN(e);
  assert.ok(e.center.every((c) => Math.abs(c) < 1e-6 * 0.25), JSON.stringify(e.center));
  assert.ok(e.missProbability < 1e-130, `${e.missProbability}`);
});

test('fuzz #13: jdeMonteCarlo with a gain that overflows H P Hᵀ + R is a RangeError naming it, not a NaN risk', () => {
  // Found by `node fuzz/run.mjs --cases 1000000` (seed 888070): gain 1e308 made every
  // measurement ±∞ and the likelihoods ∞ · 0 = NaN. The core now refuses such a gain.
  const base = { model: 'II', existence: 0.9999999999999999, prior: { multivariateGaussian: { mean: [0], cov: [[1]] } }, observation: { detectionProbability: 0.030435958513577614, gain: [[1e308]], noiseCov: [[1]] }, falseAlarmError: 0, missError: 0, clutter: { rate: 5e-324, density: { gaussian: { mean: 0, variance: 25 } } }, samples: 200, seed: 1 };
  assert.throws(() => fisst.jdeMonteCarlo(base), (e) => e instanceof RangeError && e.message.startsWith('options.observation.gain: H P Hᵀ + R'));
  const ok = fisst.jdeMonteCarlo({ ...base, observation: { ...base.observation, gain: [[1e150]] } });
  noNaN(ok);
});

test('fuzz #14: splitForRegions of a mixture weighing f64::MAX gives an infinite outside weight, not NaN', () => {
  // Found by `node fuzz/run.mjs --cases 1000000` (seed 86144): the split children's weights
  // summed past the f64 range, and the compensated sum's correction was ∞ − ∞ = NaN. An
  // overflowed sum is now ±∞ (core math::sum).
  const r = fisst.splitForRegions({ mixture: [{ weight: 1.7976931348623157e+308, mean: [0, 0], cov: [[1, 0], [0, 1]] }], regions: [{ disc: { center: [1e+308, 0], radius: 1e-9 } }, { polygon: [[0.1, 0], [-0.04999999999999998, 0.08660254037844388], [-0.050000000000000044, -0.08660254037844385]] }], components: 3, gridPoints: 5 });
  noNaN(r);
  assert.equal(r.inside, 0);
});
