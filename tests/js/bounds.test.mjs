// The JavaScript contract of the joint detection-estimation bounds (issue 13, paper 002:
// Rezaeian & Vo): jdeBoundNoClutter, gaussianFisherInformation, jdeSequentialBound and
// jdeBound, against oracles written here in plain JS — the closed forms (27)–(31), (35), (37)
// and Theorem 1 (17)/(21) recomputed from the paper for the linear-Gaussian case, and a seeded
// Monte Carlo of the optimal joint detector-estimator (MAP detection, posterior mean;
// oracle/bounds_mc.mjs) whose MSE must equal the bound within Z standard errors where the
// Gaussian case attains it (Corollary 3, Theorem 1, Enumeration) and never fall below it by
// more than that (Theorem 2).
import { test } from 'node:test';
import assert from 'node:assert/strict';
import * as fisst from 'fisst';
import { example2Prior, mcExample2, mcGaussian, mcGaussianVector, mcSequential } from './oracle/bounds_mc.mjs';

const Z = 4; // standard errors allowed between a Monte Carlo MSE and the bound it attains
const SAMPLES = 40_000;
const close = (a, b, tol, what) => assert.ok(Math.abs(a - b) <= tol * Math.max(1, Math.abs(b)), `${what}: ${a} vs ${b}`);
const zScores = []; // every (MSE − bound)/SE, for the summary line
const record = (what, mc, bound, extra = 0) => {
  const se = Math.hypot(mc.se, extra);
  const z = se > 0 ? (mc.mse - bound) / se : (Math.abs(mc.mse - bound) < 1e-9 ? 0 : Infinity * Math.sign(mc.mse - bound));
  zScores.push({ what, z, mse: mc.mse, bound });
  return z;
};
const waiting = (name) => (typeof fisst[name] === 'function' ? false : `waiting for ${name} (branch issue13)`);

// ------------------------------------------------------------------ closed-form oracles
/** Example 1 with NOTES.md's erratum: J_1 = 1/σx² + a²/σv². */
const fisher = (vx, a, vv) => 1 / vx + (a * a) / vv;

/** Corollary 3 in the Gaussian form (31): both pieces, r*, and the MAP-on-∅ variant (Sec. IV-A). */
function corollary3({ existence: r, detectionProbability: P, priorVariance: vf, posteriorVariance: vh, falseAlarmError: e0, missError: e1 }) {
  const hpe = r * (vf - P * (vf - vh)) + (1 - r) * e0;
  const lpe = r * (e1 - P * (e1 - vh));
  const threshold = e0 / (e0 + (1 - P) * (e1 - vf));
  const mapThreshold = 1 / (2 - P);
  return { hpe, lpe, bound: Math.min(hpe, lpe), threshold, mapThreshold, mapBound: r >= mapThreshold ? hpe : lpe };
}

/** IRF (35) and Enumeration (37). */
const irf = (j0, j1, P, k) => 1 / (j0 + k * P * (j1 - j0));
function enumeration(j0, j1, P, k) {
  let s = 0;
  let binom = 1; // C(k, m)
  for (let m = 0; m <= k; m++) {
    s += binom * P ** m * (1 - P) ** (k - m) / (j0 + m * (j1 - j0));
    binom = (binom * (k - m)) / (m + 1);
  }
  return s;
}

/** erfc, Numerical Recipes' Chebyshev fit (fractional error < 1.2e-7). */
function erfc(x) {
  const z = Math.abs(x);
  const t = 1 / (1 + 0.5 * z);
  const r = t * Math.exp(-z * z - 1.26551223 + t * (1.00002368 + t * (0.37409196 + t * (0.09678418 + t * (-0.18628806
    + t * (0.27886807 + t * (-1.13520398 + t * (1.48851587 + t * (-0.82215223 + t * 0.17087277)))))))));
  return x >= 0 ? r : 2 - r;
}
/** P(lo ≤ N(m, v) ≤ hi). */
const mass = (lo, hi, m, v) => 0.5 * (erfc((lo - m) / Math.sqrt(2 * v)) - erfc((hi - m) / Math.sqrt(2 * v)));

/** The intervals where A z² + B z + C ≥ 0. */
function quadraticRegion(A, B, C) {
  if (Math.abs(A) < 1e-300) {
    if (B === 0) return C >= 0 ? [[-Infinity, Infinity]] : [];
    return B > 0 ? [[-C / B, Infinity]] : [[-Infinity, -C / B]];
  }
  const d = B * B - 4 * A * C;
  if (d <= 0) return A > 0 ? [[-Infinity, Infinity]] : [];
  const [z1, z2] = [(-B - Math.sqrt(d)) / (2 * A), (-B + Math.sqrt(d)) / (2 * A)].sort((u, v) => u - v);
  return A > 0 ? [[-Infinity, z1], [z2, Infinity]] : [[z1, z2]];
}

/**
 * Theorem 1 (17)/(21) for f = N(m, σf²), g(z|x) = N(a x + b, σv²), constant P_o, ψ = N(μψ, σψ²):
 * ∂²log p_1/∂x² = −J_1 everywhere, so J'_1 = J_1/w_1 (20); Z'_0 (19) is where a quadratic in z
 * is ≥ 0, and w_1 and η_1 are Gaussian masses of it.
 */
function theorem1({ existence: r, prior: { mean: m, variance: vf }, gain: a, offset: b, noiseVariance: vv, detectionProbability: P, falseAlarm, falseAlarmError: e0, missError: e1 }) {
  const q = falseAlarm.probability;
  const [mm, vm] = [a * m + b, a * a * vf + vv]; // ∫p_1(x, z)dx = N(z; mm, vm)
  const { mean: mp, variance: vp } = falseAlarm.density.gaussian;
  let region;
  if (q === 0) region = [[-Infinity, Infinity]];
  else if (r === 0 || P === 0) region = [];
  else {
    // log(r P N(z; mm, vm)) ≥ log((1 − r) q N(z; mp, vp))
    const A = 1 / (2 * vp) - 1 / (2 * vm);
    const B = mm / vm - mp / vp;
    const C = Math.log((r * P) / ((1 - r) * q)) + 0.5 * Math.log(vp / vm) - (mm * mm) / (2 * vm) + (mp * mp) / (2 * vp);
    region = r === 1 ? [[-Infinity, Infinity]] : quadraticRegion(A, B, C);
  }
  const w1 = region.reduce((s, [lo, hi]) => s + mass(lo, hi, mm, vm), 0);
  const eta1 = q * (1 - region.reduce((s, [lo, hi]) => s + mass(lo, hi, mp, vp), 0));
  const vh = 1 / fisher(vf, a, vv);
  const threshold = ((1 - q) * e0) / ((1 - q) * e0 + (1 - P) * (e1 - vf));
  const piece = (lpe) => {
    const [mu0, mu1] = lpe ? [1, eta1 + 1 - q] : [0, eta1];
    const terms = {
      estimation: r * P * w1 * vh,
      undetected: r * (1 - P) * (1 - mu0) * vf,
      missed: r * (mu0 * (1 - P) + P - P * w1) * e1,
      falseTarget: (1 - r) * (1 - mu1) * e0,
    };
    return { terms, bound: Object.values(terms).reduce((s, v) => s + v, 0) };
  };
  const [hpe, lpe] = [piece(false), piece(true)];
  return { hpe, lpe, threshold, w1, eta1, best: hpe.bound <= lpe.bound ? 'HPE' : 'LPE' };
}

// Fig. 2 (left): σf² = 100, σh² = 25 (a = 1, σv² = 100/3), e0² = 150, e1² = 200.
const FIG2 = { priorVariance: 100, gain: 1, noiseVariance: 100 / 3, falseAlarmError: 150, missError: 200 };

