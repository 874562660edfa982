//! Optimal Bernoulli point estimation (paper `000_…`): the estimate of Theorem III.3, q(a),
//! the MMUC estimate and the threshold curves of Fig. 3.

use wasm_bindgen::prelude::*;

use crate::convert::{
    JsResult, Options, OrThrow, array, core_error, number, number_array, numbers, object, points,
    range_error, type_error,
};
use fisst::bernoulli::{
    self, ApplicationLoss, BernoulliEstimate, Costs, Direction, MmucMethod, ParticleSet,
    SpatialDensity,
};
use fisst::gaussian::{Gaussian, GaussianMixture};
use js_sys::Array;

#[wasm_bindgen(typescript_custom_section)]
const TS_BERNOULLI: &'static str = r#"
/**
 * A covariance: a nested row-major array `[[…], …]` (n rows of n), a flat row-major array of
 * n·n numbers, or, in 1D only, the variance as a bare number.
 */
export type BernoulliCovariance = number[][] | number[] | Float64Array | number;

/**
 * The spatial density of a Bernoulli: one Gaussian (any dimension, full covariance), a
 * Gaussian mixture (weights ≥ 0 with a positive sum; normalised), or weighted particles
 * (weights ≥ 0 with a positive sum, default equal; normalised).
 */
export type BernoulliDensity =
  | { mean: number[] | Float64Array; cov: BernoulliCovariance }
  | { mixture: { weight: number; mean: number[] | Float64Array; cov: BernoulliCovariance }[] }
  | { particles: (number[] | Float64Array)[]; weights?: number[] | Float64Array };

/**
 * Costs of the loss (7): the MPE preset `'mpe'` (0, 1, 1, 0, 1), the MMOL preset
 * `{ mmol: { asset: c_A, countermeasure: c_M } }` (c00 = 0, c01 = c_A, c10 = c_M,
 * c11 = c_M, c = c_A), or the five costs (finite, ≥ 0).
 */
export type BernoulliCosts =
  | 'mpe'
  | { mmol: { asset: number; countermeasure: number } }
  | { c00: number; c01: number; c10: number; c11: number; c: number };

export interface BernoulliEstimateOptions {
  /** p, in [0, 1]. */
  existence: number;
  density: BernoulliDensity;
  /** r0 > 0. */
  radius: number;
  costs: BernoulliCosts;
}

/**
 * Theorem III.3. `declare` is the optimal decision (ties p = Γ report nothing); `estimate` is
 * `mmuc` when declared, else `null`; `threshold` is Γ of eq. (11) (p > Γ reports for every
 * cost matrix with c11 + c·q < c01 + c10 − c00, which includes MPE and MMOL; ±Infinity when
 * the decision does not depend on p); `missProbability` is q(a*); the expected losses are
 * ρ_∅ (14) and ρ_{a*} (13).
 */
export interface BernoulliEstimateResult {
  declare: boolean;
  estimate: number[] | null;
  mmuc: number[];
  threshold: number;
  missProbability: number;
  expectedLossEmpty: number;
  expectedLossSingleton: number;
}

export interface ProbabilityOutsideBallOptions {
  density: BernoulliDensity;
  center: number[] | Float64Array;
  radius: number;
}

export interface BernoulliThresholdCurveOptions {
  /** Standard deviations σ > 0 of the isotropic Gaussian N(a*, σ² I). */
  sigmas: number[] | Float64Array;
  radius: number;
  costs: BernoulliCosts;
  /** Dimension, an integer in [1, 10000] (default 1, as in Fig. 3). */
  dim?: number;
}

export interface MmucEstimateOptions { density: BernoulliDensity; radius: number; }

export interface MmucEstimateResult {
  center: number[];
  missProbability: number;
  method: 'gaussian-mean' | 'shared-mean' | 'mixture-search' | 'particles-exact' | 'particles-heuristic';
}

export interface MultiBernoulliPointEstimateOptions {
  components: { existence: number; density: BernoulliDensity }[];
  radius: number;
  costs: BernoulliCosts;
}

export interface MultiBernoulliPointEstimateResult {
  /** Indices of the declared components, increasing. */
  reported: number[];
  /** Their estimates, in the same order. */
  estimates: number[][];
  components: BernoulliEstimateResult[];
}

export interface BernoulliLossCurveOptions {
  /** The existence probabilities p at which to evaluate. */
  existences: number[] | Float64Array;
  /** q(a*) in [0, 1]. */
  missProbability: number;
  costs: BernoulliCosts;
  /** Report when p > threshold; default: the optimal rule of Theorem III.3. */
  threshold?: number;
}

