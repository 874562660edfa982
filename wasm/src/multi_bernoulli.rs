//! Multi-Bernoulli cardinality and optimal estimation (Section III of the spooky-effect
//! paper).

use js_sys::Uint8Array;
use serde::{Deserialize, Serialize};
use tsify::Tsify;
use wasm_bindgen::prelude::*;

use crate::boundary::{JsResult, OrThrow, read, write};
use crate::types::Numbers;
use fisst::cardinality::{leave_one_out_cardinalities, multi_bernoulli_cardinality};
use fisst::estimators::alternatives::{self, alternative_estimate};
use fisst::estimators::figures::{
    self, DecisionMapOptions, IdenticalComponentCountsOptions, decision_map,
    identical_component_counts,
};
use fisst::estimators::multi_bernoulli::{SetMetric, mean_error, optimal_estimate};

fn one() -> f64 {
    1.0
}

fn two() -> f64 {
    2.0
}

/// A set metric of Section III.
#[derive(Clone, Copy, Debug, Deserialize, Tsify)]
#[serde(rename_all = "lowercase")]
pub enum SetMetricName {
    /// GOSPA with the given `alpha`.
    Gospa,
    /// OSPA.
    Ospa,
    /// UOSPA (GOSPA with α = 1).
    Uospa,
}

impl SetMetricName {
    fn metric(self, alpha: f64) -> SetMetric {
        match self {
            SetMetricName::Gospa => SetMetric::Gospa { alpha },
            SetMetricName::Ospa => SetMetric::Ospa,
            SetMetricName::Uospa => SetMetric::Uospa,
        }
    }
}

/// Options of `mbOptimalEstimate`.
#[derive(Deserialize, Tsify)]
pub struct MbOptimalEstimateOptions {
    /// Existence probability r_i in [0, 1] of each far-apart component.
    pub existence: Numbers,
    /// The metric whose mean error is minimised.
    pub metric: SetMetricName,
    /// Cut-off c > 0 (default 1).
    #[serde(default = "one")]
    pub c: f64,
    /// Order p ≥ 1 (default 2). The error minimised is E[d^p], the mean square error for
    /// p = 2.
    #[serde(default = "two")]
    pub p: f64,
    /// GOSPA's α in (0, 2] (default 2; ignored by OSPA and UOSPA).
    #[serde(default = "two")]
    pub alpha: f64,
}

/// Result of `mbOptimalEstimate`.
#[derive(Serialize, Tsify)]
#[serde(rename_all = "camelCase")]
pub struct MbOptimalEstimateResult {
    /// `report[i]`: whether component i is in the optimal estimate.
    pub report: Vec<bool>,
    /// Its mean error E[d^p] (the mean square error for p = 2).
    pub mean_square_error: f64,
}

/// Options of `mbMeanSquareError`.
#[derive(Deserialize, Tsify)]
pub struct MbMeanSquareErrorOptions {
    /// Existence probability r_i in [0, 1] of each far-apart component.
    pub existence: Numbers,
    /// The estimate: `report[i]` says whether component i is reported (one per component).
    pub report: Vec<bool>,
    /// The metric.
    pub metric: SetMetricName,
    /// Cut-off c > 0 (default 1).
    #[serde(default = "one")]
    pub c: f64,
    /// Order p ≥ 1 (default 2).
    #[serde(default = "two")]
    pub p: f64,
    /// GOSPA's α in (0, 2] (default 2).
    #[serde(default = "two")]
    pub alpha: f64,
}

/// A classical multi-object estimator of Fig. 2.
#[derive(Clone, Copy, Debug, Deserialize, Tsify)]
#[serde(rename_all = "kebab-case")]
pub enum AlternativeMethod {
    /// Marginal multi-target.
    Mam,
    /// Joint multi-target.
    Jom,
    /// Maximise the cardinality pmf, then report the most probable components.
    MapCardinality,
}

impl From<AlternativeMethod> for alternatives::AlternativeMethod {
    fn from(m: AlternativeMethod) -> Self {
        match m {
            AlternativeMethod::Mam => Self::Mam,
            AlternativeMethod::Jom => Self::Jom,
            AlternativeMethod::MapCardinality => Self::MapCardinality,
        }
    }
}

/// Options of `mbAlternativeEstimate`.
#[derive(Deserialize, Tsify)]
#[serde(rename_all = "camelCase")]
pub struct MbAlternativeEstimateOptions {
    /// Existence probability r_i in [0, 1] of each component.
    pub existence: Numbers,
    /// The estimator.
    pub method: AlternativeMethod,
    /// `lnPeak[i]` = −½ ln det(2π P_i) of component i's Gaussian (default 0 for all: equal
    /// covariances); one per component.
    #[tsify(optional)]
    pub ln_peak: Option<Numbers>,
    /// ln of JoM's constant (default 0, i.e. c = (2πε)^(d/2) for P = εI).
    #[serde(default)]
    pub ln_c: f64,
}

