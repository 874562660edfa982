//! `gospa`, `ospa`, `uospa`, `linearAssignment`.

use serde::{Deserialize, Serialize};
use tsify::Tsify;
use wasm_bindgen::prelude::*;

use crate::boundary::{JsResult, OrThrow, read, write};
use crate::names::Renamed;
use crate::types::PointSet;
use fisst::metrics::{Gospa, Ospa};

fn two() -> f64 {
    2.0
}

/// Options of `gospa`.
#[derive(Deserialize, Tsify)]
pub struct GospaOptions {
    /// The cut-off c > 0, in the units of the points.
    pub c: f64,
    /// The order p ≥ 1 (finite; default 2).
    #[serde(default = "two")]
    pub p: f64,
    /// α in (0, 2], the weight of cardinality mismatch (default 2; the decomposition into
    /// localisation, missed and false targets exists for α = 2 only).
    #[serde(default = "two")]
    pub alpha: f64,
}

/// Result of `gospa`. `localisation` is Σ d^p over the assigned pairs (not rooted); `missed`
/// and `falseTargets` count unassigned truth and estimate points; `assignment` lists
/// `[truthIndex, estimateIndex]` pairs. Only `distance` is present when `alpha` ≠ 2.
#[derive(Serialize, Tsify)]
#[serde(rename_all = "camelCase")]
pub struct GospaResult {
    /// The GOSPA distance.
    pub distance: f64,
    /// Σ d^p over the assigned pairs (α = 2 only).
    #[serde(skip_serializing_if = "Option::is_none")]
    #[tsify(optional)]
    pub localisation: Option<f64>,
    /// Unassigned truth points (α = 2 only).
    #[serde(skip_serializing_if = "Option::is_none")]
    #[tsify(optional)]
    pub missed: Option<usize>,
    /// Unassigned estimate points (α = 2 only).
    #[serde(skip_serializing_if = "Option::is_none")]
    #[tsify(optional)]
    pub false_targets: Option<usize>,
    /// `[truthIndex, estimateIndex]` pairs of the optimal assignment (α = 2 only).
    #[serde(skip_serializing_if = "Option::is_none")]
    #[tsify(optional)]
    pub assignment: Option<Vec<(usize, usize)>>,
}

/// Options of `ospa` and `uospa`.
#[derive(Deserialize, Tsify)]
pub struct OspaOptions {
    /// The cut-off c > 0, in the units of the points.
    pub c: f64,
    /// The order p ≥ 1 (finite; default 2).
    #[serde(default = "two")]
    pub p: f64,
}

/// Result of `ospa`: rooted parts with distance^p = localisation^p + cardinality^p.
#[derive(Serialize, Tsify)]
pub struct OspaResult {
    /// The OSPA distance, in [0, c].
    pub distance: f64,
    /// The localisation part (rooted).
    pub localisation: f64,
    /// The cardinality part (rooted).
    pub cardinality: f64,
    /// `[truthIndex, estimateIndex]` pairs of the optimal permutation.
    pub assignment: Vec<(usize, usize)>,
}

/// Result of `uospa`.
#[derive(Serialize, Tsify)]
pub struct UospaResult {
    /// The UOSPA distance (GOSPA with α = 1).
    pub distance: f64,
}

/// Options of `gospaSeries`: a whole scenario, one truth set and one estimate set per time
/// step.
#[derive(Deserialize, Tsify)]
pub struct GospaSeriesOptions {
    /// The truth at each step (arrays of points of one common dimension; empty sets allowed).
    pub truths: Vec<PointSet>,
    /// The estimate at each step (as many steps as `truths`).
    pub estimates: Vec<PointSet>,
    /// The cut-off c > 0, in the units of the points.
    pub c: f64,
    /// The order p ≥ 1 (finite; default 2).
    #[serde(default = "two")]
    pub p: f64,
    /// α in (0, 2] (default 2; the decomposition exists for α = 2 only).
    #[serde(default = "two")]
    pub alpha: f64,
}

/// Result of `gospaSeries`: per-step values (arrays indexed by step) and their means. The
/// decomposition (`localisation`, `missed`, `falseTargets` and their means) is present for
/// α = 2 only.
#[derive(Serialize, Tsify)]
#[serde(rename_all = "camelCase")]
pub struct GospaSeriesResult {
    /// GOSPA at each step.
    pub distance: Vec<f64>,
    /// The mean of `distance` (0 for no steps).
    pub mean_distance: f64,
    /// Σ d^p over the assigned pairs at each step (α = 2 only).
    #[serde(skip_serializing_if = "Option::is_none")]
    #[tsify(optional)]
    pub localisation: Option<Vec<f64>>,
    /// Unassigned truths at each step (α = 2 only).
    #[serde(skip_serializing_if = "Option::is_none")]
    #[tsify(optional)]
    pub missed: Option<Vec<usize>>,
    /// Unassigned estimates at each step (α = 2 only).
    #[serde(skip_serializing_if = "Option::is_none")]
    #[tsify(optional)]
    pub false_targets: Option<Vec<usize>>,
    /// The mean of `localisation` (α = 2 only).
    #[serde(skip_serializing_if = "Option::is_none")]
    #[tsify(optional)]
    pub mean_localisation: Option<f64>,
    /// The mean of `missed` (α = 2 only).
    #[serde(skip_serializing_if = "Option::is_none")]
    #[tsify(optional)]
    pub mean_missed: Option<f64>,
    /// The mean of `falseTargets` (α = 2 only).
    #[serde(skip_serializing_if = "Option::is_none")]
    #[tsify(optional)]
    pub mean_false_targets: Option<f64>,
}

