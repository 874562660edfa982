//! Optimal Bernoulli point estimation (Narykov, Üney & Ralph, "Optimal Bernoulli point
//! estimation with applications", paper 000): the estimate of Theorem III.3, q(a), the MMUC
//! estimate and the threshold curves of Fig. 3.

use wasm_bindgen::prelude::*;

use crate::boundary::{JsResult, OrThrow, read, write};
use fisst::bernoulli::{
    self, BernoulliEstimateOptions, LossCurveOptions, MmucOptions, MultiBernoulliPointOptions,
    ProbabilityOutsideBallOptions, ThresholdCurveOptions,
};

// The spatial density of a Bernoulli is the core's `SpatialDensity`, read by its own
// deserializer (errors name `.mixture[2].cov`, `.particles[1]` under the density's path); its
// TypeScript is generated, `BernoulliDensity` its contract name (`ts_aliases.rs`).

// The costs of the loss (7) are the core's `Costs`, read by its own deserializer ('mpe',
// `{ mmol }` or the five costs; errors name `.c01`, `.mmol.asset` under `options.costs`); its
// TypeScript is generated, `BernoulliCosts` its contract name (`ts_aliases.rs`).

/// The Bayes-optimal point estimate of a Bernoulli (Theorem III.3 of Narykov, Üney & Ralph,
/// "Optimal Bernoulli point estimation with applications", paper 000): report the MMUC point a*
/// (12) when the existence probability exceeds Γ (11), else nothing. Options `{ existence, density,
/// radius, costs }`; returns `{ declare, estimate, mmuc, threshold, missProbability,
/// expectedLossEmpty, expectedLossSingleton }`.
#[cfg(feature = "bernoulli")]
#[wasm_bindgen(js_name = bernoulliEstimate, unchecked_return_type = "BernoulliEstimateResult")]
pub fn bernoulli_estimate(
    #[wasm_bindgen(unchecked_param_type = "BernoulliEstimateOptions")] options: JsValue,
) -> JsResult<JsValue> {
    let o: BernoulliEstimateOptions = read(options, "options")?;
    write(&o.estimate().or_throw_rendered("options")?)
}

/// q(center) = P(‖x − center‖ > radius) for x drawn from `density`: exact in 1D, to 1e-10
/// (absolute) by error-controlled quadrature or characteristic-function inversion in higher
/// dimensions, the weighted sum for mixtures and the weighted count for particles. This is the miss
/// probability of the loss (7) of Narykov, Üney & Ralph, "Optimal Bernoulli point estimation with
/// applications" (paper 000).
#[cfg(feature = "bernoulli")]
#[wasm_bindgen(js_name = probabilityOutsideBall)]
pub fn probability_outside_ball(
    #[wasm_bindgen(unchecked_param_type = "ProbabilityOutsideBallOptions")] options: JsValue,
) -> JsResult<f64> {
    let o: ProbabilityOutsideBallOptions = read(options, "options")?;
    o.probability().or_throw_in("options")
}

/// Γ (11) for each σ of an isotropic Gaussian N(a*, σ² I_dim) — Fig. 3 of Narykov, Üney & Ralph,
/// "Optimal Bernoulli point estimation with applications" (paper 000) — from
/// the closed form q = P(χ²_dim > (radius/σ)²). Options `{ sigmas, radius, costs, dim = 1 }`.
#[cfg(feature = "bernoulli")]
#[wasm_bindgen(js_name = bernoulliThresholdCurve, unchecked_return_type = "number[]")]
pub fn bernoulli_threshold_curve(
    #[wasm_bindgen(unchecked_param_type = "BernoulliThresholdCurveOptions")] options: JsValue,
) -> JsResult<JsValue> {
    let o: ThresholdCurveOptions = read(options, "options")?;
    write(&o.curve().or_throw_in("options")?)
}

/// The MMUC estimate a* = argmin_a q(a) (eq. (12)) alone. Options `{ density, radius }`;
/// returns `{ center, missProbability, method }`.
#[cfg(feature = "bernoulli")]
#[wasm_bindgen(js_name = mmucEstimate, unchecked_return_type = "MmucEstimateResult")]
pub fn mmuc_estimate(
    #[wasm_bindgen(unchecked_param_type = "MmucEstimateOptions")] options: JsValue,
) -> JsResult<JsValue> {
    let o: MmucOptions = read(options, "options")?;
    write(&o.estimate().or_throw_rendered("options")?)
}

/// Theorem III.3 of Narykov, Üney & Ralph, "Optimal Bernoulli point estimation with applications"
/// applied to each component of a multi-Bernoulli. Options `{ components: [{ existence, density }],
/// radius, costs }`; returns `{ reported, estimates, components }`. Each component is decided
/// alone, from its existence, its density and the loss (7) of paper 000 (Narykov, Üney & Ralph);
/// `mbOptimalEstimate` instead decides far-apart Dirac components jointly, minimising a set
/// metric's E[d^p] (García-Fernández & Svensson, "Spooky effect in optimal OSPA estimation and how
/// GOSPA solves it", paper 003).
#[cfg(feature = "bernoulli")]
#[wasm_bindgen(
    js_name = multiBernoulliPointEstimate,
    unchecked_return_type = "MultiBernoulliPointEstimateResult"
)]
pub fn multi_bernoulli_point_estimate(
    #[wasm_bindgen(unchecked_param_type = "MultiBernoulliPointEstimateOptions")] options: JsValue,
) -> JsResult<JsValue> {
    let o: MultiBernoulliPointOptions = read(options, "options")?;
    write(&o.estimate().or_throw_rendered("options")?)
}

/// The expected losses against p for Fig. 2: ρ_∅ (14), ρ_{a*} (13), and the loss of the rule
/// "report when p > threshold" (default: the optimal rule), from Narykov, Üney & Ralph, "Optimal
/// Bernoulli point estimation with applications" (paper 000). Options `{ existences,
/// missProbability, costs, threshold? }`; returns `{ empty, singleton, rule, threshold }`.
#[cfg(feature = "bernoulli")]
#[wasm_bindgen(js_name = bernoulliLossCurve, unchecked_return_type = "BernoulliLossCurveResult")]
pub fn bernoulli_loss_curve(
    #[wasm_bindgen(unchecked_param_type = "BernoulliLossCurveOptions")] options: JsValue,
) -> JsResult<JsValue> {
    let o: LossCurveOptions = read(options, "options")?;
    write(&bernoulli::loss_curve(&o).or_throw_rendered("options")?)
}
