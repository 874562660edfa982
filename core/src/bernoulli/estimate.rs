//! Theorem III.3 of `000_…`: the Bayes-optimal Bernoulli point estimate (a* from [`mmuc`](super::mmuc),
//! reported when p is on the right side of Γ from [`threshold`](super::threshold())); and its
//! application to each component of a multi-Bernoulli.

use alloc::vec::Vec;

use crate::bernoulli::density::SpatialDensity;
use crate::bernoulli::loss::{ApplicationLoss, Costs};
use crate::bernoulli::mmuc::Mmuc;
use crate::bernoulli::threshold::{
    Threshold, expected_loss_empty, expected_loss_singleton, threshold,
};
#[cfg(doc)]
use crate::error::Error;
use crate::error::{Result, check_probability};

/// The Bayes-optimal point estimate of a Bernoulli (Theorem III.3 of `000_…`) with what it
/// was decided from.
#[derive(Clone, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct BernoulliEstimate {
    /// Whether {a*} is reported (`true`) or ∅ (`false`), eq. (10).
    pub declare: bool,
    /// The reported point: a* when declared, else `None`.
    pub estimate: Option<Vec<f64>>,
    /// The MMUC estimate a* of eq. (12) (how it was found: [`Mmuc::method`]).
    pub mmuc: Mmuc,
    /// The existence threshold Γ of eq. (11) and the side of it that reports.
    pub threshold: Threshold,
    /// The expected loss ρ_∅ of reporting nothing, eq. (14).
    pub expected_loss_empty: f64,
    /// The expected loss ρ_{a*} of reporting the single point a*, eq. (13).
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
/// (with the comparison reversed for the cost matrices described under [`Direction`](super::Direction)).
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
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
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

/// The most components [`multi_bernoulli_estimate`] takes: each costs an MMUC search, up to
/// about a millisecond for a capped mixture or particle set.
pub const MAX_MULTI_BERNOULLI_COMPONENTS: usize = 10_000;

/// `Ok` if a multi-Bernoulli of `count` components is within
/// [`MAX_MULTI_BERNOULLI_COMPONENTS`] (a binding checks it before reading the densities).
///
/// # Errors
/// [`Error::Count`] naming `components`.
pub fn check_multi_bernoulli_count(count: usize) -> Result<()> {
    crate::Error::check_count(
        "components",
        "entries",
        count,
        0,
        MAX_MULTI_BERNOULLI_COMPONENTS,
    )
}

/// Theorem III.3 applied to each Bernoulli component `(r_i, s_i)` of a multi-Bernoulli, the
/// use the paper's introduction names for it (the paper proves optimality for a single
/// Bernoulli only; applying it per component is optimal when the components' losses add
/// up, as for far-apart targets).
///
/// # Errors
/// [`Error::Count`] naming `components` for more than [`MAX_MULTI_BERNOULLI_COMPONENTS`];
/// [`Error::InvalidProbability`] naming `components[i].existence` unless r_i ∈ [0, 1].
pub fn multi_bernoulli_estimate(
    components: &[(f64, SpatialDensity)],
    loss: &ApplicationLoss,
) -> Result<MultiBernoulliEstimate> {
    check_multi_bernoulli_count(components.len())?;
    decide_each(components.iter().map(|(p, s)| (*p, s)), loss)
}

/// Theorem III.3 on each `(r_i, s_i)`, in order (the loop of [`multi_bernoulli_estimate`]).
fn decide_each<'a>(
    components: impl ExactSizeIterator<Item = (f64, &'a SpatialDensity)>,
    loss: &ApplicationLoss,
) -> Result<MultiBernoulliEstimate> {
    let mut out = Vec::with_capacity(components.len());
    let mut reported = Vec::new();
    for (i, (p, s)) in components.enumerate() {
        let p = check_probability(|| alloc::format!("components[{i}].existence"), p)?;
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

/// The options of a Bernoulli's optimal estimate ([`BernoulliEstimateOptions::estimate`]): one
/// Bernoulli (existence p and spatial density s) and the loss (7) of `000_…` (radius r0, costs).
#[derive(Clone, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct BernoulliEstimateOptions {
    /// The existence probability p ∈ [0, 1]: the probability that the object exists.
    pub existence: f64,
    /// The spatial density of the object when it exists. The MMUC search takes a mixture of
    /// at most 100 components ([`MAX_MMUC_COMPONENTS`](super::MAX_MMUC_COMPONENTS)), and in 2 or
    /// more dimensions 1,500 particles ([`MAX_MMUC_PARTICLES`](super::MAX_MMUC_PARTICLES)).
    pub density: SpatialDensity,
    /// The radius r0 > 0 of the tolerance ball of the loss (7), in state units.
    pub radius: f64,
    /// The costs of the loss (7).
    pub costs: Costs,
}

impl BernoulliEstimateOptions {
    /// Theorem III.3 of `000_…` ([`estimate`]) on these options, within the MMUC search's
    /// size caps, as a [`BernoulliReport`].
    ///
    /// # Errors
    /// [`Error::Count`] naming `density.mixture` or `density.particles` beyond the caps of
    /// [`SpatialDensity::check_mmuc_size`]; as [`ApplicationLoss::new`] (`radius`); as
    /// [`estimate`] (`existence`).
    pub fn estimate(&self) -> Result<BernoulliReport> {
        self.density.check_mmuc_size()?;
        let loss = ApplicationLoss::new(self.costs, self.radius)?;
        estimate(self.existence, &self.density, &loss).map(|e| BernoulliReport::from(&e))
    }
}

/// A [`BernoulliEstimate`] flattened to what a caller reads (Theorem III.3 of `000_…`):
/// the decision, the point, a* and q(a*), Γ (11) and the two expected losses (13)–(14).
#[derive(Clone, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct BernoulliReport {
    /// Whether to report the object: the optimal decision (10) (ties p = Γ report nothing).
    pub declare: bool,
    /// The reported point estimate: `mmuc` when `declare` is true, else null.
    #[cfg_attr(feature = "serde", serde(with = "crate::serde_shapes::nullable"))]
    pub estimate: Option<Vec<f64>>,
    /// The MMUC point a* (12): the centre of the radius-r0 ball most likely to hold the object.
    pub mmuc: Vec<f64>,
    /// The existence threshold Γ of eq. (11) (p > Γ reports for every cost matrix with c11 +
    /// c·q < c01 + c10 − c00, which includes MPE and MMOL; ±Infinity when the decision does
    /// not depend on p).
    pub threshold: f64,
    /// The miss probability q(a*) ∈ [0, 1]: the probability that the object, if it exists,
    /// lies outside the radius-r0 ball about a*.
    pub miss_probability: f64,
    /// The expected loss ρ_∅ (14) of reporting nothing.
    pub expected_loss_empty: f64,
    /// The expected loss ρ_{a*} (13) of reporting the single point a*.
    pub expected_loss_singleton: f64,
}

