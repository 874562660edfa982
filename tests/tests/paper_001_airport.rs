//! The airport example of `001_0f0df91eee9b30d5.txt`, Section V-C (Figs. 6–8): the GM
//! Bernoulli filter for imprecise measurements (Algorithm 3) and the Bernoulli particle
//! filter on the same seeded reports.
//!
//! The full reproduction — 100 seeded runs, both filters with the paper's settings (5,000
//! particles and an MCMC move) — takes a few minutes and is `#[ignore]`d:
//! `cargo test --release -p fisst-tests --test paper_001_airport -- --ignored --nocapture`.
//! The in-budget version checks the same properties on 24 runs (GM) and 4 runs (both
//! filters, 5,000 particles).

use fisst::filters::{
    EstimateOptions, FilterEstimate, GmBernoulliFilter, ParticleBernoulliFilter, ParticleOptions,
};
use fisst::sim::airport::{AirportScenario, airport_scenario};

const STEPS: usize = 60;

struct Run {
    scenario: AirportScenario,
    gm: Vec<FilterEstimate>,
    pf: Option<Vec<FilterEstimate>>,
}

fn run(seed: u64, particles: Option<usize>) -> Run {
    let scenario = airport_scenario(seed, STEPS).unwrap();
    let mut gm = GmBernoulliFilter::new(scenario.config.clone()).unwrap();
    let mut gm_est = Vec::with_capacity(STEPS);
    for k in 0..STEPS {
        gm.predict().unwrap();
        gm.update(&scenario.report_regions(k)).unwrap();
        gm_est.push(gm.estimate(&EstimateOptions::default()).unwrap());
    }
    let pf = particles.map(|n| {
        let options = ParticleOptions {
            particles: n,
            seed: seed + 1000,
            ..ParticleOptions::default()
        };
        let mut pf = ParticleBernoulliFilter::new(scenario.config.clone(), options).unwrap();
        (0..STEPS)
            .map(|k| {
                pf.predict();
                pf.update(&scenario.report_regions(k)).unwrap();
                pf.estimate(&EstimateOptions::default()).unwrap()
            })
            .collect()
    });
    Run {
        scenario,
        gm: gm_est,
        pf,
    }
}

/// Runs `seeds` on two threads (the machine's cores), in seed order.
fn runs(seeds: std::ops::Range<u64>, particles: Option<usize>) -> Vec<Run> {
    let seeds: Vec<u64> = seeds.collect();
    let half = seeds.len().div_ceil(2);
    std::thread::scope(|s| {
        let handles: Vec<_> = seeds
            .chunks(half.max(1))
            .map(|chunk| {
                s.spawn(move || chunk.iter().map(|&k| run(k, particles)).collect::<Vec<_>>())
            })
            .collect();
        handles
            .into_iter()
            .flat_map(|h| h.join().unwrap())
            .collect()
    })
}

/// The squared Mahalanobis distance of the true position from the posterior's position
/// mean under its position covariance.
fn position_nees(e: &FilterEstimate, truth: &[f64; 4]) -> f64 {
    let (dx, dy) = (truth[0] - e.mean[0], truth[1] - e.mean[1]);
    let (a, b, c) = (e.cov[0][0], e.cov[0][1], e.cov[1][1]);
    (c * dx * dx - 2.0 * b * dx * dy + a * dy * dy) / (a * c - b * b)
}

fn position_error(e: &FilterEstimate, truth: &[f64; 4]) -> f64 {
    ((truth[0] - e.mean[0]).powi(2) + (truth[1] - e.mean[1]).powi(2)).sqrt()
}

fn velocity_rss(e: &FilterEstimate) -> f64 {
    (e.cov[2][2] + e.cov[3][3]).sqrt()
}

fn median(mut v: Vec<f64>) -> f64 {
    v.sort_by(f64::total_cmp);
    v[v.len() / 2]
}

struct Summary {
    coverage: f64,
    mean_error: f64,
    mean_rss: f64,
    median_velocity_rss: f64,
    mean_velocity_error: f64,
    miss_streaks: usize,
    /// Empty scans that lowered the existence / all empty scans (after step 3).
    empty_scans_lowering: (usize, usize),
    /// Position RSS at the end of a streak of ≥ 2 empty scans over the run's median RSS.
    rss_growth_after_misses: f64,
    /// Existence at the end of such a streak (median).
    existence_after_misses: f64,
    /// Existence one step after the streak ends with a report (median).
    existence_recovered: f64,
}

