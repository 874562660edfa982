use criterion::{BenchmarkId, Criterion, criterion_group, criterion_main};
use fisst::gaussian::{Gaussian, GaussianMixture};
use fisst::mixture::runnalls;
use fisst::splitting::{NegativeInformationScenario, split_for_region};
use std::hint::black_box;

/// A deterministic 4D mixture of `n` components (a Weyl sequence).
fn cloud(n: usize) -> GaussianMixture {
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

fn splitting(c: &mut Criterion) {
    // Algorithm 1 on each time step's prediction of the Fig. 5 scenario (w_min = 0.01, R = 3,
    // λ = 0.001).
    let scenario = NegativeInformationScenario::fig5().unwrap();
    let steps = scenario.run().unwrap();
    let mut group = c.benchmark_group("splitting/fig5_algorithm1");
    for step in &steps {
        group.bench_with_input(BenchmarkId::from_parameter(step.step), step, |b, s| {
            b.iter(|| {
                split_for_region(
                    black_box(&s.predicted),
                    &scenario.fov,
                    &scenario.library,
                    &scenario.options,
                )
                .unwrap()
            })
        });
    }
    group.finish();
    let mut group = c.benchmark_group("mixture/runnalls");
    group.sample_size(10);
    let big = cloud(1000);
    group.bench_function("1000_to_100_4d", |b| {
        b.iter(|| runnalls(black_box(&big), 100).unwrap())
    });
    group.finish();
}

criterion_group!(benches, splitting);
criterion_main!(benches);
