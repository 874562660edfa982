//! `jdeBoundNoClutter`, `gaussianFisherInformation`, `jdeSequentialBound`, `jdeBound`: the
//! error bounds for joint detection and estimation of paper 002 (Rezaeian & Vo).

use serde::{Deserialize, Serialize};
use tsify::Tsify;
use wasm_bindgen::prelude::*;

use crate::boundary::{JsResult, OrThrow, check_range, read, write};
use crate::names::Renamed;
use crate::types::{Covariance, Gaussian, Numbers};
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
    /// k_max, the number of steps (integer in [1, 5000]; the Enumeration sum is O(steps²)).
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

/// N(mean, variance).
#[derive(Deserialize, Tsify)]
pub struct GaussianShape {
    /// The mean (finite).
    pub mean: f64,
    /// The variance (> 0, a normal float: at least 2.2250738585072014e-308).
    pub variance: f64,
}

/// U[low, high].
#[derive(Deserialize, Tsify)]
pub struct UniformShape {
    /// The lower end.
    pub low: f64,
    /// The upper end (> low).
    pub high: f64,
}

/// One component of a Gaussian mixture.
#[derive(Deserialize, Tsify)]
pub struct MixtureShape {
    /// Weight > 0 (the weights are normalised).
    pub weight: f64,
    /// Mean.
    pub mean: f64,
    /// Variance > 0.
    pub variance: f64,
}

/// A tabulated density: linear interpolation between knots, 0 outside, normalised.
#[derive(Deserialize, Tsify)]
pub struct TableShape {
    /// Knots, strictly increasing (2 to 10,000).
    pub x: Numbers,
    /// Density ≥ 0 at each knot (any positive scale: it is normalised).
    pub density: Numbers,
}

/// A 1D density: `{ gaussian: { mean, variance } }`, `{ uniform: { low, high } }`,
/// `{ mixture: [{ weight, mean, variance }, …] }` (1 to 1,000 components) or
/// `{ table: { x, density } }`.
#[derive(Deserialize, Tsify)]
#[serde(rename_all = "camelCase")]
pub enum DensityShape {
    /// Gaussian.
    Gaussian(GaussianShape),
    /// Uniform.
    Uniform(UniformShape),
    /// Gaussian mixture.
    Mixture(Vec<MixtureShape>),
    /// Tabulated.
    Table(TableShape),
}

impl DensityShape {
    fn into_core(self, path: &str) -> JsResult<bounds::Density1> {
        match self {
            DensityShape::Gaussian(g) => bounds::Density1::gaussian(g.mean, g.variance)
                .or_throw_in(&format!("{path}.gaussian")),
            DensityShape::Uniform(u) => {
                bounds::Density1::uniform(u.low, u.high).or_throw_in(&format!("{path}.uniform"))
            }
            DensityShape::Mixture(c) => {
                let c: Vec<(f64, f64, f64)> =
                    c.iter().map(|c| (c.weight, c.mean, c.variance)).collect();
                bounds::Density1::mixture(&c).or_throw_in(&format!("{path}.mixture"))
            }
            DensityShape::Table(t) => {
                bounds::Density1::table(&t.x.0, &t.density.0).or_throw_in(&format!("{path}.table"))
            }
        }
    }
}

/// A tabulated P_o(x): linear interpolation, held constant beyond the end knots.
#[derive(Deserialize, Tsify)]
pub struct DetectionTableShape {
    /// Knots, strictly increasing (2 to 10,000).
    pub x: Numbers,
    /// P_o at each knot, in [0, 1].
    pub probability: Numbers,
}

/// `{ table: { x, probability } }`.
#[derive(Deserialize)]
struct DetectionTableWrapper {
    table: DetectionTableShape,
}

/// P_o(x): a number in [0, 1] (constant) or `{ table: { x, probability } }`.
#[derive(Tsify)]
#[tsify(type = "number | { table: DetectionTableShape }")]
pub enum DetectionShape {
    /// Constant.
    Constant(f64),
    /// Tabulated.
    Table(DetectionTableShape),
}

impl<'de> Deserialize<'de> for DetectionShape {
    fn deserialize<D: serde::Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        struct V;
        impl<'de> serde::de::Visitor<'de> for V {
            type Value = DetectionShape;
            fn expecting(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
                f.write_str("a probability or { table: { x, probability } }")
            }
            fn visit_f64<E: serde::de::Error>(self, x: f64) -> Result<Self::Value, E> {
                Ok(DetectionShape::Constant(x))
            }
            fn visit_map<A: serde::de::MapAccess<'de>>(
                self,
                map: A,
            ) -> Result<Self::Value, A::Error> {
                let w = DetectionTableWrapper::deserialize(
                    serde::de::value::MapAccessDeserializer::new(map),
                )?;
                Ok(DetectionShape::Table(w.table))
            }
        }
        d.deserialize_any(V)
    }
}

/// The gain of g: a number a (z = a·x + b, a 1D state, the default 1) or the measurement
/// matrix H as m rows of l numbers (z = H x + b, a `multivariateGaussian` prior).
#[derive(Clone, Debug, Tsify)]
#[tsify(type = "number | (number[] | Float64Array)[]")]
pub enum GainShape {
    /// a.
    Scalar(f64),
    /// H, row by row.
    Rows(Vec<Vec<f64>>),
}

impl Default for GainShape {
    fn default() -> Self {
        GainShape::Scalar(1.0)
    }
}

