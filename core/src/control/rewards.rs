//! Sensor-control rewards of paper `004`: the Rényi divergence (15)–(17), the Fisher
//! information gain (27)–(29) and PENT (30)–(34).
//!
//! ## Which average in (17)
//! The expected reward is E[D(u)] = ∫ D(u, Z) p(Z | u) δZ with p the predictive measurement
//! density (7). The paper draws Z^1 … Z^M *from* p (approximated by γ_1: pick a particle by its
//! weight, then a scan from its likelihood), and then writes Σ_j γ_1(Z^j | u) D(u, Z^j).
//! With draws from p, the Monte Carlo estimate of the expectation is the plain mean
//! (1/M) Σ_j D(u, Z^j): weighting each draw by γ_1(Z^j) once more estimates ∫ p² D (a
//! different functional, which moreover depends on the units of z, because γ_1 is a density,
//! and grows with M because the weights are not normalised). The γ_1 weights belong in the
//! sum only for Z^j on a grid or drawn from a density other than p (a quadrature or
//! importance-sampling form). So [`expected_renyi`] is the plain mean of
//! D(u, Z^j) = (1/(α−1)) ln(γ_α(Z^j) / γ_1(Z^j)^α) (15)–(16), and the test
//! `eq9_expected_renyi_is_the_direct_evaluation` checks it against an exact evaluation of
//! (9) on a discrete case (and shows the γ_1-weighted sum is not).
//!
//! α → 1: with L_i = ln g(Z | X_i) and posterior weights π_i = w_i e^{L_i}/γ_1, d/dα at α = 1
//! of ln γ_α − α ln γ_1 is Σ_i π_i L_i − ln γ_1 = Σ_i π_i ln(π_i / w_i), so D → KL(π ‖ w),
//! the Kullback–Leibler divergence of the posterior from the prior, which is used for
//! |α − 1| < 10⁻⁶.

use crate::math::fns::{exp, ln};
use crate::math::log_sum::ln_sum_exp;
use crate::math::special::LN_SQRT_2PI;
use crate::smc::State;

/// The Rényi divergence (15) of the particle posterior after one scan from the prior:
/// (1/(α−1)) ln( Σ_i w_i g_i^α / (Σ_i w_i g_i)^α ), from `ln_weights[i]` = ln w_i (normalised)
/// and `ln_g[i]` = ln g(Z | X_i). α → 1 gives KL(posterior ‖ prior) (see the module docs).
/// `None` when Σ_i w_i g_i = 0 (a scan the particles cannot explain).
pub fn renyi_divergence(ln_weights: &[f64], ln_g: &[f64], alpha: f64) -> Option<f64> {
    let ln_g1 = ln_sum_exp(ln_weights.iter().zip(ln_g).map(|(w, g)| w + g));
    if ln_g1 == f64::NEG_INFINITY || !ln_g1.is_finite() {
        return None;
    }
    if (alpha - 1.0).abs() < 1e-6 {
        let mut kl = 0.0;
        for (w, g) in ln_weights.iter().zip(ln_g) {
            let ln_post = w + g - ln_g1;
            if ln_post > f64::NEG_INFINITY {
                kl += exp(ln_post) * (g - ln_g1);
            }
        }
        return Some(kl.max(0.0));
    }
    let ln_ga = ln_sum_exp(ln_weights.iter().zip(ln_g).map(|(w, g)| w + alpha * g));
    Some(((ln_ga - alpha * ln_g1) / (alpha - 1.0)).max(0.0))
}

/// E[D(u)] of (17) as the plain Monte Carlo mean over scans drawn from the predictive density
/// (see the module docs for why the γ_1 factor is dropped): the mean of
/// [`renyi_divergence`] over `scans`, each the vector ln g(Z^j | X_i) over the particles.
/// Scans the particles cannot explain are skipped; 0 when none is left.
pub fn expected_renyi<'a>(
    ln_weights: &[f64],
    scans: impl IntoIterator<Item = &'a [f64]>,
    alpha: f64,
) -> f64 {
    let (mut sum, mut count) = (0.0, 0usize);
    for ln_g in scans {
        if let Some(d) = renyi_divergence(ln_weights, ln_g, alpha) {
            sum += d;
            count += 1;
        }
    }
    if count == 0 { 0.0 } else { sum / count as f64 }
}

/// The trace of the approximate Fisher information gain (28)–(29),
/// Σ_m H_mᵀ H_m / σ²(x̂_m) with H_m = (x̂_m − u)ᵀ/‖x̂_m − u‖ the Jacobian of the range: as
/// ‖H_m‖ = 1 the trace is Σ_m 1/σ²(x̂_m). As printed, (29) keeps the mean term only (σ
/// depends on x too, which would add (∂σ²/∂x)²/(2σ⁴)). `sigma(d)` is σ at range d.
pub fn fisher_reward(estimate: &[State], sensor: State, sigma: impl Fn(f64) -> f64) -> f64 {
    estimate
        .iter()
        .map(|x| {
            let d = libm::hypot(x[0] - sensor[0], x[1] - sensor[1]);
            let s = sigma(d);
            if d > 0.0 { 1.0 / (s * s) } else { 0.0 }
        })
        .sum()
}

