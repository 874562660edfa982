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
use crate::error::{Error, Result};
use crate::math::fns::exp;
use crate::math::rng::{SeededRng, index, seeded};
use crate::metrics::Ospa;
use crate::smc::{
    Area, LikelihoodWorkspace, MultiObjectLikelihood, MultiObjectParticles, Regularisation,
    SetEstimate, State, regularise, resample, reweight,
};

/// K when a binding's options omit it (`steps`): 40 (the text of `004_…` does not state the
/// length of the runs of Fig. 3).
pub const DEFAULT_STEPS: usize = 40;

/// The bindings' cap on N (`particles`).
pub const MAX_PARTICLES: usize = 20_000;
/// The bindings' cap on M (`futureScans`).
pub const MAX_FUTURE_SCANS: usize = 2_000;
/// The bindings' cap on N·M (one Rényi step then takes about a second).
pub const MAX_WORK: usize = 1_000_000;
/// The bindings' cap on K (`steps`).
pub const MAX_STEPS: usize = 1_000;

/// The four control schemes compared in Fig. 3.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub enum Scheme {
    /// The expected Rényi divergence (15)–(17).
    Renyi,
    /// The trace of the Fisher information gain (27)–(29).
    Fisher,
    /// PENT (30)–(34).
    Pent,
    /// Uniformly random among the admissible actions.
    Random,
}

/// Settings of one run of Algorithm 1.
#[derive(Clone, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct ControlConfig {
    /// The control scheme.
    pub scheme: Scheme,
    /// N (750).
    #[cfg_attr(feature = "serde", serde(default = "ControlConfig::default_particles"))]
    pub particles: usize,
    /// M (200): ideal future scans per step (Rényi only).
    #[cfg_attr(
        feature = "serde",
        serde(default = "ControlConfig::default_future_scans")
    )]
    pub future_scans: usize,
    /// α of the Rényi divergence (0.5); α = 1 is the Kullback–Leibler divergence.
    #[cfg_attr(feature = "serde", serde(default = "ControlConfig::default_alpha"))]
    pub alpha: f64,
    /// K: the number of steps.
    pub steps: usize,
    /// The sensor's initial location (the paper does not state it; default [0, 0]).
    #[cfg_attr(feature = "serde", serde(default = "ControlConfig::default_start"))]
    pub start: State,
    /// n_max (4; the paper does not state it).
    #[cfg_attr(
        feature = "serde",
        serde(default = "ControlConfig::default_max_objects")
    )]
    pub max_objects: usize,
    /// 𝒜.
    pub area: Area,
    /// The true objects.
    pub truth: Vec<State>,
    /// The sensor.
    #[cfg_attr(feature = "serde", serde(default))]
    pub sensor: RangeSensor,
    /// The actions (23).
    #[cfg_attr(feature = "serde", serde(default))]
    pub actions: ActionGrid,
    /// The regularisation (Sec. 5.2).
    #[cfg_attr(feature = "serde", serde(default))]
    pub regularisation: Regularisation,
}

impl ControlConfig {
    /// The default N (the paper's).
    const fn default_particles() -> usize {
        750
    }

    /// The default M (the paper's).
    const fn default_future_scans() -> usize {
        200
    }

    /// The default α (the paper's).
    const fn default_alpha() -> f64 {
        0.5
    }

    /// The default initial sensor location.
    const fn default_start() -> State {
        [0.0, 0.0]
    }

    /// The default n_max.
    const fn default_max_objects() -> usize {
        4
    }

    /// The paper's case study with `scheme` and K = `steps`.
    pub fn paper(scheme: Scheme, steps: usize) -> Self {
        Self {
            scheme,
            particles: Self::default_particles(),
            future_scans: Self::default_future_scans(),
            alpha: Self::default_alpha(),
            steps,
            start: Self::default_start(),
            max_objects: Self::default_max_objects(),
            area: Area {
                lo: [0.0, 0.0],
                hi: [1000.0, 1000.0],
            },
            truth: vec![[300.0, 600.0], [750.0, 250.0]],
            sensor: RangeSensor::default(),
            actions: ActionGrid::default(),
            regularisation: Regularisation::default(),
        }
    }

