//! Multi-Bernoulli cardinality and optimal estimation (Section III of the spooky-effect
//! paper).

use wasm_bindgen::prelude::*;

use crate::convert::{
    JsResult, Options, OrThrow, boolean_array, booleans, number_array, numbers, object,
    range_error, string,
};
use fisst::cardinality::{leave_one_out_cardinalities, multi_bernoulli_cardinality};
use fisst::estimators::alternatives::{jom_estimate, mam_estimate, map_cardinality_estimate};
use fisst::estimators::multi_bernoulli::{SetMetric, mean_error, optimal_estimate};
use js_sys::{Array, Uint8Array};

/// The cardinality pmf of a multi-Bernoulli (Poisson-binomial): `pmf[n] = P(N = n)`,
/// n = 0 … existence.length. Exact, nonnegative, sums to 1.
#[wasm_bindgen(js_name = multiBernoulliCardinality, unchecked_return_type = "number[]")]
pub fn multi_bernoulli_cardinality_js(
    #[wasm_bindgen(unchecked_param_type = "number[] | Float64Array")] existence: JsValue,
) -> JsResult<JsValue> {
    let r = numbers(&existence, "existence")?;
    Ok(number_array(&multi_bernoulli_cardinality(&r).or_throw()?))
}

/// The leave-one-out cardinality pmfs ρ₋ᵢ: element i is the pmf without component i.
#[wasm_bindgen(js_name = multiBernoulliLeaveOneOut, unchecked_return_type = "number[][]")]
pub fn multi_bernoulli_leave_one_out(
    #[wasm_bindgen(unchecked_param_type = "number[] | Float64Array")] existence: JsValue,
) -> JsResult<JsValue> {
    let r = numbers(&existence, "existence")?;
    let all = leave_one_out_cardinalities(&r).or_throw()?;
    Ok(all
        .iter()
        .map(|p| number_array(p))
        .collect::<Array>()
        .into())
}

fn set_metric(opts: &Options) -> JsResult<SetMetric> {
    let name = string(&opts.require("metric")?, "metric")?;
    match name.as_str() {
        "gospa" => Ok(SetMetric::Gospa {
            alpha: opts.number_or("alpha", 2.0)?,
        }),
        "ospa" => Ok(SetMetric::Ospa),
        "uospa" => Ok(SetMetric::Uospa),
        other => Err(range_error(format!(
            "metric must be one of 'gospa', 'ospa', 'uospa', got {other:?}"
        ))),
    }
}

struct MbInputs {
    existence: Vec<f64>,
    metric: SetMetric,
    c: f64,
    p: f64,
}

fn mb_inputs(options: &JsValue) -> JsResult<(Options, MbInputs)> {
    let opts = Options::new(options, "options", true)?;
    let existence = numbers(&opts.require("existence")?, "existence")?;
    let metric = set_metric(&opts)?;
    let c = opts.number_or("c", 1.0)?;
    let p = opts.number_or("p", 2.0)?;
    Ok((
        opts,
        MbInputs {
            existence,
            metric,
            c,
            p,
        },
    ))
}

/// The estimate of a multi-Bernoulli with far-apart Dirac components that minimises the mean
/// error E[d^p] (the mean square error for p = 2) under GOSPA, OSPA or UOSPA — exact for any
/// number of components. Options `{ existence, metric, c = 1, p = 2, alpha = 2 }`; returns
/// `{ report, meanSquareError }`.
#[wasm_bindgen(js_name = mbOptimalEstimate, unchecked_return_type = "MbOptimalEstimateResult")]
pub fn mb_optimal_estimate(
    #[wasm_bindgen(unchecked_param_type = "MbOptimalEstimateOptions")] options: JsValue,
) -> JsResult<JsValue> {
    let (_, m) = mb_inputs(&options)?;
    let e = optimal_estimate(&m.existence, m.metric, m.c, m.p).or_throw()?;
    Ok(object(&[
        ("report", boolean_array(&e.report)),
        ("meanSquareError", e.mean_error.into()),
    ]))
}

/// The mean error E[d^p] (mean square for p = 2) of the estimate `report` (a boolean per
/// component): Lemma 4 of the spooky-effect paper. Options
/// `{ existence, report, metric, c = 1, p = 2, alpha = 2 }`.
#[wasm_bindgen(js_name = mbMeanSquareError)]
pub fn mb_mean_square_error(
    #[wasm_bindgen(unchecked_param_type = "MbMeanSquareErrorOptions")] options: JsValue,
) -> JsResult<f64> {
    let (opts, m) = mb_inputs(&options)?;
    let report = booleans(&opts.require("report")?, "report")?;
    mean_error(&m.existence, &report, m.metric, m.c, m.p).or_throw()
}

/// The classical estimators of Fig. 2: `method` is `'mam'` (marginal multi-target),
/// `'jom'` (joint multi-target) or `'map-cardinality'` (maximise the cardinality pmf, then
/// report the most probable components). `lnPeak[i]` is `−½ ln det(2π P_i)` for component i's
/// Gaussian (default 0: equal covariances), `lnC` the log of JoM's constant (default 0, i.e.
/// c = (2πε)^(d/2) for P = εI). Returns `{ report }`.
#[wasm_bindgen(js_name = mbAlternativeEstimate, unchecked_return_type = "{ report: boolean[] }")]
pub fn mb_alternative_estimate(
    #[wasm_bindgen(unchecked_param_type = "MbAlternativeEstimateOptions")] options: JsValue,
) -> JsResult<JsValue> {
    let opts = Options::new(&options, "options", true)?;
    let existence = numbers(&opts.require("existence")?, "existence")?;
    let method = string(&opts.require("method")?, "method")?;
    let ln_peak = match opts.get("lnPeak")? {
        Some(v) => numbers(&v, "lnPeak")?,
        None => vec![0.0; existence.len()],
    };
    let ln_c = opts.number_or("lnC", 0.0)?;
    let report = alternative(&existence, &method, &ln_peak, ln_c)?;
    Ok(object(&[("report", boolean_array(&report))]))
}

