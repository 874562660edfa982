//! Pruning of light components.

use alloc::vec::Vec;

use crate::error::{Error, Result};
use crate::gaussian::{Gaussian, GaussianMixture};
use crate::math::sum::sum;

/// Drops every component with weight below `threshold` and rescales the survivors by
/// W/W_kept so the total weight W is unchanged:
///
/// ```text
/// I = {ℓ : w_ℓ ≥ T},   w_ℓ ← w_ℓ · (Σ_all w) / (Σ_{i∈I} w_i)   for ℓ ∈ I
/// ```
///
/// The pruning step of Table II of Vo & Ma, with the renormalisation that keeps the total
/// weight (a density stays normalised; a PHD keeps its expected count). If every component
/// is below the threshold the heaviest one is kept (the first on ties), carrying the whole
/// weight; an empty mixture stays empty. Components keep their order.
///
/// # Errors
/// [`Error::InvalidParameter`] naming `pruneBelow` if `threshold` is negative or not finite.
///
/// # References
/// B.-N. Vo, W.-K. Ma, "The Gaussian mixture probability hypothesis density filter," IEEE
/// Trans. Signal Process. 54(11):4091–4104, 2006, doi:10.1109/TSP.2006.881190 — Table II.
pub fn prune(mixture: &GaussianMixture, threshold: f64) -> Result<GaussianMixture> {
    if !(threshold.is_finite() && threshold >= 0.0) {
        return Err(Error::parameter("pruneBelow", threshold, "finite and >= 0"));
    }
    if mixture.components().iter().all(|(w, _)| *w >= threshold) {
        // Nothing to drop: the scale below, on the mixture itself.
        return prune_owned(mixture.clone(), threshold);
    }
    let kept = mixture
        .components()
        .iter()
        .filter(|(w, _)| *w >= threshold)
        .cloned()
        .collect();
    rescale(kept, mixture)
}

/// [`prune`] of a mixture the caller gives away: the kept components are moved, not copied
/// (the same numbers).
pub(crate) fn prune_owned(mixture: GaussianMixture, threshold: f64) -> Result<GaussianMixture> {
    if !(threshold.is_finite() && threshold >= 0.0) {
        return Err(Error::parameter("pruneBelow", threshold, "finite and >= 0"));
    }
    let total = mixture.total_weight();
    if mixture.components().iter().any(|(w, _)| *w < threshold) {
        if mixture.components().iter().all(|(w, _)| *w < threshold) {
            return prune(&mixture, threshold);
        }
        // Move the survivors out (in order) instead of copying them; the same numbers as
        // `prune`'s `rescale`.
        let kept: Vec<_> = mixture
            .into_components()
            .into_iter()
            .filter(|(w, _)| *w >= threshold)
            .collect();
        return scaled_to(kept, total);
    }
    let components = mixture.into_components();
    if components.is_empty() {
        return GaussianMixture::new(components, "mixture");
    }
    scaled_to(components, total)
}

/// The survivors `kept` (in order, at least one of `mixture`'s components is below the
/// threshold) rescaled to the total weight of `mixture`; when none survives, the heaviest
/// component (the first on ties) with the whole weight.
fn rescale(mut kept: Vec<(f64, Gaussian)>, mixture: &GaussianMixture) -> Result<GaussianMixture> {
    let components = mixture.components();
    let total = mixture.total_weight();
    if kept.is_empty() {
        let mut best = 0;
        for (i, (w, _)) in components.iter().enumerate() {
            if *w > components[best].0 {
                best = i;
            }
        }
        kept.push(components[best].clone());
    }
    scaled_to(kept, total)
}

/// The mixture of `kept` with every weight scaled by W/W_kept, W = `total` (by 1 when
/// W_kept = Σ kept w is not positive): the renormalisation of [`prune`].
fn scaled_to(mut kept: Vec<(f64, Gaussian)>, total: f64) -> Result<GaussianMixture> {
    let kept_total = sum(kept.iter().map(|(w, _)| *w));
    let scale = if kept_total > 0.0 {
        total / kept_total
    } else {
        1.0
    };
    for (w, _) in &mut kept {
        *w *= scale;
    }
    GaussianMixture::new(kept, "mixture")
}
