//! One file per binding area; each test is a `#[wasm_bindgen_test]` so the same suite runs in
//! Node (`tests/node.rs`) and in Chromium (`tests/browser.rs`).
#![allow(dead_code)]

mod bernoulli;
mod bernoulli_filters;
mod boundary;
mod bounds;
mod control;
mod fov;
mod metrics;
mod multi_bernoulli;
mod splitting;

use wasm_bindgen::{JsCast, JsValue};

/// Parses a JSON literal into a JS value (test input).
pub fn js(json: &str) -> JsValue {
    js_sys::JSON::parse(json).expect("test JSON")
}

/// Reads `obj[key]`.
pub fn get(obj: &JsValue, key: &str) -> JsValue {
    js_sys::Reflect::get(obj, &JsValue::from_str(key)).expect("property")
}

/// Reads `obj[key]` as a number.
pub fn num(obj: &JsValue, key: &str) -> f64 {
    get(obj, key).as_f64().expect("a number")
}

/// A JS array of numbers as a Vec.
pub fn nums(v: &JsValue) -> Vec<f64> {
    js_sys::Array::from(v)
        .iter()
        .map(|x| x.as_f64().expect("a number"))
        .collect()
}

/// The JSON text of a value (for comparing shapes).
pub fn json(v: &JsValue) -> String {
    js_sys::JSON::stringify(v).expect("stringify").into()
}

/// Asserts that `result` is an error of JS class `class` whose message contains `needle`.
pub fn assert_throws(result: Result<JsValue, JsValue>, class: &str, needle: &str) {
    let err = match result {
        Ok(v) => panic!("expected a {class}, got {}", json(&v)),
        Err(e) => e,
    };
    let e: js_sys::Error = err.dyn_into().expect("an Error object");
    let name: String = e.name().into();
    let message: String = e.message().into();
    assert_eq!(name, class, "message: {message}");
    assert!(
        message.contains(needle),
        "{message:?} does not name {needle:?}"
    );
}
