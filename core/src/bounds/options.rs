//! The options of [`jde_bound`] and [`jde_monte_carlo`] as a user writes them (feature
//! `serde`), for the joint detection-estimation bounds of paper 002 (Rezaeian & Vo, "Error
//! bounds for joint detection and estimation of a single object with random finite set
//! observation"): [`JdeBoundOptions`] and [`JdeMonteCarloRequest`], with the prior
//! ([`PriorOptions`], [`MonteCarloPrior`]) and the observation ([`ObservationOptions`]) in
//! the forms the bindings take ("a number or an array", a covariance as rows, row-major
//! numbers or a bare variance).
//!
//! Each binding reads these types under its own names and calls [`JdeBoundOptions::run`] or
//! [`JdeMonteCarloRequest::run`]; the checks that need the options together (a 1D prior's
//! observation is a number gain, a Gaussian vector prior's is H with `noise_cov`, the false
//! observations of the model) are here, and their errors name the Rust field path
//! (`observation.noise_cov`, `prior.multivariate_gaussian.cov[1]`). A field of the wrong kind
//! for the others is an [`Error::Form`] with `wrong_kind` (a `TypeError` in the bindings).
//!
//! The defaults of the optional fields are those of [`JdeOptions`] (its `None`s: see
//! [`jde_bound`]) and of [`JdeMonteCarloOptions::default`], one place each.

use alloc::format;
use alloc::vec;
use alloc::vec::Vec;

use serde::{Deserialize, Deserializer, Serialize};

use crate::bounds::Density1;
use crate::bounds::{
    DensityOr, Detection, EmptyRule, GaussianPrior, JdeBoundReport, JdeClutter, JdeFalseAlarm,
    JdeModel, JdeMonteCarlo, JdeMonteCarloOptions, JdeObservation, JdeOptions, JdePrior,
    LinearGaussian, LinearGaussianSensor, MonteCarloModel, SimulatedSystem, UnitUniform,
    VectorMeasurement, check_measurement_dims, check_state_dims, deserialize_density_or, jde_bound,
    jde_monte_carlo, wrong_model,
};
use crate::error::{Error, Phrase, Result};
use crate::serde_shapes::{Covariance, ScalarOr, covariance_row_major};

/// A Gaussian N(mean, cov) in R^l as written: `mean` l finite numbers (1 ≤ l ≤ 64), `cov`
/// l rows of l numbers, l·l row-major numbers or (l = 1) a bare variance; symmetric positive
/// definite.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct GaussianOptions {
    /// The mean x0, l finite numbers (1 ≤ l ≤ 64).
    #[serde(serialize_with = "crate::serde_shapes::numbers::serialize")]
    pub mean: Vec<f64>,
    /// The covariance P, l × l, symmetric positive definite: l rows of l numbers, l·l
    /// row-major numbers or (l = 1) a bare variance.
    pub cov: Covariance,
}

impl GaussianOptions {
    /// The Gaussian prior of Section V (63); errors name `mean.length`, `mean[i]`, `cov`,
    /// `cov[i]` (relative to this value).
    ///
    /// # Errors
    /// [`check_state_dims`]'s, the covariance's form ([`Error::Form`]) and
    /// [`GaussianPrior::new`]'s.
    pub fn prior(self) -> Result<GaussianPrior> {
        let l = check_state_dims(self.mean.len())?;
        let cov = covariance_row_major(self.cov, l, "").map_err(|e| {
            Error::form(
                "cov",
                e.wrong_type,
                vec![Phrase::text(e.message.trim_start())],
            )
        })?;
        GaussianPrior::new(&self.mean, &cov)
    }
}

/// The prior f of [`JdeBoundOptions`]: a 1D density (`{"gaussian": …}`, `{"uniform": …}`,
/// `{"mixture": …}`, `{"table": …}`, a [`Density1`]) or, for a state in R^l,
/// `{"multivariate_gaussian": {mean, cov}}` (the vector bounds (63)–(72) of Section V).
#[derive(Clone, Debug, PartialEq)]
pub enum PriorOptions {
    /// A 1D density.
    Density(Density1),
    /// N(mean, cov) in R^l.
    MultivariateGaussian(GaussianOptions),
}

