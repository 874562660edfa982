//! Tests of the filters' transactional guarantee: a `&mut self` method that returns `Err`
//! leaves the filter unchanged (state, weights, particles, random stream), so the next
//! successful call gives what it gives on a filter that never saw the failing one.

use std::format;
use std::string::String;
use std::vec;
use std::vec::Vec;

use nalgebra::DMatrix;

use super::tests::ncv_filter_config;
use super::*;
use crate::regions::Region;

/// Every private field of a filter, through `Debug` (floats print their exact value).
fn snapshot<T: core::fmt::Debug>(filter: &T) -> String {
    format!("{filter:?}")
}

/// A report about the object's start, and one of the wrong dimension.
fn reports() -> (Vec<Region>, Vec<Region>) {
    let near = vec![Region::ball(&[1.0, 0.0], 3.0, "reports[0]").unwrap()];
    let three_d = vec![Region::ball(&[0.0, 0.0, 0.0], 1.0, "reports[0]").unwrap()];
    (near, three_d)
}

/// The scan each bad call is followed by, applied to either filter kind.
trait Filter: Clone + core::fmt::Debug {
    fn predict_ok(&mut self) -> Result<(), crate::Error>;
    fn update(&mut self, reports: &[Region]) -> Result<UpdateInfo, crate::Error>;
    fn update_measurements(&mut self, z: &[Vec<f64>]) -> Result<UpdateInfo, crate::Error>;
    fn update_with_fn(&mut self, g: f64) -> Result<UpdateInfo, crate::Error>;
}

impl Filter for GmBernoulliFilter {
    fn predict_ok(&mut self) -> Result<(), crate::Error> {
        self.predict()
    }
    fn update(&mut self, reports: &[Region]) -> Result<UpdateInfo, crate::Error> {
        GmBernoulliFilter::update(self, reports)
    }
    fn update_measurements(&mut self, z: &[Vec<f64>]) -> Result<UpdateInfo, crate::Error> {
        GmBernoulliFilter::update_measurements(self, z)
    }
    fn update_with_fn(&mut self, g: f64) -> Result<UpdateInfo, crate::Error> {
        self.update_with(&FnLikelihood::new(1, move |_, _| g, Vec::new()))
    }
}

impl Filter for ParticleBernoulliFilter {
    fn predict_ok(&mut self) -> Result<(), crate::Error> {
        self.predict();
        Ok(())
    }
    fn update(&mut self, reports: &[Region]) -> Result<UpdateInfo, crate::Error> {
        ParticleBernoulliFilter::update(self, reports)
    }
    fn update_measurements(&mut self, z: &[Vec<f64>]) -> Result<UpdateInfo, crate::Error> {
        ParticleBernoulliFilter::update_measurements(self, z)
    }
    fn update_with_fn(&mut self, g: f64) -> Result<UpdateInfo, crate::Error> {
        self.update_with(&FnLikelihood::new(1, move |_, _| g, Vec::new()))
    }
}

/// Runs `bad` on `filter`: it must fail naming `field`, leave every field as it was, and the
/// next predict and update must give, bit for bit, what a twin that never saw it gives.
fn assert_unchanged<F: Filter>(
    filter: &mut F,
    field: &str,
    bad: impl FnOnce(&mut F) -> Result<UpdateInfo, crate::Error>,
) {
    let mut twin = filter.clone();
    let before = snapshot(filter);
    let e = bad(filter).unwrap_err();
    assert_eq!(e.field(), field, "{e}");
    assert_eq!(
        snapshot(filter),
        before,
        "the failed call ({e}) changed the filter"
    );
    let (near, _) = reports();
    filter.predict_ok().unwrap();
    twin.predict_ok().unwrap();
    assert_eq!(filter.update(&near).unwrap(), twin.update(&near).unwrap());
    assert_eq!(snapshot(filter), snapshot(&twin));
}

