//! The bounds on joint detection and estimation (paper 002, Rezaeian & Vo, "Error bounds for
//! joint detection and estimation of a single object with random finite set observation"):
//! `jde_bound_no_clutter` (eq. (31)), `gaussian_fisher_information`, `jde_sequential_bound`
//! (eqs. (35), (37)), `jde_bound` (Theorems 1 and 2, (63)–(72)), `jde_monte_carlo` (the risk
//! (11) of the optimal joint detector-estimator), `jde_example2` and `jde_example2_regularity`
//! (Example 2), on the core's own `fisst::bounds` types.

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

/// Theorems 1 and 2 of paper 002 (Rezaeian & Vo): the lower bound on the risk E e²(X, X̂(Z))
/// (11) of joint detection and estimation of a single object, for ``model`` ``"I"`` (a
/// Bernoulli observation with false alarms, (13); Theorem 1, (14)–(21)) or ``"II"`` (Poisson
/// clutter, (22); Theorem 2, (22)–(26)), and for a state in R^l their vector extensions
/// (63)–(72).
///
/// Keyword arguments (as the npm package's ``jdeBound`` options, in snake_case):
/// ``existence`` r ∈ [0, 1]; ``prior`` f, a dict of one kind: ``{"gaussian": {"mean",
/// "variance"}}``, ``{"uniform": {"low", "high"}}``, ``{"mixture": [{"weight", "mean",
/// "variance"}, …]}``, ``{"table": {"x", "density"}}`` or ``{"multivariate_gaussian":
/// {"mean", "cov"}}``; ``observation`` ``{"detection_probability", "gain", "offset",
/// "noise_variance", "noise_cov"}`` (P_o a number or ``{"table": {"x", "probability"}}``;
/// with a vector prior ``gain`` is H, m rows of l numbers, and ``noise_cov`` R);
/// ``false_alarm`` ``{"probability", "density"}`` (model I: q, ψ) or ``clutter`` ``{"rate",
/// "density"}`` (model II: λ, v/λ); ``false_alarm_error`` e0² and ``miss_error`` e1²;
/// optional ``dims``, ``tolerance`` (1e-10), ``samples`` (20,000 per cardinality of
/// Theorem 2's Monte Carlo, samples × Σ n ≤ 10⁷), ``seed`` (omitted: fresh entropy,
/// reported as ``seed``) and ``quadrature_cardinality`` (1 or 2; default 2 on a
/// linear-Gaussian model, Gaussian prior and constant P_o, else 1). Returns a ``Result`` with
/// ``bound``, ``phase`` (``"HPE"``/``"LPE"``), ``existence_threshold``, ``terms``,
/// ``error``, ``hpe``, ``lpe``, … and for a vector state ``components`` and
/// ``inverse_information_matrix``. A wrong kind of value (rows as a 1D prior's gain,
/// ``clutter`` with model I) is a ``TypeError``, a bad value a ``ValueError``, each naming
/// the argument. The GIL is released while it computes.
#[pyfunction]
#[pyo3(
    signature = (**options),
    text_signature = "(*, model, existence, prior, observation, false_alarm_error, miss_error, false_alarm=None, clutter=None, dims=None, tolerance=None, samples=None, seed=None, quadrature_cardinality=None)"
)]
pub fn jde_bound<'py>(
    py: Python<'py>,
    options: Option<&Bound<'py, PyDict>>,
) -> PyResult<Bound<'py, PyAny>> {
    let o: bounds::JdeBoundOptions = from_kwargs(py, "jde_bound", options)?;
    let r = py
        .detach(|| o.run(fisst::math::rng::entropy_seed))
        .map_err(to_py)?;
    result(py, &r)
}

/// The seeded Monte Carlo of the optimal joint detector-estimator of paper 002 (Rezaeian &
/// Vo): MAP detection (39)/(40), the posterior mean, and on Z = ∅ the rule ``empty_rule``
/// (``"optimal"``: HPE/LPE (46); ``"map"``: Section IV-A; ``"declare"``; ``"reject"``),
/// simulated to give the risk E e² (11) that ``jde_bound`` bounds, with its standard error
/// and parts, over ``scans`` scans of one target (Section III-E).
///
/// Keyword arguments (as the npm package's ``jdeMonteCarlo`` options, in snake_case): ``model``
/// ``"I"`` or ``"II"``, ``existence``, ``prior`` (``{"gaussian": {"mean", "variance"}}``,
/// ``{"multivariate_gaussian": {"mean", "cov"}}`` or ``"example2"``, Example 2 (32)),
/// ``observation`` (a constant ``detection_probability`` and, for a Gaussian prior, the
/// linear-Gaussian ``gain``/``offset``/``noise_variance``/``noise_cov`` as in
/// ``jde_bound``), ``false_alarm`` or ``clutter``, ``false_alarm_error``, ``miss_error``,
/// and optional ``empty_rule``, ``scans`` (1), ``samples`` (20,000; samples × scans × (1 +
/// ⌈q or λ⌉) ≤ 10⁷) and ``seed`` (omitted: fresh entropy, reported as ``seed``). The same
/// seed gives the npm package's numbers bit for bit. Returns a ``Result`` (``mse``, ``se``,
/// the false-alarm, miss and estimation parts, per coordinate and per scan). The GIL is
/// released while it runs.
#[pyfunction]
#[pyo3(
    signature = (**options),
    text_signature = "(*, model, existence, prior, observation, false_alarm_error, miss_error, false_alarm=None, clutter=None, empty_rule=None, scans=None, samples=None, seed=None)"
)]
pub fn jde_monte_carlo<'py>(
    py: Python<'py>,
    options: Option<&Bound<'py, PyDict>>,
) -> PyResult<Bound<'py, PyAny>> {
    let o: bounds::JdeMonteCarloRequest = from_kwargs(py, "jde_monte_carlo", options)?;
    let r = py
        .detach(|| o.run(fisst::math::rng::entropy_seed))
        .map_err(to_py)?;
    result(py, &r)
}
