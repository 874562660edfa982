//! Example 2 of paper 002 (32), Fig. 2 right: x, z ∈ [0, 1], f(x) = 2x(eˣ − 1),
//! g(z|x) = x e^{xz}/(eˣ − 1), ψ = 1, constant P_o; so p_1(x, z) = 2x² e^{xz} and
//! ∂²_x ln p_1 = −2/x².
//!
//! Two things the paper does not say (NOTES.md):
//! - (32) writes J'_1 = ∫_{Z'_0} (4/z)(e^z − 1) dz, which is −∫∫ p_1 ∂² ln p_1 without the
//!   1/w_1² of (20); [`Example2::paper_bound`] uses it ("as the paper computes it"),
//!   [`Example2::bound`] uses (20). They agree only when Z'_0 = [0, 1].
//! - p_1 does not vanish at x = 1, so the regularity condition of the information inequality
//!   fails: at r = 1, P_o = 1, 1/J_1 = 0.1897 while the posterior mean attains 0.0340
//!   ([`example2_regularity`]). Neither curve is a lower bound where the estimation term
//!   matters; label them so.

use alloc::vec::Vec;

use crate::bounds::closed::{Ingredients, Phase, assemble};
use crate::bounds::model::{Density, Detection, Observation};
use crate::bounds::theorem::{ModelI, TheoremOptions, integrate, theorem1};
use crate::error::Result;
use crate::math::fns;

/// f(x) = 2x(eˣ − 1) on [0, 1].
#[derive(Clone, Copy, Debug, Default)]
pub struct Example2Prior;

impl Density for Example2Prior {
    fn support(&self) -> (f64, f64) {
        (0.0, 1.0)
    }
    fn pdf(&self, x: f64) -> f64 {
        if (0.0..=1.0).contains(&x) {
            2.0 * x * libm::expm1(x)
        } else {
            0.0
        }
    }
    fn d2_ln_pdf(&self, x: f64) -> f64 {
        let e = libm::expm1(x);
        -1.0 / (x * x) - fns::exp(x) / (e * e)
    }
}

/// ψ(z) = 1 on [0, 1].
#[derive(Clone, Copy, Debug, Default)]
pub struct UnitUniform;

impl Density for UnitUniform {
    fn support(&self) -> (f64, f64) {
        (0.0, 1.0)
    }
    fn pdf(&self, z: f64) -> f64 {
        if (0.0..=1.0).contains(&z) { 1.0 } else { 0.0 }
    }
    fn d2_ln_pdf(&self, _: f64) -> f64 {
        0.0
    }
    fn mass(&self, a: f64, b: f64) -> f64 {
        (b.min(1.0) - a.max(0.0)).max(0.0)
    }
}

/// g(z|x) = x e^{xz}/(eˣ − 1) on [0, 1], with a constant P_o.
#[derive(Clone, Debug)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct Example2Observation {
    /// The detection probability P_o, a constant.
    pub detection: Detection,
}

impl Observation for Example2Observation {
    fn detection(&self, _x: f64) -> f64 {
        match self.detection {
            Detection::Constant(p) => p,
            Detection::Table { .. } => 0.0,
        }
    }
    fn d2_ln_detection(&self, _: f64) -> f64 {
        0.0
    }
    fn likelihood(&self, z: f64, x: f64) -> f64 {
        if !(0.0..=1.0).contains(&z) {
            return 0.0;
        }
        if x == 0.0 {
            return 1.0;
        }
        x * fns::exp(x * z) / libm::expm1(x)
    }
    fn d_ln_likelihood(&self, z: f64, x: f64) -> f64 {
        1.0 / x + z - fns::exp(x) / libm::expm1(x)
    }
    fn d2_ln_likelihood(&self, _z: f64, x: f64) -> f64 {
        let e = libm::expm1(x);
        -1.0 / (x * x) + fns::exp(x) / (e * e)
    }
    fn z_range(&self, _: f64, _: f64) -> (f64, f64) {
        (0.0, 1.0)
    }
    fn likelihood_mass(&self, a: f64, b: f64, x: f64) -> f64 {
        let (a, b) = (a.max(0.0), b.min(1.0));
        if b <= a {
            return 0.0;
        }
        if x == 0.0 {
            return b - a;
        }
        (fns::exp(x * b) - fns::exp(x * a)) / libm::expm1(x)
    }
}

