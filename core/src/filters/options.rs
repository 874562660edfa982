//! The options of the Bernoulli filters as a user writes them (what the bindings read, with
//! the `serde` feature): F, Q, H and R as rows, unchecked ([`TransitionRows`],
//! [`LikelihoodRows`]), so that the shapes of all the fields are checked against each other
//! ([`ConfigShapes::check`](super::ConfigShapes::check)) before any model is built, and the
//! splitting step as its knobs ([`SplittingOptions`]). For the GM Bernoulli prediction,
//! eqs. (40)–(49) of `001_0f0df91eee9b30d5.txt`, and both filters of its Section V.

use alloc::vec::Vec;

use super::{
    BernoulliFilterOptions, Birth, Clutter, Detection, GmBernoulli, LikelihoodRows,
    ParticleOptions, PredictOptions, Splitting, SplittingOptions, TransitionRows, UpdateOptions,
};
use super::{GmBernoulliUpdate, gm_bernoulli_update, gm_bernoulli_update_vector};
#[cfg(feature = "serde")]
use super::{
    default_mcmc_moves, default_particles, default_position_dims, default_reduction,
    default_survival,
};
use crate::error::{Error, Phrase, Result};
use crate::gaussian::GaussianMixture;
use crate::mixture::ReductionOptions;
use crate::regions::Region;

/// The splitting step of `options` for positions of `position_dims` coordinates
/// ([`SplittingOptions::build`]); `None`: [`Splitting::default`].
///
/// # Errors
/// As [`SplittingOptions::build`].
pub fn splitting_or_default(
    options: Option<&SplittingOptions>,
    position_dims: usize,
) -> Result<Splitting> {
    match options {
        Some(s) => s.build(position_dims),
        None => Ok(Splitting::default()),
    }
}

/// Options of the GM Bernoulli prediction, eqs. (40)–(49) of `001_0f0df91eee9b30d5.txt`:
/// the Bernoulli before it and the model.
#[derive(Clone, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct GmBernoulliPredictOptions {
    /// The existence probability r ∈ [0, 1] before the prediction.
    pub existence: f64,
    /// The spatial density p(x) before the prediction, a Gaussian mixture: weights sum to 1 (at
    /// most 10,000 components).
    pub mixture: GaussianMixture,
    /// The motion model: transition matrix F and process noise covariance Q.
    pub transition: TransitionRows,
    /// The survival probability p_S ∈ [0, 1]: the probability that an existing object survives one
    /// step (default 0.99).
    #[cfg_attr(feature = "serde", serde(default = "default_survival"))]
    pub survival: f64,
    /// Object birth: the birth probability p_b and birth density b(x); omitted: no birth.
    #[cfg_attr(feature = "serde", serde(default = "Birth::none"))]
    pub birth: Birth,
}

impl GmBernoulliPredictOptions {
    /// The Bernoulli and the prediction's options, F and Q checked against the mixtures
    /// before the transition is built.
    ///
    /// # Errors
    /// As [`TransitionRows::check_shapes`], then [`TransitionRows::build`].
    pub fn build(self) -> Result<(GmBernoulli, PredictOptions)> {
        (self.transition).check_shapes(&self.mixture, &self.birth.mixture, None, 0)?;
        let state = GmBernoulli {
            existence: self.existence,
            mixture: self.mixture,
        };
        let options = PredictOptions {
            transition: self.transition.build()?,
            survival: self.survival,
            birth: self.birth,
        };
        Ok((state, options))
    }
}

