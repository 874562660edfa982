//! Tests of the Bernoulli filters: prediction against its closed form, the update against
//! exact masses and importance-weighted Monte Carlo of (53)–(55), the Fig. 5 reduction, the
//! empty scan in every filter, the Kalman filter limit, and the error paths.

extern crate std;

use std::string::ToString;
use std::vec;
use std::vec::Vec;

use nalgebra::{DMatrix, DVector};

use super::*;
use crate::gaussian::{Gaussian, GaussianMixture, normal};
use crate::math::rng::{seeded, uniform};
use crate::mixture::{ReductionOptions, moments};
use crate::regions::Region;
use crate::splitting::{
    NegativeInformationScenario, SplitLibrary, SplitOptions, predict as ni_predict,
};

fn gauss(mean: &[f64], cov: &[f64], what: &str) -> Gaussian {
    Gaussian::from_slices(mean, cov, what).unwrap()
}

fn mixture(c: Vec<(f64, Gaussian)>) -> GaussianMixture {
    GaussianMixture::new(c, "mixture").unwrap()
}

fn identity_reduction() -> ReductionOptions {
    ReductionOptions::default()
}

// --------------------------------------------------------------------------- models

#[test]
fn nearly_constant_velocity_in_one_to_three_dimensions() {
    for d in 1..=3 {
        let (dt, q) = (2.5, 0.3);
        let m = LinearGaussianTransition::nearly_constant_velocity(d, dt, q).unwrap();
        assert_eq!(m.dim(), 2 * d);
        for i in 0..2 * d {
            for j in 0..2 * d {
                let f = if i == j {
                    1.0
                } else if j == i + d && i < d {
                    dt
                } else {
                    0.0
                };
                assert_eq!(m.f()[(i, j)], f);
                let (pi, pj) = (i % d, j % d);
                let qq = if pi != pj {
                    0.0
                } else {
                    match (i < d, j < d) {
                        (true, true) => q * dt * dt * dt / 3.0,
                        (false, false) => q * dt,
                        _ => q * dt * dt / 2.0,
                    }
                };
                assert!((m.q()[(i, j)] - qq).abs() < 1e-15, "d={d} ({i},{j})");
            }
        }
        assert!(m.has_density());
    }
    // (70)–(71) verbatim for d = 2, T = 15, ϖ = 0.004.
    let m = LinearGaussianTransition::nearly_constant_velocity(2, 15.0, 0.004).unwrap();
    assert!((m.q()[(0, 0)] - 4.5).abs() < 1e-12);
    assert!((m.q()[(0, 2)] - 0.45).abs() < 1e-12);
    assert!((m.q()[(2, 2)] - 0.06).abs() < 1e-12);
    // ϖ = 0: Q singular but allowed (no density).
    let z = LinearGaussianTransition::nearly_constant_velocity(2, 1.0, 0.0).unwrap();
    assert!(!z.has_density());
    for (e, field) in [
        (
            LinearGaussianTransition::nearly_constant_velocity(0, 1.0, 0.1),
            "position_dims",
        ),
        (
            LinearGaussianTransition::nearly_constant_velocity(2, f64::NAN, 0.1),
            "dt",
        ),
        (
            LinearGaussianTransition::nearly_constant_velocity(2, 1.0, -1.0),
            "intensity",
        ),
        (
            LinearGaussianTransition::from_row_slices(&[1.0, 0.0, 0.0], &[1.0]),
            "transition.f",
        ),
        (
            LinearGaussianTransition::from_row_slices(
                &[1.0, 0.0, 0.0, 1.0],
                &[1.0, 0.5, 0.5, -1.0],
            ),
            "transition.q",
        ),
        (
            LinearGaussianTransition::from_row_slices(
                &[1.0, f64::INFINITY, 0.0, 1.0],
                &[1.0, 0.0, 0.0, 1.0],
            ),
            "transition.f[0][1]",
        ),
    ] {
        assert_eq!(e.unwrap_err().field(), field);
    }
}

#[test]
fn eq40_eq49_prediction_matches_its_closed_form() {
    let f = DMatrix::from_row_slice(3, 3, &[1.0, 0.5, 0.0, 0.0, 1.0, 0.2, 0.1, 0.0, 0.9]);
    let q = DMatrix::from_row_slice(3, 3, &[0.3, 0.1, 0.0, 0.1, 0.2, 0.05, 0.0, 0.05, 0.4]);
    let transition = LinearGaussianTransition::new(f.clone(), q.clone()).unwrap();
    let c1 = gauss(
        &[1.0, -2.0, 0.5],
        &[1.0, 0.2, 0.0, 0.2, 0.5, 0.1, 0.0, 0.1, 0.3],
        "m",
    );
    let c2 = gauss(
        &[-3.0, 0.0, 1.0],
        &[0.4, 0.0, 0.0, 0.0, 0.4, 0.0, 0.0, 0.0, 0.4],
        "m",
    );
    let b = gauss(
        &[0.0, 0.0, 0.0],
        &[9.0, 0.0, 0.0, 0.0, 9.0, 0.0, 0.0, 0.0, 1.0],
        "b",
    );
    let state =
        GmBernoulli::new(0.7, mixture(vec![(0.25, c1.clone()), (0.75, c2.clone())])).unwrap();
    let config = PredictOptions {
        transition,
        survival: 0.95,
        birth: Birth::new(0.2, mixture(vec![(1.0, b.clone())])).unwrap(),
    };
    let out = gm_bernoulli_predict(&state, &config).unwrap();
    let r_pred = 0.2 * 0.3 + 0.95 * 0.7; // (41)
    assert!((out.existence - r_pred).abs() < 1e-15);
    let comps = out.mixture.components();
    assert_eq!(comps.len(), 3);
    // (46): the birth component first.
    assert!((comps[0].0 - 0.2 * 0.3 / r_pred).abs() < 1e-15);
    assert_eq!(comps[0].1.mean(), b.mean());
    for (k, (w, g)) in [(0.25, &c1), (0.75, &c2)].into_iter().enumerate() {
        let (wp, gp) = &comps[k + 1];
        assert!((wp - w * 0.95 * 0.7 / r_pred).abs() < 1e-15); // (47)
        let m = &f * g.mean(); // (48)
        let p = &f * g.cov() * f.transpose() + &q; // (49)
        assert!((gp.mean() - m).amax() < 1e-14);
        assert!((gp.cov() - p).amax() < 1e-14);
    }
    assert!((out.mixture.total_weight() - 1.0).abs() < 1e-15);
    // r = 0 with p_b = 0: nothing exists after prediction either; the density is kept.
    let dead = GmBernoulli::new(0.0, state.mixture.clone()).unwrap();
    let none = PredictOptions {
        birth: Birth::none(),
        ..config.clone()
    };
    let out = gm_bernoulli_predict(&dead, &none).unwrap();
    assert_eq!(out.existence, 0.0);
    assert_eq!(out.mixture.len(), 2);
    // Errors.
    let bad = PredictOptions {
        survival: 1.5,
        ..config.clone()
    };
    assert_eq!(
        gm_bernoulli_predict(&state, &bad).unwrap_err().field(),
        "survival"
    );
    let wrong_dim = GmBernoulli {
        existence: 0.5,
        mixture: mixture(vec![(1.0, gauss(&[0.0, 0.0], &[1.0, 0.0, 0.0, 1.0], "m"))]),
    };
    assert_eq!(
        gm_bernoulli_predict(&wrong_dim, &config)
            .unwrap_err()
            .to_string(),
        "mixture[0].mean has length 2 but transition.f is 3×3"
    );
    let unnormalised = GmBernoulli {
        existence: 0.5,
        mixture: mixture(vec![(0.5, c1.clone())]),
    };
    assert_eq!(
        gm_bernoulli_predict(&unnormalised, &config)
            .unwrap_err()
            .field(),
        "mixture[].weight"
    );
}

