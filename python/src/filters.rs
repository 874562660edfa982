//! The GM and particle Bernoulli filters for imprecise (region) reports and negative
//! information (paper 001, LeGrand & Ferrari, "Split Happens! Imprecise and negative
//! information in Gaussian mixture random finite set filtering", Section V, eqs. (40)–(60)),
//! on the core's own `fisst::filters` types (Rust names; regions `{"box": {"min", "max"}}`,
//! `{"ball": {"center", "radius"}}`, `{"polygon": {"vertices"}}`, `{"union": [...]}`,
//! `{"intersection": [...]}`, `{"complement": region}`; mixtures `[{"weight", "mean", "cov"}]`;
//! the transition `{"F", "Q"}` and the likelihood `{"H", "R"}`).

use std::sync::{Mutex, MutexGuard};

use pyo3::exceptions::{PyRuntimeError, PyTypeError};
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyList, PyTuple};

use crate::convert::{points, result, seed_or_entropy, to_py};
use crate::options::{from_kwargs, from_value};
use fisst::bernoulli::{ApplicationLoss, Costs};
use fisst::filters::{
    BernoulliFilterOptions, EstimateOptions, GmBernoulli, GmBernoulliFilter as CoreGm,
    LinearGaussianLikelihood, ParticleBernoulliFilter as CorePf, ParticleOptions, PredictOptions,
    UpdateOptions, gm_bernoulli_predict as core_predict, gm_bernoulli_update as core_update,
    gm_bernoulli_update_vector,
};
use fisst::regions::Region;

/// The keyword arguments `kwargs` split into those named in `keys` and the rest.
fn split<'py>(
    py: Python<'py>,
    kwargs: Option<&Bound<'py, PyDict>>,
    keys: &[&str],
) -> PyResult<(Bound<'py, PyDict>, Bound<'py, PyDict>)> {
    let (these, rest) = (PyDict::new(py), PyDict::new(py));
    if let Some(kwargs) = kwargs {
        for (k, v) in kwargs.iter() {
            let key: String = k.extract()?;
            if keys.contains(&key.as_str()) {
                these.set_item(k, v)?;
            } else {
                rest.set_item(k, v)?;
            }
        }
    }
    Ok((these, rest))
}

/// The estimate options: omitted, the MMSE estimate; `radius` and `costs` together, the
/// optimal point estimate of the loss (7) of paper 000.
fn estimate_options(
    radius: Option<f64>,
    costs: Option<&Bound<'_, PyAny>>,
) -> PyResult<EstimateOptions> {
    match (radius, costs) {
        (None, None) => Ok(EstimateOptions { loss: None }),
        (Some(r), Some(c)) => {
            let costs: Costs = from_value(c, "costs")?;
            Ok(EstimateOptions {
                loss: Some(ApplicationLoss::new(costs, r).map_err(to_py)?),
            })
        }
        (Some(_), None) => Err(PyTypeError::new_err(
            "estimate() missing the keyword argument 'costs' (radius and costs go together)",
        )),
        (None, Some(_)) => Err(PyTypeError::new_err(
            "estimate() missing the keyword argument 'radius' (radius and costs go together)",
        )),
    }
}

/// One scan of reports: a list of regions (positional) or `measurements`, an `(m, d)` array
/// (keyword).
enum Scan {
    Reports(Vec<Region>),
    Measurements(Vec<f64>, usize, usize),
}

fn scan(
    reports: Option<&Bound<'_, PyAny>>,
    measurements: Option<&Bound<'_, PyAny>>,
) -> PyResult<Scan> {
    match (reports, measurements) {
        (Some(r), None) => Ok(Scan::Reports(from_value(r, "reports")?)),
        (None, Some(m)) => {
            let p = points(m, "measurements")?;
            Ok(Scan::Measurements(p.flat().to_vec(), p.len(), p.dim()))
        }
        (None, None) => Err(PyTypeError::new_err(
            "update() takes the reports (a list of regions; [] is an empty scan) or measurements=",
        )),
        (Some(_), Some(_)) => Err(PyTypeError::new_err(
            "update() takes either the reports or measurements=, not both",
        )),
    }
}

