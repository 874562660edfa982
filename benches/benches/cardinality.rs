use criterion::{BenchmarkId, Criterion, criterion_group, criterion_main};
use fisst::cardinality::multi_bernoulli_cardinality;
use fisst::estimators::multi_bernoulli::{SetMetric, optimal_estimate};
use fisst_benches::SplitMix;
use std::hint::black_box;

fn existence(m: usize) -> Vec<f64> {
    let mut rng = SplitMix::new(11);
    (0..m).map(|_| 0.35 + 0.65 * rng.uniform()).collect()
}

fn cardinality(c: &mut Criterion) {
    let mut group = c.benchmark_group("cardinality");
    group.sample_size(20);
    for m in [10, 100, 1000, 10_000] {
        let r = existence(m);
        group.bench_with_input(BenchmarkId::from_parameter(m), &m, |b, _| {
            b.iter(|| multi_bernoulli_cardinality(black_box(&r)).unwrap())
        });
    }
    group.finish();
    let mut group = c.benchmark_group("mb_optimal_ospa");
    group.sample_size(10);
    for m in [10, 100, 1000] {
        let r = existence(m);
        group.bench_with_input(BenchmarkId::from_parameter(m), &m, |b, _| {
            b.iter(|| optimal_estimate(black_box(&r), SetMetric::Ospa, 1.0, 2.0).unwrap())
        });
    }
    group.finish();
}

criterion_group!(benches, cardinality);
criterion_main!(benches);
