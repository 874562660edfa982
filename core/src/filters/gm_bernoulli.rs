//! The Gaussian-mixture Bernoulli filter for imprecise and vector measurements: Algorithm 3
//! and eqs. (40)–(60) of `001_0f0df91eee9b30d5.txt`.

use alloc::vec::Vec;

use nalgebra::{DMatrix, DVector};

use super::config::{
    BernoulliFilterOptions, GmBernoulli, PredictOptions, UpdateOptions, check_state,
};
use super::estimate::{EstimateOptions, FilterEstimate, gm_estimate};
use super::likelihood::{GeneralizedLikelihood, LinearGaussianLikelihood, RegionReports};
use crate::error::{Error, Result, Shape};
use crate::gaussian::{Gaussian, GaussianMixture, covariance};
use crate::math::sum::NeumaierSum;
use crate::mixture::reduce_owned;
use crate::regions::Region;
use crate::splitting::split_for_regions;

/// The Bernoulli prediction of eqs. (40)–(49) of `001_0f0df91eee9b30d5.txt` for a GM density
/// and a linear-Gaussian transition (`gmBernoulliPredict`):
///
/// ```text
/// r_{k|k−1} = p_b (1 − r) + p_S r                                        (41)
/// p_{k|k−1} = Σ_ℓ w_b,ℓ N(m_b,ℓ, P_b,ℓ) + Σ_ℓ w_S,ℓ N(F m_ℓ, F P_ℓ Fᵀ + Q)  (45), (48)–(49)
/// w_b,ℓ = ŵ_b,ℓ p_b (1 − r) / r_{k|k−1},   w_S,ℓ = w_ℓ p_S r / r_{k|k−1}    (46)–(47)
/// ```
///
/// Components of weight 0 (all birth components when p_b (1 − r) = 0, all survivors when
/// p_S r = 0) are left out. When r_{k|k−1} = 0 the density is irrelevant and (40) is
/// undefined; the survivors' prediction (or the birth density when there is no survivor
/// mixture) is returned with existence 0.
///
/// # Errors
/// As [`GmBernoulli::new`] for `state`; [`PredictOptions::validate`];
/// [`Error::DimensionMismatch`] naming `mixture` if its dimension differs from F's;
/// [`Error::NotDefinite`] naming `mixture[ℓ].cov` if a predicted covariance is not
/// positive definite.
///
/// # Examples
/// ```
/// use fisst::filters::{Birth, GmBernoulli, LinearGaussianTransition, PredictOptions, gm_bernoulli_predict};
/// use fisst::gaussian::{Gaussian, GaussianMixture};
/// let g = |m: f64| Gaussian::from_slices(&[m, 1.0], &[1.0, 0.0, 0.0, 0.1], "mixture[0]").unwrap();
/// let state = GmBernoulli::new(0.6, GaussianMixture::new(vec![(1.0, g(0.0))], "mixture")?)?;
/// let config = PredictOptions {
///     transition: LinearGaussianTransition::nearly_constant_velocity(1, 1.0, 0.01)?,
///     survival: 0.99,
///     birth: Birth::new(0.1, GaussianMixture::new(vec![(1.0, g(5.0))], "birth.mixture")?)?,
/// };
/// let p = gm_bernoulli_predict(&state, &config)?;
/// assert!((p.existence - (0.1 * 0.4 + 0.99 * 0.6)).abs() < 1e-15);
/// assert_eq!(p.mixture.len(), 2);
/// # Ok::<(), fisst::Error>(())
/// ```
pub fn gm_bernoulli_predict(state: &GmBernoulli, config: &PredictOptions) -> Result<GmBernoulli> {
    config.validate()?;
    let total = check_state(state)?;
    let f = config.transition.f();
    let n = config.transition.dim();
    super::validate::check_means(
        state.mixture.components().iter().map(|(_, g)| g.dim()),
        "mixture",
        n,
        "transition.f",
        Shape::Matrix(n, n),
    )?;
    let r = state.existence;
    let born = config.birth.probability * (1.0 - r);
    let survive = config.survival * r;
    let predicted = born + survive;
    let survivors = || -> Result<Vec<(f64, Gaussian)>> {
        let mut out = Vec::with_capacity(state.mixture.len());
        for (i, (w, g)) in state.mixture.components().iter().enumerate() {
            let m = f * g.mean();
            let p = f * g.cov() * f.transpose() + config.transition.q();
            let p = (&p + p.transpose()) * 0.5;
            out.push((
                w / total,
                Gaussian::named(m, p, &|| alloc::format!("mixture[{i}]"))?,
            ));
        }
        Ok(out)
    };
    let components: Vec<(f64, Gaussian)> = if predicted > 0.0 {
        let mut out = Vec::new();
        if born > 0.0 {
            for (w, g) in config.birth.mixture.components() {
                out.push((w * born / predicted, g.clone()));
            }
        }
        if survive > 0.0 {
            for (w, g) in survivors()? {
                out.push((w * survive / predicted, g));
            }
        }
        out
    } else {
        survivors()?
    };
    Ok(GmBernoulli {
        existence: predicted.clamp(0.0, 1.0),
        mixture: GaussianMixture::new(components, "mixture")?,
    })
}

