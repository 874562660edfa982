//! The compiled half of `fisst.campaign` (Monte Carlo campaigns on Dask): the seeds of a
//! campaign's runs, derived as `compare_schemes` derives them, and one run of an experiment on
//! one thread (a campaign's parallelism is the engine's workers, not rayon inside a task).
//! Private names (`_campaign_…`): the public API is the Python module `fisst.campaign`.

use pyo3::prelude::*;
use pyo3::types::PyDict;

use crate::convert::to_py;
use crate::options::from_kwargs;
use fisst::control::{CompareOptions, run_seeds, run_series};

/// Runs `f` on a rayon pool of one thread, so that a task of a campaign uses one core whatever
/// the core's `parallel` feature would do (the numbers do not depend on the thread count).
fn on_one_thread<T: Send>(f: impl FnOnce() -> T + Send) -> PyResult<T> {
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(1)
        .build()
        .map_err(|e| pyo3::exceptions::PyRuntimeError::new_err(e.to_string()))?;
    Ok(pool.install(f))
}

/// The seeds of runs ``0 … runs − 1`` of a campaign with master seed ``seed``: the
/// ``run_seeds`` of ``compare_schemes(seed=seed, runs=runs)`` (a prefix does not depend on
/// ``runs``, so a campaign extended to more runs keeps its first ones).
#[pyfunction]
#[pyo3(text_signature = "(seed, runs)")]
pub fn _campaign_run_seeds(seed: u64, runs: usize) -> PyResult<Vec<u64>> {
    if runs == 0 || runs > 1_000_000 {
        return Err(pyo3::exceptions::PyValueError::new_err(format!(
            "runs must be in [1, 1000000], got {runs}"
        )));
    }
    Ok(run_seeds(seed, runs))
}

/// Checks the settings of a ``"control"`` campaign (the keyword arguments of
/// ``compare_schemes`` without ``seed``), as ``compare_schemes`` checks them.
#[pyfunction]
#[pyo3(signature = (**options))]
pub fn _campaign_control_check(
    py: Python<'_>,
    options: Option<&Bound<'_, PyDict>>,
) -> PyResult<()> {
    let o: CompareOptions = from_kwargs(py, "settings", options)?;
    o.check().map_err(to_py)
}

/// One run of the ``"control"`` experiment (Fig. 3 of paper 004, Ristic & Vo): run seed
/// ``run_seed`` of every scheme in ``schemes``, as ``compare_schemes`` runs run r, on one
/// thread with the GIL released. Returns a float64 array of shape ``(schemes, steps, 3)``: the
/// OSPA distance (24), its localisation (26) and cardinality (25) parts at each step.
#[pyfunction]
#[pyo3(signature = (run_seed, **options))]
pub fn _campaign_control_run<'py>(
    py: Python<'py>,
    run_seed: u64,
    options: Option<&Bound<'py, PyDict>>,
) -> PyResult<Bound<'py, PyAny>> {
    let o: CompareOptions = from_kwargs(py, "settings", options)?;
    o.check().map_err(to_py)?;
    let base = o.run_options();
    let flat = py
        .detach(|| {
            on_one_thread(|| -> fisst::Result<Vec<f64>> {
                let mut flat = Vec::with_capacity(o.schemes.len() * o.steps * 3);
                for &scheme in &o.schemes {
                    let config = fisst::control::ControlOptions {
                        scheme,
                        ..base.clone()
                    };
                    for step in run_series(&config, run_seed)? {
                        flat.extend_from_slice(&step);
                    }
                }
                Ok(flat)
            })
        })?
        .map_err(to_py)?;
    numpy::ToPyArray::to_pyarray(&flat[..], py)
        .call_method1("reshape", ((o.schemes.len(), o.steps, 3),))
}

/// The settings of an ``"airport"`` campaign (all required: the Python side fills the
/// defaults): report times, and the particle filter's size and MCMC moves.
#[derive(serde::Deserialize)]
struct AirportSettings {
    steps: usize,
    particles: usize,
    mcmc_moves: usize,
}

impl AirportSettings {
    /// The particle filter's options for run seed `seed` (the seed `airport_scenario` gives
    /// its `config`, so that a run replays on the airport page).
    fn particle_options(&self, seed: u64) -> fisst::filters::ParticleOptions {
        fisst::filters::ParticleOptions {
            particles: self.particles,
            mcmc_moves: self.mcmc_moves,
            seed,
            ..Default::default()
        }
    }

    /// The caps and the filters' own checks, on the scenario of seed 0.
    fn check(&self) -> fisst::Result<()> {
        fisst::Error::check_range(
            "steps",
            self.steps,
            1,
            fisst::sim::airport::MAX_AIRPORT_STEPS,
        )?;
        let sc = fisst::sim::airport::airport_scenario(0, 1)?;
        fisst::filters::ParticleBernoulliFilter::new(sc.config.clone(), self.particle_options(0))?;
        Ok(())
    }
}

