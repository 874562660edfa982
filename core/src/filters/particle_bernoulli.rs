//! The Bernoulli particle filter (Ristic, Vo, Vo & Farina's tutorial form), the filter the
//! airport example of `001_…` Section V-C compares the GM filter with.

use alloc::vec::Vec;

use rand::Rng;

use super::config::{BernoulliFilterOptions, PredictOptions, UpdateOptions};
use super::estimate::{EstimateOptions, FilterEstimate, particle_estimate};
use super::gm_bernoulli::{
    Term, UpdateInfo, add_report, bernoulli_weights, check_measurements, count_zero_kappa,
};
use super::likelihood::{GeneralizedLikelihood, LinearGaussianLikelihood, RegionReports};
use crate::error::{Error, Result};
use crate::gaussian::{GaussianMixture, normal};
use crate::math::fns;
use crate::math::rng::{SeededRng, seeded, systematic, uniform};
use crate::math::sum::NeumaierSum;
use crate::regions::Region;

/// Largest particle count (memory: 2 n f64 per particle).
pub const MAX_PARTICLES: usize = 200_000;
/// Largest number of MCMC moves per update.
pub const MAX_MCMC_MOVES: usize = 10;

/// The most likelihood evaluations of one update, counted as (N + B) · max(m, 1) ·
/// (1 + `mcmc_moves`) for the N + B particles after a prediction and m reports, and times
/// ⌈d (n + d) / 12⌉ for m vector measurements of dimension d and an n-dimensional state (the
/// cost of one N(z; H x, R) relative to a 2-D measurement of a 4-D state): `2·10^7`, at most
/// about 1.1 s in Node (20,000 particles × 1000 2-D measurements; an update over 200,000
/// particles and 1000 report regions, 2·10^8 evaluations, ran for more than 2.5 s). Beyond
/// it the update returns [`Error::OverBudget`] naming `reports` (or `measurements`) before
/// any work.
pub const MAX_UPDATE_EVALUATIONS: usize = 20_000_000;

/// The particle filter's own settings (`particles`, `mcmcMoves`, `seed`, `birthParticles`).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[cfg_attr(
    feature = "serde",
    derive(serde::Serialize, serde::Deserialize),
    serde(default)
)]
pub struct ParticleOptions {
    /// N, the number of particles kept after each update (`particles`, default 5000, the
    /// paper's count).
    pub particles: usize,
    /// B, the birth particles drawn from b(x) at each prediction (`birthParticles`);
    /// `None`: N/10 (at least 1). None are drawn when p_b (1 − r) = 0.
    pub birth_particles: Option<usize>,
    /// Metropolis–Hastings move steps after each resampling (`mcmcMoves`, default 1).
    pub mcmc_moves: usize,
    /// The seed of the filter's [`crate::math::rng`] stream (`seed`, default 0).
    pub seed: u64,
}

/// N when a user's options omit it (`particles`): 5000, the paper's count.
pub const fn default_particles() -> usize {
    5000
}

/// The MCMC moves per update when a user's options omit them (`mcmc_moves`): 1.
pub const fn default_mcmc_moves() -> usize {
    1
}

impl Default for ParticleOptions {
    fn default() -> Self {
        Self {
            particles: default_particles(),
            birth_particles: None,
            mcmc_moves: default_mcmc_moves(),
            seed: 0,
        }
    }
}

/// Where a particle's predicted density came from (for the move step's target).
#[derive(Clone, Copy, Debug, PartialEq)]
enum Origin {
    /// Drawn from π(· | x′): the prior is N(x; F x′, Q) with F x′ stored in `parents`.
    Survived,
    /// Drawn from the birth density b(x).
    Born,
    /// Not predicted since the last update (two updates in a row): not moved.
    Fixed,
}