/// The result of a GM Bernoulli update (`gmBernoulliUpdate`'s result).
#[derive(Clone, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct GmBernoulliUpdate {
    /// The posterior existence probability r_{k|k} ∈ [0, 1] (`existence`).
    pub existence: f64,
    /// The posterior spatial density p_{k|k} after the reduction (`mixture`), weights summing
    /// to 1.
    #[cfg_attr(feature = "serde", serde(with = "crate::serde_shapes::components"))]
    pub mixture: GaussianMixture,
    /// The update's Δ_k of eq. (58) (`delta`), computed on the split, exclusion-constrained
    /// prediction; 1 − Δ_k is the likelihood ratio of the scan under "the object exists" against
    /// "it does not". −∞ when a report has zero clutter intensity (it can only be the object's).
    pub delta: f64,
    /// The number of components after splitting, before the update and reduction
    /// (`splitComponents`).
    pub split_components: usize,
}

/// The GM Bernoulli update for imprecise measurements given as regions, with the
/// generalized likelihood g̃(ζ | x) = 1_ζ(s) (eqs. (63)–(65) of `001_…`): Algorithm 3's
/// split–update–reduce step (`gmBernoulliUpdate` with `reports`). See
/// [`gm_bernoulli_update_with`] for the method.
///
/// # Errors
/// [`Error::DimensionMismatch`] naming `reports[i]` for a region whose dimension is not
/// n_s; as [`gm_bernoulli_update_with`].
///
/// # Examples
/// The empty scan of the Stone Soup comparison: r = 0.8, p_D = 0.9, the whole density in
/// the field of view: r ← 0.8 · 0.1 / (1 − 0.8 · 0.9) = 0.2857.
/// ```
/// use fisst::filters::{Clutter, ClutterDensity, Detection, GmBernoulli, UpdateOptions, gm_bernoulli_update};
/// use fisst::gaussian::{Gaussian, GaussianMixture};
/// let g = Gaussian::from_slices(&[0.0, 0.0], &[1.0, 0.0, 0.0, 1.0], "mixture[0]")?;
/// let state = GmBernoulli::new(0.8, GaussianMixture::new(vec![(1.0, g)], "mixture")?)?;
/// let config = UpdateOptions::new(2, Detection::new(0.9, None)?, Clutter::new(0.25, ClutterDensity::Constant(0.1))?);
/// let out = gm_bernoulli_update(&state, &[], &config)?;
/// assert!((out.existence - 0.08 / 0.28).abs() < 1e-15);
/// assert!((out.delta - 0.9).abs() < 1e-15);
/// # Ok::<(), fisst::Error>(())
/// ```
pub fn gm_bernoulli_update(
    state: &GmBernoulli,
    reports: &[Region],
    config: &UpdateOptions,
) -> Result<GmBernoulliUpdate> {
    super::likelihood::check_reports(reports, config.position_dims)?;
    gm_bernoulli_update_with(state, &RegionReports(reports), config)
}