/// Checks the settings of an ``"airport"`` campaign (``steps``, ``particles``,
/// ``mcmc_moves``).
#[pyfunction]
#[pyo3(signature = (**options))]
pub fn _campaign_airport_check(
    py: Python<'_>,
    options: Option<&Bound<'_, PyDict>>,
) -> PyResult<()> {
    let o: AirportSettings = from_kwargs(py, "run", options)?;
    o.check().map_err(to_py)
}

/// One run of the ``"airport"`` experiment (Section V-C, Figs. 6–8 of paper 001, LeGrand &
/// Ferrari, "Split Happens!"): the seeded scenario of ``run_seed``, then the GM Bernoulli
/// filter (Algorithm 3) and the particle Bernoulli filter on the same reports, on one thread.
/// Returns a float64 array of shape ``(2, steps, 5)``: for each filter (GM, then particle)
/// and step, the existence r_{k|k}, the position error |x_true − x̂| (m), the position
/// covariance RSS √tr P_ss (Fig. 8), the squared Mahalanobis distance of the true position
/// (≤ 9: inside the 3σ ellipse, Fig. 7a) and the seconds the step took (predict, update and
/// estimate; wall time, the one column that differs between runs of the same seed).
#[pyfunction]
#[pyo3(signature = (run_seed, **options))]
pub fn _campaign_airport_run<'py>(
    py: Python<'py>,
    run_seed: u64,
    options: Option<&Bound<'py, PyDict>>,
) -> PyResult<Bound<'py, PyAny>> {
    use fisst::filters::{
        EstimateOptions, FilterEstimate, GmBernoulliFilter, ParticleBernoulliFilter,
    };
    let o: AirportSettings = from_kwargs(py, "run", options)?;
    // the run's own filters check the particle settings: no throw-away filter per task
    fisst::Error::check_range("steps", o.steps, 1, fisst::sim::airport::MAX_AIRPORT_STEPS)
        .map_err(to_py)?;
    let steps = o.steps;
    let flat = py
        .detach(|| -> fisst::Result<Vec<f64>> {
            let sc = fisst::sim::airport::airport_scenario(run_seed, steps)?;
            let mut out = Vec::with_capacity(2 * steps * 5);
            let row = |out: &mut Vec<f64>, k: usize, e: &FilterEstimate, seconds: f64| {
                let t = &sc.truth[k].state;
                let (dx, dy) = (t[0] - e.mean[0], t[1] - e.mean[1]);
                let (a, b, c) = (e.cov[0][0], e.cov[0][1], e.cov[1][1]);
                let nees = (c * dx * dx - 2.0 * b * dx * dy + a * dy * dy) / (a * c - b * b);
                out.extend_from_slice(&[
                    e.existence,
                    fisst::math::fns::sqrt(dx * dx + dy * dy),
                    e.rss(0..2),
                    nees,
                    seconds,
                ]);
            };
            let none = EstimateOptions::default();
            let mut gm = GmBernoulliFilter::new(sc.config.clone())?;
            for k in 0..steps {
                let start = std::time::Instant::now();
                gm.predict()?;
                gm.update(&sc.report_regions(k))?;
                let e = gm.estimate(&none)?;
                row(&mut out, k, &e, start.elapsed().as_secs_f64());
            }
            let mut pf =
                ParticleBernoulliFilter::new(sc.config.clone(), o.particle_options(run_seed))?;
            for k in 0..steps {
                let start = std::time::Instant::now();
                pf.predict();
                pf.update(&sc.report_regions(k))?;
                let e = pf.estimate(&none)?;
                row(&mut out, k, &e, start.elapsed().as_secs_f64());
            }
            Ok(out)
        })
        .map_err(to_py)?;
    numpy::ToPyArray::to_pyarray(&flat[..], py).call_method1("reshape", ((2, steps, 5),))
}

/// The settings of a ``"bounds"`` campaign (all required: the Python side fills the
/// defaults): the grid of existence probabilities r and detection probabilities P̄o, the
/// scalar linear-Gaussian system of Fig. 2 of paper 002 (prior variance σf², mean posterior
/// variance σh² < σf²: z = x + v with σv² = σf² σh² / (σf² − σh²)), the squared errors e0²
/// and e1², the draws per grid point and run, and the rule on Z = ∅.
#[derive(serde::Deserialize)]
struct BoundsSettings {
    existence: Vec<f64>,
    detection_probability: Vec<f64>,
    prior_variance: f64,
    posterior_variance: f64,
    false_alarm_error: f64,
    miss_error: f64,
    samples: usize,
    empty_rule: fisst::bounds::EmptyRule,
}

