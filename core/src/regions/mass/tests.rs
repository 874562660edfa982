//! Region masses ⟨1_S, N(m, P)⟩ (eq. (8) of `001_…`, whose indicator 1_S is also checked) against
//! closed forms, independent quadratures and Monte Carlo.

use super::*;
use crate::gaussian::normal;
use rand::{RngExt, SeedableRng, rngs::SmallRng};
use std::f64::consts::PI;

fn gauss(mean: &[f64], cov: &[f64]) -> Gaussian {
    Gaussian::from_slices(mean, cov, "p").unwrap()
}

fn random_gauss2(rng: &mut SmallRng) -> Gaussian {
    let sx: f64 = rng.random_range(0.2..2.0);
    let sy: f64 = rng.random_range(0.2..2.0);
    let r: f64 = rng.random_range(-0.97..0.97);
    gauss(
        &[rng.random_range(-1.0..1.0), rng.random_range(-1.0..1.0)],
        &[sx * sx, r * sx * sy, r * sx * sy, sy * sy],
    )
}

/// The "slab" oracle for a 2D region: whiten, condition on z₀, and integrate
/// φ(z₀)·P(z₁ ∈ slice) over z₀ with the exact inner Φ differences. `slice(t)` gives the
/// sorted s₁-intervals of the region at s₀ = t; `breaks` the s₀ values where it changes.
fn slab_oracle(g: &Gaussian, slice: impl Fn(f64) -> Vec<(f64, f64)>, breaks: &[f64]) -> f64 {
    let l = g.chol();
    let (m0, m1) = (g.mean()[0], g.mean()[1]);
    let (l00, l10, l11) = (l[(0, 0)], l[(1, 0)], l[(1, 1)]);
    let mut pts: Vec<f64> = breaks
        .iter()
        .map(|t| (t - m0) / l00)
        .filter(|z| z.abs() < 9.0)
        .collect();
    pts.extend([-9.0, 9.0]);
    pts.sort_by(f64::total_cmp);
    let q = integrate_smooth_ends(
        |z| {
            let t = m0 + l00 * z;
            let c = m1 + l10 * z;
            let inner: f64 = slice(t)
                .iter()
                .map(|&(a, b)| normal::interval((a - c) / l11, (b - c) / l11))
                .sum();
            normal::pdf(z) * inner
        },
        &pts,
        1e-15,
        20_000,
    );
    q.value
}

/// The s₁-intervals of a polygon at s₀ = t (even–odd rule).
fn polygon_slice(v: &[[f64; 2]], t: f64) -> Vec<(f64, f64)> {
    let mut ys = Vec::new();
    for i in 0..v.len() {
        let (a, b) = (v[i], v[(i + 1) % v.len()]);
        if (a[0] > t) != (b[0] > t) {
            ys.push(a[1] + (t - a[0]) * (b[1] - a[1]) / (b[0] - a[0]));
        }
    }
    ys.sort_by(f64::total_cmp);
    ys.chunks(2)
        .filter(|c| c.len() == 2)
        .map(|c| (c[0], c[1]))
        .collect()
}

/// Monte Carlo estimate of P(s ∈ S) and its standard error.
fn monte_carlo(region: &Region, g: &Gaussian, n: usize, seed: u64) -> (f64, f64) {
    let mut rng = SmallRng::seed_from_u64(seed);
    let mut hits = 0usize;
    for _ in 0..n {
        let x = g.sample(&mut rng);
        if region.contains(x.as_slice()) {
            hits += 1;
        }
    }
    let p = hits as f64 / n as f64;
    (p, (p * (1.0 - p) / n as f64).sqrt().max(1.0 / n as f64))
}

