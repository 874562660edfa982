//! Times fisst's GOSPA on point sets from a JSON file (for benches/gospa_vs_scipy.py):
//! `gospa_timing <file.json> <repetitions> [baseline]`; the file is `{"truth": [[x, y], …],
//! "estimate": […], "c": …, "p": …}`. Prints `median_seconds distance`. With `baseline`, times
//! the method before issue 15 instead ([`fisst_benches::baseline_gospa`]: the full distance
//! matrix and one dense assignment per component).
use fisst::metrics::Gospa;
use fisst_benches::baseline_gospa;
use std::time::Instant;

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let text = std::fs::read_to_string(&args[1]).expect("input file");
    let reps: usize = args[2].parse().expect("repetitions");
    let baseline = args.get(3).is_some_and(|a| a == "baseline");
    let v: serde_json::Value = serde_json::from_str(&text).expect("json");
    let pts = |k: &str| -> Vec<[f64; 2]> { serde_json::from_value(v[k].clone()).expect("points") };
    let (truth, estimate) = (pts("truth"), pts("estimate"));
    let (c, p) = (v["c"].as_f64().unwrap(), v["p"].as_f64().unwrap());
    drop(v);
    let g = Gospa::new(c, p, 2.0).unwrap();
    let mut times = Vec::with_capacity(reps);
    let mut distance = 0.0;
    for _ in 0..reps {
        let t0 = Instant::now();
        distance = if baseline {
            baseline_gospa(&truth, &estimate, c, p).0
        } else {
            g.decompose(&truth, &estimate).unwrap().distance
        };
        times.push(t0.elapsed().as_secs_f64());
    }
    times.sort_by(f64::total_cmp);
    println!("{} {}", times[reps / 2], distance);
}
