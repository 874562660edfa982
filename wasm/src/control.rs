//! Sensor control with the SMC multi-object filter (paper 004, Ristic & Vo):
//! `multiObjectLikelihood` (eq. (20)). The shapes are also listed in
//! `core/src/control/JS_SHAPES.md`.

use std::string::String;
use std::vec;
use std::{format, vec::Vec};

use serde::{Deserialize, Serialize};
use tsify::Tsify;
use wasm_bindgen::prelude::*;

use crate::boundary::{JsResult, OrThrow, range_error, read, write};
use crate::types::Numbers;

/// At most this many objects (rows of `likelihoods`).
const MAX_OBJECTS: usize = 64;
/// At most this many measurements (entries of `clutterDensity`).
const MAX_MEASUREMENTS: usize = 1000;
/// At most this many on the smaller side (the dynamic programme has 2^k states).
const MAX_SMALLER: usize = 12;

/// Options of `multiObjectLikelihood`.
#[derive(Deserialize, Tsify)]
#[serde(rename_all = "camelCase")]
pub struct MultiObjectLikelihoodOptions {
    /// `likelihoods[i][j]` = g(z_j | x_i) ≥ 0, one row of m numbers per object of the
    /// particle (`[]` for n = 0). At most 64 objects, and min(n, m) ≤ 12.
    pub likelihoods: Vec<Numbers>,
    /// p_D, in [0, 1].
    pub detection_probability: f64,
    /// λ ≥ 0, the mean number of clutter measurements.
    pub clutter_rate: f64,
    /// `clutterDensity[j]` = c(z_j) ≥ 0, one per measurement (m ≤ 1000), so that
    /// f_c(Z) = e^{−λ} Π_j λ c(z_j).
    pub clutter_density: Numbers,
}

/// Result of `multiObjectLikelihood`.
#[derive(Serialize, Tsify)]
#[serde(rename_all = "camelCase")]
pub struct MultiObjectLikelihoodResult {
    /// ln g(Z | X) of (20); `-Infinity` when the likelihood is zero (never NaN).
    pub log_likelihood: f64,
}

/// The multi-object likelihood (20) of paper 004 for one particle, in log space, summing over
/// the associations θ by dynamic programming over subsets (exact; no enumeration). Options
/// `{ likelihoods, detectionProbability, clutterRate, clutterDensity }`; returns
/// `{ logLikelihood }`.
#[wasm_bindgen(
    js_name = multiObjectLikelihood,
    unchecked_return_type = "MultiObjectLikelihoodResult"
)]
pub fn multi_object_likelihood(
    #[wasm_bindgen(unchecked_param_type = "MultiObjectLikelihoodOptions")] options: JsValue,
) -> JsResult<JsValue> {
    let o: MultiObjectLikelihoodOptions = read(options, "options")?;
    let n = o.likelihoods.len();
    let m = o.clutter_density.0.len();
    if n > MAX_OBJECTS {
        return Err(range_error(format!(
            "options.likelihoods: at most {MAX_OBJECTS} objects are supported, got {n}"
        )));
    }
    if m > MAX_MEASUREMENTS {
        return Err(range_error(format!(
            "options.clutterDensity: at most {MAX_MEASUREMENTS} measurements are supported, got {m}"
        )));
    }
    if n.min(m) > MAX_SMALLER {
        return Err(range_error(format!(
            "options.likelihoods: min(objects, measurements) must be at most {MAX_SMALLER}, got {}",
            n.min(m)
        )));
    }
    let rows: Vec<Vec<f64>> = o.likelihoods.into_iter().map(|r| r.0).collect();
    let log_likelihood = fisst::smc::ln_likelihood(
        &rows,
        o.detection_probability,
        o.clutter_rate,
        &o.clutter_density.0,
    )
    .or_throw_in("options")?;
    write(&MultiObjectLikelihoodResult { log_likelihood })
}

// ------------------------------------------------------------------ the case study

use fisst::control::case_study::MAX_WORK;
use fisst::control::{
    Action, ControlConfig, ControlRun, MeanSeries, Scheme as CoreScheme, SchemeSummary, StepOutcome,
};

use crate::boundary::{check_range, seed_or_entropy};
use crate::types::Point;

/// At most this many runs per scheme in `compareSchemes`.
const MAX_RUNS: usize = 1_000;