impl DensityOr for PriorOptions {
    const KINDS: &'static [&'static str] = &[
        "gaussian",
        "uniform",
        "mixture",
        "table",
        "multivariate_gaussian",
    ];
    fn density(d: Density1) -> Self {
        PriorOptions::Density(d)
    }
    fn other<'de, V: serde::de::VariantAccess<'de>>(kind: &str, v: V) -> Result<Self, V::Error> {
        match kind {
            "multivariate_gaussian" => v.newtype_variant().map(PriorOptions::MultivariateGaussian),
            _ => Err(serde::de::Error::unknown_variant(kind, Self::KINDS)),
        }
    }
}

impl<'de> Deserialize<'de> for PriorOptions {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        deserialize_density_or(d)
    }
}

// [`PriorOptions`] as written (and read, by [`deserialize_density_or`]); the JavaScript
// binding's TypeScript generator declares `PriorOptions` by this form (its `rename`).
/// The prior f of `jde_bound`: a 1D density (`{ gaussian }`, `{ uniform }`, `{ mixture }`,
/// `{ table }`) or, for a state in R^l, `{ multivariate_gaussian: { mean, cov } }` (the
/// vector bounds (63)–(72) of Section V).
#[derive(Serialize)]
#[serde(rename = "PriorOptions", untagged)]
enum PriorOptionsRepr<'a> {
    /// A 1D density (`Density1`).
    Density(&'a Density1),
    /// `{ multivariate_gaussian: { mean, cov } }`: N(mean, cov) in R^l.
    MultivariateGaussian {
        /// N(mean, cov) in R^l (1 ≤ l ≤ 64); the observation then has a constant P_o, gain
        /// rows H and `noise_cov`.
        multivariate_gaussian: &'a GaussianOptions,
    },
}

impl Serialize for PriorOptions {
    fn serialize<S: serde::Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        match self {
            PriorOptions::Density(d) => PriorOptionsRepr::Density(d),
            PriorOptions::MultivariateGaussian(g) => PriorOptionsRepr::MultivariateGaussian {
                multivariate_gaussian: g,
            },
        }
        .serialize(s)
    }
}

impl PriorOptions {
    /// The prior of [`JdeOptions`]; errors name `multivariate_gaussian.…` (relative to this
    /// value).
    ///
    /// # Errors
    /// [`GaussianOptions::prior`]'s.
    pub fn into_core(self) -> Result<JdePrior> {
        match self {
            PriorOptions::Density(d) => Ok(JdePrior::Scalar(d)),
            PriorOptions::MultivariateGaussian(g) => g
                .prior()
                .map(JdePrior::Vector)
                .map_err(|e| e.within("multivariate_gaussian")),
        }
    }
}

/// The detection probability P_o(x) as written: a number (a constant) or
/// `{"table": {x, probability}}` (linear interpolation, held constant beyond the end knots).
/// It is checked when the observation is built ([`Detection::constant`],
/// [`Detection::table`]), after the checks of its kind (a Gaussian vector prior and Example 2
/// take a constant only).
#[derive(Clone, Debug, PartialEq)]
pub enum JdeDetectionOptions {
    /// A constant P_o ∈ [0, 1].
    Constant(f64),
    /// A table of P_o at the knots `x` (strictly increasing, 2 to 10,000).
    Table {
        /// The knots.
        x: Vec<f64>,
        /// P_o ∈ [0, 1] at each knot.
        probability: Vec<f64>,
    },
}

/// A tabulated detection probability P_o(x), `{ x, probability }` (a table of
/// `JdeDetectionOptions`): linear interpolation, held constant beyond the end knots.
#[derive(Serialize, Deserialize)]
struct DetectionTable {
    /// The knots x, strictly increasing (2 to 10,000).
    #[serde(serialize_with = "crate::serde_shapes::numbers::serialize")]
    x: Vec<f64>,
    /// The detection probability P_o ∈ [0, 1] at each knot.
    #[serde(serialize_with = "crate::serde_shapes::numbers::serialize")]
    probability: Vec<f64>,
}