/// The Bernoulli particle filter of B. Ristic, B.-T. Vo, B.-N. Vo, A. Farina, "A tutorial on
/// Bernoulli filters: theory, implementation and applications," IEEE Trans. Signal Process.
/// 61(13):3406–3430, 2013, doi:10.1109/TSP.2013.2257765 (reference \[23\] of `001_…`), with the
/// models of a [`BernoulliFilterOptions`] (`ParticleBernoulliFilter`):
///
/// - **Prediction** (their eqs. (34)–(35), with a known birth density instead of the
///   measurement-driven one): r_{k|k−1} = p_b (1 − r) + p_S r; every particle moves by
///   x ← F x + G ε (G Gᵀ = Q) and keeps weight w p_S r / r_{k|k−1}; B birth particles are
///   drawn from b(x) with weight p_b (1 − r) / (B r_{k|k−1}).
/// - **Update** (their eqs. (57)–(59), the same formulas as the GM update but at every
///   particle, so no expansion): with L(x) = 1 − p_D(x) + p_D(x) Σ_ζ g̃(ζ | x)/κ(ζ) (region
///   reports 1_ζ(s), any [`GeneralizedLikelihood`], or N(z; H x, R) for vector
///   measurements), Δ = Σ_i w_i (1 − L(x_i)), r ← r (1 − Δ)/(1 − r Δ), w_i ∝ w_i L(x_i).
///   Exclusion regions zero the weight of the particles inside them before the update and
///   renormalise (the existence is unchanged, as in the GM filter). An empty scan is a real
///   update, never skipped.
/// - **Resampling**: systematic, back to N particles.
/// - **MCMC move** (the resample-move step of Gilks & Berzuini that the tutorial uses for
///   diversity): each particle, with its predicted parent x′ kept fixed, takes
///   `mcmc_moves` Metropolis–Hastings steps targeting L(x) π(x | x′) 1_{C(E)}(x) (b(x) for a
///   birth particle), which leaves the posterior invariant; the proposal is a Gaussian random
///   walk with covariance h² Σ̂ (Σ̂ the particles' covariance, h = (4/((n + 2) N))^{1/(n+4)},
///   the regularisation bandwidth of Musso, Oudjane & Le Gland). Needs Q positive definite.
///
/// Seeded: the same seed gives the same particles on every platform.
#[derive(Clone, Debug)]
pub struct ParticleBernoulliFilter {
    dim: usize,
    existence: f64,
    /// Row-major, `dim` numbers per particle.
    particles: Vec<f64>,
    weights: Vec<f64>,
    /// F x′ of each particle's parent (survivors) since the last prediction.
    parents: Vec<f64>,
    origins: Vec<Origin>,
    predict: PredictOptions,
    update: UpdateOptions,
    likelihood: Option<LinearGaussianLikelihood>,
    options: ParticleOptions,
    rng: SeededRng,
    last: Option<UpdateInfo>,
}

impl ParticleBernoulliFilter {
    /// A filter at r_{0|0} with N particles drawn from p_{0|0} (equal weights).
    ///
    /// # Errors
    /// As [`BernoulliFilterOptions::validate`]; [`Error::OutOfRange`] naming `particles`
    /// (outside [1, [`MAX_PARTICLES`]]), `birth_particles` (above [`MAX_PARTICLES`]) or
    /// `mcmc_moves` (above [`MAX_MCMC_MOVES`]). A singular (positive semidefinite) Q is
    /// accepted: the prediction samples its noise with a factor G Gᵀ = Q that allows it
    /// ([`LinearGaussianTransition`](super::LinearGaussianTransition)), and the move step
    /// leaves the survivors where the prediction put them (their transition density is
    /// degenerate, so every Metropolis–Hastings proposal off Q's range would be rejected).
    pub fn new(config: BernoulliFilterOptions, options: ParticleOptions) -> Result<Self> {
        config.validate()?;
        Error::check_range("particles", options.particles, 1, MAX_PARTICLES)?;
        if let Some(b) = options.birth_particles {
            Error::check_range("birth_particles", b, 0, MAX_PARTICLES)?;
        }
        Error::check_range("mcmc_moves", options.mcmc_moves, 0, MAX_MCMC_MOVES)?;
        let dim = config.transition.dim();
        let mut rng = seeded(options.seed);
        let n = options.particles;
        let mixture = super::config::normalised_density(&config.mixture, "mixture")?;
        let mut particles = Vec::with_capacity(n * dim);
        for _ in 0..n {
            sample_mixture(&mixture, &mut rng, &mut particles);
        }
        Ok(Self {
            dim,
            existence: config.existence,
            particles,
            weights: alloc::vec![1.0 / n as f64; n],
            parents: Vec::new(),
            origins: Vec::new(),
            predict: config.predict_options(),
            update: config.update_options(),
            likelihood: config.likelihood,
            options,
            rng,
            last: None,
        })
    }