/// The paper's settings (Sec. 5), read for the options that are omitted.
fn paper() -> ControlConfig {
    ControlConfig::paper(
        CoreScheme::Random,
        fisst::control::case_study::DEFAULT_STEPS,
    )
}
fn particles_default() -> usize {
    paper().particles
}
fn future_scans_default() -> usize {
    paper().future_scans
}
fn alpha_default() -> f64 {
    paper().alpha
}
fn steps_default() -> usize {
    paper().steps
}
fn max_objects_default() -> usize {
    paper().max_objects
}

/// A sensor-control scheme of Fig. 3: the expected Rényi divergence (15)–(17), the Fisher
/// information gain (27)–(29), PENT (30)–(34), or a uniformly random admissible action.
#[derive(Clone, Copy, Debug, Deserialize, Serialize, Tsify, PartialEq, Eq)]
#[serde(rename_all = "kebab-case")]
pub enum Scheme {
    /// The expected Rényi divergence.
    Renyi,
    /// The trace of the Fisher information.
    Fisher,
    /// The posterior expected number of targets.
    Pent,
    /// Uniformly random.
    Random,
}

impl Scheme {
    fn core(self) -> CoreScheme {
        match self {
            Scheme::Renyi => CoreScheme::Renyi,
            Scheme::Fisher => CoreScheme::Fisher,
            Scheme::Pent => CoreScheme::Pent,
            Scheme::Random => CoreScheme::Random,
        }
    }
    fn of(s: CoreScheme) -> Self {
        match s {
            CoreScheme::Renyi => Scheme::Renyi,
            CoreScheme::Fisher => Scheme::Fisher,
            CoreScheme::Pent => Scheme::Pent,
            CoreScheme::Random => Scheme::Random,
        }
    }
    fn name(self) -> &'static str {
        match self {
            Scheme::Renyi => "renyi",
            Scheme::Fisher => "fisher",
            Scheme::Pent => "pent",
            Scheme::Random => "random",
        }
    }
}

/// Options of `new SensorControlRun`: the case study of paper 004, Sec. 5 (𝒜 = [0, 1000]² m,
/// p_D = 0.95, λ = 0.8, sources at (300, 600) and (750, 250), σ = 10 + 4·10⁻⁵ d²).
#[derive(Deserialize, Tsify)]
#[serde(rename_all = "camelCase")]
pub struct SensorControlRunOptions {
    /// Seed (integer in [0, 2^53 − 1]); omitted: fresh entropy, read back as `run.seed`.
    #[tsify(optional)]
    pub seed: Option<u64>,
    /// The control scheme.
    pub scheme: Scheme,
    /// N, the number of multi-object particles (default 750; 1 … 20,000).
    #[serde(default = "particles_default")]
    pub particles: usize,
    /// M, the ideal future scans per Rényi reward (default 200; 1 … 2,000;
    /// particles · futureScans ≤ 1,000,000).
    #[serde(default = "future_scans_default")]
    pub future_scans: usize,
    /// α > 0 of the Rényi divergence (default 0.5; 1 is the Kullback–Leibler divergence).
    #[serde(default = "alpha_default")]
    pub alpha: f64,
    /// K, the number of steps (default 40; 1 … 1,000).
    #[serde(default = "steps_default")]
    pub steps: usize,
    /// The sensor's initial location [x, y] in the area (default [0, 0]).
    #[tsify(optional)]
    pub start: Option<Point>,
    /// n_max, the largest cardinality of a particle (default 4; 1 … 8).
    #[serde(default = "max_objects_default")]
    pub max_objects: usize,
}

struct Common {
    particles: usize,
    future_scans: usize,
    alpha: f64,
    steps: usize,
    start: Option<Point>,
    max_objects: usize,
}

fn config(scheme: CoreScheme, c: Common) -> JsResult<ControlConfig> {
    let mut cfg = ControlConfig::paper(scheme, c.steps);
    cfg.particles = c.particles;
    cfg.future_scans = c.future_scans;
    cfg.alpha = c.alpha;
    cfg.max_objects = c.max_objects;
    cfg.check_limits().or_throw_in("options")?;
    if c.particles.saturating_mul(c.future_scans) > MAX_WORK {
        return Err(range_error(format!(
            "options.futureScans: particles · futureScans must be at most {MAX_WORK}, got {}",
            c.particles * c.future_scans
        )));
    }
    if let Some(p) = c.start {
        let [x, y] = p.0[..] else {
            return Err(range_error(format!(
                "options.start has length {}, expected 2",
                p.0.len()
            )));
        };
        cfg.start = [x, y];
    }
    cfg.validate().or_throw_in("options")?;
    Ok(cfg)
}