/// PENT (30) without its constant C: p_D Σ_m (1 − λc(z_m) / (λc(z_m) + p_D 𝓘(z_m))), with the
/// ideal ranges z_m = ‖x̂_m − u‖ of the estimate and 𝓘 (31) by the particle intensity
/// (32)–(34), 𝓘(z) = Σ_i w_i Σ_{x ∈ X_i} g(z | x, u) (= (1/N) Σ_j g(z | x^j, u) after
/// resampling). `ln_g(z, x)` is ln g(z | x, u); `clutter(z)` is λ c(z).
pub fn pent_reward<'a>(
    estimate: &[State],
    sensor: State,
    particles: impl IntoIterator<Item = (f64, &'a [State])> + Clone,
    detection: f64,
    clutter: impl Fn(f64) -> f64,
    ln_g: impl Fn(f64, State) -> f64,
) -> f64 {
    let mut total = 0.0;
    for x_hat in estimate {
        let z = libm::hypot(x_hat[0] - sensor[0], x_hat[1] - sensor[1]);
        let mut intensity = 0.0;
        for (w, set) in particles.clone() {
            for &x in set {
                intensity += w * exp(ln_g(z, x));
            }
        }
        let lc = clutter(z);
        let denom = lc + detection * intensity;
        total += if denom > 0.0 { 1.0 - lc / denom } else { 0.0 };
    }
    detection * total
}

/// ln of the normal density N(z; mean, σ²).
#[inline]
pub(crate) fn ln_normal(z: f64, mean: f64, sigma: f64) -> f64 {
    let u = (z - mean) / sigma;
    -0.5 * u * u - ln(sigma) - LN_SQRT_2PI
}

#[cfg(test)]
#[allow(clippy::needless_range_loop)]
mod tests {
    use super::*;
    use crate::math::rng::{seeded, uniform};
    use alloc::vec::Vec;

    /// A discrete case: 3 "multi-object particles" (states), each with a pmf over 4 scans.
    const PRIOR: [f64; 3] = [0.5, 0.3, 0.2];
    const LIK: [[f64; 4]; 3] = [
        [0.7, 0.1, 0.1, 0.1],
        [0.1, 0.6, 0.2, 0.1],
        [0.25, 0.25, 0.25, 0.25],
    ];

    /// (9) evaluated directly: D(Z) = (1/(α−1)) ln Σ_X post(X|Z)^α prior(X)^{1−α}, and its
    /// expectation over p(Z) = Σ_X g(Z|X) prior(X), exactly.
    fn direct(alpha: f64) -> f64 {
        let mut e = 0.0;
        for z in 0..4 {
            let p: f64 = (0..3).map(|i| PRIOR[i] * LIK[i][z]).sum();
            let d = if (alpha - 1.0).abs() < 1e-12 {
                (0..3)
                    .map(|i| {
                        let post = PRIOR[i] * LIK[i][z] / p;
                        post * (post / PRIOR[i]).ln()
                    })
                    .sum::<f64>()
            } else {
                let s: f64 = (0..3)
                    .map(|i| {
                        let post = PRIOR[i] * LIK[i][z] / p;
                        post.powf(alpha) * PRIOR[i].powf(1.0 - alpha)
                    })
                    .sum();
                s.ln() / (alpha - 1.0)
            };
            e += p * d;
        }
        e
    }

    fn draw_scans(m: usize, seed: u64) -> Vec<usize> {
        let mut rng = seeded(seed);
        let pick = |u: f64, pmf: &[f64]| {
            let mut acc = 0.0;
            for (k, &q) in pmf.iter().enumerate() {
                acc += q;
                if u < acc {
                    return k;
                }
            }
            pmf.len() - 1
        };
        (0..m)
            .map(|_| {
                let i = pick(uniform(&mut rng), &PRIOR);
                pick(uniform(&mut rng), &LIK[i])
            })
            .collect()
    }