/// `{"table": {x, probability}}`, as read.
#[derive(Deserialize)]
struct DetectionTableWrapper {
    table: DetectionTable,
}

// [`JdeDetectionOptions`] as written (and read, by its `Deserialize`); the JavaScript
// binding's TypeScript generator declares `JdeDetectionOptions` by this form (its `rename`).
/// The detection probability P_o(x): a number in [0, 1] (a constant) or
/// `{ table: { x, probability } }`.
#[derive(Serialize)]
#[serde(rename = "JdeDetectionOptions", untagged)]
enum JdeDetectionRepr {
    /// A constant P_o ∈ [0, 1].
    Constant(f64),
    /// `{ table: { x, probability } }`: P_o tabulated at the knots x.
    Table {
        /// The knots and P_o at each.
        table: DetectionTable,
    },
}

impl Serialize for JdeDetectionOptions {
    fn serialize<S: serde::Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        match self {
            JdeDetectionOptions::Constant(p) => JdeDetectionRepr::Constant(*p),
            JdeDetectionOptions::Table { x, probability } => JdeDetectionRepr::Table {
                table: DetectionTable {
                    x: x.clone(),
                    probability: probability.clone(),
                },
            },
        }
        .serialize(s)
    }
}

impl<'de> Deserialize<'de> for JdeDetectionOptions {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        use serde::de::{MapAccess, Visitor, value::MapAccessDeserializer};
        struct V;
        impl<'de> Visitor<'de> for V {
            type Value = JdeDetectionOptions;
            fn expecting(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
                f.write_str("a probability or { table: { x, probability } }")
            }
            fn visit_f64<E: serde::de::Error>(self, p: f64) -> Result<Self::Value, E> {
                Ok(JdeDetectionOptions::Constant(p))
            }
            // self-describing formats other than JavaScript's (JSON, Python) give integers
            fn visit_i64<E: serde::de::Error>(self, p: i64) -> Result<Self::Value, E> {
                Ok(JdeDetectionOptions::Constant(p as f64))
            }
            fn visit_u64<E: serde::de::Error>(self, p: u64) -> Result<Self::Value, E> {
                Ok(JdeDetectionOptions::Constant(p as f64))
            }
            fn visit_map<A: MapAccess<'de>>(self, map: A) -> Result<Self::Value, A::Error> {
                let w = DetectionTableWrapper::deserialize(MapAccessDeserializer::new(map))?;
                Ok(JdeDetectionOptions::Table {
                    x: w.table.x,
                    probability: w.table.probability,
                })
            }
        }
        d.deserialize_any(V)
    }
}

impl JdeDetectionOptions {
    /// The checked [`Detection`]; errors name `detection_probability` or
    /// `detection_probability.table.x[i]`, `….probability[i]` (relative to the observation).
    ///
    /// # Errors
    /// [`Detection::constant`]'s or [`Detection::table`]'s.
    pub fn detection(&self) -> Result<Detection> {
        match self {
            JdeDetectionOptions::Constant(p) => Detection::constant(*p),
            JdeDetectionOptions::Table { x, probability } => Detection::table(x, probability)
                .map_err(|e| e.within("detection_probability.table")),
        }
    }
}

/// The observation: P_o(x) and g(z|x) = N(z; gain·x + offset, noise_variance) for a 1D prior,
/// or g(z|x) = N(z; H x + b, R) with H = `gain` (m rows of l numbers) and R = `noise_cov`
/// (or, for m = 1, `noise_variance`) for a Gaussian vector prior (Section V).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct ObservationOptions {
    /// The detection probability P_o(x): a number in [0, 1] or `{"table": {x, probability}}`
    /// (a Gaussian vector prior takes a constant only).
    pub detection_probability: JdeDetectionOptions,
    /// The gain a, a finite number (default 1); with a Gaussian vector prior H, m rows of l
    /// finite numbers (1 ≤ m ≤ 64; a number is H = `[[a]]` when l = 1). False alarms or clutter
    /// need m = 1: their densities are on the measurement line.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub gain: Option<ScalarOr<Vec<f64>>>,
    /// The offset b (default 0): a number, or with a Gaussian vector prior m numbers (a number
    /// serves m = 1; 0 serves any m).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub offset: Option<ScalarOr<f64>>,
    /// The measurement noise variance σ_v² > 0 of a one-coordinate measurement (required with
    /// a 1D prior; with a Gaussian vector prior give it or `noise_cov`, and only for m = 1).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub noise_variance: Option<f64>,
    /// The measurement noise covariance R, m × m, of a Gaussian vector prior's measurement:
    /// m rows of m numbers or m·m row-major numbers, symmetric positive definite.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub noise_cov: Option<Covariance>,
}

