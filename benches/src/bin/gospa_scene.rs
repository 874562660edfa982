//! One GOSPA scene generated natively, for timing and peak memory without any input parsing
//! (`benches/gospa_vs_scipy.py` runs it under `/usr/bin/time -v` for the 100,000-point
//! scene):
//!
//! `gospa_scene <sparse|percolating|all-pairs> <n> <repetitions> [baseline]`
//!
//! Prints one JSON line: `{"scene", "n", "m", "c", "seconds" (median wall time),
//! "cpu_seconds" (mean CPU time of the thread: its clock ticks at 4 ms), "distance",
//! "localisation", "missed", "false_targets", "peak_rss_kb"}`. With `baseline`, times the
//! method before issue 15 ([`fisst_benches::baseline_gospa`]) instead.
use fisst::metrics::Gospa;
use fisst_benches::{
    C, all_pairs_cutoff, baseline_gospa, peak_rss_kb, percolating_scene, scene, thread_cpu_seconds,
};
use serde_json::json;
use std::time::Instant;

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let kind = args[1].as_str();
    let n: usize = args[2].parse().expect("n");
    let reps: usize = args[3].parse().expect("repetitions");
    let baseline = args.get(4).is_some_and(|a| a == "baseline");
    let (truth, estimate, c) = match kind {
        "sparse" => {
            let (x, y) = scene(n, 7);
            (x, y, C)
        }
        "percolating" => {
            let (x, y) = percolating_scene(n, 7);
            (x, y, C)
        }
        "all-pairs" => {
            let (x, y) = percolating_scene(n, 7);
            (x, y, all_pairs_cutoff(n))
        }
        _ => panic!("scene: sparse, percolating or all-pairs"),
    };
    let g = Gospa::new(c, 2.0, 2.0).unwrap();
    let mut times = Vec::with_capacity(reps);
    let mut cpu = Vec::with_capacity(reps);
    let mut out = (0.0, 0.0, 0, 0);
    for _ in 0..reps {
        let c0 = thread_cpu_seconds();
        let t0 = Instant::now();
        out = if baseline {
            baseline_gospa(&truth, &estimate, c, 2.0)
        } else {
            let d = g.decompose(&truth, &estimate).unwrap();
            (d.distance, d.localisation, d.missed, d.false_targets)
        };
        times.push(t0.elapsed().as_secs_f64());
        cpu.push(thread_cpu_seconds() - c0);
    }
    times.sort_by(f64::total_cmp);

    println!(
        "{}",
        json!({"scene": kind, "n": truth.len(), "m": estimate.len(), "c": c,
               "seconds": times[reps / 2], "cpu_seconds": cpu.iter().sum::<f64>() / reps as f64, "distance": out.0, "localisation": out.1,
               "missed": out.2, "false_targets": out.3, "peak_rss_kb": peak_rss_kb(),
               "method": if baseline { "baseline" } else { "fisst" }})
    );
}
