//! The vector problem of paper 002, Section V: the Gaussian prior of a state in R^l, the
//! linear-Gaussian sensor, the false observations of models I (13) and II (22), and the
//! checks of their entries.

use alloc::vec::Vec;
use nalgebra::DMatrix;

use crate::bounds::MAX_DIMS;
use crate::bounds::model::Density;
use crate::error::{Error, Result};
use crate::gaussian::covariance;

/// `l` if a state dimension (the length of a prior's mean) lies in [1, [`MAX_DIMS`]], else an
/// [`Error::OutOfRange`] naming `mean.length`. [`GaussianPrior::new`] checks it first; a
/// binding that must know l before it reads the covariance can check it earlier.
pub fn check_state_dims(l: usize) -> Result<usize> {
    Error::check_range("mean.length", l, 1, MAX_DIMS)
}

/// `Ok` if a gain of `m` rows (the measurement dimension) has 1 to [`MAX_DIMS`] of them, else
/// an [`Error::Count`] naming `gain`. [`LinearGaussianSensor::new`] checks it before the
/// offset and the noise, whose sizes follow from m.
pub fn check_measurement_dims(m: usize) -> Result<()> {
    Error::check_count("gain", "rows", m, 1, MAX_DIMS)
}

/// The Gaussian prior f = N(x; x0, P) of a state in R^l (Section V).
#[derive(Clone, Debug, PartialEq)]
pub struct GaussianPrior {
    pub(crate) mean: Vec<f64>,
    pub(crate) cov: DMatrix<f64>,
}

impl GaussianPrior {
    /// N(`mean`, `cov`), `cov` the l × l covariance in row-major order (symmetric positive
    /// definite), 1 ≤ l ≤ [`MAX_DIMS`]. Errors name `mean.length` ([`check_state_dims`]),
    /// `mean[i]` or `cov`.
    pub fn new(mean: &[f64], cov: &[f64]) -> Result<Self> {
        let l = check_state_dims(mean.len())?;
        for (i, &v) in mean.iter().enumerate() {
            if !v.is_finite() {
                return Err(Error::parameter(alloc::format!("mean[{i}]"), v, "finite"));
            }
        }
        let cov = spd("cov", l, cov)?;
        Ok(GaussianPrior {
            mean: mean.to_vec(),
            cov,
        })
    }

    /// The state dimension l.
    pub fn dims(&self) -> usize {
        self.mean.len()
    }
}

/// A linear-Gaussian sensor with a constant detection probability: P_o(x) = P_o and
/// g(z|x) = N(z; H x + b, R), z in R^m.
#[derive(Clone, Debug, PartialEq)]
pub struct LinearGaussianSensor {
    pub(crate) detection: f64,
    pub(crate) gain: DMatrix<f64>,
    pub(crate) offset: Vec<f64>,
    pub(crate) noise: DMatrix<f64>,
}

impl LinearGaussianSensor {
    /// P_o = `detection`, H = `gain` (m × `dims`, row-major; m = `gain.len() / dims`),
    /// b = `offset` (length m), R = `noise_cov` (m × m, row-major, symmetric positive
    /// definite), 1 ≤ m ≤ [`MAX_DIMS`] ([`check_measurement_dims`]). Errors name
    /// `detection_probability`, `gain`, `offset` or `noise_cov`.
    pub fn new(
        detection: f64,
        gain: &[f64],
        dims: usize,
        offset: &[f64],
        noise_cov: &[f64],
    ) -> Result<Self> {
        crate::error::check_probability(|| "detection_probability".into(), detection)?;
        if dims == 0 || !gain.len().is_multiple_of(dims) {
            return Err(Error::dimension("gain", dims.max(1), gain.len()));
        }
        let m = gain.len() / dims;
        check_measurement_dims(m)?;
        for &v in gain {
            check_finite_gain(v)?;
        }
        if offset.len() != m {
            return Err(Error::dimension("offset", m, offset.len()));
        }
        for (i, &v) in offset.iter().enumerate() {
            if !v.is_finite() {
                return Err(Error::parameter(alloc::format!("offset[{i}]"), v, "finite"));
            }
        }
        let noise = spd("noise_cov", m, noise_cov)?;
        Ok(LinearGaussianSensor {
            detection,
            gain: DMatrix::from_row_slice(m, dims, gain),
            offset: offset.to_vec(),
            noise,
        })
    }

    /// The measurement dimension m.
    pub fn measurement_dims(&self) -> usize {
        self.gain.nrows()
    }
}

/// A symmetric positive definite n × n matrix from row-major entries: every entry finite,
/// then the checks of [`covariance`] (symmetric to a relative 1e-9, then positive definite).
fn spd(what: &'static str, n: usize, entries: &[f64]) -> Result<DMatrix<f64>> {
    if entries.len() != n * n {
        return Err(Error::dimension(what, n * n, entries.len()));
    }
    if let Some(&v) = entries.iter().find(|v| !v.is_finite()) {
        return Err(Error::parameter(what, v, "finite"));
    }
    let a = DMatrix::from_row_slice(n, n, entries);
    covariance::check_symmetric(&a, &|| what.into())?;
    if a.clone().cholesky().is_none() {
        return Err(covariance::not_positive_definite(&a, what.into()));
    }
    Ok(a)
}

/// The false observations of the vector bounds: model I's (q, ψ) or model II's (λ, c). Their
/// densities live on the measurement space, so they need m = 1 (a gain of one row) when
/// q > 0 or λ > 0.
#[derive(Clone, Copy)]
pub enum VectorMeasurement<'a> {
    /// Model I (13): a false observation with probability q and density ψ.
    I {
        /// The false-observation probability q ∈ [0, 1].
        false_alarm_probability: f64,
        /// The false-observation density ψ.
        false_alarm_density: &'a dyn Density,
    },
    /// Model II (22): Poisson clutter of rate λ and density c (v = λ c).
    II {
        /// The clutter rate λ ≥ 0: the mean number of clutter points.
        clutter_rate: f64,
        /// The density c = v/λ of one clutter point.
        clutter_density: &'a dyn Density,
    },
}

/// The vector problem of Section V: a Gaussian state in R^l, a linear-Gaussian sensor,
/// models I or II, and the component errors e0²/l, e1²/l.
#[derive(Clone, Copy)]
pub struct VectorModel<'a> {
    /// The prior existence probability r ∈ [0, 1]: the probability that the target exists.
    pub existence: f64,
    /// The Gaussian prior f = N(x0, P) of the target's state.
    pub prior: &'a GaussianPrior,
    /// The linear-Gaussian sensor: detection probability P_o, H, offset b, noise covariance R.
    pub sensor: &'a LinearGaussianSensor,
    /// Model I or II and its false observations.
    pub measurement: VectorMeasurement<'a>,
    /// The squared error e0² ≥ 0 of a false target (of the whole state; component i uses e0²/l).
    pub false_alarm_error: f64,
    /// The squared error e1² ≥ 0 of a missed target (of the whole state; component i uses e1²/l).
    pub miss_error: f64,
}

/// A gain entry must be finite; the error names `gain`.
pub(super) fn check_finite_gain(v: f64) -> Result<()> {
    if v.is_finite() {
        Ok(())
    } else {
        Err(Error::parameter("gain", v, "finite"))
    }
}
