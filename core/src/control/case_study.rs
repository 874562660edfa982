//! The case study of paper `004`, Sec. 5: a range-only sensor moving in 𝒜 = [0, 1000]² m,
//! p_D = 0.95, λ = 0.8 clutter uniform on [0, √2·1000] m, sources at (300, 600) and
//! (750, 250), σ(x) = 10 + 4·10⁻⁵ ‖x − u‖², N = 750 particles, M = 200 ideal future scans,
//! and Algorithm 1 with one of four control schemes, scored by OSPA (c = 100, p = 2).

use alloc::vec;
use alloc::vec::Vec;

use rand::Rng;

use super::actions::{Action, ActionGrid};
use super::rewards::{fisher_reward, ln_normal, pent_reward, renyi_divergence};
use crate::error::{Error, Result};
use crate::gaussian::normal;
use crate::math::fns::{exp, ln, sqrt};
use crate::math::rng::{SeededRng, index, poisson, seeded, uniform};
use crate::metrics::Ospa;
use crate::smc::likelihood::{SmallTables, negligible_pair_bound};
use crate::smc::{
    Area, LikelihoodWorkspace, MultiObjectLikelihood, MultiObjectParticles, Regularisation,
    SetEstimate, State, regularise, resample, reweight, systematic,
};

/// The range sensor of (19) and (21): z = ‖x − u‖ + v, v ~ N(0, σ²(x)), σ = σ₀ + s‖x − u‖²,
/// detection p_D, Poisson clutter of rate λ uniform on [0, R_max].
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RangeSensor {
    /// p_D (0.95).
    pub detection: f64,
    /// λ (0.8).
    pub clutter_rate: f64,
    /// R_max (√2·1000 m).
    pub max_range: f64,
    /// σ₀ (10 m).
    pub sigma0: f64,
    /// s (4·10⁻⁵ m⁻¹).
    pub sigma_slope: f64,
}

impl Default for RangeSensor {
    fn default() -> Self {
        Self {
            detection: 0.95,
            clutter_rate: 0.8,
            max_range: core::f64::consts::SQRT_2 * 1000.0,
            sigma0: 10.0,
            sigma_slope: 4e-5,
        }
    }
}

impl RangeSensor {
    /// σ at range d.
    #[inline]
    pub fn sigma(&self, d: f64) -> f64 {
        self.sigma0 + self.sigma_slope * d * d
    }

    /// ln c(z) (uniform on [0, R_max]; −∞ outside).
    #[inline]
    pub fn ln_clutter_density(&self, z: f64) -> f64 {
        if (0.0..=self.max_range).contains(&z) {
            -ln(self.max_range)
        } else {
            f64::NEG_INFINITY
        }
    }

    /// ln g(z | x, u) of (21).
    #[inline]
    pub fn ln_g(&self, z: f64, x: State, u: State) -> f64 {
        let d = libm::hypot(x[0] - u[0], x[1] - u[1]);
        ln_normal(z, d, self.sigma(d))
    }

    /// One scan from `u` of the objects `truth`: each detected with p_D, plus Poisson clutter.
    pub fn scan<R: Rng + ?Sized>(&self, truth: &[State], u: State, rng: &mut R) -> Vec<f64> {
        let mut z = Vec::new();
        for x in truth {
            if uniform(rng) < self.detection {
                let d = libm::hypot(x[0] - u[0], x[1] - u[1]);
                z.push(d + self.sigma(d) * normal::sample(rng));
            }
        }
        // Poisson count by inversion (λ is small).
        for _ in 0..poisson(rng, self.clutter_rate, 10_000) {
            z.push(self.max_range * uniform(rng));
        }
        z
    }

    /// ln g(Z | X, u) of (20) for the particle `set`.
    pub fn ln_likelihood(
        &self,
        model: &MultiObjectLikelihood,
        set: &[State],
        z: &[f64],
        u: State,
        ws: &mut LikelihoodWorkspace,
        buf: &mut Vec<f64>,
    ) -> f64 {
        let ln_c: Vec<f64> = z.iter().map(|&z| self.ln_clutter_density(z)).collect();
        buf.clear();
        for &x in set {
            buf.extend(z.iter().map(|&zj| self.ln_g(zj, x, u)));
        }
        model.ln_likelihood_from_logs(set.len(), buf, &ln_c, ws)
    }
}

/// The four control schemes compared in Fig. 3.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
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
pub struct ControlConfig {
    /// The control scheme.
    pub scheme: Scheme,
    /// N (750).
    pub particles: usize,
    /// M (200): ideal future scans per step (Rényi only).
    pub future_scans: usize,
    /// α of the Rényi divergence (0.5); α = 1 is the Kullback–Leibler divergence.
    pub alpha: f64,
    /// K: the number of steps.
    pub steps: usize,
    /// The sensor's initial location (the paper does not state it; default [0, 0]).
    pub start: State,
    /// n_max (4; the paper does not state it).
    pub max_objects: usize,
    /// 𝒜.
    pub area: Area,
    /// The true objects.
    pub truth: Vec<State>,
    /// The sensor.
    pub sensor: RangeSensor,
    /// The actions (23).
    pub actions: ActionGrid,
    /// The regularisation (Sec. 5.2).
    pub regularisation: Regularisation,
}