fn summarise(runs: &[Run], pick: impl Fn(&Run) -> &[FilterEstimate]) -> Summary {
    let (mut inside, mut total) = (0usize, 0usize);
    let (mut err, mut rss, mut verr) = (0.0, 0.0, 0.0);
    let mut vrss = Vec::new();
    let mut streaks = 0;
    let (mut lowered, mut empties) = (0, 0);
    let mut growth = Vec::new();
    let (mut after, mut recovered) = (Vec::new(), Vec::new());
    for r in runs {
        let est = pick(r);
        let rss_run: Vec<f64> = est.iter().map(|e| e.rss(0..2)).collect();
        let med = median(rss_run.clone());
        let mut streak = 0;
        for (k, e) in est.iter().enumerate() {
            let t = &r.scenario.truth[k].state;
            total += 1;
            if position_nees(e, t) <= 9.0 {
                inside += 1;
            }
            err += position_error(e, t);
            rss += rss_run[k];
            verr += ((t[2] - e.mean[2]).powi(2) + (t[3] - e.mean[3]).powi(2)).sqrt();
            if k >= 5 {
                vrss.push(velocity_rss(e));
            }
            let empty = r.scenario.reports[k].is_empty();
            if empty && k >= 3 {
                empties += 1;
                if e.existence < est[k - 1].existence {
                    lowered += 1;
                }
            }
            if empty {
                streak += 1;
            } else {
                if streak >= 2 && k >= 4 {
                    streaks += 1;
                    growth.push(rss_run[k - 1] / med);
                    after.push(est[k - 1].existence);
                    recovered.push(e.existence);
                }
                streak = 0;
            }
        }
    }
    Summary {
        coverage: inside as f64 / total as f64,
        mean_error: err / total as f64,
        mean_rss: rss / total as f64,
        median_velocity_rss: median(vrss),
        mean_velocity_error: verr / total as f64,
        miss_streaks: streaks,
        empty_scans_lowering: (lowered, empties),
        rss_growth_after_misses: median(growth),
        existence_after_misses: median(after),
        existence_recovered: median(recovered),
    }
}

fn print(label: &str, s: &Summary) {
    println!(
        "{label}: 3σ coverage {:.4}, mean position error {:.2}, mean position RSS {:.2}, median velocity RSS {:.3}, mean velocity error {:.3}; {} streaks of ≥2 empty scans: RSS ×{:.2} of the median, existence {:.3} → {:.3} after the next report; empty scans lowering r {}/{}",
        s.coverage,
        s.mean_error,
        s.mean_rss,
        s.median_velocity_rss,
        s.mean_velocity_error,
        s.miss_streaks,
        s.rss_growth_after_misses,
        s.existence_after_misses,
        s.existence_recovered,
        s.empty_scans_lowering.0,
        s.empty_scans_lowering.1,
    );
}

/// The checks shared by the in-budget and the full runs.
///
/// - Fig. 7a: the truth lies inside the posterior's 3σ position ellipse (moment-matched)
///   at ≥ 95 % of the steps.
/// - Fig. 7b: every empty scan lowers the existence (the negative information), so it
///   drops over consecutive misses, and the next report restores it.
/// - Fig. 8: the velocity RSS settles at 0.4–0.9 dist/s, the paper's "approximately 0.7" (here
///   0.48–0.56; its lower bound is set by
///   ϖ = 0.004 and T = 15 s); the position RSS grows over consecutive misses (the paper's
///   largest uncertainty follows three misses); the position error is of the order of the
///   RSS (here below it: the mixture is conservative).
fn check(label: &str, s: &Summary) {
    print(label, s);
    assert!(s.coverage >= 0.95, "{label}: coverage {}", s.coverage);
    assert!(
        (0.4..=0.9).contains(&s.median_velocity_rss),
        "{label}: velocity RSS {}",
        s.median_velocity_rss
    );
    assert!(s.mean_error < s.mean_rss, "{label}: error above RSS");
    assert!(
        (5.0..=30.0).contains(&s.mean_rss),
        "{label}: RSS {}",
        s.mean_rss
    );
    assert!(s.miss_streaks > 0);
    assert!(
        s.rss_growth_after_misses > 1.2,
        "{label}: {}",
        s.rss_growth_after_misses
    );
    assert!(
        s.existence_recovered > s.existence_after_misses,
        "{label}: existence does not recover"
    );
    let (lowered, empties) = s.empty_scans_lowering;
    assert!(
        lowered as f64 >= 0.95 * empties as f64,
        "{label}: {lowered}/{empties}"
    );
}