// --------------------------------------------------------------------------- empty scans

fn no_fov_config(pd: f64) -> UpdateOptions {
    UpdateOptions::new(
        2,
        Detection::new(pd, None).unwrap(),
        Clutter::new(0.25, ClutterDensity::Constant(0.01)).unwrap(),
    )
}

pub(super) fn ncv_filter_config(existence: f64, pd: f64) -> BernoulliFilterOptions {
    let g = gauss(
        &[0.0, 0.0, 1.0, 0.0],
        &[
            1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 0.1, 0.0, 0.0, 0.0, 0.0, 0.1,
        ],
        "mixture[0]",
    );
    let h = DMatrix::from_row_slice(2, 4, &[1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0]);
    BernoulliFilterOptions {
        existence,
        mixture: mixture(vec![(1.0, g)]),
        transition: LinearGaussianTransition::nearly_constant_velocity(2, 1.0, 0.01).unwrap(),
        survival: 1.0,
        birth: Birth::none(),
        position_dims: 2,
        detection: Detection::new(pd, None).unwrap(),
        clutter: Clutter::new(0.25, ClutterDensity::Constant(0.01)).unwrap(),
        likelihood: Some(LinearGaussianLikelihood::new(h, DMatrix::identity(2, 2) * 0.25).unwrap()),
        splitting: Splitting::default(),
        reduction: default_reduction(),
        exclusions: Vec::new(),
    }
}

/// Stone Soup 1.9.1's Bernoulli updater returns the prediction when a scan is empty; the
/// Bernoulli update gives r (1 − p_D) / (1 − r p_D) = 0.08 / 0.28.
#[test]
fn an_empty_scan_is_a_real_update_in_every_filter() {
    let expected: f64 = 0.8 * 0.1 / (1.0 - 0.8 * 0.9);
    assert!((expected - 0.2857142857142857).abs() < 1e-15);
    let state = GmBernoulli::new(0.8, ncv_filter_config(0.8, 0.9).mixture).unwrap();
    let config = no_fov_config(0.9);
    let none: [Region; 0] = [];
    let out = gm_bernoulli_update(&state, &none, &config).unwrap();
    assert!((out.existence - expected).abs() < 1e-15);
    assert!((out.delta - 0.9).abs() < 1e-15);
    let h = DMatrix::from_row_slice(2, 4, &[1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0]);
    let lik = LinearGaussianLikelihood::new(h, DMatrix::identity(2, 2)).unwrap();
    let empty: [Vec<f64>; 0] = [];
    let out = gm_bernoulli_update_vector(&state, &empty, &lik, &config).unwrap();
    assert!((out.existence - expected).abs() < 1e-15);
    // The filter objects.
    let mut gm = GmBernoulliFilter::new(ncv_filter_config(0.8, 0.9)).unwrap();
    gm.update(&none).unwrap();
    assert!((gm.existence() - expected).abs() < 1e-15);
    let mut gm = GmBernoulliFilter::new(ncv_filter_config(0.8, 0.9)).unwrap();
    gm.update_measurements(&empty).unwrap();
    assert!((gm.existence() - expected).abs() < 1e-15);
    let options = ParticleOptions {
        particles: 500,
        ..ParticleOptions::default()
    };
    let mut pf = ParticleBernoulliFilter::new(ncv_filter_config(0.8, 0.9), options).unwrap();
    pf.update(&none).unwrap();
    assert!((pf.existence() - expected).abs() < 1e-14);
    let mut pf = ParticleBernoulliFilter::new(ncv_filter_config(0.8, 0.9), options).unwrap();
    pf.update_measurements(&empty).unwrap();
    assert!((pf.existence() - expected).abs() < 1e-14);
}

// --------------------------------------------------------------------------- Fig. 5

/// With no report, p_D = 1 and the FoV of Fig. 5, the update is the non-detection update of
/// the Fig. 5 scenario already in `splitting`: the same split (Algorithm 1 = Algorithm 2 with
/// one region), the same posterior, and 1 − Δ its non-detection probability.
#[test]
fn fig5_no_report_reduces_to_the_negative_information_scenario() {
    let sc = NegativeInformationScenario::fig5().unwrap();
    let steps = sc.run().unwrap();
    let config = UpdateOptions {
        position_dims: 2,
        detection: Detection::new(sc.detection_prob, Some(sc.fov.clone())).unwrap(),
        clutter: Clutter::new(0.5, ClutterDensity::Constant(0.1)).unwrap(),
        splitting: Splitting {
            enabled: true,
            library: sc.library.clone(),
            options: sc.options.clone(),
        },
        reduction: sc.reduction,
        exclusions: Vec::new(),
    };
    let mut posterior = sc.initial.clone();
    let mut r = 0.6;
    for s in &steps {
        let predicted = ni_predict(&posterior, &sc.transition, &sc.process_noise).unwrap();
        assert_eq!(predicted, s.predicted);
        let state = GmBernoulli::new(r, predicted).unwrap();
        let out = gm_bernoulli_update(&state, &[], &config).unwrap();
        assert_eq!(out.split_components, s.split.mixture.len());
        assert_eq!(out.mixture.len(), s.posterior.len());
        for ((w, g), (w0, g0)) in out
            .mixture
            .components()
            .iter()
            .zip(s.posterior.components())
        {
            assert!((w - w0).abs() < 1e-14, "{w} vs {w0}");
            assert_eq!(g, g0);
        }
        assert!((1.0 - out.delta - s.non_detection_prob).abs() < 1e-14);
        let l = s.non_detection_prob;
        assert!((out.existence - r * l / (1.0 - r + r * l)).abs() < 1e-15);
        posterior = out.mixture;
        r = out.existence;
    }
}