fn rows(flat: &[f64], n: usize, d: usize) -> Vec<&[f64]> {
    if d == 0 {
        vec![&[][..]; n]
    } else {
        flat.chunks(d).collect()
    }
}

/// What a filter did since it was made, replayed to unpickle it (the filters are
/// deterministic given their configuration and seed).
enum Op {
    Predict,
    Update(Vec<Region>),
    Measurements(Vec<f64>, usize, usize),
}

fn ops_to_py<'py>(py: Python<'py>, ops: &[Op]) -> PyResult<Bound<'py, PyList>> {
    let list = PyList::empty(py);
    for op in ops {
        let item = match op {
            Op::Predict => PyTuple::new(py, ["predict".into_pyobject(py)?.into_any()])?,
            Op::Update(r) => PyTuple::new(
                py,
                [
                    "update".into_pyobject(py)?.into_any(),
                    pythonize::pythonize(py, r)
                        .map_err(|e| PyRuntimeError::new_err(e.to_string()))?,
                ],
            )?,
            Op::Measurements(z, n, d) => PyTuple::new(
                py,
                [
                    "measurements".into_pyobject(py)?.into_any(),
                    numpy::ToPyArray::to_pyarray(&z[..], py)
                        .call_method1("reshape", ((*n, *d),))?,
                ],
            )?,
        };
        list.append(item)?;
    }
    Ok(list)
}

/// What the two core filters share, so that one update serves both classes.
trait Scans: Send {
    fn by_reports(&mut self, reports: &[Region]) -> fisst::Result<fisst::filters::UpdateInfo>;
    fn by_measurements(&mut self, z: &[&[f64]]) -> fisst::Result<fisst::filters::UpdateInfo>;
}

impl Scans for CoreGm {
    fn by_reports(&mut self, reports: &[Region]) -> fisst::Result<fisst::filters::UpdateInfo> {
        self.update(reports)
    }
    fn by_measurements(&mut self, z: &[&[f64]]) -> fisst::Result<fisst::filters::UpdateInfo> {
        self.update_measurements(z)
    }
}

impl Scans for CorePf {
    fn by_reports(&mut self, reports: &[Region]) -> fisst::Result<fisst::filters::UpdateInfo> {
        self.update(reports)
    }
    fn by_measurements(&mut self, z: &[&[f64]]) -> fisst::Result<fisst::filters::UpdateInfo> {
        self.update_measurements(z)
    }
}

/// The update of `filter` with a scan (GIL released), recorded in `ops` when it succeeds (a
/// failed update leaves the filter as it was, and the record too).
fn update_with<'py, F: Scans>(
    py: Python<'py>,
    filter: &mut F,
    ops: &mut Vec<Op>,
    scan: Scan,
) -> PyResult<Bound<'py, PyAny>> {
    let (info, op) = match scan {
        Scan::Reports(r) => (
            py.detach(|| filter.by_reports(&r)).map_err(to_py)?,
            Op::Update(r),
        ),
        Scan::Measurements(z, n, d) => {
            let info = py
                .detach(|| filter.by_measurements(&rows(&z, n, d)))
                .map_err(to_py)?;
            (info, Op::Measurements(z, n, d))
        }
    };
    ops.push(op);
    result(py, &info)
}

fn busy<'a, T>(m: &'a Mutex<T>, class: &str) -> PyResult<MutexGuard<'a, T>> {
    m.try_lock().map_err(|_| {
        PyRuntimeError::new_err(format!(
            "{class} is in use by another thread (a filter is one sequence of scans: use one \
             filter per thread)"
        ))
    })
}

struct GmState {
    filter: CoreGm,
    ops: Vec<Op>,
}