/// The action u_k (23).
#[derive(Serialize, Tsify)]
pub struct ActionOut {
    /// 0 … 16: 0 = stay, else 1 + (ring − 1)·8 + (heading − 1).
    pub index: usize,
    /// j: 0 (stay), 1 or 2 (a move of j·50 m).
    pub ring: usize,
    /// ℓ: 0 for stay, else 1 … 8 (angle ℓ·45°, counter-clockwise from +x).
    pub heading: usize,
    /// The sensor's next location [x, y].
    pub position: [f64; 2],
}

fn action_out(a: &Action) -> ActionOut {
    ActionOut {
        index: a.index,
        ring: a.ring,
        heading: a.heading,
        position: a.position,
    }
}

/// The point estimate of Sec. 5.2.
#[derive(Serialize, Tsify)]
#[serde(rename_all = "camelCase")]
pub struct ControlEstimate {
    /// n̂, the MAP cardinality (22).
    pub cardinality: usize,
    /// n̂ points [x, y]: the mean of the particles with n̂ objects.
    pub states: Vec<[f64; 2]>,
    /// The fraction of particles with 0 … maxObjects objects.
    pub cardinality_pmf: Vec<f64>,
}

/// OSPA (c = 100 m, p = 2) of the estimate against the truth, with its rooted parts
/// (distance² = localisation² + cardinality²), eqs (24)–(26).
#[derive(Serialize, Tsify)]
pub struct OspaParts {
    /// OSPA, in [0, 100].
    pub distance: f64,
    /// The localisation part (26).
    pub localisation: f64,
    /// The cardinality part (25).
    pub cardinality: f64,
}

/// Result of `SensorControlRun.step()`.
#[derive(Serialize, Tsify)]
pub struct ControlStep {
    /// k, the 1-based step just processed.
    pub k: usize,
    /// Where Z_k was taken [x, y].
    pub sensor: [f64; 2],
    /// Z_k, the ranges received (m).
    pub measurements: Vec<f64>,
    /// u_k, chosen after the update: where the sensor goes next.
    pub action: ActionOut,
    /// 17 rewards indexed like `action.index`; `-Infinity` (a number) for actions outside the
    /// area (postMessage keeps it; JSON.stringify writes null). 'random': 0 when admissible.
    #[tsify(type = "number[]")]
    pub rewards: Vec<f64>,
    /// X̂_k.
    pub estimate: ControlEstimate,
    /// OSPA of X̂_k.
    pub ospa: OspaParts,
}

fn step_out(s: StepOutcome) -> ControlStep {
    ControlStep {
        k: s.k,
        sensor: s.sensor,
        measurements: s.measurements,
        action: action_out(&s.action),
        rewards: s.rewards,
        estimate: ControlEstimate {
            cardinality: s.estimate.cardinality,
            states: s.estimate.states,
            cardinality_pmf: s.estimate.cardinality_pmf,
        },
        ospa: OspaParts {
            distance: s.ospa[0],
            localisation: s.ospa[1],
            cardinality: s.ospa[2],
        },
    }
}

/// The particles, flat: particle i has `cardinalities[i]` objects whose x, y are
/// `positions[2o]`, `positions[2o + 1]` for o = Σ_{i′<i} cardinalities[i′] + 0 … − 1.
#[derive(Serialize, Tsify)]
pub struct ControlParticles {
    /// w_i (1/N after each step).
    pub weights: Vec<f64>,
    /// n_i.
    pub cardinalities: Vec<usize>,
    /// The objects' x, y, particle after particle.
    pub positions: Vec<f64>,
}

/// One run of Algorithm 1 of paper 004 (sensor control for multi-object estimation). Call
/// `free()` when done.
#[wasm_bindgen(js_name = SensorControlRun)]
pub struct SensorControlRunJs {
    inner: ControlRun,
    seed: u64,
    scheme: Scheme,
}

