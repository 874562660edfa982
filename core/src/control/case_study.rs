//! The case study of paper `004`, Sec. 5: a range-only sensor moving in 𝒜 = [0, 1000]² m,
//! p_D = 0.95, λ = 0.8 clutter uniform on [0, √2·1000] m, sources at (300, 600) and
//! (750, 250), σ(x) = 10 + 4·10⁻⁵ ‖x − u‖², N = 750 particles, M = 200 ideal future scans,
//! and the run driver of Algorithm 1 with one of four control schemes, scored by OSPA
//! (c = 100, p = 2). The sensor is in [`super::sensor`], the batched Rényi reward (17) in
//! `control/renyi_kernel.rs`.

use alloc::vec;
use alloc::vec::Vec;

use rand::Rng;

use super::actions::{Action, ActionGrid};
use super::renyi_kernel::{FutureScans, renyi_rewards};
use super::rewards::{fisher_reward, pent_reward};
pub use super::sensor::RangeSensor;
use crate::error::{Error, Phrase, Result};
use crate::math::fns::exp;
use crate::math::rng::{SeededRng, index, seeded};
use crate::metrics::Ospa;
use crate::smc::{
    Area, LikelihoodWorkspace, MultiObjectLikelihood, MultiObjectParticles, Regularisation,
    SetEstimate, State, regularise, resample, reweight,
};

/// K when the options omit it (`steps`): 40 (the text of `004_…` does not state the length of
/// the runs of Fig. 3).
pub const DEFAULT_STEPS: usize = 40;

/// The bindings' cap on N (`particles`).
pub const MAX_PARTICLES: usize = 20_000;
/// The bindings' cap on M (`future_scans`).
pub const MAX_FUTURE_SCANS: usize = 2_000;
/// The bindings' cap on the work of one step, N·M·w(n_max) with w = 1 up to four objects and
/// 2^(n_max − 3) past four ([`work_weight`]): 300,000 (the paper's N·M = 750 × 200 = 150,000
/// with n_max = 4 fits twice). The cost of a Rényi step grows with N·M and, past four objects,
/// with n_max (the subset sums over the objects of a particle, 2^n terms for n objects).
/// Measured in Node (CPU time of each of the first three steps, the worst of seeds 1, 4, 5, 6;
/// seed 1 is the slow one, its first scans see most objects): N·M = 300,000 at n_max = 4 took
/// 0.65–0.76 s, i.e. 2.3 µs per unit; at n_max = 5 to 8 a unit cost 6.0–6.5 µs, 2.6 times as
/// much (150,000 at n_max = 5 took 0.91–1.33 s, and 2.5 s inside the fuzzer's 10^6-case run,
/// over its 2 s bound: the cap used to be N·M·2^max(n_max − 4, 0)). The weight 4 at five
/// objects keeps that step near 0.5 s, and the doubling past it bounds a particle with
/// n_max objects, the worst case.
pub const MAX_WORK: usize = 300_000;
/// How [`MAX_WORK`] counts, as its errors say it (bindings render the names).
pub const WORK_MEASURE: &str =
    "particles · future_scans · (max_objects ≤ 4 ? 1 : 2^(max_objects − 3))";

/// The weight w(n_max) of one particle-scan in [`MAX_WORK`]: 1 for n_max ≤ 4, 2^(n_max − 3)
/// past four (4 at five objects, 32 at eight); see [`MAX_WORK`] for the measurements behind it.
#[must_use]
pub const fn work_weight(max_objects: usize) -> usize {
    if max_objects <= 4 {
        1
    } else if max_objects >= usize::BITS as usize + 3 {
        usize::MAX
    } else {
        1 << (max_objects - 3)
    }
}

/// The bindings' cap on K (`steps`).
pub const MAX_STEPS: usize = 1_000;
/// The largest n_max (`max_objects`).
pub const MAX_MAX_OBJECTS: usize = 8;

/// A sensor-control scheme of Fig. 3 of Ristic & Vo, "Sensor control for multi-object state-space estimation using random finite sets" (paper 004): the expected Rényi divergence (15)–(17), the Fisher
/// information gain (27)–(29), PENT (30)–(34), or a uniformly random admissible action.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[cfg_attr(
    feature = "serde",
    derive(serde::Serialize, serde::Deserialize),
    serde(rename_all = "lowercase")
)]
pub enum Scheme {
    /// `renyi`: maximise the expected Rényi divergence (15)–(17).
    Renyi,
    /// `fisher`: maximise the trace of the Fisher information gain (27)–(29).
    Fisher,
    /// `pent`: maximise PENT, the posterior expected number of targets (30)–(34).
    Pent,
    /// `random`: an action drawn uniformly among the admissible ones.
    Random,
}