/// The GM Bernoulli filter of Algorithm 3 of paper 001 (LeGrand & Ferrari): it holds the
/// Bernoulli (r, p(x)) and its models. ``GmBernoulliFilter(*, existence, mixture, transition,
/// survival, birth, position_dims, detection, clutter, likelihood=None, splitting=...,
/// reduction=..., exclusions=[])``, the core's ``BernoulliFilterOptions`` (Rust names; the
/// transition ``{"F", "Q"}``, the likelihood ``{"H", "R"}``). The particle filter's keys
/// (``particles``, ``birth_particles``, ``mcmc_moves``, ``seed``) are read and ignored, so that
/// one configuration makes both filters: ``GmBernoulliFilter(**airport_scenario().config)``.
///
/// ``predict()`` applies (40)–(49); ``update(reports)`` the imprecise update for a list of
/// region reports (``[]`` is an empty scan: the non-detection update, never skipped), and
/// ``update(measurements=Z)`` the vector update for an ``(m, d)`` array; each returns a
/// ``Result`` (``UpdateInfo``: ``delta``, ``split_components``). A call that fails leaves the
/// filter as it was. ``estimate()`` gives the MMSE estimate, ``estimate(radius=r0,
/// costs=...)`` the optimal point estimate of the loss (7) of paper 000. The filter pickles
/// (its configuration and the scans so far, replayed); one filter used from two threads at
/// once raises ``RuntimeError``.
#[pyclass(name = "GmBernoulliFilter", module = "fisst._fisst", frozen)]
pub struct GmBernoulliFilter {
    inner: Mutex<GmState>,
    options: BernoulliFilterOptions,
}

#[pymethods]
impl GmBernoulliFilter {
    #[new]
    #[pyo3(signature = (**config))]
    fn new(py: Python<'_>, config: Option<&Bound<'_, PyDict>>) -> PyResult<Self> {
        // The particle filter's keys of a configuration shared by both filters (as
        // `airport_scenario().config`): read as ParticleBernoulliFilter reads them, so that a
        // wrong kind of value is still an error, then ignored, as the npm package does.
        let (particle, rest) = split(py, config, &PARTICLE_KEYS)?;
        if !particle.is_empty() {
            if particle.get_item("seed")?.is_none_or(|s| s.is_none()) {
                particle.set_item("seed", 0)?;
            }
            let _: ParticleOptions = from_kwargs(py, "GmBernoulliFilter", Some(&particle))?;
        }
        let options: BernoulliFilterOptions = from_kwargs(py, "GmBernoulliFilter", Some(&rest))?;
        let filter = CoreGm::new(options.clone()).map_err(to_py)?;
        Ok(Self {
            inner: Mutex::new(GmState {
                filter,
                ops: Vec::new(),
            }),
            options,
        })
    }

    /// The prediction (40)–(49) of paper 001.
    fn predict(&self, py: Python<'_>) -> PyResult<()> {
        let mut s = busy(&self.inner, "GmBernoulliFilter")?;
        let f: &mut CoreGm = &mut s.filter;
        py.detach(|| f.predict()).map_err(to_py)?;
        s.ops.push(Op::Predict);
        Ok(())
    }