/// The GM Bernoulli filter update for imprecise measurements (Algorithm 3 of
/// `001_0f0df91eee9b30d5.txt`) with any generalized likelihood g̃ the caller supplies.
///
/// 1. **Split** (Algorithm 2, [`split_for_regions`]) the predicted mixture about the field
///    of view ∂S, every ∂ζ of [`GeneralizedLikelihood::split_regions`] and every exclusion
///    region ∂E, all in one pass, so the result does not depend on their order.
/// 2. **Exclusions**: the mean-based partition (12) about ∪E — components whose mean lies in
///    an exclusion region are removed and the rest renormalised. This conditions the
///    *density* on x ∉ E and leaves the existence unchanged: an exclusion region is a
///    constraint of the state space (the motion model put mass where the object cannot
///    be), not evidence that the object does not exist. Δ_k and r_{k|k} are computed from
///    the constrained prediction.
/// 3. **Update** to zeroth order about the component means (Appendix B), with
///    κ_i = λ_c c̃(ζ_i) and p_D,ℓ = p_D(m_ℓ; S) (51):
///
///    ```text
///    α_ℓ = 1 − p_D,ℓ + p_D,ℓ Σ_i g̃(ζ_i | m_ℓ) / κ_i
///    Δ_k = Σ_ℓ w_ℓ p_D,ℓ − Σ_i Σ_ℓ w_ℓ p_D,ℓ g̃(ζ_i | m_ℓ) / κ_i           (58)
///    w_ℓ ← w_ℓ α_ℓ / (1 − Δ_k),  m_ℓ, P_ℓ unchanged                         (57), (59)–(60)
///    r_{k|k} = r (1 − Δ_k) / (1 − r Δ_k)                                     (54)
///    ```
///
///    (1 − Δ_k = Σ_ℓ w_ℓ α_ℓ is summed directly, without cancellation.) Components whose
///    weight becomes 0 are dropped. With no report (Υ_k = ∅) this is the non-detection
///    update: r = 0.8, p_D = 0.9 with the density inside S gives 0.286.
///
///    **Zero clutter intensity.** A report with κ_i = 0 can only come from the object: then
///    r_{k|k} = 1, the density is ∝ Σ_ℓ w_ℓ p_D,ℓ g̃(ζ_i | m_ℓ) N(m_ℓ, P_ℓ) and Δ_k = −∞. Two
///    or more such reports are impossible for a single object (an error).
/// 4. **Reduce** ([`crate::mixture::reduce`], default: prune 1e-6, Mahalanobis merge,
///    Runnalls to L_max = 100).
///
/// # Errors
/// [`Error::InvalidProbability`] naming `existence`; those of [`UpdateOptions::validate`];
/// [`Error::DimensionMismatch`] naming `clutter.density` (one value per report needed);
/// [`Error::InvalidParameter`] naming `likelihood[i]` when g̃ returns a negative or
/// non-finite value, `exclusions` when the exclusions remove the whole density, `reports`
/// when the scan has probability 0 under the model while r = 1 (or while r = 0 and only an
/// object can explain it), `clutter.rate` when two or more reports have zero clutter
/// intensity; those of [`split_for_regions`] and [`reduce`](crate::mixture::reduce).
pub fn gm_bernoulli_update_with<L: GeneralizedLikelihood + ?Sized>(
    state: &GmBernoulli,
    likelihood: &L,
    config: &UpdateOptions,
) -> Result<GmBernoulliUpdate> {
    check_state(state)?;
    config.validate(state.dim())?;
    let m = likelihood.reports();
    let kappa = config.clutter.intensities(m, |_| None)?;
    let split_about: Vec<Region> = likelihood.split_regions();
    let (split, split_components) = refine(&state.mixture, split_about, config)?;
    let kept = constrain(&split, &config.exclusions)?;
    let prior: Vec<(f64, &Gaussian)> = kept
        .iter()
        .filter_map(|&(w, i)| split.components().get(i).map(|(_, g)| (w, g)))
        .collect();
    let detection = &config.detection;
    let mut terms = Vec::with_capacity(prior.len());
    for (w, g) in &prior {
        let x = g.mean().as_slice();
        let pd = detection.probability_at(x);
        let mut ratio = 0.0;
        let mut certain = 0.0;
        if pd > 0.0 {
            for (i, k) in kappa.iter().enumerate() {
                let gi = likelihood.likelihood(i, x);
                if !(gi.is_finite() && gi >= 0.0) {
                    return Err(Error::parameter(
                        alloc::format!("likelihood[{i}]"),
                        gi,
                        "finite and >= 0",
                    ));
                }
                add_report(&mut ratio, &mut certain, gi, *k);
            }
        }
        terms.push(Term::new(*w, pd, ratio, certain));
    }
    let zero_kappa = count_zero_kappa(&kappa);
    let (existence, weights, delta) = bernoulli_weights(state.existence, &terms, zero_kappa)?;
    let posterior: Vec<(usize, f64)> = kept
        .iter()
        .zip(weights)
        .filter(|(_, w)| *w > 0.0)
        .map(|(&(_, i), w)| (i, w))
        .collect();
    drop(prior);
    finish(
        existence,
        pick(split, &posterior),
        delta,
        split_components,
        config,
    )
}

/// The per-component quantities of the zeroth-order update.
pub(crate) struct Term {
    /// w_ℓ (constrained prediction).
    pub(crate) weight: f64,
    /// p_D,ℓ.
    pub(crate) pd: f64,
    /// w_ℓ (1 − p_D,ℓ).
    pub(crate) missed: f64,
    /// w_ℓ p_D,ℓ Σ_{κ_i > 0} g̃_iℓ / κ_i.
    pub(crate) detected: f64,
    /// w_ℓ p_D,ℓ Σ_{κ_i = 0} g̃_iℓ.
    pub(crate) certain: f64,
}

