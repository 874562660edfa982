use criterion::{Criterion, criterion_group, criterion_main};
use fisst::bernoulli::SpatialDensity;
use fisst::gaussian::{Gaussian, GaussianMixture};
use fisst_benches::SplitMix;
use std::hint::black_box;

/// The inputs of `bernoulli_vs_scipy.py`: correlated 2D and 3D Gaussians, r0 = 1.
const MEAN_2D: [f64; 2] = [0.3, -0.2];
const COV_2D: [f64; 4] = [1.0, 0.6, 0.6, 0.8];
const MEAN_3D: [f64; 3] = [0.3, -0.2, 0.1];
const COV_3D: [f64; 9] = [1.0, 0.4, 0.2, 0.4, 0.8, -0.3, 0.2, -0.3, 1.5];
const RADIUS: f64 = 1.0;

/// Ten 2D components: weight in [0.2, 1), mean in [−3, 3)², standard deviations in
/// [0.3, 0.8), correlation in [−0.6, 0.6) (the same draws as `bernoulli_vs_scipy.py`).
fn mixture10() -> SpatialDensity {
    let mut rng = SplitMix::new(2026);
    let comps = (0..10)
        .map(|_| {
            let w = 0.2 + 0.8 * rng.uniform();
            let m = [-3.0 + 6.0 * rng.uniform(), -3.0 + 6.0 * rng.uniform()];
            let (sx, sy) = (0.3 + 0.5 * rng.uniform(), 0.3 + 0.5 * rng.uniform());
            let rho = -0.6 + 1.2 * rng.uniform();
            let c = rho * sx * sy;
            let g = Gaussian::from_slices(&m, &[sx * sx, c, c, sy * sy], "mixture").unwrap();
            (w, g)
        })
        .collect();
    SpatialDensity::mixture(&GaussianMixture::new(comps, "mixture").unwrap()).unwrap()
}

fn bernoulli(c: &mut Criterion) {
    let g2 = SpatialDensity::gaussian_from_slices(&MEAN_2D, &COV_2D).unwrap();
    let g3 = SpatialDensity::gaussian_from_slices(&MEAN_3D, &COV_3D).unwrap();
    let mix = mixture10();
    let mut group = c.benchmark_group("bernoulli/q");
    group.sample_size(30);
    group.bench_function("2d-off-mean", |b| {
        b.iter(|| {
            g2.prob_outside_ball(black_box(&[0.8, 0.2]), RADIUS)
                .unwrap()
        })
    });
    group.bench_function("3d-off-mean", |b| {
        b.iter(|| {
            g3.prob_outside_ball(black_box(&[0.8, 0.2, -0.4]), RADIUS)
                .unwrap()
        })
    });
    group.bench_function("mixture10-2d", |b| {
        b.iter(|| {
            mix.prob_outside_ball(black_box(&[0.5, -0.5]), RADIUS)
                .unwrap()
        })
    });
    group.finish();
    // a*: the mean and q there for a Gaussian (Sherman); the multi-start search for the mixture.
    let mut group = c.benchmark_group("bernoulli/mmuc");
    group.sample_size(20);
    group.bench_function("2d", |b| b.iter(|| black_box(&g2).mmuc(RADIUS).unwrap()));
    group.bench_function("3d", |b| b.iter(|| black_box(&g3).mmuc(RADIUS).unwrap()));
    group.bench_function("mixture10-2d", |b| {
        b.iter(|| black_box(&mix).mmuc(RADIUS).unwrap())
    });
    group.finish();
}

criterion_group!(benches, bernoulli);
criterion_main!(benches);
