//! The split of a full-state component along one of its covariance eigenvectors, eqs.
//! (27)–(31) of `001_…`.

use alloc::string::String;
use alloc::vec::Vec;

use nalgebra::{DMatrix, DVector, SymmetricEigen};

use super::SplitLibrary;
use crate::error::{Error, Result};
use crate::gaussian::Gaussian;
use crate::gaussian::covariance;
use crate::math::fns;

/// Iteration cap of the symmetric eigensolver (it converges in a few sweeps; the cap only
/// guarantees termination).
const EIGEN_MAX_ITER: usize = 10_000;

/// The eigendecomposition P = V Λ Vᵀ of a symmetric positive definite matrix, eigenvalues in
/// descending order (ties keep the solver's order), each eigenvector's largest-magnitude
/// entry positive (the first such on ties), so the order and signs are reproducible.
#[derive(Clone, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct Eigen {
    /// The eigenvalues λ₁ ≥ λ₂ ≥ … > 0.
    pub values: Vec<f64>,
    /// Column i is the unit eigenvector of `values[i]`.
    #[cfg_attr(feature = "serde", serde(with = "crate::serde_shapes::matrix"))]
    pub vectors: DMatrix<f64>,
}

impl Eigen {
    /// The decomposition of `cov` (symmetric positive definite). `what` names it in errors.
    ///
    /// # Errors
    /// The checks of [`covariance`]: [`Error::NotSymmetric`] naming `what` and the first
    /// asymmetric pair; [`Error::NotDefinite`] naming `what` with the smallest eigenvalue if
    /// an eigenvalue is not finite and > 0 (NaN if the solver does not converge).
    pub fn new(cov: &DMatrix<f64>, what: &str) -> Result<Self> {
        Self::named(cov, &|| String::from(what))
    }

    /// [`Eigen::new`] with the name built only for an error.
    pub(crate) fn named(cov: &DMatrix<f64>, what: &dyn Fn() -> String) -> Result<Self> {
        let n = cov.nrows();
        covariance::check_symmetric(cov, what)?;
        let not_definite = |smallest_eigenvalue: f64| Error::NotDefinite {
            what: what(),
            smallest_eigenvalue,
            semidefinite: false,
        };
        let not_pd = || not_definite(f64::NAN);
        if n == 2 {
            return Self::closed_form_2x2(
                cov[(0, 0)],
                0.5 * (cov[(0, 1)] + cov[(1, 0)]),
                cov[(1, 1)],
            )
            .map_err(not_definite);
        }
        let (eigenvalues, eigenvectors) = if n == 4 {
            // The same solver on a fixed-size matrix: no heap allocation.
            let m = nalgebra::Matrix4::from_fn(|i, j| cov[(i, j)]);
            let eig =
                SymmetricEigen::try_new(m, f64::EPSILON, EIGEN_MAX_ITER).ok_or_else(not_pd)?;
            (
                DVector::from_column_slice(eig.eigenvalues.as_slice()),
                DMatrix::from_column_slice(4, 4, eig.eigenvectors.as_slice()),
            )
        } else {
            let eig = SymmetricEigen::try_new(cov.clone(), f64::EPSILON, EIGEN_MAX_ITER)
                .ok_or_else(not_pd)?;
            (eig.eigenvalues, eig.eigenvectors)
        };
        let eig = Decomposed {
            eigenvalues,
            eigenvectors,
        };
        let mut order: Vec<usize> = (0..n).collect();
        // Stable sort: equal eigenvalues keep the solver's (deterministic) order.
        crate::math::sort::sort_by(&mut order, |&a, &b| {
            eig.eigenvalues[b]
                .partial_cmp(&eig.eigenvalues[a])
                .unwrap_or(core::cmp::Ordering::Equal)
        });
        let mut values = Vec::with_capacity(n);
        let mut vectors = DMatrix::zeros(n, n);
        for (col, &i) in order.iter().enumerate() {
            let value = eig.eigenvalues[i];
            if !(value.is_finite() && value > 0.0) {
                // Sorted descending (NaN as equal): say the smallest, or NaN if any is.
                let smallest = eig.eigenvalues.iter().fold(f64::INFINITY, |a, &v| {
                    if a.is_nan() || v.is_nan() {
                        f64::NAN
                    } else {
                        a.min(v)
                    }
                });
                return Err(not_definite(smallest));
            }
            values.push(value);
            let v = eig.eigenvectors.column(i);
            let mut big = 0;
            for r in 1..n {
                if fns::abs(v[r]) > fns::abs(v[big]) {
                    big = r;
                }
            }
            let sign = if v[big] < 0.0 { -1.0 } else { 1.0 };
            for r in 0..n {
                vectors[(r, col)] = sign * v[r];
            }
        }
        Ok(Self { values, vectors })
    }