    /// The update with a scan: ``update(reports)`` (a list of regions) or
    /// ``update(measurements=Z)`` (an ``(m, d)`` array).
    #[pyo3(signature = (reports = None, *, measurements = None))]
    fn update<'py>(
        &self,
        py: Python<'py>,
        reports: Option<&Bound<'py, PyAny>>,
        measurements: Option<&Bound<'py, PyAny>>,
    ) -> PyResult<Bound<'py, PyAny>> {
        let scan = scan(reports, measurements)?;
        let mut s = busy(&self.inner, "GmBernoulliFilter")?;
        let s = &mut *s;
        update_with(py, &mut s.filter, &mut s.ops, scan)
    }

    /// The MMSE estimate (``estimate()``) or the optimal point estimate of the loss (7) of
    /// paper 000 (``estimate(radius=r0, costs=...)``): a ``Result`` (``FilterEstimate``).
    #[pyo3(signature = (*, radius = None, costs = None))]
    fn estimate<'py>(
        &self,
        py: Python<'py>,
        radius: Option<f64>,
        costs: Option<&Bound<'py, PyAny>>,
    ) -> PyResult<Bound<'py, PyAny>> {
        let o = estimate_options(radius, costs)?;
        let s = busy(&self.inner, "GmBernoulliFilter")?;
        let e = s.filter.estimate(&o).map_err(to_py)?;
        result(py, &e)
    }

    /// The existence probability r.
    #[getter]
    fn existence(&self) -> PyResult<f64> {
        Ok(busy(&self.inner, "GmBernoulliFilter")?.filter.existence())
    }

    /// The spatial density p(x), a list of ``{weight, mean, cov}`` results.
    #[getter]
    fn mixture<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        result(py, busy(&self.inner, "GmBernoulliFilter")?.filter.mixture())
    }

    fn __repr__(&self) -> PyResult<String> {
        let s = busy(&self.inner, "GmBernoulliFilter")?;
        Ok(format!(
            "GmBernoulliFilter(existence={}, components={}, scans={})",
            s.filter.existence(),
            s.filter.mixture().len(),
            s.ops.len()
        ))
    }

    fn __reduce__<'py>(slf: &Bound<'py, Self>) -> PyResult<Bound<'py, PyTuple>> {
        let py = slf.py();
        let this = slf.get();
        let s = busy(&this.inner, "GmBernoulliFilter")?;
        let options = pythonize::pythonize(py, &this.options)
            .map_err(|e| PyRuntimeError::new_err(e.to_string()))?;
        let restore = slf.get_type().getattr("_restore")?;
        PyTuple::new(
            py,
            [
                restore,
                (options, ops_to_py(py, &s.ops)?)
                    .into_pyobject(py)?
                    .into_any(),
            ],
        )
    }

    /// Rebuilds a pickled filter: the filter from its configuration, then its scans replayed.
    #[staticmethod]
    fn _restore(
        py: Python<'_>,
        options: Bound<'_, PyDict>,
        ops: Bound<'_, PyList>,
    ) -> PyResult<Self> {
        let f = Self::new(py, Some(&options))?;
        replay(py, ops, |py, op| match op {
            Replay::Predict => f.predict(py),
            Replay::Update(r) => f.update(py, Some(&r), None).map(|_| ()),
            Replay::Measurements(z) => f.update(py, None, Some(&z)).map(|_| ()),
        })?;
        Ok(f)
    }
}

enum Replay<'py> {
    Predict,
    Update(Bound<'py, PyAny>),
    Measurements(Bound<'py, PyAny>),
}

fn replay<'py>(
    py: Python<'py>,
    ops: Bound<'py, PyList>,
    mut apply: impl FnMut(Python<'py>, Replay<'py>) -> PyResult<()>,
) -> PyResult<()> {
    for op in ops.iter() {
        let op = op.cast::<PyTuple>()?;
        let kind: String = op.get_item(0)?.extract()?;
        match kind.as_str() {
            "predict" => apply(py, Replay::Predict)?,
            "update" => apply(py, Replay::Update(op.get_item(1)?))?,
            _ => apply(py, Replay::Measurements(op.get_item(1)?))?,
        }
    }
    Ok(())
}

struct PfState {
    filter: CorePf,
    ops: Vec<Op>,
}

/// The particle Bernoulli filter of paper 001 (Section V-C; systematic resampling, an MCMC
/// move): ``ParticleBernoulliFilter(*, <the GmBernoulliFilter configuration>, particles=5000,
/// birth_particles=None, mcmc_moves=1, seed=None)``; ``seed`` omitted draws one from the
/// operating system (read it back as ``filter.seed``). Methods as ``GmBernoulliFilter``;
/// ``particles`` is an ``(N, n)`` array and ``weights`` its weights.
#[pyclass(name = "ParticleBernoulliFilter", module = "fisst._fisst", frozen)]
pub struct ParticleBernoulliFilter {
    inner: Mutex<PfState>,
    options: BernoulliFilterOptions,
    particle_options: ParticleOptions,
}

const PARTICLE_KEYS: [&str; 4] = ["particles", "birth_particles", "mcmc_moves", "seed"];

#[pymethods]
impl ParticleBernoulliFilter {
    #[new]
    #[pyo3(signature = (**config))]
    fn new(py: Python<'_>, config: Option<&Bound<'_, PyDict>>) -> PyResult<Self> {
        let (particle, rest) = split(py, config, &PARTICLE_KEYS)?;
        let seed_given = particle.get_item("seed")?.is_some_and(|s| !s.is_none());
        if !seed_given {
            particle.set_item("seed", seed_or_entropy(None)?)?;
        }
        let particle_options: ParticleOptions =
            from_kwargs(py, "ParticleBernoulliFilter", Some(&particle))?;
        let options: BernoulliFilterOptions =
            from_kwargs(py, "ParticleBernoulliFilter", Some(&rest))?;
        let filter = py
            .detach(|| CorePf::new(options.clone(), particle_options))
            .map_err(to_py)?;
        Ok(Self {
            inner: Mutex::new(PfState {
                filter,
                ops: Vec::new(),
            }),
            options,
            particle_options,
        })
    }

