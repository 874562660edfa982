//! The range-only sensor of paper `004` (Ristic & Vo), Sec. 5.1: the measurement model (19)
//! with the single-object likelihood (21), p_D, Poisson clutter uniform on [0, R_max], and the
//! multi-object likelihood (20) of one particle seen from the sensor.

use alloc::vec::Vec;

use rand::Rng;

use super::rewards::ln_normal;
use crate::gaussian::normal;
use crate::math::fns::ln;
use crate::math::rng::{poisson, uniform};
use crate::smc::{LikelihoodWorkspace, MultiObjectLikelihood, State};

/// The range sensor of (19) and (21): z = ‖x − u‖ + v, v ~ N(0, σ²(x)), σ = σ₀ + s‖x − u‖²,
/// detection p_D, Poisson clutter of rate λ uniform on [0, R_max].
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(
    feature = "serde",
    derive(serde::Serialize, serde::Deserialize),
    serde(default)
)]
pub struct RangeSensor {
    /// The detection probability p_D ∈ [0, 1] of each object (0.95).
    pub detection: f64,
    /// The clutter rate λ ≥ 0: the mean number of clutter ranges per scan (0.8).
    pub clutter_rate: f64,
    /// The largest range R_max, in m; clutter is uniform on [0, R_max] (√2·1000 m).
    pub max_range: f64,
    /// The range noise's standard deviation σ₀ at zero range, in m (10 m).
    pub sigma0: f64,
    /// The growth s of the range noise's standard deviation with the squared range, in m⁻¹
    /// (4·10⁻⁵ m⁻¹).
    pub sigma_slope: f64,
}

impl Default for RangeSensor {
    fn default() -> Self {
        Self {
            detection: 0.95,
            clutter_rate: 0.8,
            max_range: core::f64::consts::SQRT_2 * 1000.0,
            sigma0: 10.0,
            sigma_slope: 4e-5,
        }
    }
}

impl RangeSensor {
    /// σ at range d.
    #[inline]
    pub fn sigma(&self, d: f64) -> f64 {
        self.sigma0 + self.sigma_slope * d * d
    }

    /// ln c(z) (uniform on [0, R_max]; −∞ outside).
    #[inline]
    pub fn ln_clutter_density(&self, z: f64) -> f64 {
        if (0.0..=self.max_range).contains(&z) {
            -ln(self.max_range)
        } else {
            f64::NEG_INFINITY
        }
    }

    /// ln g(z | x, u) of (21).
    #[inline]
    pub fn ln_g(&self, z: f64, x: State, u: State) -> f64 {
        let d = libm::hypot(x[0] - u[0], x[1] - u[1]);
        ln_normal(z, d, self.sigma(d))
    }

    /// One scan from `u` of the objects `truth`: each detected with p_D, plus Poisson clutter.
    pub fn scan<R: Rng + ?Sized>(&self, truth: &[State], u: State, rng: &mut R) -> Vec<f64> {
        let mut z = Vec::new();
        for x in truth {
            if uniform(rng) < self.detection {
                let d = libm::hypot(x[0] - u[0], x[1] - u[1]);
                z.push(d + self.sigma(d) * normal::sample(rng));
            }
        }
        // Poisson count by inversion (λ is small).
        for _ in 0..poisson(rng, self.clutter_rate, 10_000) {
            z.push(self.max_range * uniform(rng));
        }
        z
    }

    /// ln g(Z | X, u) of (20) for the particle `set`.
    pub fn ln_likelihood(
        &self,
        model: &MultiObjectLikelihood,
        set: &[State],
        z: &[f64],
        u: State,
        ws: &mut LikelihoodWorkspace,
        buf: &mut Vec<f64>,
    ) -> f64 {
        let ln_c: Vec<f64> = z.iter().map(|&z| self.ln_clutter_density(z)).collect();
        buf.clear();
        for &x in set {
            buf.extend(z.iter().map(|&zj| self.ln_g(zj, x, u)));
        }
        model.ln_likelihood_from_logs(set.len(), buf, &ln_c, ws)
    }
}
