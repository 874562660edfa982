//! Reproductions of García-Fernández & Svensson, "Spooky effect in optimal OSPA estimation and
//! how GOSPA solves it" (`003_…`): Fig. 1's transitions, Example 5, eq. (11) and Fig. 3, and
//! Fig. 2's classical estimators against a direct maximisation of the multi-object density.

use fisst::cardinality::multi_bernoulli_cardinality;
use fisst::estimators::alternatives::{jom_estimate, mam_estimate, map_cardinality_estimate};
use fisst::estimators::multi_bernoulli::{SetMetric, mean_error, optimal_estimate};

const METRICS: [SetMetric; 3] = [SetMetric::GOSPA, SetMetric::Ospa, SetMetric::Uospa];

fn report(r: &[f64], metric: SetMetric) -> Vec<bool> {
    optimal_estimate(r, metric, 1.0, 2.0).unwrap().report
}

fn count(u: &[bool]) -> usize {
    u.iter().filter(|&&b| b).count()
}

#[test]
fn fig1_single_component_threshold_is_one_half_for_every_metric() {
    // With r2 = 0 every optimal estimator reports target 1 exactly when r1 > 1/2.
    for metric in METRICS {
        for k in 0..=200 {
            let r1 = k as f64 / 200.0;
            let u = report(&[r1, 0.0], metric);
            assert_eq!(u, vec![r1 > 0.5, false], "{metric:?} r1={r1}");
        }
    }
}

#[test]
fn fig1_gospa_decides_each_component_alone() {
    for i in 0..=40 {
        for j in 0..=40 {
            let (r1, r2) = (i as f64 / 40.0, j as f64 / 40.0);
            assert_eq!(
                report(&[r1, r2], SetMetric::GOSPA),
                vec![r1 > 0.5, r2 > 0.5]
            );
        }
    }
}

#[test]
fn fig1_ospa_and_uospa_are_spooky() {
    // OSPA: both reported although neither is more likely than not.
    assert_eq!(report(&[0.4, 0.4], SetMetric::Ospa), vec![true, true]);
    // UOSPA: target 1 (r1 = 0.55 > 1/2) is dropped when a far-away r2 = 0.6 appears, and
    // reported when r2 = 0.3. Hand computation (c = 1, p = 2), E[max(N, k)] − E[D]:
    // (1,0): 1 + r1 r2 − r1;  (0,1): 1 + r1 r2 − r2;  (1,1): 2 − r1 − r2;  (0,0): r1 + r2.
    assert_eq!(report(&[0.55, 0.6], SetMetric::Uospa), vec![false, true]);
    assert_eq!(report(&[0.55, 0.3], SetMetric::Uospa), vec![true, false]);
    let e = mean_error(&[0.55, 0.6], &[false, true], SetMetric::Uospa, 1.0, 2.0).unwrap();
    assert!((e - (1.0 + 0.33 - 0.6)).abs() < 1e-14);
    // Along r2, the decision for component 1 (r1 fixed) changes for OSPA and UOSPA but never
    // for GOSPA.
    for metric in METRICS {
        let first: Vec<bool> = (0..=100)
            .map(|j| report(&[0.45, j as f64 / 100.0], metric)[0])
            .collect();
        let changes = first.windows(2).filter(|w| w[0] != w[1]).count();
        match metric {
            SetMetric::Gospa { .. } => assert_eq!(changes, 0),
            _ => assert!(changes > 0, "{metric:?} shows no spooky effect"),
        }
    }
}

