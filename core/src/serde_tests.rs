//! Tests of the `serde` feature: every derived family round-trips through JSON, required
//! fields stay required, omitted optional fields take the type's default, and a deserialised
//! invalid value fails with the core's own error message.

use alloc::string::{String, ToString};
use alloc::vec;
use alloc::vec::Vec;
use core::fmt::Debug;

use serde::Serialize;
use serde::de::DeserializeOwned;

use crate::bernoulli::{ApplicationLoss, Costs, SpatialDensity};
use crate::bounds::{
    self, Cardinality, Density1, JdeBound, LinearGaussian, Method, TheoremOptions, assemble,
};
use crate::control::case_study::{ControlOptions, Scheme};
use crate::estimators::multi_bernoulli::{SetMetric, optimal_estimate};
use crate::filters::{
    BernoulliFilterOptions, Clutter, ClutterDensity, ClutterFunction, Detection, GmBernoulli,
    ParticleOptions, Splitting, default_reduction,
};
use crate::fov::{FovCardinality, MultiObjectDensity, SceneOptions};
use crate::gaussian::{Gaussian, GaussianMixture};
use crate::metrics::{Gospa, GospaSeries, Ospa};
use crate::mixture::ReductionOptions;
use crate::regions::{MAX_MEMBERS, MAX_VERTICES, Region};
use crate::sim::airport::{AirportScenarioOptions, airport_scenario};
use crate::smc::{MultiObjectLikelihood, Regularisation};
use crate::splitting::{SplitLibrary, SplitOptions, split_for_region};

/// Writes `value` to JSON, reads it back, and checks that nothing changed.
fn round_trip<T: Serialize + DeserializeOwned + PartialEq + Debug>(value: &T) -> String {
    let json = serde_json::to_string(value).unwrap();
    let back: T = serde_json::from_str(&json).unwrap();
    assert_eq!(&back, value, "{json}");
    json
}

/// The error message of reading `json` as a `T`.
fn rejected<T: DeserializeOwned + Debug>(json: &str) -> String {
    serde_json::from_str::<T>(json).unwrap_err().to_string()
}

/// A serde_json message without its " at line 1 column 9".
fn without_position(message: String) -> String {
    match message.rfind(" at line ") {
        Some(i) => message[..i].into(),
        None => message,
    }
}

fn gaussian(mean: &[f64], cov: &[f64]) -> Gaussian {
    Gaussian::from_slices(mean, cov, "g").unwrap()
}

