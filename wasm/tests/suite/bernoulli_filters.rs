//! The Bernoulli filters of paper 001, Section V (`gmBernoulliPredict`, `gmBernoulliUpdate`,
//! `GmBernoulliFilter`, `ParticleBernoulliFilter`, `airportScenario`): shapes, values against
//! the core called directly, errors, and objects left as they were after a throw.
use super::{assert_throws, get, js, json, num, nums};
use fisst::filters::{self as core, EstimateOptions, GmBernoulli, ParticleOptions, UpdateOptions};
use fisst::gaussian::{Gaussian, GaussianMixture};
use fisst::regions::Region;
use fisst_wasm::{
    GmBernoulliFilterJs, ParticleBernoulliFilterJs, airport_scenario, gm_bernoulli_predict,
    gm_bernoulli_update,
};
use wasm_bindgen::JsValue;
use wasm_bindgen_test::wasm_bindgen_test;

fn keys(v: &JsValue) -> String {
    json(&js_sys::Object::keys(&js_sys::Object::from(v.clone())).into())
}

/// The NCV model (70)–(71) with T = 1, ϖ = 0.01, as JSON.
const NCV: &str = r#"{"F":[[1,0,1,0],[0,1,0,1],[0,0,1,0],[0,0,0,1]],
  "Q":[[0.0033333333333333335,0,0.005,0],[0,0.0033333333333333335,0,0.005],[0.005,0,0.01,0],[0,0.005,0,0.01]]}"#;
const PRIOR: &str =
    r#"[{"weight":1,"mean":[0,0,1,0],"cov":[[4,0,0,0],[0,4,0,0],[0,0,0.1,0],[0,0,0,0.1]]}]"#;

fn config(extra: &str) -> JsValue {
    js(&format!(
        r#"{{"existence":0.8,"mixture":{PRIOR},"transition":{NCV},"detection":{{"probability":0.9}},
            "clutter":{{"rate":0.25,"density":0.1}},"particles":300,"seed":5{extra}}}"#
    ))
}

/// The core's Bernoulli of the same prior.
fn core_prior(existence: f64) -> GmBernoulli {
    let cov = [
        4.0, 0.0, 0.0, 0.0, 0.0, 4.0, 0.0, 0.0, 0.0, 0.0, 0.1, 0.0, 0.0, 0.0, 0.0, 0.1,
    ];
    let c = Gaussian::from_slices(&[0.0, 0.0, 1.0, 0.0], &cov, "prior").unwrap();
    GmBernoulli::new(
        existence,
        GaussianMixture::new(vec![(1.0, c)], "prior").unwrap(),
    )
    .unwrap()
}

fn core_update_config() -> UpdateOptions {
    UpdateOptions::new(
        2,
        core::Detection::new(0.9, None).unwrap(),
        core::Clutter::new(0.25, core::ClutterDensity::Constant(0.1)).unwrap(),
    )
}

#[wasm_bindgen_test]
fn predict_is_41_and_46_to_49() {
    let out = gm_bernoulli_predict(js(&format!(
        r#"{{"existence":0.6,"mixture":{PRIOR},"transition":{NCV},"survival":0.95,
            "birth":{{"probability":0.1,"mixture":[{{"weight":1,"mean":[5,5,0,0],"cov":[[1,0,0,0],[0,1,0,0],[0,0,1,0],[0,0,0,1]]}}]}}}}"#
    )))
    .unwrap();
    assert_eq!(keys(&out), r#"["existence","mixture"]"#);
    // (41): r = p_b (1 − r′) + p_S r′.
    let r = 0.1 * 0.4 + 0.95 * 0.6;
    assert!((num(&out, "existence") - r).abs() < 1e-15);
    let mix = js_sys::Array::from(&get(&out, "mixture"));
    assert_eq!(mix.length(), 2);
    // The birth term first, weight p_b (1 − r′)/r; the survival term F m, F P Fᵀ + Q.
    assert!((num(&mix.get(0), "weight") - 0.04 / r).abs() < 1e-15);
    assert_eq!(nums(&get(&mix.get(1), "mean")), vec![1.0, 0.0, 1.0, 0.0]);
    let cov = js_sys::Array::from(&get(&mix.get(1), "cov"));
    assert!((nums(&cov.get(0))[0] - (4.0 + 0.1 + 1.0 / 300.0)).abs() < 1e-12);
    assert!((nums(&cov.get(0))[2] - (0.1 + 0.005)).abs() < 1e-15);
}

