// Lower bounds on the mean-square error of jointly detecting and estimating one object that may
// not exist: Rezaeian & Vo, "Error bounds for joint detection and estimation of a single object
// with random finite set observation" — Corollary 3 in the Gaussian form (31), Theorem 1, and
// Example 2, i.e. Fig. 2 left and right. Paper values are printed next to the library's.
import * as fisst from 'fisst';

// Fig. 2 left: prior variance σ_f² = 100, mean posterior variance after one observation σ_h² = 25,
// e_0² = 150 (squared error of declaring an object that is not there), e_1² = 200 (of missing one).
// σ_h² comes from z = x + v with noise variance σ_v² = 100/3: 1/J_1 = 1/(1/σ_f² + 1/σ_v²) = 25.
console.log(fisst.gaussianFisherInformation({ priorVariance: 100, gain: 1, noiseVariance: 100 / 3 })); // { information: 0.04, posteriorVariance: 25 }
const fig2 = { priorVariance: 100, posteriorVariance: 25, falseAlarmError: 150, missError: 200 };
for (const P of [0, 0.5, 1]) {
  // P̄_o = `detectionProbability`, the probability of observing the object; r = `existence`.
  // (31): the bound is linear in r on each side of r* = e_0² / (e_0² + (1 − P̄_o)(e_1² − σ_f²)),
  // and at r = 1 it is σ_f² − P̄_o(σ_f² − σ_h²) = 100 − 75 P̄_o.
  const b = fisst.jdeBoundNoClutter({ ...fig2, existence: 1, detectionProbability: P });
  const paper = { rStar: 150 / (150 + (1 - P) * 100), atOne: 100 - 75 * P };
  console.log(`P̄o=${P}: r* paper ${paper.rStar.toFixed(3)} library ${b.existenceThreshold.toFixed(3)}; bound at r=1 paper ${paper.atOne} library ${b.bound}`);
  // P̄o=0: r* paper 0.600 library 0.600; bound at r=1 paper 100 library 100
  // P̄o=0.5: r* paper 0.750 library 0.750; bound at r=1 paper 62.5 library 62.5
  // P̄o=1: r* paper 1.000 library 1.000; bound at r=1 paper 25 library 25
}
// The MAP detector on Z = ∅ switches at r_M* = 1/(2 − P̄_o) instead of r*, raising the bound between them.
const m = fisst.jdeBoundNoClutter({ ...fig2, existence: 0.7, detectionProbability: 0.5 });
console.log(m.bound, m.mapThreshold.toFixed(4), m.mapBound); // 78.75 0.6667 88.75

// Theorem 1 computed in general (quadrature over z) for the same system gives the same number, with
// its summands: estimation error, undetected-object error, missed-object and false-target costs.
// `model: 'I'` is the paper's measurement model I (at most one measurement: the object's, or a false
// alarm with probability q, Theorem 1); 'II' is Poisson clutter (Theorem 2).
const t1 = fisst.jdeBound({ model: 'I', existence: 0.7, prior: { gaussian: { mean: 0, variance: 100 } },
  observation: { detectionProbability: 0.5, noiseVariance: 100 / 3 }, falseAlarmError: 150, missError: 200 });
console.log(t1.bound.toFixed(6), t1.phase, t1.terms.map((x) => `${x.name}=${x.value.toFixed(2)}`).join(' ')); // 78.750000 LPE estimation=8.75 undetected=0.00 missed=70.00 falseTarget=0.00

// Fig. 2 right, Example 2: f(x) = 2x(eˣ − 1) on [0, 1], r = 0.6, e_0² = 1.2, e_1² = e_0² + σ_e².
// Its regularity check at r = P_o = 1 (the paper does not say it: p_1 does not vanish at x = 1, so the
// information inequality's regularity condition fails): J_1 = 5.2716, 1/J_1 = 0.1897, yet the
// posterior mean attains 0.0340, so the curve is not a bound everywhere.
const reg = fisst.jdeExample2Regularity();
console.log([reg.information, reg.inverseInformation, reg.posteriorMeanMse, reg.priorVariance].map((v) => v.toFixed(4)).join(' ')); // 5.2716 0.1897 0.0340 0.0341
// The paper: at P_o = 0, q = 1 only r σ_e² = 0.6 × 0.0341 is left; at low P_o, more false alarms
// (probability q) lower the bound. `paperBound` is the curve as the paper computes it, (32); `bound`
// uses (20), with 1/w_1². Where w_1 = 0 (Z'_0 = `region` empty: P_o = 0, or q high at a low P_o, as at
// (P_o, q) = (0, 1) and (0.1, 1) below) `information` (A/w_1²) is Infinity (null in JSON).
const ex2 = (P, q) => fisst.jdeExample2({ existence: 0.6, detectionProbability: P, falseAlarmProbability: q, falseAlarmError: 1.2 }).paperBound;
console.log((0.6 * reg.priorVariance).toFixed(4), ex2(0, 1).toFixed(4)); // 0.0205 0.0205
console.log(ex2(0.1, 0).toFixed(4), '>', ex2(0.1, 1).toFixed(4)); // 0.5098 > 0.0925
