// The JavaScript contract of the Bernoulli filters (issue 12, paper 001 Section V):
// gmBernoulliPredict, gmBernoulliUpdate, GmBernoulliFilter, ParticleBernoulliFilter and
// airportScenario, against closed forms written here in plain JS.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import * as fisst from 'fisst';

const matmul = (a, b) => a.map((r) => b[0].map((_, j) => r.reduce((s, x, k) => s + x * b[k][j], 0)));
const transpose = (a) => a[0].map((_, j) => a.map((r) => r[j]));
const add = (a, b) => a.map((r, i) => r.map((x, j) => x + b[i][j]));
const close = (a, b, tol, what) => assert.ok(Math.abs(a - b) <= tol, `${what}: ${a} vs ${b}`);
const closeM = (a, b, tol, what) => a.forEach((r, i) => (Array.isArray(r) ? r : [r]).forEach((x, j) =>
  close(x, Array.isArray(b[i]) ? b[i][j] : b[i], tol, `${what}[${i}][${j}]`)));

const ncv = (dt, q) => ({
  F: [[1, 0, dt, 0], [0, 1, 0, dt], [0, 0, 1, 0], [0, 0, 0, 1]],
  Q: [[q * dt ** 3 / 3, 0, q * dt ** 2 / 2, 0], [0, q * dt ** 3 / 3, 0, q * dt ** 2 / 2],
    [q * dt ** 2 / 2, 0, q * dt, 0], [0, q * dt ** 2 / 2, 0, q * dt]],
});
const prior = { weight: 1, mean: [0, 0, 1, 0], cov: [[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 0.1, 0], [0, 0, 0, 0.1]] };

test('gmBernoulliPredict is eqs. (41) and (46)-(49)', () => {
  const transition = ncv(2, 0.05);
  const birth = { probability: 0.1, mixture: [{ weight: 1, mean: [5, 5, 0, 0], cov: prior.cov }] };
  const out = fisst.gmBernoulliPredict({ existence: 0.6, mixture: [prior], transition, survival: 0.95, birth });
  const r = 0.1 * 0.4 + 0.95 * 0.6;
  close(out.existence, r, 1e-15, 'existence');
  assert.equal(out.mixture.length, 2);
  close(out.mixture[0].weight, 0.04 / r, 1e-15, 'birth weight');
  const m = matmul(transition.F, prior.mean.map((x) => [x])).map((r) => r[0]);
  const P = add(matmul(matmul(transition.F, prior.cov), transpose(transition.F)), transition.Q);
  closeM(out.mixture[1].mean, m, 1e-12, 'mean');
  closeM(out.mixture[1].cov, P, 1e-12, 'cov');
});

test('an empty scan is a real update: r = 0.8, p_D = 0.9 gives 0.2857', () => {
  const out = fisst.gmBernoulliUpdate({
    existence: 0.8, mixture: [prior], detection: { probability: 0.9 }, reports: [],
    clutter: { rate: 0.25, density: 0.1 },
  });
  close(out.existence, 0.08 / 0.28, 1e-15, 'existence');
  close(out.delta, 0.9, 1e-15, 'delta');
  assert.equal(typeof out.splitComponents, 'number');
  const config = {
    existence: 0.8, mixture: [prior], transition: ncv(1, 0.01), detection: { probability: 0.9 },
    clutter: { rate: 0.25, density: 0.1 }, particles: 300, seed: 1,
  };
  for (const C of [fisst.GmBernoulliFilter, fisst.ParticleBernoulliFilter]) {
    const f = new C(config);
    try {
      f.update([]);
      close(f.existence, 0.08 / 0.28, 1e-12, C.name);
    } finally {
      f.free();
    }
  }
});

test('the vector update is the Kalman filter with p_D = 1, no clutter and r = 1', () => {
  const H = [[1, 0, 0, 0], [0, 1, 0, 0]];
  const R = [[0.25, 0], [0, 0.25]];
  const z = [0.7, -0.4];
  const out = fisst.gmBernoulliUpdate({
    existence: 1, mixture: [prior], detection: { probability: 1 }, measurements: [z],
    likelihood: { H, R }, clutter: { rate: 0, density: 1 }, reduction: {},
  });
  assert.equal(out.existence, 1);
  assert.equal(out.delta, -Infinity);
  const S = add(matmul(matmul(H, prior.cov), transpose(H)), R);
  const Sinv = [[S[1][1], -S[0][1]], [-S[1][0], S[0][0]]].map((r) => r.map((x) => x / (S[0][0] * S[1][1] - S[0][1] * S[1][0])));
  const K = matmul(matmul(prior.cov, transpose(H)), Sinv);
  const innov = [z[0] - prior.mean[0], z[1] - prior.mean[1]];
  const m = prior.mean.map((x, i) => x + K[i][0] * innov[0] + K[i][1] * innov[1]);
  assert.equal(out.mixture.length, 1);
  closeM(out.mixture[0].mean, m, 1e-12, 'mean');
});