// ------------------------------------------------------------------ closed forms
test('gaussianFisherInformation is J_1 = 1/σx² + a²/σv² (Example 1, NOTES.md erratum) and its inverse', { skip: waiting('gaussianFisherInformation') }, () => {
  for (const [vx, a, vv] of [[100, 1, 100 / 3], [4, 2, 1], [1, 0, 1], [1e-3, 5, 1e4], [2.5, -1.5, 0.3]]) {
    const out = fisst.gaussianFisherInformation({ priorVariance: vx, gain: a, noiseVariance: vv });
    assert.deepEqual(Object.keys(out).sort(), ['information', 'posteriorVariance']);
    close(out.information, fisher(vx, a, vv), 1e-14, 'J_1');
    close(out.posteriorVariance, 1 / fisher(vx, a, vv), 1e-14, '1/J_1');
  }
  // Fig. 2: σh² = 25 exactly when σv² = 100/3 (the paper's J_1 = 1/σx² + a²/(2σv²) would give 40).
  close(fisst.gaussianFisherInformation({ priorVariance: 100, gain: 1, noiseVariance: 100 / 3 }).posteriorVariance, 25, 1e-13, 'σh²');
});

test('jdeBoundNoClutter is Corollary 3 / (31): both phases, r*, and whether ∅ declares a target', { skip: waiting('jdeBoundNoClutter') }, () => {
  const cases = [];
  for (const r of [0, 0.1, 0.5, 0.6, 0.7, 0.75, 0.9, 1]) {
    for (const P of [0, 0.25, 0.5, 0.9, 1]) cases.push({ existence: r, detectionProbability: P, priorVariance: 100, posteriorVariance: 25, falseAlarmError: 150, missError: 200 });
  }
  cases.push({ existence: 0.3, detectionProbability: 0.2, priorVariance: 2, posteriorVariance: 0.5, falseAlarmError: 0.4, missError: 9 });
  cases.push({ existence: 0.99, detectionProbability: 0.6, priorVariance: 1, posteriorVariance: 1, falseAlarmError: 3, missError: 3 });
  for (const c of cases) {
    const out = fisst.jdeBoundNoClutter(c);
    for (const k of ['bound', 'existenceThreshold', 'declareOnEmpty']) assert.ok(k in out, `missing ${k}`);
    const want = corollary3(c);
    const what = JSON.stringify(c);
    close(out.bound, want.bound, 1e-12, `bound ${what}`);
    close(out.existenceThreshold, want.threshold, 1e-12, `r* ${what}`);
    assert.equal(out.declareOnEmpty, c.existence >= want.threshold, `declareOnEmpty ${what}`);
    // The bound is the piece of its phase, and the lower one.
    close(out.bound, out.declareOnEmpty ? want.hpe : want.lpe, 1e-12, `phase ${what}`);
    if ('mapBound' in out) {
      close(out.mapThreshold, want.mapThreshold, 1e-12, `r_M* ${what}`);
      close(out.mapBound, want.mapBound, 1e-12, `MAP bound ${what}`);
      assert.ok(out.mapBound >= out.bound - 1e-12, 'MAP detection on ∅ can only raise the bound');
    }
  }
  // r = 1 is Corollary 1: P̄o σh² + (1 − P̄o)σf², linear in P̄o (Fig. 2 left at r = 1).
  for (const P of [0, 0.3, 1]) close(fisst.jdeBoundNoClutter({ ...cases[0], existence: 1, detectionProbability: P }).bound, 100 - 75 * P, 1e-12, `r = 1, P̄o = ${P}`);
  // The paper's r* for Fig. 2: 150/(150 + 100(1 − P̄o)).
  close(fisst.jdeBoundNoClutter({ ...cases[0], detectionProbability: 0.5 }).existenceThreshold, 0.75, 1e-12, 'r* at P̄o = 0.5');
});

test('the Monte Carlo MSE of the optimal detector-estimator equals the no-clutter bound (Corollary 3)', { skip: waiting('jdeBoundNoClutter') }, () => {
  const { posteriorVariance } = fisst.gaussianFisherInformation({ priorVariance: 100, gain: 1, noiseVariance: 100 / 3 });
  let seed = 1;
  for (const [e0, e1] of [[150, 200], [50, 60]]) { // e1² < σf² in the second: ∅ is never declared a target
    for (const r of [0.2, 0.5, 0.65, 0.8, 1]) {
      for (const P of [0, 0.4, 0.8, 1]) {
        const opts = { existence: r, detectionProbability: P, priorVariance: 100, posteriorVariance, falseAlarmError: e0, missError: e1 };
        const out = fisst.jdeBoundNoClutter(opts);
        const mc = mcGaussian({ ...FIG2, existence: r, prior: { mean: 3, variance: 100 }, detectionProbability: P, falseAlarmError: e0, missError: e1, samples: SAMPLES, seed: seed++ });
        const z = record(`Cor. 3 r=${r} P=${P} e0²=${e0}`, mc, out.bound);
        assert.ok(Math.abs(z) < Z, `r = ${r}, P̄o = ${P}, e0² = ${e0}: MC ${mc.mse} ± ${mc.se} vs bound ${out.bound} (z = ${z})`);
        assert.equal(mc.declareOnEmpty, out.declareOnEmpty, `rule on ∅ at r = ${r}, P̄o = ${P}`);
        if ('mapBound' in out) {
          const map = mcGaussian({ ...FIG2, existence: r, prior: { mean: 3, variance: 100 }, detectionProbability: P, falseAlarmError: e0, missError: e1, rule: 'map', samples: SAMPLES, seed: seed++ });
          const zm = record(`MAP on ∅ r=${r} P=${P} e0²=${e0}`, map, out.mapBound);
          assert.ok(Math.abs(zm) < Z, `MAP on ∅: MC ${map.mse} ± ${map.se} vs ${out.mapBound}`);
        }
      }
    }
  }
});

test('jdeSequentialBound is IRF (35) and Enumeration (37); Enum ≥ IRF, equal at P̄o = 1; the Monte Carlo attains Enum', { skip: waiting('jdeSequentialBound') }, () => {
  for (const [j0, j1] of [[0.01, 0.04], [1, 1.5], [2, 50]]) {
    for (const P of [0, 0.2, 0.5, 0.9, 1]) {
      const steps = 30;
      const opts = { priorInformation: j0, detectedInformation: j1, detectionProbability: P, steps };
      const e = fisst.jdeSequentialBound({ method: 'enumeration', ...opts });
      const i = fisst.jdeSequentialBound({ method: 'irf', ...opts });
      assert.deepEqual(Object.keys(e), ['bound']);
      assert.equal(e.bound.length, steps);
      assert.equal(i.bound.length, steps);
      for (let k = 1; k <= steps; k++) {
        close(e.bound[k - 1], enumeration(j0, j1, P, k), 1e-12, `Enum k=${k}`);
        close(i.bound[k - 1], irf(j0, j1, P, k), 1e-12, `IRF k=${k}`);
        assert.ok(e.bound[k - 1] >= i.bound[k - 1] * (1 - 1e-14), `Enum ≥ IRF (Jensen), k = ${k}, P̄o = ${P}`);
        if (P === 1 || P === 0) close(e.bound[k - 1], i.bound[k - 1], 1e-13, `Enum = IRF at P̄o = ${P}`);
        if (k > 1) assert.ok(e.bound[k - 1] <= e.bound[k - 2] * (1 + 1e-14), 'decreasing in k');
      }
    }
  }
  // k = 1: (33) and (34) for Fig. 2's system.
  const one = (method) => fisst.jdeSequentialBound({ method, priorInformation: 0.01, detectedInformation: 0.04, detectionProbability: 0.5, steps: 1 }).bound[0];
  close(one('enumeration'), 62.5, 1e-12, '(33)');
  close(one('irf'), 40, 1e-12, '(34)');
  // The posterior mean from k scans attains Enum (Fig. 3's system, r = 1).
  for (const [P, seed] of [[0.3, 7], [0.8, 8]]) {
    const steps = 12;
    const e = fisst.jdeSequentialBound({ method: 'enumeration', priorInformation: 0.01, detectedInformation: 0.04, detectionProbability: P, steps });
    const mc = mcSequential({ priorInformation: 0.01, detectedInformation: 0.04, detectionProbability: P, steps, samples: SAMPLES, seed });
    for (let k = 0; k < steps; k++) {
      const z = record(`Enum k=${k + 1} P=${P}`, { mse: mc.mse[k], se: mc.se[k] }, e.bound[k]);
      assert.ok(Math.abs(z) < Z, `Enum k = ${k + 1}, P̄o = ${P}: MC ${mc.mse[k]} ± ${mc.se[k]} vs ${e.bound[k]}`);
    }
  }
});