impl ControlConfig {
    /// The paper's case study with `scheme` and K = `steps`.
    pub fn paper(scheme: Scheme, steps: usize) -> Self {
        Self {
            scheme,
            particles: 750,
            future_scans: 200,
            alpha: 0.5,
            steps,
            start: [0.0, 0.0],
            max_objects: 4,
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
    model: MultiObjectLikelihood,
    world: SeededRng,
    rng: SeededRng,
    particles: MultiObjectParticles,
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
    /// [`Error::Unsupported`] naming `steps` once K steps are done.
    pub fn step(&mut self) -> Result<StepOutcome> {
        if self.k >= self.config.steps {
            return Err(Error::Unsupported {
                what: "steps".into(),
                reason: "the run has done all its steps",
            });
        }
        let cfg = &self.config;
        let u = *self.path.last().unwrap_or(&cfg.start);
        let z = cfg.sensor.scan(&cfg.truth, u, &mut self.world);
        if self.k == 0 {
            let sensor = cfg.sensor;
            self.particles = MultiObjectParticles::from_ranges(
                cfg.particles,
                cfg.max_objects,
                &cfg.area,
                u,
                &z,
                |r| sensor.sigma(r),
                &mut self.rng,
            );
        }
        let (mut ws, mut buf) = (LikelihoodWorkspace::new(), Vec::new());
        let (sensor, model) = (cfg.sensor, self.model);
        reweight(&mut self.particles, |set| {
            sensor.ln_likelihood(&model, set, &z, u, &mut ws, &mut buf)
        });
        resample(&mut self.particles, &mut self.rng);
        regularise(
            &mut self.particles,
            &cfg.area,
            &cfg.regularisation,
            &mut self.rng,
        );
        let estimate = self.particles.estimate();
        let ospa = Ospa::new(100.0, 2.0)?.decompose(&cfg.truth, &estimate.states)?;
        let actions = cfg.actions.actions(u, &cfg.area);
        let rewards = rewards(
            cfg,
            &self.model,
            &self.particles,
            &estimate,
            u,
            &actions,
            &mut self.rng,
        );
        let chosen = choose(&rewards, cfg.scheme, &mut self.rng);
        let action = actions[chosen];
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
    let sensor = cfg.sensor;
    let per_action = |a: &Action, scans: &FutureScans, ws: &mut LikelihoodWorkspace| -> f64 {
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
            Scheme::Renyi => renyi_reward(cfg, model, particles, u, scans, ws),
        }
    };
    if cfg.scheme == Scheme::Renyi {
        let scans = FutureScans::draw(particles, cfg.future_scans, cfg.max_objects, rng);
        return renyi_rewards(cfg, model, particles, actions, &scans);
    }
    let scans = FutureScans::default();
    #[cfg(feature = "parallel")]
    {
        use rayon::prelude::*;
        actions
            .par_iter()
            .map_init(LikelihoodWorkspace::new, |ws, a| per_action(a, &scans, ws))
            .collect()
    }
    #[cfg(not(feature = "parallel"))]
    {
        let mut ws = LikelihoodWorkspace::new();
        actions
            .iter()
            .map(|a| per_action(a, &scans, &mut ws))
            .collect()
    }
}

/// Future scans per task of [`renyi_rewards`]: an action's M scans are split into chunks of
/// this many, so that the tasks balance over the threads (17 actions, of which often about
/// 11 inside the area, over 2 threads leave one idle for a twelfth of the step).
const SCANS_PER_TASK: usize = 50;

/// The Rényi rewards (17) of every action ([`renyi_reward`], −∞ outside the area), evaluated
/// as tasks of one action and [`SCANS_PER_TASK`] scans (in parallel with `parallel`), whose
/// divergences are then summed per action in the order of the scans: the same bits as one
/// [`renyi_reward`] per action, whatever the split.
fn renyi_rewards(
    cfg: &ControlConfig,
    model: &MultiObjectLikelihood,
    particles: &MultiObjectParticles,
    actions: &[Action],
    scans: &FutureScans,
) -> Vec<f64> {
    let setup = |a: &Action| {
        a.inside
            .then(|| RenyiSetup::new(cfg, model, particles, a.position))
    };
    #[cfg(feature = "parallel")]
    let setups: Vec<Option<RenyiSetup>> = {
        use rayon::prelude::*;
        actions.par_iter().map(setup).collect()
    };
    #[cfg(not(feature = "parallel"))]
    let setups: Vec<Option<RenyiSetup>> = actions.iter().map(setup).collect();
    let m = scans.picks.len();
    // (action, its setup, a chunk of scans), actions ascending and chunks in scan order.
    type Task<'a> = (usize, &'a RenyiSetup, core::ops::Range<usize>);
    let tasks: Vec<Task> = setups
        .iter()
        .enumerate()
        .filter_map(|(k, s)| s.as_ref().map(|s| (k, s)))
        .flat_map(|(k, s)| {
            (0..m)
                .step_by(SCANS_PER_TASK)
                .map(move |lo| (k, s, lo..(lo + SCANS_PER_TASK).min(m)))
        })
        .collect();
    let task = |ws: &mut LikelihoodWorkspace, (_, setup, range): &Task| {
        renyi_divergences(cfg, model, particles, setup, scans, range.clone(), ws)
    };
    #[cfg(feature = "parallel")]
    let done: Vec<Vec<Option<f64>>> = {
        use rayon::prelude::*;
        tasks
            .par_iter()
            .map_init(LikelihoodWorkspace::new, task)
            .collect()
    };
    #[cfg(not(feature = "parallel"))]
    let done: Vec<Vec<Option<f64>>> = {
        let mut ws = LikelihoodWorkspace::new();
        tasks.iter().map(|t| task(&mut ws, t)).collect()
    };
    actions
        .iter()
        .enumerate()
        .map(|(k, a)| {
            if !a.inside {
                return f64::NEG_INFINITY;
            }
            mean_divergence(
                tasks
                    .iter()
                    .zip(&done)
                    .filter(|((t, _, _), _)| *t == k)
                    .map(|(_, d)| d.as_slice()),
            )
        })
        .collect()
}

/// The ideal future scans (Sec. 5.2: p_D = 1, no clutter), drawn once per step and shared
/// by every action (common random numbers): scan j is the particle `picks[j]` (drawn by
/// weight) seen with standard normal noise `noise[j·n_max + o]` on its object o.
#[derive(Clone, Debug, Default)]
struct FutureScans {
    picks: Vec<usize>,
    noise: Vec<f64>,
    stride: usize,
}

impl FutureScans {
    fn draw<R: Rng + ?Sized>(
        p: &MultiObjectParticles,
        m: usize,
        stride: usize,
        rng: &mut R,
    ) -> Self {
        let mut picks = systematic(&p.weights, m, rng);
        // Systematic picks are ordered; shuffle is unnecessary for a mean, keep them.
        picks.truncate(m);
        let noise = (0..m * stride).map(|_| normal::sample(rng)).collect();
        Self {
            picks,
            noise,
            stride,
        }
    }
}

/// The most measurements of a future scan the plain path takes (a scan has one per object of
/// a particle, at most n_max ≤ 8).
const MAX_SCAN: usize = 16;

/// E[D(u)] (17) as the plain mean over the ideal future scans (see [`super::rewards`]).
///
/// Per action everything that depends only on the particles and u (the ranges h, 1/σ and
/// ln of the normal's constant of every object) is computed once, per future scan what depends
/// only on Z^j (λ c(z_j)); (20) is then evaluated in plain arithmetic from the factors
/// p_D g(z_j | x) = e^{ln p_D + ln g} (one exp per pair, none when it is exactly 0, no
/// exp-then-ln, none below `negligible_pair_bound`) and the divergence (15) from those plain
/// values by [`renyi_plain`] (√ for α = 1/2, no exp or ln per particle). Whenever either
/// declines (large sets, factors above 1, possible underflow) the scan is redone in log
/// space, exact at every scale. The same numbers as the reference `renyi_reward_reference`
/// (the former evaluation, kept in the tests) to rounding.
///
/// Layout: the particles are grouped by cardinality n, and each group's objects are stored
/// object-major ([o·P + q] for object o of the group's particle q), so that per scan the
/// exponents of every pair of a group are one contiguous loop, the exps one tight loop over
/// the pairs that need one, and (20) one call of
/// `MultiObjectLikelihood::scaled_likelihood_batch` per group. Every number is computed by
/// the same operations as in the per-particle evaluation this replaced (up to 2caa890):
/// the rewards are the same bits.
fn renyi_reward(
    cfg: &ControlConfig,
    model: &MultiObjectLikelihood,
    p: &MultiObjectParticles,
    u: State,
    scans: &FutureScans,
    ws: &mut LikelihoodWorkspace,
) -> f64 {
    let setup = RenyiSetup::new(cfg, model, p, u);
    let d = renyi_divergences(cfg, model, p, &setup, scans, 0..scans.picks.len(), ws);
    mean_divergence([d.as_slice()])
}

/// The plain mean of the divergences of the scans that have one (0 when none has), summed in
/// the order given: the same sum whether the scans were evaluated in one piece or in chunks.
fn mean_divergence<'a>(chunks: impl IntoIterator<Item = &'a [Option<f64>]>) -> f64 {
    let (mut sum, mut count) = (0.0, 0usize);
    for d in chunks.into_iter().flatten().flatten() {
        sum += d;
        count += 1;
    }
    if count == 0 { 0.0 } else { sum / count as f64 }
}

