//! Times `fisst::fov::variance_map` on the sensor-placement scene of Section VII of
//! `001_…`: 100 multi-Bernoulli components (existence in [0.35, 1], means in [−3, 3]²,
//! random orientations and standard deviations), a 1 × 1 FoV, 121 × 121 FoV centres.
//!
//! `cargo run --release -p fisst --example fov_variance_map`

use std::time::Instant;

use fisst::fov::{GridAxis, variance_map};
use fisst::gaussian::Gaussian;
use rand::{RngExt, SeedableRng, rngs::SmallRng};

fn scene(seed: u64, n: usize, sd: (f64, f64), max_aspect: f64) -> Vec<(f64, Gaussian)> {
    let mut rng = SmallRng::seed_from_u64(seed);
    (0..n)
        .map(|_| {
            let a: f64 = rng.random_range(0.0..std::f64::consts::PI);
            let s1: f64 = rng.random_range(sd.0..sd.1);
            let s2: f64 = (s1 / rng.random_range(1.0..max_aspect)).max(sd.0 * 0.5);
            let (c, s) = (a.cos(), a.sin());
            let p = [
                c * c * s1 * s1 + s * s * s2 * s2,
                c * s * (s1 * s1 - s2 * s2),
                c * s * (s1 * s1 - s2 * s2),
                s * s * s1 * s1 + c * c * s2 * s2,
            ];
            let m = [rng.random_range(-3.0..3.0), rng.random_range(-3.0..3.0)];
            (
                rng.random_range(0.35..1.0),
                Gaussian::from_slices(&m, &p, "p").unwrap(),
            )
        })
        .collect()
}

fn main() {
    let axis = GridAxis {
        min: -3.0,
        max: 3.0,
        count: 121,
    };
    // FOV_SCENE=k (0-based, scene × FoV) runs only that case, FOV_REPS times (default 15), so
    // that `time` can report its CPU time on a busy machine.
    let only: Option<usize> = std::env::var("FOV_SCENE").ok().and_then(|v| v.parse().ok());
    let reps: usize = std::env::var("FOV_REPS")
        .ok()
        .and_then(|v| v.parse().ok())
        .unwrap_or(15);
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
            if only.is_some_and(|k| k + 1 != case) {
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
            let mut times = Vec::new();
            let mut last = None;
            for _ in 0..reps {
                let t = Instant::now();
                let map = variance_map(&comps, fov, axis, axis).unwrap();
                times.push(t.elapsed().as_secs_f64() * 1e3);
                last = Some(map);
            }
            times.sort_by(f64::total_cmp);
            let map = last.unwrap();
            println!(
                "{name},{fov_name},{:.2},{:.2},{:.6},{:.3},{:.3},{high}",
                times[times.len() / 2],
                times[0],
                map.max,
                map.argmax[0],
                map.argmax[1]
            );
        }
    }
}