#[wasm_bindgen(js_class = SensorControlRun)]
impl SensorControlRunJs {
    /// Validates `options` (see `SensorControlRunOptions`).
    #[wasm_bindgen(constructor)]
    pub fn new(
        #[wasm_bindgen(unchecked_param_type = "SensorControlRunOptions")] options: JsValue,
    ) -> JsResult<SensorControlRunJs> {
        let o: SensorControlRunOptions = read(options, "options")?;
        let seed = seed_or_entropy(o.seed)?;
        let cfg = config(
            o.scheme.core(),
            Common {
                particles: o.particles,
                future_scans: o.future_scans,
                alpha: o.alpha,
                steps: o.steps,
                start: o.start,
                max_objects: o.max_objects,
            },
        )?;
        let inner = ControlRun::new(cfg, seed).or_throw_in("options")?;
        Ok(SensorControlRunJs {
            inner,
            seed,
            scheme: o.scheme,
        })
    }

    /// One step of Algorithm 1: scan, update (20), resample and regularise, estimate (22),
    /// OSPA, choose the next action. A `RangeError` once `k` reached `steps`.
    #[wasm_bindgen(unchecked_return_type = "ControlStep")]
    pub fn step(&mut self) -> JsResult<JsValue> {
        if self.inner.k() >= self.inner.config().steps {
            return Err(range_error(format!(
                "step: the run has done all its {} steps",
                self.inner.config().steps
            )));
        }
        let s = self.inner.step().or_throw_in("step")?;
        write(&step_out(s))
    }

    /// The particles (a copy).
    #[wasm_bindgen(getter, unchecked_return_type = "ControlParticles")]
    pub fn particles(&self) -> JsResult<JsValue> {
        let p = self.inner.particles();
        write(&ControlParticles {
            weights: p.weights.clone(),
            cardinalities: p.sets.iter().map(|s| s.len()).collect(),
            positions: p.sets.iter().flatten().flat_map(|x| [x[0], x[1]]).collect(),
        })
    }

    /// The start and every location moved to (length k + 1).
    #[wasm_bindgen(getter, js_name = sensorPath, unchecked_return_type = "[number, number][]")]
    pub fn sensor_path(&self) -> JsResult<JsValue> {
        write(self.inner.sensor_path())
    }

    /// The true sources, [[300, 600], [750, 250]].
    #[wasm_bindgen(getter, unchecked_return_type = "[number, number][]")]
    pub fn truth(&self) -> JsResult<JsValue> {
        write(&self.inner.config().truth)
    }

    /// Z_1 … Z_k (measurements[k − 1] was taken at sensorPath[k − 1]).
    #[wasm_bindgen(getter, unchecked_return_type = "number[][]")]
    pub fn measurements(&self) -> JsResult<JsValue> {
        write(self.inner.measurements())
    }

    /// Steps done.
    #[wasm_bindgen(getter)]
    pub fn k(&self) -> usize {
        self.inner.k()
    }

    /// K.
    #[wasm_bindgen(getter)]
    pub fn steps(&self) -> usize {
        self.inner.config().steps
    }

    /// The seed used (53-bit integer).
    #[wasm_bindgen(getter)]
    pub fn seed(&self) -> f64 {
        self.seed as f64
    }

    /// The scheme's name.
    #[wasm_bindgen(getter)]
    pub fn scheme(&self) -> String {
        self.scheme.name().into()
    }
}

/// Options of `compareSchemes`.
#[derive(Deserialize, Tsify)]
#[serde(rename_all = "camelCase")]
pub struct CompareSchemesOptions {
    /// Monte Carlo runs per scheme (1 … 1,000).
    pub runs: usize,
    /// K (1 … 1,000).
    pub steps: usize,
    /// Master seed; run r of every scheme uses the same derived seed. Omitted: entropy.
    #[tsify(optional)]
    pub seed: Option<u64>,
    /// The schemes (default all four: renyi, fisher, pent, random).
    #[tsify(optional)]
    pub schemes: Option<Vec<Scheme>>,
    /// N (default 750).
    #[serde(default = "particles_default")]
    pub particles: usize,
    /// M (default 200).
    #[serde(default = "future_scans_default")]
    pub future_scans: usize,
    /// α (default 0.5).
    #[serde(default = "alpha_default")]
    pub alpha: f64,
    /// The sensor's initial location (default [0, 0]).
    #[tsify(optional)]
    pub start: Option<Point>,
    /// n_max (default 4).
    #[serde(default = "max_objects_default")]
    pub max_objects: usize,
    /// Called as runs finish with (done, total), total = runs · schemes.length.
    #[tsify(type = "(done: number, total: number) => void", optional)]
    pub on_progress: Option<crate::de::JsFunction>,
}

