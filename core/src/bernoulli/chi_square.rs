//! The chi-square survival function P(χ²_d > t) in closed form: the probability that an
//! isotropic Gaussian lies outside a ball about its mean, and the bound behind the
//! shortcuts of [`ball`](super::ball).

use crate::math::fns;
use crate::math::special;

/// 2/√π.
const FRAC_2_SQRT_PI: f64 = core::f64::consts::FRAC_2_SQRT_PI;

/// P(χ²_d > t), the chi-square survival function with d degrees of freedom, from the closed
/// forms of the regularised upper incomplete gamma function Q(d/2, t/2):
///
/// ```text
/// d = 2k:      Q(k, x)     = e^{−x} Σ_{j=0}^{k−1} x^j / j!
/// d = 2k + 1:  Q(k + ½, x) = erfc(√x) + e^{−x} Σ_{j=0}^{k−1} x^{j+½} / Γ(j + 3/2),   x = t/2
/// ```
///
/// Every term is positive, so the sums lose nothing to cancellation (relative error a few
/// ulps times the number of terms). For x ≥ 700 the terms are formed in log space; a sum
/// stops early once its geometric tail is below 1e-17 of the total. `t ≤ 0` gives 1,
/// `t = ∞` gives 0, NaN gives NaN. `d = 0` is the point mass at 0 (0 for t ≥ 0).
pub fn chi_square_sf(d: usize, t: f64) -> f64 {
    if t.is_nan() {
        return f64::NAN;
    }
    if t <= 0.0 {
        return 1.0;
    }
    if d == 0 || t == f64::INFINITY {
        return 0.0;
    }
    let x = 0.5 * t;
    let k = d / 2;
    let odd = d % 2 == 1;
    // Term j of the finite sum, without the factor e^{−x}, is x^{j+h}/Γ(j + h + 1) with h = ½
    // for odd d and 0 for even d; consecutive terms differ by the factor x/(j + h).
    let h = if odd { 0.5 } else { 0.0 };
    let head = if odd { fns::erfc(fns::sqrt(x)) } else { 0.0 };
    let terms = if odd { k } else { k.max(1) };
    if odd && k == 0 {
        return head;
    }
    let mut total = 0.0;
    if x < 700.0 {
        let mut term = fns::exp(-x)
            * if odd {
                FRAC_2_SQRT_PI * fns::sqrt(x)
            } else {
                1.0
            };
        for j in 0..terms {
            if j > 0 {
                term *= x / (j as f64 + h);
            }
            total += term;
            if tail_is_negligible(x, j, h, term, total) {
                break;
            }
        }
    } else {
        let ln_x = fns::ln(x);
        let mut ln_term = -x + h * ln_x - special::ln_gamma(h + 1.0);
        for j in 0..terms {
            if j > 0 {
                ln_term += ln_x - fns::ln(j as f64 + h);
            }
            let term = fns::exp(ln_term);
            total += term;
            if total > 0.0 && tail_is_negligible(x, j, h, term, total) {
                break;
            }
        }
    }
    (head + total).min(1.0)
}

/// True when the terms after `term` (index j) decrease geometrically with ratio
/// r = x/(j + 1 + h) < 1 and their sum, at most term·r/(1 − r), is below 1e-17·total.
fn tail_is_negligible(x: f64, j: usize, h: f64, term: f64, total: f64) -> bool {
    let r = x / (j as f64 + 1.0 + h);
    r < 1.0 && term * r / (1.0 - r) <= 1e-17 * total
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::gaussian::normal;

    #[test]
    fn chi_square_matches_known_values() {
        // d = 1: 2Φ(−√t); d = 2: e^{−t/2}; d = 3: erfc(√(t/2)) + √(2t/π) e^{−t/2}.
        for &t in &[1e-6f64, 0.3, 1.0, 4.0, 25.0, 100.0, 1000.0, 1600.0] {
            let d1 = 2.0 * normal::cdf(-t.sqrt());
            assert!(
                (chi_square_sf(1, t) - d1).abs() <= 1e-15 * d1.max(1e-300),
                "t={t}"
            );
            let d2 = (-t / 2.0).exp();
            assert!((chi_square_sf(2, t) - d2).abs() <= 1e-14 * d2, "t={t}");
            let d3 = libm::erfc((t / 2.0).sqrt())
                + (2.0 * t / core::f64::consts::PI).sqrt() * (-t / 2.0).exp();
            assert!((chi_square_sf(3, t) - d3).abs() <= 1e-14 * d3, "t={t}");
        }
        // Table values (to their printed three decimals, hence the tolerance of a
        // half-unit times the density): P(χ²_10 > 18.307) = 0.05, P(χ²_5 > 1.145) = 0.95,
        // P(χ²_100 > 124.342) = 0.05.
        assert!((chi_square_sf(10, 18.307) - 0.05).abs() < 1e-5);
        assert!((chi_square_sf(5, 1.145) - 0.95).abs() < 1e-4);
        assert!((chi_square_sf(100, 124.342) - 0.05).abs() < 1e-5);
        assert_eq!(chi_square_sf(3, 0.0), 1.0);
        assert_eq!(chi_square_sf(3, f64::INFINITY), 0.0);
        // Log-space branch (x ≥ 700) agrees with the direct one across the switch.
        for d in [2, 3, 1500, 1501, 2000] {
            let a = chi_square_sf(d, 1399.999);
            let b = chi_square_sf(d, 1400.001);
            assert!(a >= b && (a - b) <= 1e-3 * a.max(1e-300), "d={d}: {a} {b}");
        }
        // Large d, moderate t: the mean of χ²_d is d, so P(χ²_2000 > 2000) ≈ 0.5 - small.
        let m = chi_square_sf(2000, 2000.0);
        assert!((m - 0.4958).abs() < 1e-3, "{m}");
    }

    #[test]
    fn chi_square_sum_matches_series_by_numerical_integration() {
        // P(χ²_d > t) = ∫_t^∞ f_d, checked against a Simpson rule for d = 4, 7.
        for d in [4usize, 7] {
            let t = 3.3;
            let lg = libm::lgamma(d as f64 / 2.0);
            let f = |x: f64| {
                ((d as f64 / 2.0 - 1.0) * x.ln() - x / 2.0 - (d as f64 / 2.0) * 2f64.ln() - lg)
                    .exp()
            };
            let (a, b, n) = (t, 120.0, 200_000);
            let h = (b - a) / n as f64;
            let mut s = f(a) + f(b);
            for i in 1..n {
                s += f(a + i as f64 * h) * if i % 2 == 1 { 4.0 } else { 2.0 };
            }
            let simpson = s * h / 3.0;
            assert!((chi_square_sf(d, t) - simpson).abs() < 1e-12, "d={d}");
        }
    }
}
