use super::{assert_throws, get, js, num, nums};
use fisst_wasm::{gaussian_fisher_information, jde_bound_no_clutter, jde_sequential_bound};
use wasm_bindgen_test::wasm_bindgen_test;

#[wasm_bindgen_test]
fn no_clutter_bound_matches_the_core() {
    let r = jde_bound_no_clutter(js(
        r#"{"existence":0.7,"detectionProbability":0.4,"priorVariance":100,"posteriorVariance":25,"falseAlarmError":150,"missError":200}"#,
    ))
    .unwrap();
    let b = fisst::bounds::gaussian_no_clutter(0.7, 0.4, 100.0, 25.0, 150.0, 200.0).unwrap();
    assert_eq!(num(&r, "bound"), b.bound);
    assert_eq!(num(&r, "existenceThreshold"), b.existence_threshold);
    assert_eq!(
        get(&r, "declareOnEmpty").as_bool(),
        Some(b.declare_on_empty)
    );
    assert_eq!(num(&r, "mapBound"), b.map_bound);
    // r* = 150 / (150 + 0.6 · 100) = 5/7 > 0.7: LPE, bound r(e1² − P(e1² − σh²))
    assert!((num(&r, "existenceThreshold") - 150.0 / 210.0).abs() < 1e-15);
    assert_eq!(get(&r, "declareOnEmpty").as_bool(), Some(false));
    assert!((num(&r, "bound") - 0.7 * (200.0 - 0.4 * 175.0)).abs() < 1e-12);
}

#[wasm_bindgen_test]
fn no_clutter_bound_errors_name_the_field() {
    assert_throws(
        jde_bound_no_clutter(js(
            r#"{"existence":1.5,"detectionProbability":0.4,"priorVariance":100,"posteriorVariance":25,"falseAlarmError":150,"missError":200}"#,
        )),
        "RangeError",
        "options.existence",
    );
    assert_throws(
        jde_bound_no_clutter(js(
            r#"{"existence":0.5,"detectionProbability":0.4,"priorVariance":10,"posteriorVariance":25,"falseAlarmError":150,"missError":200}"#,
        )),
        "RangeError",
        "options.posteriorVariance",
    );
    assert_throws(
        jde_bound_no_clutter(js(r#"{"existence":0.5}"#)),
        "TypeError",
        "options",
    );
}

#[wasm_bindgen_test]
fn fisher_information_of_the_linear_gaussian_model() {
    let r = gaussian_fisher_information(js(r#"{"priorVariance":4,"gain":2,"noiseVariance":1}"#))
        .unwrap();
    assert_eq!(num(&r, "information"), 0.25 + 4.0);
    assert!((num(&r, "posteriorVariance") - 1.0 / 4.25).abs() < 1e-15);
    assert_throws(
        gaussian_fisher_information(js(r#"{"priorVariance":4,"gain":2,"noiseVariance":0}"#)),
        "RangeError",
        "options.noiseVariance",
    );
}

#[wasm_bindgen_test]
fn sequential_bounds_match_the_core() {
    for (name, method) in [
        ("enumeration", fisst::bounds::Sequential::Enumeration),
        ("irf", fisst::bounds::Sequential::Irf),
    ] {
        let r = jde_sequential_bound(js(&format!(
            r#"{{"method":"{name}","priorInformation":0.01,"detectedInformation":0.04,"detectionProbability":0.6,"steps":20}}"#
        )))
        .unwrap();
        let native = fisst::bounds::sequential_bound(method, 0.01, 0.04, 0.6, 20).unwrap();
        assert_eq!(nums(&get(&r, "bound")), native);
    }
    assert_throws(
        jde_sequential_bound(js(
            r#"{"method":"irf","priorInformation":0.01,"detectedInformation":0.04,"detectionProbability":0.6,"steps":0}"#,
        )),
        "RangeError",
        "options.steps",
    );
    assert_throws(
        jde_sequential_bound(js(
            r#"{"method":"crb","priorInformation":0.01,"detectedInformation":0.04,"detectionProbability":0.6,"steps":3}"#,
        )),
        "RangeError",
        "options.method",
    );
    assert_throws(
        jde_sequential_bound(js(
            r#"{"method":"irf","priorInformation":0.05,"detectedInformation":0.04,"detectionProbability":0.6,"steps":3}"#,
        )),
        "RangeError",
        "options.detectedInformation",
    );
}