// --------------------------------------------------------------------------- brute force

/// The exact update (53)–(55) for indicator likelihoods: Δ from exact region masses, the
/// posterior moments by importance-weighted Monte Carlo (draws from the prior weighted by
/// α(x) of (104)).
struct Exact {
    delta: f64,
    existence: f64,
    mean: DVector<f64>,
    cov: DMatrix<f64>,
    /// Standard errors of the mean's entries.
    mean_se: DVector<f64>,
}

fn alpha(x: &[f64], pd: f64, fov: &Region, reports: &[Region], kappa: f64) -> f64 {
    if !fov.contains(x) {
        return 1.0;
    }
    let hits = reports.iter().filter(|z| z.contains(x)).count() as f64;
    1.0 - pd + pd * hits / kappa
}

#[allow(clippy::too_many_arguments)]
fn exact_update(
    r: f64,
    prior: &GaussianMixture,
    pd: f64,
    fov: &Region,
    reports: &[Region],
    kappa: f64,
    samples: usize,
    seed: u64,
) -> Exact {
    // Δ = p_D ⟨1_S, p⟩ − Σ_ζ p_D ⟨1_{S∩ζ}, p⟩ / κ, eq. (55), by Region::gaussian_mass.
    let mass = |region: &Region| -> f64 {
        prior
            .components()
            .iter()
            .map(|(w, g)| w * region.gaussian_mass(g, "p").unwrap().value)
            .sum()
    };
    let mut delta = pd * mass(fov);
    for z in reports {
        let both = Region::intersection(vec![fov.clone(), z.clone()], "both").unwrap();
        delta -= pd * mass(&both) / kappa;
    }
    let existence = r * (1.0 - delta) / (1.0 - r * delta); // (54)
    let n = prior.dim().unwrap();
    let mut rng = seeded(seed);
    let cum: Vec<f64> = prior
        .components()
        .iter()
        .scan(0.0, |a, (w, _)| {
            *a += w;
            Some(*a)
        })
        .collect();
    let (mut sw, mut sw2) = (0.0, 0.0);
    let mut s1 = vec![0.0; n];
    let mut s2 = vec![0.0; n * n];
    let mut z = vec![0.0; n];
    let mut x = vec![0.0; n];
    // Sums about a fixed centre (the prior mean) to avoid cancellation.
    let (_, centre, _) = moments(prior).unwrap();
    for _ in 0..samples {
        let u = uniform(&mut rng);
        let k = cum.iter().position(|c| u < *c).unwrap_or(cum.len() - 1);
        let g = &prior.components()[k].1;
        for zi in z.iter_mut() {
            *zi = normal::sample(&mut rng);
        }
        let l = g.chol();
        for i in 0..n {
            let mut v = g.mean()[i];
            for j in 0..=i {
                v += l[(i, j)] * z[j];
            }
            x[i] = v;
        }
        let a = alpha(&x, pd, fov, reports, kappa);
        if a == 0.0 {
            continue;
        }
        sw += a;
        sw2 += a * a;
        for i in 0..n {
            let di = x[i] - centre[i];
            s1[i] += a * di;
            for j in 0..=i {
                s2[i * n + j] += a * di * (x[j] - centre[j]);
            }
        }
    }
    let d = DVector::from_iterator(n, s1.iter().map(|v| v / sw));
    let mean = &centre + &d;
    let cov = DMatrix::from_fn(n, n, |i, j| {
        let (a, b) = if j <= i { (i, j) } else { (j, i) };
        s2[a * n + b] / sw - d[i] * d[j]
    });
    // Effective sample size of the weights; the mean's standard error per entry.
    let ess = sw * sw / sw2;
    let mean_se = DVector::from_iterator(n, (0..n).map(|i| (cov[(i, i)] / ess).sqrt()));
    Exact {
        delta,
        existence,
        mean,
        cov,
        mean_se,
    }
}

/// A 2D case: a two-component prior straddling the edge of a box FoV, two disc reports (one
/// near the density, one far: clutter-like), κ = λ_c c̃ = 0.5 · 0.2.
fn case_2d() -> (GaussianMixture, Region, Vec<Region>) {
    let prior = mixture(vec![
        (0.6, gauss(&[0.0, 0.0], &[2.0, 0.6, 0.6, 1.0], "p0")),
        (0.4, gauss(&[2.5, 1.0], &[1.0, -0.3, -0.3, 1.5], "p1")),
    ]);
    let fov = Region::axis_box(&[-1.0, -4.0], &[6.0, 4.0], "fov").unwrap();
    let reports = vec![
        Region::ball(&[1.0, 0.5], 1.2, "r0").unwrap(),
        Region::ball(&[5.0, -3.0], 1.0, "r1").unwrap(),
    ];
    (prior, fov, reports)
}

/// A 4D case (x, y, ẋ, ẏ) with position–velocity correlation, so the velocity moments move
/// with the position update.
fn case_4d() -> (GaussianMixture, Region, Vec<Region>) {
    #[rustfmt::skip]
    let p0 = [
        2.0, 0.6, 0.5, 0.1,
        0.6, 1.0, 0.1, 0.3,
        0.5, 0.1, 0.4, 0.05,
        0.1, 0.3, 0.05, 0.3,
    ];
    #[rustfmt::skip]
    let p1 = [
        1.0, -0.3, -0.2, 0.0,
        -0.3, 1.5, 0.0, 0.4,
        -0.2, 0.0, 0.3, 0.0,
        0.0, 0.4, 0.0, 0.5,
    ];
    let prior = mixture(vec![
        (0.6, gauss(&[0.0, 0.0, 1.0, 0.0], &p0, "p0")),
        (0.4, gauss(&[2.5, 1.0, 0.0, -0.5], &p1, "p1")),
    ]);
    let (_, fov, reports) = case_2d();
    (prior, fov, reports)
}