/// The divergence (15) of each future scan j in `range` from u, in order (`None`
/// for a scan the particles cannot explain): the body of [`renyi_reward`], which the
/// parallel build splits by action and by chunk of scans (see [`renyi_rewards`]).
fn renyi_divergences(
    cfg: &ControlConfig,
    model: &MultiObjectLikelihood,
    p: &MultiObjectParticles,
    setup: &RenyiSetup,
    scans: &FutureScans,
    range: core::ops::Range<usize>,
    ws: &mut LikelihoodWorkspace,
) -> Vec<Option<f64>> {
    let sensor = cfg.sensor;
    let mut out = Vec::with_capacity(range.len());
    let RenyiSetup {
        offsets,
        h,
        s,
        c,
        groups,
        pairs_below_one,
        ln_w,
    } = setup;
    let ln_rate = ln(model.clutter_rate());
    let mut batch = GroupScratch::default();
    let mut tables = model.small_tables();
    let ln_miss = ln(1.0 - model.detection());
    let mut ln_l = vec![0.0; p.len()];
    // e^{λ} g(Z^j | X_i) from the plain path, NaN where it declined.
    let mut lin_l = vec![0.0; p.len()];
    let (mut z, mut ln_c, mut lin_c, mut ln_g) = (Vec::new(), Vec::new(), Vec::new(), Vec::new());
    for j in range {
        let pick = scans.picks[j];
        z.clear();
        for o in offsets[pick]..offsets[pick + 1] {
            let e = scans.noise[j * scans.stride + (o - offsets[pick])];
            z.push(h[o] + e / s[o]);
        }
        ln_c.clear();
        ln_c.extend(z.iter().map(|&zj| sensor.ln_clutter_density(zj)));
        lin_c.clear();
        lin_c.extend(ln_c.iter().map(|&l| exp(ln_rate + l)));
        let fast = *pairs_below_one && z.len() <= MAX_SCAN && lin_c.iter().all(|&v| v <= 1.0);
        let mut all_plain = fast;
        if fast {
            // Pair factors below `negligible_pair_bound` are replaced by 0 (they change each
            // likelihood by less than 2^{−58} relatively, see there), and so are those below
            // e^{−746}, where exp is exactly 0: neither needs an exp.
            let mut cutoff = [0.0f64; MAX_SCAN];
            for (cut, &cj) in cutoff.iter_mut().zip(&lin_c) {
                *cut = negligible_pair_bound(ln_miss, ln(cj)).max(-746.0);
            }
            for g in &groups.groups {
                batch.evaluate(model, g, &z, &cutoff[..z.len()], &lin_c, &mut tables);
                for (&i, &t) in g.members.iter().zip(&batch.out[..g.members.len()]) {
                    lin_l[i] = t;
                    all_plain &= !t.is_nan();
                }
            }
        } else {
            lin_l.fill(f64::NAN);
        }
        let plain = if all_plain {
            renyi_plain(&p.weights, &lin_l, cfg.alpha)
        } else {
            None
        };
        let d = match plain {
            Some(d) => Some(d),
            None => {
                for (i, l) in ln_l.iter_mut().enumerate() {
                    let t = lin_l[i];
                    if !t.is_nan() {
                        *l = -model.clutter_rate() + ln(t);
                        continue;
                    }
                    ln_g.clear();
                    for o in offsets[i]..offsets[i + 1] {
                        for &zj in &z {
                            let v = (zj - h[o]) * s[o];
                            ln_g.push(c[o] - 0.5 * v * v);
                        }
                    }
                    *l = model.ln_likelihood_from_logs(
                        offsets[i + 1] - offsets[i],
                        &ln_g,
                        &ln_c,
                        ws,
                    );
                }
                renyi_divergence(ln_w, &ln_l, cfg.alpha)
            }
        };
        out.push(d);
    }
    out
}