    /// r, the probability that the object exists.
    pub fn existence(&self) -> f64 {
        self.existence
    }

    /// The particles, row-major (`dim()` numbers each).
    pub fn particles(&self) -> &[f64] {
        &self.particles
    }

    /// The normalised weights (equal after an update).
    pub fn weights(&self) -> &[f64] {
        &self.weights
    }

    /// The state dimension n.
    pub fn dim(&self) -> usize {
        self.dim
    }

    /// Δ and the particle count of the last update.
    pub fn last_update(&self) -> Option<UpdateInfo> {
        self.last
    }

    /// The prediction: survivors moved through the transition, birth particles added.
    /// (A prediction that follows a prediction resamples back to N particles first.) It cannot
    /// fail: the models were checked by [`ParticleBernoulliFilter::new`].
    pub fn predict(&mut self) {
        let n = self.options.particles;
        if self.weights.len() > n {
            let idx = systematic(&self.weights, n, &mut self.rng);
            self.particles = gather(&self.particles, &idx, self.dim);
            self.weights = alloc::vec![1.0 / n as f64; n];
        }
        let dim = self.dim;
        let r = self.existence;
        let cfg = &self.predict;
        let born = cfg.birth.probability * (1.0 - r);
        let survive = cfg.survival * r;
        let predicted = born + survive;
        let f = cfg.transition.f();
        let g = cfg.transition.factor();
        let count = self.weights.len();
        let mut parents = Vec::with_capacity(count * dim);
        let mut fx = alloc::vec![0.0; dim];
        let mut eps = alloc::vec![0.0; dim];
        for p in self.particles.chunks_exact_mut(dim) {
            for (i, o) in fx.iter_mut().enumerate() {
                let mut s = 0.0;
                for (j, pj) in p.iter().enumerate() {
                    s += f[(i, j)] * pj;
                }
                *o = s;
            }
            for e in eps.iter_mut() {
                *e = normal::sample(&mut self.rng);
            }
            for (i, pi) in p.iter_mut().enumerate() {
                let mut s = fx[i];
                for (j, ej) in eps.iter().enumerate() {
                    s += g[(i, j)] * ej;
                }
                *pi = s;
            }
            parents.extend_from_slice(&fx);
        }
        let mut origins = alloc::vec![Origin::Survived; count];
        if predicted > 0.0 {
            let scale = survive / predicted;
            for w in self.weights.iter_mut() {
                *w *= scale;
            }
            let b = if born > 0.0 && !cfg.birth.mixture.is_empty() {
                self.options.birth_particles.unwrap_or((n / 10).max(1))
            } else {
                0
            };
            if b > 0 {
                let wb = born / predicted / b as f64;
                for _ in 0..b {
                    sample_mixture(&cfg.birth.mixture, &mut self.rng, &mut self.particles);
                    parents.extend(core::iter::repeat_n(0.0, dim));
                    self.weights.push(wb);
                    origins.push(Origin::Born);
                }
            }
        }
        self.existence = predicted.clamp(0.0, 1.0);
        self.parents = parents;
        self.origins = origins;
    }

    /// The update with region reports (g̃ = 1_ζ(s)); `&[]` is the non-detection update.
    ///
    /// # Errors
    /// [`Error::DimensionMismatch`] naming `reports[i]`; as
    /// [`ParticleBernoulliFilter::update_with`]. On `Err`, the filter is unchanged (particles,
    /// weights, existence and random stream).
    pub fn update(&mut self, reports: &[Region]) -> Result<UpdateInfo> {
        super::likelihood::check_reports(reports, self.update.position_dims)?;
        self.update_with(&RegionReports(reports))
    }