test('airportScenario and both filter classes on the same reports', () => {
  const s = fisst.airportScenario({ seed: 3, steps: 12 });
  assert.equal(s.anchors.length, 10);
  assert.equal(s.reports.length, 12);
  assert.equal(s.truth.length, 12);
  assert.equal(s.dt, 15);
  assert.equal(s.truth[0].t, 15);
  assert.ok(s.fov.union.length === 10);
  const gm = new fisst.GmBernoulliFilter(s.config);
  const pf = new fisst.ParticleBernoulliFilter({ ...s.config, particles: 2000 });
  try {
    for (let k = 0; k < 12; k++) {
      const reports = s.reports[k].map((a) => ({ disc: { center: s.anchors[a].position, radius: s.anchors[a].radius } }));
      gm.predict();
      pf.predict();
      const info = gm.update(reports);
      assert.ok(info.splitComponents >= 1);
      pf.update(reports);
      assert.ok(Math.abs(gm.existence - pf.existence) < 0.35, `step ${k}: ${gm.existence} vs ${pf.existence}`);
    }
    const e = gm.estimate({ radius: 5, costs: 'mpe' });
    assert.equal(e.mean.length, 4);
    assert.equal(e.cov.length, 4);
    assert.equal(typeof e.report.declare, 'boolean');
    assert.equal(gm.estimate().report, null);
    assert.ok(gm.mixture.length >= 1);
    assert.equal(pf.particles.length, 2000);
    assert.equal(pf.seed, s.seed);
  } finally {
    gm.free();
    pf.free();
  }
});

test('errors name the field', () => {
  const config = {
    existence: 0.5, mixture: [prior], transition: ncv(1, 0.01), detection: { probability: 1.5 },
    clutter: { rate: 0.25, density: 0.1 },
  };
  assert.throws(() => new fisst.GmBernoulliFilter(config), (e) => e instanceof RangeError && e.message.startsWith('config.detection.probability'));
  assert.throws(() => fisst.gmBernoulliUpdate({ existence: 0.5, mixture: [prior], detection: { probability: 0.9 }, clutter: { rate: 0.1, density: [0.1] }, reports: [] }),
    (e) => e instanceof RangeError && e.message.startsWith('options.clutter.density'));
  assert.throws(() => fisst.gmBernoulliUpdate({ existence: 0.5, mixture: [prior], detection: { probability: 0.9 }, clutter: { rate: 0.1, density: 0.1 }, measurements: [[0, 0]] }),
    (e) => e instanceof RangeError && e.message.startsWith('options.likelihood'));
});

// Fuzz edges of the filters' estimates (issue 26 point 7), found by tests/js/fuzz: states near
// the largest double gave a NaN mean or covariance.
test('fuzz edge ParticleBernoulliFilter-mean-overflow: a prior at Number.MAX_VALUE has a finite mean', () => {
  const I = [[1, 0], [0, 1]];
  const f = new fisst.ParticleBernoulliFilter({ existence: 0, mixture: [{ weight: 1, mean: [Number.MAX_VALUE, 0], cov: I }], transition: { F: I, Q: I }, detection: { probability: 0 }, clutter: { rate: 0, density: 0 }, particles: 123, seed: 0 });
  f.predict();
  const e = f.estimate();
  assert.ok(e.mean.every(Number.isFinite), JSON.stringify(e.mean));
  assert.ok(e.cov.flat().every((v) => !Number.isNaN(v)), JSON.stringify(e.cov));
  f.free();
});

test('fuzz edge GmBernoulliFilter-estimate-cov-overflow: means 1e308 apart give ±Infinity, not NaN', () => {
  const I4 = [[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]];
  const f = new fisst.GmBernoulliFilter({ existence: 0, mixture: [{ weight: 1 / 3, mean: [0, -1e308, 0, 0], cov: I4 }, { weight: 2 / 3, mean: [0, 0, 0, Number.MAX_VALUE], cov: I4 }], transition: { F: [[1, 0, 1, 0], [0, 1, 0, 1], [0, 0, 1, 0], [0, 0, 0, 1]], Q: [[0.0013333333333333333, 0, 0.002, 0], [0, 0.0013333333333333333, 0, 0.002], [0.002, 0, 0.004, 0], [0, 0.002, 0, 0.004]] }, detection: { probability: 0 }, reduction: { maxComponents: 2 }, clutter: { rate: 0, density: 0.1 } });
  f.predict();
  f.update([]);
  const e = f.estimate();
  assert.ok(e.cov.flat().every((v) => !Number.isNaN(v)), JSON.stringify(e.cov));
  assert.ok(e.mean.every((v) => !Number.isNaN(v)), JSON.stringify(e.mean));
  f.free();
});
