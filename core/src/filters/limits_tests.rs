//! Tests of the filters' size limits, checked by the constructors and validations (not by a
//! binding): 64 states, 1 to 64 measurement rows, n_s in [1, 8], the splitting's caps, 1000
//! regions per list, 10000 measurements per scan, the particle counts, the airport's steps.
//! Each error names the Rust field path and says the limit.

use std::string::ToString;
use std::vec;
use std::vec::Vec;

use super::tests::ncv_filter_config;
use super::*;
use crate::regions::Region;

/// The error message of `r`.
fn message<T: core::fmt::Debug>(r: crate::Result<T>) -> std::string::String {
    r.unwrap_err().to_string()
}

#[test]
fn a_transition_has_at_most_64_states_and_square_rows() {
    let eye = |n: usize| -> Vec<Vec<f64>> {
        (0..n)
            .map(|i| (0..n).map(|j| f64::from(u8::from(i == j))).collect())
            .collect()
    };
    assert!(LinearGaussianTransition::from_rows(&eye(64), &eye(64)).is_ok());
    assert_eq!(
        message(LinearGaussianTransition::from_rows(&eye(65), &eye(65))),
        "transition.f: at most 64 states are supported"
    );
    let mut ragged = eye(3);
    ragged[1].push(0.0);
    assert_eq!(
        message(LinearGaussianTransition::from_rows(&ragged, &eye(3))),
        "transition.f[1] has length 4, expected 3"
    );
    assert_eq!(
        message(LinearGaussianTransition::from_rows(&eye(3), &ragged)),
        "transition.q[1] has length 4, expected 3"
    );
    // the model built from the rows is the one built from the matrices
    let t = LinearGaussianTransition::from_rows(&eye(2), &eye(2)).unwrap();
    assert_eq!(t.f(), &nalgebra::DMatrix::<f64>::identity(2, 2));
}

#[test]
fn a_likelihood_has_1_to_64_rows() {
    let row = |n: usize| vec![0.0; n];
    assert_eq!(
        message(LinearGaussianLikelihood::from_rows(&[], &[])),
        "likelihood.h must have 1 to 64 rows, got 0"
    );
    let h: Vec<Vec<f64>> = (0..65).map(|_| row(2)).collect();
    assert_eq!(
        message(LinearGaussianLikelihood::from_rows(&h, &[])),
        "likelihood.h must have 1 to 64 rows, got 65"
    );
    assert_eq!(
        message(LinearGaussianLikelihood::from_rows(
            &[row(2), row(3)],
            &[row(2), row(2)]
        )),
        "likelihood.h[1] has length 3, expected 2"
    );
    assert_eq!(
        message(LinearGaussianLikelihood::from_rows(&[row(2)], &[row(2)])),
        "likelihood.r is 1×2 but likelihood.h is 1×2"
    );
    let l = LinearGaussianLikelihood::from_rows(&[vec![1.0, 0.0]], &[vec![0.5]]).unwrap();
    assert_eq!((l.measurement_dim(), l.state_dim()), (1, 2));
}

#[test]
fn position_dims_exclusions_and_the_reduction_cap_are_checked() {
    let mut c = ncv_filter_config(0.5, 0.9);
    c.position_dims = 9;
    assert_eq!(
        message(c.validate()),
        "position_dims must be an integer in [1, 8], got 9"
    );
    let mut c = ncv_filter_config(0.5, 0.9);
    c.reduction.max_components = Some(1_000_001);
    assert_eq!(
        message(c.validate()),
        "reduction.max_components must be an integer in [1, 1000000], got 1000001"
    );
    let mut c = ncv_filter_config(0.5, 0.9);
    let far = Region::ball(&[1e6, 1e6], 1.0, "e").unwrap();
    c.exclusions = vec![far; MAX_REGIONS + 1];
    assert_eq!(
        message(c.validate()),
        "exclusions has 1001 regions, at most 1000 are supported"
    );
    c.exclusions.truncate(MAX_REGIONS);
    assert!(c.validate().is_ok());
    // n_s above the state's dimension (a 4-D state) names both, in shape terms.
    let mut u = ncv_filter_config(0.5, 0.9).update_options();
    u.position_dims = 5;
    assert_eq!(
        message(u.validate(4)),
        "position_dims is 5 but mixture[0].mean has length 4"
    );
}

#[test]
fn the_splitting_options_build_within_their_caps() {
    let defaults = SplittingOptions::default();
    // the defaults build the default splitting step
    let built = defaults.build(2).unwrap();
    assert_eq!(built, Splitting::default());
    let with = |f: fn(&mut SplittingOptions)| {
        let mut o = defaults;
        f(&mut o);
        o
    };
    for (options, dims, expected) in [
        (
            with(|o| o.components = 17),
            2,
            "splitting.components must be an integer in [2, 16], got 17",
        ),
        (
            with(|o| o.max_depth = 65),
            2,
            "splitting.max_depth must be an integer in [0, 64], got 65",
        ),
        (
            with(|o| o.max_components = 0),
            2,
            "splitting.max_components must be an integer in [1, 50000], got 0",
        ),
        (
            defaults,
            4,
            "splitting.grid_points must be an integer >= 2 with gridPoints^positionDims <= 20000, got 15",
        ),
        (
            defaults,
            9,
            "position_dims must be an integer in [1, 8], got 9",
        ),
    ] {
        assert_eq!(message(options.build(dims)), expected);
    }
    // 7^4 = 2401 collocation points is within the cap
    assert!(with(|o| o.grid_points = 7).build(4).is_ok());
}

