//! Tests of Theorem 2 (22)–(26) of paper 002: the n = 2 cubature against the Monte Carlo and a
//! brute grid sum, the methods reported per cardinality, and the series' cut and η2 bracket.

use super::cubature::{outer_breakpoints, quadrature2, section};
use super::monte_carlo::{Table, monte_carlo};
use super::*;
use crate::bounds::model::{Density1, Detection, LinearGaussian};
use crate::math::rng::seeded;
use core::f64::consts::PI;

struct Case {
    prior: Density1,
    obs: LinearGaussian,
    clutter: Density1,
}

fn case(p: f64, clutter: Density1) -> Case {
    Case {
        prior: Density1::gaussian(1.0, 4.0).unwrap(),
        obs: LinearGaussian::new(Detection::constant(p).unwrap(), 1.0, 0.0, 1.0).unwrap(),
        clutter,
    }
}

fn model<'a>(c: &'a Case, r: f64, lambda: f64) -> ModelII<'a> {
    ModelII {
        existence: r,
        prior: &c.prior,
        observation: &c.obs,
        clutter_rate: lambda,
        clutter_density: &c.clutter,
        false_alarm_error: 6.0,
        miss_error: 9.0,
    }
}

/// The n = 2 Monte Carlo of the same three quantities, with its m table.
fn mc2(m: &ModelII<'_>, p: f64, samples: usize, seed: u64) -> Term {
    let table = Table::marginal(m, p, 1e-10);
    let map = MapTest { r: m.existence, p };
    monte_carlo(m, &table, p, 2, samples, &mut seeded(seed), map).unwrap()
}

/// A_1/w_1, the n = 1 information per unit of detected mass Theorem 2 scales the cubature's
/// A_2 by.
fn a1(m: &ModelII<'_>, p: f64) -> f64 {
    let zone = map_region(m, p, measurement_range(m), 1e-10);
    let (term, a1) = single_point(m, p, &zone, 1e-10);
    information_scale(term.w, a1)
}

#[test]
fn thm2_n2_cubature_agrees_with_monte_carlo() {
    for (r, p, lambda, clutter) in [
        (0.6, 0.8, 1.0, Density1::uniform(-10.0, 10.0).unwrap()),
        (0.3, 0.9, 2.0, Density1::uniform(-10.0, 10.0).unwrap()),
        (0.5, 0.7, 0.5, Density1::gaussian(0.0, 9.0).unwrap()),
    ] {
        let c = case(p, clutter);
        let m = model(&c, r, lambda);
        let q = quadrature2(&m, p, a1(&m, p), measurement_range(&m), 1e-10, false);
        let mc = mc2(&m, p, 200_000, 7);
        std::println!(
            "r {r} P {p} λ {lambda}: w {:.6}±{:.1e} vs {:.6}±{:.1e}; J'^-1 {:.6}±{:.1e} vs {:.6}±{:.1e}; null {:.6}±{:.1e} vs {:.6}±{:.1e}",
            q.w,
            q.ew,
            mc.w,
            mc.ew,
            q.s,
            q.es,
            mc.s,
            mc.es,
            q.null,
            q.enull,
            mc.null,
            mc.enull
        );
        for (a, ea, b, eb, what) in [
            (q.w, q.ew, mc.w, mc.ew, "w2"),
            (q.s, q.es, mc.s, mc.es, "J'2^-1"),
            (q.null, q.enull, mc.null, mc.enull, "null2"),
        ] {
            assert!(ea < 1e-4 * a.max(1e-2), "{what}: quadrature error {ea}");
            assert!(
                fns::abs(a - b) <= 4.0 * eb + ea + 1e-12,
                "{what}: quadrature {a} vs Monte Carlo {b} ± {eb}"
            );
        }
    }
}

