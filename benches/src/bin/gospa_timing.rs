//! Times fisst's GOSPA on point sets from a JSON file (for benches/gospa_vs_scipy.py):
//! `gospa_timing <file.json> <repetitions> [baseline]`; the file is `{"truth": [[x, y], …],
//! "estimate": […], "c": …, "p": …}`. Prints `median_seconds distance`. With `baseline`, times
//! the method before issue 15 instead ([`fisst_benches::baseline_gospa`]: the full distance
//! matrix and one dense assignment per component). With `assignment`, times what SciPy's
//! side does on a scene with every pair closer than c (the whole `min(d, c)^p` matrix, then
//! [`fisst::math::linear_assignment`]; for sets beyond the dense-work cap of GOSPA itself) and
//! prints the GOSPA distance of that assignment.
use fisst::metrics::Gospa;
use fisst_benches::baseline_gospa;
use std::time::Instant;

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let text = std::fs::read_to_string(&args[1]).expect("input file");
    let reps: usize = args[2].parse().expect("repetitions");
    let baseline = args.get(3).is_some_and(|a| a == "baseline");
    let assignment = args.get(3).is_some_and(|a| a == "assignment");
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
        distance = if assignment {
            dense_assignment_gospa(&truth, &estimate, c, p)
        } else if baseline {
            baseline_gospa(&truth, &estimate, c, p).0
        } else {
            g.decompose(&truth, &estimate).unwrap().distance
        };
        times.push(t0.elapsed().as_secs_f64());
    }
    times.sort_by(f64::total_cmp);
    println!("{} {}", times[reps / 2], distance);
}

/// GOSPA (alpha = 2) by one dense assignment on the full `min(d, c)^p` matrix, as
/// `gospa_scipy` in benches/gospa_vs_scipy.py computes it.
fn dense_assignment_gospa(truth: &[[f64; 2]], estimate: &[[f64; 2]], c: f64, p: f64) -> f64 {
    let d = |a: &[f64; 2], b: &[f64; 2]| ((a[0] - b[0]).powi(2) + (a[1] - b[1]).powi(2)).sqrt();
    let pow = |x: f64| if p == 2.0 { x * x } else { x.powf(p) };
    let cost: Vec<f64> = truth
        .iter()
        .flat_map(|a| estimate.iter().map(move |b| pow(d(a, b).min(c))))
        .collect();
    let a = fisst::math::linear_assignment(&cost, truth.len(), estimate.len()).unwrap();
    let (mut loc, mut assigned) = (0.0, 0);
    for &(i, j) in &a.pairs {
        let dij = d(&truth[i], &estimate[j]);
        if dij < c {
            loc += pow(dij);
            assigned += 1;
        }
    }
    let unassigned = (truth.len() + estimate.len() - 2 * assigned) as f64;
    (loc + c.powf(p) / 2.0 * unassigned).powf(1.0 / p)
}
