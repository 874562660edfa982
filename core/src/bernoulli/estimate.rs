//! Theorem III.3 of `000_…`: the Bayes-optimal Bernoulli point estimate, its threshold Γ and
//! expected losses; and its application to each component of a multi-Bernoulli.

use alloc::vec::Vec;

use crate::bernoulli::density::SpatialDensity;
use crate::bernoulli::loss::{ApplicationLoss, Costs};
use crate::bernoulli::mmuc::Mmuc;
#[cfg(doc)]
use crate::error::Error;
use crate::error::{Result, check_probability};
use crate::math::sum::sum;

/// Which side of Γ reports a target.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
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

/// The Bayes-optimal point estimate of a Bernoulli (Theorem III.3 of `000_…`) with what it
/// was decided from.
#[derive(Clone, Debug, PartialEq)]
pub struct BernoulliEstimate {
    /// Whether {a*} is reported (`true`) or ∅ (`false`), eq. (10).
    pub declare: bool,
    /// a* when declared, else `None`.
    pub estimate: Option<Vec<f64>>,
    /// The MMUC estimate a* of eq. (12) (how it was found: [`Mmuc::method`]).
    pub mmuc: Mmuc,
    /// Γ and its side, eq. (11).
    pub threshold: Threshold,
    /// ρ_∅, eq. (14).
    pub expected_loss_empty: f64,
    /// ρ_{a*}, eq. (13).
    pub expected_loss_singleton: f64,
}

impl BernoulliEstimate {
    /// q(a*), the probability that the target is farther than r0 from a*.
    pub fn miss_probability(&self) -> f64 {
        self.mmuc.miss_probability
    }

    /// ρ*, eq. (10): the expected loss of the optimal estimate.
    pub fn expected_loss(&self) -> f64 {
        if self.declare {
            self.expected_loss_singleton
        } else {
            self.expected_loss_empty
        }
    }
}

/// The Bayes-optimal point estimate (Theorem III.3 of `000_…`) of a Bernoulli with
/// existence probability p (`existence`) and spatial density s, under the loss (7):
///
/// ```text
/// a*  = argmin_a q(a),  q(a) = ∫ 1{‖x − a‖ > r0} s(dx)                     (12)
/// Γ   = (c00 − c10) / (c00 − c01 − c10 + c11 + c q(a*))                    (11)
/// α*  = {a*} if p > Γ,  ∅ if p < Γ  (and ∅ at p = Γ, a tie)               (10)
/// ρ_∅ = (1 − p) c00 + p c01,   ρ_{a*} = (1 − p) c10 + p (c11 + c q(a*))   (14), (13)
/// ```
///
/// (with the comparison reversed for the cost matrices described under [`Direction`]).
/// a* is found by [`SpatialDensity::mmuc`].
///
/// # Errors
/// [`Error::InvalidProbability`] naming `existence` unless p ∈ [0, 1]; as
/// [`SpatialDensity::mmuc`].
///
/// # Examples
/// Section IV's Bernoulli-Gaussian N(0, 1) with r0 = 1 (Figs. 2a and 2b):
/// ```
/// use fisst::bernoulli::{estimate, ApplicationLoss, Costs, SpatialDensity};
/// let s = SpatialDensity::gaussian_from_slices(&[0.0], &[1.0])?;
/// let mpe = estimate(0.55, &s, &ApplicationLoss::new(Costs::mpe(), 1.0)?)?;
/// assert!((mpe.threshold.gamma - 0.5943).abs() < 5e-5);
/// assert!(!mpe.declare); // 0.5 < p < Γ: the MPE estimate reports nothing
/// let mmol = estimate(0.2, &s, &ApplicationLoss::new(Costs::mmol(0.9, 0.1)?, 1.0)?)?;
/// assert!((mmol.threshold.gamma - 0.1628).abs() < 5e-5);
/// assert_eq!(mmol.estimate, Some(vec![0.0]));
/// # Ok::<(), fisst::Error>(())
/// ```
pub fn estimate(
    existence: f64,
    density: &SpatialDensity,
    loss: &ApplicationLoss,
) -> Result<BernoulliEstimate> {
    let p = check_probability(|| "existence".into(), existence)?;
    let mmuc = density.mmuc(loss.radius())?;
    decide(p, mmuc, loss.costs())
}

/// Theorem III.3 given a* and q(a*).
pub(crate) fn decide(p: f64, mmuc: Mmuc, costs: &Costs) -> Result<BernoulliEstimate> {
    let q = mmuc.miss_probability;
    let threshold = threshold(costs, q)?;
    let declare = threshold.declares(p);
    Ok(BernoulliEstimate {
        declare,
        estimate: declare.then(|| mmuc.center.clone()),
        threshold,
        expected_loss_empty: expected_loss_empty(costs, p)?,
        expected_loss_singleton: expected_loss_singleton(costs, p, q)?,
        mmuc,
    })
}

/// The estimates of the components of a multi-Bernoulli and the reported set.
#[derive(Clone, Debug, PartialEq)]
pub struct MultiBernoulliEstimate {
    /// Theorem III.3 applied to each component, in input order.
    pub components: Vec<BernoulliEstimate>,
    /// The indices of the declared components, increasing.
    pub reported: Vec<usize>,
}

impl MultiBernoulliEstimate {
    /// The reported set: a* of every declared component.
    pub fn points(&self) -> Vec<&[f64]> {
        self.components
            .iter()
            .filter_map(|c| c.estimate.as_deref())
            .collect()
    }
}

/// Theorem III.3 applied to each Bernoulli component `(r_i, s_i)` of a multi-Bernoulli, the
/// use the paper's introduction names for it (the paper proves optimality for a single
/// Bernoulli only; applying it per component is optimal when the components' losses add
/// up, as for far-apart targets).
///
/// # Errors
/// [`Error::InvalidProbability`] naming `components[i].existence` unless r_i ∈ [0, 1].
pub fn multi_bernoulli_estimate(
    components: &[(f64, SpatialDensity)],
    loss: &ApplicationLoss,
) -> Result<MultiBernoulliEstimate> {
    let mut out = Vec::with_capacity(components.len());
    let mut reported = Vec::new();
    for (i, (p, s)) in components.iter().enumerate() {
        let p = check_probability(|| alloc::format!("components[{i}].existence"), *p)?;
        let mmuc = s.mmuc(loss.radius())?;
        let e = decide(p, mmuc, loss.costs())?;
        if e.declare {
            reported.push(i);
        }
        out.push(e);
    }
    Ok(MultiBernoulliEstimate {
        components: out,
        reported,
    })
}
