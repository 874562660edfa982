//! One entry point to the joint detection-estimation bounds of paper 002 (Rezaeian & Vo):
//! [`jde_bound`] takes a [`JdeOptions`] (model I or II, a scalar or a Gaussian vector prior,
//! the observation, the errors and the numerical settings), checks the options that only
//! make sense together (model against false observations, `dims` against the prior, the
//! integer ranges, and Theorem 2's Monte Carlo work cap), and dispatches to Theorem 1
//! ([`theorem1`], (14)–(21)), Theorem 2 ([`theorem2`], (22)–(26)) or their vector extensions
//! (63)–(72) ([`vector_bound`]).
//!
//! The bindings only convert their arguments into a [`JdeOptions`] and the
//! [`JdeBoundOutcome`] back; the errors name the Rust field paths (`samples`,
//! `quadrature_cardinality`, `clutter`, `dims`), which each binding renders in its own names.

use alloc::vec::Vec;

use crate::bounds::{
    Cardinality, ComponentBound, Density1, GaussianPrior, JdeBound, LinearGaussian,
    LinearGaussianSensor, Method, ModelI, ModelII, Phase, Terms, TheoremOptions, VectorMeasurement,
    VectorModel, is_linear_gaussian, poisson_pmf, theorem1, theorem2, vector_bound,
};
use crate::error::{Error, Phrase, Result};

/// At most this many state coordinates l (and measurement coordinates m).
pub const MAX_DIMS: usize = 64;

/// Monte Carlo samples per cardinality: at least this many …
pub const MIN_SAMPLES: usize = 100;
/// … and at most this many.
pub const MAX_SAMPLES: usize = 1_000_000;
/// Theorem 2's Monte Carlo work cap: samples × Σ n over the sampled cardinalities n.
pub const MAX_SAMPLE_POINTS: usize = 10_000_000;

/// The measurement model: I (13), a Bernoulli observation with false alarms (Theorem 1), or
/// II (22), Poisson clutter (Theorem 2). Serialised as `"I"` or `"II"`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub enum JdeModel {
    /// Model I (13): a Bernoulli observation with false alarms.
    I,
    /// Model II (22): Poisson clutter.
    II,
}

/// The prior f: a 1D density, or N(x0, P) for a state in R^l (Section V).
#[derive(Clone, Debug, PartialEq)]
pub enum JdePrior {
    /// A 1D density.
    Scalar(Density1),
    /// A Gaussian state in R^l.
    Vector(GaussianPrior),
}

/// P_o and g: a 1D linear-Gaussian observation for a [`JdePrior::Scalar`], a
/// linear-Gaussian sensor (constant P_o) for a [`JdePrior::Vector`].
#[derive(Clone, Debug, PartialEq)]
pub enum JdeObservation {
    /// A 1D linear-Gaussian observation z = a x + b + v.
    Scalar(LinearGaussian),
    /// A vector linear-Gaussian observation z = H x + b + v.
    Vector(LinearGaussianSensor),
}

/// Model I's false observations: probability q and density ψ.
#[derive(Clone, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct JdeFalseAlarm {
    /// The false alarm probability q ∈ [0, 1]: the probability of one false observation.
    pub probability: f64,
    /// The density ψ of a false observation.
    pub density: Density1,
}

/// Model II's Poisson clutter: rate λ and the density of its points (v = λ · density).
#[derive(Clone, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct JdeClutter {
    /// The clutter rate λ ≥ 0: the mean number of clutter points.
    pub rate: f64,
    /// The density v/λ of one clutter point (v the clutter intensity).
    pub density: Density1,
}

