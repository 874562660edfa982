//! The per-component bounds of paper 002, Section V, from given ingredients: (63)/(64) for one
//! component, Corollary 3 per component (72), Corollary 1 per component (70), and the Fisher
//! information matrix J_1 = P⁻¹ + HᵀR⁻¹H of a Gaussian prior and a linear-Gaussian sensor.

use alloc::vec::Vec;
use nalgebra::DMatrix;

use super::problem::check_finite_gain;
use crate::bounds::closed::{Assembled, Ingredients, NoClutterBound, assemble, corollary3};
use crate::error::{Error, Result};
use crate::gaussian::covariance;

/// (63)/(64) for component i: the scalar ingredients `base` (η, w, r, P̄o, e0², e1² of the
/// whole state) with component i's [J'⁻¹]_ii and σ_{e,i}², and the errors divided by l.
pub fn component_bound(
    base: &Ingredients,
    dims: usize,
    inverse_information: f64,
    undetected_variance: f64,
) -> Result<Assembled> {
    if dims == 0 {
        return Err(Error::parameter("dims", 0.0, "≥ 1"));
    }
    let l = dims as f64;
    Ok(assemble(&Ingredients {
        inverse_information,
        undetected_variance,
        false_alarm_error: base.false_alarm_error / l,
        miss_error: base.miss_error / l,
        ..*base
    }))
}

/// (72): Corollary 3 per component, from the diagonal of J_1⁻¹ and the variances σ_{e,i}² of
/// f_d'. Errors name `inverseInformation[i]` etc.
pub fn component_bounds_no_clutter(
    existence: f64,
    mean_detection: f64,
    inverse_information: &[f64],
    undetected_variance: &[f64],
    false_alarm_error: f64,
    miss_error: f64,
) -> Result<Vec<NoClutterBound>> {
    let l = inverse_information.len();
    if l == 0 {
        return Err(Error::dimension("inverse_information", 1, 0));
    }
    if undetected_variance.len() != l {
        return Err(Error::dimension(
            "undetected_variance",
            l,
            undetected_variance.len(),
        ));
    }
    let lf = l as f64;
    inverse_information
        .iter()
        .zip(undetected_variance)
        .enumerate()
        .map(|(i, (&j, &s))| {
            corollary3(
                existence,
                mean_detection,
                j,
                s,
                false_alarm_error / lf,
                miss_error / lf,
            )
            .map_err(|e| match e.field() {
                "inverse_information" | "undetected_variance" => {
                    e.map_field(|f| alloc::format!("{f}[{i}]"))
                }
                _ => e,
            })
        })
        .collect()
}

/// (70): P̄o [J_1⁻¹]_ii + (1 − P̄o) σ_{e,i}² per component.
pub fn component_corollary1(
    mean_detection: f64,
    inverse_information: &[f64],
    undetected_variance: &[f64],
) -> Vec<f64> {
    inverse_information
        .iter()
        .zip(undetected_variance)
        .map(|(&j, &s)| mean_detection * j + (1.0 - mean_detection) * s)
        .collect()
}

/// J_1 = P⁻¹ + Hᵀ R⁻¹ H, the Fisher information matrix of N(x; x0, P) N(z; Hx, R) (the vector
/// form of Example 1, corrected as NOTES.md says), and its inverse (the posterior covariance).
///
/// # Errors
/// [`Error::DimensionMismatch`] naming `prior_covariance`, `gain` or `noise_covariance` for
/// shapes that do not fit; [`Error::InvalidParameter`] for a non-finite entry;
/// [`Error::NotSymmetric`] or [`Error::NotDefinite`] naming `prior_covariance` or
/// `noise_covariance` (the checks of [`covariance`]); [`Error::NotDefinite`] naming `gain` if
/// J_1 itself fails its Cholesky factorisation.
pub fn gaussian_information_matrix(
    prior_cov: &DMatrix<f64>,
    gain: &DMatrix<f64>,
    noise_cov: &DMatrix<f64>,
) -> Result<(DMatrix<f64>, DMatrix<f64>)> {
    let l = prior_cov.nrows();
    if prior_cov.ncols() != l {
        return Err(Error::dimension("prior_covariance", l, prior_cov.ncols()));
    }
    if gain.ncols() != l {
        return Err(Error::dimension("gain", l, gain.ncols()));
    }
    let m = gain.nrows();
    if noise_cov.nrows() != m || noise_cov.ncols() != m {
        return Err(Error::dimension("noise_covariance", m, noise_cov.nrows()));
    }
    for (what, a) in [
        ("prior_covariance", prior_cov),
        ("noise_covariance", noise_cov),
    ] {
        for v in a.iter() {
            if !v.is_finite() {
                return Err(Error::parameter(what, *v, "finite"));
            }
        }
    }
    for v in gain.iter() {
        check_finite_gain(*v)?;
    }
    covariance::check_symmetric(prior_cov, &|| "prior_covariance".into())?;
    covariance::check_symmetric(noise_cov, &|| "noise_covariance".into())?;
    let p_inv = spd_inverse(prior_cov, "prior_covariance")?;
    let r_inv = spd_inverse(noise_cov, "noise_covariance")?;
    let j = &p_inv + gain.transpose() * r_inv * gain;
    let inv = spd_inverse(&j, "gain")?;
    Ok((j, inv))
}

/// A⁻¹ through the Cholesky factor; the error ([`Error::NotDefinite`]) names `what` and the
/// smallest eigenvalue when A is not positive definite.
fn spd_inverse(a: &DMatrix<f64>, what: &str) -> Result<DMatrix<f64>> {
    let factor = a
        .clone()
        .cholesky()
        .ok_or_else(|| covariance::not_positive_definite(a, what.into()))?;
    Ok(factor.inverse())
}
