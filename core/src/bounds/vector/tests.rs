//! Tests of the vector bounds of paper 002, Section V: (63)/(64) against the scalar theorems,
//! (65) against the matrix information, (72) per component, and the errors' field names.

use super::*;
use crate::bounds::closed::{corollary1, corollary3, gaussian_no_clutter, no_clutter_ingredients};
use crate::bounds::model::{Density, Density1, Detection, LinearGaussian};
use crate::bounds::theorem::{Method, ModelI, theorem1};
use crate::bounds::theorem2::{ModelII, theorem2};

fn tight() -> TheoremOptions {
    TheoremOptions {
        tolerance: 1e-12,
        ..TheoremOptions::default()
    }
}

/// The vector problem with e0² = 6, e1² = 9 and the false observations `measurement`.
fn vector<'a>(
    r: f64,
    prior: &'a GaussianPrior,
    sensor: &'a LinearGaussianSensor,
    measurement: VectorMeasurement<'a>,
) -> VectorModel<'a> {
    VectorModel {
        existence: r,
        prior,
        sensor,
        measurement,
        false_alarm_error: 6.0,
        miss_error: 9.0,
    }
}

/// Model I's false observations: probability q, density ψ.
fn false_alarms(q: f64, psi: &dyn Density) -> VectorMeasurement<'_> {
    VectorMeasurement::I {
        false_alarm_probability: q,
        false_alarm_density: psi,
    }
}

/// Model II's clutter: rate λ, density c.
fn clutter(lambda: f64, c: &dyn Density) -> VectorMeasurement<'_> {
    VectorMeasurement::II {
        clutter_rate: lambda,
        clutter_density: c,
    }
}

/// Theorem 1 of a scalar problem with errors e0², e1², at the tight tolerance.
fn scalar_theorem1(
    r: f64,
    prior: &Density1,
    obs: &LinearGaussian,
    (q, psi): (f64, &Density1),
    (e0, e1): (f64, f64),
) -> JdeBound {
    theorem1(
        &ModelI {
            existence: r,
            prior,
            observation: obs,
            false_alarm_probability: q,
            false_alarm_density: psi,
            false_alarm_error: e0,
            miss_error: e1,
        },
        &tight(),
    )
    .unwrap()
}

#[test]
fn eq72_one_component_is_the_scalar_bound() {
    for &r in &[0.1, 0.5, 0.9] {
        let v = component_bounds_no_clutter(r, 0.4, &[25.0], &[100.0], 150.0, 200.0).unwrap();
        let s = gaussian_no_clutter(r, 0.4, 100.0, 25.0, 150.0, 200.0).unwrap();
        assert_eq!(v[0], s);
        let base = no_clutter_ingredients(r, 0.4, 25.0, 100.0, 150.0, 200.0);
        let c = component_bound(&base, 1, 25.0, 100.0).unwrap();
        assert!((c.bound - s.bound).abs() < 1e-12);
    }
    assert_eq!(
        component_corollary1(0.3, &[2.0], &[5.0])[0],
        corollary1(0.3, 2.0, 5.0)
    );
    let (j, inv) = gaussian_information_matrix(
        &DMatrix::from_element(1, 1, 4.0),
        &DMatrix::from_element(1, 1, 2.0),
        &DMatrix::from_element(1, 1, 1.0),
    )
    .unwrap();
    let s = crate::bounds::gaussian_fisher_information(4.0, 2.0, 1.0).unwrap();
    assert!((j[(0, 0)] - s.information).abs() < 1e-12);
    assert!((inv[(0, 0)] - s.posterior_variance).abs() < 1e-12);
}

