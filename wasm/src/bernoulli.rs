//! Optimal Bernoulli point estimation (Narykov, Üney & Ralph, "Optimal Bernoulli point
//! estimation with applications", paper 000): the estimate of Theorem III.3, q(a), the MMUC
//! estimate and the threshold curves of Fig. 3.

use serde::{Deserialize, Serialize};
use tsify::Tsify;
use wasm_bindgen::prelude::*;

use crate::boundary::{JsResult, OrThrow, read, type_error, write};
use crate::types::{self, Covariance, Numbers, Point, WeightedGaussian};
use fisst::bernoulli::{
    self, ApplicationLoss, BernoulliEstimate, Costs, LossCurveOptions, MmucMethod, ParticleSet,
    SpatialDensity,
};
use fisst::gaussian::Gaussian as CoreGaussian;

/// The spatial density of a Bernoulli: one Gaussian (any dimension, full covariance), a
/// Gaussian mixture (weights ≥ 0 with a positive sum; normalised), or weighted particles
/// (weights ≥ 0 with a positive sum, default equal; normalised). Exactly one form.
#[derive(Deserialize, Tsify)]
#[tsify(
    type = "{ mean: Point; cov: Covariance } | { mixture: WeightedGaussian[] } | { particles: Point[]; weights?: Numbers }"
)]
pub struct BernoulliDensity {
    mean: Option<Point>,
    cov: Option<Covariance>,
    mixture: Option<Vec<WeightedGaussian>>,
    particles: Option<Vec<Point>>,
    weights: Option<Numbers>,
}

const DENSITY_FORMS: &str = "{ mean, cov }, { mixture: [...] } or { particles: [...], weights }";

impl BernoulliDensity {
    /// The core density; errors name `path` (`options.density`, `options.components[2].density`).
    fn into_core(self, path: &str) -> JsResult<SpatialDensity> {
        let gaussian_keys = self.mean.is_some() || self.cov.is_some();
        let forms = usize::from(gaussian_keys)
            + usize::from(self.mixture.is_some())
            + usize::from(self.particles.is_some());
        if forms != 1 || (self.weights.is_some() && self.particles.is_none()) {
            return Err(type_error(format!(
                "{path} must be exactly one of {DENSITY_FORMS}"
            )));
        }
        // The core names density errors `density…`; `within` puts them under `path`'s parent.
        let parent = path
            .strip_suffix("density")
            .map_or(path, |p| p.trim_end_matches('.'));
        if let Some(items) = self.mixture {
            let m = types::mixture(items, &format!("{path}.mixture"))?;
            return SpatialDensity::mixture(&m).or_throw_in(parent);
        }
        if let Some(points) = self.particles {
            let pts: Vec<Vec<f64>> = points.into_iter().map(|p| p.0).collect();
            let w = self.weights.map(|w| w.0);
            let p = ParticleSet::new(&pts, w.as_deref()).or_throw_in(parent)?;
            return Ok(SpatialDensity::particles(p));
        }
        let Some(mean) = self.mean else {
            return Err(type_error(format!("{path}.mean is required")));
        };
        let Some(cov) = self.cov else {
            return Err(type_error(format!("{path}.cov is required")));
        };
        let n = mean.0.len();
        let cov = cov.row_major(n, &format!("{path}.cov"))?;
        let g = CoreGaussian::from_slices(&mean.0, &cov, path).or_throw()?;
        SpatialDensity::gaussian(g).or_throw_in(parent)
    }
}

// The costs of the loss (7) are the core's `Costs`, read by its own deserializer ('mpe',
// `{ mmol }` or the five costs; errors name `.c01`, `.mmol.asset` under `options.costs`).
#[wasm_bindgen(typescript_custom_section)]
const COSTS: &str = r#"
/**
 * Costs of the loss (7) of Narykov, Üney & Ralph, "Optimal Bernoulli point estimation with
 * applications" (paper 000): the MPE preset `'mpe'` (0, 1, 1, 0, 1), the MMOL preset `{ mmol: {
 * asset: c_A, countermeasure: c_M } }` (c00 = 0, c01 = c_A, c10 = c_M, c11 = c_M, c = c_A), or the
 * five costs (finite, ≥ 0).
 */
export type BernoulliCosts = 'mpe' | { mmol: { asset: number; countermeasure: number } } | { c00: number; c01: number; c10: number; c11: number; c: number };
"#;

