//! Times fisst's GOSPA on point sets from a JSON file (for benches/gospa_vs_scipy.py):
//! `gospa_timing <file.json> <repetitions>`; the file is `{"truth": [[x, y], …],
//! "estimate": […], "c": …, "p": …}`. Prints `median_seconds distance`.
use fisst::metrics::Gospa;
use fisst_benches::median_time;

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let text = std::fs::read_to_string(&args[1]).expect("input file");
    let reps: usize = args[2].parse().expect("repetitions");
    let v: serde_json::Value = serde_json::from_str(&text).expect("json");
    let pts = |k: &str| -> Vec<Vec<f64>> { serde_json::from_value(v[k].clone()).expect("points") };
    let (truth, estimate) = (pts("truth"), pts("estimate"));
    let g = Gospa::new(v["c"].as_f64().unwrap(), v["p"].as_f64().unwrap(), 2.0).unwrap();
    let (seconds, distance) =
        median_time(reps, || g.decompose(&truth, &estimate).unwrap().distance);
    println!("{seconds} {distance}");
}
