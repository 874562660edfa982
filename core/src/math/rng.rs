//! The crate's portable seeded random-number generator and draws that give the same stream on
//! every platform.
//!
//! `rand`'s `SmallRng` is Xoshiro256++ on 64-bit targets but Xoshiro128++ on 32-bit ones
//! (wasm32, thumbv7em), and `random_range` over `usize` samples through `u32` on 32-bit
//! targets, so either would make a seeded run in the browser differ from the same run
//! natively. Every seeded algorithm of the crate therefore draws from [`SeededRng`]
//! (Xoshiro256++, seeded through SplitMix64 by [`seeded`]) and takes indices from
//! [`index`], which works in `u64` whatever the pointer width.
//!
//! Algorithms take `&mut R` with `R: rand::Rng + ?Sized`, so a caller may pass any generator;
//! only [`SeededRng`] is promised to reproduce across platforms.
//!
//! Beside it: [`SplitMix64`] (Steele, Lea & Flood 2014), the bare 64-bit stream that the
//! seeded scenes of [`fov::placement_scene`](crate::fov::placement_scene) draw from, and
//! [`poisson`], a Poisson count by inversion of the cdf (Devroye 1986, Sec. X.3.3).

use rand::{Rng, RngExt, SeedableRng};

/// The portable generator: Xoshiro256++ (Blackman & Vigna), 64-bit on every target.
pub type SeededRng = rand::rngs::Xoshiro256PlusPlus;

/// A [`SeededRng`] from a 64-bit seed (expanded by SplitMix64, as `rand` specifies for
/// `seed_from_u64`).
///
/// ```
/// use fisst::math::rng::{seeded, uniform};
/// let (mut a, mut b) = (seeded(7), seeded(7));
/// assert_eq!(uniform(&mut a), uniform(&mut b));
/// ```
pub fn seeded(seed: u64) -> SeededRng {
    SeededRng::seed_from_u64(seed)
}

/// A uniform draw in [0, 1) with 53 random bits (`next_u64() >> 11`, the same on every
/// platform).
#[inline]
pub fn uniform<R: Rng + ?Sized>(rng: &mut R) -> f64 {
    rng.random::<f64>()
}

/// A uniform index in `0..n` computed in `u64` (Lemire's method as `rand` implements it for
/// `u64`), so the stream does not depend on the width of `usize`.
///
/// # Panics
/// If `n == 0` (a caller bug: there is no index to draw).
#[inline]
pub fn index<R: Rng + ?Sized>(rng: &mut R, n: usize) -> usize {
    assert!(n > 0, "index: empty range");
    rng.random_range(0..n as u64) as usize
}

/// A 53-bit seed (an integer exactly representable as a JavaScript number) drawn from `rng`,
/// e.g. to derive independent per-run seeds from one master seed.
#[inline]
pub fn js_safe_seed<R: Rng + ?Sized>(rng: &mut R) -> u64 {
    rng.next_u64() >> 11
}

/// A fresh seed from the platform's entropy: the operating system natively, and
/// `crypto.getRandomValues` in a browser or Node (getrandom's JavaScript backend, which the
/// wasm bindings select). The seed has 53 bits, so it is exactly representable as a JavaScript
/// number: a caller that records it reproduces the run by passing it back.
///
/// # Errors
/// [`Error::Unsupported`](crate::Error::Unsupported) naming `seed` when the platform has no
/// entropy source (then pass a seed).
#[cfg(feature = "std")]
pub fn entropy_seed() -> crate::Result<u64> {
    getrandom::u64()
        .map(|x| x >> 11)
        .map_err(|_| crate::Error::Unsupported {
            what: "seed".into(),
            reason: "no entropy source is available on this platform; pass a seed",
        })
}

/// SplitMix64 (Steele, Lea & Flood 2014; Vigna's reference `splitmix64.c`): a portable 64-bit
/// stream, integer arithmetic only, so the same seed gives the same stream on every platform.
/// Every draw depends only on the seed and its position, so a run that draws n values reads a
/// prefix of a run that draws more (the property the seeded scenes of `001_…` rely on).
///
/// ```
/// use fisst::math::rng::SplitMix64;
/// let mut a = SplitMix64::new(1_234_567);
/// assert_eq!(a.next_u64(), 6_457_827_717_110_365_317);
/// assert!((0.0..1.0).contains(&a.uniform()));
/// ```
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct SplitMix64(u64);

impl SplitMix64 {
    /// The stream from `seed`.
    pub fn new(seed: u64) -> Self {
        SplitMix64(seed)
    }

    /// The next 64-bit output.
    pub fn next_u64(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9e37_79b9_7f4a_7c15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
        z ^ (z >> 31)
    }

    /// Uniform in [0, 1) from the top 53 bits of the next output, a multiple of 2⁻⁵³.
    pub fn uniform(&mut self) -> f64 {
        (self.next_u64() >> 11) as f64 * (1.0 / (1u64 << 53) as f64)
    }
}