    #[test]
    fn eq9_expected_renyi_is_the_direct_evaluation() {
        let ln_w: Vec<f64> = PRIOR.iter().map(|w| w.ln()).collect();
        let columns: Vec<Vec<f64>> = (0..4)
            .map(|z| (0..3).map(|i| LIK[i][z].ln()).collect())
            .collect();
        let m = 200_000;
        let scans = draw_scans(m, 9);
        for alpha in [0.5, 0.9, 1.0, 2.0] {
            let exact = direct(alpha);
            let mc = expected_renyi(&ln_w, scans.iter().map(|&z| columns[z].as_slice()), alpha);
            // D(Z) ≤ 0.5 here, so the MC standard error is below 0.5/√m ≈ 1.1e-3: allow 5e-3.
            assert!((mc - exact).abs() < 5e-3, "α={alpha}: {mc} vs {exact}");
            // The printed form (17), Σ_j γ_1(Z^j) D(Z^j), is off by orders of magnitude.
            let weighted: f64 = scans
                .iter()
                .map(|&z| {
                    let g1: f64 = (0..3).map(|i| PRIOR[i] * LIK[i][z]).sum();
                    g1 * renyi_divergence(&ln_w, &columns[z], alpha).unwrap()
                })
                .sum();
            assert!(weighted > 100.0 * exact, "{weighted} vs {exact}");
        }
        // Exactly, with every scan at its probability: the per-scan formula (15) is (9).
        for alpha in [0.5, 2.0, 1.0] {
            let e: f64 = (0..4)
                .map(|z| {
                    let p: f64 = (0..3).map(|i| PRIOR[i] * LIK[i][z]).sum();
                    p * renyi_divergence(&ln_w, &columns[z], alpha).unwrap()
                })
                .sum();
            assert!(
                (e - direct(alpha)).abs() < 1e-14,
                "{e} vs {}",
                direct(alpha)
            );
        }
    }

    #[test]
    fn eq15_alpha_to_one_is_the_kl_divergence() {
        let ln_w: Vec<f64> = PRIOR.iter().map(|w| w.ln()).collect();
        let ln_g: Vec<f64> = (0..3).map(|i| LIK[i][0].ln()).collect();
        let kl = renyi_divergence(&ln_w, &ln_g, 1.0).unwrap();
        let p: f64 = (0..3).map(|i| PRIOR[i] * LIK[i][0]).sum();
        let direct: f64 = (0..3)
            .map(|i| {
                let post = PRIOR[i] * LIK[i][0] / p;
                post * (post / PRIOR[i]).ln()
            })
            .sum();
        assert!((kl - direct).abs() < 1e-15);
        for eps in [1e-3, 1e-4, -1e-4, 1e-5] {
            let d = renyi_divergence(&ln_w, &ln_g, 1.0 + eps).unwrap();
            assert!((d - kl).abs() < 2.0 * eps.abs(), "{eps}: {d} vs {kl}");
        }
        // A scan no particle explains.
        let none = [f64::NEG_INFINITY; 3];
        assert_eq!(renyi_divergence(&ln_w, &none, 0.5), None);
        assert_eq!(expected_renyi(&ln_w, [none.as_slice()], 0.5), 0.0);
    }

    /// The estimate of the Fisher and PENT examples: the two sources of Sec. 5.
    const EST: [State; 2] = [[300.0, 600.0], [750.0, 250.0]];

    #[test]
    fn eq29_fisher_reward_by_hand() {
        let f = fisher_reward(&EST, [300.0, 500.0], |d| 10.0 + 4e-5 * d * d);
        let s1: f64 = 10.0 + 4e-5 * 100.0 * 100.0;
        let d2 = libm::hypot(450.0, 250.0);
        let s2 = 10.0 + 4e-5 * d2 * d2;
        assert!((f - 1.0 / (s1 * s1) - 1.0 / (s2 * s2)).abs() < 1e-15);
    }

    #[test]
    fn eq30_pent_reward_by_hand() {
        // PENT: one particle holding the estimate, tiny noise: every term is close to 1.
        let set = EST.to_vec();
        let parts = [(1.0, set.as_slice())];
        let u = [0.0, 0.0];
        let p = pent_reward(
            &EST,
            u,
            parts.iter().copied(),
            0.95,
            |_| 0.8 / 1414.0,
            |z, x| ln_normal(z, libm::hypot(x[0] - u[0], x[1] - u[1]), 10.0),
        );
        // By hand: 𝓘(z_m) = Σ_x N(z_m; ‖x − u‖, 10²), the own term dominating.
        let lc = 0.8 / 1414.0;
        let z: Vec<f64> = EST.iter().map(|x| libm::hypot(x[0], x[1])).collect();
        let mut expected = 0.0;
        for &zm in &z {
            let i: f64 = z
                .iter()
                .map(|&h| {
                    (-0.5 * ((zm - h) / 10.0).powi(2)).exp()
                        / (10.0 * (2.0 * core::f64::consts::PI).sqrt())
                })
                .sum();
            expected += 1.0 - lc / (lc + 0.95 * i);
        }
        assert!(
            (p - 0.95 * expected).abs() < 1e-12,
            "{p} vs {}",
            0.95 * expected
        );
    }
}
