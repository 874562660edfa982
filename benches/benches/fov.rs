use criterion::{BenchmarkId, Criterion, criterion_group, criterion_main};
use fisst::fov::{GridAxis, SceneOptions, multi_bernoulli, placement_scene, variance_map};
use fisst_benches::SplitMix;
use std::hint::black_box;

/// Inclusion probabilities r_S = r ⟨1_S, p⟩ with r uniform in [0.35, 1) and the mass uniform
/// in [0, 1) (the inputs of pmf_vs_scipy.py have the same law).
fn inclusion(m: usize) -> Vec<f64> {
    let mut rng = SplitMix::new(12);
    (0..m)
        .map(|_| (0.35 + 0.65 * rng.uniform()) * rng.uniform())
        .collect()
}

fn fov(c: &mut Criterion) {
    let mut group = c.benchmark_group("fov/pmf");
    group.sample_size(20);
    for m in [10, 100, 1000, 10_000] {
        let r = inclusion(m);
        group.bench_with_input(BenchmarkId::from_parameter(m), &m, |b, _| {
            b.iter(|| multi_bernoulli(black_box(&r)).unwrap())
        });
    }
    group.finish();
    // Section VII's map: 100 components, FoV centres on 121 × 121 points of [−3, 3]², a
    // 1 × 1 FoV (a whole number of grid steps) and a 0.97 × 0.97 one (not).
    let mut group = c.benchmark_group("fov/variance_map");
    group.sample_size(20);
    let scene = placement_scene(&SceneOptions::default()).unwrap();
    let axis = GridAxis {
        min: -3.0,
        max: 3.0,
        count: 121,
    };
    for (name, side) in [("100x121", 1.0), ("100x121-unaligned", 0.97)] {
        group.bench_function(name, |b| {
            b.iter(|| variance_map(black_box(&scene), [side, side], axis, axis).unwrap())
        });
    }
    group.finish();
}

criterion_group!(benches, fov);
criterion_main!(benches);
