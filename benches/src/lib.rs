//! Shared inputs and timers for the benchmarks and the timing programs in `src/bin/`: seeded
//! point sets like a tracker's output, a 4D mixture, median wall times.

use fisst::gaussian::{Gaussian, GaussianMixture};

/// SplitMix64: a portable seeded generator.
pub struct SplitMix(u64);

impl SplitMix {
    /// A generator from a seed.
    pub fn new(seed: u64) -> Self {
        Self(seed)
    }

    /// A uniform draw in [0, 1).
    pub fn uniform(&mut self) -> f64 {
        self.0 = self.0.wrapping_add(0x9e37_79b9_7f4a_7c15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
        ((z ^ (z >> 31)) >> 11) as f64 / (1u64 << 53) as f64
    }
}

/// n truth points uniform in a square of side 10·√n (constant density), and an estimate with
/// 90 % of them detected (Gaussian-ish noise of scale 1) plus 10 % clutter: the shape of a
/// tracker's output scored with GOSPA (c = 5).
pub fn scene(n: usize, seed: u64) -> (Vec<[f64; 2]>, Vec<[f64; 2]>) {
    let mut rng = SplitMix::new(seed);
    let side = 10.0 * (n as f64).sqrt();
    let truth: Vec<[f64; 2]> = (0..n)
        .map(|_| [side * rng.uniform(), side * rng.uniform()])
        .collect();
    let mut estimate = Vec::with_capacity(n);
    for t in &truth {
        if rng.uniform() < 0.9 {
            let noise = |r: &mut SplitMix| (r.uniform() + r.uniform() + r.uniform() - 1.5) * 2.0;
            estimate.push([t[0] + noise(&mut rng), t[1] + noise(&mut rng)]);
        }
    }
    for _ in 0..n / 10 {
        estimate.push([side * rng.uniform(), side * rng.uniform()]);
    }
    (truth, estimate)
}

/// The median wall time in seconds of `reps` calls of `f` (`reps` ≥ 1), and the last result.
pub fn median_time<T>(reps: usize, mut f: impl FnMut() -> T) -> (f64, T) {
    let (seconds, out) = times(reps, &mut f);
    (seconds[seconds.len() / 2], out)
}

/// The median and the minimum wall time in microseconds of `reps` calls of `f` (`reps` ≥ 1;
/// the minimum is the robust figure on a shared machine).
pub fn median_min_us(reps: usize, mut f: impl FnMut()) -> (f64, f64) {
    let (seconds, ()) = times(reps, &mut f);
    (seconds[seconds.len() / 2] * 1e6, seconds[0] * 1e6)
}

/// The sorted wall times in seconds of `reps` calls of `f`, and the last result.
fn times<T>(reps: usize, f: &mut impl FnMut() -> T) -> (Vec<f64>, T) {
    assert!(reps >= 1, "at least one repetition");
    let mut seconds = Vec::with_capacity(reps);
    let mut out = None;
    for _ in 0..reps {
        let t0 = std::time::Instant::now();
        out = Some(f());
        seconds.push(t0.elapsed().as_secs_f64());
    }
    seconds.sort_by(f64::total_cmp);
    (seconds, out.expect("reps >= 1"))
}

/// A deterministic 4D mixture of `n` components (a Weyl sequence, no RNG): the input of the
/// Runnalls benchmarks.
pub fn cloud(n: usize) -> GaussianMixture {
    let frac = |x: f64| x - x.floor();
    let comps = (0..n)
        .map(|i| {
            let t = i as f64;
            let m = [
                10.0 * frac(t * 0.618_033_988_75),
                10.0 * frac(t * 0.414_213_562_37),
                frac(t * 0.732_050_807_57) - 0.5,
                frac(t * 0.236_067_977_5) - 0.5,
            ];
            let s = 0.2 + 0.3 * frac(t * 0.302_775_637_73);
            let c = 0.3 * s * s * (frac(t * 0.577_215_664_9) - 0.5);
            #[rustfmt::skip]
            let p = [
                s * s, c, 0.0, 0.0,
                c, s * s, 0.0, 0.0,
                0.0, 0.0, 0.04, 0.0,
                0.0, 0.0, 0.0, 0.04,
            ];
            (
                0.5 + frac(t * 0.141_421_356_2),
                Gaussian::from_slices(&m, &p, "cloud").unwrap(),
            )
        })
        .collect();
    GaussianMixture::new(comps, "cloud").unwrap()
}
