//! Tests of the options of `jde_bound` and `jde_monte_carlo` as the bindings read them
//! (paper 002): defaults, the checks that need the options together, and the Rust paths of
//! their errors.

use alloc::string::ToString;

use super::*;
use crate::error::Error;

fn read<T: serde::de::DeserializeOwned>(json: &str) -> T {
    serde_json::from_str(json).unwrap()
}

const SCALAR: &str = r#"{"model": "I", "existence": 0.5,
    "prior": {"gaussian": {"mean": 0, "variance": 4}},
    "observation": {"detection_probability": 0.9, "noise_variance": 1},
    "false_alarm_error": 1, "miss_error": 2}"#;

fn scalar_with(observation: &str) -> JdeBoundOptions {
    let mut o: JdeBoundOptions = read(SCALAR);
    o.observation = read(observation);
    o
}

fn vector_with(observation: &str) -> JdeBoundOptions {
    let mut o: JdeBoundOptions = read(SCALAR);
    o.prior = read(r#"{"multivariate_gaussian": {"mean": [0, 1], "cov": [[2, 0.5], [0.5, 1]]}}"#);
    o.observation = read(observation);
    o
}

fn no_entropy() -> crate::Result<u64> {
    panic!("no Monte Carlo here")
}

#[test]
fn defaults_are_the_core_options() {
    // gain 1, offset 0, every numerical setting the core's default (None)
    let o: JdeBoundOptions = read(SCALAR);
    let core = o.clone().into_core().unwrap();
    let expected = JdeOptions::new(
        JdeModel::I,
        0.5,
        JdePrior::Scalar(Density1::gaussian(0.0, 4.0).unwrap()),
        JdeObservation::Scalar(
            LinearGaussian::new(Detection::constant(0.9).unwrap(), 1.0, 0.0, 1.0).unwrap(),
        ),
        1.0,
        2.0,
    );
    assert_eq!(core, expected);
    // and the report is jde_bound's, bit for bit
    let report = o.run(no_entropy).unwrap();
    let direct = JdeBoundReport::from(&jde_bound(&expected, no_entropy).unwrap());
    assert_eq!(report, direct);
    // a Monte Carlo request's omitted fields are JdeMonteCarloOptions::default()'s
    let r: JdeMonteCarloRequest = read(
        r#"{"model": "I", "existence": 1, "prior": {"gaussian": {"mean": 0, "variance": 100}},
            "observation": {"detection_probability": 0.5, "noise_variance": 33.3},
            "false_alarm_error": 150, "miss_error": 200}"#,
    );
    assert_eq!(
        (r.samples, r.scans, r.empty_rule, r.seed),
        (None, None, None, None)
    );
}

