//! Native timings of optimal Bernoulli point estimation (paper `000_…`). Not a test: run it
//! in release mode, from `benches/`.
//!
//! - `cargo run --release --bin bernoulli_timing` prints a fixed table (CSV: what, median and
//!   minimum microseconds, value): q(a) for 2D–6D Gaussians, a* for Gaussian mixtures of 2–10
//!   components in 1D–3D, particles, and a 200-point threshold curve. The inputs are fixed,
//!   so the printed values (q, q(a*)) can be compared with another implementation.
//! - `bernoulli_timing <in.json> <out.json>` times a job for `benches/bernoulli_vs_scipy.py`.
//!   The input is `{"cases": [{"mode": "q" | "mmuc", "density": {"mean", "cov"} |
//!   {"mixture": [{"weight", "mean", "cov"}]}, "centers": [[…]], "radius", "reps"}]}`
//!   (covariances nested row-major), the densities as the npm package takes them. Mode `q`
//!   times `prob_outside_ball` at every centre (tolerance 1e-10), `mmuc` times `mmuc`.
//!   Writes `{"results": [{"seconds": median seconds per call, "q": [...], "center": [...]}]}`.
use fisst::bernoulli::{Costs, ParticleSet, SpatialDensity, isotropic_threshold_curve};
use fisst::gaussian::{Gaussian, GaussianMixture};
use fisst_benches::{median_min_us as time_us, median_time};
use serde_json::{Value, json};

fn main() -> Result<(), fisst::Error> {
    let args: Vec<String> = std::env::args().collect();
    match args.as_slice() {
        [_] => table(),
        [_, input, output] => {
            job(input, output);
            Ok(())
        }
        _ => panic!("usage: bernoulli_timing [<in.json> <out.json>]"),
    }
}

/// The fixed table.
fn table() -> Result<(), fisst::Error> {
    println!("what,median_us,min_us,value");
    for d in 2..=6usize {
        let eig: Vec<f64> = (0..d).map(|k| 0.3 + 0.25 * k as f64).collect();
        let mean = vec![0.0; d];
        let s = SpatialDensity::gaussian_from_slices(&mean, &rotated(&eig))?;
        let center: Vec<f64> = (0..d).map(|k| 0.2 - 0.1 * k as f64).collect();
        let mut q = 0.0;
        let (med, min) = time_us(21, || q = s.prob_outside_ball(&center, 1.2).unwrap());
        println!("q gaussian d={d},{med:.1},{min:.1},{q:.12}");
    }
    let mut rng = Lcg(12345);
    for d in 1..=3usize {
        for n in [2usize, 10] {
            let comps: Vec<(f64, Gaussian)> = (0..n)
                .map(|j| {
                    let w = rng.next() + 0.1;
                    let m: Vec<f64> = (0..d).map(|_| 4.0 * rng.next()).collect();
                    let eig: Vec<f64> = (0..d).map(|_| 0.05 + 0.4 * rng.next()).collect();
                    let cov = if d == 1 { eig.clone() } else { rotated(&eig) };
                    let name = format!("density.mixture[{j}]");
                    (w, Gaussian::from_slices(&m, &cov, &name).unwrap())
                })
                .collect();
            let s = SpatialDensity::mixture(&GaussianMixture::new(comps, "density.mixture")?)?;
            let mut q = 0.0;
            let runs = if d == 3 { 3 } else { 11 };
            let (med, min) = time_us(runs, || q = s.mmuc(1.0).unwrap().miss_probability);
            println!("mmuc mixture d={d} n={n},{med:.1},{min:.1},{q:.12}");
        }
    }
    for (d, n) in [(1usize, 100_000usize), (2, 1000), (3, 100)] {
        let pts: Vec<Vec<f64>> = (0..n)
            .map(|_| (0..d).map(|_| 3.0 * rng.next()).collect())
            .collect();
        let s = SpatialDensity::particles(ParticleSet::new(&pts, None)?);
        let mut q = 0.0;
        let (med, min) = time_us(5, || q = s.mmuc(0.5).unwrap().miss_probability);
        println!("mmuc particles d={d} n={n},{med:.1},{min:.1},{q:.12}");
    }
    let sigmas: Vec<f64> = (1..=200).map(|i| 0.05 * i as f64).collect();
    let mut last = 0.0;
    let (med, min) = time_us(101, || {
        last = isotropic_threshold_curve(&sigmas, 1.0, &Costs::mpe(), 1).unwrap()[199];
    });
    println!("threshold curve 200 points d=1,{med:.1},{min:.1},{last:.12}");
    Ok(())
}

/// A fixed pseudo-random stream in [0, 1) (Park–Miller), so the inputs are reproducible in
/// any language.
struct Lcg(u64);

impl Lcg {
    fn next(&mut self) -> f64 {
        self.0 = (self.0 * 16807) % 2_147_483_647;
        self.0 as f64 / 2_147_483_647.0
    }
}

/// A covariance with eigenvalues `eig` rotated by a fixed angle in each coordinate plane.
fn rotated(eig: &[f64]) -> Vec<f64> {
    let d = eig.len();
    let mut u = vec![0.0; d * d];
    for i in 0..d {
        u[i * d + i] = 1.0;
    }
    for i in 0..d {
        for j in i + 1..d {
            let a: f64 = 0.3 + 0.7 * (i as f64 + 2.0 * j as f64);
            let (c, s) = (a.cos(), a.sin());
            for row in 0..d {
                let (x, y) = (u[row * d + i], u[row * d + j]);
                u[row * d + i] = c * x + s * y;
                u[row * d + j] = -s * x + c * y;
            }
        }
    }
    let mut p = vec![0.0; d * d];
    for r in 0..d {
        for c in 0..d {
            p[r * d + c] = (0..d).map(|k| u[r * d + k] * eig[k] * u[c * d + k]).sum();
        }
    }
    for r in 0..d {
        for c in 0..r {
            let m = 0.5 * (p[r * d + c] + p[c * d + r]);
            p[r * d + c] = m;
            p[c * d + r] = m;
        }
    }
    p
}

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

/// The JSON job of `benches/bernoulli_vs_scipy.py`.
fn job(input: &str, output: &str) {
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
