//! Times fisst's FoV functions natively, for `benches/pmf_vs_scipy.py` and
//! `benches/map_vs_numpy.py`:
//!
//! - `fov_timing pmf <in.json> <reps> <out.json>`: the multi-Bernoulli FoV pmf (88) of the
//!   inclusion probabilities `{"r": [r_S, …]}` by `fisst::fov::multi_bernoulli`;
//! - `fov_timing map <in.json> <reps> <out.json>`: the variance map of the seeded scene
//!   `{"count", "seed", "extent", "side", "grid": [min, max, count]}` (the same axis for x and
//!   y) by `fisst::fov::variance_map`.
//!
//! Prints the median seconds; writes the result (`{"pmf": […]}`, or `{"scene": […],
//! "variance": […], "argmax": [x, y], "max": v}`) to `out.json`.
//!
//! - `fov_timing scenes [<reps>=15] [<case>]` times `variance_map` on the sensor-placement
//!   scenes of Section VII of `001_…` with four spreads of the covariances (100 components,
//!   existence in [0.35, 1), means in [−3, 3]², random orientations; 121 × 121 FoV centres)
//!   and two FoV shapes, and prints a CSV table (median and minimum ms). A case number
//!   (1–8) runs only that case, so that `time` can report its CPU time on a busy machine.
use fisst::fov::{GridAxis, SceneOptions, multi_bernoulli, placement_scene, variance_map};
use fisst::gaussian::Gaussian;
use fisst_benches::{SplitMix, median_min_us, median_time};
use serde_json::{Value, json};

fn main() {
    let args: Vec<String> = std::env::args().collect();
    if args.get(1).map(String::as_str) == Some("scenes") {
        let reps = args.get(2).map_or(15, |r| r.parse().expect("repetitions"));
        scenes(reps, args.get(3).map(|k| k.parse().expect("case number")));
        return;
    }
    let (mode, input, reps, output) = (&args[1], &args[2], &args[3], &args[4]);
    let v: Value =
        serde_json::from_str(&std::fs::read_to_string(input).expect("input file")).expect("json");
    let reps: usize = reps.parse().expect("repetitions");
    let result = match mode.as_str() {
        "pmf" => {
            let r: Vec<f64> = serde_json::from_value(v["r"].clone()).expect("r");
            let (t, c) = median_time(reps, || multi_bernoulli(&r).unwrap());
            println!("{t}");
            json!({ "pmf": c.pmf })
        }
        "map" => {
            let num = |k: &str| v[k].as_f64().expect(k);
            let scene = placement_scene(&SceneOptions {
                count: num("count") as usize,
                seed: num("seed") as u64,
                extent: num("extent"),
                ..SceneOptions::default()
            })
            .unwrap();
            let g: Vec<f64> = serde_json::from_value(v["grid"].clone()).expect("grid");
            let axis = GridAxis {
                min: g[0],
                max: g[1],
                count: g[2] as usize,
            };
            let side = num("side");
            let (t, map) = median_time(reps, || {
                variance_map(&scene, [side, side], axis, axis).unwrap()
            });
            println!("{t}");
            let comps: Vec<Value> = scene
                .iter()
                .map(|(r, g)| {
                    let (m, p) = (g.mean(), g.cov());
                    json!({ "existence": r, "mean": [m[0], m[1]],
                            "cov": [[p[(0, 0)], p[(0, 1)]], [p[(1, 0)], p[(1, 1)]]] })
                })
                .collect();
            json!({ "scene": comps, "variance": map.variance, "argmax": map.argmax, "max": map.max })
        }
        _ => panic!("mode must be pmf or map"),
    };
    std::fs::write(output, result.to_string()).expect("output file");
}

/// A scene of `n` components whose principal standard deviations are drawn from `sd` with
/// an aspect ratio up to `max_aspect`.
fn scene(seed: u64, n: usize, sd: (f64, f64), max_aspect: f64) -> Vec<(f64, Gaussian)> {
    let mut rng = SplitMix::new(seed);
    let mut range = |lo: f64, hi: f64| lo + (hi - lo) * rng.uniform();
    (0..n)
        .map(|_| {
            let a: f64 = range(0.0, std::f64::consts::PI);
            let s1: f64 = range(sd.0, sd.1);
            let s2: f64 = (s1 / range(1.0, max_aspect)).max(sd.0 * 0.5);
            let (c, s) = (a.cos(), a.sin());
            let p = [
                c * c * s1 * s1 + s * s * s2 * s2,
                c * s * (s1 * s1 - s2 * s2),
                c * s * (s1 * s1 - s2 * s2),
                s * s * s1 * s1 + c * c * s2 * s2,
            ];
            let m = [range(-3.0, 3.0), range(-3.0, 3.0)];
            (
                range(0.35, 1.0),
                Gaussian::from_slices(&m, &p, "p").unwrap(),
            )
        })
        .collect()
}

/// The `scenes` table.
fn scenes(reps: usize, only: Option<usize>) {
    let axis = GridAxis {
        min: -3.0,
        max: 3.0,
        count: 121,
    };
    let mut case = 0;
    println!("scene,fov,median_ms,min_ms,max_variance,argmax_x,argmax_y,high_rho_components");
    for (name, sd, aspect) in [
        ("sd 0.1-0.5, aspect <= 3", (0.1, 0.5), 3.0),
        ("sd 0.2-1.0, aspect <= 3", (0.2, 1.0), 3.0),
        ("sd 0.1-0.5, aspect <= 10", (0.1, 0.5), 10.0),
        ("sd 0.05-0.3, round", (0.05, 0.3), 1.0 + 1e-9),
    ] {
        for (fov_name, fov) in [("1x1", [1.0, 1.0]), ("0.93x1.07", [0.93, 1.07])] {
            case += 1;
            if only.is_some_and(|k| k != case) {
                continue;
            }
            let comps = scene(7, 100, sd, aspect);
            let high = comps
                .iter()
                .filter(|(_, g)| {
                    let p = g.cov();
                    (p[(0, 1)] / (p[(0, 0)] * p[(1, 1)]).sqrt()).abs() >= 0.925
                })
                .count();
            let mut map = None;
            let (median, min) = median_min_us(reps, || {
                map = Some(variance_map(&comps, fov, axis, axis).unwrap());
            });
            let map = map.expect("reps >= 1");
            println!(
                "{name},{fov_name},{:.2},{:.2},{:.6},{:.3},{:.3},{high}",
                median / 1e3,
                min / 1e3,
                map.max,
                map.argmax[0],
                map.argmax[1]
            );
        }
    }
}
