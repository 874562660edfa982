//! The Bernoulli state, the prediction and update configurations, and the filter
//! configuration shared by [`GmBernoulliFilter`](super::GmBernoulliFilter) and
//! [`ParticleBernoulliFilter`](super::ParticleBernoulliFilter).

use alloc::vec::Vec;

use super::{Clutter, Detection, LinearGaussianLikelihood, LinearGaussianTransition};
use crate::error::{Error, Result, Shape, check_probability};
use crate::gaussian::{Gaussian, GaussianMixture};
use crate::math::fns;
use crate::mixture::ReductionOptions;
use crate::regions::Region;
use crate::splitting::{Spacing, SplitLibrary, SplitOptions};

/// Tolerance on Σ w = 1 for a mixture that must be a density.
const DENSITY_TOL: f64 = 1e-6;

/// Checks that `mixture` is a probability density (non-empty, weights summing to 1 within
/// 1e-6) and returns the sum of its weights.
pub(crate) fn density_total(mixture: &GaussianMixture, what: &str) -> Result<f64> {
    if mixture.is_empty() {
        return Err(Error::Unsupported {
            what: what.into(),
            reason: "a density needs at least one component",
        });
    }
    let total = mixture.total_weight();
    if total.is_nan() || fns::abs(total - 1.0) > DENSITY_TOL {
        return Err(Error::parameter(
            alloc::format!("{what}[].weight"),
            total,
            "weights summing to 1",
        ));
    }
    Ok(total)
}

/// Checks a Bernoulli without copying it; returns the sum of its weights.
pub(crate) fn check_state(state: &GmBernoulli) -> Result<f64> {
    check_probability(|| "existence".into(), state.existence)?;
    density_total(&state.mixture, "mixture")
}

/// Checks that `mixture` is a probability density (non-empty, weights summing to 1 within
/// 1e-6) and returns it with the weights divided by their sum (exactly normalised).
pub(crate) fn normalised_density(mixture: &GaussianMixture, what: &str) -> Result<GaussianMixture> {
    let total = density_total(mixture, what)?;
    if total == 1.0 {
        return Ok(mixture.clone());
    }
    let out: Vec<(f64, Gaussian)> = mixture
        .components()
        .iter()
        .map(|(w, g)| (w / total, g.clone()))
        .collect();
    GaussianMixture::new(out, what)
}

/// A Bernoulli random finite set with a Gaussian-mixture spatial density, eq. (39) of
/// `001_0f0df91eee9b30d5.txt`: f(∅) = 1 − r, f({x}) = r p(x), p(x) = Σ_ℓ w_ℓ N(x; m_ℓ, P_ℓ)
/// with Σ_ℓ w_ℓ = 1 (eq. (42)).
#[derive(Clone, Debug, PartialEq)]
pub struct GmBernoulli {
    /// The existence probability r ∈ [0, 1]: the probability that the object exists (`existence`).
    pub existence: f64,
    /// The spatial density p(x) of the object's state (`mixture`), a Gaussian mixture with weights
    /// summing to 1.
    pub mixture: GaussianMixture,
}

impl GmBernoulli {
    /// A validated Bernoulli; the weights are renormalised to sum to 1 (to rounding).
    ///
    /// # Errors
    /// [`Error::InvalidProbability`] naming `existence`; [`Error::Unsupported`] naming
    /// `mixture` when it is empty; [`Error::InvalidParameter`] naming `mixture[].weight`
    /// when the weights do not sum to 1 within 1e-6.
    pub fn new(existence: f64, mixture: GaussianMixture) -> Result<Self> {
        check_probability(|| "existence".into(), existence)?;
        let mixture = normalised_density(&mixture, "mixture")?;
        Ok(Self { existence, mixture })
    }

    /// The state dimension n.
    pub fn dim(&self) -> usize {
        self.mixture.dim().unwrap_or(0)
    }
}