/// One point of Fig. 2 (right) of Rezaeian & Vo, "Error bounds for joint detection and estimation
/// of a single object with random finite set observation" (paper 002): Example 2's bound at one (r,
/// P_o, q).
#[derive(Clone, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct Example2 {
    /// Theorem 1 with J'_1 as (20) (with 1/w_1²).
    pub bound: f64,
    /// Theorem 1 with J'_1 as (32) prints it (no 1/w_1²): the paper's curve.
    pub paper_bound: f64,
    /// The information J'_1 of (20): A / w_1².
    pub information: f64,
    /// The information J'_1 as (32) prints it: A = ∫_{Z'_0} (4/z)(e^z − 1) dz.
    pub paper_information: f64,
    /// The mass w_1 ∈ [0, 1] of p_1 on the MAP region Z'_0.
    pub w: f64,
    /// The probability η1 = q(1 − |Z'_0|) that a false observation occurs and is rejected.
    pub eta: f64,
    /// The variance σ_e² of an undetected target's state (the prior variance: P_o is constant).
    pub undetected_variance: f64,
    /// The squared error e_1² of a missed target used (the option, or e_0² + σ_e²).
    pub miss_error: f64,
    /// The MAP region Z'_0 of one-point observations, as `[low, high]` intervals of [0, 1].
    pub region: Vec<(f64, f64)>,
    /// The phase of the (20) bound: the rule on Z = ∅, HPE (declare {x*}) or LPE (declare ∅).
    pub phase: Phase,
}

/// The arguments of [`example2`]: Example 2 of Rezaeian & Vo, "Error bounds for joint detection and
/// estimation of a single object with random finite set observation" (paper 002) at one (r, P_o, q)
/// (Fig. 2 right).
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct Example2Options {
    /// The prior existence probability r ∈ [0, 1] (the figure: 0.6).
    pub existence: f64,
    /// The detection probability P_o ∈ [0, 1], a constant.
    pub detection_probability: f64,
    /// q, the false-alarm probability, in [0, 1] (the figure's abscissa).
    pub false_alarm_probability: f64,
    /// e_0² ≥ 0, the squared error of a false target: the square itself (the figure: 1.2).
    pub false_alarm_error: f64,
    /// e_1² ≥ 0, the squared error of a missed target: the square itself (default
    /// e_0² + σ_e², the figure's choice).
    pub miss_error: Option<f64>,
}

impl Example2Options {
    /// [`example2`] of these options.
    ///
    /// # Errors
    /// As [`example2`].
    pub fn example2(&self) -> Result<Example2> {
        example2(
            self.existence,
            self.detection_probability,
            self.false_alarm_probability,
            self.false_alarm_error,
            self.miss_error,
        )
    }
}