/// Result of `mbAlternativeEstimate`.
#[derive(Serialize, Tsify)]
pub struct MbAlternativeEstimateResult {
    /// `report[i]`: whether component i is reported.
    pub report: Vec<bool>,
}

/// An estimator of the decision maps.
#[derive(Clone, Copy, Debug, Deserialize, Tsify)]
#[serde(rename_all = "kebab-case")]
pub enum DecisionEstimator {
    /// Optimal GOSPA estimate.
    Gospa,
    /// Optimal OSPA estimate.
    Ospa,
    /// Optimal UOSPA estimate.
    Uospa,
    /// Marginal multi-target.
    Mam,
    /// Joint multi-target.
    Jom,
    /// MAP cardinality, then the most probable components.
    MapCardinality,
}

impl From<DecisionEstimator> for figures::DecisionEstimator {
    fn from(e: DecisionEstimator) -> Self {
        match e {
            DecisionEstimator::Gospa => Self::Gospa,
            DecisionEstimator::Ospa => Self::Ospa,
            DecisionEstimator::Uospa => Self::Uospa,
            DecisionEstimator::Mam => Self::Mam,
            DecisionEstimator::Jom => Self::Jom,
            DecisionEstimator::MapCardinality => Self::MapCardinality,
        }
    }
}

fn hundred() -> usize {
    100
}

/// Options of `mbDecisionMap`.
#[derive(Deserialize, Tsify)]
pub struct MbDecisionMapOptions {
    /// The estimator whose decisions are mapped.
    pub estimator: DecisionEstimator,
    /// Cells per axis, an integer in [1, 2000] (default 100).
    #[serde(default = "hundred")]
    pub resolution: usize,
    /// Cut-off c > 0 (default 1).
    #[serde(default = "one")]
    pub c: f64,
    /// Order p ≥ 1 (default 2).
    #[serde(default = "two")]
    pub p: f64,
    /// GOSPA's α in (0, 2] (default 2).
    #[serde(default = "two")]
    pub alpha: f64,
}

/// Result of `mbDecisionMap`.
#[derive(Serialize, Tsify)]
pub struct MbDecisionMapResult {
    /// Cells per axis.
    pub resolution: usize,
    /// `decisions[row * resolution + col]` = u1 + 2·u2 at r1 = (col + ½)/resolution,
    /// r2 = (row + ½)/resolution.
    #[serde(with = "serde_wasm_bindgen::preserve")]
    #[tsify(type = "Uint8Array")]
    pub decisions: Uint8Array,
}

/// Options of `mbIdenticalComponentCounts`.
#[derive(Deserialize, Tsify)]
#[serde(rename_all = "camelCase")]
pub struct MbIdenticalComponentCountsOptions {
    /// The common existence probability r in [0, 1].
    pub existence: f64,
    /// n runs over 1 … maxComponents, an integer in [1, 1000].
    pub max_components: usize,
}

/// Result of `mbIdenticalComponentCounts`: for each n, the number of targets each rule
/// reports.
#[derive(Serialize, Tsify)]
#[serde(rename_all = "camelCase")]
pub struct MbIdenticalComponentCountsResult {
    /// n = 1 … maxComponents.
    pub n: Vec<usize>,
    /// Optimal GOSPA estimate (α = 2).
    pub gospa: Vec<usize>,
    /// Optimal OSPA estimate.
    pub ospa: Vec<usize>,
    /// Optimal UOSPA estimate.
    pub uospa: Vec<usize>,
    /// MAP cardinality rule.
    pub map_cardinality: Vec<usize>,
}

/// The cardinality pmf of a multi-Bernoulli (Poisson-binomial): `pmf[n] = P(N = n)`,
/// n = 0 … existence.length. Exact, nonnegative, sums to 1.
#[wasm_bindgen(js_name = multiBernoulliCardinality, unchecked_return_type = "number[]")]
pub fn multi_bernoulli_cardinality_js(
    #[wasm_bindgen(unchecked_param_type = "Numbers")] existence: JsValue,
) -> JsResult<JsValue> {
    let r = read::<Numbers>(existence, "existence")?.0;
    write(&multi_bernoulli_cardinality(&r).or_throw()?)
}

/// The leave-one-out cardinality pmfs ρ₋ᵢ: element i is the pmf without component i.
#[wasm_bindgen(js_name = multiBernoulliLeaveOneOut, unchecked_return_type = "number[][]")]
pub fn multi_bernoulli_leave_one_out(
    #[wasm_bindgen(unchecked_param_type = "Numbers")] existence: JsValue,
) -> JsResult<JsValue> {
    let r = read::<Numbers>(existence, "existence")?.0;
    write(&leave_one_out_cardinalities(&r).or_throw()?)
}