    /// The closed form for a symmetric 2 × 2 matrix [[a, b], [b, c]] (the position block of
    /// the airport example, eqs. (15)–(17) of `001_…`):
    ///
    /// ```text
    /// λ₁ = (a + c)/2 + √(((a − c)/2)² + b²),   λ₂ = (a c − b²)/λ₁
    /// v₁ ∝ (λ₁ − c, b) or (b, λ₁ − a) (the longer),   v₂ = v₁ turned by 90°
    /// ```
    ///
    /// (λ₂ from the determinant, not by cancellation). With the conventions of
    /// [`Eigen::new`]: descending values, the identity's columns when b = 0 and a = c, and
    /// each vector's largest-magnitude entry positive. `Err(λ₂)` unless λ₁ and λ₂ are finite
    /// and λ₂ > 0 (`Err(NaN)` if either is not finite: the closed form over- or underflowed).
    fn closed_form_2x2(a: f64, b: f64, c: f64) -> core::result::Result<Self, f64> {
        let half = 0.5 * (a - c);
        let radius = fns::sqrt(half * half + b * b);
        let l1 = 0.5 * (a + c) + radius;
        let l2 = (a * c - b * b) / l1;
        if !(l1.is_finite() && l2.is_finite() && l2 > 0.0) {
            return Err(if l1.is_finite() && l2.is_finite() {
                l2
            } else {
                f64::NAN
            });
        }
        let (mut x, mut y) = if b == 0.0 {
            if a >= c { (1.0, 0.0) } else { (0.0, 1.0) }
        } else {
            let (p, q) = ((l1 - c, b), (b, l1 - a));
            let (u, v) = if p.0 * p.0 + p.1 * p.1 >= q.0 * q.0 + q.1 * q.1 {
                p
            } else {
                q
            };
            let norm = fns::sqrt(u * u + v * v);
            (u / norm, v / norm)
        };
        let positive = |x: f64, y: f64| {
            let big = if fns::abs(y) > fns::abs(x) { y } else { x };
            if big < 0.0 { (-x, -y) } else { (x, y) }
        };
        (x, y) = positive(x, y);
        let (x2, y2) = positive(-y, x);
        Ok(Self {
            values: alloc::vec![l1, l2],
            vectors: DMatrix::from_column_slice(2, 2, &[x, y, x2, y2]),
        })
    }
}

/// The solver's output before sorting.
struct Decomposed {
    eigenvalues: DVector<f64>,
    eigenvectors: DMatrix<f64>,
}

