//! Native timings of optimal Bernoulli point estimation (issue 3, paper `000_…`): q(a) for
//! 2D–6D Gaussians, a* for Gaussian mixtures of 2–10 components in 1D–3D, particles, and a
//! 200-point threshold curve. Not a test: run it in release mode,
//!
//! ```text
//! cargo run --release -p fisst --example bernoulli_timing
//! ```
//!
//! and read the medians and minima it prints (microseconds). The inputs are fixed, so the
//! printed values (q, q(a*)) can be compared with another implementation.

use std::time::Instant;

use fisst::bernoulli::{Costs, ParticleSet, SpatialDensity, isotropic_threshold_curve};
use fisst::gaussian::{Gaussian, GaussianMixture};

/// Median and minimum wall time in microseconds of `runs` calls of `f`.
fn time_us(runs: usize, mut f: impl FnMut()) -> (f64, f64) {
    let mut t: Vec<f64> = (0..runs)
        .map(|_| {
            let start = Instant::now();
            f();
            start.elapsed().as_secs_f64() * 1e6
        })
        .collect();
    t.sort_by(f64::total_cmp);
    (t[t.len() / 2], t[0])
}

/// A fixed pseudo-random stream in [0, 1) (Park–Miller), so the inputs are reproducible in
/// any language.
struct Lcg(u64);

impl Lcg {
    fn next(&mut self) -> f64 {
        self.0 = (self.0 * 16807) % 2_147_483_647;
        self.0 as f64 / 2_147_483_647.0
    }
}

/// A covariance with eigenvalues `eig` rotated by a fixed angle in each coordinate plane.
fn rotated(eig: &[f64]) -> Vec<f64> {
    let d = eig.len();
    let mut u = vec![0.0; d * d];
    for i in 0..d {
        u[i * d + i] = 1.0;
    }
    for i in 0..d {
        for j in i + 1..d {
            let a: f64 = 0.3 + 0.7 * (i as f64 + 2.0 * j as f64);
            let (c, s) = (a.cos(), a.sin());
            for row in 0..d {
                let (x, y) = (u[row * d + i], u[row * d + j]);
                u[row * d + i] = c * x + s * y;
                u[row * d + j] = -s * x + c * y;
            }
        }
    }
    let mut p = vec![0.0; d * d];
    for r in 0..d {
        for c in 0..d {
            p[r * d + c] = (0..d).map(|k| u[r * d + k] * eig[k] * u[c * d + k]).sum();
        }
    }
    for r in 0..d {
        for c in 0..r {
            let m = 0.5 * (p[r * d + c] + p[c * d + r]);
            p[r * d + c] = m;
            p[c * d + r] = m;
        }
    }
    p
}

fn main() -> Result<(), fisst::Error> {
    println!("what,median_us,min_us,value");
    for d in 2..=6usize {
        let eig: Vec<f64> = (0..d).map(|k| 0.3 + 0.25 * k as f64).collect();
        let mean = vec![0.0; d];
        let s = SpatialDensity::gaussian_from_slices(&mean, &rotated(&eig))?;
        let center: Vec<f64> = (0..d).map(|k| 0.2 - 0.1 * k as f64).collect();
        let mut q = 0.0;
        let (med, min) = time_us(21, || q = s.prob_outside_ball(&center, 1.2).unwrap());
        println!("q gaussian d={d},{med:.1},{min:.1},{q:.12}");
    }
    let mut rng = Lcg(12345);
    for d in 1..=3usize {
        for n in [2usize, 10] {
            let comps: Vec<(f64, Gaussian)> = (0..n)
                .map(|j| {
                    let w = rng.next() + 0.1;
                    let m: Vec<f64> = (0..d).map(|_| 4.0 * rng.next()).collect();
                    let eig: Vec<f64> = (0..d).map(|_| 0.05 + 0.4 * rng.next()).collect();
                    let cov = if d == 1 { eig.clone() } else { rotated(&eig) };
                    let name = format!("density.mixture[{j}]");
                    (w, Gaussian::from_slices(&m, &cov, &name).unwrap())
                })
                .collect();
            let s = SpatialDensity::mixture(&GaussianMixture::new(comps, "density.mixture")?)?;
            let mut q = 0.0;
            let runs = if d == 3 { 3 } else { 11 };
            let (med, min) = time_us(runs, || q = s.mmuc(1.0).unwrap().miss_probability);
            println!("mmuc mixture d={d} n={n},{med:.1},{min:.1},{q:.12}");
        }
    }
    for (d, n) in [(1usize, 100_000usize), (2, 1000), (3, 100)] {
        let pts: Vec<Vec<f64>> = (0..n)
            .map(|_| (0..d).map(|_| 3.0 * rng.next()).collect())
            .collect();
        let s = SpatialDensity::particles(ParticleSet::new(&pts, None)?);
        let mut q = 0.0;
        let (med, min) = time_us(5, || q = s.mmuc(0.5).unwrap().miss_probability);
        println!("mmuc particles d={d} n={n},{med:.1},{min:.1},{q:.12}");
    }
    let sigmas: Vec<f64> = (1..=200).map(|i| 0.05 * i as f64).collect();
    let mut last = 0.0;
    let (med, min) = time_us(101, || {
        last = isotropic_threshold_curve(&sigmas, 1.0, &Costs::mpe(), 1).unwrap()[199];
    });
    println!("threshold curve 200 points d=1,{med:.1},{min:.1},{last:.12}");
    Ok(())
}
