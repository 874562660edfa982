//! The multi-object likelihood (20) of paper `004` (Ristic & Vo), exactly and in log space.
//!
//! With n objects x_1 … x_n, m measurements z_1 … z_m, detection probability p_D, Poisson
//! clutter of rate λ and density c(z), and f_c(Z) = e^{−λ} Π_j λ c(z_j), eq. (20) reads
//!
//! ```text
//! g(Z | X) = f_c(Z) (1 − p_D)^n Σ_θ Π_{i: θ(i) > 0} p_D g(z_θ(i) | x_i) / ((1 − p_D) λ c(z_θ(i)))
//! ```
//!
//! with θ over the associations {1 … n} → {0 … m} that are one-to-one on the detected
//! objects. Multiplying the factors out gives the form evaluated here, which has no division
//! (so it is also defined for p_D = 1, λ = 0 or c(z) = 0):
//!
//! ```text
//! g(Z | X) = e^{−λ} Σ_θ Π_{i undetected} (1 − p_D) · Π_{(i, j) ∈ θ} p_D g(z_j | x_i) · Π_{j unassigned} λ c(z_j),
//! ```
//!
//! a sum over the partial matchings of the bipartite graph objects × measurements. It is
//! computed by dynamic programming over the subsets of the smaller side (k = min(n, m)),
//! sweeping the larger side once: O(max(n, m) · k · 2^k) operations instead of the
//! Σ_d C(n, d) m!/(m − d)! associations. A zero likelihood is −∞, never NaN.
//!
//! The sweep runs in linear arithmetic, each row scaled by its largest factor, with a
//! rigorous bound on what gradual underflow can have lost; when that bound is not 10^{-13}
//! of the result it is redone with log-sum-exp arithmetic throughout, so the returned value
//! is exact to rounding in every case.

use alloc::vec;
use alloc::vec::Vec;

use super::matchings::ln_sum_matchings;
use crate::error::{Error, Result};
use crate::math::fns::{ln, ln_1p};
use crate::math::log_sum::ln_add;

/// The largest min(n, m) the dynamic programme accepts (2^k states).
pub const MAX_SMALLER_SIDE: usize = 20;

/// Reusable scratch memory of the dynamic programme (no allocation per call once warm).
#[derive(Clone, Debug, Default)]
pub struct LikelihoodWorkspace {
    dp: Vec<f64>,
    miss: Vec<f64>,
    pair: Vec<f64>,
    row_miss: Vec<f64>,
    col_miss: Vec<f64>,
    group: Vec<f64>,
}

impl LikelihoodWorkspace {
    /// An empty workspace.
    pub fn new() -> Self {
        Self::default()
    }
}

/// The multi-object likelihood model of (20): p_D and the clutter rate λ (the clutter density
/// c(z_j) comes with each scan).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct MultiObjectLikelihood {
    detection: f64,
    clutter_rate: f64,
    ln_detection: f64,
    ln_miss: f64,
    ln_rate: f64,
}

impl MultiObjectLikelihood {
    /// Validates p_D ∈ [0, 1] (`detection_probability`) and λ ≥ 0 finite (`clutter_rate`).
    pub fn new(detection: f64, clutter_rate: f64) -> Result<Self> {
        crate::error::check_probability(|| "detection_probability".into(), detection)?;
        if !(clutter_rate.is_finite() && clutter_rate >= 0.0) {
            return Err(Error::parameter(
                "clutter_rate",
                clutter_rate,
                "finite and ≥ 0",
            ));
        }
        Ok(Self {
            detection,
            clutter_rate,
            ln_detection: ln(detection),
            ln_miss: ln_1p(-detection),
            ln_rate: ln(clutter_rate),
        })
    }

    /// p_D.
    pub fn detection(&self) -> f64 {
        self.detection
    }

    /// λ.
    pub fn clutter_rate(&self) -> f64 {
        self.clutter_rate
    }

