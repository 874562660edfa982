//! The spatial density s of a Bernoulli (Definition II.1 of `000_…`): a Gaussian, a Gaussian
//! mixture, or a weighted particle set; and q(a), the mass it puts outside the ball of
//! radius r0 about a.

use alloc::string::String;
use alloc::vec::Vec;

use rand::{Rng, RngExt};

use crate::bernoulli::ball::{BallProbability, DEFAULT_TOLERANCE, GaussianBall, dist2};
use crate::bernoulli::loss::check_radius;
use crate::error::{Error, Result};
use crate::gaussian::{Gaussian, GaussianMixture};
use crate::math::sum::{NeumaierSum, sum};

/// Tolerances below this are raised to it (the quadrature cannot do better in f64).
pub const MIN_TOLERANCE: f64 = 1e-14;

/// A weighted particle set: n points of one dimension d and nonnegative weights normalised
/// to sum to 1.
#[derive(Clone, Debug, PartialEq)]
pub struct ParticleSet {
    dim: usize,
    /// Row-major n × d.
    points: Vec<f64>,
    weights: Vec<f64>,
}

impl ParticleSet {
    /// Particles `points` with `weights` (`None`: equal weights). The weights need not be
    /// normalised; they are divided by their sum. Errors are named as in the JavaScript
    /// binding: `density.particles[i]`, `density.weights[i]`.
    ///
    /// # Errors
    /// [`Error::Unsupported`] for no particles; [`Error::DimensionMismatch`] for an empty
    /// point, points of different lengths, or a weight count different from the point count;
    /// [`Error::InvalidParameter`] for a non-finite coordinate, a negative or non-finite
    /// weight, or weights summing to 0.
    pub fn new<P: AsRef<[f64]>>(points: &[P], weights: Option<&[f64]>) -> Result<Self> {
        let Some(first) = points.first() else {
            return Err(Error::Unsupported {
                what: "density.particles".into(),
                reason: "at least one particle is needed",
            });
        };
        let dim = first.as_ref().len();
        if dim == 0 {
            return Err(Error::dimension("density.particles[0]", 1, 0));
        }
        let mut flat = Vec::with_capacity(points.len() * dim);
        for (i, p) in points.iter().enumerate() {
            let p = p.as_ref();
            if p.len() != dim {
                return Err(Error::dimension(
                    alloc::format!("density.particles[{i}]"),
                    dim,
                    p.len(),
                ));
            }
            if let Some(j) = p.iter().position(|x| !x.is_finite()) {
                return Err(Error::parameter(
                    alloc::format!("density.particles[{i}][{j}]"),
                    p[j],
                    "finite",
                ));
            }
            flat.extend_from_slice(p);
        }
        let n = points.len();
        let weights = match weights {
            None => alloc::vec![1.0 / n as f64; n],
            Some(w) => {
                if w.len() != n {
                    return Err(Error::dimension("density.weights", n, w.len()));
                }
                normalised_weights(
                    w,
                    |i| alloc::format!("density.weights[{i}]"),
                    || "sum of density.weights".into(),
                )?
            }
        };
        Ok(Self {
            dim,
            points: flat,
            weights,
        })
    }

    /// The dimension d.
    pub fn dim(&self) -> usize {
        self.dim
    }

    /// The number of particles.
    pub fn len(&self) -> usize {
        self.weights.len()
    }

    /// Always false (a set has at least one particle).
    pub fn is_empty(&self) -> bool {
        self.weights.is_empty()
    }

    /// Particle i.
    ///
    /// # Panics
    /// If `i >= self.len()`.
    pub fn point(&self, i: usize) -> &[f64] {
        &self.points[i * self.dim..(i + 1) * self.dim]
    }

    /// The normalised weights.
    pub fn weights(&self) -> &[f64] {
        &self.weights
    }

    /// The same particles with every coordinate multiplied by 2^`exp` (exact unless a
    /// coordinate underflows), the same weights.
    pub(crate) fn scaled(&self, exp: i32) -> Self {
        Self {
            dim: self.dim,
            points: self.points.iter().map(|&x| libm::scalbn(x, exp)).collect(),
            weights: self.weights.clone(),
        }
    }

