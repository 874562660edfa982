//! `gospa`, `ospa`, `uospa`, `gospa_series`, `ospa_series`, `linear_assignment`: the core's
//! `fisst::metrics` (paper 003, García-Fernández & Svensson, "Spooky effect in optimal OSPA
//! estimation and how GOSPA solves it"; OSPA of Schuhmacher, Vo & Vo 2008).

use pyo3::prelude::*;

use crate::convert::{
    OnPoints, Points, number, number_or, point_sets, points, result, to_py, with_points,
};
use fisst::metrics::{Gospa, GospaReport, GospaSeries, Ospa, OspaDecomposition, OspaSeries};

/// The core's metric calls on a truth and an estimate set (`sets[0]`, `sets[1]`), or on the
/// truths and estimates of a scenario (`sets[..steps]`, `sets[steps..]`), through
/// [`with_points`].
enum Call<'a> {
    GospaReport(&'a Gospa),
    OspaDecompose(&'a Ospa),
    GospaSeries(&'a Gospa, usize),
    OspaSeries(&'a Ospa, usize),
}

/// What a [`Call`] returns.
enum Out {
    GospaReport(GospaReport),
    OspaDecomposition(OspaDecomposition),
    GospaSeries(GospaSeries),
    OspaSeries(OspaSeries),
}

impl OnPoints for Call<'_> {
    type Output = fisst::Result<Out>;
    fn call<P: AsRef<[f64]> + Sync>(self, sets: &[Vec<P>]) -> Self::Output {
        Ok(match self {
            Call::GospaReport(m) => Out::GospaReport(m.report(&sets[0], &sets[1])?),
            Call::OspaDecompose(m) => Out::OspaDecomposition(m.decompose(&sets[0], &sets[1])?),
            Call::GospaSeries(m, n) => Out::GospaSeries(m.series(&sets[..n], &sets[n..])?),
            Call::OspaSeries(m, n) => Out::OspaSeries(m.series(&sets[..n], &sets[n..])?),
        })
    }
}

/// Runs `call` on `sets` with the GIL released and converts its result.
fn run<'py>(py: Python<'py>, sets: &[&Points], call: Call<'_>) -> PyResult<Bound<'py, PyAny>> {
    match py.detach(|| with_points(sets, call)).map_err(to_py)? {
        Out::GospaReport(r) => result(py, &r),
        Out::OspaDecomposition(r) => result(py, &r),
        Out::GospaSeries(r) => result(py, &r),
        Out::OspaSeries(r) => result(py, &r),
    }
}

/// GOSPA between two point sets (García-Fernández & Svensson, "Spooky effect in optimal OSPA
/// estimation and how GOSPA solves it", paper 003, Def. 2 and Prop. 3).
///
/// ``truth`` and ``estimate`` are ``(n, d)`` arrays of points (lists, any numeric dtype and
/// pandas frames are converted once; an empty list is the empty set). ``c`` > 0 is the
/// cut-off, ``p`` ≥ 1 the order, ``alpha`` in (0, 2] the cardinality-mismatch weight.
///
/// Returns a ``Result`` (``GospaReport``) with ``distance`` and, for ``alpha == 2``, its
/// decomposition ``localisation`` (Σ d^p over the assigned pairs, not rooted), ``missed``,
/// ``false_targets`` and ``assignment`` (a ``(k, 2)`` array of (truth, estimate) index pairs),
/// so that ``distance**p == localisation + c**p / 2 * (missed + false_targets)``.
///
/// Raises ``ValueError`` naming the argument for a bad value or shape (``c must be > 0``,
/// ``estimate[3] has length 1, expected 2``), ``TypeError`` for a wrong kind of value. The
/// same size caps as the npm package (at most 524,288 points in all).
#[pyfunction]
#[pyo3(signature = (truth, estimate, *, c, p = None, alpha = None), text_signature = "(truth, estimate, *, c, p=2.0, alpha=2.0)")]
pub fn gospa<'py>(
    py: Python<'py>,
    truth: &Bound<'py, PyAny>,
    estimate: &Bound<'py, PyAny>,
    c: &Bound<'py, PyAny>,
    p: Option<&Bound<'py, PyAny>>,
    alpha: Option<&Bound<'py, PyAny>>,
) -> PyResult<Bound<'py, PyAny>> {
    let (c, p, alpha) = (
        number(c, "c")?,
        number_or(p, "p", 2.0)?,
        number_or(alpha, "alpha", 2.0)?,
    );
    let (t, e) = (points(truth, "truth")?, points(estimate, "estimate")?);
    let metric = Gospa::new(c, p, alpha).map_err(to_py)?;
    run(py, &[&t, &e], Call::GospaReport(&metric))
}

/// OSPA between two point sets with its rooted localisation and cardinality parts (Schuhmacher,
/// Vo & Vo, "A consistent metric for performance evaluation of multi-object filters", 2008;
/// eqs. 24–26 of Ristic & Vo, paper 004): ``distance**p == localisation**p + cardinality**p``.
///
/// Returns a ``Result`` (``OspaDecomposition``): ``distance``, ``localisation``,
/// ``cardinality`` and the optimal ``assignment`` (a ``(k, 2)`` array of index pairs). The
/// assignment minimises Σ min(d, c)^p for the given p (Stone Soup's OSPA assigns on p = 1
/// distances whatever p is, which is above the optimum for p ≠ 1).
#[pyfunction]
#[pyo3(signature = (truth, estimate, *, c, p = None), text_signature = "(truth, estimate, *, c, p=2.0)")]
pub fn ospa<'py>(
    py: Python<'py>,
    truth: &Bound<'py, PyAny>,
    estimate: &Bound<'py, PyAny>,
    c: &Bound<'py, PyAny>,
    p: Option<&Bound<'py, PyAny>>,
) -> PyResult<Bound<'py, PyAny>> {
    let (c, p) = (number(c, "c")?, number_or(p, "p", 2.0)?);
    let (t, e) = (points(truth, "truth")?, points(estimate, "estimate")?);
    let metric = Ospa::new(c, p).map_err(to_py)?;
    run(py, &[&t, &e], Call::OspaDecompose(&metric))
}