impl From<&BernoulliEstimate> for BernoulliReport {
    fn from(e: &BernoulliEstimate) -> Self {
        BernoulliReport {
            declare: e.declare,
            estimate: e.estimate.clone(),
            mmuc: e.mmuc.center.clone(),
            threshold: e.threshold.gamma,
            miss_probability: e.mmuc.miss_probability,
            expected_loss_empty: e.expected_loss_empty,
            expected_loss_singleton: e.expected_loss_singleton,
        }
    }
}

/// One Bernoulli component of [`MultiBernoulliPointOptions`].
#[derive(Clone, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct BernoulliComponent {
    /// The existence probability r ∈ [0, 1] of this component.
    pub existence: f64,
    /// The component's spatial density: at most 100 components and at most 1,500 particles in
    /// 2 or more dimensions, the MMUC search's caps ([`SpatialDensity::check_mmuc_size`]).
    pub density: SpatialDensity,
}

/// The options of a multi-Bernoulli's estimate, a Bernoulli estimate per component
/// ([`MultiBernoulliPointOptions::estimate`]): its components and the loss (7) of `000_…`.
#[derive(Clone, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct MultiBernoulliPointOptions {
    /// The Bernoulli components, each decided alone (at most 10,000
    /// ([`MAX_MULTI_BERNOULLI_COMPONENTS`])).
    pub components: Vec<BernoulliComponent>,
    /// The radius r0 > 0 of the tolerance ball of the loss (7), in state units.
    pub radius: f64,
    /// The costs of the loss (7).
    pub costs: Costs,
}

impl MultiBernoulliPointOptions {
    /// Theorem III.3 of `000_…` on each component ([`multi_bernoulli_estimate`]), within the
    /// MMUC search's size caps, as a [`MultiBernoulliReport`].
    ///
    /// # Errors
    /// [`Error::Count`] naming `components` beyond [`MAX_MULTI_BERNOULLI_COMPONENTS`], or
    /// `components[i].density.mixture` / `components[i].density.particles` beyond the caps of
    /// [`SpatialDensity::check_mmuc_size`]; as [`ApplicationLoss::new`] (`radius`); as
    /// [`multi_bernoulli_estimate`] (`components[i].existence`).
    pub fn estimate(&self) -> Result<MultiBernoulliReport> {
        check_multi_bernoulli_count(self.components.len())?;
        for (i, c) in self.components.iter().enumerate() {
            c.density
                .check_mmuc_size()
                .map_err(|e| e.within(&alloc::format!("components[{i}]")))?;
        }
        let loss = ApplicationLoss::new(self.costs, self.radius)?;
        let m = decide_each(
            self.components.iter().map(|c| (c.existence, &c.density)),
            &loss,
        )?;
        Ok(MultiBernoulliReport::from(&m))
    }
}

/// A [`MultiBernoulliEstimate`] flattened to what a caller reads: the reported indices, their
/// points, and each component's [`BernoulliReport`].
#[derive(Clone, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct MultiBernoulliReport {
    /// Indices of the declared components, increasing.
    pub reported: Vec<usize>,
    /// The point estimates a* of the reported components, in the order of `reported`.
    pub estimates: Vec<Vec<f64>>,
    /// The full Theorem III.3 result of each component, in the order of the components.
    pub components: Vec<BernoulliReport>,
}

impl From<&MultiBernoulliEstimate> for MultiBernoulliReport {
    fn from(m: &MultiBernoulliEstimate) -> Self {
        MultiBernoulliReport {
            reported: m.reported.clone(),
            estimates: m.points().into_iter().map(<[f64]>::to_vec).collect(),
            components: m.components.iter().map(BernoulliReport::from).collect(),
        }
    }
}