/// The default gain a = 1.
const DEFAULT_GAIN: f64 = 1.0;
/// The default offset b = 0.
const DEFAULT_OFFSET: f64 = 0.0;

fn text(s: impl Into<alloc::string::String>) -> Phrase {
    Phrase::text(s)
}

impl ObservationOptions {
    /// The 1D observation z = a x + b + v of a 1D prior (Theorems 1 and 2); errors name
    /// `gain`, `offset`, `noise_cov`, `noise_variance` and [`LinearGaussian::new`]'s fields
    /// (relative to this value).
    ///
    /// # Errors
    /// An [`Error::Form`] for rows given as the gain or the offset, a `noise_cov`, or no
    /// `noise_variance`; [`LinearGaussian::new`]'s.
    pub fn scalar(self) -> Result<LinearGaussian> {
        let gain = match self.gain.unwrap_or(ScalarOr::Scalar(DEFAULT_GAIN)) {
            ScalarOr::Scalar(a) => a,
            ScalarOr::Array(_) => {
                return Err(Error::form(
                    "gain",
                    true,
                    vec![
                        text("must be a number with a 1D prior (gain rows are H for a "),
                        Phrase::name("multivariate_gaussian"),
                        text(" prior)"),
                    ],
                ));
            }
        };
        let offset = match self.offset.unwrap_or(ScalarOr::Scalar(DEFAULT_OFFSET)) {
            ScalarOr::Scalar(b) => b,
            ScalarOr::Array(_) => {
                return Err(Error::form(
                    "offset",
                    true,
                    vec![text("must be a number with a 1D prior")],
                ));
            }
        };
        if self.noise_cov.is_some() {
            return Err(Error::form(
                "noise_cov",
                true,
                vec![
                    text("is for a "),
                    Phrase::name("multivariate_gaussian"),
                    text(" prior (use "),
                    Phrase::name("noise_variance"),
                    text(" with a 1D prior)"),
                ],
            ));
        }
        let Some(noise) = self.noise_variance else {
            return Err(Error::form(
                "noise_variance",
                true,
                vec![text("is required")],
            ));
        };
        LinearGaussian::new(self.detection_probability.detection()?, gain, offset, noise)
    }

    /// The constant P_o this observation needs with a Gaussian vector prior or Example 2;
    /// `for_what` ends the error's sentence.
    fn constant_detection(&self, for_what: Vec<Phrase>) -> Result<f64> {
        match self.detection_probability {
            JdeDetectionOptions::Constant(p) => Ok(p),
            JdeDetectionOptions::Table { .. } => {
                let mut problem = vec![text("must be a number (a constant P_o) ")];
                problem.extend(for_what);
                Err(Error::form("detection_probability", true, problem))
            }
        }
    }

