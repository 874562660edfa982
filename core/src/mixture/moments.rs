//! Moment-matched merging of Gaussian components.

use alloc::vec::Vec;

use nalgebra::{DMatrix, DVector};

use crate::error::{Error, Result};
use crate::gaussian::{Gaussian, GaussianMixture};

/// Weight, mean and covariance of the moment-matched merge of `(w_i, m_i, P_i)`:
///
/// ```text
/// w̃ = Σ_i w_i
/// m̃ = Σ_i w_i m_i / w̃
/// P̃ = Σ_i w_i (P_i + (m̃ − m_i)(m̃ − m_i)ᵀ) / w̃
/// ```
///
/// (equal weights for the moments when w̃ = 0). The covariance is exactly symmetric.
pub(crate) fn merged_moments<'a>(
    items: impl Iterator<Item = (f64, &'a DVector<f64>, &'a DMatrix<f64>)> + Clone,
    n: usize,
) -> (f64, DVector<f64>, DMatrix<f64>) {
    let total: f64 = crate::math::sum::sum(items.clone().map(|(w, _, _)| w));
    let count = items.clone().count() as f64;
    let share = |w: f64| if total > 0.0 { w / total } else { 1.0 / count };
    let mut mean = DVector::zeros(n);
    for (w, m, _) in items.clone() {
        mean.axpy(share(w), m, 1.0);
    }
    let mut cov = DMatrix::zeros(n, n);
    for (w, m, p) in items {
        let a = share(w);
        let d = m - &mean;
        for i in 0..n {
            for j in 0..=i {
                cov[(i, j)] += a * (0.5 * (p[(i, j)] + p[(j, i)]) + d[i] * d[j]);
            }
        }
    }
    for i in 0..n {
        for j in 0..i {
            cov[(j, i)] = cov[(i, j)];
        }
    }
    (total, mean, cov)
}

/// The moment-matched merge of `components` into one weighted Gaussian: total weight, mean
/// and covariance (with the spread-of-means term) of the sub-mixture, so the merge preserves
/// the sub-mixture's weight, mean and covariance.
///
/// ```text
/// w̃ = Σ_i w_i,   m̃ = Σ_i w_i m_i / w̃,   P̃ = Σ_i w_i (P_i + (m̃ − m_i)(m̃ − m_i)ᵀ) / w̃
/// ```
///
/// This is the merge step of Table II of Vo & Ma and of Runnalls' reduction.
///
/// # Errors
/// [`Error::DimensionMismatch`] naming `components` for an empty list or `components[i]` for
/// a component of another dimension; [`Error::NotDefinite`] naming `{what}.cov` if the
/// merged covariance fails Cholesky (it cannot in exact arithmetic).
///
/// # References
/// B.-N. Vo, W.-K. Ma, "The Gaussian mixture probability hypothesis density filter," IEEE
/// Trans. Signal Process. 54(11):4091–4104, 2006, doi:10.1109/TSP.2006.881190 — Table II.
pub fn merge_components(components: &[(f64, Gaussian)], what: &str) -> Result<(f64, Gaussian)> {
    let Some((_, first)) = components.first() else {
        return Err(Error::dimension("components", 1, 0));
    };
    let n = first.dim();
    for (i, (_, g)) in components.iter().enumerate() {
        if g.dim() != n {
            return Err(Error::dimension(
                alloc::format!("components[{i}]"),
                n,
                g.dim(),
            ));
        }
    }
    let (w, m, p) = merged_moments(components.iter().map(|(w, g)| (*w, g.mean(), g.cov())), n);
    Ok((w, Gaussian::new(m, p, what)?))
}

/// The total weight, mean and covariance of a mixture (its moment-matched single Gaussian,
/// with weights normalised by their total):
///
/// ```text
/// W = Σ_ℓ w_ℓ,   m = Σ_ℓ w_ℓ m_ℓ / W,   P = Σ_ℓ w_ℓ (P_ℓ + (m_ℓ − m)(m_ℓ − m)ᵀ) / W
/// ```
///
/// `None` for an empty mixture.
pub fn moments(mixture: &GaussianMixture) -> Option<(f64, DVector<f64>, DMatrix<f64>)> {
    let components = mixture.components();
    let n = components.first()?.1.dim();
    let refs: Vec<(f64, &DVector<f64>, &DMatrix<f64>)> = components
        .iter()
        .map(|(w, g)| (*w, g.mean(), g.cov()))
        .collect();
    Some(merged_moments(refs.iter().copied(), n))
}