/// What [`renyi_divergences`] needs of the particles seen from u, computed once per action:
/// per object of every particle (`offsets[i]..offsets[i + 1]` for particle i) the range h,
/// 1/σ and c = ln 1/(σ√(2π)), and the [`CardinalityGroups`].
struct RenyiSetup {
    offsets: Vec<usize>,
    h: Vec<f64>,
    s: Vec<f64>,
    c: Vec<f64>,
    groups: CardinalityGroups,
    /// Whether every pair factor p_D g is at most 1 (k ≤ 0), which the plain path needs.
    pairs_below_one: bool,
    /// ln w_i, for the log-space path.
    ln_w: Vec<f64>,
}

impl RenyiSetup {
    fn new(
        cfg: &ControlConfig,
        model: &MultiObjectLikelihood,
        p: &MultiObjectParticles,
        u: State,
    ) -> Self {
        let sensor = cfg.sensor;
        let mut offsets = Vec::with_capacity(p.len() + 1);
        let total: usize = p.sets.iter().map(|s| s.len()).sum();
        let (mut h, mut s, mut c) = (
            Vec::with_capacity(total),
            Vec::with_capacity(total),
            Vec::with_capacity(total),
        );
        offsets.push(0);
        for set in &p.sets {
            for x in set {
                let d = libm::hypot(x[0] - u[0], x[1] - u[1]);
                let sig = sensor.sigma(d);
                h.push(d);
                s.push(1.0 / sig);
                c.push(-ln(sig) - 0.918_938_533_204_672_8);
            }
            offsets.push(h.len());
        }
        // k = ln of p_D/(σ√(2π)), the largest factor p_D g of an object.
        let ln_pd = ln(model.detection());
        let pairs_below_one = c.iter().all(|&c| c + ln_pd <= 0.0);
        let groups = CardinalityGroups::new(p, &offsets, &h, &s, &c, ln_pd);
        Self {
            offsets,
            h,
            s,
            c,
            groups,
            pairs_below_one,
            ln_w: p.weights.iter().map(|&w| ln(w)).collect(),
        }
    }
}

