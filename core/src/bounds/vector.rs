//! The vector extensions of paper 002 (Section V, (63)–(72)): a state in R^l, the component
//! metric e_i with e_i(∅, x') = e0/√l and e_i(x, ∅) = e1/√l, so that Σ_i e_i² = e².
//!
//! Each component bound is the scalar one with e0² → e0²/l, e1² → e1²/l, σ_e² → σ_{e,i}² and
//! J'⁻¹ → [J'⁻¹]_ii: the threshold e0²/(e0² + (1 − P̄o)(e1² − l σ_{e,i}²)) of (72) is the scalar
//! r* of these scaled errors. (For model I with false alarms the switch also carries the
//! (1 − q) of (18), which Section V's sentence drops; [`component_bound`] keeps it, since it is
//! where the HPE and LPE bounds of (63) cross.)

use alloc::vec::Vec;
use nalgebra::DMatrix;

use crate::bounds::closed::{Assembled, Ingredients, NoClutterBound, assemble, corollary3};
use crate::error::{Error, Result};

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
        return Err(Error::dimension("inverseInformation", 1, 0));
    }
    if undetected_variance.len() != l {
        return Err(Error::dimension(
            "undetectedVariance",
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
                "inverseInformation" | "undetectedVariance" => {
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
pub fn gaussian_information_matrix(
    prior_cov: &DMatrix<f64>,
    gain: &DMatrix<f64>,
    noise_cov: &DMatrix<f64>,
) -> Result<(DMatrix<f64>, DMatrix<f64>)> {
    let l = prior_cov.nrows();
    if prior_cov.ncols() != l {
        return Err(Error::dimension("priorCovariance", l, prior_cov.ncols()));
    }
    if gain.ncols() != l {
        return Err(Error::dimension("gain", l, gain.ncols()));
    }
    let m = gain.nrows();
    if noise_cov.nrows() != m || noise_cov.ncols() != m {
        return Err(Error::dimension("noiseCovariance", m, noise_cov.nrows()));
    }
    for (what, a) in [
        ("priorCovariance", prior_cov),
        ("noiseCovariance", noise_cov),
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
    let p_inv = prior_cov
        .clone()
        .cholesky()
        .ok_or_else(|| Error::NotPositiveDefinite {
            what: "priorCovariance".into(),
        })?
        .inverse();
    let r_inv = noise_cov
        .clone()
        .cholesky()
        .ok_or_else(|| Error::NotPositiveDefinite {
            what: "noiseCovariance".into(),
        })?
        .inverse();
    let j = &p_inv + gain.transpose() * r_inv * gain;
    let inv = j
        .clone()
        .cholesky()
        .ok_or_else(|| Error::NotPositiveDefinite {
            what: "gain".into(),
        })?
        .inverse();
    Ok((j, inv))
}

fn check_finite_gain(v: f64) -> Result<()> {
    if v.is_finite() {
        Ok(())
    } else {
        Err(Error::parameter("gain", v, "finite"))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::bounds::closed::{corollary1, gaussian_no_clutter, no_clutter_ingredients};

    #[test]
    fn one_component_is_the_scalar_bound() {
        for &r in &[0.1, 0.5, 0.9] {
            let v = component_bounds_no_clutter(r, 0.4, &[25.0], &[100.0], 150.0, 200.0).unwrap();
            let s = gaussian_no_clutter(r, 0.4, 100.0, 25.0, 150.0, 200.0).unwrap();
            assert_eq!(v[0], s);
            let base = no_clutter_ingredients(r, 0.4, 25.0, 100.0, 150.0, 200.0);
            let c = component_bound(&base, 1, 25.0, 100.0).unwrap();
            assert!((c.bound - s.bound).abs() < 1e-12);
        }
        assert_eq!(
            component_corollary1(0.3, &[2.0], &[5.0])[0],
            corollary1(0.3, 2.0, 5.0)
        );
        let (j, inv) = gaussian_information_matrix(
            &DMatrix::from_element(1, 1, 4.0),
            &DMatrix::from_element(1, 1, 2.0),
            &DMatrix::from_element(1, 1, 1.0),
        )
        .unwrap();
        let s = crate::bounds::gaussian_fisher_information(4.0, 2.0, 1.0).unwrap();
        assert!((j[(0, 0)] - s.information).abs() < 1e-12);
        assert!((inv[(0, 0)] - s.posterior_variance).abs() < 1e-12);
    }

    #[test]
    fn independent_components_split_the_scalar_error() {
        // Two independent, identically observed components: the thresholds use l σ_{e,i}²,
        // and each HPE line is the scalar one with e0²/2, e1²/2.
        let v =
            component_bounds_no_clutter(0.8, 0.5, &[1.0, 1.0], &[4.0, 4.0], 10.0, 20.0).unwrap();
        let rs = 10.0 / (10.0 + 0.5 * (20.0 - 2.0 * 4.0));
        assert!((v[0].existence_threshold - rs).abs() < 1e-15);
        assert_eq!(v[0], v[1]);
        assert!(component_bounds_no_clutter(0.8, 0.5, &[1.0], &[4.0, 4.0], 1.0, 1.0).is_err());
    }
}
