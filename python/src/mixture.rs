//! Gaussian mixture reduction: pruning (with renormalisation), Vo & Ma's Mahalanobis merge and
//! Runnalls' KL-based reduction (as used by paper 001's filters), on the core's mixtures.

use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;
use pyo3::types::PyDict;

use crate::convert::{result, to_py};
use crate::options::from_kwargs;
use fisst::gaussian::GaussianMixture;
use fisst::mixture::{merge_close, prune, runnalls};
use fisst::splitting::{MAX_REDUCED_COMPONENTS, MAX_RUNNALLS_INPUT, check_reduce_input};

/// The keyword arguments of [`reduce_mixture`].
#[derive(serde::Deserialize)]
struct ReduceOptions {
    mixture: GaussianMixture,
    #[serde(default)]
    prune_below: f64,
    #[serde(default)]
    merge_distance: Option<f64>,
    #[serde(default)]
    max_components: Option<usize>,
}

/// Mixture reduction: prune components lighter than ``prune_below`` (renormalising), then Vo
/// & Ma's merge within the Mahalanobis distance ``merge_distance`` (U = distance², omitted: no
/// merging), then Runnalls' KL-based reduction to at most ``max_components`` (omitted: no cap;
/// it takes at most 3000 components left after pruning and merging). The total weight is
/// preserved; merges preserve the mixture's mean and covariance. ``mixture`` is a list of
/// ``{"weight", "mean", "cov"}`` (at most 5000). Returns the reduced mixture, the same form.
#[pyfunction]
#[pyo3(
    signature = (**options),
    text_signature = "(*, mixture, prune_below=0.0, merge_distance=None, max_components=None)"
)]
pub fn reduce_mixture<'py>(
    py: Python<'py>,
    options: Option<&Bound<'py, PyDict>>,
) -> PyResult<Bound<'py, PyAny>> {
    if let Some(m) = options.and_then(|o| o.get_item("mixture").ok().flatten())
        && let Ok(n) = m.len()
    {
        // before reading them: reading 10^6 components alone takes seconds
        check_reduce_input(n).map_err(to_py)?;
    }
    let o: ReduceOptions = from_kwargs(py, "reduce_mixture", options)?;
    check_reduce_input(o.mixture.len()).map_err(to_py)?;
    let max = o
        .max_components
        .map(|m| fisst::Error::check_range("max_components", m, 1, MAX_REDUCED_COMPONENTS))
        .transpose()
        .map_err(to_py)?;
    let out = py
        .detach(|| -> Result<Result<GaussianMixture, usize>, fisst::Error> {
            let mut out = prune(&o.mixture, o.prune_below)?;
            if let Some(d) = o.merge_distance {
                out = merge_close(&out, d)?;
            }
            if let Some(max) = max {
                if out.len() > max && out.len() > MAX_RUNNALLS_INPUT {
                    return Ok(Err(out.len()));
                }
                out = runnalls(&out, max)?;
            }
            Ok(Ok(out))
        })
        .map_err(to_py)?
        .map_err(|left| {
            PyValueError::new_err(format!(
                "max_components: Runnalls' reduction takes at most {MAX_RUNNALLS_INPUT} \
                 components, {left} remain after pruning and merging; raise prune_below or \
                 merge_distance"
            ))
        })?;
    result(py, &out)
}