/// w_2 and null_2 by a brute midpoint sum over a 1500 × 1500 grid of Z² (m by quadrature
/// at the grid's nodes, the MAP indicator evaluated cell by cell).
#[test]
fn thm2_n2_cubature_agrees_with_a_fine_grid_sum() {
    let (r, p, lambda) = (0.6, 0.8, 1.0);
    let c = case(p, Density1::uniform(-10.0, 10.0).unwrap());
    let m = model(&c, r, lambda);
    let (zl, zh) = measurement_range(&m);
    let q = quadrature2(&m, p, a1(&m, p), (zl, zh), 1e-10, false);
    let n = 1500;
    let h1 = (zh - zl) / n as f64;
    let z1: Vec<f64> = (0..n).map(|i| zl + h1 * (i as f64 + 0.5)).collect();
    let m1: Vec<f64> = z1
        .iter()
        .map(|&z| marginal(m.prior, m.observation, p, z, 1e-10))
        .collect();
    let v1: Vec<f64> = z1.iter().map(|&z| lambda * c.clutter.pdf(z)).collect();
    let (cl, ch) = (-10.0, 10.0);
    let h2 = (ch - cl) / n as f64;
    let k0 = (1.0 - r) - r * (1.0 - p);
    let (mut w, mut null) = (0.0, 0.0);
    for j in 0..n {
        let z2 = cl + h2 * (j as f64 + 0.5);
        let c2 = c.clutter.pdf(z2);
        let b2 = marginal(m.prior, m.observation, p, z2, 1e-10) / (lambda * c2);
        for i in 0..n {
            let declared = v1[i] <= 0.0 || r * p * (m1[i] / v1[i] + b2) >= k0;
            if declared {
                w += c2 * m1[i] * h1 * h2;
            } else {
                null += c2 * (v1[i] / lambda) * h1 * h2;
            }
        }
    }
    std::println!(
        "grid: w {w:.6} null {null:.6}; quadrature w {:.6} null {:.6}",
        q.w,
        q.null
    );
    assert!(
        fns::abs(w - q.w) < 2e-3,
        "w2: grid {w} vs quadrature {}",
        q.w
    );
    assert!(
        fns::abs(null - q.null) < 2e-3,
        "null2: grid {null} vs quadrature {}",
        q.null
    );
}

/// The outer breakpoints of the n = 2 cubature with uniform clutter on [cl, ch] and
/// m = N(1, 5): β_1 = r P̄o m/v has its maximum at 1 and its other critical values at cl and
/// ch, so R(z_2) changes form where β_1(z_2) = k0 − b, b ∈ {0, β_1(1), β_1(cl), β_1(ch)}, at
/// z_2 = 1 ± (−10 ln((k0 − b) v √(10π)/(r P̄o)))^{1/2}; the breakpoints are the 8 equal
/// pieces' nodes and exactly these, for a model where the section appears inside (r 0.3) and
/// one where it is the whole range near the middle (r 0.6).
#[test]
fn thm2_n2_outer_breakpoints_are_where_the_section_changes_form() {
    for (r, p, lambda) in [(0.6, 0.8, 1.0), (0.3, 0.9, 2.0)] {
        let (cl, ch) = (-10.0, 10.0);
        let c = case(p, Density1::uniform(cl, ch).unwrap());
        let m = model(&c, r, lambda);
        let pts = outer_breakpoints(&m, p, measurement_range(&m));
        let (rp, k0, v) = (r * p, (1.0 - r) - r * (1.0 - p), lambda / (ch - cl));
        let beta =
            |z: f64| rp * fns::exp(-0.1 * (z - 1.0) * (z - 1.0)) / (fns::sqrt(10.0 * PI) * v);
        let mut expected = Vec::new();
        for b in [0.0, beta(1.0), beta(cl), beta(ch)] {
            let arg = (k0 - b) * v * fns::sqrt(10.0 * PI) / rp;
            if arg > 0.0 && arg < 1.0 {
                let h = fns::sqrt(-10.0 * fns::ln(arg));
                expected.extend([1.0 - h, 1.0 + h].into_iter().filter(|&z| z > cl && z < ch));
            }
        }
        std::println!("r {r}: breakpoints {pts:?}, expected {expected:?}");
        assert!(!expected.is_empty());
        for z in &expected {
            let near = pts
                .iter()
                .map(|q| fns::abs(q - z))
                .fold(f64::INFINITY, f64::min);
            assert!(near < 1e-8, "r {r}: no breakpoint at {z} (nearest {near})");
        }
        assert_eq!(pts.len(), 9 + expected.len(), "r {r}: {pts:?}");
    }
}

