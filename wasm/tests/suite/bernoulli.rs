//! Optimal Bernoulli point estimation: shapes, the paper's numbers, and errors.
use super::{assert_throws, get, js, json, num, nums};
use fisst_wasm::{
    bernoulli_estimate, bernoulli_loss_curve, bernoulli_threshold_curve, mmuc_estimate,
    multi_bernoulli_point_estimate, probability_outside_ball,
};
use wasm_bindgen::JsValue;
use wasm_bindgen_test::wasm_bindgen_test;

/// 2Φ(−1): q at the mean of N(0, 1) with r0 = 1.
const Q_STD: f64 = 0.317_310_507_862_914_1;

fn keys(v: &JsValue) -> String {
    json(&js_sys::Object::keys(&js_sys::Object::from(v.clone())).into())
}

/// `obj[path…]` set to `value` (for NaN, which JSON cannot carry).
fn set(obj: &JsValue, path: &[&str], value: JsValue) -> JsValue {
    let mut target = obj.clone();
    for key in &path[..path.len() - 1] {
        target = get(&target, key);
    }
    js_sys::Reflect::set(&target, &(*path.last().unwrap()).into(), &value).unwrap();
    obj.clone()
}

fn q(options: &str) -> f64 {
    probability_outside_ball(js(options)).unwrap()
}

#[wasm_bindgen_test]
fn estimate_has_the_contract_shape_and_the_papers_mpe_number() {
    let e = bernoulli_estimate(js(
        r#"{"existence":0.55,"density":{"mean":[0],"cov":[[1]]},"radius":1,"costs":"mpe"}"#,
    ))
    .unwrap();
    assert_eq!(
        keys(&e),
        r#"["declare","estimate","mmuc","threshold","missProbability","expectedLossEmpty","expectedLossSingleton"]"#
    );
    // Γ_MPE = 0.5943 (Fig. 2a): 0.5 < p = 0.55 < Γ, so nothing is reported.
    assert!((num(&e, "threshold") - 0.5943).abs() < 5e-5);
    assert!((num(&e, "threshold") - 1.0 / (2.0 - Q_STD)).abs() < 1e-15);
    assert_eq!(get(&e, "declare"), JsValue::FALSE);
    assert!(get(&e, "estimate").is_null());
    assert_eq!(nums(&get(&e, "mmuc")), vec![0.0]);
    assert!((num(&e, "missProbability") - Q_STD).abs() < 1e-15);
    // (17) and (16): ρ_∅ = p, ρ_{a*} = 1 − p + p q.
    assert!((num(&e, "expectedLossEmpty") - 0.55).abs() < 1e-15);
    assert!((num(&e, "expectedLossSingleton") - (0.45 + 0.55 * Q_STD)).abs() < 1e-15);
}

#[wasm_bindgen_test]
fn estimate_reproduces_the_mmol_threshold() {
    // Γ_MMOL = 0.1628 (Fig. 2b: c_A = 0.9, c_M = 0.1, σ = 1, r0 = 1); p = 0.3 reports {μ}.
    let e = bernoulli_estimate(js(
        r#"{"existence":0.3,"density":{"mean":[2.5],"cov":1},"radius":1,
            "costs":{"mmol":{"asset":0.9,"countermeasure":0.1}}}"#,
    ))
    .unwrap();
    assert!((num(&e, "threshold") - 0.1628).abs() < 5e-5);
    assert_eq!(get(&e, "declare"), JsValue::TRUE);
    assert_eq!(json(&get(&e, "estimate")), "[2.5]");
    // (20), (21): ρ_{a*} = c_M + p c_A q, ρ_∅ = p c_A.
    assert!((num(&e, "expectedLossSingleton") - (0.1 + 0.3 * 0.9 * Q_STD)).abs() < 1e-15);
    assert!((num(&e, "expectedLossEmpty") - 0.27).abs() < 1e-15);
    // The same costs written out: (0, c_A, c_M, c_M, c_A).
    let g = bernoulli_estimate(js(
        r#"{"existence":0.3,"density":{"mean":[2.5],"cov":[[1]]},"radius":1,
            "costs":{"c00":0,"c01":0.9,"c10":0.1,"c11":0.1,"c":0.9}}"#,
    ))
    .unwrap();
    assert_eq!(num(&g, "threshold"), num(&e, "threshold"));
}