/** ρ_∅(p) (14), ρ_{a*}(p) (13), and the expected loss of the rule, for each p. */
export interface BernoulliLossCurveResult {
  empty: number[];
  singleton: number[];
  rule: number[];
  threshold: number;
}
"#;

/// Maps a core error whose field starts with `density` to the JS path `field`.
fn renamed(e: fisst::Error, field: &str) -> JsValue {
    if field == "density" {
        return core_error(e);
    }
    range_error(e.to_string().replacen("density", field, 1))
}

/// A required number at `path.key`.
fn required_number(opts: &Options, path: &str, key: &str) -> JsResult<f64> {
    let full = format!("{path}.{key}");
    match opts.get(key)? {
        Some(v) => number(&v, &full),
        None => Err(type_error(format!("{full} is required"))),
    }
}

/// A required value at `path.key`.
fn required(opts: &Options, path: &str, key: &str) -> JsResult<JsValue> {
    opts.get(key)?
        .ok_or_else(|| type_error(format!("{path}.{key} is required")))
}

/// A covariance for a mean of length n, as a row-major n·n vector.
fn covariance(v: &JsValue, n: usize, field: &str) -> JsResult<Vec<f64>> {
    if v.as_f64().is_some() {
        let x = number(v, field)?;
        if n != 1 {
            return Err(type_error(format!(
                "{field} must be a nested {n}×{n} array (a bare number is a 1D variance)"
            )));
        }
        return Ok(vec![x]);
    }
    if Array::is_array(v) {
        let rows: Array = v.clone().unchecked_into();
        if Array::is_array(&rows.get(0)) {
            if rows.length() as usize != n {
                return Err(core_error(fisst::Error::dimension(
                    field,
                    n,
                    rows.length() as usize,
                )));
            }
            let mut flat = Vec::with_capacity(n * n);
            for (i, row) in rows.iter().enumerate() {
                let name = format!("{field}[{i}]");
                let r = numbers(&row, &name)?;
                if r.len() != n {
                    return Err(core_error(fisst::Error::dimension(name, n, r.len())));
                }
                flat.extend(r);
            }
            return Ok(flat);
        }
    }
    numbers(v, field)
}

/// A Gaussian `{ mean, cov }` named `path` (`path.mean`, `path.cov`).
fn gaussian(opts: &Options, path: &str) -> JsResult<Gaussian> {
    let mean = numbers(&required(opts, path, "mean")?, &format!("{path}.mean"))?;
    let cov = covariance(
        &required(opts, path, "cov")?,
        mean.len(),
        &format!("{path}.cov"),
    )?;
    Gaussian::from_slices(&mean, &cov, path).or_throw()
}

/// A [`SpatialDensity`] from its JS form, errors named under `field` (`density` or
/// `components[i].density`).
pub(crate) fn density(v: &JsValue, field: &str) -> JsResult<SpatialDensity> {
    let opts = Options::new(v, field, true)?;
    if let Some(mixture) = opts.get("mixture")? {
        let name = format!("{field}.mixture");
        let items = array(&mixture, &name, "an array of { weight, mean, cov }")?;
        let mut comps = Vec::with_capacity(items.length() as usize);
        for (j, item) in items.iter().enumerate() {
            let path = format!("{name}[{j}]");
            let o = Options::new(&item, &path, true)?;
            let w = required_number(&o, &path, "weight")?;
            comps.push((w, gaussian(&o, &path)?));
        }
        let m = GaussianMixture::new(comps, &name).or_throw()?;
        return SpatialDensity::mixture(&m).map_err(|e| renamed(e, field));
    }
    if let Some(pts) = opts.get("particles")? {
        let pts = points(&pts, &format!("{field}.particles"))?;
        let weights = match opts.get("weights")? {
            Some(w) => Some(numbers(&w, &format!("{field}.weights"))?),
            None => None,
        };
        let p = ParticleSet::new(&pts, weights.as_deref()).map_err(|e| renamed(e, field))?;
        return Ok(SpatialDensity::particles(p));
    }
    if opts.get("mean")?.is_some() || opts.get("cov")?.is_some() {
        let g = gaussian(&opts, field)?;
        return SpatialDensity::gaussian(g).map_err(|e| renamed(e, field));
    }
    Err(type_error(format!(
        "{field} must be {{ mean, cov }}, {{ mixture: [...] }} or {{ particles: [...], weights }}"
    )))
}

