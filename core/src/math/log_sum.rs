//! Sums of exponentials in log space: ln(e^a + e^b) and ln Σ e^{x_i}, shifted by the largest
//! term so that nothing overflows and the largest term is exact (−∞ stands for a zero term).
//!
//! # References
//! P. Blanchard, D. J. Higham and N. J. Higham, "Accurately computing the log-sum-exp and
//! softmax functions," IMA Journal of Numerical Analysis 41(4):2311–2330, 2021 (the shifted
//! form and its error analysis).

use crate::math::fns::{exp, ln, ln_1p};

/// ln(e^a + e^b), −∞ when both are −∞: hi + ln(1 + e^{lo − hi}) with hi = max(a, b), the
/// shifted form of Blanchard, Higham & Higham (2021) for two terms.
#[inline]
pub fn ln_add(a: f64, b: f64) -> f64 {
    let (hi, lo) = if a >= b { (a, b) } else { (b, a) };
    if hi == f64::NEG_INFINITY {
        return f64::NEG_INFINITY;
    }
    hi + ln_1p(exp(lo - hi))
}

/// ln Σ e^{x_i} (−∞ for an empty or all −∞ input, +∞ when a term is +∞): the shifted form
/// max + ln Σ e^{x_i − max} of Blanchard, Higham & Higham (2021).
pub fn ln_sum_exp(xs: impl IntoIterator<Item = f64> + Clone) -> f64 {
    let hi = xs.clone().into_iter().fold(f64::NEG_INFINITY, f64::max);
    if hi == f64::NEG_INFINITY {
        return f64::NEG_INFINITY;
    }
    if hi == f64::INFINITY {
        return f64::INFINITY;
    }
    let s: f64 = xs.into_iter().map(|x| exp(x - hi)).sum();
    hi + ln(s)
}

#[cfg(test)]
mod tests {
    use super::*;

    const NEG: f64 = f64::NEG_INFINITY;

    fn close(a: f64, b: f64, tol: f64) -> bool {
        (a - b).abs() <= tol * (1.0 + a.abs().max(b.abs()))
    }

    #[test]
    fn ln_add_is_the_direct_formula_where_that_is_representable() {
        for (a, b) in [
            (0.0f64, 0.0f64),
            (1.5, -2.0),
            (-3.0, 4.0),
            (-700.0, -701.0),
            (10.0, 9.9),
        ] {
            let direct = (a.exp() + b.exp()).ln();
            assert!(close(ln_add(a, b), direct, 1e-15), "{a} {b}");
            // Symmetric, to the bit.
            assert_eq!(ln_add(a, b).to_bits(), ln_add(b, a).to_bits());
        }
    }

    #[test]
    fn ln_add_with_zero_terms() {
        assert_eq!(ln_add(NEG, NEG), NEG);
        assert_eq!(ln_add(NEG, -3.25), -3.25);
        assert_eq!(ln_add(7.0, NEG), 7.0);
    }

    #[test]
    fn ln_add_over_large_spreads() {
        // e^{1000} overflows; the shifted form does not.
        let v = ln_add(1000.0, 999.0);
        assert!(
            close(v, 1000.0 + (1.0 + (-1.0f64).exp()).ln(), 1e-15),
            "{v}"
        );
        // e^{-1000} underflows to 0; the shifted form keeps the sum.
        let v = ln_add(-1000.0, -1000.0);
        assert!(close(v, -1000.0 + core::f64::consts::LN_2, 1e-15), "{v}");
        // A spread beyond double precision: the larger term, exactly.
        assert_eq!(ln_add(0.0, -800.0), 0.0);
        assert_eq!(ln_add(-5e3, 3e2), 3e2);
    }

    #[test]
    fn ln_sum_exp_is_the_direct_formula_where_that_is_representable() {
        let xs = [0.5f64, -1.0, 2.25, -7.0, 0.0];
        let direct = xs.iter().map(|x| x.exp()).sum::<f64>().ln();
        assert!(close(ln_sum_exp(xs), direct, 1e-15));
        // One term: itself.
        assert_eq!(ln_sum_exp([-3.5]), -3.5);
        // Agrees with folding ln_add.
        let folded = xs.iter().fold(NEG, |acc, &x| ln_add(acc, x));
        assert!(close(ln_sum_exp(xs), folded, 1e-15));
    }

    #[test]
    fn ln_sum_exp_with_zero_and_infinite_terms() {
        assert_eq!(ln_sum_exp(core::iter::empty()), NEG);
        assert_eq!(ln_sum_exp([NEG, NEG]), NEG);
        assert_eq!(ln_sum_exp([NEG, 2.0, NEG]), 2.0);
        assert_eq!(ln_sum_exp([1.0, f64::INFINITY]), f64::INFINITY);
    }

    #[test]
    fn ln_sum_exp_over_large_spreads() {
        // n equal terms far outside the double range: x + ln n.
        for x in [-2000.0, 2000.0] {
            let v = ln_sum_exp([x; 8]);
            assert!(close(v, x + 8.0f64.ln(), 1e-15), "{x}: {v}");
        }
        // Terms spread over 1500 nats: the small ones vanish below rounding.
        let v = ln_sum_exp([-1500.0, 0.0, -40.0]);
        assert!(close(v, (-40.0f64).exp().ln_1p(), 1e-15), "{v}");
    }
}
