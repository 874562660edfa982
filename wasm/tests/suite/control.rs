use super::{assert_throws, get, js, json, num, nums};
use fisst_wasm::{SensorControlRunJs, compare_schemes, multi_object_likelihood};
use wasm_bindgen::JsValue;
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

#[wasm_bindgen_test]
fn a_control_run_matches_the_core_step_by_step() {
    let mut run = SensorControlRunJs::new(js(
        r#"{"seed":7,"scheme":"renyi","particles":60,"futureScans":8,"steps":3}"#,
    ))
    .unwrap();
    let mut cfg = fisst::control::ControlOptions::paper(fisst::control::Scheme::Renyi, 3);
    cfg.particles = 60;
    cfg.future_scans = 8;
    let mut core = fisst::control::ControlRun::new(cfg, 7).unwrap();
    for k in 1..=3 {
        let s = run.step().unwrap();
        let c = core.step().unwrap();
        assert_eq!(num(&s, "k"), k as f64);
        let rewards = nums(&get(&s, "rewards"));
        assert_eq!(rewards, c.rewards);
        // The sensor starts in the corner: the moves outside the area are −∞ numbers.
        if k == 1 {
            assert!(rewards.contains(&f64::NEG_INFINITY));
        }
        let action = get(&s, "action");
        assert_eq!(num(&action, "index"), c.action.index as f64);
        assert_eq!(nums(&get(&action, "position")), c.action.position.to_vec());
        let ospa = get(&s, "ospa");
        assert_eq!(num(&ospa, "distance"), c.ospa.distance);
        let est = get(&s, "estimate");
        assert_eq!(num(&est, "cardinality"), c.estimate.cardinality as f64);
        assert_eq!(nums(&get(&est, "cardinalityPmf")).len(), 5);
        assert_eq!(nums(&get(&s, "measurements")), c.measurements);
    }
    assert_eq!(json(&run.truth().unwrap()), "[[300,600],[750,250]]");
    assert_eq!(js_sys::Array::from(&run.sensor_path().unwrap()).length(), 4);
    assert_eq!(
        js_sys::Array::from(&run.measurements().unwrap()).length(),
        3
    );
    let p = run.particles().unwrap();
    assert_eq!(nums(&get(&p, "weights")).len(), 60);
    let total: f64 = nums(&get(&p, "cardinalities")).iter().sum();
    assert_eq!(nums(&get(&p, "positions")).len() as f64, 2.0 * total);
    assert_eq!((run.k(), run.steps(), run.seed()), (3, 3, 7.0));
    assert_eq!(run.scheme(), "renyi");
    assert_throws(run.step(), "RangeError", "step");
}

#[wasm_bindgen_test]
fn control_run_options_are_checked() {
    let bad = |o: &str| SensorControlRunJs::new(js(o)).map(|_| JsValue::NULL);
    assert_throws(bad(r#"{"scheme":"best"}"#), "RangeError", "options.scheme");
    assert_throws(
        bad(r#"{"scheme":"pent","particles":0}"#),
        "RangeError",
        "options.particles",
    );
    assert_throws(
        bad(r#"{"scheme":"pent","particles":10000,"futureScans":1000}"#),
        "RangeError",
        "options.futureScans",
    );
    assert_throws(
        bad(r#"{"scheme":"pent","alpha":0}"#),
        "RangeError",
        "options.alpha",
    );
    assert_throws(
        bad(r#"{"scheme":"pent","start":[-1,5]}"#),
        "RangeError",
        "options.start",
    );
    assert_throws(
        bad(r#"{"scheme":"pent","stpes":3}"#),
        "TypeError",
        "options",
    );
}

#[wasm_bindgen_test]
fn compare_schemes_shape_and_progress() {
    let calls = js_sys::Array::new();
    let f = js_sys::Function::new_with_args("d, t", "this.push([d, t])").bind0(&calls);
    let o = js(
        r#"{"runs":2,"steps":3,"seed":1,"schemes":["random","pent"],"particles":40,"futureScans":4}"#,
    );
    js_sys::Reflect::set(&o, &"onProgress".into(), &f).unwrap();
    let r = compare_schemes(o).unwrap();
    assert_eq!(num(&r, "runs"), 2.0);
    let schemes = js_sys::Array::from(&get(&r, "schemes"));
    assert_eq!(schemes.length(), 2);
    let first = schemes.get(0);
    assert_eq!(get(&first, "scheme").as_string().unwrap(), "random");
    let d = get(&first, "distance");
    assert_eq!(nums(&get(&d, "mean")).len(), 3);
    assert_eq!(nums(&get(&d, "standardError")).len(), 3);
    assert_eq!(json(&calls.get(calls.length() - 1)), "[4,4]");
    // A throwing callback stops the comparison with its exception.
    let o =
        js(r#"{"runs":2,"steps":2,"seed":1,"schemes":["random"],"particles":20,"futureScans":2}"#);
    let thrower = js_sys::Function::new_no_args("throw new TypeError('stop here')");
    js_sys::Reflect::set(&o, &"onProgress".into(), &thrower).unwrap();
    assert_throws(compare_schemes(o), "TypeError", "stop here");
    assert_throws(
        compare_schemes(js(r#"{"runs":0,"steps":2}"#)),
        "RangeError",
        "options.runs",
    );
}
