//! Sensor control (issue 14, paper 004): `control_step/<scheme>` is one step of Algorithm 1 at
//! the paper's size (N = 750, M = 200, 17 actions) from a state reached after 5 steps;
//! `likelihood_20/dp` and `likelihood_20/brute_force` compare (20) by the subset dynamic
//! programme with the enumeration of every association at n = 4, m = 6.
//!
//! `cargo bench --bench control -- --warm-up-time 1 --measurement-time 5`
use criterion::{BatchSize, Criterion, criterion_group, criterion_main};
use fisst::control::{ControlConfig, ControlRun, Scheme};
use fisst::smc::{brute_force_ln_likelihood, ln_likelihood};
use std::hint::black_box;

fn control_step(c: &mut Criterion) {
    let mut group = c.benchmark_group("control_step");
    group.sample_size(10);
    for (name, scheme) in [
        ("renyi", Scheme::Renyi),
        ("fisher", Scheme::Fisher),
        ("pent", Scheme::Pent),
    ] {
        let mut run = ControlRun::new(ControlConfig::paper(scheme, 1000), 3).unwrap();
        for _ in 0..5 {
            run.step().unwrap();
        }
        group.bench_function(name, |b| {
            b.iter_batched(
                || run.clone(),
                |mut r| black_box(r.step().unwrap()),
                BatchSize::SmallInput,
            )
        });
    }
    group.finish();
}

fn likelihood(c: &mut Criterion) {
    let (n, m) = (4, 6);
    let g: Vec<Vec<f64>> = (0..n)
        .map(|i| {
            (0..m)
                .map(|j| 0.01 + ((i * 7 + j * 3) % 11) as f64 * 0.003)
                .collect()
        })
        .collect();
    let density = vec![1.0 / 1414.2; m];
    let mut group = c.benchmark_group("likelihood_20");
    group.bench_function("dp", |b| {
        b.iter(|| ln_likelihood(black_box(&g), 0.95, 0.8, black_box(&density)).unwrap())
    });
    group.bench_function("brute_force", |b| {
        b.iter(|| brute_force_ln_likelihood(black_box(&g), 0.95, 0.8, black_box(&density)))
    });
    group.finish();
}

criterion_group!(benches, control_step, likelihood);
criterion_main!(benches);
