//! Multi-Bernoulli cardinality and optimal estimation (Section III of paper 003,
//! García-Fernández & Svensson, "Spooky effect in optimal OSPA estimation and how GOSPA
//! solves it"): the core's `fisst::estimators` options and results.

use pyo3::prelude::*;
use pyo3::types::PyDict;

use crate::convert::{result, to_py};
use crate::options::{from_kwargs, from_value};
use fisst::cardinality::{leave_one_out_cardinalities, multi_bernoulli_cardinality as pmf};
use fisst::estimators::figures::{
    DecisionMapOptions, IdenticalComponentCountsOptions, decision_map, identical_component_counts,
};
use fisst::estimators::{
    MbAlternativeEstimateOptions, MbMeanSquareErrorOptions, MbOptimalEstimateOptions,
};

/// The cardinality distribution of a multi-Bernoulli RFS with existence probabilities
/// ``existence`` (eq. (6) of paper 003: the Poisson-binomial pmf, by the stable recursion).
/// Returns a float64 array ``pmf`` of length ``len(existence) + 1``, ``pmf[n] = P(|X| = n)``.
#[pyfunction]
#[pyo3(text_signature = "(existence)")]
pub fn multi_bernoulli_cardinality<'py>(
    py: Python<'py>,
    existence: &Bound<'py, PyAny>,
) -> PyResult<Bound<'py, PyAny>> {
    let r: Vec<f64> = from_value(existence, "existence")?;
    let out = py.detach(|| pmf(&r)).map_err(to_py)?;
    result(py, &out)
}

/// The cardinality pmfs of the multi-Bernoulli with each component left out in turn: row i
/// is ``multi_bernoulli_cardinality`` without component i (a ``(n, n)`` array).
#[pyfunction]
#[pyo3(text_signature = "(existence)")]
pub fn multi_bernoulli_leave_one_out<'py>(
    py: Python<'py>,
    existence: &Bound<'py, PyAny>,
) -> PyResult<Bound<'py, PyAny>> {
    let r: Vec<f64> = from_value(existence, "existence")?;
    let out = py
        .detach(|| leave_one_out_cardinalities(&r))
        .map_err(to_py)?;
    result(py, &out)
}

/// The estimate of a multi-Bernoulli with identical spatial densities that minimises the
/// mean (G)OSPA error of order ``p`` (Section III, Props 1–2 and Lemma 4 of paper 003):
/// ``metric`` is ``"gospa"``, ``"ospa"`` or ``"uospa"``, ``c`` the cut-off and ``alpha``
/// GOSPA's cardinality weight. Returns a ``Result`` (``MbEstimate``): ``report`` (a bool
/// array, which components to report) and ``mean_square_error``.
#[pyfunction]
#[pyo3(signature = (**options), text_signature = "(*, existence, metric, c=1.0, p=2.0, alpha=2.0)")]
pub fn mb_optimal_estimate<'py>(
    py: Python<'py>,
    options: Option<&Bound<'py, PyDict>>,
) -> PyResult<Bound<'py, PyAny>> {
    let o: MbOptimalEstimateOptions = from_kwargs(py, "mb_optimal_estimate", options)?;
    let e = py.detach(|| o.estimate()).map_err(to_py)?;
    result(py, &e)
}

/// The mean (G)OSPA error of order ``p`` of reporting the components ``report`` (bools) of
/// a multi-Bernoulli with identical spatial densities (Section III of paper 003). Returns
/// a float.
#[pyfunction]
#[pyo3(signature = (**options), text_signature = "(*, report, existence, metric, c=1.0, p=2.0, alpha=2.0)")]
pub fn mb_mean_square_error(py: Python<'_>, options: Option<&Bound<'_, PyDict>>) -> PyResult<f64> {
    let o: MbMeanSquareErrorOptions = from_kwargs(py, "mb_mean_square_error", options)?;
    py.detach(|| o.mean_error()).map_err(to_py)
}

/// The alternative multi-object estimators that paper 003 compares with the optimal one:
/// ``method`` ``"mam"`` (marginal a posteriori), ``"jom"`` (joint object manager, with the
/// log peak densities ``ln_peak`` and ``ln_c``) or ``"map-cardinality"``. Returns a
/// ``Result`` (``AlternativeEstimate``).
#[pyfunction]
#[pyo3(signature = (**options), text_signature = "(*, existence, method, ln_peak=None, ln_c=0.0)")]
pub fn mb_alternative_estimate<'py>(
    py: Python<'py>,
    options: Option<&Bound<'py, PyDict>>,
) -> PyResult<Bound<'py, PyAny>> {
    let o: MbAlternativeEstimateOptions = from_kwargs(py, "mb_alternative_estimate", options)?;
    let e = py.detach(|| o.estimate()).map_err(to_py)?;
    result(py, &e)
}

/// Fig. 1 of paper 003: over a ``resolution`` × ``resolution`` grid of the existence
/// probabilities (r1, r2) of two components, how many components ``estimator`` reports
/// (``"gospa"``, ``"ospa"``, ``"uospa"``, ``"mam"``, ``"jom"``, ``"map-cardinality"``).
/// Returns a ``Result`` (``DecisionMap``).
#[pyfunction]
#[pyo3(signature = (**options), text_signature = "(*, estimator, resolution=100, c=1.0, p=2.0, alpha=2.0)")]
pub fn mb_decision_map<'py>(
    py: Python<'py>,
    options: Option<&Bound<'py, PyDict>>,
) -> PyResult<Bound<'py, PyAny>> {
    let o: DecisionMapOptions = from_kwargs(py, "mb_decision_map", options)?;
    let m = py.detach(|| decision_map(&o)).map_err(to_py)?;
    result(py, &m)
}

/// Paper 003's identical-components example: for n = 1 … ``max_components`` components of
/// existence probability ``existence``, how many each estimator reports. Returns a ``Result``
/// (``IdenticalComponentCounts``).
#[pyfunction]
#[pyo3(signature = (**options), text_signature = "(*, existence, max_components)")]
pub fn mb_identical_component_counts<'py>(
    py: Python<'py>,
    options: Option<&Bound<'py, PyDict>>,
) -> PyResult<Bound<'py, PyAny>> {
    let o: IdenticalComponentCountsOptions =
        from_kwargs(py, "mb_identical_component_counts", options)?;
    let c = py
        .detach(|| identical_component_counts(&o))
        .map_err(to_py)?;
    result(py, &c)
}
