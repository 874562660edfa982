//! Times fisst's whole-scenario metrics natively (for `benches/gospa_vs_stonesoup.py`):
//!
//! `series_timing <gospa|ospa> <in.json> <repetitions> <out.json>`; the input is
//! `{"truths": [[[x, y], …], …], "estimates": […], "c": …, "p": …, "alpha": …}` (one set per
//! step; `alpha` for GOSPA only). Prints the median seconds of `Gospa::series` /
//! `Ospa::series`; writes the series to `out.json` (`distance`, `localisation`, `missed`,
//! `false_targets` or `cardinality`, and the means).
use fisst::metrics::{Gospa, Ospa};
use serde_json::{Value, json};
use std::time::Instant;

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let (metric, input, reps, output) = (&args[1], &args[2], &args[3], &args[4]);
    let reps: usize = reps.parse().expect("repetitions");
    let v: Value =
        serde_json::from_str(&std::fs::read_to_string(input).expect("input")).expect("json");
    let sets = |k: &str| -> Vec<Vec<Vec<f64>>> {
        serde_json::from_value(v[k].clone()).expect("sets of points")
    };
    let (truths, estimates) = (sets("truths"), sets("estimates"));
    let (c, p) = (v["c"].as_f64().unwrap(), v["p"].as_f64().unwrap());
    let mut times = Vec::with_capacity(reps);
    let mut out = Value::Null;
    for _ in 0..reps {
        let t0 = Instant::now();
        out = match metric.as_str() {
            "gospa" => {
                let alpha = v["alpha"].as_f64().unwrap_or(2.0);
                let s = Gospa::new(c, p, alpha)
                    .unwrap()
                    .series(&truths, &estimates)
                    .unwrap();
                assert!(s.missed.is_some(), "alpha = 2");
                json!({"distance": s.distance, "mean_distance": s.mean_distance,
                       "localisation": s.localisation, "missed": s.missed,
                       "false_targets": s.false_targets,
                       "mean_localisation": s.mean_localisation,
                       "mean_missed": s.mean_missed,
                       "mean_false_targets": s.mean_false_targets})
            }
            "ospa" => {
                let s = Ospa::new(c, p)
                    .unwrap()
                    .series(&truths, &estimates)
                    .unwrap();
                json!({"distance": s.distance, "localisation": s.localisation,
                       "cardinality": s.cardinality, "mean_distance": s.mean_distance})
            }
            _ => panic!("metric: gospa or ospa"),
        };
        times.push(t0.elapsed().as_secs_f64());
    }
    times.sort_by(f64::total_cmp);
    std::fs::write(output, out.to_string()).expect("output");
    println!("{}", times[reps / 2]);
}
