//! The closed forms of paper 002: the assembly of (17)/(21) and (23)–(24) from their
//! ingredients, Corollaries 1–3 (27)–(29), the Gaussian forms (30)–(31), the MAP detector on
//! Z = ∅ (Section IV-A), the sequential IRF (35) and Enumeration (37) bounds.

use alloc::vec::Vec;

use crate::error::{Error, Result, check_probability};
use crate::math::fns;

/// Which rule the bound's estimator uses on Z = ∅ (46): HPE declares {x*}, LPE declares ∅.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub enum Phase {
    /// High probability of existence: Z = ∅ ⇒ X̂ = {x*}.
    #[cfg_attr(feature = "serde", serde(rename = "HPE"))]
    Hpe,
    /// Low probability of existence: Z = ∅ ⇒ X̂ = ∅.
    #[cfg_attr(feature = "serde", serde(rename = "LPE"))]
    Lpe,
}

/// The four summands of (17) (Theorem 1) or (23) (Theorem 2), in the paper's order.
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct Terms {
    /// r P̄_o J'_1⁻¹ (17), or r P̄_o Σ_n C_n J'_{1+n}⁻¹ (23).
    pub estimation: f64,
    /// r (1 − P̄_o)(1 − μ) σ_e²: an undetected target estimated by x*.
    pub undetected: f64,
    /// r (μ (1 − P̄_o) + P̄_o − P̄_o w) e_1²: a target declared absent.
    pub missed: f64,
    /// (1 − r)(1 − μ') e_0²: a target declared where none exists.
    pub false_target: f64,
}

impl Terms {
    /// Their sum, the bound.
    pub fn total(&self) -> f64 {
        self.estimation + self.undetected + self.missed + self.false_target
    }
}

/// The ingredients of Theorems 1 and 2 once the integrals are done. With ε = Pr(Z = ∅ | X = ∅),
/// ν = Pr(Z ≠ ∅ and the MAP detector says ∅ | X = ∅), and ε_u, ν_u the same probabilities for a
/// target that exists but was not observed, the HPE and LPE bounds (48)/(47) and (57)/(58) are
///
/// ```text
/// HPE = (1 − r)(1 − ν) e0² + r(1 − P̄o)[(1 − ν_u) σe² + ν_u e1²] + r P̄o (1 − W) e1² + r P̄o S
/// LPE = (1 − r)(1 − ε − ν) e0² + r(1 − P̄o)[ε_u e1² + (1 − ε_u − ν_u) σe² + ν_u e1²]
///       + r P̄o (1 − W) e1² + r P̄o S
/// ```
///
/// Model I: ε = 1 − q, ν = η1, ε_u = 1, ν_u = 0, S = J'_1⁻¹, W = w_1 (this is (21)).
/// Model II: ε = ε_u = e^{−λ}, ν = ν_u = η2, S = Σ C_n J'_{1+n}⁻¹, W = Σ C_n w_{n+1}
/// ((23) with NOTES.md's reading). The bound is the smaller of the two (the estimator is free
/// on Z = ∅), which is (18)/(24)'s switch at r* = ε e0² / (ε e0² + (1 − P̄o) ε_u (e1² − σe²)).
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct Ingredients {
    /// The prior existence probability r ∈ [0, 1]: the probability that the target exists.
    pub existence: f64,
    /// The mean detection probability P̄_o (14) = ∫ P_o(x) f(x) dx, in [0, 1].
    pub mean_detection: f64,
    /// The variance σ_e² (16) of an undetected target's state: the variance of f_d'.
    pub undetected_variance: f64,
    /// The estimation term S of a detected target: J'_1⁻¹, or Σ_n C_n J'_{1+n}⁻¹.
    pub inverse_information: f64,
    /// The detected mass W: w_1, or Σ_n C_n w_{n+1}, in [0, 1].
    pub detected_mass: f64,
    /// The probability ε = Pr(Z = ∅ | X = ∅) of an empty observation when no target exists.
    pub absent_empty: f64,
    /// The probability ν = Pr(Z ≠ ∅, declared ∅ | X = ∅) that a target-free, non-empty observation
    /// is declared empty: η1 or η2.
    pub absent_null: f64,
    /// ε_u = Pr(Z = ∅ | target exists, not observed).
    pub undetected_empty: f64,
    /// ν_u = Pr(Z ≠ ∅, declared ∅ | target exists, not observed).
    pub undetected_null: f64,
    /// The squared error e_0² ≥ 0 of a false target (declaring one when none exists).
    pub false_alarm_error: f64,
    /// The squared error e_1² ≥ 0 of a missed target (declaring none when one exists).
    pub miss_error: f64,
}

