//! The reporting threshold Γ of eq. (11) of `000_…` and the expected losses (13)–(14) of
//! the two reports, from the costs and q(a*) alone, and their curves against p (Fig. 2).

use alloc::vec::Vec;

use crate::bernoulli::loss::Costs;
use crate::error::{Error, Result, check_probability};
use crate::math::sum::sum;

/// Which side of Γ reports a target.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub enum Direction {
    /// Report {a*} when p > Γ: the case of Theorem III.3, which holds whenever the
    /// denominator of (11) is negative, i.e. `c11 + c·q < c01 + c10 − c00` (a correctly
    /// placed report is cheaper than a miss plus a false alarm) — MPE and MMOL always.
    Above,
    /// Report {a*} when p < Γ: the reversed comparison, for cost matrices that make a
    /// report costlier than `c01 + c10 − c00` (the denominator of (11) is positive).
    Below,
}

/// The reporting threshold Γ of eq. (11) and the side of it on which {a*} is reported.
///
/// Ties (p = Γ, where ρ_∅ = ρ_{a*}) report nothing: the estimate changes only when reporting
/// is strictly better. When the denominator of (11) vanishes the decision does not depend
/// on p and Γ is −∞ (always report, when c10 < c00) or +∞ (never).
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct Threshold {
    /// Γ. With [`Direction::Above`]: Γ > 1 never reports, Γ < 0 always does, and Γ = 0
    /// reports every p > 0.
    pub gamma: f64,
    /// The side of Γ that reports.
    pub direction: Direction,
}

impl Threshold {
    /// True when existence probability `p` reports {a*} (strictly better than ∅).
    pub fn declares(&self, p: f64) -> bool {
        match self.direction {
            Direction::Above => p > self.gamma,
            Direction::Below => p < self.gamma,
        }
    }
}

/// Γ, eq. (11) of `000_…`, for q = q(a*) (`miss_probability`):
///
/// ```text
/// Γ = (c00 − c10) / (c00 − c01 − c10 + c11 + c·q)
/// ```
///
/// obtained by solving ρ_∅ = ρ_{a*} for p, with ρ_∅ from (14) and ρ_{a*} from (13). Since
/// `ρ_{a*} − ρ_∅ = (c10 − c00) + p·D` with D the denominator, reporting is better for p > Γ
/// when D < 0 and for p < Γ when D > 0 (see [`Direction`]). D is a compensated sum, so its
/// sign is exact for costs exactly representable.
///
/// # Errors
/// [`Error::InvalidProbability`] naming `missProbability` unless q ∈ [0, 1].
pub fn threshold(costs: &Costs, miss_probability: f64) -> Result<Threshold> {
    let q = check_probability(|| "missProbability".into(), miss_probability)?;
    let numerator = costs.c00() - costs.c10();
    let denominator = sum([
        costs.c00(),
        -costs.c01(),
        -costs.c10(),
        costs.c11(),
        costs.c() * q,
    ]);
    // A zero numerator over a negative denominator is −0 (MMOL with c_M = 0): report +0.
    let ratio = |n: f64, d: f64| if n == 0.0 { 0.0 } else { n / d };
    Ok(if denominator < 0.0 {
        Threshold {
            gamma: ratio(numerator, denominator),
            direction: Direction::Above,
        }
    } else if denominator > 0.0 {
        Threshold {
            gamma: ratio(numerator, denominator),
            direction: Direction::Below,
        }
    } else {
        Threshold {
            gamma: if numerator > 0.0 {
                f64::NEG_INFINITY
            } else {
                f64::INFINITY
            },
            direction: Direction::Above,
        }
    })
}

/// ρ_∅, eq. (14) of `000_…`: the expected loss of reporting nothing,
///
/// ```text
/// ρ_∅ = (1 − p) c00 + p c01
/// ```
///
/// # Errors
/// [`Error::InvalidProbability`] naming `existence` unless p ∈ [0, 1].
pub fn expected_loss_empty(costs: &Costs, existence: f64) -> Result<f64> {
    let p = check_probability(|| "existence".into(), existence)?;
    Ok((1.0 - p) * costs.c00() + p * costs.c01())
}

