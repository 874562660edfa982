//! The airport example of `001_…` Section V-C (60 steps, T = 15 s): the whole run of the GM
//! Bernoulli filter (Algorithm 3) against the Bernoulli particle filter (5,000 particles and
//! one MCMC move, the paper's settings) on the same seeded reports. Before timing it prints
//! each filter's mean MMSE position error and covariance RSS over the run, so the speed is
//! read next to the accuracy.
use criterion::{Criterion, criterion_group, criterion_main};
use fisst::filters::{
    EstimateOptions, GmBernoulliFilter, ParticleBernoulliFilter, ParticleOptions,
};
use fisst::regions::Region;
use fisst::sim::airport::{AirportScenario, airport_scenario};
use std::hint::black_box;

fn gm_run(sc: &AirportScenario, reports: &[Vec<Region>]) -> Vec<(f64, Vec<f64>, f64)> {
    let mut f = GmBernoulliFilter::new(sc.config.clone()).unwrap();
    reports
        .iter()
        .map(|r| {
            f.predict().unwrap();
            f.update(r).unwrap();
            let e = f.estimate(&EstimateOptions::default()).unwrap();
            (e.existence, e.mean.clone(), e.rss(0..2))
        })
        .collect()
}

fn pf_run(sc: &AirportScenario, reports: &[Vec<Region>], seed: u64) -> Vec<(f64, Vec<f64>, f64)> {
    let options = ParticleOptions {
        particles: 5000,
        mcmc_moves: 1,
        seed,
        ..ParticleOptions::default()
    };
    let mut f = ParticleBernoulliFilter::new(sc.config.clone(), options).unwrap();
    reports
        .iter()
        .map(|r| {
            f.predict();
            f.update(r).unwrap();
            let e = f.estimate(&EstimateOptions::default()).unwrap();
            (e.existence, e.mean.clone(), e.rss(0..2))
        })
        .collect()
}

fn accuracy(sc: &AirportScenario, out: &[(f64, Vec<f64>, f64)]) -> (f64, f64) {
    let n = out.len() as f64;
    let err = out
        .iter()
        .zip(&sc.truth)
        .map(|((_, m, _), t)| ((t.state[0] - m[0]).powi(2) + (t.state[1] - m[1]).powi(2)).sqrt())
        .sum::<f64>()
        / n;
    let rss = out.iter().map(|(_, _, r)| r).sum::<f64>() / n;
    (err, rss)
}

fn airport(c: &mut Criterion) {
    let sc = airport_scenario(1, 60).unwrap();
    let reports: Vec<Vec<Region>> = (0..60).map(|k| sc.report_regions(k)).collect();
    // Accuracy over 10 seeds (same reports for both filters in each).
    let (mut gm_acc, mut pf_acc) = ((0.0, 0.0), (0.0, 0.0));
    for seed in 1..=10 {
        let s = airport_scenario(seed, 60).unwrap();
        let r: Vec<Vec<Region>> = (0..60).map(|k| s.report_regions(k)).collect();
        let g = accuracy(&s, &gm_run(&s, &r));
        let p = accuracy(&s, &pf_run(&s, &r, seed));
        gm_acc = (gm_acc.0 + g.0 / 10.0, gm_acc.1 + g.1 / 10.0);
        pf_acc = (pf_acc.0 + p.0 / 10.0, pf_acc.1 + p.1 / 10.0);
    }
    println!(
        "airport, 10 seeds: GM mean position error {:.2} (RSS {:.2}); PF 5000 + MCMC {:.2} (RSS {:.2})",
        gm_acc.0, gm_acc.1, pf_acc.0, pf_acc.1
    );
    let mut g = c.benchmark_group("airport");
    g.sample_size(10);
    g.bench_function("gm/60", |b| b.iter(|| black_box(gm_run(&sc, &reports))));
    g.bench_function("pf5000_mcmc1/60", |b| {
        b.iter(|| black_box(pf_run(&sc, &reports, 1)))
    });
    g.finish();
}

criterion_group!(benches, airport);
criterion_main!(benches);
