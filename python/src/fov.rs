//! Field-of-view cardinality and sensor placement (Sections VI–VII of paper 001, LeGrand &
//! Ferrari, "Split Happens! Imprecise and negative information in Gaussian mixture random
//! finite set filtering"): `fov_cardinality`, `fov_variance_map`, `placement_scene` and
//! `mixture_density_grid`, on the core's own `fisst::fov` option and result types.

use pyo3::prelude::*;
use pyo3::types::PyDict;

use crate::convert::{result, to_py};
use crate::options::from_kwargs;
use fisst::fov::{
    FovCardinalityOptions, FovVarianceMapOptions, FovVarianceMapResult, MixtureDensityGridOptions,
    SceneOptions,
};

/// The pmf of the number of objects inside a field of view (Propositions 1–4 of paper 001:
/// eqs. (72)–(73); Poisson (78), i.i.d. cluster (84), multi-Bernoulli (88), GLMB (92); with
/// ``detection_probability`` < 1 the pmf of object-originated detections, eq. (75)).
///
/// ``rfs`` is a dict with exactly one key: ``{"multi_bernoulli": [{"existence", "mean",
/// "cov"}, …]}``, ``{"poisson": [{"weight", "mean", "cov"}, …]}`` (the PHD),
/// ``{"iid_cluster": {"cardinality", "density"}}`` or ``{"glmb": [{"weight", "components":
/// [{"mean", "cov"}, …]}, …]}`` (at most 10,000 Gaussians in all). ``fov`` is a region of the
/// position subspace: ``{"box": {"min", "max"}}``, ``{"ball": {"center", "radius"}}``,
/// ``{"polygon": {"vertices"}}`` (at most 1,000), ``{"union": [...]}``,
/// ``{"intersection": [...]}`` or ``{"complement": region}``. A call whose masses would take
/// more than about 2 s is refused (``ValueError`` naming ``rfs``).
///
/// Returns a ``Result`` with ``pmf`` (``pmf[n]`` = P(n objects in the FoV)), ``mean``,
/// ``variance`` and ``mass_in_fov`` (⟨1_S, p_i⟩ of each Gaussian in input order, without p_D).
#[pyfunction]
#[pyo3(
    signature = (**options),
    text_signature = "(*, rfs, fov, detection_probability=1.0)"
)]
pub fn fov_cardinality<'py>(
    py: Python<'py>,
    options: Option<&Bound<'py, PyDict>>,
) -> PyResult<Bound<'py, PyAny>> {
    let o: FovCardinalityOptions = from_kwargs(py, "fov_cardinality", options)?;
    let r = py.detach(|| o.run()).map_err(to_py)?;
    result(py, &r)
}

/// The variance of the number of objects in an axis-aligned field of view of size
/// ``fov_size`` = ``(width, height)`` centred at every point of a grid, for a multi-Bernoulli
/// (eq. (88)'s variance Σ r_S(1 − r_S); the sensor placement of Section VII of paper 001,
/// Fig. 10). ``multi_bernoulli`` is ``[{"existence", "mean", "cov"}, …]`` (2D or more, the
/// first two components positions; ``placement_scene().multi_bernoulli`` fits), ``grid`` is
/// ``{"x": (min, max, count), "y": (min, max, count)}`` (counts in [1, 4096]; components ×
/// cells at most 2e8).
///
/// Returns a ``Result`` with ``variance``, a 2-D float64 array of shape ``(ny, nx)``
/// (``variance[j, i]`` with the FoV centred at (x_i, y_j): y the row index), ``argmax`` (the
/// centre ``[x, y]`` of the largest variance: the best placement) and ``max``.
#[pyfunction]
#[pyo3(
    signature = (**options),
    text_signature = "(*, multi_bernoulli, fov_size, grid)"
)]
pub fn fov_variance_map<'py>(
    py: Python<'py>,
    options: Option<&Bound<'py, PyDict>>,
) -> PyResult<Bound<'py, PyAny>> {
    let o: FovVarianceMapOptions = from_kwargs(py, "fov_variance_map", options)?;
    let map = py
        .detach(|| o.run().map(FovVarianceMapResult::from))
        .map_err(to_py)?;
    result(py, &map)
}

/// A seeded random multi-Bernoulli scene like the sensor-placement example of paper 001
/// (Section VII, Figs 9–10): ``count`` components (at most 10,000), means uniform in
/// [−extent, extent]², principal standard deviations uniform in ``sigma`` = ``(min, max)``,
/// existences uniform in [0.35, 1). The same seed gives the same scene on every platform, and
/// a smaller ``count`` is a prefix of a larger one.
///
/// Returns a ``Result`` with ``multi_bernoulli``: a list of ``Result`` with ``existence``,
/// ``mean`` (shape ``(2,)``) and ``cov`` (shape ``(2, 2)``), ready for ``fov_cardinality``
/// and ``fov_variance_map``.
#[pyfunction]
#[pyo3(
    signature = (**options),
    text_signature = "(*, count=100, seed=1, extent=3.0, sigma=(0.1, 0.5))"
)]
pub fn placement_scene<'py>(
    py: Python<'py>,
    options: Option<&Bound<'py, PyDict>>,
) -> PyResult<Bound<'py, PyAny>> {
    let o: SceneOptions = from_kwargs(py, "placement_scene", options)?;
    let scene = py.detach(|| o.scene()).map_err(to_py)?;
    result(py, &scene)
}

/// A Gaussian mixture's density Σ w N(s; m, P) at every position of a grid, e.g. a
/// multi-Bernoulli's PHD Σ r N(s; m, P) (eq. (99) of paper 001) as the heat map of Fig. 9.
/// ``mixture`` is ``[{"weight", "mean", "cov"}, …]`` (components of 3 or more dimensions
/// contribute their position marginal, the first two components); ``grid`` is ``{"x": (min,
/// max, count), "y": (min, max, count)}`` (components × cells at most 2.5e7).
///
/// Returns a 2-D float64 array of shape ``(ny, nx)``: entry ``[j, i]`` is the density at
/// (x_i, y_j) (y the row index, as ``matplotlib.pyplot.imshow`` expects with
/// ``origin="lower"``).
#[pyfunction]
#[pyo3(signature = (**options), text_signature = "(*, mixture, grid)")]
pub fn mixture_density_grid<'py>(
    py: Python<'py>,
    options: Option<&Bound<'py, PyDict>>,
) -> PyResult<Bound<'py, PyAny>> {
    let o: MixtureDensityGridOptions = from_kwargs(py, "mixture_density_grid", options)?;
    let rows = py.detach(|| o.run_rows()).map_err(to_py)?;
    result(py, &rows)
}