/// A bound of Theorem 1 or 2 (or a corollary), with both phases.
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct Assembled {
    /// The bound: the smaller of `hpe` and `lpe`.
    pub bound: f64,
    /// The phase that attains it (HPE on a tie).
    pub phase: Phase,
    /// r*, where the HPE and LPE bounds cross (18)/(24); may exceed 1 (never HPE), and is
    /// +∞ when HPE is never the smaller.
    pub existence_threshold: f64,
    /// The summands of the attaining phase.
    pub terms: Terms,
    /// The HPE bound (48)/(57): the estimator declares {x*} on Z = ∅.
    pub hpe: f64,
    /// The LPE bound (47)/(58): the estimator declares ∅ on Z = ∅.
    pub lpe: f64,
}

/// Builds [`Assembled`] from [`Ingredients`] (see there for the formulas).
pub fn assemble(i: &Ingredients) -> Assembled {
    let r = i.existence;
    let p = i.mean_detection;
    let (e0, e1, s2) = (i.false_alarm_error, i.miss_error, i.undetected_variance);
    let estimation = r * p * i.inverse_information;
    let missed_detected = r * p * (1.0 - i.detected_mass) * e1;
    let terms_for = |phase: Phase| {
        // μ_u, μ_f: the μ of (17)/(23) for the undetected and the false-target summands.
        let (mu_u, mu_f) = match phase {
            Phase::Hpe => (i.undetected_null, i.absent_null),
            Phase::Lpe => (
                i.undetected_null + i.undetected_empty,
                i.absent_null + i.absent_empty,
            ),
        };
        Terms {
            estimation,
            undetected: r * (1.0 - p) * (1.0 - mu_u) * s2,
            missed: r * (1.0 - p) * mu_u * e1 + missed_detected,
            false_target: (1.0 - r) * (1.0 - mu_f) * e0,
        }
    };
    let (th, tl) = (terms_for(Phase::Hpe), terms_for(Phase::Lpe));
    let (hpe, lpe) = (th.total(), tl.total());
    let a = i.absent_empty * e0;
    let denom = a + (1.0 - p) * i.undetected_empty * (e1 - s2);
    let existence_threshold = if denom > 0.0 {
        a / denom
    } else {
        f64::INFINITY
    };
    let (bound, phase, terms) = if hpe <= lpe {
        (hpe, Phase::Hpe, th)
    } else {
        (lpe, Phase::Lpe, tl)
    };
    Assembled {
        bound,
        phase,
        existence_threshold,
        terms,
        hpe,
        lpe,
    }
}

pub(crate) fn check_positive(what: &str, value: f64) -> Result<f64> {
    if value.is_finite() && value > 0.0 {
        Ok(value)
    } else {
        Err(Error::parameter(what, value, "finite and > 0"))
    }
}

/// A variance that the quadrature of a density uses: finite and at least `f64::MIN_POSITIVE`
/// (≈ 2.2e-308). A subnormal variance is rejected: its density's width is below every float
/// spacing near the mean, and the adaptive quadrature would subdivide for seconds to find it.
pub(crate) fn check_variance(what: &str, value: f64) -> Result<f64> {
    if value.is_finite() && value >= f64::MIN_POSITIVE {
        Ok(value)
    } else {
        Err(Error::parameter(
            what,
            value,
            "finite and >= 2.2250738585072014e-308 (a normal float)",
        ))
    }
}

pub(crate) fn check_nonnegative(what: &str, value: f64) -> Result<f64> {
    if value.is_finite() && value >= 0.0 {
        Ok(value)
    } else {
        Err(Error::parameter(what, value, "finite and ≥ 0"))
    }
}

