//! The linear-Gaussian transition π(x | x′) = N(x; F x′, Q), eq. (44) of `001_…`, and the
//! nearly-constant-velocity model (70)–(71).

use alloc::vec::Vec;

use nalgebra::DMatrix;

use crate::error::{Error, Result, Shape};
use crate::gaussian::covariance;
use crate::math::fns;

/// π_{k|k−1}(x | x′) = N(x; F x′, Q), eq. (44) (and (69)) of `001_0f0df91eee9b30d5.txt`.
///
/// Q may be singular (positive semidefinite, e.g. ϖ = 0, or noise on the velocity only):
/// the prediction samples with a factor G Gᵀ = Q that allows it (Cholesky when Q is positive
/// definite, V √Λ otherwise), and the particle filter's MCMC move step, which needs the
/// transition density, leaves the survivors of a singular Q where the prediction put them.
#[derive(Clone, Debug, PartialEq)]
pub struct LinearGaussianTransition {
    f: DMatrix<f64>,
    q: DMatrix<f64>,
    /// A factor G with G Gᵀ = Q (Cholesky when Q is positive definite, V √Λ otherwise),
    /// for sampling.
    factor: DMatrix<f64>,
    /// The Cholesky factor of Q when Q is positive definite.
    chol: Option<DMatrix<f64>>,
    /// ln det Q when Q is positive definite.
    ln_det: f64,
}

/// The most states a transition may have (n ≤ 64: the eigendecompositions and the
/// splitting's collocation grids of larger states are beyond any interactive use).
pub const MAX_STATES: usize = 64;

impl LinearGaussianTransition {
    /// F (`transition.f`, n × n) and Q (`transition.q`, n × n, symmetric positive
    /// semidefinite).
    ///
    /// # Errors
    /// [`Error::Unsupported`] naming `transition.f` for more than [`MAX_STATES`] states;
    /// [`Error::DimensionMismatch`] naming `transition.f` (not square, or empty);
    /// [`Error::ShapeMismatch`] naming `transition.q` (not n × n) and `transition.f`;
    /// [`Error::InvalidParameter`] naming `transition.f[i][j]` or `transition.q[i][j]` for a
    /// non-finite entry; [`Error::NotSymmetric`] naming `transition.q` if Q is not symmetric
    /// (to a relative 1e-9), [`Error::NotDefinite`] (semidefinite) if it has a negative
    /// eigenvalue (below −1e-9 of its largest): the checks of [`covariance`].
    pub fn new(f: DMatrix<f64>, q: DMatrix<f64>) -> Result<Self> {
        let n = f.nrows();
        check_states(n)?;
        if n == 0 {
            return Err(Error::dimension("transition.f", 1, 0));
        }
        if f.ncols() != n {
            return Err(Error::dimension("transition.f", n, f.ncols()));
        }
        if q.nrows() != n || q.ncols() != n {
            return Err(Error::shapes(
                "transition.q",
                Shape::Matrix(q.nrows(), q.ncols()),
                "transition.f",
                Shape::Matrix(n, n),
            ));
        }
        check_finite(&f, "transition.f")?;
        check_finite(&q, "transition.q")?;
        let name = || "transition.q".into();
        covariance::check_symmetric(&q, &name)?;
        let q = (&q + q.transpose()) * 0.5;
        let (factor, chol, ln_det) = match q.clone().cholesky() {
            Some(c) => {
                let l = c.unpack();
                let ln_det = (0..n).map(|i| 2.0 * fns::ln(l[(i, i)])).sum();
                (l.clone(), Some(l), ln_det)
            }
            None => {
                let eig = covariance::eigen(&q, &name, true)?;
                covariance::check_semidefinite(eig.eigenvalues.as_slice(), &name)?;
                let mut g = eig.eigenvectors.clone();
                for (k, v) in eig.eigenvalues.iter().enumerate() {
                    let s = fns::sqrt(v.max(0.0));
                    for r in 0..n {
                        g[(r, k)] *= s;
                    }
                }
                (g, None, f64::NEG_INFINITY)
            }
        };
        Ok(Self {
            f,
            q,
            factor,
            chol,
            ln_det,
        })
    }