    /// The linear-Gaussian sensor z = H x + b + v of a state in R^`dims` (Section V, (63));
    /// errors name `detection_probability`, `gain`, `gain[i]`, `offset`, `noise_variance`,
    /// `noise_cov` (relative to this value).
    ///
    /// # Errors
    /// An [`Error::Form`] for a tabulated P_o, a number gain for `dims` > 1, rows of other
    /// than `dims` numbers, an offset that does not fit the rows, both or neither of
    /// `noise_variance` and `noise_cov`, or `noise_variance` with more than one row;
    /// [`check_measurement_dims`]'s, the covariance's form and [`LinearGaussianSensor::new`]'s.
    pub fn sensor(self, dims: usize) -> Result<LinearGaussianSensor> {
        let detection = self.constant_detection(vec![
            text("with a "),
            Phrase::name("multivariate_gaussian"),
            text(" prior"),
        ])?;
        let rows = match self.gain.unwrap_or(ScalarOr::Scalar(DEFAULT_GAIN)) {
            ScalarOr::Scalar(a) if dims == 1 => vec![vec![a]],
            ScalarOr::Scalar(_) => {
                return Err(Error::form(
                    "gain",
                    true,
                    vec![text(format!(
                        "must be H, m rows of {dims} numbers, for a state in R^{dims}"
                    ))],
                ));
            }
            ScalarOr::Array(rows) => rows,
        };
        let m = rows.len();
        check_measurement_dims(m)?;
        for (i, r) in rows.iter().enumerate() {
            if r.len() != dims {
                return Err(Error::form(
                    format!("gain[{i}]"),
                    false,
                    vec![text(format!(
                        "has length {}, expected {dims} (the state dimension)",
                        r.len()
                    ))],
                ));
            }
        }
        let offset = match self.offset.unwrap_or(ScalarOr::Scalar(DEFAULT_OFFSET)) {
            ScalarOr::Scalar(b) if m == 1 => vec![b],
            ScalarOr::Scalar(0.0) => vec![0.0; m],
            ScalarOr::Scalar(_) => {
                return Err(Error::form(
                    "offset",
                    true,
                    vec![text(format!("must be {m} numbers (gain has {m} rows)"))],
                ));
            }
            ScalarOr::Array(v) => {
                if v.len() != m {
                    return Err(Error::form(
                        "offset",
                        false,
                        vec![text(format!(
                            "has length {}, expected {m} (gain has {m} rows)",
                            v.len()
                        ))],
                    ));
                }
                v
            }
        };
        let noise = match (self.noise_variance, self.noise_cov) {
            (Some(_), Some(_)) => {
                return Err(Error::form(
                    "noise_variance",
                    true,
                    vec![
                        text("and "),
                        Phrase::path("noise_cov"),
                        text(" are alternatives: give one"),
                    ],
                ));
            }
            (None, None) => {
                return Err(Error::form(
                    "noise_cov",
                    true,
                    vec![
                        text("is required (or "),
                        Phrase::name("noise_variance"),
                        text(" when gain has one row)"),
                    ],
                ));
            }
            (Some(v), None) => {
                if m != 1 {
                    return Err(Error::form(
                        "noise_variance",
                        true,
                        vec![
                            text(format!(
                                "serves a gain of one row; gain has {m} rows: give "
                            )),
                            Phrase::name("noise_cov"),
                            text(format!(" ({m} × {m})")),
                        ],
                    ));
                }
                // NaN fails too
                if v.partial_cmp(&0.0) != Some(core::cmp::Ordering::Greater) {
                    return Err(Error::parameter("noise_variance", v, "> 0"));
                }
                vec![v]
            }
            (None, Some(c)) => covariance_row_major(c, m, "").map_err(|e| {
                Error::form(
                    "noise_cov",
                    e.wrong_type,
                    vec![text(e.message.trim_start())],
                )
            })?,
        };
        LinearGaussianSensor::new(detection, &rows.concat(), dims, &offset, &noise)
    }
}

