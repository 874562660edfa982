//! Times fisst's Bernoulli functions natively, for `benches/bernoulli_vs_scipy.py`:
//! `bernoulli_timing <in.json> <out.json>`. The input is `{"cases": [{"mode": "q" | "mmuc",
//! "density": {"mean", "cov"} | {"mixture": [{"weight", "mean", "cov"}]}, "centers": [[…]],
//! "radius", "reps"}]}` (covariances nested row-major), the densities as the npm package takes
//! them. Mode `q` times `prob_outside_ball` at every centre (tolerance 1e-10), `mmuc` times
//! `mmuc`. Writes `{"results": [{"seconds": median seconds per call, "q": [...],
//! "center": [...]}]}`.
use fisst::bernoulli::SpatialDensity;
use fisst::gaussian::{Gaussian, GaussianMixture};
use serde_json::{Value, json};
use std::time::Instant;

fn vector(v: &Value) -> Vec<f64> {
    serde_json::from_value(v.clone()).expect("numbers")
}

fn gaussian(v: &Value) -> Gaussian {
    let mean = vector(&v["mean"]);
    let rows: Vec<Vec<f64>> = serde_json::from_value(v["cov"].clone()).expect("cov");
    let cov: Vec<f64> = rows.concat();
    Gaussian::from_slices(&mean, &cov, "density").expect("gaussian")
}

fn density(v: &Value) -> SpatialDensity {
    match v.get("mixture") {
        Some(Value::Array(items)) => {
            let comps = items
                .iter()
                .map(|c| (c["weight"].as_f64().expect("weight"), gaussian(c)))
                .collect();
            let m = GaussianMixture::new(comps, "density.mixture").expect("mixture");
            SpatialDensity::mixture(&m).expect("mixture density")
        }
        _ => SpatialDensity::gaussian(gaussian(v)).expect("gaussian density"),
    }
}

/// The median over `reps` runs of `f`, and its last result.
fn median_time<T>(reps: usize, mut f: impl FnMut() -> T) -> (f64, T) {
    let mut times = Vec::with_capacity(reps);
    let mut out = None;
    for _ in 0..reps {
        let t0 = Instant::now();
        out = Some(f());
        times.push(t0.elapsed().as_secs_f64());
    }
    times.sort_by(f64::total_cmp);
    (times[reps / 2], out.expect("reps >= 1"))
}

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let (input, output) = (&args[1], &args[2]);
    let v: Value =
        serde_json::from_str(&std::fs::read_to_string(input).expect("input file")).expect("json");
    let mut results = Vec::new();
    for case in v["cases"].as_array().expect("cases") {
        let s = density(&case["density"]);
        let radius = case["radius"].as_f64().expect("radius");
        let reps = case["reps"].as_u64().expect("reps") as usize;
        let result = match case["mode"].as_str().expect("mode") {
            "q" => {
                let centers: Vec<Vec<f64>> =
                    serde_json::from_value(case["centers"].clone()).expect("centers");
                let mut q = Vec::new();
                let mut seconds = 0.0;
                for c in &centers {
                    let (t, value) = median_time(reps, || s.prob_outside_ball(c, radius).unwrap());
                    seconds += t;
                    q.push(value);
                }
                json!({ "seconds": seconds / centers.len() as f64, "q": q })
            }
            "mmuc" => {
                let (t, m) = median_time(reps, || s.mmuc(radius).unwrap());
                json!({ "seconds": t, "q": [m.miss_probability], "center": m.center })
            }
            other => panic!("mode must be q or mmuc, got {other}"),
        };
        results.push(result);
    }
    std::fs::write(output, json!({ "results": results }).to_string()).expect("output file");
}
