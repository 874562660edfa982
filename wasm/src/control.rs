//! Sensor control with the SMC multi-object filter (paper 004, Ristic & Vo):
//! `multiObjectLikelihood` (eq. (20)). The shapes are also listed in
//! `core/src/control/JS_SHAPES.md`.

use std::format;
use std::vec::Vec;

use serde::{Deserialize, Serialize};
use tsify::Tsify;
use wasm_bindgen::prelude::*;

use crate::boundary::{JsResult, OrThrow, range_error, read, write};
use crate::types::Numbers;

/// At most this many objects (rows of `likelihoods`).
const MAX_OBJECTS: usize = 64;
/// At most this many measurements (entries of `clutterDensity`).
const MAX_MEASUREMENTS: usize = 1000;
/// At most this many on the smaller side (the dynamic programme has 2^k states).
const MAX_SMALLER: usize = 12;

/// Options of `multiObjectLikelihood`.
#[derive(Deserialize, Tsify)]
#[serde(rename_all = "camelCase")]
pub struct MultiObjectLikelihoodOptions {
    /// `likelihoods[i][j]` = g(z_j | x_i) ≥ 0, one row of m numbers per object of the
    /// particle (`[]` for n = 0). At most 64 objects, and min(n, m) ≤ 12.
    pub likelihoods: Vec<Numbers>,
    /// p_D, in [0, 1].
    pub detection_probability: f64,
    /// λ ≥ 0, the mean number of clutter measurements.
    pub clutter_rate: f64,
    /// `clutterDensity[j]` = c(z_j) ≥ 0, one per measurement (m ≤ 1000), so that
    /// f_c(Z) = e^{−λ} Π_j λ c(z_j).
    pub clutter_density: Numbers,
}

/// Result of `multiObjectLikelihood`.
#[derive(Serialize, Tsify)]
#[serde(rename_all = "camelCase")]
pub struct MultiObjectLikelihoodResult {
    /// ln g(Z | X) of (20); `-Infinity` when the likelihood is zero (never NaN).
    pub log_likelihood: f64,
}

/// The multi-object likelihood (20) of paper 004 for one particle, in log space, summing over
/// the associations θ by dynamic programming over subsets (exact; no enumeration). Options
/// `{ likelihoods, detectionProbability, clutterRate, clutterDensity }`; returns
/// `{ logLikelihood }`.
#[wasm_bindgen(
    js_name = multiObjectLikelihood,
    unchecked_return_type = "MultiObjectLikelihoodResult"
)]
pub fn multi_object_likelihood(
    #[wasm_bindgen(unchecked_param_type = "MultiObjectLikelihoodOptions")] options: JsValue,
) -> JsResult<JsValue> {
    let o: MultiObjectLikelihoodOptions = read(options, "options")?;
    let n = o.likelihoods.len();
    let m = o.clutter_density.0.len();
    if n > MAX_OBJECTS {
        return Err(range_error(format!(
            "options.likelihoods: at most {MAX_OBJECTS} objects are supported, got {n}"
        )));
    }
    if m > MAX_MEASUREMENTS {
        return Err(range_error(format!(
            "options.clutterDensity: at most {MAX_MEASUREMENTS} measurements are supported, got {m}"
        )));
    }
    if n.min(m) > MAX_SMALLER {
        return Err(range_error(format!(
            "options.likelihoods: min(objects, measurements) must be at most {MAX_SMALLER}, got {}",
            n.min(m)
        )));
    }
    let rows: Vec<Vec<f64>> = o.likelihoods.into_iter().map(|r| r.0).collect();
    let log_likelihood = fisst::smc::ln_likelihood(
        &rows,
        o.detection_probability,
        o.clutter_rate,
        &o.clutter_density.0,
    )
    .or_throw_in("options")?;
    write(&MultiObjectLikelihoodResult { log_likelihood })
}