#[test]
fn eq8_box_2d_is_the_bivariate_rectangle_and_the_ray_method_agrees() {
    let mut rng = SmallRng::seed_from_u64(21);
    for _ in 0..60 {
        let g = random_gauss2(&mut rng);
        let x0 = rng.random_range(-2.0..1.0);
        let y0 = rng.random_range(-2.0..1.0);
        let (w, h) = (rng.random_range(0.1..3.0), rng.random_range(0.1..3.0));
        let bx = Region::axis_box(&[x0, y0], &[x0 + w, y0 + h], "fov").unwrap();
        let exact = bx.gaussian_mass(&g, "p").unwrap();
        // The same box as a polygon goes through the ray method.
        let poly = Region::polygon(
            &[[x0, y0], [x0 + w, y0], [x0 + w, y0 + h], [x0, y0 + h]],
            "fov",
        )
        .unwrap();
        let ray = poly.gaussian_mass(&g, "p").unwrap();
        assert!(
            (exact.value - ray.value).abs() < 1e-13,
            "{} vs {} ({:e})",
            exact.value,
            ray.value,
            exact.value - ray.value
        );
        assert!(ray.error < 1e-12);
        // and through the slab oracle
        let slab = slab_oracle(
            &g,
            |t| {
                if (x0..=x0 + w).contains(&t) {
                    vec![(y0, y0 + h)]
                } else {
                    vec![]
                }
            },
            &[x0, x0 + w],
        );
        assert!((exact.value - slab).abs() < 1e-13);
    }
}

#[test]
fn eq8_discs_match_closed_forms() {
    // Centred on the mean of σ²I: 1 − exp(−r²/2σ²).
    for (sigma, r) in [(1.0, 1.0), (0.3, 0.1), (2.0, 5.0), (1.0, 1e-3), (0.5, 4.0)] {
        let g = gauss(&[0.5, -0.25], &[sigma * sigma, 0.0, 0.0, sigma * sigma]);
        let d = Region::ball(&[0.5, -0.25], r, "fov").unwrap();
        let m = d.gaussian_mass(&g, "p").unwrap();
        let want = -(-(r * r) / (2.0 * sigma * sigma)).exp_m1();
        assert!(
            (m.value - want).abs() < 1e-13,
            "σ={sigma} r={r}: {m:?} vs {want}"
        );
    }
    // Off-centre under N(0, I): the noncentral χ²₂ distribution function, a Poisson mixture
    // of central χ²'s: P = Σ_j e^{−λ/2} (λ/2)^j / j! · P(χ²_{2+2j} ≤ r²), λ = |c|².
    for (c, r) in [
        ([1.0, 0.5], 1.0),
        ([3.0, 0.0], 1.0),
        ([0.2, -0.1], 2.0),
        ([4.0, 3.0], 2.5),
    ] {
        let g = gauss(&[0.0, 0.0], &[1.0, 0.0, 0.0, 1.0]);
        let d = Region::ball(&c, r, "fov").unwrap();
        let m = d.gaussian_mass(&g, "p").unwrap();
        let lam: f64 = c[0] * c[0] + c[1] * c[1];
        let x = r * r / 2.0;
        let mut want = 0.0;
        let mut pois = (-lam / 2.0).exp();
        for j in 0..200 {
            // P(χ²_{2k} ≤ 2x) = 1 − e^{−x} Σ_{i<k} x^i/i!, k = j + 1
            let mut term = 1.0;
            let mut s = 0.0;
            for i in 0..=j {
                if i > 0 {
                    term *= x / i as f64;
                }
                s += term;
            }
            want += pois * (1.0 - (-x).exp() * s);
            pois *= lam / 2.0 / (j as f64 + 1.0);
        }
        assert!(
            (m.value - want).abs() < 1e-13,
            "c={c:?} r={r}: {} vs {want}",
            m.value
        );
    }
}

