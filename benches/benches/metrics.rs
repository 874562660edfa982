use criterion::{BenchmarkId, Criterion, criterion_group, criterion_main};
use fisst::metrics::{Gospa, Ospa};
use fisst_benches::scene;
use std::hint::black_box;

fn gospa(c: &mut Criterion) {
    let mut group = c.benchmark_group("gospa");
    group.sample_size(20);
    for n in [10, 100, 500, 1000, 2000] {
        let (truth, estimate) = scene(n, 7);
        let g = Gospa::new(5.0, 2.0, 2.0).unwrap();
        group.bench_with_input(BenchmarkId::from_parameter(n), &n, |b, _| {
            b.iter(|| {
                g.decompose(black_box(&truth), black_box(&estimate))
                    .unwrap()
            })
        });
    }
    group.finish();
    let mut group = c.benchmark_group("ospa");
    group.sample_size(20);
    for n in [10, 100, 1000] {
        let (truth, estimate) = scene(n, 7);
        let o = Ospa::new(5.0, 2.0).unwrap();
        group.bench_with_input(BenchmarkId::from_parameter(n), &n, |b, _| {
            b.iter(|| {
                o.decompose(black_box(&truth), black_box(&estimate))
                    .unwrap()
            })
        });
    }
    group.finish();
}

criterion_group!(benches, gospa);
criterion_main!(benches);
