use super::{assert_throws, get, js, num, nums};
use fisst_wasm::{
    fov_cardinality_js, fov_variance_map, mixture_density_grid_js, placement_scene_js,
};
use wasm_bindgen::JsCast;
use wasm_bindgen_test::wasm_bindgen_test;

/// A tight Gaussian at (x, y) (σ = 0.01), as JSON.
fn tight(x: f64, y: f64) -> String {
    format!(r#""mean":[{x},{y}],"cov":[[1e-4,0],[0,1e-4]]"#)
}

const UNIT_BOX: &str = r#"{"box":{"min":[-1,-1],"max":[1,1]}}"#;

fn cardinality(
    rfs: &str,
    fov: &str,
    extra: &str,
) -> Result<wasm_bindgen::JsValue, wasm_bindgen::JsValue> {
    fov_cardinality_js(js(&format!(r#"{{"rfs":{rfs},"fov":{fov}{extra}}}"#)))
}

#[wasm_bindgen_test]
fn multi_bernoulli_shapes_and_values() {
    // Two certain-ish objects inside, one outside: ρ_S is the Poisson binomial of (0.5, 0.8).
    let rfs = format!(
        r#"{{"multiBernoulli":[{{"existence":0.5,{}}},{{"existence":0.8,{}}},{{"existence":0.9,{}}}]}}"#,
        tight(0.0, 0.0),
        tight(0.5, -0.5),
        tight(5.0, 5.0)
    );
    let out = cardinality(&rfs, UNIT_BOX, "").unwrap();
    let pmf = nums(&get(&out, "pmf"));
    assert_eq!(pmf.len(), 4);
    let want = [0.5 * 0.2, 0.5 * 0.2 + 0.5 * 0.8, 0.4, 0.0];
    for (p, w) in pmf.iter().zip(want) {
        assert!((p - w).abs() < 1e-12, "{pmf:?}");
    }
    assert!((num(&out, "mean") - 1.3).abs() < 1e-12);
    assert!((num(&out, "variance") - (0.25 + 0.16)).abs() < 1e-12);
    let mass = nums(&get(&out, "massInFov"));
    assert_eq!(mass.len(), 3);
    assert!((mass[0] - 1.0).abs() < 1e-12 && mass[2] < 1e-12);
    // p_D halves every inclusion probability (eq. 75); massInFov is unchanged.
    let out = cardinality(&rfs, UNIT_BOX, r#","detectionProbability":0.5"#).unwrap();
    assert!((num(&out, "mean") - 0.65).abs() < 1e-12);
    assert!((nums(&get(&out, "massInFov"))[0] - 1.0).abs() < 1e-12);
}

#[wasm_bindgen_test]
fn regions_and_extra_state_components() {
    // A 4D state (x, y, vx, vy) under N(0, I): the FoV looks at (x, y) only.
    let rfs = r#"{"multiBernoulli":[{"existence":1,"mean":[0,0,3,-3],
        "cov":[[1,0,0,0],[0,1,0,0],[0,0,1,0],[0,0,0,1]]}]}"#;
    let disc = cardinality(rfs, r#"{"disc":{"center":[0,0],"radius":1}}"#, "").unwrap();
    let m = nums(&get(&disc, "massInFov"))[0];
    assert!((m - (1.0 - (-0.5f64).exp())).abs() < 1e-13, "{m}");
    // The box [0, ∞)² is not expressible in JSON; use a large box: the quadrant mass 1/4.
    let quad = cardinality(rfs, r#"{"box":{"min":[0,0],"max":[40,40]}}"#, "").unwrap();
    assert!((nums(&get(&quad, "massInFov"))[0] - 0.25).abs() < 1e-14);
    // The same quadrant as a polygon (clockwise) goes through the ray method.
    let poly = cardinality(rfs, r#"{"polygon":[[0,0],[0,40],[40,40],[40,0]]}"#, "").unwrap();
    assert!((nums(&get(&poly, "massInFov"))[0] - 0.25).abs() < 1e-12);
    assert_eq!(nums(&get(&poly, "pmf")).len(), 2);
}

#[wasm_bindgen_test]
fn poisson_iid_cluster_and_glmb() {
    // PHD of mass 2 inside (weights sum to N_X = 3): the count is Poisson(2), truncated
    // where the tail is below 1e-15.
    let rfs = format!(
        r#"{{"poisson":[{{"weight":2,{}}},{{"weight":1,{}}}]}}"#,
        tight(0.0, 0.0),
        tight(9.0, 0.0)
    );
    let out = cardinality(&rfs, UNIT_BOX, "").unwrap();
    let pmf = nums(&get(&out, "pmf"));
    assert!((pmf[0] - (-2.0f64).exp()).abs() < 1e-12);
    assert!((pmf[3] - (-2.0f64).exp() * 8.0 / 6.0).abs() < 1e-12);
    assert!((1.0 - pmf.iter().sum::<f64>()) < 1e-14 && pmf.len() < 30);
    assert!((num(&out, "mean") - 2.0).abs() < 1e-12 && (num(&out, "variance") - 2.0).abs() < 1e-12);
    assert_eq!(nums(&get(&out, "massInFov")).len(), 2);
    // i.i.d. cluster: ρ = (0.2, 0.3, 0.5), half of p inside → binomial thinning with q = 1/2.
    let rfs = format!(
        r#"{{"iidCluster":{{"cardinality":[0.2,0.3,0.5],"density":[{{"weight":0.5,{}}},{{"weight":0.5,{}}}]}}}}"#,
        tight(0.0, 0.0),
        tight(-7.0, 0.0)
    );
    let out = cardinality(&rfs, UNIT_BOX, "").unwrap();
    let pmf = nums(&get(&out, "pmf"));
    let want = [0.2 + 0.15 + 0.125, 0.15 + 0.25, 0.125];
    for (p, w) in pmf.iter().zip(want) {
        assert!((p - w).abs() < 1e-12, "{pmf:?}");
    }
    // GLMB: hypothesis A (w 0.4) has no labels, B (w 0.6) two labels, one inside.
    let rfs = format!(
        r#"{{"glmb":[{{"weight":0.4,"components":[]}},{{"weight":0.6,"components":[{{{}}},{{{}}}]}}]}}"#,
        tight(0.0, 0.0),
        tight(0.0, 8.0)
    );
    let out = cardinality(&rfs, UNIT_BOX, "").unwrap();
    let pmf = nums(&get(&out, "pmf"));
    assert_eq!(pmf.len(), 3);
    assert!((pmf[0] - 0.4).abs() < 1e-12 && (pmf[1] - 0.6).abs() < 1e-12 && pmf[2] < 1e-12);
    assert_eq!(nums(&get(&out, "massInFov")).len(), 2);
}

#[wasm_bindgen_test]
fn fov_cardinality_errors_name_the_field() {
    let mb = format!(
        r#"{{"multiBernoulli":[{{"existence":0.5,{}}}]}}"#,
        tight(0.0, 0.0)
    );
    assert_throws(
        fov_cardinality_js(js(r#"{"fov":{"disc":{"center":[0,0],"radius":1}}}"#)),
        "TypeError",
        "options.rfs",
    );
    assert_throws(fov_cardinality_js(js("[1]")), "TypeError", "options");
    assert_throws(cardinality(&mb, "[]", ""), "TypeError", "fov");
    assert_throws(
        cardinality(&mb, r#"{"box":{"min":[0,0],"max":[1,1]},"disc":{}}"#, ""),
        "TypeError",
        "exactly one",
    );
    assert_throws(
        cardinality(r#"{"poisson":[],"glmb":[]}"#, UNIT_BOX, ""),
        "TypeError",
        "exactly one",
    );
    let bad_r = format!(
        r#"{{"multiBernoulli":[{{"existence":0.5,{0}}},{{"existence":1.5,{0}}}]}}"#,
        tight(0.0, 0.0)
    );
    assert_throws(
        cardinality(&bad_r, UNIT_BOX, ""),
        "RangeError",
        "rfs.multiBernoulli[1].existence",
    );
    assert_throws(
        cardinality(
            r#"{"multiBernoulli":[{"existence":0.5,"mean":[0,0]}]}"#,
            UNIT_BOX,
            "",
        ),
        "TypeError",
        "rfs.multiBernoulli[0].cov is required",
    );
    assert_throws(
        cardinality(
            r#"{"poisson":[{"weight":1,"mean":[0,0],"cov":[[1,2],[2,1]]}]}"#,
            UNIT_BOX,
            "",
        ),
        "RangeError",
        "rfs.poisson[0].cov",
    );
    assert_throws(
        cardinality(
            r#"{"poisson":[{"weight":1,"mean":[0,0],"cov":[[1,0],[0]]}]}"#,
            UNIT_BOX,
            "",
        ),
        "RangeError",
        "rfs.poisson[0].cov[1]",
    );
    assert_throws(
        cardinality(
            r#"{"poisson":[{"weight":-1,"mean":[0,0],"cov":[[1,0],[0,1]]}]}"#,
            UNIT_BOX,
            "",
        ),
        "RangeError",
        "rfs.poisson[0].weight",
    );
    assert_throws(
        cardinality(
            r#"{"multiBernoulli":[{"existence":0.5,"mean":[0],"cov":[[1]]}]}"#,
            UNIT_BOX,
            "",
        ),
        "RangeError",
        "rfs.multiBernoulli[0].mean",
    );
    assert_throws(
        cardinality(
            r#"{"iidCluster":{"cardinality":[0.5,0.6],"density":[]}}"#,
            UNIT_BOX,
            "",
        ),
        "RangeError",
        "rfs.iidCluster.density",
    );
    let iid = format!(
        r#"{{"iidCluster":{{"cardinality":[0.5,0.6],"density":[{{"weight":1,{}}}]}}}}"#,
        tight(0.0, 0.0)
    );
    assert_throws(
        cardinality(&iid, UNIT_BOX, ""),
        "RangeError",
        "rfs.iidCluster.cardinality",
    );
    assert_throws(
        cardinality(r#"{"glmb":[{"weight":0.5,"components":[]}]}"#, UNIT_BOX, ""),
        "RangeError",
        "rfs.glmb",
    );
    assert_throws(
        cardinality(r#"{"glmb":[{"weight":1}]}"#, UNIT_BOX, ""),
        "TypeError",
        "rfs.glmb[0].components",
    );
    assert_throws(
        cardinality(&mb, r#"{"box":{"min":[0,0],"max":[1,-1]}}"#, ""),
        "RangeError",
        "fov.box.max[1]",
    );
    assert_throws(
        cardinality(&mb, r#"{"box":{"min":[0,0],"max":[1]}}"#, ""),
        "RangeError",
        "fov.box.max",
    );
    assert_throws(
        cardinality(&mb, r#"{"polygon":[[0,0],[1,1]]}"#, ""),
        "RangeError",
        "fov.polygon",
    );
    assert_throws(
        cardinality(&mb, r#"{"polygon":[[0,0],[1,1],[2,2]]}"#, ""),
        "RangeError",
        "fov.polygon",
    );
    assert_throws(
        cardinality(&mb, r#"{"polygon":[[0,0],[1,0,3],[2,2]]}"#, ""),
        "RangeError",
        "fov.polygon[1]",
    );
    assert_throws(
        cardinality(&mb, r#"{"polygon":[[0,0],[1,"a"],[2,2]]}"#, ""),
        "TypeError",
        "fov.polygon[1][1]",
    );
    assert_throws(
        cardinality(&mb, r#"{"disc":{"center":[0,0],"radius":-1}}"#, ""),
        "RangeError",
        "fov.disc.radius",
    );
    assert_throws(
        cardinality(&mb, r#"{"disc":{"center":[0,0]}}"#, ""),
        "TypeError",
        "fov.disc.radius",
    );
    assert_throws(
        cardinality(&mb, UNIT_BOX, r#","detectionProbability":2"#),
        "RangeError",
        "detectionProbability",
    );
    assert_throws(
        cardinality(&mb, UNIT_BOX, r#","detectionProbability":"x""#),
        "TypeError",
        "detectionProbability",
    );
    // Too large a Poisson count for a pmf, too expensive a request.
    let big = format!(r#"{{"poisson":[{{"weight":1e7,{}}}]}}"#, tight(0.0, 0.0));
    assert_throws(cardinality(&big, UNIT_BOX, ""), "RangeError", "rfs.poisson");
    assert_throws(
        cardinality(&mb, r#"{"disc":{"center":[0,0,0,0],"radius":1}}"#, ""),
        "RangeError",
        "fov",
    );
    // A FoV of more dimensions than the state.
    assert_throws(
        cardinality(&mb, r#"{"box":{"min":[0,0,0],"max":[1,1,1]}}"#, ""),
        "RangeError",
        "rfs.multiBernoulli[0].mean",
    );
}

fn scene_json(n: usize) -> String {
    // A deterministic scene: means on a spiral, varied shapes and correlations.
    let comps: Vec<String> = (0..n)
        .map(|i| {
            let t = i as f64 * 0.7;
            let (x, y) = (0.3 * t * t.cos() / 3.0, 0.3 * t * t.sin() / 3.0);
            let (sx, sy) = (0.1 + 0.05 * (i % 5) as f64, 0.15 + 0.04 * (i % 3) as f64);
            let r = -0.9 + 1.8 * ((i * 37) % 19) as f64 / 18.0;
            let c = r * sx * sy;
            format!(
                r#"{{"existence":{},"mean":[{x},{y}],"cov":[[{},{c}],[{c},{}]]}}"#,
                0.35 + 0.65 * ((i * 13) % 11) as f64 / 10.0,
                sx * sx,
                sy * sy
            )
        })
        .collect();
    format!("[{}]", comps.join(","))
}

#[wasm_bindgen_test]
fn variance_map_shapes_and_agreement_with_the_pmf() {
    let mb = scene_json(20);
    let opts = format!(
        r#"{{"multiBernoulli":{mb},"fovSize":[1,0.8],"grid":{{"x":[-2,2,21],"y":[-1.5,1.5,13]}}}}"#
    );
    let out = fov_variance_map(js(&opts)).unwrap();
    let var: js_sys::Float64Array = get(&out, "variance").dyn_into().expect("a Float64Array");
    let var = var.to_vec();
    assert_eq!(var.len(), 21 * 13);
    let max = num(&out, "max");
    let best = var.iter().copied().fold(f64::NEG_INFINITY, f64::max);
    assert_eq!(max, best);
    let k = var.iter().position(|&v| v == best).unwrap();
    let argmax = nums(&get(&out, "argmax"));
    assert_eq!(argmax.len(), 2);
    let (i, j) = (k % 21, k / 21);
    assert!((argmax[0] - (-2.0 + 0.2 * i as f64)).abs() < 1e-12);
    assert!((argmax[1] - (-1.5 + 0.25 * j as f64)).abs() < 1e-12);
    // The variance at the optimum equals that of fovCardinality's pmf for that FoV.
    let (x, y) = (argmax[0], argmax[1]);
    let card = fov_cardinality_js(js(&format!(
        r#"{{"rfs":{{"multiBernoulli":{mb}}},"fov":{{"box":{{"min":[{},{}],"max":[{},{}]}}}}}}"#,
        x - 0.5,
        y - 0.4,
        x + 0.5,
        y + 0.4
    )))
    .unwrap();
    assert!(
        (num(&card, "variance") - max).abs() < 1e-12,
        "{} vs {max}",
        num(&card, "variance")
    );
    // every cell: 0 ≤ variance ≤ Σ r(1 − r) bound of 1/4 per component
    assert!(var.iter().all(|&v| (0.0..=20.0 * 0.25).contains(&v)));
}

#[wasm_bindgen_test]
fn variance_map_errors_name_the_field() {
    let mb = scene_json(2);
    let call = |size: &str, grid: &str| {
        fov_variance_map(js(&format!(
            r#"{{"multiBernoulli":{mb},"fovSize":{size},"grid":{grid}}}"#
        )))
    };
    let grid = r#"{"x":[0,1,3],"y":[0,1,3]}"#;
    assert!(call("[1,1]", grid).is_ok());
    assert_throws(call("[1]", grid), "RangeError", "fovSize");
    assert_throws(call("[1,0]", grid), "RangeError", "fovSize[1]");
    assert_throws(call("1", grid), "TypeError", "fovSize");
    assert_throws(call("[1,1]", r#"{"x":[0,1,3]}"#), "TypeError", "grid.y");
    assert_throws(
        call("[1,1]", r#"{"x":[0,1,0],"y":[0,1,3]}"#),
        "RangeError",
        "grid.x[2]",
    );
    assert_throws(
        call("[1,1]", r#"{"x":[0,1,2.5],"y":[0,1,3]}"#),
        "RangeError",
        "grid.x[2]",
    );
    assert_throws(
        call("[1,1]", r#"{"x":[0,1,5000],"y":[0,1,3]}"#),
        "RangeError",
        "grid.x[2]",
    );
    assert_throws(
        call("[1,1]", r#"{"x":[0,1,3],"y":[2,1,3]}"#),
        "RangeError",
        "grid.y[1]",
    );
    assert_throws(
        call("[1,1]", r#"{"x":[0,1],"y":[0,1,3]}"#),
        "RangeError",
        "grid.x",
    );
    assert_throws(
        fov_variance_map(js(r#"{"fovSize":[1,1],"grid":{"x":[0,1,3],"y":[0,1,3]}}"#)),
        "TypeError",
        "options.multiBernoulli",
    );
    assert_throws(
        fov_variance_map(js(
            r#"{"multiBernoulli":[{"existence":-0.1,"mean":[0,0],"cov":[[1,0],[0,1]]}],"fovSize":[1,1],"grid":{"x":[0,1,3],"y":[0,1,3]}}"#,
        )),
        "RangeError",
        "multiBernoulli[0].existence",
    );
    assert_throws(
        fov_variance_map(js(
            r#"{"multiBernoulli":[{"existence":0.5,"mean":[0],"cov":[[1]]}],"fovSize":[1,1],"grid":{"x":[0,1,3],"y":[0,1,3]}}"#,
        )),
        "RangeError",
        "multiBernoulli[0].mean",
    );
    // 4096 × 4096 cells exceed the cell cap.
    assert_throws(
        call("[1,1]", r#"{"x":[0,1,4096],"y":[0,1,4096]}"#),
        "RangeError",
        "grid",
    );
}

/// Component `k` of a `placementScene` result as (existence, mx, my, P00, P01, P11), checking
/// the shape of the entry on the way.
fn scene_entry(scene: &wasm_bindgen::JsValue, k: u32) -> [f64; 6] {
    let mb = js_sys::Array::from(&get(scene, "multiBernoulli"));
    let e = mb.get(k);
    let mean = nums(&get(&e, "mean"));
    let cov = js_sys::Array::from(&get(&e, "cov"));
    assert_eq!((mean.len(), cov.length()), (2, 2));
    let (c0, c1) = (nums(&cov.get(0)), nums(&cov.get(1)));
    assert_eq!(c0[1], c1[0]);
    [num(&e, "existence"), mean[0], mean[1], c0[0], c0[1], c1[1]]
}

#[wasm_bindgen_test]
fn placement_scene_is_the_native_scene() {
    // The same numbers as the native test `fov::scene::tests::default_scene_is_pinned`:
    // bit-identical scenes natively and in wasm32.
    let golden: [(u32, [f64; 6]); 2] = [
        (
            0,
            [
                0.7182650238619825,
                1.4746905435762068,
                2.8260165215207773,
                0.07713190551083224,
                -1.046535880936458e-5,
                0.07713020602897852,
            ],
        ),
        (
            99,
            [
                0.5111431663750448,
                0.693157593170812,
                0.7195304907966535,
                0.06554451512016446,
                0.04699713313188498,
                0.2250281971638252,
            ],
        ),
    ];
    let scene = placement_scene_js(None).unwrap();
    assert_eq!(
        js_sys::Array::from(&get(&scene, "multiBernoulli")).length(),
        100
    );
    for (k, want) in golden {
        assert_eq!(
            scene_entry(&scene, k).map(f64::to_bits),
            want.map(f64::to_bits)
        );
    }
    // Explicit defaults give the same scene; a smaller count is a prefix; the recipe holds.
    let explicit = placement_scene_js(Some(js(
        r#"{"count":100,"seed":1,"extent":3,"sigma":[0.1,0.5]}"#,
    )))
    .unwrap();
    assert_eq!(super::json(&explicit), super::json(&scene));
    let small =
        placement_scene_js(Some(js(r#"{"count":7,"extent":2,"sigma":[0.2,0.2]}"#))).unwrap();
    assert_eq!(
        js_sys::Array::from(&get(&small, "multiBernoulli")).length(),
        7
    );
    let prefix =
        placement_scene_js(Some(js(r#"{"count":3,"extent":2,"sigma":[0.2,0.2]}"#))).unwrap();
    for k in 0..3 {
        assert_eq!(scene_entry(&small, k), scene_entry(&prefix, k));
    }
    for k in 0..7 {
        let [r, x, y, a, b, c] = scene_entry(&small, k);
        assert!((0.35..1.0).contains(&r) && x.abs() <= 2.0 && y.abs() <= 2.0);
        // σ₁ = σ₂ = 0.2: P = 0.04 I whatever the rotation.
        assert!((a - 0.04).abs() < 1e-15 && b.abs() < 1e-15 && (c - 0.04).abs() < 1e-15);
    }
    let other = placement_scene_js(Some(js(r#"{"seed":2}"#))).unwrap();
    assert_ne!(scene_entry(&other, 0), scene_entry(&scene, 0));
    // The result feeds fovVarianceMap and fovCardinality unchanged.
    let mb = super::json(&get(&small, "multiBernoulli"));
    let map = fov_variance_map(js(&format!(
        r#"{{"multiBernoulli":{mb},"fovSize":[1,1],"grid":{{"x":[-2,2,9],"y":[-2,2,9]}}}}"#
    )))
    .unwrap();
    assert!(num(&map, "max") > 0.0);
    let card = cardinality(
        &format!(r#"{{"multiBernoulli":{mb}}}"#),
        r#"{"box":{"min":[-9,-9],"max":[9,9]}}"#,
        "",
    )
    .unwrap();
    let total: f64 = (0..7).map(|k| scene_entry(&small, k)[0]).sum();
    assert!((num(&card, "mean") - total).abs() < 1e-12);
}

#[wasm_bindgen_test]
fn placement_scene_errors_name_the_field() {
    let call = |o: &str| placement_scene_js(Some(js(o)));
    assert_throws(call("[1]"), "TypeError", "options");
    assert_throws(call(r#"{"count":10001}"#), "RangeError", "count");
    assert_throws(call(r#"{"count":2.5}"#), "RangeError", "count");
    assert_throws(call(r#"{"count":"5"}"#), "TypeError", "count");
    assert_throws(call(r#"{"seed":-1}"#), "RangeError", "seed");
    assert_throws(call(r#"{"seed":0.5}"#), "RangeError", "seed");
    assert_throws(call(r#"{"seed":1e300}"#), "RangeError", "seed");
    assert_throws(call(r#"{"extent":0}"#), "RangeError", "extent");
    assert_throws(call(r#"{"sigma":[0.5]}"#), "RangeError", "sigma");
    assert_throws(call(r#"{"sigma":[0,1]}"#), "RangeError", "sigma[0]");
    assert_throws(call(r#"{"sigma":[0.5,0.4]}"#), "RangeError", "sigma[1]");
    assert_throws(call(r#"{"sigma":[0.5,"x"]}"#), "TypeError", "sigma[1]");
    // The largest exact integer seed and seed 0 are fine; count 0 gives an empty scene.
    assert!(call(r#"{"seed":9007199254740991,"count":1}"#).is_ok());
    let empty = call(r#"{"seed":0,"count":0}"#).unwrap();
    assert_eq!(
        js_sys::Array::from(&get(&empty, "multiBernoulli")).length(),
        0
    );
}

#[wasm_bindgen_test]
fn mixture_density_grid_values_and_shape() {
    // 0.7 N((1, −1), [[0.5, 0.1], [0.1, 0.3]]) + 0.4 N((0, 2), [[1, −0.2], [−0.2, 0.4]]).
    let pdf = |x: f64, y: f64, m: [f64; 2], p: [f64; 3]| {
        let det = p[0] * p[2] - p[1] * p[1];
        let (dx, dy) = (x - m[0], y - m[1]);
        let q = (p[2] * dx * dx - 2.0 * p[1] * dx * dy + p[0] * dy * dy) / det;
        (-0.5 * q).exp() / (2.0 * std::f64::consts::PI * det.sqrt())
    };
    let mix = r#"[{"weight":0.7,"mean":[1,-1],"cov":[[0.5,0.1],[0.1,0.3]]},
                  {"weight":0.4,"mean":[0,2],"cov":[[1,-0.2],[-0.2,0.4]]}]"#;
    let out = mixture_density_grid_js(js(&format!(
        r#"{{"mixture":{mix},"grid":{{"x":[-2,3,11],"y":[-3,4,8]}}}}"#
    )))
    .unwrap();
    let d = out.to_vec();
    assert_eq!(d.len(), 88);
    for j in 0..8 {
        for i in 0..11 {
            let (x, y) = (-2.0 + 0.5 * i as f64, -3.0 + j as f64);
            let want = 0.7 * pdf(x, y, [1.0, -1.0], [0.5, 0.1, 0.3])
                + 0.4 * pdf(x, y, [0.0, 2.0], [1.0, -0.2, 0.4]);
            assert!(
                (d[j * 11 + i] - want).abs() <= 1e-14 * want + 1e-300,
                "({i}, {j}): {} vs {want}",
                d[j * 11 + i]
            );
        }
    }
    // 4D states (x, y, vx, vy): the position marginal.
    let mix4 = r#"[{"weight":1,"mean":[1,-1,5,5],
        "cov":[[0.5,0.1,0.2,0],[0.1,0.3,0,0],[0.2,0,1,0],[0,0,0,1]]}]"#;
    let out = mixture_density_grid_js(js(&format!(
        r#"{{"mixture":{mix4},"grid":{{"x":[1,1,1],"y":[-1,-1,1]}}}}"#
    )))
    .unwrap();
    let want = pdf(1.0, -1.0, [1.0, -1.0], [0.5, 0.1, 0.3]);
    assert!((out.to_vec()[0] - want).abs() < 1e-14 * want);
    // An empty mixture is zero everywhere.
    let out =
        mixture_density_grid_js(js(r#"{"mixture":[],"grid":{"x":[0,1,2],"y":[0,1,3]}}"#)).unwrap();
    assert_eq!(out.to_vec(), vec![0.0; 6]);
}

/// `mixtureDensityGrid` with its `Float64Array` as a `JsValue`.
fn density(opts: wasm_bindgen::JsValue) -> Result<wasm_bindgen::JsValue, wasm_bindgen::JsValue> {
    mixture_density_grid_js(opts).map(Into::into)
}

#[wasm_bindgen_test]
fn mixture_density_grid_errors_name_the_field() {
    let call =
        |mix: &str, grid: &str| density(js(&format!(r#"{{"mixture":{mix},"grid":{grid}}}"#)));
    let ok_mix = r#"[{"weight":1,"mean":[0,0],"cov":[[1,0],[0,1]]}]"#;
    let grid = r#"{"x":[0,1,3],"y":[0,1,3]}"#;
    assert!(call(ok_mix, grid).is_ok());
    assert_throws(
        density(js(r#"{"grid":{"x":[0,1,3],"y":[0,1,3]}}"#)),
        "TypeError",
        "options.mixture",
    );
    assert_throws(
        density(js(&format!(r#"{{"mixture":{ok_mix}}}"#))),
        "TypeError",
        "options.grid",
    );
    assert_throws(
        call(r#"[{"weight":-1,"mean":[0,0],"cov":[[1,0],[0,1]]}]"#, grid),
        "RangeError",
        "mixture[0].weight",
    );
    assert_throws(
        call(r#"[{"mean":[0,0],"cov":[[1,0],[0,1]]}]"#, grid),
        "TypeError",
        "mixture[0].weight",
    );
    assert_throws(
        call(r#"[{"weight":1,"mean":[0],"cov":[[1]]}]"#, grid),
        "RangeError",
        "mixture[0].mean",
    );
    assert_throws(
        call(r#"[{"weight":1,"mean":[0,0],"cov":[[1,2],[2,1]]}]"#, grid),
        "RangeError",
        "mixture[0].cov",
    );
    assert_throws(
        call(ok_mix, r#"{"x":[0,1,0],"y":[0,1,3]}"#),
        "RangeError",
        "grid.x[2]",
    );
    assert_throws(
        call(ok_mix, r#"{"x":[0,1,3],"y":[1,0,3]}"#),
        "RangeError",
        "grid.y[1]",
    );
    assert_throws(call(ok_mix, r#"{"x":[0,1,3]}"#), "TypeError", "grid.y");
    // 100 components × 600² points exceed the work cap.
    let many = format!(
        "[{}]",
        vec![r#"{"weight":1,"mean":[0,0],"cov":[[1,0],[0,1]]}"#; 100].join(",")
    );
    assert_throws(
        call(&many, r#"{"x":[0,1,600],"y":[0,1,600]}"#),
        "RangeError",
        "mixture",
    );
}
