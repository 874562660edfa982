//! `gospa`, `ospa`, `uospa`, `linearAssignment`.

use wasm_bindgen::prelude::*;

use crate::convert::{JsResult, Options, OrThrow, array, numbers, object, pair_array, points};
use fisst::metrics::{Gospa, Ospa};

/// GOSPA between two point sets (García-Fernández & Svensson 2019, Def. 2 and Prop. 3).
///
/// `truth` and `estimate` are arrays of points, each an array of numbers of one common
/// dimension (empty arrays allowed). `options.c` (> 0) is the cut-off, `options.p` (≥ 1,
/// default 2) the order, `options.alpha` (in (0, 2], default 2) the cardinality-mismatch
/// weight. Returns `{ distance, localisation, missed, falseTargets, assignment }`; for
/// `alpha ≠ 2` only `distance` is defined (the decomposition exists for α = 2 only).
#[wasm_bindgen(unchecked_return_type = "GospaResult")]
pub fn gospa(
    #[wasm_bindgen(unchecked_param_type = "Point[]")] truth: JsValue,
    #[wasm_bindgen(unchecked_param_type = "Point[]")] estimate: JsValue,
    #[wasm_bindgen(unchecked_param_type = "GospaOptions")] options: JsValue,
) -> JsResult<JsValue> {
    let truth = points(&truth, "truth")?;
    let estimate = points(&estimate, "estimate")?;
    let opts = Options::new(&options, "options", true)?;
    let c = opts.number("c")?;
    let p = opts.number_or("p", 2.0)?;
    let alpha = opts.number_or("alpha", 2.0)?;
    let g = Gospa::new(c, p, alpha).or_throw()?;
    if alpha != 2.0 {
        let distance = g.distance(&truth, &estimate).or_throw()?;
        return Ok(object(&[("distance", distance.into())]));
    }
    let d = g.decompose(&truth, &estimate).or_throw()?;
    Ok(object(&[
        ("distance", d.distance.into()),
        ("localisation", d.localisation.into()),
        ("missed", (d.missed as f64).into()),
        ("falseTargets", (d.false_targets as f64).into()),
        ("assignment", pair_array(&d.assignment)),
    ]))
}

/// OSPA between two point sets with its rooted localisation and cardinality parts
/// (Schuhmacher et al. 2008; eqs. 24–26 of Ristic & Vo 2010):
/// `distance^p = localisation^p + cardinality^p`. Options `{ c, p = 2 }`. Also returns the
/// optimal permutation's pairs as `assignment`.
#[wasm_bindgen(unchecked_return_type = "OspaResult")]
pub fn ospa(
    #[wasm_bindgen(unchecked_param_type = "Point[]")] truth: JsValue,
    #[wasm_bindgen(unchecked_param_type = "Point[]")] estimate: JsValue,
    #[wasm_bindgen(unchecked_param_type = "OspaOptions")] options: JsValue,
) -> JsResult<JsValue> {
    let truth = points(&truth, "truth")?;
    let estimate = points(&estimate, "estimate")?;
    let opts = Options::new(&options, "options", true)?;
    let o = Ospa::new(opts.number("c")?, opts.number_or("p", 2.0)?).or_throw()?;
    let d = o.decompose(&truth, &estimate).or_throw()?;
    Ok(object(&[
        ("distance", d.distance.into()),
        ("localisation", d.localisation.into()),
        ("cardinality", d.cardinality.into()),
        ("assignment", pair_array(&d.assignment)),
    ]))
}

/// UOSPA (GOSPA with α = 1) between two point sets. Options `{ c, p = 2 }`; returns
/// `{ distance }`.
#[wasm_bindgen(unchecked_return_type = "{ distance: number }")]
pub fn uospa(
    #[wasm_bindgen(unchecked_param_type = "Point[]")] truth: JsValue,
    #[wasm_bindgen(unchecked_param_type = "Point[]")] estimate: JsValue,
    #[wasm_bindgen(unchecked_param_type = "OspaOptions")] options: JsValue,
) -> JsResult<JsValue> {
    let truth = points(&truth, "truth")?;
    let estimate = points(&estimate, "estimate")?;
    let opts = Options::new(&options, "options", true)?;
    let g = Gospa::uospa(opts.number("c")?, opts.number_or("p", 2.0)?).or_throw()?;
    let distance = g.distance(&truth, &estimate).or_throw()?;
    Ok(object(&[("distance", distance.into())]))
}

/// Exact rectangular linear assignment: `cost` is an array of rows (equal lengths). Returns
/// `{ pairs: [row, column][], cost }` minimising the total cost, covering every row when
/// there are no more rows than columns, every column otherwise.
#[wasm_bindgen(js_name = linearAssignment, unchecked_return_type = "{ pairs: [number, number][]; cost: number }")]
pub fn linear_assignment(
    #[wasm_bindgen(unchecked_param_type = "number[][]")] cost: JsValue,
) -> JsResult<JsValue> {
    let rows = array(&cost, "cost", "an array of rows")?;
    let mut flat = Vec::new();
    let mut cols = None;
    for (i, row) in rows.iter().enumerate() {
        let row = numbers(&row, &format!("cost[{i}]"))?;
        match cols {
            None => cols = Some(row.len()),
            Some(c) if c != row.len() => {
                return Err(fisst::Error::dimension(format!("cost[{i}]"), c, row.len())).or_throw();
            }
            _ => {}
        }
        flat.extend(row);
    }
    let n_rows = rows.length() as usize;
    let a = fisst::math::linear_assignment(&flat, n_rows, cols.unwrap_or(0)).or_throw()?;
    Ok(object(&[
        ("pairs", pair_array(&a.pairs)),
        ("cost", a.cost.into()),
    ]))
}
