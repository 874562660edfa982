//! Measurement likelihoods: generalized likelihoods g̃(ζ | x) of imprecise (set-valued)
//! reports, eqs. (38), (63)–(65) of `001_…`, and the linear-Gaussian likelihood of vector
//! measurements.

use alloc::vec::Vec;

use nalgebra::DMatrix;

use crate::error::{Error, Result, Shape};
use crate::gaussian::Gaussian;
use crate::regions::Region;

/// The generalized likelihoods g̃(ζ_i | x) of the m_k reports Υ_k = {ζ_1 … ζ_{m_k}} of one
/// scan (eq. (38) of `001_0f0df91eee9b30d5.txt`): any nonnegative function of the state.
///
/// The GM update evaluates g̃ at the component means (the zeroth-order expansion (57)–(58),
/// Appendix B), which is accurate only where the mixture is fine compared with how fast g̃
/// changes; [`GeneralizedLikelihood::split_regions`] names the regions whose boundaries
/// g̃ jumps across (or bends sharply near), so that the update splits the mixture about
/// them first (Algorithm 3). The particle filter evaluates g̃ at every particle.
pub trait GeneralizedLikelihood {
    /// m_k, the number of reports.
    fn reports(&self) -> usize;

    /// g̃(ζ_i | x) ≥ 0 for report i (0 ≤ i < m_k) at the full state x.
    fn likelihood(&self, report: usize, state: &[f64]) -> f64;

    /// Regions of the position subspace about whose boundaries the mixture should be split
    /// before the update (the ∂ζ of Algorithm 3). Default: none.
    fn split_regions(&self) -> Vec<Region> {
        Vec::new()
    }
}

/// Reports that are regions ζ_i of the position subspace with the indicator likelihood
/// g̃(ζ | x) = 1_ζ(s) (eqs. (63)–(65) of `001_…`: "the object is near anchor a" as the disc
/// 𝒜_a), s the first n_s components of x.
#[derive(Clone, Copy, Debug)]
pub struct RegionReports<'a>(pub &'a [Region]);

impl GeneralizedLikelihood for RegionReports<'_> {
    fn reports(&self) -> usize {
        self.0.len()
    }

    #[inline]
    fn likelihood(&self, report: usize, state: &[f64]) -> f64 {
        if self.0[report].contains(state) {
            1.0
        } else {
            0.0
        }
    }

    fn split_regions(&self) -> Vec<Region> {
        self.0.to_vec()
    }
}

/// Checks the report regions of one scan: at most [`MAX_REGIONS`](super::config::MAX_REGIONS)
/// of them, each of dimension n_s = `position_dims`.
///
/// # Errors
/// [`Error::Count`] naming `reports`; [`Error::ShapeMismatch`] naming the field of
/// `reports[i]` that carries its dimension (`reports[0].box.min`) and `position_dims`.
pub(crate) fn check_reports(reports: &[Region], position_dims: usize) -> Result<()> {
    Error::check_count(
        "reports",
        "regions",
        reports.len(),
        0,
        super::config::MAX_REGIONS,
    )?;
    for (i, r) in reports.iter().enumerate() {
        super::validate::check_region(r, &alloc::format!("reports[{i}]"), position_dims)?;
    }
    Ok(())
}

/// A caller-supplied generalized likelihood: `likelihood(i, x)` = g̃(ζ_i | x) for
/// `reports` reports, with the regions to split about.
///
/// ```
/// use fisst::filters::{FnLikelihood, GeneralizedLikelihood};
/// // "x is roughly 3": a soft bump on the first state component.
/// let g = FnLikelihood::new(1, |_, x: &[f64]| fisst::math::fns::exp(-0.5 * (x[0] - 3.0) * (x[0] - 3.0)), vec![]);
/// assert_eq!(g.likelihood(0, &[3.0, 0.0]), 1.0);
/// ```
#[derive(Clone, Debug)]
pub struct FnLikelihood<F> {
    reports: usize,
    likelihood: F,
    split_regions: Vec<Region>,
}

impl<F: Fn(usize, &[f64]) -> f64> FnLikelihood<F> {
    /// m_k = `reports` reports with g̃(ζ_i | x) = `likelihood(i, x)`, splitting about
    /// `split_regions`.
    pub fn new(reports: usize, likelihood: F, split_regions: Vec<Region>) -> Self {
        Self {
            reports,
            likelihood,
            split_regions,
        }
    }
}

impl<F: Fn(usize, &[f64]) -> f64> GeneralizedLikelihood for FnLikelihood<F> {
    fn reports(&self) -> usize {
        self.reports
    }

    fn likelihood(&self, report: usize, state: &[f64]) -> f64 {
        (self.likelihood)(report, state)
    }

    fn split_regions(&self) -> Vec<Region> {
        self.split_regions.clone()
    }
}

/// The most measurement components a [`LinearGaussianLikelihood`] may have (rows of H).
pub const MAX_MEASUREMENT_DIM: usize = 64;

/// The error for an R of `r` = (rows, columns) with an H of `h` = (m, n): R must be m × m.
fn r_against_h(r: (usize, usize), h: (usize, usize)) -> Error {
    Error::shapes(
        "likelihood.r",
        Shape::Matrix(r.0, r.1),
        "likelihood.h",
        Shape::Matrix(h.0, h.1),
    )
}

/// The linear-Gaussian likelihood g(z | x) = N(z; H x, R) of a vector measurement z
/// (`likelihood: { H, R }`).
#[derive(Clone, Debug, PartialEq)]
pub struct LinearGaussianLikelihood {
    h: DMatrix<f64>,
    /// N(0, R), validated (R symmetric positive definite).
    noise: Gaussian,
}