impl Term {
    /// The term of a component of weight w_ℓ and detection probability p_D,ℓ whose
    /// likelihoods add up to `ratio` = Σ_{κ_i > 0} g̃_iℓ / κ_i and `certain` = Σ_{κ_i = 0} g̃_iℓ
    /// (see [`add_report`]).
    #[inline]
    pub(crate) fn new(w: f64, pd: f64, ratio: f64, certain: f64) -> Term {
        Term {
            weight: w,
            pd,
            missed: w * (1.0 - pd),
            detected: w * pd * ratio,
            certain: w * pd * certain,
        }
    }
}

/// Adds one report's likelihood `g` = g̃_iℓ to `ratio` as g / κ_i where its clutter
/// intensity `kappa` = κ_i > 0, and to `certain` where κ_i = 0 (the sums of [`Term`]).
#[inline]
pub(crate) fn add_report(ratio: &mut f64, certain: &mut f64, g: f64, kappa: f64) {
    if kappa > 0.0 {
        *ratio += g / kappa;
    } else {
        *certain += g;
    }
}

/// How many reports have zero clutter intensity (at most one is allowed, see
/// [`bernoulli_weights`]).
pub(crate) fn count_zero_kappa(kappa: &[f64]) -> usize {
    kappa.iter().filter(|k| **k <= 0.0).count()
}

/// Checks that every measurement has the m components of `likelihood`'s H, all finite.
///
/// # Errors
/// [`Error::DimensionMismatch`] naming `measurements[j]`, [`Error::InvalidParameter`] naming
/// `measurements[j][i]`.
pub(crate) fn check_measurements<M: AsRef<[f64]>>(
    measurements: &[M],
    likelihood: &LinearGaussianLikelihood,
) -> Result<()> {
    let mdim = likelihood.measurement_dim();
    Error::check_count(
        "measurements",
        "measurements",
        measurements.len(),
        0,
        super::config::MAX_MEASUREMENTS,
    )?;
    for (j, z) in measurements.iter().enumerate() {
        let z = z.as_ref();
        if z.len() != mdim {
            return Err(Error::shapes(
                alloc::format!("measurements[{j}]"),
                Shape::Length(z.len()),
                "likelihood.h",
                Shape::Matrix(mdim, likelihood.state_dim()),
            ));
        }
        if let Some(i) = z.iter().position(|v| !v.is_finite()) {
            return Err(Error::parameter(
                alloc::format!("measurements[{j}][{i}]"),
                z[i],
                "finite",
            ));
        }
    }
    Ok(())
}

/// r_{k|k}, the posterior weights of the terms and Δ_k, eqs. (54), (57)–(58).
pub(crate) fn bernoulli_weights(
    r: f64,
    terms: &[Term],
    zero_kappa: usize,
) -> Result<(f64, Vec<f64>, f64)> {
    if zero_kappa >= 2 {
        return Err(Error::parameter(
            "clutter.rate",
            0.0,
            "> 0 (with zero clutter intensity at two or more reports, no single object explains the scan)",
        ));
    }
    if zero_kappa == 1 {
        let total: f64 = terms
            .iter()
            .map(|t| t.certain)
            .collect::<NeumaierSum>()
            .total();
        if total.is_nan() || total <= 0.0 || r == 0.0 {
            return Err(Error::parameter(
                "reports",
                total,
                "a scan the model can explain (a report with zero clutter intensity that the object cannot produce)",
            ));
        }
        let weights = terms.iter().map(|t| t.certain / total).collect();
        return Ok((1.0, weights, f64::NEG_INFINITY));
    }
    let mut kept = NeumaierSum::new(); // 1 − Δ
    let mut delta = NeumaierSum::new();
    for t in terms {
        kept.add(t.missed);
        kept.add(t.detected);
        delta.add(t.weight * t.pd);
        delta.add(-t.detected);
    }
    let kept = kept.total();
    let delta = delta.total();
    if !kept.is_finite() {
        return Err(Error::parameter(
            "clutter.density",
            kept,
            "clutter intensities that keep g/κ finite",
        ));
    }
    if kept <= 0.0 {
        // The scan is impossible if the object exists.
        if r >= 1.0 {
            return Err(Error::parameter(
                "reports",
                kept,
                "a scan the model can explain (it has probability 0 while the existence is 1)",
            ));
        }
        let weights = terms.iter().map(|t| t.weight).collect();
        return Ok((0.0, weights, delta));
    }
    let existence = (r * kept / (1.0 - r + r * kept)).clamp(0.0, 1.0);
    let weights = terms
        .iter()
        .map(|t| (t.missed + t.detected) / kept)
        .collect();
    Ok((existence, weights, delta))
}

