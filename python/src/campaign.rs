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
