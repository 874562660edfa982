use criterion::{BenchmarkId, Criterion, criterion_group, criterion_main};
use fisst::mixture::runnalls;
use fisst::splitting::{NegativeInformationScenario, split_for_region};
use fisst_benches::cloud;
use std::hint::black_box;

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