#[test]
fn metrics_options_and_results_round_trip() {
    let gospa = Gospa::new(5.0, 2.0, 2.0).unwrap();
    assert_eq!(round_trip(&gospa), r#"{"c":5.0,"p":2.0,"alpha":2.0}"#);
    round_trip(&Ospa::new(5.0, 1.0).unwrap());
    let truth = [[0.0, 0.0], [10.0, 0.0]];
    let estimate = [[0.5, 0.0], [30.0, 0.0], [40.0, 0.0]];
    let d = gospa.decompose(&truth, &estimate).unwrap();
    let json = round_trip(&d);
    assert!(json.contains(r#""false_targets":2"#), "{json}");
    round_trip(
        &Ospa::new(5.0, 2.0)
            .unwrap()
            .decompose(&truth, &estimate)
            .unwrap(),
    );
    let series: GospaSeries = gospa
        .series(&[truth.to_vec()], &[estimate.to_vec()])
        .unwrap();
    round_trip(&series);
    round_trip(&crate::math::assignment::linear_assignment(&[1.0, 2.0, 3.0, 0.5], 2, 2).unwrap());
    assert_eq!(
        rejected::<Gospa>(r#"{"c":-1.0,"p":2.0,"alpha":2.0}"#),
        Gospa::new(-1.0, 2.0, 2.0).unwrap_err().to_string()
    );
    assert!(rejected::<Gospa>(r#"{"c":1.0,"p":2.0}"#).contains("missing field `alpha`"));
}

#[test]
fn gaussians_are_rows_and_reject_a_non_positive_definite_covariance() {
    let g = gaussian(&[1.0, 2.0], &[2.0, 0.5, 0.5, 1.0]);
    assert_eq!(
        round_trip(&g),
        r#"{"mean":[1.0,2.0],"cov":[[2.0,0.5],[0.5,1.0]]}"#
    );
    let m = GaussianMixture::new(vec![(0.25, g.clone()), (0.75, g)], "m").unwrap();
    round_trip(&m);
    assert_eq!(
        rejected::<Gaussian>(r#"{"mean":[0.0,0.0],"cov":[[1.0,2.0],[2.0,1.0]]}"#),
        ".cov is not positive definite (smallest eigenvalue -1)"
    );
    assert_eq!(
        rejected::<GaussianMixture>(r#"[{"weight":1.0,"mean":[0.0],"cov":[[-1.0]]}]"#),
        "[0].cov is not positive definite (smallest eigenvalue -1)"
    );
    assert_eq!(
        rejected::<GaussianMixture>(r#"[{"weight":-1.0,"mean":[0.0],"cov":1.0}]"#),
        "[0].weight must be finite and >= 0, got -1"
    );
    assert!(rejected::<Gaussian>(r#"{"mean":[0.0]}"#).contains("missing field `cov`"));
}

#[test]
fn gaussians_read_nested_flat_and_scalar_covariances() {
    let nested: Gaussian =
        serde_json::from_str(r#"{"mean":[0,0],"cov":[[2,0.5],[0.5,1]]}"#).expect("nested rows");
    let flat: Gaussian =
        serde_json::from_str(r#"{"mean":[0,0],"cov":[2,0.5,0.5,1]}"#).expect("row-major");
    assert_eq!(nested, flat);
    let scalar: Gaussian = serde_json::from_str(r#"{"mean":[1],"cov":4}"#).expect("1D");
    assert_eq!(scalar, gaussian(&[1.0], &[4.0]));
    // `cov` of a 2D Gaussian | the message when `mean` comes first (the covariance is
    // checked as it is read, its errors relative to it) | when `cov` comes first
    for case in [
        "4 | invalid type: floating point `4.0`, expected a nested 2×2 array (a bare number is a 1D variance) \
         | invalid type: floating point `4.0`, expected an object whose cov is a nested 2×2 array (a bare number is a 1D variance)",
        "[1,0,0] | has length 3, expected 2 rows or 4 row-major numbers \
         | .cov has length 3, expected 2 rows or 4 row-major numbers",
        "[[1,0]] | has length 1, expected 2 | .cov has length 1, expected 2",
        "[[1,0],[0]] | [1] has length 1, expected 2 | .cov[1] has length 1, expected 2",
        "[[1,0],0] | [1] must be a row (array of numbers) like the entries before it \
         | .cov[1] must be a row (array of numbers) like the entries before it",
        "[1,[0]] | [1] must be a number like the entries before it \
         | .cov[1] must be a number like the entries before it",
    ] {
        let [cov, mean_first, cov_first] = [0, 1, 2].map(|i| case.split(" | ").nth(i).unwrap());
        let json = alloc::format!(r#"{{"mean":[0,0],"cov":{cov}}}"#);
        assert_eq!(
            without_position(rejected::<Gaussian>(&json)),
            mean_first,
            "{json}"
        );
        let json = alloc::format!(r#"{{"cov":{cov},"mean":[0,0]}}"#);
        assert_eq!(
            without_position(rejected::<Gaussian>(&json)),
            cov_first,
            "{json}"
        );
    }
    let wrong = rejected::<Gaussian>(r#"{"mean":[0],"cov":"x"}"#);
    assert!(
        wrong.contains("a covariance (nested rows, flat row-major numbers, or a 1D variance)"),
        "{wrong}"
    );
}

#[test]
fn filter_config_round_trips_and_omitted_fields_take_the_defaults() {
    let config = airport_scenario(1, 3).unwrap().config;
    round_trip(&config);
    let mut value: serde_json::Value = serde_json::to_value(&config).unwrap();
    let map = value.as_object_mut().unwrap();
    for optional in ["likelihood", "splitting", "reduction", "exclusions"] {
        map.remove(optional);
    }
    let back: BernoulliFilterOptions = serde_json::from_value(value.clone()).unwrap();
    assert_eq!(back.splitting, Splitting::default());
    assert_eq!(back.reduction, default_reduction());
    assert!(back.exclusions.is_empty() && back.likelihood.is_none());
    // survival, birth and position_dims take the npm package's defaults when omitted
    for optional in ["survival", "birth", "position_dims"] {
        value.as_object_mut().unwrap().remove(optional);
    }
    let back: BernoulliFilterOptions = serde_json::from_value(value.clone()).unwrap();
    assert_eq!(back.survival, crate::filters::default_survival());
    assert_eq!(back.birth, crate::filters::Birth::none());
    assert_eq!(back.position_dims, crate::filters::default_position_dims());
    // the models without a default stay required
    value.as_object_mut().unwrap().remove("clutter");
    let missing = serde_json::from_value::<BernoulliFilterOptions>(value).unwrap_err();
    assert!(
        missing.to_string().contains("missing field `clutter`"),
        "{missing}"
    );
    round_trip(&ParticleOptions::default());
    let state = GmBernoulli::new(0.5, config.mixture.clone()).unwrap();
    round_trip(&state);
}

#[test]
fn airport_options_omitted_take_the_defaults_and_round_trip() {
    let empty: AirportScenarioOptions = serde_json::from_str("{}").unwrap();
    assert_eq!(empty, AirportScenarioOptions::default());
    assert_eq!((empty.seed, empty.steps), (None, 60));
    let given = AirportScenarioOptions {
        seed: Some(7),
        steps: 3,
    };
    assert_eq!(round_trip(&given), r#"{"seed":7,"steps":3}"#);
    let run = airport_scenario(given.seed.unwrap(), given.steps).unwrap();
    assert_eq!(run.truth.len(), 3);
}

#[test]
fn eq39_existence_and_detection_probability_1_5_are_rejected() {
    let state = r#"{"existence":1.5,"mixture":[{"weight":1.0,"mean":[0.0],"cov":[[1.0]]}]}"#;
    assert_eq!(
        rejected::<GmBernoulli>(state),
        "existence must be a probability in [0, 1], got 1.5"
    );
    // named relative to the value read (`config.detection` + `.probability` in a binding)
    let detection = rejected::<Detection>(r#"{"probability":1.5}"#);
    assert_eq!(
        without_position(detection),
        ".probability must be a probability in [0, 1], got 1.5"
    );
    let birth = r#"{"probability":0.1,"mixture":[{"weight":0.5,"mean":[0.0],"cov":[[1.0]]}]}"#;
    assert_eq!(
        without_position(rejected::<crate::filters::Birth>(birth)),
        ".mixture[].weight must be weights summing to 1, got 0.5"
    );
    let d: Detection = serde_json::from_str(r#"{"probability":0.9}"#).unwrap();
    assert_eq!(d, Detection::new(0.9, None).unwrap());
}

#[test]
fn clutter_functions_cannot_be_serialised() {
    let constant = Clutter::new(2.0, ClutterDensity::Constant(0.1)).unwrap();
    assert_eq!(round_trip(&constant), r#"{"rate":2.0,"density":0.1}"#);
    assert_eq!(
        round_trip(&Clutter::new(2.0, ClutterDensity::PerReport(vec![0.1, 0.2])).unwrap()),
        r#"{"rate":2.0,"density":[0.1,0.2]}"#
    );
    let f = ClutterDensity::Function(ClutterFunction(alloc::sync::Arc::new(|_: &[f64]| 1.0)));
    assert!(serde_json::to_string(&f).is_err());
    assert!(serde_json::from_str::<ClutterDensity>(r#"{"Function":null}"#).is_err());
}

#[test]
fn options_with_a_default_take_it_for_every_omitted_field() {
    fn empty_is_default<T: DeserializeOwned + Default + PartialEq + Debug + Serialize>() {
        assert_eq!(serde_json::from_str::<T>("{}").unwrap(), T::default());
        round_trip(&T::default());
    }
    empty_is_default::<SplitOptions>();
    empty_is_default::<TheoremOptions>();
    empty_is_default::<ParticleOptions>();
    empty_is_default::<Regularisation>();
    empty_is_default::<ReductionOptions>();
    empty_is_default::<SceneOptions>();
    empty_is_default::<Splitting>();
    empty_is_default::<crate::filters::EstimateOptions>();
    empty_is_default::<crate::control::RangeSensor>();
    empty_is_default::<crate::control::ActionGrid>();
    let some: SplitOptions = serde_json::from_str(r#"{"grid_points":21}"#).unwrap();
    assert_eq!(
        some,
        SplitOptions {
            grid_points: 21,
            ..SplitOptions::default()
        }
    );
}

#[test]
fn control_config_defaults_are_the_papers() {
    let paper = ControlOptions::paper(Scheme::Renyi, 3);
    round_trip(&paper);
    let json = r#"{"scheme":"renyi","steps":3}"#;
    assert_eq!(serde_json::from_str::<ControlOptions>(json).unwrap(), paper);
    // the scene is the paper's and is not written
    assert!(!round_trip(&paper).contains("truth"));
    round_trip(&MultiObjectLikelihood::new(0.9, 2.0).unwrap());
    assert_eq!(
        rejected::<MultiObjectLikelihood>(r#"{"detection":1.5,"clutter_rate":1.0}"#),
        MultiObjectLikelihood::new(1.5, 1.0)
            .unwrap_err()
            .to_string()
    );
}

#[test]
fn bounds_models_and_results_round_trip() {
    round_trip(&Density1::gaussian(1.0, 4.0).unwrap());
    round_trip(&Density1::mixture(&[(0.5, 0.0, 1.0), (0.5, 2.0, 1.0)]).unwrap());
    let table = Density1::table(&[0.0, 1.0, 2.0], &[0.0, 1.0, 0.0]).unwrap();
    assert!(!round_trip(&table).contains("cdf"));
    assert_eq!(
        rejected::<Density1>(r#"{"uniform":{"low":1.0,"high":0.0}}"#),
        Density1::uniform(1.0, 0.0)
            .unwrap_err()
            .within(".uniform")
            .to_string()
    );
    let detection = bounds::Detection::constant(0.9).unwrap();
    round_trip(&LinearGaussian::new(detection, 1.0, 0.0, 1.0).unwrap());
    assert!(
        rejected::<bounds::Detection>("1.5")
            .starts_with("must be a probability in [0, 1], got 1.5")
    );
}

/// The shapes of paper 002's f, ψ, c (13), (22) and P_o are the ones every binding shows:
/// lower-case kinds, mixture components as objects, P_o a number or `{"table": …}`; a
/// constructor's error names the part of the value at fault.
#[test]
fn eq13_densities_and_detection_read_in_the_bindings_shape() {
    let g: Density1 = serde_json::from_str(r#"{"gaussian":{"mean":1,"variance":4}}"#).unwrap();
    assert_eq!(g, Density1::gaussian(1.0, 4.0).unwrap());
    let m = Density1::mixture(&[(1.0, 0.0, 1.0), (3.0, 2.0, 0.5)]).unwrap();
    let json = serde_json::to_string(&m).unwrap();
    assert_eq!(
        json,
        r#"{"mixture":[{"weight":0.25,"mean":0.0,"variance":1.0},{"weight":0.75,"mean":2.0,"variance":0.5}]}"#
    );
    assert_eq!(
        rejected::<Density1>(r#"{"mixture":[{"weight":1,"mean":0,"variance":-1}]}"#),
        ".mixture[0].variance must be finite and >= 2.2250738585072014e-308 (a normal float), got -1"
    );
    assert!(
        rejected::<Density1>(r#"{"gaussian":{"mean":0,"variance":0}}"#)
            .starts_with(".gaussian.variance must be")
    );
    let t = bounds::Detection::table(&[0.0, 1.0], &[0.5, 0.9]).unwrap();
    assert_eq!(
        round_trip(&t),
        r#"{"table":{"x":[0.0,1.0],"probability":[0.5,0.9]}}"#
    );
    assert_eq!(
        round_trip(&bounds::Detection::constant(0.5).unwrap()),
        "0.5"
    );
    assert_eq!(
        serde_json::from_str::<bounds::Detection>("1").unwrap(),
        bounds::Detection::Constant(1.0)
    );
    assert!(
        rejected::<bounds::Detection>(r#"{"table":{"x":[0,1],"probability":[0.5,2]}}"#)
            .starts_with(".table.probability[1] must be a probability in [0, 1], got 2")
    );
    let no_clutter = bounds::gaussian_no_clutter(0.5, 0.9, 4.0, 1.0, 1.0, 5.0).unwrap();
    round_trip(&no_clutter);
    let assembled = assemble(&bounds::Ingredients {
        existence: 0.5,
        mean_detection: 0.9,
        undetected_variance: 4.0,
        inverse_information: 1.0,
        detected_mass: 0.4,
        absent_empty: 0.4,
        absent_null: 0.1,
        undetected_empty: 0.05,
        undetected_null: 0.05,
        false_alarm_error: 1.0,
        miss_error: 5.0,
    });
    round_trip(&JdeBound {
        assembled,
        mean_detection: 0.9,
        undetected_mean: 1.0,
        undetected_variance: 4.0,
        eta: 0.2,
        region: vec![(0.0, 1.0)],
        cardinalities: vec![Cardinality {
            n: 1,
            probability: 0.5,
            w: 0.1,
            inverse_information: 1.0,
            clutter_null: 0.2,
            method: Method::Quadrature,
            error: 1e-12,
            w_error: 1e-12,
            clutter_null_error: 1e-12,
        }],
        error: 1e-9,
        regular: true,
    });
}

#[test]
fn regions_splitting_and_fov_round_trip() {
    let disc = Region::ball(&[0.0, 0.0], 2.0, "r").unwrap();
    let square = Region::axis_box(&[-1.0, -1.0], &[1.0, 1.0], "r").unwrap();
    let triangle = Region::polygon(&[[0.0, 0.0], [1.0, 0.0], [0.0, 1.0]], "r").unwrap();
    let both = Region::union(vec![Region::complement(disc), square, triangle], "r").unwrap();
    let json = round_trip(&both);
    assert!(
        json.starts_with(r#"{"union":[{"complement":{"ball":{"center""#),
        "{json}"
    );
    // the constructors' errors, named relative to the region read
    assert_eq!(
        without_position(rejected::<Region>(
            r#"{"ball":{"center":[0.0],"radius":-1.0}}"#
        )),
        ".ball.radius must be finite and > 0, got -1"
    );
    assert_eq!(
        without_position(rejected::<Region>(r#"{"union":[]}"#)),
        ".union must be a non-empty list of regions, got 0"
    );
    assert_eq!(
        without_position(rejected::<Region>(
            r#"{"complement":{"box":{"min":[0,1],"max":[1,0]}}}"#
        )),
        ".box.max[1] must be a number not below the matching min, got 0"
    );
    let disc = r#"{"ball":{"center":[0,0],"radius":1}}"#;
    let ball3 = r#"{"ball":{"center":[0,0,0],"radius":1}}"#;
    assert_eq!(
        without_position(rejected::<Region>(&std::format!(
            r#"{{"intersection":[{disc},{ball3}]}}"#
        ))),
        ".intersection[1] has length 3, expected 2"
    );
    // the caps of the constructors
    let many = vec![disc; MAX_MEMBERS + 1].join(",");
    assert_eq!(
        without_position(rejected::<Region>(&std::format!(r#"{{"union":[{many}]}}"#))),
        ".union has 1001 members, at most 1000 are supported"
    );
    let vertices = vec!["[0,0]"; MAX_VERTICES + 1].join(",");
    assert_eq!(
        without_position(rejected::<Region>(&std::format!(
            r#"{{"polygon":{{"vertices":[{vertices}]}}}}"#
        ))),
        ".polygon has 1001 vertices, at most 1000 are supported"
    );
    let library = SplitLibrary::table_i();
    round_trip(&library);
    let mixture = GaussianMixture::new(
        vec![(1.0, gaussian(&[0.5, 0.0], &[1.0, 0.0, 0.0, 1.0]))],
        "m",
    )
    .unwrap();
    let fov = Region::axis_box(&[0.0, -5.0], &[5.0, 5.0], "fov").unwrap();
    round_trip(&split_for_region(&mixture, &fov, &library, &SplitOptions::default()).unwrap());
    let pmf: FovCardinality = crate::fov::pmf::multi_bernoulli(&[0.5, 0.25]).unwrap();
    round_trip(&pmf);
    round_trip(&MultiObjectDensity::Poisson(mixture));
}

#[test]
fn estimators_and_bernoulli_results_round_trip() {
    let best = optimal_estimate(&[0.4, 0.4], SetMetric::Ospa, 1.0, 2.0).unwrap();
    round_trip(&best);
    assert_eq!(round_trip(&SetMetric::GOSPA), r#"{"Gospa":{"alpha":2.0}}"#);
    let loss = ApplicationLoss::new(Costs::mmol(10.0, 1.0).unwrap(), 1.0).unwrap();
    round_trip(&loss);
    let density = SpatialDensity::gaussian_from_slices(&[0.5, 0.0], &[1.0, 0.0, 0.0, 1.0]).unwrap();
    round_trip(&crate::bernoulli::estimate(0.7, &density, &loss).unwrap());
    round_trip(&density);
    let g = gaussian(&[0.0], &[1.0]);
    let mixture = GaussianMixture::new(vec![(1.0, g.clone()), (3.0, g)], "m").unwrap();
    round_trip(&SpatialDensity::mixture(&mixture).unwrap());
    let points = [[0.0], [1.0]];
    let particles = crate::bernoulli::ParticleSet::new(&points, Some(&[0.25, 0.75])).unwrap();
    round_trip(&SpatialDensity::particles(particles));
    // the constructor's message, the field named relative to the costs (`.c01`)
    let expected = Costs::new(0.0, -1.0, 1.0, 0.0, 1.0)
        .unwrap_err()
        .map_field(|f| f.strip_prefix("costs").unwrap().into())
        .to_string();
    assert!(expected.starts_with(".c01 must be"), "{expected}");
    assert!(
        rejected::<Costs>(r#"{"c00":0.0,"c01":-1.0,"c10":1.0,"c11":0.0,"c":1.0}"#)
            .starts_with(&expected)
    );
}

/// A [`SpatialDensity`] is written and read as the user writes it: `{mean, cov}`,
/// `{mixture: [...]}` or `{particles, weights}`, exactly one form.
#[test]
fn spatial_densities_read_one_of_three_forms() {
    let g = SpatialDensity::gaussian_from_slices(&[0.5, 0.0], &[1.0, 0.0, 0.0, 1.0]).unwrap();
    assert_eq!(
        serde_json::to_string(&g).unwrap(),
        r#"{"mean":[0.5,0.0],"cov":[[1.0,0.0],[0.0,1.0]]}"#
    );
    let one = gaussian(&[0.0], &[1.0]);
    let mixture = GaussianMixture::new(vec![(1.0, one.clone()), (3.0, one)], "m").unwrap();
    let json = serde_json::to_string(&SpatialDensity::mixture(&mixture).unwrap()).unwrap();
    assert!(json.starts_with(r#"{"mixture":[{"weight":0.25,"#), "{json}");
    let read: SpatialDensity =
        serde_json::from_str(r#"{"particles":[[0],[1]]}"#).expect("weights optional");
    assert_eq!(
        serde_json::to_string(&read).unwrap(),
        r#"{"particles":[[0.0],[1.0]],"weights":[0.5,0.5]}"#
    );
    let flat: SpatialDensity = serde_json::from_str(r#"{"cov":[1,0,0,1],"mean":[0.5,0]}"#).unwrap();
    assert_eq!(flat, g);
    // the density | the message (relative to the density: a binding that tracks paths puts
    // its own in front)
    for case in [
        r#"{"mean":[0,0],"cov":1} | invalid type: floating point `1.0`, expected a nested 2×2 array (a bare number is a 1D variance)"#,
        r#"{"mean":[0,0],"cov":[[1,2],[2,1]]} | .cov is not positive definite (smallest eigenvalue -1)"#,
        r#"{"mean":[],"cov":[]} | .mean has length 0, expected 1"#,
        r#"{"mean":[0]} | missing field `cov`"#,
        r#"{"cov":1} | missing field `mean`"#,
        r#"{"mixture":[]} | .mixture: a mixture needs at least one component"#,
        r#"{"mixture":[{"weight":0,"mean":[0],"cov":1}]} | .mixture[].weight sum must be finite and > 0, got 0"#,
        r#"{"mixture":[{"weight":1,"mean":[0],"cov":[[-1]]}]} | [0].cov is not positive definite (smallest eigenvalue -1)"#,
        r#"{"mixture":[{"mean":[0],"cov":1}]} | missing field `weight`"#,
        r#"{"particles":[]} | .particles: at least one particle is needed"#,
        r#"{"particles":[[0],[0,1]]} | .particles[1] has length 2, expected 1"#,
        r#"{"particles":[[0],[1]],"weights":[1]} | .weights has length 1, expected 2"#,
        r#"{"particles":[[0],[1]],"weights":[0,0]} | .weights sum must be finite and > 0, got 0"#,
        r#"{"mean":[0],"cov":1,"mixture":[]} | invalid type: more than one, expected exactly one of { mean, cov }, { mixture: [...] } or { particles: [...], weights }"#,
        r#"{} | invalid type: none of them, expected exactly one of { mean, cov }, { mixture: [...] } or { particles: [...], weights }"#,
        r#"{"mean":[0],"cov":1,"weights":[1]} | invalid type: weights without particles, expected exactly one of { mean, cov }, { mixture: [...] } or { particles: [...], weights }"#,
        r#"{"mean":[0],"cov":1,"mixtur":[]} | unknown field `mixtur`, expected one of `mean`, `cov`, `mixture`, `particles`, `weights`"#,
    ] {
        let (json, message) = case.split_once(" | ").unwrap();
        let got = without_position(rejected::<SpatialDensity>(json));
        assert_eq!(got, message, "{json}");
    }
}

/// A multi-Bernoulli of Gaussians through `serde_shapes::bernoullis`.
#[test]
fn bernoullis_read_existence_mean_cov() {
    #[derive(serde::Serialize, serde::Deserialize, Debug)]
    struct Mb {
        #[serde(with = "crate::serde_shapes::bernoullis")]
        mb: Vec<(f64, Gaussian)>,
    }
    let mb = Mb {
        mb: vec![(0.5, gaussian(&[1.0, 2.0], &[2.0, 0.5, 0.5, 1.0]))],
    };
    let json = serde_json::to_string(&mb).unwrap();
    assert_eq!(
        json,
        r#"{"mb":[{"existence":0.5,"mean":[1.0,2.0],"cov":[[2.0,0.5],[0.5,1.0]]}]}"#
    );
    let back: Mb = serde_json::from_str(&json).unwrap();
    assert_eq!(back.mb, mb.mb);
    let flat: Mb =
        serde_json::from_str(r#"{"mb":[{"cov":[2,0.5,0.5,1],"mean":[1,2],"existence":0.5}]}"#)
            .unwrap();
    assert_eq!(flat.mb, mb.mb);
    for case in [
        r#"[{"existence":0.5,"mean":[0,0],"cov":1}] | invalid type: floating point `1.0`, expected a nested 2×2 array (a bare number is a 1D variance)"#,
        r#"[{"existence":0.5,"mean":[0,0],"cov":[[1,2],[2,1]]}] | [0].cov is not positive definite (smallest eigenvalue -1)"#,
        r#"[{"mean":[0],"cov":1}] | missing field `existence`"#,
        r#"[{"existence":1,"weight":1,"mean":[0],"cov":1}] | unknown field `weight`, expected one of `existence`, `mean`, `cov`"#,
    ] {
        let (items, message) = case.split_once(" | ").unwrap();
        let got = without_position(rejected::<Mb>(&alloc::format!(r#"{{"mb":{items}}}"#)));
        assert_eq!(got, message, "{items}");
    }
    let component = r#"{"existence":1,"mean":[0],"cov":1}"#;
    let many = alloc::format!(r#"{{"mb":[{}]}}"#, vec![component; 10_001].join(","));
    assert_eq!(
        without_position(rejected::<Mb>(&many)),
        "has 10001 entries, at most 10000 are supported"
    );
}

/// A mixture read has at most `MAX_GAUSSIANS` components.
#[test]
fn mixtures_read_at_most_max_gaussians_components() {
    use crate::serde_shapes::MAX_GAUSSIANS;
    let component = r#"{"weight":1,"mean":[0],"cov":1}"#;
    let many = |n: usize| alloc::format!("[{}]", vec![component; n].join(","));
    let m: GaussianMixture = serde_json::from_str(&many(MAX_GAUSSIANS)).unwrap();
    assert_eq!(m.len(), MAX_GAUSSIANS);
    assert_eq!(
        without_position(rejected::<GaussianMixture>(&many(MAX_GAUSSIANS + 1))),
        "has 10001 entries, at most 10000 are supported"
    );
    assert_eq!(
        without_position(rejected::<GaussianMixture>(
            r#"[{"weight":1,"mean":[0],"cov":1,"w":1}]"#
        )),
        "unknown field `w`, expected one of `weight`, `mean`, `cov`"
    );
}

#[test]
fn costs_read_the_mpe_and_mmol_presets_and_name_fields_relative_to_the_costs() {
    let read = |json: &str| serde_json::from_str::<Costs>(json);
    assert_eq!(read(r#""mpe""#).unwrap(), Costs::mpe());
    let mmol = read(r#"{"mmol":{"asset":0.9,"countermeasure":0.1}}"#).unwrap();
    assert_eq!(mmol, Costs::mmol(0.9, 0.1).unwrap());
    // written as the five costs, read back equal
    assert_eq!(read(&serde_json::to_string(&mmol).unwrap()).unwrap(), mmol);
    assert!(rejected::<Costs>(r#""MPE""#).contains(r#"must be 'mpe', { mmol: { asset, countermeasure } } or { c00, c01, c10, c11, c }, got "MPE""#));
    assert!(
        rejected::<Costs>(r#"{"mmol":{"asset":-1.0,"countermeasure":0.1}}"#)
            .starts_with(".mmol.asset must be finite and >= 0")
    );
    assert!(
        rejected::<Costs>(r#"{"mmol":{"asset":1.0,"countermeasure":0.1},"c00":0.0}"#)
            .contains("mmol together with c00…c")
    );
    assert!(rejected::<Costs>(r#"{"c00":0.0,"c01":1.0,"c10":1.0,"c":1.0}"#).contains("c11"));
    assert!(
        rejected::<Costs>(r#"{"c00":0.0,"c01":1.0,"c10":1.0,"c11":0.0,"c":1.0,"d":1.0}"#)
            .contains("unknown field `d`")
    );
}

#[test]
fn loss_curve_options_read_with_the_threshold_optional_and_the_curve_round_trips() {
    use crate::bernoulli::{LossCurveOptions, loss_curve};
    let o: LossCurveOptions =
        serde_json::from_str(r#"{"existences":[0.2,0.9],"miss_probability":0.3,"costs":"mpe"}"#)
            .unwrap();
    assert_eq!(
        o,
        LossCurveOptions {
            existences: vec![0.2, 0.9],
            miss_probability: 0.3,
            costs: Costs::mpe(),
            threshold: None,
        }
    );
    round_trip(&o);
    round_trip(&loss_curve(&o).unwrap());
    assert!(
        rejected::<LossCurveOptions>(r#"{"existences":[0.2],"costs":"mpe"}"#)
            .contains("miss_probability")
    );
}

/// The Bernoulli estimators' options and results (paper 000): the options read the density and
/// costs in their written forms, a report writes `estimate: null` when nothing is declared, and
/// the MMUC method is kebab case.
#[test]
fn bernoulli_estimate_options_and_reports_round_trip() {
    use crate::bernoulli::{
        BernoulliEstimateOptions, MmucOptions, MultiBernoulliPointOptions, MultiBernoulliReport,
    };
    let o: BernoulliEstimateOptions = serde_json::from_str(
        r#"{"existence": 0.3, "density": {"mean": [0.0], "cov": 4.0}, "radius": 1.0, "costs": "mpe"}"#,
    )
    .unwrap();
    round_trip(&o);
    let r = o.estimate().unwrap();
    assert!(!r.declare);
    let json = round_trip(&r);
    assert!(json.contains(r#""estimate":null"#), "{json}");
    assert!(json.contains(r#""miss_probability":"#), "{json}");
    let m: MmucOptions = serde_json::from_str(
        r#"{"density": {"mean": [1.0, 2.0], "cov": [[1.0, 0.0], [0.0, 1.0]]}, "radius": 0.5}"#,
    )
    .unwrap();
    let json = round_trip(&m.estimate().unwrap());
    assert!(json.contains(r#""method":"gaussian-mean""#), "{json}");
    let mb: MultiBernoulliPointOptions = serde_json::from_str(
        r#"{"components": [{"existence": 0.9, "density": {"particles": [[0.0], [0.1]]}}], "radius": 1.0, "costs": {"mmol": {"asset": 0.9, "countermeasure": 0.1}}}"#,
    )
    .unwrap();
    let r: MultiBernoulliReport = mb.estimate().unwrap();
    assert_eq!(r.reported, vec![0]);
    round_trip(&r);
    assert!(
        rejected::<BernoulliEstimateOptions>(
            r#"{"existence": 0.3, "radius": 1.0, "costs": "mpe"}"#
        )
        .contains("missing field `density`")
    );
}

/// `jde_bound`'s report (paper 002) is written as the bindings return it: named terms,
/// `"HPE"`/`"LPE"`, kebab-case methods, and no `seed`/`components` when absent.
#[test]
fn jde_bound_report_is_written_with_named_terms_and_methods() {
    use crate::bounds::{
        JdeBoundReport, JdeModel, JdeObservation, JdeOptions, JdePrior, jde_bound,
    };
    let o = JdeOptions::new(
        JdeModel::I,
        0.6,
        JdePrior::Scalar(Density1::gaussian(1.0, 4.0).unwrap()),
        JdeObservation::Scalar(
            LinearGaussian::new(bounds::Detection::constant(0.8).unwrap(), 2.0, 0.5, 1.5).unwrap(),
        ),
        6.0,
        9.0,
    );
    let r = JdeBoundReport::from(&jde_bound(&o, || unreachable!()).unwrap());
    let json = round_trip(&r);
    for part in [
        r#""name":"estimation""#,
        r#""name":"falseTarget""#,
        r#""method":"quadrature""#,
        r#""existence_threshold":"#,
    ] {
        assert!(json.contains(part), "{part} not in {json}");
    }
    assert!(json.contains(r#""phase":"HPE""#) || json.contains(r#""phase":"LPE""#));
    assert!(
        !json.contains("seed") && !json.contains("components"),
        "{json}"
    );
}

#[test]
fn split_requests_read_their_defaults_and_write_the_flat_shapes() {
    use crate::splitting::{
        NegativeInformationOptions, NegativeInformationReport, NegativeInformationResult, Spacing,
        SplitForRegionsOptions, SplitLibraryOptions, SplitLibraryReport,
    };
    let lib: SplitLibraryOptions =
        serde_json::from_str(r#"{"components":4,"lambda_":0.001}"#).unwrap();
    assert_eq!(lib.spacing, Spacing::Equal);
    let free: SplitLibraryOptions =
        serde_json::from_str(r#"{"components":4,"lambda_":0.001,"spacing":"free"}"#).unwrap();
    assert_eq!(free.spacing, Spacing::Free);
    let json = serde_json::to_value(SplitLibraryReport::from(&lib.library().unwrap())).unwrap();
    let keys: Vec<&str> = json
        .as_object()
        .unwrap()
        .keys()
        .map(|k| k.as_str())
        .collect();
    assert_eq!(keys, ["means", "objective", "sigma", "variance", "weights"]);

    let o: SplitForRegionsOptions = serde_json::from_str(
        r#"{"mixture":[{"weight":1,"mean":[0,0],"cov":[[1,0],[0,1]]}],
            "regions":[{"box":{"min":[0,0],"max":[1,1]}},{"ball":{"center":[0,0],"radius":1}}]}"#,
    )
    .unwrap();
    let d = SplitForRegionsOptions::new(o.mixture.clone(), o.regions.clone());
    assert_eq!(
        (
            o.position_dims,
            o.min_weight,
            o.components,
            o.lambda_,
            o.spacing
        ),
        (
            d.position_dims,
            d.min_weight,
            d.components,
            d.lambda_,
            d.spacing
        )
    );
    assert_eq!(
        (o.grid_bound, o.grid_points, o.max_depth, o.max_components),
        (d.grid_bound, d.grid_points, d.max_depth, d.max_components)
    );

    let none: NegativeInformationOptions = serde_json::from_str("{}").unwrap();
    assert_eq!(none.step, None);
    let report = NegativeInformationReport::fig5().unwrap();
    let one = NegativeInformationOptions { step: Some(1) }
        .select(&report)
        .unwrap();
    let NegativeInformationResult::Step(s) = &one else {
        panic!("{one:?}")
    };
    let json = serde_json::to_value(&one).unwrap();
    assert_eq!(json["depth"], s.depth);
    assert_eq!(json["split"].as_array().unwrap().len(), s.split.len());
    let whole = serde_json::to_value(&report).unwrap();
    assert_eq!(
        whole["fov"],
        serde_json::json!({"box": {"min": [-1.5, -1.5], "max": [1.5, 1.5]}})
    );
}

#[test]
fn airport_report_is_the_scenario_with_its_filter_config_and_seed() {
    use crate::filters::{default_mcmc_moves, default_particles};
    use crate::sim::airport::AirportScenarioReport;
    let r = AirportScenarioReport::new(7, 3).unwrap();
    let sc = airport_scenario(7, 3).unwrap();
    assert_eq!((r.seed, r.config.seed), (7, 7));
    assert_eq!(
        (r.config.particles, r.config.mcmc_moves),
        (default_particles(), default_mcmc_moves())
    );
    assert_eq!(r.truth, sc.truth);
    assert_eq!(r.concourse, Region::from(sc.concourse));
    let json = serde_json::to_value(&r).unwrap();
    assert_eq!(
        json["concourse"],
        serde_json::json!({"box": {"min": [0.0, 0.0], "max": [300.0, 30.0]}})
    );
    assert_eq!(json["config"]["clutter"]["density"], 0.1);
    assert!(AirportScenarioReport::new(7, 2001).is_err());
}