#[test]
fn eq72_independent_components_split_the_scalar_error() {
    // Two independent, identically observed components: the thresholds use l σ_{e,i}²,
    // and each HPE line is the scalar one with e0²/2, e1²/2.
    let v = component_bounds_no_clutter(0.8, 0.5, &[1.0, 1.0], &[4.0, 4.0], 10.0, 20.0).unwrap();
    let rs = 10.0 / (10.0 + 0.5 * (20.0 - 2.0 * 4.0));
    assert!((v[0].existence_threshold - rs).abs() < 1e-15);
    assert_eq!(v[0], v[1]);
    let scalar = corollary3(0.8, 0.5, 1.0, 4.0, 5.0, 10.0).unwrap();
    assert_eq!(v[0], scalar);
    assert!(component_bounds_no_clutter(0.8, 0.5, &[1.0], &[4.0, 4.0], 1.0, 1.0).is_err());
}

#[test]
fn eq63_one_dimension_is_the_scalar_theorem() {
    let psi = Density1::uniform(-10.0, 10.0).unwrap();
    let (x0, var, gain, offset, noise) = (1.0, 4.0, 2.0, 0.5, 1.5);
    let prior = GaussianPrior::new(&[x0], &[var]).unwrap();
    let sensor = LinearGaussianSensor::new(0.8, &[gain], 1, &[offset], &[noise]).unwrap();
    let sprior = Density1::gaussian(x0, var).unwrap();
    let sobs = LinearGaussian::new(Detection::constant(0.8).unwrap(), gain, offset, noise).unwrap();
    for &r in &[0.2, 0.6, 0.95] {
        for &q in &[0.0, 0.3] {
            let v =
                vector_bound(&vector(r, &prior, &sensor, false_alarms(q, &psi)), &tight()).unwrap();
            let b = scalar_theorem1(r, &sprior, &sobs, (q, &psi), (6.0, 9.0));
            let c = &v.components[0].assembled;
            assert!((c.bound - b.assembled.bound).abs() < 1e-10, "{r} {q}");
            assert!((v.total.assembled.bound - b.assembled.bound).abs() < 1e-10);
            assert_eq!(c.phase, b.assembled.phase);
            assert!((c.existence_threshold - b.assembled.existence_threshold).abs() < 1e-10);
        }
    }
    // model II, Monte Carlo for n ≥ 2: with gain 1 the draws are the scalar ones
    let sensor1 = LinearGaussianSensor::new(0.8, &[1.0], 1, &[0.0], &[noise]).unwrap();
    let sobs1 = LinearGaussian::new(Detection::constant(0.8).unwrap(), 1.0, 0.0, noise).unwrap();
    let st = TheoremOptions {
        samples: 2000,
        seed: 7,
        ..tight()
    };
    for &lambda in &[0.0, 0.8] {
        let v = vector_bound(&vector(0.7, &prior, &sensor1, clutter(lambda, &psi)), &st).unwrap();
        let b = theorem2(
            &ModelII {
                existence: 0.7,
                prior: &sprior,
                observation: &sobs1,
                clutter_rate: lambda,
                clutter_density: &psi,
                false_alarm_error: 6.0,
                miss_error: 9.0,
            },
            &st,
        )
        .unwrap();
        assert!((v.components[0].assembled.bound - b.assembled.bound).abs() < 1e-10);
        assert!((v.components[0].error - b.error).abs() < 1e-10);
        assert!((v.total.eta - b.eta).abs() < 1e-15);
        assert_eq!(v.total.cardinalities.len(), b.cardinalities.len());
    }
}