#[test]
fn example5_madrid_and_liverpool() {
    // Before: r = (0.4, 0.4): OSPA reports both.
    assert_eq!(report(&[0.4, 0.4], SetMetric::Ospa), vec![true, true]);
    // Case 1: Liverpool's r rises to 0.9; OSPA drops Madrid.
    assert_eq!(report(&[0.4, 0.9], SetMetric::Ospa), vec![false, true]);
    // Case 2: Liverpool's r falls to 0.1; OSPA reports nothing.
    assert_eq!(report(&[0.4, 0.1], SetMetric::Ospa), vec![false, false]);
    // The mean square errors behind those decisions (hand-derived, see the unit tests).
    let mse =
        |r2: f64, u: [bool; 2]| mean_error(&[0.4, r2], &u, SetMetric::Ospa, 1.0, 2.0).unwrap();
    assert!((mse(0.9, [true, true]) - 0.35).abs() < 1e-14);
    assert!((mse(0.9, [false, true]) - 0.28).abs() < 1e-14);
    assert!((mse(0.1, [false, false]) - 0.46).abs() < 1e-14);
    // GOSPA is unmoved by Liverpool: Madrid (0.4) is never reported.
    for r2 in [0.1, 0.4, 0.9] {
        assert!(!report(&[0.4, r2], SetMetric::GOSPA)[0]);
    }
}

#[test]
fn eq11_all_or_nothing_for_many_identical_components() {
    for r in [0.005, 0.01, 0.05, 0.2, 0.35, 0.5, 0.7] {
        for n in (1..=120).chain([300, 1000]) {
            let k = count(&report(&vec![r; n], SetMetric::Ospa));
            let expected = if (1.0 - r).powi(n as i32) < r { n } else { 0 };
            assert_eq!(k, expected, "r={r} n={n}");
        }
    }
}

#[test]
fn fig3_uospa_reports_the_r_quantile_and_moves_one_by_one() {
    // For identical components, E[max(N, k)] − k r changes by P(N ≤ k) − r from k to k + 1, so
    // the optimal UOSPA count is the smallest k with P(N ≤ k) > r (a quantile of Bin(n, r)).
    for r in [0.2, 0.4, 0.6, 0.8] {
        let mut previous = 0usize;
        for n in 1..=80 {
            let rs = vec![r; n];
            let k = count(&report(&rs, SetMetric::Uospa));
            let pmf = multi_bernoulli_cardinality(&rs).unwrap();
            let mut cdf = 0.0;
            let quantile = pmf
                .iter()
                .position(|p| {
                    cdf += p;
                    cdf > r + 1e-12
                })
                .unwrap();
            assert_eq!(k, quantile, "r={r} n={n}");
            assert!(
                k.abs_diff(previous) <= 1,
                "UOSPA adds or drops one at a time"
            );
            previous = k;
            // GOSPA reports all or nothing by r alone; the MAP-cardinality count is the mode.
            assert_eq!(
                count(&report(&rs, SetMetric::GOSPA)),
                if r > 0.5 { n } else { 0 }
            );
            let mode = (0..pmf.len()).fold(0, |b, i| if pmf[i] > pmf[b] { i } else { b });
            assert_eq!(count(&map_cardinality_estimate(&rs).unwrap()), mode);
        }
    }
    // r > 1/2: UOSPA leaves some targets out for large n (the paper: one at n = 4 … for r = 0.6
    // it drops one at a time).
    let k = count(&report(&vec![0.6; 60], SetMetric::Uospa));
    assert!(k < 60 && k > 30);
}

// ------------------------------------------------------------ Fig. 2 against the density

const EPS: f64 = 1e-4; // covariance εI, σ = 0.01
const M: [f64; 2] = [0.0, 50.0];

fn normal(x: f64, m: f64) -> f64 {
    (-(x - m) * (x - m) / (2.0 * EPS)).exp() / (2.0 * std::f64::consts::PI * EPS).sqrt()
}

/// Grid points around both means (and between them, coarsely).
fn grid() -> Vec<f64> {
    let mut g: Vec<f64> = (-2000..=2000).map(|i| i as f64 * 2.5e-5).collect();
    g.extend((-2000..=2000).map(|i| 50.0 + i as f64 * 2.5e-5));
    g.extend((1..50).map(|i| i as f64));
    g
}