fn alternative(existence: &[f64], method: &str, ln_peak: &[f64], ln_c: f64) -> JsResult<Vec<bool>> {
    match method {
        "mam" => mam_estimate(existence, ln_peak).or_throw(),
        "jom" => jom_estimate(existence, ln_peak, ln_c).or_throw(),
        "map-cardinality" => map_cardinality_estimate(existence).or_throw(),
        other => Err(range_error(format!(
            "method must be one of 'mam', 'jom', 'map-cardinality', got {other:?}"
        ))),
    }
}

/// Fig. 1 / Fig. 2 decision maps for two far-apart components: for every cell of a
/// `resolution × resolution` grid of (r1, r2) (cell centres, r = (i + ½)/resolution), the
/// optimal decision coded as `u1 + 2·u2`. Row-major with r2 as the outer (row) index and r1
/// the inner. `estimator` is `'gospa'`, `'ospa'`, `'uospa'`, `'mam'`, `'jom'` or
/// `'map-cardinality'`. Returns `{ resolution, decisions: Uint8Array }`.
#[wasm_bindgen(js_name = mbDecisionMap, unchecked_return_type = "{ resolution: number; decisions: Uint8Array }")]
pub fn mb_decision_map(
    #[wasm_bindgen(
        unchecked_param_type = "{ estimator: string; resolution?: number; c?: number; p?: number; alpha?: number }"
    )]
    options: JsValue,
) -> JsResult<JsValue> {
    let opts = Options::new(&options, "options", true)?;
    let estimator = string(&opts.require("estimator")?, "estimator")?;
    let res = opts.integer_or("resolution", 100, 1, 2000)?;
    let c = opts.number_or("c", 1.0)?;
    let p = opts.number_or("p", 2.0)?;
    let metric = match estimator.as_str() {
        "gospa" => Some(SetMetric::Gospa {
            alpha: opts.number_or("alpha", 2.0)?,
        }),
        "ospa" => Some(SetMetric::Ospa),
        "uospa" => Some(SetMetric::Uospa),
        "mam" | "jom" | "map-cardinality" => None,
        other => {
            return Err(range_error(format!(
                "estimator must be one of 'gospa', 'ospa', 'uospa', 'mam', 'jom', \
                 'map-cardinality', got {other:?}"
            )));
        }
    };
    let mut codes = vec![0u8; res * res];
    for row in 0..res {
        for col in 0..res {
            let r = [
                (col as f64 + 0.5) / res as f64,
                (row as f64 + 0.5) / res as f64,
            ];
            let u = match metric {
                Some(m) => optimal_estimate(&r, m, c, p).or_throw()?.report,
                None => alternative(&r, &estimator, &[0.0, 0.0], 0.0)?,
            };
            codes[row * res + col] = u8::from(u[0]) + 2 * u8::from(u[1]);
        }
    }
    let decisions = Uint8Array::from(codes.as_slice());
    Ok(object(&[
        ("resolution", (res as f64).into()),
        ("decisions", decisions.into()),
    ]))
}

/// Fig. 3: the optimal number of reported targets for n = 1 … maxComponents identical
/// far-apart components of existence `existence`, under GOSPA, OSPA, UOSPA and the
/// MAP-cardinality rule. Returns `{ n, gospa, ospa, uospa, mapCardinality }` (arrays).
#[wasm_bindgen(js_name = mbIdenticalComponentCounts, unchecked_return_type = "{ n: number[]; gospa: number[]; ospa: number[]; uospa: number[]; mapCardinality: number[] }")]
pub fn mb_identical_component_counts(
    #[wasm_bindgen(unchecked_param_type = "{ existence: number; maxComponents: number }")]
    options: JsValue,
) -> JsResult<JsValue> {
    let opts = Options::new(&options, "options", true)?;
    let r = opts.number("existence")?;
    opts.require("maxComponents")?;
    let max_n = opts.integer_or("maxComponents", 1, 1, 1000)?;
    let count = |u: &[bool]| u.iter().filter(|&&b| b).count() as f64;
    let (mut ns, mut g, mut o, mut u, mut m) = (vec![], vec![], vec![], vec![], vec![]);
    for n in 1..=max_n {
        let rs = vec![r; n];
        ns.push(n as f64);
        g.push(count(
            &optimal_estimate(&rs, SetMetric::GOSPA, 1.0, 2.0)
                .or_throw()?
                .report,
        ));
        o.push(count(
            &optimal_estimate(&rs, SetMetric::Ospa, 1.0, 2.0)
                .or_throw()?
                .report,
        ));
        u.push(count(
            &optimal_estimate(&rs, SetMetric::Uospa, 1.0, 2.0)
                .or_throw()?
                .report,
        ));
        m.push(count(&map_cardinality_estimate(&rs).or_throw()?));
    }
    Ok(object(&[
        ("n", number_array(&ns)),
        ("gospa", number_array(&g)),
        ("ospa", number_array(&o)),
        ("uospa", number_array(&u)),
        ("mapCardinality", number_array(&m)),
    ]))
}