    /// Σ_i w_i 1{‖x_i − a‖ > r0} (compensated sum).
    pub(crate) fn outside(&self, center: &[f64], radius: f64) -> f64 {
        let r2 = radius * radius;
        let mut s = NeumaierSum::new();
        for (i, &w) in self.weights.iter().enumerate() {
            if dist2(self.point(i), center) > r2 {
                s.add(w);
            }
        }
        s.total().clamp(0.0, 1.0)
    }
}

fn normalised_weights(
    w: &[f64],
    name: impl Fn(usize) -> String,
    sum_name: impl Fn() -> String,
) -> Result<Vec<f64>> {
    if let Some(i) = w.iter().position(|x| !(x.is_finite() && *x >= 0.0)) {
        return Err(Error::parameter(name(i), w[i], "finite and >= 0"));
    }
    let total = sum(w.iter().copied());
    if !(total > 0.0 && total.is_finite()) {
        return Err(Error::parameter(sum_name(), total, "finite and > 0"));
    }
    Ok(w.iter().map(|x| x / total).collect())
}

/// The representation behind [`SpatialDensity`].
#[derive(Clone, Debug, PartialEq)]
pub(crate) enum Repr {
    Gaussian(GaussianBall),
    Mixture {
        components: Vec<(f64, GaussianBall)>,
        mean: Vec<f64>,
    },
    Particles(ParticleSet),
}

/// Which kind of density a [`SpatialDensity`] is.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub enum DensityKind {
    /// One Gaussian.
    Gaussian,
    /// A Gaussian mixture.
    Mixture,
    /// A weighted particle set.
    Particles,
}

/// The spatial density s of a Bernoulli, eq. (1) of `000_…`, validated and prepared for
/// ball probabilities (each Gaussian's covariance is eigen-decomposed once, here).
#[derive(Clone, Debug, PartialEq)]
pub struct SpatialDensity {
    repr: Repr,
}

impl SpatialDensity {
    /// A Gaussian s = N(m, P) of any dimension with a full covariance.
    ///
    /// # Errors
    /// [`Error::NotDefinite`] naming `density.cov` (smallest eigenvalue NaN) if the
    /// eigen-decomposition does not converge.
    pub fn gaussian(gaussian: Gaussian) -> Result<Self> {
        Ok(Self {
            repr: Repr::Gaussian(GaussianBall::new(gaussian, "density")?),
        })
    }

    /// N(mean, cov) from a row-major covariance, named `density` in errors
    /// (`density.mean[i]`, `density.cov`).
    ///
    /// # Errors
    /// As [`Gaussian::from_slices`] (non-finite entries, wrong sizes; [`Error::NotSymmetric`]
    /// or [`Error::NotDefinite`] naming `density.cov` for a covariance not symmetric or not
    /// positive definite).
    pub fn gaussian_from_slices(mean: &[f64], cov_row_major: &[f64]) -> Result<Self> {
        Self::gaussian(Gaussian::from_slices(mean, cov_row_major, "density")?)
    }

    /// A Gaussian mixture s = Σ_j w_j N(m_j, P_j) / Σ_j w_j: the weights are normalised.
    /// Build the mixture with `what = "density.mixture"` so that its errors carry the
    /// JavaScript names (`density.mixture[2].weight`).
    ///
    /// # Errors
    /// [`Error::Unsupported`] for an empty mixture; [`Error::InvalidParameter`] naming
    /// `sum of density.mixture[].weight` if the weights sum to 0;
    /// [`Error::NotDefinite`] naming `density.mixture[j].cov` if an eigen-decomposition does
    /// not converge.
    pub fn mixture(mixture: &GaussianMixture) -> Result<Self> {
        if mixture.is_empty() {
            return Err(Error::Unsupported {
                what: "density.mixture".into(),
                reason: "a mixture needs at least one component",
            });
        }
        let raw: Vec<f64> = mixture.components().iter().map(|(w, _)| *w).collect();
        let weights = normalised_weights(
            &raw,
            |j| alloc::format!("density.mixture[{j}].weight"),
            || "sum of density.mixture[].weight".into(),
        )?;
        let dim = mixture.dim().unwrap_or(0);
        let mut mean = alloc::vec![NeumaierSum::new(); dim];
        let mut components = Vec::with_capacity(weights.len());
        for (j, (w, (_, g))) in weights.iter().zip(mixture.components()).enumerate() {
            for (acc, m) in mean.iter_mut().zip(g.mean().iter()) {
                acc.add(w * m);
            }
            let name = alloc::format!("density.mixture[{j}]");
            components.push((*w, GaussianBall::new(g.clone(), &name)?));
        }
        Ok(Self {
            repr: Repr::Mixture {
                components,
                mean: mean.iter().map(NeumaierSum::total).collect(),
            },
        })
    }

