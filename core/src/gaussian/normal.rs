//! The standard normal distribution: density, distribution function, and sampling.

use crate::math::fns;
use rand::{Rng, RngExt};

/// 1/√(2π).
pub use crate::math::special::FRAC_1_SQRT_2PI;

/// φ(x), the standard normal density.
#[inline]
pub fn pdf(x: f64) -> f64 {
    FRAC_1_SQRT_2PI * fns::exp(-0.5 * x * x)
}

/// Φ(x) = P(Z ≤ x), accurate in both tails (through `erfc`).
#[inline]
pub fn cdf(x: f64) -> f64 {
    0.5 * libm::erfc(-x * core::f64::consts::FRAC_1_SQRT_2)
}

/// 1 − Φ(x) = Φ(−x), accurate for large x.
#[inline]
pub fn sf(x: f64) -> f64 {
    0.5 * libm::erfc(x * core::f64::consts::FRAC_1_SQRT_2)
}

/// P(a < Z ≤ b) for a ≤ b, computed in the tail where it loses no digits.
pub fn interval(a: f64, b: f64) -> f64 {
    if a >= b {
        return 0.0;
    }
    if a > 0.0 {
        sf(a) - sf(b)
    } else if b < 0.0 {
        cdf(b) - cdf(a)
    } else {
        1.0 - sf(b) - cdf(a)
    }
}

/// A standard normal draw (Marsaglia's polar method on uniform draws from `rng`): the same
/// seed gives the same stream on every platform for a portable generator.
pub fn sample<R: Rng + ?Sized>(rng: &mut R) -> f64 {
    loop {
        let u = 2.0 * rng.random::<f64>() - 1.0;
        let v = 2.0 * rng.random::<f64>() - 1.0;
        let s = u * u + v * v;
        if s > 0.0 && s < 1.0 {
            return u * fns::sqrt(-2.0 * fns::ln(s) / s);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn known_values() {
        assert!((cdf(0.0) - 0.5).abs() < 1e-16);
        assert!((cdf(1.959_963_984_540_054) - 0.975).abs() < 1e-15);
        // Φ(−10) = 7.619853024160527e-24
        assert!((cdf(-10.0) / 7.619_853_024_160_527e-24 - 1.0).abs() < 1e-13);
        assert!((interval(-1.0, 1.0) - 0.682_689_492_137_085_9).abs() < 1e-15);
        assert!((interval(8.0, 9.0) - (sf(8.0) - sf(9.0))).abs() < 1e-30);
    }

    #[test]
    fn sampling_moments() {
        use rand::SeedableRng;
        let mut rng = rand::rngs::SmallRng::seed_from_u64(1);
        let n = 200_000;
        let xs: alloc::vec::Vec<f64> = (0..n).map(|_| sample(&mut rng)).collect();
        let mean = xs.iter().sum::<f64>() / n as f64;
        let var = xs.iter().map(|x| (x - mean) * (x - mean)).sum::<f64>() / n as f64;
        // 5 standard errors
        assert!(mean.abs() < 5.0 / (n as f64).sqrt());
        assert!((var - 1.0).abs() < 5.0 * (2.0 / n as f64).sqrt());
    }
}