/// Algorithm 3's splitting step: the mixture split about ∂S, the extra regions and ∂E.
fn refine<'a>(
    mixture: &'a GaussianMixture,
    mut regions: Vec<Region>,
    config: &UpdateOptions,
) -> Result<(alloc::borrow::Cow<'a, GaussianMixture>, usize)> {
    if let Some(fov) = &config.detection.fov
        && config.detection.probability > 0.0
    {
        regions.push(fov.clone());
    }
    regions.extend(config.exclusions.iter().cloned());
    // The same region twice changes nothing but the cost.
    let mut unique: Vec<Region> = Vec::with_capacity(regions.len());
    for r in regions {
        if !unique.contains(&r) {
            unique.push(r);
        }
    }
    if !config.splitting.enabled || unique.is_empty() {
        return Ok((alloc::borrow::Cow::Borrowed(mixture), mixture.len()));
    }
    let mut options = config.splitting.options.clone();
    options.position_dims = config.position_dims;
    let out = split_for_regions(mixture, &unique, &config.splitting.library, &options)?;
    let n = out.mixture.len();
    Ok((alloc::borrow::Cow::Owned(out.mixture), n))
}

/// The components `keep` ((index, weight), indices ascending) of `split` with their new
/// weights: moved out when the split mixture is owned, copied when it is the caller's.
fn pick(
    split: alloc::borrow::Cow<'_, GaussianMixture>,
    keep: &[(usize, f64)],
) -> Vec<(f64, Gaussian)> {
    match split {
        alloc::borrow::Cow::Owned(m) => {
            let mut next = keep.iter().peekable();
            let mut out = Vec::with_capacity(keep.len());
            for (i, (_, g)) in m.into_components().into_iter().enumerate() {
                if let Some(&&(j, w)) = next.peek()
                    && j == i
                {
                    out.push((w, g));
                    next.next();
                }
            }
            out
        }
        alloc::borrow::Cow::Borrowed(m) => keep
            .iter()
            .filter_map(|&(i, w)| m.components().get(i).map(|(_, g)| (w, g.clone())))
            .collect(),
    }
}

/// The exclusion constraint: drop the components whose mean lies in some exclusion region
/// and renormalise (the mean-based partition (12) about ∪E). Returns (weight, index into
/// `mixture`), indices ascending.
fn constrain(mixture: &GaussianMixture, exclusions: &[Region]) -> Result<Vec<(f64, usize)>> {
    let kept: Vec<(f64, usize)> = mixture
        .components()
        .iter()
        .enumerate()
        .filter(|(_, (_, g))| {
            let x = g.mean().as_slice();
            !exclusions.iter().any(|e| e.contains(x))
        })
        .map(|(i, (w, _))| (*w, i))
        .collect();
    let total: f64 = kept
        .iter()
        .map(|(w, _)| *w)
        .collect::<NeumaierSum>()
        .total();
    if total.is_nan() || total <= 0.0 {
        return Err(Error::parameter(
            "exclusions",
            total,
            "regions that leave some of the predicted density outside them",
        ));
    }
    Ok(kept.into_iter().map(|(w, i)| (w / total, i)).collect())
}

/// Builds the posterior mixture, reduces it and packs the result.
fn finish(
    existence: f64,
    components: Vec<(f64, Gaussian)>,
    delta: f64,
    split_components: usize,
    config: &UpdateOptions,
) -> Result<GmBernoulliUpdate> {
    let total: f64 = components
        .iter()
        .map(|(w, _)| *w)
        .collect::<NeumaierSum>()
        .total();
    let components = components
        .into_iter()
        .map(|(w, g)| (w / total, g))
        .collect();
    let mixture = GaussianMixture::new(components, "mixture")?;
    let mixture = reduce_owned(mixture, &config.reduction).map_err(|e| match e {
        Error::InvalidParameter {
            what,
            value,
            expected,
        } if what == "pruneBelow" || what == "mergeDistance" || what == "maxComponents" => {
            Error::InvalidParameter {
                what: alloc::format!("reduction.{what}"),
                value,
                expected,
            }
        }
        other => other,
    })?;
    Ok(GmBernoulliUpdate {
        existence,
        mixture,
        delta,
        split_components,
    })
}