impl<'de> Deserialize<'de> for GainShape {
    fn deserialize<D: serde::Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        struct V;
        impl<'de> serde::de::Visitor<'de> for V {
            type Value = GainShape;
            fn expecting(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
                f.write_str("a number or an array of rows (arrays of numbers)")
            }
            fn visit_f64<E: serde::de::Error>(self, x: f64) -> Result<Self::Value, E> {
                Ok(GainShape::Scalar(x))
            }
            fn visit_seq<A: serde::de::SeqAccess<'de>>(
                self,
                mut seq: A,
            ) -> Result<Self::Value, A::Error> {
                let mut rows = Vec::new();
                while let Some(r) = seq.next_element::<Vec<f64>>()? {
                    rows.push(r);
                }
                Ok(GainShape::Rows(rows))
            }
        }
        d.deserialize_any(V)
    }
}

/// The offset b of g: a number (one measurement coordinate, the default 0) or m numbers.
#[derive(Clone, Debug, Tsify)]
#[tsify(type = "number | number[] | Float64Array")]
pub enum OffsetShape {
    /// b.
    Scalar(f64),
    /// b, one number per measurement coordinate.
    Vector(Vec<f64>),
}

impl Default for OffsetShape {
    fn default() -> Self {
        OffsetShape::Scalar(0.0)
    }
}

impl<'de> Deserialize<'de> for OffsetShape {
    fn deserialize<D: serde::Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        struct V;
        impl<'de> serde::de::Visitor<'de> for V {
            type Value = OffsetShape;
            fn expecting(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
                f.write_str("a number or an array of numbers")
            }
            fn visit_f64<E: serde::de::Error>(self, x: f64) -> Result<Self::Value, E> {
                Ok(OffsetShape::Scalar(x))
            }
            fn visit_seq<A: serde::de::SeqAccess<'de>>(
                self,
                mut seq: A,
            ) -> Result<Self::Value, A::Error> {
                let mut v = Vec::new();
                while let Some(x) = seq.next_element::<f64>()? {
                    v.push(x);
                }
                Ok(OffsetShape::Vector(v))
            }
        }
        d.deserialize_any(V)
    }
}

/// At most this many state coordinates l, and this many measurement coordinates m.
pub use bounds::MAX_DIMS;

/// The observation: P_o(x) and g(z|x) = N(z; gain·x + offset, noiseVariance) for a 1D prior,
/// or g(z|x) = N(z; H x + b, R) with H = `gain` (m rows of l numbers) and R = `noiseCov`
/// (or, for m = 1, `noiseVariance`) for a `multivariateGaussian` prior.
#[derive(Deserialize, Tsify)]
#[serde(rename_all = "camelCase")]
pub struct ObservationShape {
    /// P_o(x): a number in [0, 1] or `{ table: { x, probability } }` (a
    /// `multivariateGaussian` prior takes a constant only).
    pub detection_probability: DetectionShape,
    /// a, a finite number (default 1); with a `multivariateGaussian` prior H, m rows of l
    /// finite numbers (1 ≤ m ≤ 64; a number is H = [[a]] when l = 1). False alarms or
    /// clutter need m = 1: their densities are on the measurement line.
    #[serde(default)]
    #[tsify(optional)]
    pub gain: GainShape,
    /// b (default 0): a number, or with a `multivariateGaussian` prior m numbers (a number
    /// serves m = 1).
    #[serde(default)]
    #[tsify(optional)]
    pub offset: OffsetShape,
    /// σ_v² > 0, the noise variance of a one-coordinate measurement (required with a 1D
    /// prior; with a `multivariateGaussian` prior give it or `noiseCov`, and only for m = 1).
    #[tsify(optional)]
    pub noise_variance: Option<f64>,
    /// R, the m × m noise covariance of a `multivariateGaussian` prior's measurement:
    /// m rows of m numbers or m·m row-major numbers, symmetric positive definite.
    #[tsify(optional)]
    pub noise_cov: Option<Covariance>,
}

impl ObservationShape {
    fn into_core(self, path: &str) -> JsResult<bounds::LinearGaussian> {
        let gain = match self.gain {
            GainShape::Scalar(a) => a,
            GainShape::Rows(_) => {
                return Err(crate::boundary::type_error(format!(
                    "{path}.gain must be a number with a 1D prior (gain rows are H for a multivariateGaussian prior)"
                )));
            }
        };
        let offset = match self.offset {
            OffsetShape::Scalar(b) => b,
            OffsetShape::Vector(_) => {
                return Err(crate::boundary::type_error(format!(
                    "{path}.offset must be a number with a 1D prior"
                )));
            }
        };
        if self.noise_cov.is_some() {
            return Err(crate::boundary::type_error(format!(
                "{path}.noiseCov is for a multivariateGaussian prior (use noiseVariance with a 1D prior)"
            )));
        }
        let Some(noise) = self.noise_variance else {
            return Err(crate::boundary::type_error(format!(
                "{path}.noiseVariance is required"
            )));
        };
        let det = match self.detection_probability {
            DetectionShape::Constant(p) => bounds::Detection::constant(p).or_throw_in(path),
            DetectionShape::Table(t) => bounds::Detection::table(&t.x.0, &t.probability.0)
                .or_throw_in(&format!("{path}.detectionProbability.table")),
        }?;
        bounds::LinearGaussian::new(det, gain, offset, noise).or_throw_in(path)
    }

