//! Tests of [`jde_bound`](super::jde_bound): each dispatch branch against the function it
//! dispatches to (bit for bit, with the settings the JavaScript binding used to build), each
//! error, and the scalar/vector agreement for l = 1 (paper 002 Theorems 1, 2, (63)–(72)).

use alloc::string::ToString;

use super::*;
use crate::bounds::Detection;

const ENTROPY_SEED: u64 = 12_345;

fn no_entropy() -> Result<u64> {
    panic!("entropy must not be asked for here")
}

fn some_entropy() -> Result<u64> {
    Ok(ENTROPY_SEED)
}

fn scalar_prior() -> Density1 {
    Density1::gaussian(1.0, 4.0).unwrap()
}

fn scalar_observation() -> LinearGaussian {
    LinearGaussian::new(Detection::constant(0.8).unwrap(), 2.0, 0.5, 1.5).unwrap()
}

fn unit_clutter(rate: f64) -> JdeClutter {
    JdeClutter {
        rate,
        density: Density1::uniform(-10.0, 10.0).unwrap(),
    }
}

fn scalar(model: JdeModel) -> JdeOptions {
    JdeOptions::new(
        model,
        0.6,
        JdePrior::Scalar(scalar_prior()),
        JdeObservation::Scalar(scalar_observation()),
        6.0,
        9.0,
    )
}

/// The same problem with a Gaussian prior in R^1 and the sensor H = [[2]].
fn vector_of_one(model: JdeModel) -> JdeOptions {
    JdeOptions {
        prior: JdePrior::Vector(GaussianPrior::new(&[1.0], &[4.0]).unwrap()),
        observation: JdeObservation::Vector(
            LinearGaussianSensor::new(0.8, &[2.0], 1, &[0.5], &[1.5]).unwrap(),
        ),
        ..scalar(model)
    }
}

fn with_false_alarms(o: JdeOptions) -> JdeOptions {
    JdeOptions {
        false_alarm: Some(JdeFalseAlarm {
            probability: 0.3,
            density: Density1::uniform(-10.0, 10.0).unwrap(),
        }),
        ..o
    }
}

#[test]
fn thm1_model_i_dispatches_to_theorem1() {
    let o = with_false_alarms(scalar(JdeModel::I));
    let out = jde_bound(&o, no_entropy).unwrap();
    let want = theorem1(
        &ModelI {
            existence: 0.6,
            prior: &scalar_prior(),
            observation: &scalar_observation(),
            false_alarm_probability: 0.3,
            false_alarm_density: &Density1::uniform(-10.0, 10.0).unwrap(),
            false_alarm_error: 6.0,
            miss_error: 9.0,
        },
        &TheoremOptions::default(),
    )
    .unwrap();
    assert_eq!(out.bound, want);
    assert_eq!(
        (out.components, out.inverse_information, out.seed),
        (None, None, None)
    );
    // without false alarms: q = 0
    let out = jde_bound(&scalar(JdeModel::I), no_entropy).unwrap();
    assert_eq!(out.bound.cardinalities.len(), 1);
}

#[test]
fn thm2_model_ii_dispatches_to_theorem2_with_the_seed_and_samples() {
    let o = JdeOptions {
        clutter: Some(unit_clutter(0.5)),
        samples: Some(200),
        seed: Some(3),
        ..scalar(JdeModel::II)
    };
    let out = jde_bound(&o, no_entropy).unwrap();
    let settings = TheoremOptions {
        samples: 200,
        seed: 3,
        ..TheoremOptions::default()
    };
    let want = theorem2(
        &ModelII {
            existence: 0.6,
            prior: &scalar_prior(),
            observation: &scalar_observation(),
            clutter_rate: 0.5,
            clutter_density: &unit_clutter(0.5).density,
            false_alarm_error: 6.0,
            miss_error: 9.0,
        },
        &settings,
    )
    .unwrap();
    assert_eq!(out.bound, want);
    assert_eq!(out.seed, Some(3));
    // no seed given: entropy gives it, and it is reported
    let o = JdeOptions { seed: None, ..o };
    assert_eq!(
        jde_bound(&o, some_entropy).unwrap().seed,
        Some(ENTROPY_SEED)
    );
    // entropy's error is the error
    let e = jde_bound(&o, || Err(Error::parameter("seed", 0.0, "available"))).unwrap_err();
    assert_eq!(e.field(), "seed");
}