    /// The prediction (particles moved by the transition, birth particles drawn).
    fn predict(&self, py: Python<'_>) -> PyResult<()> {
        let mut s = busy(&self.inner, "ParticleBernoulliFilter")?;
        let f: &mut CorePf = &mut s.filter;
        py.detach(|| f.predict());
        s.ops.push(Op::Predict);
        Ok(())
    }

    /// The update with a scan: ``update(reports)`` or ``update(measurements=Z)``.
    #[pyo3(signature = (reports = None, *, measurements = None))]
    fn update<'py>(
        &self,
        py: Python<'py>,
        reports: Option<&Bound<'py, PyAny>>,
        measurements: Option<&Bound<'py, PyAny>>,
    ) -> PyResult<Bound<'py, PyAny>> {
        let scan = scan(reports, measurements)?;
        let mut s = busy(&self.inner, "ParticleBernoulliFilter")?;
        let s = &mut *s;
        update_with(py, &mut s.filter, &mut s.ops, scan)
    }

    /// The MMSE estimate or the optimal point estimate (as ``GmBernoulliFilter.estimate``).
    #[pyo3(signature = (*, radius = None, costs = None))]
    fn estimate<'py>(
        &self,
        py: Python<'py>,
        radius: Option<f64>,
        costs: Option<&Bound<'py, PyAny>>,
    ) -> PyResult<Bound<'py, PyAny>> {
        let o = estimate_options(radius, costs)?;
        let s = busy(&self.inner, "ParticleBernoulliFilter")?;
        let f: &CorePf = &s.filter;
        let e = py.detach(|| f.estimate(&o)).map_err(to_py)?;
        result(py, &e)
    }

    /// The existence probability r.
    #[getter]
    fn existence(&self) -> PyResult<f64> {
        Ok(busy(&self.inner, "ParticleBernoulliFilter")?
            .filter
            .existence())
    }

    /// The particles, an ``(N, n)`` array.
    #[getter]
    fn particles<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        let s = busy(&self.inner, "ParticleBernoulliFilter")?;
        let (flat, d) = (s.filter.particles(), s.filter.dim());
        let n = flat.len().checked_div(d).unwrap_or(0);
        numpy::ToPyArray::to_pyarray(flat, py).call_method1("reshape", ((n, d),))
    }

    /// The particle weights, an ``(N,)`` array summing to 1.
    #[getter]
    fn weights<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        let s = busy(&self.inner, "ParticleBernoulliFilter")?;
        Ok(numpy::ToPyArray::to_pyarray(s.filter.weights(), py).into_any())
    }

    /// The seed of the filter's random stream (given, or drawn from the operating system).
    #[getter]
    fn seed(&self) -> u64 {
        self.particle_options.seed
    }

    fn __repr__(&self) -> PyResult<String> {
        let s = busy(&self.inner, "ParticleBernoulliFilter")?;
        Ok(format!(
            "ParticleBernoulliFilter(existence={}, particles={}, seed={}, scans={})",
            s.filter.existence(),
            s.filter.weights().len(),
            self.particle_options.seed,
            s.ops.len()
        ))
    }

    fn __reduce__<'py>(slf: &Bound<'py, Self>) -> PyResult<Bound<'py, PyTuple>> {
        let py = slf.py();
        let this = slf.get();
        let s = busy(&this.inner, "ParticleBernoulliFilter")?;
        let options = pythonize::pythonize(py, &this.options)
            .map_err(|e| PyRuntimeError::new_err(e.to_string()))?;
        let particle = pythonize::pythonize(py, &this.particle_options)
            .map_err(|e| PyRuntimeError::new_err(e.to_string()))?;
        let restore = slf.get_type().getattr("_restore")?;
        PyTuple::new(
            py,
            [
                restore,
                (options, particle, ops_to_py(py, &s.ops)?)
                    .into_pyobject(py)?
                    .into_any(),
            ],
        )
    }

    /// Rebuilds a pickled filter: the filter from its configuration and seed, then its scans
    /// replayed.
    #[staticmethod]
    fn _restore(
        py: Python<'_>,
        options: Bound<'_, PyDict>,
        particle: Bound<'_, PyDict>,
        ops: Bound<'_, PyList>,
    ) -> PyResult<Self> {
        options.update(particle.as_mapping())?;
        let f = Self::new(py, Some(&options))?;
        replay(py, ops, |py, op| match op {
            Replay::Predict => f.predict(py),
            Replay::Update(r) => f.update(py, Some(&r), None).map(|_| ()),
            Replay::Measurements(z) => f.update(py, None, Some(&z)).map(|_| ()),
        })?;
        Ok(f)
    }
}