    /// ln g(Z | X) of (20) from logs: `ln_g[i·m + j]` = ln g(z_j | x_i) for the n objects and
    /// m measurements, `ln_clutter[j]` = ln c(z_j). Entries may be −∞ (zero), never NaN or
    /// +∞ (the caller's invariant; [`ln_likelihood`] checks it). min(n, m) ≤
    /// [`MAX_SMALLER_SIDE`].
    pub fn ln_likelihood_from_logs(
        &self,
        n: usize,
        ln_g: &[f64],
        ln_clutter: &[f64],
        ws: &mut LikelihoodWorkspace,
    ) -> f64 {
        let m = ln_clutter.len();
        debug_assert_eq!(ln_g.len(), n * m);
        let ln_rate = self.ln_rate;
        let LikelihoodWorkspace {
            dp,
            miss,
            pair,
            row_miss,
            col_miss,
            group,
        } = ws;
        miss.clear();
        miss.extend(ln_clutter.iter().map(|c| ln_rate + c));
        pair.clear();
        row_miss.clear();
        col_miss.clear();
        let body = if n > m {
            // Rows: objects (miss 1 − p_D); columns: measurements (miss λ c(z_j)).
            pair.extend(ln_g.iter().map(|g| self.ln_detection + g));
            row_miss.resize(n, self.ln_miss);
            ln_sum_matchings(n, m, pair, row_miss, miss, dp, group)
        } else {
            // Rows: measurements; columns: objects.
            for j in 0..m {
                pair.extend((0..n).map(|i| self.ln_detection + ln_g[i * m + j]));
            }
            col_miss.resize(n, self.ln_miss);
            ln_sum_matchings(m, n, pair, miss, col_miss, dp, group)
        };
        -self.clutter_rate + body
    }
}

/// ln g(Z | X) of (20) for one particle, validated: `likelihoods[i][j]` = g(z_j | x_i) ≥ 0
/// (n rows of m numbers, `[]` for n = 0), `clutter_density[j]` = c(z_j) ≥ 0 (length m),
/// p_D ∈ [0, 1], λ ≥ 0. A zero likelihood is −∞.
///
/// # Errors
/// Field-named errors (`likelihoods[i][j]`, `clutter_density[j]`, `detection_probability`,
/// `clutter_rate`), and [`Error::Unsupported`] when min(n, m) > [`MAX_SMALLER_SIDE`].
pub fn ln_likelihood<R: AsRef<[f64]>>(
    likelihoods: &[R],
    detection: f64,
    clutter_rate: f64,
    clutter_density: &[f64],
) -> Result<f64> {
    let model = MultiObjectLikelihood::new(detection, clutter_rate)?;
    let m = clutter_density.len();
    let n = likelihoods.len();
    let mut ln_g = Vec::with_capacity(n * m);
    for (i, row) in likelihoods.iter().enumerate() {
        let row = row.as_ref();
        if row.len() != m {
            return Err(Error::dimension(
                alloc::format!("likelihoods[{i}]"),
                m,
                row.len(),
            ));
        }
        for (j, &g) in row.iter().enumerate() {
            if !(g.is_finite() && g >= 0.0) {
                return Err(Error::parameter(
                    alloc::format!("likelihoods[{i}][{j}]"),
                    g,
                    "finite and ≥ 0",
                ));
            }
            ln_g.push(ln(g));
        }
    }
    let mut ln_c = Vec::with_capacity(m);
    for (j, &c) in clutter_density.iter().enumerate() {
        if !(c.is_finite() && c >= 0.0) {
            return Err(Error::parameter(
                alloc::format!("clutter_density[{j}]"),
                c,
                "finite and ≥ 0",
            ));
        }
        ln_c.push(ln(c));
    }
    if n.min(m) > MAX_SMALLER_SIDE {
        return Err(Error::Unsupported {
            what: "likelihoods".into(),
            reason: "min(objects, measurements) must be at most 20",
        });
    }
    Ok(model.ln_likelihood_from_logs(n, &ln_g, &ln_c, &mut LikelihoodWorkspace::new()))
}