#[test]
fn eq8_discs_and_polygons_match_the_slab_oracle_and_monte_carlo() {
    let mut rng = SmallRng::seed_from_u64(22);
    for trial in 0..25 {
        let g = random_gauss2(&mut rng);
        // disc
        let c = [rng.random_range(-2.0..2.0), rng.random_range(-2.0..2.0)];
        let r: f64 = rng.random_range(0.1..2.5);
        let disc = Region::ball(&c, r, "fov").unwrap();
        let m = disc.gaussian_mass(&g, "p").unwrap();
        let slab = slab_oracle(
            &g,
            |t| {
                let d = r * r - (t - c[0]) * (t - c[0]);
                if d > 0.0 {
                    vec![(c[1] - d.sqrt(), c[1] + d.sqrt())]
                } else {
                    vec![]
                }
            },
            &[c[0] - r, c[0] + r],
        );
        assert!(
            (m.value - slab).abs() < 1e-12,
            "disc {trial}: {} vs {slab}",
            m.value
        );
        // a random non-convex polygon: a star-shaped one around a random centre
        let k = rng.random_range(3..9);
        let centre = [rng.random_range(-1.0..1.0), rng.random_range(-1.0..1.0)];
        let mut angles: Vec<f64> = (0..k).map(|_| rng.random_range(0.0..2.0 * PI)).collect();
        angles.sort_by(f64::total_cmp);
        let v: Vec<[f64; 2]> = angles
            .iter()
            .map(|a| {
                let rr = rng.random_range(0.2..2.5);
                [centre[0] + rr * a.cos(), centre[1] + rr * a.sin()]
            })
            .collect();
        let Ok(poly) = Region::polygon(&v, "fov") else {
            continue;
        };
        let m = poly.gaussian_mass(&g, "p").unwrap();
        let xs: Vec<f64> = v.iter().map(|p| p[0]).collect();
        let slab = slab_oracle(&g, |t| polygon_slice(&v, t), &xs);
        assert!(
            (m.value - slab).abs() < 1e-12,
            "polygon {trial}: {} vs {slab}",
            m.value
        );
        if trial < 4 {
            let (mc, se) = monte_carlo(&poly, &g, 200_000, 100 + trial);
            assert!(
                (m.value - mc).abs() < 5.0 * se,
                "MC {mc} ± {se} vs {}",
                m.value
            );
            let (mc, se) = monte_carlo(&disc, &g, 200_000, 200 + trial);
            let md = disc.gaussian_mass(&g, "p").unwrap().value;
            assert!((md - mc).abs() < 5.0 * se, "MC {mc} ± {se} vs {md}");
        }
    }
}

#[test]
fn eq8_self_intersecting_polygons_follow_the_even_odd_rule() {
    // A bow tie = two triangles meeting at (1, 1); a pentagram's centre pentagon is outside.
    let g = gauss(&[1.0, 1.2], &[0.7, 0.2, 0.2, 0.5]);
    let bow = [[0.0, 0.0], [2.0, 2.0], [2.0, 0.0], [0.0, 2.0]];
    let m = Region::polygon(&bow, "fov")
        .unwrap()
        .gaussian_mass(&g, "p")
        .unwrap();
    let left = Region::polygon(&[[0.0, 0.0], [1.0, 1.0], [0.0, 2.0]], "fov").unwrap();
    let right = Region::polygon(&[[2.0, 0.0], [2.0, 2.0], [1.0, 1.0]], "fov").unwrap();
    let parts =
        left.gaussian_mass(&g, "p").unwrap().value + right.gaussian_mass(&g, "p").unwrap().value;
    assert!((m.value - parts).abs() < 1e-13, "{} vs {parts}", m.value);
    let star: Vec<[f64; 2]> = (0..5)
        .map(|i| {
            let a = PI / 2.0 + 4.0 * PI * i as f64 / 5.0;
            [a.cos(), a.sin()]
        })
        .collect();
    let star = Region::polygon(&star, "fov").unwrap();
    assert!(!star.contains(&[0.0, 0.0]));
    let g = gauss(&[0.1, -0.05], &[0.3, 0.05, 0.05, 0.2]);
    let m = star.gaussian_mass(&g, "p").unwrap();
    let (mc, se) = monte_carlo(&star, &g, 400_000, 9);
    assert!(
        (m.value - mc).abs() < 5.0 * se,
        "{} vs {mc} ± {se}",
        m.value
    );
}