#[wasm_bindgen_test]
fn estimate_of_2d_gaussians_mixtures_and_particles() {
    // A correlated 2D Gaussian: a* is the mean; q matches probabilityOutsideBall.
    let e = bernoulli_estimate(js(
        r#"{"existence":0.9,"density":{"mean":[1,-1],"cov":[[1,0.6],[0.6,0.8]]},"radius":1.5,"costs":"mpe"}"#,
    ))
    .unwrap();
    assert_eq!(json(&get(&e, "estimate")), "[1,-1]");
    let qa = q(r#"{"density":{"mean":[1,-1],"cov":[1,0.6,0.6,0.8]},"center":[1,-1],"radius":1.5}"#);
    assert_eq!(num(&e, "missProbability"), qa);
    // A bimodal mixture whose best ball lies between the modes.
    let mix = r#"{"mixture":[{"weight":1,"mean":[-1,0],"cov":[[0.09,0],[0,0.09]]},
                             {"weight":1,"mean":[1,0],"cov":[[0.09,0],[0,0.09]]}]}"#;
    let e = bernoulli_estimate(js(&format!(
        r#"{{"existence":0.9,"density":{mix},"radius":1.3,"costs":"mpe"}}"#
    )))
    .unwrap();
    let a = nums(&get(&e, "mmuc"));
    assert!(a[0].abs() < 1e-5 && a[1].abs() < 1e-5, "{a:?}");
    let at_mode = q(&format!(
        r#"{{"density":{mix},"center":[1,0],"radius":1.3}}"#
    ));
    assert!(num(&e, "missProbability") < at_mode - 0.1);
    let m = mmuc_estimate(js(&format!(r#"{{"density":{mix},"radius":1.3}}"#))).unwrap();
    assert_eq!(json(&get(&m, "method")), r#""mixture-search""#);
    assert_eq!(nums(&get(&m, "center")), a);
    // Particles: the best closed disc of radius 1 holds the three heavy particles.
    let e = bernoulli_estimate(js(r#"{"existence":0.6,"radius":1,"costs":"mpe",
            "density":{"particles":[[0,0],[1,0],[0.5,0.8],[5,5]],"weights":[1,1,1,1]}}"#))
    .unwrap();
    assert!((num(&e, "missProbability") - 0.25).abs() < 1e-15);
    assert!((num(&e, "threshold") - 1.0 / 1.75).abs() < 1e-15);
    assert_eq!(get(&e, "declare"), JsValue::TRUE);
}

#[wasm_bindgen_test]
fn probability_outside_ball_values() {
    assert!(
        (q(r#"{"density":{"mean":[0],"cov":[[1]]},"center":[0],"radius":1}"#) - Q_STD).abs()
            < 1e-15
    );
    // Centred isotropic 2D: q = e^{−r²/2σ²}; 3D correlated against its value at 1e-9.
    let v = q(
        r#"{"density":{"mean":[0.3,0.3],"cov":[[0.25,0],[0,0.25]]},"center":[0.3,0.3],"radius":0.8}"#,
    );
    assert!((v - (-0.64f64 / 0.5).exp()).abs() < 1e-10);
    let p = q(
        r#"{"density":{"particles":[[0],[1],[2]],"weights":[1,2,1]},"center":[0.5],"radius":0.5}"#,
    );
    assert!((p - 0.25).abs() < 1e-15);
    let typed = js_sys::Float64Array::from(&[0.0, 0.0][..]);
    let o = js(r#"{"density":{"mean":[0,0],"cov":[[1,0],[0,1]]},"radius":1}"#);
    let o = set(&o, &["center"], typed.into());
    let v = probability_outside_ball(o).unwrap();
    assert!((v - (-0.5f64).exp()).abs() < 1e-10);
}

#[wasm_bindgen_test]
fn threshold_curve_reproduces_figure_three() {
    let g = nums(
        &bernoulli_threshold_curve(js(r#"{"sigmas":[0.5,1,2,4],"radius":1,"costs":"mpe"}"#))
            .unwrap(),
    );
    assert_eq!(g.len(), 4);
    assert!((g[1] - 0.5943).abs() < 5e-5);
    assert!(g.windows(2).all(|w| w[1] > w[0]) && g[0] >= 0.5);
    let m = nums(
        &bernoulli_threshold_curve(js(
            r#"{"sigmas":[1],"radius":1,"costs":{"mmol":{"asset":0.9,"countermeasure":0.1}}}"#,
        ))
        .unwrap(),
    );
    assert!((m[0] - 0.1628).abs() < 5e-5);
    // dim = 2: q = e^{−r²/2σ²}, Γ_MPE = 1/(2 − q).
    let g2 = nums(
        &bernoulli_threshold_curve(js(r#"{"sigmas":[1],"radius":1,"costs":"mpe","dim":2}"#))
            .unwrap(),
    );
    assert!((g2[0] - 1.0 / (2.0 - (-0.5f64).exp())).abs() < 1e-15);
    // c_M = 0 always reports (Γ = 0); c_M ≥ c_A never (Γ ≥ 1).
    let z = nums(
        &bernoulli_threshold_curve(js(
            r#"{"sigmas":[0.1,10],"radius":1,"costs":{"mmol":{"asset":1,"countermeasure":0}}}"#,
        ))
        .unwrap(),
    );
    assert_eq!(z, vec![0.0, 0.0]);
    let n = nums(
        &bernoulli_threshold_curve(js(
            r#"{"sigmas":[0.1,10],"radius":1,"costs":{"mmol":{"asset":1,"countermeasure":1}}}"#,
        ))
        .unwrap(),
    );
    assert!(n.iter().all(|&x| x >= 1.0));
    // A 200-point curve from a Float64Array.
    let sigmas: Vec<f64> = (1..=200).map(|i| 0.05 * i as f64).collect();
    let o = set(
        &js(r#"{"radius":3,"costs":"mpe","dim":3}"#),
        &["sigmas"],
        js_sys::Float64Array::from(sigmas.as_slice()).into(),
    );
    assert_eq!(nums(&bernoulli_threshold_curve(o).unwrap()).len(), 200);
}

#[wasm_bindgen_test]
fn multi_bernoulli_and_loss_curve() {
    let m = multi_bernoulli_point_estimate(js(r#"{"radius":1,"costs":"mpe","components":[
            {"existence":0.9,"density":{"mean":[0,0],"cov":[[0.2,0],[0,0.2]]}},
            {"existence":0.55,"density":{"mean":[5,5],"cov":[[4,0],[0,4]]}},
            {"existence":0.7,"density":{"particles":[[9,9]]}}]}"#))
    .unwrap();
    assert_eq!(json(&get(&m, "reported")), "[0,2]");
    assert_eq!(json(&get(&m, "estimates")), "[[0,0],[9,9]]");
    let comps = js_sys::Array::from(&get(&m, "components"));
    assert_eq!(comps.length(), 3);
    assert_eq!(get(&comps.get(1), "declare"), JsValue::FALSE);

    let c = bernoulli_loss_curve(js(&format!(
        r#"{{"existences":[0,0.55,1],"missProbability":{Q_STD},"costs":"mpe"}}"#
    )))
    .unwrap();
    assert_eq!(keys(&c), r#"["empty","singleton","rule","threshold"]"#);
    assert_eq!(nums(&get(&c, "empty")), vec![0.0, 0.55, 1.0]);
    let rule = nums(&get(&c, "rule"));
    // The optimal rule never loses to either constant decision; at p = 0.55 it reports ∅.
    assert_eq!(rule[1], 0.55);
    let half = bernoulli_loss_curve(js(&format!(
        r#"{{"existences":[0.55],"missProbability":{Q_STD},"costs":"mpe","threshold":0.5}}"#
    )))
    .unwrap();
    assert!(nums(&get(&half, "rule"))[0] > 0.55);
}

#[wasm_bindgen_test]
fn bad_input_names_the_field() {
    let base = r#"{"existence":0.5,"radius":1,"costs":"mpe","density":{"mean":[0,0],"cov":[[1,0],[0,1]]}}"#;
    let with = |path: &[&str], v: JsValue| bernoulli_estimate(set(&js(base), path, v));
    assert!(bernoulli_estimate(js(base)).is_ok());
    // Not symmetric positive definite; mismatched dimensions; NaN anywhere.
    assert_throws(
        with(&["density", "cov"], js("[[1,2],[2,1]]")),
        "RangeError",
        "density.cov",
    );
    assert_throws(
        with(&["density", "cov"], js("[[1,0,0],[0,1,0],[0,0,1]]")),
        "RangeError",
        "density.cov",
    );
    assert_throws(
        with(&["density", "cov"], js("[[1,0],[0]]")),
        "RangeError",
        "density.cov[1]",
    );
    assert_throws(
        with(&["density", "cov"], js("[[1,0],[0,\"x\"]]")),
        "TypeError",
        "density.cov[1][1]",
    );
    assert_throws(
        with(&["density", "mean"], js("[0,1,2]")),
        "RangeError",
        "density.cov",
    );
    let nan = JsValue::from_f64(f64::NAN);
    // NaN inside arrays (JSON cannot carry it): a mean entry, a covariance entry.
    let nan_at = |path: &[&str], index: u32| {
        let o = js(base);
        let mut target = o.clone();
        for key in path {
            target = get(&target, key);
        }
        js_sys::Reflect::set(&target, &index.into(), &JsValue::from_f64(f64::NAN)).unwrap();
        bernoulli_estimate(o)
    };
    assert_throws(
        nan_at(&["density", "mean"], 1),
        "RangeError",
        "density.mean[1]",
    );
    assert_throws(
        nan_at(&["density", "cov", "0"], 1),
        "RangeError",
        "density.cov[0][1]",
    );
    assert_throws(
        with(&["density", "cov"], "abc".into()),
        "TypeError",
        "density.cov",
    );
    assert_throws(
        with(&["density", "cov"], 2.0.into()),
        "TypeError",
        "density.cov",
    );
    assert_throws(with(&["radius"], nan.clone()), "RangeError", "radius");
    assert_throws(with(&["radius"], 0.0.into()), "RangeError", "radius");
    assert_throws(with(&["radius"], (-2.0).into()), "RangeError", "radius");
    assert_throws(with(&["existence"], 1.5.into()), "RangeError", "existence");
    assert_throws(
        with(&["existence"], (-0.1).into()),
        "RangeError",
        "existence",
    );
    assert_throws(with(&["existence"], nan.clone()), "RangeError", "existence");
    assert_throws(with(&["existence"], "0.5".into()), "TypeError", "existence");
    // Weights: negative, or not summing to a positive number.
    let mix = |w1: &str| {
        js(&format!(
            r#"{{"existence":0.5,"radius":1,"costs":"mpe","density":{{"mixture":[
                {{"weight":1,"mean":[0],"cov":[[1]]}},{{"weight":{w1},"mean":[1],"cov":[[1]]}}]}}}}"#
        ))
    };
    assert_throws(
        bernoulli_estimate(mix("-1")),
        "RangeError",
        "density.mixture[1].weight",
    );
    assert_throws(
        bernoulli_estimate(js(
            r#"{"existence":0.5,"radius":1,"costs":"mpe","density":{"mixture":[{"weight":0,"mean":[0],"cov":[[1]]}]}}"#,
        )),
        "RangeError",
        "density.mixture",
    );
    assert_throws(
        bernoulli_estimate(js(
            r#"{"existence":0.5,"radius":1,"costs":"mpe","density":{"mixture":[{"weight":1,"mean":[0],"cov":[[1]]},{"weight":1,"mean":[0,1],"cov":[[1,0],[0,1]]}]}}"#,
        )),
        "RangeError",
        "density.mixture[1].mean",
    );
    assert_throws(
        bernoulli_estimate(js(
            r#"{"existence":0.5,"radius":1,"costs":"mpe","density":{"mixture":[{"mean":[0],"cov":[[1]]}]}}"#,
        )),
        "TypeError",
        "density.mixture[0].weight",
    );
    let parts = |w: &str| {
        js(&format!(
            r#"{{"existence":0.5,"radius":1,"costs":"mpe","density":{{"particles":[[0,0],[1,1]],"weights":{w}}}}}"#
        ))
    };
    assert_throws(
        bernoulli_estimate(parts("[-1,2]")),
        "RangeError",
        "density.weights[0]",
    );
    assert_throws(
        bernoulli_estimate(parts("[0,0]")),
        "RangeError",
        "density.weights",
    );
    assert_throws(
        bernoulli_estimate(parts("[1]")),
        "RangeError",
        "density.weights",
    );
    assert_throws(
        bernoulli_estimate(js(
            r#"{"existence":0.5,"radius":1,"costs":"mpe","density":{"particles":[[0,0],[1]]}}"#,
        )),
        "RangeError",
        "density.particles[1]",
    );
    // Costs.
    assert_throws(with(&["costs"], "mmse".into()), "RangeError", "costs");
    assert_throws(
        with(
            &["costs"],
            js(r#"{"c00":0,"c01":-1,"c10":1,"c11":0,"c":1}"#),
        ),
        "RangeError",
        "costs.c01",
    );
    assert_throws(
        with(&["costs"], js(r#"{"c00":0,"c01":1,"c10":1,"c":1}"#)),
        "TypeError",
        "costs.c11",
    );
    assert_throws(
        with(&["costs"], js(r#"{"mmol":{"asset":0.9}}"#)),
        "TypeError",
        "costs.mmol.countermeasure",
    );
    assert_throws(
        with(
            &["costs"],
            js(r#"{"mmol":{"asset":-0.9,"countermeasure":0.1}}"#),
        ),
        "RangeError",
        "costs.mmol.asset",
    );
    assert_throws(with(&["costs"], JsValue::UNDEFINED), "TypeError", "costs");
    // Missing or malformed density.
    assert_throws(
        with(&["density"], JsValue::UNDEFINED),
        "TypeError",
        "density",
    );
    assert_throws(with(&["density"], js("{}")), "TypeError", "density");
    assert_throws(with(&["density"], js("[1,2]")), "TypeError", "density");
    assert_throws(
        bernoulli_estimate(JsValue::UNDEFINED),
        "TypeError",
        "options",
    );
    // probabilityOutsideBall: the centre's dimension.
    let r = probability_outside_ball(js(
        r#"{"density":{"mean":[0,0],"cov":[[1,0],[0,1]]},"center":[0],"radius":1}"#,
    ))
    .map(JsValue::from);
    assert_throws(r, "RangeError", "center");
    let r = probability_outside_ball(set(
        &js(r#"{"density":{"mean":[0,0],"cov":[[1,0],[0,1]]},"center":[0,0],"radius":1}"#),
        &["center"],
        js_sys::Float64Array::from(&[0.0, f64::NAN][..]).into(),
    ))
    .map(JsValue::from);
    assert_throws(r, "RangeError", "center[1]");
    let r = probability_outside_ball(js(
        r#"{"density":{"particles":[[]]},"center":[0],"radius":1}"#,
    ))
    .map(JsValue::from);
    assert_throws(r, "RangeError", "density.particles[0]");
    let r = probability_outside_ball(js(
        r#"{"density":{"particles":[[0]],"weights":[1]},"center":[0],"radius":1}"#,
    ))
    .map(JsValue::from);
    assert!(r.is_ok());
    // The curve.
    assert_throws(
        bernoulli_threshold_curve(js(r#"{"sigmas":[1,-1],"radius":1,"costs":"mpe"}"#)),
        "RangeError",
        "sigmas[1]",
    );
    assert_throws(
        bernoulli_threshold_curve(js(r#"{"sigmas":[1],"radius":1,"costs":"mpe","dim":0}"#)),
        "RangeError",
        "dim",
    );
    assert_throws(
        bernoulli_threshold_curve(js(r#"{"sigmas":[1],"radius":0,"costs":"mpe"}"#)),
        "RangeError",
        "radius",
    );
    assert_throws(
        bernoulli_threshold_curve(set(
            &js(r#"{"radius":1,"costs":"mpe"}"#),
            &["sigmas"],
            js_sys::Float64Array::from(&[1.0, f64::NAN][..]).into(),
        )),
        "RangeError",
        "sigmas[1]",
    );
    assert_throws(
        bernoulli_threshold_curve(js(r#"{"sigmas":[1],"radius":1,"costs":"mpe","dim":1.5}"#)),
        "RangeError",
        "dim",
    );
    // Multi-Bernoulli: errors carry the component's path.
    assert_throws(
        multi_bernoulli_point_estimate(js(
            r#"{"radius":1,"costs":"mpe","components":[{"existence":0.5,"density":{"mean":[0],"cov":[[1]]}},
               {"existence":0.5,"density":{"mean":[0,0],"cov":[[1,2],[2,1]]}}]}"#,
        )),
        "RangeError",
        "components[1].density.cov",
    );
    assert_throws(
        multi_bernoulli_point_estimate(js(
            r#"{"radius":1,"costs":"mpe","components":[{"existence":2,"density":{"mean":[0],"cov":[[1]]}}]}"#,
        )),
        "RangeError",
        "components[0].existence",
    );
}