#[test]
fn eq13_a_scalar_prior_takes_numbers() {
    let ok = scalar_with(
        r#"{"detection_probability": 0.9, "gain": 2, "offset": 1, "noise_variance": 3}"#,
    );
    match ok.into_core().unwrap().observation {
        JdeObservation::Scalar(g) => assert_eq!(
            g,
            LinearGaussian::new(Detection::constant(0.9).unwrap(), 2.0, 1.0, 3.0).unwrap()
        ),
        JdeObservation::Vector(_) => panic!("a 1D prior has a scalar observation"),
    }
    let cases = [
        (
            r#"{"detection_probability": 0.9, "gain": [[1]], "noise_variance": 1}"#,
            "observation.gain must be a number with a 1D prior (gain rows are H for a multivariate_gaussian prior)",
        ),
        (
            r#"{"detection_probability": 0.9, "offset": [0], "noise_variance": 1}"#,
            "observation.offset must be a number with a 1D prior",
        ),
        (
            r#"{"detection_probability": 0.9, "noise_cov": [[1]], "noise_variance": 1}"#,
            "observation.noise_cov is for a multivariate_gaussian prior (use noise_variance with a 1D prior)",
        ),
        (
            r#"{"detection_probability": 0.9}"#,
            "observation.noise_variance is required",
        ),
    ];
    for (observation, message) in cases {
        let e = scalar_with(observation).into_core().unwrap_err();
        assert!(e.is_wrong_kind(), "{e}");
        assert_eq!(e.to_string(), message);
    }
    // a bad value is the core's value error, named under `observation`
    let e = scalar_with(r#"{"detection_probability": 0.9, "noise_variance": 0}"#)
        .into_core()
        .unwrap_err();
    assert!(!e.is_wrong_kind());
    assert_eq!(e.field(), "observation.noise_variance");
}

#[test]
fn eq63_a_vector_prior_takes_rows_and_noise_cov() {
    let o = vector_with(r#"{"detection_probability": 0.8, "gain": [[1, 0]], "noise_variance": 2}"#);
    let core = o.into_core().unwrap();
    assert_eq!(
        core.prior,
        JdePrior::Vector(GaussianPrior::new(&[0.0, 1.0], &[2.0, 0.5, 0.5, 1.0]).unwrap())
    );
    assert_eq!(
        core.observation,
        JdeObservation::Vector(
            LinearGaussianSensor::new(0.8, &[1.0, 0.0], 2, &[0.0], &[2.0]).unwrap()
        )
    );
    // two rows: an offset of 0 serves both, R as row-major numbers
    let o = vector_with(
        r#"{"detection_probability": 0.8, "gain": [[1, 0], [0, 1]], "offset": 0, "noise_cov": [1, 0, 0, 1]}"#,
    );
    assert_eq!(
        o.into_core().unwrap().observation,
        JdeObservation::Vector(
            LinearGaussianSensor::new(
                0.8,
                &[1.0, 0.0, 0.0, 1.0],
                2,
                &[0.0, 0.0],
                &[1.0, 0.0, 0.0, 1.0]
            )
            .unwrap()
        )
    );
    // (observation, wrong kind?, message)
    let cases = [
        (
            r#"{"detection_probability": {"table": {"x": [0, 1], "probability": [0.5, 0.9]}}, "gain": [[1, 0]], "noise_variance": 1}"#,
            true,
            "observation.detection_probability must be a number (a constant P_o) with a multivariate_gaussian prior",
        ),
        (
            r#"{"detection_probability": 0.8, "gain": 1, "noise_variance": 1}"#,
            true,
            "observation.gain must be H, m rows of 2 numbers, for a state in R^2",
        ),
        (
            r#"{"detection_probability": 0.8, "gain": [[1, 0.5], [1]], "noise_cov": [[1, 0], [0, 1]]}"#,
            false,
            "observation.gain[1] has length 1, expected 2 (the state dimension)",
        ),
        (
            r#"{"detection_probability": 0.8, "gain": [[1, 0], [0, 1]], "offset": 1, "noise_cov": [[1, 0], [0, 1]]}"#,
            true,
            "observation.offset must be 2 numbers (gain has 2 rows)",
        ),
        (
            r#"{"detection_probability": 0.8, "gain": [[1, 0]], "offset": [0, 1], "noise_variance": 1}"#,
            false,
            "observation.offset has length 2, expected 1 (gain has 1 rows)",
        ),
        (
            r#"{"detection_probability": 0.8, "gain": [[1, 0]], "noise_variance": 1, "noise_cov": [[1]]}"#,
            true,
            "observation.noise_variance and observation.noise_cov are alternatives: give one",
        ),
        (
            r#"{"detection_probability": 0.8, "gain": [[1, 0]]}"#,
            true,
            "observation.noise_cov is required (or noise_variance when gain has one row)",
        ),
        (
            r#"{"detection_probability": 0.8, "gain": [[1, 0], [0, 1]], "noise_variance": 1}"#,
            true,
            "observation.noise_variance serves a gain of one row; gain has 2 rows: give noise_cov (2 × 2)",
        ),
        (
            r#"{"detection_probability": 0.8, "gain": [[1, 0]], "noise_variance": -1}"#,
            false,
            "observation.noise_variance must be > 0, got -1",
        ),
        (
            r#"{"detection_probability": 0.8, "gain": [[1, 0], [0, 1]], "noise_cov": [[1, 0], [0]]}"#,
            false,
            "observation.noise_cov[1] has length 1, expected 2",
        ),
    ];
    for (observation, wrong_kind, message) in cases {
        let e = vector_with(observation).into_core().unwrap_err();
        assert_eq!(e.is_wrong_kind(), wrong_kind, "{e}");
        assert_eq!(e.to_string(), message);
    }
    // the kind comes first: a bad table is still "a constant only" with a vector prior
    let e = vector_with(
        r#"{"detection_probability": {"table": {"x": [1, 0], "probability": [0.5, 0.9]}}, "gain": [[1, 0]]}"#,
    )
    .into_core()
    .unwrap_err();
    assert!(e.is_wrong_kind());
    assert_eq!(e.field(), "observation.detection_probability");
    // and with a 1D prior the table's own error names its knot
    let e = scalar_with(
        r#"{"detection_probability": {"table": {"x": [1, 0], "probability": [0.5, 0.9]}}, "noise_variance": 1}"#,
    )
    .into_core()
    .unwrap_err();
    assert_eq!(e.field(), "observation.detection_probability.table.x[1]");
    let e = scalar_with(r#"{"detection_probability": 1.5, "noise_variance": 1}"#)
        .into_core()
        .unwrap_err();
    assert_eq!(
        e.to_string(),
        "observation.detection_probability must be a probability in [0, 1], got 1.5"
    );
    let e = vector_with(r#"{"detection_probability": 0.8, "gain": [], "noise_variance": 1}"#)
        .into_core()
        .unwrap_err();
    assert_eq!(e.field(), "observation.gain");
    // the prior's own errors, under prior.multivariate_gaussian
    let prior = |json: &str| {
        let mut o =
            vector_with(r#"{"detection_probability": 0.8, "gain": [[1, 0]], "noise_variance": 1}"#);
        o.prior = read(json);
        o.into_core().unwrap_err()
    };
    let e = prior(r#"{"multivariate_gaussian": {"mean": [0, 0], "cov": 1}}"#);
    assert!(e.is_wrong_kind());
    assert_eq!(e.field(), "prior.multivariate_gaussian.cov");
    let e = prior(r#"{"multivariate_gaussian": {"mean": [0, 0], "cov": [[1, 0], [0]]}}"#);
    assert_eq!(
        e.to_string(),
        "prior.multivariate_gaussian.cov[1] has length 1, expected 2"
    );
    let e = prior(r#"{"multivariate_gaussian": {"mean": [], "cov": []}}"#);
    assert_eq!(e.field(), "prior.multivariate_gaussian.mean.length");
    let e = prior(r#"{"multivariate_gaussian": {"mean": [0, 0], "cov": [[1.25, 0], [0, -0.25]]}}"#);
    assert_eq!(
        e.to_string(),
        "prior.multivariate_gaussian.cov is not positive definite (smallest eigenvalue -0.25)"
    );
}

#[test]
fn eq13_eq22_false_observations_belong_to_their_model() {
    let mut o: JdeBoundOptions = read(SCALAR);
    o.clutter = Some(read(
        r#"{"rate": 1, "density": {"uniform": {"low": -10, "high": 10}}}"#,
    ));
    let e = o.run(no_entropy).unwrap_err();
    assert!(e.is_wrong_kind());
    assert_eq!(
        e.to_string(),
        "clutter is for model 'II' (use false_alarm with model 'I')"
    );
    let mut r: JdeMonteCarloRequest = read(
        r#"{"model": "II", "existence": 1, "prior": {"gaussian": {"mean": 0, "variance": 1}},
            "observation": {"detection_probability": 0.5, "noise_variance": 1},
            "false_alarm_error": 1, "miss_error": 1, "seed": 1, "samples": 100}"#,
    );
    r.false_alarm = Some(read(
        r#"{"probability": 0.2, "density": {"uniform": {"low": -10, "high": 10}}}"#,
    ));
    let e = r.run(no_entropy).unwrap_err();
    assert!(e.is_wrong_kind());
    assert_eq!(
        e.to_string(),
        "false_alarm is for model 'I' (use clutter with model 'II')"
    );
    // renamed by a binding: the field by map_paths, the other model's field by map_names
    let js = e
        .within("options")
        .map_names(|n| n.replace("false_alarm", "falseAlarm"));
    assert_eq!(
        js.to_string(),
        "options.false_alarm is for model 'I' (use clutter with model 'II')"
    );
}

#[test]
fn eq11_the_request_runs_the_monte_carlo_with_its_defaults() {
    // Fig. 2 left at r = 1, P̄o = 0.5 (the core's jde_monte_carlo doctest), from the request
    let r: JdeMonteCarloRequest = read(
        r#"{"model": "I", "existence": 1, "prior": {"gaussian": {"mean": 0, "variance": 100}},
            "observation": {"detection_probability": 0.5, "noise_variance": 33.333333333333336},
            "false_alarm_error": 150, "miss_error": 200, "seed": 3, "samples": 2000}"#,
    );
    let out = r.run(no_entropy).unwrap();
    let prior = GaussianPrior::new(&[0.0], &[100.0]).unwrap();
    let sensor = LinearGaussianSensor::new(0.5, &[1.0], 1, &[0.0], &[100.0 / 3.0]).unwrap();
    let direct = jde_monte_carlo(
        &MonteCarloModel {
            existence: 1.0,
            system: SimulatedSystem::LinearGaussian {
                prior: &prior,
                sensor: &sensor,
            },
            measurement: VectorMeasurement::I {
                false_alarm_probability: 0.0,
                false_alarm_density: &UnitUniform,
            },
            false_alarm_error: 150.0,
            miss_error: 200.0,
        },
        &JdeMonteCarloOptions {
            samples: 2000,
            seed: 3,
            ..JdeMonteCarloOptions::default()
        },
    )
    .unwrap();
    assert_eq!(out, direct);
    assert_eq!(out.seed, 3);
    // no seed: the entropy's, reported
    let mut r2: JdeMonteCarloRequest = serde_json::from_str(
        r#"{"model": "I", "existence": 1, "prior": "example2",
            "observation": {"detection_probability": 0.9}, "false_alarm_error": 1,
            "miss_error": 1, "samples": 100}"#,
    )
    .unwrap();
    assert_eq!(r2.clone().run(|| Ok(42)).unwrap().seed, 42);
    // Example 2 takes a constant P_o; a 1D prior other than a Gaussian is not simulated
    r2.observation =
        read(r#"{"detection_probability": {"table": {"x": [0, 1], "probability": [0.5, 0.9]}}}"#);
    let e = r2.run(no_entropy).unwrap_err();
    assert!(e.is_wrong_kind());
    assert_eq!(
        e.to_string(),
        "observation.detection_probability must be a number (a constant P_o) for 'example2'"
    );
    let mut r3: JdeMonteCarloRequest = read(
        r#"{"model": "I", "existence": 1, "prior": {"uniform": {"low": 0, "high": 1}},
            "observation": {"detection_probability": 0.9, "noise_variance": 1},
            "false_alarm_error": 1, "miss_error": 1, "seed": 1}"#,
    );
    assert!(matches!(
        r3.clone().run(no_entropy).unwrap_err(),
        Error::Unsupported { ref what, .. } if what == "prior"
    ));
    r3.prior = MonteCarloPrior::MultivariateGaussian(read(r#"{"mean": [0], "cov": 0}"#));
    assert_eq!(
        r3.run(no_entropy).unwrap_err().field(),
        "prior.multivariate_gaussian.cov"
    );
}

#[test]
fn the_options_write_back_as_they_read() {
    let o = vector_with(r#"{"detection_probability": 0.8, "gain": [[1, 0]], "noise_variance": 2}"#);
    let json = serde_json::to_string(&o).unwrap();
    assert!(
        json.contains(r#""multivariate_gaussian":{"mean":[0.0,1.0]"#),
        "{json}"
    );
    let back: JdeBoundOptions = read(&json);
    assert_eq!(back, o);
    let r: JdeMonteCarloRequest = read(
        r#"{"model": "II", "existence": 1, "prior": "example2",
            "observation": {"detection_probability": 0.9}, "false_alarm_error": 1,
            "miss_error": 1, "empty_rule": "map"}"#,
    );
    let back: JdeMonteCarloRequest = read(&serde_json::to_string(&r).unwrap());
    assert_eq!(back, r);
    // each form writes as it reads (a 1D density other than a Gaussian, which the Monte
    // Carlo refuses, as the density)
    for (prior, json) in [
        (
            r#"{"gaussian": {"mean": 0, "variance": 2}}"#,
            r#"{"gaussian":{"mean":0.0,"variance":2.0}}"#,
        ),
        (
            r#"{"uniform": {"low": 0, "high": 1}}"#,
            r#"{"uniform":{"low":0.0,"high":1.0}}"#,
        ),
        (
            r#"{"multivariate_gaussian": {"mean": [1], "cov": 2}}"#,
            r#"{"multivariate_gaussian":{"mean":[1.0],"cov":2.0}}"#,
        ),
    ] {
        let p: MonteCarloPrior = read(prior);
        assert_eq!(serde_json::to_string(&p).unwrap(), json);
    }
    for (detection, json) in [
        ("0.5", "0.5"),
        (
            r#"{"table": {"x": [0, 1], "probability": [0.5, 0.9]}}"#,
            r#"{"table":{"x":[0.0,1.0],"probability":[0.5,0.9]}}"#,
        ),
    ] {
        let d: JdeDetectionOptions = read(detection);
        assert_eq!(serde_json::to_string(&d).unwrap(), json);
    }
}
