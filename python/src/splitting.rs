//! Gaussian splitting along region boundaries and the worked examples of paper 001 (LeGrand &
//! Ferrari, "Split Happens! Imprecise and negative information in Gaussian mixture random
//! finite set filtering"): the core's `fisst::splitting` requests and `fisst::sim::airport`.

use std::sync::OnceLock;

use pyo3::prelude::*;
use pyo3::types::PyDict;

use crate::convert::{result, seed_or_entropy, to_py};
use crate::options::from_kwargs;
use fisst::sim::airport::{AirportScenarioOptions, AirportScenarioReport};
use fisst::splitting::{
    NegativeInformationOptions, NegativeInformationReport, SplitForRegionsOptions,
    SplitLibraryOptions, SplitLibraryReport, split_for_regions_report,
};

/// The optimal R-component split of N(0, 1) of eqs. (13)–(14) of paper 001 (LeGrand &
/// Ferrari, "Split Happens! Imprecise and negative information in Gaussian mixture random
/// finite set filtering"): ``components`` R in [2, 16], ``lambda_`` the weight λ in [1e-6, 10]
/// of the σ̃² penalty of the objective J (13), ``spacing`` ``"equal"`` (symmetric, equally
/// spaced means: Table I's family) or ``"free"`` (symmetric free means, a lower J). Returns a
/// ``Result`` (``SplitLibraryReport``): ``weights`` and ``means`` (arrays), ``sigma``,
/// ``objective`` (J at the optimum) and ``variance`` (σ̃² + Σ w m²). ``components=4,
/// lambda_=0.001`` is Table I verbatim (``lambda_``: ``lambda`` is a Python keyword).
#[pyfunction]
#[pyo3(signature = (**options), text_signature = "(*, components, lambda_, spacing='equal')")]
pub fn split_library<'py>(
    py: Python<'py>,
    options: Option<&Bound<'py, PyDict>>,
) -> PyResult<Bound<'py, PyAny>> {
    let o: SplitLibraryOptions = from_kwargs(py, "split_library", options)?;
    let lib = py.detach(|| o.library()).map_err(to_py)?;
    result(py, &SplitLibraryReport::from(&lib))
}

/// Algorithm 2 (Algorithm 1 for one region) of paper 001 (LeGrand & Ferrari, "Split Happens!
/// Imprecise and negative information in Gaussian mixture random finite set filtering"):
/// recursively splits the components of ``mixture`` (a list of ``{"weight", "mean", "cov"}``)
/// that straddle a boundary of any of ``regions`` (1 to 32 regions: ``{"box": {"min",
/// "max"}}``, ``{"ball": {"center", "radius"}}``, ``{"polygon": {"vertices"}}``, ``{"union":
/// [...]}``, ``{"intersection": [...]}``, ``{"complement": region}``) with the split library
/// (``components`` R, ``lambda_``, ``spacing``, eqs. (13)–(14)) along the direction (26),
/// then the mean-based partition (11)–(12) for the first region. ``position_dims`` n_s (the
/// first state components are the position), ``min_weight`` w_min, ``grid_bound`` ζ and
/// ``grid_points`` N_g of the collocation grid (20)–(22), ``max_depth`` and
/// ``max_components`` cap the recursion. Returns a ``Result`` (``SplitForRegionsReport``):
/// ``mixture``, ``inside``, ``outside``, ``inside_mask`` (bool array: component i's mean is in
/// the first region), ``exact_inside`` (the exact mass (8), or None when too costly),
/// ``depth``, ``splits`` and ``stop`` (None, ``"maxDepth"`` or ``"maxComponents"``).
#[pyfunction]
#[pyo3(
    signature = (**options),
    text_signature = "(*, mixture, regions, position_dims=2, min_weight=0.01, components=3, \
                      lambda_=0.001, spacing='equal', grid_bound=2.0, grid_points=15, \
                      max_depth=16, max_components=10000)"
)]
pub fn split_for_regions<'py>(
    py: Python<'py>,
    options: Option<&Bound<'py, PyDict>>,
) -> PyResult<Bound<'py, PyAny>> {
    let o: SplitForRegionsOptions = from_kwargs(py, "split_for_regions", options)?;
    let report = py
        .detach(|| {
            o.validate()?;
            let library = o.library_options().library()?;
            split_for_regions_report(&o, &library)
        })
        .map_err(to_py)?;
    result(py, &report)
}

/// The Fig. 5 scenario, computed once (it is deterministic).
static FIG5: OnceLock<NegativeInformationReport> = OnceLock::new();

/// The negative-information example of Fig. 5 (Section IV-G) of paper 001 (LeGrand &
/// Ferrari, "Split Happens! Imprecise and negative information in Gaussian mixture random
/// finite set filtering"): a constant-velocity object crossing a square field of view with
/// three non-detections (p_D = 1), each step predicted, split by Algorithm 1 (w_min = 0.01,
/// R = 3, λ = 0.001) and updated by (57)–(58). Without ``step`` returns a ``Result``
/// (``NegativeInformationReport``): ``fov``, ``initial`` and ``steps``; with ``step`` (1–3)
/// the one step (``NegativeInformationStepReport``): ``step``, ``predicted``, ``split``,
/// ``posterior``, ``non_detection_prob``, ``predicted_inside``, ``posterior_inside``,
/// ``depth``, ``splits``.
#[pyfunction]
#[pyo3(signature = (**options), text_signature = "(*, step=None)")]
pub fn negative_information_scenario<'py>(
    py: Python<'py>,
    options: Option<&Bound<'py, PyDict>>,
) -> PyResult<Bound<'py, PyAny>> {
    let o: NegativeInformationOptions = from_kwargs(py, "negative_information_scenario", options)?;
    o.validate().map_err(to_py)?;
    let report = match FIG5.get() {
        Some(r) => r,
        None => {
            let r = py.detach(NegativeInformationReport::fig5).map_err(to_py)?;
            FIG5.get_or_init(|| r)
        }
    };
    let out = o.select(report).map_err(to_py)?;
    result(py, &out)
}

/// The airport example of Section V-C (Figs. 6–8) of paper 001 (LeGrand & Ferrari, "Split
/// Happens! Imprecise and negative information in Gaussian mixture random finite set
/// filtering"): a seeded walk through a concourse with ten anchors and four exclusion
/// rectangles, and the natural-language reports "near anchor a" (p_D = 0.9 in the anchors'
/// discs (64), Poisson clutter λ_c = 0.25). ``seed`` omitted draws one from the operating
/// system (reported back as ``seed``); ``steps`` report times (default 60, at most 2000).
/// Returns a ``Result`` (``AirportScenarioReport``): ``anchors``, ``exclusions``,
/// ``concourse``, ``fov``, ``dt``, ``config`` (for ``GmBernoulliFilter`` and
/// ``ParticleBernoulliFilter``), ``truth``, ``reports``, ``true_reports``, ``in_fov`` and
/// ``seed``. Report ``a`` at step k is ``{"ball": {"center": anchors[a].position, "radius":
/// anchors[a].radius}}``.
#[pyfunction]
#[pyo3(signature = (**options), text_signature = "(*, seed=None, steps=60)")]
pub fn airport_scenario<'py>(
    py: Python<'py>,
    options: Option<&Bound<'py, PyDict>>,
) -> PyResult<Bound<'py, PyAny>> {
    let o: AirportScenarioOptions = from_kwargs(py, "airport_scenario", options)?;
    let seed = seed_or_entropy(o.seed)?;
    let report = py
        .detach(|| AirportScenarioReport::new(seed, o.steps))
        .map_err(to_py)?;
    result(py, &report)
}