/// A Poisson count with mean `mean` by inversion of the cdf (Devroye 1986, Sec. X.3.3):
/// one uniform u, then the smallest k with u ≤ Σ_{j≤k} e^{−mean} meanʲ/j!, the terms built by
/// p_k = p_{k−1} · mean/k. The count is capped at `max` (a guard against rounding making the
/// cdf stall below u). Cost O(mean): meant for small means.
///
/// ```
/// use fisst::math::rng::{poisson, seeded};
/// let mut rng = seeded(1);
/// assert_eq!(poisson(&mut rng, 0.0, 10), 0);
/// assert!(poisson(&mut rng, 1e9, 10) <= 10);
/// ```
pub fn poisson<R: Rng + ?Sized>(rng: &mut R, mean: f64, max: usize) -> usize {
    let u = uniform(rng);
    let mut k = 0;
    let mut p = crate::math::fns::exp(-mean);
    let mut cdf = p;
    while u > cdf && k < max {
        k += 1;
        p *= mean / k as f64;
        cdf += p;
    }
    k
}

/// Systematic resampling (Kitagawa 1996; Ristic, Arulampalam & Gordon 2004, Table 3.2): `n`
/// indices into `weights` from one uniform offset and a stride of Σw/n (the weights need not
/// be normalised; Σw is compensated). Shared by the particle Bernoulli filter and the SMC
/// multi-object filter.
pub fn systematic<R: Rng + ?Sized>(
    weights: &[f64],
    n: usize,
    rng: &mut R,
) -> alloc::vec::Vec<usize> {
    let total: f64 = weights
        .iter()
        .copied()
        .collect::<super::sum::NeumaierSum>()
        .total();
    let step = total / n as f64;
    let mut u = uniform(rng) * step;
    let mut out = alloc::vec::Vec::with_capacity(n);
    let mut acc = 0.0;
    let mut i = 0;
    // The last index with positive weight: rounding can never push a draw past it.
    let last = weights.iter().rposition(|w| *w > 0.0).unwrap_or(0);
    for _ in 0..n {
        while i < last && acc + weights[i] <= u {
            acc += weights[i];
            i += 1;
        }
        out.push(i);
        u += step;
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn stream_is_pinned() {
        // Pinned values: a change here changes every seeded result of the crate.
        let mut r = seeded(1);
        let first: [u64; 2] = [r.next_u64(), r.next_u64()];
        let mut again = seeded(1);
        assert_eq!(first, [again.next_u64(), again.next_u64()]);
        let mut r = seeded(1);
        let u = uniform(&mut r);
        assert!((0.0..1.0).contains(&u));
        assert_eq!(u, (first[0] >> 11) as f64 * (1.0 / (1u64 << 53) as f64));
    }

    #[test]
    fn index_is_uniform() {
        let mut r = seeded(3);
        let mut counts = [0usize; 7];
        for _ in 0..70_000 {
            counts[index(&mut r, 7)] += 1;
        }
        // 10,000 expected per cell, standard deviation about 93: allow 6σ.
        for c in counts {
            assert!((c as f64 - 10_000.0).abs() < 560.0, "{counts:?}");
        }
        assert!(js_safe_seed(&mut r) < 1u64 << 53);
    }

    #[test]
    fn splitmix64_matches_the_reference_outputs() {
        // The reference outputs of SplitMix64 seeded with 1234567 (Vigna's splitmix64.c).
        let mut rng = SplitMix64::new(1_234_567);
        let want: [u64; 3] = [
            6_457_827_717_110_365_317,
            3_203_168_211_198_807_973,
            9_817_491_932_198_370_423,
        ];
        for w in want {
            assert_eq!(rng.next_u64(), w);
        }
        // The uniform is the top 53 bits of the next output.
        let (mut a, mut b) = (SplitMix64::new(5), SplitMix64::new(5));
        assert_eq!(
            a.uniform(),
            (b.next_u64() >> 11) as f64 / (1u64 << 53) as f64
        );
    }

    #[test]
    fn poisson_has_the_mean_and_variance() {
        // 200,000 draws of mean 2.5: the sample mean has sd √(2.5/2e5) ≈ 0.0035 and the sample
        // variance sd ≈ √((2.5 + 2·2.5²)/2e5) ≈ 0.0086; allow 5σ of each.
        let (n, mean) = (200_000, 2.5);
        let mut r = seeded(11);
        let draws: alloc::vec::Vec<f64> =
            (0..n).map(|_| poisson(&mut r, mean, 1000) as f64).collect();
        let m = draws.iter().sum::<f64>() / n as f64;
        let v = draws.iter().map(|x| (x - m) * (x - m)).sum::<f64>() / (n - 1) as f64;
        assert!((m - mean).abs() < 5.0 * 0.0035, "mean {m}");
        assert!((v - mean).abs() < 5.0 * 0.0086, "variance {v}");
    }

    #[test]
    fn poisson_caps_and_mean_zero() {
        let mut r = seeded(2);
        for _ in 0..100 {
            // Mean 0: p₀ = 1 ≥ u always.
            assert_eq!(poisson(&mut r, 0.0, 1000), 0);
            // A mean far above the cap stops at the cap (e^{−1e3} underflows to 0: the cdf
            // never reaches u).
            assert_eq!(poisson(&mut r, 1e3, 7), 7);
        }
        // Each draw takes exactly one uniform from the stream.
        let (mut a, mut b) = (seeded(3), seeded(3));
        poisson(&mut a, 4.0, 1000);
        uniform(&mut b);
        assert_eq!(a.next_u64(), b.next_u64());
    }

    #[cfg(feature = "std")]
    #[test]
    fn entropy_seeds_are_js_safe_and_vary() {
        let a = entropy_seed().unwrap();
        let b = entropy_seed().unwrap();
        assert!(a < 1u64 << 53 && b < 1u64 << 53);
        assert_ne!(a, b, "two 53-bit entropy draws collided");
    }
}