/// The particles of one cardinality n for [`renyi_reward`]: their indices and their objects'
/// (h, 1/σ, k = ln p_D/(σ√(2π))) object-major, `[o·P + q]` for object o of member q.
struct CardinalityGroup {
    n: usize,
    members: Vec<usize>,
    h: Vec<f64>,
    s: Vec<f64>,
    k: Vec<f64>,
}

/// The non-empty [`CardinalityGroup`]s, n ascending.
struct CardinalityGroups {
    groups: Vec<CardinalityGroup>,
}

impl CardinalityGroups {
    fn new(
        p: &MultiObjectParticles,
        offsets: &[usize],
        h: &[f64],
        s: &[f64],
        c: &[f64],
        ln_pd: f64,
    ) -> Self {
        let n_max = p.sets.iter().map(|s| s.len()).max().unwrap_or(0);
        let mut groups: Vec<CardinalityGroup> = (0..=n_max)
            .map(|n| CardinalityGroup {
                n,
                members: Vec::new(),
                h: Vec::new(),
                s: Vec::new(),
                k: Vec::new(),
            })
            .collect();
        for (i, set) in p.sets.iter().enumerate() {
            groups[set.len()].members.push(i);
        }
        groups.retain(|g| !g.members.is_empty());
        for g in &mut groups {
            let count = g.members.len();
            for o in 0..g.n {
                for &i in &g.members {
                    let at = offsets[i] + o;
                    g.h.push(h[at]);
                    g.s.push(s[at]);
                    g.k.push(c[at] + ln_pd);
                }
            }
            debug_assert_eq!(g.h.len(), g.n * count);
        }
        Self { groups }
    }
}

/// Scratch of [`renyi_reward`]'s per-group evaluation of (20) (reused across scans).
#[derive(Default)]
struct GroupScratch {
    /// The pair factors of the group, `[(j·n + o)·P + q]`.
    factors: Vec<f64>,
    /// e^{λ} g(Z | X_q), NaN where the plain path declined.
    out: Vec<f64>,
}

impl GroupScratch {
    /// `out[q]` = e^{λ} g(Z | X_q) for every member q of `g` (NaN where declined), from the
    /// factors p_D g(z_j | x_o) = e^{k_o − v²/2}, v = (z_j − h_o)/σ_o, or 0 below `cutoff[j]`.
    fn evaluate(
        &mut self,
        model: &MultiObjectLikelihood,
        g: &CardinalityGroup,
        z: &[f64],
        cutoff: &[f64],
        lin_c: &[f64],
        tables: &mut SmallTables,
    ) {
        let count = g.members.len();
        let len = g.n * count;
        let need = z.len() * len;
        // Every entry used is written below: grow only, never clear.
        if self.factors.len() < need {
            self.factors.resize(need, 0.0);
        }
        if self.out.len() < count {
            self.out.resize(count, 0.0);
        }
        let f = &mut self.factors[..need];
        for (row, (&zj, &cut)) in f.chunks_exact_mut(len.max(1)).zip(z.iter().zip(cutoff)) {
            // The exponents (a loop without calls or branches), then the exps. The objects
            // of a particle are aligned (see `MultiObjectParticles::align`), so along a row
            // (one object slot against one measurement) the test is mostly the same.
            for ((fq, &ho), (&so, &ko)) in row.iter_mut().zip(&g.h).zip(g.s.iter().zip(&g.k)) {
                let v = (zj - ho) * so;
                *fq = ko - 0.5 * v * v;
            }
            for x in row.iter_mut() {
                *x = if *x < cut { 0.0 } else { exp(*x) };
            }
        }
        model.scaled_likelihood_batch(g.n, lin_c, f, tables, &mut self.out[..count]);
    }
}

