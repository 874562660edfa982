//! The closed-form bounds on joint detection and estimation (paper 002, "error bounds for
//! joint detection and estimation"): `jde_bound_no_clutter` (eq. (31)),
//! `gaussian_fisher_information`, `jde_sequential_bound` (eqs. (35), (37)), `jde_example2`
//! and `jde_example2_regularity` (Example 2), on the core's own `fisst::bounds` types.

use pyo3::prelude::*;
use pyo3::types::PyDict;

use crate::convert::{result, to_py};
use crate::options::from_kwargs;
use fisst::bounds;

/// The bound (31) of paper 002 without clutter (Sec. IV-A): ``existence`` r,
/// ``detection_probability`` P̄o, the prior and posterior variances, and the errors charged
/// for a false alarm and a miss. Returns a ``Result`` with ``bound``, ``existence_threshold``,
/// ``declare_on_empty``, the two linear pieces ``hpe``/``lpe``, ``map_threshold`` (r_M* =
/// 1/(2 − P̄o)) and ``map_bound``.
#[pyfunction]
#[pyo3(
    signature = (**options),
    text_signature = "(*, existence, detection_probability, prior_variance, posterior_variance, false_alarm_error, miss_error)"
)]
pub fn jde_bound_no_clutter<'py>(
    py: Python<'py>,
    options: Option<&Bound<'py, PyDict>>,
) -> PyResult<Bound<'py, PyAny>> {
    let o: bounds::NoClutterOptions = from_kwargs(py, "jde_bound_no_clutter", options)?;
    result(py, &o.bound().map_err(to_py)?)
}

/// The Fisher information of a scalar Gaussian measurement z = gain·x + v (paper 002,
/// Sec. V): J1 = 1/σx² + gain²/σv², and the posterior variance 1/J1. Returns a ``Result``
/// with ``information`` and ``posterior_variance``.
#[pyfunction]
#[pyo3(
    signature = (**options),
    text_signature = "(*, prior_variance, gain, noise_variance)"
)]
pub fn gaussian_fisher_information<'py>(
    py: Python<'py>,
    options: Option<&Bound<'py, PyDict>>,
) -> PyResult<Bound<'py, PyAny>> {
    let o: bounds::GaussianInformationOptions =
        from_kwargs(py, "gaussian_fisher_information", options)?;
    result(py, &o.information().map_err(to_py)?)
}

/// The sequential bound of paper 002 over ``steps`` scans (1 … 5000): ``method``
/// ``"enumeration"`` (eq. (35)) or ``"irf"`` (eq. (37)), with the prior and per-detection
/// information and ``detection_probability``. Returns a ``Result`` with ``bound``, an array
/// (``bound[k - 1]`` = P_k).
#[pyfunction]
#[pyo3(
    signature = (**options),
    text_signature = "(*, method, prior_information, detected_information, detection_probability, steps)"
)]
pub fn jde_sequential_bound<'py>(
    py: Python<'py>,
    options: Option<&Bound<'py, PyDict>>,
) -> PyResult<Bound<'py, PyAny>> {
    let o: bounds::SequentialOptions = from_kwargs(py, "jde_sequential_bound", options)?;
    let b = py.detach(|| o.bound()).map_err(to_py)?;
    result(py, &b)
}

/// Example 2 of paper 002 (the non-Gaussian example): the bound and the risk of the optimal
/// joint detector-estimator for ``existence``, ``detection_probability``,
/// ``false_alarm_probability``, ``false_alarm_error`` and ``miss_error``. Returns a
/// ``Result``.
#[pyfunction]
#[pyo3(
    signature = (**options),
    text_signature = "(*, existence, detection_probability, false_alarm_probability, false_alarm_error, miss_error=None)"
)]
pub fn jde_example2<'py>(
    py: Python<'py>,
    options: Option<&Bound<'py, PyDict>>,
) -> PyResult<Bound<'py, PyAny>> {
    let o: bounds::Example2Options = from_kwargs(py, "jde_example2", options)?;
    let r = py.detach(|| o.example2()).map_err(to_py)?;
    result(py, &r)
}

/// The regularity conditions of Example 2 of paper 002, checked numerically. Returns a
/// ``Result``.
#[pyfunction]
pub fn jde_example2_regularity(py: Python<'_>) -> PyResult<Bound<'_, PyAny>> {
    let r = py.detach(bounds::example2_regularity);
    result(py, &r)
}
