use super::{assert_throws, js, num};
use fisst_wasm::multi_object_likelihood;
use wasm_bindgen_test::wasm_bindgen_test;

#[wasm_bindgen_test]
fn likelihood_matches_the_core_and_edge_cases() {
    let r = multi_object_likelihood(js(
        r#"{"likelihoods":[[0.2,0.01],[0.03,0.4]],"detectionProbability":0.95,"clutterRate":0.8,"clutterDensity":[0.5,0.5]}"#,
    ))
    .unwrap();
    let core =
        fisst::smc::ln_likelihood(&[[0.2, 0.01], [0.03, 0.4]], 0.95, 0.8, &[0.5, 0.5]).unwrap();
    assert_eq!(num(&r, "logLikelihood"), core);
    // n = 0, |Z| = 0: e^{−λ}.
    let r = multi_object_likelihood(js(
        r#"{"likelihoods":[],"detectionProbability":0.9,"clutterRate":0.8,"clutterDensity":[]}"#,
    ))
    .unwrap();
    assert_eq!(num(&r, "logLikelihood"), -0.8);
    // p_D = 1 and an object without a measurement: −∞.
    let r = multi_object_likelihood(js(
        r#"{"likelihoods":[[]],"detectionProbability":1,"clutterRate":0.8,"clutterDensity":[]}"#,
    ))
    .unwrap();
    assert_eq!(num(&r, "logLikelihood"), f64::NEG_INFINITY);
}

#[wasm_bindgen_test]
fn likelihood_errors_name_the_field() {
    assert_throws(
        multi_object_likelihood(js(
            r#"{"likelihoods":[[0.2,-1]],"detectionProbability":0.9,"clutterRate":0.8,"clutterDensity":[1,1]}"#,
        )),
        "RangeError",
        "options.likelihoods[0][1]",
    );
    assert_throws(
        multi_object_likelihood(js(
            r#"{"likelihoods":[[0.2]],"detectionProbability":0.9,"clutterRate":0.8,"clutterDensity":[1,1]}"#,
        )),
        "RangeError",
        "options.likelihoods[0]",
    );
    assert_throws(
        multi_object_likelihood(js(
            r#"{"likelihoods":[],"detectionProbability":2,"clutterRate":0.8,"clutterDensity":[]}"#,
        )),
        "RangeError",
        "options.detectionProbability",
    );
    assert_throws(
        multi_object_likelihood(js(
            r#"{"likelihoods":[],"detectionProbability":0.5,"clutterRate":0.8}"#,
        )),
        "TypeError",
        "options",
    );
}