/// The configuration of both Bernoulli filters as a user writes it (the particle filter also
/// reads `particles`, `birth_particles`, `mcmc_moves`, `seed`, and ignores `splitting` and
/// `reduction`).
#[derive(Clone, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct BernoulliFilterConfig {
    /// The initial existence probability r_{0|0} ∈ [0, 1].
    pub existence: f64,
    /// The initial spatial density p_{0|0}, a Gaussian mixture (weights sum to 1).
    pub mixture: GaussianMixture,
    /// The motion model: transition matrix F and process noise covariance Q.
    pub transition: TransitionRows,
    /// The survival probability p_S ∈ [0, 1]: the probability that an existing object survives one
    /// step (default 0.99).
    #[cfg_attr(feature = "serde", serde(default = "default_survival"))]
    pub survival: f64,
    /// Object birth: the birth probability p_b and birth density b(x); omitted: no birth.
    #[cfg_attr(feature = "serde", serde(default = "Birth::none"))]
    pub birth: Birth,
    /// The number n_s of position components: the first n_s state components are the position that
    /// regions refer to (default 2).
    #[cfg_attr(feature = "serde", serde(default = "default_position_dims"))]
    pub position_dims: usize,
    /// Detection: the detection probability p_D inside the field of view S.
    pub detection: Detection,
    /// Clutter (false reports): the rate λ_c and density c̃.
    pub clutter: Clutter,
    /// The likelihood (measurement matrix H, noise covariance R) for vector measurements.
    #[cfg_attr(feature = "serde", serde(default))]
    pub likelihood: Option<LikelihoodRows>,
    /// The splitting step (GM filter only); omitted: the defaults.
    #[cfg_attr(feature = "serde", serde(default))]
    pub splitting: Option<SplittingOptions>,
    /// The reduction after each update (GM filter only); omitted: prune 1e-6, merge within 2,
    /// Runnalls to 100.
    #[cfg_attr(feature = "serde", serde(default = "default_reduction"))]
    pub reduction: ReductionOptions,
    /// Regions the object cannot occupy.
    #[cfg_attr(feature = "serde", serde(default))]
    pub exclusions: Vec<Region>,
    /// Particle filter: the number of particles N (default 5000, at most 200000).
    #[cfg_attr(feature = "serde", serde(default = "default_particles"))]
    pub particles: usize,
    /// Particle filter: birth particles per prediction (default N/10).
    #[cfg_attr(feature = "serde", serde(default))]
    pub birth_particles: Option<usize>,
    /// Particle filter: MCMC moves per update (default 1, at most 10).
    #[cfg_attr(feature = "serde", serde(default = "default_mcmc_moves"))]
    pub mcmc_moves: usize,
    /// Particle filter: the seed; omitted: fresh entropy (the `seed` getter returns it).
    #[cfg_attr(feature = "serde", serde(default))]
    pub seed: Option<u64>,
}

impl BernoulliFilterConfig {
    /// The filters' configuration and the particle filter's settings (its seed `seed` or 0),
    /// the shapes of all the fields checked against each other first, then the splitting
    /// step, the likelihood and the transition built.
    ///
    /// # Errors
    /// As [`TransitionRows::check_shapes`], [`splitting_or_default`],
    /// [`LikelihoodRows::build`], [`TransitionRows::build`].
    pub fn build(self) -> Result<(BernoulliFilterOptions, ParticleOptions)> {
        (self.transition).check_shapes(
            &self.mixture,
            &self.birth.mixture,
            self.likelihood.as_ref(),
            self.position_dims,
        )?;
        let splitting = splitting_or_default(self.splitting.as_ref(), self.position_dims)?;
        let likelihood = match &self.likelihood {
            Some(l) => Some(l.build()?),
            None => None,
        };
        let config = BernoulliFilterOptions {
            existence: self.existence,
            mixture: self.mixture,
            transition: self.transition.build()?,
            survival: self.survival,
            birth: self.birth,
            position_dims: self.position_dims,
            detection: self.detection,
            clutter: self.clutter,
            likelihood,
            splitting,
            reduction: self.reduction,
            exclusions: self.exclusions,
        };
        let particle = ParticleOptions {
            particles: self.particles,
            birth_particles: self.birth_particles,
            mcmc_moves: self.mcmc_moves,
            seed: self.seed.unwrap_or(0),
        };
        Ok((config, particle))
    }
}