#[wasm_bindgen_test]
fn an_empty_scan_is_the_non_detection_update() {
    // (54) with no report: r = r′(1 − Δ)/(1 − r′Δ), Δ = p_D ∫ p = 0.9 (no FoV): the Poisson
    // clutter's empty-scan probability e^{−λ_c} cancels, so 0.8·0.1/(1 − 0.72) = 0.2857.
    let out = gm_bernoulli_update(js(&format!(
        r#"{{"existence":0.8,"mixture":{PRIOR},"detection":{{"probability":0.9}},"reports":[],
            "clutter":{{"rate":0.25,"density":0.1}}}}"#
    )))
    .unwrap();
    assert_eq!(
        keys(&out),
        r#"["existence","mixture","delta","splitComponents"]"#
    );
    assert!((num(&out, "existence") - 0.08 / 0.28).abs() < 1e-15);
    assert!((num(&out, "existence") - 0.2857).abs() < 5e-5);
    assert!((num(&out, "delta") - 0.9).abs() < 1e-15);
    // The spatial density is unchanged by a constant p_D.
    let mix = js_sys::Array::from(&get(&out, "mixture"));
    assert_eq!(mix.length(), 1);
    assert_eq!(nums(&get(&mix.get(0), "mean")), vec![0.0, 0.0, 1.0, 0.0]);
    // Both classes give the same.
    let mut gm = GmBernoulliFilterJs::new(config("")).unwrap();
    gm.update(js("[]")).unwrap();
    assert!((gm.existence() - 0.08 / 0.28).abs() < 1e-12);
    let mut pf = ParticleBernoulliFilterJs::new(config("")).unwrap();
    pf.update(js("[]")).unwrap();
    assert!((pf.existence() - 0.08 / 0.28).abs() < 1e-12);
}

#[wasm_bindgen_test]
fn update_with_reports_equals_the_core() {
    let reports = r#"[{"disc":{"center":[1,0],"radius":1.5}},{"box":{"min":[5,5],"max":[7,8]}}]"#;
    let out = gm_bernoulli_update(js(&format!(
        r#"{{"existence":0.8,"mixture":{PRIOR},"detection":{{"probability":0.9}},"reports":{reports},
            "clutter":{{"rate":0.25,"density":0.1}}}}"#
    )))
    .unwrap();
    let regions = vec![
        Region::ball(&[1.0, 0.0], 1.5, "r0").unwrap(),
        Region::axis_box(&[5.0, 5.0], &[7.0, 8.0], "r1").unwrap(),
    ];
    let native =
        core::gm_bernoulli_update(&core_prior(0.8), &regions, &core_update_config()).unwrap();
    assert_eq!(num(&out, "existence"), native.existence);
    assert_eq!(num(&out, "delta"), native.delta);
    assert_eq!(num(&out, "splitComponents"), native.split_components as f64);
    let mix = js_sys::Array::from(&get(&out, "mixture"));
    assert_eq!(mix.length() as usize, native.mixture.len());
    for (i, (w, c)) in native.mixture.components().iter().enumerate() {
        assert_eq!(num(&mix.get(i as u32), "weight"), *w);
        assert_eq!(
            nums(&get(&mix.get(i as u32), "mean")),
            c.mean().as_slice().to_vec()
        );
    }
    // A report near the prior mean raises the existence above the prior's 0.8.
    assert!(native.existence > 0.8 && native.existence <= 1.0);
}

/// The report discs of step k of a scenario as JSON.
fn reports_of(s: &fisst::sim::airport::AirportScenario, k: usize) -> JsValue {
    let discs: Vec<String> = s.reports[k]
        .iter()
        .map(|&a| {
            let p = &s.anchors[a];
            format!(
                r#"{{"disc":{{"center":[{},{}],"radius":{}}}}}"#,
                p.position[0], p.position[1], p.radius
            )
        })
        .collect();
    js(&format!("[{}]", discs.join(",")))
}

