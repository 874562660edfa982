//! Pruning of light components.

use alloc::vec::Vec;

use crate::error::{Error, Result};
use crate::gaussian::GaussianMixture;
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
    let components = mixture.components();
    if components.is_empty() {
        return Ok(mixture.clone());
    }
    let total = mixture.total_weight();
    let mut kept: Vec<usize> = (0..components.len())
        .filter(|&i| components[i].0 >= threshold)
        .collect();
    if kept.is_empty() {
        let mut best = 0;
        for (i, (w, _)) in components.iter().enumerate() {
            if *w > components[best].0 {
                best = i;
            }
        }
        kept.push(best);
    }
    let kept_total = sum(kept.iter().map(|&i| components[i].0));
    let scale = if kept_total > 0.0 {
        total / kept_total
    } else {
        1.0
    };
    let out = kept
        .into_iter()
        .map(|i| (components[i].0 * scale, components[i].1.clone()))
        .collect();
    GaussianMixture::new(out, "mixture")
}