/// The section of the MAP region {z_1 : r P̄o m(z_1) ≥ K v(z_1)} just below the top of
/// β_1 = r P̄o m/v, narrower than the scan's cell (clutter U[−60, 49], m = N(1, 5), the peak at 1
/// between two of the scan's nodes): the interval 1 ± (−10 ln(K/β_1(1)))^{1/2}, not empty.
#[test]
fn thm2_n2_a_section_narrower_than_the_scan_is_found() {
    let (r, p, lambda, cl, ch) = (0.6, 0.8, 1.0, -60.0, 49.0);
    let c = case(p, Density1::uniform(cl, ch).unwrap());
    let m = model(&c, r, lambda);
    let range = measurement_range(&m);
    let cell = (range.1 - range.0) / 512.0;
    let t = (1.0 - range.0) / cell;
    assert!(
        fns::abs(t - libm::round(t)) > 0.1,
        "the peak is a node: {t}"
    );
    let top = r * p / (fns::sqrt(10.0 * PI) * lambda / (ch - cl));
    for drop in [1e-6, 1e-4] {
        let k = top * (1.0 - drop);
        let h = fns::sqrt(-10.0 * fns::ln(1.0 - drop));
        assert!(2.0 * h < cell);
        let s = section(&m, p, range, k);
        assert_eq!(s.len(), 1, "drop {drop}: {s:?}");
        assert!(
            fns::abs(s[0].0 - (1.0 - h)) < 1e-8 && fns::abs(s[0].1 - (1.0 + h)) < 1e-8,
            "drop {drop}: {s:?} vs 1 ± {h}"
        );
    }
}

/// (25) in the linear-Gaussian case: the n = 2 terms with the x-integrals in closed form
/// ([`LinearGaussianCase`](super::cubature::LinearGaussianCase)) equal the general nested
/// cubature (forced) to the cubature's error estimates, and the Monte Carlo within four
/// standard errors, for uniform and Gaussian clutter and several r, P_o, λ, a, b, R.
#[test]
fn thm2_n2_closed_form_equals_the_general_cubature() {
    let lg = |p: f64, a: f64, b: f64, r: f64| {
        LinearGaussian::new(Detection::constant(p).unwrap(), a, b, r).unwrap()
    };
    for (r, p, lambda, clutter, obs) in [
        (
            0.6,
            0.8,
            1.0,
            Density1::uniform(-10.0, 10.0).unwrap(),
            lg(0.8, 1.0, 0.0, 1.0),
        ),
        (
            0.3,
            0.9,
            2.0,
            Density1::uniform(-10.0, 10.0).unwrap(),
            lg(0.9, 1.0, 0.0, 1.0),
        ),
        (
            0.5,
            0.7,
            0.5,
            Density1::gaussian(0.0, 9.0).unwrap(),
            lg(0.7, 1.0, 0.0, 1.0),
        ),
        (
            0.8,
            0.95,
            3.0,
            Density1::uniform(-12.0, 14.0).unwrap(),
            lg(0.95, 0.5, 1.0, 2.0),
        ),
        (
            0.45,
            0.6,
            1.5,
            Density1::gaussian(1.0, 25.0).unwrap(),
            lg(0.6, -2.0, 0.5, 0.5),
        ),
    ] {
        let c = Case {
            prior: Density1::gaussian(1.0, 4.0).unwrap(),
            obs,
            clutter,
        };
        let m = model(&c, r, lambda);
        assert!(super::cubature::LinearGaussianCase::of(m.prior, m.observation).is_some());
        let (range, scale) = (measurement_range(&m), a1(&m, p));
        let t0 = std::time::Instant::now();
        let closed = quadrature2(&m, p, scale, range, 1e-10, true);
        let t_closed = t0.elapsed();
        let t0 = std::time::Instant::now();
        let general = quadrature2(&m, p, scale, range, 1e-10, false);
        let t_general = t0.elapsed();
        let mc = mc2(&m, p, 200_000, 11);
        std::println!(
            "r {r} P {p} λ {lambda}: closed {t_closed:?} general {t_general:?}; \
             w {:.9}/{:.9} J'^-1 {:.9}/{:.9} null {:.9}/{:.9}; MC J'^-1 {:.6}±{:.1e}",
            closed.w,
            general.w,
            closed.s,
            general.s,
            closed.null,
            general.null,
            mc.s,
            mc.es
        );
        for (a, ea, b, eb, e_mc, mc_v, what) in [
            (
                closed.w, closed.ew, general.w, general.ew, mc.ew, mc.w, "w2",
            ),
            (
                closed.s, closed.es, general.s, general.es, mc.es, mc.s, "J'2^-1",
            ),
            (
                closed.null,
                closed.enull,
                general.null,
                general.enull,
                mc.enull,
                mc.null,
                "null2",
            ),
        ] {
            assert!(ea < 1e-4 * a.max(1e-2), "{what}: closed-form error {ea}");
            assert!(
                fns::abs(a - b) <= ea + eb + 1e-12,
                "{what}: closed form {a} ± {ea} vs general cubature {b} ± {eb}"
            );
            assert!(
                fns::abs(a - mc_v) <= 4.0 * e_mc + ea + 1e-12,
                "{what}: closed form {a} vs Monte Carlo {mc_v} ± {e_mc}"
            );
        }
    }
}