/// Object birth: the probability p_b that an object is born when none exists, and the birth
/// density b(x) (eq. (43) of `001_…`) as a Gaussian mixture with weights summing to 1.
#[derive(Clone, Debug, PartialEq)]
pub struct Birth {
    /// The birth probability p_b ∈ [0, 1] (`birth.probability`): the probability that an object
    /// appears in one step when none exists.
    pub probability: f64,
    /// The birth density b(x) of a new object's state (`birth.mixture`); may be empty when p_b = 0.
    pub mixture: GaussianMixture,
}

impl Birth {
    /// A validated birth model (weights renormalised to exactly 1).
    ///
    /// # Errors
    /// [`Error::InvalidProbability`] naming `birth.probability`; as
    /// [`GmBernoulli::new`] for `birth.mixture` when p_b > 0 or the mixture is not empty.
    pub fn new(probability: f64, mixture: GaussianMixture) -> Result<Self> {
        check_probability(|| "birth.probability".into(), probability)?;
        let mixture = if mixture.is_empty() && probability == 0.0 {
            mixture
        } else {
            normalised_density(&mixture, "birth.mixture")?
        };
        Ok(Self {
            probability,
            mixture,
        })
    }

    /// No birth (p_b = 0).
    pub fn none() -> Self {
        Self {
            probability: 0.0,
            mixture: GaussianMixture::default(),
        }
    }
}

/// p_S when a user's options omit it (`survival`): 0.99, the survival of the airport
/// example of `001_…` Section V-C.
pub const fn default_survival() -> f64 {
    0.99
}

/// n_s when a user's options omit it (`position_dims`): 2, a position in the plane, as in
/// every example of `001_…` (and [`SplitOptions::default`]).
pub const fn default_position_dims() -> usize {
    2
}

/// The largest n_s (`position_dims`): 8 position coordinates (the splitting's collocation
/// grid has N_g^{n_s} points).
pub const MAX_POSITION_DIMS: usize = 8;

/// The most regions in one list (the reports of a scan, the exclusions).
pub const MAX_REGIONS: usize = 1000;

/// The most vector measurements in one scan.
pub const MAX_MEASUREMENTS: usize = 10_000;

/// The largest reduction cap L_max (`reduction.max_components`).
pub const MAX_REDUCED_COMPONENTS: usize = 1_000_000;

/// The prediction model of eqs. (40)–(49) of `001_…` (`gmBernoulliPredict`'s `transition`,
/// `survival`, `birth`).
#[derive(Clone, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct PredictOptions {
    /// The motion model π(x | x′) = N(x; F x′, Q) (`transition: { F, Q }`).
    pub transition: LinearGaussianTransition,
    /// The survival probability p_S ∈ [0, 1]: the probability that an existing object survives
    /// one step (`survival`; default [`default_survival`], 0.99).
    #[cfg_attr(feature = "serde", serde(default = "default_survival"))]
    pub survival: f64,
    /// Object birth: the birth probability p_b and birth density b(x) (`birth`; default
    /// [`Birth::none`]).
    #[cfg_attr(feature = "serde", serde(default = "Birth::none"))]
    pub birth: Birth,
}

impl PredictOptions {
    /// Checks p_S and the dimensions of the birth density against F.
    ///
    /// # Errors
    /// [`Error::InvalidProbability`] naming `survival` or `birth.probability`;
    /// [`Error::ShapeMismatch`] naming `birth.mixture[i].mean` and `transition.f`.
    pub fn validate(&self) -> Result<()> {
        check_probability(|| "survival".into(), self.survival)?;
        check_probability(|| "birth.probability".into(), self.birth.probability)?;
        let n = self.transition.dim();
        super::validate::check_means(
            self.birth.mixture.components().iter().map(|(_, g)| g.dim()),
            "birth.mixture",
            n,
            "transition.f",
            Shape::Matrix(n, n),
        )
    }
}

/// The splitting step of Algorithm 3 (`splitting`): the split library and the options of
/// Algorithms 1–2 ([`crate::splitting::split_for_regions`]). `position_dims` of the options
/// is overridden by [`UpdateOptions::position_dims`].
#[derive(Clone, Debug, PartialEq)]
#[cfg_attr(
    feature = "serde",
    derive(serde::Serialize, serde::Deserialize),
    serde(default)
)]
pub struct Splitting {
    /// Whether to split at all (`false`: the plain zeroth-order update on the predicted
    /// components).
    pub enabled: bool,
    /// The univariate split (default: [`default_split_library`]).
    pub library: SplitLibrary,
    /// w_min, the collocation grid, the caps (default: [`SplitOptions::default`]).
    pub options: SplitOptions,
}