    /// The sensor of a state in R^`dims`.
    fn into_sensor(self, dims: usize, path: &str) -> JsResult<bounds::LinearGaussianSensor> {
        let detection = match self.detection_probability {
            DetectionShape::Constant(p) => p,
            DetectionShape::Table(_) => {
                return Err(crate::boundary::type_error(format!(
                    "{path}.detectionProbability must be a number (a constant P_o) with a multivariateGaussian prior"
                )));
            }
        };
        let rows = match self.gain {
            GainShape::Scalar(a) if dims == 1 => vec![vec![a]],
            GainShape::Scalar(_) => {
                return Err(crate::boundary::type_error(format!(
                    "{path}.gain must be H, m rows of {dims} numbers, for a state in R^{dims}"
                )));
            }
            GainShape::Rows(rows) => rows,
        };
        let m = rows.len();
        if m == 0 || m > MAX_DIMS {
            return Err(crate::boundary::range_error(format!(
                "{path}.gain must have 1 to {MAX_DIMS} rows, got {m}"
            )));
        }
        for (i, r) in rows.iter().enumerate() {
            if r.len() != dims {
                return Err(crate::boundary::range_error(format!(
                    "{path}.gain[{i}] has length {}, expected {dims} (the state dimension)",
                    r.len()
                )));
            }
        }
        let offset = match self.offset {
            OffsetShape::Scalar(b) if m == 1 => vec![b],
            OffsetShape::Scalar(0.0) => vec![0.0; m],
            OffsetShape::Scalar(_) => {
                return Err(crate::boundary::type_error(format!(
                    "{path}.offset must be {m} numbers (gain has {m} rows)"
                )));
            }
            OffsetShape::Vector(v) => {
                if v.len() != m {
                    return Err(crate::boundary::range_error(format!(
                        "{path}.offset has length {}, expected {m} (gain has {m} rows)",
                        v.len()
                    )));
                }
                v
            }
        };
        let noise = match (self.noise_variance, self.noise_cov) {
            (Some(_), Some(_)) => {
                return Err(crate::boundary::type_error(format!(
                    "{path}.noiseVariance and {path}.noiseCov are alternatives: give one"
                )));
            }
            (None, None) => {
                return Err(crate::boundary::type_error(format!(
                    "{path}.noiseCov is required (or noiseVariance when gain has one row)"
                )));
            }
            (Some(v), None) => {
                if m != 1 {
                    return Err(crate::boundary::type_error(format!(
                        "{path}.noiseVariance serves a gain of one row; gain has {m} rows: give noiseCov ({m} × {m})"
                    )));
                }
                if v <= 0.0 {
                    return Err(crate::boundary::range_error(format!(
                        "{path}.noiseVariance must be > 0, got {v}"
                    )));
                }
                vec![v]
            }
            (None, Some(c)) => c.row_major(m, &format!("{path}.noiseCov"))?,
        };
        bounds::LinearGaussianSensor::new(detection, &rows.concat(), dims, &offset, &noise)
            .or_throw_in(path)
    }
}

/// Model I's false observations: probability q and density ψ.
#[derive(Deserialize, Tsify)]
pub struct FalseAlarmShape {
    /// q in [0, 1].
    pub probability: f64,
    /// ψ.
    pub density: DensityShape,
}

/// Model II's Poisson clutter: rate λ and the density of its points (v = λ · density).
#[derive(Deserialize, Tsify)]
pub struct ClutterShape {
    /// λ ≥ 0 (at most 1000).
    pub rate: f64,
    /// v/λ.
    pub density: DensityShape,
}

/// `'I'` (Theorem 1: Bernoulli observation with false alarms) or `'II'` (Theorem 2: Poisson
/// clutter).
#[derive(Deserialize, Tsify, Clone, Copy)]
pub enum MeasurementModel {
    /// Model I (13).
    #[serde(rename = "I")]
    One,
    /// Model II (22).
    #[serde(rename = "II")]
    Two,
}

/// The prior f of `jdeBound`: a 1D density (`{ gaussian }`, `{ uniform }`, `{ mixture }`,
/// `{ table }`, as [`DensityShape`]) or, for a state in R^l, `{ multivariateGaussian: { mean,
/// cov } }` (the vector bounds (63)–(72) of Section V).
#[derive(Deserialize, Tsify)]
#[serde(rename_all = "camelCase")]
pub enum PriorShape {
    /// Gaussian N(mean, variance).
    Gaussian(GaussianShape),
    /// Uniform.
    Uniform(UniformShape),
    /// Gaussian mixture (1 to 1,000 components).
    Mixture(Vec<MixtureShape>),
    /// Tabulated.
    Table(TableShape),
    /// N(mean, cov) in R^l: `mean` l finite numbers (1 ≤ l ≤ 64), `cov` l rows of l numbers
    /// (or l·l row-major numbers; a bare number when l = 1), symmetric positive definite.
    /// The observation then has a constant P_o, gain rows H and `noiseCov`.
    MultivariateGaussian(Gaussian),
}

impl PriorShape {
    fn into_core(self, path: &str) -> JsResult<bounds::JdePrior> {
        let scalar = |d: DensityShape| d.into_core(path).map(bounds::JdePrior::Scalar);
        match self {
            PriorShape::Gaussian(g) => scalar(DensityShape::Gaussian(g)),
            PriorShape::Uniform(u) => scalar(DensityShape::Uniform(u)),
            PriorShape::Mixture(m) => scalar(DensityShape::Mixture(m)),
            PriorShape::Table(t) => scalar(DensityShape::Table(t)),
            PriorShape::MultivariateGaussian(g) => {
                let p = format!("{path}.multivariateGaussian");
                let l = check_range(&format!("{p}.mean.length"), g.mean.0.len(), 1, MAX_DIMS)?;
                let cov = g.cov.row_major(l, &format!("{p}.cov"))?;
                bounds::GaussianPrior::new(&g.mean.0, &cov)
                    .or_throw_in(&p)
                    .map(bounds::JdePrior::Vector)
            }
        }
    }
}