// ------------------------------------------------------------------ Theorems 1 and 2
const gaussianSystem = (r, P) => ({
  existence: r,
  prior: { gaussian: { mean: 0.5, variance: 4 } },
  observation: { detectionProbability: P, gain: 1, offset: 0, noiseVariance: 1 },
  falseAlarmError: 6,
  missError: 8,
});
const mcOf = (c, extra) => ({
  existence: c.existence, prior: { mean: 0.5, variance: 4 }, gain: 1, offset: 0, noiseVariance: 1,
  detectionProbability: c.observation.detectionProbability, falseAlarmError: c.falseAlarmError, missError: c.missError, samples: SAMPLES, ...extra,
});

test('jdeBound model I is Theorem 1 (17) in the Gaussian case, and the Monte Carlo of MAP detection + posterior mean attains it', { skip: waiting('jdeBound') }, () => {
  let seed = 100;
  for (const r of [0.2, 0.5, 0.8, 1]) {
    for (const P of [0.5, 0.9]) {
      for (const q of [0.1, 0.5, 0.9]) {
        const c = { ...gaussianSystem(r, P), model: 'I', falseAlarm: { probability: q, density: { gaussian: { mean: 1, variance: 25 } } } };
        const out = fisst.jdeBound(c);
        for (const k of ['bound', 'phase', 'existenceThreshold', 'terms', 'error']) assert.ok(k in out, `missing ${k}`);
        const want = theorem1({ ...c, prior: { mean: 0.5, variance: 4 }, gain: 1, offset: 0, noiseVariance: 1, detectionProbability: P });
        const what = `r = ${r}, P̄o = ${P}, q = ${q}`;
        const piece = want[out.phase === 'HPE' ? 'hpe' : 'lpe'];
        close(out.bound, piece.bound, 1e-6, `bound ${what}`);
        close(out.existenceThreshold, want.threshold, 1e-9, `r₁* ${what}`);
        assert.equal(out.phase, r >= want.threshold ? 'HPE' : 'LPE', `phase ${what}`);
        assert.deepEqual(out.terms.map((t) => t.name), ['estimation', 'undetected', 'missed', 'falseTarget']);
        for (const t of out.terms) close(t.value, piece.terms[t.name], 1e-6, `${t.name} ${what}`);
        close(out.terms.reduce((s, t) => s + t.value, 0), out.bound, 1e-12, 'terms sum to the bound');
        assert.ok(out.error >= 0 && out.error < 1e-4 * Math.max(1, out.bound), `error ${out.error}`);
        const mc = mcGaussian(mcOf(c, { falseAlarm: { probability: q, mean: 1, variance: 25 }, seed: seed++ }));
        const z = record(`Thm 1 r=${r} P=${P} q=${q}`, mc, out.bound, out.error);
        assert.ok(Math.abs(z) < Z, `${what}: MC ${mc.mse} ± ${mc.se} vs bound ${out.bound} (z = ${z})`);
      }
    }
  }
  // q = 0 (falseAlarm omitted) is Corollary 3.
  const c = { ...gaussianSystem(0.7, 0.6), model: 'I' };
  const nc = fisst.jdeBoundNoClutter({ existence: 0.7, detectionProbability: 0.6, priorVariance: 4, posteriorVariance: 0.8, falseAlarmError: 6, missError: 8 });
  close(fisst.jdeBound(c).bound, nc.bound, 1e-9, 'model I with q = 0');
  close(fisst.jdeBound({ ...c, model: 'II' }).bound, nc.bound, 1e-9, 'model II with λ = 0');
});

test('jdeBound model II (Theorem 2): the Monte Carlo MSE of MAP detection + posterior mean never falls below it', { skip: waiting('jdeBound') }, () => {
  let seed = 200;
  for (const r of [0.3, 0.7, 1]) {
    for (const P of [0.6, 0.95]) {
      for (const lambda of [0.5, 2]) {
        const c = { ...gaussianSystem(r, P), model: 'II', clutter: { rate: lambda, density: { gaussian: { mean: 0, variance: 25 } } }, seed: 5, samples: 5000 };
        const out = fisst.jdeBound(c);
        assert.deepEqual(out.terms.map((t) => t.name), ['estimation', 'undetected', 'missed', 'falseTarget']);
        close(out.terms.reduce((s, t) => s + t.value, 0), out.bound, 1e-12, 'terms sum to the bound');
        const nc = corollary3({ existence: r, detectionProbability: P, priorVariance: 4, posteriorVariance: 0.8, falseAlarmError: 6, missError: 8 });
        close(out.existenceThreshold, nc.threshold, 1e-12, 'r* of (24) does not depend on λ');
        const mc = mcGaussian(mcOf(c, { clutter: { rate: lambda, mean: 0, variance: 25 }, seed: seed++ }));
        const z = record(`Thm 2 r=${r} P=${P} λ=${lambda}`, mc, out.bound, out.error);
        assert.ok(z > -Z, `r = ${r}, P̄o = ${P}, λ = ${lambda}: MC ${mc.mse} ± ${mc.se} below the bound ${out.bound} ± ${out.error} (z = ${z})`);
      }
    }
  }
  // r = 1 is Corollary 2: its first cardinality term is J_1⁻¹ = σh² with w_1 = 1.
  const out = fisst.jdeBound({ ...gaussianSystem(1, 0.9), model: 'II', clutter: { rate: 1, density: { gaussian: { mean: 0, variance: 25 } } }, seed: 3, samples: 5000 });
  if (out.cardinalities) {
    close(out.cardinalities[0].inverseInformation, 0.8, 1e-6, 'J_1⁻¹');
    close(out.cardinalities[0].w, 1, 1e-9, 'w_1 at r = 1');
  }
  assert.equal(out.phase, 'HPE');
});

// ------------------------------------------------------------------ a state in R^l (Section V, (63)–(72))
// A correlated 2D Gaussian state; one measurement coordinate z = hᵀx + b + v (models I and II
// with false observations), or two (H 2 × 2, no false observations: the closed form (72)).
const PRIOR2 = { mean: [0.5, -1], cov: [[4, 1.2], [1.2, 2]] };
const vectorSystem = (r, P, observation) => ({
  existence: r,
  prior: { multivariateGaussian: PRIOR2 },
  observation: { detectionProbability: P, ...observation },
  falseAlarmError: 6,
  missError: 8,
});
const ROW = { gain: [[1, 0.5]], offset: [0.2], noiseCov: [[1]] };
const TWO_ROWS = { gain: [[1, 0], [0.5, 1]], offset: [0, 0.3], noiseCov: [[1, 0.3], [0.3, 2]] };
const mcVectorOf = (c, extra) => ({
  existence: c.existence, prior: PRIOR2, gain: c.observation.gain, offset: c.observation.offset, noiseCov: c.observation.noiseCov,
  detectionProbability: c.observation.detectionProbability, falseAlarmError: c.falseAlarmError, missError: c.missError, samples: SAMPLES, ...extra,
});
/** The bound's fields of one coordinate or the whole state. */
function checkVectorShape(out, l) {
  for (const k of ['bound', 'phase', 'existenceThreshold', 'terms', 'error', 'components', 'inverseInformationMatrix']) assert.ok(k in out, `missing ${k}`);
  assert.equal(out.components.length, l);
  assert.equal(out.inverseInformationMatrix.length, l);
  for (const row of out.inverseInformationMatrix) assert.equal(row.length, l);
  let [hpe, lpe, sum] = [0, 0, 0];
  for (const [i, c] of out.components.entries()) {
    assert.deepEqual(c.terms.map((t) => t.name), ['estimation', 'undetected', 'missed', 'falseTarget']);
    close(c.terms.reduce((s, t) => s + t.value, 0), c.bound, 1e-12, `component ${i}: terms sum to the bound`);
    close(c.bound, Math.min(c.hpe, c.lpe), 1e-12, `component ${i}: the smaller phase`);
    close(c.inverseInformation, out.inverseInformationMatrix[i][i], 1e-12, `component ${i}: the matrix diagonal`);
    close(c.undetectedVariance, PRIOR2.cov[i][i], 1e-12, `σe,${i}² = P_ii`);
    hpe += c.hpe;
    lpe += c.lpe;
    sum += c.bound;
  }
  // Each phase's whole-state line is the sum of the coordinates' (e²/l each); one rule on ∅
  // for the whole state can only be worse than each coordinate picking its own.
  close(out.hpe, hpe, 1e-10, 'HPE = Σ_i HPE_i');
  close(out.lpe, lpe, 1e-10, 'LPE = Σ_i LPE_i');
  assert.ok(out.bound >= sum - 1e-12, `whole-state bound ${out.bound} ≥ Σ components ${sum}`);
}