impl Scheme {
    /// The four schemes of Fig. 3, in its order.
    pub const ALL: [Scheme; 4] = [Scheme::Renyi, Scheme::Fisher, Scheme::Pent, Scheme::Random];

    /// The scheme's name: `renyi`, `fisher`, `pent` or `random` (its serde name).
    pub fn name(self) -> &'static str {
        match self {
            Scheme::Renyi => "renyi",
            Scheme::Fisher => "fisher",
            Scheme::Pent => "pent",
            Scheme::Random => "random",
        }
    }
}

/// Options of one run of Algorithm 1 on the case study of Ristic & Vo, "Sensor control for multi-object state-space estimation using random finite sets" (paper 004), Sec. 5 (𝒜 = [0, 1000]²
/// m, p_D = 0.95, λ = 0.8, sources at (300, 600) and (750, 250), σ = 10 + 4·10⁻⁵ d²). The
/// scene (area, truth, sensor, actions, regularisation) is the paper's and is not read from
/// the options.
#[derive(Clone, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct ControlOptions {
    /// The seed (integer in [0, 2^53 − 1]); omitted: fresh entropy, read back as `run.seed`
    /// (in Rust, the caller draws it: [`ControlRun::new`] takes the seed it uses).
    #[cfg_attr(
        feature = "serde",
        serde(default, skip_serializing_if = "Option::is_none")
    )]
    pub seed: Option<u64>,
    /// The control scheme: which reward chooses the sensor's next action.
    pub scheme: Scheme,
    /// The number N of multi-object particles (default 750; 1 … 20,000).
    #[cfg_attr(
        feature = "serde",
        serde(default = "ControlOptions::default_particles")
    )]
    pub particles: usize,
    /// The number M of ideal future scans per Rényi reward (default 200; 1 … 2,000;
    /// N·M·w(n_max) ≤ 300,000, [`work_weight`]).
    #[cfg_attr(
        feature = "serde",
        serde(default = "ControlOptions::default_future_scans")
    )]
    pub future_scans: usize,
    /// The order α > 0 of the Rényi divergence (default 0.5; 1 is the Kullback–Leibler divergence).
    #[cfg_attr(feature = "serde", serde(default = "ControlOptions::default_alpha"))]
    pub alpha: f64,
    /// The number K of steps of the run (default 40; 1 … 1,000).
    #[cfg_attr(feature = "serde", serde(default = "ControlOptions::default_steps"))]
    pub steps: usize,
    /// The sensor's initial location [x, y] in m, in the area (the paper does not state it;
    /// default [0, 0]).
    #[cfg_attr(feature = "serde", serde(default = "ControlOptions::default_start"))]
    pub start: State,
    /// The largest number n_max of objects in a particle (default 4; 1 … 8; the paper does not
    /// state it).
    #[cfg_attr(
        feature = "serde",
        serde(default = "ControlOptions::default_max_objects")
    )]
    pub max_objects: usize,
    /// The surveillance area 𝒜 = [0, 1000]² m².
    #[cfg_attr(feature = "serde", serde(skip, default = "ControlOptions::paper_area"))]
    pub area: Area,
    /// The true objects' positions [x, y] in m, (300, 600) and (750, 250).
    #[cfg_attr(
        feature = "serde",
        serde(skip, default = "ControlOptions::paper_truth")
    )]
    pub truth: Vec<State>,
    /// The range-only sensor: detection probability, clutter and range noise of Sec. 5.
    #[cfg_attr(feature = "serde", serde(skip))]
    pub sensor: RangeSensor,
    /// The sensor's admissible actions (23): a grid of rings and headings.
    #[cfg_attr(feature = "serde", serde(skip))]
    pub actions: ActionGrid,
    /// The particle regularisation after resampling (Sec. 5.2).
    #[cfg_attr(feature = "serde", serde(skip))]
    pub regularisation: Regularisation,
}

impl ControlOptions {
    /// The default N (the paper's).
    pub const fn default_particles() -> usize {
        750
    }

    /// The default M (the paper's).
    pub const fn default_future_scans() -> usize {
        200
    }

    /// The default α (the paper's).
    pub const fn default_alpha() -> f64 {
        0.5
    }

    /// The default K, [`DEFAULT_STEPS`].
    pub const fn default_steps() -> usize {
        DEFAULT_STEPS
    }