#[test]
fn eq8_unions_intersections_and_complements() {
    let mut rng = SmallRng::seed_from_u64(23);
    for _ in 0..20 {
        let g = random_gauss2(&mut rng);
        let a = Region::axis_box(&[-1.0, -0.5], &[0.6, 1.0], "a").unwrap();
        let b = Region::axis_box(&[0.1, -1.2], &[1.5, 0.3], "b").unwrap();
        let ab = Region::axis_box(&[0.1, -0.5], &[0.6, 0.3], "ab").unwrap();
        let mass = |r: &Region| r.gaussian_mass(&g, "p").unwrap().value;
        let union = Region::union(vec![a.clone(), b.clone()], "u").unwrap();
        let want = mass(&a) + mass(&b) - mass(&ab);
        assert!((mass(&union) - want).abs() < 1e-13);
        let inter = Region::intersection(vec![a.clone(), b.clone()], "i").unwrap();
        assert!((mass(&inter) - mass(&ab)).abs() < 1e-13);
        let comp = Region::complement(union.clone());
        assert!((mass(&comp) + want - 1.0).abs() < 1e-13);
        // a box minus a disc, and a disc minus a box, add up to the symmetric difference
        let disc = Region::ball(&[0.3, 0.2], 0.8, "d").unwrap();
        let a_minus_d =
            Region::intersection(vec![a.clone(), Region::complement(disc.clone())], "x").unwrap();
        let a_and_d = Region::intersection(vec![a.clone(), disc.clone()], "x").unwrap();
        assert!((mass(&a_minus_d) + mass(&a_and_d) - mass(&a)).abs() < 1e-12);
        let u = Region::union(vec![a.clone(), disc.clone()], "x").unwrap();
        assert!((mass(&u) - (mass(&a) + mass(&disc) - mass(&a_and_d))).abs() < 1e-12);
        let (mc, se) = monte_carlo(&a_minus_d, &g, 100_000, 5);
        assert!((mass(&a_minus_d) - mc).abs() < 5.0 * se);
    }
}

#[test]
fn eq8_one_dimensional_regions_are_exact() {
    let g = gauss(&[0.3], &[4.0]);
    let a = Region::axis_box(&[-1.0], &[0.5], "a").unwrap();
    let b = Region::ball(&[1.0], 1.5, "b").unwrap(); // [−0.5, 2.5]
    let u = Region::union(vec![a, b], "u").unwrap(); // [−1, 2.5]
    let m = u.gaussian_mass(&g, "p").unwrap().value;
    let want = normal::cdf((2.5 - 0.3) / 2.0) - normal::cdf((-1.0 - 0.3) / 2.0);
    assert!((m - want).abs() < 1e-16);
    let c = Region::complement(u);
    assert!((c.gaussian_mass(&g, "p").unwrap().value - (1.0 - want)).abs() < 1e-15);
}

