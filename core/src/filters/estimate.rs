//! Estimates from a Bernoulli filter's output: the existence, the MMSE mean and covariance,
//! and the Bayes-optimal Bernoulli point estimate of paper `000`.

use alloc::vec::Vec;

use super::config::GmBernoulli;
use crate::bernoulli::{
    ApplicationLoss, BernoulliEstimate, BernoulliReport, Costs, ParticleSet, SpatialDensity,
    estimate,
};
use crate::error::{Error, Phrase, Result};
use crate::gaussian::{Gaussian, GaussianMixture};
use crate::math::sum::NeumaierSum;

/// What [`GmBernoulliFilter::estimate`](super::GmBernoulliFilter::estimate) and
/// [`ParticleBernoulliFilter::estimate`](super::ParticleBernoulliFilter::estimate) compute
/// (`estimate(options)`).
#[derive(Clone, Debug, Default, PartialEq)]
#[cfg_attr(
    feature = "serde",
    derive(serde::Serialize, serde::Deserialize),
    serde(default)
)]
pub struct EstimateOptions {
    /// The application-oriented loss (7) of paper `000` (`{ radius, costs }`). When given, the
    /// estimate includes the optimal Bernoulli point estimate (`report`), computed on the
    /// position marginal (the first n_s state components), so r0 is a position distance.
    pub loss: Option<ApplicationLoss>,
}

/// The loss of [`EstimateOptions`] as a caller writes it: `radius` and `costs` side by side,
/// both given or neither (the npm package's `estimate({ radius, costs })`).
#[derive(Clone, Debug, Default, PartialEq)]
#[cfg_attr(
    feature = "serde",
    derive(serde::Serialize, serde::Deserialize),
    serde(default)
)]
pub struct EstimateLossOptions {
    /// The radius r0 > 0 of the loss's tolerance ball (a position distance).
    pub radius: Option<f64>,
    /// The costs of the loss (7) of paper `000`.
    pub costs: Option<Costs>,
}

impl EstimateLossOptions {
    /// The [`EstimateOptions`]: with the loss when both are given, without it when neither is.
    ///
    /// # Errors
    /// [`Error::Form`] (a wrong kind) naming the one missing when only the other is given;
    /// as [`ApplicationLoss::new`].
    pub fn options(&self) -> Result<EstimateOptions> {
        let missing = |what: &str, with: &str| {
            Err(Error::form(
                what,
                true,
                alloc::vec![
                    Phrase::text("is required with "),
                    Phrase::path(with),
                    Phrase::text(" (the loss (7) takes both)"),
                ],
            ))
        };
        match (self.radius, self.costs) {
            (Some(r), Some(c)) => Ok(EstimateOptions {
                loss: Some(ApplicationLoss::new(c, r)?),
            }),
            (None, None) => Ok(EstimateOptions::default()),
            (Some(_), None) => missing("costs", "radius"),
            (None, Some(_)) => missing("radius", "costs"),
        }
    }
}

/// A Bernoulli filter's estimate (`{ existence, mean, cov, report }`).
#[derive(Clone, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct FilterEstimate {
    /// The posterior existence probability r_{k|k} ∈ [0, 1].
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

/// A [`FilterEstimate`] in the flat form the npm package returns: the point estimate as a
/// [`BernoulliReport`], always written (null without a loss).
#[derive(Clone, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct FilterEstimateReport {
    /// The posterior existence probability r_{k|k} ∈ [0, 1].
    pub existence: f64,
    /// The MMSE state estimate.
    pub mean: Vec<f64>,
    /// The posterior covariance, rows.
    pub cov: Vec<Vec<f64>>,
    /// The optimal Bernoulli point estimate (Theorem III.3 of paper 000) on the position
    /// marginal; null without a loss.
    #[cfg_attr(feature = "serde", serde(with = "crate::serde_shapes::nullable"))]
    pub report: Option<BernoulliReport>,
}

