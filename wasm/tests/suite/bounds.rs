use super::{assert_throws, get, js, num, nums};
use fisst_wasm::{
    gaussian_fisher_information, jde_bound, jde_bound_no_clutter, jde_example2,
    jde_example2_regularity, jde_sequential_bound,
};
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
    #[rustfmt::skip]
    let cases = [
        (r#"{"existence":1.5,"detectionProbability":0.4,"priorVariance":100,"posteriorVariance":25,"falseAlarmError":150,"missError":200}"#, "RangeError", "options.existence"),
        (r#"{"existence":0.5,"detectionProbability":0.4,"priorVariance":10,"posteriorVariance":25,"falseAlarmError":150,"missError":200}"#, "RangeError", "options.posteriorVariance"),
        (r#"{"existence":0.5}"#, "TypeError", "options"),
    ];
    for (input, class, needle) in cases {
        assert_throws(jde_bound_no_clutter(js(input)), class, needle);
    }
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
    #[rustfmt::skip]
    let cases = [
        (r#"{"method":"irf","priorInformation":0.01,"detectedInformation":0.04,"detectionProbability":0.6,"steps":0}"#, "RangeError", "options.steps"),
        (r#"{"method":"crb","priorInformation":0.01,"detectedInformation":0.04,"detectionProbability":0.6,"steps":3}"#, "RangeError", "options.method"),
        (r#"{"method":"irf","priorInformation":0.05,"detectedInformation":0.04,"detectionProbability":0.6,"steps":3}"#, "RangeError", "options.detectedInformation"),
    ];
    for (input, class, needle) in cases {
        assert_throws(jde_sequential_bound(js(input)), class, needle);
    }
}

fn native_model_i(q: f64) -> fisst::bounds::JdeBound {
    use fisst::bounds::*;
    let prior = Density1::gaussian(1.0, 4.0).unwrap();
    let obs = LinearGaussian::new(Detection::constant(0.8).unwrap(), 1.0, 0.0, 1.0).unwrap();
    let psi = Density1::uniform(-10.0, 10.0).unwrap();
    theorem1(
        &ModelI {
            existence: 0.6,
            prior: &prior,
            observation: &obs,
            false_alarm_probability: q,
            false_alarm_density: &psi,
            false_alarm_error: 6.0,
            miss_error: 9.0,
        },
        &TheoremOptions::default(),
    )
    .unwrap()
}

#[wasm_bindgen_test]
fn jde_bound_model_i_matches_the_core() {
    let r = jde_bound(js(
        r#"{"model":"I","existence":0.6,"prior":{"gaussian":{"mean":1,"variance":4}},
            "observation":{"detectionProbability":0.8,"noiseVariance":1},
            "falseAlarm":{"probability":0.3,"density":{"uniform":{"low":-10,"high":10}}},
            "falseAlarmError":6,"missError":9}"#,
    ))
    .unwrap();
    let b = native_model_i(0.3);
    assert_eq!(num(&r, "bound"), b.assembled.bound);
    assert_eq!(num(&r, "eta"), b.eta);
    let terms = js_sys::Array::from(&get(&r, "terms"));
    assert_eq!(terms.length(), 4);
    let sum: f64 = terms.iter().map(|t| num(&t, "value")).sum();
    assert!((sum - num(&r, "bound")).abs() < 1e-12);
    assert_eq!(
        get(&terms.get(0), "name").as_string().as_deref(),
        Some("estimation")
    );
    let phase = get(&r, "phase").as_string().unwrap();
    assert!(phase == "HPE" || phase == "LPE");
    assert_eq!(get(&r, "regular").as_bool(), Some(true));
}

#[wasm_bindgen_test]
fn jde_bound_model_ii_is_seeded_and_reproducible() {
    let opts = r#"{"model":"II","existence":0.7,"prior":{"mixture":[{"weight":1,"mean":-1,"variance":1},{"weight":1,"mean":2,"variance":2}]},
            "observation":{"detectionProbability":{"table":{"x":[-3,3],"probability":[0.6,0.9]}},"gain":1.5,"noiseVariance":0.5},
            "clutter":{"rate":1,"density":{"table":{"x":[-15,0,15],"density":[1,2,1]}}},
            "falseAlarmError":6,"missError":9,"samples":500,"seed":3}"#;
    let a = jde_bound(js(opts)).unwrap();
    let b = jde_bound(js(opts)).unwrap();
    assert_eq!(num(&a, "bound"), num(&b, "bound"));
    assert_eq!(num(&a, "seed"), 3.0);
    let cards = js_sys::Array::from(&get(&a, "cardinalities"));
    assert!(cards.length() > 2);
    assert_eq!(
        get(&cards.get(1), "method").as_string().as_deref(),
        Some("monte-carlo")
    );
    assert!(num(&a, "error") > 0.0);
}

#[wasm_bindgen_test]
fn jde_bound_errors_name_the_field() {
    let base = |extra: &str| {
        js(&format!(
            r#"{{"model":"I","existence":0.6,"prior":{{"gaussian":{{"mean":1,"variance":4}}}},
                "observation":{{"detectionProbability":0.8,"noiseVariance":1}},
                "falseAlarmError":6,"missError":9{extra}}}"#
        ))
    };
    assert!(jde_bound(base("")).is_ok());
    #[rustfmt::skip]
    let cases = [
        (r#","dims":2"#, "RangeError", "options.dims"),
        (r#","falseAlarm":{"probability":2,"density":{"uniform":{"low":0,"high":1}}}"#, "RangeError", "options.falseAlarm.probability"),
        (r#","falseAlarm":{"probability":0.2,"density":{"uniform":{"low":1,"high":0}}}"#, "RangeError", "options.falseAlarm.density.uniform.high"),
        (r#","clutter":{"rate":1,"density":{"uniform":{"low":0,"high":1}}}"#, "TypeError", "options.clutter"),
    ];
    for (input, class, needle) in cases {
        assert_throws(jde_bound(base(input)), class, needle);
    }
    #[rustfmt::skip]
    let cases = [
        (r#"{"model":"III","existence":0.6,"prior":{"gaussian":{"mean":1,"variance":4}},"observation":{"detectionProbability":0.8,"noiseVariance":1},"falseAlarmError":6,"missError":9}"#, "RangeError", "options.model"),
        (r#"{"model":"I","existence":0.6,"prior":{"table":{"x":[0,1],"density":[0,0]}},"observation":{"detectionProbability":0.8,"noiseVariance":1},"falseAlarmError":6,"missError":9}"#, "RangeError", "options.prior.table.density"),
        (r#"{"model":"I","existence":0.6,"prior":{"gaussian":{"mean":1,"variance":4}},"observation":{"detectionProbability":{"table":{"x":[0,1],"probability":[0.5,1.5]}},"noiseVariance":1},"falseAlarmError":6,"missError":9}"#, "RangeError", "options.observation.detectionProbability.table.probability[1]"),
    ];
    for (input, class, needle) in cases {
        assert_throws(jde_bound(js(input)), class, needle);
    }
}

#[wasm_bindgen_test]
fn example_2_and_its_regularity_failure() {
    let r = jde_example2_regularity().unwrap();
    assert!((num(&r, "inverseInformation") - 0.1897).abs() < 5e-5);
    assert!((num(&r, "posteriorMeanMse") - 0.0340).abs() < 5e-5);
    let e = jde_example2(js(
        r#"{"existence":0.6,"detectionProbability":0.9,"falseAlarmProbability":1,"falseAlarmError":1.2}"#,
    ))
    .unwrap();
    let native = fisst::bounds::example2(0.6, 0.9, 1.0, 1.2, None).unwrap();
    assert_eq!(num(&e, "bound"), native.bound);
    assert_eq!(num(&e, "paperBound"), native.paper_bound);
    assert_throws(
        jde_example2(js(
            r#"{"existence":0.6,"detectionProbability":0.9,"falseAlarmProbability":-1,"falseAlarmError":1.2}"#,
        )),
        "RangeError",
        "options.falseAlarmProbability",
    );
}

fn native_vector(q: f64) -> fisst::bounds::VectorBound {
    use fisst::bounds::*;
    let prior = GaussianPrior::new(&[0.5, -1.0], &[4.0, 1.2, 1.2, 2.0]).unwrap();
    let sensor = LinearGaussianSensor::new(0.8, &[1.0, 0.5], 2, &[0.2], &[1.0]).unwrap();
    let psi = Density1::uniform(-10.0, 10.0).unwrap();
    vector_bound(
        &VectorModel {
            existence: 0.6,
            prior: &prior,
            sensor: &sensor,
            measurement: VectorMeasurement::I {
                false_alarm_probability: q,
                false_alarm_density: &psi,
            },
            false_alarm_error: 6.0,
            miss_error: 9.0,
        },
        &TheoremOptions::default(),
    )
    .expect("the core's vector bound")
}

#[wasm_bindgen_test]
fn jde_bound_vector_state_matches_the_core() {
    let r = jde_bound(js(
        r#"{"model":"I","existence":0.6,"prior":{"multivariateGaussian":{"mean":[0.5,-1],"cov":[[4,1.2],[1.2,2]]}},
            "observation":{"detectionProbability":0.8,"gain":[[1,0.5]],"offset":[0.2],"noiseCov":[[1]]},
            "falseAlarm":{"probability":0.3,"density":{"uniform":{"low":-10,"high":10}}},
            "falseAlarmError":6,"missError":9,"dims":2}"#,
    ))
    .unwrap();
    let v = native_vector(0.3);
    assert_eq!(num(&r, "bound"), v.total.assembled.bound);
    assert_eq!(num(&r, "undetectedVariance"), 6.0);
    let comps = js_sys::Array::from(&get(&r, "components"));
    assert_eq!(comps.length(), 2);
    for (i, c) in v.components.iter().enumerate() {
        let got = comps.get(i as u32);
        assert_eq!(num(&got, "bound"), c.assembled.bound);
        assert_eq!(num(&got, "hpe"), c.assembled.hpe);
        assert_eq!(num(&got, "lpe"), c.assembled.lpe);
        assert_eq!(num(&got, "inverseInformation"), c.inverse_information);
        assert_eq!(num(&got, "error"), c.error);
        let terms = js_sys::Array::from(&get(&got, "terms"));
        let sum: f64 = terms.iter().map(|t| num(&t, "value")).sum();
        assert!((sum - c.assembled.bound).abs() < 1e-12);
    }
    let rows = js_sys::Array::from(&get(&r, "inverseInformationMatrix"));
    assert_eq!(rows.length(), 2);
    for i in 0..2 {
        assert_eq!(
            nums(&rows.get(i as u32)),
            v.inverse_information[2 * i..2 * i + 2]
        );
    }
    // A 1D prior has neither field.
    let s = jde_bound(js(
        r#"{"model":"I","existence":0.6,"prior":{"gaussian":{"mean":1,"variance":4}},
            "observation":{"detectionProbability":0.8,"noiseVariance":1},"falseAlarmError":6,"missError":9}"#,
    ))
    .unwrap();
    assert!(get(&s, "components").is_undefined());
    assert!(get(&s, "inverseInformationMatrix").is_undefined());
}

#[wasm_bindgen_test]
fn jde_bound_vector_errors_name_the_field() {
    let base = |prior: &str, obs: &str, extra: &str| {
        js(&format!(
            r#"{{"model":"II","existence":0.6,"prior":{{"multivariateGaussian":{prior}}},
                "observation":{obs},"falseAlarmError":6,"missError":9{extra}}}"#
        ))
    };
    let good_prior = r#"{"mean":[0,0],"cov":[[1,0],[0,1]]}"#;
    let two = r#"{"detectionProbability":0.8,"gain":[[1,0],[0,1]],"noiseCov":[[1,0],[0,1]]}"#;
    assert!(jde_bound(base(good_prior, two, "")).is_ok());
    assert_throws(
        jde_bound(base(good_prior, two, r#","dims":3"#)),
        "RangeError",
        "options.dims",
    );
    assert_throws(
        jde_bound(base(
            good_prior,
            two,
            r#","clutter":{"rate":1,"density":{"uniform":{"low":0,"high":1}}}"#,
        )),
        "RangeError",
        "options.observation.gain",
    );
    assert_throws(
        jde_bound(base(r#"{"mean":[0,0],"cov":[[1,2],[2,1]]}"#, two, "")),
        "RangeError",
        "options.prior.multivariateGaussian.cov",
    );
    assert_throws(
        jde_bound(base(
            good_prior,
            r#"{"detectionProbability":0.8,"gain":[[1,0,0]],"noiseVariance":1}"#,
            "",
        )),
        "RangeError",
        "options.observation.gain[0]",
    );
    assert_throws(
        jde_bound(base(
            good_prior,
            r#"{"detectionProbability":0.8,"gain":[[1,0],[0,1]],"noiseVariance":1}"#,
            "",
        )),
        "TypeError",
        "options.observation.noiseVariance",
    );
    assert_throws(
        jde_bound(base(
            good_prior,
            r#"{"detectionProbability":0.8,"gain":[[1,0],[0,1]],"noiseCov":[[1,0],[0,-1]]}"#,
            "",
        )),
        "RangeError",
        "options.observation.noiseCov",
    );
    assert_throws(
        jde_bound(base(good_prior, two, r#","quadratureCardinality":3"#)),
        "RangeError",
        "options.quadratureCardinality",
    );
}
