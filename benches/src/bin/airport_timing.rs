//! The airport example of `001_…` Section V-C, natively, outside criterion:
//!
//! ```text
//! airport_timing time [reps]          wall time of one 60-step run, GM and PF (median of reps)
//! airport_timing table [reps]         the same per seed 1..=10: GM ms, PF ms, PF/GM (issue 29)
//! airport_timing curve [runs]         GM only, one knob at a time (N_g, merge distance,
//!                                     L_max, prune threshold): mean position error and 3σ
//!                                     coverage over seeds 1..=runs (default 100) against the
//!                                     mean time per run (the accuracy / time trade-off)
//! airport_timing gm [reps]            only the GM filter, seed 1 (for callgrind / perf)
//! airport_timing dump [runs]          every GM estimate of seeds 1..=runs, exactly
//! airport_timing stats                 per-step component counts of seed 1 (GM)
//! airport_timing accuracy [runs]      both filters over seeds 1..=runs (default 100):
//!                                     3σ coverage, mean position error, mean position RSS
//! ```
//!
//! A third argument sets the GM filter's grid N_g (`SplitOptions::grid_points`, default 15),
//! e.g. `airport_timing accuracy 100 7`; a fourth the prune threshold (default 1e-6),
//! e.g. `airport_timing gm 1 15 1e-4`.
//!
//! The PF has 5,000 particles and one MCMC move (the paper's settings), seed 1000 + seed.
//!
//! Measured (issue 29, goal 1; 2026-12-05, 422dfaa, load average 0.7–1.0):
//! `table 3`: GM 14.95–15.85 ms, PF 134.5–139.3 ms, PF/GM 8.6–9.2× (mean 8.9×; the goal is
//! 20× on every seed). `accuracy 100`: GM mean position error 9.274 (3σ coverage 0.9940,
//! 15.6 ms per run), PF 8.817 (0.9865, 135.6 ms). `curve 100`: the reduction and grid knobs
//! move the GM's error only within 9.23–9.39 (merge 0.5: 9.79); w_min, the weight below which
//! Algorithm 2 leaves a component unsplit, is the knob that matters:
//!
//! ```text
//! w_min          0.03   0.01 (default)  0.005  0.003  0.002  0.001  0.001 with N_g 5
//! error          9.640  9.274           9.151  9.126  9.074  8.974  8.979
//! ms per run     6.12   15.66           28.50  44.63  64.23  113.4  82.3
//! ```
//!
//! so on this algorithm the goal's two conditions pull apart: 20× the PF (≤ 6.8 ms) is
//! w_min ≈ 0.03 at error 9.64, and even w_min = 0.001, at 113 ms (1.2× the PF), stays above
//! the PF's 8.82. The default 0.01 is the curve's knee: from 0.03 to 0.01 the error falls by
//! 0.37 for 9.5 ms more, from 0.01 to 0.005 by 0.12 for 12.8 ms more, from 0.005 to 0.003 by
//! 0.025 for 16 ms more. Over seeds 1–20 (the w_min knob set by hand) the GM first matches the
//! PF at w_min = 0.0003: error 9.106 against the PF's 9.124, at 397 ms per run, 2.9× the PF's
//! time; a larger merge distance (3) saves time at no cost in error (w_min 0.001: 9.165 at
//! 103 ms against 9.195 at 122 ms). Equal error at 20× the speed would take the fine-split
//! GM about 60× faster: not a matter of settings. Tried, and worse (seeds 1–20, by a
//! temporary switch): the update's p_D and likelihoods averaged over each component's
//! position marginal by a 3×3 or 5×5 Gauss–Hermite rule instead of taken at its mean
//! (Appendix B's zeroth order): error 9.475 / 9.637 against 9.406, position RSS 17.8 against
//! 15.7: with the means left in place, averaging only re-weights a straddling component where
//! the split truncates it.
use fisst::filters::{
    EstimateOptions, FilterEstimate, GmBernoulliFilter, ParticleBernoulliFilter, ParticleOptions,
};
use fisst::regions::Region;
use fisst::sim::airport::{AirportScenario, airport_scenario};
use std::time::Instant;