impl From<FilterEstimate> for FilterEstimateReport {
    fn from(e: FilterEstimate) -> Self {
        Self {
            existence: e.existence,
            mean: e.mean,
            cov: e.cov,
            report: e.report.as_ref().map(BernoulliReport::from),
        }
    }
}

/// The smallest power of two ≥ `t` (1 for 0 or a non-finite `t`), at most 2¹⁰²³ (the largest
/// finite one: a `t` above it, up to `f64::MAX`, is then at most twice the scale): dividing
/// by it is exact.
fn pow2_above(t: f64) -> f64 {
    if !(t > 0.0 && t.is_finite()) {
        return 1.0;
    }
    let (_, e) = libm::frexp(t);
    libm::ldexp(1.0, e.min(1023))
}

/// Σ_k w_k x_k of the finite values `x` (weights summing to 1) when the plain sum `plain`
/// overflowed: the values scaled by a power of two first (exact), the result clamped to the
/// values' range (a convex combination lies in it; rounding could step past `f64::MAX`).
fn scaled_mean(plain: f64, x: impl Iterator<Item = (f64, f64)> + Clone) -> f64 {
    if plain.is_finite() {
        return plain;
    }
    let (lo, hi) = x
        .clone()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), (_, v)| {
            (lo.min(v), hi.max(v))
        });
    let s = pow2_above(lo.abs().max(hi.abs()));
    let mut acc = NeumaierSum::new();
    for (w, v) in x {
        acc.add(w * (v / s));
    }
    crate::math::fns::clamp(acc.total() * s, lo, hi)
}

/// The covariance Σ_k a_k (P_k + d_k d_kᵀ), d_k = m_k − mean (shares a_k summing to 1; P_k
/// omitted for points), computed so that a second moment beyond the f64 range is ±∞ with
/// its sign and never ∞ − ∞ or 0 · ∞ (NaN): each coordinate is scaled by a power of two
/// t_i ≥ max_k(|d_ki|/2, √P_k,ii / 2) — d_k/2 = m_k/2 − mean/2 cannot overflow — so every
/// term of the sum is at most 2 in magnitude, and the sum is scaled back at the end
/// (cov_ij = 4 t_i t_j S_ij); items of share 0 are skipped. Scaling by powers of two is
/// exact: in range the result is the plain formula's, bit for bit (a term below 2⁻¹⁰⁷⁴ of
/// the largest one underflows to 0, far below the rounding of the sum).
fn spread_cov<'a>(
    items: impl Iterator<Item = (f64, &'a [f64], Option<&'a nalgebra::DMatrix<f64>>)> + Clone,
    mean: &[f64],
) -> Vec<Vec<f64>> {
    let n = mean.len();
    let half = |m: &[f64], i: usize| 0.5 * m[i] - 0.5 * mean[i];
    let mut t = alloc::vec![0.0_f64; n];
    // Weightless items add exactly 0: they must not set the scale (their 0 · ∞ is the NaN).
    let items = items.filter(|(a, _, _)| *a != 0.0);
    for (_, m, p) in items.clone() {
        for (i, ti) in t.iter_mut().enumerate() {
            let pii = p.map_or(0.0, |p| crate::math::fns::sqrt(p[(i, i)].max(0.0)) * 0.5);
            *ti = ti.max(crate::math::fns::abs(half(m, i))).max(pii);
        }
    }
    let t: Vec<f64> = t.into_iter().map(pow2_above).collect();
    let mut cov = alloc::vec![alloc::vec![0.0; n]; n];
    for (a, m, p) in items {
        for i in 0..n {
            let hi = half(m, i) / t[i];
            for j in 0..=i {
                let hj = half(m, j) / t[j];
                cov[i][j] += match p {
                    Some(p) => a * (0.5 * (p[(i, j)] + p[(j, i)]) / t[i] / t[j] * 0.25 + hi * hj),
                    None => a * hi * hj,
                };
            }
        }
    }
    for i in 0..n {
        for j in 0..=i {
            let v = 4.0 * cov[i][j] * t[j] * t[i];
            cov[i][j] = v;
            cov[j][i] = v;
        }
    }
    cov
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
    // The moments Σ a_ℓ m_ℓ and Σ a_ℓ (P_ℓ + d_ℓ d_ℓᵀ) with a_ℓ = w_ℓ / Σ w (equal shares
    // when Σ w = 0), as `crate::mixture::moments`, but with `spread_cov` (no NaN on overflow).
    let n = state.dim();
    let comps = state.mixture.components();
    let total = crate::math::sum::sum(comps.iter().map(|(w, _)| *w));
    let count = comps.len() as f64;
    let share = |w: f64| if total > 0.0 { w / total } else { 1.0 / count };
    let mut mean = alloc::vec![0.0; n];
    for (w, g) in comps {
        for (acc, m) in mean.iter_mut().zip(g.mean().iter()) {
            *acc += share(*w) * m;
        }
    }
    // Means near ±f64::MAX: the plain sum overflowed (then ∞ − ∞ in the spread), the scaled
    // one cannot; in range the plain sum is kept, bit for bit.
    for (i, acc) in mean.iter_mut().enumerate() {
        *acc = scaled_mean(*acc, comps.iter().map(|(w, g)| (share(*w), g.mean()[i])));
    }
    let cov = spread_cov(
        comps
            .iter()
            .map(|(w, g)| (share(*w), g.mean().as_slice(), Some(g.cov()))),
        &mean,
    );
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
        mean,
        cov,
        report,
    })
}

