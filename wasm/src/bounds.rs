//! `jdeBoundNoClutter`, `gaussianFisherInformation`, `jdeSequentialBound`, `jdeBound`: the
//! error bounds for joint detection and estimation of paper 002 (Rezaeian & Vo).

use serde::{Deserialize, Serialize};
use tsify::Tsify;
use wasm_bindgen::prelude::*;

use crate::boundary::{JsResult, OrThrow, check_range, read, write};
use fisst::bounds;

/// Options of `jdeBoundNoClutter`: Corollary 3 in the Gaussian form (31) (constant P_o,
/// Gaussian prior and likelihood, no false alarms).
#[derive(Deserialize, Tsify)]
#[serde(rename_all = "camelCase")]
pub struct JdeBoundNoClutterOptions {
    /// r, the prior probability that the target exists, in [0, 1].
    pub existence: f64,
    /// P̄_o, the (constant) probability of observing the target, in [0, 1].
    pub detection_probability: f64,
    /// σ_f², the prior variance (> 0); also σ_e², the variance given Z = ∅.
    pub prior_variance: f64,
    /// σ_h², the mean posterior variance given an observation (> 0, ≤ `priorVariance`):
    /// J_1⁻¹ (see `gaussianFisherInformation`).
    pub posterior_variance: f64,
    /// e_0², the squared error of declaring a target that does not exist (≥ 0).
    pub false_alarm_error: f64,
    /// e_1², the squared error of missing a target that exists (≥ 0).
    pub miss_error: f64,
}

/// Result of `jdeBoundNoClutter`.
#[derive(Serialize, Tsify)]
#[serde(rename_all = "camelCase")]
pub struct JdeBoundNoClutterResult {
    /// The lower bound (31) on the mean-square error E e²(X, X̂(Z)).
    pub bound: f64,
    /// r* = e0² / (e0² + (1 − P̄o)(e1² − σf²)), the existence above which the bound's
    /// estimator declares a target on Z = ∅ (may exceed 1: never; `Infinity` when the
    /// denominator is ≤ 0).
    pub existence_threshold: f64,
    /// Whether the bound's estimator declares a target on Z = ∅ (r ≥ r*).
    pub declare_on_empty: bool,
    /// The HPE line r(σf² − P̄o(σf² − σh²)) + (1 − r)e0².
    pub hpe: f64,
    /// The LPE line r(e1² − P̄o(e1² − σh²)).
    pub lpe: f64,
    /// r_M* = 1 / (2 − P̄o): where an estimator that also uses MAP detection on Z = ∅ switches
    /// (Section IV-A).
    pub map_threshold: f64,
    /// The bound of that MAP-on-∅ estimator (HPE line for r ≥ r_M*, LPE below); ≥ `bound`.
    pub map_bound: f64,
}

/// Corollary 3 of paper 002 in the Gaussian form (31). Options `{ existence,
/// detectionProbability, priorVariance, posteriorVariance, falseAlarmError, missError }`;
/// returns `{ bound, existenceThreshold, declareOnEmpty, hpe, lpe, mapThreshold, mapBound }`.
#[wasm_bindgen(js_name = jdeBoundNoClutter, unchecked_return_type = "JdeBoundNoClutterResult")]
pub fn jde_bound_no_clutter(
    #[wasm_bindgen(unchecked_param_type = "JdeBoundNoClutterOptions")] options: JsValue,
) -> JsResult<JsValue> {
    let o: JdeBoundNoClutterOptions = read(options, "options")?;
    let b = bounds::gaussian_no_clutter(
        o.existence,
        o.detection_probability,
        o.prior_variance,
        o.posterior_variance,
        o.false_alarm_error,
        o.miss_error,
    )
    .or_throw_in("options")?;
    write(&JdeBoundNoClutterResult {
        bound: b.bound,
        existence_threshold: b.existence_threshold,
        declare_on_empty: b.declare_on_empty,
        hpe: b.hpe,
        lpe: b.lpe,
        map_threshold: b.map_threshold,
        map_bound: b.map_bound,
    })
}

