//! The four-scheme Monte Carlo comparison of Fig. 3 (paper 004), natively on all cores
//! (rayon, the `parallel` feature), with its wall-clock time and the last-step figures.
//!
//! `cargo run --release --bin control_comparison -- [runs=200] [steps=40] [particles=750] [futureScans=200] [seed=1]`
use fisst::control::{ControlOptions, Scheme, compare_schemes};
use std::time::Instant;

fn main() {
    let args: Vec<u64> = std::env::args()
        .skip(1)
        .map(|a| a.parse().expect("integer arguments"))
        .collect();
    let get = |i: usize, d: u64| args.get(i).copied().unwrap_or(d);
    let (runs, steps, particles, scans, seed) =
        (get(0, 200), get(1, 40), get(2, 750), get(3, 200), get(4, 1));
    let mut cfg = ControlOptions::paper(Scheme::Renyi, steps as usize);
    cfg.particles = particles as usize;
    cfg.future_scans = scans as usize;
    let schemes = [Scheme::Renyi, Scheme::Fisher, Scheme::Pent, Scheme::Random];
    let t = Instant::now();
    let out = compare_schemes::<fisst::Error>(&cfg, &schemes, runs as usize, seed, |d, n| {
        eprintln!("{d}/{n} runs, {:.1} s", t.elapsed().as_secs_f64());
        Ok(())
    })
    .unwrap();
    let secs = t.elapsed().as_secs_f64();
    println!(
        "runs={runs} steps={steps} N={particles} M={scans} seed={seed} threads={} time={secs:.1} s",
        rayon_threads()
    );
    println!("scheme   OSPA(K) ± se     loc(K) ± se     card(K) ± se    mean OSPA over k");
    for s in &out {
        let k = steps as usize - 1;
        let avg: f64 = s.distance.mean.iter().sum::<f64>() / steps as f64;
        println!(
            "{:<8} {:6.2} ± {:4.2}    {:6.2} ± {:4.2}    {:6.2} ± {:4.2}    {avg:6.2}",
            format!("{:?}", s.scheme),
            s.distance.mean[k],
            s.distance.standard_error[k],
            s.localisation.mean[k],
            s.localisation.standard_error[k],
            s.cardinality.mean[k],
            s.cardinality.standard_error[k],
        );
    }
    for s in &out {
        let m: Vec<String> = s.distance.mean.iter().map(|x| format!("{x:.1}")).collect();
        println!("{:?} OSPA by k: {}", s.scheme, m.join(" "));
    }
}

fn rayon_threads() -> usize {
    std::thread::available_parallelism()
        .map(|n| n.get())
        .unwrap_or(1)
}