test('jdeBound with a multivariateGaussian prior: the per-coordinate bounds (63)/(70)–(72) are attained by the Monte Carlo of MAP detection + posterior mean (model I, and no false observations)', { skip: waiting('jdeBound') }, () => {
  let seed = 300;
  const cases = [];
  for (const r of [0.3, 0.7, 0.95]) {
    for (const P of [0.6, 0.9]) {
      for (const q of [0.3, 0.8]) cases.push([`m=1 q=${q}`, { ...vectorSystem(r, P, ROW), model: 'I', falseAlarm: { probability: q, density: { gaussian: { mean: 1, variance: 25 } } } }, { falseAlarm: { probability: q, mean: 1, variance: 25 } }]);
      cases.push(['m=2 q=0', { ...vectorSystem(r, P, TWO_ROWS), model: 'I' }, {}]);
      cases.push(['m=2 λ=0', { ...vectorSystem(r, P, TWO_ROWS), model: 'II' }, {}]);
    }
  }
  for (const [label, c, extra] of cases) {
    const out = fisst.jdeBound(c);
    checkVectorShape(out, 2);
    const what = `${label} r = ${c.existence}, P̄o = ${c.observation.detectionProbability}`;
    if (label.startsWith('m=2')) {
      // (72): J'_1⁻¹ = (P⁻¹ + HᵀR⁻¹H)⁻¹ = P − P Hᵀ(H P Hᵀ + R)⁻¹ H P, the posterior covariance.
      const [a, b2, d] = [PRIOR2.cov[0][0], PRIOR2.cov[0][1], PRIOR2.cov[1][1]];
      const Hm = TWO_ROWS.gain;
      const PH = [[a * Hm[0][0] + b2 * Hm[0][1], a * Hm[1][0] + b2 * Hm[1][1]], [b2 * Hm[0][0] + d * Hm[0][1], b2 * Hm[1][0] + d * Hm[1][1]]]; // P Hᵀ
      const S = [0, 1].map((i) => [0, 1].map((j) => Hm[i][0] * PH[0][j] + Hm[i][1] * PH[1][j] + TWO_ROWS.noiseCov[i][j]));
      const det = S[0][0] * S[1][1] - S[0][1] * S[1][0];
      const Si = [[S[1][1] / det, -S[0][1] / det], [-S[1][0] / det, S[0][0] / det]];
      for (let i = 0; i < 2; i++) {
        for (let j = 0; j < 2; j++) {
          let v = PRIOR2.cov[i][j];
          for (let k = 0; k < 2; k++) for (let n = 0; n < 2; n++) v -= PH[i][k] * Si[k][n] * PH[j][n];
          close(out.inverseInformationMatrix[i][j], v, 1e-12, `posterior covariance [${i}][${j}] ${what}`);
        }
      }
      assert.equal(out.error, 0);
      assert.equal(out.cardinalities[0].method, 'closed-form');
    }
    const mc = mcGaussianVector(mcVectorOf(c, { ...extra, seed: seed++ }));
    for (const rule of ['hpe', 'lpe']) {
      for (let i = 0; i < 2; i++) {
        const line = out.components[i][rule];
        const z = record(`Vec ${label} r=${c.existence} P=${c.observation.detectionProbability} x${i} ${rule}`, mc[rule].components[i], line, out.components[i].error);
        assert.ok(Math.abs(z) < Z, `${what}, x${i}, ${rule}: MC ${mc[rule].components[i].mse} ± ${mc[rule].components[i].se} vs ${line} (z = ${z})`);
      }
      const z = record(`Vec ${label} r=${c.existence} P=${c.observation.detectionProbability} whole ${rule}`, mc[rule].total, out[rule], out.error);
      assert.ok(Math.abs(z) < Z, `${what}, whole state, ${rule}: MC ${mc[rule].total.mse} ± ${mc[rule].total.se} vs ${out[rule]} (z = ${z})`);
    }
  }
});

test('jdeBound with a multivariateGaussian prior, model II: no coordinate\'s Monte Carlo MSE falls below its bound (64)', { skip: waiting('jdeBound') }, () => {
  let seed = 400;
  for (const r of [0.3, 0.7, 1]) {
    for (const P of [0.6, 0.95]) {
      for (const lambda of [0.5, 2]) {
        const c = { ...vectorSystem(r, P, ROW), model: 'II', clutter: { rate: lambda, density: { gaussian: { mean: 0, variance: 25 } } }, seed: 5, samples: 5000 };
        const out = fisst.jdeBound(c);
        checkVectorShape(out, 2);
        assert.equal(out.seed, 5);
        const mc = mcGaussianVector(mcVectorOf(c, { clutter: { rate: lambda, mean: 0, variance: 25 }, seed: seed++ }));
        for (const rule of ['hpe', 'lpe']) {
          for (let i = 0; i < 2; i++) {
            const z = record(`Vec Thm 2 r=${r} P=${P} λ=${lambda} x${i} ${rule}`, mc[rule].components[i], out.components[i][rule], out.components[i].error);
            assert.ok(z > -Z, `r = ${r}, P̄o = ${P}, λ = ${lambda}, x${i}, ${rule}: MC ${mc[rule].components[i].mse} below ${out.components[i][rule]} (z = ${z})`);
          }
          const z = record(`Vec Thm 2 r=${r} P=${P} λ=${lambda} whole ${rule}`, mc[rule].total, out[rule], out.error);
          assert.ok(z > -Z, `whole state ${rule}: MC ${mc[rule].total.mse} below ${out[rule]} (z = ${z})`);
        }
      }
    }
  }
});

