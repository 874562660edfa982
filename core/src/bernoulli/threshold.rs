//! The reporting threshold Γ of eq. (11) of `000_…` and the expected losses (13)–(14) of
//! the two reports, from the costs and q(a*) alone.

use crate::bernoulli::loss::Costs;
#[cfg(doc)]
use crate::error::Error;
use crate::error::{Result, check_probability};
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
    Ok((1.0 - p) * costs.c10() + p * (costs.c11() + costs.c() * q))
}
