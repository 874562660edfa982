//! One cycle of the SMC multi-object filter of paper `004` (Alg. 1, lines 9–10): the weights
//! from the multi-object likelihood (20), systematic resampling, and regularisation in the
//! state space (a Gaussian kernel, Musso et al.) and in cardinality (birth and death with
//! p_b = p_d = 0.025, Sec. 5.2).

use alloc::vec;
use alloc::vec::Vec;

use nalgebra::{DMatrix, DVector};
use rand::Rng;

use super::particles::{Area, MultiObjectParticles, State};
use crate::gaussian::normal;
use crate::math::fns::{exp, ln, pow};
use crate::math::log_sum::ln_sum_exp;
use crate::math::rng::{index, uniform};

/// Regularisation settings (Sec. 5.2).
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(
    feature = "serde",
    derive(serde::Serialize, serde::Deserialize),
    serde(default)
)]
pub struct Regularisation {
    /// p_b: the probability that a particle with fewer than n_max objects gains one, drawn
    /// uniformly in the area (0.025).
    pub birth: f64,
    /// p_d: the probability that a particle with objects loses a random one (0.025).
    pub death: f64,
    /// A multiplier of Musso's optimal bandwidth h_opt = (4/(d+2))^{1/(d+4)} N^{−1/(d+4)}
    /// (1).
    pub bandwidth: f64,
    /// The kernel's standard deviation floor in each coordinate (units of the state; 1),
    /// and its scale when too few particles share a cardinality to estimate a covariance.
    pub floor: f64,
}

impl Default for Regularisation {
    fn default() -> Self {
        Self {
            birth: 0.025,
            death: 0.025,
            bandwidth: 1.0,
            floor: 1.0,
        }
    }
}

/// Multiplies each weight by e^{ln_g(X_i)} and normalises, in log space (line 9 of Alg. 1:
/// w̃_i = w_i g(Z | X_i)). Returns ln Σ_i w_i g(Z | X_i), the log evidence; when every
/// likelihood is zero the weights are left unchanged and −∞ is returned.
pub fn reweight(
    particles: &mut MultiObjectParticles,
    mut ln_g: impl FnMut(&[State]) -> f64,
) -> f64 {
    let ln_w: Vec<f64> = particles
        .sets
        .iter()
        .zip(&particles.weights)
        .map(|(s, &w)| ln(w) + ln_g(s))
        .collect();
    let total = ln_sum_exp(ln_w.iter().copied());
    if total == f64::NEG_INFINITY || total.is_nan() {
        return f64::NEG_INFINITY;
    }
    for (w, l) in particles.weights.iter_mut().zip(&ln_w) {
        *w = exp(l - total);
    }
    total
}

pub use crate::math::rng::systematic;

/// Resamples to the same N with [`systematic`]; the weights become 1/N.
pub fn resample<R: Rng + ?Sized>(particles: &mut MultiObjectParticles, rng: &mut R) {
    let n = particles.len();
    if n == 0 {
        return;
    }
    let idx = systematic(&particles.weights, n, rng);
    particles.sets = idx.iter().map(|&i| particles.sets[i].clone()).collect();
    particles.weights = vec![1.0 / n as f64; n];
}