/// The GM Bernoulli update for vector measurements z with the linear-Gaussian likelihood
/// N(z; H x, R) (`gmBernoulliUpdate` with `measurements` and `likelihood: { H, R }`): the
/// Bernoulli filter update of Ristic, Vo, Vo & Farina (2013), eqs. (57)–(58), in Gaussian-
/// mixture form, written on the same types as the imprecise update. With q_ℓ(z) =
/// N(z; H m_ℓ, S_ℓ), S_ℓ = H P_ℓ Hᵀ + R, κ(z) = λ_c c(z) and p_D,ℓ = p_D(m_ℓ; S) (51):
///
/// ```text
/// Δ_k = Σ_ℓ w_ℓ p_D,ℓ − Σ_z Σ_ℓ w_ℓ p_D,ℓ q_ℓ(z) / κ(z)
/// p_{k|k} ∝ Σ_ℓ w_ℓ (1 − p_D,ℓ) N(m_ℓ, P_ℓ) + Σ_z Σ_ℓ w_ℓ p_D,ℓ q_ℓ(z)/κ(z) N(m_ℓ(z), P_ℓ⁺)
/// m_ℓ(z) = m_ℓ + K_ℓ (z − H m_ℓ),  K_ℓ = P_ℓ Hᵀ S_ℓ⁻¹
/// P_ℓ⁺ = (I − K_ℓ H) P_ℓ (I − K_ℓ H)ᵀ + K_ℓ R K_ℓᵀ   (Joseph form)
/// r_{k|k} = r (1 − Δ_k) / (1 − r Δ_k)
/// ```
///
/// With a field of view the mixture is first split about ∂S (and any exclusions, handled as
/// in [`gm_bernoulli_update_with`]) so that p_D evaluated at the means is accurate; with a
/// constant p_D and no exclusion nothing is split. A measurement with κ(z) = 0 can only be
/// the object's (as in [`gm_bernoulli_update_with`]): with p_D = 1, no clutter and r = 1
/// this is the Kalman filter.
///
/// # Errors
/// [`Error::DimensionMismatch`] naming `likelihood.h` (its column count is not the state
/// dimension) or `measurements[j]` (length not m); [`Error::InvalidParameter`] naming
/// `measurements[j][i]` for a non-finite coordinate; [`Error::NotDefinite`] naming
/// `mixture[ℓ].cov`, with the smallest eigenvalue of S = H P Hᵀ + R, if an innovation
/// covariance is not positive definite ([`Error::NotPositiveDefinite`] if it overflows); as
/// [`gm_bernoulli_update_with`].
pub fn gm_bernoulli_update_vector<M: AsRef<[f64]>>(
    state: &GmBernoulli,
    measurements: &[M],
    likelihood: &LinearGaussianLikelihood,
    config: &UpdateOptions,
) -> Result<GmBernoulliUpdate> {
    check_state(state)?;
    let n = state.dim();
    config.validate(n)?;
    if likelihood.state_dim() != n {
        return Err(Error::shapes(
            "likelihood.h",
            Shape::Matrix(likelihood.measurement_dim(), likelihood.state_dim()),
            "mixture[0].mean",
            Shape::Length(n),
        ));
    }
    check_measurements(measurements, likelihood)?;
    let kappa = config
        .clutter
        .intensities(measurements.len(), |j| Some(measurements[j].as_ref()))?;
    check_vector_work(state.mixture.len(), measurements.len(), n)?;
    let (split, split_components) = refine(&state.mixture, Vec::new(), config)?;
    check_vector_work(split.len(), measurements.len(), n)?;
    let prior: Vec<(f64, &Gaussian)> = constrain(&split, &config.exclusions)?
        .into_iter()
        .filter_map(|(w, i)| split.components().get(i).map(|(_, g)| (w, g)))
        .collect();
    let h = likelihood.h();
    let ht = h.transpose();
    // Per component: the missed term and one detected term per measurement.
    let mut terms = Vec::with_capacity(prior.len());
    let mut updated: Vec<Vec<(f64, f64, Option<Gaussian>)>> = Vec::with_capacity(prior.len());
    for (l, (w, g)) in prior.iter().enumerate() {
        let pd = config.detection.probability_at(g.mean().as_slice());
        let mut per_z = Vec::with_capacity(measurements.len());
        let (mut ratio, mut certain) = (0.0, 0.0);
        if pd > 0.0 && !measurements.is_empty() {
            let what = alloc::format!("mixture[{l}].cov");
            let p = g.cov();
            let s = h * p * &ht + likelihood.r();
            let s = (&s + s.transpose()) * 0.5;
            let hm = h * g.mean();
            // S is symmetric by construction: only its definiteness can fail, said with its
            // smallest eigenvalue under the name of the component whose P gave it.
            let innov = Gaussian::new(hm.clone(), s, &what).map_err(|e| match e {
                Error::NotDefinite {
                    smallest_eigenvalue,
                    semidefinite,
                    ..
                } => Error::NotDefinite {
                    what: what.clone(),
                    smallest_eigenvalue,
                    semidefinite,
                },
                _ => Error::NotPositiveDefinite { what: what.clone() },
            })?;
            // K = P Hᵀ S⁻¹ via the Cholesky factor of S.
            let chol = nalgebra::Cholesky::new(innov.cov().clone())
                .ok_or_else(|| covariance::not_positive_definite(innov.cov(), what.clone()))?;
            let pht = p * &ht;
            let k = chol.solve(&pht.transpose()).transpose();
            let ikh = DMatrix::identity(n, n) - &k * h;
            let post = &ikh * p * ikh.transpose() + &k * likelihood.r() * k.transpose();
            let post = (&post + post.transpose()) * 0.5;
            for (j, z) in measurements.iter().enumerate() {
                let z = z.as_ref();
                let q = innov.pdf(z);
                let mean = g.mean() + &k * (DVector::from_column_slice(z) - &hm);
                let comp = Gaussian::new(mean, post.clone(), &alloc::format!("mixture[{l}]"))?;
                if kappa[j] > 0.0 {
                    ratio += q / kappa[j];
                    per_z.push((w * pd * q / kappa[j], 0.0, Some(comp)));
                } else {
                    certain += q;
                    per_z.push((0.0, w * pd * q, Some(comp)));
                }
            }
        }
        terms.push(Term::new(*w, pd, ratio, certain));
        updated.push(per_z);
    }
    let zero_kappa = count_zero_kappa(&kappa);
    let (existence, _, delta) = bernoulli_weights(state.existence, &terms, zero_kappa)?;
    // Expand the per-component weights into missed and per-measurement components.
    let mut out: Vec<(f64, Gaussian)> = Vec::new();
    if zero_kappa == 1 {
        for per_z in updated {
            for (_, c, g) in per_z {
                if c > 0.0
                    && let Some(g) = g
                {
                    out.push((c, g));
                }
            }
        }
    } else {
        let kept: f64 = terms
            .iter()
            .flat_map(|t| [t.missed, t.detected])
            .collect::<NeumaierSum>()
            .total();
        if kept > 0.0 {
            for (((_, g), t), per_z) in prior.iter().zip(&terms).zip(updated) {
                if t.missed > 0.0 {
                    out.push((t.missed, (*g).clone()));
                }
                for (d, _, comp) in per_z {
                    if d > 0.0
                        && let Some(comp) = comp
                    {
                        out.push((d, comp));
                    }
                }
            }
        } else {
            out = prior.iter().map(|(w, g)| (*w, (*g).clone())).collect();
        }
    }
    finish(existence, out, delta, split_components, config)
}