/// Options of `jdeBound`.
#[derive(Deserialize, Tsify)]
#[serde(rename_all = "camelCase")]
pub struct JdeBoundOptions {
    /// `'I'` or `'II'`.
    pub model: MeasurementModel,
    /// r in [0, 1].
    pub existence: f64,
    /// f, the prior density of the state: a 1D density, or `{ multivariateGaussian: { mean,
    /// cov } }` for a state in R^l (then `result.components` holds the bound of each
    /// coordinate).
    pub prior: PriorShape,
    /// P_o and g.
    pub observation: ObservationShape,
    /// Model I: `{ probability, density }` (q, ψ); omitted: q = 0. Not allowed with model II.
    #[tsify(optional)]
    pub false_alarm: Option<FalseAlarmShape>,
    /// Model II: `{ rate, density }` (λ, v/λ); omitted: λ = 0. Not allowed with model I.
    #[tsify(optional)]
    pub clutter: Option<ClutterShape>,
    /// e_0² ≥ 0 (of the whole state; coordinate i of a vector state uses e_0²/l).
    pub false_alarm_error: f64,
    /// e_1² ≥ 0 (of the whole state; coordinate i of a vector state uses e_1²/l).
    pub miss_error: f64,
    /// l, the state dimension, an integer in [1, 64] (default: 1 for a 1D prior, the length
    /// of `prior.multivariateGaussian.mean` otherwise, which it must equal; l > 1 needs a
    /// `multivariateGaussian` prior).
    #[tsify(optional)]
    pub dims: Option<usize>,
    /// Relative quadrature tolerance in [1e-14, 0.1] (default 1e-10).
    #[tsify(optional)]
    pub tolerance: Option<f64>,
    /// Monte Carlo samples per cardinality n ≥ 2 (n ≥ 3 with `quadratureCardinality: 2`)
    /// (model II with clutter; 100 to 1,000,000, default 20,000; samples × Σ n at most 10^7).
    #[tsify(optional)]
    pub samples: Option<usize>,
    /// Seed of the Monte Carlo (integer; omitted: fresh entropy, returned as `seed`).
    #[tsify(optional)]
    pub seed: Option<u64>,
    /// Model II with clutter: the largest |Z| = n integrated by deterministic quadrature, 1
    /// (default: n = 1 by 1D quadrature, every n ≥ 2 by Monte Carlo) or 2 (also n = 2, by
    /// 2D cubature over Z² (Theorem 2), which removes the n = 2 Monte Carlo error). Cost:
    /// the n = 2 cubature takes seconds (about 3.5 s natively; 6–15 s in wasm under Node on
    /// a loaded 2-core machine, for λ = 1, an N(1, 4) prior and U[−10, 10] clutter, against
    /// about 0.4 s with 1; a looser `tolerance` such as 1e-5 halves it): do not use it while
    /// a slider moves. No effect on model I or without clutter.
    #[tsify(optional, type = "1 | 2")]
    pub quadrature_cardinality: Option<usize>,
}

/// One summand of (17) or (23).
#[derive(Serialize, Tsify)]
pub struct BoundTerm {
    /// `'estimation'`, `'undetected'`, `'missed'` or `'falseTarget'`.
    pub name: &'static str,
    /// Its value.
    pub value: f64,
}

/// The n-point part of Theorem 2 (model I: only n = 1).
#[derive(Serialize, Tsify)]
#[serde(rename_all = "camelCase")]
pub struct CardinalityTerm {
    /// n = |Z|.
    pub n: usize,
    /// C_{n−1}, the probability of n − 1 clutter points.
    pub probability: f64,
    /// w_n (20)/(25).
    pub w: f64,
    /// J'_n⁻¹ (with the 1/w_n² of (20)/(25)); for a vector state its trace.
    pub inverse_information: f64,
    /// Pr(the detector rejects n clutter-only points).
    pub clutter_null: f64,
    /// `'quadrature'`, `'monte-carlo'` or (a vector state without false observations)
    /// `'closed-form'`.
    #[tsify(type = "'quadrature' | 'monte-carlo' | 'closed-form'")]
    pub method: &'static str,
    /// Error estimate of `inverseInformation` (Monte Carlo: one standard error).
    pub error: f64,
}

/// The bound (63)/(64) on the mean-square error σ_i² of one coordinate x_i of a vector
/// state, with the component metric e_i (e_i(∅, {x'}) = e_0/√l, e_i({x}, ∅) = e_1/√l).
#[derive(Serialize, Tsify)]
#[serde(rename_all = "camelCase")]
pub struct JdeComponentBound {
    /// The lower bound on E e_i²: the smaller of `hpe` and `lpe`.
    pub bound: f64,
    /// This coordinate's rule on Z = ∅ (each coordinate may pick its own).
    #[tsify(type = "'HPE' | 'LPE'")]
    pub phase: &'static str,
    /// r* of this coordinate (72): e_0²/(e_0² + (1 − P̄o)(e_1² − l σ_{e,i}²)) without false
    /// observations (may exceed 1; `Infinity` when HPE never wins).
    pub existence_threshold: f64,
    /// The summands of (63)/(64) for this coordinate, named as the top-level `terms`.
    pub terms: Vec<BoundTerm>,
    /// Error estimate of `bound` (quadrature, one Monte Carlo standard error).
    pub error: f64,
    /// The HPE bound of this coordinate.
    pub hpe: f64,
    /// The LPE bound of this coordinate.
    pub lpe: f64,
    /// [J'_1⁻¹]_ii (63), or Σ_n C_n [J'_{1+n}⁻¹]_ii (64).
    pub inverse_information: f64,
    /// x*_i, the prior mean of this coordinate (P_o is constant, so f_d' = f).
    pub undetected_mean: f64,
    /// σ_{e,i}² = P_ii, the prior variance of this coordinate.
    pub undetected_variance: f64,
}