/// Everything [`jde_bound`] needs. The optional fields take their defaults when `None`.
#[derive(Clone, Debug, PartialEq)]
pub struct JdeOptions {
    /// The measurement model: I (false alarms) or II (Poisson clutter).
    pub model: JdeModel,
    /// The prior existence probability r ∈ [0, 1]: the probability that the target exists.
    pub existence: f64,
    /// The prior density f of the target's state.
    pub prior: JdePrior,
    /// The observation: the detection probability P_o and the likelihood g (of the prior's kind).
    pub observation: JdeObservation,
    /// Model I: (q, ψ); `None`: q = 0. An error with model II.
    pub false_alarm: Option<JdeFalseAlarm>,
    /// Model II: (λ, v/λ); `None`: λ = 0. An error with model I.
    pub clutter: Option<JdeClutter>,
    /// e_0² ≥ 0, the squared error of a false target: the square itself (of the whole state;
    /// coordinate i of a vector state uses e_0²/l).
    pub false_alarm_error: f64,
    /// e_1² ≥ 0, the squared error of a missed target: the square itself (of the whole state;
    /// coordinate i of a vector state uses e_1²/l).
    pub miss_error: f64,
    /// l, in [1, [`MAX_DIMS`]]; must be 1 for a scalar prior and the prior's dimension for a
    /// vector one (default: the prior's).
    pub dims: Option<usize>,
    /// Relative quadrature tolerance (default [`TheoremOptions::default`]'s 1e-10).
    pub tolerance: Option<f64>,
    /// Monte Carlo samples per sampled cardinality (model II with clutter), in
    /// [[`MIN_SAMPLES`], [`MAX_SAMPLES`]] with samples × Σ n ≤ [`MAX_SAMPLE_POINTS`]
    /// (default 20,000).
    pub samples: Option<usize>,
    /// Seed of the Monte Carlo (default: fresh entropy, see [`jde_bound`]).
    pub seed: Option<u64>,
    /// The largest |Z| = n integrated by deterministic quadrature, 1 or 2 (default: 2 for a
    /// linear-Gaussian model, 1 otherwise; see [`TheoremOptions::quadrature_cardinality`]).
    pub quadrature_cardinality: Option<usize>,
}

impl JdeOptions {
    /// The options with every optional field `None`.
    pub fn new(
        model: JdeModel,
        existence: f64,
        prior: JdePrior,
        observation: JdeObservation,
        false_alarm_error: f64,
        miss_error: f64,
    ) -> Self {
        JdeOptions {
            model,
            existence,
            prior,
            observation,
            false_alarm: None,
            clutter: None,
            false_alarm_error,
            miss_error,
            dims: None,
            tolerance: None,
            samples: None,
            seed: None,
            quadrature_cardinality: None,
        }
    }
}

/// What [`jde_bound`] returns.
#[derive(Clone, Debug, PartialEq)]
pub struct JdeBoundOutcome {
    /// The bound of Theorem 1 or 2 (a vector state: of the whole state, (63)–(65)).
    pub bound: JdeBound,
    /// A vector state only: the bound of each coordinate (63)/(64), (70)–(72).
    pub components: Option<Vec<ComponentBound>>,
    /// A vector state only: J'_1⁻¹ (model I) or Σ_n C_n J'_{1+n}⁻¹ (model II), l rows of l.
    pub inverse_information: Option<Vec<Vec<f64>>>,
    /// The Monte Carlo seed used (model II with clutter sampled only).
    pub seed: Option<u64>,
}

/// The false observations after the model check.
enum FalseObservations {
    I { q: f64, psi: Density1 },
    II { lambda: f64, c: Density1 },
}