/// UOSPA, GOSPA with alpha = 1 (paper 003). Returns a ``Result`` with ``distance``.
#[pyfunction]
#[pyo3(signature = (truth, estimate, *, c, p = None), text_signature = "(truth, estimate, *, c, p=2.0)")]
pub fn uospa<'py>(
    py: Python<'py>,
    truth: &Bound<'py, PyAny>,
    estimate: &Bound<'py, PyAny>,
    c: &Bound<'py, PyAny>,
    p: Option<&Bound<'py, PyAny>>,
) -> PyResult<Bound<'py, PyAny>> {
    let (c, p) = (number(c, "c")?, number_or(p, "p", 2.0)?);
    let (t, e) = (points(truth, "truth")?, points(estimate, "estimate")?);
    let metric = Gospa::uospa(c, p).map_err(to_py)?;
    run(py, &[&t, &e], Call::GospaReport(&metric))
}

/// The point sets of a scenario, `truths[t]` and `estimates[t]`, with the step cap checked
/// before reading them (reading 10^6 steps alone takes seconds) and after.
fn series_sets(
    truths: &Bound<'_, PyAny>,
    estimates: &Bound<'_, PyAny>,
) -> PyResult<(Vec<Points>, Vec<Points>)> {
    if let Ok(steps) = truths.len() {
        fisst::metrics::check_series_steps(steps).map_err(to_py)?;
    }
    let t = point_sets(truths, "truths")?;
    fisst::metrics::check_series_steps(t.len()).map_err(to_py)?;
    Ok((t, point_sets(estimates, "estimates")?))
}

/// GOSPA over a whole scenario in one call: ``truths[t]`` and ``estimates[t]`` are the point
/// sets (``(n, d)`` arrays) at step t. Returns a ``Result`` (``GospaSeries``): per-step
/// ``distance`` (and, for ``alpha == 2``, ``localisation``, ``missed``, ``false_targets``)
/// as numpy arrays, with their means. The same numbers as calling ``gospa`` per step. At most
/// 262,144 steps and 262,144 points over all steps.
#[pyfunction]
#[pyo3(signature = (*, truths, estimates, c, p = None, alpha = None), text_signature = "(*, truths, estimates, c, p=2.0, alpha=2.0)")]
pub fn gospa_series<'py>(
    py: Python<'py>,
    truths: &Bound<'py, PyAny>,
    estimates: &Bound<'py, PyAny>,
    c: &Bound<'py, PyAny>,
    p: Option<&Bound<'py, PyAny>>,
    alpha: Option<&Bound<'py, PyAny>>,
) -> PyResult<Bound<'py, PyAny>> {
    let (c, p, alpha) = (
        number(c, "c")?,
        number_or(p, "p", 2.0)?,
        number_or(alpha, "alpha", 2.0)?,
    );
    let metric = Gospa::new(c, p, alpha).map_err(to_py)?;
    let (t, e) = series_sets(truths, estimates)?;
    let sets: Vec<&Points> = t.iter().chain(&e).collect();
    run(py, &sets, Call::GospaSeries(&metric, t.len()))
}

/// OSPA with its localisation and cardinality parts over a whole scenario in one call (eqs.
/// 24–26 of Ristic & Vo, paper 004, at every step). Returns a ``Result`` (``OspaSeries``) of
/// per-step numpy arrays and their means. At most 262,144 steps and 262,144 points in all.
#[pyfunction]
#[pyo3(signature = (*, truths, estimates, c, p = None), text_signature = "(*, truths, estimates, c, p=2.0)")]
pub fn ospa_series<'py>(
    py: Python<'py>,
    truths: &Bound<'py, PyAny>,
    estimates: &Bound<'py, PyAny>,
    c: &Bound<'py, PyAny>,
    p: Option<&Bound<'py, PyAny>>,
) -> PyResult<Bound<'py, PyAny>> {
    let (c, p) = (number(c, "c")?, number_or(p, "p", 2.0)?);
    let metric = Ospa::new(c, p).map_err(to_py)?;
    let (t, e) = series_sets(truths, estimates)?;
    let sets: Vec<&Points> = t.iter().chain(&e).collect();
    run(py, &sets, Call::OspaSeries(&metric, t.len()))
}

/// Exact rectangular linear assignment: ``cost`` is an ``(r, k)`` array of finite costs.
/// Returns a ``Result`` (``Assignment``): ``pairs``, an ``(min(r, k), 2)`` int array of
/// (row, column) pairs sorted by row, and ``cost``, their total, the least possible: every
/// row is assigned when ``r <= k``, every column otherwise.
#[pyfunction]
#[pyo3(signature = (cost))]
pub fn linear_assignment<'py>(
    py: Python<'py>,
    cost: &Bound<'py, PyAny>,
) -> PyResult<Bound<'py, PyAny>> {
    let cost = points(cost, "cost")?;
    let (rows, cols, flat) = (cost.len(), cost.dim(), cost.flat());
    let a = py
        .detach(|| fisst::math::linear_assignment(flat, rows, cols))
        .map_err(to_py)?;
    result(py, &a)
}