/// [`renyi_divergence`] (15) from the prior weights w_i and T_i = e^{λ} g(Z | X_i) in plain
/// arithmetic: the factor e^{−λ} cancels in ln γ_α − α ln γ_1, so
/// D = (ln Σ w_i T_i^α − α ln Σ w_i T_i)/(α − 1), and KL(π ‖ w) = Σ π_i (ln T_i − ln Σ w T)
/// for |α − 1| < 10⁻⁶. T_i^α is √T_i for α = 1/2 (no exp or ln per particle). `None` when
/// a sum is below 10⁻²⁸⁰ or not finite (gradual underflow could matter): the caller then
/// takes the log-space path.
fn renyi_plain(weights: &[f64], t: &[f64], alpha: f64) -> Option<f64> {
    let g1: f64 = weights.iter().zip(t).map(|(w, t)| w * t).sum();
    if !(g1.is_finite() && g1 > 1e-280) {
        return None;
    }
    if (alpha - 1.0).abs() < 1e-6 {
        let ln_g1 = ln(g1);
        let mut kl = 0.0;
        for (w, &t) in weights.iter().zip(t) {
            let post = w * t / g1;
            if post > 0.0 {
                kl += post * (ln(t) - ln_g1);
            }
        }
        return Some(kl.max(0.0));
    }
    let ga: f64 = if alpha == 0.5 {
        weights.iter().zip(t).map(|(w, &t)| w * sqrt(t)).sum()
    } else {
        weights
            .iter()
            .zip(t)
            .map(|(w, &t)| if t > 0.0 { w * exp(alpha * ln(t)) } else { 0.0 })
            .sum()
    };
    if !(ga.is_finite() && ga > 1e-280) {
        return None;
    }
    Some(((ln(ga) - alpha * ln(g1)) / (alpha - 1.0)).max(0.0))
}

/// The per-particle evaluation that [`renyi_reward`] replaced (up to 2caa890), kept as the
/// reference of its bits: (20) by `MultiObjectLikelihood::scaled_likelihood_factors` one
/// particle at a time, the exps inside the programme's factor closure.
#[cfg(test)]
fn renyi_reward_per_particle(
    cfg: &ControlConfig,
    model: &MultiObjectLikelihood,
    p: &MultiObjectParticles,
    u: State,
    scans: &FutureScans,
    ws: &mut LikelihoodWorkspace,
) -> f64 {
    let sensor = cfg.sensor;
    // Per object of every particle: the range h, 1/σ and ln of the normal's constant.
    let mut offsets = Vec::with_capacity(p.len() + 1);
    let total: usize = p.sets.iter().map(|s| s.len()).sum();
    let (mut h, mut s, mut c) = (
        Vec::with_capacity(total),
        Vec::with_capacity(total),
        Vec::with_capacity(total),
    );
    offsets.push(0);
    for set in &p.sets {
        for x in set {
            let d = libm::hypot(x[0] - u[0], x[1] - u[1]);
            let sig = sensor.sigma(d);
            h.push(d);
            s.push(1.0 / sig);
            c.push(-ln(sig) - 0.918_938_533_204_672_8);
        }
        offsets.push(h.len());
    }
    let ln_pd = ln(model.detection());
    let ln_rate = ln(model.clutter_rate());
    // Per object (h, 1/σ, k) with k = ln of p_D/(σ√(2π)), its largest factor p_D g.
    let obj: Vec<[f64; 3]> = (0..h.len()).map(|o| [h[o], s[o], c[o] + ln_pd]).collect();
    // The plain-arithmetic path needs every factor in [0, 1].
    let pairs_below_one = obj.iter().all(|&[_, _, k]| k <= 0.0);
    let mut tables = model.small_tables();
    let ln_miss = ln(1.0 - model.detection());
    let ln_w: Vec<f64> = p.weights.iter().map(|&w| ln(w)).collect();
    let mut ln_l = vec![0.0; p.len()];
    // e^{λ} g(Z^j | X_i) from the plain path, NaN where it declined.
    let mut lin_l = vec![0.0; p.len()];
    let (mut z, mut ln_c, mut lin_c, mut ln_g) = (Vec::new(), Vec::new(), Vec::new(), Vec::new());
    let (mut sum, mut count) = (0.0, 0usize);
    for (j, &pick) in scans.picks.iter().enumerate() {
        z.clear();
        for o in offsets[pick]..offsets[pick + 1] {
            let e = scans.noise[j * scans.stride + (o - offsets[pick])];
            z.push(h[o] + e / s[o]);
        }
        ln_c.clear();
        ln_c.extend(z.iter().map(|&zj| sensor.ln_clutter_density(zj)));
        lin_c.clear();
        lin_c.extend(ln_c.iter().map(|&l| exp(ln_rate + l)));
        let fast = pairs_below_one && z.len() <= MAX_SCAN && lin_c.iter().all(|&v| v <= 1.0);
        // Pair factors below `negligible_pair_bound` are replaced by 0 (they change each
        // likelihood by less than 2^{−58} relatively, see there), and so are those below
        // e^{−746}, where exp is exactly 0: neither needs an exp. Fixed-size copies of the
        // scan for the inner loop.
        let (mut zf, mut cutoff) = ([0.0f64; MAX_SCAN], [0.0f64; MAX_SCAN]);
        if fast {
            for (jj, (&zj, &cj)) in z.iter().zip(&lin_c).enumerate() {
                zf[jj] = zj;
                cutoff[jj] = negligible_pair_bound(ln_miss, ln(cj)).max(-746.0);
            }
        }
        let mut all_plain = fast;
        for (i, t) in lin_l.iter_mut().enumerate() {
            *t = f64::NAN;
            if !fast {
                continue;
            }
            let objects = &obj[offsets[i]..offsets[i + 1]];
            // p_D g(z_j | x_o) = e^{k_o − v²/2}, v = (z_j − h_o)/σ_o, or 0 below `cutoff[j]`.
            let sum =
                model.scaled_likelihood_factors(objects.len(), &lin_c, &mut tables, |o, jj| {
                    let [ho, so, ko] = objects[o];
                    let v = (zf[jj] - ho) * so;
                    let q = ko - 0.5 * v * v;
                    if q < cutoff[jj] { 0.0 } else { exp(q) }
                });
            match sum {
                Some(v) => *t = v,
                None => all_plain = false,
            }
        }
        let plain = if all_plain {
            renyi_plain(&p.weights, &lin_l, cfg.alpha)
        } else {
            None
        };
        let d = match plain {
            Some(d) => Some(d),
            None => {
                for (i, l) in ln_l.iter_mut().enumerate() {
                    let t = lin_l[i];
                    if !t.is_nan() {
                        *l = -model.clutter_rate() + ln(t);
                        continue;
                    }
                    ln_g.clear();
                    for o in offsets[i]..offsets[i + 1] {
                        for &zj in &z {
                            let v = (zj - h[o]) * s[o];
                            ln_g.push(c[o] - 0.5 * v * v);
                        }
                    }
                    *l = model.ln_likelihood_from_logs(
                        offsets[i + 1] - offsets[i],
                        &ln_g,
                        &ln_c,
                        ws,
                    );
                }
                renyi_divergence(&ln_w, &ln_l, cfg.alpha)
            }
        };
        if let Some(d) = d {
            sum += d;
            count += 1;
        }
    }
    if count == 0 { 0.0 } else { sum / count as f64 }
}