/// The estimate of a weighted particle set (flat rows of `dim` numbers, normalised weights).
///
/// # Errors
/// [`Error::InvalidParameter`] naming `transition` when a particle is not finite (the
/// prediction overflowed); those of [`crate::bernoulli::estimate`].
pub(crate) fn particle_estimate(
    existence: f64,
    particles: &[f64],
    weights: &[f64],
    dim: usize,
    position_dims: usize,
    options: &EstimateOptions,
) -> Result<FilterEstimate> {
    // A prediction whose F x or noise left the f64 range leaves ±∞ particles, whose mean
    // and covariance are ∞ − ∞: an error naming the model rather than NaN.
    if particles.iter().any(|x| !x.is_finite()) {
        return Err(Error::parameter(
            "transition",
            f64::INFINITY,
            "a model whose predicted particles stay finite (a prediction overflowed f64)",
        ));
    }
    let mut mean = alloc::vec![NeumaierSum::new(); dim];
    for (p, w) in particles.chunks_exact(dim).zip(weights) {
        for (acc, x) in mean.iter_mut().zip(p) {
            acc.add(w * x);
        }
    }
    // Particles near ±f64::MAX: the plain sum overflowed, the scaled one cannot.
    let mean: Vec<f64> = mean
        .iter()
        .enumerate()
        .map(|(i, acc)| {
            let column = particles
                .chunks_exact(dim)
                .zip(weights)
                .map(|(p, w)| (*w, p[i]));
            scaled_mean(acc.total(), column)
        })
        .collect();
    let cov = spread_cov(
        particles
            .chunks_exact(dim)
            .zip(weights)
            .map(|(p, w)| (*w, p, None)),
        &mean,
    );
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

#[cfg(test)]
mod tests {
    #[cfg(feature = "serde")]
    #[test]
    fn filter_estimate_report_writes_the_report_or_null() {
        use super::{FilterEstimate, FilterEstimateReport};
        use crate::bernoulli::{ApplicationLoss, Costs, SpatialDensity, estimate};
        let density = SpatialDensity::gaussian_from_slices(&[0.0], &[1.0]).unwrap();
        let loss = ApplicationLoss::new(Costs::mpe(), 1.0).unwrap();
        let e = FilterEstimate {
            existence: 0.9,
            mean: alloc::vec![0.0],
            cov: alloc::vec![alloc::vec![1.0]],
            report: None,
        };
        let without = serde_json::to_string(&FilterEstimateReport::from(e.clone())).unwrap();
        assert_eq!(
            without,
            r#"{"existence":0.9,"mean":[0.0],"cov":[[1.0]],"report":null}"#
        );
        let b = estimate(0.9, &density, &loss).unwrap();
        let with = FilterEstimateReport::from(FilterEstimate {
            report: Some(b.clone()),
            ..e
        });
        assert_eq!(
            with.report,
            Some(crate::bernoulli::BernoulliReport::from(&b))
        );
        assert_eq!(
            (with.existence, with.mean, with.cov),
            (0.9, alloc::vec![0.0], alloc::vec![alloc::vec![1.0]])
        );
    }

    #[test]
    fn estimate_loss_options_take_radius_and_costs_together() {
        use super::{EstimateLossOptions, EstimateOptions};
        use crate::bernoulli::{ApplicationLoss, Costs};
        let costs = Costs::mpe();
        let both = EstimateLossOptions {
            radius: Some(2.0),
            costs: Some(costs),
        };
        let loss = ApplicationLoss::new(costs, 2.0).unwrap();
        assert_eq!(both.options().unwrap().loss, Some(loss));
        assert_eq!(
            EstimateLossOptions::default().options().unwrap(),
            EstimateOptions::default()
        );
        let radius = EstimateLossOptions {
            costs: None,
            ..both.clone()
        };
        let e = radius.options().unwrap_err();
        assert!(e.is_wrong_kind());
        assert_eq!(
            alloc::format!("{}", e.within("options")),
            "options.costs is required with options.radius (the loss (7) takes both)"
        );
        let costs_only = EstimateLossOptions {
            radius: None,
            ..both.clone()
        };
        assert_eq!(
            alloc::format!("{}", costs_only.options().unwrap_err()),
            "radius is required with costs (the loss (7) takes both)"
        );
        let bad = EstimateLossOptions {
            radius: Some(-1.0),
            ..both
        };
        assert_eq!(
            bad.options().unwrap_err(),
            ApplicationLoss::new(costs, -1.0).unwrap_err()
        );
    }

    use super::*;

    fn gm(components: &[(f64, [f64; 2], f64)]) -> GmBernoulli {
        let comps = components
            .iter()
            .map(|(w, m, v)| {
                (
                    *w,
                    Gaussian::from_slices(m, &[*v, 0.1 * v, 0.1 * v, *v], "c").unwrap(),
                )
            })
            .collect();
        GmBernoulli::new(0.5, GaussianMixture::new(comps, "m").unwrap()).unwrap()
    }

    #[test]
    fn moments_in_range_are_the_moment_matched_merge_bit_for_bit() {
        let s = gm(&[
            (0.3, [1.0, -2.0], 0.7),
            (0.5, [4.5, 3.0], 2.0),
            (0.2, [-3.0, 0.25], 1e-3),
        ]);
        let e = gm_estimate(&s, 2, &EstimateOptions::default()).unwrap();
        let (_, mean, cov) = crate::mixture::moments(&s.mixture).unwrap();
        assert_eq!(e.mean, mean.as_slice());
        for i in 0..2 {
            for j in 0..2 {
                assert_eq!(e.cov[i][j], cov[(i, j)], "cov[{i}][{j}]");
            }
        }
        // Particles: Σ w (x − x̄)(x − x̄)ᵀ, the two-pass formula.
        let pts = [0.5, 1.0, -1.5, 2.0, 3.25, -0.75];
        let w = [0.2, 0.5, 0.3];
        let p = particle_estimate(0.5, &pts, &w, 2, 2, &EstimateOptions::default()).unwrap();
        for i in 0..2 {
            for j in 0..2 {
                let plain: f64 = (0..3)
                    .map(|k| w[k] * (pts[2 * k + i] - p.mean[i]) * (pts[2 * k + j] - p.mean[j]))
                    .sum();
                assert!((p.cov[i][j] - plain).abs() <= 1e-15 * plain.abs().max(1.0));
            }
        }
    }

    #[test]
    fn overflowing_second_moments_are_infinite_not_nan() {
        // A weightless component 1e300 away: 0 · ∞ in the plain formula (fuzz #6).
        let s = gm(&[(1.0, [0.0, 0.0], 1.0), (0.0, [1e300, 0.0], 1.0)]);
        let e = gm_estimate(&s, 2, &EstimateOptions::default()).unwrap();
        assert_eq!(e.cov[0][0], 1.0);
        assert!(e.cov.iter().flatten().all(|v| !v.is_nan()));
        // A light one: the variance is w(1 − w)·1e600, beyond f64: +∞.
        let s = gm(&[(1.0 - 1e-9, [0.0, 0.0], 1.0), (1e-9, [1e300, -1e300], 1.0)]);
        let e = gm_estimate(&s, 2, &EstimateOptions::default()).unwrap();
        assert_eq!(e.cov[0][0], f64::INFINITY);
        assert_eq!(e.cov[0][1], f64::NEG_INFINITY);
        // Particles spread beyond f64 in both signs (∞ − ∞ in the plain sum).
        let pts = [0.0, 1e300, 1e200, -1e300, -1e200, 0.0];
        let p = particle_estimate(
            0.5,
            &pts,
            &[1.0 / 3.0; 3],
            2,
            2,
            &EstimateOptions::default(),
        )
        .unwrap();
        assert!(p.cov.iter().flatten().all(|v| !v.is_nan()), "{:?}", p.cov);
        assert_eq!(p.cov[1][1], f64::INFINITY);
        // x: {0, 1e200, −1e200}, variance 2/3 · 1e400: +∞.
        assert_eq!(p.cov[0][0], f64::INFINITY);
    }

    #[test]
    fn eq39_moments_of_states_near_the_largest_double_are_not_nan() {
        // Fuzz edge ParticleBernoulliFilter-mean-overflow: 123 particles at f64::MAX, whose
        // plain weighted sum rounds past it.
        let n = 123;
        let pts: Vec<f64> = (0..n).flat_map(|_| [f64::MAX, 0.0]).collect();
        let w = std::vec![1.0 / n as f64; n];
        let p = particle_estimate(0.5, &pts, &w, 2, 2, &EstimateOptions::default()).unwrap();
        assert_eq!(p.mean, [f64::MAX, 0.0]);
        assert!(p.cov.iter().flatten().all(|v| v.is_finite()), "{:?}", p.cov);
        // Fuzz edge GmBernoulliFilter-estimate-cov-overflow: means −1e308 and f64::MAX apart
        // on one axis; the scale of the spread was 2¹⁰²⁴ = ∞ (then 0 · ∞).
        let s = gm(&[
            (1.0 / 3.0, [0.0, -1e308], 1.0),
            (2.0 / 3.0, [0.0, f64::MAX], 1.0),
        ]);
        let e = gm_estimate(&s, 2, &EstimateOptions::default()).unwrap();
        assert!(e.cov.iter().flatten().all(|v| !v.is_nan()), "{:?}", e.cov);
        assert_eq!(e.cov[1][1], f64::INFINITY);
        assert_eq!(e.cov[0][0], 1.0);
        // Fuzz seed 946630 (GmBernoulliFilter, after splitting about a FoV): components at
        // −f64::MAX whose plain weighted mean rounds to −∞ (then ∞ · 0 in the spread).
        let comps: Vec<_> = (0..123)
            .map(|i| (1.0 / 123.0, [-f64::MAX, f64::from(i % 2)], 1.0))
            .collect();
        let plain: f64 = comps.iter().map(|(w, m, _)| w * m[0]).sum();
        assert_eq!(plain, f64::NEG_INFINITY);
        let e = gm_estimate(&gm(&comps), 2, &EstimateOptions::default()).unwrap();
        assert_eq!(e.mean[0], -f64::MAX);
        assert!(e.cov.iter().flatten().all(|v| !v.is_nan()), "{:?}", e.cov);
    }
}
