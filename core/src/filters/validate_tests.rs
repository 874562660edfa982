//! Tests of the whole-configuration checks ([`super::validate`]) on a user's first-day
//! mistakes, each error naming the field that disagrees and the one it disagrees with, and
//! of a positive semidefinite Q (eq. (44) of `001_0f0df91eee9b30d5.txt`: Q may be
//! singular) in both filters.

use std::string::ToString;
use std::vec;
use std::vec::Vec;

use nalgebra::DMatrix;

use super::tests::ncv_filter_config;
use super::*;
use crate::gaussian::{Gaussian, GaussianMixture};
use crate::regions::Region;

/// The error message of `r`.
fn message<T: core::fmt::Debug>(r: crate::Result<T>) -> std::string::String {
    r.unwrap_err().to_string()
}

fn rows(n: usize, m: usize, v: f64) -> Vec<Vec<f64>> {
    (0..n)
        .map(|i| (0..m).map(|j| if i == j { v } else { 0.0 }).collect())
        .collect()
}

#[test]
fn eq44_shapes_of_rows_as_a_user_gives_them() {
    assert_eq!(ConfigShapes::of_rows(&rows(2, 3, 1.0)), (2, 3));
    assert_eq!(ConfigShapes::of_rows(&[]), (0, 0));
    // the first row decides the columns; ragged rows are left to the matrix's own check
    assert_eq!(ConfigShapes::of_rows(&[vec![1.0], vec![1.0, 2.0]]), (2, 1));
    let shapes = ConfigShapes {
        f: ConfigShapes::of_rows(&rows(2, 2, 1.0)),
        q: ConfigShapes::of_rows(&rows(3, 3, 1.0)),
        ..ConfigShapes::default()
    };
    assert_eq!(
        message(shapes.check()),
        "transition.q is 3×3 but transition.f is 2×2"
    );
}

#[test]
fn eq39_a_4d_mixture_with_a_2x2_f_names_both() {
    let mut c = ncv_filter_config(0.5, 0.9);
    c.transition = LinearGaussianTransition::from_rows(&rows(2, 2, 1.0), &rows(2, 2, 0.1)).unwrap();
    c.likelihood = None;
    assert_eq!(
        message(c.validate()),
        "mixture[0].mean has length 4 but transition.f is 2×2"
    );
    let mut c = ncv_filter_config(0.5, 0.9);
    let g = Gaussian::from_slices(&[0.0; 2], &[1.0, 0.0, 0.0, 1.0], "b").unwrap();
    c.birth = Birth::new(0.1, GaussianMixture::new(vec![(1.0, g)], "b").unwrap()).unwrap();
    assert_eq!(
        message(c.validate()),
        "birth.mixture[0].mean has length 2 but transition.f is 4×4"
    );
}

#[test]
fn eq44_a_2x2_q_with_a_4x4_f_in_matrix_terms() {
    assert_eq!(
        message(LinearGaussianTransition::from_rows(
            &rows(4, 4, 1.0),
            &rows(2, 2, 0.1)
        )),
        "transition.q is 2×2 but transition.f is 4×4"
    );
    assert_eq!(
        message(LinearGaussianTransition::from_row_slices(
            &[1.0; 16], &[0.1; 4]
        )),
        "transition.q is 2×2 but transition.f is 4×4"
    );
    let q = DMatrix::from_row_slice(2, 2, &[1.0, 0.5, 0.4, 1.0]);
    assert_eq!(
        message(LinearGaussianTransition::new(DMatrix::identity(2, 2), q)),
        "transition.q is not symmetric: [0][1] = 0.5 but [1][0] = 0.4"
    );
    let q = DMatrix::from_row_slice(2, 2, &[1.0, 0.0, 0.0, -0.25]);
    assert_eq!(
        message(LinearGaussianTransition::new(DMatrix::identity(2, 2), q)),
        "transition.q is not positive semidefinite (smallest eigenvalue -0.25)"
    );
}