#[test]
fn thm2_without_clutter_samples_nothing_and_needs_no_seed() {
    for o in [
        scalar(JdeModel::II),
        JdeOptions {
            clutter: Some(unit_clutter(0.0)),
            ..scalar(JdeModel::II)
        },
    ] {
        let out = jde_bound(&o, no_entropy).unwrap();
        assert_eq!(out.seed, None);
    }
}

#[test]
fn thm2_samples_lie_in_their_range() {
    for (samples, ok) in [
        (99, false),
        (100, true),
        (1_000_000, true),
        (1_000_001, false),
    ] {
        let o = JdeOptions {
            samples: Some(samples),
            ..scalar(JdeModel::II)
        };
        let r = jde_bound(&o, no_entropy);
        assert_eq!(r.is_ok(), ok, "{samples}");
        if let Err(e) = r {
            assert_eq!(
                e.to_string(),
                alloc::format!("samples must be an integer in [100, 1000000], got {samples}")
            );
        }
    }
}

/// λ = 1 keeps N = 9 clutter counts (the Poisson tail beyond 9 is 1.1e-7 < 1e-6), so the
/// Monte Carlo samples n = 2 … 10, Σ n = 54 (52 with the n = 2 cubature, the default on this
/// linear-Gaussian model).
#[test]
fn thm2_work_cap_is_samples_times_the_sampled_cardinalities() {
    let o = JdeOptions {
        clutter: Some(unit_clutter(1.0)),
        samples: Some(1_000_000),
        seed: Some(1),
        quadrature_cardinality: Some(1),
        ..scalar(JdeModel::II)
    };
    let e = jde_bound(&o, no_entropy).unwrap_err();
    assert_eq!(
        e.to_string(),
        "samples: samples × Σ n = 54000000 exceeds 10^7 at this clutter rate; pass fewer samples (at most 185185)"
    );
    for k in [Some(2), None] {
        let o = JdeOptions {
            quadrature_cardinality: k,
            ..o.clone()
        };
        let e = jde_bound(&o, no_entropy).unwrap_err();
        assert!(matches!(
            e,
            Error::OverBudget {
                work: 52_000_000,
                at_most: 192_307,
                ..
            }
        ));
    }
    // 185185 × 54 = 9,999,990 is within the cap: the check passes (then the dims check of a
    // bad option fails, so the Monte Carlo is not run)
    let o = JdeOptions {
        samples: Some(185_185),
        quadrature_cardinality: None,
        observation: JdeObservation::Vector(
            LinearGaussianSensor::new(0.8, &[2.0], 1, &[0.5], &[1.5]).unwrap(),
        ),
        ..o
    };
    assert_eq!(
        jde_bound(&o, no_entropy).unwrap_err().field(),
        "observation"
    );
}

#[test]
fn thm1_thm2_false_observations_belong_to_their_model() {
    let o = JdeOptions {
        clutter: Some(unit_clutter(1.0)),
        ..scalar(JdeModel::I)
    };
    let e = jde_bound(&o, no_entropy).unwrap_err();
    assert_eq!(e, wrong_model(true));
    assert!(e.is_wrong_kind());
    assert_eq!(
        e.to_string(),
        "clutter is for model 'II' (use false_alarm with model 'I')"
    );
    let o = with_false_alarms(scalar(JdeModel::II));
    assert_eq!(
        jde_bound(&o, no_entropy).unwrap_err().field(),
        "false_alarm"
    );
}