    /// [`LinearGaussianTransition::new`] from F and Q given as n rows of n numbers each (the
    /// shape a user writes, `transition: { f, q }`).
    ///
    /// # Errors
    /// [`Error::Unsupported`] naming `transition.f` for more than [`MAX_STATES`] rows;
    /// [`Error::DimensionMismatch`] naming `transition.f[i]` or `transition.q[i]` for a row
    /// whose length differs from its matrix's row count; [`Error::ShapeMismatch`] naming
    /// `transition.q` and `transition.f` when Q (its rows × the length of its first row) is
    /// not F's n × n; as
    /// [`LinearGaussianTransition::from_row_slices`].
    pub fn from_rows(f: &[Vec<f64>], q: &[Vec<f64>]) -> Result<Self> {
        check_states(f.len())?;
        let n = f.len();
        let f = square_rows(f, "transition.f")?;
        let q_shape = rows_shape(q);
        if q_shape != (n, n) {
            return Err(Error::shapes(
                "transition.q",
                Shape::Matrix(q_shape.0, q_shape.1),
                "transition.f",
                Shape::Matrix(n, n),
            ));
        }
        let q = square_rows(q, "transition.q")?;
        Self::from_row_slices(&f, &q)
    }

    /// [`LinearGaussianTransition::new`] from row-major slices of n² numbers each.
    ///
    /// # Errors
    /// [`Error::DimensionMismatch`] naming `transition.f` if `f.len()` is not a square
    /// number; [`Error::ShapeMismatch`] naming `transition.q` and `transition.f` if
    /// `q.len() != f.len()`; as [`LinearGaussianTransition::new`].
    pub fn from_row_slices(f: &[f64], q: &[f64]) -> Result<Self> {
        let n = isqrt(f.len());
        if n * n != f.len() || n == 0 {
            return Err(Error::dimension("transition.f", (n + 1) * (n + 1), f.len()));
        }
        if q.len() != f.len() {
            let k = isqrt(q.len());
            let shape = if k * k == q.len() {
                Shape::Matrix(k, k)
            } else {
                Shape::Length(q.len())
            };
            return Err(Error::shapes(
                "transition.q",
                shape,
                "transition.f",
                Shape::Matrix(n, n),
            ));
        }
        Self::new(
            DMatrix::from_row_slice(n, n, f),
            DMatrix::from_row_slice(n, n, q),
        )
    }

    /// The nearly-constant-velocity (white-noise acceleration) model of eqs. (70)–(71) of
    /// `001_…`, generalised to d = `position_dims` position coordinates: the state is
    /// (s, v) = (s_1 … s_d, v_1 … v_d), positions first as in (61), and with T = `dt`,
    /// ϖ = `intensity`,
    ///
    /// ```text
    /// F = [ I  T·I ]        Q = ϖ [ T³/3·I  T²/2·I ]
    ///     [ 0   I  ]              [ T²/2·I   T·I   ]      (70)–(71)
    /// ```
    ///
    /// (d = 2 is the airport example's 4-state model; T = 15 s, ϖ = 0.004 there.)
    ///
    /// # Errors
    /// [`Error::InvalidParameter`] naming `position_dims` (0 or above 32, [`MAX_STATES`] / 2), `dt` (not finite
    /// and > 0) or `intensity` (not finite and ≥ 0).
    ///
    /// # Examples
    /// ```
    /// use fisst::filters::LinearGaussianTransition;
    /// let m = LinearGaussianTransition::nearly_constant_velocity(2, 15.0, 0.004)?;
    /// assert_eq!(m.f()[(0, 2)], 15.0);
    /// assert!((m.q()[(0, 0)] - 0.004 * 15f64.powi(3) / 3.0).abs() < 1e-12);
    /// # Ok::<(), fisst::Error>(())
    /// ```
    pub fn nearly_constant_velocity(position_dims: usize, dt: f64, intensity: f64) -> Result<Self> {
        if position_dims == 0 || 2 * position_dims > MAX_STATES {
            return Err(Error::parameter(
                "position_dims",
                position_dims as f64,
                "an integer in [1, 32]",
            ));
        }
        if !(dt.is_finite() && dt > 0.0) {
            return Err(Error::parameter("dt", dt, "finite and > 0"));
        }
        if !(intensity.is_finite() && intensity >= 0.0) {
            return Err(Error::parameter("intensity", intensity, "finite and >= 0"));
        }
        let d = position_dims;
        let n = 2 * d;
        let mut f = DMatrix::identity(n, n);
        let mut q = DMatrix::zeros(n, n);
        let (a, b, c) = (
            intensity * dt * dt * dt / 3.0,
            intensity * dt * dt / 2.0,
            intensity * dt,
        );
        for i in 0..d {
            f[(i, d + i)] = dt;
            q[(i, i)] = a;
            q[(i, d + i)] = b;
            q[(d + i, i)] = b;
            q[(d + i, d + i)] = c;
        }
        Self::new(f, q)
    }