pub(crate) fn check_finite(what: &str, value: f64) -> Result<f64> {
    if value.is_finite() {
        Ok(value)
    } else {
        Err(Error::parameter(what, value, "finite"))
    }
}

/// The bound of Corollary 3 (29) with the MAP-detector variant of Section IV-A.
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct NoClutterBound {
    /// The bound (29): the smaller of `hpe` and `lpe`.
    pub bound: f64,
    /// r* of (29) (may exceed 1; +∞ when HPE never wins).
    pub existence_threshold: f64,
    /// Whether the bound's estimator declares a target on Z = ∅ (HPE).
    pub declare_on_empty: bool,
    /// The HPE line r(P̄o J1⁻¹ + (1 − P̄o)σe²) + (1 − r)e0².
    pub hpe: f64,
    /// The LPE bound, the line r(P̄o J1⁻¹ + (1 − P̄o)e1²) in r.
    pub lpe: f64,
    /// r_M* = (1 − q)/(2 − P̄o − q) with q = 0: where a MAP detector on Z = ∅ switches.
    pub map_threshold: f64,
    /// The bound of the estimator that also uses MAP detection on Z = ∅: HPE for r ≥ r_M*,
    /// LPE below (Section IV-A); never below `bound`.
    pub map_bound: f64,
}

/// r_M* = (1 − q)/(2 − P̄_o − q), the HPE/LPE switch of a MAP detector on Z = ∅ (Section
/// IV-A): it declares a target on Z = ∅ when r(1 − P̄_o) ≥ (1 − r)(1 − q).
pub fn map_threshold(false_alarm_probability: f64, mean_detection: f64) -> f64 {
    let q = false_alarm_probability;
    let d = 2.0 - mean_detection - q;
    if d > 0.0 { (1.0 - q) / d } else { 1.0 }
}

/// Corollary 3 (29): the no-clutter model Θ_b0 with any r. `inverse_information` is J_1⁻¹,
/// `undetected_variance` σ_e²; errors name the field (`existence`, `detection_probability`,
/// …).
pub fn corollary3(
    existence: f64,
    mean_detection: f64,
    inverse_information: f64,
    undetected_variance: f64,
    false_alarm_error: f64,
    miss_error: f64,
) -> Result<NoClutterBound> {
    let r = check_probability(|| "existence".into(), existence)?;
    let p = check_probability(|| "detection_probability".into(), mean_detection)?;
    check_nonnegative("inverse_information", inverse_information)?;
    check_nonnegative("undetected_variance", undetected_variance)?;
    check_nonnegative("false_alarm_error", false_alarm_error)?;
    check_nonnegative("miss_error", miss_error)?;
    let a = assemble(&no_clutter_ingredients(
        r,
        p,
        inverse_information,
        undetected_variance,
        false_alarm_error,
        miss_error,
    ));
    let map_threshold = map_threshold(0.0, p);
    let map_bound = if r >= map_threshold { a.hpe } else { a.lpe };
    Ok(NoClutterBound {
        bound: a.bound,
        existence_threshold: a.existence_threshold,
        declare_on_empty: a.phase == Phase::Hpe,
        hpe: a.hpe,
        lpe: a.lpe,
        map_threshold,
        map_bound,
    })
}

pub(crate) fn no_clutter_ingredients(
    r: f64,
    p: f64,
    inverse_information: f64,
    undetected_variance: f64,
    e0: f64,
    e1: f64,
) -> Ingredients {
    Ingredients {
        existence: r,
        mean_detection: p,
        undetected_variance,
        inverse_information,
        detected_mass: 1.0,
        absent_empty: 1.0,
        absent_null: 0.0,
        undetected_empty: 1.0,
        undetected_null: 0.0,
        false_alarm_error: e0,
        miss_error: e1,
    }
}

