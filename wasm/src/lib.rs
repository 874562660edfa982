//! WebAssembly bindings of [`fisst`]: the npm package `fisst`.
//!
//! Thin conversions only: every function converts its JavaScript arguments (with errors that
//! name the offending field), calls `fisst` once, and converts the result back. Bad input
//! throws a `TypeError` (wrong type, missing field) or a `RangeError` (bad value, with the
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

mod bernoulli;
mod convert;
mod fov;
mod metrics;
mod multi_bernoulli;
mod splitting;

pub use bernoulli::{
    bernoulli_estimate, bernoulli_loss_curve, bernoulli_threshold_curve, mmuc_estimate,
    multi_bernoulli_point_estimate, probability_outside_ball,
};
pub use fov::{fov_cardinality_js, fov_variance_map, mixture_density_grid_js, placement_scene_js};
pub use metrics::{gospa, linear_assignment, ospa, uospa};
pub use multi_bernoulli::{
    mb_alternative_estimate, mb_decision_map, mb_identical_component_counts, mb_mean_square_error,
    mb_optimal_estimate, multi_bernoulli_cardinality_js, multi_bernoulli_leave_one_out,
};
pub use splitting::{
    negative_information_scenario_js, reduce_mixture_js, split_for_regions_js, split_library_js,
};

use wasm_bindgen::prelude::*;

#[wasm_bindgen(typescript_custom_section)]
const TS_TYPES: &'static str = r#"
/** A point: one number per dimension; every point of a call has the same dimension. */
export type Point = number[] | Float64Array;

/** Options of `gospa`: cut-off `c` > 0, order `p` ≥ 1 (default 2), `alpha` in (0, 2] (default 2). */
export interface GospaOptions { c: number; p?: number; alpha?: number; }

/**
 * Result of `gospa`. `localisation` is Σ d^p over the assigned pairs (not rooted); `missed` and
 * `falseTargets` count unassigned truth and estimate points; `assignment` lists
 * `[truthIndex, estimateIndex]` pairs. Only `distance` is defined when `alpha` ≠ 2.
 */
export interface GospaResult {
  distance: number;
  localisation?: number;
  missed?: number;
  falseTargets?: number;
  assignment?: [number, number][];
}

/** Options of `ospa` and `uospa`: cut-off `c` > 0, order `p` ≥ 1 (default 2). */
export interface OspaOptions { c: number; p?: number; }

/** Result of `ospa`: rooted parts with distance^p = localisation^p + cardinality^p. */
export interface OspaResult {
  distance: number;
  localisation: number;
  cardinality: number;
  assignment: [number, number][];
}

export type SetMetricName = 'gospa' | 'ospa' | 'uospa';

export interface MbOptimalEstimateOptions {
  /** Existence probability of each far-apart component. */
  existence: number[] | Float64Array;
  metric: SetMetricName;
  /** Cut-off (default 1). */
  c?: number;
  /** Order (default 2). The error minimised is E[d^p], the mean square error for p = 2. */
  p?: number;
  /** GOSPA's alpha (default 2). */
  alpha?: number;
}

export interface MbOptimalEstimateResult { report: boolean[]; meanSquareError: number; }

export interface MbMeanSquareErrorOptions extends MbOptimalEstimateOptions { report: boolean[]; }

export interface MbAlternativeEstimateOptions {
  existence: number[] | Float64Array;
  method: 'mam' | 'jom' | 'map-cardinality';
  lnPeak?: number[];
  lnC?: number;
}
"#;

/// The package version (the Cargo version of `fisst-wasm`).
#[wasm_bindgen]
pub fn version() -> String {
    env!("CARGO_PKG_VERSION").into()
}
