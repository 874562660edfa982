//! The vector extensions of paper 002 (Section V, (63)–(72)): a state in R^l, the component
//! metric e_i with e_i(∅, x') = e0/√l and e_i(x, ∅) = e1/√l, so that Σ_i e_i² = e².
//!
//! Each component bound is the scalar one with e0² → e0²/l, e1² → e1²/l, σ_e² → σ_{e,i}² and
//! J'⁻¹ → [J'⁻¹]_ii: the threshold e0²/(e0² + (1 − P̄o)(e1² − l σ_{e,i}²)) of (72) is the scalar
//! r* of these scaled errors. (For model I with false alarms the switch also carries the
//! (1 − q) of (18), which Section V's sentence drops; [`component_bound`] keeps it, since it is
//! where the HPE and LPE bounds of (63) cross.)
//!
//! | file | holds |
//! |---|---|
//! | `problem.rs` | [`GaussianPrior`], [`LinearGaussianSensor`], [`VectorMeasurement`], [`VectorModel`] and their checks |
//! | `components.rs` | (63)/(64), (70), (72) per component from given ingredients; J_1 of the Gaussian case |
//! | `mod.rs` | [`vector_bound`]: which of the two forms below serves, and the results [`ComponentBound`], [`VectorBound`] |
//! | `rank_one.rs` | m = 1: the scalar Theorem 1 or 2 of s = hᵀx lifted by Sherman–Morrison |
//! | `closed_form.rs` | m > 1 (or h = 0) without false observations: J_1 = P⁻¹ + HᵀR⁻¹H (72) |
//! | `zone.rs` | the shared measurement-side ingredients and the assembly per component and for the whole state |

use alloc::vec::Vec;
use nalgebra::DMatrix;

use crate::bounds::closed::{Assembled, check_nonnegative};
use crate::bounds::theorem::{JdeBound, TheoremOptions, check_common};
use crate::error::{Error, Result};

mod closed_form;
mod components;
mod problem;
mod rank_one;
mod zone;

pub use components::{
    component_bound, component_bounds_no_clutter, component_corollary1, gaussian_information_matrix,
};
pub use problem::{
    GaussianPrior, LinearGaussianSensor, VectorMeasurement, VectorModel, check_measurement_dims,
    check_state_dims,
};
use zone::Zone;

/// The bound (63)/(64) on the MSE σ_i² of component i.
#[derive(Clone, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct ComponentBound {
    /// The bound, its phase (the component's own rule on Z = ∅), threshold (72) and terms.
    pub assembled: Assembled,
    /// [J'_1⁻¹]_ii (63) or Σ_n C_n [J'_{1+n}⁻¹]_ii (64).
    pub inverse_information: f64,
    /// x*_i, the mean of f_d' (the prior mean: P_o is constant).
    pub undetected_mean: f64,
    /// The prior variance σ_{e,i}² = P_ii of this coordinate.
    pub undetected_variance: f64,
    /// Error estimate of the bound (quadrature, one Monte Carlo standard error).
    pub error: f64,
}

/// The vector bounds: per component (63)/(64), and for the whole state.
#[derive(Clone, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct VectorBound {
    /// The bound on σ² = E e²(X, X̂) with the Euclidean metric (σ² = Σ_i σ_i²): the scalar
    /// assembly with S = tr(J'⁻¹) (or Σ C_n tr J'_{1+n}⁻¹) and σ_e² = tr P, one rule on Z = ∅
    /// for all components. It is ≥ Σ_i `components[i].bound` (each component may pick its own
    /// rule). `undetected_mean` is x*_1 (x* is in the components); `cardinalities` carry
    /// tr J'_n⁻¹; `region` is the MAP region of a one-point (scalar) measurement, empty when
    /// m > 1 (then there are no false observations and the region is all of R^m).
    pub total: JdeBound,
    /// One bound per component x_i.
    pub components: Vec<ComponentBound>,
    /// Σ_n C_n J'_{1+n}⁻¹ (J'_1⁻¹ for model I), the l × l matrix whose diagonal enters the
    /// estimation terms, row-major.
    pub inverse_information: Vec<f64>,
}