/// Fig. 2 right at (r, P_o, q) with e_0² and e_1² = e_0² + σ_e² (the paper's choice when
/// `miss_error` is None).
pub fn example2(
    existence: f64,
    detection_probability: f64,
    false_alarm_probability: f64,
    false_alarm_error: f64,
    miss_error: Option<f64>,
) -> Result<Example2> {
    crate::error::check_probability(|| "false_alarm_probability".into(), false_alarm_probability)?;
    let obs = Example2Observation {
        detection: Detection::constant(detection_probability)?,
    };
    let prior = Example2Prior;
    // σ_e² first (e1² depends on it in the paper's setting).
    let s = TheoremOptions::default();
    let sigma_e2 = {
        let (m1, _) = integrate(&mut |x| x * prior.pdf(x), 0.0, 1.0, 1e-12);
        integrate(&mut |x| (x - m1) * (x - m1) * prior.pdf(x), 0.0, 1.0, 1e-12).0
    };
    let e1 = miss_error.unwrap_or(false_alarm_error + sigma_e2);
    let m = ModelI {
        existence,
        prior: &prior,
        observation: &obs,
        false_alarm_probability,
        false_alarm_density: &UnitUniform,
        false_alarm_error,
        miss_error: e1,
    };
    let b = theorem1(&m, &s)?;
    let c = b.cardinalities.first().copied();
    let (w, s20) = c.map_or((0.0, 0.0), |c| (c.w, c.inverse_information));
    // A = ∫_{Z'_0} 4(e^z − 1)/z dz, the paper's J'_1 (32).
    let a: f64 = b
        .region
        .iter()
        .map(|&(lo, hi)| {
            integrate(
                &mut |z| {
                    if z == 0.0 {
                        4.0
                    } else {
                        4.0 * libm::expm1(z) / z
                    }
                },
                lo,
                hi,
                1e-12,
            )
            .0
        })
        .sum();
    let paper = assemble(&Ingredients {
        existence,
        mean_detection: b.mean_detection,
        undetected_variance: b.undetected_variance,
        inverse_information: if a > 0.0 { 1.0 / a } else { 0.0 },
        detected_mass: w,
        absent_empty: 1.0 - false_alarm_probability,
        absent_null: b.eta,
        undetected_empty: 1.0,
        undetected_null: 0.0,
        false_alarm_error,
        miss_error: e1,
    });
    Ok(Example2 {
        bound: b.assembled.bound,
        paper_bound: paper.bound,
        information: if s20 > 0.0 { 1.0 / s20 } else { f64::INFINITY },
        paper_information: a,
        w,
        eta: b.eta,
        undetected_variance: sigma_e2,
        miss_error: e1,
        region: b.region.clone(),
        phase: b.assembled.phase,
    })
}

/// The regularity failure of Example 2 at r = 1, P_o = 1.
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct Example2Regularity {
    /// The Fisher information J_1 = ∫₀¹ 4(e^z − 1)/z dz = 5.2716.
    pub information: f64,
    /// 1/J_1 = 0.1897: what the information inequality would claim as a bound.
    pub inverse_information: f64,
    /// E (x − E[x|z])² = 0.0340: the MSE the posterior mean attains, below 1/J_1.
    pub posterior_mean_mse: f64,
    /// The prior variance σ_f² = 0.0341 (the MSE of ignoring z).
    pub prior_variance: f64,
}

/// 1/J_1 against the posterior mean's MSE in Example 2 (NOTES.md), by nested quadrature.
pub fn example2_regularity() -> Example2Regularity {
    let p1 = |x: f64, z: f64| 2.0 * x * x * fns::exp(x * z);
    let (j, _) = integrate(
        &mut |z| {
            if z == 0.0 {
                4.0
            } else {
                4.0 * libm::expm1(z) / z
            }
        },
        0.0,
        1.0,
        1e-13,
    );
    let (mse, _) = integrate(
        &mut |z| {
            let m0 = integrate(&mut |x| p1(x, z), 0.0, 1.0, 1e-13).0;
            let m1 = integrate(&mut |x| x * p1(x, z), 0.0, 1.0, 1e-13).0;
            let m2 = integrate(&mut |x| x * x * p1(x, z), 0.0, 1.0, 1e-13).0;
            m2 - m1 * m1 / m0
        },
        0.0,
        1.0,
        1e-12,
    );
    let prior = Example2Prior;
    let (m1, _) = integrate(&mut |x| x * prior.pdf(x), 0.0, 1.0, 1e-13);
    let (v, _) = integrate(&mut |x| (x - m1) * (x - m1) * prior.pdf(x), 0.0, 1.0, 1e-13);
    Example2Regularity {
        information: j,
        inverse_information: 1.0 / j,
        posterior_mean_mse: mse,
        prior_variance: v,
    }
}