impl LinearGaussianLikelihood {
    /// H (`likelihood.h`, m × n) and R (`likelihood.r`, m × m symmetric positive definite).
    ///
    /// # Errors
    /// [`Error::Count`] naming `likelihood.h` for more than [`MAX_MEASUREMENT_DIM`] rows;
    /// [`Error::DimensionMismatch`] naming `likelihood.h` (empty); [`Error::ShapeMismatch`]
    /// naming `likelihood.r` (not m × m) and `likelihood.h`; [`Error::InvalidParameter`]
    /// naming `likelihood.h[i][j]` or `likelihood.r[i][j]` for a non-finite entry;
    /// [`Error::NotSymmetric`] or [`Error::NotDefinite`] naming `likelihood.r` (the checks of
    /// [`crate::gaussian::covariance`]).
    pub fn new(h: DMatrix<f64>, r: DMatrix<f64>) -> Result<Self> {
        let m = h.nrows();
        Error::check_count("likelihood.h", "rows", m, 0, MAX_MEASUREMENT_DIM)?;
        if m == 0 || h.ncols() == 0 {
            return Err(Error::dimension("likelihood.h", 1, 0));
        }
        if let Some(k) = h.iter().position(|v| !v.is_finite()) {
            return Err(Error::parameter(
                alloc::format!("likelihood.h[{}][{}]", k % m, k / m),
                h[k],
                "finite",
            ));
        }
        if r.nrows() != m || r.ncols() != m {
            return Err(r_against_h((r.nrows(), r.ncols()), (m, h.ncols())));
        }
        let noise = Gaussian::new(nalgebra::DVector::zeros(m), r, "likelihood.r").map_err(|e| {
            // the Gaussian's `likelihood.r.cov…` is the contract's `likelihood.r…`
            e.map_field(|what| match what.strip_prefix("likelihood.r.cov") {
                Some(rest) => alloc::format!("likelihood.r{rest}"),
                None => what.into(),
            })
        })?;
        Ok(Self { h, noise })
    }

    /// [`LinearGaussianLikelihood::new`] from H (m rows of n numbers) and R (m rows of m
    /// numbers), the shape a user writes (`likelihood: { h, r }`).
    ///
    /// # Errors
    /// [`Error::Count`] naming `likelihood.h` unless it has 1 to [`MAX_MEASUREMENT_DIM`]
    /// rows; [`Error::DimensionMismatch`] naming `likelihood.h[i]` (length not row 0's) or
    /// `likelihood.r[i]` (length not m); [`Error::ShapeMismatch`] naming `likelihood.r` and
    /// `likelihood.h` when R (its rows × the length of its first row) is not m × m; as
    /// [`LinearGaussianLikelihood::from_row_slices`].
    pub fn from_rows(h: &[Vec<f64>], r: &[Vec<f64>]) -> Result<Self> {
        let m = h.len();
        Error::check_count("likelihood.h", "rows", m, 1, MAX_MEASUREMENT_DIM)?;
        let n = h[0].len();
        let rows_of = |rows: &[Vec<f64>], len: usize, what: &str| match rows
            .iter()
            .position(|row| row.len() != len)
        {
            Some(i) => Err(Error::dimension(
                alloc::format!("{what}[{i}]"),
                len,
                rows[i].len(),
            )),
            None => Ok(rows.concat()),
        };
        let h = rows_of(h, n, "likelihood.h")?;
        let r_shape = super::transition::rows_shape(r);
        if r_shape != (m, m) {
            return Err(r_against_h(r_shape, (m, n)));
        }
        let r = rows_of(r, m, "likelihood.r")?;
        Self::from_row_slices(&h, m, &r)
    }

    /// [`LinearGaussianLikelihood::new`] from row-major slices: H with `measurement_dim`
    /// rows (`h.len() / measurement_dim` columns) and R (m² numbers).
    ///
    /// # Errors
    /// [`Error::DimensionMismatch`] naming `likelihood.h` (empty, or its length not a
    /// multiple of m); [`Error::ShapeMismatch`] naming `likelihood.r` (length not m²) and
    /// `likelihood.h`; as [`LinearGaussianLikelihood::new`].
    pub fn from_row_slices(h: &[f64], measurement_dim: usize, r: &[f64]) -> Result<Self> {
        let m = measurement_dim;
        if m == 0 || h.is_empty() || !h.len().is_multiple_of(m) {
            return Err(Error::dimension("likelihood.h", m.max(1), h.len()));
        }
        if r.len() != m * m {
            return Err(Error::shapes(
                "likelihood.r",
                Shape::Length(r.len()),
                "likelihood.h",
                Shape::Matrix(m, h.len() / m),
            ));
        }
        Self::new(
            DMatrix::from_row_slice(m, h.len() / m, h),
            DMatrix::from_row_slice(m, m, r),
        )
    }

    /// H.
    pub fn h(&self) -> &DMatrix<f64> {
        &self.h
    }

    /// R.
    pub fn r(&self) -> &DMatrix<f64> {
        self.noise.cov()
    }

    /// The measurement dimension m.
    pub fn measurement_dim(&self) -> usize {
        self.h.nrows()
    }

    /// The state dimension n.
    pub fn state_dim(&self) -> usize {
        self.h.ncols()
    }

    /// N(z; H x, R).
    pub fn density(&self, z: &[f64], x: &[f64]) -> f64 {
        let m = self.measurement_dim();
        let mut r: Vec<f64> = Vec::with_capacity(m);
        for (i, zi) in z.iter().enumerate().take(m) {
            let mut hx = 0.0;
            for (j, xj) in x.iter().enumerate().take(self.state_dim()) {
                hx += self.h[(i, j)] * xj;
            }
            r.push(zi - hx);
        }
        self.noise.pdf(&r)
    }
}