/// Result of `jdeBound`.
#[derive(Serialize, Tsify)]
#[serde(rename_all = "camelCase")]
pub struct JdeBoundResult {
    /// The lower bound on E e²(X, X̂(Z)) (a valid one only when `regular`); for a vector
    /// state with the Euclidean metric, one rule on Z = ∅ for the whole state (≥ the sum of
    /// `components[i].bound`, which may each pick their own rule).
    pub bound: f64,
    /// The rule on Z = ∅ of the bound's estimator.
    #[tsify(type = "'HPE' | 'LPE'")]
    pub phase: &'static str,
    /// r* (18)/(24) (may exceed 1; `Infinity` when HPE never wins).
    pub existence_threshold: f64,
    /// The summands of (17)/(23) in order: estimation, undetected, missed, falseTarget.
    pub terms: Vec<BoundTerm>,
    /// Error estimate of `bound` (quadrature, one Monte Carlo standard error).
    pub error: f64,
    /// The HPE bound.
    pub hpe: f64,
    /// The LPE bound.
    pub lpe: f64,
    /// P̄_o (14).
    pub mean_detection: f64,
    /// x*, the mean of f_d' (a vector state: of its first coordinate; see
    /// `components[i].undetectedMean`).
    pub undetected_mean: f64,
    /// σ_e² (16) (a vector state: tr P).
    pub undetected_variance: f64,
    /// η1 or η2.
    pub eta: f64,
    /// The MAP region of one-point observations, `[low, high]` intervals (a vector state:
    /// of the measurement line; empty when the gain has more than one row, where there are
    /// no false observations and every measurement is kept).
    pub region: Vec<(f64, f64)>,
    /// Per cardinality n.
    pub cardinalities: Vec<CardinalityTerm>,
    /// false when f·P_o does not vanish at the prior's support ends (uniform, tables ending
    /// above 0): the information inequality's regularity fails, the estimation term may not
    /// be a bound.
    pub regular: bool,
    /// The Monte Carlo seed used (model II with clutter only).
    #[serde(skip_serializing_if = "Option::is_none")]
    #[tsify(optional)]
    pub seed: Option<u64>,
    /// A `multivariateGaussian` prior only: the bound of each coordinate x_i, i = 0 … l − 1
    /// ((63)/(64), (70)–(72)).
    #[serde(skip_serializing_if = "Option::is_none")]
    #[tsify(optional)]
    pub components: Option<Vec<JdeComponentBound>>,
    /// A `multivariateGaussian` prior only: J'_1⁻¹ (model I), or Σ_n C_n J'_{1+n}⁻¹
    /// (model II), l rows of l numbers, whose diagonal enters `components[i]`'s estimation
    /// term (without false observations, (P⁻¹ + HᵀR⁻¹H)⁻¹, the posterior covariance).
    #[serde(skip_serializing_if = "Option::is_none")]
    #[tsify(optional)]
    pub inverse_information_matrix: Option<Vec<Vec<f64>>>,
}

/// Theorems 1 and 2 of paper 002, and their vector extensions (63)–(72) for a
/// `multivariateGaussian` prior. Options `{ model, existence, prior, observation,
/// falseAlarm?, clutter?, falseAlarmError, missError, dims?, tolerance?, samples?, seed?,
/// quadratureCardinality? }`; returns `{ bound, phase, existenceThreshold, terms, error, … }`
/// and, for a vector state, `components` and `inverseInformationMatrix`.
#[wasm_bindgen(js_name = jdeBound, unchecked_return_type = "JdeBoundResult")]
pub fn jde_bound(
    #[wasm_bindgen(unchecked_param_type = "JdeBoundOptions")] options: JsValue,
) -> JsResult<JsValue> {
    let o: JdeBoundOptions = read(options, "options")?;
    let prior = o.prior.into_core("options.prior")?;
    let observation = match &prior {
        bounds::JdePrior::Scalar(_) => {
            bounds::JdeObservation::Scalar(o.observation.into_core("options.observation")?)
        }
        bounds::JdePrior::Vector(g) => bounds::JdeObservation::Vector(
            o.observation.into_sensor(g.dims(), "options.observation")?,
        ),
    };
    let false_alarm = match o.false_alarm {
        Some(f) => Some(bounds::FalseAlarm {
            probability: f.probability,
            density: f.density.into_core("options.falseAlarm.density")?,
        }),
        None => None,
    };
    let clutter = match o.clutter {
        Some(c) => Some(bounds::Clutter {
            rate: c.rate,
            density: c.density.into_core("options.clutter.density")?,
        }),
        None => None,
    };
    let options = bounds::JdeOptions {
        model: match o.model {
            MeasurementModel::One => bounds::JdeModel::I,
            MeasurementModel::Two => bounds::JdeModel::II,
        },
        existence: o.existence,
        prior,
        observation,
        false_alarm,
        clutter,
        false_alarm_error: o.false_alarm_error,
        miss_error: o.miss_error,
        dims: o.dims,
        tolerance: o.tolerance,
        samples: o.samples,
        seed: o.seed,
        quadrature_cardinality: o.quadrature_cardinality,
    };
    let out = bounds::jde_bound(&options, fisst::math::rng::entropy_seed)
        .map_err(|e| jde_error(e, &options.prior))?;
    let mut result = result(&out.bound, out.seed);
    result.components = out.components.map(|c| {
        c.iter()
            .map(|c| JdeComponentBound {
                bound: c.assembled.bound,
                phase: phase_name(c.assembled.phase),
                existence_threshold: c.assembled.existence_threshold,
                terms: terms(&c.assembled.terms),
                error: c.error,
                hpe: c.assembled.hpe,
                lpe: c.assembled.lpe,
                inverse_information: c.inverse_information,
                undetected_mean: c.undetected_mean,
                undetected_variance: c.undetected_variance,
            })
            .collect()
    });
    result.inverse_information_matrix = out.inverse_information;
    write(&result)
}

