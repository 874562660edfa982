//! Optimal Bernoulli point estimation (paper 000, Narykov, Üney & Ralph, "Optimal Bernoulli
//! point estimation with applications"): the loss curves and the threshold curve, on the
//! core's own `fisst::bernoulli` types.

use pyo3::prelude::*;
use pyo3::types::PyDict;

use crate::convert::{result, to_py};
use crate::options::from_kwargs;
use fisst::bernoulli::{
    self, BernoulliEstimateOptions, LossCurveOptions, MmucOptions, MultiBernoulliPointOptions,
    ThresholdCurveOptions,
};

/// Fig. 2 of paper 000: the expected losses against the existence probability p at each of
/// ``existences``, for a point whose miss probability is ``miss_probability`` and the
/// ``costs`` of the loss (7) (``"mpe"``, ``{"mmol": {"asset": .., "countermeasure": ..}}``
/// or ``{"c00": .., "c01": .., "c10": .., "c11": .., "c": ..}``): ρ_∅(p) (14), ρ_a*(p) (13)
/// and the loss of the rule "report when p > threshold" (default: the optimal Γ of (11)).
/// Returns a ``Result`` (``LossCurve``: ``empty``, ``singleton``, ``rule``, ``threshold``).
#[pyfunction]
#[pyo3(
    signature = (**options),
    text_signature = "(*, existences, miss_probability, costs, threshold=None)"
)]
pub fn bernoulli_loss_curve<'py>(
    py: Python<'py>,
    options: Option<&Bound<'py, PyDict>>,
) -> PyResult<Bound<'py, PyAny>> {
    let o: LossCurveOptions = from_kwargs(py, "bernoulli_loss_curve", options)?;
    let c = py.detach(|| bernoulli::loss_curve(&o)).map_err(to_py)?;
    result(py, &c)
}

/// Fig. 3 of paper 000: the optimal existence threshold Γ of (11) against the standard
/// deviation σ of an isotropic Gaussian spatial density, one per entry of ``sigmas``, for
/// the tolerance radius ``radius`` and the ``costs`` (as ``bernoulli_loss_curve``), in
/// ``dim`` dimensions (default 1, as in Fig. 3). Returns a float64 array.
#[pyfunction]
#[pyo3(
    signature = (**options),
    text_signature = "(*, sigmas, radius, costs, dim=None)"
)]
pub fn bernoulli_threshold_curve<'py>(
    py: Python<'py>,
    options: Option<&Bound<'py, PyDict>>,
) -> PyResult<Bound<'py, PyAny>> {
    let o: ThresholdCurveOptions = from_kwargs(py, "bernoulli_threshold_curve", options)?;
    let c = py.detach(|| o.curve()).map_err(to_py)?;
    result(py, &c)
}

/// q(a) of eq. (9) of paper 000: the probability that the object lies outside the ball of
/// radius ``radius`` about ``center``, for a spatial ``density`` written as one of
/// ``{"mean": m, "cov": P}`` (a Gaussian), ``{"mixture": [{"weight", "mean", "cov"}, ...]}``
/// or ``{"particles": X, "weights": w}`` (weights optional, equal by default). Error-controlled
/// quadrature for Gaussians (1e-10), exact for particles. Returns a float.
#[pyfunction]
#[pyo3(signature = (**options), text_signature = "(*, density, center, radius)")]
pub fn probability_outside_ball(
    py: Python<'_>,
    options: Option<&Bound<'_, PyDict>>,
) -> PyResult<f64> {
    let o: OutsideBallOptions = from_kwargs(py, "probability_outside_ball", options)?;
    let (density, center, radius) = (o.density, o.center, o.radius);
    py.detach(|| density.prob_outside_ball(&center, radius))
        .map_err(to_py)
}

/// The keyword arguments of [`probability_outside_ball`], read into the core's density.
#[derive(serde::Deserialize)]
struct OutsideBallOptions {
    density: fisst::bernoulli::SpatialDensity,
    center: Vec<f64>,
    radius: f64,
}

/// Theorem III.3 of paper 000: the Bayes-optimal point estimate of a Bernoulli with
/// existence probability ``existence`` and spatial ``density`` (as in
/// ``probability_outside_ball``) under the loss (7) with tolerance ``radius`` r0 and ``costs``
/// (as in ``bernoulli_loss_curve``): report the MMUC point a* (12) when p is beyond the
/// threshold Γ (11), else nothing (ties report nothing). Returns a ``Result``
/// (``BernoulliReport``: ``declare``, ``estimate`` (None when not declared), ``mmuc``,
/// ``threshold``, ``miss_probability``, ``expected_loss_empty`` (14),
/// ``expected_loss_singleton`` (13)).
#[pyfunction]
#[pyo3(
    signature = (**options),
    text_signature = "(*, existence, density, radius, costs)"
)]
pub fn bernoulli_estimate<'py>(
    py: Python<'py>,
    options: Option<&Bound<'py, PyDict>>,
) -> PyResult<Bound<'py, PyAny>> {
    let o: BernoulliEstimateOptions = from_kwargs(py, "bernoulli_estimate", options)?;
    let r = py.detach(|| o.estimate()).map_err(to_py)?;
    result(py, &r)
}

/// The MMUC estimate a* = argmin_a q(a) of eq. (12) of paper 000: the centre of the ball of
/// radius ``radius`` most likely to hold an object with spatial ``density`` (as in
/// ``probability_outside_ball``; at most 100 mixture components, at most 1500 particles in 2
/// or more dimensions). Returns a ``Result`` (``MmucEstimate``: ``center``,
/// ``miss_probability`` q(a*), ``method``: ``"gaussian-mean"``, ``"shared-mean"``,
/// ``"mixture-search"``, ``"particles-exact"`` or ``"particles-heuristic"``).
#[pyfunction]
#[pyo3(signature = (**options), text_signature = "(*, density, radius)")]
pub fn mmuc_estimate<'py>(
    py: Python<'py>,
    options: Option<&Bound<'py, PyDict>>,
) -> PyResult<Bound<'py, PyAny>> {
    let o: MmucOptions = from_kwargs(py, "mmuc_estimate", options)?;
    let r = py.detach(|| o.estimate()).map_err(to_py)?;
    result(py, &r)
}

/// Theorem III.3 of paper 000 applied to each component of a multi-Bernoulli, each decided
/// alone: ``components`` a list of ``{"existence": r, "density": s}`` (at most 10,000), with
/// the loss (7)'s ``radius`` and ``costs`` (as in ``bernoulli_estimate``). Returns a
/// ``Result`` (``MultiBernoulliReport``: ``reported``, the indices of the declared
/// components; ``estimates``, their points a*; ``components``, each one's
/// ``bernoulli_estimate`` result).
#[pyfunction]
#[pyo3(
    signature = (**options),
    text_signature = "(*, components, radius, costs)"
)]
pub fn multi_bernoulli_point_estimate<'py>(
    py: Python<'py>,
    options: Option<&Bound<'py, PyDict>>,
) -> PyResult<Bound<'py, PyAny>> {
    let o: MultiBernoulliPointOptions = from_kwargs(py, "multi_bernoulli_point_estimate", options)?;
    let r = py.detach(|| o.estimate()).map_err(to_py)?;
    result(py, &r)
}