#[test]
fn thm2_each_cardinality_reports_its_method() {
    let c = case(0.8, Density1::uniform(-10.0, 10.0).unwrap());
    let m = model(&c, 0.6, 1.0);
    let mc = theorem2(
        &m,
        &TheoremOptions {
            quadrature_cardinality: 1,
            ..TheoremOptions::default()
        },
    )
    .unwrap();
    // the default on a linear-Gaussian model: the n = 2 cubature
    let quad = theorem2(&m, &TheoremOptions::default()).unwrap();
    let forced = theorem2(
        &m,
        &TheoremOptions {
            quadrature_cardinality: 2,
            ..TheoremOptions::default()
        },
    )
    .unwrap();
    assert_eq!(quad, forced);
    let s = TheoremOptions::default();
    assert_eq!(s.quadrature_cardinality_for(true), 2);
    assert_eq!(s.quadrature_cardinality_for(false), 1);
    let methods = |b: &JdeBound| b.cardinalities.iter().map(|c| c.method).collect::<Vec<_>>();
    let (a, b) = (methods(&mc), methods(&quad));
    assert!(a.len() > 3 && a.len() == b.len());
    assert_eq!(&a[..2], &[Method::Quadrature, Method::MonteCarlo]);
    assert_eq!(
        &b[..3],
        &[Method::Quadrature, Method::Quadrature, Method::MonteCarlo]
    );
    assert!(
        a[2..]
            .iter()
            .chain(&b[2..])
            .all(|&m| m == Method::MonteCarlo)
    );
    let (x, y) = (&mc.cardinalities[1], &quad.cardinalities[1]);
    assert!(fns::abs(x.inverse_information - y.inverse_information) <= 4.0 * x.error + y.error);
    let d = fns::abs(mc.assembled.bound - quad.assembled.bound);
    assert!(
        d <= 4.0 * (mc.error + quad.error),
        "{d} vs {} {}",
        mc.error,
        quad.error
    );
}

/// (23): the series is cut at the first N whose tail Σ_{k>N} C_k is below the tolerance, or
/// at `max_clutter`.
#[test]
fn thm2_series_is_cut_where_its_tail_is_below_the_tolerance() {
    let s = TheoremOptions::default();
    for lambda in [0.0, 0.5, 3.0, 10.0] {
        let (last, kept) = series::truncation(lambda, &s);
        assert!(
            1.0 - kept <= s.series_tolerance,
            "λ {lambda}: tail {}",
            1.0 - kept
        );
        if last > 0 {
            let before = kept - poisson_pmf(lambda, last);
            assert!(1.0 - before > s.series_tolerance, "λ {lambda}: cut late");
        }
    }
    assert_eq!(series::truncation(0.0, &s), (0, 1.0));
    let capped = TheoremOptions {
        max_clutter: 3,
        ..TheoremOptions::default()
    };
    assert_eq!(series::truncation(20.0, &capped).0, 3);
}