/// Options of [`jde_bound`] as a user writes them (Theorems 1 and 2 of paper 002 and their
/// vector extensions (63)–(72)) (in Rust, [`JdeBoundOptions::into_core`] makes the options).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct JdeBoundOptions {
    /// The measurement model: `"I"` (false alarms, (13)) or `"II"` (Poisson clutter, (22)).
    pub model: JdeModel,
    /// The prior existence probability r ∈ [0, 1]: the probability that the target exists.
    pub existence: f64,
    /// The prior density f of the state: a 1D density, or `{"multivariate_gaussian": {mean,
    /// cov}}` for a state in R^l (then the report holds the bound of each coordinate).
    pub prior: PriorOptions,
    /// The observation: the detection probability P_o and the likelihood g(z|x).
    pub observation: ObservationOptions,
    /// Model I: `{probability, density}` (q, ψ); omitted: q = 0. Not allowed with model II.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub false_alarm: Option<JdeFalseAlarm>,
    /// Model II: `{rate, density}` (λ, v/λ); omitted: λ = 0. Not allowed with model I.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub clutter: Option<JdeClutter>,
    /// The squared error e_0² ≥ 0 of a false target: the square itself (of the whole state;
    /// coordinate i of a vector state uses e_0²/l).
    pub false_alarm_error: f64,
    /// The squared error e_1² ≥ 0 of a missed target: the square itself (of the whole state;
    /// coordinate i of a vector state uses e_1²/l).
    pub miss_error: f64,
    /// The state dimension l, an integer in [1, 64] (default: 1 for a 1D prior, the length of
    /// `prior.multivariate_gaussian.mean` otherwise, which it must equal).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub dims: Option<usize>,
    /// The relative quadrature tolerance, in [1e-14, 0.1] (default 1e-10).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub tolerance: Option<f64>,
    /// Monte Carlo samples per cardinality n ≥ 2 (n ≥ 3 with `quadrature_cardinality` 2, the
    /// default for a linear-Gaussian model) (model II with clutter; 100 to 1,000,000, default
    /// 20,000; samples × Σ n at most 10^7).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub samples: Option<usize>,
    /// The seed of the Monte Carlo (omitted: fresh entropy, reported as `seed`).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub seed: Option<u64>,
    /// Model II with clutter: the largest |Z| = n integrated by deterministic quadrature, 1
    /// or 2 (also n = 2, by 2D cubature over Z², Theorem 2); default 2 for a linear-Gaussian
    /// model (Gaussian prior, constant P_o: 3–35 ms native), 1 otherwise (the general
    /// cubature takes seconds, not for sliders).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub quadrature_cardinality: Option<usize>,
}

impl JdeBoundOptions {
    /// The [`JdeOptions`] of [`jde_bound`]: the prior, and the observation of the prior's
    /// kind ([`ObservationOptions::scalar`] or [`ObservationOptions::sensor`]).
    ///
    /// # Errors
    /// [`PriorOptions::into_core`]'s under `prior`, the observation's under `observation`.
    pub fn into_core(self) -> Result<JdeOptions> {
        let prior = self.prior.into_core().map_err(|e| e.within("prior"))?;
        let observation = match &prior {
            JdePrior::Scalar(_) => self.observation.scalar().map(JdeObservation::Scalar),
            JdePrior::Vector(g) => self
                .observation
                .sensor(g.dims())
                .map(JdeObservation::Vector),
        }
        .map_err(|e| e.within("observation"))?;
        Ok(JdeOptions {
            model: self.model,
            existence: self.existence,
            prior,
            observation,
            false_alarm: self.false_alarm,
            clutter: self.clutter,
            false_alarm_error: self.false_alarm_error,
            miss_error: self.miss_error,
            dims: self.dims,
            tolerance: self.tolerance,
            samples: self.samples,
            seed: self.seed,
            quadrature_cardinality: self.quadrature_cardinality,
        })
    }

    /// [`jde_bound`] on these options, as its report; `entropy` gives the Monte Carlo seed
    /// when clutter is sampled and `seed` is omitted (see [`jde_bound`]).
    ///
    /// # Errors
    /// [`JdeBoundOptions::into_core`]'s and [`jde_bound`]'s.
    pub fn run(self, entropy: impl FnOnce() -> Result<u64>) -> Result<JdeBoundReport> {
        let options = self.into_core()?;
        jde_bound(&options, entropy).map(|out| JdeBoundReport::from(&out))
    }
}

/// The state of [`JdeMonteCarloRequest`]: `{"gaussian": {mean, variance}}`,
/// `{"multivariate_gaussian": {mean, cov}}` (a linear-Gaussian observation), or `"example2"`
/// (Example 2 (32): f(x) = 2x(eˣ − 1) on [0, 1] and g(z|x) = x e^{xz}/(eˣ − 1), with a
/// constant P_o).
#[derive(Clone, Debug, PartialEq)]
pub enum MonteCarloPrior {
    /// A 1D Gaussian N(mean, variance) (a [`Density1::Gaussian`]).
    Gaussian(Density1),
    /// N(mean, cov) in R^l.
    MultivariateGaussian(GaussianOptions),
    /// Example 2's f and g.
    Example2,
}