struct Errors {
    delta: f64,
    existence: f64,
    /// max_i |mean_i − exact_i| / √P_ii (exact).
    mean: f64,
    /// max_ij |P_ij − exact_ij| / √(P_ii P_jj) (exact).
    cov: f64,
}

fn gm_errors(
    prior: &GaussianMixture,
    fov: &Region,
    reports: &[Region],
    exact: &Exact,
    library: SplitLibrary,
    options: SplitOptions,
) -> (Errors, usize) {
    let (pd, kappa, r) = (0.9, 0.1, 0.7);
    let config = UpdateOptions {
        position_dims: 2,
        detection: Detection::new(pd, Some(fov.clone())).unwrap(),
        clutter: Clutter::new(0.5, ClutterDensity::Constant(kappa / 0.5)).unwrap(),
        splitting: Splitting {
            enabled: true,
            library,
            options,
        },
        reduction: identity_reduction(),
        exclusions: Vec::new(),
    };
    let state = GmBernoulli::new(r, prior.clone()).unwrap();
    let out = gm_bernoulli_update(&state, reports, &config).unwrap();
    let (_, m, p) = moments(&out.mixture).unwrap();
    let n = m.len();
    let sd = |i: usize| exact.cov[(i, i)].sqrt();
    let mean = (0..n)
        .map(|i| (m[i] - exact.mean[i]).abs() / sd(i))
        .fold(0.0, f64::max);
    let mut cov: f64 = 0.0;
    for i in 0..n {
        for j in 0..n {
            cov = cov.max((p[(i, j)] - exact.cov[(i, j)]).abs() / (sd(i) * sd(j)));
        }
    }
    (
        Errors {
            delta: (out.delta - exact.delta).abs(),
            existence: (out.existence - exact.existence).abs(),
            mean,
            cov,
        },
        out.split_components,
    )
}

fn fine_options() -> SplitOptions {
    SplitOptions {
        min_weight: 1e-3,
        grid_bound: 3.0,
        ..SplitOptions::default()
    }
}

/// The test cases: on 2D and 4D states, a small report disc inside the field of view
/// ("report", positive information dominated by the disc, κ = 0.1), a wide one ("wide"),
/// and no report at all ("miss", negative information).
fn cases() -> Vec<(std::string::String, GaussianMixture, Region, Vec<Region>)> {
    let mut out = Vec::new();
    for (dim, (prior, fov, reports)) in [("2d", case_2d()), ("4d", case_4d())] {
        out.push((
            std::format!("{dim} report"),
            prior.clone(),
            fov.clone(),
            reports,
        ));
        let wide = vec![Region::ball(&[1.0, 0.5], 3.0, "wide").unwrap()];
        out.push((std::format!("{dim} wide"), prior.clone(), fov.clone(), wide));
        out.push((std::format!("{dim} miss"), prior, fov, Vec::new()));
    }
    out
}

/// Measured errors of the GM update against the exact update, for a split library and
/// split options, over [`cases`]: (case, errors, components).
fn measure(
    exacts: &[Exact],
    library: &SplitLibrary,
    options: &SplitOptions,
) -> Vec<(std::string::String, Errors, usize)> {
    cases()
        .into_iter()
        .zip(exacts)
        .map(|((name, prior, fov, reports), exact)| {
            let (e, n) = gm_errors(
                &prior,
                &fov,
                &reports,
                exact,
                library.clone(),
                options.clone(),
            );
            (name, e, n)
        })
        .collect()
}

fn exacts(samples: usize, seed: u64) -> Vec<Exact> {
    cases()
        .iter()
        .enumerate()
        .map(|(i, (_, prior, fov, reports))| {
            exact_update(0.7, prior, 0.9, fov, reports, 0.1, samples, seed + i as u64)
        })
        .collect()
}