#[test]
fn eq44_h_needs_f_columns_and_r_needs_h_rows() {
    let mut c = ncv_filter_config(0.5, 0.9);
    c.likelihood =
        Some(LinearGaussianLikelihood::from_rows(&rows(2, 3, 1.0), &rows(2, 2, 1.0)).unwrap());
    assert_eq!(
        message(c.validate()),
        "likelihood.h is 2×3 but transition.f is 4×4"
    );
    assert_eq!(
        message(LinearGaussianLikelihood::from_rows(
            &rows(2, 4, 1.0),
            &rows(3, 3, 1.0)
        )),
        "likelihood.r is 3×3 but likelihood.h is 2×4"
    );
    let r = DMatrix::from_row_slice(2, 2, &[1.0, 0.0, 0.0, -0.25]);
    let h = DMatrix::from_row_slice(2, 4, &[1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0]);
    assert_eq!(
        message(LinearGaussianLikelihood::new(h, r)),
        "likelihood.r is not positive definite (smallest eigenvalue -0.25)"
    );
}

#[test]
fn eq51_regions_name_the_field_that_carries_their_dimension() {
    let mut c = ncv_filter_config(0.5, 0.9);
    c.detection.fov = Some(Region::axis_box(&[0.0; 3], &[1.0; 3], "fov").unwrap());
    assert_eq!(
        message(c.validate()),
        "detection.fov.box.min has length 3 but position_dims is 2"
    );
    let mut c = ncv_filter_config(0.5, 0.9);
    c.exclusions = vec![Region::ball(&[0.0; 3], 1.0, "e").unwrap()];
    assert_eq!(
        message(c.validate()),
        "exclusions[0].ball.center has length 3 but position_dims is 2"
    );
    let mut c = ncv_filter_config(0.5, 0.9);
    c.position_dims = 6;
    assert_eq!(
        message(c.validate()),
        "position_dims is 6 but transition.f is 4×4"
    );
    let three_d = [Region::axis_box(&[0.0; 3], &[1.0; 3], "r").unwrap()];
    let mut gm = GmBernoulliFilter::new(ncv_filter_config(0.5, 0.9)).unwrap();
    assert_eq!(
        message(gm.update(&three_d)),
        "reports[0].box.min has length 3 but position_dims is 2"
    );
    assert_eq!(
        message(gm.update_measurements(&[vec![1.0, 2.0, 3.0]])),
        "measurements[0] has length 3 but likelihood.h is 2×4"
    );
}

#[test]
fn eq63_a_mixture_covariance_says_which_property_fails() {
    let e = Gaussian::from_slices(&[0.0; 2], &[1.0, 0.5, 0.4, 1.0], "mixture[0]").unwrap_err();
    assert_eq!(
        e.to_string(),
        "mixture[0].cov is not symmetric: [0][1] = 0.5 but [1][0] = 0.4"
    );
    let e = Gaussian::from_slices(&[0.0; 2], &[1.0, 0.0, 0.0, -0.25], "mixture[0]").unwrap_err();
    assert_eq!(
        e.to_string(),
        "mixture[0].cov is not positive definite (smallest eigenvalue -0.25)"
    );
}

/// Nearly constant velocity with noise on the velocity only: Q = diag(0, 0, q, q), rank 2.
fn velocity_noise_config() -> BernoulliFilterOptions {
    let mut c = ncv_filter_config(0.8, 0.9);
    let f = LinearGaussianTransition::nearly_constant_velocity(2, 1.0, 0.01)
        .unwrap()
        .f()
        .clone();
    let q = DMatrix::from_diagonal(&nalgebra::DVector::from_vec(vec![0.0, 0.0, 0.01, 0.01]));
    c.transition = LinearGaussianTransition::new(f, q).unwrap();
    assert!(!c.transition.has_density());
    c
}

