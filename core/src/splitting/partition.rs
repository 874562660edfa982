//! The mean-based partition (11)–(12) of `001_…` and its measured accuracy.

use alloc::vec::Vec;

use crate::error::{Error, Result};
use crate::gaussian::GaussianMixture;
use crate::math::sum::{NeumaierSum, sum};
use crate::regions::Region;

/// The two halves of a mixture by the mean-based partition (11)–(12).
#[derive(Clone, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct Partition {
    /// The inside part p_S: the components whose mean lies in S (11).
    pub inside: GaussianMixture,
    /// The outside part p_C(S): the components whose mean lies outside S (12).
    pub outside: GaussianMixture,
    /// The inside weight, Σ of the inside weights: the partition's estimate of ⟨1_S, p⟩.
    pub inside_weight: f64,
    /// The outside weight: Σ of the weights of the components whose mean lies outside.
    pub outside_weight: f64,
}

/// The mean-based partition of eqs. (11)–(12) of `001_0f0df91eee9b30d5.txt`: the indicator
/// is evaluated at each component mean,
///
/// ```text
/// p_S(x)    ≈ Σ_ℓ w^{(ℓ)} 1_S(m^{(ℓ)}) N(x; m^{(ℓ)}, P^{(ℓ)})             (11)
/// p_C(S)(x) ≈ Σ_ℓ w^{(ℓ)} (1 − 1_S(m^{(ℓ)})) N(x; m^{(ℓ)}, P^{(ℓ)})       (12)
/// ```
///
/// with the region's exact inclusion test on the first n_s = `region.dim()` components of
/// the mean. Accurate once the mixture has been refined near ∂S by
/// [`split_for_regions`](super::split_for_regions); see [`partition_accuracy`].
///
/// # Errors
/// [`Error::DimensionMismatch`] naming `mixture` if the mixture's dimension is below the
/// region's.
pub fn partition(mixture: &GaussianMixture, region: &Region) -> Result<Partition> {
    if let Some(n) = mixture.dim()
        && n < region.dim()
    {
        return Err(Error::dimension("mixture", region.dim(), n));
    }
    let (mut inside, mut outside) = (Vec::new(), Vec::new());
    for (w, g) in mixture.components() {
        let target = if region.contains(g.mean().as_slice()) {
            &mut inside
        } else {
            &mut outside
        };
        target.push((*w, g.clone()));
    }
    let inside_weight = sum(inside.iter().map(|(w, _)| *w));
    let outside_weight = sum(outside.iter().map(|(w, _)| *w));
    Ok(Partition {
        inside: GaussianMixture::new(inside, "mixture")?,
        outside: GaussianMixture::new(outside, "mixture")?,
        inside_weight,
        outside_weight,
    })
}

/// How well the mean-based partition of a (split) mixture reproduces the exact mass of a
/// region under the mixture it approximates.
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct PartitionAccuracy {
    /// Σ_ℓ w^{(ℓ)} 1_S(m^{(ℓ)}) over the split mixture: the weight of p_S in (11).
    pub partitioned: f64,
    /// ⟨1_S, p⟩ = Σ_ℓ w^{(ℓ)} ⟨1_S, N(m^{(ℓ)}, P^{(ℓ)})⟩ over the reference mixture, by
    /// [`Region::gaussian_mass`].
    pub exact: f64,
    /// The error estimate of `exact` (sum of the per-component estimates).
    pub exact_error: f64,
    /// The partition error |partitioned − exact|.
    pub error: f64,
}

/// Measures the mean-based partition of `split` against the exact mass of `region` under
/// `reference` (the mixture before splitting). The error falls as the recursion of
/// [`split_for_regions`](super::split_for_regions) deepens, down to a floor set by the split
/// library's own approximation error (each split changes the density slightly).
///
/// # Errors
/// [`Error::DimensionMismatch`] if a mixture's dimension is below the region's; the errors
/// of [`Region::gaussian_mass`] (e.g. [`Error::Unsupported`] for n_s > 4).
pub fn partition_accuracy(
    reference: &GaussianMixture,
    split: &GaussianMixture,
    region: &Region,
) -> Result<PartitionAccuracy> {
    let partitioned = partition(split, region)?.inside_weight;
    let mut exact = NeumaierSum::new();
    let mut exact_error = 0.0;
    for (i, (w, g)) in reference.components().iter().enumerate() {
        let m = region.gaussian_mass(g, &alloc::format!("mixture[{i}]"))?;
        exact.add(w * m.value);
        exact_error += w * m.error;
    }
    let exact = exact.total();
    Ok(PartitionAccuracy {
        partitioned,
        exact,
        exact_error,
        error: crate::math::fns::abs(partitioned - exact),
    })
}
