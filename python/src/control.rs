//! Sensor control with the SMC multi-object filter (paper 004, Ristic & Vo, "Sensor control
//! for multi-object state-space estimation using random finite sets"):
//! `multi_object_likelihood` (eq. (20)), `SensorControlRun` (Algorithm 1) and
//! `compare_schemes` (Fig. 3), on the core's own `fisst::control` types.

use std::sync::Mutex;

use pyo3::exceptions::PyRuntimeError;
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyTuple};

use crate::convert::{result, seed_or_entropy, to_py};
use crate::options::from_kwargs;
use fisst::control::{
    CompareOptions, ControlOptions, ControlParticles, ControlRun, MultiObjectLikelihoodOptions,
};

/// The multi-object likelihood g(Z|X) of eq. (20) of paper 004 for point detections with
/// clutter, as a log: ``likelihoods[i][j] = g(z_j | x_i) >= 0`` (an ``(n, m)`` array),
/// ``detection_probability`` p_D, ``clutter_rate`` λ and ``clutter_density`` c(z_j) (length
/// m). Returns a ``Result`` (``ParticleLikelihood``) with ``log_likelihood`` (``-inf`` when
/// the likelihood is 0, never NaN). At most 64 objects, 1000 measurements, min(n, m) <= 12.
#[pyfunction]
#[pyo3(
    signature = (**options),
    text_signature = "(*, likelihoods, detection_probability, clutter_rate, clutter_density)"
)]
pub fn multi_object_likelihood<'py>(
    py: Python<'py>,
    options: Option<&Bound<'py, PyDict>>,
) -> PyResult<Bound<'py, PyAny>> {
    let o: MultiObjectLikelihoodOptions = from_kwargs(py, "multi_object_likelihood", options)?;
    let r = py.detach(|| o.evaluate()).map_err(to_py)?;
    result(py, &r)
}

/// One run of Algorithm 1 of paper 004 (Ristic & Vo): the SMC multi-object filter of the
/// case study (range-only sensor, Sec. 5) with the sensor moved each step by ``scheme``:
/// ``"renyi"`` (the Rényi-divergence reward, eq. (16)), ``"fisher"``, ``"pent"`` or
/// ``"random"``.
///
/// ``SensorControlRun(*, scheme, seed=None, particles=750, future_scans=200, alpha=0.5,
/// steps=40, start=[0, 0], max_objects=4)``: ``seed`` omitted draws one from the operating
/// system (read it back as ``run.seed``). ``particles × future_scans × w`` is at most 300,000
/// per step, with ``w = 1`` up to four ``max_objects`` and ``2^(max_objects − 3)`` past four. ``run.step()`` processes the next step and returns a
/// ``Result`` (``StepOutcome``: ``k``, ``sensor``, ``measurements``, ``action``, ``rewards``,
/// ``estimate``, ``ospa``); after ``steps`` steps it raises ``ValueError``.
///
/// The run pickles (its options, seed and step count; unpickling replays the steps, which are
/// deterministic). One run used from two threads at once raises ``RuntimeError`` in the
/// second. The GIL is released while a step runs.
#[pyclass(name = "SensorControlRun", module = "fisst._fisst", frozen)]
pub struct SensorControlRun {
    inner: Mutex<ControlRun>,
    seed: u64,
}

impl SensorControlRun {
    fn run(&self) -> PyResult<std::sync::MutexGuard<'_, ControlRun>> {
        self.inner.try_lock().map_err(|_| {
            PyRuntimeError::new_err(
                "SensorControlRun is in use by another thread (a run is one sequence of steps: \
                 use one run per thread)",
            )
        })
    }
}

#[pymethods]
impl SensorControlRun {
    #[new]
    #[pyo3(signature = (**options))]
    fn new(py: Python<'_>, options: Option<&Bound<'_, PyDict>>) -> PyResult<Self> {
        let o: ControlOptions = from_kwargs(py, "SensorControlRun", options)?;
        let seed = seed_or_entropy(o.seed)?;
        o.check_limits().map_err(to_py)?;
        let inner = py.detach(|| ControlRun::new(o, seed)).map_err(to_py)?;
        Ok(Self {
            inner: Mutex::new(inner),
            seed,
        })
    }