impl DensityOr for MonteCarloPrior {
    const KINDS: &'static [&'static str] = &["gaussian", "multivariate_gaussian", "example2"];
    fn density(d: Density1) -> Self {
        MonteCarloPrior::Gaussian(d)
    }
    fn other<'de, V: serde::de::VariantAccess<'de>>(kind: &str, v: V) -> Result<Self, V::Error> {
        match kind {
            "example2" => v.unit_variant().map(|()| MonteCarloPrior::Example2),
            "multivariate_gaussian" => v
                .newtype_variant()
                .map(MonteCarloPrior::MultivariateGaussian),
            _ => Err(serde::de::Error::unknown_variant(kind, Self::KINDS)),
        }
    }
}

impl<'de> Deserialize<'de> for MonteCarloPrior {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        deserialize_density_or(d)
    }
}

// [`MonteCarloPrior`] as written (and read, by [`deserialize_density_or`], which also takes
// the other 1D densities, for [`JdeMonteCarloRequest::run`] to refuse: they are written as
// their [`Density1`]); the JavaScript binding's TypeScript generator declares
// `MonteCarloPrior` by this form (its `rename`).
/// The state of `jde_monte_carlo`: `{ gaussian: { mean, variance } }`,
/// `{ multivariate_gaussian: { mean, cov } }` (a linear-Gaussian `observation`), or
/// `'example2'` (Example 2 (32): f and g fixed, `observation.detection_probability` a
/// constant P_o).
#[derive(Serialize)]
#[serde(rename = "MonteCarloPrior", rename_all = "snake_case")]
enum MonteCarloPriorRepr<'a> {
    /// `{ gaussian: { mean, variance } }`: N(mean, variance) on the line.
    Gaussian {
        /// The mean, a finite number.
        mean: f64,
        /// The variance, > 0.
        variance: f64,
    },
    /// `{ multivariate_gaussian: { mean, cov } }`: N(mean, cov) in R^l (1 ≤ l ≤ 64), with a
    /// linear-Gaussian `observation`.
    MultivariateGaussian(&'a GaussianOptions),
    /// `'example2'`: Example 2 (32), f(x) = 2x(eˣ − 1) on [0, 1] with
    /// g(z|x) = x e^{xz}/(eˣ − 1).
    Example2,
}

impl Serialize for MonteCarloPrior {
    fn serialize<S: serde::Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        match self {
            &MonteCarloPrior::Gaussian(Density1::Gaussian { mean, variance }) => {
                MonteCarloPriorRepr::Gaussian { mean, variance }
            }
            MonteCarloPrior::Gaussian(d) => return d.serialize(s),
            MonteCarloPrior::MultivariateGaussian(g) => {
                MonteCarloPriorRepr::MultivariateGaussian(g)
            }
            MonteCarloPrior::Example2 => MonteCarloPriorRepr::Example2,
        }
        .serialize(s)
    }
}

/// Options of [`jde_monte_carlo`] as a user writes them: the problem of [`JdeBoundOptions`]
/// (Gaussian priors and Example 2), the rule on Z = ∅, the number of scans and the Monte
/// Carlo's size and seed (in Rust, [`JdeMonteCarloRequest::run`] runs it).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct JdeMonteCarloRequest {
    /// The measurement model, `"I"` or `"II"`.
    pub model: JdeModel,
    /// The prior existence probability r ∈ [0, 1]: the probability that the target exists.
    pub existence: f64,
    /// The prior density f of the target's state.
    pub prior: MonteCarloPrior,
    /// The observation: a constant detection probability P_o and the likelihood g, as in
    /// [`JdeBoundOptions`].
    pub observation: ObservationOptions,
    /// Model I: `{probability, density}` (q, ψ; a density that draws); omitted: q = 0.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub false_alarm: Option<JdeFalseAlarm>,
    /// Model II: `{rate, density}` (λ, v/λ); omitted: λ = 0.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub clutter: Option<JdeClutter>,
    /// The squared error (cost) e_0² ≥ 0 of a false target: the square itself.
    pub false_alarm_error: f64,
    /// The squared error (cost) e_1² ≥ 0 of a missed target: the square itself.
    pub miss_error: f64,
    /// The rule on Z = ∅ (default `"optimal"`).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub empty_rule: Option<EmptyRule>,
    /// The number k of scans of one target, 1 to 5,000 (default 1; k > 1 needs a Gaussian
    /// prior and no false alarms or clutter).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub scans: Option<usize>,
    /// The number of simulated scenes, 2 to 10^7 (default 20,000; samples × scans ×
    /// (1 + ⌈q or λ⌉) at most 10^7).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub samples: Option<usize>,
    /// The seed of the Monte Carlo (omitted: fresh entropy, reported as `seed`).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub seed: Option<u64>,
}