/// Theorems 1 and 2 of paper 002 and their vector extensions (63)–(72), chosen by
/// `options.model` and the prior's kind.
///
/// `entropy` gives the Monte Carlo seed when clutter is sampled and `options.seed` is `None`
/// (it is not called otherwise): with `std`, pass
/// [`entropy_seed`](crate::math::rng::entropy_seed); without, a closure returning an error or
/// a seed of your own. The seed used is returned in [`JdeBoundOutcome::seed`].
///
/// # Errors
/// [`Error::OutOfRange`] naming `dims`, `quadrature_cardinality` or `samples`;
/// [`Error::Form`] naming `dims` when it is not the prior's dimension (1 for a scalar prior:
/// it says that a state in R^l needs a `multivariate_gaussian` prior); [`Error::Form`] ([`wrong_model`]) naming `clutter` with model I or `false_alarm` with
/// model II; [`Error::Unsupported`] naming `observation` when its kind is not the prior's;
/// [`Error::OverBudget`] naming `samples` when samples × Σ n exceeds 10^7; `entropy`'s
/// error; and the errors of [`theorem1`], [`theorem2`] and [`vector_bound`].
pub fn jde_bound(
    options: &JdeOptions,
    entropy: impl FnOnce() -> Result<u64>,
) -> Result<JdeBoundOutcome> {
    let o = options;
    if let Some(l) = o.dims {
        Error::check_range("dims", l, 1, MAX_DIMS)?;
        let but = Phrase::text(alloc::format!("is {l}, but "));
        let problem = match &o.prior {
            JdePrior::Scalar(_) if l != 1 => Some(alloc::vec![
                but,
                Phrase::path("prior"),
                Phrase::text(alloc::format!(" is a 1D density: a state in R^{l} needs ")),
                Phrase::name("prior"),
                Phrase::text(": { "),
                Phrase::name("multivariate_gaussian"),
                Phrase::text(": { mean, cov } }"),
            ]),
            JdePrior::Vector(g) if l != g.dims() => Some(alloc::vec![
                but,
                Phrase::path("prior.multivariate_gaussian.mean"),
                Phrase::text(alloc::format!(" has length {}", g.dims())),
            ]),
            _ => None,
        };
        if let Some(problem) = problem {
            return Err(Error::form("dims", false, problem));
        }
    }
    let mut settings = TheoremOptions::default();
    if let Some(t) = o.tolerance {
        settings.tolerance = t;
    }
    if let Some(k) = o.quadrature_cardinality {
        settings.quadrature_cardinality = Error::check_range("quadrature_cardinality", k, 1, 2)?;
    }
    let unit = || Density1::uniform(0.0, 1.0);
    let (false_obs, seed) = match o.model {
        JdeModel::I => {
            if o.clutter.is_some() {
                return Err(wrong_model(true));
            }
            let (q, psi) = match &o.false_alarm {
                Some(f) => (f.probability, f.density.clone()),
                None => (0.0, unit()?),
            };
            (FalseObservations::I { q, psi }, None)
        }
        JdeModel::II => {
            if o.false_alarm.is_some() {
                return Err(wrong_model(false));
            }
            let (lambda, c) = match &o.clutter {
                Some(c) => (c.rate, c.density.clone()),
                None => (0.0, unit()?),
            };
            // the vector path is rank-one over a Gaussian prior and a constant P_o, or clutter-free
            let linear_gaussian = match (&o.prior, &o.observation) {
                (JdePrior::Scalar(prior), JdeObservation::Scalar(obs)) => {
                    is_linear_gaussian(prior, obs)
                }
                _ => true,
            };
            let seed = monte_carlo_settings(
                &mut settings,
                linear_gaussian,
                lambda,
                o.samples,
                o.seed,
                entropy,
            )?;
            (FalseObservations::II { lambda, c }, seed)
        }
    };
    match (&o.prior, &o.observation) {
        (JdePrior::Scalar(prior), JdeObservation::Scalar(obs)) => {
            let bound = match &false_obs {
                FalseObservations::I { q, psi } => theorem1(
                    &ModelI {
                        existence: o.existence,
                        prior,
                        observation: obs,
                        false_alarm_probability: *q,
                        false_alarm_density: psi,
                        false_alarm_error: o.false_alarm_error,
                        miss_error: o.miss_error,
                    },
                    &settings,
                ),
                FalseObservations::II { lambda, c } => theorem2(
                    &ModelII {
                        existence: o.existence,
                        prior,
                        observation: obs,
                        clutter_rate: *lambda,
                        clutter_density: c,
                        false_alarm_error: o.false_alarm_error,
                        miss_error: o.miss_error,
                    },
                    &settings,
                ),
            }?;
            Ok(JdeBoundOutcome {
                bound,
                components: None,
                inverse_information: None,
                seed,
            })
        }
        (JdePrior::Vector(prior), JdeObservation::Vector(sensor)) => {
            let measurement = match &false_obs {
                FalseObservations::I { q, psi } => VectorMeasurement::I {
                    false_alarm_probability: *q,
                    false_alarm_density: psi,
                },
                FalseObservations::II { lambda, c } => VectorMeasurement::II {
                    clutter_rate: *lambda,
                    clutter_density: c,
                },
            };
            let v = vector_bound(
                &VectorModel {
                    existence: o.existence,
                    prior,
                    sensor,
                    measurement,
                    false_alarm_error: o.false_alarm_error,
                    miss_error: o.miss_error,
                },
                &settings,
            )?;
            let l = prior.dims();
            Ok(JdeBoundOutcome {
                bound: v.total,
                components: Some(v.components),
                inverse_information: Some(
                    v.inverse_information
                        .chunks(l)
                        .map(<[f64]>::to_vec)
                        .collect(),
                ),
                seed,
            })
        }
        _ => Err(Error::Unsupported {
            what: "observation".into(),
            reason: "must be of the prior's kind (a scalar observation for a 1D prior, a sensor for a Gaussian vector prior)",
        }),
    }
}