#[test]
fn eq44_a_semidefinite_q_runs_in_both_filters() {
    let disc = [Region::ball(&[1.0, 0.0], 3.0, "r").unwrap()];
    let mut gm = GmBernoulliFilter::new(velocity_noise_config()).unwrap();
    let options = ParticleOptions {
        particles: 500,
        birth_particles: None,
        mcmc_moves: 1,
        seed: 7,
    };
    let mut pf = ParticleBernoulliFilter::new(velocity_noise_config(), options).unwrap();
    for _ in 0..5 {
        gm.predict().unwrap();
        gm.update(&disc).unwrap();
        gm.update_measurements(&[vec![1.0, 0.5]]).unwrap();
        pf.predict();
        pf.update(&disc).unwrap();
        pf.update_measurements(&[vec![1.0, 0.5]]).unwrap();
    }
    for e in [
        gm.estimate(&EstimateOptions::default()).unwrap(),
        pf.estimate(&EstimateOptions::default()).unwrap(),
    ] {
        assert!(e.existence > 0.0 && e.existence <= 1.0, "{e:?}");
        assert!(e.mean.iter().all(|v| v.is_finite()), "{e:?}");
        assert!(e.cov.iter().flatten().all(|v| v.is_finite()), "{e:?}");
    }
}

/// The unchecked forms a binding reads: F, Q, H, R as rows, their shapes checked against the
/// mixtures, H and n_s before either model is built, then built by the rows constructors.
#[test]
fn rows_forms_check_shapes_then_build() {
    let eye = |n: usize| -> Vec<Vec<f64>> {
        (0..n)
            .map(|i| (0..n).map(|j| f64::from(u8::from(i == j))).collect())
            .collect()
    };
    let mixture = |n: usize| {
        let g = Gaussian::new(
            nalgebra::DVector::zeros(n),
            DMatrix::identity(n, n),
            "mixture",
        )
        .unwrap();
        GaussianMixture::new(vec![(1.0, g)], "mixture").unwrap()
    };
    let t = TransitionRows {
        f: eye(2),
        q: eye(2),
    };
    assert_eq!(
        message(t.check_shapes(&mixture(4), &GaussianMixture::default(), None, 0)),
        "mixture[0].mean has length 4 but transition.f is 2×2"
    );
    let h = LikelihoodRows {
        h: vec![vec![1.0, 0.0]],
        r: eye(2),
    };
    assert_eq!(
        message(t.check_shapes(&mixture(2), &GaussianMixture::default(), Some(&h), 2)),
        "likelihood.r is 2×2 but likelihood.h is 1×2"
    );
    t.check_shapes(&mixture(2), &mixture(2), None, 2).unwrap();
    assert_eq!(
        t.build().unwrap(),
        LinearGaussianTransition::from_rows(&t.f, &t.q).unwrap()
    );
    let bad = TransitionRows {
        f: eye(2),
        q: vec![vec![1.0, 0.5], vec![0.4, 1.0]],
    };
    assert_eq!(
        message(bad.build()),
        message(LinearGaussianTransition::from_rows(&bad.f, &bad.q))
    );
    assert_eq!(
        message(h.build()),
        "likelihood.r is 2×2 but likelihood.h is 1×2"
    );
}