/// The Gaussian form (31) of Corollary 3 (constant P_o, Gaussian f and g): σ_e² = σ_f², the
/// prior variance, and J_1⁻¹ = σ_h², the mean posterior variance (for z = ax + v,
/// [`gaussian_fisher_information`]). (30) is the case σ_h² = σ_x²σ_v²/(σ_v² + a²σ_x²) (with
/// NOTES.md's erratum: the paper's 2σ_v² is σ_v²). Needs σ_h² ≤ σ_f².
pub fn gaussian_no_clutter(
    existence: f64,
    detection_probability: f64,
    prior_variance: f64,
    posterior_variance: f64,
    false_alarm_error: f64,
    miss_error: f64,
) -> Result<NoClutterBound> {
    check_positive("prior_variance", prior_variance)?;
    check_positive("posterior_variance", posterior_variance)?;
    if posterior_variance > prior_variance {
        return Err(Error::parameter(
            "posterior_variance",
            posterior_variance,
            "≤ priorVariance (observing cannot add variance on average)",
        ));
    }
    corollary3(
        existence,
        detection_probability,
        posterior_variance,
        prior_variance,
        false_alarm_error,
        miss_error,
    )
    .map_err(|e| match e.field() {
        "inverse_information" => e.map_field(|_| "posterior_variance".into()),
        "undetected_variance" => e.map_field(|_| "prior_variance".into()),
        _ => e,
    })
}

/// Corollary 1 (27): P̄_o J_1⁻¹ + (1 − P̄_o) σ_e² (asserted target, model I).
pub fn corollary1(mean_detection: f64, inverse_information: f64, undetected_variance: f64) -> f64 {
    mean_detection * inverse_information + (1.0 - mean_detection) * undetected_variance
}

/// Corollary 2 (28): P̄_o Σ_n C_n J_{1+n}⁻¹ + (1 − P̄_o) σ_e² with C_n the Poisson(λ) pmf;
/// `inverse_information[n]` = J_{1+n}⁻¹. The series is truncated at the slice's length: each
/// term is ≥ 0, so the truncation is still a lower bound.
pub fn corollary2(
    mean_detection: f64,
    inverse_information: &[f64],
    clutter_rate: f64,
    undetected_variance: f64,
) -> Result<f64> {
    check_nonnegative("clutter_rate", clutter_rate)?;
    let mut s = 0.0;
    for (n, &j) in inverse_information.iter().enumerate() {
        s += poisson_pmf(clutter_rate, n) * j;
    }
    Ok(mean_detection * s + (1.0 - mean_detection) * undetected_variance)
}

/// The Poisson pmf C_n = e^{−λ} λⁿ / n! ([`special::poisson_pmf`](crate::math::special::poisson_pmf),
/// Loader's form).
pub fn poisson_pmf(rate: f64, n: usize) -> f64 {
    crate::math::special::poisson_pmf(rate, n)
}

/// Fisher information of the linear-Gaussian model (Example 1, with NOTES.md's erratum).
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct GaussianInformation {
    /// J_1 = 1/σ_x² + a²/σ_v², the Fisher information of p(x, z) = N(x; x0, σ_x²) N(z; ax, σ_v²).
    pub information: f64,
    /// 1/J_1 = σ_x² σ_v² / (σ_v² + a² σ_x²), the posterior variance (the same for every z).
    pub posterior_variance: f64,
}

/// J_1 for z = a x + v, x ~ N(x0, σ_x²), v ~ N(0, σ_v²): −E ∂²/∂x² log p(x, z) = 1/σ_x² +
/// a²/σ_v². Example 1 prints a²/(2σ_v²), an erratum (NOTES.md).
pub fn gaussian_fisher_information(
    prior_variance: f64,
    gain: f64,
    noise_variance: f64,
) -> Result<GaussianInformation> {
    check_positive("prior_variance", prior_variance)?;
    check_finite("gain", gain)?;
    check_positive("noise_variance", noise_variance)?;
    let t = gain * gain / noise_variance;
    let information = 1.0 / prior_variance + t;
    // σx² / (1 + σx² a²/σv²): no overflow for huge σx², exact σx² for a = 0
    let pt = prior_variance * t;
    let posterior_variance = if pt.is_finite() {
        prior_variance / (1.0 + pt)
    } else {
        1.0 / t
    };
    Ok(GaussianInformation {
        information,
        posterior_variance,
    })
}