/// Options of `bernoulliEstimate` (the loss (7) and Theorem III.3 of Narykov, Üney & Ralph,
/// "Optimal Bernoulli point estimation with applications" (paper 000)).
#[derive(Deserialize, Tsify)]
pub struct BernoulliEstimateOptions {
    /// The existence probability p ∈ [0, 1]: the probability that the object exists.
    pub existence: f64,
    /// The spatial density of the object when it exists. The MMUC search takes a mixture of at most
    /// 100 components and at most 1500 particles in 2 or more dimensions (a RangeError naming the
    /// array beyond).
    pub density: BernoulliDensity,
    /// The radius r0 > 0 of the tolerance ball of the loss (7), in state units.
    pub radius: f64,
    /// The costs of the loss (7).
    #[tsify(type = "BernoulliCosts")]
    pub costs: Costs,
}

/// Result of `bernoulliEstimate`: the Bayes-optimal estimate of Theorem III.3 of Narykov, Üney &
/// Ralph, "Optimal Bernoulli point estimation with applications" (paper 000).
#[derive(Serialize, Tsify)]
#[serde(rename_all = "camelCase")]
pub struct BernoulliEstimateResult {
    /// Whether to report the object: the optimal decision (ties p = Γ report nothing).
    pub declare: bool,
    /// The reported point estimate: `mmuc` when `declare` is true, else null.
    #[tsify(type = "number[] | null")]
    pub estimate: Option<Vec<f64>>,
    /// The MMUC point a* (12): the centre of the radius-r0 ball most likely to hold the object.
    pub mmuc: Vec<f64>,
    /// The existence threshold Γ of eq. (11) (p > Γ reports for every cost matrix with c11 + c·q <
    /// c01 + c10 − c00, which includes MPE and MMOL; ±Infinity when the decision does not depend on
    /// p).
    pub threshold: f64,
    /// The miss probability q(a*) ∈ [0, 1]: the probability that the object, if it exists, lies
    /// outside the radius-r0 ball about a*.
    pub miss_probability: f64,
    /// The expected loss ρ_∅ (14) of reporting nothing.
    pub expected_loss_empty: f64,
    /// The expected loss ρ_{a*} (13) of reporting the single point a*.
    pub expected_loss_singleton: f64,
}

/// Options of `probabilityOutsideBall`: a density and a ball.
#[derive(Deserialize, Tsify)]
pub struct ProbabilityOutsideBallOptions {
    /// The spatial density of the object's state.
    pub density: BernoulliDensity,
    /// The ball's centre (the density's dimension).
    pub center: Point,
    /// The ball's radius, > 0, in state units.
    pub radius: f64,
}

fn dim_one() -> usize {
    1
}

/// Options of `bernoulliThresholdCurve` (Fig. 3 of Narykov, Üney & Ralph, "Optimal Bernoulli point
/// estimation with applications" (paper 000)).
#[derive(Deserialize, Tsify)]
pub struct BernoulliThresholdCurveOptions {
    /// Standard deviations σ > 0 of the isotropic Gaussian N(a*, σ² I).
    pub sigmas: Numbers,
    /// The radius r0 > 0 of the tolerance ball of the loss (7), in state units.
    pub radius: f64,
    /// The costs of the loss (7).
    #[tsify(type = "BernoulliCosts")]
    pub costs: Costs,
    /// Dimension, an integer in [1, 10000] (default 1, as in Fig. 3).
    #[serde(default = "dim_one")]
    pub dim: usize,
}

/// Options of `mmucEstimate`: the MMUC (minimum mean uniform cost) point a* (12) of
/// Narykov, Üney & Ralph, "Optimal Bernoulli point estimation with applications" (paper 000).
#[derive(Deserialize, Tsify)]
pub struct MmucEstimateOptions {
    /// The spatial density of the object's state. The MMUC search takes a mixture of at most 100
    /// components and at most 1500 particles in 2 or more dimensions (a RangeError naming the array
    /// beyond).
    pub density: BernoulliDensity,
    /// The radius r0 > 0 of the ball whose miss probability q(a) is minimised, in state units.
    pub radius: f64,
}