/// A [`bounds::jde_bound`] error in this binding's words: the model mix-ups are
/// `TypeError`s, a `dims` that is not the prior's says what the prior is, and the rest name
/// their path under `options` in camelCase.
fn jde_error(e: fisst::Error, prior: &bounds::JdePrior) -> JsValue {
    match &e {
        fisst::Error::Unsupported { what, reason } if *reason == bounds::WRONG_MODEL => {
            crate::boundary::type_error(if what == "clutter" {
                "options.clutter is for model 'II' (use falseAlarm with model 'I')"
            } else {
                "options.falseAlarm is for model 'I' (use clutter with model 'II')"
            })
        }
        fisst::Error::DimensionMismatch {
            what,
            expected,
            found: l,
        } if what == "dims" => crate::boundary::range_error(match prior {
            bounds::JdePrior::Scalar(_) => format!(
                "options.dims is {l}, but options.prior is a 1D density: a state in R^{l} needs prior: {{ multivariateGaussian: {{ mean, cov }} }}"
            ),
            bounds::JdePrior::Vector(_) => format!(
                "options.dims is {l}, but options.prior.multivariateGaussian.mean has length {expected}"
            ),
        }),
        _ => crate::boundary::core_error_rendered(e, "options"),
    }
}

fn phase_name(p: bounds::Phase) -> &'static str {
    match p {
        bounds::Phase::Hpe => "HPE",
        bounds::Phase::Lpe => "LPE",
    }
}

fn terms(t: &bounds::Terms) -> Vec<BoundTerm> {
    vec![
        BoundTerm {
            name: "estimation",
            value: t.estimation,
        },
        BoundTerm {
            name: "undetected",
            value: t.undetected,
        },
        BoundTerm {
            name: "missed",
            value: t.missed,
        },
        BoundTerm {
            name: "falseTarget",
            value: t.false_target,
        },
    ]
}

fn result(b: &bounds::JdeBound, seed: Option<u64>) -> JdeBoundResult {
    let a = &b.assembled;
    JdeBoundResult {
        bound: a.bound,
        phase: phase_name(a.phase),
        existence_threshold: a.existence_threshold,
        terms: terms(&a.terms),
        error: b.error,
        hpe: a.hpe,
        lpe: a.lpe,
        mean_detection: b.mean_detection,
        undetected_mean: b.undetected_mean,
        undetected_variance: b.undetected_variance,
        eta: b.eta,
        region: b.region.clone(),
        cardinalities: b
            .cardinalities
            .iter()
            .map(|c| CardinalityTerm {
                n: c.n,
                probability: c.probability,
                w: c.w,
                inverse_information: c.inverse_information,
                clutter_null: c.clutter_null,
                method: match c.method {
                    bounds::Method::Quadrature => "quadrature",
                    bounds::Method::MonteCarlo => "monte-carlo",
                    bounds::Method::ClosedForm => "closed-form",
                },
                error: c.error,
            })
            .collect(),
        regular: b.regular,
        seed,
        components: None,
        inverse_information_matrix: None,
    }
}

/// Options of `jdeExample2` (paper 002 Example 2, Fig. 2 right).
#[derive(Deserialize, Tsify)]
#[serde(rename_all = "camelCase")]
pub struct JdeExample2Options {
    /// r in [0, 1] (the figure: 0.6).
    pub existence: f64,
    /// P_o (constant) in [0, 1].
    pub detection_probability: f64,
    /// q, the false-alarm probability, in [0, 1] (the figure's abscissa).
    pub false_alarm_probability: f64,
    /// e_0² ≥ 0 (the figure: 1.2).
    pub false_alarm_error: f64,
    /// e_1² ≥ 0 (default e_0² + σ_e², the figure's choice).
    #[tsify(optional)]
    pub miss_error: Option<f64>,
}

/// Result of `jdeExample2`. Neither number is a lower bound where the estimation term
/// matters: p_1 does not vanish at x = 1 (see `jdeExample2Regularity`).
#[derive(Serialize, Tsify)]
#[serde(rename_all = "camelCase")]
pub struct JdeExample2Result {
    /// Theorem 1 with J'_1 as (20) (with 1/w_1²).
    pub bound: f64,
    /// Theorem 1 with J'_1 as (32) prints it (no 1/w_1²): the paper's curve.
    pub paper_bound: f64,
    /// J'_1 of (20).
    pub information: f64,
    /// J'_1 of (32): ∫_{Z'_0} 4(e^z − 1)/z dz.
    pub paper_information: f64,
    /// w_1.
    pub w: f64,
    /// η_1.
    pub eta: f64,
    /// σ_e² (the prior variance, 0.0341).
    pub undetected_variance: f64,
    /// e_1² used.
    pub miss_error: f64,
    /// Z'_0 as `[low, high]` intervals of [0, 1].
    pub region: Vec<(f64, f64)>,
    /// The phase of the (20) bound.
    #[tsify(type = "'HPE' | 'LPE'")]
    pub phase: &'static str,
}

