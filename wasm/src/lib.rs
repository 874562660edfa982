//! WebAssembly bindings of [`fisst`]: the npm package `fisst`.
//!
//! Thin conversions only: every function reads its JavaScript arguments into
//! `#[derive(Deserialize)]` option types ([`de`], with errors that name the full path of the
//! offending field), calls `fisst` once, and writes a `#[derive(Serialize)]` result back with
//! serde-wasm-bindgen ([`boundary`]). The TypeScript declarations of every option and result
//! are generated from the same types by tsify, doc comments included. Bad input throws a
//! `TypeError` (wrong type, missing field, unknown key) or a `RangeError` (bad value, with the
//! Rust error's message); nothing panics across the boundary.
//!
//! ```js
//! // Node ≥ 20: no init call
//! import * as fisst from 'fisst';
//! fisst.gospa([[0, 0]], [[0, 1]], { c: 2 }).distance; // 1
//! // Browser: one await, then the same functions
//! import init, * as fisst from 'fisst';
//! await init();
//! ```

// A build of some parts only leaves shared types and helpers unused; the full build (the
// default, which clippy checks with `-D warnings`) uses every one.
#![cfg_attr(
    not(all(
        feature = "bernoulli",
        feature = "splitting",
        feature = "filters",
        feature = "bounds",
        feature = "metrics",
        feature = "control"
    )),
    allow(dead_code, unused_imports)
)]

pub mod boundary;
pub mod de;
pub mod names;
pub mod types;

// One module of bindings per part of the npm package (a Cargo feature each, all on by default;
// `scripts/build-pkg.sh` builds one wasm module per part, see the README's "Parts").
#[cfg(any(feature = "bernoulli", feature = "filters"))]
mod bernoulli;
#[cfg(feature = "filters")]
mod bernoulli_filters;
#[cfg(feature = "bounds")]
mod bounds;
#[cfg(feature = "control")]
mod control;
#[cfg(any(feature = "bernoulli", feature = "splitting"))]
mod fov;
#[cfg(feature = "metrics")]
mod metrics;
#[cfg(feature = "metrics")]
mod multi_bernoulli;
#[cfg(feature = "splitting")]
mod splitting;

#[cfg(feature = "bernoulli")]
pub use bernoulli::{
    bernoulli_estimate, bernoulli_loss_curve, bernoulli_threshold_curve, mmuc_estimate,
    multi_bernoulli_point_estimate, probability_outside_ball,
};
#[cfg(feature = "filters")]
pub use bernoulli_filters::{
    GmBernoulliFilterJs, ParticleBernoulliFilterJs, airport_scenario, gm_bernoulli_predict,
    gm_bernoulli_update,
};
#[cfg(feature = "bounds")]
pub use bounds::{
    gaussian_fisher_information, jde_bound, jde_bound_no_clutter, jde_example2,
    jde_example2_regularity, jde_sequential_bound,
};
#[cfg(feature = "control")]
pub use control::{SensorControlRunJs, compare_schemes, multi_object_likelihood};
#[cfg(any(feature = "bernoulli", feature = "splitting"))]
pub use fov::mixture_density_grid_js;
#[cfg(feature = "splitting")]
pub use fov::{fov_cardinality_js, fov_variance_map, placement_scene_js};
#[cfg(feature = "metrics")]
pub use metrics::{gospa, gospa_series, linear_assignment, ospa, ospa_series, uospa};
#[cfg(feature = "metrics")]
pub use multi_bernoulli::{
    mb_alternative_estimate, mb_decision_map, mb_identical_component_counts, mb_mean_square_error,
    mb_optimal_estimate, multi_bernoulli_cardinality_js, multi_bernoulli_leave_one_out,
};
#[cfg(feature = "splitting")]
pub use splitting::{
    negative_information_scenario_js, reduce_mixture_js, split_for_regions_js, split_library_js,
};

use wasm_bindgen::prelude::*;

/// The package version (the Cargo version of `fisst-wasm`).
#[wasm_bindgen]
pub fn version() -> String {
    env!("CARGO_PKG_VERSION").into()
}