const STEPS: usize = 60;

/// The GM filter's collocation grid N_g: the third argument, else the default (15).
fn grid_points() -> Option<usize> {
    std::env::args().nth(3).and_then(|s| s.parse().ok())
}

fn gm_run(sc: &AirportScenario, reports: &[Vec<Region>]) -> Vec<FilterEstimate> {
    gm_run_with(
        sc,
        reports,
        Knobs {
            grid: grid_points(),
            prune: std::env::args().nth(4).and_then(|s| s.parse().ok()),
            ..Knobs::default()
        },
    )
}

/// The GM filter's knobs that `curve` varies (`None`: the scenario's default).
#[derive(Clone, Copy, Default)]
struct Knobs {
    /// N_g of eqs. (20)–(22).
    grid: Option<usize>,
    /// The Mahalanobis merge distance of the reduction (default 2).
    merge: Option<f64>,
    /// Runnalls' L_max (default 100).
    keep: Option<usize>,
    /// The prune threshold (default 1e-6).
    prune: Option<f64>,
    /// w_min of Algorithm 2, the weight below which a component is not split (default 0.01).
    min_weight: Option<f64>,
    /// ζ, the half-width of the collocation grid in standard deviations (default 2).
    zeta: Option<f64>,
}

/// The GM filter with `knobs`.
fn gm_run_with(sc: &AirportScenario, reports: &[Vec<Region>], knobs: Knobs) -> Vec<FilterEstimate> {
    let mut config = sc.config.clone();
    if let Some(g) = knobs.grid {
        config.splitting.options.grid_points = g;
    }
    if let Some(d) = knobs.merge {
        config.reduction.merge_distance = Some(d);
    }
    if let Some(k) = knobs.keep {
        config.reduction.max_components = Some(k);
    }
    if let Some(p) = knobs.prune {
        config.reduction.prune_below = p;
    }
    if let Some(w) = knobs.min_weight {
        config.splitting.options.min_weight = w;
    }
    if let Some(z) = knobs.zeta {
        config.splitting.options.grid_bound = z;
    }
    let mut f = GmBernoulliFilter::new(config).unwrap();
    reports
        .iter()
        .map(|r| {
            f.predict().unwrap();
            f.update(r).unwrap();
            f.estimate(&EstimateOptions::default()).unwrap()
        })
        .collect()
}

fn pf_run(sc: &AirportScenario, reports: &[Vec<Region>], seed: u64) -> Vec<FilterEstimate> {
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
            f.estimate(&EstimateOptions::default()).unwrap()
        })
        .collect()
}

fn reports(sc: &AirportScenario) -> Vec<Vec<Region>> {
    (0..sc.reports.len())
        .map(|k| sc.report_regions(k))
        .collect()
}

fn median(mut v: Vec<f64>) -> f64 {
    v.sort_by(f64::total_cmp);
    v[v.len() / 2]
}

/// (3σ hits, position error sum, RSS sum, steps).
fn score(sc: &AirportScenario, est: &[FilterEstimate]) -> (usize, f64, f64, usize) {
    let (mut hits, mut err, mut rss) = (0, 0.0, 0.0);
    for (e, t) in est.iter().zip(&sc.truth) {
        let t = &t.state;
        let (dx, dy) = (t[0] - e.mean[0], t[1] - e.mean[1]);
        let (a, b, c) = (e.cov[0][0], e.cov[0][1], e.cov[1][1]);
        if (c * dx * dx - 2.0 * b * dx * dy + a * dy * dy) / (a * c - b * b) <= 9.0 {
            hits += 1;
        }
        err += (dx * dx + dy * dy).sqrt();
        rss += e.rss(0..2);
    }
    (hits, err, rss, est.len())
}

