//! The deserializer of the boundary (`fisst_wasm::de`) on its own: paths, classes, unknown
//! keys, absent values, typed arrays, depth and cycles, and callbacks.

use fisst_wasm::de::{ErrorClass, from_js, from_js_with_callback};
use serde::Deserialize;
use wasm_bindgen::JsValue;
use wasm_bindgen_test::wasm_bindgen_test;

use super::js;

#[derive(Debug, Deserialize)]
#[serde(rename_all = "camelCase")]
struct Inner {
    cov: Vec<Vec<f64>>,
    #[serde(default)]
    count: usize,
}

#[derive(Debug, Deserialize)]
#[serde(rename_all = "camelCase")]
struct Outer {
    alpha: f64,
    #[serde(default)]
    items: Vec<Inner>,
    label: Option<String>,
}

fn err(v: JsValue) -> (ErrorClass, String) {
    let e = from_js::<Outer>(v, "options").unwrap_err();
    (e.class, e.message)
}

#[wasm_bindgen_test]
fn paths_classes_and_unknown_keys() {
    let ok: Outer = from_js(js(r#"{"alpha":1,"items":[{"cov":[[1]]}]}"#), "options").unwrap();
    assert_eq!(ok.items[0].cov, vec![vec![1.0]]);
    assert_eq!(
        err(js(r#"{"alpha":1,"items":[{"cov":[[1],[2,"x"]]}]}"#)),
        (
            ErrorClass::Type,
            "options.items[0].cov[1][1] must be a number, got the string \"x\"".into()
        )
    );
    assert_eq!(
        err(js(r#"{"aplha":1}"#)),
        (
            ErrorClass::Type,
            "options has an unknown key \"aplha\" (did you mean alpha?); its keys are alpha, \
             items, label"
                .into()
        )
    );
    assert_eq!(err(js("{}")).1, "options.alpha is required");
    assert_eq!(err(js(r#"{"alpha":1e999}"#)).0, ErrorClass::Range);
    assert_eq!(
        err(js(r#"{"alpha":1,"items":[{"cov":[],"count":2.5}]}"#)),
        (
            ErrorClass::Range,
            "options.items[0].count must be a non-negative integer, got 2.5".into()
        )
    );
    assert_eq!(
        err(JsValue::UNDEFINED).1,
        "options must be an object, got undefined"
    );
    assert_eq!(err(js("[1]")).1, "options must be an object, got an array");
}

#[wasm_bindgen_test]
fn undefined_and_null_are_absent_and_typed_arrays_read() {
    let o: Outer = from_js(js(r#"{"alpha":2,"label":null,"items":null}"#), "options").unwrap();
    assert!(o.label.is_none() && o.items.is_empty());
    let obj = js_sys::Object::new();
    js_sys::Reflect::set(&obj, &"alpha".into(), &3.0.into()).unwrap();
    js_sys::Reflect::set(&obj, &"label".into(), &JsValue::UNDEFINED).unwrap();
    let row = js_sys::Float64Array::from(&[1.0, 2.0][..]);
    let inner = js(r#"{"cov":[]}"#);
    js_sys::Reflect::set(&inner, &"cov".into(), &js_sys::Array::of1(&row)).unwrap();
    js_sys::Reflect::set(&obj, &"items".into(), &js_sys::Array::of1(&inner)).unwrap();
    let o: Outer = from_js(obj.into(), "options").unwrap();
    assert_eq!(o.alpha, 3.0);
    assert_eq!(o.items[0].cov, vec![vec![1.0, 2.0]]);
    let bad = js_sys::Float64Array::from(&[1.0, f64::NAN][..]);
    let inner = js(r#"{"cov":[]}"#);
    js_sys::Reflect::set(&inner, &"cov".into(), &js_sys::Array::of1(&bad)).unwrap();
    let obj = js(r#"{"alpha":1}"#);
    js_sys::Reflect::set(&obj, &"items".into(), &js_sys::Array::of1(&inner)).unwrap();
    assert_eq!(
        err(obj).1,
        "options.items[0].cov[0][1] must be a finite number, got NaN"
    );
}

#[wasm_bindgen_test]
fn cycles_and_depth_are_errors_not_stack_overflows() {
    #[derive(Debug, Deserialize)]
    struct Node(#[allow(dead_code)] Vec<Node>);
    // A cyclic array read by a recursive type.
    let a = js_sys::Array::new();
    a.push(&a);
    let e = from_js::<Node>(a.into(), "tree").unwrap_err();
    assert_eq!(e.class, ErrorClass::Range, "{}", e.message);
    assert!(e.message.contains("nested more than"), "{}", e.message);
    // A cycle where a plain shape is expected is a type error at the first wrong level.
    let a = js_sys::Array::new();
    a.push(&a);
    let obj = js(r#"{"alpha":1}"#);
    js_sys::Reflect::set(&obj, &"items".into(), &a).unwrap();
    assert_eq!(
        err(obj).1,
        "options.items[0] must be an object, got an array"
    );
    // A recursive type on 200 nested arrays: stopped at the depth cap, with the path.
    let mut v = js_sys::Array::new();
    for _ in 0..200 {
        let outer = js_sys::Array::new();
        outer.push(&v);
        v = outer;
    }
    let e = from_js::<Node>(v.into(), "tree").unwrap_err();
    assert_eq!(e.class, ErrorClass::Range, "{}", e.message);
    assert!(e.message.starts_with("tree[0][0]"), "{}", e.message);
    let shallow = js("[[[]],[]]");
    assert!(from_js::<Node>(shallow, "tree").is_ok());
}

#[wasm_bindgen_test]
fn callbacks_pass_through() {
    let f = js_sys::Function::new_with_args("a, b", "return a + b");
    let obj = js(r#"{"alpha":1}"#);
    js_sys::Reflect::set(&obj, &"onProgress".into(), &f).unwrap();
    let (o, callback) = from_js_with_callback::<Outer>(obj, "options", "onProgress").unwrap();
    assert_eq!(o.alpha, 1.0);
    let got = callback
        .expect("the callback")
        .call2(&JsValue::NULL, &1.into(), &2.into())
        .unwrap();
    assert_eq!(got.as_f64(), Some(3.0));
    let e = from_js_with_callback::<Outer>(
        js(r#"{"alpha":1,"onProgress":5}"#),
        "options",
        "onProgress",
    )
    .unwrap_err();
    assert_eq!(e.class, ErrorClass::Type);
    assert!(
        e.message
            .starts_with("options.onProgress must be a function"),
        "{}",
        e.message
    );
    // without the callback key, `onProgress` is an unknown key
    let (class, _) = err(js(r#"{"alpha":1,"onProgress":5}"#));
    assert_eq!(class, ErrorClass::Type);
}