/// Example 2 of paper 002 at one (r, P_o, q): the bound with (20)'s J'_1 and with (32)'s.
/// Options `{ existence, detectionProbability, falseAlarmProbability, falseAlarmError,
/// missError? }`; returns `{ bound, paperBound, information, paperInformation, w, eta, … }`.
#[wasm_bindgen(js_name = jdeExample2, unchecked_return_type = "JdeExample2Result")]
pub fn jde_example2(
    #[wasm_bindgen(unchecked_param_type = "JdeExample2Options")] options: JsValue,
) -> JsResult<JsValue> {
    let o: JdeExample2Options = read(options, "options")?;
    let e = bounds::example2(
        o.existence,
        o.detection_probability,
        o.false_alarm_probability,
        o.false_alarm_error,
        o.miss_error,
    )
    .or_throw_in("options")?;
    write(&JdeExample2Result {
        bound: e.bound,
        paper_bound: e.paper_bound,
        information: e.information,
        paper_information: e.paper_information,
        w: e.w,
        eta: e.eta,
        undetected_variance: e.undetected_variance,
        miss_error: o
            .miss_error
            .unwrap_or(o.false_alarm_error + e.undetected_variance),
        region: e.region,
        phase: match e.assembled.0.phase {
            bounds::Phase::Hpe => "HPE",
            bounds::Phase::Lpe => "LPE",
        },
    })
}

/// Result of `jdeExample2Regularity`.
#[derive(Serialize, Tsify)]
#[serde(rename_all = "camelCase")]
pub struct JdeExample2RegularityResult {
    /// J_1 = ∫₀¹ 4(e^z − 1)/z dz = 5.2716.
    pub information: f64,
    /// 1/J_1 = 0.1897, the information inequality's claim.
    pub inverse_information: f64,
    /// The MSE the posterior mean attains, 0.0340 (below 1/J_1: the inequality fails).
    pub posterior_mean_mse: f64,
    /// The prior variance 0.0341.
    pub prior_variance: f64,
}

/// Example 2's regularity failure (r = 1, P_o = 1): 1/J_1 against the posterior mean's MSE.
#[wasm_bindgen(
    js_name = jdeExample2Regularity,
    unchecked_return_type = "JdeExample2RegularityResult"
)]
pub fn jde_example2_regularity() -> JsResult<JsValue> {
    let r = bounds::example2_regularity();
    write(&JdeExample2RegularityResult {
        information: r.information,
        inverse_information: r.inverse_information,
        posterior_mean_mse: r.posterior_mean_mse,
        prior_variance: r.prior_variance,
    })
}

/// The rule of `jdeMonteCarlo` on Z = ∅: `'optimal'` (the cheaper of HPE and LPE (46)),
/// `'map'` (MAP detection, Section IV-A), `'declare'` (always HPE) or `'reject'` (always LPE).
#[derive(Deserialize, Tsify, Clone, Copy)]
#[serde(rename_all = "kebab-case")]
pub enum EmptyRuleShape {
    /// The cheaper of HPE and LPE.
    Optimal,
    /// MAP detection.
    Map,
    /// Always {x*}.
    Declare,
    /// Always ∅.
    Reject,
}

/// The state of `jdeMonteCarlo`: `{ gaussian: { mean, variance } }`, `{ multivariateGaussian:
/// { mean, cov } }` (a linear-Gaussian `observation`), or `'example2'` (Example 2 (32): f and
/// g fixed, `observation.detectionProbability` a constant P_o).
#[derive(Deserialize, Tsify)]
#[serde(rename_all = "camelCase")]
pub enum MonteCarloPriorShape {
    /// N(mean, variance).
    Gaussian(GaussianShape),
    /// N(mean, cov) in R^l.
    MultivariateGaussian(Gaussian),
    /// f(x) = 2x(eˣ − 1) on [0, 1] with g(z|x) = x e^{xz}/(eˣ − 1).
    Example2,
}

/// Options of `jdeMonteCarlo`: the problem of `jdeBound` (Gaussian priors and Example 2), the
/// rule on Z = ∅, the number of scans and the Monte Carlo's size and seed.
#[derive(Deserialize, Tsify)]
#[serde(rename_all = "camelCase")]
pub struct JdeMonteCarloOptions {
    /// The measurement model, `'I'` or `'II'`.
    pub model: MeasurementModel,
    /// r, the probability that the target exists, in [0, 1].
    pub existence: f64,
    /// f.
    pub prior: MonteCarloPriorShape,
    /// P_o (a constant) and g, as in `jdeBound`.
    pub observation: ObservationShape,
    /// Model I: `{ probability, density }` (q, ψ; the density must be one that draws: any of
    /// `jdeBound`'s); omitted: q = 0.
    #[tsify(optional)]
    pub false_alarm: Option<FalseAlarmShape>,
    /// Model II: `{ rate, density }` (λ, v/λ); omitted: λ = 0.
    #[tsify(optional)]
    pub clutter: Option<ClutterShape>, // model II only
    /// e_0² ≥ 0, the cost of a false target.
    pub false_alarm_error: f64,
    /// e_1² ≥ 0, the cost of a missed target.
    pub miss_error: f64,
    /// The rule on Z = ∅ (default `'optimal'`).
    #[tsify(optional)]
    pub empty_rule: Option<EmptyRuleShape>,
    /// k scans of one target, 1 to 5,000 (default 1; k > 1 needs a Gaussian prior and no
    /// false alarms or clutter): `result.scans[k − 1]` is the risk after scan k.
    #[tsify(optional)]
    pub scans: Option<usize>,
    /// Simulated scenes, 2 to 10^7 (default 20,000; samples × scans × (1 + ⌈q or λ⌉) at
    /// most 10^7).
    #[tsify(optional)]
    pub samples: Option<usize>,
    /// Seed (integer; omitted: fresh entropy, returned as `seed`).
    #[tsify(optional)]
    pub seed: Option<u64>,
}

