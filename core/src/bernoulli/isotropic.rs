//! Closed forms for isotropic Gaussians: q at the MMUC estimate and the threshold curve of
//! Fig. 3 of `000_…`.

use alloc::vec::Vec;

use crate::bernoulli::chi_square::chi_square_sf;
use crate::bernoulli::loss::{Costs, check_radius};
use crate::bernoulli::threshold::threshold;
use crate::error::{Error, Result};

/// The largest dimension d [`isotropic_miss_probability`] and [`isotropic_threshold_curve`]
/// accept: each q costs d/2 terms of [`chi_square_sf`], so a curve of a few hundred σ stays
/// within milliseconds up to it.
pub const MAX_ISOTROPIC_DIM: usize = 10_000;

/// q(a*) for an isotropic Gaussian N(μ, σ² I_d) at its MMUC estimate a* = μ:
///
/// ```text
/// q = P(‖x − μ‖ > r0) = P(χ²_d > (r0/σ)²)
/// ```
///
/// the integral in (11)–(13) of `000_…` for the Bernoulli-Gaussians of Section IV (d = 1
/// there: q = 2 Φ(−r0/σ)).
///
/// # Errors
/// [`Error::InvalidParameter`] naming `sigma` or `radius` unless finite and > 0;
/// [`Error::OutOfRange`] naming `dim` outside [1, [`MAX_ISOTROPIC_DIM`]].
pub fn isotropic_miss_probability(sigma: f64, radius: f64, dim: usize) -> Result<f64> {
    check_sigma("sigma", sigma)?;
    check_radius(radius)?;
    check_dim(dim)?;
    Ok(chi_square_sf(dim, sq(radius / sigma)))
}

/// The reporting threshold Γ, eq. (11) of `000_…`, of an isotropic Gaussian N(μ, σ² I_d)
/// for each σ in `sigmas`: the curves of Fig. 3 (d = 1). Each point costs d/2 terms of
/// [`chi_square_sf`], so a few hundred points take microseconds.
///
/// For costs whose comparison is reversed (see [`Threshold`](super::Threshold)) the values
/// are still eq. (11); Γ = ±∞ when its denominator vanishes.
///
/// # Errors
/// [`Error::OutOfRange`] naming `dim` outside [1, [`MAX_ISOTROPIC_DIM`]] (checked first);
/// [`Error::InvalidParameter`] naming `sigmas[i]` unless finite and > 0, or `radius` unless
/// finite and > 0.
pub fn isotropic_threshold_curve(
    sigmas: &[f64],
    radius: f64,
    costs: &Costs,
    dim: usize,
) -> Result<Vec<f64>> {
    check_dim(dim)?;
    check_radius(radius)?;
    sigmas
        .iter()
        .enumerate()
        .map(|(i, &s)| {
            if !(s.is_finite() && s > 0.0) {
                return Err(Error::parameter(
                    alloc::format!("sigmas[{i}]"),
                    s,
                    "finite and > 0",
                ));
            }
            Ok(threshold(costs, chi_square_sf(dim, sq(radius / s)))?.gamma)
        })
        .collect()
}

/// The options of [`isotropic_threshold_curve`] as one value: Fig. 3 of `000_…`.
#[derive(Clone, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct ThresholdCurveOptions {
    /// Standard deviations σ > 0 of the isotropic Gaussian N(a*, σ² I).
    #[cfg_attr(feature = "serde", serde(with = "crate::serde_shapes::numbers"))]
    pub sigmas: Vec<f64>,
    /// The radius r0 > 0 of the tolerance ball of the loss (7), in state units.
    pub radius: f64,
    /// The costs of the loss (7).
    pub costs: Costs,
    /// The dimension d, an integer in [1, 10,000] ([`MAX_ISOTROPIC_DIM`]); `None` (the
    /// default): 1, as in Fig. 3.
    #[cfg_attr(feature = "serde", serde(default))]
    pub dim: Option<usize>,
}

impl ThresholdCurveOptions {
    /// Γ for each σ: [`isotropic_threshold_curve`] with d = `dim` (default 1).
    ///
    /// # Errors
    /// As [`isotropic_threshold_curve`].
    pub fn curve(&self) -> Result<Vec<f64>> {
        isotropic_threshold_curve(
            &self.sigmas,
            self.radius,
            &self.costs,
            self.dim.unwrap_or(1),
        )
    }
}

fn sq(x: f64) -> f64 {
    x * x
}

fn check_sigma(what: &str, sigma: f64) -> Result<f64> {
    if sigma.is_finite() && sigma > 0.0 {
        Ok(sigma)
    } else {
        Err(Error::parameter(what, sigma, "finite and > 0"))
    }
}

fn check_dim(dim: usize) -> Result<usize> {
    if (1..=MAX_ISOTROPIC_DIM).contains(&dim) {
        Ok(dim)
    } else {
        Err(Error::range("dim", dim, 1, MAX_ISOTROPIC_DIM))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use alloc::string::ToString;

    #[test]
    fn isotropic_q_and_curve_validate() {
        assert!(
            (isotropic_miss_probability(1.0, 1.0, 1).unwrap() - 0.317_310_507_862_914_1).abs()
                < 1e-15
        );
        assert_eq!(
            isotropic_miss_probability(0.0, 1.0, 1).unwrap_err().field(),
            "sigma"
        );
        assert_eq!(
            isotropic_miss_probability(1.0, -1.0, 1)
                .unwrap_err()
                .field(),
            "radius"
        );
        assert_eq!(
            isotropic_miss_probability(1.0, 1.0, 0).unwrap_err().field(),
            "dim"
        );
        let e = isotropic_threshold_curve(&[1.0, f64::NAN], 1.0, &Costs::mpe(), 1).unwrap_err();
        assert_eq!(e.field(), "sigmas[1]");
    }

    #[test]
    fn curve_options_default_to_one_dimension() {
        let mut o = ThresholdCurveOptions {
            sigmas: alloc::vec![0.5, 2.0],
            radius: 1.0,
            costs: Costs::mpe(),
            dim: None,
        };
        let one = isotropic_threshold_curve(&o.sigmas, 1.0, &Costs::mpe(), 1).unwrap();
        assert_eq!(o.curve().unwrap(), one);
        o.dim = Some(3);
        assert_ne!(o.curve().unwrap(), one);
        o.dim = Some(0);
        assert_eq!(o.curve().unwrap_err().field(), "dim");
    }

    #[test]
    fn dim_lies_in_one_to_the_cap_and_is_checked_first() {
        let curve = |dim| isotropic_threshold_curve(&[1.0], 1.0, &Costs::mpe(), dim);
        assert!(curve(MAX_ISOTROPIC_DIM).is_ok());
        for dim in [0, MAX_ISOTROPIC_DIM + 1] {
            assert_eq!(
                curve(dim).unwrap_err().to_string(),
                alloc::format!("dim must be an integer in [1, 10000], got {dim}")
            );
        }
        // before the radius, as the JavaScript binding always reported it
        let e = isotropic_threshold_curve(&[1.0], -1.0, &Costs::mpe(), 0).unwrap_err();
        assert_eq!(e.field(), "dim");
        assert_eq!(
            isotropic_miss_probability(1.0, 1.0, MAX_ISOTROPIC_DIM + 1)
                .unwrap_err()
                .field(),
            "dim"
        );
    }
}
