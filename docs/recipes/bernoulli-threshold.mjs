// The Bayes-optimal point estimate of a Bernoulli (an object that exists with probability p and
// then lies at x ~ s(x)), and its threshold Γ: Narykov, Üney & Ralph, "Optimal Bernoulli point
// estimation with applications" (Theorem III.3, Figs 2–3). Report a point only when p > Γ.
import * as fisst from 'fisst';

// The loss (7): c00 (nothing there, nothing reported), c01 (missed object), c10 (false report),
// c11 + c·1{|x − a| > r0} (object reported at a, charged c more when the object is farther than
// the tolerance radius r0). Presets: 'mpe' = (0, 1, 1, 0, 1); MMOL, { mmol: { asset: c_A,
// countermeasure: c_M } } = (0, c_A, c_M, c_M, c_A); or give { c00, c01, c10, c11, c } yourself.
const mpe = 'mpe';
const mmol = { mmol: { asset: 0.9, countermeasure: 0.1 } };

// p = 0.55 and s = N(0, 1) in 1D, r0 = 1 (`radius`): Fig. 2 of the paper.
const density = { mean: [0], cov: 1 }; // a 1D covariance may be the bare variance
const e = fisst.bernoulliEstimate({ existence: 0.55, density, radius: 1, costs: mpe });
// threshold = Γ (11); mmuc = the point a* minimising the miss probability q(a) (12);
// missProbability = q(a*) = P(|x − a*| > r0); declare = p > Γ; estimate = a* or null.
console.log(e.threshold.toFixed(4), e.mmuc, e.missProbability.toFixed(4)); // 0.5943 [ 0 ] 0.3173
// p = 0.55 > 0.5, yet under MPE the optimal estimate is empty: Γ = 0.5943 > p.
console.log(e.declare, e.estimate); // false null
// ρ_∅ (14) and ρ_{a*} (13): the expected losses of reporting nothing and of reporting a*.
console.log(e.expectedLossEmpty.toFixed(4), e.expectedLossSingleton.toFixed(4)); // 0.5500 0.6245

// MMOL with c_A = 0.9, c_M = 0.1: a cheap countermeasure lowers Γ to 0.1628, so the same
// Bernoulli is reported.
const m = fisst.bernoulliEstimate({ existence: 0.55, density, radius: 1, costs: mmol });
console.log(m.threshold.toFixed(4), m.declare, m.estimate); // 0.1628 true [ 0 ]

// Fig. 3: Γ against the spread σ of s = N(a*, σ²) (closed form, r0 = 1, dimension 1 by default).
// The vaguer the object's position, the surer of its existence one must be to report it.
const sigmas = [0.5, 1, 2, 5];
const row = (costs) => fisst.bernoulliThresholdCurve({ sigmas, radius: 1, costs }).map((g) => g.toFixed(4)).join(' ');
console.log('MPE ', row(mpe)); // MPE  0.5116 0.5943 0.7231 0.8632
console.log('MMOL', row(mmol)); // MMOL 0.1164 0.1628 0.2902 0.7009
