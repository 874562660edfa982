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
use fisst::fov::{GridAxis, SceneOptions, multi_bernoulli, placement_scene, variance_map};
use serde_json::{Value, json};
use std::time::Instant;

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
