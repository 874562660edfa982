//! A multivariate Gaussian with a validated covariance.

use alloc::string::String;
use alloc::sync::Arc;
use alloc::vec::Vec;

use nalgebra::{DMatrix, DVector};
use rand::Rng;

use crate::error::{Error, Result};
use crate::math::fns;

/// N(m, P): a mean and a symmetric positive definite covariance, validated once and stored
/// with its Cholesky factor (P is never inverted).
///
/// P, L and ln det P are held behind one shared pointer: the R children of a split (eqs.
/// (27)–(31) of `001_…`) share one covariance, so they share one factor, and a clone copies
/// only the mean (issue 29: no heap matrix per split child).
#[derive(Clone, Debug, PartialEq)]
pub struct Gaussian {
    mean: DVector<f64>,
    factor: Arc<Factor>,
}

/// P, its lower Cholesky factor L (L Lᵀ = P) and ln det P.
#[derive(Debug, PartialEq)]
struct Factor {
    cov: DMatrix<f64>,
    chol: DMatrix<f64>,
    ln_det: f64,
}

impl Gaussian {
    /// N(mean, cov). `what` names the Gaussian in errors (e.g. `density` or
    /// `mixture[2]`); the mean is reported as `{what}.mean`, the covariance as `{what}.cov`.
    ///
    /// # Errors
    /// [`Error::InvalidParameter`] for a non-finite entry, [`Error::DimensionMismatch`] if
    /// `cov` is not `n × n` for `n = mean.len()`, [`Error::NotSymmetric`] if `cov` is not
    /// symmetric (to a relative 1e-9), [`Error::NotDefinite`] if it is not positive definite
    /// (the checks of [`super::covariance`]).
    pub fn new(mean: DVector<f64>, cov: DMatrix<f64>, what: &str) -> Result<Self> {
        Self::named(mean, cov, &|| String::from(what))
    }

    /// [`Gaussian::new`] with the name built only for an error (the filters' hot loops
    /// name thousands of components that are almost never wrong).
    pub(crate) fn named(
        mean: DVector<f64>,
        cov: DMatrix<f64>,
        what: &dyn Fn() -> String,
    ) -> Result<Self> {
        let n = mean.len();
        if n == 0 {
            return Err(Error::dimension(alloc::format!("{}.mean", what()), 1, 0));
        }
        if let Some(i) = mean.iter().position(|v| !v.is_finite()) {
            return Err(Error::parameter(
                alloc::format!("{}.mean[{i}]", what()),
                mean[i],
                "finite",
            ));
        }
        if cov.nrows() != n || cov.ncols() != n {
            let found = if cov.nrows() != n {
                cov.nrows()
            } else {
                cov.ncols()
            };
            return Err(Error::dimension(alloc::format!("{}.cov", what()), n, found));
        }
        let cov_name = || -> String { alloc::format!("{}.cov", what()) };
        if let Some(k) = cov.iter().position(|v| !v.is_finite()) {
            // nalgebra is column-major: k = col·n + row.
            return Err(Error::parameter(
                alloc::format!("{}.cov[{}][{}]", what(), k % n, k / n),
                cov[k],
                "finite",
            ));
        }
        super::covariance::check_symmetric(&cov, &cov_name)?;
        // Symmetrise exactly so that downstream results do not depend on which triangle
        // carried the rounding: A/2 + Aᵀ/2, which is (A + Aᵀ)/2 bit for bit but cannot
        // overflow for entries near f64::MAX (1e308 + 1e308 = ∞ gave an infinite Cholesky
        // factor and infinite samples). In place: a_ij/2 + a_ji/2 and a_ji/2 + a_ij/2 are
        // the same sum (addition commutes exactly), so both entries get it.
        let mut cov = cov;
        for j in 0..n {
            cov[(j, j)] = cov[(j, j)] * 0.5 + cov[(j, j)] * 0.5;
            for i in j + 1..n {
                let s = cov[(i, j)] * 0.5 + cov[(j, i)] * 0.5;
                cov[(i, j)] = s;
                cov[(j, i)] = s;
            }
        }
        let chol = match cov.clone().cholesky() {
            Some(c) => c.unpack(),
            None => return Err(super::covariance::not_positive_definite(&cov, cov_name())),
        };
        let ln_det = chol.diagonal().iter().map(|d| 2.0 * fns::ln(*d)).sum();
        Ok(Self {
            mean,
            factor: Arc::new(Factor { cov, chol, ln_det }),
        })
    }