/// Options of `ospaSeries`.
#[derive(Deserialize, Tsify)]
pub struct OspaSeriesOptions {
    /// The truth at each step.
    pub truths: Vec<PointSet>,
    /// The estimate at each step (as many steps as `truths`).
    pub estimates: Vec<PointSet>,
    /// The cut-off c > 0.
    pub c: f64,
    /// The order p ≥ 1 (finite; default 2).
    #[serde(default = "two")]
    pub p: f64,
}

/// Result of `ospaSeries`: OSPA and its rooted parts at each step (distance^p =
/// localisation^p + cardinality^p step by step), and the means of each over the steps.
#[derive(Serialize, Tsify)]
#[serde(rename_all = "camelCase")]
pub struct OspaSeriesResult {
    /// OSPA at each step, eq. (24) of `004_…`.
    pub distance: Vec<f64>,
    /// The localisation part at each step, eq. (26).
    pub localisation: Vec<f64>,
    /// The cardinality part at each step, eq. (25).
    pub cardinality: Vec<f64>,
    /// The mean of `distance` (0 for no steps).
    pub mean_distance: f64,
    /// The mean of `localisation`.
    pub mean_localisation: f64,
    /// The mean of `cardinality`.
    pub mean_cardinality: f64,
}

/// A cost matrix: an array of rows of equal length.
#[derive(Deserialize, Tsify)]
#[tsify(type = "(number[] | Float64Array)[]")]
pub struct CostMatrix(pub Vec<Vec<f64>>);

// `linearAssignment` returns the core's own `fisst::math::Assignment` (its TypeScript is
// generated by build.rs from the core's source); the contract's name for it stays.
#[wasm_bindgen(typescript_custom_section)]
const LINEAR_ASSIGNMENT_RESULT: &str = r#"
/**
 * Result of `linearAssignment`: the core's `Assignment`.
 */
export type LinearAssignmentResult = Assignment;
"#;

/// GOSPA between two point sets (García-Fernández & Svensson 2019, Def. 2 and Prop. 3).
///
/// `truth` and `estimate` are arrays of points, each an array of numbers of one common
/// dimension (empty arrays allowed). `options.c` (> 0) is the cut-off, `options.p` (≥ 1,
/// default 2) the order, `options.alpha` (in (0, 2], default 2) the cardinality-mismatch
/// weight. Returns `{ distance, localisation, missed, falseTargets, assignment }`; for
/// `alpha ≠ 2` only `distance` is defined (the decomposition exists for α = 2 only).
#[wasm_bindgen(unchecked_return_type = "GospaResult")]
pub fn gospa(
    #[wasm_bindgen(unchecked_param_type = "PointSet")] truth: JsValue,
    #[wasm_bindgen(unchecked_param_type = "PointSet")] estimate: JsValue,
    #[wasm_bindgen(unchecked_param_type = "GospaOptions")] options: JsValue,
) -> JsResult<JsValue> {
    let truth = read::<PointSet>(truth, "truth")?.into_rows();
    let estimate = read::<PointSet>(estimate, "estimate")?.into_rows();
    let o: GospaOptions = read(options, "options")?;
    let g = Gospa::new(o.c, o.p, o.alpha).or_throw_in("options")?;
    if o.alpha != 2.0 {
        let distance = g.distance(&truth, &estimate).or_throw()?;
        return write(&GospaResult {
            distance,
            localisation: None,
            missed: None,
            false_targets: None,
            assignment: None,
        });
    }
    let d = g.decompose(&truth, &estimate).or_throw()?;
    write(&GospaResult {
        distance: d.distance,
        localisation: Some(d.localisation),
        missed: Some(d.missed),
        false_targets: Some(d.false_targets),
        assignment: Some(d.assignment),
    })
}

/// OSPA between two point sets with its rooted localisation and cardinality parts
/// (Schuhmacher et al. 2008; eqs. 24–26 of Ristic & Vo 2010):
/// `distance^p = localisation^p + cardinality^p`. Options `{ c, p = 2 }`. Also returns the
/// optimal permutation's pairs as `assignment`.
#[wasm_bindgen(unchecked_return_type = "OspaResult")]
pub fn ospa(
    #[wasm_bindgen(unchecked_param_type = "PointSet")] truth: JsValue,
    #[wasm_bindgen(unchecked_param_type = "PointSet")] estimate: JsValue,
    #[wasm_bindgen(unchecked_param_type = "OspaOptions")] options: JsValue,
) -> JsResult<JsValue> {
    let truth = read::<PointSet>(truth, "truth")?.into_rows();
    let estimate = read::<PointSet>(estimate, "estimate")?.into_rows();
    let o: OspaOptions = read(options, "options")?;
    let metric = Ospa::new(o.c, o.p).or_throw_in("options")?;
    let d = metric.decompose(&truth, &estimate).or_throw()?;
    write(&OspaResult {
        distance: d.distance,
        localisation: d.localisation,
        cardinality: d.cardinality,
        assignment: d.assignment,
    })
}

