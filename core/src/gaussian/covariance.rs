//! The checks of a covariance matrix, in one wording for every function that takes one:
//! symmetric (to a relative 1e-9), then positive definite (a Gaussian's P, a likelihood's R)
//! or positive semidefinite (a transition's Q, eq. (44) of `001_0f0df91eee9b30d5.txt`), the
//! error naming the entry that breaks the symmetry ([`Error::NotSymmetric`]) or the smallest
//! eigenvalue ([`Error::NotDefinite`]).

use alloc::string::String;

use nalgebra::{DMatrix, SymmetricEigen};

use crate::error::{Error, Result};
use crate::math::fns;

/// Relative tolerance of the symmetry check: |P_ij − P_ji| ≤ 1e-9 √|P_ii P_jj|.
pub const SYMMETRY_TOL: f64 = 1e-9;

/// Relative tolerance of the semidefiniteness check: no eigenvalue below −1e-9 times the
/// largest.
pub const SEMIDEFINITE_TOL: f64 = 1e-9;

/// Sweeps of the eigendecomposition before it gives up.
const EIGEN_MAX_ITER: usize = 10_000;

/// Checks that the square matrix `cov` is symmetric: |P_ij − P_ji| ≤ 1e-9 √|P_ii P_jj| for
/// every pair (entries assumed finite).
///
/// # Errors
/// [`Error::NotSymmetric`] naming `what()` and the first pair `[i][j]`, i < j, that differs.
pub fn check_symmetric(cov: &DMatrix<f64>, what: &dyn Fn() -> String) -> Result<()> {
    let n = cov.nrows();
    for i in 0..n {
        for j in 0..i {
            let (lower, upper) = (cov[(i, j)], cov[(j, i)]);
            let scale = fns::sqrt(fns::abs(cov[(i, i)] * cov[(j, j)]));
            if fns::abs(lower - upper) > SYMMETRY_TOL * scale.max(f64::MIN_POSITIVE) {
                return Err(Error::NotSymmetric {
                    what: what(),
                    row: j,
                    col: i,
                    upper,
                    lower,
                });
            }
        }
    }
    Ok(())
}

/// The eigendecomposition of the symmetric matrix `cov`, or [`Error::NotDefinite`] naming
/// `what()` (eigenvalue NaN) when it does not converge.
pub fn eigen(
    cov: &DMatrix<f64>,
    what: &dyn Fn() -> String,
    semidefinite: bool,
) -> Result<SymmetricEigen<f64, nalgebra::Dyn>> {
    SymmetricEigen::try_new(cov.clone(), f64::EPSILON, EIGEN_MAX_ITER).ok_or_else(|| {
        Error::NotDefinite {
            what: what(),
            smallest_eigenvalue: f64::NAN,
            semidefinite,
        }
    })
}

/// The smallest eigenvalue of the symmetric matrix `cov` (NaN if the eigendecomposition does
/// not converge).
pub fn smallest_eigenvalue(cov: &DMatrix<f64>) -> f64 {
    SymmetricEigen::try_new(cov.clone(), f64::EPSILON, EIGEN_MAX_ITER).map_or(f64::NAN, |e| {
        e.eigenvalues.iter().fold(f64::INFINITY, |a, v| a.min(*v))
    })
}

/// The error for the symmetric matrix `cov` whose Cholesky factorisation failed:
/// [`Error::NotDefinite`] naming `what` with its smallest eigenvalue.
pub fn not_positive_definite(cov: &DMatrix<f64>, what: String) -> Error {
    Error::NotDefinite {
        what,
        smallest_eigenvalue: smallest_eigenvalue(cov),
        semidefinite: false,
    }
}

/// Checks that the eigenvalues `values` of a symmetric matrix are ≥ −1e-9 times the largest
/// (positive semidefinite to rounding).
///
/// # Errors
/// [`Error::NotDefinite`] (semidefinite) naming `what()` with the smallest eigenvalue.
pub fn check_semidefinite(values: &[f64], what: &dyn Fn() -> String) -> Result<()> {
    let top = values.iter().fold(0.0f64, |a, v| a.max(*v));
    let smallest = values.iter().fold(f64::INFINITY, |a, v| a.min(*v));
    if smallest < -SEMIDEFINITE_TOL * top.max(0.0) {
        return Err(Error::NotDefinite {
            what: what(),
            smallest_eigenvalue: smallest,
            semidefinite: true,
        });
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;
    use alloc::string::ToString;

    fn name() -> String {
        "transition.q".into()
    }

    #[test]
    fn asymmetry_names_the_first_pair_and_both_entries() {
        let q = DMatrix::from_row_slice(2, 2, &[1.0, 0.5, 0.4, 1.0]);
        let e = check_symmetric(&q, &name).unwrap_err();
        assert_eq!(
            e.to_string(),
            "transition.q is not symmetric: [0][1] = 0.5 but [1][0] = 0.4"
        );
        assert!(check_symmetric(&DMatrix::identity(3, 3), &name).is_ok());
    }

    #[test]
    fn indefiniteness_says_the_smallest_eigenvalue() {
        let p = DMatrix::from_row_slice(2, 2, &[1.25, 0.0, 0.0, -0.25]);
        let e = not_positive_definite(&p, "mixture[0].cov".into());
        assert_eq!(
            e.to_string(),
            "mixture[0].cov is not positive definite (smallest eigenvalue -0.25)"
        );
        let eig = eigen(&p, &name, true).unwrap();
        let e = check_semidefinite(eig.eigenvalues.as_slice(), &name).unwrap_err();
        assert_eq!(
            e.to_string(),
            "transition.q is not positive semidefinite (smallest eigenvalue -0.25)"
        );
        assert!(check_semidefinite(&[0.0, 2.0, -1e-12], &name).is_ok());
    }
}
