//! The split objective (13)–(14) of `001_…` in closed form, with its gradient.

use core::f64::consts::PI;

use crate::math::fns;
use crate::math::sum::NeumaierSum;

/// φ(x; v) = N(x; 0, v) = exp(−x²/(2v)) / √(2πv).
#[inline]
fn phi(x: f64, v: f64) -> f64 {
    fns::exp(-0.5 * x * x / v) / fns::sqrt(2.0 * PI * v)
}

/// The gradient of [`objective_with_gradient`] with respect to the raw parameters.
pub(crate) struct RawGradient {
    /// ∂J/∂w̃_j.
    pub weights: alloc::vec::Vec<f64>,
    /// ∂J/∂m̃_j.
    pub means: alloc::vec::Vec<f64>,
    /// ∂J/∂σ̃.
    pub sigma: f64,
}

/// J of eq. (13) and, when asked, its gradient with respect to (w̃, m̃, σ̃).
///
/// ```text
/// J = ‖q − q̃‖² + λσ̃²
///   = 1/(2√π) − 2 Σ_j w̃_j N(m̃_j; 0, 1 + σ̃²) + Σ_i Σ_j w̃_i w̃_j N(m̃_i − m̃_j; 0, 2σ̃²) + λσ̃²
/// ```
///
/// from ∫ N(x; a, s²) N(x; b, t²) dx = N(a − b; 0, s² + t²). The three sums are compensated
/// (they cancel to a few 1e-4 from terms of order 0.3).
pub(crate) fn objective_with_gradient(
    weights: &[f64],
    means: &[f64],
    sigma: f64,
    lambda: f64,
    want_gradient: bool,
) -> (f64, Option<RawGradient>) {
    let r = weights.len();
    let s2 = sigma * sigma;
    let v1 = 1.0 + s2;
    let v2 = 2.0 * s2;
    let mut total = NeumaierSum::new();
    total.add(0.5 / fns::sqrt(PI));
    total.add(lambda * s2);
    let mut gw = alloc::vec![0.0; if want_gradient { r } else { 0 }];
    let mut gm = alloc::vec![0.0; if want_gradient { r } else { 0 }];
    let mut gv1 = NeumaierSum::new(); // ∂J/∂v1
    let mut gv2 = NeumaierSum::new(); // ∂J/∂v2
    for j in 0..r {
        let (wj, mj) = (weights[j], means[j]);
        let b = phi(mj, v1);
        total.add(-2.0 * wj * b);
        if want_gradient {
            gw[j] -= 2.0 * b;
            gm[j] += 2.0 * wj * b * mj / v1;
            gv1.add(-2.0 * wj * b * (mj * mj / (2.0 * v1 * v1) - 0.5 / v1));
        }
        for i in 0..r {
            let d = means[i] - mj;
            let c = phi(d, v2);
            let wc = weights[i] * wj * c;
            total.add(wc);
            if want_gradient {
                // C = Σ_i Σ_j w_i w_j φ(m_i − m_j): each ordered pair contributes to both
                // w_i and w_j; summing over j for fixed j's row covers both by symmetry.
                gw[j] += 2.0 * weights[i] * c;
                // ∂/∂m_j of φ(m_i − m_j) and of φ(m_j − m_i) (the (j, i) term): 2·w_i w_j φ d/v2.
                gm[j] += 2.0 * wc * d / v2;
                gv2.add(wc * (d * d / (2.0 * v2 * v2) - 0.5 / v2));
            }
        }
    }
    let gradient = want_gradient.then(|| RawGradient {
        weights: gw,
        means: gm,
        sigma: gv1.total() * 2.0 * sigma + gv2.total() * 4.0 * sigma + 2.0 * lambda * sigma,
    });
    (total.total(), gradient)
}

/// J of eq. (13) (see [`objective_with_gradient`]).
pub(crate) fn objective(weights: &[f64], means: &[f64], sigma: f64, lambda: f64) -> f64 {
    objective_with_gradient(weights, means, sigma, lambda, false).0
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn gradient_matches_central_differences() {
        let w = [0.1, 0.25, 0.4, 0.25];
        let m = [-1.3, -0.4, 0.2, 1.1];
        let (s, lam) = (0.55, 0.01);
        let (_, g) = objective_with_gradient(&w, &m, s, lam, true);
        let g = g.unwrap();
        let h = 1e-6;
        for j in 0..4 {
            let (mut wp, mut wm) = (w, w);
            wp[j] += h;
            wm[j] -= h;
            let fd = (objective(&wp, &m, s, lam) - objective(&wm, &m, s, lam)) / (2.0 * h);
            assert!(
                (fd - g.weights[j]).abs() < 1e-8,
                "w{j}: {fd} vs {}",
                g.weights[j]
            );
            let (mut mp, mut mm) = (m, m);
            mp[j] += h;
            mm[j] -= h;
            let fd = (objective(&w, &mp, s, lam) - objective(&w, &mm, s, lam)) / (2.0 * h);
            assert!(
                (fd - g.means[j]).abs() < 1e-8,
                "m{j}: {fd} vs {}",
                g.means[j]
            );
        }
        let fd = (objective(&w, &m, s + h, lam) - objective(&w, &m, s - h, lam)) / (2.0 * h);
        assert!((fd - g.sigma).abs() < 1e-8, "sigma: {fd} vs {}", g.sigma);
    }

    #[test]
    fn exact_fit_has_zero_distance() {
        // One component equal to N(0, 1): J = λ.
        let j = objective(&[1.0], &[0.0], 1.0, 0.25);
        assert!((j - 0.25).abs() < 1e-16, "{j}");
    }
}