    /// A weighted particle set.
    pub fn particles(particles: ParticleSet) -> Self {
        Self {
            repr: Repr::Particles(particles),
        }
    }

    /// Which kind of density this is.
    pub fn kind(&self) -> DensityKind {
        match self.repr {
            Repr::Gaussian(_) => DensityKind::Gaussian,
            Repr::Mixture { .. } => DensityKind::Mixture,
            Repr::Particles(_) => DensityKind::Particles,
        }
    }

    /// The dimension d.
    pub fn dim(&self) -> usize {
        match &self.repr {
            Repr::Gaussian(g) => g.dim(),
            Repr::Mixture { mean, .. } => mean.len(),
            Repr::Particles(p) => p.dim(),
        }
    }

    /// The mean ∫ x s(dx).
    pub fn mean(&self) -> Vec<f64> {
        match &self.repr {
            Repr::Gaussian(g) => g.gaussian().mean().iter().copied().collect(),
            Repr::Mixture { mean, .. } => mean.clone(),
            Repr::Particles(p) => {
                let mut m = alloc::vec![NeumaierSum::new(); p.dim()];
                for (i, w) in p.weights().iter().enumerate() {
                    for (acc, x) in m.iter_mut().zip(p.point(i)) {
                        acc.add(w * x);
                    }
                }
                m.iter().map(NeumaierSum::total).collect()
            }
        }
    }

    /// The Gaussian, for a single-Gaussian density.
    pub fn as_gaussian(&self) -> Option<&Gaussian> {
        match &self.repr {
            Repr::Gaussian(g) => Some(g.gaussian()),
            _ => None,
        }
    }

    /// The normalised mixture components `(w_j, N(m_j, P_j))`, for a mixture.
    pub fn mixture_components(&self) -> Option<Vec<(f64, &Gaussian)>> {
        match &self.repr {
            Repr::Mixture { components, .. } => {
                Some(components.iter().map(|(w, g)| (*w, g.gaussian())).collect())
            }
            _ => None,
        }
    }

    /// The particle set, for particles.
    pub fn as_particles(&self) -> Option<&ParticleSet> {
        match &self.repr {
            Repr::Particles(p) => Some(p),
            _ => None,
        }
    }

    pub(crate) fn repr(&self) -> &Repr {
        &self.repr
    }

    /// q(a) = ∫ 1{‖x − a‖ > r0} s(dx), the integral in eqs. (11)–(13) of `000_…` (with
    /// a = a*), to the default absolute tolerance 1e-10. Exact in 1D (normal cdf), an
    /// error-controlled nested quadrature in the covariance eigenbasis in 2D and up (see
    /// [`ball`](super::ball)), the weighted sum for a mixture and the weighted count of
    /// particles strictly farther than r0 for particles.
    ///
    /// # Errors
    /// [`Error::DimensionMismatch`] naming `center`, [`Error::InvalidParameter`] naming
    /// `center[i]` (non-finite) or `radius` (not finite and > 0).
    pub fn prob_outside_ball(&self, center: &[f64], radius: f64) -> Result<f64> {
        Ok(self
            .prob_outside_ball_with_tolerance(center, radius, DEFAULT_TOLERANCE)?
            .outside)
    }