/// The [`Error::Form`] (a wrong kind) of `clutter` given with model I (`clutter` true) or
/// `false_alarm` with model II: each belongs to the other measurement model ((13) or (22)).
pub fn wrong_model(clutter: bool) -> Error {
    let (what, model, other, other_model) = if clutter {
        ("clutter", "II", "false_alarm", "I")
    } else {
        ("false_alarm", "I", "clutter", "II")
    };
    Error::form(
        what,
        true,
        alloc::vec![
            Phrase::text(alloc::format!("is for model '{model}' (use ")),
            Phrase::name(other),
            Phrase::text(alloc::format!(" with model '{other_model}')")),
        ],
    )
}

/// The Monte Carlo budget of model II (Theorem 2): `samples` × Σ n over the cardinalities it
/// samples (n = 2 … N + 1, or n = 3 … with the n = 2 cubature, N the last clutter count
/// the Poisson series keeps) at most [`MAX_SAMPLE_POINTS`]. Sets `settings.samples` and
/// `settings.seed` and returns the seed used when clutter is sampled at all.
fn monte_carlo_settings(
    settings: &mut TheoremOptions,
    linear_gaussian: bool,
    lambda: f64,
    samples: Option<usize>,
    seed: Option<u64>,
    entropy: impl FnOnce() -> Result<u64>,
) -> Result<Option<u64>> {
    let samples = Error::check_range(
        "samples",
        samples.unwrap_or(settings.samples),
        MIN_SAMPLES,
        MAX_SAMPLES,
    )?;
    settings.samples = samples;
    // N, the last clutter count kept
    let mut last = 0usize;
    let mut kept = poisson_pmf(lambda.max(0.0), 0);
    while lambda.is_finite()
        && 1.0 - kept > settings.series_tolerance
        && last < settings.max_clutter
    {
        last += 1;
        kept += poisson_pmf(lambda, last);
    }
    let first = if settings.quadrature_cardinality_for(linear_gaussian) >= 2 {
        3
    } else {
        2
    };
    let points: usize = (first..=last + 1).sum();
    Error::check_work(
        "samples",
        "samples × Σ n",
        "10^7 at this clutter rate; pass fewer samples",
        points,
        samples,
        MAX_SAMPLE_POINTS,
    )?;
    let seed = if last > 0 {
        Some(match seed {
            Some(s) => s,
            None => entropy()?,
        })
    } else {
        None
    };
    settings.seed = seed.unwrap_or(0);
    Ok(seed)
}

#[cfg(test)]
#[path = "jde_tests.rs"]
mod tests;

/// One summand of the bound (17) or (23) of paper 002, named.
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct BoundTerm {
    /// Which summand: the estimation error, the undetected target, the missed detection or
    /// the false target.
    pub name: TermName,
    /// The summand's value (a squared error, ≥ 0).
    pub value: f64,
}

/// The summands of (17)/(23) of paper 002 ([`Terms`]), in the paper's order; written
/// `"estimation"`, `"undetected"`, `"missed"`, `"falseTarget"`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "serde", serde(rename_all = "camelCase"))]
pub enum TermName {
    /// r P̄_o J'_1⁻¹ (17), or r P̄_o Σ_n C_n J'_{1+n}⁻¹ (23).
    Estimation,
    /// r (1 − P̄_o)(1 − μ) σ_e²: an undetected target estimated by x*.
    Undetected,
    /// r (μ (1 − P̄_o) + P̄_o − P̄_o w) e_1²: a target declared absent.
    Missed,
    /// (1 − r)(1 − μ') e_0²: a target declared where none exists.
    FalseTarget,
}