    /// N(mean, P) with this Gaussian's P (and its Cholesky factor): the same result as
    /// [`Gaussian::new`]`(mean, self.cov())` without factorising P again (the children of a
    /// split share their covariance).
    ///
    /// # Errors
    /// As [`Gaussian::new`] for the mean (named `{what}.mean`).
    pub(crate) fn with_mean(&self, mean: DVector<f64>, what: &dyn Fn() -> String) -> Result<Self> {
        if mean.len() != self.dim() {
            return Err(Error::dimension(
                alloc::format!("{}.cov", what()),
                mean.len(),
                self.dim(),
            ));
        }
        if let Some(i) = mean.iter().position(|v| !v.is_finite()) {
            return Err(Error::parameter(
                alloc::format!("{}.mean[{i}]", what()),
                mean[i],
                "finite",
            ));
        }
        Ok(Self {
            mean,
            factor: Arc::clone(&self.factor),
        })
    }

    /// N(mean, cov) from a slice and a row-major `n·n` slice.
    ///
    /// # Errors
    /// As [`Gaussian::new`]; [`Error::DimensionMismatch`] if `cov.len() != n²`.
    pub fn from_slices(mean: &[f64], cov_row_major: &[f64], what: &str) -> Result<Self> {
        let n = mean.len();
        if cov_row_major.len() != n * n {
            return Err(Error::dimension(
                alloc::format!("{what}.cov"),
                n * n,
                cov_row_major.len(),
            ));
        }
        Self::new(
            DVector::from_column_slice(mean),
            DMatrix::from_row_slice(n, n, cov_row_major),
            what,
        )
    }

    /// N(mean, σ²I).
    ///
    /// # Errors
    /// As [`Gaussian::new`] (σ must be finite and > 0).
    pub fn isotropic(mean: &[f64], sigma: f64, what: &str) -> Result<Self> {
        if !(sigma.is_finite() && sigma > 0.0) {
            return Err(Error::parameter(
                alloc::format!("{what}.sigma"),
                sigma,
                "finite and > 0",
            ));
        }
        let n = mean.len();
        Self::new(
            DVector::from_column_slice(mean),
            DMatrix::from_diagonal_element(n, n, sigma * sigma),
            what,
        )
    }

    /// The dimension n.
    pub fn dim(&self) -> usize {
        self.mean.len()
    }

    /// The mean m.
    pub fn mean(&self) -> &DVector<f64> {
        &self.mean
    }

    /// The covariance P (exactly symmetric).
    pub fn cov(&self) -> &DMatrix<f64> {
        &self.factor.cov
    }

    /// The lower Cholesky factor L, L Lᵀ = P.
    pub fn chol(&self) -> &DMatrix<f64> {
        &self.factor.chol
    }

    /// ln det P.
    pub fn ln_det(&self) -> f64 {
        self.factor.ln_det
    }

    /// (x − m)ᵀ P⁻¹ (x − m), by a triangular solve. `x` must have length n.
    ///
    /// A point so far away that a whitened coordinate overflows gives +∞ (never NaN: the
    /// substitution stops as soon as the sum of squares is infinite, before an `∞ · 0` or
    /// `∞ − ∞` could appear), so the density there is 0.
    #[allow(clippy::needless_range_loop)]
    pub fn mahalanobis_sq(&self, x: &[f64]) -> f64 {
        debug_assert_eq!(x.len(), self.dim());
        let n = self.dim();
        // Forward substitution L y = x − m (on the stack for small n).
        let mut small = [0.0f64; 8];
        let mut large: Vec<f64> = Vec::new();
        let y: &mut [f64] = if n <= small.len() {
            &mut small[..n]
        } else {
            large.resize(n, 0.0);
            &mut large
        };
        // L column-major: L_ij at i + j·n (flat slices, no per-entry bounds checks; the
        // same operations in the same order).
        let chol = self.factor.chol.as_slice();
        let mean = self.mean.as_slice();
        if n == 4 && x.len() == 4 {
            // The loop below unrolled for the 4-D state (the same operations in the same
            // order, the same early exit).
            let l = chol;
            let y0 = (x[0] - mean[0]) / l[0];
            let mut total = y0 * y0;
            if total == f64::INFINITY {
                return f64::INFINITY;
            }
            let y1 = (x[1] - mean[1] - l[1] * y0) / l[5];
            total += y1 * y1;
            if total == f64::INFINITY {
                return f64::INFINITY;
            }
            let y2 = (x[2] - mean[2] - l[2] * y0 - l[6] * y1) / l[10];
            total += y2 * y2;
            if total == f64::INFINITY {
                return f64::INFINITY;
            }
            let y3 = (x[3] - mean[3] - l[3] * y0 - l[7] * y1 - l[11] * y2) / l[15];
            total += y3 * y3;
            return total;
        }
        let mut total = 0.0;
        for i in 0..n.min(x.len()) {
            let mut s = x[i] - mean[i];
            for j in 0..i {
                s -= chol[i + j * n] * y[j];
            }
            let yi = s / chol[i + i * n];
            total += yi * yi;
            if total == f64::INFINITY {
                return f64::INFINITY;
            }
            y[i] = yi;
        }
        total
    }