/// The most work of one vector update ([`gm_bernoulli_update_vector`]), counted as
/// components (after splitting) × measurements × ⌈n² / 16⌉ for an n-dimensional state (the
/// pairs, each a posterior Gaussian; its n × n covariance counted in units of a 4-D one):
/// `2^18 = 262,144`. At the cap an update took 0.2–0.3 s in Node (2-D states: 10,000
/// components × 26 measurements, 2000 × 131; 4-D: 2000 × 131), while 10,000 × 104 2-D
/// pairs took 6.2 s (the reduction of a million posterior components) and 10,000 × 10,000
/// ran out of time and memory. Beyond it the update returns [`Error::OverBudget`] naming
/// `measurements` before any pair is formed.
pub const MAX_VECTOR_UPDATE_WORK: usize = 1 << 18;

/// `Ok` if components × measurements × ⌈n² / 16⌉ is within [`MAX_VECTOR_UPDATE_WORK`].
///
/// # Errors
/// [`Error::OverBudget`] naming `measurements`.
fn check_vector_work(components: usize, measurements: usize, n: usize) -> Result<()> {
    Error::check_work(
        "measurements",
        "mixture components (after splitting) × measurements × ⌈n²/16⌉",
        "MAX_VECTOR_UPDATE_WORK = 2^18 (pass fewer measurements or reduce the mixture)",
        components.saturating_mul(n.saturating_mul(n).div_ceil(16)),
        measurements,
        MAX_VECTOR_UPDATE_WORK,
    )
}

/// What an update reported besides the new state.
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct UpdateInfo {
    /// The update's Δ_k of eq. (58) (−∞ when a report has zero clutter intensity).
    pub delta: f64,
    /// Components after splitting (GM filter); the particle count (particle filter).
    pub split_components: usize,
}