impl Default for Splitting {
    fn default() -> Self {
        Self {
            enabled: true,
            library: default_split_library(),
            options: SplitOptions::default(),
        }
    }
}

/// The splitting step as a user gives it (`splitting`): the parameters of the split library
/// and of Algorithms 1–2 of LeGrand & Ferrari, "Split Happens! Imprecise and negative
/// information in Gaussian mixture random finite set filtering" (paper 001), every one optional,
/// with the defaults given below ([`Splitting::default`]).
/// (In Rust, [`SplittingOptions::build`] checks them and makes the [`Splitting`].)
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(
    feature = "serde",
    derive(serde::Serialize, serde::Deserialize),
    serde(default)
)]
pub struct SplittingOptions {
    /// Whether to split at all (default true; false: the plain zeroth-order update on the
    /// predicted components).
    pub enabled: bool,
    /// w_min, the weight below which a component is not split (default 0.01).
    pub min_weight: f64,
    /// R, the components of the univariate split, an integer in [2, 16] (default 4: Table I).
    pub components: usize,
    /// λ, the weight of the split's spread in its cost (default 0.001).
    pub lambda: f64,
    /// true: the variance-preserving library of pyest (default false: Table I for R = 4,
    /// λ = 0.001, the filters' default; see [`default_split_library`] for the measured
    /// errors of both).
    pub variance_preserving: bool,
    /// ζ, the half-width of the collocation grid in standard deviations (default 2).
    pub grid_bound: f64,
    /// N_g, the collocation points per axis (default 15; N_g^{n_s} ≤ 20000).
    pub grid_points: usize,
    /// The depth cap of the recursion (default 16, at most 64).
    pub max_depth: usize,
    /// The component cap of the recursion (default 10000, at most 50000).
    pub max_components: usize,
}

/// The defaults: those of [`Splitting::default`] (R and λ of its library).
impl Default for SplittingOptions {
    fn default() -> Self {
        let s = Splitting::default();
        Self {
            enabled: s.enabled,
            min_weight: s.options.min_weight,
            components: s.library.components(),
            lambda: s.library.lambda(),
            variance_preserving: false,
            grid_bound: s.options.grid_bound,
            grid_points: s.options.grid_points,
            max_depth: s.options.max_depth,
            max_components: s.options.max_components,
        }
    }
}

/// The most collocation points of one grid, N_g^{n_s}.
pub const MAX_GRID_POINTS: usize = 20_000;

impl SplittingOptions {
    /// The splitting step for positions of `position_dims` coordinates.
    ///
    /// # Errors
    /// [`Error::OutOfRange`] naming `position_dims` (outside [1, [`MAX_POSITION_DIMS`]]),
    /// `splitting.components` (outside [2, 16]),
    /// `splitting.max_depth` (above 64) or `splitting.max_components` (outside [1, 50000]);
    /// [`Error::InvalidParameter`] naming `splitting.grid_points` (below 2, or
    /// N_g^{n_s} above [`MAX_GRID_POINTS`]); those of the library's constructor
    /// ([`SplitLibrary::for_components`], [`SplitLibrary::variance_preserving`]) under
    /// `splitting`.
    pub fn build(&self, position_dims: usize) -> Result<Splitting> {
        Error::check_range("position_dims", position_dims, 1, MAX_POSITION_DIMS)?;
        let r = Error::check_range("splitting.components", self.components, 2, 16)?;
        Error::check_range("splitting.max_depth", self.max_depth, 0, 64)?;
        Error::check_range("splitting.max_components", self.max_components, 1, 50_000)?;
        let grid = (0..position_dims).try_fold(1usize, |a, _| a.checked_mul(self.grid_points));
        if self.grid_points < 2 || grid.is_none_or(|g| g > MAX_GRID_POINTS) {
            return Err(Error::parameter(
                "splitting.grid_points",
                self.grid_points as f64,
                "an integer >= 2 with gridPoints^positionDims <= 20000",
            ));
        }
        let library = if self.variance_preserving {
            SplitLibrary::variance_preserving(r, self.lambda)
        } else {
            SplitLibrary::for_components(r, self.lambda, Spacing::Equal)
        }
        .map_err(|e| e.within("splitting"))?;
        Ok(Splitting {
            enabled: self.enabled,
            library,
            options: SplitOptions {
                position_dims,
                min_weight: self.min_weight,
                grid_bound: self.grid_bound,
                grid_points: self.grid_points,
                max_depth: self.max_depth,
                max_components: self.max_components,
            },
        })
    }
}

