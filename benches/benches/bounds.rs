//! Paper 002 bounds: the closed forms, Theorem 1 (quadrature and root-finding) and Theorem 2
//! (quadrature for n = 1, Monte Carlo beyond).
use criterion::{Criterion, criterion_group, criterion_main};
use fisst::bounds::{
    Density1, Detection, LinearGaussian, ModelI, ModelII, Sequential, TheoremOptions,
    gaussian_no_clutter, sequential_bound, theorem1, theorem2,
};
use std::hint::black_box;

fn bounds(c: &mut Criterion) {
    let prior = Density1::gaussian(1.0, 4.0).unwrap();
    let obs = LinearGaussian::new(Detection::constant(0.8).unwrap(), 1.0, 0.0, 1.0).unwrap();
    let flat = Density1::uniform(-10.0, 10.0).unwrap();
    let mut group = c.benchmark_group("bounds");
    group.sample_size(10);
    group.bench_function("gaussian_no_clutter", |b| {
        b.iter(|| gaussian_no_clutter(black_box(0.7), 0.4, 100.0, 25.0, 150.0, 200.0).unwrap())
    });
    group.bench_function("sequential_enumeration_1000", |b| {
        b.iter(|| {
            sequential_bound(Sequential::Enumeration, 0.01, 0.04, black_box(0.6), 1000).unwrap()
        })
    });
    group.bench_function("theorem1_q0.3", |b| {
        b.iter(|| {
            theorem1(
                &ModelI {
                    existence: black_box(0.6),
                    prior: &prior,
                    observation: &obs,
                    false_alarm_probability: 0.3,
                    false_alarm_density: &flat,
                    false_alarm_error: 6.0,
                    miss_error: 9.0,
                },
                &TheoremOptions::default(),
            )
            .unwrap()
        })
    });
    for (name, samples) in [
        ("theorem2_lambda1_mc2000", 2000),
        ("theorem2_lambda1_mc20000", 20_000),
    ] {
        group.bench_function(name, |b| {
            b.iter(|| {
                theorem2(
                    &ModelII {
                        existence: black_box(0.6),
                        prior: &prior,
                        observation: &obs,
                        clutter_rate: 1.0,
                        clutter_density: &flat,
                        false_alarm_error: 6.0,
                        miss_error: 9.0,
                    },
                    &TheoremOptions {
                        samples,
                        ..TheoremOptions::default()
                    },
                )
                .unwrap()
            })
        });
    }
    group.finish();
}

criterion_group!(benches, bounds);
criterion_main!(benches);