/// The GM Bernoulli filter of Algorithm 3 of `001_0f0df91eee9b30d5.txt` as an object
/// (`GmBernoulliFilter`): it holds the Bernoulli (r, p(x)) and the models of a
/// [`BernoulliFilterOptions`]; [`predict`](Self::predict) applies (40)–(49),
/// [`update`](Self::update) the imprecise update ([`gm_bernoulli_update`]) and
/// [`update_measurements`](Self::update_measurements) the vector update
/// ([`gm_bernoulli_update_vector`]). An empty scan is a real update (the non-detection
/// update), never skipped.
#[derive(Clone, Debug)]
pub struct GmBernoulliFilter {
    state: GmBernoulli,
    predict: PredictOptions,
    update: UpdateOptions,
    likelihood: Option<LinearGaussianLikelihood>,
    last: Option<UpdateInfo>,
}

impl GmBernoulliFilter {
    /// A filter at r_{0|0}, p_{0|0} of `config`.
    ///
    /// # Errors
    /// As [`BernoulliFilterOptions::validate`].
    pub fn new(config: BernoulliFilterOptions) -> Result<Self> {
        config.validate()?;
        Ok(Self {
            state: GmBernoulli::new(config.existence, config.mixture.clone())?,
            predict: config.predict_options(),
            update: config.update_options(),
            likelihood: config.likelihood,
            last: None,
        })
    }

    /// The current Bernoulli.
    pub fn state(&self) -> &GmBernoulli {
        &self.state
    }

    /// r, the probability that the object exists.
    pub fn existence(&self) -> f64 {
        self.state.existence
    }

    /// p(x).
    pub fn mixture(&self) -> &GaussianMixture {
        &self.state.mixture
    }

    /// Δ_k and the split size of the last update.
    pub fn last_update(&self) -> Option<UpdateInfo> {
        self.last
    }

    /// The prediction (40)–(49).
    ///
    /// # Errors
    /// As [`gm_bernoulli_predict`]. On `Err`, the filter is unchanged (the prediction is
    /// computed out of place and stored only on success).
    pub fn predict(&mut self) -> Result<()> {
        self.state = gm_bernoulli_predict(&self.state, &self.predict)?;
        Ok(())
    }

    /// The update with imprecise reports (regions); `&[]` is the non-detection update.
    ///
    /// # Errors
    /// As [`gm_bernoulli_update`]. On `Err`, the filter is unchanged (the update is computed
    /// out of place and stored only on success).
    pub fn update(&mut self, reports: &[Region]) -> Result<UpdateInfo> {
        let out = gm_bernoulli_update(&self.state, reports, &self.update)?;
        Ok(self.store(out))
    }

    /// The update with a caller-supplied generalized likelihood.
    ///
    /// # Errors
    /// As [`gm_bernoulli_update_with`]. On `Err`, the filter is unchanged.
    pub fn update_with<L: GeneralizedLikelihood + ?Sized>(
        &mut self,
        likelihood: &L,
    ) -> Result<UpdateInfo> {
        let out = gm_bernoulli_update_with(&self.state, likelihood, &self.update)?;
        Ok(self.store(out))
    }

    /// The update with vector measurements (the config's `likelihood`).
    ///
    /// # Errors
    /// [`Error::Unsupported`] naming `likelihood` when the config has none; as
    /// [`gm_bernoulli_update_vector`]. On `Err`, the filter is unchanged.
    pub fn update_measurements<M: AsRef<[f64]>>(
        &mut self,
        measurements: &[M],
    ) -> Result<UpdateInfo> {
        let Some(l) = &self.likelihood else {
            return Err(Error::Unsupported {
                what: "likelihood".into(),
                reason: "vector measurements need a likelihood { H, R } in the filter's config",
            });
        };
        let out = gm_bernoulli_update_vector(&self.state, measurements, l, &self.update)?;
        Ok(self.store(out))
    }

    fn store(&mut self, out: GmBernoulliUpdate) -> UpdateInfo {
        let info = UpdateInfo {
            delta: out.delta,
            split_components: out.split_components,
        };
        self.state = GmBernoulli {
            existence: out.existence,
            mixture: out.mixture,
        };
        self.last = Some(info);
        info
    }

    /// The MMSE estimate, the existence and (with a loss) the optimal Bernoulli point
    /// estimate of paper `000` ([`FilterEstimate`]).
    ///
    /// # Errors
    /// As [`gm_estimate`](super::estimate::gm_estimate).
    pub fn estimate(&self, options: &EstimateOptions) -> Result<FilterEstimate> {
        gm_estimate(&self.state, self.update.position_dims, options)
    }
}