/// The filters' default split library: Table I of `001_…` (R = 4, λ = 0.001,
/// [`SplitLibrary::table_i`]), chosen against the variance-preserving split of the
/// authors' `pyest` ([`SplitLibrary::variance_preserving`], R = 4, λ = 0.001) by which one's
/// posterior moments come closer to the exact update (53)–(55) (the test
/// `table1_default_library_is_closer_to_the_exact_update_with_a_million_draws`, 2D and 4D states, a small report
/// disc, a wide one and a miss, filter defaults and fine splitting; 10⁶ importance-weighted
/// draws for the exact moments).
///
/// Measured (max over entries; means in posterior σ, covariances relative to σ_i σ_j):
///
/// ```text
///                       Table I                      variance-preserving
///  case (defaults)   |dr|    mean    cov          |dr|    mean    cov
///  2d small report   0.018   0.065   0.48         0.019   0.030   0.52
///  2d wide report    0.0026  0.020   0.12         0.0020  0.038   0.11
///  2d miss           0.0097  0.079   0.13         0.0033  0.100   0.12
///  4d small report   0.020   0.117   0.46         0.022   0.049   0.59
///  4d wide report    0.0034  0.043   0.15         0.0023  0.043   0.13
///  4d miss           0.013   0.090   0.13         0.0033  0.109   0.11
///  sum of mean + cov over these and the fine settings:   2.63   (Table I)   2.77   (VP)
/// ```
///
/// The variance-preserving split gives the better Δ and r in every case (Δ errors 30–65 %
/// lower), and the better covariance after a miss, but a worse covariance after a report:
/// the mean-based partition over-counts a report disc whose boundary curves on the scale of
/// the components, which over-disperses the posterior, and Table I's 5 % variance loss per
/// split happens to offset part of it. On the airport example (20 runs, measured with a
/// birth density at the entrance only) the two were indistinguishable (mean position error
/// 9.64 against 9.59, 3σ coverage 99.4 % against 99.8 %).
pub fn default_split_library() -> SplitLibrary {
    SplitLibrary::table_i()
}

/// The filters' default reduction after an update (`reduction`): the two-pass strategy of
/// Section V-C of `001_…` — Vo & Ma's Mahalanobis merge first, at their threshold U = 4
/// (distance 2, Table II of reference \[31\] of `001_…`), then Runnalls down to L_max = 100
/// — after pruning components lighter than 1e-6 (renormalising the rest).
///
/// # Why U = 4 and not a tighter merge
/// The split library's components are consistent only on the scale of the collocation grid,
/// and w_min (absolute) stops the recursion: a component lighter than w_min that straddles
/// a report disc is kept or dropped whole by the mean-based partition (12), which widens the
/// posterior. A tighter merge leaves more, lighter components, so fewer of them are split at
/// the next update and the posterior is wider: on the airport example (100 seeded runs,
/// `airport_timing accuracy`) distance 0 (Runnalls only) / 0.5 / 1 / 2 / 3 gave a mean
/// position error of 10.40 / 9.79 / 9.35 / 9.27 / 9.30 and a position RSS of 30.2 / 22.8 /
/// 18.0 / 15.8 / 15.3 (the particle filter: 8.82 and 13.0), and distance 2 is also the
/// fastest of them.
pub fn default_reduction() -> ReductionOptions {
    ReductionOptions {
        prune_below: 1e-6,
        merge_distance: Some(2.0),
        max_components: Some(100),
    }
}

