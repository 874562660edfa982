//! The reference evaluation of the expected Rényi reward (17) of paper `004` (Ristic & Vo):
//! slow and plain, for the tests of the batched kernel [`super::renyi_kernel`], in the manner
//! of RustFFT's `Dft` (the naive transform its fast algorithms are checked against).

use alloc::vec::Vec;

use super::case_study::ControlOptions;
use super::renyi_kernel::{FutureScans, ObjectRanges};
use super::rewards::expected_renyi;
use crate::math::fns::ln;
use crate::smc::{LikelihoodWorkspace, MultiObjectLikelihood, MultiObjectParticles, State};

/// E[D(u)] (17) the obvious way: for each ideal future scan Z^j, ln g(Z^j | X_i) of (20) for
/// every particle by [`super::sensor::RangeSensor::ln_likelihood`] (the filter's own update,
/// exact in log space), then [`expected_renyi`]: the plain mean of the divergences (15).
/// O(M · N) likelihoods and no shortcut; the batched kernel must agree with it to rounding.
pub(super) struct RenyiReference<'a> {
    cfg: &'a ControlOptions,
    model: &'a MultiObjectLikelihood,
    particles: &'a MultiObjectParticles,
}

impl<'a> RenyiReference<'a> {
    /// The reference for the particles `particles` of a run of `cfg` with the model `model`.
    pub(super) fn new(
        cfg: &'a ControlOptions,
        model: &'a MultiObjectLikelihood,
        particles: &'a MultiObjectParticles,
    ) -> Self {
        Self {
            cfg,
            model,
            particles,
        }
    }

    /// E[D(u)] (17) of the action at `u` over `scans`.
    pub(super) fn reward(&self, u: State, scans: &FutureScans) -> f64 {
        let (sensor, p) = (self.cfg.sensor, self.particles);
        let objects = ObjectRanges::new(&sensor, p, u);
        let ln_w: Vec<f64> = p.weights.iter().map(|&w| ln(w)).collect();
        let (mut ws, mut buf, mut z) = (LikelihoodWorkspace::new(), Vec::new(), Vec::new());
        let columns: Vec<Vec<f64>> = (0..scans.len())
            .map(|j| {
                scans.scan_into(j, &objects, &mut z);
                p.sets
                    .iter()
                    .map(|set| sensor.ln_likelihood(self.model, set, &z, u, &mut ws, &mut buf))
                    .collect()
            })
            .collect();
        expected_renyi(&ln_w, columns.iter().map(|c| c.as_slice()), self.cfg.alpha)
    }
}