/// The oracle: (20) as printed, by enumerating every association θ (one-to-one on the detected
/// objects) in log space. Exponential in n and m; for tests and the benchmark's comparison.
/// Inputs as in [`ln_likelihood`], unchecked; p_D < 1 and λ c(z) > 0 are needed by the printed
/// ratio form, so this evaluates the equivalent product form term by term instead.
pub fn brute_force_ln_likelihood<R: AsRef<[f64]>>(
    likelihoods: &[R],
    detection: f64,
    clutter_rate: f64,
    clutter_density: &[f64],
) -> f64 {
    let n = likelihoods.len();
    let m = clutter_density.len();
    let mut theta = vec![0usize; n];
    let mut used = vec![false; m];
    let mut total = f64::NEG_INFINITY;
    #[allow(clippy::too_many_arguments)]
    fn recurse<R: AsRef<[f64]>>(
        i: usize,
        g: &[R],
        pd: f64,
        rate: f64,
        c: &[f64],
        theta: &mut [usize],
        used: &mut [bool],
        total: &mut f64,
    ) {
        if i == g.len() {
            let mut t = -rate;
            for (k, &a) in theta.iter().enumerate() {
                t += if a == 0 {
                    ln(1.0 - pd)
                } else {
                    ln(pd) + ln(g[k].as_ref()[a - 1])
                };
            }
            for (j, &u) in used.iter().enumerate() {
                if !u {
                    t += ln(rate * c[j]);
                }
            }
            *total = ln_add(*total, t);
            return;
        }
        theta[i] = 0;
        recurse(i + 1, g, pd, rate, c, theta, used, total);
        for j in 0..c.len() {
            if !used[j] {
                used[j] = true;
                theta[i] = j + 1;
                recurse(i + 1, g, pd, rate, c, theta, used, total);
                used[j] = false;
            }
        }
    }
    recurse(
        0,
        likelihoods,
        detection,
        clutter_rate,
        clutter_density,
        &mut theta,
        &mut used,
        &mut total,
    );
    total
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::math::fns::exp;
    use crate::math::log_sum::ln_sum_exp;
    use crate::math::rng::{seeded, uniform};

    fn close(a: f64, b: f64, tol: f64) -> bool {
        (a == b) || (a - b).abs() <= tol * (1.0 + a.abs().max(b.abs()))
    }

    #[test]
    fn eq20_matches_enumeration_for_small_sets() {
        let mut rng = seeded(14);
        for n in 0..=5 {
            for m in 0..=7 {
                for trial in 0..4 {
                    let pd = [0.95, 1.0, 0.0, 0.5][trial];
                    let rate = [0.8, 0.0, 2.5, 1e-3][trial];
                    let g: Vec<Vec<f64>> = (0..n)
                        .map(|_| {
                            (0..m)
                                .map(|_| {
                                    let u = uniform(&mut rng);
                                    if u < 0.15 { 0.0 } else { exp(-40.0 * u) * 3.0 }
                                })
                                .collect()
                        })
                        .collect();
                    let c: Vec<f64> = (0..m).map(|_| 1e-3 + uniform(&mut rng)).collect();
                    let fast = ln_likelihood(&g, pd, rate, &c).unwrap();
                    let slow = brute_force_ln_likelihood(&g, pd, rate, &c);
                    assert!(!fast.is_nan());
                    assert!(
                        close(fast, slow, 1e-12),
                        "n={n} m={m} pd={pd}: {fast} vs {slow}"
                    );
                }
            }
        }
    }

    #[test]
    fn eq20_edge_cases() {
        let empty: [[f64; 0]; 0] = [];
        // n = 0, |Z| = 0: e^{−λ}.
        assert_eq!(ln_likelihood(&empty, 0.9, 0.8, &[]).unwrap(), -0.8);
        // n = 0: pure clutter.
        let v = ln_likelihood(&empty, 0.9, 0.8, &[0.5, 0.25]).unwrap();
        assert!(close(v, -0.8 + ln(0.8 * 0.5) + ln(0.8 * 0.25), 1e-15));
        // |Z| = 0: all missed.
        let v = ln_likelihood(&[[0.0; 0]; 3], 0.9, 0.8, &[]).unwrap();
        assert!(close(v, -0.8 + 3.0 * ln(0.1), 1e-14));
        // p_D = 1 with no measurement for an object: zero, i.e. −∞, not NaN.
        assert_eq!(
            ln_likelihood(&[[0.0; 0]; 2], 1.0, 0.8, &[]).unwrap(),
            f64::NEG_INFINITY
        );
        // p_D = 1, λ = 0, one object per measurement: the permanent.
        let v = ln_likelihood(&[[1.0, 2.0], [3.0, 4.0]], 1.0, 0.0, &[1.0, 1.0]).unwrap();
        assert!(close(v, ln(1.0 * 4.0 + 2.0 * 3.0), 1e-15));
        // λ = 0 and more measurements than objects: impossible.
        assert_eq!(
            ln_likelihood(&[[1.0, 2.0]], 0.9, 0.0, &[1.0, 1.0]).unwrap(),
            f64::NEG_INFINITY
        );
        // Tiny likelihoods (below the double range after products) stay finite.
        let g = [[1e-200, 1e-250], [1e-300, 1e-220]];
        let v = ln_likelihood(&g, 1.0, 0.0, &[1.0, 1.0]).unwrap();
        let exact = ln_add(ln(1e-200) + ln(1e-220), ln(1e-250) + ln(1e-300));
        assert!(close(v, exact, 1e-13), "{v} vs {exact}");
    }

    #[test]
    fn eq20_extreme_logs_take_the_log_path() {
        let model = MultiObjectLikelihood::new(0.95, 0.8).unwrap();
        let mut ws = LikelihoodWorkspace::new();
        // ln g far below the double range: the linear sweep underflows, the log one does not.
        let ln_g = [-2000.0, -5000.0, -4000.0, -2500.0];
        let ln_c = [-7.0, -7.0];
        let v = model.ln_likelihood_from_logs(2, &ln_g, &ln_c, &mut ws);
        let g: Vec<f64> = ln_g.to_vec();
        // Oracle in logs: enumerate the 7 associations by hand.
        let (lp, lq, lr) = (ln(0.95), ln(0.05), ln(0.8) - 7.0);
        let terms = [
            2.0 * lq + 2.0 * lr,
            lp + g[0] + lq + lr,
            lp + g[1] + lq + lr,
            lp + g[2] + lq + lr,
            lp + g[3] + lq + lr,
            2.0 * lp + g[0] + g[3],
            2.0 * lp + g[1] + g[2],
        ];
        let exact = -0.8 + ln_sum_exp(terms);
        assert!(close(v, exact, 1e-13));
        let ln_g = [-2000.0, -5000.0];
        let v = MultiObjectLikelihood::new(1.0, 0.0)
            .unwrap()
            .ln_likelihood_from_logs(1, &ln_g, &[0.0, 0.0], &mut ws);
        assert_eq!(v, f64::NEG_INFINITY);
        let v = MultiObjectLikelihood::new(1.0, 0.0)
            .unwrap()
            .ln_likelihood_from_logs(2, &[-3000.0, -1e4, -1e4, -3000.0], &[0.0, 0.0], &mut ws);
        assert!(close(v, -6000.0, 1e-13), "{v}");
    }

    #[test]
    fn eq20_bad_input_names_the_field() {
        let e = ln_likelihood(&[[0.5, -1.0]], 0.9, 0.8, &[1.0, 1.0]).unwrap_err();
        assert_eq!(e.field(), "likelihoods[0][1]");
        let e = ln_likelihood(&[[0.5]], 0.9, 0.8, &[1.0, 1.0]).unwrap_err();
        assert_eq!(e.field(), "likelihoods[0]");
        let e = ln_likelihood(&[[0.5]], 1.5, 0.8, &[1.0]).unwrap_err();
        assert_eq!(e.field(), "detection_probability");
        let e = ln_likelihood(&[[0.5]], 0.5, f64::NAN, &[1.0]).unwrap_err();
        assert_eq!(e.field(), "clutter_rate");
        let e = ln_likelihood(&[[0.5]], 0.5, 1.0, &[f64::INFINITY]).unwrap_err();
        assert_eq!(e.field(), "clutter_density[0]");
    }
}