/// How the MMUC point was found.
#[derive(Serialize, Tsify)]
#[serde(rename_all = "kebab-case")]
pub enum MmucMethodName {
    /// `'gaussian-mean'`: a Gaussian's mean (exact).
    GaussianMean,
    /// `'shared-mean'`: the common mean of a mixture (exact).
    SharedMean,
    /// `'mixture-search'`: a multi-start local search over a mixture.
    MixtureSearch,
    /// `'particles-exact'`: an exhaustive search over the particles.
    ParticlesExact,
    /// `'particles-heuristic'`: a heuristic search over many particles.
    ParticlesHeuristic,
}

/// Result of `mmucEstimate`: the MMUC point a* (12) and its miss probability.
#[derive(Serialize, Tsify)]
#[serde(rename_all = "camelCase")]
pub struct MmucEstimateResult {
    /// The MMUC point a*: the centre of the radius-r0 ball most likely to hold the object.
    pub center: Vec<f64>,
    /// The miss probability q(a*) ∈ [0, 1]: the probability that the object lies outside the
    /// radius-r0 ball about a*.
    pub miss_probability: f64,
    /// How a* was found (exact or heuristic).
    pub method: MmucMethodName,
}

/// One component of `multiBernoulliPointEstimate`.
#[derive(Deserialize, Tsify)]
pub struct BernoulliComponent {
    /// The existence probability r ∈ [0, 1] of this component.
    pub existence: f64,
    /// The component's spatial density. The MMUC search takes a mixture of at most 100 components
    /// and at most 1500 particles in 2 or more dimensions (a RangeError naming the array beyond).
    pub density: BernoulliDensity,
}

/// Options of `multiBernoulliPointEstimate` (the loss (7) of Narykov, Üney & Ralph, "Optimal
/// Bernoulli point estimation with applications" (paper 000)).
#[derive(Deserialize, Tsify)]
pub struct MultiBernoulliPointEstimateOptions {
    /// The Bernoulli components, each decided alone (at most 10,000).
    pub components: Vec<BernoulliComponent>,
    /// The radius r0 > 0 of the tolerance ball of the loss (7), in state units.
    pub radius: f64,
    /// The costs of the loss (7).
    #[tsify(type = "BernoulliCosts")]
    pub costs: Costs,
}

/// Result of `multiBernoulliPointEstimate`: the reported components and their estimates.
#[derive(Serialize, Tsify)]
pub struct MultiBernoulliPointEstimateResult {
    /// Indices of the declared components, increasing.
    pub reported: Vec<usize>,
    /// The point estimates a* of the reported components, in the order of `reported`.
    pub estimates: Vec<Vec<f64>>,
    /// The full Theorem III.3 result of each component, in the order of `components`.
    pub components: Vec<BernoulliEstimateResult>,
}

/// Options of `bernoulliLossCurve` (Fig. 2 of Narykov, Üney & Ralph, "Optimal Bernoulli point
/// estimation with applications" (paper 000)).
#[derive(Deserialize, Tsify)]
#[serde(rename_all = "camelCase")]
pub struct BernoulliLossCurveOptions {
    /// The existence probabilities p at which to evaluate.
    pub existences: Numbers,
    /// The miss probability q(a*) ∈ [0, 1] of the point that would be reported.
    pub miss_probability: f64,
    /// The costs of the loss (7).
    #[tsify(type = "BernoulliCosts")]
    pub costs: Costs,
    /// Report when p > threshold; default: the optimal rule of Theorem III.3.
    #[tsify(optional)]
    pub threshold: Option<f64>,
}

/// Result of `bernoulliLossCurve`: ρ_∅(p) (14), ρ_{a*}(p) (13), and the expected loss of the rule,
/// for each p (the expected losses of Narykov, Üney & Ralph, "Optimal Bernoulli point estimation
/// with applications" (paper 000)).
#[derive(Serialize, Tsify)]
pub struct BernoulliLossCurveResult {
    /// The expected loss ρ_∅(p) (14) of reporting nothing, one per p.
    pub empty: Vec<f64>,
    /// The expected loss ρ_{a*}(p) (13) of reporting a*, one per p.
    pub singleton: Vec<f64>,
    /// The expected loss of the rule "report when p > threshold", one per p.
    pub rule: Vec<f64>,
    /// The rule's existence threshold (the given one, or the optimal Γ (11)).
    pub threshold: f64,
}

