use super::{assert_throws, get, js, json, num, nums};
use fisst_wasm::{
    mb_decision_map, mb_mean_square_error, mb_optimal_estimate, multi_bernoulli_cardinality_js,
};
use wasm_bindgen::JsValue;
use wasm_bindgen_test::wasm_bindgen_test;

#[wasm_bindgen_test]
fn cardinality_pmf() {
    let pmf = nums(&multi_bernoulli_cardinality_js(js("[0.5,0.5]")).unwrap());
    assert_eq!(pmf, vec![0.25, 0.5, 0.25]);
    let r: Vec<f64> = (0..2000)
        .map(|i| (i as f64 * 0.618_033_988_7) % 1.0)
        .collect();
    let arr = js_sys::Float64Array::from(r.as_slice());
    let pmf = nums(&multi_bernoulli_cardinality_js(arr.into()).unwrap());
    assert_eq!(pmf.len(), 2001);
    assert!(pmf.iter().all(|&p| p >= 0.0));
    assert!((pmf.iter().sum::<f64>() - 1.0).abs() < 1e-12);
    assert_throws(
        multi_bernoulli_cardinality_js(js("[0.1,-0.2]")),
        "RangeError",
        "existence[1]",
    );
    assert_throws(
        multi_bernoulli_cardinality_js(js("{}")),
        "TypeError",
        "existence",
    );
}

#[wasm_bindgen_test]
fn spooky_example_5() {
    let est = |r2: f64| {
        let o = js(&format!(r#"{{"existence":[0.4,{r2}],"metric":"ospa"}}"#));
        json(&get(&mb_optimal_estimate(o).unwrap(), "report"))
    };
    assert_eq!(est(0.4), "[true,true]");
    assert_eq!(est(0.9), "[false,true]");
    assert_eq!(est(0.1), "[false,false]");
    let g = mb_optimal_estimate(js(r#"{"existence":[0.4,0.4],"metric":"gospa"}"#)).unwrap();
    assert_eq!(json(&get(&g, "report")), "[false,false]");
    assert!((num(&g, "meanSquareError") - 0.4).abs() < 1e-15);
}

#[wasm_bindgen_test]
fn mean_square_error_matches_the_optimum() {
    let e = mb_optimal_estimate(js(
        r#"{"existence":[0.3,0.7,0.5,0.9],"metric":"uospa","c":2}"#,
    ))
    .unwrap();
    let report = get(&e, "report");
    let opts = js(r#"{"existence":[0.3,0.7,0.5,0.9],"metric":"uospa","c":2}"#);
    js_sys::Reflect::set(&opts, &"report".into(), &report).unwrap();
    let mse = mb_mean_square_error(opts).unwrap();
    assert!((mse - num(&e, "meanSquareError")).abs() < 1e-12);
}

#[wasm_bindgen_test]
fn mb_bad_input() {
    assert_throws(
        mb_optimal_estimate(js(r#"{"existence":[0.2],"metric":"hausdorff"}"#)),
        "RangeError",
        "metric",
    );
    assert_throws(
        mb_optimal_estimate(js(r#"{"existence":[0.2]}"#)),
        "TypeError",
        "metric",
    );
    assert_throws(
        mb_optimal_estimate(js(r#"{"existence":[0.2],"metric":"ospa","p":0}"#)),
        "RangeError",
        "p",
    );
    assert_throws(
        mb_optimal_estimate(js(r#"{"existence":[2],"metric":"ospa"}"#)),
        "RangeError",
        "existence[0]",
    );
    let r = mb_mean_square_error(js(r#"{"existence":[0.2],"metric":"ospa","report":[1,0]}"#));
    assert_throws(r.map(JsValue::from), "RangeError", "report");
    let r = mb_mean_square_error(js(
        r#"{"existence":[0.2],"metric":"ospa","report":["yes"]}"#,
    ));
    assert_throws(r.map(JsValue::from), "TypeError", "report[0]");
}

#[wasm_bindgen_test]
fn decision_map_codes() {
    let m = mb_decision_map(js(r#"{"estimator":"gospa","resolution":4}"#)).unwrap();
    let d: js_sys::Uint8Array = get(&m, "decisions").into();
    // cell centres 0.125, 0.375, 0.625, 0.875: GOSPA reports r > 0.5
    assert_eq!(
        d.to_vec(),
        vec![0, 0, 1, 1, 0, 0, 1, 1, 2, 2, 3, 3, 2, 2, 3, 3]
    );
}
