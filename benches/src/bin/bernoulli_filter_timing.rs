//! Runs fisst's GM and particle Bernoulli filters natively on a vector-measurement scan
//! sequence, for `benches/bernoulli_vs_stonesoup.py`: `bernoulli_filter_timing <in.json>
//! <out.json>`. The input has the model (`F`, `Q`, `H`, `R` as nested row-major arrays,
//! `detection`, `survival`, `birth: {probability, mean, cov}`, `initial: {existence, mean,
//! cov}`, `clutter: {rate, density}`), `particles`, `mcmcMoves`, `seed`, `reps` and `scans`
//! (per step a list of measurement vectors). Writes, per filter, the median over `reps` of
//! the seconds per step and the last run's existence and mean per step, and the existence
//! after one empty scan from r = 0.8 with p_D = 0.9 (`empty`).
use fisst::filters::{
    BernoulliFilterOptions, Birth, Clutter, ClutterDensity, Detection, EstimateOptions,
    GmBernoulliFilter, LinearGaussianLikelihood, LinearGaussianTransition, ParticleBernoulliFilter,
    ParticleOptions, Splitting, default_reduction,
};
use fisst::gaussian::{Gaussian, GaussianMixture};
use serde_json::{Value, json};
use std::time::Instant;

fn rows(v: &Value) -> (Vec<f64>, usize) {
    let r: Vec<Vec<f64>> = serde_json::from_value(v.clone()).expect("matrix");
    let n = r.len();
    (r.concat(), n)
}

fn vector(v: &Value) -> Vec<f64> {
    serde_json::from_value(v.clone()).expect("numbers")
}

fn density(v: &Value, what: &str) -> GaussianMixture {
    let (cov, _) = rows(&v["cov"]);
    let g = Gaussian::from_slices(&vector(&v["mean"]), &cov, what).expect("gaussian");
    GaussianMixture::new(vec![(1.0, g)], what).expect("mixture")
}

fn config(v: &Value) -> BernoulliFilterOptions {
    let (f, _) = rows(&v["F"]);
    let (q, _) = rows(&v["Q"]);
    let (h, m) = rows(&v["H"]);
    let (r, _) = rows(&v["R"]);
    BernoulliFilterOptions {
        existence: v["initial"]["existence"].as_f64().expect("existence"),
        mixture: density(&v["initial"], "mixture"),
        transition: LinearGaussianTransition::from_row_slices(&f, &q).expect("transition"),
        survival: v["survival"].as_f64().expect("survival"),
        birth: Birth::new(
            v["birth"]["probability"].as_f64().expect("birth"),
            density(&v["birth"], "birth.mixture"),
        )
        .expect("birth"),
        position_dims: m,
        detection: Detection::new(v["detection"].as_f64().expect("detection"), None)
            .expect("detection"),
        clutter: Clutter::new(
            v["clutter"]["rate"].as_f64().expect("rate"),
            ClutterDensity::Constant(v["clutter"]["density"].as_f64().expect("density")),
        )
        .expect("clutter"),
        likelihood: Some(LinearGaussianLikelihood::from_row_slices(&h, m, &r).expect("H, R")),
        splitting: Splitting::default(),
        reduction: default_reduction(),
        exclusions: Vec::new(),
    }
}

fn median(mut v: Vec<f64>) -> f64 {
    v.sort_by(f64::total_cmp);
    v[v.len() / 2]
}

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let (input, output) = (&args[1], &args[2]);
    let v: Value =
        serde_json::from_str(&std::fs::read_to_string(input).expect("input file")).expect("json");
    let cfg = config(&v);
    let scans: Vec<Vec<Vec<f64>>> = serde_json::from_value(v["scans"].clone()).expect("scans");
    let reps = v["reps"].as_u64().unwrap_or(3) as usize;
    let options = ParticleOptions {
        particles: v["particles"].as_u64().unwrap_or(5000) as usize,
        mcmc_moves: v["mcmcMoves"].as_u64().unwrap_or(1) as usize,
        seed: v["seed"].as_u64().unwrap_or(1),
        birth_particles: v["birthParticles"].as_u64().map(|b| b as usize),
    };
    let steps = scans.len() as f64;
    let mut gm_times = Vec::new();
    let mut gm_out = (Vec::new(), Vec::new());
    for _ in 0..reps {
        let t0 = Instant::now();
        let mut f = GmBernoulliFilter::new(cfg.clone()).expect("gm");
        let (mut ex, mut mean) = (Vec::new(), Vec::new());
        for scan in &scans {
            f.predict().expect("predict");
            f.update_measurements(scan).expect("update");
            let e = f.estimate(&EstimateOptions::default()).expect("estimate");
            ex.push(e.existence);
            mean.push(e.mean);
        }
        gm_times.push(t0.elapsed().as_secs_f64() / steps);
        gm_out = (ex, mean);
    }
    let mut pf_times = Vec::new();
    let mut pf_out = (Vec::new(), Vec::new());
    for _ in 0..reps {
        let t0 = Instant::now();
        let mut f = ParticleBernoulliFilter::new(cfg.clone(), options).expect("pf");
        let (mut ex, mut mean) = (Vec::new(), Vec::new());
        for scan in &scans {
            f.predict();
            f.update_measurements(scan).expect("update");
            let e = f.estimate(&EstimateOptions::default()).expect("estimate");
            ex.push(e.existence);
            mean.push(e.mean);
        }
        pf_times.push(t0.elapsed().as_secs_f64() / steps);
        pf_out = (ex, mean);
    }
    // One empty scan from r = 0.8, p_D = 0.9 (no prediction).
    let mut empty_cfg = cfg.clone();
    empty_cfg.existence = 0.8;
    empty_cfg.detection = Detection::new(0.9, None).expect("detection");
    let none: [Vec<f64>; 0] = [];
    let mut g = GmBernoulliFilter::new(empty_cfg.clone()).expect("gm");
    g.update_measurements(&none).expect("update");
    let mut p = ParticleBernoulliFilter::new(empty_cfg, options).expect("pf");
    p.update_measurements(&none).expect("update");
    let out = json!({
        "gm": {"secondsPerStep": median(gm_times), "existence": gm_out.0, "mean": gm_out.1},
        "pf": {"secondsPerStep": median(pf_times), "existence": pf_out.0, "mean": pf_out.1},
        "empty": {"gm": g.existence(), "pf": p.existence()},
    });
    std::fs::write(output, serde_json::to_string(&out).expect("json")).expect("output file");
}