/// The update model of eqs. (51)–(60) of `001_…` and of the vector-measurement update
/// (`gmBernoulliUpdate`'s `positionDims`, `detection`, `clutter`, `splitting`, `reduction`,
/// `exclusions`).
#[derive(Clone, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct UpdateOptions {
    /// n_s: the position is the first `position_dims` state components (`positionDims`,
    /// default 2). Every region (FoV, report, exclusion) has this dimension.
    #[cfg_attr(feature = "serde", serde(default = "default_position_dims"))]
    pub position_dims: usize,
    /// Detection: the detection probability p_D(x; S) = 1_S(x) p_D inside the field of view S
    /// (`detection`).
    pub detection: Detection,
    /// Clutter (false reports): the rate λ_c and density c̃(ζ) (`clutter`).
    pub clutter: Clutter,
    /// Algorithm 3's splitting step (`splitting`).
    #[cfg_attr(feature = "serde", serde(default))]
    pub splitting: Splitting,
    /// The reduction after the update (`reduction`; default [`default_reduction`]).
    #[cfg_attr(feature = "serde", serde(default = "default_reduction"))]
    pub reduction: ReductionOptions,
    /// Regions the object cannot occupy (`exclusions`; Fig. 6's grey areas). See
    /// [`crate::filters`] for how their mass is removed.
    #[cfg_attr(feature = "serde", serde(default))]
    pub exclusions: Vec<Region>,
}

impl UpdateOptions {
    /// The configuration with the default splitting, reduction and no exclusions.
    pub fn new(position_dims: usize, detection: Detection, clutter: Clutter) -> Self {
        Self {
            position_dims,
            detection,
            clutter,
            splitting: Splitting::default(),
            reduction: default_reduction(),
            exclusions: Vec::new(),
        }
    }

    /// Checks every field against the state dimension `state_dim`.
    ///
    /// # Errors
    /// [`Error::OutOfRange`] naming `position_dims` (outside [1, [`MAX_POSITION_DIMS`]]) or
    /// `reduction.max_components` (outside [1, [`MAX_REDUCED_COMPONENTS`]]);
    /// [`Error::Count`] naming `exclusions` (more than [`MAX_REGIONS`]);
    /// [`Error::ShapeMismatch`] naming `position_dims` and `mixture[0].mean` (n_s above the
    /// state dimension); [`Error::InvalidParameter`] naming `reduction.prune_below`, `reduction.merge_distance` or `reduction.max_components`; those
    /// of [`Detection::validate`] and [`Clutter::validate`]; [`Error::ShapeMismatch`]
    /// naming the field of `exclusions[i]` that carries its dimension and `position_dims`.
    pub fn validate(&self, state_dim: usize) -> Result<()> {
        let ns = Error::check_range("position_dims", self.position_dims, 1, MAX_POSITION_DIMS)?;
        Error::check_count(
            "exclusions",
            "regions",
            self.exclusions.len(),
            0,
            MAX_REGIONS,
        )?;
        if let Some(m) = self.reduction.max_components {
            Error::check_range("reduction.max_components", m, 1, MAX_REDUCED_COMPONENTS)?;
        }
        if ns > state_dim {
            // the state's dimension is the mixture's (a filter checks its transition first)
            return Err(Error::shapes(
                "position_dims",
                crate::error::Shape::Value(ns),
                "mixture[0].mean",
                crate::error::Shape::Length(state_dim),
            ));
        }
        self.detection.validate(Some(ns))?;
        self.clutter.validate()?;
        for (i, e) in self.exclusions.iter().enumerate() {
            super::validate::check_region(e, &alloc::format!("exclusions[{i}]"), ns)?;
        }
        let r = &self.reduction;
        if !(r.prune_below.is_finite() && (0.0..1.0).contains(&r.prune_below)) {
            return Err(Error::parameter(
                "reduction.prune_below",
                r.prune_below,
                "in [0, 1)",
            ));
        }
        if let Some(d) = r.merge_distance
            && !(d.is_finite() && d >= 0.0)
        {
            return Err(Error::parameter(
                "reduction.merge_distance",
                d,
                "finite and >= 0",
            ));
        }
        Ok(())
    }
}