    /// The update with any generalized likelihood.
    ///
    /// # Errors
    /// [`Error::InvalidParameter`] naming `likelihood[i]` when g̃ returns a negative or
    /// non-finite value, `exclusions` when every particle lies in an exclusion region,
    /// `reports` or `clutter.rate` as [`gm_bernoulli_update_with`](super::gm_bernoulli_update_with);
    /// those of [`crate::filters::Clutter`]. On `Err`, the filter is unchanged.
    pub fn update_with<L: GeneralizedLikelihood + ?Sized>(
        &mut self,
        likelihood: &L,
    ) -> Result<UpdateInfo> {
        let m = likelihood.reports();
        self.check_update_work(m, None)?;
        let kappa = self.update.clutter.intensities(m, |_| None)?;
        let eval = |x: &[f64]| -> (f64, f64) {
            let (mut ratio, mut certain) = (0.0, 0.0);
            for (i, k) in kappa.iter().enumerate() {
                let g = likelihood.likelihood(i, x);
                if !(g.is_finite() && g >= 0.0) {
                    return (f64::NAN, i as f64);
                }
                add_report(&mut ratio, &mut certain, g, *k);
            }
            (ratio, certain)
        };
        self.update_inner(&eval, count_zero_kappa(&kappa))
    }

    /// The update with vector measurements (the config's `likelihood`).
    ///
    /// # Errors
    /// [`Error::Unsupported`] naming `likelihood` when the config has none;
    /// [`Error::DimensionMismatch`] naming `measurements[j]`; [`Error::InvalidParameter`]
    /// naming `measurements[j][i]`; as [`ParticleBernoulliFilter::update_with`]. On `Err`, the
    /// filter is unchanged.
    pub fn update_measurements<M: AsRef<[f64]>>(
        &mut self,
        measurements: &[M],
    ) -> Result<UpdateInfo> {
        let Some(lik) = self.likelihood.clone() else {
            return Err(Error::Unsupported {
                what: "likelihood".into(),
                reason: "vector measurements need a likelihood { H, R } in the filter's config",
            });
        };
        check_measurements(measurements, &lik)?;
        let (d, n) = (lik.measurement_dim(), self.dim);
        self.check_update_work(measurements.len(), Some((d * (n + d)).div_ceil(12)))?;
        let kappa = self
            .update
            .clutter
            .intensities(measurements.len(), |j| Some(measurements[j].as_ref()))?;
        let eval = |x: &[f64]| -> (f64, f64) {
            let (mut ratio, mut certain) = (0.0, 0.0);
            for (z, k) in measurements.iter().zip(&kappa) {
                add_report(&mut ratio, &mut certain, lik.density(z.as_ref(), x), *k);
            }
            (ratio, certain)
        };
        self.update_inner(&eval, count_zero_kappa(&kappa))
    }

    /// `Ok` if an update with `m` reports (`cost` = 1) or measurements (`cost` per
    /// evaluation) stays within [`MAX_UPDATE_EVALUATIONS`].
    ///
    /// # Errors
    /// [`Error::OverBudget`] naming `reports` or `measurements`.
    fn check_update_work(&self, m: usize, cost: Option<usize>) -> Result<()> {
        let per_report = self
            .weights
            .len()
            .saturating_mul(1 + self.options.mcmc_moves)
            .saturating_mul(cost.unwrap_or(1).max(1));
        let (what, measure, limit) = match cost {
            None => (
                "reports",
                "particles × reports × (1 + MCMC moves)",
                "MAX_UPDATE_EVALUATIONS = 2·10^7 (pass fewer reports or particles)",
            ),
            Some(_) => (
                "measurements",
                "particles × measurements × (1 + MCMC moves) × ⌈d (n + d) / 12⌉",
                "MAX_UPDATE_EVALUATIONS = 2·10^7 (pass fewer measurements or particles)",
            ),
        };
        Error::check_work(
            what,
            measure,
            limit,
            per_report,
            m.max(1),
            MAX_UPDATE_EVALUATIONS,
        )
    }