test('jdeBound with l = 1: a multivariateGaussian prior is the scalar theorem to 1e-10', { skip: waiting('jdeBound') }, () => {
  const tight = { tolerance: 1e-12 };
  const scalar = (extra) => ({ existence: 0.6, prior: { gaussian: { mean: 1, variance: 4 } }, observation: { detectionProbability: 0.8, gain: 2, offset: 0.5, noiseVariance: 1.5 }, falseAlarmError: 6, missError: 9, ...tight, ...extra });
  const vector = (extra, obs = {}) => ({ ...scalar(extra), dims: 1, prior: { multivariateGaussian: { mean: [1], cov: [[4]] } }, observation: { detectionProbability: 0.8, gain: [[2]], offset: [0.5], noiseCov: [[1.5]], ...obs } });
  const same = (a, b, what) => {
    close(a.bound, b.bound, 1e-10, `bound ${what}`);
    close(a.components[0].bound, b.bound, 1e-10, `component bound ${what}`);
    close(a.existenceThreshold, b.existenceThreshold, 1e-10, `r* ${what}`);
    close(a.components[0].existenceThreshold, b.existenceThreshold, 1e-10, `component r* ${what}`);
    assert.equal(a.phase, b.phase, what);
    for (const [i, t] of a.terms.entries()) close(t.value, b.terms[i].value, 1e-10, `${t.name} ${what}`);
    close(a.eta, b.eta, 1e-10, `η ${what}`);
  };
  for (const r of [0.2, 0.6, 0.95]) {
    for (const q of [0, 0.3]) {
      const fa = q > 0 ? { falseAlarm: { probability: q, density: { uniform: { low: -10, high: 10 } } } } : {};
      const b = fisst.jdeBound({ ...scalar(fa), model: 'I', existence: r });
      same(fisst.jdeBound({ ...vector(fa), model: 'I', existence: r }), b, `model I r = ${r}, q = ${q}`);
      // the other spellings of a 1D sensor: a number gain/offset, noiseVariance, a bare variance
      same(fisst.jdeBound({ ...vector(fa, { gain: 2, offset: 0.5, noiseCov: undefined, noiseVariance: 1.5 }), model: 'I', existence: r, prior: { multivariateGaussian: { mean: [1], cov: 4 } } }), b, `model I (scalar spellings) r = ${r}`);
    }
  }
  // model II with clutter: the same Monte Carlo draws when the gain is 1 (the problem in s = hᵀx is the problem in x)
  for (const lambda of [0, 0.8]) {
    const clutter = { clutter: { rate: lambda, density: { uniform: { low: -10, high: 10 } } }, samples: 2000, seed: 7 };
    const b = fisst.jdeBound({ ...scalar(clutter), model: 'II', existence: 0.7, observation: { detectionProbability: 0.8, noiseVariance: 1.5 } });
    const v = fisst.jdeBound({ ...vector(clutter, { gain: [[1]], offset: [0] }), model: 'II', existence: 0.7 });
    same(v, b, `model II λ = ${lambda}`);
    close(v.components[0].error, b.error, 1e-10, `Monte Carlo error λ = ${lambda}`);
  }
});

test('jdeBound quadratureCardinality: 2 integrates n = 2 by the cubature of Theorem 2 and agrees with its Monte Carlo', { skip: waiting('jdeBound') }, () => {
  // A linear-Gaussian model (Gaussian prior, constant P_o): the n = 2 x-integrals in closed form
  const c = { ...gaussianSystem(0.6, 0.8), model: 'II', prior: { gaussian: { mean: 1, variance: 4 } }, observation: { detectionProbability: 0.8, noiseVariance: 1 }, clutter: { rate: 1, density: { uniform: { low: -10, high: 10 } } }, seed: 9, tolerance: 1e-5 };
  const mc = fisst.jdeBound({ ...c, quadratureCardinality: 1 });
  const t0 = performance.now();
  const quad = fisst.jdeBound({ ...c, quadratureCardinality: 2 });
  const ms = performance.now() - t0;
  console.log(`quadratureCardinality: 2 took ${ms.toFixed(0)} ms (λ = 1, N(1, 4) prior, U[−10, 10] clutter); n = 2 Monte Carlo: J'_2⁻¹ = ${mc.cardinalities[1].inverseInformation.toFixed(5)} ± ${mc.cardinalities[1].error.toExponential(2)}, cubature ${quad.cardinalities[1].inverseInformation.toFixed(5)} ± ${quad.cardinalities[1].error.toExponential(2)}`);
  assert.deepEqual(mc.cardinalities.slice(0, 3).map((k) => k.method), ['quadrature', 'monte-carlo', 'monte-carlo']);
  assert.deepEqual(quad.cardinalities.slice(0, 3).map((k) => k.method), ['quadrature', 'quadrature', 'monte-carlo']);
  assert.equal(quad.cardinalities.length, mc.cardinalities.length);
  const [a, b] = [mc.cardinalities[1], quad.cardinalities[1]];
  assert.ok(Math.abs(a.inverseInformation - b.inverseInformation) <= Z * a.error + b.error, `J'_2⁻¹: ${a.inverseInformation} ± ${a.error} vs ${b.inverseInformation} ± ${b.error}`);
  assert.ok(Math.abs(mc.bound - quad.bound) <= Z * (mc.error + quad.error), `bound ${mc.bound} ± ${mc.error} vs ${quad.bound} ± ${quad.error}`);
  assert.ok(b.error < a.error, 'the cubature error is below the Monte Carlo standard error');
  // 2 is the default on a linear-Gaussian model, 1 on any other (a tabulated P_o); 1 and 2 only
  assert.equal(fisst.jdeBound(c).bound, quad.bound);
  const tabulated = { ...c, observation: { detectionProbability: { table: { x: [-20, 20], probability: [0.8, 0.8] } }, noiseVariance: 1 } };
  assert.deepEqual(fisst.jdeBound(tabulated).cardinalities.slice(0, 3).map((k) => k.method), ['quadrature', 'monte-carlo', 'monte-carlo']);
  throwsAt(() => fisst.jdeBound({ ...c, quadratureCardinality: 3 }), RangeError, 'options.quadratureCardinality');
  throwsAt(() => fisst.jdeBound({ ...c, quadratureCardinality: 1.5 }), RangeError, 'options.quadratureCardinality');
});

// ------------------------------------------------------------------ Example 2 (32), Fig. 2 right
/** The 24 Gauss–Legendre nodes and weights on [−1, 1]. */
const GL24 = Array.from({ length: 24 }, (_, j) => {
  const n = 24;
  let x = Math.cos((Math.PI * (j + 0.75)) / (n + 0.5));
  let dp = 0;
  for (let it = 0; it < 50; it++) {
    let [p0, p1] = [1, x];
    for (let k = 2; k <= n; k++) [p0, p1] = [p1, ((2 * k - 1) * x * p1 - (k - 1) * p0) / k];
    dp = (n * (x * p1 - p0)) / (x * x - 1);
    const dx = p1 / dp;
    x -= dx;
    if (Math.abs(dx) < 1e-15) break;
  }
  return [x, 2 / ((1 - x * x) * dp * dp)];
});
/** ∫_a^b h by 24-point Gauss–Legendre, composite over `panels` panels. */
function quad(h, a, b, panels = 8) {
  let total = 0;
  for (let p = 0; p < panels; p++) {
    const [lo, hi] = [a + ((b - a) * p) / panels, a + ((b - a) * (p + 1)) / panels];
    for (const [x, w] of GL24) total += ((hi - lo) / 2) * w * h(lo + ((hi - lo) * (1 + x)) / 2);
  }
  return total;
}

/**
 * Theorem 1 (21) for Example 2: ∫p_1(x, z)dx = m(z) = ∫₀¹ 2x²e^{xz}dx increases in z, so
 * Z'_0 = [z₀, 1] with m(z₀) = q(1 − r)/(r P_o) (19); w_1 = ∫_{Z'_0} m, η_1 = q z₀,
 * −∫∫_{Z'_0} p_1 ∂²ln p_1 = ∫_{Z'_0} 4(eᶻ − 1)/z dz ((32) takes this for J'_1; (20) divides it by w_1²).
 */