/// ρ_{a}, eqs. (13) and (23c) of `000_…`: the expected loss of reporting {a} when the ball
/// about a misses the target with probability q = q(a):
///
/// ```text
/// ρ_{a} = (1 − p) c10 + p (c11 + c q)
/// ```
///
/// The first term is c10 as in (13); the c01 printed in (23c) is a typo (erratum in
/// `shared/papers/NOTES.md`: reporting {a} when nothing exists is a false alarm, c10).
///
/// # Errors
/// [`Error::InvalidProbability`] naming `existence` or `missProbability` unless in [0, 1].
pub fn expected_loss_singleton(
    costs: &Costs,
    existence: f64,
    miss_probability: f64,
) -> Result<f64> {
    let p = check_probability(|| "existence".into(), existence)?;
    let q = check_probability(|| "missProbability".into(), miss_probability)?;
    let rho = (1.0 - p) * costs.c10() + p * (costs.c11() + costs.c() * q);
    if rho.is_nan() {
        // c11 + c q overflowed to ±∞ and p = 0 (0 · ∞), or the two terms overflowed with
        // opposite signs: each product alone is finite (p, q ≤ 1), so their plain sum is the
        // loss or ±∞, never NaN (a compensated sum could meet ∞ − ∞ in its correction).
        return Ok((1.0 - p) * costs.c10() + p * costs.c11() + (p * q) * costs.c());
    }
    Ok(rho)
}

/// Options of [`loss_curve`].
#[derive(Clone, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct LossCurveOptions {
    /// The existence probabilities p at which to evaluate, each in [0, 1].
    #[cfg_attr(feature = "serde", serde(with = "crate::serde_shapes::numbers"))]
    pub existences: Vec<f64>,
    /// The miss probability q(a*) ∈ [0, 1] of the point that would be reported.
    pub miss_probability: f64,
    /// The costs of the loss (7).
    pub costs: Costs,
    /// Report when p > `threshold`; `None` (the default): the optimal rule of Theorem III.3,
    /// [`threshold`].
    #[cfg_attr(feature = "serde", serde(default))]
    pub threshold: Option<f64>,
}

/// The expected losses against p ([`loss_curve`]), one entry per p.
#[derive(Clone, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct LossCurve {
    /// The expected loss ρ_∅(p) of reporting nothing, eq. (14), one per p.
    pub empty: Vec<f64>,
    /// The expected loss ρ_{a*}(p) of reporting a*, eq. (13), one per p.
    pub singleton: Vec<f64>,
    /// The expected loss of the rule: ρ_{a*}(p) where it reports, else ρ_∅(p).
    pub rule: Vec<f64>,
    /// The rule's existence threshold (the given one, or the optimal Γ (11)).
    pub threshold: f64,
}

/// Fig. 2 of `000_…`: ρ_∅(p) (14), ρ_{a*}(p) (13) and the expected loss of the rule "report
/// when p > threshold" (default: the optimal rule, Γ of (11) on its [`Direction`]) at each
/// p of `existences`.
///
/// # Errors
/// [`Error::InvalidProbability`] naming `missProbability` unless q ∈ [0, 1], or
/// `existences[i]` unless p_i ∈ [0, 1].
///
/// # Examples
/// ```
/// use fisst::bernoulli::{loss_curve, Costs, LossCurveOptions};
/// let c = loss_curve(&LossCurveOptions {
///     existences: vec![0.2, 0.9],
///     miss_probability: 0.3,
///     costs: Costs::mpe(),
///     threshold: None,
/// })?;
/// assert_eq!(c.rule, vec![c.empty[0], c.singleton[1]]);
/// # Ok::<(), fisst::Error>(())
/// ```
pub fn loss_curve(options: &LossCurveOptions) -> Result<LossCurve> {
    let (costs, q) = (&options.costs, options.miss_probability);
    let optimal = threshold(costs, q)?;
    let rule = match options.threshold {
        Some(gamma) => Threshold {
            gamma,
            direction: Direction::Above,
        },
        None => optimal,
    };
    let n = options.existences.len();
    let mut out = LossCurve {
        empty: Vec::with_capacity(n),
        singleton: Vec::with_capacity(n),
        rule: Vec::with_capacity(n),
        threshold: rule.gamma,
    };
    for (i, &p) in options.existences.iter().enumerate() {
        let rename = |e: Error| match e {
            Error::InvalidProbability { what, value } if what == "existence" => {
                Error::probability(alloc::format!("existences[{i}]"), value)
            }
            other => other,
        };
        let e = expected_loss_empty(costs, p).map_err(rename)?;
        let a = expected_loss_singleton(costs, p, q).map_err(rename)?;
        out.empty.push(e);
        out.singleton.push(a);
        out.rule.push(if rule.declares(p) { a } else { e });
    }
    Ok(out)
}