/// A mean over runs per step, with its standard error (sample sd / √runs; 0 for one run).
#[derive(Serialize, Tsify)]
#[serde(rename_all = "camelCase")]
pub struct MeanOverRuns {
    /// At k = 1 … K.
    pub mean: Vec<f64>,
    /// At k = 1 … K.
    pub standard_error: Vec<f64>,
}

fn mean_out(m: MeanSeries) -> MeanOverRuns {
    MeanOverRuns {
        mean: m.mean,
        standard_error: m.standard_error,
    }
}

/// One scheme of `compareSchemes`.
#[derive(Serialize, Tsify)]
pub struct SchemeComparison {
    /// The scheme.
    pub scheme: Scheme,
    /// OSPA (24).
    pub distance: MeanOverRuns,
    /// The localisation part (26).
    pub localisation: MeanOverRuns,
    /// The cardinality part (25).
    pub cardinality: MeanOverRuns,
}

/// Result of `compareSchemes`.
#[derive(Serialize, Tsify)]
#[serde(rename_all = "camelCase")]
pub struct CompareSchemesResult {
    /// The master seed used.
    pub seed: u64,
    /// The seed of run r (the same for every scheme; 53-bit integers): `new
    /// SensorControlRun({ seed: runSeeds[r], scheme, … })` repeats that run exactly.
    pub run_seeds: Vec<u64>,
    /// Runs per scheme.
    pub runs: usize,
    /// K.
    pub steps: usize,
    /// One entry per requested scheme, in order.
    pub schemes: Vec<SchemeComparison>,
}

/// Fig. 3 of paper 004: `runs` seeded runs of each scheme, averaged. Options
/// `{ runs, steps, seed, schemes, onProgress, … }`; returns `{ seed, runs, steps, schemes:
/// [{ scheme, distance, localisation, cardinality }] }`, each part `{ mean, standardError }`.
#[wasm_bindgen(js_name = compareSchemes, unchecked_return_type = "CompareSchemesResult")]
pub fn compare_schemes(
    #[wasm_bindgen(unchecked_param_type = "CompareSchemesOptions")] options: JsValue,
) -> JsResult<JsValue> {
    let o: CompareSchemesOptions = read(options, "options")?;
    let seed = seed_or_entropy(o.seed)?;
    check_range("options.runs", o.runs, 1, MAX_RUNS)?;
    let schemes = o
        .schemes
        .unwrap_or_else(|| vec![Scheme::Renyi, Scheme::Fisher, Scheme::Pent, Scheme::Random]);
    check_range("options.schemes.length", schemes.len(), 1, 16)?;
    let base = config(
        CoreScheme::Random,
        Common {
            particles: o.particles,
            future_scans: o.future_scans,
            alpha: o.alpha,
            steps: o.steps,
            start: o.start,
            max_objects: o.max_objects,
        },
    )?;
    let core_schemes: Vec<CoreScheme> = schemes.iter().map(|s| s.core()).collect();
    let progress = o.on_progress;
    let out: Vec<SchemeSummary> = fisst::control::compare_schemes::<Failure>(
        &base,
        &core_schemes,
        o.runs,
        seed,
        |done, total| {
            if let Some(f) = &progress {
                f.0.call2(
                    &JsValue::NULL,
                    &(done as f64).into(),
                    &(total as f64).into(),
                )
                .map_err(Failure::Js)?;
            }
            Ok(())
        },
    )
    .map_err(|e| match e {
        Failure::Js(v) => v,
        Failure::Core(e) => crate::boundary::core_error(e.within("options")),
    })?;
    write(&CompareSchemesResult {
        seed,
        run_seeds: fisst::control::run_seeds(seed, o.runs),
        runs: o.runs,
        steps: o.steps,
        schemes: out
            .into_iter()
            .map(|s| SchemeComparison {
                scheme: Scheme::of(s.scheme),
                distance: mean_out(s.distance),
                localisation: mean_out(s.localisation),
                cardinality: mean_out(s.cardinality),
            })
            .collect(),
    })
}

/// A failure inside the comparison: a core error or the callback's exception.
enum Failure {
    Core(fisst::Error),
    Js(JsValue),
}

impl From<fisst::Error> for Failure {
    fn from(e: fisst::Error) -> Self {
        Failure::Core(e)
    }
}
