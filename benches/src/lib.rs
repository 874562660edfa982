//! Shared inputs for the benchmarks: seeded point sets like a tracker's output.

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
