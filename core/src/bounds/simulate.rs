//! A seeded Monte Carlo of the optimal joint detector-estimator of paper 002 (Rezaeian & Vo),
//! the risk E e²(X, X̂(Z)) (11) that the bounds of Theorems 1 and 2 are held to.
//!
//! The detector-estimator: on Z ≠ ∅ MAP detection (Lemma 1, (39) in model I (13), (40) in
//! model II (22)), and the posterior mean of x when a target is declared (in model II the
//! mixture over "undetected" and "point i is the target's"); on Z = ∅ the rule of
//! [`EmptyRule`]: by default the better of the HPE rule ({x*}) and the LPE rule (∅) of (46),
//! or MAP detection (Section IV-A). The state is Gaussian in R^l with a linear-Gaussian sensor
//! and a constant P_o (Example 1, Section V), or Example 2's (32). With `scans` k > 1 and no
//! false observations, the target is observed k times (Section III-E): the risk after each
//! scan is that of the posterior mean given every detection so far, which the Enumeration
//! bound (37) gives when r = 1.
//!
//! Draws come from [`math::rng`](crate::math::rng) and every float function from libm
//! ([`math::fns`](crate::math::fns)), so a seed gives the same bits natively and in wasm.

use alloc::vec;
use alloc::vec::Vec;
use nalgebra::DMatrix;

use crate::bounds::closed::check_nonnegative;
use crate::bounds::model::{Density, Observation, standard_normal};
use crate::bounds::theorem::{TheoremOptions, check_common};
use crate::bounds::{Example2Observation, Example2Prior, GaussianPrior, LinearGaussianSensor};
use crate::bounds::{MAX_CLUTTER_RATE, MAX_STEPS, VectorMeasurement, VectorModel};
use crate::error::{Error, Result, check_probability};
use crate::gaussian::covariance;
use crate::math::fns;
use crate::math::quadrature::Rule;
use crate::math::rng::{SeededRng, poisson, seeded, uniform};

/// The most work one call does: samples × scans × (1 + ⌈q or λ⌉) draws of a scene.
pub const MAX_MONTE_CARLO_WORK: usize = 10_000_000;

/// What the detector-estimator does on Z = ∅ (after every scan so far was empty). Serialised
/// in lower case: `"optimal"`, `"map"`, `"declare"`, `"reject"`.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
#[cfg_attr(
    feature = "serde",
    derive(serde::Serialize, serde::Deserialize),
    serde(rename_all = "lowercase")
)]
pub enum EmptyRule {
    /// The cheaper of HPE and LPE (46): declare {x*} iff
    /// (1 − r)ε e0² + r(1 − P_o)^k σ² ≤ r(1 − P_o)^k e1² (ε = P(Z = ∅ | no target)).
    #[default]
    Optimal,
    /// MAP detection (Section IV-A): declare iff r(1 − P_o)^k ≥ (1 − r)ε.
    Map,
    /// Always declare {x*} (the HPE rule).
    Declare,
    /// Never declare (the LPE rule).
    Reject,
}

/// The state and its observation g(z|x), P_o.
#[derive(Clone, Copy)]
pub enum SimulatedSystem<'a> {
    /// x ~ N(x0, P) in R^l, z = H x + b + v, v ~ N(0, R), constant P_o (Section V; l = 1 is
    /// Example 1).
    LinearGaussian {
        /// The Gaussian prior N(x0, P) of the target's state.
        prior: &'a GaussianPrior,
        /// The linear-Gaussian sensor: detection probability P_o, H, offset b, noise covariance R.
        sensor: &'a LinearGaussianSensor,
    },
    /// Example 2 (32): f(x) = 2x(eˣ − 1), g(z|x) = x e^{xz}/(eˣ − 1) on [0, 1], constant P_o.
    Example2 {
        /// The detection probability P_o, a constant.
        detection_probability: f64,
    },
}

/// The problem simulated: r, the system, models I or II and the errors e0², e1².
#[derive(Clone, Copy)]
pub struct MonteCarloModel<'a> {
    /// The prior existence probability r ∈ [0, 1]: the probability that the target exists.
    pub existence: f64,
    /// The system: prior f, likelihood g and detection probability P_o.
    pub system: SimulatedSystem<'a>,
    /// Model I's (q, ψ) or model II's (λ, c); the densities must draw
    /// ([`Density::sample`]).
    pub measurement: VectorMeasurement<'a>,
    /// The squared error e0² ≥ 0 of a false target (of the whole state; coordinate i uses e0²/l).
    pub false_alarm_error: f64,
    /// The squared error e1² ≥ 0 of a missed target (of the whole state; coordinate i uses e1²/l).
    pub miss_error: f64,
}

impl<'a> From<&VectorModel<'a>> for MonteCarloModel<'a> {
    fn from(m: &VectorModel<'a>) -> Self {
        MonteCarloModel {
            existence: m.existence,
            system: SimulatedSystem::LinearGaussian {
                prior: m.prior,
                sensor: m.sensor,
            },
            measurement: m.measurement,
            false_alarm_error: m.false_alarm_error,
            miss_error: m.miss_error,
        }
    }
}

/// The options of [`jde_monte_carlo`].
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct JdeMonteCarloOptions {
    /// Simulated scenes, 2 to [`MAX_MONTE_CARLO_WORK`] (default 20,000; samples × scans ×
    /// (1 + ⌈q or λ⌉) at most [`MAX_MONTE_CARLO_WORK`]).
    pub samples: usize,
    /// The seed of the [`SeededRng`] (default 0).
    pub seed: u64,
    /// The rule on Z = ∅ (default [`EmptyRule::Optimal`]).
    pub empty_rule: EmptyRule,
    /// Scans k of one target, 1 to [`MAX_STEPS`] (default 1; k > 1 needs a linear-Gaussian
    /// system and no false observations).
    pub scans: usize,
}

impl Default for JdeMonteCarloOptions {
    fn default() -> Self {
        JdeMonteCarloOptions {
            samples: 20_000,
            seed: 0,
            empty_rule: EmptyRule::Optimal,
            scans: 1,
        }
    }
}

/// An empirical mean square error and its standard error (the sample standard deviation of
/// e² over √samples).
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct MonteCarloRisk {
    /// The mean of the squared error e² over the samples.
    pub mse: f64,
    /// The standard error of `mse`.
    pub se: f64,
}