/// Options of `gaussianFisherInformation`: z = a x + v, x ~ N(x0, σx²), v ~ N(0, σv²).
#[derive(Deserialize, Tsify)]
#[serde(rename_all = "camelCase")]
pub struct GaussianFisherInformationOptions {
    /// σ_x², the prior variance (> 0).
    pub prior_variance: f64,
    /// a, the gain (finite).
    pub gain: f64,
    /// σ_v², the measurement-noise variance (> 0).
    pub noise_variance: f64,
}

/// Result of `gaussianFisherInformation`.
#[derive(Serialize, Tsify)]
#[serde(rename_all = "camelCase")]
pub struct GaussianFisherInformationResult {
    /// J_1 = 1/σx² + a²/σv² (paper 002 Example 1 prints a²/(2σv²): an erratum).
    pub information: f64,
    /// 1/J_1 = σx²σv²/(σv² + a²σx²), the posterior variance.
    pub posterior_variance: f64,
}

/// The Fisher information J_1 of p(x, z) for z = a x + v and its inverse (paper 002,
/// Example 1 corrected). Options `{ priorVariance, gain, noiseVariance }`; returns
/// `{ information, posteriorVariance }`.
#[wasm_bindgen(
    js_name = gaussianFisherInformation,
    unchecked_return_type = "GaussianFisherInformationResult"
)]
pub fn gaussian_fisher_information(
    #[wasm_bindgen(unchecked_param_type = "GaussianFisherInformationOptions")] options: JsValue,
) -> JsResult<JsValue> {
    let o: GaussianFisherInformationOptions = read(options, "options")?;
    let j = bounds::gaussian_fisher_information(o.prior_variance, o.gain, o.noise_variance)
        .or_throw_in("options")?;
    write(&GaussianFisherInformationResult {
        information: j.information,
        posterior_variance: j.posterior_variance,
    })
}

/// The sequential bound of `jdeSequentialBound`.
#[derive(Deserialize, Tsify, Clone, Copy)]
#[serde(rename_all = "kebab-case")]
pub enum SequentialMethod {
    /// P_k(Enum) (37).
    Enumeration,
    /// P_k(IRF) (35).
    Irf,
}

/// Options of `jdeSequentialBound`.
#[derive(Deserialize, Tsify)]
#[serde(rename_all = "camelCase")]
pub struct JdeSequentialBoundOptions {
    /// `'enumeration'` (37) or `'irf'` (35).
    pub method: SequentialMethod,
    /// J_0 > 0, the information of the prior (of f_d').
    pub prior_information: f64,
    /// J_1 ≥ J_0, the information after one observation.
    pub detected_information: f64,
    /// P̄_o, the probability of an observation at each step, in [0, 1].
    pub detection_probability: f64,
    /// k_max, the number of steps (integer in [1, 10000]).
    pub steps: usize,
}

/// Result of `jdeSequentialBound`.
#[derive(Serialize, Tsify)]
#[serde(rename_all = "camelCase")]
pub struct JdeSequentialBoundResult {
    /// `bound[k − 1]` = P_k for k = 1 … steps.
    pub bound: Vec<f64>,
}

/// The IRF (35) and Enumeration (37) bounds of paper 002 for k = 1 … steps observations.
/// Options `{ method, priorInformation, detectedInformation, detectionProbability, steps }`;
/// returns `{ bound }` (Enum ≥ IRF; equal at P̄o ∈ {0, 1}).
#[wasm_bindgen(js_name = jdeSequentialBound, unchecked_return_type = "JdeSequentialBoundResult")]
pub fn jde_sequential_bound(
    #[wasm_bindgen(unchecked_param_type = "JdeSequentialBoundOptions")] options: JsValue,
) -> JsResult<JsValue> {
    let o: JdeSequentialBoundOptions = read(options, "options")?;
    let steps = check_range("options.steps", o.steps, 1, bounds::MAX_STEPS)?;
    let method = match o.method {
        SequentialMethod::Enumeration => bounds::Sequential::Enumeration,
        SequentialMethod::Irf => bounds::Sequential::Irf,
    };
    let bound = bounds::sequential_bound(
        method,
        o.prior_information,
        o.detected_information,
        o.detection_probability,
        steps,
    )
    .or_throw_in("options")?;
    write(&JdeSequentialBoundResult { bound })
}
