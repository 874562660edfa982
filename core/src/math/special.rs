//! Special functions and constants: ln Γ, ln n!, the Poisson pmf (Loader's form), and the
//! constants ln 2π, ln √(2π), 1/√(2π) as literals (each pinned by a test to the value the
//! crate's functions compute).
//!
//! # References
//! C. Loader, "Fast and accurate computation of binomial probabilities," 2000 (the `bd0` and
//! `stirlerr` terms of R's `dpois`).

use crate::math::fns;

/// ln 2π (equal to `fns::ln(2π)`, bit for bit).
pub const LN_2PI: f64 = 1.837_877_066_409_345_3;
/// ln √(2π), the normalising constant of a one-dimensional Gaussian's log-density, correctly
/// rounded (one ulp above `0.5 * LN_2PI`, so the two are not interchangeable bit for bit).
pub const LN_SQRT_2PI: f64 = 0.918_938_533_204_672_8;
/// 1/√(2π), the standard normal density at 0.
pub const FRAC_1_SQRT_2PI: f64 = 0.398_942_280_401_432_7;

/// ln Γ(x) for x > 0 (libm's `lgamma`).
#[inline]
pub fn ln_gamma(x: f64) -> f64 {
    libm::lgamma(x)
}

/// ln n! as a sum of ln k (exact to rounding for the sizes used here).
pub fn ln_factorial(n: usize) -> f64 {
    (2..=n).map(|k| fns::ln(k as f64)).sum()
}

/// Loader's deviance term bd0(x, np) = x ln(x/np) + np − x, without cancellation.
fn bd0(x: f64, np: f64) -> f64 {
    if fns::abs(x - np) < 0.1 * (x + np) {
        let mut v = (x - np) / (x + np);
        let mut s = (x - np) * v;
        let mut ej = 2.0 * x * v;
        v *= v;
        for j in 1..1000 {
            ej *= v;
            let s1 = s + ej / (2 * j + 1) as f64;
            if s1 == s {
                return s1;
            }
            s = s1;
        }
        s
    } else {
        x * fns::ln(x / np) + np - x
    }
}

/// Stirling's error ln n! − (n + ½) ln n + n − ½ ln 2π for n ≥ 16 (Loader's series).
fn stirlerr(n: f64) -> f64 {
    const S0: f64 = 1.0 / 12.0;
    const S1: f64 = 1.0 / 360.0;
    const S2: f64 = 1.0 / 1260.0;
    const S3: f64 = 1.0 / 1680.0;
    const S4: f64 = 1.0 / 1188.0;
    let nn = n * n;
    if n > 500.0 {
        (S0 - S1 / nn) / n
    } else if n > 80.0 {
        (S0 - (S1 - S2 / nn) / nn) / n
    } else if n > 35.0 {
        (S0 - (S1 - (S2 - S3 / nn) / nn) / nn) / n
    } else {
        (S0 - (S1 - (S2 - (S3 - S4 / nn) / nn) / nn) / nn) / n
    }
}

/// The Poisson pmf e^{−λ} λⁿ / n!, accurate to a few ulps relative: directly for n < 16,
/// Loader's saddle-point form e^{−stirlerr(n) − bd0(n, λ)} / √(2π n) from n = 16 on (no
/// overflow or cancellation for large n or λ).
///
/// ```
/// use fisst::math::special::poisson_pmf;
/// assert_eq!(poisson_pmf(2.0, 0), (-2.0f64).exp());
/// assert!((poisson_pmf(2.0, 3) - 8.0 / 6.0 * (-2.0f64).exp()).abs() < 1e-16);
/// ```
pub fn poisson_pmf(lambda: f64, n: usize) -> f64 {
    if lambda == 0.0 {
        return if n == 0 { 1.0 } else { 0.0 };
    }
    if n == 0 {
        return fns::exp(-lambda);
    }
    let x = n as f64;
    if n < 16 {
        return fns::exp(x * fns::ln(lambda) - lambda - ln_factorial(n));
    }
    fns::exp(-stirlerr(x) - bd0(x, lambda)) / fns::sqrt(2.0 * core::f64::consts::PI * x)
}

#[cfg(test)]
mod tests {
    use super::*;
    use core::f64::consts::PI;

    #[test]
    fn constants_are_the_computed_values() {
        assert_eq!(LN_2PI, fns::ln(2.0 * PI));
        assert_eq!(LN_SQRT_2PI.to_bits(), (0.5 * LN_2PI).to_bits() + 1);
        assert_eq!(FRAC_1_SQRT_2PI, 1.0 / fns::sqrt(2.0 * PI));
    }

    #[test]
    fn factorials_and_gamma_agree() {
        assert_eq!(ln_factorial(0), 0.0);
        assert_eq!(ln_factorial(1), 0.0);
        assert_eq!(
            ln_factorial(5),
            fns::ln(2.0) + fns::ln(3.0) + fns::ln(4.0) + fns::ln(5.0)
        );
        for n in [3usize, 10, 40, 170] {
            let (a, b) = (ln_factorial(n), ln_gamma(n as f64 + 1.0));
            assert!((a - b).abs() <= 1e-13 * b, "{n}: {a} vs {b}");
        }
        assert!((ln_gamma(0.5) - 0.5 * fns::ln(PI)).abs() < 1e-15);
    }

    #[test]
    fn poisson_pmf_matches_the_direct_formula() {
        // Below 16 it is the direct formula, bit for bit; above, within a few ulps of it.
        for lambda in [0.1, 1.0, 3.0, 20.0, 55.5] {
            for n in 0..60 {
                let direct = fns::exp(-lambda + n as f64 * fns::ln(lambda) - ln_factorial(n));
                let p = poisson_pmf(lambda, n);
                if n < 16 {
                    assert_eq!(p.to_bits(), direct.to_bits(), "λ {lambda}, n {n}");
                } else {
                    assert!(
                        (p - direct).abs() <= 1e-12 * direct,
                        "λ {lambda}, n {n}: {p}"
                    );
                }
            }
            let total: f64 = (0..400).map(|n| poisson_pmf(lambda, n)).sum();
            assert!((total - 1.0).abs() < 1e-14, "λ {lambda}: Σ {total}");
        }
        assert_eq!((poisson_pmf(0.0, 0), poisson_pmf(0.0, 3)), (1.0, 0.0));
        // Far in the tail the direct formula overflows in λⁿ / n! but Loader's form does not.
        let far = poisson_pmf(1e6, 1_000_000);
        assert!(
            (far - 1.0 / fns::sqrt(2.0 * PI * 1e6)).abs() < 1e-9,
            "{far}"
        );
    }
}