/// What [`jde_monte_carlo`] returns: the risk after the last scan and its parts, per
/// coordinate, and after each scan.
#[derive(Clone, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct JdeMonteCarlo {
    /// The risk E e² (11): the mean squared error over the samples.
    pub mse: f64,
    /// The standard error of `mse`.
    pub se: f64,
    /// The number of simulated scenes.
    pub samples: usize,
    /// The false-target part: the mean of e0² 1{no target, one declared}.
    pub false_alarm: f64,
    /// The missed-target part: the mean of e1² 1{a target, none declared}.
    pub miss: f64,
    /// The estimation part: the mean of |x − x̂|² 1{a target, declared};
    /// `false_alarm + miss + estimation = mse` up to rounding.
    pub estimation: f64,
    /// Whether Z = ∅ declares {x*} (after the last scan).
    pub declare_on_empty: bool,
    /// Per coordinate i: E e_i² with e_i(∅, {x'}) = e0/√l, e_i({x}, ∅) = e1/√l.
    pub components: Vec<MonteCarloRisk>,
    /// The risk after each scan 1 … k (the last is `mse`, `se`).
    pub scans: Vec<MonteCarloRisk>,
    /// The seed of the draws ([`JdeMonteCarloOptions::seed`]): the run is reproduced by it.
    pub seed: u64,
}

/// Running mean and sum of squared deviations (Welford).
#[derive(Clone, Copy, Default)]
struct Tally {
    n: usize,
    mean: f64,
    m2: f64,
}

impl Tally {
    fn add(&mut self, v: f64) {
        self.n += 1;
        // A squared error past the f64 range (a prior of variance near 1e308) is +∞: the
        // mean and its spread are then +∞, not ∞ − ∞ = NaN.
        if v == f64::INFINITY || self.mean == f64::INFINITY {
            self.mean = f64::INFINITY;
            self.m2 = f64::INFINITY;
            return;
        }
        let d = v - self.mean;
        self.mean += d / self.n as f64;
        self.m2 += d * (v - self.mean);
    }
    fn risk(&self) -> MonteCarloRisk {
        let n = self.n as f64;
        MonteCarloRisk {
            mse: self.mean,
            se: fns::sqrt(self.m2 / (n - 1.0) / n),
        }
    }
}

/// The linear-Gaussian system's precomputed matrices.
struct Gaussian {
    x0: Vec<f64>,
    /// Lower Cholesky factors of P and R.
    lp: DMatrix<f64>,
    lr: DMatrix<f64>,
    h: DMatrix<f64>,
    b: Vec<f64>,
    /// H x0 + b, S⁻¹ (S = H P Hᵀ + R), 1/√((2π)^m det S), K = P Hᵀ S⁻¹.
    z_mean: Vec<f64>,
    s_inv: DMatrix<f64>,
    norm: f64,
    gain: DMatrix<f64>,
    /// With k scans: for m = 0 … k detections, (P_m P⁻¹, P_m Hᵀ R⁻¹) with
    /// P_m = (P⁻¹ + m Hᵀ R⁻¹ H)⁻¹, so x̂ = P_m P⁻¹ x0 + P_m Hᵀ R⁻¹ Σ (z_i − b).
    scans: Vec<(DMatrix<f64>, DMatrix<f64>)>,
}

/// The SPD inverse by Cholesky (the matrices were checked SPD when built); a failure is
/// [`Error::NotDefinite`] naming `what` with the smallest eigenvalue.
fn spd_inverse(a: &DMatrix<f64>, what: &str) -> Result<DMatrix<f64>> {
    a.clone()
        .cholesky()
        .map(|c| c.inverse())
        .ok_or_else(|| covariance::not_positive_definite(a, what.into()))
}

/// The lower Cholesky factor, failing as [`spd_inverse`].
fn lower(a: &DMatrix<f64>, what: &str) -> Result<DMatrix<f64>> {
    a.clone()
        .cholesky()
        .map(|c| c.l())
        .ok_or_else(|| covariance::not_positive_definite(a, what.into()))
}

impl Gaussian {
    fn new(prior: &GaussianPrior, sensor: &LinearGaussianSensor, scans: usize) -> Result<Self> {
        let (p, h, r) = (&prior.cov, &sensor.gain, &sensor.noise);
        if h.ncols() != prior.dims() {
            return Err(Error::dimension(
                "observation.gain",
                prior.dims(),
                h.ncols(),
            ));
        }
        let s = h * p * h.transpose() + r;
        let hx0 = h * nalgebra::DVector::from_column_slice(&prior.mean);
        if !(s.iter().chain(hx0.iter()).all(|v| v.is_finite())) {
            // A gain so large that H P Hᵀ + R or H x̄ overflows: every measurement would be
            // ±∞ (then ∞ · 0 = NaN in the likelihoods); fuzz seed 888070, gain 1e308.
            return Err(Error::Unsupported {
                what: "observation.gain".into(),
                reason: "H P Hᵀ + R or H times the prior mean overflows the f64 range; \
                         rescale the measurement (a smaller gain and noise)",
            });
        }
        let s_chol = s
            .clone()
            .cholesky()
            .ok_or_else(|| covariance::not_positive_definite(&s, "S".into()))?;
        let det: f64 = s_chol.l().diagonal().iter().map(|d| d * d).product();
        let two_pi_m = (0..h.nrows()).fold(1.0, |a, _| a * 2.0 * core::f64::consts::PI);
        let s_inv = s_chol.inverse();
        let mut post = Vec::new();
        if scans > 1 {
            let p_inv = spd_inverse(p, "prior.cov")?;
            let ht_r_inv = h.transpose() * spd_inverse(r, "observation.noise_cov")?;
            let info = &ht_r_inv * h;
            for m in 0..=scans {
                let pm = spd_inverse(&(&p_inv + &info * m as f64), "P_m")?;
                post.push((&pm * &p_inv, &pm * &ht_r_inv));
            }
            let finite = |a: &DMatrix<f64>| a.iter().all(|v| v.is_finite());
            if !post.iter().all(|(a, b)| finite(a) && finite(b)) {
                // A prior variance near the smallest double makes P⁻¹ overflow (then
                // ∞ · 0): the same matrices without P⁻¹, P_m P⁻¹ = (I + m P Hᵀ R⁻¹ H)⁻¹
                // and P_m Hᵀ R⁻¹ = (P_m P⁻¹) P Hᵀ R⁻¹.
                post.clear();
                let p_info = p * &info;
                let p_ht_r_inv = p * &ht_r_inv;
                let n = p.nrows();
                for m in 0..=scans {
                    let a = (DMatrix::identity(n, n) + &p_info * m as f64)
                        .try_inverse()
                        .ok_or_else(|| covariance::not_positive_definite(p, "P_m".into()))?;
                    let b = &a * &p_ht_r_inv;
                    post.push((a, b));
                }
            }
        }
        Ok(Gaussian {
            x0: prior.mean.clone(),
            lp: lower(p, "prior.cov")?,
            lr: lower(r, "observation.noise_cov")?,
            h: h.clone(),
            b: sensor.offset.clone(),
            z_mean: hx0.iter().zip(&sensor.offset).map(|(a, b)| a + b).collect(),
            norm: 1.0 / fns::sqrt(two_pi_m * det),
            gain: p * h.transpose() * &s_inv,
            s_inv,
            scans: post,
        })
    }
}