#[test]
fn eq63_dims_and_quadrature_cardinality_are_checked() {
    let dims = |o: JdeOptions, l| jde_bound(&JdeOptions { dims: Some(l), ..o }, no_entropy);
    for l in [0, 65] {
        let e = dims(scalar(JdeModel::I), l).unwrap_err();
        assert_eq!(e, Error::range("dims", l, 1, 64));
    }
    assert_eq!(
        dims(scalar(JdeModel::I), 2).unwrap_err().to_string(),
        "dims is 2, but prior is a 1D density: a state in R^2 needs prior: { multivariate_gaussian: { mean, cov } }"
    );
    assert!(dims(scalar(JdeModel::I), 1).is_ok());
    let e = dims(vector_of_one(JdeModel::I), 3).unwrap_err();
    assert_eq!(
        e.to_string(),
        "dims is 3, but prior.multivariate_gaussian.mean has length 1"
    );
    // each binding renders the paths and names in its own names
    let e = e
        .within("options")
        .map_paths(|p| p.replace("multivariate_gaussian", "mvg"));
    assert_eq!(
        e.to_string(),
        "options.dims is 3, but options.prior.mvg.mean has length 1"
    );
    assert!(dims(vector_of_one(JdeModel::I), 1).is_ok());
    let o = JdeOptions {
        quadrature_cardinality: Some(3),
        ..scalar(JdeModel::II)
    };
    let e = jde_bound(&o, no_entropy).unwrap_err();
    assert_eq!(
        e.to_string(),
        "quadrature_cardinality must be an integer in [1, 2], got 3"
    );
    let o = JdeOptions {
        observation: JdeObservation::Vector(
            LinearGaussianSensor::new(0.8, &[2.0], 1, &[0.5], &[1.5]).unwrap(),
        ),
        ..scalar(JdeModel::I)
    };
    assert_eq!(
        jde_bound(&o, no_entropy).unwrap_err().field(),
        "observation"
    );
}

/// (63): a Gaussian prior in R^1 with H = [[a]] is the scalar problem; the outcome carries
/// the component bound and the 1 × 1 inverse information matrix.
#[test]
fn eq63_a_vector_of_one_is_the_scalar_bound() {
    let tight = Some(1e-12);
    for model in [JdeModel::I, JdeModel::II] {
        let (s, v) = match model {
            JdeModel::I => (
                with_false_alarms(scalar(model)),
                with_false_alarms(vector_of_one(model)),
            ),
            JdeModel::II => (scalar(model), vector_of_one(model)),
        };
        let s = jde_bound(
            &JdeOptions {
                tolerance: tight,
                ..s
            },
            no_entropy,
        )
        .unwrap();
        let v = jde_bound(
            &JdeOptions {
                tolerance: tight,
                ..v
            },
            no_entropy,
        )
        .unwrap();
        let (a, b) = (&s.bound.assembled, &v.bound.assembled);
        assert!((a.bound - b.bound).abs() < 1e-10, "{model:?}");
        assert_eq!(a.phase, b.phase);
        let c = v.components.as_ref().unwrap();
        assert_eq!(c.len(), 1);
        assert!((c[0].assembled.bound - a.bound).abs() < 1e-10);
        let rows = v.inverse_information.unwrap();
        assert_eq!(rows.len(), 1);
        assert_eq!(rows[0], [c[0].inverse_information]);
    }
}

/// The vector branch returns [`vector_bound`]'s numbers, with its matrix as rows.
#[test]
fn eq64_vector_outcome_is_the_vector_bound() {
    let prior = GaussianPrior::new(&[0.5, -1.0], &[4.0, 1.2, 1.2, 2.0]).unwrap();
    let sensor = LinearGaussianSensor::new(0.8, &[1.0, 0.5], 2, &[0.2], &[1.0]).unwrap();
    let o = with_false_alarms(JdeOptions {
        prior: JdePrior::Vector(prior.clone()),
        observation: JdeObservation::Vector(sensor.clone()),
        dims: Some(2),
        ..scalar(JdeModel::I)
    });
    let out = jde_bound(&o, no_entropy).unwrap();
    let psi = Density1::uniform(-10.0, 10.0).unwrap();
    let want = vector_bound(
        &VectorModel {
            existence: 0.6,
            prior: &prior,
            sensor: &sensor,
            measurement: VectorMeasurement::I {
                false_alarm_probability: 0.3,
                false_alarm_density: &psi,
            },
            false_alarm_error: 6.0,
            miss_error: 9.0,
        },
        &TheoremOptions::default(),
    )
    .unwrap();
    assert_eq!(out.bound, want.total);
    assert_eq!(out.components.unwrap(), want.components);
    let rows = out.inverse_information.unwrap();
    assert_eq!(rows.concat(), want.inverse_information);
    assert_eq!(rows.len(), 2);
}