/// UOSPA (GOSPA with α = 1) between two point sets. Options `{ c, p = 2 }`; returns
/// `{ distance }`.
#[wasm_bindgen(unchecked_return_type = "UospaResult")]
pub fn uospa(
    #[wasm_bindgen(unchecked_param_type = "PointSet")] truth: JsValue,
    #[wasm_bindgen(unchecked_param_type = "PointSet")] estimate: JsValue,
    #[wasm_bindgen(unchecked_param_type = "OspaOptions")] options: JsValue,
) -> JsResult<JsValue> {
    let truth = read::<PointSet>(truth, "truth")?.into_rows();
    let estimate = read::<PointSet>(estimate, "estimate")?.into_rows();
    let o: OspaOptions = read(options, "options")?;
    let g = Gospa::uospa(o.c, o.p).or_throw_in("options")?;
    let distance = g.distance(&truth, &estimate).or_throw()?;
    write(&UospaResult { distance })
}

fn steps(sets: Vec<PointSet>) -> Vec<Vec<Vec<f64>>> {
    sets.into_iter().map(PointSet::into_rows).collect()
}

/// GOSPA over a whole scenario in one call: `options.truths[t]` and `options.estimates[t]`
/// are the sets at step t. Returns per-step `distance` (and, for α = 2, `localisation`,
/// `missed`, `falseTargets`) with their means. The same numbers as calling `gospa` per step.
#[wasm_bindgen(js_name = gospaSeries, unchecked_return_type = "GospaSeriesResult")]
pub fn gospa_series(
    #[wasm_bindgen(unchecked_param_type = "GospaSeriesOptions")] options: JsValue,
) -> JsResult<JsValue> {
    let o: GospaSeriesOptions = read(options, "options")?;
    let g = Gospa::new(o.c, o.p, o.alpha).or_throw_in("options")?;
    let (truths, estimates) = (steps(o.truths), steps(o.estimates));
    let s = g.series(&truths, &estimates).or_throw_in("options")?;
    let parts = s.parts;
    write(&GospaSeriesResult {
        distance: s.distance,
        mean_distance: s.mean_distance,
        mean_localisation: parts.as_ref().map(|p| p.mean_localisation),
        mean_missed: parts.as_ref().map(|p| p.mean_missed),
        mean_false_targets: parts.as_ref().map(|p| p.mean_false_targets),
        localisation: parts.as_ref().map(|p| p.localisation.clone()),
        missed: parts.as_ref().map(|p| p.missed.clone()),
        false_targets: parts.map(|p| p.false_targets),
    })
}

/// OSPA with its localisation and cardinality parts over a whole scenario in one call
/// (eqs. 24–26 of Ristic & Vo 2010 at every step). Returns per-step arrays and their means.
#[wasm_bindgen(js_name = ospaSeries, unchecked_return_type = "OspaSeriesResult")]
pub fn ospa_series(
    #[wasm_bindgen(unchecked_param_type = "OspaSeriesOptions")] options: JsValue,
) -> JsResult<JsValue> {
    let o: OspaSeriesOptions = read(options, "options")?;
    let metric = Ospa::new(o.c, o.p).or_throw_in("options")?;
    let (truths, estimates) = (steps(o.truths), steps(o.estimates));
    let s = metric.series(&truths, &estimates).or_throw_in("options")?;
    write(&OspaSeriesResult {
        distance: s.distance,
        localisation: s.localisation,
        cardinality: s.cardinality,
        mean_distance: s.mean_distance,
        mean_localisation: s.mean_localisation,
        mean_cardinality: s.mean_cardinality,
    })
}

/// Exact rectangular linear assignment: `cost` is an array of rows (equal lengths). Returns
/// `{ pairs: [row, column][], cost }` minimising the total cost, covering every row when
/// there are no more rows than columns, every column otherwise.
#[wasm_bindgen(js_name = linearAssignment, unchecked_return_type = "LinearAssignmentResult")]
pub fn linear_assignment(
    #[wasm_bindgen(unchecked_param_type = "CostMatrix")] cost: JsValue,
) -> JsResult<JsValue> {
    let rows = read::<CostMatrix>(cost, "cost")?.0;
    let cols = rows.first().map_or(0, Vec::len);
    let mut flat = Vec::with_capacity(rows.len() * cols);
    for (i, row) in rows.iter().enumerate() {
        if row.len() != cols {
            return Err(fisst::Error::dimension(
                format!("cost[{i}]"),
                cols,
                row.len(),
            ))
            .or_throw();
        }
        flat.extend_from_slice(row);
    }
    let a = fisst::math::linear_assignment(&flat, rows.len(), cols).or_throw()?;
    write(&Renamed::new(&a))
}