/// The vector extensions (63)–(65) of Theorems 1 and 2 for a Gaussian prior and a
/// linear-Gaussian sensor with constant P_o.
///
/// **How.** With m = 1 (z = hᵀx + b + v), everything on the measurement side (the MAP regions
/// Z'_0, Z_0^n, w_n, η, μ, C_n) depends on x only through s = hᵀx ~ N(hᵀx0, σ_s² = hᵀPh), so
/// it is the scalar [`theorem1`](super::theorem1) / [`theorem2`](super::theorem2) of the
/// problem in s. Given s, x is Gaussian with the constant covariance P − (Ph)(Ph)ᵀ/σ_s² and
/// p_n(x, Z) = N(x; x0 + a (s − hᵀx0), P − a aᵀσ_s²) p_n^s(s, Z), a = Ph/σ_s², so the Fisher
/// matrix (65) of the detected case is
///
/// ```text
/// J'_n = (1/w_n) (P⁻¹ + κ̄_n h hᵀ),   κ̄_n = w_n J'^s_n − 1/σ_s²,
/// [J'_n⁻¹]_ij = w_n (P_ij − a_i a_j σ_s²) + a_i a_j J'^s_n⁻¹
/// ```
///
/// (Sherman–Morrison; J'^s_n the scalar (20)/(25) of the problem in s). The per-component
/// bound is then [`component_bound`] with these [J'⁻¹]_ii, σ_{e,i}² = P_ii and e0²/l, e1²/l.
/// Each quadrature / Monte Carlo error propagates linearly. With m > 1 (any H, R) the
/// false-observation densities would live on R^m: only q = 0 / λ = 0 is served, where the
/// MAP region is all of R^m, w = 1 and J'_1 = J_1 = P⁻¹ + HᵀR⁻¹H ((72) and its matrix form);
/// the same closed form is used for m = 1 with h = 0.
pub fn vector_bound(m: &VectorModel<'_>, s: &TheoremOptions) -> Result<VectorBound> {
    let clutter_free = check(m, s)?;
    if let Some(proj) = rank_one::projection(m) {
        return rank_one::bound(m, s, &proj);
    }
    if !clutter_free {
        return Err(Error::Unsupported {
            what: "observation.gain".into(),
            reason: "false alarms or clutter need a scalar measurement (a gain of one row, not all zero); with m > 1 only q = 0 or λ = 0 is served",
        });
    }
    closed_form::bound(m)
}

/// The checks of [`vector_bound`]'s inputs; returns whether there are no false observations
/// (q = 0 or λ = 0).
fn check(m: &VectorModel<'_>, s: &TheoremOptions) -> Result<bool> {
    let (prior, sensor) = (m.prior, m.sensor);
    let l = prior.dims();
    if sensor.gain.ncols() != l {
        return Err(Error::dimension("observation.gain", l, sensor.gain.ncols()));
    }
    check_common(m.existence, m.false_alarm_error, m.miss_error, s)?;
    Ok(match m.measurement {
        VectorMeasurement::I {
            false_alarm_probability: q,
            ..
        } => {
            crate::error::check_probability(|| "false_alarm.probability".into(), q)?;
            q == 0.0
        }
        VectorMeasurement::II {
            clutter_rate: lambda,
            ..
        } => check_nonnegative("clutter.rate", lambda)? == 0.0,
    })
}

/// The per-component bounds (63)/(64) from the diagonal of S = `big_s` and of P, with the
/// error `error(i, P_ii)` of each.
fn components(
    zone: &Zone,
    m: &VectorModel<'_>,
    big_s: &DMatrix<f64>,
    error: impl Fn(usize, f64) -> f64,
) -> Vec<ComponentBound> {
    let p = &m.prior.cov;
    (0..m.prior.dims())
        .map(|i| {
            let (s_i, var_i) = (big_s[(i, i)], p[(i, i)]);
            ComponentBound {
                assembled: zone.component(s_i, var_i),
                inverse_information: s_i,
                undetected_mean: m.prior.mean[i],
                undetected_variance: var_i,
                error: error(i, var_i),
            }
        })
        .collect()
}

/// [`check_result`] for the components and the matrix too: a NaN anywhere is an error.
fn check_vector(v: VectorBound) -> Result<VectorBound> {
    let nan = v.components.iter().any(|c| {
        let a = &c.assembled;
        [a.bound, a.hpe, a.lpe, c.error, c.inverse_information]
            .iter()
            .any(|x| x.is_nan())
    }) || v.inverse_information.iter().any(|x| x.is_nan());
    if nan {
        return Err(Error::Unsupported {
            what: "prior".into(),
            reason: "the integrals did not converge at this scale (NaN); rescale the problem",
        });
    }
    Ok(v)
}

fn row_major(a: &DMatrix<f64>) -> Vec<f64> {
    let mut v = Vec::with_capacity(a.nrows() * a.ncols());
    for i in 0..a.nrows() {
        for j in 0..a.ncols() {
            v.push(a[(i, j)]);
        }
    }
    v
}

#[cfg(test)]
mod tests;
