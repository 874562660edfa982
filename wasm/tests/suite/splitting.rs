use super::{assert_throws, get, js, json, num, nums};
use fisst_wasm::{
    negative_information_scenario_js, reduce_mixture_js, split_for_regions_js, split_library_js,
};
use js_sys::Array;
use wasm_bindgen::JsValue;
use wasm_bindgen_test::wasm_bindgen_test;

/// The weights of a JS mixture.
fn weights(m: &JsValue) -> Vec<f64> {
    Array::from(m).iter().map(|c| num(&c, "weight")).collect()
}

const ONE_GAUSSIAN: &str = r#"[{"weight":1,"mean":[0,0,1,0],
    "cov":[[1,0.3,0,0],[0.3,0.8,0,0],[0,0,0.1,0],[0,0,0,0.1]]}]"#;

fn split(extra: &str) -> Result<JsValue, JsValue> {
    split_for_regions_js(js(&format!(
        r#"{{"mixture":{ONE_GAUSSIAN},"regions":[{{"box":{{"min":[0.5,-5],"max":[5,5]}}}}]{extra}}}"#
    )))
}

#[wasm_bindgen_test]
fn split_library_reproduces_table_i() {
    let t = split_library_js(js(r#"{"components":4,"lambda":0.001}"#)).unwrap();
    assert_eq!(
        nums(&get(&t, "weights")),
        vec![
            0.10766586425362,
            0.39233413574638,
            0.39233413574638,
            0.10766586425362
        ]
    );
    assert_eq!(nums(&get(&t, "means"))[3], 1.42237156603631);
    assert_eq!(num(&t, "sigma"), 0.58160633157686);
    assert!((num(&t, "objective") - 4.123_605_388_7e-4).abs() < 1e-14);
    assert!((num(&t, "variance") - 0.9503).abs() < 5e-5);
    // Free means: lower J (3.60e-4), still symmetric and normalised.
    let f = split_library_js(js(r#"{"components":4,"lambda":0.001,"spacing":"free"}"#)).unwrap();
    assert!((num(&f, "objective") - 3.595_108_527_7e-4).abs() < 1e-13);
    let w = nums(&get(&f, "weights"));
    assert!((w.iter().sum::<f64>() - 1.0).abs() < 1e-14);
    let m = nums(&get(&f, "means"));
    assert_eq!(m[0], -m[3]);
    // R = 3 (the splitForRegions default).
    let r3 = split_library_js(js(r#"{"components":3,"lambda":0.001,"spacing":"equal"}"#)).unwrap();
    assert!((num(&r3, "sigma") - 0.671_566_545_496_193).abs() < 1e-12);
}

#[wasm_bindgen_test]
fn split_library_bad_input() {
    assert_throws(
        split_library_js(js(r#"{"lambda":0.001}"#)),
        "TypeError",
        "components",
    );
    assert_throws(
        split_library_js(js(r#"{"components":1,"lambda":0.001}"#)),
        "RangeError",
        "components",
    );
    assert_throws(
        split_library_js(js(r#"{"components":2.5,"lambda":0.001}"#)),
        "RangeError",
        "components",
    );
    assert_throws(
        split_library_js(js(r#"{"components":3}"#)),
        "TypeError",
        "lambda",
    );
    assert_throws(
        split_library_js(js(r#"{"components":3,"lambda":0}"#)),
        "RangeError",
        "lambda",
    );
    assert_throws(
        split_library_js(js(r#"{"components":3,"lambda":0.01,"spacing":"odd"}"#)),
        "RangeError",
        "spacing",
    );
    assert_throws(
        split_library_js(js(r#"{"components":3,"lambda":0.01,"spacing":1}"#)),
        "TypeError",
        "spacing",
    );
    assert_throws(split_library_js(JsValue::UNDEFINED), "TypeError", "options");
}

#[wasm_bindgen_test]
fn split_for_regions_shapes_and_values() {
    let out = split("").unwrap();
    let mixture = get(&out, "mixture");
    let comps = Array::from(&mixture);
    assert!(comps.length() > 10);
    // Same shape as the input: weight, 4-vector mean, 4 × 4 nested covariance.
    let c0 = comps.get(0);
    assert_eq!(nums(&get(&c0, "mean")).len(), 4);
    let cov = Array::from(&get(&c0, "cov"));
    assert_eq!(cov.length(), 4);
    assert_eq!(nums(&cov.get(2)).len(), 4);
    let w = weights(&mixture);
    assert!((w.iter().sum::<f64>() - 1.0).abs() < 1e-13);
    let (inside, outside) = (num(&out, "inside"), num(&out, "outside"));
    assert!((inside + outside - 1.0).abs() < 1e-13);
    // P(0.5 ≤ x ≤ 5, |y| ≤ 5) ≈ P(x ≥ 0.5) = 0.3085 for x ~ N(0, 1): exact and partitioned.
    let exact = num(&out, "exactInside");
    assert!((exact - 0.308_537_538_725_986_9).abs() < 1e-6, "{exact}");
    assert!((inside - exact).abs() < 0.02, "{inside} vs {exact}");
    assert_eq!(get(&out, "stop"), JsValue::NULL);
    assert!(num(&out, "depth") >= 3.0 && num(&out, "splits") >= 3.0);
    // A re-split of the output changes nothing more than w_min allows (idempotent-ish):
    // the defaults reproduce bit for bit.
    assert_eq!(json(&split("").unwrap()), json(&out));
}

#[wasm_bindgen_test]
fn split_for_regions_inside_mask() {
    let out = split("").unwrap();
    let comps = Array::from(&get(&out, "mixture"));
    let mask: Vec<bool> = Array::from(&get(&out, "insideMask"))
        .iter()
        .map(|b| b.as_bool().expect("a boolean"))
        .collect();
    assert_eq!(mask.len(), comps.length() as usize);
    assert!(mask.iter().any(|&b| b) && mask.iter().any(|&b| !b));
    // Each flag is the box test of the component's position mean (x, y of the 4-D state).
    let mut selected = 0.0;
    for (c, &inside) in comps.iter().zip(&mask) {
        let m = nums(&get(&c, "mean"));
        assert_eq!(
            inside,
            (0.5..=5.0).contains(&m[0]) && (-5.0..=5.0).contains(&m[1])
        );
        if inside {
            selected += num(&c, "weight");
        }
    }
    assert!((selected - num(&out, "inside")).abs() < 1e-15);
    // maxDepth 0: nothing is split, the result is the partition of the input itself.
    let none = split(r#","maxDepth":0"#).unwrap();
    assert_eq!(json(&get(&none, "mixture")), json(&js(ONE_GAUSSIAN)));
    assert_eq!(json(&get(&none, "insideMask")), "[false]");
    assert_eq!(num(&none, "inside"), 0.0);
    assert_eq!(num(&none, "outside"), 1.0);
    // Only the first region decides the flags; the others only refine the split.
    let two = split_for_regions_js(js(&format!(
        r#"{{"mixture":{ONE_GAUSSIAN},"regions":[{{"disc":{{"center":[0,0],"radius":0.5}}}},
        {{"box":{{"min":[0.5,-5],"max":[5,5]}}}}]}}"#
    )))
    .unwrap();
    for (c, b) in Array::from(&get(&two, "mixture"))
        .iter()
        .zip(Array::from(&get(&two, "insideMask")).iter())
    {
        let m = nums(&get(&c, "mean"));
        assert_eq!(b.as_bool(), Some(m[0] * m[0] + m[1] * m[1] <= 0.25));
    }
}

#[wasm_bindgen_test]
fn split_for_regions_is_invariant_to_region_order() {
    let regions = [
        r#"{"box":{"min":[-1,-0.5],"max":[0.8,2]}}"#,
        r#"{"polygon":[[1,-2],[3,-1],[1.5,0],[3,1.5],[0.5,1]]}"#,
        r#"{"disc":{"center":[-0.5,-1.5],"radius":0.9}}"#,
    ];
    let run = |order: [usize; 3]| {
        let list: Vec<&str> = order.iter().map(|&i| regions[i]).collect();
        let out = split_for_regions_js(js(&format!(
            r#"{{"mixture":{ONE_GAUSSIAN},"regions":[{}],"minWeight":0.005}}"#,
            list.join(",")
        )))
        .unwrap();
        json(&get(&out, "mixture"))
    };
    let reference = run([0, 1, 2]);
    assert!(reference.len() > 1000);
    for order in [[2, 1, 0], [1, 0, 2], [2, 0, 1]] {
        assert_eq!(run(order), reference);
    }
}

#[wasm_bindgen_test]
fn split_for_regions_caps() {
    let capped = split(r#","minWeight":0,"maxComponents":10"#).unwrap();
    assert_eq!(
        get(&capped, "stop").as_string().as_deref(),
        Some("maxComponents")
    );
    assert!(Array::from(&get(&capped, "mixture")).length() <= 10);
    let shallow = split(r#","minWeight":0,"maxDepth":2"#).unwrap();
    assert_eq!(
        get(&shallow, "stop").as_string().as_deref(),
        Some("maxDepth")
    );
    assert_eq!(num(&shallow, "depth"), 2.0);
    // Custom library and grid.
    let r4 = split(r#","components":4,"lambda":0.001,"gridPoints":21,"gridBound":3"#).unwrap();
    assert!((weights(&get(&r4, "mixture")).iter().sum::<f64>() - 1.0).abs() < 1e-13);
}

#[wasm_bindgen_test]
fn split_for_regions_bad_input() {
    let m = ONE_GAUSSIAN;
    let call = |body: &str| split_for_regions_js(js(body));
    assert_throws(call(r#"{"regions":[]}"#), "TypeError", "mixture");
    assert_throws(
        call(&format!(r#"{{"mixture":{m}}}"#)),
        "TypeError",
        "regions",
    );
    assert_throws(
        call(&format!(r#"{{"mixture":{m},"regions":[]}}"#)),
        "RangeError",
        "regions",
    );
    assert_throws(
        call(&format!(r#"{{"mixture":{m},"regions":{{}}}}"#)),
        "TypeError",
        "regions",
    );
    // Region errors name regions[i] (the fov converter, given that path).
    assert_throws(
        call(&format!(
            r#"{{"mixture":{m},"regions":[{{"box":{{"min":[0,0],"max":[1,1]}}}},{{"disc":{{"center":[0,0],"radius":-1}}}}]}}"#
        )),
        "RangeError",
        "regions[1].disc.radius",
    );
    assert_throws(
        call(&format!(r#"{{"mixture":{m},"regions":[{{"circle":1}}]}}"#)),
        "TypeError",
        "regions[0]",
    );
    assert_throws(
        call(&format!(
            r#"{{"mixture":{m},"regions":[{{"polygon":[[0,0],[1,0,2],[0,1]]}}]}}"#
        )),
        "RangeError",
        "regions[0].polygon[1]",
    );
    // A region of the wrong dimension.
    assert_throws(
        call(&format!(
            r#"{{"mixture":{m},"regions":[{{"box":{{"min":[0,0,0],"max":[1,1,1]}}}}]}}"#
        )),
        "RangeError",
        "regions[0]",
    );
    // Mixture errors name the component.
    assert_throws(
        call(
            r#"{"mixture":[{"weight":1,"mean":[0,0],"cov":[[1,0],[0,1]]},{"weight":1,"mean":[0,0],"cov":[[1,2],[2,1]]}],
            "regions":[{"box":{"min":[0,0],"max":[1,1]}}]}"#,
        ),
        "RangeError",
        "mixture[1].cov",
    );
    assert_throws(
        call(
            r#"{"mixture":[{"weight":-1,"mean":[0,0],"cov":[[1,0],[0,1]]}],
            "regions":[{"box":{"min":[0,0],"max":[1,1]}}]}"#,
        ),
        "RangeError",
        "mixture[0].weight",
    );
    let bad = [
        (r#","minWeight":-1"#, "RangeError", "minWeight"),
        (r#","minWeight":"x""#, "TypeError", "minWeight"),
        (r#","positionDims":5"#, "RangeError", "positionDims"),
        (r#","positionDims":0"#, "RangeError", "positionDims"),
        (r#","components":20"#, "RangeError", "components"),
        (r#","lambda":-1"#, "RangeError", "lambda"),
        (r#","gridPoints":1"#, "RangeError", "gridPoints"),
        (r#","gridPoints":200"#, "RangeError", "gridPoints"),
        (r#","gridBound":0"#, "RangeError", "gridBound"),
        (r#","maxDepth":65"#, "RangeError", "maxDepth"),
        (r#","maxComponents":0"#, "RangeError", "maxComponents"),
        (r#","spacing":"wide""#, "RangeError", "spacing"),
    ];
    for (extra, class, field) in bad {
        assert_throws(split(extra), class, field);
    }
    // The worst-case work budget: 50000 components × 141² grid points × (box + disc).
    assert_throws(
        call(&format!(
            r#"{{"mixture":{m},"regions":[{{"box":{{"min":[0,0],"max":[1,1]}}}},
            {{"disc":{{"center":[0,0],"radius":1}}}}],"maxComponents":50000,"gridPoints":141}}"#
        )),
        "RangeError",
        "maxComponents",
    );
}

#[wasm_bindgen_test]
fn reduce_mixture_shapes_values_and_errors() {
    let c = |x: f64, w: f64| format!(r#"{{"weight":{w},"mean":[{x},0],"cov":[[1,0],[0,1]]}}"#);
    let m = format!(
        "[{},{},{},{},{}]",
        c(0.0, 0.4),
        c(0.5, 0.3),
        c(4.0, 0.2),
        c(8.0, 0.099),
        c(20.0, 0.001)
    );
    let total = 1.0;
    // Prune only: the 0.001 component goes, the rest is rescaled.
    let p = reduce_mixture_js(js(&format!(r#"{{"mixture":{m},"pruneBelow":0.01}}"#))).unwrap();
    let w = weights(&p);
    assert_eq!(w.len(), 4);
    assert!((w.iter().sum::<f64>() - total).abs() < 1e-15);
    // Merge within Mahalanobis distance 1: 0 and 0.5 merge (moments preserved).
    let mg = reduce_mixture_js(js(&format!(r#"{{"mixture":{m},"mergeDistance":1}}"#))).unwrap();
    let comps = Array::from(&mg);
    assert_eq!(comps.length(), 4);
    let first = comps.get(0);
    assert!((num(&first, "weight") - 0.7).abs() < 1e-15);
    let mean = 0.3 * 0.5 / 0.7;
    assert!((nums(&get(&first, "mean"))[0] - mean).abs() < 1e-15);
    let var = (0.4 * (1.0 + mean * mean) + 0.3 * (1.0 + (0.5 - mean) * (0.5f64 - mean))) / 0.7;
    let cov = Array::from(&get(&first, "cov"));
    assert!((nums(&cov.get(0))[0] - var).abs() < 1e-14);
    // Runnalls down to two components; everything together.
    let r = reduce_mixture_js(js(&format!(r#"{{"mixture":{m},"maxComponents":2}}"#))).unwrap();
    assert_eq!(weights(&r).len(), 2);
    assert!((weights(&r).iter().sum::<f64>() - total).abs() < 1e-15);
    let all = reduce_mixture_js(js(&format!(
        r#"{{"mixture":{m},"pruneBelow":0.01,"mergeDistance":2,"maxComponents":1}}"#
    )))
    .unwrap();
    assert_eq!(weights(&all).len(), 1);
    // No pass asked: unchanged.
    let same = reduce_mixture_js(js(&format!(r#"{{"mixture":{m}}}"#))).unwrap();
    assert_eq!(weights(&same), vec![0.4, 0.3, 0.2, 0.099, 0.001]);
    let bad = [
        (r#","pruneBelow":-1"#, "RangeError", "pruneBelow"),
        (r#","mergeDistance":"x""#, "TypeError", "mergeDistance"),
        (r#","mergeDistance":-2"#, "RangeError", "mergeDistance"),
        (r#","maxComponents":0"#, "RangeError", "maxComponents"),
        (r#","maxComponents":1.5"#, "RangeError", "maxComponents"),
    ];
    for (extra, class, field) in bad {
        assert_throws(
            reduce_mixture_js(js(&format!(r#"{{"mixture":{m}{extra}}}"#))),
            class,
            field,
        );
    }
    assert_throws(reduce_mixture_js(js("{}")), "TypeError", "mixture");
    assert_throws(
        reduce_mixture_js(js(r#"{"mixture":[{"weight":1,"mean":[0]}]}"#)),
        "TypeError",
        "mixture[0].cov",
    );
}

#[wasm_bindgen_test]
fn negative_information_scenario_steps() {
    let all = negative_information_scenario_js(None).unwrap();
    let steps = Array::from(&get(&all, "steps"));
    assert_eq!(steps.length(), 3);
    assert_eq!(
        json(&get(&all, "fov")),
        r#"{"box":{"min":[-1.5,-1.5],"max":[1.5,1.5]}}"#
    );
    assert_eq!(weights(&get(&all, "initial")), vec![0.7, 0.3]);
    for (k, s) in steps.iter().enumerate() {
        assert_eq!(num(&s, "step"), (k + 1) as f64);
        let post = weights(&get(&s, "posterior"));
        assert!((post.iter().sum::<f64>() - 1.0).abs() < 1e-13);
        let split = Array::from(&get(&s, "split")).length() as usize;
        assert!(split > post.len() && split < 300);
        assert!(num(&s, "posteriorInside") < num(&s, "predictedInside"));
        let nd = num(&s, "nonDetectionProb");
        assert!(nd > 0.0 && nd < 1.0);
    }
    let two = negative_information_scenario_js(Some(js(r#"{"step":2}"#))).unwrap();
    assert_eq!(json(&two), json(&steps.get(1)));
    assert_throws(
        negative_information_scenario_js(Some(js(r#"{"step":4}"#))),
        "RangeError",
        "step",
    );
    assert_throws(
        negative_information_scenario_js(Some(js(r#"{"step":"2"}"#))),
        "TypeError",
        "step",
    );
}