#[test]
fn a_scan_has_at_most_1000_regions_or_10000_measurements() {
    let config = ncv_filter_config(0.5, 0.9);
    let mut gm = GmBernoulliFilter::new(config.clone()).unwrap();
    let mut pf = ParticleBernoulliFilter::new(config, ParticleOptions::default()).unwrap();
    let report = Region::ball(&[0.0, 0.0], 1.0, "r").unwrap();
    let too_many = vec![report; MAX_REGIONS + 1];
    let expected = "reports has 1001 regions, at most 1000 are supported";
    assert_eq!(message(gm.update(&too_many)), expected);
    assert_eq!(message(pf.update(&too_many)), expected);
    let z = vec![vec![0.0, 0.0]; MAX_MEASUREMENTS + 1];
    let expected = "measurements has 10001 measurements, at most 10000 are supported";
    assert_eq!(message(gm.update_measurements(&z)), expected);
    assert_eq!(message(pf.update_measurements(&z)), expected);
}

#[test]
fn the_particle_counts_are_capped() {
    let new = |options: ParticleOptions| {
        ParticleBernoulliFilter::new(ncv_filter_config(0.5, 0.9), options)
    };
    let base = ParticleOptions {
        particles: 10,
        ..ParticleOptions::default()
    };
    for (options, expected) in [
        (
            ParticleOptions {
                particles: MAX_PARTICLES + 1,
                ..base
            },
            "particles must be an integer in [1, 200000], got 200001",
        ),
        (
            ParticleOptions {
                birth_particles: Some(MAX_PARTICLES + 1),
                ..base
            },
            "birth_particles must be an integer in [0, 200000], got 200001",
        ),
        (
            ParticleOptions {
                mcmc_moves: 11,
                ..base
            },
            "mcmc_moves must be an integer in [0, 10], got 11",
        ),
    ] {
        assert_eq!(message(new(options)), expected);
    }
}

#[test]
fn the_airport_scenario_has_at_most_2000_steps() {
    use crate::sim::airport::{MAX_AIRPORT_STEPS, airport_scenario};
    assert_eq!(MAX_AIRPORT_STEPS, 2000);
    assert_eq!(
        message(airport_scenario(1, 2001)),
        "steps must be an integer in [0, 2000], got 2001"
    );
}

/// Issue 26 point 7: an update's work is bounded before it starts. The particle filter
/// counts (N + B) · max(m, 1) · (1 + moves) likelihood evaluations against
/// [`MAX_UPDATE_EVALUATIONS`]; the GM vector update counts components × measurements against
/// [`MAX_VECTOR_UPDATE_WORK`] (with ⌈n²/16⌉). Beyond either the error names the list to shorten, with the
/// most it may hold, and the filter is unchanged.
#[test]
fn an_update_past_its_work_cap_names_the_list_and_leaves_the_filter_unchanged() {
    let config = ncv_filter_config(0.5, 0.9);
    // 100,000 particles, one move: at most 100 reports.
    let options = ParticleOptions {
        particles: 100_000,
        ..ParticleOptions::default()
    };
    let mut pf = ParticleBernoulliFilter::new(config.clone(), options).unwrap();
    let before = (pf.existence(), pf.particles().to_vec());
    let report = Region::ball(&[0.0, 0.0], 1.0, "r").unwrap();
    assert_eq!(
        message(pf.update(&vec![report.clone(); 101])),
        "reports: particles × reports × (1 + MCMC moves) = 20200000 exceeds \
         MAX_UPDATE_EVALUATIONS = 2·10^7 (pass fewer reports or particles) (at most 100)"
    );
    // 2-D measurements of a 4-D state cost one unit each (⌈2 · 6 / 12⌉ = 1).
    let z = vec![vec![0.0, 0.0]; 101];
    assert_eq!(
        message(pf.update_measurements(&z)),
        "measurements: particles × measurements × (1 + MCMC moves) × ⌈d (n + d) / 12⌉ = \
         20200000 exceeds MAX_UPDATE_EVALUATIONS = 2·10^7 (pass fewer measurements or \
         particles) (at most 100)"
    );
    assert_eq!((pf.existence(), pf.particles().to_vec()), before);
    // At the cap exactly the update runs (10 particles, no move: 2·10^6 reports would be
    // over the count cap, so the product is reached with the particles).
    let small = ParticleOptions {
        particles: 10,
        mcmc_moves: 0,
        ..ParticleOptions::default()
    };
    let mut pf = ParticleBernoulliFilter::new(config.clone(), small).unwrap();
    assert!(pf.update(&vec![report; 1000]).is_ok());

    // The GM vector update: 66 components × 4000 measurements (4-D states: one unit each)
    // > 2^18.
    let mut gm_config = config;
    let (w, g) = gm_config.mixture.components()[0].clone();
    let many: Vec<_> = (0..66).map(|_| (w / 66.0, g.clone())).collect();
    gm_config.mixture = crate::gaussian::GaussianMixture::new(many, "mixture").unwrap();
    let mut gm = GmBernoulliFilter::new(gm_config).unwrap();
    let before = gm.state().clone();
    let z = vec![vec![0.0, 0.0]; 4000];
    assert_eq!(
        message(gm.update_measurements(&z)),
        "measurements: mixture components (after splitting) × measurements × ⌈n²/16⌉ = \
         264000 exceeds MAX_VECTOR_UPDATE_WORK = 2^18 (pass fewer measurements or reduce \
         the mixture) (at most 3971)"
    );
    assert_eq!(gm.state(), &before);
    assert_eq!(MAX_VECTOR_UPDATE_WORK / 66, 3971);
}