/// The two split settings every comparison runs: the filter defaults and [`fine_options`].
fn settings() -> [(&'static str, SplitOptions); 2] {
    [
        ("defaults", SplitOptions::default()),
        ("fine", fine_options()),
    ]
}

/// The two libraries compared (both R = 4, λ = 0.001): Table I and the variance-preserving
/// split.
fn compared_libraries() -> [(&'static str, SplitLibrary); 2] {
    [
        ("table I", SplitLibrary::table_i()),
        (
            "variance-preserving",
            SplitLibrary::variance_preserving(4, 0.001).unwrap(),
        ),
    ]
}

/// [`measure`] for one library and one setting, printing each case's errors (run with
/// `--nocapture` for the numbers).
fn measure_and_print(
    exacts: &[Exact],
    (lname, library): (&str, &SplitLibrary),
    (label, options): (&str, &SplitOptions),
) -> Vec<(std::string::String, Errors, usize)> {
    let measured = measure(exacts, library, options);
    for (name, e, comps) in &measured {
        std::println!(
            "{name} {label} {lname}: |dΔ| {:.2e} |dr| {:.2e} mean {:.2e} cov {:.2e} ({comps} components)",
            e.delta,
            e.existence,
            e.mean,
            e.cov
        );
    }
    measured
}

/// Table I against the variance-preserving split over all cases and both settings, with
/// the exact moments from `samples` draws: the summed (mean, cov) errors per library (rows
/// in the order of [`compared_libraries`]) and setting (columns in the order of
/// [`settings`]).
fn library_comparison(samples: usize, seed: u64) -> [[[f64; 2]; 2]; 2] {
    let exacts = exacts(samples, seed);
    let mut sums = [[[0.0f64; 2]; 2]; 2];
    for (si, (label, options)) in settings().iter().enumerate() {
        for (li, (lname, lib)) in compared_libraries().iter().enumerate() {
            for (_, e, _) in measure_and_print(&exacts, (lname, lib), (label, options)) {
                sums[li][si][0] += e.mean;
                sums[li][si][1] += e.cov;
            }
        }
    }
    std::println!(
        "summed (mean, cov) errors per setting: table I {:?}, variance-preserving {:?}",
        sums[0],
        sums[1]
    );
    sums
}

/// The summed mean + covariance error of one library over both settings.
fn total_error(sums: &[[f64; 2]; 2]) -> f64 {
    sums.iter().map(|s| s[0] + s[1]).sum()
}

/// The GM update against the exact update (53)–(55) on 2D and 4D states. The exact Δ and
/// r come from region masses (error ~1e-13); the exact moments from 10⁶ importance-weighted
/// draws (standard error of each mean entry below 0.003 σ, checked).
///
/// The tolerances are what the splitting reaches, with a margin of about 1.5×. The
/// mean-based partition over-counts a convex region whose boundary curves on the scale of
/// the components (a component whose mean lies just inside a disc spills more mass out
/// than its neighbour just outside spills in): with the defaults (w_min = 0.01, ζ = 2) a
/// disc of radius 1.2 under components of σ ≈ 1.2 gets 0.319 of mass for an exact 0.266,
/// and w_min = 10⁻⁴ (10⁴ components) still 0.279. Δ multiplies that error by p_D/κ = 9, so
/// with a small disc and κ = 0.1 Δ is off by ~0.5 and the posterior covariance by ~50 %,
/// while r (through (54)) stays within 0.02; wide discs (radius 3) keep r within 0.004 and
/// the covariance within 15 %, misses Δ and r within 0.014.
#[test]
fn eq53_update_matches_the_exact_update_on_2d_and_4d_states() {
    let exacts = exacts(1_000_000, 11);
    for e in &exacts {
        assert!(e.mean_se.amax() / e.cov[(0, 0)].sqrt() < 0.003);
    }
    let library = default_split_library();
    //             Δ     r      mean  cov
    let tol = |name: &str| -> [f64; 4] {
        if name.ends_with("report") {
            [0.9, 0.035, 0.18, 0.9]
        } else if name.ends_with("wide") {
            [0.8, 0.006, 0.07, 0.25]
        } else {
            [0.02, 0.02, 0.17, 0.22]
        }
    };
    for (label, options) in settings() {
        for (name, e, _) in measure_and_print(&exacts, ("default", &library), (label, &options)) {
            let t = tol(&name);
            assert!(e.delta < t[0], "{name} {label} Δ: {}", e.delta);
            assert!(e.existence < t[1], "{name} {label} r: {}", e.existence);
            assert!(e.mean < t[2], "{name} {label} mean: {}", e.mean);
            assert!(e.cov < t[3], "{name} {label} cov: {}", e.cov);
        }
    }
}

/// Table I against the variance-preserving split (both R = 4, λ = 0.001) over all cases and
/// both settings, with 10⁶ draws for the exact moments (the record behind
/// [`default_split_library`]'s choice): the default is the library whose posterior moments
/// are closer to the exact update (summed mean + covariance errors). Takes about as long as
/// the rest of the module together:
/// `cargo test -p fisst --lib -- --ignored table1_default_library_is_closer_to_the_exact_update_with_a_million_draws --nocapture`.
#[test]
#[ignore = "10⁶ draws per case; run with `cargo test -p fisst --lib -- --ignored table1_default_library_is_closer_to_the_exact_update_with_a_million_draws --nocapture`"]
fn table1_default_library_is_closer_to_the_exact_update_with_a_million_draws() {
    let sums = library_comparison(1_000_000, 12);
    let best = if total_error(&sums[0]) < total_error(&sums[1]) {
        0
    } else {
        1
    };
    assert_eq!(
        compared_libraries()[best].1,
        default_split_library(),
        "{sums:?}"
    );
}

/// The same comparison in the default run, with 10⁵ draws (seed 12). The Monte Carlo
/// standard error of each exact mean entry is then below 0.01 σ (checked). The summed
/// errors are sums of max-norm errors against the same exact moments, so they move far
/// less than that: 10⁵ against 10⁶ draws moved the totals by 0.005 (Table I, 2.622 against
/// 2.627) and 0.006 (variance-preserving, 2.765 against 2.771). Tolerance: 0.05 on each
/// total against the 10⁶-draw record, ten times that; the margins asserted (0.1 overall,
/// 0.05 per setting; measured 0.14, 0.07 and 0.07) are more than twice it.
#[test]
fn table1_default_library_is_closer_to_the_exact_update() {
    for e in exacts(100_000, 12) {
        assert!(e.mean_se.amax() / e.cov[(0, 0)].sqrt() < 0.01);
    }
    let sums = library_comparison(100_000, 12);
    // Table I is the default, and it wins overall and in each setting.
    assert_eq!(compared_libraries()[0].1, default_split_library());
    let (table_i, vp) = (total_error(&sums[0]), total_error(&sums[1]));
    assert!((table_i - 2.627).abs() < 0.05, "table I {table_i}");
    assert!((vp - 2.771).abs() < 0.05, "variance-preserving {vp}");
    assert!(
        table_i + 0.1 < vp,
        "table I {table_i}, variance-preserving {vp}"
    );
    for (si, (label, _)) in settings().iter().enumerate() {
        let (t, v) = (sums[0][si], sums[1][si]);
        assert!(
            t[0] + t[1] + 0.05 < v[0] + v[1],
            "{label}: table I {t:?}, variance-preserving {v:?}"
        );
    }
}

/// The same comparison with 10⁷ draws (about a minute at opt-level 1):
/// `cargo test -p fisst --release -- --ignored ten_million --nocapture`.
#[test]
#[ignore = "10⁷ draws per case; run with `cargo test -p fisst --release -- --ignored ten_million --nocapture`"]
fn eq53_update_matches_the_exact_update_with_ten_million_draws() {
    let exacts = exacts(10_000_000, 13);
    for (lname, lib) in compared_libraries() {
        for (label, options) in settings() {
            for (_, e, _) in measure_and_print(&exacts, (lname, &lib), (label, &options)) {
                assert!(e.existence < 0.035 && e.mean < 0.18 && e.cov < 0.9);
            }
        }
    }
}

/// The particle filter's update against the same exact update: 200 000 particles drawn from
/// the prior (no prediction, no move), so Δ and r carry Monte Carlo error ~1/√N · O(1)
/// ≈ 0.005 (tolerance 0.02) and the means ~0.005 σ (tolerance 0.03).
#[test]
fn eq53_particle_update_matches_the_exact_update() {
    let (prior, fov, reports) = case_4d();
    let exact = exact_update(0.7, &prior, 0.9, &fov, &reports, 0.1, 1_000_000, 14);
    let config = BernoulliFilterOptions {
        existence: 0.7,
        mixture: prior.clone(),
        transition: LinearGaussianTransition::nearly_constant_velocity(2, 1.0, 0.01).unwrap(),
        survival: 1.0,
        birth: Birth::none(),
        position_dims: 2,
        detection: Detection::new(0.9, Some(fov.clone())).unwrap(),
        clutter: Clutter::new(0.5, ClutterDensity::Constant(0.2)).unwrap(),
        likelihood: None,
        splitting: Splitting::default(),
        reduction: default_reduction(),
        exclusions: Vec::new(),
    };
    let options = ParticleOptions {
        particles: 200_000,
        mcmc_moves: 0,
        seed: 3,
        ..ParticleOptions::default()
    };
    let mut pf = ParticleBernoulliFilter::new(config, options).unwrap();
    let info = pf.update(&reports).unwrap();
    assert!(
        (info.delta - exact.delta).abs() < 0.02,
        "{} {}",
        info.delta,
        exact.delta
    );
    assert!((pf.existence() - exact.existence).abs() < 0.02);
    let e = pf.estimate(&EstimateOptions::default()).unwrap();
    for i in 0..4 {
        let sd = exact.cov[(i, i)].sqrt();
        assert!((e.mean[i] - exact.mean[i]).abs() / sd < 0.03, "mean[{i}]");
        assert!(
            (e.cov[i][i] - exact.cov[(i, i)]).abs() / (sd * sd) < 0.05,
            "cov[{i}]"
        );
    }
}

/// Algorithm 2 makes the split independent of the order of the regions; the update's sum
/// over reports then agrees to rounding.
#[test]
fn alg2_the_update_does_not_depend_on_the_order_of_the_reports() {
    let (prior, fov, mut reports) = case_4d();
    reports.push(Region::ball(&[-0.5, -0.5], 1.5, "r2").unwrap());
    let config = UpdateOptions {
        exclusions: vec![Region::axis_box(&[2.0, 2.0], &[3.0, 3.0], "e").unwrap()],
        ..UpdateOptions::new(
            2,
            Detection::new(0.9, Some(fov)).unwrap(),
            Clutter::new(0.5, ClutterDensity::Constant(0.2)).unwrap(),
        )
    };
    let state = GmBernoulli::new(0.7, prior).unwrap();
    let a = gm_bernoulli_update(&state, &reports, &config).unwrap();
    reports.reverse();
    let b = gm_bernoulli_update(&state, &reports, &config).unwrap();
    assert_eq!(a.split_components, b.split_components);
    assert!((a.existence - b.existence).abs() < 1e-14);
    assert!((a.delta - b.delta).abs() < 1e-13);
    let (_, ma, pa) = moments(&a.mixture).unwrap();
    let (_, mb, pb) = moments(&b.mixture).unwrap();
    assert!((ma - mb).amax() < 1e-12 && (pa - pb).amax() < 1e-12);
}

/// Exclusions: the posterior puts (almost) no mass in the exclusion region, the existence
/// is that of the update on the constrained prior, and it matches the exact conditional
/// density's moments.
#[test]
fn exclusions_remove_their_mass_and_keep_the_existence() {
    let prior = mixture(vec![(1.0, gauss(&[0.0, 0.0], &[1.0, 0.0, 0.0, 1.0], "p0"))]);
    let exclusion = Region::axis_box(&[0.5, -10.0], &[10.0, 10.0], "e").unwrap();
    let config = UpdateOptions {
        exclusions: vec![exclusion.clone()],
        reduction: identity_reduction(),
        ..UpdateOptions::new(
            2,
            Detection::new(0.0, None).unwrap(),
            Clutter::new(0.5, ClutterDensity::Constant(0.2)).unwrap(),
        )
    };
    let state = GmBernoulli::new(0.7, prior).unwrap();
    let out = gm_bernoulli_update(&state, &[], &config).unwrap();
    assert_eq!(out.existence, 0.7); // p_D = 0: no information about existence
    // Exact: N(0, 1) truncated to x < 0.5: mean −φ(0.5)/Φ(0.5) = −0.5092.
    let exact_mean = -normal::pdf(0.5) / normal::cdf(0.5);
    let (_, m, _) = moments(&out.mixture).unwrap();
    assert!((m[0] - exact_mean).abs() < 0.03, "{} vs {exact_mean}", m[0]);
    assert!(m[1].abs() < 1e-12);
    let inside: f64 = out
        .mixture
        .components()
        .iter()
        .map(|(w, g)| w * exclusion.gaussian_mass(g, "g").unwrap().value)
        .sum();
    assert!(inside < 0.05, "{inside}");
    // An exclusion that covers everything is an error.
    let all = Region::axis_box(&[-100.0, -100.0], &[100.0, 100.0], "e").unwrap();
    let config = UpdateOptions {
        exclusions: vec![all],
        ..config
    };
    assert_eq!(
        gm_bernoulli_update(&state, &[], &config)
            .unwrap_err()
            .field(),
        "exclusions"
    );
}

// --------------------------------------------------------------------------- vector

/// With p_D = 1, no clutter and r = 1 the vector update is the Kalman filter.
#[test]
fn vector_filter_is_the_kalman_filter_with_certain_detection_and_no_clutter() {
    let mut config = ncv_filter_config(1.0, 1.0);
    config.clutter = Clutter::none();
    config.reduction = identity_reduction();
    let transition = config.transition.clone();
    let lik = config.likelihood.clone().unwrap();
    let mut filter = GmBernoulliFilter::new(config.clone()).unwrap();
    let (mut m, mut p) = {
        let g = &config.mixture.components()[0].1;
        (g.mean().clone(), g.cov().clone())
    };
    let mut rng = seeded(5);
    let (f, q, h, r) = (transition.f(), transition.q(), lik.h(), lik.r());
    for k in 0..25 {
        let z = vec![
            k as f64 + normal::sample(&mut rng),
            0.5 * normal::sample(&mut rng),
        ];
        filter.predict().unwrap();
        filter
            .update_measurements(core::slice::from_ref(&z))
            .unwrap();
        // Kalman filter.
        m = f * &m;
        p = f * &p * f.transpose() + q;
        let s = h * &p * h.transpose() + r;
        let k_gain = &p * h.transpose() * s.clone().try_inverse().unwrap();
        m = &m + &k_gain * (DVector::from_vec(z) - h * &m);
        p = (DMatrix::identity(4, 4) - &k_gain * h) * &p;
        assert_eq!(filter.existence(), 1.0);
        assert_eq!(filter.mixture().len(), 1);
        let g = &filter.mixture().components()[0].1;
        assert!((g.mean() - &m).amax() < 1e-9, "k={k}");
        assert!((g.cov() - &p).amax() < 1e-9, "k={k}");
        assert!(filter.last_update().unwrap().delta == f64::NEG_INFINITY);
    }
}

/// The vector update against its closed form for one Gaussian, constant p_D, two
/// measurements and clutter: the weights and existence of the Bernoulli filter equations.
#[test]
fn vector_update_matches_its_closed_form() {
    let config = ncv_filter_config(0.6, 0.8);
    let state = GmBernoulli::new(0.6, config.mixture.clone()).unwrap();
    let mut uc = config.update_options();
    uc.reduction = identity_reduction();
    uc.clutter = Clutter::new(2.0, ClutterDensity::PerReport(vec![0.01, 0.02])).unwrap();
    let lik = config.likelihood.clone().unwrap();
    let zs = [vec![0.5, -0.3], vec![4.0, 3.0]];
    let out = gm_bernoulli_update_vector(&state, &zs, &lik, &uc).unwrap();
    let g = &state.mixture.components()[0].1;
    let s = lik.h() * g.cov() * lik.h().transpose() + lik.r();
    let hm = lik.h() * g.mean();
    let q: Vec<f64> = zs
        .iter()
        .map(|z| Gaussian::new(hm.clone(), s.clone(), "s").unwrap().pdf(z))
        .collect();
    let kappa = [0.02, 0.04];
    let ratio: f64 = q.iter().zip(kappa).map(|(q, k)| q / k).sum();
    let delta = 0.8 - 0.8 * ratio;
    assert!((out.delta - delta).abs() < 1e-12);
    assert!((out.existence - 0.6 * (1.0 - delta) / (1.0 - 0.6 * delta)).abs() < 1e-12);
    let w: Vec<f64> = out.mixture.components().iter().map(|(w, _)| *w).collect();
    assert_eq!(w.len(), 3);
    let total = 0.2 + 0.8 * ratio;
    assert!((w[0] - 0.2 / total).abs() < 1e-12);
    assert!((w[1] - 0.8 * q[0] / kappa[0] / total).abs() < 1e-12);
    // Errors.
    let bad = [vec![1.0]];
    assert_eq!(
        gm_bernoulli_update_vector(&state, &bad, &lik, &uc)
            .unwrap_err()
            .field(),
        "measurements[0]"
    );
    let three = [vec![1.0, 2.0], vec![0.0, 0.0], vec![1.0, 1.0]];
    assert_eq!(
        gm_bernoulli_update_vector(&state, &three, &lik, &uc)
            .unwrap_err()
            .field(),
        "clutter.density"
    );
    let mut none = uc.clone();
    none.clutter = Clutter::none();
    assert_eq!(
        gm_bernoulli_update_vector(&state, &zs, &lik, &none)
            .unwrap_err()
            .field(),
        "clutter.rate"
    );
    let e = LinearGaussianLikelihood::new(
        DMatrix::from_row_slice(1, 4, &[1.0, 0.0, 0.0, 0.0]),
        DMatrix::from_row_slice(1, 1, &[-1.0]),
    )
    .unwrap_err();
    assert_eq!(e.field(), "likelihood.r");
}

/// A clutter density given as a function of the measurement.
#[test]
fn clutter_density_function() {
    let config = ncv_filter_config(0.6, 0.8);
    let state = GmBernoulli::new(0.6, config.mixture.clone()).unwrap();
    let lik = config.likelihood.clone().unwrap();
    let mut uc = config.update_options();
    uc.reduction = identity_reduction();
    let f = ClutterFunction(alloc::sync::Arc::new(
        |z: &[f64]| if z[0] > 0.0 { 0.01 } else { 0.02 },
    ));
    uc.clutter = Clutter::new(2.0, ClutterDensity::Function(f)).unwrap();
    let zs = [vec![0.5, -0.3], vec![-4.0, 3.0]];
    let a = gm_bernoulli_update_vector(&state, &zs, &lik, &uc).unwrap();
    uc.clutter = Clutter::new(2.0, ClutterDensity::PerReport(vec![0.01, 0.02])).unwrap();
    let b = gm_bernoulli_update_vector(&state, &zs, &lik, &uc).unwrap();
    // The whole update (existence, Δ, every component), not just the existence; and the
    // clutter densities matter: a constant 0.01 gives another update.
    assert_eq!(a, b);
    assert!(
        a.existence != 0.6 && a.existence.is_finite(),
        "{}",
        a.existence
    );
    uc.clutter = Clutter::new(2.0, ClutterDensity::Constant(0.01)).unwrap();
    let c = gm_bernoulli_update_vector(&state, &zs, &lik, &uc).unwrap();
    assert!(c.existence != a.existence && c.delta != a.delta);
    // Region reports cannot use a function.
    uc.clutter = Clutter::new(
        2.0,
        ClutterDensity::Function(ClutterFunction(alloc::sync::Arc::new(|_: &[f64]| 0.1))),
    )
    .unwrap();
    let disc = [Region::ball(&[0.0, 0.0], 1.0, "z").unwrap()];
    assert_eq!(
        gm_bernoulli_update(&state, &disc, &uc).unwrap_err().field(),
        "clutter.density"
    );
}

// --------------------------------------------------------------------------- misc

/// A caller-supplied generalized likelihood equal to the indicator gives the same update
/// as the region reports.
#[test]
fn a_closure_likelihood_equal_to_the_indicator_gives_the_same_update() {
    let (prior, fov, reports) = case_2d();
    let config = UpdateOptions::new(
        2,
        Detection::new(0.9, Some(fov)).unwrap(),
        Clutter::new(0.5, ClutterDensity::Constant(0.2)).unwrap(),
    );
    let state = GmBernoulli::new(0.7, prior).unwrap();
    let a = gm_bernoulli_update(&state, &reports, &config).unwrap();
    let rs = reports.clone();
    let g = FnLikelihood::new(
        2,
        move |i, x: &[f64]| if rs[i].contains(x) { 1.0 } else { 0.0 },
        reports.clone(),
    );
    let b = gm_bernoulli_update_with(&state, &g, &config).unwrap();
    assert_eq!(a, b);
    let negative = FnLikelihood::new(1, |_, _: &[f64]| -1.0, Vec::new());
    assert_eq!(
        gm_bernoulli_update_with(&state, &negative, &config)
            .unwrap_err()
            .field(),
        "likelihood[0]"
    );
}

#[test]
fn update_errors_name_the_field() {
    let (prior, fov, reports) = case_2d();
    let state = GmBernoulli::new(0.7, prior.clone()).unwrap();
    let good = UpdateOptions::new(
        2,
        Detection::new(0.9, Some(fov.clone())).unwrap(),
        Clutter::new(0.5, ClutterDensity::Constant(0.2)).unwrap(),
    );
    let three_d = [Region::ball(&[0.0, 0.0, 0.0], 1.0, "z").unwrap()];
    assert_eq!(
        gm_bernoulli_update(&state, &three_d, &good)
            .unwrap_err()
            .to_string(),
        "reports[0].ball.center has length 3 but position_dims is 2"
    );
    let mut c = good.clone();
    c.position_dims = 3;
    c.detection.fov = None;
    assert_eq!(
        gm_bernoulli_update(&state, &[], &c).unwrap_err().field(),
        "position_dims",
    );
    let mut c = good.clone();
    c.clutter.density = ClutterDensity::PerReport(vec![0.1]);
    assert_eq!(
        gm_bernoulli_update(&state, &reports, &c)
            .unwrap_err()
            .field(),
        "clutter.density"
    );
    let mut c = good.clone();
    c.clutter.rate = f64::NAN;
    assert_eq!(
        gm_bernoulli_update(&state, &reports, &c)
            .unwrap_err()
            .field(),
        "clutter.rate"
    );
    let mut c = good.clone();
    c.detection.probability = 2.0;
    assert_eq!(
        gm_bernoulli_update(&state, &reports, &c)
            .unwrap_err()
            .field(),
        "detection.probability"
    );
    let mut c = good.clone();
    c.reduction.max_components = Some(0);
    assert_eq!(
        gm_bernoulli_update(&state, &reports, &c)
            .unwrap_err()
            .field(),
        "reduction.max_components"
    );
    let bad_state = GmBernoulli {
        existence: f64::NAN,
        mixture: prior,
    };
    assert_eq!(
        gm_bernoulli_update(&bad_state, &reports, &good)
            .unwrap_err()
            .field(),
        "existence"
    );
    // No clutter and a report only the object explains: certain existence.
    let mut c = good.clone();
    c.clutter = Clutter::none();
    let near = [reports[0].clone()];
    let out = gm_bernoulli_update(&state, &near, &c).unwrap();
    assert_eq!(out.existence, 1.0);
    assert_eq!(out.delta, f64::NEG_INFINITY);
    // ... and one it cannot explain.
    let far = [Region::ball(&[50.0, 50.0], 1.0, "z").unwrap()];
    assert_eq!(
        gm_bernoulli_update(&state, &far, &c).unwrap_err().field(),
        "reports"
    );
    let particles = ParticleOptions {
        particles: 0,
        ..ParticleOptions::default()
    };
    assert_eq!(
        ParticleBernoulliFilter::new(ncv_filter_config(0.5, 0.9), particles)
            .unwrap_err()
            .field(),
        "particles"
    );
}

/// The variance-preserving entries shipped as constants are what the optimiser finds, and
/// they are local minima of J under the constraint.
#[test]
fn eq13_variance_preserving_constants_are_the_optimiser_output() {
    for r in [3, 4] {
        let lib = SplitLibrary::variance_preserving(r, 0.001).unwrap();
        let (w, m, s) = crate::splitting::variance_preserving_optimise(r, 0.001);
        for (a, b) in lib.weights().iter().zip(&w) {
            assert!((a - b).abs() < 1e-9);
        }
        for (a, b) in lib.means().iter().zip(&m) {
            assert!((a - b).abs() < 1e-9);
        }
        assert!((lib.sigma() - s).abs() < 1e-9);
        assert!((lib.variance() - 1.0).abs() < 1e-12);
        assert!(
            lib.objective()
                > SplitLibrary::for_components(r, 0.001, Default::default())
                    .unwrap()
                    .objective()
        );
    }
}

#[test]
fn estimates_include_the_optimal_bernoulli_report() {
    use crate::bernoulli::{ApplicationLoss, Costs};
    let filter = GmBernoulliFilter::new(ncv_filter_config(0.8, 0.9)).unwrap();
    let loss = ApplicationLoss::new(Costs::mpe(), 1.0).unwrap();
    let e = filter
        .estimate(&EstimateOptions { loss: Some(loss) })
        .unwrap();
    assert_eq!(e.existence, 0.8);
    assert_eq!(e.mean, vec![0.0, 0.0, 1.0, 0.0]);
    let report = e.report.clone().unwrap();
    // One Gaussian: a* is the position mean, q(a*) = e^{−1/2} for N(0, I₂) and r0 = 1.
    assert_eq!(report.mmuc.center, vec![0.0, 0.0]);
    assert!((report.miss_probability() - (-0.5f64).exp()).abs() < 1e-9);
    let direct = crate::bernoulli::estimate(
        0.8,
        &crate::bernoulli::SpatialDensity::gaussian_from_slices(&[0.0, 0.0], &[1.0, 0.0, 0.0, 1.0])
            .unwrap(),
        &loss,
    )
    .unwrap();
    assert_eq!(report.declare, direct.declare);
    assert!((report.threshold.gamma - direct.threshold.gamma).abs() < 1e-9);
    assert!((e.rss(0..2) - 2f64.sqrt()).abs() < 1e-12);
}

/// An innovation covariance S = H P Hᵀ + R = [[3, 3], [3, 3]] that is singular to rounding
/// (H of rank one, R negligible next to H P Hᵀ; Cholesky's 3 − (3/√3)² < 0): the error names the component and says S's smallest
/// eigenvalue. (Asymmetric or indefinite P and R are refused by `Gaussian` and
/// `LinearGaussianLikelihood`, see `validate_tests`.)
#[test]
fn vector_update_says_the_innovation_smallest_eigenvalue() {
    use alloc::string::ToString;
    let g = gauss(&[0.0, 0.0], &[1.5, 0.0, 0.0, 1.5], "mixture[0]");
    let state = GmBernoulli::new(
        0.5,
        GaussianMixture::new(vec![(1.0, g)], "mixture").unwrap(),
    )
    .unwrap();
    let lik = LinearGaussianLikelihood::new(
        DMatrix::from_row_slice(2, 2, &[1.0, 1.0, 1.0, 1.0]),
        DMatrix::from_row_slice(2, 2, &[1e-30, 0.0, 0.0, 1e-30]),
    )
    .unwrap();
    let e = gm_bernoulli_update_vector(&state, &[vec![0.0, 0.0]], &lik, &no_fov_config(0.9))
        .unwrap_err();
    let crate::Error::NotDefinite {
        smallest_eigenvalue,
        ..
    } = e
    else {
        panic!("{e}");
    };
    assert!(smallest_eigenvalue.abs() < 1e-14, "{e}");
    assert_eq!(
        e.to_string(),
        alloc::format!(
            "mixture[0].cov is not positive definite (smallest eigenvalue {smallest_eigenvalue})"
        )
    );
}
