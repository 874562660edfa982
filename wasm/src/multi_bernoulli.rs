//! Multi-Bernoulli cardinality and optimal estimation (Section III of the spooky-effect
//! paper): the core's `fisst::estimators` options and results, under the contract's names.

use wasm_bindgen::prelude::*;

use crate::boundary::{JsResult, OrThrow, read, write};
use crate::types::Numbers;
use fisst::cardinality::{leave_one_out_cardinalities, multi_bernoulli_cardinality};
use fisst::estimators::figures::{
    DecisionMapOptions, IdenticalComponentCountsOptions, decision_map, identical_component_counts,
};
use fisst::estimators::{
    MbAlternativeEstimateOptions, MbMeanSquareErrorOptions, MbOptimalEstimateOptions,
};

/// The cardinality pmf of a multi-Bernoulli (Poisson-binomial): `pmf[n] = P(N = n)`,
/// n = 0 … existence.length. Exact, nonnegative, sums to 1. At most 20,000 existence
/// probabilities (the exact pmf costs n²/2 operations); more throw a `RangeError` naming
/// `existence`.
#[wasm_bindgen(js_name = multiBernoulliCardinality, unchecked_return_type = "number[]")]
pub fn multi_bernoulli_cardinality_js(
    #[wasm_bindgen(unchecked_param_type = "Numbers")] existence: JsValue,
) -> JsResult<JsValue> {
    let r = read::<Numbers>(existence, "existence")?.0;
    write(&multi_bernoulli_cardinality(&r).or_throw()?)
}

/// The leave-one-out cardinality pmfs ρ₋ᵢ: element i is the pmf without component i. At
/// most 1,000 existence probabilities (the result holds n² numbers); more throw a
/// `RangeError` naming `existence`.
#[wasm_bindgen(js_name = multiBernoulliLeaveOneOut, unchecked_return_type = "number[][]")]
pub fn multi_bernoulli_leave_one_out(
    #[wasm_bindgen(unchecked_param_type = "Numbers")] existence: JsValue,
) -> JsResult<JsValue> {
    let r = read::<Numbers>(existence, "existence")?.0;
    write(&leave_one_out_cardinalities(&r).or_throw()?)
}

/// The estimate of a multi-Bernoulli with far-apart Dirac components that minimises the mean error
/// E[d^p] (the mean square error for p = 2) under GOSPA, OSPA or UOSPA — exact for any number of
/// components. Options `{ existence, metric, c = 1, p = 2, alpha = 2 }`; returns `{ report,
/// meanSquareError }`. The components are decided jointly, from their existence probabilities alone
/// (García-Fernández & Svensson, "Spooky effect in optimal OSPA estimation and how GOSPA solves
/// it", paper 003); `multiBernoulliPointEstimate` instead decides each component alone from its
/// density and the loss (7) of Narykov, Üney & Ralph, "Optimal Bernoulli point estimation with
/// applications" (paper 000).
#[wasm_bindgen(js_name = mbOptimalEstimate, unchecked_return_type = "MbOptimalEstimateResult")]
pub fn mb_optimal_estimate(
    #[wasm_bindgen(unchecked_param_type = "MbOptimalEstimateOptions")] options: JsValue,
) -> JsResult<JsValue> {
    let o: MbOptimalEstimateOptions = read(options, "options")?;
    write(&o.estimate().or_throw_in("options")?)
}

/// The mean error E[d^p] (mean square for p = 2) of the estimate `report` (a boolean per
/// component): Lemma 4 of García-Fernández & Svensson, "Spooky effect in optimal OSPA estimation
/// and how GOSPA solves it" (paper 003). Options `{ existence, report, metric, c = 1, p = 2, alpha
/// = 2 }`.
#[wasm_bindgen(js_name = mbMeanSquareError)]
pub fn mb_mean_square_error(
    #[wasm_bindgen(unchecked_param_type = "MbMeanSquareErrorOptions")] options: JsValue,
) -> JsResult<f64> {
    let o: MbMeanSquareErrorOptions = read(options, "options")?;
    o.mean_error().or_throw_in("options")
}

/// The classical estimators of Fig. 2 of García-Fernández & Svensson, "Spooky effect in optimal
/// OSPA estimation and how GOSPA solves it" (paper 003): `method` is `'mam'` (marginal
/// multi-target), `'jom'` (joint multi-target) or `'map-cardinality'` (maximise the cardinality
/// pmf, then report the most probable components). `lnPeak[i]` is `−½ ln det(2π P_i)` for component
/// i's Gaussian (default 0: equal covariances), `lnC` the log of JoM's constant (default 0, i.e. c
/// = (2πε)^(d/2) for P = εI). Returns `{ report }`.
#[wasm_bindgen(js_name = mbAlternativeEstimate, unchecked_return_type = "MbAlternativeEstimateResult")]
pub fn mb_alternative_estimate(
    #[wasm_bindgen(unchecked_param_type = "MbAlternativeEstimateOptions")] options: JsValue,
) -> JsResult<JsValue> {
    let o: MbAlternativeEstimateOptions = read(options, "options")?;
    write(&o.estimate().or_throw_in("options")?)
}

/// Fig. 1 / Fig. 2 decision maps of García-Fernández & Svensson, "Spooky effect in optimal OSPA
/// estimation and how GOSPA solves it" (paper 003), for two far-apart components: for every cell of
/// a `resolution × resolution` grid of (r1, r2) (cell centres, r = (i + ½)/resolution), the optimal
/// decision coded as `u1 + 2·u2`. Row-major with r2 as the outer (row) index and r1 the inner.
/// `estimator` is `'gospa'`, `'ospa'`, `'uospa'`, `'mam'`, `'jom'` or `'map-cardinality'`. Returns
/// `{ resolution, decisions: Uint8Array }`.
#[wasm_bindgen(js_name = mbDecisionMap, unchecked_return_type = "MbDecisionMapResult")]
pub fn mb_decision_map(
    #[wasm_bindgen(unchecked_param_type = "MbDecisionMapOptions")] options: JsValue,
) -> JsResult<JsValue> {
    let o: DecisionMapOptions = read(options, "options")?;
    write(&decision_map(&o).or_throw_rendered("options")?)
}

/// Fig. 3 of García-Fernández & Svensson, "Spooky effect in optimal OSPA estimation and how GOSPA
/// solves it" (paper 003): the optimal number of reported targets for n = 1 … maxComponents
/// identical far-apart components of existence `existence`, under GOSPA, OSPA, UOSPA and the
/// MAP-cardinality rule. Returns `{ n, gospa, ospa, uospa, mapCardinality }` (arrays).
#[wasm_bindgen(js_name = mbIdenticalComponentCounts, unchecked_return_type = "MbIdenticalComponentCountsResult")]
pub fn mb_identical_component_counts(
    #[wasm_bindgen(unchecked_param_type = "MbIdenticalComponentCountsOptions")] options: JsValue,
) -> JsResult<JsValue> {
    let o: IdenticalComponentCountsOptions = read(options, "options")?;
    write(&identical_component_counts(&o).or_throw_rendered("options")?)
}