/// The arguments of [`gaussian_no_clutter`]: Corollary 3 in the Gaussian form (31) (constant
/// P_o, Gaussian prior and likelihood, no false alarms).
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct NoClutterOptions {
    /// r, the prior probability that the target exists, in [0, 1].
    pub existence: f64,
    /// P̄_o, the (constant) probability of observing the target, in [0, 1].
    pub detection_probability: f64,
    /// σ_f², the prior variance (> 0); also σ_e², the variance given Z = ∅.
    pub prior_variance: f64,
    /// σ_h², the mean posterior variance given an observation (> 0, ≤ `prior_variance`):
    /// J_1⁻¹ (see [`gaussian_fisher_information`]).
    pub posterior_variance: f64,
    /// e_0² ≥ 0, the squared error charged for declaring a target that does not exist: the
    /// square itself (for e_0 = 12, give 144), in squared state units like the variances.
    pub false_alarm_error: f64,
    /// e_1² ≥ 0, the squared error charged for missing a target that exists: the square
    /// itself (for e_1 = 12, give 144).
    pub miss_error: f64,
}

impl NoClutterOptions {
    /// [`gaussian_no_clutter`] of these options.
    ///
    /// # Errors
    /// As [`gaussian_no_clutter`].
    pub fn bound(&self) -> Result<NoClutterBound> {
        gaussian_no_clutter(
            self.existence,
            self.detection_probability,
            self.prior_variance,
            self.posterior_variance,
            self.false_alarm_error,
            self.miss_error,
        )
    }
}

/// The arguments of [`gaussian_fisher_information`]: z = a x + v, x ~ N(x0, σ_x²),
/// v ~ N(0, σ_v²).
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct GaussianInformationOptions {
    /// The prior variance σ_x² > 0 of the state x.
    pub prior_variance: f64,
    /// The gain a of the measurement z = a x + v, finite.
    pub gain: f64,
    /// The measurement noise variance σ_v² > 0 of v.
    pub noise_variance: f64,
}

impl GaussianInformationOptions {
    /// [`gaussian_fisher_information`] of these options.
    ///
    /// # Errors
    /// As [`gaussian_fisher_information`].
    pub fn information(&self) -> Result<GaussianInformation> {
        gaussian_fisher_information(self.prior_variance, self.gain, self.noise_variance)
    }
}

/// The two sequential bounds of Section III-E: `enumeration` (37) or `irf` (35).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[cfg_attr(
    feature = "serde",
    derive(serde::Serialize, serde::Deserialize),
    serde(rename_all = "lowercase")
)]
pub enum Sequential {
    /// P_k(Enum) = Σ_m B_m (J_0 + m(J_1 − J_0))⁻¹ (37), B_m the Binomial(k, P̄_o) pmf.
    Enumeration,
    /// P_k(IRF) = (J_0 + k P̄_o (J_1 − J_0))⁻¹ (35).
    Irf,
}

/// Most steps [`sequential_bound`] computes (the Enumeration sum is O(k²) in total).
pub const MAX_STEPS: usize = 5_000;

/// The arguments of [`sequential_bound`]: the IRF (35) or Enumeration (37) bound of Rezaeian & Vo,
/// "Error bounds for joint detection and estimation of a single object with random finite set
/// observation" (paper 002).
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct SequentialOptions {
    /// The bound to compute: `'enumeration'` (37) or `'irf'` (35).
    pub method: Sequential,
    /// J_0 > 0, the information of the prior (of f_d').
    pub prior_information: f64,
    /// J_1 ≥ J_0, the information after one observation.
    pub detected_information: f64,
    /// P̄_o, the probability of an observation at each step, in [0, 1].
    pub detection_probability: f64,
    /// k_max, the number of steps (integer in [1, 5000]; the Enumeration sum is O(steps²)).
    pub steps: usize,
}

/// The sequential bound P_1 … P_steps of (35) or (37).
#[derive(Clone, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct SequentialBound {
    /// The bound P_k on the mean-square error after k observations: `bound[k − 1]` = P_k for k = 1
    /// … steps.
    pub bound: Vec<f64>,
}