#[test]
fn eq72_independent_components_are_corollary3_per_component() {
    // P, H, R diagonal with m = l = 3, no false observations: (72) per component with
    // e²/3, i.e. Corollary 3 of each component's own scalar problem.
    let (var, gain, noise) = ([4.0, 1.0, 9.0], [1.0, 2.0, 0.5], [1.0, 3.0, 2.0]);
    let mut p = [0.0; 9];
    let mut h = [0.0; 9];
    let mut rr = [0.0; 9];
    for i in 0..3 {
        p[4 * i] = var[i];
        h[4 * i] = gain[i];
        rr[4 * i] = noise[i];
    }
    let prior = GaussianPrior::new(&[0.0, 1.0, -2.0], &p).unwrap();
    let sensor = LinearGaussianSensor::new(0.6, &h, 3, &[0.0; 3], &rr).unwrap();
    let psi = Density1::uniform(0.0, 1.0).unwrap();
    for &r in &[0.1, 0.5, 0.9] {
        for model_ii in [false, true] {
            let measurement = if model_ii {
                clutter(0.0, &psi)
            } else {
                false_alarms(0.0, &psi)
            };
            let v = vector_bound(
                &VectorModel {
                    false_alarm_error: 30.0,
                    miss_error: 45.0,
                    ..vector(r, &prior, &sensor, measurement)
                },
                &TheoremOptions::default(),
            )
            .unwrap();
            let mut sum = 0.0;
            for i in 0..3 {
                let post = crate::bounds::gaussian_fisher_information(var[i], gain[i], noise[i])
                    .unwrap()
                    .posterior_variance;
                let c = corollary3(r, 0.6, post, var[i], 10.0, 15.0).unwrap();
                let got = &v.components[i];
                assert!((got.assembled.bound - c.bound).abs() < 1e-12, "{r} {i}");
                assert!((got.assembled.existence_threshold - c.existence_threshold).abs() < 1e-12);
                assert!((got.inverse_information - post).abs() < 1e-12);
                assert_eq!(got.error, 0.0);
                sum += got.assembled.bound;
            }
            assert!(v.total.assembled.bound >= sum - 1e-12);
            assert_eq!(v.total.cardinalities[0].method, Method::ClosedForm);
        }
    }
}

#[test]
fn eq63_an_observed_component_with_false_alarms_is_the_scalar_theorem() {
    // m = 1, h = (1.5, 0, 0), P diagonal: x_1 is the scalar problem (with e²/3), x_2 and
    // x_3 are never observed: [J'⁻¹]_ii = w P_ii per cardinality.
    let prior = GaussianPrior::new(
        &[1.0, 0.0, 2.0],
        &[4.0, 0.0, 0.0, 0.0, 2.0, 0.0, 0.0, 0.0, 0.5],
    )
    .unwrap();
    let sensor = LinearGaussianSensor::new(0.9, &[1.5, 0.0, 0.0], 3, &[0.0], &[1.0]).unwrap();
    let psi = Density1::uniform(-10.0, 10.0).unwrap();
    let sprior = Density1::gaussian(1.0, 4.0).unwrap();
    let sobs = LinearGaussian::new(Detection::constant(0.9).unwrap(), 1.5, 0.0, 1.0).unwrap();
    for &r in &[0.3, 0.8] {
        let v = vector_bound(
            &vector(r, &prior, &sensor, false_alarms(0.5, &psi)),
            &tight(),
        )
        .unwrap();
        let b = scalar_theorem1(r, &sprior, &sobs, (0.5, &psi), (2.0, 3.0));
        assert!((v.components[0].assembled.bound - b.assembled.bound).abs() < 1e-10);
        let w = b.cardinalities[0].w;
        assert!((v.components[1].inverse_information - 2.0 * w).abs() < 1e-12);
        assert!((v.components[2].inverse_information - 0.5 * w).abs() < 1e-12);
        // the whole-state matrix: off-diagonal zero here
        assert!(v.inverse_information[1].abs() < 1e-12);
    }
}