impl BoundTerm {
    /// The four summands of `t` in the paper's order.
    pub fn all(t: &Terms) -> Vec<BoundTerm> {
        [
            (TermName::Estimation, t.estimation),
            (TermName::Undetected, t.undetected),
            (TermName::Missed, t.missed),
            (TermName::FalseTarget, t.false_target),
        ]
        .map(|(name, value)| BoundTerm { name, value })
        .into()
    }
}

/// The n-point part of Theorem 2 of paper 002 (model I: only n = 1), as [`JdeBoundReport`]
/// gives it: a [`Cardinality`] without the error estimates of `w` and `clutter_null`.
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct CardinalityTerm {
    /// The number of observed points n = |Z|.
    pub n: usize,
    /// The probability C_{n−1} of n − 1 clutter points.
    pub probability: f64,
    /// The mass w_n (20)/(25) of p_n on the MAP region, in [0, 1].
    pub w: f64,
    /// The inverse information J'_n⁻¹ (with the 1/w_n² of (20)/(25)); for a vector state its
    /// trace.
    pub inverse_information: f64,
    /// The probability that the detector rejects n clutter-only points.
    pub clutter_null: f64,
    /// `'quadrature'`, `'monte-carlo'` or (a vector state without false observations)
    /// `'closed-form'`.
    pub method: Method,
    /// The error estimate of `inverse_information` (Monte Carlo: one standard error).
    pub error: f64,
}

impl From<&Cardinality> for CardinalityTerm {
    fn from(c: &Cardinality) -> Self {
        CardinalityTerm {
            n: c.n,
            probability: c.probability,
            w: c.w,
            inverse_information: c.inverse_information,
            clutter_null: c.clutter_null,
            method: c.method,
            error: c.error,
        }
    }
}

/// The bound (63)/(64) of paper 002 on the mean-square error σ_i² of one coordinate x_i of
/// a vector state, with the component metric e_i (e_i(∅, {x'}) = e_0/√l, e_i({x}, ∅) =
/// e_1/√l): a [`ComponentBound`] flattened.
#[derive(Clone, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct JdeComponentBound {
    /// The lower bound on E e_i²: the smaller of `hpe` and `lpe`.
    pub bound: f64,
    /// This coordinate's rule on Z = ∅ (each coordinate may pick its own).
    pub phase: Phase,
    /// The existence threshold r* of this coordinate (72): e_0²/(e_0² + (1 − P̄o)(e_1² − l
    /// σ_{e,i}²)) without false observations (may exceed 1; `Infinity` when HPE never wins).
    pub existence_threshold: f64,
    /// The summands of (63)/(64) for this coordinate, named as the top-level `terms`.
    pub terms: Vec<BoundTerm>,
    /// The error estimate of `bound` (quadrature, one Monte Carlo standard error).
    pub error: f64,
    /// The HPE bound of this coordinate: the estimator declares {x*} on Z = ∅.
    pub hpe: f64,
    /// The LPE bound of this coordinate: the estimator declares ∅ on Z = ∅.
    pub lpe: f64,
    /// The estimation term of this coordinate: [J'_1⁻¹]_ii (63), or Σ_n C_n [J'_{1+n}⁻¹]_ii
    /// (64).
    pub inverse_information: f64,
    /// The prior mean x*_i of this coordinate (P_o is constant, so f_d' = f).
    pub undetected_mean: f64,
    /// The prior variance σ_{e,i}² = P_ii of this coordinate.
    pub undetected_variance: f64,
}

impl From<&ComponentBound> for JdeComponentBound {
    fn from(c: &ComponentBound) -> Self {
        let a = &c.assembled;
        JdeComponentBound {
            bound: a.bound,
            phase: a.phase,
            existence_threshold: a.existence_threshold,
            terms: BoundTerm::all(&a.terms),
            error: c.error,
            hpe: a.hpe,
            lpe: a.lpe,
            inverse_information: c.inverse_information,
            undetected_mean: c.undetected_mean,
            undetected_variance: c.undetected_variance,
        }
    }
}