/// [`Costs`] from `'mpe'`, `{ mmol: { asset, countermeasure } }` or the five costs.
pub(crate) fn costs(v: &JsValue) -> JsResult<Costs> {
    const EXPECTED: &str =
        "'mpe', { mmol: { asset, countermeasure } } or { c00, c01, c10, c11, c }";
    if let Some(s) = v.as_string() {
        return match s.as_str() {
            "mpe" => Ok(Costs::mpe()),
            other => Err(range_error(format!(
                "costs must be {EXPECTED}, got {other:?}"
            ))),
        };
    }
    let opts = Options::new(v, "costs", true)?;
    if let Some(m) = opts.get("mmol")? {
        let o = Options::new(&m, "costs.mmol", true)?;
        let asset = required_number(&o, "costs.mmol", "asset")?;
        let countermeasure = required_number(&o, "costs.mmol", "countermeasure")?;
        return Costs::mmol(asset, countermeasure).or_throw();
    }
    let mut c = [0.0; 5];
    for (x, key) in c.iter_mut().zip(["c00", "c01", "c10", "c11", "c"]) {
        *x = required_number(&opts, "costs", key)?;
    }
    Costs::new(c[0], c[1], c[2], c[3], c[4]).or_throw()
}

fn required_costs(opts: &Options) -> JsResult<Costs> {
    match opts.get("costs")? {
        Some(v) => costs(&v),
        None => Err(type_error("costs is required")),
    }
}

fn estimate_object(e: &BernoulliEstimate) -> JsValue {
    object(&[
        ("declare", e.declare.into()),
        (
            "estimate",
            e.estimate.as_deref().map_or(JsValue::NULL, number_array),
        ),
        ("mmuc", number_array(&e.mmuc.center)),
        ("threshold", e.threshold.gamma.into()),
        ("missProbability", e.mmuc.miss_probability.into()),
        ("expectedLossEmpty", e.expected_loss_empty.into()),
        ("expectedLossSingleton", e.expected_loss_singleton.into()),
    ])
}

/// The Bayes-optimal point estimate of a Bernoulli (Theorem III.3 of the optimal Bernoulli
/// point estimation paper): report the MMUC point a* (12) when the existence probability
/// exceeds Γ (11), else nothing. Options `{ existence, density, radius, costs }`; returns
/// `{ declare, estimate, mmuc, threshold, missProbability, expectedLossEmpty,
/// expectedLossSingleton }`.
#[wasm_bindgen(js_name = bernoulliEstimate, unchecked_return_type = "BernoulliEstimateResult")]
pub fn bernoulli_estimate(
    #[wasm_bindgen(unchecked_param_type = "BernoulliEstimateOptions")] options: JsValue,
) -> JsResult<JsValue> {
    let opts = Options::new(&options, "options", true)?;
    let existence = opts.number("existence")?;
    let s = density(&opts.require("density")?, "density")?;
    let radius = opts.number("radius")?;
    let loss = ApplicationLoss::new(required_costs(&opts)?, radius).or_throw()?;
    let e = bernoulli::estimate(existence, &s, &loss).or_throw()?;
    Ok(estimate_object(&e))
}

/// q(center) = P(‖x − center‖ > radius) for x drawn from `density`: exact in 1D, to 1e-10
/// (absolute) by error-controlled quadrature or characteristic-function inversion in higher
/// dimensions, the weighted sum for mixtures and the weighted count for particles.
#[wasm_bindgen(js_name = probabilityOutsideBall)]
pub fn probability_outside_ball(
    #[wasm_bindgen(unchecked_param_type = "ProbabilityOutsideBallOptions")] options: JsValue,
) -> JsResult<f64> {
    let opts = Options::new(&options, "options", true)?;
    let s = density(&opts.require("density")?, "density")?;
    let center = numbers(&opts.require("center")?, "center")?;
    let radius = opts.number("radius")?;
    s.prob_outside_ball(&center, radius).or_throw()
}

/// Γ (11) for each σ of an isotropic Gaussian N(a*, σ² I_dim) — Fig. 3 of the paper — from
/// the closed form q = P(χ²_dim > (radius/σ)²). Options `{ sigmas, radius, costs, dim = 1 }`.
#[wasm_bindgen(js_name = bernoulliThresholdCurve, unchecked_return_type = "number[]")]
pub fn bernoulli_threshold_curve(
    #[wasm_bindgen(unchecked_param_type = "BernoulliThresholdCurveOptions")] options: JsValue,
) -> JsResult<JsValue> {
    let opts = Options::new(&options, "options", true)?;
    let sigmas = numbers(&opts.require("sigmas")?, "sigmas")?;
    let radius = opts.number("radius")?;
    let costs = required_costs(&opts)?;
    let dim = opts.integer_or("dim", 1, 1, 10_000)?;
    let curve = bernoulli::isotropic_threshold_curve(&sigmas, radius, &costs, dim).or_throw()?;
    Ok(number_array(&curve))
}