#[test]
fn eq65_the_rank_one_reduction_is_the_matrix_information_without_clutter() {
    // m = 1 with a full P: the rank-one reduction must give diag((P⁻¹ + hhᵀ/R)⁻¹).
    let pm = [4.0, 1.5, 0.3, 1.5, 2.0, -0.4, 0.3, -0.4, 1.0];
    let prior = GaussianPrior::new(&[0.0, 1.0, 2.0], &pm).unwrap();
    let sensor = LinearGaussianSensor::new(0.7, &[1.0, 0.5, -2.0], 3, &[0.2], &[0.8]).unwrap();
    let psi = Density1::uniform(-10.0, 10.0).unwrap();
    let v = vector_bound(
        &vector(0.6, &prior, &sensor, false_alarms(0.0, &psi)),
        &tight(),
    )
    .unwrap();
    let (_, inv) = gaussian_information_matrix(
        &DMatrix::from_row_slice(3, 3, &pm),
        &DMatrix::from_row_slice(1, 3, &[1.0, 0.5, -2.0]),
        &DMatrix::from_element(1, 1, 0.8),
    )
    .unwrap();
    for i in 0..3 {
        for j in 0..3 {
            assert!((v.inverse_information[3 * i + j] - inv[(i, j)]).abs() < 1e-9);
        }
    }
}

#[test]
fn eq72_a_negligible_gain_is_no_gain() {
    // σ_s² = hᵀPh underflows to a subnormal: without false observations the closed form
    // (h = 0, the prior), with clutter an error naming the gain, both at once.
    let prior = GaussianPrior::new(&[0.0, 0.0], &[6e-208, 0.0, 0.0, 1.5e-223]).unwrap();
    let sensor = LinearGaussianSensor::new(0.5, &[-6.4e-59, -6e-107], 2, &[0.0], &[1e150]).unwrap();
    let psi = Density1::gaussian(0.0, 25.0).unwrap();
    let m = |lambda| VectorModel {
        false_alarm_error: 1.0,
        miss_error: 1.0,
        ..vector(0.5, &prior, &sensor, clutter(lambda, &psi))
    };
    let v = vector_bound(&m(0.0), &TheoremOptions::default()).unwrap();
    assert_eq!(v.total.cardinalities[0].method, Method::ClosedForm);
    // J_1 ≈ P⁻¹: the bound is the prior's (Corollary 3 with J_1⁻¹ = σ_{e,i}²).
    for (i, c) in v.components.iter().enumerate() {
        assert_eq!(c.undetected_variance, [6e-208, 1.5e-223][i]);
        assert!(
            (c.inverse_information - c.undetected_variance).abs() <= 1e-9 * c.undetected_variance
        );
    }
    let e = vector_bound(&m(1e-113), &TheoremOptions::default()).unwrap_err();
    assert_eq!(e.field(), "observation.gain");
}

#[test]
fn eq63_vector_errors_name_the_field() {
    let psi = Density1::uniform(-10.0, 10.0).unwrap();
    let prior = GaussianPrior::new(&[0.0, 0.0], &[1.0, 0.0, 0.0, 1.0]).unwrap();
    let two = LinearGaussianSensor::new(
        0.7,
        &[1.0, 0.0, 0.0, 1.0],
        2,
        &[0.0, 0.0],
        &[1.0, 0.0, 0.0, 1.0],
    )
    .unwrap();
    let m = VectorModel {
        false_alarm_error: 1.0,
        miss_error: 1.0,
        ..vector(0.5, &prior, &two, clutter(1.0, &psi))
    };
    let e = vector_bound(&m, &TheoremOptions::default()).unwrap_err();
    assert_eq!(e.field(), "observation.gain");
    assert_eq!(
        GaussianPrior::new(&[0.0, 0.0], &[1.0, 2.0, 2.0, 1.0])
            .unwrap_err()
            .field(),
        "cov"
    );
    assert_eq!(
        GaussianPrior::new(&[0.0, 0.0], &[1.0, 0.5, 0.0, 1.0])
            .unwrap_err()
            .field(),
        "cov"
    );
    assert_eq!(
        LinearGaussianSensor::new(0.7, &[1.0, 0.0, 1.0], 2, &[0.0], &[1.0])
            .unwrap_err()
            .field(),
        "gain"
    );
    assert_eq!(
        LinearGaussianSensor::new(0.7, &[1.0, 0.0], 2, &[0.0], &[-1.0])
            .unwrap_err()
            .field(),
        "noise_cov"
    );
    let three = LinearGaussianSensor::new(0.7, &[1.0, 0.0, 0.0], 3, &[0.0], &[1.0]).unwrap();
    let e = vector_bound(
        &VectorModel {
            sensor: &three,
            ..m
        },
        &TheoremOptions::default(),
    )
    .unwrap_err();
    assert_eq!(e.field(), "observation.gain");
}