    /// The default initial sensor location.
    pub const fn default_start() -> State {
        [0.0, 0.0]
    }

    /// The default n_max.
    pub const fn default_max_objects() -> usize {
        4
    }

    /// The paper's 𝒜.
    const fn paper_area() -> Area {
        Area {
            lo: [0.0, 0.0],
            hi: [1000.0, 1000.0],
        }
    }

    /// The paper's sources.
    fn paper_truth() -> Vec<State> {
        vec![[300.0, 600.0], [750.0, 250.0]]
    }

    /// The paper's case study with `scheme` and K = `steps`.
    pub fn paper(scheme: Scheme, steps: usize) -> Self {
        Self {
            seed: None,
            scheme,
            particles: Self::default_particles(),
            future_scans: Self::default_future_scans(),
            alpha: Self::default_alpha(),
            steps,
            start: Self::default_start(),
            max_objects: Self::default_max_objects(),
            area: Self::paper_area(),
            truth: Self::paper_truth(),
            sensor: RangeSensor::default(),
            actions: ActionGrid::default(),
            regularisation: Regularisation::default(),
        }
    }

    /// The bindings' work caps, before [`ControlOptions::validate`]: N in
    /// [1, [`MAX_PARTICLES`]], M in [1, [`MAX_FUTURE_SCANS`]], K in [1, [`MAX_STEPS`]],
    /// n_max in [1, [`MAX_MAX_OBJECTS`]], then N·M·w(n_max) ≤ [`MAX_WORK`] ([`work_weight`]).
    ///
    /// # Errors
    /// [`Error::OutOfRange`] naming `particles`, `future_scans`, `steps` or `max_objects`;
    /// [`Error::Form`] naming `future_scans` when N·M·w(n_max) exceeds [`MAX_WORK`]
    /// (`future_scans: {WORK_MEASURE} must be at most 300000, got …`, the measure a
    /// [`Phrase::Name`] that bindings render in their names).
    pub fn check_limits(&self) -> Result<()> {
        Error::check_range("particles", self.particles, 1, MAX_PARTICLES)?;
        Error::check_range("future_scans", self.future_scans, 1, MAX_FUTURE_SCANS)?;
        Error::check_range("steps", self.steps, 1, MAX_STEPS)?;
        Error::check_range("max_objects", self.max_objects, 1, MAX_MAX_OBJECTS)?;
        let per_scan = self.particles.saturating_mul(work_weight(self.max_objects));
        let work = per_scan.max(1).saturating_mul(self.future_scans);
        if work > MAX_WORK {
            let got = alloc::format!(" must be at most {MAX_WORK}, got {work}");
            let problem = vec![
                Phrase::text(": "),
                Phrase::name(WORK_MEASURE),
                Phrase::text(got),
            ];
            return Err(Error::form("future_scans", false, problem));
        }
        Ok(())
    }

    /// Checks the fields (Rust names).
    ///
    /// # Errors
    /// [`Error::InvalidParameter`] naming `particles`, `future_scans`, `alpha`, `steps`,
    /// `max_objects` or `start`.
    pub fn validate(&self) -> Result<()> {
        if self.particles == 0 {
            return Err(Error::parameter("particles", 0.0, "≥ 1"));
        }
        if self.future_scans == 0 {
            return Err(Error::parameter("future_scans", 0.0, "≥ 1"));
        }
        if !(self.alpha.is_finite() && self.alpha > 0.0) {
            return Err(Error::parameter("alpha", self.alpha, "finite and > 0"));
        }
        if self.steps == 0 {
            return Err(Error::parameter("steps", 0.0, "≥ 1"));
        }
        if !(1..=MAX_MAX_OBJECTS).contains(&self.max_objects) {
            return Err(Error::parameter(
                "max_objects",
                self.max_objects as f64,
                "an integer in [1, 8]",
            ));
        }
        if !self.area.contains(self.start) {
            return Err(Error::parameter(
                "start",
                if self.start[0].is_finite() {
                    self.start[1]
                } else {
                    self.start[0]
                },
                "a point of the area [0, 1000]²",
            ));
        }
        MultiObjectLikelihood::new(self.sensor.detection, self.sensor.clutter_rate)?;
        Ok(())
    }
}