    /// ln N(x; m, P).
    pub fn ln_pdf(&self, x: &[f64]) -> f64 {
        let n = self.dim() as f64;
        -0.5 * (n * crate::math::special::LN_2PI + self.factor.ln_det + self.mahalanobis_sq(x))
    }

    /// N(x; m, P).
    pub fn pdf(&self, x: &[f64]) -> f64 {
        fns::exp(self.ln_pdf(x))
    }

    /// A draw m + L z with z standard normal.
    pub fn sample<R: Rng + ?Sized>(&self, rng: &mut R) -> DVector<f64> {
        let z = DVector::from_iterator(
            self.dim(),
            (0..self.dim()).map(|_| super::normal::sample(rng)),
        );
        &self.mean + &self.factor.chol * z
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The unrolled 4-D forward substitution equals a triangular solve, and overflows to +∞.
    #[test]
    fn mahalanobis_4d_matches_a_solve() {
        let cov = [
            4.0, 0.3, 0.2, 0.1, 0.3, 2.0, 0.05, 0.4, 0.2, 0.05, 1.5, 0.3, 0.1, 0.4, 0.3, 1.0,
        ];
        let g = Gaussian::from_slices(&[1.0, -2.0, 0.5, 0.25], &cov, "g").unwrap();
        let x = [0.3, 1.1, -0.7, 2.0];
        let d = DVector::from_column_slice(&x) - g.mean();
        let y = g.chol().solve_lower_triangular(&d).unwrap();
        let want = y.norm_squared();
        assert!((g.mahalanobis_sq(&x) - want).abs() <= 1e-13 * want);
        assert_eq!(g.mahalanobis_sq(&[1e300, 0.0, 0.0, 0.0]), f64::INFINITY);
        assert_eq!(g.mahalanobis_sq(&[1.0, -2.0, 0.5, 0.25]), 0.0);
    }

    #[test]
    fn a_variance_near_f64_max_stays_finite() {
        // Found by the fuzzer (fuzz #7): the symmetrisation overflowed.
        let g = Gaussian::from_slices(&[0.0, 0.0], &[1.0, 0.0, 0.0, 1e308], "g").unwrap();
        assert_eq!(g.cov()[(1, 1)], 1e308);
        assert_eq!(g.chol()[(1, 1)], fns::sqrt(1e308));
        let x = g.sample(&mut crate::math::rng::seeded(0));
        assert!(x.iter().all(|v| v.is_finite()), "{x:?}");
    }

    #[test]
    fn astronomically_far_points_have_zero_density_not_nan() {
        let g = Gaussian::from_slices(&[-1e308, 1.6e-215], &[0.002, 0.0, 0.0, 0.002], "p").unwrap();
        assert_eq!(g.mahalanobis_sq(&[0.0, 0.0]), f64::INFINITY);
        assert_eq!(g.pdf(&[0.0, 0.0]), 0.0);
        let h = Gaussian::from_slices(&[1e308, 0.0], &[1.0, 0.5, 0.5, 1.0], "p").unwrap();
        assert_eq!(h.mahalanobis_sq(&[-1e308, 0.0]), f64::INFINITY);
    }

    #[test]
    fn validates_and_evaluates() {
        let g = Gaussian::from_slices(&[1.0, 2.0], &[4.0, 1.0, 1.0, 2.0], "density").unwrap();
        assert_eq!(g.dim(), 2);
        assert!((g.ln_det() - (7.0f64).ln()).abs() < 1e-14);
        // P⁻¹ = [2 −1; −1 4]/7; x − m = (1, 0) → 2/7
        assert!((g.mahalanobis_sq(&[2.0, 2.0]) - 2.0 / 7.0).abs() < 1e-15);
        let e = Gaussian::from_slices(&[0.0, 0.0], &[1.0, 2.0, 2.0, 1.0], "density").unwrap_err();
        assert_eq!(e.field(), "density.cov");
        let e = Gaussian::from_slices(&[0.0, 0.0], &[1.0, 0.5, 0.4, 1.0], "d").unwrap_err();
        assert_eq!(e.field(), "d.cov");
        let e = Gaussian::from_slices(&[0.0, f64::NAN], &[1.0, 0.0, 0.0, 1.0], "d").unwrap_err();
        assert_eq!(e.field(), "d.mean[1]");
        let e = Gaussian::from_slices(&[0.0], &[1.0, 0.0], "d").unwrap_err();
        assert_eq!(e.field(), "d.cov");
        for sigma in [0.0, -1.0, f64::NAN, f64::INFINITY] {
            let e = Gaussian::isotropic(&[0.0], sigma, "d").unwrap_err();
            assert!(matches!(e, Error::InvalidParameter { .. }), "{e}");
            assert_eq!(e.field(), "d.sigma");
        }
    }
}