#[wasm_bindgen_test]
fn airport_scenario_and_both_classes_equal_the_core() {
    let s = airport_scenario(Some(js(r#"{"seed":11,"steps":8}"#))).unwrap();
    assert_eq!(
        keys(&s),
        r#"["anchors","exclusions","concourse","fov","dt","config","truth","reports","trueReports","inFov","seed"]"#
    );
    assert_eq!(num(&s, "seed"), 11.0);
    assert_eq!(js_sys::Array::from(&get(&s, "anchors")).length(), 10);
    assert_eq!(js_sys::Array::from(&get(&s, "truth")).length(), 8);
    assert_eq!(js_sys::Array::from(&get(&s, "exclusions")).length(), 5);
    let native = fisst::sim::airport::airport_scenario(11, 8).unwrap();
    let reports = js_sys::Array::from(&get(&s, "reports"));
    for k in 0..8 {
        assert_eq!(
            json(&reports.get(k as u32)),
            json(&js(&format!("{:?}", native.reports[k])))
        );
    }
    // The same seed gives the same scenario.
    assert_eq!(
        json(&airport_scenario(Some(js(r#"{"seed":11,"steps":8}"#))).unwrap()),
        json(&s)
    );
    // The JS config through both classes equals the core filters on the core's config.
    let config = get(&s, "config");
    js_sys::Reflect::set(&config, &"particles".into(), &JsValue::from_f64(400.0)).unwrap();
    let mut gm = GmBernoulliFilterJs::new(config.clone()).unwrap();
    let mut pf = ParticleBernoulliFilterJs::new(config).unwrap();
    let mut gm_core = core::GmBernoulliFilter::new(native.config.clone()).unwrap();
    let options = ParticleOptions {
        particles: 400,
        birth_particles: None,
        mcmc_moves: 1,
        seed: 11,
    };
    let mut pf_core = core::ParticleBernoulliFilter::new(native.config.clone(), options).unwrap();
    for k in 0..8 {
        let regions: Vec<Region> = native.reports[k]
            .iter()
            .map(|&a| {
                let p = &native.anchors[a];
                Region::ball(&p.position, p.radius, "report").unwrap()
            })
            .collect();
        gm.predict().unwrap();
        pf.predict();
        gm_core.predict().unwrap();
        pf_core.predict();
        let info = gm.update(reports_of(&native, k)).unwrap();
        pf.update(reports_of(&native, k)).unwrap();
        let info_core = gm_core.update(&regions).unwrap();
        pf_core.update(&regions).unwrap();
        assert_eq!(gm.existence(), gm_core.existence(), "GM step {k}");
        assert_eq!(pf.existence(), pf_core.existence(), "PF step {k}");
        assert_eq!(num(&info, "delta"), info_core.delta);
        assert_eq!(
            js_sys::Array::from(&gm.mixture().unwrap()).length() as usize,
            gm_core.mixture().len()
        );
    }
    let e = gm.estimate(JsValue::UNDEFINED).unwrap();
    assert_eq!(keys(&e), r#"["existence","mean","cov","report"]"#);
    assert!(get(&e, "report").is_null());
    let native_e = gm_core.estimate(&EstimateOptions::default()).unwrap();
    assert_eq!(nums(&get(&e, "mean")), native_e.mean);
    let pe = pf.estimate(js(r#"{"radius":5,"costs":"mpe"}"#)).unwrap();
    assert_eq!(
        nums(&get(&pe, "mean")),
        pf_core.estimate(&EstimateOptions::default()).unwrap().mean
    );
    assert!(get(&get(&pe, "report"), "declare").as_bool().is_some());
    assert_eq!(js_sys::Array::from(&pf.particles().unwrap()).length(), 400);
    assert_eq!(pf.weights().len(), 400);
    assert_eq!(pf.seed(), 11.0);
}

#[wasm_bindgen_test]
fn errors_name_the_field() {
    assert_throws(
        gm_bernoulli_predict(js(&format!(
            r#"{{"existence":1.5,"mixture":{PRIOR},"transition":{NCV}}}"#
        ))),
        "RangeError",
        "options.existence",
    );
    assert_throws(
        gm_bernoulli_predict(js(&format!(
            r#"{{"existence":0.5,"mixture":{PRIOR},"transition":{{"F":[[1,0],[0,1]],"Q":[[1,0],[0,1]]}}}}"#
        ))),
        "RangeError",
        "options.",
    );
    assert_throws(
        gm_bernoulli_update(js(&format!(
            r#"{{"existence":0.5,"mixture":{PRIOR},"detection":{{"probability":0.9}},"reports":[{{"disc":{{"center":[0,0],"radius":-1}}}}],
                "clutter":{{"rate":0.25,"density":0.1}}}}"#
        ))),
        "RangeError",
        "options.reports[0]",
    );
    assert_throws(
        gm_bernoulli_update(js(&format!(
            r#"{{"existence":0.5,"mixture":{PRIOR},"detection":{{"probability":0.9}},"measurements":[[0,0]],
                "clutter":{{"rate":0.25,"density":0.1}}}}"#
        ))),
        "RangeError",
        "options.likelihood",
    );
    assert_throws(
        GmBernoulliFilterJs::new(config(r#","detection":{"probability":2}"#))
            .map(|_| JsValue::NULL),
        "RangeError",
        "config.detection.probability",
    );
    assert_throws(
        ParticleBernoulliFilterJs::new(config(r#","particles":0"#)).map(|_| JsValue::NULL),
        "RangeError",
        "config.particles",
    );
    // An update error about the config (two reports, no clutter to explain the second) names
    // the config's field, not the scan's.
    let mut gm =
        GmBernoulliFilterJs::new(config(r#","clutter":{"rate":0,"density":0.1}"#)).unwrap();
    let two = r#"[{"disc":{"center":[0,0],"radius":1}},{"disc":{"center":[1,0],"radius":1}}]"#;
    assert_throws(gm.update(js(two)), "RangeError", "config.clutter.rate");
    // A 3-D report in a 2-D filter names the region's field and the config's (issue 26).
    assert_throws(
        gm.update(js(r#"[{"disc":{"center":[0,0,0],"radius":1}}]"#)),
        "RangeError",
        "reports[0].disc.center has length 3 but config.positionDims is 2",
    );
    // A 2 × 2 F with a 4-D mixture, a 2 × 2 Q with a 4 × 4 F: both fields, in matrix terms.
    assert_throws(
        GmBernoulliFilterJs::new(config(
            r#","transition":{"F":[[1,0],[0,1]],"Q":[[1,0],[0,1]]}"#,
        ))
        .map(|_| JsValue::NULL),
        "RangeError",
        "config.mixture[0].mean has length 4 but config.transition.F is 2×2",
    );
    assert_throws(
        gm_bernoulli_predict(js(&format!(
            r#"{{"existence":0.5,"mixture":{PRIOR},"transition":{{"F":{F4},"Q":[[1,0],[0,1]]}}}}"#,
            F4 = "[[1,0,1,0],[0,1,0,1],[0,0,1,0],[0,0,0,1]]"
        ))),
        "RangeError",
        "options.transition.Q is 2×2 but options.transition.F is 4×4",
    );
    assert_throws(
        airport_scenario(Some(js(r#"{"steps":2001}"#))),
        "RangeError",
        "options.steps",
    );
    assert_throws(
        airport_scenario(Some(js(r#"{"steps":-1}"#))),
        "RangeError",
        "options.steps",
    );
}

#[wasm_bindgen_test]
fn a_method_that_throws_leaves_the_filter_as_it_was() {
    let bad = [
        // A 3D report for a 2D position: the core's dimension check, after the read.
        r#"[{"disc":{"center":[0,0,0],"radius":1}}]"#,
        r#"[{"disc":{"center":[0,0],"radius":-1}}]"#,
        // Measurements without a likelihood in the config.
        r#"{"measurements":[[0,0]]}"#,
        r#"{"nothing":1}"#,
    ];
    let mut gm = GmBernoulliFilterJs::new(config("")).unwrap();
    gm.predict().unwrap();
    gm.update(js(r#"[{"disc":{"center":[1,0],"radius":2}}]"#))
        .unwrap();
    let mut pf = ParticleBernoulliFilterJs::new(config("")).unwrap();
    pf.predict();
    pf.update(js(r#"[{"disc":{"center":[1,0],"radius":2}}]"#))
        .unwrap();
    let (gm_r, gm_mix) = (gm.existence(), json(&gm.mixture().unwrap()));
    let (pf_r, pf_p) = (pf.existence(), json(&pf.particles().unwrap()));
    for b in bad {
        assert!(gm.update(js(b)).is_err(), "{b}");
        assert!(pf.update(js(b)).is_err(), "{b}");
        assert_eq!(gm.existence(), gm_r);
        assert_eq!(json(&gm.mixture().unwrap()), gm_mix);
        assert_eq!(pf.existence(), pf_r);
        assert_eq!(json(&pf.particles().unwrap()), pf_p);
    }
    assert_throws(
        gm.estimate(js(r#"{"radius":-1,"costs":"mpe"}"#)),
        "RangeError",
        "options.radius",
    );
    assert_throws(
        pf.estimate(js(r#"{"radius":1}"#)),
        "TypeError",
        "options.costs",
    );
    assert_eq!(json(&gm.mixture().unwrap()), gm_mix);
    // Still usable after the throws.
    gm.update(js("[]")).unwrap();
    pf.update(js("[]")).unwrap();
    assert!(gm.existence() < gm_r && pf.existence() < pf_r);
}