    /// The state dimension n.
    pub fn dim(&self) -> usize {
        self.f.nrows()
    }

    /// F.
    pub fn f(&self) -> &DMatrix<f64> {
        &self.f
    }

    /// Q (exactly symmetric).
    pub fn q(&self) -> &DMatrix<f64> {
        &self.q
    }

    /// True when Q is positive definite (the transition has a density).
    pub fn has_density(&self) -> bool {
        self.chol.is_some()
    }

    /// A factor G with G Gᵀ = Q.
    pub(crate) fn factor(&self) -> &DMatrix<f64> {
        &self.factor
    }

    /// ln N(x; F x′, Q) with `fx` = F x′ precomputed; −∞ when Q is singular.
    pub(crate) fn ln_density(&self, x: &[f64], fx: &[f64]) -> f64 {
        let Some(l) = &self.chol else {
            return f64::NEG_INFINITY;
        };
        let n = x.len();
        let mut y: Vec<f64> = Vec::with_capacity(n);
        let mut m2 = 0.0;
        for i in 0..n {
            let mut s = x[i] - fx[i];
            for (j, yj) in y.iter().enumerate() {
                s -= l[(i, j)] * yj;
            }
            let yi = s / l[(i, i)];
            m2 += yi * yi;
            y.push(yi);
        }
        -0.5 * (n as f64 * crate::math::special::LN_2PI + self.ln_det + m2)
    }
}

/// At most [`MAX_STATES`] states.
fn check_states(n: usize) -> Result<()> {
    if n > MAX_STATES {
        return Err(Error::Unsupported {
            what: "transition.f".into(),
            reason: "at most 64 states are supported",
        });
    }
    Ok(())
}

/// The rows of a square matrix, concatenated; a row whose length is not the row count is
/// an error naming `what[i]`.
fn square_rows(rows: &[Vec<f64>], what: &str) -> Result<Vec<f64>> {
    let n = rows.len();
    if let Some(i) = rows.iter().position(|r| r.len() != n) {
        return Err(Error::dimension(
            alloc::format!("{what}[{i}]"),
            n,
            rows[i].len(),
        ));
    }
    Ok(rows.concat())
}

/// The shape of a matrix given as rows: (rows, length of the first row).
pub(crate) fn rows_shape(rows: &[Vec<f64>]) -> (usize, usize) {
    (rows.len(), rows.first().map_or(0, Vec::len))
}

fn check_finite(m: &DMatrix<f64>, what: &str) -> Result<()> {
    let n = m.nrows();
    if let Some(k) = m.iter().position(|v| !v.is_finite()) {
        return Err(Error::parameter(
            alloc::format!("{what}[{}][{}]", k % n, k / n),
            m[k],
            "finite",
        ));
    }
    Ok(())
}

/// ⌊√n⌋ for small n.
pub(crate) fn isqrt(n: usize) -> usize {
    let mut r = fns::sqrt(n as f64) as usize;
    while r * r > n {
        r -= 1;
    }
    while (r + 1) * (r + 1) <= n {
        r += 1;
    }
    r
}
