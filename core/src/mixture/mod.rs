//! Gaussian mixture reduction: pruning, Mahalanobis-distance merging (Vo & Ma) and
//! Runnalls' KL-based reduction to a maximum count, and the moment-matched merge they share.
//!
//! Splitting ([`crate::splitting`]) multiplies components near region boundaries; a filter
//! reduces the mixture again after its update. Section V-C of `001_0f0df91eee9b30d5.txt`
//! uses two passes: a Mahalanobis merge first, then Runnalls down to L_max = 100;
//! [`reduce`] runs prune → merge → Runnalls with the passes you enable.
//!
//! Every pass preserves the total weight; the merges also preserve the mixture's mean and
//! covariance (each merge is moment-matched, with the spread-of-means term).

mod merge;
mod moments;
mod prune;
mod runnalls;

pub use merge::merge_close;
pub use moments::{merge_components, moments};
pub use prune::prune;
pub use runnalls::{RUNNALLS_CACHE_LIMIT, runnalls};

use crate::error::Result;
use crate::gaussian::GaussianMixture;

/// Which reduction passes [`reduce`] runs, in this order.
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(
    feature = "serde",
    derive(serde::Serialize, serde::Deserialize),
    serde(default)
)]
pub struct ReductionOptions {
    /// Pruning threshold ≥ 0: components lighter than this are dropped and the rest
    /// renormalised ([`prune`]); 0 (the default) keeps all.
    pub prune_below: f64,
    /// Merge distance ≥ 0: components within this Mahalanobis distance of the heaviest are
    /// merged (Vo & Ma, [`merge_close`]); omitted (`None`): no merging.
    pub merge_distance: Option<f64>,
    /// The most components kept, in [1, 1e6], by Runnalls' merging ([`runnalls`]); omitted
    /// (`None`): no cap.
    pub max_components: Option<usize>,
}

impl Default for ReductionOptions {
    /// No pruning, no merging, no cap: the identity.
    fn default() -> Self {
        Self {
            prune_below: 0.0,
            merge_distance: None,
            max_components: None,
        }
    }
}

/// Prunes, merges and caps the mixture as `options` asks ([`prune`], then [`merge_close`],
/// then [`runnalls`]). The total weight is preserved by every pass.
///
/// # Errors
/// Those of the passes: [`crate::Error::InvalidParameter`] naming `pruneBelow`,
/// `mergeDistance` or `maxComponents`.
///
/// # Examples
/// ```
/// use fisst::gaussian::{Gaussian, GaussianMixture};
/// use fisst::mixture::{ReductionOptions, reduce};
/// let c = |x: f64, w: f64| (w, Gaussian::from_slices(&[x], &[1.0], "m").unwrap());
/// let p = GaussianMixture::new(vec![c(0.0, 0.5), c(0.1, 0.3), c(5.0, 0.199), c(9.0, 0.001)], "mixture")?;
/// let opts = ReductionOptions { prune_below: 0.01, merge_distance: Some(1.0), max_components: Some(1) };
/// let r = reduce(&p, &opts)?;
/// assert_eq!(r.len(), 1);
/// assert!((r.total_weight() - 1.0).abs() < 1e-15);
/// # Ok::<(), fisst::Error>(())
/// ```
pub fn reduce(mixture: &GaussianMixture, options: &ReductionOptions) -> Result<GaussianMixture> {
    reduce_owned(mixture.clone(), options)
}

/// [`reduce`] of a mixture the caller gives away (the filters' posterior): no component is
/// copied that a pass leaves alone; the same numbers.
pub(crate) fn reduce_owned(
    mixture: GaussianMixture,
    options: &ReductionOptions,
) -> Result<GaussianMixture> {
    let mut out = prune::prune_owned(mixture, options.prune_below)?;
    if let Some(d) = options.merge_distance {
        out = merge::merge_close_owned(out, d)?;
    }
    if let Some(max) = options.max_components {
        out = runnalls(&out, max)?;
    }
    Ok(out)
}

#[cfg(test)]
mod tests;