#[test]
fn eq8_higher_dimensions_against_closed_forms() {
    // The positive orthant of a correlated trivariate normal:
    // 1/8 + (asin ρ₁₂ + asin ρ₁₃ + asin ρ₂₃)/(4π).
    let (r12, r13, r23) = (0.3f64, -0.4f64, 0.5f64);
    let g = gauss(&[0.0; 3], &[1.0, r12, r13, r12, 1.0, r23, r13, r23, 1.0]);
    let inf = f64::INFINITY;
    let orthant = Region::axis_box(&[0.0; 3], &[inf; 3], "o").unwrap();
    let m = orthant.gaussian_mass(&g, "p").unwrap();
    let want = 0.125 + (r12.asin() + r13.asin() + r23.asin()) / (4.0 * PI);
    assert!((m.value - want).abs() < 1e-12, "{m:?} vs {want}");
    assert!(m.error < 1e-11);
    // A ball centred on the mean of N(0, σ²I₃): P(χ²₃ ≤ r²/σ²).
    let s = 0.7;
    let g = gauss(
        &[1.0, 2.0, 3.0],
        &[s * s, 0.0, 0.0, 0.0, s * s, 0.0, 0.0, 0.0, s * s],
    );
    let ball = Region::ball(&[1.0, 2.0, 3.0], 1.1, "b").unwrap();
    let m = ball.gaussian_mass(&g, "p").unwrap();
    let x = 1.1 / s;
    let want = libm::erf(x / 2f64.sqrt()) - (2.0 / PI).sqrt() * x * (-x * x / 2.0).exp();
    assert!((m.value - want).abs() < 1e-11, "{m:?} vs {want}");
    // A correlated 3D box and ball against Monte Carlo.
    let g = gauss(
        &[0.2, -0.1, 0.4],
        &[1.0, 0.5, 0.2, 0.5, 2.0, -0.3, 0.2, -0.3, 0.8],
    );
    let bx = Region::axis_box(&[-0.5, -1.0, 0.0], &[1.0, 2.0, 1.5], "b").unwrap();
    let bl = Region::ball(&[0.5, 0.0, 0.0], 1.2, "b").unwrap();
    for r in [bx, bl] {
        let m = r.gaussian_mass(&g, "p").unwrap();
        let (mc, se) = monte_carlo(&r, &g, 200_000, 31);
        assert!((m.value - mc).abs() < 5.0 * se, "{m:?} vs {mc} ± {se}");
    }
    // 4D diagonal box: a product of intervals.
    let g = gauss(
        &[0.0, 1.0, -1.0, 0.5],
        &[
            1.0, 0.0, 0.0, 0.0, 0.0, 0.25, 0.0, 0.0, 0.0, 0.0, 4.0, 0.0, 0.0, 0.0, 0.0, 1.0,
        ],
    );
    let lo = [-0.5, 0.5, -2.0, 0.0];
    let hi = [1.0, 1.8, 1.0, 3.0];
    let bx = Region::axis_box(&lo, &hi, "b").unwrap();
    let sd = [1.0, 0.5, 2.0, 1.0];
    let mean = [0.0, 1.0, -1.0, 0.5];
    let want: f64 = (0..4)
        .map(|k| normal::interval((lo[k] - mean[k]) / sd[k], (hi[k] - mean[k]) / sd[k]))
        .product();
    let m = bx.gaussian_mass(&g, "p").unwrap();
    assert!((m.value - want).abs() < 1e-12, "{m:?} vs {want}");
}

#[test]
fn eq8_extra_state_components_are_ignored_and_dimensions_checked() {
    // A 4D state (position, velocity): only the position marginal matters.
    let full = gauss(
        &[0.5, -0.5, 3.0, 4.0],
        &[
            1.0, 0.3, 0.5, 0.1, 0.3, 2.0, 0.2, 0.4, 0.5, 0.2, 3.0, 0.0, 0.1, 0.4, 0.0, 1.0,
        ],
    );
    let marginal = gauss(&[0.5, -0.5], &[1.0, 0.3, 0.3, 2.0]);
    let disc = Region::ball(&[1.0, 0.0], 1.0, "fov").unwrap();
    let a = disc.gaussian_mass(&full, "p").unwrap().value;
    let b = disc.gaussian_mass(&marginal, "p").unwrap().value;
    assert!((a - b).abs() < 1e-15);
    let one_d = gauss(&[0.0], &[1.0]);
    let e = disc.gaussian_mass(&one_d, "rfs.poisson[1]").unwrap_err();
    assert_eq!(e.field(), "rfs.poisson[1].mean");
    let big = Region::axis_box(&[0.0; 5], &[1.0; 5], "b").unwrap();
    let g5 = gauss(&[0.0; 5], &{
        let mut c = [0.0; 25];
        for i in 0..5 {
            c[i * 6] = 1.0;
        }
        c
    });
    assert!(matches!(
        big.gaussian_mass(&g5, "p"),
        Err(Error::Unsupported { .. })
    ));
}