/// The MMUC estimate a* = argmin_a q(a) (eq. (12)) alone. Options `{ density, radius }`;
/// returns `{ center, missProbability, method }`.
#[wasm_bindgen(js_name = mmucEstimate, unchecked_return_type = "MmucEstimateResult")]
pub fn mmuc_estimate(
    #[wasm_bindgen(unchecked_param_type = "MmucEstimateOptions")] options: JsValue,
) -> JsResult<JsValue> {
    let opts = Options::new(&options, "options", true)?;
    let s = density(&opts.require("density")?, "density")?;
    let radius = opts.number("radius")?;
    let m = s.mmuc(radius).or_throw()?;
    let method = match m.method {
        MmucMethod::GaussianMean => "gaussian-mean",
        MmucMethod::SharedMean => "shared-mean",
        MmucMethod::MixtureSearch => "mixture-search",
        MmucMethod::ParticlesExact => "particles-exact",
        MmucMethod::ParticlesHeuristic => "particles-heuristic",
    };
    Ok(object(&[
        ("center", number_array(&m.center)),
        ("missProbability", m.miss_probability.into()),
        ("method", method.into()),
    ]))
}

/// Theorem III.3 applied to each component of a multi-Bernoulli. Options
/// `{ components: [{ existence, density }], radius, costs }`; returns
/// `{ reported, estimates, components }`.
#[wasm_bindgen(
    js_name = multiBernoulliPointEstimate,
    unchecked_return_type = "MultiBernoulliPointEstimateResult"
)]
pub fn multi_bernoulli_point_estimate(
    #[wasm_bindgen(unchecked_param_type = "MultiBernoulliPointEstimateOptions")] options: JsValue,
) -> JsResult<JsValue> {
    let opts = Options::new(&options, "options", true)?;
    let items = array(
        &opts.require("components")?,
        "components",
        "an array of { existence, density }",
    )?;
    let mut comps = Vec::with_capacity(items.length() as usize);
    for (i, item) in items.iter().enumerate() {
        let path = format!("components[{i}]");
        let o = Options::new(&item, &path, true)?;
        let p = required_number(&o, &path, "existence")?;
        let s = density(&required(&o, &path, "density")?, &format!("{path}.density"))?;
        comps.push((p, s));
    }
    let radius = opts.number("radius")?;
    let loss = ApplicationLoss::new(required_costs(&opts)?, radius).or_throw()?;
    let m = bernoulli::multi_bernoulli_estimate(&comps, &loss).or_throw()?;
    let reported: Vec<f64> = m.reported.iter().map(|&i| i as f64).collect();
    let estimates: Array = m.points().into_iter().map(number_array).collect();
    let components: Array = m.components.iter().map(estimate_object).collect();
    Ok(object(&[
        ("reported", number_array(&reported)),
        ("estimates", estimates.into()),
        ("components", components.into()),
    ]))
}

/// The expected losses against p for Fig. 2: ρ_∅ (14), ρ_{a*} (13), and the loss of the rule
/// "report when p > threshold" (default: the optimal rule). Options
/// `{ existences, missProbability, costs, threshold? }`; returns
/// `{ empty, singleton, rule, threshold }`.
#[wasm_bindgen(js_name = bernoulliLossCurve, unchecked_return_type = "BernoulliLossCurveResult")]
pub fn bernoulli_loss_curve(
    #[wasm_bindgen(unchecked_param_type = "BernoulliLossCurveOptions")] options: JsValue,
) -> JsResult<JsValue> {
    let opts = Options::new(&options, "options", true)?;
    let ps = numbers(&opts.require("existences")?, "existences")?;
    let q = opts.number("missProbability")?;
    let costs = required_costs(&opts)?;
    let optimal = bernoulli::threshold(&costs, q).or_throw()?;
    let rule = match opts.get("threshold")? {
        Some(v) => bernoulli::Threshold {
            gamma: number(&v, "threshold")?,
            direction: Direction::Above,
        },
        None => optimal,
    };
    let (mut empty, mut singleton, mut chosen) = (vec![], vec![], vec![]);
    for (i, &p) in ps.iter().enumerate() {
        let name = || format!("existences[{i}]");
        let e = bernoulli::expected_loss_empty(&costs, p).map_err(|e| renamed_field(e, &name()))?;
        let a = bernoulli::expected_loss_singleton(&costs, p, q)
            .map_err(|e| renamed_field(e, &name()))?;
        empty.push(e);
        singleton.push(a);
        chosen.push(if rule.declares(p) { a } else { e });
    }
    Ok(object(&[
        ("empty", number_array(&empty)),
        ("singleton", number_array(&singleton)),
        ("rule", number_array(&chosen)),
        ("threshold", rule.gamma.into()),
    ]))
}

/// Maps a core `existence` error to the JS field `name`.
fn renamed_field(e: fisst::Error, name: &str) -> JsValue {
    range_error(e.to_string().replacen("existence", name, 1))
}