#[cfg(feature = "serde")]
#[test]
fn thm1_thm2_models_and_empty_rules_read_their_names() {
    use crate::bounds::EmptyRule;
    let m: [JdeModel; 2] = serde_json::from_str(r#"["I", "II"]"#).unwrap();
    assert_eq!(m, [JdeModel::I, JdeModel::II]);
    assert!(serde_json::from_str::<JdeModel>(r#""III""#).is_err());
    let rules: [EmptyRule; 4] =
        serde_json::from_str(r#"["optimal", "map", "declare", "reject"]"#).unwrap();
    assert_eq!(
        rules,
        [
            EmptyRule::Optimal,
            EmptyRule::Map,
            EmptyRule::Declare,
            EmptyRule::Reject
        ]
    );
    assert_eq!(serde_json::to_string(&EmptyRule::Map).unwrap(), r#""map""#);
    assert!(serde_json::from_str::<EmptyRule>(r#""hpe""#).is_err());
}

/// The flattened report (what the bindings return) holds the outcome's numbers unchanged:
/// the assembled bound, the four named terms in the paper's order, each cardinality, the
/// seed, and for a vector state each coordinate and J'⁻¹.
#[test]
fn report_flattens_the_outcome_of_theorems_1_and_2() {
    let o = JdeOptions {
        clutter: Some(unit_clutter(0.5)),
        samples: Some(200),
        seed: Some(3),
        ..scalar(JdeModel::II)
    };
    let out = jde_bound(&o, no_entropy).unwrap();
    let r = JdeBoundReport::from(&out);
    let a = &out.bound.assembled;
    assert_eq!(
        (r.bound, r.phase, r.existence_threshold, r.hpe, r.lpe),
        (a.bound, a.phase, a.existence_threshold, a.hpe, a.lpe)
    );
    let names = r.terms.iter().map(|t| t.name).collect::<Vec<_>>();
    assert_eq!(
        names,
        [
            TermName::Estimation,
            TermName::Undetected,
            TermName::Missed,
            TermName::FalseTarget
        ]
    );
    let values = r.terms.iter().map(|t| t.value).collect::<Vec<_>>();
    assert_eq!(
        values,
        [
            a.terms.estimation,
            a.terms.undetected,
            a.terms.missed,
            a.terms.false_target
        ]
    );
    assert_eq!(r.cardinalities.len(), out.bound.cardinalities.len());
    for (c, k) in r.cardinalities.iter().zip(&out.bound.cardinalities) {
        assert_eq!(
            (c.n, c.w, c.inverse_information, c.method, c.error),
            (k.n, k.w, k.inverse_information, k.method, k.error)
        );
    }
    assert!(
        r.cardinalities
            .iter()
            .any(|c| c.method == Method::MonteCarlo)
    );
    assert_eq!(
        (r.seed, r.error, r.regular),
        (Some(3), out.bound.error, true)
    );
    assert_eq!((r.components, r.inverse_information_matrix), (None, None));

    let v = jde_bound(&vector_of_one(JdeModel::I), no_entropy).unwrap();
    let r = JdeBoundReport::from(&v);
    let comps = v.components.as_ref().unwrap();
    let rc = r.components.as_ref().unwrap();
    assert_eq!(rc.len(), comps.len());
    assert_eq!(rc[0].bound, comps[0].assembled.bound);
    assert_eq!(rc[0].inverse_information, comps[0].inverse_information);
    assert_eq!(rc[0].terms.len(), 4);
    assert_eq!(r.inverse_information_matrix, v.inverse_information);
    assert_eq!(r.seed, None);
}