/// The straightforward evaluation of [`renyi_reward`], kept as its reference: (20) in log
/// space by `MultiObjectLikelihood::ln_likelihood_from_logs` for every particle and scan.
#[cfg(test)]
fn renyi_reward_reference(
    cfg: &ControlConfig,
    model: &MultiObjectLikelihood,
    p: &MultiObjectParticles,
    u: State,
    scans: &FutureScans,
    ws: &mut LikelihoodWorkspace,
) -> f64 {
    let sensor = cfg.sensor;
    // Per object of every particle: the range h, σ and ln of the normal's constant.
    let mut offsets = Vec::with_capacity(p.len() + 1);
    let (mut h, mut s, mut c) = (Vec::new(), Vec::new(), Vec::new());
    offsets.push(0);
    for set in &p.sets {
        for x in set {
            let d = libm::hypot(x[0] - u[0], x[1] - u[1]);
            let sig = sensor.sigma(d);
            h.push(d);
            s.push(1.0 / sig);
            c.push(-ln(sig) - 0.918_938_533_204_672_8);
        }
        offsets.push(h.len());
    }
    let ln_w: Vec<f64> = p.weights.iter().map(|&w| ln(w)).collect();
    let mut ln_l = vec![0.0; p.len()];
    let (mut z, mut ln_c, mut ln_g) = (Vec::new(), Vec::new(), Vec::new());
    let (mut sum, mut count) = (0.0, 0usize);
    for (j, &pick) in scans.picks.iter().enumerate() {
        z.clear();
        for o in offsets[pick]..offsets[pick + 1] {
            let e = scans.noise[j * scans.stride + (o - offsets[pick])];
            z.push(h[o] + e / s[o]);
        }
        ln_c.clear();
        ln_c.extend(z.iter().map(|&zj| sensor.ln_clutter_density(zj)));
        for (i, l) in ln_l.iter_mut().enumerate() {
            ln_g.clear();
            for o in offsets[i]..offsets[i + 1] {
                for &zj in &z {
                    let v = (zj - h[o]) * s[o];
                    ln_g.push(c[o] - 0.5 * v * v);
                }
            }
            *l = model.ln_likelihood_from_logs(offsets[i + 1] - offsets[i], &ln_g, &ln_c, ws);
        }
        if let Some(d) = renyi_divergence(&ln_w, &ln_l, cfg.alpha) {
            sum += d;
            count += 1;
        }
    }
    if count == 0 { 0.0 } else { sum / count as f64 }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The fast evaluation of (17) gives the rewards of the straightforward one to rounding,
    /// on the paper's settings, with n_max = 6 (sets beyond the fixed-size table), α = 1,
    /// σ₀ = 0.1 (factors above 1: the log path) and far-off future scans (underflow); and
    /// the bits of the per-particle evaluation it replaced, exactly.
    #[test]
    fn renyi_reward_matches_the_reference() {
        let mut cases = Vec::new();
        let base = {
            let mut c = ControlConfig::paper(Scheme::Renyi, 6);
            c.particles = 200;
            c.future_scans = 30;
            c
        };
        cases.push(base.clone());
        let mut c = base.clone();
        c.max_objects = 6;
        cases.push(c);
        let mut c = base.clone();
        c.alpha = 1.0;
        cases.push(c);
        let mut c = base.clone();
        c.sensor.sigma0 = 0.1;
        c.sensor.sigma_slope = 1e-7;
        cases.push(c);
        let (mut fast_total, mut checked) = (0usize, 0usize);
        for (ci, cfg) in cases.into_iter().enumerate() {
            let mut run = ControlRun::new(cfg.clone(), 11 + ci as u64).unwrap();
            for _ in 0..4 {
                run.step().unwrap();
            }
            let model = run.model;
            let mut rng = seeded(99);
            let mut scans =
                FutureScans::draw(&run.particles, cfg.future_scans, cfg.max_objects, &mut rng);
            if ci == 0 {
                // Noise of 40σ on some scans: pair factors underflow to 0.
                for (k, e) in scans.noise.iter_mut().enumerate() {
                    if k % 3 == 0 {
                        *e *= 40.0;
                    }
                }
            }
            let from = *run.sensor_path().last().unwrap();
            let mut ws = LikelihoodWorkspace::new();
            for a in cfg.actions.actions(from, &cfg.area) {
                if !a.inside {
                    continue;
                }
                let u = a.position;
                let fast = renyi_reward(&cfg, &model, &run.particles, u, &scans, &mut ws);
                let former =
                    renyi_reward_per_particle(&cfg, &model, &run.particles, u, &scans, &mut ws);
                assert_eq!(
                    fast.to_bits(),
                    former.to_bits(),
                    "case {ci}, action {}: {fast} vs {former}",
                    a.index
                );
                let exact =
                    renyi_reward_reference(&cfg, &model, &run.particles, u, &scans, &mut ws);
                assert!(
                    (fast - exact).abs() <= 1e-12 * exact.abs().max(1e-300),
                    "case {ci}, action {}: {fast} vs {exact}",
                    a.index
                );
                assert!(exact > 0.0, "case {ci}: {exact}");
                checked += 1;
                fast_total += usize::from(fast.to_bits() != exact.to_bits());
            }
        }
        assert!(checked > 40, "{checked}");
        // The fast path was taken (its rounding differs somewhere).
        assert!(fast_total > 0);
    }

    /// The rewards evaluated in tasks of [`SCANS_PER_TASK`] scans (in parallel with
    /// `parallel`) are the bits of one [`renyi_reward`] per action.
    #[test]
    fn chunked_rewards_are_the_whole_ones() {
        let mut cfg = ControlConfig::paper(Scheme::Renyi, 6);
        cfg.particles = 200;
        cfg.future_scans = 2 * SCANS_PER_TASK + 7;
        let mut run = ControlRun::new(cfg.clone(), 21).unwrap();
        for _ in 0..3 {
            run.step().unwrap();
        }
        let scans = FutureScans::draw(
            &run.particles,
            cfg.future_scans,
            cfg.max_objects,
            &mut seeded(4),
        );
        let from = *run.sensor_path().last().unwrap();
        let actions = cfg.actions.actions(from, &cfg.area);
        let chunked = renyi_rewards(&cfg, &run.model, &run.particles, &actions, &scans);
        let mut ws = LikelihoodWorkspace::new();
        let mut inside = 0;
        for (a, r) in actions.iter().zip(&chunked) {
            if !a.inside {
                assert_eq!(*r, f64::NEG_INFINITY);
                continue;
            }
            let whole = renyi_reward(
                &cfg,
                &run.model,
                &run.particles,
                a.position,
                &scans,
                &mut ws,
            );
            assert_eq!(r.to_bits(), whole.to_bits(), "action {}", a.index);
            inside += 1;
        }
        assert!(inside >= 3, "{inside}");
    }

    #[test]
    fn a_reduced_run_localises_both_sources() {
        let mut cfg = ControlConfig::paper(Scheme::Renyi, 30);
        cfg.particles = 300;
        cfg.future_scans = 40;
        let mut run = ControlRun::new(cfg, 5).unwrap();
        let t = std::time::Instant::now();
        let mut last = None;
        for _ in 0..30 {
            let s = run.step().unwrap();
            assert_eq!(s.rewards.len(), 17);
            assert!(s.rewards.iter().all(|r| !r.is_nan()));
            std::println!(
                "k={} n̂={} ospa={:?} u={:?}",
                s.k,
                s.estimate.cardinality,
                s.ospa,
                s.action.position
            );
            last = Some(s);
        }
        std::println!("{:?}", t.elapsed());
        let last = last.unwrap();
        assert_eq!(last.estimate.cardinality, 2);
        assert!(run.step().is_err());
        assert_eq!(run.sensor_path().len(), 31);
    }
}