function example2Oracle(r, P, q, e0) {
  const ve = example2Prior.variance;
  const e1 = e0 + ve;
  const m = (z) => quad((x) => 2 * x * x * Math.exp(x * z), 0, 1, 1); // smooth: one panel is exact to 1e-15
  const level = r * P > 0 ? (q * (1 - r)) / (r * P) : Infinity;
  let z0;
  if (level <= m(0)) z0 = 0;
  else if (level > m(1)) z0 = 1;
  else {
    let [lo, hi] = [0, 1];
    for (let i = 0; i < 60; i++) [lo, hi] = m((lo + hi) / 2) < level ? [(lo + hi) / 2, hi] : [lo, (lo + hi) / 2];
    z0 = (lo + hi) / 2;
  }
  const w1 = z0 < 1 ? quad(m, z0, 1) : 0;
  const info = z0 < 1 ? quad((z) => (z === 0 ? 4 : (4 * Math.expm1(z)) / z), z0, 1) : 0;
  const eta = q * z0;
  const restHpe = r * (1 - P) * ve + r * (P - P * w1) * e1 + (1 - r) * (1 - eta) * e0;
  const restLpe = r * (1 - P * w1) * e1 + (1 - r) * (q - eta) * e0;
  // r ≥ r₁* (18) is where the HPE piece is the lower; when Z = ∅ cannot happen (q = 1, P_o = 1)
  // the two pieces are equal and either phase is right.
  const hpe = restHpe <= restLpe;
  const rest = Math.min(restHpe, restLpe);
  return { w1, eta, paperInformation: info, information: w1 > 0 ? info / (w1 * w1) : Infinity, paperBound: (w1 > 0 ? (r * P) / info : 0) + rest, bound: (w1 > 0 ? (r * P * w1 * w1) / info : 0) + rest, hpe, tie: Math.abs(restHpe - restLpe) < 1e-12 };
}

test('jdeExample2 is Theorem 1 for Example 2 ((32) and (20)); its curve is no bound where the Monte Carlo falls below it', { skip: waiting('jdeExample2') }, () => {
  for (const r of [0.3, 0.6, 0.9, 1]) {
    for (const P of [0.1, 0.4, 0.7, 1]) {
      for (const q of [0, 0.2, 0.5, 0.8, 1]) {
        const out = fisst.jdeExample2({ existence: r, detectionProbability: P, falseAlarmProbability: q, falseAlarmError: 1.2 });
        const want = example2Oracle(r, P, q, 1.2);
        const what = `r = ${r}, P_o = ${P}, q = ${q}`;
        close(out.paperBound, want.paperBound, 1e-6, `paper curve ${what}`);
        close(out.bound, want.bound, 1e-6, `(20) curve ${what}`);
        close(out.w, want.w1, 1e-6, `w_1 ${what}`);
        close(out.eta, want.eta, 1e-6, `η_1 ${what}`);
        close(out.undetectedVariance, example2Prior.variance, 1e-9, 'σe²');
        close(out.missError, 1.2 + example2Prior.variance, 1e-12, 'e1² = e0² + σe²');
        if (!want.tie) assert.equal(out.phase, want.hpe ? 'HPE' : 'LPE', what);
      }
    }
  }
  // NOTES.md: J_1 = 5.2716, 1/J_1 = 0.1897 > the posterior mean's 0.0340 at r = 1, P_o = 1.
  const reg = fisst.jdeExample2Regularity();
  close(reg.information, 5.2716, 1e-4, 'J_1');
  close(reg.inverseInformation, 0.1897, 3e-4, '1/J_1');
  close(reg.priorVariance, example2Prior.variance, 1e-9, 'σe²');
  const mc = mcExample2({ existence: 1, detectionProbability: 1, falseAlarmProbability: 0, falseAlarmError: 1.2, missError: 1.2 + example2Prior.variance, samples: SAMPLES, seed: 11 });
  assert.ok(Math.abs(mc.mse - reg.posteriorMeanMse) < Z * mc.se, `MMSE ${mc.mse} ± ${mc.se} vs ${reg.posteriorMeanMse}`);
  assert.ok(mc.mse + Z * mc.se < fisst.jdeExample2({ existence: 1, detectionProbability: 1, falseAlarmProbability: 0, falseAlarmError: 1.2 }).paperBound, 'the curve is above the MMSE: not a bound');
  throwsAt(() => fisst.jdeExample2({ existence: 1.1, detectionProbability: 1, falseAlarmProbability: 0, falseAlarmError: 1.2 }), RangeError, 'options.existence');
  throwsAt(() => fisst.jdeExample2({ existence: 1, detectionProbability: 1, falseAlarm: 0, falseAlarmError: 1.2 }), TypeError, 'options');
});

// ------------------------------------------------------------------ jdeMonteCarlo (the package's own Monte Carlo)
test('jdeMonteCarlo (the core\'s seeded Monte Carlo of the optimal JDE) agrees with the JS oracle within Z combined standard errors, and is seeded', { skip: waiting('jdeMonteCarlo') }, () => {
  const both = (what, mine, oracle) => {
    const se = Math.hypot(mine.se, oracle.se);
    const z = se > 0 ? (mine.mse - oracle.mse) / se : 0;
    assert.ok(Math.abs(z) < Z, `${what}: jdeMonteCarlo ${mine.mse} ± ${mine.se} vs oracle ${oracle.mse} ± ${oracle.se} (z = ${z})`);
    return z;
  };
  const gaussian = (r, P) => ({ ...gaussianSystem(r, P), samples: SAMPLES });
  let seed = 900;
  const zs = [];
  for (const r of [0.3, 0.8]) {
    for (const P of [0.5, 0.9]) {
      const base = gaussian(r, P);
      const fa = { probability: 0.4, mean: 1, variance: 25 };
      const cl = { rate: 1.5, mean: 0, variance: 25 };
      const one = fisst.jdeMonteCarlo({ ...base, model: 'I', falseAlarm: { probability: fa.probability, density: { gaussian: { mean: fa.mean, variance: fa.variance } } }, seed: seed++ });
      zs.push(both(`model I r=${r} P=${P}`, one, mcGaussian(mcOf(base, { falseAlarm: fa, seed: seed++ }))));
      const two = fisst.jdeMonteCarlo({ ...base, model: 'II', clutter: { rate: cl.rate, density: { gaussian: { mean: cl.mean, variance: cl.variance } } }, seed: seed++ });
      zs.push(both(`model II r=${r} P=${P}`, two, mcGaussian(mcOf(base, { clutter: cl, seed: seed++ }))));
      const map = fisst.jdeMonteCarlo({ ...base, model: 'I', emptyRule: 'map', seed: seed++ });
      zs.push(both(`MAP on ∅ r=${r} P=${P}`, map, mcGaussian(mcOf(base, { rule: 'map', seed: seed++ }))));
      for (const out of [one, two, map]) close(out.falseAlarm + out.miss + out.estimation, out.mse, 1e-9, 'the parts sum to the risk');
      // a vector state with model I false alarms: the whole state and each coordinate
      const v = { ...vectorSystem(r, P, ROW), model: 'I', falseAlarm: { probability: 0.3, density: { gaussian: { mean: 1, variance: 25 } } }, samples: SAMPLES };
      const mv = fisst.jdeMonteCarlo({ ...v, emptyRule: 'declare', seed: seed++ });
      const ov = mcGaussianVector(mcVectorOf(v, { falseAlarm: { probability: 0.3, mean: 1, variance: 25 }, seed: seed++ })).hpe;
      zs.push(both(`vector r=${r} P=${P}`, mv, ov.total));
      mv.components.forEach((c, i) => zs.push(both(`vector r=${r} P=${P} x${i + 1}`, c, ov.components[i])));
    }
  }
  // Example 2 and the sequential posterior mean (the page's Fig. 2 right and Fig. 3)
  const ve = example2Prior.variance;
  for (const [P, q] of [[0.4, 0.5], [1, 0]]) {
    const mine = fisst.jdeMonteCarlo({ model: 'I', existence: 0.6, prior: 'example2', observation: { detectionProbability: P }, falseAlarm: { probability: q, density: { uniform: { low: 0, high: 1 } } }, falseAlarmError: 1.2, missError: 1.2 + ve, samples: SAMPLES, seed: seed++ });
    zs.push(both(`Example 2 P=${P} q=${q}`, mine, mcExample2({ existence: 0.6, detectionProbability: P, falseAlarmProbability: q, falseAlarmError: 1.2, missError: 1.2 + ve, samples: SAMPLES, seed: seed++ })));
  }
  const seq = fisst.jdeMonteCarlo({ model: 'I', existence: 1, prior: { gaussian: { mean: 0, variance: 100 } }, observation: { detectionProbability: 0.5, gain: 1, noiseVariance: 100 / 3 }, falseAlarmError: 0, missError: 0, emptyRule: 'declare', scans: 8, samples: SAMPLES, seed: seed++ });
  const oseq = mcSequential({ priorInformation: 0.01, detectedInformation: 0.04, detectionProbability: 0.5, steps: 8, samples: SAMPLES, seed: seed++ });
  seq.scans.forEach((s, k) => zs.push(both(`scan ${k + 1}`, s, { mse: oseq.mse[k], se: oseq.se[k] })));
  console.log(`jdeMonteCarlo vs the JS oracle (${SAMPLES} samples each): worst |z| ${Math.max(...zs.map(Math.abs)).toFixed(2)} over ${zs.length} comparisons`);
  // seeded: the same seed gives the same numbers, another seed others
  const o = { ...gaussian(0.6, 0.7), model: 'II', clutter: { rate: 1, density: { uniform: { low: -20, high: 20 } } }, samples: 5000 };
  assert.deepEqual(fisst.jdeMonteCarlo({ ...o, seed: 5 }), fisst.jdeMonteCarlo({ ...o, seed: 5 }));
  assert.notEqual(fisst.jdeMonteCarlo({ ...o, seed: 6 }).mse, fisst.jdeMonteCarlo({ ...o, seed: 5 }).mse);
  const fresh = fisst.jdeMonteCarlo({ ...o, samples: 100 });
  assert.ok(Number.isSafeInteger(fresh.seed), 'an omitted seed is drawn and returned');
  // bad options name their field
  throwsAt(() => fisst.jdeMonteCarlo({ ...o, samples: 1 }), RangeError, 'options.samples');
  throwsAt(() => fisst.jdeMonteCarlo({ ...o, samples: 20_000_000 }), RangeError, 'options.samples');
  throwsAt(() => fisst.jdeMonteCarlo({ ...o, samples: 6_000_000 }), RangeError, 'options.samples'); // × (1 + λ) > 10^7
  throwsAt(() => fisst.jdeMonteCarlo({ ...o, scans: 2 }), RangeError, 'options.scans'); // k > 1 needs no clutter
  throwsAt(() => fisst.jdeMonteCarlo({ ...o, existence: 2 }), RangeError, 'options.existence');
  throwsAt(() => fisst.jdeMonteCarlo({ ...o, emptyRule: 'hpe' }), RangeError, 'options.emptyRule');
  throwsAt(() => fisst.jdeMonteCarlo({ ...o, sample: 10 }), TypeError, 'options');
});