    /// The bindings' work caps, before [`ControlConfig::validate`]: N in
    /// [1, [`MAX_PARTICLES`]], M in [1, [`MAX_FUTURE_SCANS`]], K in [1, [`MAX_STEPS`]],
    /// n_max in [1, 8] (N·M ≤ [`MAX_WORK`] is the caller's, whose message gives the product).
    ///
    /// # Errors
    /// [`Error::InvalidParameter`] naming `particles`, `futureScans`, `steps` or `maxObjects`.
    pub fn check_limits(&self) -> Result<()> {
        let limits: [(&str, usize, usize, &'static str); 4] = [
            (
                "particles",
                self.particles,
                MAX_PARTICLES,
                "an integer in [1, 20000]",
            ),
            (
                "futureScans",
                self.future_scans,
                MAX_FUTURE_SCANS,
                "an integer in [1, 2000]",
            ),
            ("steps", self.steps, MAX_STEPS, "an integer in [1, 1000]"),
            ("maxObjects", self.max_objects, 8, "an integer in [1, 8]"),
        ];
        for (what, value, max, expected) in limits {
            if !(1..=max).contains(&value) {
                return Err(Error::parameter(what, value as f64, expected));
            }
        }
        Ok(())
    }

    /// Checks the fields (names as in the bindings).
    pub fn validate(&self) -> Result<()> {
        if self.particles == 0 {
            return Err(Error::parameter("particles", 0.0, "≥ 1"));
        }
        if self.future_scans == 0 {
            return Err(Error::parameter("futureScans", 0.0, "≥ 1"));
        }
        if !(self.alpha.is_finite() && self.alpha > 0.0) {
            return Err(Error::parameter("alpha", self.alpha, "finite and > 0"));
        }
        if self.steps == 0 {
            return Err(Error::parameter("steps", 0.0, "≥ 1"));
        }
        if !(1..=8).contains(&self.max_objects) {
            return Err(Error::parameter(
                "maxObjects",
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

/// What one step of Algorithm 1 produced.
#[derive(Clone, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct StepOutcome {
    /// k (1-based).
    pub k: usize,
    /// Where Z_k was taken.
    pub sensor: State,
    /// Z_k.
    pub measurements: Vec<f64>,
    /// u_k, the action chosen after the update.
    pub action: Action,
    /// The reward of each of the actions (−∞ outside the area).
    pub rewards: Vec<f64>,
    /// X̂_k.
    pub estimate: SetEstimate,
    /// OSPA (c = 100, p = 2) of X̂_k against the truth: (distance, localisation, cardinality).
    pub ospa: [f64; 3],
}

/// One run of Algorithm 1.
#[derive(Clone, Debug)]
pub struct ControlRun {
    config: ControlConfig,
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
    pub fn new(config: ControlConfig, seed: u64) -> Result<Self> {
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

    /// The settings.
    pub fn config(&self) -> &ControlConfig {
        &self.config
    }
    /// The particles (empty before the first step).
    pub fn particles(&self) -> &MultiObjectParticles {
        &self.particles
    }
    /// The start and every location moved to.
    pub fn sensor_path(&self) -> &[State] {
        &self.path
    }
    /// Z_1 … Z_k.
    pub fn measurements(&self) -> &[Vec<f64>] {
        &self.measurements
    }
    /// Steps done.
    pub fn k(&self) -> usize {
        self.k
    }

    /// One step of Algorithm 1: scan, (initialise,) reweight by (20), resample and
    /// regularise, estimate, score, choose the next action.
    ///
    /// # Errors
    /// [`Error::Unsupported`] naming `steps` once K steps are done. On `Err`, the run is
    /// unchanged (the step works on its own copies of the particles and of both random
    /// streams, and stores them only on success).
    pub fn step(&mut self) -> Result<StepOutcome> {
        if self.k >= self.config.steps {
            return Err(Error::Unsupported {
                what: "steps".into(),
                reason: "the run has done all its steps",
            });
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
            ospa: [ospa.distance, ospa.localisation, ospa.cardinality],
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
    cfg: &ControlConfig,
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
