use super::{assert_throws, get, js, json, num, nums};
use fisst_wasm::{gospa, gospa_series, linear_assignment, ospa, ospa_series, uospa};
use wasm_bindgen::JsValue;
use wasm_bindgen_test::wasm_bindgen_test;

#[wasm_bindgen_test]
fn gospa_decomposition_shape_and_values() {
    let r = gospa(js("[[0,0],[10,0]]"), js("[[0,1]]"), js(r#"{"c":2}"#)).unwrap();
    assert!((num(&r, "distance") - 3f64.sqrt()).abs() < 1e-15);
    assert_eq!(num(&r, "localisation"), 1.0);
    assert_eq!(num(&r, "missed"), 1.0);
    assert_eq!(num(&r, "falseTargets"), 0.0);
    assert_eq!(json(&get(&r, "assignment")), "[[0,0]]");
    // p = 1, alpha ≠ 2: only the distance
    let r = gospa(
        js("[[0]]"),
        js("[[0.5],[9]]"),
        js(r#"{"c":3,"p":1,"alpha":1}"#),
    )
    .unwrap();
    assert_eq!(num(&r, "distance"), 3.5);
    assert!(get(&r, "missed").is_undefined());
    // empty sets
    let r = gospa(js("[]"), js("[]"), js(r#"{"c":1}"#)).unwrap();
    assert_eq!(num(&r, "distance"), 0.0);
    assert_eq!(json(&get(&r, "assignment")), "[]");
}

#[wasm_bindgen_test]
fn gospa_accepts_typed_array_points() {
    let truth = js_sys::Array::of1(&js_sys::Float64Array::from(&[3.0, 4.0][..]));
    let r = gospa(truth.into(), js("[[0,0]]"), js(r#"{"c":10,"p":1}"#)).unwrap();
    assert_eq!(num(&r, "distance"), 5.0);
}

#[wasm_bindgen_test]
fn ospa_parts() {
    let r = ospa(js("[[0],[5]]"), js("[[1]]"), js(r#"{"c":10,"p":1}"#)).unwrap();
    assert_eq!(num(&r, "distance"), 5.5);
    assert_eq!(num(&r, "localisation"), 0.5);
    assert_eq!(num(&r, "cardinality"), 5.0);
    let r = ospa(js("[]"), js("[]"), js(r#"{"c":10}"#)).unwrap();
    assert_eq!(num(&r, "distance"), 0.0);
    let r = uospa(js("[[0]]"), js("[]"), js(r#"{"c":2,"p":1}"#)).unwrap();
    assert_eq!(num(&r, "distance"), 2.0);
}

#[wasm_bindgen_test]
fn assignment_of_a_matrix() {
    let r = linear_assignment(js("[[4,1,3],[2,0,5]]")).unwrap();
    assert_eq!(json(&get(&r, "pairs")), "[[0,1],[1,0]]");
    assert_eq!(num(&r, "cost"), 3.0);
    assert_throws(
        linear_assignment(js("[[1,2],[3]]")),
        "RangeError",
        "cost[1]",
    );
}

#[wasm_bindgen_test]
fn bad_input_throws_naming_the_field() {
    let ok = || js("[[0,0]]");
    assert_throws(
        gospa(ok(), js("[[0]]"), js(r#"{"c":1}"#)),
        "RangeError",
        "estimate[0]",
    );
    assert_throws(
        gospa(js("[[0,0],[1]]"), ok(), js(r#"{"c":1}"#)),
        "RangeError",
        "truth[1]",
    );
    assert_throws(gospa(ok(), ok(), js(r#"{"c":0}"#)), "RangeError", "c");
    assert_throws(
        gospa(ok(), ok(), js(r#"{"c":1,"p":0.5}"#)),
        "RangeError",
        "p",
    );
    assert_throws(
        gospa(ok(), ok(), js(r#"{"c":1,"alpha":2.5}"#)),
        "RangeError",
        "alpha",
    );
    assert_throws(
        gospa(ok(), ok(), js(r#"{"c":1,"alpha":0}"#)),
        "RangeError",
        "alpha",
    );
    assert_throws(gospa(ok(), ok(), js("{}")), "TypeError", "c");
    assert_throws(
        gospa(ok(), ok(), JsValue::UNDEFINED),
        "TypeError",
        "options",
    );
    assert_throws(gospa(ok(), ok(), js(r#"{"c":"1"}"#)), "TypeError", "c");
    assert_throws(
        gospa(js(r#""x""#), ok(), js(r#"{"c":1}"#)),
        "TypeError",
        "truth",
    );
    assert_throws(
        gospa(ok(), js(r#"[[0,"a"]]"#), js(r#"{"c":1}"#)),
        "TypeError",
        "estimate[0][1]",
    );
    assert_throws(
        gospa(ok(), js("[5]"), js(r#"{"c":1}"#)),
        "TypeError",
        "estimate[0]",
    );
    let nan_point = js_sys::Array::of1(&js_sys::Array::of2(&0.into(), &f64::NAN.into()));
    assert_throws(
        gospa(nan_point.into(), ok(), js(r#"{"c":1}"#)),
        "RangeError",
        "truth[0][1]",
    );
    let inf = js_sys::Object::new();
    js_sys::Reflect::set(&inf, &"c".into(), &f64::INFINITY.into()).unwrap();
    assert_throws(ospa(ok(), ok(), inf.into()), "RangeError", "c");
    // The module is still alive after all of these.
    assert_eq!(
        num(&gospa(ok(), ok(), js(r#"{"c":1}"#)).unwrap(), "distance"),
        0.0
    );
}

#[wasm_bindgen_test]
fn series_equal_the_per_step_calls_and_name_the_step_in_errors() {
    let r = gospa_series(js(
        r#"{"truths":[[[0,0],[10,0]],[],[[1,1]]],"estimates":[[[0,1]],[[5,5]],[[1,2]]],"c":2}"#,
    ))
    .unwrap();
    let d = nums(&get(&r, "distance"));
    assert_eq!(d.len(), 3);
    assert!((d[0] - 3f64.sqrt()).abs() < 1e-15);
    assert!((d[1] - 2f64.sqrt()).abs() < 1e-15);
    assert_eq!(d[2], 1.0);
    assert_eq!(nums(&get(&r, "missed")), vec![1.0, 0.0, 0.0]);
    assert_eq!(nums(&get(&r, "falseTargets")), vec![0.0, 1.0, 0.0]);
    assert!((num(&r, "meanDistance") - (d[0] + d[1] + d[2]) / 3.0).abs() < 1e-15);
    let o = ospa_series(js(
        r#"{"truths":[[[0],[5]]],"estimates":[[[1]]],"c":10,"p":1}"#,
    ))
    .unwrap();
    assert_eq!(nums(&get(&o, "distance")), vec![5.5]);
    assert_eq!(nums(&get(&o, "localisation")), vec![0.5]);
    assert_throws(
        gospa_series(js(
            r#"{"truths":[[],[[0,1],[2]]],"estimates":[[],[]],"c":1}"#,
        )),
        "RangeError",
        "options.truths[1][1]",
    );
    assert_throws(
        ospa_series(js(r#"{"truths":[[]],"estimates":[],"c":1}"#)),
        "RangeError",
        "options.estimates",
    );
}