/// Splits `weight · N(m, P)` into R components along the k-th eigenvector of P (eigenvalues
/// in descending order, k = 0 the largest), eqs. (27)–(31) of `001_0f0df91eee9b30d5.txt`:
///
/// ```text
/// w N(x; m, P) ≈ Σ_{j=1}^{R} w^{(j)} N(x; m^{(j)}, P^{(j)})            (27)
/// w^{(j)} = w̃_j w                                                    (28)
/// m^{(j)} = m + √λ_k m̃_j v_k                                         (29)
/// P^{(j)} = V Λ' Vᵀ,  Λ' = diag(λ₁ … σ̃² λ_k … λ_n)                    (30)–(31)
/// ```
///
/// with (w̃, m̃, σ̃) from `library`. P^{(j)} is computed in the equivalent rank-one form
/// P − (1 − σ̃²) λ_k v_k v_kᵀ, which leaves every direction orthogonal to v_k exactly as in P.
///
/// # Moments
/// The children's mixture has mean m (the library is symmetric: Σ w̃_j m̃_j = 0; exact up to
/// rounding) and covariance P − (1 − V) λ_k v_k v_kᵀ with V = [`SplitLibrary::variance`]:
/// for Table I, 4.97 % of λ_k is lost along v_k and nothing in any other direction.
///
/// # Errors
/// [`Error::InvalidParameter`] naming `k` if k ≥ n, `weight` if not finite and ≥ 0;
/// [`Error::NotSymmetric`] or [`Error::NotDefinite`] naming `{what}.cov` as [`Eigen::new`]
/// (P not symmetric, an eigenvalue not finite and > 0), or if a child's covariance fails its
/// Cholesky factorisation (only for extremely ill-conditioned P).
///
/// # Examples
/// ```
/// use fisst::gaussian::Gaussian;
/// use fisst::splitting::{SplitLibrary, split_component};
/// let g = Gaussian::from_slices(&[1.0, 2.0], &[4.0, 0.0, 0.0, 1.0], "p")?;
/// let parts = split_component(1.0, &g, 0, &SplitLibrary::table_i(), "p")?;
/// assert_eq!(parts.len(), 4);
/// // Along x (eigenvalue 4): means 1 + 2·m̃_j, variance 4·σ̃².
/// assert!((parts[3].1.mean()[0] - (1.0 + 2.0 * 1.42237156603631)).abs() < 1e-12);
/// assert!((parts[0].1.cov()[(0, 0)] - 4.0 * 0.58160633157686f64.powi(2)).abs() < 1e-12);
/// # Ok::<(), fisst::Error>(())
/// ```
pub fn split_component(
    weight: f64,
    gaussian: &Gaussian,
    k: usize,
    library: &SplitLibrary,
    what: &str,
) -> Result<Vec<(f64, Gaussian)>> {
    if !(weight.is_finite() && weight >= 0.0) {
        return Err(Error::parameter("weight", weight, "finite and >= 0"));
    }
    let n = gaussian.dim();
    if k >= n {
        return Err(Error::parameter(
            "k",
            k as f64,
            "an eigenvector index below the dimension",
        ));
    }
    let eigen = Eigen::new(gaussian.cov(), &alloc::format!("{what}.cov"))?;
    split_with_eigen(
        weight,
        gaussian.mean(),
        gaussian.cov(),
        &eigen,
        k,
        library,
        what,
    )
}

/// The children's common covariance P − (1 − σ̃²) λ_k v_k v_kᵀ, exactly symmetric.
pub(crate) fn child_covariance(
    cov: &DMatrix<f64>,
    eigen: &Eigen,
    k: usize,
    sigma: f64,
) -> DMatrix<f64> {
    let n = cov.nrows();
    let c = (1.0 - sigma * sigma) * eigen.values[k];
    let v = eigen.vectors.column(k);
    let mut out = DMatrix::zeros(n, n);
    for i in 0..n {
        for j in 0..=i {
            let x = 0.5 * (cov[(i, j)] + cov[(j, i)]) - c * v[i] * v[j];
            out[(i, j)] = x;
            out[(j, i)] = x;
        }
    }
    out
}

/// The children's means m + √λ_k m̃_j v_k.
pub(crate) fn child_means(
    mean: &DVector<f64>,
    eigen: &Eigen,
    k: usize,
    library: &SplitLibrary,
) -> Vec<DVector<f64>> {
    let root = fns::sqrt(eigen.values[k]);
    let v = eigen.vectors.column(k);
    library
        .means()
        .iter()
        .map(|&mt| {
            let step = root * mt;
            DVector::from_iterator(
                mean.len(),
                mean.iter().zip(v.iter()).map(|(m, vi)| m + step * vi),
            )
        })
        .collect()
}

pub(crate) fn split_with_eigen(
    weight: f64,
    mean: &DVector<f64>,
    cov: &DMatrix<f64>,
    eigen: &Eigen,
    k: usize,
    library: &SplitLibrary,
    what: &str,
) -> Result<Vec<(f64, Gaussian)>> {
    let child_cov = child_covariance(cov, eigen, k, library.sigma());
    let means = child_means(mean, eigen, k, library);
    let mut out = Vec::with_capacity(means.len());
    for (m, &wt) in means.into_iter().zip(library.weights()) {
        out.push((wt * weight, Gaussian::new(m, child_cov.clone(), what)?));
    }
    Ok(out)
}