    /// L(x) of the update (0 in an exclusion region).
    fn target_likelihood(
        &self,
        x: &[f64],
        eval: &dyn Fn(&[f64]) -> (f64, f64),
        zero_kappa: usize,
    ) -> f64 {
        if self.update.exclusions.iter().any(|e| e.contains(x)) {
            return 0.0;
        }
        let pd = self.update.detection.probability_at(x);
        let (ratio, certain) = if pd > 0.0 { eval(x) } else { (0.0, 0.0) };
        if zero_kappa == 1 {
            pd * certain
        } else {
            1.0 - pd + pd * ratio
        }
    }

    fn update_inner(
        &mut self,
        eval: &dyn Fn(&[f64]) -> (f64, f64),
        zero_kappa: usize,
    ) -> Result<UpdateInfo> {
        let dim = self.dim;
        // Every check comes before the first change to `self` (On `Err`, the filter is
        // unchanged): the exclusions, g̃ and the Bernoulli terms are read-only.
        // Exclusion constraint, then the Bernoulli update terms.
        let mut kept = NeumaierSum::new();
        let mut excluded = alloc::vec![false; self.weights.len()];
        for (i, p) in self.particles.chunks_exact(dim).enumerate() {
            if self.update.exclusions.iter().any(|e| e.contains(p)) {
                excluded[i] = true;
            } else {
                kept.add(self.weights[i]);
            }
        }
        let kept = kept.total();
        if kept.is_nan() || kept <= 0.0 {
            return Err(Error::parameter(
                "exclusions",
                kept,
                "regions that leave some of the predicted particles outside them",
            ));
        }
        let mut terms = Vec::with_capacity(self.weights.len());
        for (i, p) in self.particles.chunks_exact(dim).enumerate() {
            let w = if excluded[i] {
                0.0
            } else {
                self.weights[i] / kept
            };
            let pd = if w > 0.0 {
                self.update.detection.probability_at(p)
            } else {
                0.0
            };
            let (ratio, certain) = if pd > 0.0 { eval(p) } else { (0.0, 0.0) };
            if ratio.is_nan() {
                // `eval` flags a bad g̃ with (NaN, report index).
                return Err(Error::parameter(
                    alloc::format!("likelihood[{}]", certain as usize),
                    f64::NAN,
                    "finite and >= 0",
                ));
            }
            terms.push(Term::new(w, pd, ratio, certain));
        }
        let (existence, weights, delta) = bernoulli_weights(self.existence, &terms, zero_kappa)?;
        // Nothing below fails.
        if self.parents.len() != self.particles.len() {
            // No prediction since the last update: there is no parent to move against.
            self.parents = alloc::vec![0.0; self.particles.len()];
            self.origins = alloc::vec![Origin::Fixed; self.weights.len()];
        }
        self.existence = existence;
        // Resample back to N.
        let n = self.options.particles;
        let idx = systematic(&weights, n, &mut self.rng);
        let mut particles = gather(&self.particles, &idx, dim);
        let parents = gather(&self.parents, &idx, dim);
        let origins: Vec<Origin> = idx.iter().map(|&i| self.origins[i]).collect();
        // MCMC move.
        if self.options.mcmc_moves > 0 && n > 1 {
            self.mcmc(&mut particles, &parents, &origins, eval, zero_kappa);
        }
        self.particles = particles;
        self.weights = alloc::vec![1.0 / n as f64; n];
        self.parents.clear();
        self.origins.clear();
        let info = UpdateInfo {
            delta,
            split_components: n,
        };
        self.last = Some(info);
        Ok(info)
    }

    /// ln of the move step's target for one particle.
    fn ln_target(
        &self,
        x: &[f64],
        parent: &[f64],
        origin: Origin,
        eval: &dyn Fn(&[f64]) -> (f64, f64),
        zero_kappa: usize,
    ) -> f64 {
        let l = self.target_likelihood(x, eval, zero_kappa);
        if l.is_nan() || l <= 0.0 {
            return f64::NEG_INFINITY;
        }
        let prior = match origin {
            Origin::Survived => self.predict.transition.ln_density(x, parent),
            Origin::Born => {
                let p = self.predict.birth.mixture.pdf(x);
                if p > 0.0 {
                    fns::ln(p)
                } else {
                    f64::NEG_INFINITY
                }
            }
            Origin::Fixed => return f64::NEG_INFINITY,
        };
        fns::ln(l) + prior
    }