/// Existence of the two filters: mean, 95th percentile and largest |r_GM − r_PF| over all
/// steps.
fn existence_gap(runs: &[Run]) -> (f64, f64, f64) {
    let mut gaps: Vec<f64> = runs
        .iter()
        .flat_map(|r| {
            r.gm.iter()
                .zip(r.pf.as_ref().unwrap())
                .map(|(g, p)| (g.existence - p.existence).abs())
        })
        .collect();
    let mean = gaps.iter().sum::<f64>() / gaps.len() as f64;
    gaps.sort_by(f64::total_cmp);
    let p95 = gaps[(gaps.len() * 95) / 100];
    (mean, p95, *gaps.last().unwrap())
}

/// The existence of the two filters agree to a mean |r_GM − r_PF| below 0.03, a 95th
/// percentile below 0.15 and a largest gap below 0.5 (100 runs, 5,000 particles: measured
/// 0.0074, 0.041 and 0.41). The largest gaps are lapses of the particle filter: in seed 40 its
/// existence falls to 0.54 over three steps in which true reports keep arriving (the GM
/// filter's stays at 0.95–0.999) because too few particles were left in the reported discs;
/// otherwise they differ most late in streaks of empty scans. With fewer particles such
/// lapses grow (1,000 particles: a gap of 0.76; 2,500: 0.88), so both checks use the
/// paper's 5,000.
#[test]
fn fig7_fig8_airport_gm_and_particle_filters_in_budget() {
    let gm_runs = runs(1..25, None);
    check("GM, 24 runs", &summarise(&gm_runs, |r| &r.gm));
    let both = runs(101..105, Some(5000));
    check("GM, 4 runs", &summarise(&both, |r| &r.gm));
    check(
        "PF (5000 particles + MCMC), 4 runs",
        &summarise(&both, |r| r.pf.as_deref().unwrap()),
    );
    let (mean, p95, max) = existence_gap(&both);
    println!("existence |GM − PF|: mean {mean:.4}, 95th percentile {p95:.4}, max {max:.4}");
    assert!(mean < 0.03 && p95 < 0.15 && max < 0.5, "{mean} {p95} {max}");
}

#[test]
#[ignore]
fn fig7_fig8_airport_gm_and_particle_filters_100_runs() {
    let all = runs(1..101, Some(5000));
    check("GM, 100 runs", &summarise(&all, |r| &r.gm));
    check(
        "PF (5000 particles + MCMC), 100 runs",
        &summarise(&all, |r| r.pf.as_deref().unwrap()),
    );
    let (mean, p95, max) = existence_gap(&all);
    println!("existence |GM − PF|: mean {mean:.4}, 95th percentile {p95:.4}, max {max:.4}");
    assert!(mean < 0.03 && p95 < 0.15 && max < 0.5, "{mean} {p95} {max}");
}

#[test]
fn fig6_airport_scenario_is_seeded_and_respects_the_layout() {
    let a = airport_scenario(7, STEPS).unwrap();
    let b = airport_scenario(7, STEPS).unwrap();
    assert_eq!(a.truth, b.truth);
    assert_eq!(a.reports, b.reports);
    assert_ne!(a.reports, airport_scenario(8, STEPS).unwrap().reports);
    assert_eq!(a.anchors.len(), 10);
    for s in 1..30 {
        let sc = airport_scenario(s, STEPS).unwrap();
        for (k, t) in sc.truth.iter().enumerate() {
            assert!(
                !sc.exclusions.iter().any(|e| e.contains(&t.state)),
                "seed {s} step {k}"
            );
            assert_eq!(t.t, 15.0 * (k + 1) as f64);
            // A true report names an anchor whose disc holds the person.
            if let Some(a) = sc.true_reports[k] {
                assert!(sc.anchors[a].disc().unwrap().contains(&t.state));
                assert!(sc.reports[k].contains(&a));
            }
            assert_eq!(sc.in_fov[k], sc.fov.contains(&t.state));
        }
    }
    // The radii are 2 d_a / 3, d_a the distance to the nearest other anchor.
    for (i, x) in a.anchors.iter().enumerate() {
        let d = a
            .anchors
            .iter()
            .enumerate()
            .filter(|(j, _)| *j != i)
            .map(|(_, y)| {
                ((x.position[0] - y.position[0]).powi(2) + (x.position[1] - y.position[1]).powi(2))
                    .sqrt()
            })
            .fold(f64::INFINITY, f64::min);
        assert!((x.radius - 2.0 * d / 3.0).abs() < 1e-12);
    }
}