// `jdeMonteCarlo` returns the core's own `fisst::bounds::JdeMonteCarlo` (its TypeScript is
// generated by build.rs from the core's source) under the contract's name.
#[wasm_bindgen(typescript_custom_section)]
const JDE_MONTE_CARLO_RESULT: &str = r#"
/**
 * Result of `jdeMonteCarlo`: the core's `JdeMonteCarlo`.
 */
export type JdeMonteCarloResult = JdeMonteCarlo;
"#;

/// The seeded Monte Carlo of the optimal joint detector-estimator of paper 002 (MAP
/// detection, the posterior mean; the core's `bounds::jde_monte_carlo`): the risk that
/// `jdeBound` bounds, with its parts and standard error. Options `{ model, existence, prior,
/// observation, falseAlarm?, clutter?, falseAlarmError, missError, emptyRule?, scans?,
/// samples?, seed? }`.
#[wasm_bindgen(js_name = jdeMonteCarlo, unchecked_return_type = "JdeMonteCarloResult")]
pub fn jde_monte_carlo(
    #[wasm_bindgen(unchecked_param_type = "JdeMonteCarloOptions")] options: JsValue,
) -> JsResult<JsValue> {
    let o: JdeMonteCarloOptions = read(options, "options")?;
    let samples = check_range(
        "options.samples",
        o.samples.unwrap_or(20_000),
        2,
        10_000_000,
    )?;
    let scans = check_range("options.scans", o.scans.unwrap_or(1), 1, bounds::MAX_STEPS)?;
    let (flat, false_density, clutter_density);
    let measurement = match (o.model, o.false_alarm, o.clutter) {
        (MeasurementModel::One, _, Some(_)) => {
            return Err(crate::boundary::type_error(
                "options.clutter is for model 'II' (use falseAlarm with model 'I')",
            ));
        }
        (MeasurementModel::Two, Some(_), _) => {
            return Err(crate::boundary::type_error(
                "options.falseAlarm is for model 'I' (use clutter with model 'II')",
            ));
        }
        (MeasurementModel::One, Some(f), None) => {
            false_density = f.density.into_core("options.falseAlarm.density")?;
            bounds::VectorMeasurement::I {
                false_alarm_probability: f.probability,
                false_alarm_density: &false_density,
            }
        }
        (MeasurementModel::Two, None, Some(c)) => {
            clutter_density = c.density.into_core("options.clutter.density")?;
            bounds::VectorMeasurement::II {
                clutter_rate: c.rate,
                clutter_density: &clutter_density,
            }
        }
        (_, None, None) => {
            flat = bounds::UnitUniform;
            bounds::VectorMeasurement::I {
                false_alarm_probability: 0.0,
                false_alarm_density: &flat,
            }
        }
    };
    let path = "options.prior";
    let (prior, sensor);
    let system = match o.prior {
        MonteCarloPriorShape::Example2 => match o.observation.detection_probability {
            DetectionShape::Constant(p) => bounds::SimulatedSystem::Example2 {
                detection_probability: p,
            },
            DetectionShape::Table(_) => {
                return Err(crate::boundary::type_error(
                    "options.observation.detectionProbability must be a number (a constant P_o) for 'example2'",
                ));
            }
        },
        shape => {
            prior = match shape {
                MonteCarloPriorShape::Gaussian(g) => {
                    let (mean, variance) = (g.mean, g.variance);
                    PriorShape::Gaussian(g).into_core(path)?;
                    bounds::GaussianPrior::new(&[mean], &[variance]).or_throw_in(path)?
                }
                MonteCarloPriorShape::MultivariateGaussian(g) => {
                    match PriorShape::MultivariateGaussian(g).into_core(path)? {
                        bounds::JdePrior::Vector(v) => v,
                        bounds::JdePrior::Scalar(_) => {
                            unreachable!("a multivariateGaussian is a vector")
                        }
                    }
                }
                MonteCarloPriorShape::Example2 => unreachable!("matched above"),
            };
            sensor = o
                .observation
                .into_sensor(prior.dims(), "options.observation")?;
            bounds::SimulatedSystem::LinearGaussian {
                prior: &prior,
                sensor: &sensor,
            }
        }
    };
    let seed = crate::boundary::seed_or_entropy(o.seed)?;
    let empty_rule = match o.empty_rule.unwrap_or(EmptyRuleShape::Optimal) {
        EmptyRuleShape::Optimal => bounds::EmptyRule::Optimal,
        EmptyRuleShape::Map => bounds::EmptyRule::Map,
        EmptyRuleShape::Declare => bounds::EmptyRule::Declare,
        EmptyRuleShape::Reject => bounds::EmptyRule::Reject,
    };
    let out = bounds::jde_monte_carlo(
        &bounds::MonteCarloModel {
            existence: o.existence,
            system,
            measurement,
            false_alarm_error: o.false_alarm_error,
            miss_error: o.miss_error,
        },
        &bounds::JdeMonteCarloOptions {
            samples,
            seed,
            empty_rule,
            scans,
        },
    )
    .or_throw_in("options")?;
    write(&Renamed::new(&out))
}