/// f, g and P_o as the simulation needs them.
enum System {
    Gaussian(alloc::boxed::Box<Gaussian>),
    Example2(Example2Observation),
}

/// (x0 + L n) for n standard normal: a draw of N(x0, L Lᵀ) into `out`.
fn draw_normal(
    mean: &[f64],
    l: &DMatrix<f64>,
    rng: &mut SeededRng,
    n: &mut [f64],
    out: &mut [f64],
) {
    for v in n.iter_mut() {
        *v = standard_normal(rng);
    }
    for (i, o) in out.iter_mut().enumerate() {
        *o = mean[i] + (0..=i).map(|j| l[(i, j)] * n[j]).sum::<f64>();
    }
}

impl System {
    fn dims(&self) -> (usize, usize) {
        match self {
            System::Gaussian(g) => (g.x0.len(), g.h.nrows()),
            System::Example2(_) => (1, 1),
        }
    }

    /// x ~ f.
    fn draw_state(&self, rng: &mut SeededRng, n: &mut [f64], x: &mut [f64]) {
        match self {
            System::Gaussian(g) => draw_normal(&g.x0, &g.lp, rng, n, x),
            System::Example2(_) => {
                // rejection under the peak f(1) = 2(e − 1)
                let peak = 2.0 * libm::expm1(1.0);
                x[0] = loop {
                    let t = uniform(rng);
                    if uniform(rng) * peak <= Example2Prior.pdf(t) {
                        break t;
                    }
                };
            }
        }
    }

    /// z ~ g(·|x).
    fn draw_measurement(&self, x: &[f64], rng: &mut SeededRng, n: &mut [f64], z: &mut [f64]) {
        match self {
            System::Gaussian(g) => {
                let hx: Vec<f64> = (0..g.h.nrows())
                    .map(|i| g.b[i] + (0..x.len()).map(|j| g.h[(i, j)] * x[j]).sum::<f64>())
                    .collect();
                draw_normal(&hx, &g.lr, rng, n, z);
            }
            System::Example2(_) => {
                // the inverse cdf of g(·|x) = x e^{xz}/(eˣ − 1)
                let u = uniform(rng);
                z[0] = if x[0] == 0.0 {
                    u
                } else {
                    fns::ln_1p(u * libm::expm1(x[0])) / x[0]
                };
            }
        }
    }

    /// ∫ f(x) g(z|x) dx, and the posterior mean of x given that z is the target's into `mean`.
    fn marginal(&self, z: &[f64], mean: &mut [f64]) -> f64 {
        match self {
            System::Gaussian(g) => {
                let d: Vec<f64> = z.iter().zip(&g.z_mean).map(|(a, b)| a - b).collect();
                let mut q = 0.0;
                for (i, di) in d.iter().enumerate() {
                    q += di * (0..d.len()).map(|j| g.s_inv[(i, j)] * d[j]).sum::<f64>();
                }
                for (i, m) in mean.iter_mut().enumerate() {
                    *m = g.x0[i] + (0..d.len()).map(|j| g.gain[(i, j)] * d[j]).sum::<f64>();
                }
                g.norm * fns::exp(-0.5 * q)
            }
            System::Example2(obs) => {
                // p_1(x, z)/P_o = f(x) g(z|x) = 2x² e^{xz}: smooth, one G10K21 panel
                let p = Rule::G10K21.apply_vec(
                    &mut |x| {
                        let w = Example2Prior.pdf(x) * obs.likelihood(z[0], x);
                        [w, w * x]
                    },
                    0.0,
                    1.0,
                );
                mean[0] = p.value[1] / p.value[0];
                p.value[0]
            }
        }
    }
}