/// The median wall time in seconds of `reps` calls of `f` after one untimed warm-up call.
fn time_after_warmup(reps: usize, f: &dyn Fn()) -> f64 {
    f();
    median(
        (0..reps)
            .map(|_| {
                let t = Instant::now();
                f();
                t.elapsed().as_secs_f64()
            })
            .collect(),
    )
}

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let mode = args.get(1).map(String::as_str).unwrap_or("time");
    let n: usize = args.get(2).and_then(|s| s.parse().ok()).unwrap_or(0);
    match mode {
        "gm" => {
            let sc = airport_scenario(1, STEPS).unwrap();
            let r = reports(&sc);
            for _ in 0..n.max(1) {
                std::hint::black_box(gm_run(&sc, &r));
            }
        }
        "time" => {
            let reps = if n == 0 { 11 } else { n };
            let sc = airport_scenario(1, STEPS).unwrap();
            let r = reports(&sc);
            let time = |f: &dyn Fn()| time_after_warmup(reps, f);
            let gm = time(&|| {
                std::hint::black_box(gm_run(&sc, &r));
            });
            let pf = time(&|| {
                std::hint::black_box(pf_run(&sc, &r, 1));
            });
            println!(
                "airport 60 steps, seed 1, median of {reps}: GM {:.2} ms, PF 5000 + MCMC {:.2} ms, PF/GM {:.1}×",
                gm * 1e3,
                pf * 1e3,
                pf / gm
            );
        }
        "table" => {
            // Issue 29's table: each seed timed after one warm-up run of each filter.
            let reps = if n == 0 { 5 } else { n };
            println!("airport 60 steps, median of {reps} after one warm-up run");
            println!("seed   GM ms    PF ms   PF/GM");
            let (mut worst, mut gsum, mut psum) = (f64::INFINITY, 0.0, 0.0);
            for seed in 1..=10u64 {
                let sc = airport_scenario(seed, STEPS).unwrap();
                let r = reports(&sc);
                let time = |f: &dyn Fn()| time_after_warmup(reps, f);
                let gm = time(&|| {
                    std::hint::black_box(gm_run(&sc, &r));
                });
                let pf = time(&|| {
                    std::hint::black_box(pf_run(&sc, &r, seed));
                });
                worst = worst.min(pf / gm);
                gsum += gm;
                psum += pf;
                println!(
                    "{seed:>4} {:>7.2} {:>8.2} {:>6.1}×",
                    gm * 1e3,
                    pf * 1e3,
                    pf / gm
                );
            }
            println!(
                "mean {:>7.2} {:>8.2} {:>6.1}×  (worst seed {worst:.1}×)",
                gsum * 1e2,
                psum * 1e2,
                psum / gsum
            );
        }
        "curve" => {
            // Issue 29: the GM filter's error against its time as N_g (eqs. (20)–(22)) varies.
            let runs = if n == 0 { 100 } else { n };
            let scenarios: Vec<_> = (1..=runs as u64)
                .map(|seed| {
                    let sc = airport_scenario(seed, STEPS).unwrap();
                    let r = reports(&sc);
                    (sc, r)
                })
                .collect();
            println!(
                "airport GM, {runs} seeded runs of {STEPS} steps (defaults: N_g 15, merge 2, L_max 100, prune 1e-6)"
            );
            println!("knob                  mean pos. error  3σ coverage  ms per run");
            let mut rows: Vec<(String, Knobs)> = Vec::new();
            for g in [5, 7, 9, 11, 15, 19] {
                rows.push((
                    format!("N_g {g}"),
                    Knobs {
                        grid: Some(g),
                        ..Knobs::default()
                    },
                ));
            }
            for d in [0.5, 1.0, 1.5, 3.0, 4.0] {
                rows.push((
                    format!("merge {d}"),
                    Knobs {
                        merge: Some(d),
                        ..Knobs::default()
                    },
                ));
            }
            for k in [10, 20, 50, 200] {
                rows.push((
                    format!("L_max {k}"),
                    Knobs {
                        keep: Some(k),
                        ..Knobs::default()
                    },
                ));
            }
            for p in [1e-5, 3e-5, 1e-4, 3e-4, 1e-3] {
                rows.push((
                    format!("prune {p:e}"),
                    Knobs {
                        prune: Some(p),
                        ..Knobs::default()
                    },
                ));
            }
            for w in [0.03, 0.005, 0.003, 0.002, 0.001] {
                rows.push((
                    format!("w_min {w}"),
                    Knobs {
                        min_weight: Some(w),
                        ..Knobs::default()
                    },
                ));
            }
            for z in [1.5, 2.5, 3.0] {
                rows.push((
                    format!("zeta {z}"),
                    Knobs {
                        zeta: Some(z),
                        ..Knobs::default()
                    },
                ));
            }
            // Finer splitting on a coarser grid: the accuracy of a small w_min at less cost.
            for (w, g) in [(0.003, 7), (0.001, 7), (0.001, 5)] {
                rows.push((
                    format!("w_min {w}, N_g {g}"),
                    Knobs {
                        min_weight: Some(w),
                        grid: Some(g),
                        ..Knobs::default()
                    },
                ));
            }
            for (name, knobs) in rows {
                let (mut s, mut t) = ((0, 0.0, 0.0, 0), 0.0);
                for (sc, r) in &scenarios {
                    let t0 = Instant::now();
                    let e = gm_run_with(sc, r, knobs);
                    t += t0.elapsed().as_secs_f64();
                    let a = score(sc, &e);
                    s = (s.0 + a.0, s.1 + a.1, s.2 + a.2, s.3 + a.3);
                }
                println!(
                    "{name:<20}  {:>15.3}  {:>11.4}  {:>10.2}",
                    s.1 / s.3 as f64,
                    s.0 as f64 / s.3 as f64,
                    t * 1e3 / runs as f64
                );
            }
        }
        "accuracy" => {
            let runs = if n == 0 { 100 } else { n };
            let (mut g, mut p) = ((0, 0.0, 0.0, 0), (0, 0.0, 0.0, 0));
            let (mut tg, mut tp) = (0.0, 0.0);
            for seed in 1..=runs as u64 {
                let sc = airport_scenario(seed, STEPS).unwrap();
                let r = reports(&sc);
                let t = Instant::now();
                let ge = gm_run(&sc, &r);
                tg += t.elapsed().as_secs_f64();
                let t = Instant::now();
                let pe = pf_run(&sc, &r, seed + 1000);
                tp += t.elapsed().as_secs_f64();
                let (a, b) = (score(&sc, &ge), score(&sc, &pe));
                g = (g.0 + a.0, g.1 + a.1, g.2 + a.2, g.3 + a.3);
                p = (p.0 + b.0, p.1 + b.1, p.2 + b.2, p.3 + b.3);
            }
            let line = |name: &str, s: (usize, f64, f64, usize), t: f64| {
                println!(
                    "{name}: 3σ coverage {:.4}, mean position error {:.3}, mean position RSS {:.3}, {:.2} ms per run",
                    s.0 as f64 / s.3 as f64,
                    s.1 / s.3 as f64,
                    s.2 / s.3 as f64,
                    t * 1e3 / runs as f64
                );
            };
            println!("airport, {runs} seeded runs of {STEPS} steps (seeds 1..={runs}):");
            line("GM", g, tg);
            line("PF 5000 + MCMC", p, tp);
        }
        "stats" => stats(),
        "dump" => {
            // Every GM estimate of seeds 1..=n, exactly (to compare two builds bit for bit).
            for seed in 1..=n.max(1) as u64 {
                let sc = airport_scenario(seed, STEPS).unwrap();
                for (k, e) in gm_run(&sc, &reports(&sc)).iter().enumerate() {
                    println!("{seed} {k} {:?} {:?} {:?}", e.existence, e.mean, e.cov);
                }
            }
        }
        other => {
            panic!("mode must be time, table, curve, gm, stats, dump or accuracy, got {other}")
        }
    }
}

#[allow(dead_code)]
fn stats() {
    let sc = airport_scenario(1, STEPS).unwrap();
    let r = reports(&sc);
    let mut f = GmBernoulliFilter::new(sc.config.clone()).unwrap();
    for (k, rep) in r.iter().enumerate() {
        f.predict().unwrap();
        let pred = f.mixture().len();
        let info = f.update(rep).unwrap();
        println!(
            "step {k}: reports {}, predicted {pred}, split {}, posterior {}, r {:.3}",
            rep.len(),
            info.split_components,
            f.mixture().len(),
            f.existence()
        );
    }
}