/// Options of the GM Bernoulli update (Algorithm 3 of `001_0f0df91eee9b30d5.txt`) of one
/// Bernoulli, with imprecise `reports` or with vector `measurements` and their `likelihood`.
#[derive(Clone, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct GmBernoulliUpdateOptions {
    /// The predicted existence probability r_{k|k−1} ∈ [0, 1].
    pub existence: f64,
    /// The predicted spatial density p_{k|k−1}, a Gaussian mixture: weights sum to 1.
    pub mixture: GaussianMixture,
    /// The number n_s of position components: the first n_s state components are the position that
    /// regions refer to (default 2, in [1, 8]).
    #[cfg_attr(feature = "serde", serde(default = "default_position_dims"))]
    pub position_dims: usize,
    /// Detection: the detection probability p_D inside the field of view S.
    pub detection: Detection,
    /// The imprecise reports ζ (regions, g̃ = 1_ζ); omitted or empty with no `measurements`:
    /// the non-detection update.
    #[cfg_attr(feature = "serde", serde(default))]
    pub reports: Option<Vec<Region>>,
    /// Vector measurements (with `likelihood`): the vector-measurement update instead. At most
    /// 10,000, and components (after splitting) × measurements × ⌈n²/16⌉ ≤ 2^18 (an error
    /// naming `measurements` beyond).
    #[cfg_attr(
        feature = "serde",
        serde(default, with = "crate::serde_shapes::rows_of_numbers")
    )]
    pub measurements: Option<Vec<Vec<f64>>>,
    /// The likelihood of the vector measurements: measurement matrix H and noise covariance R.
    #[cfg_attr(feature = "serde", serde(default))]
    pub likelihood: Option<LikelihoodRows>,
    /// Clutter (false reports): the rate λ_c and density c̃.
    pub clutter: Clutter,
    /// The splitting step; omitted: the defaults.
    #[cfg_attr(feature = "serde", serde(default))]
    pub splitting: Option<SplittingOptions>,
    /// The reduction; omitted: prune 1e-6, merge within 2, Runnalls to 100.
    #[cfg_attr(feature = "serde", serde(default = "default_reduction"))]
    pub reduction: ReductionOptions,
    /// Regions the object cannot occupy (mass removed by the mean-based partition after
    /// splitting; the existence is unchanged).
    #[cfg_attr(feature = "serde", serde(default))]
    pub exclusions: Vec<Region>,
}

impl GmBernoulliUpdateOptions {
    /// The update's options (the splitting step built for n_s).
    ///
    /// # Errors
    /// As [`splitting_or_default`].
    pub fn update_options(&self) -> Result<UpdateOptions> {
        Ok(UpdateOptions {
            position_dims: self.position_dims,
            detection: self.detection.clone(),
            clutter: self.clutter.clone(),
            splitting: splitting_or_default(self.splitting.as_ref(), self.position_dims)?,
            reduction: self.reduction,
            exclusions: self.exclusions.clone(),
        })
    }

    /// The update these options ask for: with `measurements` and `likelihood` the
    /// vector-measurement update ([`gm_bernoulli_update_vector`]), else the update with
    /// `reports` ([`gm_bernoulli_update`]; omitted: the non-detection update).
    ///
    /// # Errors
    /// [`Error::Form`] naming `likelihood` when `measurements` come without it; as
    /// [`GmBernoulliUpdateOptions::update_options`], [`LikelihoodRows::build`] and the update.
    #[inline] // instantiates the updates in the caller's crate, with the filter classes' copies
    pub fn run(self) -> Result<GmBernoulliUpdate> {
        let config = self.update_options()?;
        let state = GmBernoulli {
            existence: self.existence,
            mixture: self.mixture,
        };
        match (self.measurements, self.likelihood) {
            (Some(z), Some(l)) => gm_bernoulli_update_vector(&state, &z, &l.build()?, &config),
            (Some(_), None) => Err(Error::form(
                "likelihood",
                false,
                alloc::vec![
                    Phrase::text("is needed with "),
                    Phrase::path("measurements")
                ],
            )),
            (None, _) => gm_bernoulli_update(&state, &self.reports.unwrap_or_default(), &config),
        }
    }
}