/// The bound of Theorem 1 or 2 of paper 002 with its parts, flattened from a
/// [`JdeBoundOutcome`] (what the bindings' `jdeBound` / `jde_bound` return).
#[derive(Clone, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct JdeBoundReport {
    /// The lower bound on E e²(X, X̂(Z)) (a valid one only when `regular`); for a vector
    /// state with the Euclidean metric, one rule on Z = ∅ for the whole state (≥ the sum of
    /// `components[i].bound`, which may each pick their own rule).
    pub bound: f64,
    /// The rule on Z = ∅ of the bound's estimator: `'HPE'` declares {x*}, `'LPE'` declares ∅.
    pub phase: Phase,
    /// The existence threshold r* (18)/(24) above which HPE wins (may exceed 1; `Infinity`
    /// when HPE never wins).
    pub existence_threshold: f64,
    /// The summands of (17)/(23) in order: estimation, undetected, missed, falseTarget.
    pub terms: Vec<BoundTerm>,
    /// The error estimate of `bound` (quadrature, one Monte Carlo standard error).
    pub error: f64,
    /// The HPE bound: the estimator declares {x*} on Z = ∅.
    pub hpe: f64,
    /// The LPE bound: the estimator declares ∅ on Z = ∅.
    pub lpe: f64,
    /// The mean detection probability P̄_o (14) = ∫ P_o(x) f(x) dx, in [0, 1].
    pub mean_detection: f64,
    /// The mean x* of f_d', an undetected target's state (a vector state: of its first
    /// coordinate; see `components[i].undetected_mean`).
    pub undetected_mean: f64,
    /// The variance σ_e² (16) of an undetected target's state, the variance of f_d' (a
    /// vector state: tr P).
    pub undetected_variance: f64,
    /// The probability that a target-free observation is declared empty, Pr(Z ≠ ∅, declared
    /// ∅ | X = ∅): η1 (model I) or η2 (model II).
    pub eta: f64,
    /// The MAP region of one-point observations, `[low, high]` intervals (a vector state: of
    /// the measurement line; empty when the gain has more than one row, where there are no
    /// false observations and every measurement is kept).
    pub region: Vec<(f64, f64)>,
    /// The n-point parts of Theorem 2, one per cardinality n = |Z| (model I: only n = 1).
    pub cardinalities: Vec<CardinalityTerm>,
    /// Whether the bound is regular: false when f·P_o does not vanish at the prior's support
    /// ends (uniform, tables ending above 0): the information inequality's regularity fails,
    /// the estimation term may not be a bound.
    pub regular: bool,
    /// The Monte Carlo seed used (model II with clutter only).
    #[cfg_attr(
        feature = "serde",
        serde(default, skip_serializing_if = "Option::is_none")
    )]
    pub seed: Option<u64>,
    /// A vector state only: the bound of each coordinate x_i, i = 0 … l − 1 ((63)/(64),
    /// (70)–(72)).
    #[cfg_attr(
        feature = "serde",
        serde(default, skip_serializing_if = "Option::is_none")
    )]
    pub components: Option<Vec<JdeComponentBound>>,
    /// A vector state only: J'_1⁻¹ (model I), or Σ_n C_n J'_{1+n}⁻¹ (model II), l rows of
    /// l numbers, whose diagonal enters `components[i]`'s estimation term (without false
    /// observations, (P⁻¹ + HᵀR⁻¹H)⁻¹, the posterior covariance).
    #[cfg_attr(
        feature = "serde",
        serde(default, skip_serializing_if = "Option::is_none")
    )]
    pub inverse_information_matrix: Option<Vec<Vec<f64>>>,
}

impl From<&JdeBoundOutcome> for JdeBoundReport {
    fn from(o: &JdeBoundOutcome) -> Self {
        let b = &o.bound;
        let a = &b.assembled;
        JdeBoundReport {
            bound: a.bound,
            phase: a.phase,
            existence_threshold: a.existence_threshold,
            terms: BoundTerm::all(&a.terms),
            error: b.error,
            hpe: a.hpe,
            lpe: a.lpe,
            mean_detection: b.mean_detection,
            undetected_mean: b.undetected_mean,
            undetected_variance: b.undetected_variance,
            eta: b.eta,
            region: b.region.clone(),
            cardinalities: b.cardinalities.iter().map(CardinalityTerm::from).collect(),
            regular: b.regular,
            seed: o.seed,
            components: o
                .components
                .as_ref()
                .map(|c| c.iter().map(JdeComponentBound::from).collect()),
            inverse_information_matrix: o.inverse_information.clone(),
        }
    }
}