    /// [`prob_outside_ball`](Self::prob_outside_ball) with an absolute tolerance `tol`
    /// (raised to [`MIN_TOLERANCE`] if smaller) and the error estimate.
    ///
    /// # Errors
    /// As [`prob_outside_ball`](Self::prob_outside_ball); [`Error::InvalidParameter`]
    /// naming `tolerance` unless it is > 0 and finite.
    pub fn prob_outside_ball_with_tolerance(
        &self,
        center: &[f64],
        radius: f64,
        tol: f64,
    ) -> Result<BallProbability> {
        self.check_center(center, "center")?;
        check_radius(radius)?;
        if !(tol.is_finite() && tol > 0.0) {
            return Err(Error::parameter("tolerance", tol, "finite and > 0"));
        }
        Ok(self.outside_unchecked(center, radius, tol.max(MIN_TOLERANCE)))
    }

    pub(crate) fn check_center(&self, center: &[f64], what: &str) -> Result<()> {
        if center.len() != self.dim() {
            return Err(Error::dimension(what, self.dim(), center.len()));
        }
        if let Some(i) = center.iter().position(|x| !x.is_finite()) {
            return Err(Error::parameter(
                alloc::format!("{what}[{i}]"),
                center[i],
                "finite",
            ));
        }
        Ok(())
    }

    /// q(center) without argument checks.
    pub(crate) fn outside_unchecked(
        &self,
        center: &[f64],
        radius: f64,
        tol: f64,
    ) -> BallProbability {
        match &self.repr {
            Repr::Gaussian(g) => g.outside(center, radius, tol),
            Repr::Mixture { components, .. } => mixture_outside(components, center, radius, tol),
            Repr::Particles(p) => BallProbability {
                outside: p.outside(center, radius),
                error: 0.0,
            },
        }
    }

    /// A draw x ~ s.
    pub fn sample<R: Rng + ?Sized>(&self, rng: &mut R) -> Vec<f64> {
        match &self.repr {
            Repr::Gaussian(g) => g.gaussian().sample(rng).iter().copied().collect(),
            Repr::Mixture { components, .. } => {
                let j = pick(components.iter().map(|(w, _)| *w), rng);
                components[j]
                    .1
                    .gaussian()
                    .sample(rng)
                    .iter()
                    .copied()
                    .collect()
            }
            Repr::Particles(p) => {
                let i = pick(p.weights().iter().copied(), rng);
                p.point(i).to_vec()
            }
        }
    }
}

/// Σ_j w_j q_j(a), each q_j to `tol` (the weights sum to 1, so the sum is within `tol`).
pub(crate) fn mixture_outside(
    components: &[(f64, GaussianBall)],
    center: &[f64],
    radius: f64,
    tol: f64,
) -> BallProbability {
    mixture_outside_in(components, center, radius, tol, None)
}

/// [`mixture_outside`], drawing on a search's work `budget` if given (at least one unit per
/// component; see [`GaussianBall::outside_within`]).
pub(crate) fn mixture_outside_in(
    components: &[(f64, GaussianBall)],
    center: &[f64],
    radius: f64,
    tol: f64,
    budget: Option<&core::cell::Cell<usize>>,
) -> BallProbability {
    let mut value = NeumaierSum::new();
    let mut error = 0.0;
    for (w, g) in components {
        if *w == 0.0 {
            continue;
        }
        let b = match budget {
            Some(budget) => {
                budget.set(budget.get().saturating_sub(1));
                g.outside_within(center, radius, tol, budget)
            }
            None => g.outside(center, radius, tol),
        };
        value.add(w * b.outside);
        error += w * b.error;
    }
    BallProbability {
        outside: value.total().clamp(0.0, 1.0),
        error,
    }
}

/// An index drawn with probabilities `weights` (summing to 1).
fn pick<R: Rng + ?Sized>(weights: impl Iterator<Item = f64>, rng: &mut R) -> usize {
    let u: f64 = rng.random();
    let mut acc = 0.0;
    let mut last = 0;
    for (i, w) in weights.enumerate() {
        if w > 0.0 {
            last = i;
        }
        acc += w;
        if u < acc {
            return i;
        }
    }
    last
}