/// Every kind of bad scan: a region of the wrong dimension, a measurement of the wrong
/// dimension, a NaN measurement, a negative or NaN g̃; each both after a prediction and
/// after an update (no prediction in between).
fn check_every_bad_scan<F: Filter>(mut filter: F) {
    let (near, three_d) = reports();
    for after_update in [false, true] {
        filter.predict_ok().unwrap();
        if after_update {
            filter.update(&near).unwrap();
        }
        assert_unchanged(&mut filter, "reports[0].ball.center", |f| {
            f.update(&three_d)
        });
        assert_unchanged(&mut filter, "measurements[0]", |f| {
            f.update_measurements(&[vec![1.0, 2.0, 3.0]])
        });
        assert_unchanged(&mut filter, "measurements[1][1]", |f| {
            f.update_measurements(&[vec![1.0, 2.0], vec![0.0, f64::NAN]])
        });
        assert_unchanged(&mut filter, "likelihood[0]", |f| f.update_with_fn(-1.0));
        assert_unchanged(&mut filter, "likelihood[0]", |f| f.update_with_fn(f64::NAN));
    }
}

fn particle_options() -> ParticleOptions {
    ParticleOptions {
        particles: 300,
        seed: 7,
        ..ParticleOptions::default()
    }
}

#[test]
fn transactional_gm_filter_bad_scans_leave_it_unchanged() {
    check_every_bad_scan(GmBernoulliFilter::new(ncv_filter_config(0.8, 0.9)).unwrap());
}

/// The particle filter also keeps its random stream: the next update resamples with the
/// same draws.
#[test]
fn transactional_particle_filter_bad_scans_leave_it_unchanged() {
    let filter = ParticleBernoulliFilter::new(ncv_filter_config(0.8, 0.9), particle_options());
    check_every_bad_scan(filter.unwrap());
}

/// Failures found by the update itself rather than by the input checks: a per-report
/// clutter density of the wrong length, and (no clutter) a report that nothing explains,
/// and without a likelihood in the config, vector measurements.
#[test]
fn transactional_failures_inside_the_update_leave_the_filters_unchanged() {
    let far = vec![Region::ball(&[500.0, 500.0], 1.0, "reports[0]").unwrap()];
    let (near, _) = reports();
    let two = vec![near[0].clone(), near[0].clone()];
    let mut no_clutter = ncv_filter_config(0.8, 0.9);
    no_clutter.clutter = Clutter::none();
    let mut per_report = ncv_filter_config(0.8, 0.9);
    per_report.clutter = Clutter::new(0.25, ClutterDensity::PerReport(vec![0.01])).unwrap();
    let mut no_likelihood = ncv_filter_config(0.8, 0.9);
    no_likelihood.likelihood = None;
    let cases: [(BernoulliFilterOptions, &str, &[Region]); 3] = [
        (no_clutter, "reports", &far),
        (per_report, "clutter.density", &two),
        (no_likelihood, "likelihood", &[]),
    ];
    for (config, field, scan) in cases {
        let vector = field == "likelihood";
        let mut gm = GmBernoulliFilter::new(config.clone()).unwrap();
        gm.predict().unwrap();
        let mut pf = ParticleBernoulliFilter::new(config, particle_options()).unwrap();
        pf.predict();
        if vector {
            assert_unchanged(&mut gm, field, |f| Filter::update_measurements(f, &[]));
            assert_unchanged(&mut pf, field, |f| Filter::update_measurements(f, &[]));
        } else {
            assert_unchanged(&mut gm, field, |f| Filter::update(f, scan));
            assert_unchanged(&mut pf, field, |f| Filter::update(f, scan));
        }
    }
}

/// A GM prediction whose covariance overflows (F = 10¹⁶⁰ I: F P Fᵀ = ∞) fails and keeps the
/// Bernoulli it started from.
#[test]
fn transactional_gm_filter_failed_prediction_leaves_it_unchanged() {
    let mut config = ncv_filter_config(0.8, 0.9);
    let f = DMatrix::<f64>::identity(4, 4) * 1e160;
    config.transition = LinearGaussianTransition::new(f, DMatrix::identity(4, 4)).unwrap();
    let mut gm = GmBernoulliFilter::new(config).unwrap();
    let mut twin = gm.clone();
    let before = snapshot(&gm);
    let e = gm.predict().unwrap_err();
    assert_eq!(
        snapshot(&gm),
        before,
        "the failed prediction ({e}) changed the filter"
    );
    let (near, _) = reports();
    assert_eq!(gm.update(&near).unwrap(), twin.update(&near).unwrap());
    assert_eq!(snapshot(&gm), snapshot(&twin));
}