#[test]
fn eq8_inclusion_tests_and_boundaries() {
    let bx = Region::axis_box(&[0.0, 0.0], &[1.0, 2.0], "b").unwrap();
    assert!(bx.contains(&[0.0, 2.0]) && bx.contains(&[1.0, 0.0, 9.0]));
    assert!(!bx.contains(&[1.0 + f64::EPSILON, 1.0]));
    let comp = Region::complement(bx.clone());
    assert!(!comp.contains(&[0.0, 1.0]) && comp.contains(&[-1e-300, 1.0]));
    // polygon: vertices and edge points are inside, whatever the orientation
    let tri = [[0.0, 0.0], [3.0, 0.0], [0.0, 3.0]];
    for v in [tri.to_vec(), tri.iter().rev().copied().collect()] {
        let p = Region::polygon(&v, "t").unwrap();
        for q in [[0.0, 0.0], [3.0, 0.0], [1.5, 1.5], [0.0, 1.0], [1.0, 1.0]] {
            assert!(p.contains(&q), "{q:?}");
        }
        for q in [[1.5, 1.5 + 1e-15], [-1e-300, 1.0], [2.0, 2.0], [4.0, 0.0]] {
            assert!(!p.contains(&q), "{q:?}");
        }
    }
    // agrees with the MC-free reference (a point-in-convex-polygon test) away from edges
    let mut rng = SmallRng::seed_from_u64(3);
    let hexagon: Vec<[f64; 2]> = (0..6)
        .map(|i| {
            let a = PI / 3.0 * i as f64;
            [a.cos(), a.sin()]
        })
        .collect();
    let h = Region::polygon(&hexagon, "h").unwrap();
    for _ in 0..10_000 {
        let q = [rng.random_range(-1.2..1.2), rng.random_range(-1.2..1.2)];
        let inside = (0..6).all(|i| {
            let (a, b) = (hexagon[i], hexagon[(i + 1) % 6]);
            (b[0] - a[0]) * (q[1] - a[1]) - (b[1] - a[1]) * (q[0] - a[0]) >= 0.0
        });
        assert_eq!(h.contains(&q), inside, "{q:?}");
    }
    let d = Region::ball(&[0.0, 0.0], 5.0, "d").unwrap();
    assert!(d.contains(&[3.0, 4.0]) && !d.contains(&[3.0, 4.000_000_000_000_001]));
    // validation
    assert!(Region::polygon(&[[0.0, 0.0], [1.0, 1.0], [2.0, 2.0]], "fov.polygon").is_err());
    let e = Region::polygon(&[[0.0, 0.0], [1.0, 1.0]], "fov.polygon").unwrap_err();
    assert_eq!(e.field(), "fov.polygon");
    let e = Region::polygon(&[[0.0, 0.0], [1.0, f64::NAN], [1.0, 0.0]], "fov.polygon").unwrap_err();
    assert_eq!(e.field(), "fov.polygon[1][1]");
    let e = Region::axis_box(&[0.0, 1.0], &[1.0, 0.5], "fov.box").unwrap_err();
    assert_eq!(e.field(), "fov.box.max[1]");
    let e = Region::ball(&[0.0, 0.0], -1.0, "fov.disc").unwrap_err();
    assert_eq!(e.field(), "fov.disc.radius");
    let e = Region::union(vec![bx, d, Region::ball(&[0.0], 1.0, "x").unwrap()], "u").unwrap_err();
    assert_eq!(e.field(), "u[2]");
    assert!(Region::union(vec![], "u").is_err());
}

/// Issue 26 (point 7): a box corner with both coordinates beyond ~1.4e154 under a correlated
/// Gaussian gave a NaN mass (the corner's square overflowed in the bivariate normal); it is
/// the mass of the box with that corner at infinity.
#[test]
fn eq8_box_2d_with_a_corner_at_the_largest_doubles_is_finite() {
    let g = gauss(&[0.0, 0.0], &[1.0, 0.5, 0.5, 1.0]);
    let quarter = 1.0 / 3.0; // Φ₂(0, 0; 1/2) = 1/4 + asin(1/2)/2π
    for (min, max) in [
        ([-1e308, -1e308], [0.0, 0.0]),
        ([0.0, 0.0], [1e308, 1e308]),
        ([-f64::MAX, -1e155], [0.0, 0.0]),
    ] {
        let b = Region::axis_box(&min, &max, "b").unwrap();
        let m = b.gaussian_mass(&g, "p").unwrap().value;
        assert!((m - quarter).abs() < 1e-15, "{min:?} {max:?}: {m}");
    }
    let all = Region::axis_box(&[-1e308, -1e308], &[1e308, 1e308], "b").unwrap();
    assert_eq!(all.gaussian_mass(&g, "p").unwrap().value, 1.0);
}