impl BoundsSettings {
    /// The no-clutter bound (31) at (r, P̄o).
    fn bound(&self, r: f64, po: f64) -> fisst::Result<fisst::bounds::NoClutterBound> {
        fisst::bounds::NoClutterOptions {
            existence: r,
            detection_probability: po,
            prior_variance: self.prior_variance,
            posterior_variance: self.posterior_variance,
            false_alarm_error: self.false_alarm_error,
            miss_error: self.miss_error,
        }
        .bound()
    }

    /// The grid's sizes (1 … 64 each), σh² < σf², and the bound at every grid point (its own
    /// checks name the field).
    fn check(&self) -> fisst::Result<()> {
        fisst::Error::check_count("existence", "values", self.existence.len(), 1, 64)?;
        fisst::Error::check_count(
            "detection_probability",
            "values",
            self.detection_probability.len(),
            1,
            64,
        )?;
        fisst::Error::check_range("samples", self.samples, 2, 1_000_000)?;
        for &po in &self.detection_probability {
            for &r in &self.existence {
                self.bound(r, po)?;
            }
        }
        // finite and positive by now (the bound checked them)
        if self.posterior_variance >= self.prior_variance {
            return Err(fisst::Error::parameter(
                "posterior_variance",
                self.posterior_variance,
                "< prior_variance (a measurement that informs)",
            ));
        }
        Ok(())
    }
}

/// Checks the settings of a ``"bounds"`` campaign.
#[pyfunction]
#[pyo3(signature = (**options))]
pub fn _campaign_bounds_check(py: Python<'_>, options: Option<&Bound<'_, PyDict>>) -> PyResult<()> {
    let o: BoundsSettings = from_kwargs(py, "run", options)?;
    o.check().map_err(to_py)
}

/// One run of the ``"bounds"`` experiment (paper 002, Rezaeian & Vo): at every grid point
/// (P̄o, r), ``samples`` draws of the optimal joint detector-estimator (MAP detection and the
/// posterior mean, the rule ``empty_rule`` on Z = ∅; ``fisst.jde_monte_carlo``) seeded with
/// ``run_seed`` (common random numbers across the grid), and the bound (31) it attains
/// (Theorem 1; Fig. 2 of paper 002). Returns a float64 array of shape ``(P, R, 4)``: the
/// run's mean squared error, its standard error, the bound (31) and the bound with MAP
/// detection on Z = ∅.
#[pyfunction]
#[pyo3(signature = (run_seed, **options))]
pub fn _campaign_bounds_run<'py>(
    py: Python<'py>,
    run_seed: u64,
    options: Option<&Bound<'py, PyDict>>,
) -> PyResult<Bound<'py, PyAny>> {
    use fisst::bounds::{
        GaussianPrior, JdeMonteCarloOptions, LinearGaussianSensor, MonteCarloModel,
        SimulatedSystem, UnitUniform, VectorMeasurement, jde_monte_carlo,
    };
    let o: BoundsSettings = from_kwargs(py, "run", options)?;
    o.check().map_err(to_py)?;
    let flat = py
        .detach(|| -> fisst::Result<Vec<f64>> {
            let (vf, vh) = (o.prior_variance, o.posterior_variance);
            let noise = vf * vh / (vf - vh);
            let prior = GaussianPrior::new(&[0.0], &[vf])?;
            let mut out = Vec::with_capacity(o.detection_probability.len() * o.existence.len() * 4);
            for &po in &o.detection_probability {
                let sensor = LinearGaussianSensor::new(po, &[1.0], 1, &[0.0], &[noise])?;
                for &r in &o.existence {
                    let model = MonteCarloModel {
                        existence: r,
                        system: SimulatedSystem::LinearGaussian {
                            prior: &prior,
                            sensor: &sensor,
                        },
                        measurement: VectorMeasurement::I {
                            false_alarm_probability: 0.0,
                            false_alarm_density: &UnitUniform,
                        },
                        false_alarm_error: o.false_alarm_error,
                        miss_error: o.miss_error,
                    };
                    let mc = jde_monte_carlo(
                        &model,
                        &JdeMonteCarloOptions {
                            samples: o.samples,
                            seed: run_seed,
                            empty_rule: o.empty_rule,
                            ..JdeMonteCarloOptions::default()
                        },
                    )?;
                    let b = o.bound(r, po)?;
                    out.extend_from_slice(&[mc.mse, mc.se, b.bound, b.map_bound]);
                }
            }
            Ok(out)
        })
        .map_err(to_py)?;
    numpy::ToPyArray::to_pyarray(&flat[..], py).call_method1(
        "reshape",
        ((o.detection_probability.len(), o.existence.len(), 4),),
    )
}