/// The GM Bernoulli prediction (40)–(49) of paper 001 in one call: the Bernoulli
/// ``existence``, ``mixture`` and the prediction model (``transition`` ``{"F", "Q"}``,
/// ``survival``, ``birth`` ``{"probability", "mixture"}``). Returns a ``Result``
/// (``existence``, ``mixture``).
#[pyfunction]
#[pyo3(
    signature = (**options),
    text_signature = "(*, existence, mixture, transition, survival=0.99, birth=None)"
)]
pub fn gm_bernoulli_predict<'py>(
    py: Python<'py>,
    options: Option<&Bound<'py, PyDict>>,
) -> PyResult<Bound<'py, PyAny>> {
    let (state, rest) = split(py, options, &["existence", "mixture"])?;
    let state: GmBernoulli = from_kwargs(py, "gm_bernoulli_predict", Some(&state))?;
    let config: PredictOptions = from_kwargs(py, "gm_bernoulli_predict", Some(&rest))?;
    let out = py.detach(|| core_predict(&state, &config)).map_err(to_py)?;
    result(py, &out)
}

/// The GM Bernoulli update of paper 001 in one call: the Bernoulli ``existence``,
/// ``mixture``, the scan (``reports``, a list of regions, or ``measurements``, an ``(m, d)``
/// array with ``likelihood`` ``{"H", "R"}``) and the update model (``position_dims``,
/// ``detection``, ``clutter``, ``splitting``, ``reduction``, ``exclusions``). Returns a
/// ``Result`` (``GmBernoulliUpdate``: ``existence``, ``mixture``, ``delta``,
/// ``split_components``).
#[pyfunction]
#[pyo3(
    signature = (**options),
    text_signature = "(*, existence, mixture, reports=None, measurements=None, likelihood=None, position_dims=2, detection, clutter, splitting=..., reduction=..., exclusions=[])"
)]
pub fn gm_bernoulli_update<'py>(
    py: Python<'py>,
    options: Option<&Bound<'py, PyDict>>,
) -> PyResult<Bound<'py, PyAny>> {
    let (state, rest) = split(py, options, &["existence", "mixture"])?;
    let (scan_args, rest) = split(py, Some(&rest), &["reports", "measurements", "likelihood"])?;
    let state: GmBernoulli = from_kwargs(py, "gm_bernoulli_update", Some(&state))?;
    let config: UpdateOptions = from_kwargs(py, "gm_bernoulli_update", Some(&rest))?;
    let reports = scan_args.get_item("reports")?;
    let measurements = scan_args.get_item("measurements")?;
    let out = match scan(reports.as_ref(), measurements.as_ref())? {
        Scan::Reports(r) => py
            .detach(|| core_update(&state, &r, &config))
            .map_err(to_py)?,
        Scan::Measurements(z, n, d) => {
            let Some(l) = scan_args.get_item("likelihood")? else {
                return Err(PyTypeError::new_err(
                    "gm_bernoulli_update() with measurements needs likelihood={'H': ..., 'R': ...}",
                ));
            };
            let likelihood: LinearGaussianLikelihood = from_value(&l, "likelihood")?;
            py.detach(|| gm_bernoulli_update_vector(&state, &rows(&z, n, d), &likelihood, &config))
                .map_err(to_py)?
        }
    };
    result(py, &out)
}
