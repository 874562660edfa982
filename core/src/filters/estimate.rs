//! Estimates from a Bernoulli filter's output: the existence, the MMSE mean and covariance,
//! and the Bayes-optimal Bernoulli point estimate of paper `000`.

use alloc::vec::Vec;

use super::config::GmBernoulli;
use crate::bernoulli::{ApplicationLoss, BernoulliEstimate, ParticleSet, SpatialDensity, estimate};
use crate::error::Result;
use crate::gaussian::{Gaussian, GaussianMixture};
use crate::math::sum::NeumaierSum;
use crate::mixture::moments;

/// What [`GmBernoulliFilter::estimate`](super::GmBernoulliFilter::estimate) and
/// [`ParticleBernoulliFilter::estimate`](super::ParticleBernoulliFilter::estimate) compute
/// (`estimate(options)`).
#[derive(Clone, Debug, Default, PartialEq)]
pub struct EstimateOptions {
    /// The application-oriented loss (7) of paper `000` (`{ radius, costs }`). When given, the
    /// estimate includes the optimal Bernoulli point estimate (`report`), computed on the
    /// position marginal (the first n_s state components), so r0 is a position distance.
    pub loss: Option<ApplicationLoss>,
}

/// A Bernoulli filter's estimate (`{ existence, mean, cov, report }`).
#[derive(Clone, Debug, PartialEq)]
pub struct FilterEstimate {
    /// r_{k|k}.
    pub existence: f64,
    /// The MMSE state estimate E[x | object exists] = ∫ x p(x) dx.
    pub mean: Vec<f64>,
    /// The posterior covariance ∫ (x − mean)(x − mean)ᵀ p(x) dx, rows.
    pub cov: Vec<Vec<f64>>,
    /// Theorem III.3 of paper `000` ([`crate::bernoulli::estimate`]) for (r, the position
    /// marginal of p), when a loss was given.
    pub report: Option<BernoulliEstimate>,
}

impl FilterEstimate {
    /// The root sum square of the position variances, √(tr P_ss) over the first `dims`
    /// components (Fig. 8's "covariance RSS").
    pub fn rss(&self, dims: core::ops::Range<usize>) -> f64 {
        crate::math::fns::sqrt(dims.map(|i| self.cov[i][i]).sum::<f64>())
    }
}

fn rows(p: &nalgebra::DMatrix<f64>) -> Vec<Vec<f64>> {
    (0..p.nrows())
        .map(|i| (0..p.ncols()).map(|j| p[(i, j)]).collect())
        .collect()
}

/// The position marginal Σ_ℓ w_ℓ N(m_ℓ[..n_s], P_ℓ[..n_s, ..n_s]).
pub(crate) fn position_marginal(mixture: &GaussianMixture, ns: usize) -> Result<GaussianMixture> {
    let mut out = Vec::with_capacity(mixture.len());
    for (i, (w, g)) in mixture.components().iter().enumerate() {
        let m = g.mean().rows(0, ns).into_owned();
        let p = g.cov().view((0, 0), (ns, ns)).into_owned();
        out.push((*w, Gaussian::new(m, p, &alloc::format!("mixture[{i}]"))?));
    }
    GaussianMixture::new(out, "mixture")
}

/// The estimate of a GM Bernoulli: the mixture's moments (mean and covariance with the
/// spread-of-means term) and, with a loss, [`crate::bernoulli::estimate`] on the position
/// marginal.
///
/// # Errors
/// Those of [`crate::bernoulli::estimate`] (e.g. an invalid existence).
pub fn gm_estimate(
    state: &GmBernoulli,
    position_dims: usize,
    options: &EstimateOptions,
) -> Result<FilterEstimate> {
    let n = state.dim();
    let (_, mean, cov) = moments(&state.mixture).unwrap_or((
        0.0,
        nalgebra::DVector::zeros(n),
        nalgebra::DMatrix::zeros(n, n),
    ));
    let report = match &options.loss {
        Some(loss) => {
            let marginal = position_marginal(&state.mixture, position_dims)?;
            let s = SpatialDensity::mixture(&marginal)?;
            Some(estimate(state.existence, &s, loss)?)
        }
        None => None,
    };
    Ok(FilterEstimate {
        existence: state.existence,
        mean: mean.iter().copied().collect(),
        cov: rows(&cov),
        report,
    })
}

/// The estimate of a weighted particle set (flat rows of `dim` numbers, normalised weights).
pub(crate) fn particle_estimate(
    existence: f64,
    particles: &[f64],
    weights: &[f64],
    dim: usize,
    position_dims: usize,
    options: &EstimateOptions,
) -> Result<FilterEstimate> {
    let mut mean = alloc::vec![NeumaierSum::new(); dim];
    for (p, w) in particles.chunks_exact(dim).zip(weights) {
        for (acc, x) in mean.iter_mut().zip(p) {
            acc.add(w * x);
        }
    }
    let mean: Vec<f64> = mean.iter().map(NeumaierSum::total).collect();
    let mut cov = alloc::vec![alloc::vec![0.0; dim]; dim];
    for (p, w) in particles.chunks_exact(dim).zip(weights) {
        for i in 0..dim {
            let di = p[i] - mean[i];
            for j in 0..=i {
                cov[i][j] += w * di * (p[j] - mean[j]);
            }
        }
    }
    let lower = cov.clone();
    for (i, row) in lower.iter().enumerate() {
        for (j, v) in row.iter().enumerate().take(i) {
            cov[j][i] = *v;
        }
    }
    let report = match &options.loss {
        Some(loss) => {
            let points: Vec<&[f64]> = particles
                .chunks_exact(dim)
                .map(|p| &p[..position_dims])
                .collect();
            let set = ParticleSet::new(&points, Some(weights))?;
            Some(estimate(existence, &SpatialDensity::particles(set), loss)?)
        }
        None => None,
    };
    Ok(FilterEstimate {
        existence,
        mean,
        cov,
        report,
    })
}
