//! The Python package `fisst`: the compiled module `fisst._fisst`. Each export converts its
//! arguments (numpy arrays, keyword arguments), releases the GIL while the core works, and
//! converts the core's result back through one mechanism (`convert::result`): a thin front,
//! no numerics here.

use pyo3::prelude::*;

/// mimalloc as the extension's allocator: allocation does not change a result, but glibc's
/// malloc in a host process that has freed large blocks (a SciPy or numpy call before) maps
/// and unmaps a metric's working memory on every call (GOSPA at n = 1,000 took 234 µs
/// instead of 159 µs for the next twenty calls after SciPy's).
#[global_allocator]
static ALLOCATOR: mimalloc::MiMalloc = mimalloc::MiMalloc;

mod bernoulli;
mod bounds;
mod campaign;
mod control;
mod convert;
mod filters;
mod fov;
mod metrics;
mod mixture;
mod multi_bernoulli;
mod names;
mod options;
mod result;
mod ser;
mod splitting;

/// The compiled part of the Python package `fisst` (import `fisst`, not this module).
#[pymodule]
fn _fisst(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add("__version__", env!("CARGO_PKG_VERSION"))?;
    m.add_class::<result::FisstResult>()?;
    pyo3::types::PyMapping::register::<result::FisstResult>(m.py())?;
    m.add_function(wrap_pyfunction!(metrics::gospa, m)?)?;
    m.add_function(wrap_pyfunction!(metrics::ospa, m)?)?;
    m.add_function(wrap_pyfunction!(metrics::uospa, m)?)?;
    m.add_function(wrap_pyfunction!(metrics::gospa_series, m)?)?;
    m.add_function(wrap_pyfunction!(metrics::ospa_series, m)?)?;
    m.add_function(wrap_pyfunction!(metrics::linear_assignment, m)?)?;
    m.add_function(wrap_pyfunction!(
        multi_bernoulli::multi_bernoulli_cardinality,
        m
    )?)?;
    m.add_function(wrap_pyfunction!(
        multi_bernoulli::multi_bernoulli_leave_one_out,
        m
    )?)?;
    m.add_function(wrap_pyfunction!(multi_bernoulli::mb_optimal_estimate, m)?)?;
    m.add_function(wrap_pyfunction!(multi_bernoulli::mb_mean_square_error, m)?)?;
    m.add_function(wrap_pyfunction!(
        multi_bernoulli::mb_alternative_estimate,
        m
    )?)?;
    m.add_function(wrap_pyfunction!(multi_bernoulli::mb_decision_map, m)?)?;
    m.add_function(wrap_pyfunction!(
        multi_bernoulli::mb_identical_component_counts,
        m
    )?)?;
    m.add_function(wrap_pyfunction!(bernoulli::bernoulli_loss_curve, m)?)?;
    m.add_function(wrap_pyfunction!(bernoulli::bernoulli_threshold_curve, m)?)?;
    m.add_function(wrap_pyfunction!(bernoulli::probability_outside_ball, m)?)?;
    m.add_function(wrap_pyfunction!(mixture::reduce_mixture, m)?)?;
    m.add_function(wrap_pyfunction!(bounds::jde_bound_no_clutter, m)?)?;
    m.add_function(wrap_pyfunction!(bounds::gaussian_fisher_information, m)?)?;
    m.add_function(wrap_pyfunction!(bounds::jde_sequential_bound, m)?)?;
    m.add_function(wrap_pyfunction!(bounds::jde_example2, m)?)?;
    m.add_function(wrap_pyfunction!(bounds::jde_example2_regularity, m)?)?;
    m.add_function(wrap_pyfunction!(bounds::jde_bound, m)?)?;
    m.add_function(wrap_pyfunction!(bounds::jde_monte_carlo, m)?)?;
    m.add_class::<filters::GmBernoulliFilter>()?;
    m.add_class::<filters::ParticleBernoulliFilter>()?;
    m.add_function(wrap_pyfunction!(filters::gm_bernoulli_predict, m)?)?;
    m.add_function(wrap_pyfunction!(filters::gm_bernoulli_update, m)?)?;
    m.add_function(wrap_pyfunction!(control::multi_object_likelihood, m)?)?;
    m.add_class::<control::SensorControlRun>()?;
    m.add_function(wrap_pyfunction!(control::compare_schemes, m)?)?;
    // fisst.campaign's compiled half (private names)
    m.add_function(wrap_pyfunction!(campaign::_campaign_run_seeds, m)?)?;
    m.add_function(wrap_pyfunction!(campaign::_campaign_control_check, m)?)?;
    m.add_function(wrap_pyfunction!(campaign::_campaign_control_run, m)?)?;
    m.add_function(wrap_pyfunction!(campaign::_campaign_airport_check, m)?)?;
    m.add_function(wrap_pyfunction!(campaign::_campaign_airport_run, m)?)?;
    m.add_function(wrap_pyfunction!(campaign::_campaign_bounds_check, m)?)?;
    m.add_function(wrap_pyfunction!(campaign::_campaign_bounds_run, m)?)?;
    // Field of view (paper 001, Sections VI–VII)
    m.add_function(wrap_pyfunction!(fov::fov_cardinality, m)?)?;
    m.add_function(wrap_pyfunction!(fov::fov_variance_map, m)?)?;
    m.add_function(wrap_pyfunction!(fov::placement_scene, m)?)?;
    m.add_function(wrap_pyfunction!(fov::mixture_density_grid, m)?)?;
    // paper 000's point estimates (bernoulli_estimate, mmuc_estimate, multi_bernoulli_point_estimate)
    m.add_function(wrap_pyfunction!(bernoulli::bernoulli_estimate, m)?)?;
    m.add_function(wrap_pyfunction!(bernoulli::mmuc_estimate, m)?)?;
    m.add_function(wrap_pyfunction!(
        bernoulli::multi_bernoulli_point_estimate,
        m
    )?)?;
    // splitting and the worked examples of paper 001
    m.add_function(wrap_pyfunction!(splitting::split_library, m)?)?;
    m.add_function(wrap_pyfunction!(splitting::split_for_regions, m)?)?;
    m.add_function(wrap_pyfunction!(
        splitting::negative_information_scenario,
        m
    )?)?;
    m.add_function(wrap_pyfunction!(splitting::airport_scenario, m)?)?;
    Ok(())
}
