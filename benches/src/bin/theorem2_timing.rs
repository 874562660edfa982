//! Times the n = 2 terms of Theorem 2 (25) of paper 002 natively on linear-Gaussian models
//! (prior N(1, 4), g(z|x) = N(z; x, 1), constant P_o, uniform or Gaussian clutter):
//!
//! `cd benches && cargo run --release --bin theorem2_timing [repetitions]`
//!
//! For each model prints the median milliseconds of `theorem2` with only n = 1
//! (`max_clutter` 0), with n = 1 and the n = 2 cubature (`quadrature_cardinality` 2,
//! `max_clutter` 1: no Monte Carlo), their difference (the n = 2 cubature's time), and the
//! n = 2 terms (w_2, J'_2⁻¹, null_2 with their error estimates). Then the median time of the
//! 21-point Theorem 2 curve of web/bounds.html (prior N(0.5, 4), g = N(x, 1), P_o 0.8,
//! clutter N(0, 25) of rate λ ∈ {1, 3}, r = 0, 0.05, …, 1, 2000 Monte Carlo samples for
//! n ≥ 3, the default options otherwise), with `quadrature_cardinality` 1 and 2.
//!
//! Medians of 5 (ms, x86-64 release, 2 shared cores, load average 1.8–2.5), before and after
//! the n = 2 cubature's outer breakpoints (where the MAP section changes form) and its
//! narrow-section fix, and m(z) in closed form for n = 1 and the Monte Carlo's table:
//!
//! | model (prior N(1, 4), g = N(x, 1)) | n = 2 before | n = 2 after | n = 1 before | n = 1 after |
//! |---|---|---|---|---|
//! | r 0.6, P_o 0.8, λ 1, U[−10, 10] | 63.4 | 24.3 | 5.4 | 0.21 |
//! | r 0.3, P_o 0.9, λ 2, U[−10, 10] | 16.0 | 3.6 | 4.7 | 0.15 |
//! | r 0.5, P_o 0.7, λ 0.5, N(0, 9) | 41.6 | 17.5 | 4.7 | 0.11 |
//! | r 0.8, P_o 0.95, λ 3, U[−20, 20] | 101.6 | 19.8 | 5.3 | 0.20 |
//!
//! | bounds page curve, 21 points | before | after | wasm (Node) after |
//! |---|---|---|---|
//! | λ 1, `quadrature_cardinality` 1 | 619 | 351 | 354 |
//! | λ 1, default (2) | 1925 | 517 | 503 (2.1–2.2 s before) |
//! | λ 3, `quadrature_cardinality` 1 | 938 | 686 | 703 |
//! | λ 3, default (2) | 2041 | 837 | 871 |
use fisst::bounds::{
    Density1, Detection, JdeBound, LinearGaussian, ModelII, TheoremOptions, theorem2,
};
use std::time::Instant;

fn median_ms(reps: usize, mut f: impl FnMut() -> JdeBound) -> (f64, JdeBound) {
    let mut times = Vec::with_capacity(reps);
    let mut out = None;
    for _ in 0..reps {
        let t0 = Instant::now();
        out = Some(f());
        times.push(t0.elapsed().as_secs_f64() * 1e3);
    }
    times.sort_by(f64::total_cmp);
    (times[reps / 2], out.expect("at least one repetition"))
}

fn main() {
    let reps: usize = std::env::args()
        .nth(1)
        .map(|s| s.parse().expect("repetitions"))
        .unwrap_or(5)
        .max(1);
    let prior = Density1::gaussian(1.0, 4.0).unwrap();
    let models = [
        (0.6, 0.8, 1.0, Density1::uniform(-10.0, 10.0).unwrap()),
        (0.3, 0.9, 2.0, Density1::uniform(-10.0, 10.0).unwrap()),
        (0.5, 0.7, 0.5, Density1::gaussian(0.0, 9.0).unwrap()),
        (0.8, 0.95, 3.0, Density1::uniform(-20.0, 20.0).unwrap()),
    ];
    println!("repetitions {reps}");
    for (r, p, lambda, clutter) in &models {
        let obs = LinearGaussian::new(Detection::constant(*p).unwrap(), 1.0, 0.0, 1.0).unwrap();
        let m = ModelII {
            existence: *r,
            prior: &prior,
            observation: &obs,
            clutter_rate: *lambda,
            clutter_density: clutter,
            false_alarm_error: 6.0,
            miss_error: 9.0,
        };
        let m = &m;
        let run = |qc: usize, max_clutter: usize| {
            let s = TheoremOptions {
                quadrature_cardinality: qc,
                max_clutter,
                ..TheoremOptions::default()
            };
            move || theorem2(m, &s).unwrap()
        };
        let (t1, _) = median_ms(reps, run(1, 0));
        let (t2, b) = median_ms(reps, run(2, 1));
        let c = &b.cardinalities[1];
        println!(
            "r {r} P_o {p} λ {lambda} clutter {clutter:?}: n = 1 {t1:.2} ms, n ≤ 2 {t2:.2} ms, \
             n = 2 {:.2} ms ({:?}); w2 {:.9} ± {:.1e}, J'2^-1 {:.9} ± {:.1e}, null2 {:.9} ± {:.1e}",
            t2 - t1,
            c.method,
            c.w,
            c.w_error,
            c.inverse_information,
            c.error,
            c.clutter_null,
            c.clutter_null_error
        );
    }
    let prior = Density1::gaussian(0.5, 4.0).unwrap();
    let obs = LinearGaussian::new(Detection::constant(0.8).unwrap(), 1.0, 0.0, 1.0).unwrap();
    let clutter = Density1::gaussian(0.0, 25.0).unwrap();
    for lambda in [1.0, 3.0] {
        for qc in [1, 2] {
            let (t, b) = median_ms(reps, || {
                let mut last = None;
                for i in 0..=20 {
                    let m = ModelII {
                        existence: i as f64 / 20.0,
                        prior: &prior,
                        observation: &obs,
                        clutter_rate: lambda,
                        clutter_density: &clutter,
                        false_alarm_error: 6.0,
                        miss_error: 8.0,
                    };
                    let s = TheoremOptions {
                        quadrature_cardinality: qc,
                        samples: 2000,
                        seed: 4 + i as u64,
                        ..TheoremOptions::default()
                    };
                    last = Some(theorem2(&m, &s).unwrap());
                }
                last.expect("21 points")
            });
            println!(
                "bounds page curve, λ {lambda}, quadrature_cardinality {qc}: 21 points {t:.1} ms \
                 (at r = 1: bound {:.6} ± {:.1e}, {} cardinalities)",
                b.assembled.bound,
                b.error,
                b.cardinalities.len()
            );
        }
    }
}