/// The configuration of [`GmBernoulliFilter`](super::GmBernoulliFilter) and
/// [`ParticleBernoulliFilter`](super::ParticleBernoulliFilter): the initial Bernoulli, the
/// prediction model and the update model, with the JavaScript names of the fields in
/// parentheses. The particle filter ignores `splitting` and `reduction`.
#[derive(Clone, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct BernoulliFilterOptions {
    /// The initial existence probability r_{0|0} ∈ [0, 1] (`existence`).
    pub existence: f64,
    /// The initial spatial density p_{0|0} (`mixture`), a Gaussian mixture with weights summing to
    /// 1.
    pub mixture: GaussianMixture,
    /// The motion model: transition matrix F and process noise covariance Q (`transition`).
    pub transition: LinearGaussianTransition,
    /// The survival probability p_S ∈ [0, 1] (`survival`): the probability that an existing object
    /// survives one step (default [`default_survival`], 0.99).
    #[cfg_attr(feature = "serde", serde(default = "default_survival"))]
    pub survival: f64,
    /// Object birth: the birth probability p_b and birth density b(x) (`birth`; default
    /// [`Birth::none`]: no birth).
    #[cfg_attr(feature = "serde", serde(default = "Birth::none"))]
    pub birth: Birth,
    /// The number n_s of position components (`positionDims`): the first n_s state components are
    /// the position that regions refer to (default [`default_position_dims`], 2).
    #[cfg_attr(feature = "serde", serde(default = "default_position_dims"))]
    pub position_dims: usize,
    /// Detection: the detection probability p_D(x; S) = 1_S(x) p_D inside the field of view S
    /// (`detection`).
    pub detection: Detection,
    /// Clutter (false reports): the rate λ_c and density c̃ (`clutter`).
    pub clutter: Clutter,
    /// H, R for vector measurements (`likelihood`); `None` when only region reports are
    /// processed.
    #[cfg_attr(feature = "serde", serde(default))]
    pub likelihood: Option<LinearGaussianLikelihood>,
    /// The splitting step of the GM filter's update (`splitting`; default [`Splitting::default`]).
    #[cfg_attr(feature = "serde", serde(default = "Splitting::default"))]
    pub splitting: Splitting,
    /// The GM filter's mixture reduction after each update (`reduction`; default
    /// [`default_reduction`]).
    #[cfg_attr(feature = "serde", serde(default = "default_reduction"))]
    pub reduction: ReductionOptions,
    /// Regions the object cannot occupy (`exclusions`; default none).
    #[cfg_attr(feature = "serde", serde(default = "Vec::new"))]
    pub exclusions: Vec<Region>,
}

impl BernoulliFilterOptions {
    /// The prediction part.
    pub fn predict_options(&self) -> PredictOptions {
        PredictOptions {
            transition: self.transition.clone(),
            survival: self.survival,
            birth: self.birth.clone(),
        }
    }

    /// The update part.
    pub fn update_options(&self) -> UpdateOptions {
        UpdateOptions {
            position_dims: self.position_dims,
            detection: self.detection.clone(),
            clutter: self.clutter.clone(),
            splitting: self.splitting.clone(),
            reduction: self.reduction,
            exclusions: self.exclusions.clone(),
        }
    }

    /// Checks the whole configuration: first the dimensions of its fields against each
    /// other ([`ConfigShapes::check`](super::ConfigShapes::check), then every region against
    /// n_s), then each field alone.
    ///
    /// # Errors
    /// [`Error::ShapeMismatch`] naming the field that disagrees and the one it disagrees
    /// with (`mixture[0].mean has length 4 but transition.f is 2×2`,
    /// `detection.fov.box.min has length 3 but position_dims is 2`); those of
    /// [`GmBernoulli::new`], [`PredictOptions::validate`], [`UpdateOptions::validate`].
    pub fn validate(&self) -> Result<()> {
        super::validate::check_config(self)?;
        GmBernoulli::new(self.existence, self.mixture.clone())?;
        self.predict_options().validate()?;
        self.update_options().validate(self.transition.dim())
    }
}