/// The estimate of a multi-Bernoulli with far-apart Dirac components that minimises the mean
/// error E[d^p] (the mean square error for p = 2) under GOSPA, OSPA or UOSPA — exact for any
/// number of components. Options `{ existence, metric, c = 1, p = 2, alpha = 2 }`; returns
/// `{ report, meanSquareError }`.
#[wasm_bindgen(js_name = mbOptimalEstimate, unchecked_return_type = "MbOptimalEstimateResult")]
pub fn mb_optimal_estimate(
    #[wasm_bindgen(unchecked_param_type = "MbOptimalEstimateOptions")] options: JsValue,
) -> JsResult<JsValue> {
    let o: MbOptimalEstimateOptions = read(options, "options")?;
    let e = optimal_estimate(&o.existence.0, o.metric.metric(o.alpha), o.c, o.p)
        .or_throw_in("options")?;
    write(&MbOptimalEstimateResult {
        report: e.report,
        mean_square_error: e.mean_error,
    })
}

/// The mean error E[d^p] (mean square for p = 2) of the estimate `report` (a boolean per
/// component): Lemma 4 of the spooky-effect paper. Options
/// `{ existence, report, metric, c = 1, p = 2, alpha = 2 }`.
#[wasm_bindgen(js_name = mbMeanSquareError)]
pub fn mb_mean_square_error(
    #[wasm_bindgen(unchecked_param_type = "MbMeanSquareErrorOptions")] options: JsValue,
) -> JsResult<f64> {
    let o: MbMeanSquareErrorOptions = read(options, "options")?;
    mean_error(
        &o.existence.0,
        &o.report,
        o.metric.metric(o.alpha),
        o.c,
        o.p,
    )
    .or_throw_in("options")
}

/// The classical estimators of Fig. 2: `method` is `'mam'` (marginal multi-target),
/// `'jom'` (joint multi-target) or `'map-cardinality'` (maximise the cardinality pmf, then
/// report the most probable components). `lnPeak[i]` is `−½ ln det(2π P_i)` for component i's
/// Gaussian (default 0: equal covariances), `lnC` the log of JoM's constant (default 0, i.e.
/// c = (2πε)^(d/2) for P = εI). Returns `{ report }`.
#[wasm_bindgen(js_name = mbAlternativeEstimate, unchecked_return_type = "MbAlternativeEstimateResult")]
pub fn mb_alternative_estimate(
    #[wasm_bindgen(unchecked_param_type = "MbAlternativeEstimateOptions")] options: JsValue,
) -> JsResult<JsValue> {
    let o: MbAlternativeEstimateOptions = read(options, "options")?;
    let existence = o.existence.0;
    let ln_peak = o
        .ln_peak
        .map_or_else(|| vec![0.0; existence.len()], |n| n.0);
    let report = alternative_estimate(&existence, o.method.into(), &ln_peak, o.ln_c)
        .or_throw_in("options")?;
    write(&MbAlternativeEstimateResult { report })
}

/// Fig. 1 / Fig. 2 decision maps for two far-apart components: for every cell of a
/// `resolution × resolution` grid of (r1, r2) (cell centres, r = (i + ½)/resolution), the
/// optimal decision coded as `u1 + 2·u2`. Row-major with r2 as the outer (row) index and r1
/// the inner. `estimator` is `'gospa'`, `'ospa'`, `'uospa'`, `'mam'`, `'jom'` or
/// `'map-cardinality'`. Returns `{ resolution, decisions: Uint8Array }`.
#[wasm_bindgen(js_name = mbDecisionMap, unchecked_return_type = "MbDecisionMapResult")]
pub fn mb_decision_map(
    #[wasm_bindgen(unchecked_param_type = "MbDecisionMapOptions")] options: JsValue,
) -> JsResult<JsValue> {
    let o: MbDecisionMapOptions = read(options, "options")?;
    let map = decision_map(&DecisionMapOptions {
        estimator: o.estimator.into(),
        resolution: o.resolution,
        c: o.c,
        p: o.p,
        alpha: o.alpha,
    })
    .or_throw_rendered("options")?;
    write(&MbDecisionMapResult {
        resolution: map.resolution,
        decisions: Uint8Array::from(map.decisions.as_slice()),
    })
}

/// Fig. 3: the optimal number of reported targets for n = 1 … maxComponents identical
/// far-apart components of existence `existence`, under GOSPA, OSPA, UOSPA and the
/// MAP-cardinality rule. Returns `{ n, gospa, ospa, uospa, mapCardinality }` (arrays).
#[wasm_bindgen(js_name = mbIdenticalComponentCounts, unchecked_return_type = "MbIdenticalComponentCountsResult")]
pub fn mb_identical_component_counts(
    #[wasm_bindgen(unchecked_param_type = "MbIdenticalComponentCountsOptions")] options: JsValue,
) -> JsResult<JsValue> {
    let o: MbIdenticalComponentCountsOptions = read(options, "options")?;
    let k = identical_component_counts(&IdenticalComponentCountsOptions {
        existence: o.existence,
        max_components: o.max_components,
    })
    .or_throw_rendered("options")?;
    write(&MbIdenticalComponentCountsResult {
        n: k.n,
        gospa: k.gospa,
        ospa: k.ospa,
        uospa: k.uospa,
        map_cardinality: k.map_cardinality,
    })
}