    fn mcmc(
        &mut self,
        particles: &mut [f64],
        parents: &[f64],
        origins: &[Origin],
        eval: &dyn Fn(&[f64]) -> (f64, f64),
        zero_kappa: usize,
    ) {
        let dim = self.dim;
        let n = particles.len() / dim;
        // Σ̂ and its Cholesky factor.
        let mut mean = alloc::vec![0.0; dim];
        for p in particles.chunks_exact(dim) {
            for (m, x) in mean.iter_mut().zip(p) {
                *m += x / n as f64;
            }
        }
        let mut cov = nalgebra::DMatrix::zeros(dim, dim);
        for p in particles.chunks_exact(dim) {
            for i in 0..dim {
                for j in 0..=i {
                    cov[(i, j)] += (p[i] - mean[i]) * (p[j] - mean[j]) / n as f64;
                }
            }
        }
        for i in 0..dim {
            for j in 0..i {
                cov[(j, i)] = cov[(i, j)];
            }
        }
        let Some(chol) = cov.cholesky() else {
            return; // degenerate cloud (e.g. one distinct particle): no move
        };
        let h = fns::pow(
            4.0 / ((dim as f64 + 2.0) * n as f64),
            1.0 / (dim as f64 + 4.0),
        );
        let l = chol.unpack() * h;
        let mut proposal = alloc::vec![0.0; dim];
        let mut eps = alloc::vec![0.0; dim];
        for i in 0..n {
            let degenerate =
                origins[i] == Origin::Survived && !self.predict.transition.has_density();
            if origins[i] == Origin::Fixed || degenerate {
                continue;
            }
            let x = &particles[i * dim..(i + 1) * dim];
            let parent = &parents[i * dim..(i + 1) * dim];
            let mut current = self.ln_target(x, parent, origins[i], eval, zero_kappa);
            for _ in 0..self.options.mcmc_moves {
                for e in eps.iter_mut() {
                    *e = normal::sample(&mut self.rng);
                }
                let x = &particles[i * dim..(i + 1) * dim];
                for (r, pr) in proposal.iter_mut().enumerate() {
                    let mut s = x[r];
                    for (c, ec) in eps.iter().enumerate().take(r + 1) {
                        s += l[(r, c)] * ec;
                    }
                    *pr = s;
                }
                let cand = self.ln_target(&proposal, parent, origins[i], eval, zero_kappa);
                let u = uniform(&mut self.rng);
                if cand > f64::NEG_INFINITY && (u <= 0.0 || fns::ln(u) < cand - current) {
                    particles[i * dim..(i + 1) * dim].copy_from_slice(&proposal);
                    current = cand;
                }
            }
        }
    }

    /// The estimate from the weighted particles ([`FilterEstimate`]).
    ///
    /// # Errors
    /// Those of [`crate::bernoulli::estimate`].
    pub fn estimate(&self, options: &EstimateOptions) -> Result<FilterEstimate> {
        particle_estimate(
            self.existence,
            &self.particles,
            &self.weights,
            self.dim,
            self.update.position_dims,
            options,
        )
    }
}

/// Appends one draw of the mixture (component by weight, then the Gaussian) to `out`.
fn sample_mixture<R: Rng + ?Sized>(mixture: &GaussianMixture, rng: &mut R, out: &mut Vec<f64>) {
    let u = uniform(rng);
    let comps = mixture.components();
    let mut acc = 0.0;
    let mut pick = comps.len() - 1;
    for (i, (w, _)) in comps.iter().enumerate() {
        acc += w;
        if u < acc {
            pick = i;
            break;
        }
    }
    let x = comps[pick].1.sample(rng);
    out.extend(x.iter());
}

fn gather(rows: &[f64], idx: &[usize], dim: usize) -> Vec<f64> {
    let mut out = Vec::with_capacity(idx.len() * dim);
    for &i in idx {
        out.extend_from_slice(&rows[i * dim..(i + 1) * dim]);
    }
    out
}