impl JdeMonteCarloRequest {
    /// The seeded Monte Carlo of the optimal joint detector-estimator ([`jde_monte_carlo`]:
    /// MAP detection (39)/(40), the posterior mean, the rule on Z = ∅), the risk (11) that
    /// [`jde_bound`] bounds. `entropy` gives the seed when `seed` is omitted (it is reported
    /// in the result).
    ///
    /// # Errors
    /// [`wrong_model`]'s for false observations of the other model; an [`Error::Form`]
    /// naming `observation.detection_probability` for a tabulated P_o with `"example2"`, or
    /// an [`Error::Unsupported`] naming `prior` for a 1D density other than a Gaussian; the
    /// prior's under `prior`, the observation's under `observation`; `entropy`'s; and
    /// [`jde_monte_carlo`]'s.
    pub fn run(self, entropy: impl FnOnce() -> Result<u64>) -> Result<JdeMonteCarlo> {
        let flat = UnitUniform;
        let measurement = match (self.model, &self.false_alarm, &self.clutter) {
            (JdeModel::I, _, Some(_)) => return Err(wrong_model(true)),
            (JdeModel::II, Some(_), _) => return Err(wrong_model(false)),
            (JdeModel::I, Some(f), None) => VectorMeasurement::I {
                false_alarm_probability: f.probability,
                false_alarm_density: &f.density,
            },
            (JdeModel::II, None, Some(c)) => VectorMeasurement::II {
                clutter_rate: c.rate,
                clutter_density: &c.density,
            },
            (_, None, None) => VectorMeasurement::I {
                false_alarm_probability: 0.0,
                false_alarm_density: &flat,
            },
        };
        let (prior, sensor);
        let system = match self.prior {
            MonteCarloPrior::Example2 => SimulatedSystem::Example2 {
                detection_probability: self
                    .observation
                    .constant_detection(vec![text("for 'example2'")])
                    .map_err(|e| e.within("observation"))?,
            },
            shape => {
                prior = match shape {
                    MonteCarloPrior::Gaussian(Density1::Gaussian { mean, variance }) => {
                        GaussianPrior::new(&[mean], &[variance])
                    }
                    MonteCarloPrior::Gaussian(_) => Err(Error::Unsupported {
                        what: "".into(),
                        reason: "the Monte Carlo takes a gaussian, multivariate_gaussian or example2 prior",
                    }),
                    MonteCarloPrior::MultivariateGaussian(g) => g
                        .prior()
                        .map_err(|e| e.within("multivariate_gaussian")),
                    MonteCarloPrior::Example2 => unreachable!("matched above"),
                }
                .map_err(|e| e.within("prior"))?;
                sensor = self
                    .observation
                    .sensor(prior.dims())
                    .map_err(|e| e.within("observation"))?;
                SimulatedSystem::LinearGaussian {
                    prior: &prior,
                    sensor: &sensor,
                }
            }
        };
        let defaults = JdeMonteCarloOptions::default();
        let seed = match self.seed {
            Some(s) => s,
            None => entropy()?,
        };
        jde_monte_carlo(
            &MonteCarloModel {
                existence: self.existence,
                system,
                measurement,
                false_alarm_error: self.false_alarm_error,
                miss_error: self.miss_error,
            },
            &JdeMonteCarloOptions {
                samples: self.samples.unwrap_or(defaults.samples),
                seed,
                empty_rule: self.empty_rule.unwrap_or(defaults.empty_rule),
                scans: self.scans.unwrap_or(defaults.scans),
            },
        )
    }
}