/// The rows forms read and write the paper's capitals: `{F, Q}`, `{H, R}`.
#[cfg(feature = "serde")]
#[test]
fn rows_forms_serde_names_are_the_papers_capitals() {
    let t: TransitionRows = serde_json::from_str(r#"{"F": [[1]], "Q": [[0.5]]}"#).unwrap();
    assert_eq!(t.q, vec![vec![0.5]]);
    assert_eq!(
        serde_json::to_string(&t).unwrap(),
        r#"{"F":[[1.0]],"Q":[[0.5]]}"#
    );
    let l: LikelihoodRows = serde_json::from_str(r#"{"H": [[1, 0]], "R": [[2]]}"#).unwrap();
    assert_eq!(l.build().unwrap().measurement_dim(), 1);
}

/// The options as a user writes them: the shapes of all the fields first (a 4-D mixture with
/// a 2×2 F, before the asymmetric Q), then the models built; defaults for what is left out.
#[cfg(feature = "serde")]
#[test]
fn user_options_check_shapes_before_building() {
    let mixture = r#"[{"weight": 1, "mean": [0, 0, 0, 0], "cov": [[1,0,0,0],[0,1,0,0],[0,0,1,0],[0,0,0,1]]}]"#;
    let config = |transition: &str| {
        std::format!(
            r#"{{"existence": 0.5, "mixture": {mixture}, "transition": {transition},
                "detection": {{"probability": 0.9}}, "clutter": {{"rate": 0.25, "density": 0.01}}}}"#
        )
    };
    let bad = r#"{"F": [[1, 0], [0, 1]], "Q": [[1, 0.5], [0.4, 1]]}"#;
    let c: BernoulliFilterConfig = serde_json::from_str(&config(bad)).unwrap();
    assert_eq!(
        message(c.build()),
        "mixture[0].mean has length 4 but transition.f is 2×2"
    );
    let p: GmBernoulliPredictOptions = serde_json::from_str(&std::format!(
        r#"{{"existence": 0.5, "mixture": {mixture}, "transition": {bad}}}"#
    ))
    .unwrap();
    assert_eq!(
        message(p.build()),
        "mixture[0].mean has length 4 but transition.f is 2×2"
    );
    let eye4 = r#"{"F": [[1,0,0,0],[0,1,0,0],[0,0,1,0],[0,0,0,1]], "Q": [[1,0,0,0],[0,1,0,0],[0,0,1,0],[0,0,0,1]]}"#;
    let c: BernoulliFilterConfig = serde_json::from_str(&config(eye4)).unwrap();
    assert_eq!((c.particles, c.mcmc_moves, c.seed), (5000, 1, None));
    let (built, particle) = c.build().unwrap();
    assert_eq!((built.position_dims, built.survival), (2, 0.99));
    assert_eq!(particle.seed, 0);
    built.validate().unwrap();
}

/// The update's options as a user writes them: `measurements` optional (absent is not
/// empty), the splitting step built for n_s.
#[cfg(feature = "serde")]
#[test]
fn update_options_as_written() {
    let base = r#""existence": 0.5, "mixture": [{"weight": 1, "mean": [0, 0], "cov": [[1, 0], [0, 1]]}],
        "detection": {"probability": 0.9}, "clutter": {"rate": 0.25, "density": 0.01}"#;
    let o: GmBernoulliUpdateOptions = serde_json::from_str(&std::format!("{{{base}}}")).unwrap();
    assert_eq!(
        (o.measurements, o.reports, o.position_dims),
        (None, None, 2)
    );
    let o: GmBernoulliUpdateOptions = serde_json::from_str(&std::format!(
        r#"{{{base}, "measurements": [], "splitting": {{"components": 1}}}}"#
    ))
    .unwrap();
    assert_eq!(o.measurements, Some(Vec::new()));
    assert!(message(o.update_options()).starts_with("splitting.components"));
}

/// `run` picks the update the options ask for, and measurements need their likelihood.
#[cfg(feature = "serde")]
#[test]
fn update_options_run_the_update_they_ask_for() {
    let base = r#""existence": 0.5, "mixture": [{"weight": 1, "mean": [0, 0], "cov": [[1, 0], [0, 1]]}],
        "detection": {"probability": 0.9}, "clutter": {"rate": 0.25, "density": 0.01}"#;
    let read = |extra: &str| -> GmBernoulliUpdateOptions {
        serde_json::from_str(&std::format!("{{{base}{extra}}}")).unwrap()
    };
    let o = read("");
    let expected = super::gm_bernoulli_update(
        &GmBernoulli {
            existence: o.existence,
            mixture: o.mixture.clone(),
        },
        &[],
        &o.update_options().unwrap(),
    );
    assert_eq!(o.run(), expected);
    assert_eq!(
        message(read(r#", "measurements": [[0, 0]]"#).run()),
        "likelihood is needed with measurements"
    );
    let vector = read(
        r#", "measurements": [[0, 0]], "likelihood": {"H": [[1, 0], [0, 1]], "R": [[1, 0], [0, 1]]}"#,
    );
    let out = vector.run().unwrap();
    assert!(out.existence > 0.0 && out.existence <= 1.0);
}
