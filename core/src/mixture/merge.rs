//! Vo & Ma's Mahalanobis-distance merging.

use alloc::vec::Vec;

use super::moments::merged_moments;
use crate::error::{Error, Result};
use crate::gaussian::{Gaussian, GaussianMixture};

/// Merges components whose means are within Mahalanobis distance `distance` of the heaviest
/// remaining component, as in Table II of Vo & Ma:
///
/// ```text
/// repeat while I ≠ ∅:
///   j = argmax_{i∈I} w_i
///   L = {i ∈ I : (m_i − m_j)ᵀ P_i⁻¹ (m_i − m_j) ≤ U},   U = distance²
///   w̃ = Σ_{i∈L} w_i,   m̃ = Σ_{i∈L} w_i m_i / w̃
///   P̃ = Σ_{i∈L} w_i (P_i + (m̃ − m_i)(m̃ − m_i)ᵀ) / w̃        (the spread-of-means term)
///   I = I ∖ L
/// ```
///
/// so `distance` is a Mahalanobis distance (Vo & Ma's U = 4 is `distance = 2`). Each merge
/// preserves the weight, mean and covariance of the components it replaces, so the total
/// weight and the mixture's mean and covariance are preserved. Ties in weight go to the
/// first component; the output lists the merged components in the order their seeds j were
/// picked (heaviest first). A single component passes through unchanged (no refactoring).
///
/// # Errors
/// [`Error::InvalidParameter`] naming `mergeDistance` if `distance` is negative or not
/// finite; [`Error::NotDefinite`] if a merged covariance fails Cholesky.
///
/// # References
/// B.-N. Vo, W.-K. Ma, "The Gaussian mixture probability hypothesis density filter," IEEE
/// Trans. Signal Process. 54(11):4091–4104, 2006, doi:10.1109/TSP.2006.881190 — Table II.
pub fn merge_close(mixture: &GaussianMixture, distance: f64) -> Result<GaussianMixture> {
    merge_close_owned(mixture.clone(), distance)
}

/// [`merge_close`] of a mixture the caller gives away: the components left alone are moved,
/// not copied (the same numbers).
pub(crate) fn merge_close_owned(
    mixture: GaussianMixture,
    distance: f64,
) -> Result<GaussianMixture> {
    if !(distance.is_finite() && distance >= 0.0) {
        return Err(Error::parameter(
            "mergeDistance",
            distance,
            "finite and >= 0",
        ));
    }
    let u = distance * distance;
    let components = mixture.components();
    let n = match mixture.dim() {
        Some(n) => n,
        None => return Ok(mixture),
    };
    // (m_i − m_j)ᵀ P_i⁻¹ (m_i − m_j) ≥ |m_i − m_j|² / λ_max(P_i) ≥ |m_i − m_j|² / tr P_i, so a
    // pair with |m_i − m_j|² > 2 U tr P_i is farther than U (with a factor 2 to spare for
    // the rounding of the triangular solve): it is skipped without the solve, and the groups
    // are the same as with the solve for every pair.
    let trace: Vec<f64> = components
        .iter()
        .map(|(_, g)| g.cov().diagonal().iter().sum())
        .collect();
    let mut remaining: Vec<usize> = (0..components.len()).collect();
    let mut rest: Vec<usize> = Vec::with_capacity(remaining.len());
    let mut group: Vec<usize> = Vec::new();
    let mut out: Vec<Option<(f64, Gaussian)>> = Vec::new();
    let mut singles: Vec<(usize, usize)> = Vec::new();
    while !remaining.is_empty() {
        let mut j = remaining[0];
        for &i in &remaining {
            if components[i].0 > components[j].0 {
                j = i;
            }
        }
        let mj = components[j].1.mean().as_slice();
        group.clear();
        rest.clear();
        for &i in &remaining {
            let close = i == j || {
                let mi = components[i].1.mean().as_slice();
                let d2: f64 = mi.iter().zip(mj).map(|(a, b)| (a - b) * (a - b)).sum();
                let far = u > 0.0 && d2 > 2.0 * u * trace[i];
                !far && components[i].1.mahalanobis_sq(mj) <= u
            };
            if close {
                group.push(i);
            } else {
                rest.push(i);
            }
        }
        core::mem::swap(&mut remaining, &mut rest);
        if let [single] = group.as_slice() {
            singles.push((out.len(), *single));
            out.push(None);
            continue;
        }
        let (w, m, p) = merged_moments(
            group.iter().map(|&i| {
                let (w, g) = &components[i];
                (*w, g.mean(), g.cov())
            }),
            n,
        );
        out.push(Some((
            w,
            Gaussian::named(m, p, &|| alloc::format!("mixture[{j}]"))?,
        )));
    }
    // The components left alone, moved into their places.
    let mut slots: Vec<Option<(f64, Gaussian)>> =
        mixture.into_components().into_iter().map(Some).collect();
    for (at, i) in singles {
        if let (Some(o), Some(c)) = (out.get_mut(at), slots.get_mut(i)) {
            *o = c.take();
        }
    }
    GaussianMixture::new(out.into_iter().flatten().collect(), "mixture")
}