impl SequentialOptions {
    /// [`sequential_bound`] of these options (Enum ≥ IRF; equal at P̄_o ∈ {0, 1}).
    ///
    /// # Errors
    /// As [`sequential_bound`].
    pub fn bound(&self) -> Result<SequentialBound> {
        sequential_bound(
            self.method,
            self.prior_information,
            self.detected_information,
            self.detection_probability,
            self.steps,
        )
        .map(|bound| SequentialBound { bound })
    }
}

/// P_1 … P_steps of (35) or (37) for the static state observed k times with detection
/// probability P̄_o: `prior_information` J_0 > 0 (of f_d'), `detected_information` J_1 ≥ J_0.
/// By Jensen (1/J is convex) Enum ≥ IRF, with equality at P̄_o ∈ {0, 1}.
pub fn sequential_bound(
    method: Sequential,
    prior_information: f64,
    detected_information: f64,
    detection_probability: f64,
    steps: usize,
) -> Result<Vec<f64>> {
    // the work first: a bad `steps` is named before the values
    Error::check_range("steps", steps, 1, MAX_STEPS)?;
    let j0 = check_positive("prior_information", prior_information)?;
    let j1 = check_positive("detected_information", detected_information)?;
    if j1 < j0 {
        return Err(Error::parameter(
            "detected_information",
            j1,
            "≥ priorInformation (an observation cannot remove information)",
        ));
    }
    let p = check_probability(|| "detection_probability".into(), detection_probability)?;
    let gain = j1 - j0;
    // ln m! for m ≤ steps, once: the Enumeration sums are then O(steps²) in all.
    let mut ln_fact = Vec::with_capacity(steps + 1);
    ln_fact.push(0.0);
    for m in 1..=steps {
        ln_fact.push(ln_fact[m - 1] + fns::ln(m as f64));
    }
    let (ln_p, ln_q) = (fns::ln(p), fns::ln_1p(-p));
    let mut out = Vec::with_capacity(steps);
    for k in 1..=steps {
        out.push(match method {
            Sequential::Irf => 1.0 / (j0 + k as f64 * p * gain),
            Sequential::Enumeration => {
                // positive terms: no cancellation to compensate (and a compensated sum
                // would turn an overflowing 1/J_0 into NaN)
                (0..=k)
                    .map(|m| {
                        let b = if p == 0.0 {
                            if m == 0 { 1.0 } else { 0.0 }
                        } else if p == 1.0 {
                            if m == k { 1.0 } else { 0.0 }
                        } else {
                            fns::exp(
                                ln_fact[k] - ln_fact[m] - ln_fact[k - m]
                                    + m as f64 * ln_p
                                    + (k - m) as f64 * ln_q,
                            )
                        };
                        b / (j0 + m as f64 * gain)
                    })
                    .sum::<f64>()
            }
        });
    }
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn eq31_gaussian_form_is_cor3() {
        // Fig. 2 left: σf² = 100, σh² = 25, e0² = 150, e1² = 200.
        for &r in &[0.0, 0.2, 0.5, 0.8, 1.0] {
            for &p in &[0.0, 0.3, 0.9, 1.0] {
                let b = gaussian_no_clutter(r, p, 100.0, 25.0, 150.0, 200.0).unwrap();
                let hpe = r * (100.0 - p * (100.0 - 25.0)) + (1.0 - r) * 150.0;
                let lpe = r * (200.0 - p * (200.0 - 25.0));
                assert!((b.hpe - hpe).abs() < 1e-12 && (b.lpe - lpe).abs() < 1e-12);
                let rs = 150.0 / (150.0 + (1.0 - p) * 100.0);
                assert!((b.existence_threshold - rs).abs() < 1e-15);
                let expected = if r >= rs { hpe } else { lpe };
                assert!((b.bound - expected).abs() < 1e-12, "r {r} p {p}");
                assert!(b.map_bound >= b.bound - 1e-12);
                assert!((b.map_threshold - 1.0 / (2.0 - p)).abs() < 1e-15);
            }
        }
    }

    #[test]
    fn sec4a_map_threshold_equals_r_star_when_sigma_is_e1_minus_e0() {
        // Section IV-A: σe² = e1² − e0² ⇒ r_M* = r1*.
        let (q, p, e0, e1) = (0.2, 0.4, 3.0, 5.0);
        let s2 = e1 - e0;
        let r1 = (1.0 - q) * e0 / ((1.0 - q) * e0 + (1.0 - p) * (e1 - s2));
        assert!((map_threshold(q, p) - r1).abs() < 1e-15);
    }

    #[test]
    fn eq35_eq37_enumeration_dominates_irf() {
        for &p in &[0.0, 0.1, 0.5, 0.9, 1.0] {
            let e = sequential_bound(Sequential::Enumeration, 0.01, 0.05, p, 50).unwrap();
            let i = sequential_bound(Sequential::Irf, 0.01, 0.05, p, 50).unwrap();
            for (k, (a, b)) in e.iter().zip(&i).enumerate() {
                assert!(a >= &(b * (1.0 - 1e-14)), "k {k} p {p}");
                if p == 0.0 || p == 1.0 {
                    assert!((a - b).abs() <= 1e-15 * a);
                }
            }
            // k = 1: (33) and (34)
            assert!((e[0] - (p / 0.05 + (1.0 - p) / 0.01)).abs() < 1e-12);
            assert!((i[0] - 1.0 / (p * 0.05 + (1.0 - p) * 0.01)).abs() < 1e-12);
        }
        assert!(sequential_bound(Sequential::Irf, 1.0, 0.5, 0.5, 3).is_err());
        assert!(sequential_bound(Sequential::Irf, 1.0, 2.0, 0.5, 0).is_err());
    }

    #[test]
    fn eq35_steps_are_checked_first_and_named() {
        // a bad `steps` is named even when the informations are bad too
        let e = sequential_bound(Sequential::Irf, 0.0, 0.0, 0.5, 0).unwrap_err();
        assert_eq!(e, Error::range("steps", 0, 1, MAX_STEPS));
        let o = SequentialOptions {
            method: Sequential::Enumeration,
            prior_information: 0.01,
            detected_information: 0.05,
            detection_probability: 0.5,
            steps: 3,
        };
        let b = o.bound().unwrap();
        assert_eq!(
            b.bound,
            sequential_bound(Sequential::Enumeration, 0.01, 0.05, 0.5, 3).unwrap()
        );
    }

    #[cfg(feature = "serde")]
    #[test]
    fn eq31_options_read_their_rust_names() {
        let o: NoClutterOptions = serde_json::from_str(
            r#"{"existence": 0.5, "detection_probability": 0.3, "prior_variance": 100,
                "posterior_variance": 25, "false_alarm_error": 150, "miss_error": 200}"#,
        )
        .unwrap();
        assert_eq!(
            o.bound().unwrap(),
            gaussian_no_clutter(0.5, 0.3, 100.0, 25.0, 150.0, 200.0).unwrap()
        );
        let s: SequentialOptions = serde_json::from_str(
            r#"{"method": "irf", "prior_information": 1, "detected_information": 2,
                "detection_probability": 0.5, "steps": 2}"#,
        )
        .unwrap();
        assert_eq!(s.method, Sequential::Irf);
        let phase = serde_json::to_string(&Phase::Hpe).unwrap();
        assert_eq!(phase, r#""HPE""#);
    }

    #[test]
    fn cor2_with_no_clutter_is_cor1() {
        let c2 = corollary2(0.7, &[0.25, 0.5, 0.75], 0.0, 2.0).unwrap();
        assert!((c2 - corollary1(0.7, 0.25, 2.0)).abs() < 1e-15);
    }

    #[test]
    fn errors_name_the_field() {
        let e = gaussian_no_clutter(0.5, 0.5, 1.0, 2.0, 1.0, 1.0).unwrap_err();
        assert_eq!(e.field(), "posterior_variance");
        let e = gaussian_no_clutter(0.5, 0.5, -1.0, 0.5, 1.0, 1.0).unwrap_err();
        assert_eq!(e.field(), "prior_variance");
        let e = corollary3(0.5, 1.5, 1.0, 1.0, 1.0, 1.0).unwrap_err();
        assert_eq!(e.field(), "detection_probability");
        let e = gaussian_fisher_information(1.0, f64::NAN, 1.0).unwrap_err();
        assert_eq!(e.field(), "gain");
    }
}
