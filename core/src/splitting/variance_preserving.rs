//! The variance-preserving split library of the authors' Python implementation (`pyest`,
//! `optimize_gauss_split_variance_preserving`): eq. (13) of `001_…` minimised over
//! symmetric, equally spaced, homoscedastic splits whose variance is exactly one.

use alloc::vec;
use alloc::vec::Vec;

use super::objective::objective;
use crate::math::fns;
use crate::math::optimise::nelder_mead;

/// The weights, means and σ̃ of a variance-preserving split from its unconstrained
/// parameters θ = (t, u_1 … u_{h−1}):
///
/// ```text
/// class weights  ∝ e^{u_c} (u_0 = 0), normalised with multiplicities (1 centre, 2 pair)
/// f = Σ_j w̃_j m̃_j² = 1 / (1 + e^{−t})          ∈ (0, 1)
/// m̃_j = δ (j − (R − 1)/2),  δ = √(f / Σ_j w̃_j (j − (R − 1)/2)²)
/// σ̃ = √(1 − f)                                   (so σ̃² + Σ_j w̃_j m̃_j² = 1)
/// ```
pub(crate) fn unpack(r: usize, theta: &[f64]) -> (Vec<f64>, Vec<f64>, f64) {
    let h = r.div_ceil(2);
    let odd = r % 2 == 1;
    let mult = |c: usize| if odd && c == 0 { 1.0 } else { 2.0 };
    let logits: Vec<f64> = (0..h)
        .map(|c| if c == 0 { 0.0 } else { theta[c] })
        .collect();
    let top = logits.iter().copied().fold(f64::NEG_INFINITY, f64::max);
    let raw: Vec<f64> = logits.iter().map(|l| fns::exp(l - top)).collect();
    let z: f64 = raw.iter().enumerate().map(|(c, x)| mult(c) * x).sum();
    let class_w: Vec<f64> = raw.iter().map(|x| x / z).collect();
    let centre = (r - 1) as f64 / 2.0;
    let class_of = |j: usize| -> usize {
        if odd {
            j.abs_diff((r - 1) / 2)
        } else {
            let upper = r / 2;
            if j >= upper { j - upper } else { upper - 1 - j }
        }
    };
    let weights: Vec<f64> = (0..r).map(|j| class_w[class_of(j)]).collect();
    let f = 1.0 / (1.0 + fns::exp(-theta[0]));
    let spread: f64 = (0..r)
        .map(|j| {
            let o = j as f64 - centre;
            weights[j] * o * o
        })
        .sum();
    let delta = fns::sqrt(f / spread);
    let means = (0..r).map(|j| delta * (j as f64 - centre)).collect();
    (weights, means, fns::sqrt(1.0 - f))
}

/// J of eq. (13) at θ.
fn cost(r: usize, lambda: f64, theta: &[f64]) -> f64 {
    let (w, m, s) = unpack(r, theta);
    let j = objective(&w, &m, s, lambda);
    if j.is_finite() { j } else { f64::INFINITY }
}

/// The minimiser θ of J over variance-preserving R-component splits: Nelder–Mead from
/// deterministic starts (f ∈ {0.3, 0.5, 0.7, 0.85}, equal and normal-shaped weights), each
/// end point restarted until it stops improving; the best end point wins.
pub(crate) fn optimise(r: usize, lambda: f64) -> (Vec<f64>, Vec<f64>, f64) {
    let h = r.div_ceil(2);
    let f = |theta: &[f64]| cost(r, lambda, theta);
    let mut best: Option<(f64, Vec<f64>)> = None;
    for &frac in &[0.3f64, 0.5, 0.7, 0.85] {
        for shape in 0..2 {
            let mut x0 = vec![fns::ln(frac / (1.0 - frac))];
            for c in 1..h {
                // shape 0: equal weights; shape 1: weights falling like a normal density.
                x0.push(if shape == 0 {
                    0.0
                } else {
                    -0.5 * (c * c) as f64 * 4.0 / (r * r) as f64 * 4.0
                });
            }
            let start = nelder_mead(&f, &x0, 0.5, 4000);
            let (mut v, mut x) = (start.value, start.x);
            for _ in 0..6 {
                let next = nelder_mead(&f, &x, 0.05, 4000);
                let (v2, x2) = (next.value, next.x);
                if v2 < v {
                    let gain = v - v2;
                    v = v2;
                    x = x2;
                    if gain < 1e-18 {
                        break;
                    }
                } else {
                    break;
                }
            }
            if best.as_ref().is_none_or(|(bv, _)| v < *bv) {
                best = Some((v, x));
            }
        }
    }
    let theta = best.map(|(_, x)| x).unwrap_or_else(|| vec![0.0; h]);
    unpack(r, &theta)
}