#[test]
fn eq63_state_and_measurement_dimensions_are_1_to_max_dims() {
    use crate::bounds::MAX_DIMS;
    use alloc::string::ToString;
    use alloc::vec;
    let e = GaussianPrior::new(&[], &[]).unwrap_err();
    assert_eq!(
        e.to_string(),
        "mean.length must be an integer in [1, 64], got 0"
    );
    let big = MAX_DIMS + 1;
    let mut cov = vec![0.0; big * big];
    for i in 0..big {
        cov[i * big + i] = 1.0;
    }
    let e = GaussianPrior::new(&vec![0.0; big], &cov).unwrap_err();
    assert_eq!(e.field(), "mean.length");
    assert_eq!(check_state_dims(MAX_DIMS).unwrap(), MAX_DIMS);
    let e = LinearGaussianSensor::new(0.7, &[], 2, &[], &[]).unwrap_err();
    assert_eq!(e.to_string(), "gain must have 1 to 64 rows, got 0");
    let e = LinearGaussianSensor::new(0.7, &vec![1.0; big], 1, &vec![0.0; big], &cov).unwrap_err();
    assert_eq!(e.to_string(), "gain must have 1 to 64 rows, got 65");
    assert!(check_measurement_dims(MAX_DIMS).is_ok());
}

#[test]
fn vector_covariances_say_which_property_fails() {
    use alloc::string::ToString;
    let asym = [1.0, 0.5, 0.4, 1.0];
    let indef = [1.25, 0.0, 0.0, -0.25];
    let say = |e: crate::Error| e.to_string();
    assert_eq!(
        say(GaussianPrior::new(&[0.0, 0.0], &asym).unwrap_err()),
        "cov is not symmetric: [0][1] = 0.5 but [1][0] = 0.4"
    );
    assert_eq!(
        say(GaussianPrior::new(&[0.0, 0.0], &indef).unwrap_err()),
        "cov is not positive definite (smallest eigenvalue -0.25)"
    );
    let sensor = |r: &[f64]| LinearGaussianSensor::new(0.7, &[1.0, 0.0, 0.0, 1.0], 2, &[0.0; 2], r);
    assert_eq!(
        say(sensor(&asym).unwrap_err()),
        "noise_cov is not symmetric: [0][1] = 0.5 but [1][0] = 0.4"
    );
    assert_eq!(
        say(sensor(&indef).unwrap_err()),
        "noise_cov is not positive definite (smallest eigenvalue -0.25)"
    );
    let (asym, indef) = (
        DMatrix::from_row_slice(2, 2, &asym),
        DMatrix::from_row_slice(2, 2, &indef),
    );
    let (eye, h) = (DMatrix::identity(2, 2), DMatrix::identity(2, 2));
    assert_eq!(
        say(gaussian_information_matrix(&asym, &h, &eye).unwrap_err()),
        "prior_covariance is not symmetric: [0][1] = 0.5 but [1][0] = 0.4"
    );
    assert_eq!(
        say(gaussian_information_matrix(&indef, &h, &eye).unwrap_err()),
        "prior_covariance is not positive definite (smallest eigenvalue -0.25)"
    );
    assert_eq!(
        say(gaussian_information_matrix(&eye, &h, &asym).unwrap_err()),
        "noise_covariance is not symmetric: [0][1] = 0.5 but [1][0] = 0.4"
    );
    assert_eq!(
        say(gaussian_information_matrix(&eye, &h, &indef).unwrap_err()),
        "noise_covariance is not positive definite (smallest eigenvalue -0.25)"
    );
}