/// (23)–(24): η2's bracket holds its lower end and the cut tail (capped at 1); the bound is
/// assembled at both ends and the smaller is returned with its η.
#[test]
fn thm2_eta_bracket_takes_the_smaller_bound() {
    let c = case(0.8, Density1::uniform(-10.0, 10.0).unwrap());
    let m = model(&c, 0.6, 1.0);
    let b = theorem2(
        &m,
        &TheoremOptions {
            samples: 2000,
            max_clutter: 2,
            ..TheoremOptions::default()
        },
    )
    .unwrap();
    let bracket = EtaBracket::new(1.0, &b.cardinalities);
    let covered: f64 = (0..=3).map(|n| poisson_pmf(1.0, n)).sum();
    assert!(bracket.lo <= bracket.hi && bracket.hi <= 1.0);
    assert!(fns::abs(bracket.hi - bracket.lo - (1.0 - covered)) < 1e-12);
    assert!(b.eta == bracket.lo || b.eta == bracket.hi);
    let ingredients = |eta: f64| Ingredients {
        existence: 0.6,
        mean_detection: b.mean_detection,
        undetected_variance: b.undetected_variance,
        inverse_information: 1.0,
        detected_mass: 0.5,
        absent_empty: fns::exp(-1.0),
        absent_null: eta,
        undetected_empty: fns::exp(-1.0),
        undetected_null: eta,
        false_alarm_error: 6.0,
        miss_error: 9.0,
    };
    let (got, eta) = bracket.assemble(ingredients);
    let lo = crate::bounds::closed::assemble(&ingredients(bracket.lo)).bound;
    let hi = crate::bounds::closed::assemble(&ingredients(bracket.hi)).bound;
    assert_eq!(got.bound, lo.min(hi));
    assert_eq!(eta, if hi < lo { bracket.hi } else { bracket.lo });
    let exact = EtaBracket::exact(0.25);
    assert_eq!((exact.lo, exact.hi, exact.error), (0.25, 0.25, 0.0));
}

/// E σ'(u), u ~ N(μ, s²), by the sinh-mapped trapezoidal rule against adaptive G10/K21.
#[test]
fn thm2_logistic_normal_agrees_with_adaptive_quadrature() {
    use super::cubature::{logistic_normal, logistic_normal_adaptive};
    let mut worst: f64 = 0.0;
    for mu in [0.0, 0.3, 1.0, 2.0, 5.0, 10.0, 20.0, 35.0, -3.0, -15.0] {
        for s in [1e-6, 0.01, 0.1, 0.5, 1.0, 2.0, 5.0, 10.0, 20.0, 40.0] {
            let a = logistic_normal(mu, s, 1e-12);
            let b = logistic_normal_adaptive(mu, s, 1e-15);
            let e = fns::abs(a - b);
            std::println!("mu {mu} s {s}: {a:.12e} vs {b:.12e} diff {e:.1e}");
            worst = worst.max(e / 1e-12f64.max(1e-3 * b));
        }
    }
    assert!(worst <= 1.0, "worst {worst}");
}

/// m(z) in the linear-Gaussian case is the closed form N(z; a μ + b, a² P + R) (the m of
/// Lemma 1's β, paper 002): equal to the quadrature of ∫ f P_o g dx / P̄o to 1e-9 of its peak,
/// for several a, b, R, μ, P and z across ±8 standard deviations of m.
#[test]
fn thm2_marginal_in_closed_form_equals_its_quadrature() {
    for (mu, var, p, a, b, r) in [
        (1.0, 4.0, 0.8, 1.0, 0.0, 1.0),
        (-2.0, 0.5, 0.6, -2.0, 0.5, 0.5),
        (0.5, 9.0, 1.0, 0.5, 1.0, 2.0),
    ] {
        let prior = Density1::gaussian(mu, var).unwrap();
        let obs = LinearGaussian::new(Detection::constant(p).unwrap(), a, b, r).unwrap();
        let (mean, sd) = (a * mu + b, fns::sqrt(a * a * var + r));
        let peak = 1.0 / (sd * fns::sqrt(2.0 * PI));
        for i in 0..=32 {
            let z = mean + sd * (-8.0 + 0.5 * i as f64);
            let closed = marginal(&prior, &obs, p, z, 1e-10);
            let (xl, xh) = prior.support();
            let (quad, _) = crate::bounds::theorem::integrate(
                &mut |x| prior.pdf(x) * obs.detection(x) * obs.likelihood(z, x),
                xl,
                xh,
                1e-12,
            );
            let quad = quad / p;
            assert!(
                fns::abs(closed - quad) <= 1e-9 * peak,
                "μ {mu} P {var} a {a} b {b} R {r} z {z}: closed {closed} vs quadrature {quad}"
            );
        }
    }
}