/// What one step of Algorithm 1 of Ristic & Vo, "Sensor control for multi-object state-space estimation using random finite sets" (paper 004) produced.
#[derive(Clone, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct StepOutcome {
    /// The step number k, 1-based, of the step just processed.
    pub k: usize,
    /// The sensor location [x, y] in m where the scan Z_k was taken.
    pub sensor: State,
    /// The scan Z_k: the ranges received, in m.
    pub measurements: Vec<f64>,
    /// The action u_k, chosen after the update: where the sensor goes next.
    pub action: Action,
    /// The reward of each action, indexed like `action.index`; −∞ for actions outside the
    /// area (in JavaScript `-Infinity`, a number: postMessage keeps it, JSON.stringify writes
    /// null). The random scheme: 0 when admissible.
    pub rewards: Vec<f64>,
    /// The multi-object estimate X̂_k (22) after the update.
    pub estimate: SetEstimate,
    /// The OSPA error of X̂_k against the true objects, with its parts.
    pub ospa: OspaParts,
}

/// OSPA (c = 100 m, p = 2) of the estimate against the truth, with its rooted parts
/// (distance² = localisation² + cardinality²), eqs (24)–(26).
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct OspaParts {
    /// The OSPA distance (24), in m, in [0, 100].
    pub distance: f64,
    /// The OSPA localisation part (26), in m.
    pub localisation: f64,
    /// The OSPA cardinality part (25), in m.
    pub cardinality: f64,
}

impl OspaParts {
    /// (distance, localisation, cardinality).
    pub fn to_array(self) -> [f64; 3] {
        [self.distance, self.localisation, self.cardinality]
    }
}

/// The particles, flat: particle i has `cardinalities[i]` objects whose x, y are
/// `positions[2o]`, `positions[2o + 1]` for o = Σ_{i′<i} cardinalities[i′] + 0 … − 1.
#[derive(Clone, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct ControlParticles {
    /// The particle weights w_i, one per particle (1/N after each step).
    pub weights: Vec<f64>,
    /// The number of objects n_i of each particle.
    pub cardinalities: Vec<usize>,
    /// The objects' positions x, y in m, flat, particle after particle.
    pub positions: Vec<f64>,
}

impl From<&MultiObjectParticles> for ControlParticles {
    fn from(p: &MultiObjectParticles) -> Self {
        Self {
            weights: p.weights.clone(),
            cardinalities: p.sets.iter().map(|s| s.len()).collect(),
            positions: p.sets.iter().flatten().flat_map(|x| [x[0], x[1]]).collect(),
        }
    }
}

/// One run of Algorithm 1.
#[derive(Clone, Debug)]
pub struct ControlRun {
    config: ControlOptions,
    pub(super) model: MultiObjectLikelihood,
    world: SeededRng,
    rng: SeededRng,
    pub(super) particles: MultiObjectParticles,
    path: Vec<State>,
    measurements: Vec<Vec<f64>>,
    k: usize,
}

impl ControlRun {
    /// A run seeded by `seed` (the scans and the filter draw from two streams derived from it).
    pub fn new(config: ControlOptions, seed: u64) -> Result<Self> {
        config.validate()?;
        let model =
            MultiObjectLikelihood::new(config.sensor.detection, config.sensor.clutter_rate)?;
        let path = vec![config.start];
        let max_objects = config.max_objects;
        Ok(Self {
            config,
            model,
            world: seeded(seed),
            rng: seeded(seed ^ 0x9e37_79b9_7f4a_7c15),
            particles: MultiObjectParticles {
                sets: Vec::new(),
                weights: Vec::new(),
                max_objects,
            },
            path,
            measurements: Vec::new(),
            k: 0,
        })
    }

    /// The options of the run.
    pub fn options(&self) -> &ControlOptions {
        &self.config
    }
    /// The multi-object particles (empty before the first step).
    pub fn particles(&self) -> &MultiObjectParticles {
        &self.particles
    }
    /// The sensor's path: the start and every location moved to.
    pub fn sensor_path(&self) -> &[State] {
        &self.path
    }
    /// The scans Z_1 … Z_k received so far (ranges in m).
    pub fn measurements(&self) -> &[Vec<f64>] {
        &self.measurements
    }
    /// The number k of steps done.
    pub fn k(&self) -> usize {
        self.k
    }