// ------------------------------------------------------------------ errors
function throwsAt(fn, cls, path) {
  assert.throws(fn, (e) => {
    assert.ok(e instanceof cls, `expected ${cls.name}, got ${e?.constructor?.name}: ${e?.message}`);
    assert.ok(e.message.startsWith(path), `message ${JSON.stringify(e.message)} should start with ${path}`);
    return true;
  });
}

test('closed forms: bad values are RangeErrors and misspelt keys TypeErrors, each naming the field path', { skip: waiting('jdeBoundNoClutter') }, () => {
  const nc = { existence: 0.5, detectionProbability: 0.5, priorVariance: 100, posteriorVariance: 25, falseAlarmError: 150, missError: 200 };
  throwsAt(() => fisst.jdeBoundNoClutter({ ...nc, existence: 1.5 }), RangeError, 'options.existence');
  throwsAt(() => fisst.jdeBoundNoClutter({ ...nc, existence: NaN }), RangeError, 'options.existence');
  throwsAt(() => fisst.jdeBoundNoClutter({ ...nc, detectionProbability: -0.1 }), RangeError, 'options.detectionProbability');
  throwsAt(() => fisst.jdeBoundNoClutter({ ...nc, priorVariance: 0 }), RangeError, 'options.priorVariance');
  throwsAt(() => fisst.jdeBoundNoClutter({ ...nc, posteriorVariance: -1 }), RangeError, 'options.posteriorVariance');
  throwsAt(() => fisst.jdeBoundNoClutter({ ...nc, falseAlarmError: Infinity }), RangeError, 'options.falseAlarmError');
  throwsAt(() => fisst.jdeBoundNoClutter({ ...nc, existance: 0.5 }), TypeError, 'options');
  throwsAt(() => fisst.jdeBoundNoClutter({ ...nc, missError: '200' }), TypeError, 'options.missError');
  const fi = { priorVariance: 1, gain: 1, noiseVariance: 1 };
  throwsAt(() => fisst.gaussianFisherInformation({ ...fi, noiseVariance: 0 }), RangeError, 'options.noiseVariance');
  throwsAt(() => fisst.gaussianFisherInformation({ ...fi, priorVariance: -2 }), RangeError, 'options.priorVariance');
  throwsAt(() => fisst.gaussianFisherInformation({ ...fi, gain: NaN }), RangeError, 'options.gain');
  throwsAt(() => fisst.gaussianFisherInformation({ priorVariance: 1, gain: 1, noiseVar: 1 }), TypeError, 'options');
  const sq = { method: 'irf', priorInformation: 0.01, detectedInformation: 0.04, detectionProbability: 0.5, steps: 5 };
  throwsAt(() => fisst.jdeSequentialBound({ ...sq, steps: 0 }), RangeError, 'options.steps');
  throwsAt(() => fisst.jdeSequentialBound({ ...sq, steps: 2.5 }), RangeError, 'options.steps');
  throwsAt(() => fisst.jdeSequentialBound({ ...sq, detectionProbability: 2 }), RangeError, 'options.detectionProbability');
  throwsAt(() => fisst.jdeSequentialBound({ ...sq, priorInformation: 0 }), RangeError, 'options.priorInformation');
  assert.throws(() => fisst.jdeSequentialBound({ ...sq, method: 'enum' }), (e) => (e instanceof TypeError || e instanceof RangeError) && e.message.startsWith('options.method'));
  throwsAt(() => fisst.jdeSequentialBound({ ...sq, step: 5 }), TypeError, 'options');
  throwsAt(() => fisst.jdeSequentialBound({ ...sq, steps: 10_001 }), RangeError, 'options.steps');
  // The module survives: a good call after the bad ones.
  assert.equal(fisst.jdeSequentialBound(sq).bound.length, 5);
});