/// Regularisation after resampling (Sec. 5.2). In the state space: for each cardinality n,
/// the particles with n objects are aligned (see [`MultiObjectParticles::align`]), the sample
/// covariance C of their 2n-vectors is computed, and each is jittered by h·L·ε with L Lᵀ =
/// C + floor²·I, ε standard normal and h = bandwidth · h_opt(d = 2n, N_n) (Musso, Oudjane &
/// LeGland 2001); moved states are clamped into the area. In cardinality: with probability
/// p_b a particle with n < n_max gains a state drawn uniformly in the area, otherwise with
/// probability p_d a particle with n > 0 loses a uniformly chosen state.
pub fn regularise<R: Rng + ?Sized>(
    particles: &mut MultiObjectParticles,
    area: &Area,
    settings: &Regularisation,
    rng: &mut R,
) {
    for n in 1..=particles.max_objects {
        particles.align(n);
        let members: Vec<usize> = (0..particles.len())
            .filter(|&i| particles.sets[i].len() == n)
            .collect();
        if members.is_empty() {
            continue;
        }
        let d = 2 * n;
        let count = members.len();
        let floor2 = settings.floor * settings.floor;
        let chol = if count > d + 1 {
            let mut mean = DVector::<f64>::zeros(d);
            for &i in &members {
                for (k, x) in particles.sets[i].iter().enumerate() {
                    mean[2 * k] += x[0];
                    mean[2 * k + 1] += x[1];
                }
            }
            mean /= count as f64;
            let mut cov = DMatrix::<f64>::zeros(d, d);
            let mut v = DVector::<f64>::zeros(d);
            for &i in &members {
                for (k, x) in particles.sets[i].iter().enumerate() {
                    v[2 * k] = x[0] - mean[2 * k];
                    v[2 * k + 1] = x[1] - mean[2 * k + 1];
                }
                cov.ger(1.0, &v, &v, 1.0);
            }
            cov /= (count - 1) as f64;
            for k in 0..d {
                cov[(k, k)] += floor2;
            }
            cov.cholesky().map(|c| c.l())
        } else {
            None
        };
        let l = chol.unwrap_or_else(|| DMatrix::<f64>::identity(d, d) * settings.floor);
        let df = d as f64;
        let h = settings.bandwidth
            * pow(4.0 / (df + 2.0), 1.0 / (df + 4.0))
            * pow(count as f64, -1.0 / (df + 4.0));
        let mut eps = DVector::<f64>::zeros(d);
        for &i in &members {
            for e in eps.iter_mut() {
                *e = normal::sample(rng);
            }
            let jitter = &l * &eps;
            for (k, x) in particles.sets[i].iter_mut().enumerate() {
                *x = area.clamp([x[0] + h * jitter[2 * k], x[1] + h * jitter[2 * k + 1]]);
            }
        }
    }
    let n_max = particles.max_objects;
    for set in &mut particles.sets {
        let u = uniform(rng);
        if u < settings.birth {
            if set.len() < n_max {
                set.push(area.sample(rng));
            }
        } else if u < settings.birth + settings.death && !set.is_empty() {
            let k = index(rng, set.len());
            set.remove(k);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::math::rng::seeded;

    #[test]
    fn alg1_systematic_resampling_keeps_expected_counts() {
        let mut rng = seeded(2);
        let w = [0.5, 0.25, 0.125, 0.125];
        let idx = systematic(&w, 8, &mut rng);
        let mut counts = [0; 4];
        for i in idx {
            counts[i] += 1;
        }
        // Systematic resampling gives floor or ceil of N w_i: exactly 4, 2, 1, 1 here.
        assert_eq!(counts, [4, 2, 1, 1]);
    }

    #[test]
    fn eq20_reweight_normalises_and_handles_zero_likelihoods() {
        let mut p = MultiObjectParticles {
            sets: vec![vec![], vec![[1.0, 1.0]]],
            weights: vec![0.5, 0.5],
            max_objects: 2,
        };
        let e = reweight(&mut p, |s| if s.is_empty() { -1000.0 } else { -1001.0 });
        assert!((p.weights[0] - 1.0 / (1.0 + exp(-1.0))).abs() < 1e-12);
        assert!((e - (ln(0.5) - 1000.0 + crate::math::fns::ln_1p(exp(-1.0)))).abs() < 1e-9);
        let e = reweight(&mut p, |_| f64::NEG_INFINITY);
        assert_eq!(e, f64::NEG_INFINITY);
        assert!(p.weights.iter().all(|w| w.is_finite()));
    }

    #[test]
    fn alg1_regularisation_changes_cardinality_at_the_stated_rates() {
        let mut rng = seeded(3);
        let area = Area {
            lo: [0.0, 0.0],
            hi: [1000.0, 1000.0],
        };
        let n = 20_000;
        let mut p = MultiObjectParticles {
            sets: vec![vec![[300.0, 600.0], [750.0, 250.0]]; n],
            weights: vec![1.0 / n as f64; n],
            max_objects: 4,
        };
        regularise(&mut p, &area, &Regularisation::default(), &mut rng);
        let pmf = p.cardinality_pmf();
        // 500 expected in each of 1 and 3, sd about 22: allow 5 sd.
        assert!((pmf[1] * n as f64 - 500.0).abs() < 110.0, "{pmf:?}");
        assert!((pmf[3] * n as f64 - 500.0).abs() < 110.0, "{pmf:?}");
        for s in &p.sets {
            for x in s {
                assert!(area.contains(*x));
            }
        }
    }
}