/// The set the joint multi-object estimator picks by maximising f(X) c^|X| / |X|! over grids
/// of one- and two-point sets, c = (2πε)^(1/2).
fn jom_by_grid(r1: f64, r2: f64, g: &[f64]) -> Vec<bool> {
    let c = (2.0 * std::f64::consts::PI * EPS).sqrt();
    let empty = (1.0 - r1) * (1.0 - r2);
    let (mut best_one, mut at) = (0.0f64, 0.0);
    for &x in g {
        let f = r1 * (1.0 - r2) * normal(x, M[0]) + (1.0 - r1) * r2 * normal(x, M[1]);
        if f > best_one {
            (best_one, at) = (f, x);
        }
    }
    let one = best_one * c;
    // two points: one near each mean is the maximiser (both near one mean is exponentially
    // smaller); maximise each coordinate on its own grid.
    let near = |m: f64| (-50..=50).map(move |i| m + i as f64 * 1e-3);
    let mut best_two = 0.0f64;
    for x1 in near(M[0]) {
        for x2 in near(M[1]) {
            let f = r1
                * r2
                * (normal(x1, M[0]) * normal(x2, M[1]) + normal(x1, M[1]) * normal(x2, M[0]));
            best_two = best_two.max(f);
        }
    }
    let two = best_two * c * c / 2.0;
    if empty >= one && empty >= two {
        vec![false, false]
    } else if one >= two {
        vec![(at - M[0]).abs() < 1.0, (at - M[1]).abs() < 1.0]
    } else {
        vec![true, true]
    }
}

/// The marginal multi-object estimate: MAP cardinality, then the maximiser of the n̂-object
/// density on the grid.
fn mam_by_grid(r1: f64, r2: f64, g: &[f64]) -> Vec<bool> {
    let rho = [
        (1.0 - r1) * (1.0 - r2),
        r1 * (1.0 - r2) + (1.0 - r1) * r2,
        r1 * r2,
    ];
    let n_hat = (0..3).fold(0, |b, i| if rho[i] > rho[b] { i } else { b });
    match n_hat {
        0 => vec![false, false],
        2 => vec![true, true],
        _ => {
            let f = |x: f64| r1 * (1.0 - r2) * normal(x, M[0]) + (1.0 - r1) * r2 * normal(x, M[1]);
            let at = g
                .iter()
                .copied()
                .fold(g[0], |b, x| if f(x) > f(b) { x } else { b });
            vec![(at - M[0]).abs() < 1.0, (at - M[1]).abs() < 1.0]
        }
    }
}

#[test]
fn fig2_decision_rules_match_a_direct_maximisation() {
    let g = grid();
    let mut checked = 0;
    for i in 1..20 {
        for j in 1..20 {
            let (r1, r2) = (i as f64 / 20.0 - 0.013, j as f64 / 20.0 + 0.007);
            // JoM with c = (2πε)^(d/2): ln_peak + ln c = 0 for every component.
            let jom = jom_estimate(&[r1, r2], &[0.0, 0.0], 0.0).unwrap();
            assert_eq!(jom, jom_by_grid(r1, r2, &g), "JoM at ({r1}, {r2})");
            let lp = fisst::estimators::alternatives::isotropic_ln_peak(EPS, 1);
            let mam = mam_estimate(&[r1, r2], &[lp, lp]).unwrap();
            assert_eq!(mam, mam_by_grid(r1, r2, &g), "MaM at ({r1}, {r2})");
            checked += 1;
        }
    }
    assert_eq!(checked, 361);
}

#[test]
fn fig2_estimators_are_spooky_too() {
    // JoM: target 1 at r1 = 0.6 is reported alone, but not once a far-away r2 = 0.65 appears
    // (then only the more probable one is: Π(1 − r) Π r / |I|! favours {2} over {1, 2}).
    let lp = [0.0, 0.0];
    assert_eq!(
        jom_estimate(&[0.6, 0.0], &lp, 0.0).unwrap(),
        vec![true, false]
    );
    assert_eq!(
        jom_estimate(&[0.6, 0.65], &lp, 0.0).unwrap(),
        vec![false, true]
    );
    // MAP cardinality: r = (0.45, 0.45) has ρ(1) = 0.495 the mode, so one target is reported
    // although each has r < 1/2.
    assert_eq!(
        map_cardinality_estimate(&[0.45, 0.45]).unwrap(),
        vec![true, false]
    );
}
