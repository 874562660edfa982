//! OSPA/GOSPA on scenes of every density (issue 15): `gospa/<n>` and `ospa/<n>` are the sparse
//! scenes of the first version (ids kept), `gospa_percolating/<n>` the percolating scene (a
//! giant component), `gospa_all_pairs/<n>` the same points with every pair closer than c;
//! `gospa_before_*` the method before issue 15 ([`fisst_benches::baseline_gospa`]) on the same
//! scenes; `gospa_series/<steps>` and `ospa_series/<steps>` whole scenarios.
//!
//! `cargo bench --bench metrics -- --warm-up-time 1 --measurement-time 3`
use criterion::{BenchmarkId, Criterion, criterion_group, criterion_main};
use fisst::metrics::{Gospa, Ospa};
use fisst_benches::{C, SplitMix, all_pairs_cutoff, baseline_gospa, percolating_scene, scene};
use std::hint::black_box;

fn gospa(c: &mut Criterion) {
    let g = Gospa::new(C, 2.0, 2.0).unwrap();
    let mut group = c.benchmark_group("gospa");
    group.sample_size(20);
    for n in [10, 100, 500, 1000, 2000] {
        let (truth, estimate) = scene(n, 7);
        group.bench_with_input(BenchmarkId::from_parameter(n), &n, |b, _| {
            b.iter(|| {
                g.decompose(black_box(&truth), black_box(&estimate))
                    .unwrap()
            })
        });
    }
    group.finish();
    let mut group = c.benchmark_group("gospa_before_sparse");
    group.sample_size(10);
    for n in [100, 1000, 2000] {
        let (truth, estimate) = scene(n, 7);
        group.bench_with_input(BenchmarkId::from_parameter(n), &n, |b, _| {
            b.iter(|| baseline_gospa(black_box(&truth), black_box(&estimate), C, 2.0))
        });
    }
    group.finish();
    let mut group = c.benchmark_group("gospa_percolating");
    group.sample_size(10);
    for n in [1000, 5000, 20_000, 100_000] {
        let (truth, estimate) = percolating_scene(n, 7);
        group.bench_with_input(BenchmarkId::from_parameter(n), &n, |b, _| {
            b.iter(|| {
                g.decompose(black_box(&truth), black_box(&estimate))
                    .unwrap()
            })
        });
    }
    group.finish();
    let mut group = c.benchmark_group("gospa_before_percolating");
    group.sample_size(10);
    for n in [1000, 5000] {
        let (truth, estimate) = percolating_scene(n, 7);
        group.bench_with_input(BenchmarkId::from_parameter(n), &n, |b, _| {
            b.iter(|| baseline_gospa(black_box(&truth), black_box(&estimate), C, 2.0))
        });
    }
    group.finish();
    let mut group = c.benchmark_group("gospa_all_pairs");
    group.sample_size(10);
    for n in [100, 500, 1000] {
        let (truth, estimate) = percolating_scene(n, 7);
        let g = Gospa::new(all_pairs_cutoff(n), 2.0, 2.0).unwrap();
        group.bench_with_input(BenchmarkId::from_parameter(n), &n, |b, _| {
            b.iter(|| {
                g.decompose(black_box(&truth), black_box(&estimate))
                    .unwrap()
            })
        });
    }
    group.finish();
    let mut group = c.benchmark_group("gospa_before_all_pairs");
    group.sample_size(10);
    for n in [100, 500, 1000] {
        let (truth, estimate) = percolating_scene(n, 7);
        let cut = all_pairs_cutoff(n);
        group.bench_with_input(BenchmarkId::from_parameter(n), &n, |b, _| {
            b.iter(|| baseline_gospa(black_box(&truth), black_box(&estimate), cut, 2.0))
        });
    }
    group.finish();
}

fn ospa(c: &mut Criterion) {
    let o = Ospa::new(C, 2.0).unwrap();
    let mut group = c.benchmark_group("ospa");
    group.sample_size(20);
    for n in [10, 100, 1000] {
        let (truth, estimate) = scene(n, 7);
        group.bench_with_input(BenchmarkId::from_parameter(n), &n, |b, _| {
            b.iter(|| {
                o.decompose(black_box(&truth), black_box(&estimate))
                    .unwrap()
            })
        });
    }
    group.finish();
    let mut group = c.benchmark_group("ospa_percolating");
    group.sample_size(10);
    for n in [1000, 5000] {
        let (truth, estimate) = percolating_scene(n, 7);
        group.bench_with_input(BenchmarkId::from_parameter(n), &n, |b, _| {
            b.iter(|| {
                o.decompose(black_box(&truth), black_box(&estimate))
                    .unwrap()
            })
        });
    }
    group.finish();
}

/// A scenario of `steps` steps with 10–50 truths per step in [0, 1000]², 90 % detected with
/// noise, 0–5 false estimates (the shape of `gospa_vs_stonesoup.py`'s).
fn scenario(steps: usize) -> (Vec<Vec<[f64; 2]>>, Vec<Vec<[f64; 2]>>) {
    let mut rng = SplitMix::new(11);
    let (mut truths, mut estimates) = (vec![], vec![]);
    for _ in 0..steps {
        let n = 10 + (rng.uniform() * 41.0) as usize;
        let x: Vec<[f64; 2]> = (0..n)
            .map(|_| [1000.0 * rng.uniform(), 1000.0 * rng.uniform()])
            .collect();
        let mut y = vec![];
        for t in &x {
            if rng.uniform() < 0.9 {
                y.push([t[0] + 2.0 * rng.normal(), t[1] + 2.0 * rng.normal()]);
            }
        }
        for _ in 0..(rng.uniform() * 6.0) as usize {
            y.push([1000.0 * rng.uniform(), 1000.0 * rng.uniform()]);
        }
        truths.push(x);
        estimates.push(y);
    }
    (truths, estimates)
}

fn series(c: &mut Criterion) {
    let g = Gospa::new(10.0, 2.0, 2.0).unwrap();
    let o = Ospa::new(10.0, 2.0).unwrap();
    let mut group = c.benchmark_group("gospa_series");
    group.sample_size(10);
    for steps in [100, 1000] {
        let (truths, estimates) = scenario(steps);
        group.bench_with_input(BenchmarkId::from_parameter(steps), &steps, |b, _| {
            b.iter(|| g.series(black_box(&truths), black_box(&estimates)).unwrap())
        });
    }
    group.finish();
    let mut group = c.benchmark_group("ospa_series");
    group.sample_size(10);
    let (truths, estimates) = scenario(1000);
    group.bench_with_input(BenchmarkId::from_parameter(1000), &1000, |b, _| {
        b.iter(|| o.series(black_box(&truths), black_box(&estimates)).unwrap())
    });
    group.finish();
}

criterion_group!(benches, gospa, ospa, series);
criterion_main!(benches);