    /// Processes the next step (predict, measure, update, estimate, choose the next action)
    /// and returns its ``Result`` (``StepOutcome``). ``ValueError`` once ``k == steps``.
    fn step<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        py.check_signals()?;
        let mut run = self.run()?;
        let inner: &mut ControlRun = &mut run;
        let outcome = py.detach(|| inner.step()).map_err(to_py)?;
        result(py, &outcome)
    }

    /// The multi-object particles: a ``Result`` (``ControlParticles``) with ``weights``, the
    /// object count of each particle and the objects' states.
    #[getter]
    fn particles<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        let run = self.run()?;
        result(py, &ControlParticles::from(run.particles()))
    }

    /// The sensor's locations so far, a ``(k + 1, 2)`` array.
    #[getter]
    fn sensor_path<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        result(py, self.run()?.sensor_path())
    }

    /// The true object states of the scenario.
    #[getter]
    fn truth<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        result(py, &self.run()?.options().truth)
    }

    /// The measurements received so far, one array per step.
    #[getter]
    fn measurements<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        result(py, self.run()?.measurements())
    }

    /// The number of steps done.
    #[getter]
    fn k(&self) -> PyResult<usize> {
        Ok(self.run()?.k())
    }

    /// The number of steps of the run.
    #[getter]
    fn steps(&self) -> PyResult<usize> {
        Ok(self.run()?.options().steps)
    }

    /// The seed of the run (given, or drawn from the operating system).
    #[getter]
    fn seed(&self) -> u64 {
        self.seed
    }

    /// The control scheme.
    #[getter]
    fn scheme(&self) -> PyResult<&'static str> {
        Ok(self.run()?.options().scheme.name())
    }

    fn __repr__(&self) -> PyResult<String> {
        let run = self.run()?;
        Ok(format!(
            "SensorControlRun(scheme={:?}, seed={}, k={}, steps={})",
            run.options().scheme.name(),
            self.seed,
            run.k(),
            run.options().steps
        ))
    }

    fn __reduce__<'py>(slf: &Bound<'py, Self>) -> PyResult<Bound<'py, PyTuple>> {
        let py = slf.py();
        let this = slf.get();
        let run = this.run()?;
        let mut options = run.options().clone();
        options.seed = Some(this.seed);
        let options = pythonize::pythonize(py, &options)
            .map_err(|e| PyRuntimeError::new_err(e.to_string()))?;
        let restore = py
            .import("fisst._fisst")?
            .getattr("SensorControlRun")?
            .getattr("_restore")?;
        PyTuple::new(
            py,
            [restore, (options, run.k()).into_pyobject(py)?.into_any()],
        )
    }

    /// Rebuilds a pickled run: the run from its options (with its seed), stepped ``k`` times.
    #[staticmethod]
    fn _restore(py: Python<'_>, options: Bound<'_, PyDict>, k: usize) -> PyResult<Self> {
        let run = Self::new(py, Some(&options))?;
        {
            let mut guard = run.run()?;
            let inner: &mut ControlRun = &mut guard;
            py.detach(|| -> fisst::Result<()> {
                for _ in 0..k {
                    inner.step()?;
                }
                Ok(())
            })
            .map_err(to_py)?;
        }
        Ok(run)
    }
}

/// A failure of a comparison: the core's, or the Python exception the progress callback
/// raised (Ctrl-C included).
enum Failure {
    Core(fisst::Error),
    Py(PyErr),
}

impl From<fisst::Error> for Failure {
    fn from(e: fisst::Error) -> Self {
        Failure::Core(e)
    }
}

/// Fig. 3 of paper 004: ``runs`` Monte Carlo runs of each control scheme in ``schemes``
/// (default all four) on the case study, the mean OSPA error and its parts per step with
/// their standard errors. Keyword arguments as ``SensorControlRun`` plus ``runs``,
/// ``schemes`` and ``seed`` (omitted: drawn from the operating system, reported in the
/// result); ``on_progress(done, total)`` is called as runs finish. Returns a ``Result``
/// (``Comparison``). Ctrl-C stops it (``KeyboardInterrupt``) at the next finished batch; the
/// GIL is released while it runs, and the runs use every core (the numbers do not depend on
/// how many).
#[pyfunction]
#[pyo3(signature = (*, on_progress = None, **options), text_signature = "(*, runs, steps, seed=None, schemes=None, particles=750, future_scans=200, alpha=0.5, start=[0, 0], max_objects=4, on_progress=None)")]
pub fn compare_schemes<'py>(
    py: Python<'py>,
    on_progress: Option<Bound<'py, PyAny>>,
    options: Option<&Bound<'py, PyDict>>,
) -> PyResult<Bound<'py, PyAny>> {
    let o: CompareOptions = from_kwargs(py, "compare_schemes", options)?;
    let seed = seed_or_entropy(o.seed)?;
    let callback = on_progress.map(Bound::unbind);
    let out = py
        .detach(|| {
            o.compare::<Failure>(seed, |done, total| {
                Python::attach(|py| {
                    py.check_signals().map_err(Failure::Py)?;
                    if let Some(f) = &callback {
                        f.call1(py, (done, total)).map_err(Failure::Py)?;
                    }
                    Ok(())
                })
            })
        })
        .map_err(|e| match e {
            Failure::Core(e) => to_py(e),
            Failure::Py(e) => e,
        })?;
    result(py, &out)
}