/// Model I's or II's false observations, when there are any (q > 0 or λ > 0).
#[derive(Clone, Copy)]
enum FalseObservations<'a> {
    None,
    I(f64, &'a dyn Density),
    II(f64, &'a dyn Density),
}

/// The tallies: per scan, per coordinate (last scan) and the parts of the risk.
struct Score {
    scans: Vec<Tally>,
    components: Vec<Tally>,
    parts: [f64; 3],
    e0: f64,
    e1: f64,
}

impl Score {
    /// e²(X, X̂) after scan `k` (the per-coordinate and part tallies after the last).
    fn add(&mut self, k: usize, exists: bool, declare: bool, x: &[f64], estimate: &[f64]) {
        let last = k + 1 == self.scans.len();
        let l = self.components.len() as f64;
        let total = match (exists, declare) {
            (true, true) => {
                let mut sum = 0.0;
                for (i, (a, b)) in x.iter().zip(estimate).enumerate() {
                    let d = (a - b) * (a - b);
                    sum += d;
                    if last {
                        self.components[i].add(d);
                    }
                }
                sum
            }
            (true, false) => self.e1,
            (false, true) => self.e0,
            (false, false) => 0.0,
        };
        if last {
            if !(exists && declare) {
                for c in self.components.iter_mut() {
                    c.add(total / l);
                }
            }
            let part = match (exists, declare) {
                (false, _) => 0,
                (true, false) => 1,
                (true, true) => 2,
            };
            self.parts[part] += total;
        }
        self.scans[k].add(total);
    }
}

/// The checked inputs: the system, P_o, x* and the prior variance of each coordinate.
fn system_of(
    model: &MonteCarloModel<'_>,
    scans: usize,
) -> Result<(System, f64, Vec<f64>, Vec<f64>)> {
    Ok(match model.system {
        SimulatedSystem::LinearGaussian { prior, sensor } => {
            let var = prior.cov.diagonal().iter().copied().collect();
            let g = Gaussian::new(prior, sensor, scans)?;
            (
                System::Gaussian(alloc::boxed::Box::new(g)),
                sensor.detection,
                prior.mean.clone(),
                var,
            )
        }
        SimulatedSystem::Example2 {
            detection_probability: p,
        } => {
            // named as the observation's P_o, as in every binding's options (it was
            // `detection_probability.detection_probability`)
            let detection =
                crate::bounds::Detection::constant(p).map_err(|e| e.within("observation"))?;
            // x* and σe² of f (P_o constant, so f_d' = f): smooth, one G10K21 panel
            let f = |x: f64| Example2Prior.pdf(x);
            let m = Rule::G10K21.apply_vec(&mut |x| [f(x), x * f(x), x * x * f(x)], 0.0, 1.0);
            let mean = m.value[1] / m.value[0];
            let var = m.value[2] / m.value[0] - mean * mean;
            (
                System::Example2(Example2Observation { detection }),
                p,
                vec![mean],
                vec![var],
            )
        }
    })
}

/// The seeded Monte Carlo of the optimal joint detector-estimator (module docs): `samples`
/// scenes X ~ B(r, f), Z from model I or II, X̂(Z) by MAP detection and the posterior mean,
/// and the mean of e²(X, X̂) (11) with its standard error, its false-alarm, miss and
/// estimation parts, per coordinate, and per scan.
///
/// # Errors
/// [`Error::OutOfRange`] naming `samples` (outside [2, [`MAX_MONTE_CARLO_WORK`]]) or `scans`
/// (outside [1, [`MAX_STEPS`]]), checked first; [`Error::InvalidProbability`] /
/// [`Error::InvalidParameter`] naming `existence`, `false_alarm_error`, `miss_error`,
/// `false_alarm.probability`, `clutter.rate` or `samples` (when samples × scans ×
/// (1 + ⌈q or λ⌉) exceeds [`MAX_MONTE_CARLO_WORK`]);
/// [`Error::Unsupported`] for false observations with a measurement of more than one
/// coordinate, a false-observation density that cannot draw, or k > 1 scans with false
/// observations or Example 2.
///
/// ```
/// use fisst::bounds::{GaussianPrior, LinearGaussianSensor, UnitUniform, VectorMeasurement};
/// use fisst::bounds::{JdeMonteCarloOptions, MonteCarloModel, SimulatedSystem, jde_monte_carlo};
/// // Fig. 2 left at r = 1, P̄o = 0.5: the bound (31) is 100 − 0.5 (100 − 25) = 62.5.
/// let prior = GaussianPrior::new(&[0.0], &[100.0])?;
/// let sensor = LinearGaussianSensor::new(0.5, &[1.0], 1, &[0.0], &[100.0 / 3.0])?;
/// let model = MonteCarloModel {
///     existence: 1.0,
///     system: SimulatedSystem::LinearGaussian { prior: &prior, sensor: &sensor },
///     measurement: VectorMeasurement::I { false_alarm_probability: 0.0, false_alarm_density: &UnitUniform },
///     false_alarm_error: 150.0,
///     miss_error: 200.0,
/// };
/// let mc = jde_monte_carlo(&model, &JdeMonteCarloOptions { seed: 1, ..Default::default() })?;
/// assert!((mc.mse - 62.5).abs() < 4.0 * mc.se);
/// # Ok::<(), fisst::Error>(())
/// ```
pub fn jde_monte_carlo(
    model: &MonteCarloModel<'_>,
    options: &JdeMonteCarloOptions,
) -> Result<JdeMonteCarlo> {
    let samples = Error::check_range("samples", options.samples, 2, MAX_MONTE_CARLO_WORK)?;
    let scans = Error::check_range("scans", options.scans, 1, MAX_STEPS)?;
    let (r, e0, e1) = (model.existence, model.false_alarm_error, model.miss_error);
    check_common(r, e0, e1, &TheoremOptions::default())?;
    let false_obs = match model.measurement {
        VectorMeasurement::I {
            false_alarm_probability: q,
            false_alarm_density: d,
        } => {
            check_probability(|| "false_alarm.probability".into(), q)?;
            (q > 0.0).then_some(FalseObservations::I(q, d))
        }
        VectorMeasurement::II {
            clutter_rate: lambda,
            clutter_density: d,
        } => {
            if check_nonnegative("clutter.rate", lambda)? > MAX_CLUTTER_RATE {
                return Err(Error::parameter("clutter.rate", lambda, "≤ 1000"));
            }
            (lambda > 0.0).then_some(FalseObservations::II(lambda, d))
        }
    }
    .unwrap_or(FalseObservations::None);
    let (extra, density) = match false_obs {
        FalseObservations::None => (0.0, None),
        FalseObservations::I(q, d) => (q, Some(("false_alarm.density", d))),
        FalseObservations::II(lambda, d) => (lambda, Some(("clutter.density", d))),
    };
    let work = samples
        .saturating_mul(scans)
        .saturating_mul(1 + libm::ceil(extra) as usize);
    if work > MAX_MONTE_CARLO_WORK {
        return Err(Error::parameter(
            "samples",
            samples as f64,
            "samples × scans × (1 + ⌈q or λ⌉) ≤ 10^7",
        ));
    }
    let (system, p, x_star, variance) = system_of(model, scans)?;
    let (l, m) = system.dims();
    if let Some((what, d)) = density {
        if m != 1 {
            return Err(Error::Unsupported {
                what: "observation.gain".into(),
                reason: "false alarms or clutter need a scalar measurement (a gain of one row)",
            });
        }
        if d.sample(&mut seeded(0)).is_none() {
            return Err(Error::Unsupported {
                what: what.into(),
                reason: "the Monte Carlo draws from this density; use one that can be sampled",
            });
        }
    }
    if scans > 1 && (density.is_some() || matches!(system, System::Example2(_))) {
        return Err(Error::Unsupported {
            what: "scans".into(),
            reason: "k > 1 scans need a linear-Gaussian system without false alarms or clutter",
        });
    }
    // The rule on Z = ∅ after k scans: P(target, Z = ∅) = r(1 − P_o)^k against
    // P(no target, Z = ∅) = (1 − r)ε (46), Section IV-A.
    let eps = match false_obs {
        FalseObservations::I(q, _) => 1.0 - q,
        _ => 1.0,
    };
    let trace: f64 = variance.iter().sum();
    let mut missed = r;
    let declare_empty: Vec<bool> = (0..scans)
        .map(|_| {
            missed *= 1.0 - p;
            match options.empty_rule {
                EmptyRule::Optimal => (1.0 - r) * eps * e0 + missed * trace <= missed * e1,
                EmptyRule::Map => missed >= (1.0 - r) * eps,
                EmptyRule::Declare => true,
                EmptyRule::Reject => false,
            }
        })
        .collect();

    let mut rng = seeded(options.seed);
    let mut score = Score {
        scans: vec![Tally::default(); scans],
        components: vec![Tally::default(); l],
        parts: [0.0; 3],
        e0,
        e1,
    };
    let (mut noise, mut x, mut z) = (vec![0.0; l.max(m)], vec![0.0; l], vec![0.0; m]);
    let (mut estimate, mut mean, mut acc) = (vec![0.0; l], vec![0.0; l], vec![0.0; l]);
    let mut points: Vec<f64> = Vec::new(); // m = 1 whenever there is more than one point
    let mut z_sum = vec![0.0; m];
    for _ in 0..samples {
        let exists = uniform(&mut rng) < r;
        if exists {
            system.draw_state(&mut rng, &mut noise[..l], &mut x);
        }
        if scans > 1 {
            let System::Gaussian(g) = &system else {
                unreachable!("checked above")
            };
            let mut detections = 0;
            z_sum.iter_mut().for_each(|v| *v = 0.0);
            for (k, &empty) in declare_empty.iter().enumerate() {
                if exists && uniform(&mut rng) < p {
                    system.draw_measurement(&x, &mut rng, &mut noise[..m], &mut z);
                    detections += 1;
                    for (s, (zi, bi)) in z_sum.iter_mut().zip(z.iter().zip(&g.b)) {
                        *s += zi - bi;
                    }
                }
                if detections > 0 {
                    let (a, b) = &g.scans[detections];
                    for (i, e) in estimate.iter_mut().enumerate() {
                        *e = (0..l).map(|j| a[(i, j)] * g.x0[j]).sum::<f64>()
                            + (0..m).map(|j| b[(i, j)] * z_sum[j]).sum::<f64>();
                    }
                    score.add(k, exists, true, &x, &estimate);
                } else {
                    score.add(k, exists, empty, &x, &x_star);
                }
            }
            continue;
        }
        points.clear();
        if exists && uniform(&mut rng) < p {
            system.draw_measurement(&x, &mut rng, &mut noise[..m], &mut z);
            points.extend_from_slice(&z);
        }
        match false_obs {
            FalseObservations::None => {}
            FalseObservations::I(q, d) => {
                if !exists && uniform(&mut rng) < q {
                    points.push(d.sample(&mut rng).unwrap_or(f64::NAN));
                }
            }
            FalseObservations::II(lambda, d) => {
                let cap = 4 * libm::ceil(lambda) as usize + 100;
                for _ in 0..poisson(&mut rng, lambda, cap) {
                    points.push(d.sample(&mut rng).unwrap_or(f64::NAN));
                }
            }
        }
        let declare = if points.is_empty() {
            estimate.copy_from_slice(&x_star);
            declare_empty[0]
        } else {
            match false_obs {
                // one point: MAP (39), declare iff r P_o ∫p_1(x, z)dx ≥ (1 − r) q ψ(z)
                FalseObservations::None => {
                    system.marginal(&points, &mut estimate);
                    true
                }
                FalseObservations::I(q, psi) => {
                    let mz = system.marginal(&points, &mut estimate);
                    r * p * mz >= (1.0 - r) * q * psi.pdf(points[0])
                }
                // β(Z) = Σ_i ∫p_1(x, z_i)dx / v(z_i); MAP (40): r(1 − P_o + P_o β) ≥ 1 − r;
                // the posterior mean mixes x* (undetected) and x̂(z_i) with weights ∝ β_i
                FalseObservations::II(lambda, c) => {
                    let (mut beta, mut target, mut underflow) = (0.0, false, false);
                    acc.iter_mut().for_each(|v| *v = 0.0);
                    for &zi in &points {
                        let mz = system.marginal(&[zi], &mut mean);
                        let cz = c.pdf(zi);
                        let v = lambda * cz;
                        if v == 0.0 && cz > 0.0 {
                            // λ c(z) underflowed: clutter can make this point
                            underflow = true;
                            break;
                        }
                        if v == 0.0 {
                            // a point no clutter can make: the target's
                            estimate.copy_from_slice(&mean);
                            target = true;
                            break;
                        }
                        beta += mz / v;
                        for (a, mi) in acc.iter_mut().zip(&mean) {
                            *a += mz / v * mi;
                        }
                    }
                    let overflow = !beta.is_finite() || acc.iter().any(|a| !a.is_finite());
                    if overflow || underflow {
                        // λ c(z) underflowed to 0, or ∫p_1 / (λ c) overflowed (a clutter
                        // rate near the smallest double): the same decision and mean in
                        // logarithms, the weights scaled by their largest.
                        scaled_clutter_decision(
                            &system,
                            &points,
                            lambda,
                            c,
                            (r, p),
                            &x_star,
                            (&mut mean, &mut acc),
                            &mut estimate,
                        )
                    } else {
                        if !target {
                            let w = 1.0 - p + p * beta;
                            for (i, e) in estimate.iter_mut().enumerate() {
                                *e = ((1.0 - p) * x_star[i] + p * acc[i]) / w;
                            }
                        }
                        target || r * (1.0 - p + p * beta) >= 1.0 - r
                    }
                }
            }
        };
        score.add(0, exists, declare, &x, &estimate);
    }
    let last = score.scans[scans - 1].risk();
    let n = samples as f64;
    Ok(JdeMonteCarlo {
        mse: last.mse,
        se: last.se,
        samples,
        false_alarm: score.parts[0] / n,
        miss: score.parts[1] / n,
        estimation: score.parts[2] / n,
        declare_on_empty: declare_empty[scans - 1],
        components: score.components.iter().map(Tally::risk).collect(),
        scans: score.scans.iter().map(Tally::risk).collect(),
        seed: options.seed,
    })
}

/// Model II's MAP decision (40) and posterior mean with the clutter rate factored out, for
/// a rate λ so small that λ c(z) underflows or ∫p_1(x, z)dx / (λ c(z)) overflows. With
/// ℓ_i = ln ∫p_1(x, z_i)dx − ln c(z_i), L = max ℓ_i and u_i = e^{ℓ_i − L} ∈ [0, 1]:
///
/// ```text
/// β = e^L Σu_i / λ,   x̂ = ((1 − P_o) κ x* + P_o Σu_i x̂(z_i)) / ((1 − P_o) κ + P_o Σu_i),
/// κ = λ e^{−L};  declare iff r (1 − P_o + P_o β) ≥ 1 − r
/// ```
///
/// (a point with c(z) = 0 is the target's, as in the plain form). Returns the decision.
#[allow(clippy::too_many_arguments)]
fn scaled_clutter_decision(
    system: &System,
    points: &[f64],
    lambda: f64,
    c: &dyn Density,
    (r, p): (f64, f64),
    x_star: &[f64],
    (mean, acc): (&mut [f64], &mut [f64]),
    estimate: &mut [f64],
) -> bool {
    let mut logs = Vec::with_capacity(points.len());
    let mut means = Vec::with_capacity(points.len());
    for &zi in points {
        let mz = system.marginal(&[zi], mean);
        let cz = c.pdf(zi);
        if cz <= 0.0 {
            // a point no clutter can make: the target's
            estimate.copy_from_slice(mean);
            return true;
        }
        logs.push(fns::ln(mz) - fns::ln(cz));
        means.push(mean.to_vec());
    }
    let top = logs.iter().fold(f64::NEG_INFINITY, |a, &l| a.max(l));
    if top == f64::NEG_INFINITY {
        // no point has any target likelihood: the undetected mean, and β = 0
        estimate.copy_from_slice(x_star);
        return r * (1.0 - p) >= 1.0 - r;
    }
    let mut total = 0.0;
    acc.iter_mut().for_each(|v| *v = 0.0);
    for (l, m) in logs.iter().zip(&means) {
        let u = fns::exp(l - top);
        total += u;
        for (a, mi) in acc.iter_mut().zip(m) {
            *a += u * mi;
        }
    }
    let kappa = fns::exp(fns::ln(lambda) - top);
    for (i, e) in estimate.iter_mut().enumerate() {
        *e = if kappa.is_finite() {
            ((1.0 - p) * kappa * x_star[i] + p * acc[i]) / ((1.0 - p) * kappa + p * total)
        } else {
            x_star[i]
        };
    }
    // P_o β = P_o e^{L − ln λ} Σu (0 when P_o = 0, never 0 · ∞)
    let p_beta = if p > 0.0 {
        p * fns::exp(top - fns::ln(lambda)) * total
    } else {
        0.0
    };
    r * (1.0 - p + p_beta) >= 1.0 - r
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::bounds::{Sequential, UnitUniform, gaussian_no_clutter, sequential_bound};

    /// Fuzz seed 946630: a prior of variance 1e308 gives squared errors past the f64 range;
    /// the risk is then +∞ with a +∞ standard error, never NaN (Welford's ∞ − ∞).
    #[test]
    fn a_squared_error_past_the_f64_range_gives_an_infinite_risk_not_nan() {
        let mut t = Tally::default();
        for v in [1.0, f64::INFINITY, 2.0, 1e300] {
            t.add(v);
        }
        let r = t.risk();
        assert_eq!((r.mse, r.se), (f64::INFINITY, f64::INFINITY));
        let mut t = Tally::default();
        for v in [1.0, 2.0, 3.0] {
            t.add(v);
        }
        assert_eq!((t.risk().mse, t.risk().se), (2.0, fns::sqrt(1.0 / 3.0)));
    }

    /// Fig. 2 left's system: σf² = 100, z = x + v with σv² = 100/3 (σh² = 25).
    fn fig2<'a>(
        prior: &'a GaussianPrior,
        sensor: &'a LinearGaussianSensor,
        r: f64,
    ) -> MonteCarloModel<'a> {
        MonteCarloModel {
            existence: r,
            system: SimulatedSystem::LinearGaussian { prior, sensor },
            measurement: VectorMeasurement::I {
                false_alarm_probability: 0.0,
                false_alarm_density: &UnitUniform,
            },
            false_alarm_error: 150.0,
            miss_error: 200.0,
        }
    }

    fn system(p: f64) -> (GaussianPrior, LinearGaussianSensor) {
        (
            GaussianPrior::new(&[3.0], &[100.0]).unwrap(),
            LinearGaussianSensor::new(p, &[1.0], 1, &[0.0], &[100.0 / 3.0]).unwrap(),
        )
    }

    /// Fuzz seed 198626: a clutter rate near the smallest double (3.5e-323), where λ c(z)
    /// underflows and ∫p_1 / (λ c) overflows, gave a NaN risk. The scaled form decides as
    /// the limit λ → 0 does: every point is the target's, so the risk is that of the
    /// no-clutter system within the Monte Carlo error.
    #[test]
    fn model_ii_with_a_clutter_rate_near_the_smallest_double_has_a_finite_risk() {
        let prior = GaussianPrior::new(&[0.0], &[1.0]).unwrap();
        let sensor =
            LinearGaussianSensor::new(0.006518354876926869, &[0.0], 1, &[0.0], &[1.0]).unwrap();
        let density = crate::bounds::Density1::gaussian(0.0, 25.0).unwrap();
        let model = |rate: f64| MonteCarloModel {
            existence: 1.0,
            system: SimulatedSystem::LinearGaussian {
                prior: &prior,
                sensor: &sensor,
            },
            measurement: VectorMeasurement::II {
                clutter_rate: rate,
                clutter_density: &density,
            },
            false_alarm_error: 0.0,
            miss_error: 0.0,
        };
        let o = JdeMonteCarloOptions {
            samples: 200,
            seed: 1,
            ..JdeMonteCarloOptions::default()
        };
        let tiny = jde_monte_carlo(&model(3.5e-323), &o).unwrap();
        assert!(tiny.mse.is_finite() && tiny.se.is_finite(), "{tiny:?}");
        for rate in [1e-300, 5e-324] {
            let m = jde_monte_carlo(&model(rate), &o).unwrap();
            assert!(m.mse.is_finite(), "rate {rate}: {m:?}");
        }
    }

    /// Fuzz seed 888070: a gain of 1e308 makes H P Hᵀ + R overflow, so every measurement is
    /// ±∞ and the likelihoods ∞ · 0 = NaN (a NaN risk). Such a gain, or one that overflows
    /// H times the prior mean, is refused naming `observation.gain`; 1e150 still runs.
    #[test]
    fn a_gain_that_overflows_the_innovation_is_refused_naming_it() {
        use alloc::string::ToString;
        let density = crate::bounds::Density1::gaussian(0.0, 25.0).unwrap();
        let o = JdeMonteCarloOptions {
            samples: 200,
            seed: 1,
            ..JdeMonteCarloOptions::default()
        };
        for (mean, gain, ok) in [
            (0.0, 1e308, false),
            (1e300, 1e10, false),
            (0.0, 1e150, true),
        ] {
            let prior = GaussianPrior::new(&[mean], &[1.0]).unwrap();
            let sensor =
                LinearGaussianSensor::new(0.030435958513577614, &[gain], 1, &[0.0], &[1.0])
                    .unwrap();
            let model = MonteCarloModel {
                existence: 0.9999999999999999,
                system: SimulatedSystem::LinearGaussian {
                    prior: &prior,
                    sensor: &sensor,
                },
                measurement: VectorMeasurement::II {
                    clutter_rate: 5e-324,
                    clutter_density: &density,
                },
                false_alarm_error: 0.0,
                miss_error: 0.0,
            };
            match jde_monte_carlo(&model, &o) {
                Ok(m) => {
                    assert!(ok, "gain {gain}, mean {mean}: {m:?}");
                    assert!(m.mse.is_finite() && m.se.is_finite(), "{m:?}");
                }
                Err(e) => {
                    assert!(!ok, "gain {gain}: {e}");
                    assert!(
                        e.to_string().starts_with("observation.gain: H P Hᵀ + R"),
                        "{e}"
                    );
                }
            }
        }
    }

    #[test]
    fn a_failed_factorisation_says_the_smallest_eigenvalue() {
        use alloc::string::ToString;
        // P and R were checked when built (asymmetric or indefinite ones never get here, see
        // `vector::tests::vector_covariances_say_which_property_fails`); S and P_m fail by
        // their smallest eigenvalue.
        let indef = DMatrix::from_row_slice(2, 2, &[1.25, 0.0, 0.0, -0.25]);
        let said = "S is not positive definite (smallest eigenvalue -0.25)";
        assert_eq!(spd_inverse(&indef, "S").unwrap_err().to_string(), said);
        assert_eq!(lower(&indef, "S").unwrap_err().to_string(), said);
        let asym = GaussianPrior::new(&[0.0, 0.0], &[1.0, 0.5, 0.4, 1.0]).unwrap_err();
        assert_eq!(
            asym.to_string(),
            "cov is not symmetric: [0][1] = 0.5 but [1][0] = 0.4"
        );
    }

    /// Fuzz seed 602302: a prior variance of 5e-324 with k = 2 scans made P⁻¹ overflow
    /// (then ∞ · 0 = NaN in P_m P⁻¹); the matrices are then formed without P⁻¹.
    #[test]
    fn k_scans_with_a_prior_variance_near_the_smallest_double_have_a_finite_risk() {
        let prior = GaussianPrior::new(
            &[0.0, 0.0, 0.0],
            &[1.0, 0.0, 0.0, 0.0, 5e-324, 0.0, 0.0, 0.0, 1.0],
        )
        .unwrap();
        let sensor = LinearGaussianSensor::new(
            0.5,
            &[0.0; 9],
            3,
            &[0.0; 3],
            &[1.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0],
        )
        .unwrap();
        let model = MonteCarloModel {
            existence: 0.001214289776742761,
            system: SimulatedSystem::LinearGaussian {
                prior: &prior,
                sensor: &sensor,
            },
            measurement: VectorMeasurement::I {
                false_alarm_probability: 0.0,
                false_alarm_density: &UnitUniform,
            },
            false_alarm_error: 0.0,
            miss_error: 0.0,
        };
        let o = JdeMonteCarloOptions {
            samples: 200,
            seed: 1,
            scans: 2,
            empty_rule: EmptyRule::Declare,
        };
        let mc = jde_monte_carlo(&model, &o).unwrap();
        assert!(mc.mse.is_finite() && mc.se.is_finite(), "{mc:?}");
    }

    #[test]
    fn cor3_the_optimal_detector_estimator_attains_the_no_clutter_bound() {
        let mut seed = 1;
        for &r in &[0.3, 0.6, 0.9] {
            for &p in &[0.2, 0.7] {
                let (prior, sensor) = system(p);
                let m = fig2(&prior, &sensor, r);
                let b = gaussian_no_clutter(r, p, 100.0, 25.0, 150.0, 200.0).unwrap();
                let o = JdeMonteCarloOptions {
                    samples: 40_000,
                    seed,
                    ..Default::default()
                };
                seed += 1;
                let mc = jde_monte_carlo(&m, &o).unwrap();
                let z = (mc.mse - b.bound) / mc.se;
                assert!(
                    z.abs() < 4.0,
                    "r {r} P {p}: {} ± {} vs {}",
                    mc.mse,
                    mc.se,
                    b.bound
                );
                assert_eq!(mc.declare_on_empty, b.declare_on_empty);
                let parts = mc.false_alarm + mc.miss + mc.estimation;
                assert!((parts - mc.mse).abs() <= 1e-9 * mc.mse);
                assert_eq!(mc.components.len(), 1);
                assert!((mc.components[0].mse - mc.mse).abs() <= 1e-9 * mc.mse);
                // MAP detection on ∅ (Section IV-A) attains its own bound
                let map = jde_monte_carlo(
                    &m,
                    &JdeMonteCarloOptions {
                        empty_rule: EmptyRule::Map,
                        ..o
                    },
                )
                .unwrap();
                let want = b.map_bound;
                assert!((map.mse - want).abs() < 4.0 * map.se, "MAP r {r} P {p}");
            }
        }
    }

    #[test]
    fn eq37_the_posterior_mean_over_scans_attains_the_enumeration_bound() {
        let (prior, sensor) = system(0.4);
        let m = fig2(&prior, &sensor, 1.0);
        let o = JdeMonteCarloOptions {
            samples: 20_000,
            seed: 7,
            scans: 10,
            ..Default::default()
        };
        let mc = jde_monte_carlo(&m, &o).unwrap();
        let e = sequential_bound(Sequential::Enumeration, 0.01, 0.04, 0.4, 10).unwrap();
        assert_eq!(mc.scans.len(), 10);
        for (k, (s, b)) in mc.scans.iter().zip(&e).enumerate() {
            assert!(
                (s.mse - b).abs() < 4.0 * s.se,
                "k {}: {} ± {} vs {b}",
                k + 1,
                s.mse,
                s.se
            );
        }
        assert_eq!((mc.mse, mc.se), (mc.scans[9].mse, mc.scans[9].se));
    }

    #[test]
    fn eq11_same_seed_same_bits_and_another_seed_other_draws() {
        let (prior, sensor) = system(0.7);
        let m = fig2(&prior, &sensor, 0.6);
        let o = JdeMonteCarloOptions {
            samples: 2_000,
            seed: 42,
            ..Default::default()
        };
        let (a, b) = (
            jde_monte_carlo(&m, &o).unwrap(),
            jde_monte_carlo(&m, &o).unwrap(),
        );
        assert_eq!(a.mse.to_bits(), b.mse.to_bits());
        assert_eq!(a.se.to_bits(), b.se.to_bits());
        assert_eq!(a, b);
        let c = jde_monte_carlo(&m, &JdeMonteCarloOptions { seed: 43, ..o }).unwrap();
        assert_ne!(a.mse.to_bits(), c.mse.to_bits());
    }

    #[test]
    fn eq11_bad_options_are_errors_naming_the_field() {
        let (prior, sensor) = system(0.7);
        let m = fig2(&prior, &sensor, 0.6);
        let field = |m: &MonteCarloModel<'_>, o: JdeMonteCarloOptions| {
            alloc::string::String::from(jde_monte_carlo(m, &o).unwrap_err().field())
        };
        let o = JdeMonteCarloOptions::default();
        assert_eq!(
            field(&m, JdeMonteCarloOptions { samples: 1, ..o }),
            "samples"
        );
        assert_eq!(
            field(
                &m,
                JdeMonteCarloOptions {
                    samples: 20_000_000,
                    ..o
                }
            ),
            "samples"
        );
        assert_eq!(field(&m, JdeMonteCarloOptions { scans: 0, ..o }), "scans");
        // the integer ranges are checked first, in the words of every integer option
        let bad = MonteCarloModel {
            existence: 1.5,
            ..m
        };
        let samples = JdeMonteCarloOptions { samples: 1, ..o };
        assert_eq!(
            alloc::string::ToString::to_string(&jde_monte_carlo(&bad, &samples).unwrap_err()),
            "samples must be an integer in [2, 10000000], got 1"
        );
        let scans = JdeMonteCarloOptions { scans: 5_001, ..o };
        assert_eq!(
            alloc::string::ToString::to_string(&jde_monte_carlo(&m, &scans).unwrap_err()),
            "scans must be an integer in [1, 5000], got 5001"
        );
        assert_eq!(
            field(&m, JdeMonteCarloOptions { scans: 5_001, ..o }),
            "scans"
        );
        assert_eq!(
            field(
                &MonteCarloModel {
                    existence: 1.5,
                    ..m
                },
                o
            ),
            "existence"
        );
        assert_eq!(
            field(
                &MonteCarloModel {
                    miss_error: -1.0,
                    ..m
                },
                o
            ),
            "miss_error"
        );
        let example2 = |p| MonteCarloModel {
            system: SimulatedSystem::Example2 {
                detection_probability: p,
            },
            ..m
        };
        assert_eq!(
            field(&example2(1.5), o),
            "observation.detection_probability"
        );
        let clutter = MonteCarloModel {
            measurement: VectorMeasurement::II {
                clutter_rate: 2.0,
                clutter_density: &UnitUniform,
            },
            ..m
        };
        // UnitUniform cannot draw; and k > 1 scans need no clutter
        assert_eq!(field(&clutter, o), "clutter.density");
        let flat = crate::bounds::Density1::uniform(-50.0, 50.0).unwrap();
        let clutter = MonteCarloModel {
            measurement: VectorMeasurement::II {
                clutter_rate: 2.0,
                clutter_density: &flat,
            },
            ..m
        };
        assert_eq!(
            field(&clutter, JdeMonteCarloOptions { scans: 2, ..o }),
            "scans"
        );
        assert_eq!(
            field(
                &MonteCarloModel {
                    measurement: VectorMeasurement::II {
                        clutter_rate: 1001.0,
                        clutter_density: &flat,
                    },
                    ..m
                },
                o
            ),
            "clutter.rate"
        );
    }

    #[test]
    fn ex2_the_posterior_mean_mse_is_below_the_regularity_failing_curve() {
        // NOTES.md: at r = 1, P_o = 1 the posterior mean's MSE is 0.0340 (1/J_1 = 0.1897).
        let reg = crate::bounds::example2_regularity();
        let m = MonteCarloModel {
            existence: 1.0,
            system: SimulatedSystem::Example2 {
                detection_probability: 1.0,
            },
            measurement: VectorMeasurement::I {
                false_alarm_probability: 0.0,
                false_alarm_density: &UnitUniform,
            },
            false_alarm_error: 1.2,
            miss_error: 1.2 + reg.prior_variance,
        };
        let o = JdeMonteCarloOptions {
            samples: 40_000,
            seed: 11,
            ..Default::default()
        };
        let mc = jde_monte_carlo(&m, &o).unwrap();
        assert!(
            (mc.mse - reg.posterior_mean_mse).abs() < 4.0 * mc.se,
            "{} ± {}",
            mc.mse,
            mc.se
        );
        assert!(mc.mse + 4.0 * mc.se < reg.inverse_information);
    }
}