    /// One step of Algorithm 1: scan, (initialise,) reweight by (20), resample and
    /// regularise, estimate, score, choose the next action.
    ///
    /// # Errors
    /// [`Error::Form`] naming `step` once K steps are done (`step: the run has done all its K
    /// steps`, as both bindings say it). On `Err`, the run is unchanged (the step works on its
    /// own copies of the particles and of both random streams, and stores them only on
    /// success).
    pub fn step(&mut self) -> Result<StepOutcome> {
        if self.k >= self.config.steps {
            let done = alloc::format!(": the run has done all its {} steps", self.config.steps);
            return Err(Error::form("step", false, vec![Phrase::text(done)]));
        }
        let cfg = &self.config;
        let (mut world, mut rng) = (self.world.clone(), self.rng.clone());
        let u = *self.path.last().unwrap_or(&cfg.start);
        let z = cfg.sensor.scan(&cfg.truth, u, &mut world);
        let mut particles = if self.k == 0 {
            let sensor = cfg.sensor;
            MultiObjectParticles::from_ranges(
                cfg.particles,
                cfg.max_objects,
                &cfg.area,
                u,
                &z,
                |r| sensor.sigma(r),
                &mut rng,
            )
        } else {
            // Resampling copies every set anyway: the step is out of place.
            self.particles.clone()
        };
        let (mut ws, mut buf) = (LikelihoodWorkspace::new(), Vec::new());
        let (sensor, model) = (cfg.sensor, self.model);
        reweight(&mut particles, |set| {
            sensor.ln_likelihood(&model, set, &z, u, &mut ws, &mut buf)
        });
        resample(&mut particles, &mut rng);
        regularise(&mut particles, &cfg.area, &cfg.regularisation, &mut rng);
        let estimate = particles.estimate();
        let ospa = Ospa::new(100.0, 2.0)?.decompose(&cfg.truth, &estimate.states)?;
        let actions = cfg.actions.actions(u, &cfg.area);
        let rewards = rewards(
            cfg,
            &self.model,
            &particles,
            &estimate,
            u,
            &actions,
            &mut rng,
        );
        let chosen = choose(&rewards, cfg.scheme, &mut rng);
        let action = actions[chosen];
        (self.world, self.rng, self.particles) = (world, rng, particles);
        self.path.push(action.position);
        self.measurements.push(z.clone());
        self.k += 1;
        Ok(StepOutcome {
            k: self.k,
            sensor: u,
            measurements: z,
            action,
            rewards,
            estimate,
            ospa: OspaParts {
                distance: ospa.distance,
                localisation: ospa.localisation,
                cardinality: ospa.cardinality,
            },
        })
    }
}

/// The index of the largest reward (the first on ties), or for [`Scheme::Random`] a uniform
/// admissible one; stay when nothing is admissible.
fn choose<R: Rng + ?Sized>(rewards: &[f64], scheme: Scheme, rng: &mut R) -> usize {
    let admissible: Vec<usize> = (0..rewards.len())
        .filter(|&i| rewards[i] > f64::NEG_INFINITY)
        .collect();
    if admissible.is_empty() {
        return 0;
    }
    if scheme == Scheme::Random {
        return admissible[index(rng, admissible.len())];
    }
    let mut best = admissible[0];
    for &i in &admissible {
        if rewards[i] > rewards[best] {
            best = i;
        }
    }
    best
}

/// The rewards of every action for the scheme of `cfg` (−∞ outside the area).
fn rewards<R: Rng + ?Sized>(
    cfg: &ControlOptions,
    model: &MultiObjectLikelihood,
    particles: &MultiObjectParticles,
    estimate: &SetEstimate,
    _from: State,
    actions: &[Action],
    rng: &mut R,
) -> Vec<f64> {
    if cfg.scheme == Scheme::Renyi {
        let scans = FutureScans::draw(particles, cfg.future_scans, cfg.max_objects, rng);
        return renyi_rewards(cfg, model, particles, actions, &scans);
    }
    let sensor = cfg.sensor;
    let per_action = |a: &Action| -> f64 {
        if !a.inside {
            return f64::NEG_INFINITY;
        }
        let u = a.position;
        match cfg.scheme {
            Scheme::Random => 0.0,
            Scheme::Fisher => fisher_reward(&estimate.states, u, |d| sensor.sigma(d)),
            Scheme::Pent => pent_reward(
                &estimate.states,
                u,
                particles
                    .weights
                    .iter()
                    .copied()
                    .zip(particles.sets.iter().map(|s| s.as_slice())),
                sensor.detection,
                |z| sensor.clutter_rate * exp(sensor.ln_clutter_density(z)),
                |z, x| sensor.ln_g(z, x, u),
            ),
            Scheme::Renyi => unreachable!("the Rényi rewards are evaluated by `renyi_rewards`"),
        }
    };
    #[cfg(feature = "parallel")]
    {
        use rayon::prelude::*;
        actions.par_iter().map(per_action).collect()
    }
    #[cfg(not(feature = "parallel"))]
    {
        actions.iter().map(per_action).collect()
    }
}