pub(crate) fn estimate_out(e: &BernoulliEstimate) -> BernoulliEstimateResult {
    BernoulliEstimateResult {
        declare: e.declare,
        estimate: e.estimate.clone(),
        mmuc: e.mmuc.center.clone(),
        threshold: e.threshold.gamma,
        miss_probability: e.mmuc.miss_probability,
        expected_loss_empty: e.expected_loss_empty,
        expected_loss_singleton: e.expected_loss_singleton,
    }
}

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
    let s = o.density.into_core("options.density")?;
    s.check_mmuc_size().or_throw_in("options")?;
    let loss = ApplicationLoss::new(o.costs, o.radius).or_throw_in("options")?;
    let e = bernoulli::estimate(o.existence, &s, &loss).or_throw_in("options")?;
    write(&estimate_out(&e))
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
    let s = o.density.into_core("options.density")?;
    s.prob_outside_ball(&o.center.0, o.radius)
        .or_throw_in("options")
}

/// Γ (11) for each σ of an isotropic Gaussian N(a*, σ² I_dim) — Fig. 3 of Narykov, Üney & Ralph,
/// "Optimal Bernoulli point estimation with applications" (paper 000) — from
/// the closed form q = P(χ²_dim > (radius/σ)²). Options `{ sigmas, radius, costs, dim = 1 }`.
#[cfg(feature = "bernoulli")]
#[wasm_bindgen(js_name = bernoulliThresholdCurve, unchecked_return_type = "number[]")]
pub fn bernoulli_threshold_curve(
    #[wasm_bindgen(unchecked_param_type = "BernoulliThresholdCurveOptions")] options: JsValue,
) -> JsResult<JsValue> {
    let o: BernoulliThresholdCurveOptions = read(options, "options")?;
    let curve = bernoulli::isotropic_threshold_curve(&o.sigmas.0, o.radius, &o.costs, o.dim)
        .or_throw_in("options")?;
    write(&curve)
}

/// The MMUC estimate a* = argmin_a q(a) (eq. (12)) alone. Options `{ density, radius }`;
/// returns `{ center, missProbability, method }`.
#[cfg(feature = "bernoulli")]
#[wasm_bindgen(js_name = mmucEstimate, unchecked_return_type = "MmucEstimateResult")]
pub fn mmuc_estimate(
    #[wasm_bindgen(unchecked_param_type = "MmucEstimateOptions")] options: JsValue,
) -> JsResult<JsValue> {
    let o: MmucEstimateOptions = read(options, "options")?;
    let s = o.density.into_core("options.density")?;
    s.check_mmuc_size().or_throw_in("options")?;
    let m = s.mmuc(o.radius).or_throw_in("options")?;
    write(&MmucEstimateResult {
        center: m.center,
        miss_probability: m.miss_probability,
        method: match m.method {
            MmucMethod::GaussianMean => MmucMethodName::GaussianMean,
            MmucMethod::SharedMean => MmucMethodName::SharedMean,
            MmucMethod::MixtureSearch => MmucMethodName::MixtureSearch,
            MmucMethod::ParticlesExact => MmucMethodName::ParticlesExact,
            MmucMethod::ParticlesHeuristic => MmucMethodName::ParticlesHeuristic,
        },
    })
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
    let o: MultiBernoulliPointEstimateOptions = read(options, "options")?;
    types::check_gaussian_count(o.components.len(), "options.components")?;
    let mut comps = Vec::with_capacity(o.components.len());
    for (i, c) in o.components.into_iter().enumerate() {
        let path = format!("options.components[{i}]");
        let s = c.density.into_core(&format!("{path}.density"))?;
        s.check_mmuc_size().or_throw_in(&path)?;
        comps.push((c.existence, s));
    }
    let loss = ApplicationLoss::new(o.costs, o.radius).or_throw_in("options")?;
    let m = bernoulli::multi_bernoulli_estimate(&comps, &loss).or_throw_in("options")?;
    write(&MultiBernoulliPointEstimateResult {
        reported: m.reported.clone(),
        estimates: m.points().into_iter().map(<[f64]>::to_vec).collect(),
        components: m.components.iter().map(estimate_out).collect(),
    })
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
    let o: BernoulliLossCurveOptions = read(options, "options")?;
    let c = bernoulli::loss_curve(&LossCurveOptions {
        existences: o.existences.0,
        miss_probability: o.miss_probability,
        costs: o.costs,
        threshold: o.threshold,
    })
    .or_throw_rendered("options")?;
    write(&BernoulliLossCurveResult {
        empty: c.empty,
        singleton: c.singleton,
        rule: c.rule,
        threshold: c.threshold,
    })
}