test('jdeBound: bad values are RangeErrors and misspelt keys TypeErrors, each naming the field path', { skip: waiting('jdeBound') }, () => {
  const jb = { ...gaussianSystem(0.5, 0.5), model: 'I', falseAlarm: { probability: 0.2, density: { gaussian: { mean: 0, variance: 25 } } } };
  assert.throws(() => fisst.jdeBound({ ...jb, model: 'III' }), (e) => (e instanceof TypeError || e instanceof RangeError) && e.message.startsWith('options.model'));
  throwsAt(() => fisst.jdeBound({ ...jb, existence: -0.5 }), RangeError, 'options.existence');
  throwsAt(() => fisst.jdeBound({ ...jb, prior: { gaussian: { mean: 0, variance: -1 } } }), RangeError, 'options.prior.gaussian.variance');
  throwsAt(() => fisst.jdeBound({ ...jb, observation: { ...jb.observation, noiseVariance: 0 } }), RangeError, 'options.observation.noiseVariance');
  throwsAt(() => fisst.jdeBound({ ...jb, falseAlarm: { ...jb.falseAlarm, probability: 1.2 } }), RangeError, 'options.falseAlarm.probability');
  throwsAt(() => fisst.jdeBound({ ...jb, falseAlarms: jb.falseAlarm }), TypeError, 'options');
  throwsAt(() => fisst.jdeBound({ ...jb, prior: { gaussian: { mean: 0, varaince: 1 } } }), TypeError, 'options.prior.gaussian');
  // a vector state
  const vb = { ...vectorSystem(0.5, 0.8, ROW), model: 'I', falseAlarm: jb.falseAlarm };
  assert.equal(fisst.jdeBound(vb).components.length, 2);
  throwsAt(() => fisst.jdeBound({ ...jb, dims: 2 }), RangeError, 'options.dims');
  throwsAt(() => fisst.jdeBound({ ...vb, dims: 3 }), RangeError, 'options.dims');
  throwsAt(() => fisst.jdeBound({ ...vb, dims: 0 }), RangeError, 'options.dims');
  throwsAt(() => fisst.jdeBound({ ...vb, prior: { multivariateGaussian: { mean: [0, 0], cov: [[1, 2], [2, 1]] } } }), RangeError, 'options.prior.multivariateGaussian.cov');
  throwsAt(() => fisst.jdeBound({ ...vb, prior: { multivariateGaussian: { mean: [0, 0], cov: [[1, 0], [0]] } } }), RangeError, 'options.prior.multivariateGaussian.cov[1]');
  throwsAt(() => fisst.jdeBound({ ...vb, prior: { multivariateGaussian: { mean: [0, NaN], cov: [[1, 0], [0, 1]] } } }), RangeError, 'options.prior.multivariateGaussian.mean[1]');
  throwsAt(() => fisst.jdeBound({ ...vb, prior: { multivariateGaussian: { mean: [], cov: [] } } }), RangeError, 'options.prior.multivariateGaussian.mean');
  throwsAt(() => fisst.jdeBound({ ...vb, prior: { multivariateGaussian: { mean: [0, 0], covariance: [[1, 0], [0, 1]] } } }), TypeError, 'options.prior.multivariateGaussian');
  throwsAt(() => fisst.jdeBound({ ...vb, observation: { ...vb.observation, gain: [[1, 0.5], [1]] } }), RangeError, 'options.observation.gain[1]');
  throwsAt(() => fisst.jdeBound({ ...vb, observation: { ...vb.observation, gain: [1, 0.5] } }), TypeError, 'options.observation.gain[0]');
  throwsAt(() => fisst.jdeBound({ ...vb, observation: { ...vb.observation, gain: 1 } }), TypeError, 'options.observation.gain');
  throwsAt(() => fisst.jdeBound({ ...vb, observation: { ...vb.observation, gain: [] } }), RangeError, 'options.observation.gain');
  throwsAt(() => fisst.jdeBound({ ...vb, observation: { ...vb.observation, gain: [[1, NaN]] } }), RangeError, 'options.observation.gain[0][1]');
  throwsAt(() => fisst.jdeBound({ ...vb, observation: { ...vb.observation, offset: [0, 1] } }), RangeError, 'options.observation.offset');
  throwsAt(() => fisst.jdeBound({ ...vb, observation: { ...vb.observation, noiseCov: [[-1]] } }), RangeError, 'options.observation.noiseCov');
  throwsAt(() => fisst.jdeBound({ ...vb, observation: { ...vb.observation, noiseCov: undefined } }), TypeError, 'options.observation.noiseCov');
  throwsAt(() => fisst.jdeBound({ ...vb, observation: { ...vb.observation, noiseVariance: 1 } }), TypeError, 'options.observation.noiseVariance');
  throwsAt(() => fisst.jdeBound({ ...vb, observation: { ...vb.observation, noiseCov: undefined, noiseVariance: -1 } }), RangeError, 'options.observation.noiseVariance');
  throwsAt(() => fisst.jdeBound({ ...vb, observation: { ...vb.observation, detectionProbability: { table: { x: [0, 1], probability: [0.5, 0.9] } } } }), TypeError, 'options.observation.detectionProbability');
  throwsAt(() => fisst.jdeBound({ ...vb, observation: { ...vb.observation, detectionProbability: 1.5 } }), RangeError, 'options.observation.detectionProbability');
  throwsAt(() => fisst.jdeBound({ ...vb, observation: { ...TWO_ROWS, detectionProbability: 0.8 } }), RangeError, 'options.observation.gain'); // false alarms need m = 1
  throwsAt(() => fisst.jdeBound({ ...vb, observation: { ...TWO_ROWS, detectionProbability: 0.8, noiseCov: [[1, 0.3], [0.2, 2]] } }), RangeError, 'options.observation.noiseCov');
  // issue 26 point 1: the covariance checks of every other function, in the same words
  assert.throws(() => fisst.jdeBound({ ...vb, observation: { ...TWO_ROWS, detectionProbability: 0.8, noiseCov: [[1, 0.3], [0.2, 2]] } }),
    { name: 'RangeError', message: 'options.observation.noiseCov is not symmetric: [0][1] = 0.3 but [1][0] = 0.2' });
  assert.throws(() => fisst.jdeBound({ ...vb, prior: { multivariateGaussian: { mean: [0, 0], cov: [[1.25, 0], [0, -0.25]] } } }),
    { name: 'RangeError', message: 'options.prior.multivariateGaussian.cov is not positive definite (smallest eigenvalue -0.25)' });
  throwsAt(() => fisst.jdeBound({ ...jb, observation: { ...jb.observation, gain: [[1]] } }), TypeError, 'options.observation.gain');
  throwsAt(() => fisst.jdeBound({ ...jb, observation: { ...jb.observation, noiseCov: [[1]] } }), TypeError, 'options.observation.noiseCov');
  throwsAt(() => fisst.jdeBound({ ...jb, observation: { detectionProbability: 0.5 } }), TypeError, 'options.observation.noiseVariance');
  throwsAt(() => fisst.jdeBound({ ...jb, falseAlarm: { probability: 0.2, density: { multivariateGaussian: PRIOR2 } } }), TypeError, 'options.falseAlarm.density'); // a prior shape only
  assert.ok(Number.isFinite(fisst.jdeBound(vb).bound));
  // The module survives: a good call after the bad ones.
  assert.ok(Number.isFinite(fisst.jdeBound(jb).bound));
});

test('summary: the worst z-score of the Monte Carlo against the bounds', { skip: zScores.length === 0 && waiting('jdeBoundNoClutter') }, () => {
  const worst = zScores.reduce((w, s) => (Math.abs(s.z) > Math.abs(w.z) ? s : w), zScores[0]);
  const attained = zScores.filter((s) => !s.what.includes('Thm 2'));
  const worstAttained = attained.reduce((w, s) => (Math.abs(s.z) > Math.abs(w.z) ? s : w), attained[0]);
  const lowestOf = (list) => list.reduce((w, s) => (s.z < w.z ? s : w), { z: Infinity });
  const lowest2 = lowestOf(zScores.filter((s) => s.what.startsWith('Thm 2')));
  const lowestVec2 = lowestOf(zScores.filter((s) => s.what.startsWith('Vec Thm 2')));
  const lowestText = (w) => (Number.isFinite(w.z) ? `${w.z.toFixed(2)} (${w.what})` : '—');
  const groups = {};
  for (const g of zScores) {
    const name = g.what.split(/ r=| k=/)[0].replace(/ P=.*$/, '');
    const w = (groups[name] ??= { n: 0, worst: g });
    w.n++;
    if (Math.abs(g.z) > Math.abs(w.worst.z)) w.worst = g;
  }
  const parts = Object.entries(groups).map(([name, { n, worst: w }]) => `${name}: worst z ${w.z.toFixed(2)} of ${n} (${w.what}: ${w.mse.toFixed(4)} vs ${w.bound.toFixed(4)})`);
  console.log(`Monte Carlo vs bound (${SAMPLES} samples a point; z = (MSE − bound)/SE): ${parts.join('; ')}; `
    + `Theorem 2 (one-sided) lowest z ${lowestText(lowest2)}, vector ${lowestText(lowestVec2)}; worst |z| where attained ${worstAttained.z.toFixed(2)}; overall ${worst.what} z = ${worst.z.toFixed(2)}`);
  assert.ok(Math.abs(worstAttained.z) < Z);
});
