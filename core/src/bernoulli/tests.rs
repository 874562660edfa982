//! Cross-module tests of the Bernoulli estimator: q against independent oracles (closed
//! forms, brute-force quadrature in polar/spherical coordinates about the ball's centre,
//! Monte Carlo), a* against grid searches, Theorem III.3 and its corollaries against the
//! paper's numbers and a Monte Carlo of the loss.

use alloc::vec;
use alloc::vec::Vec;

use rand::SeedableRng;
use rand::rngs::SmallRng;

use super::*;
use crate::gaussian::{Gaussian, GaussianMixture, normal};

fn rng(seed: u64) -> SmallRng {
    SmallRng::seed_from_u64(seed)
}

/// Gauss–Legendre nodes and weights on [−1, 1] (Newton on P_n).
fn gauss_legendre(n: usize) -> Vec<(f64, f64)> {
    let mut out = Vec::with_capacity(n);
    for i in 0..n {
        let mut x = (core::f64::consts::PI * (i as f64 + 0.75) / (n as f64 + 0.5)).cos();
        let mut dp = 0.0;
        for _ in 0..100 {
            let (mut p0, mut p1) = (1.0, x);
            for k in 2..=n {
                let p2 = ((2 * k - 1) as f64 * x * p1 - (k - 1) as f64 * p0) / k as f64;
                p0 = p1;
                p1 = p2;
            }
            dp = n as f64 * (x * p1 - p0) / (x * x - 1.0);
            let dx = p1 / dp;
            x -= dx;
            if dx.abs() < 1e-16 {
                break;
            }
        }
        out.push((x, 2.0 / ((1.0 - x * x) * dp * dp)));
    }
    out
}

/// Composite Gauss–Legendre nodes on [a, b]: `panels` panels of `n` points.
fn composite(a: f64, b: f64, panels: usize, n: usize) -> Vec<(f64, f64)> {
    let gl = gauss_legendre(n);
    let h = (b - a) / panels as f64;
    let mut out = Vec::with_capacity(panels * n);
    for k in 0..panels {
        let c = a + (k as f64 + 0.5) * h;
        for &(x, w) in &gl {
            out.push((c + 0.5 * h * x, 0.5 * h * w));
        }
    }
    out
}

/// Brute force 1 − q in 2D: ∫_0^r ∫_0^{2π} N(a + ρ(cos θ, sin θ)) ρ dθ dρ with composite
/// Gauss–Legendre in ρ and the (spectrally accurate, periodic) trapezoid rule in θ.
fn brute_inside_2d(g: &Gaussian, a: &[f64], r: f64, panels: usize, n_theta: usize) -> f64 {
    let rho = composite(0.0, r, panels, 20);
    let mut total = 0.0;
    for &(p, wp) in &rho {
        let mut ring = 0.0;
        for k in 0..n_theta {
            let t = 2.0 * core::f64::consts::PI * k as f64 / n_theta as f64;
            ring += g.pdf(&[a[0] + p * t.cos(), a[1] + p * t.sin()]);
        }
        total += wp * p * ring * 2.0 * core::f64::consts::PI / n_theta as f64;
    }
    total
}

/// Brute force 1 − q in 3D in spherical coordinates about a: composite Gauss–Legendre in ρ
/// and in cos θ, trapezoid in φ.
fn brute_inside_3d(g: &Gaussian, a: &[f64], r: f64, panels: usize, n_phi: usize) -> f64 {
    let rho = composite(0.0, r, panels, 20);
    let mu = composite(-1.0, 1.0, panels, 20);
    let mut total = 0.0;
    for &(p, wp) in &rho {
        let mut shell = 0.0;
        for &(c, wc) in &mu {
            let s = (1.0 - c * c).sqrt();
            let mut ring = 0.0;
            for k in 0..n_phi {
                let f = 2.0 * core::f64::consts::PI * k as f64 / n_phi as f64;
                ring += g.pdf(&[a[0] + p * s * f.cos(), a[1] + p * s * f.sin(), a[2] + p * c]);
            }
            shell += wc * ring * 2.0 * core::f64::consts::PI / n_phi as f64;
        }
        total += wp * p * p * shell;
    }
    total
}

/// Monte Carlo q with its standard error.
fn mc_outside(s: &SpatialDensity, a: &[f64], r: f64, n: usize, seed: u64) -> (f64, f64) {
    let mut rng = rng(seed);
    let mut hits = 0usize;
    for _ in 0..n {
        let x = s.sample(&mut rng);
        let d2: f64 = x.iter().zip(a).map(|(x, a)| (x - a) * (x - a)).sum();
        if d2 > r * r {
            hits += 1;
        }
    }
    let q = hits as f64 / n as f64;
    (q, (q * (1.0 - q) / n as f64).sqrt().max(1.0 / n as f64))
}

/// (mean, covariance row-major, centre, radius)
type Case<'a> = (&'a [f64], &'a [f64], &'a [f64], f64);

fn gaussian(mean: &[f64], cov: &[f64]) -> SpatialDensity {
    SpatialDensity::gaussian_from_slices(mean, cov).unwrap()
}

// ---------------------------------------------------------------------------------------
// q(a)
// ---------------------------------------------------------------------------------------

#[test]
fn eq12_q_is_exact_in_one_dimension() {
    let s = gaussian(&[0.3], &[2.25]);
    for &(a, r) in &[
        (0.3, 1.0),
        (1.0, 0.5),
        (-4.0, 0.1),
        (20.0, 3.0),
        (0.3, 12.0),
    ] {
        let inside = normal::cdf((a + r - 0.3) / 1.5) - normal::cdf((a - r - 0.3) / 1.5);
        let q = s.prob_outside_ball(&[a], r).unwrap();
        assert!((q - (1.0 - inside)).abs() < 1e-15, "a={a} r={r}");
    }
    // Far tail: q is 1 − 1e-20-ish, and tiny q keeps relative accuracy in 1D.
    let q = s.prob_outside_ball(&[0.3], 15.0).unwrap();
    let exact = 2.0 * normal::cdf(-10.0);
    assert!((q / exact - 1.0).abs() < 1e-12, "{q} {exact}");
}

#[test]
fn eq12_q_matches_closed_forms_for_centred_isotropic_gaussians() {
    // Centred isotropic N(m, σ² I_d): q = P(χ²_d > (r/σ)²). Exercises the nested quadrature
    // (d = 2 … 4) and the inversion (d = 5 … 8) against the incomplete-gamma closed form.
    for d in 2..=8usize {
        for &(sigma, r) in &[(1.0, 1.0), (0.7, 2.0), (2.0, 0.5), (0.2, 1.0)] {
            let mean = vec![0.5; d];
            let cov: Vec<f64> = (0..d * d)
                .map(|k| if k % (d + 1) == 0 { sigma * sigma } else { 0.0 })
                .collect();
            let s = gaussian(&mean, &cov);
            let b = s
                .prob_outside_ball_with_tolerance(&mean, r, DEFAULT_TOLERANCE)
                .unwrap();
            let exact = chi_square_sf(d, (r / sigma) * (r / sigma));
            assert!(
                (b.outside - exact).abs() < 1e-10,
                "d={d} σ={sigma} r={r}: {} vs {exact} (est. error {})",
                b.outside,
                b.error
            );
            assert!(b.error < 1e-9);
        }
    }
}

#[test]
fn eq12_q_matches_brute_force_quadrature_in_2d() {
    // Correlated covariances; centres at the mean, off the mean, outside the ball's reach,
    // on a narrow direction; an elongated (κ = 400) and a small covariance.
    let cases: &[Case] = &[
        (&[0.0, 0.0], &[1.0, 0.6, 0.6, 0.8], &[0.0, 0.0], 1.0),
        (&[1.0, -0.5], &[1.0, 0.6, 0.6, 0.8], &[0.2, 0.4], 1.3),
        (&[1.0, -0.5], &[2.0, -1.2, -1.2, 1.5], &[3.0, 1.0], 0.8),
        (&[0.0, 0.0], &[4.0, 0.0, 0.0, 0.01], &[0.5, 0.05], 0.7),
        (&[0.0, 0.0], &[2.0, 1.99, 1.99, 2.0], &[0.3, -0.2], 1.0),
        (&[0.2, 0.1], &[0.09, 0.05, 0.05, 0.04], &[0.0, 0.0], 0.5),
        (&[0.0, 0.0], &[1.0, 0.3, 0.3, 1.0], &[2.5, 0.0], 1.0),
    ];
    for (k, &(m, p, a, r)) in cases.iter().enumerate() {
        let s = gaussian(m, p);
        let g = s.as_gaussian().unwrap();
        let q = s.prob_outside_ball(a, r).unwrap();
        let fine = 1.0 - brute_inside_2d(g, a, r, 40, 512);
        let coarse = 1.0 - brute_inside_2d(g, a, r, 20, 256);
        // The oracle agrees with itself at double the resolution: it is converged.
        assert!(
            (fine - coarse).abs() < 1e-11,
            "case {k}: oracle not converged"
        );
        assert!((q - fine).abs() < 1e-9, "case {k}: {q} vs {fine}");
    }
}

#[test]
fn eq12_q_matches_brute_force_quadrature_in_3d() {
    let cases: &[Case] = &[
        (
            &[0.0, 0.0, 0.0],
            &[1.0, 0.4, 0.2, 0.4, 0.8, -0.3, 0.2, -0.3, 0.6],
            &[0.0, 0.0, 0.0],
            1.0,
        ),
        (
            &[0.5, -0.2, 0.1],
            &[1.0, 0.4, 0.2, 0.4, 0.8, -0.3, 0.2, -0.3, 0.6],
            &[0.0, 0.3, -0.4],
            1.2,
        ),
        (
            &[0.0, 0.0, 0.0],
            &[2.0, 0.0, 0.9, 0.0, 0.05, 0.0, 0.9, 0.0, 0.5],
            &[0.4, 0.1, 0.0],
            0.6,
        ),
    ];
    for (k, &(m, p, a, r)) in cases.iter().enumerate() {
        let s = gaussian(m, p);
        let g = s.as_gaussian().unwrap();
        let q = s.prob_outside_ball(a, r).unwrap();
        let fine = 1.0 - brute_inside_3d(g, a, r, 6, 160);
        let coarse = 1.0 - brute_inside_3d(g, a, r, 4, 110);
        assert!(
            (fine - coarse).abs() < 1e-11,
            "case {k}: oracle not converged"
        );
        assert!((q - fine).abs() < 1e-9, "case {k}: {q} vs {fine}");
    }
}

#[test]
fn eq12_q_matches_monte_carlo_in_1d_2d_3d() {
    // 10⁶ draws: standard error ≤ 5e-4; the bound is 5 standard errors.
    let cases: &[Case] = &[
        (&[0.0], &[1.0], &[0.4], 1.0),
        (&[1.0, -0.5], &[1.0, 0.6, 0.6, 0.8], &[0.2, 0.4], 1.3),
        (
            &[0.5, -0.2, 0.1],
            &[1.0, 0.4, 0.2, 0.4, 0.8, -0.3, 0.2, -0.3, 0.6],
            &[0.0, 0.3, -0.4],
            1.2,
        ),
    ];
    for (k, &(m, p, a, r)) in cases.iter().enumerate() {
        let s = gaussian(m, p);
        let q = s.prob_outside_ball(a, r).unwrap();
        let (mc, se) = mc_outside(&s, a, r, 1_000_000, 40 + k as u64);
        assert!((q - mc).abs() < 5.0 * se, "case {k}: {q} vs MC {mc} ± {se}");
    }
}

#[test]
fn eq12_q_of_mixtures_and_particles() {
    let c1 = Gaussian::from_slices(&[0.0, 0.0], &[1.0, 0.2, 0.2, 0.5], "m").unwrap();
    let c2 = Gaussian::from_slices(&[2.0, 1.0], &[0.3, 0.0, 0.0, 0.3], "m").unwrap();
    let mix = GaussianMixture::new(
        vec![(2.0, c1.clone()), (6.0, c2.clone())],
        "density.mixture",
    )
    .unwrap();
    let s = SpatialDensity::mixture(&mix).unwrap();
    let (a, r) = ([1.0, 0.5], 1.1);
    let q1 = gaussian(&[0.0, 0.0], &[1.0, 0.2, 0.2, 0.5])
        .prob_outside_ball(&a, r)
        .unwrap();
    let q2 = gaussian(&[2.0, 1.0], &[0.3, 0.0, 0.0, 0.3])
        .prob_outside_ball(&a, r)
        .unwrap();
    let q = s.prob_outside_ball(&a, r).unwrap();
    assert!((q - (0.25 * q1 + 0.75 * q2)).abs() < 1e-15);
    let (mc, se) = mc_outside(&s, &a, r, 400_000, 9);
    assert!((q - mc).abs() < 5.0 * se);
    assert_eq!(s.mean(), vec![1.5, 0.75]);

    let pts = [[0.0, 0.0], [1.0, 0.0], [0.0, 2.0], [3.0, 3.0]];
    let p = ParticleSet::new(&pts, Some(&[1.0, 1.0, 1.0, 5.0])).unwrap();
    let s = SpatialDensity::particles(p);
    // Closed ball: the particle at distance exactly 1 is inside.
    assert_eq!(s.prob_outside_ball(&[0.0, 0.0], 1.0).unwrap(), 0.75);
    assert_eq!(s.prob_outside_ball(&[0.0, 0.0], 0.999).unwrap(), 0.875);
    assert_eq!(s.prob_outside_ball(&[3.0, 3.0], 0.5).unwrap(), 0.375);
}

#[test]
fn density_validation_names_the_field() {
    let e = SpatialDensity::gaussian_from_slices(&[0.0, 0.0], &[1.0, 2.0, 2.0, 1.0]).unwrap_err();
    assert_eq!(e.field(), "density.cov");
    let e =
        SpatialDensity::gaussian_from_slices(&[0.0, f64::NAN], &[1.0, 0.0, 0.0, 1.0]).unwrap_err();
    assert_eq!(e.field(), "density.mean[1]");
    let e = SpatialDensity::gaussian_from_slices(&[0.0, 0.0], &[1.0, 0.0, 0.0]).unwrap_err();
    assert_eq!(e.field(), "density.cov");
    let g = Gaussian::from_slices(&[0.0], &[1.0], "density.mixture[0]").unwrap();
    let zero = GaussianMixture::new(vec![(0.0, g.clone())], "density.mixture").unwrap();
    assert_eq!(
        SpatialDensity::mixture(&zero).unwrap_err().field(),
        "sum of density.mixture[].weight"
    );
    let e = GaussianMixture::new(vec![(1.0, g.clone()), (-1.0, g)], "density.mixture").unwrap_err();
    assert_eq!(e.field(), "density.mixture[1].weight");
    assert_eq!(
        SpatialDensity::mixture(&GaussianMixture::default())
            .unwrap_err()
            .field(),
        "density.mixture"
    );
    let pts = [vec![0.0, 0.0], vec![1.0]];
    assert_eq!(
        ParticleSet::new(&pts, None).unwrap_err().field(),
        "density.particles[1]"
    );
    let pts = [[0.0, 0.0], [1.0, f64::INFINITY]];
    assert_eq!(
        ParticleSet::new(&pts, None).unwrap_err().field(),
        "density.particles[1][1]"
    );
    let pts = [[0.0, 0.0], [1.0, 1.0]];
    for (w, field) in [
        (&[1.0, -0.5][..], "density.weights[1]"),
        (&[0.0, 0.0][..], "sum of density.weights"),
        (&[1.0][..], "density.weights"),
        (&[f64::NAN, 1.0][..], "density.weights[0]"),
    ] {
        assert_eq!(ParticleSet::new(&pts, Some(w)).unwrap_err().field(), field);
    }
    let empty: [[f64; 2]; 0] = [];
    assert_eq!(
        ParticleSet::new(&empty, None).unwrap_err().field(),
        "density.particles"
    );
    let s = gaussian(&[0.0, 0.0], &[1.0, 0.0, 0.0, 1.0]);
    assert_eq!(
        s.prob_outside_ball(&[0.0], 1.0).unwrap_err().field(),
        "center"
    );
    assert_eq!(
        s.prob_outside_ball(&[0.0, f64::NAN], 1.0)
            .unwrap_err()
            .field(),
        "center[1]"
    );
    assert_eq!(
        s.prob_outside_ball(&[0.0, 0.0], 0.0).unwrap_err().field(),
        "radius"
    );
    assert_eq!(s.mmuc(-1.0).unwrap_err().field(), "radius");
}

/// A d × d covariance with eigenvalues `eig` in a fixed rotated basis (products of Givens
/// rotations), row-major.
fn rotated_cov(eig: &[f64]) -> Vec<f64> {
    let d = eig.len();
    let mut u = nalgebra::DMatrix::<f64>::identity(d, d);
    for i in 0..d {
        for j in i + 1..d {
            let a = 0.3 + 0.7 * (i as f64 + 2.0 * j as f64);
            let mut g = nalgebra::DMatrix::<f64>::identity(d, d);
            g[(i, i)] = a.cos();
            g[(j, j)] = a.cos();
            g[(i, j)] = -a.sin();
            g[(j, i)] = a.sin();
            u *= g;
        }
    }
    let p = &u
        * nalgebra::DMatrix::from_diagonal(&nalgebra::DVector::from_column_slice(eig))
        * u.transpose();
    let p = (&p + p.transpose()) * 0.5;
    (0..d * d).map(|k| p[(k / d, k % d)]).collect()
}

#[test]
fn nested_quadrature_and_inversion_agree() {
    // Two independent algorithms on correlated, noncentral cases where no closed form
    // exists: d = 3 and 4 (nested by default) and 5 (inversion by default).
    use super::ball::{GaussianBall, Method};
    let cases: &[(&[f64], f64, f64)] = &[
        (&[0.3, 1.0, 2.0], 0.3, 1.5),
        (&[0.05, 0.5, 1.0, 2.0], 0.2, 1.2),
        (&[0.5, 0.5, 1.0, 1.5], 1.0, 2.0),
        (&[0.2, 0.4, 0.6, 0.8, 1.0], 0.4, 1.5),
    ];
    for (k, &(eig, shift, r)) in cases.iter().enumerate() {
        let d = eig.len();
        let mean: Vec<f64> = (0..d).map(|i| 0.1 * i as f64).collect();
        let g = Gaussian::from_slices(&mean, &rotated_cov(eig), "density").unwrap();
        let ball = GaussianBall::new(g, "density").unwrap();
        let center: Vec<f64> = mean
            .iter()
            .enumerate()
            .map(|(i, m)| m + shift * (1.0 - 0.4 * i as f64))
            .collect();
        let a = ball.outside_by(&center, r, 1e-10, Method::Nested);
        let b = ball.outside_by(&center, r, 1e-10, Method::Inversion);
        assert!(
            (a.outside - b.outside).abs() < 2e-10,
            "case {k}: nested {a:?} inversion {b:?}"
        );
        // Nested quadrature in 5D stops at its evaluation budget, and says so in its error
        // estimate (a few 1e-9) while its value still agrees to 2e-10.
        let nested_bound = if d <= 4 { 1e-9 } else { 1e-8 };
        assert!(
            a.error < nested_bound && b.error < 1e-9,
            "case {k}: {a:?} {b:?}"
        );
    }
}

#[test]
fn eq12_q_matches_monte_carlo_in_6d() {
    let d = 6;
    let eig = [0.1, 0.3, 0.5, 0.9, 1.4, 2.0];
    let mean = vec![0.2; d];
    let s = gaussian(&mean, &rotated_cov(&eig));
    let center: Vec<f64> = (0..d).map(|i| 0.3 - 0.1 * i as f64).collect();
    let q = s.prob_outside_ball(&center, 2.5).unwrap();
    let (mc, se) = mc_outside(&s, &center, 2.5, 400_000, 77);
    assert!((q - mc).abs() < 5.0 * se, "{q} vs MC {mc} ± {se}");
}

// ---------------------------------------------------------------------------------------
// a* (12)
// ---------------------------------------------------------------------------------------

fn mixture(parts: &[(f64, &[f64], &[f64])]) -> SpatialDensity {
    let comps = parts
        .iter()
        .enumerate()
        .map(|(j, (w, m, p))| {
            let name = alloc::format!("density.mixture[{j}]");
            (*w, Gaussian::from_slices(m, p, &name).unwrap())
        })
        .collect();
    SpatialDensity::mixture(&GaussianMixture::new(comps, "density.mixture").unwrap()).unwrap()
}

/// The best q on a grid with spacing `h` over the box, then on a grid 20× finer around it.
fn grid_search_2d(
    s: &SpatialDensity,
    r: f64,
    lo: [f64; 2],
    hi: [f64; 2],
    h: f64,
) -> (f64, [f64; 2]) {
    let mut best = (f64::INFINITY, [0.0, 0.0]);
    let scan = |lo: [f64; 2], hi: [f64; 2], h: f64, best: &mut (f64, [f64; 2])| {
        let nx = ((hi[0] - lo[0]) / h).round() as usize;
        let ny = ((hi[1] - lo[1]) / h).round() as usize;
        for i in 0..=nx {
            for j in 0..=ny {
                let a = [lo[0] + i as f64 * h, lo[1] + j as f64 * h];
                let q = s.prob_outside_ball(&a, r).unwrap();
                if q < best.0 {
                    *best = (q, a);
                }
            }
        }
    };
    scan(lo, hi, h, &mut best);
    let c = best.1;
    scan(
        [c[0] - h, c[1] - h],
        [c[0] + h, c[1] + h],
        h / 20.0,
        &mut best,
    );
    best
}

#[test]
fn eq12_gaussian_mmuc_is_the_mean_and_beats_its_neighbours() {
    // Sherman's theorem; checking q(mean) ≤ q(mean + δ) also tests that the quadrature
    // respects it.
    let mean = [1.0, -2.0, 0.5];
    let s = gaussian(&mean, &rotated_cov(&[0.2, 0.7, 1.5]));
    let m = s.mmuc(1.1).unwrap();
    assert_eq!(m.center, mean.to_vec());
    assert_eq!(m.method, MmucMethod::GaussianMean);
    assert_eq!(m.miss_probability, s.prob_outside_ball(&mean, 1.1).unwrap());
    for k in 0..12 {
        let t = k as f64;
        let delta = [
            0.05 * t.cos(),
            0.05 * (1.3 * t).sin(),
            0.03 * (0.7 * t).cos(),
        ];
        let a: Vec<f64> = mean.iter().zip(&delta).map(|(m, d)| m + d).collect();
        assert!(s.prob_outside_ball(&a, 1.1).unwrap() > m.miss_probability);
    }
}

#[test]
fn eq12_mixture_mmuc_finds_the_optimum_between_modes() {
    // Two modes 2 apart with r0 = 1.3: a ball between them holds more than a ball on either.
    let s = mixture(&[
        (1.0, &[-1.0, 0.0], &[0.09, 0.0, 0.0, 0.09]),
        (1.0, &[1.0, 0.2], &[0.16, 0.05, 0.05, 0.09]),
    ]);
    let r = 1.3;
    let m = s.mmuc(r).unwrap();
    assert_eq!(m.method, MmucMethod::MixtureSearch);
    let at_modes = s
        .prob_outside_ball(&[-1.0, 0.0], r)
        .unwrap()
        .min(s.prob_outside_ball(&[1.0, 0.2], r).unwrap());
    assert!(m.miss_probability < at_modes - 0.05, "{m:?} vs {at_modes}");
    let (grid_q, grid_a) = grid_search_2d(&s, r, [-2.0, -1.0], [2.0, 1.0], 0.02);
    assert!(
        m.miss_probability <= grid_q + 1e-9,
        "{m:?} vs grid {grid_q} at {grid_a:?}"
    );
    assert!(
        dist(&m.center, &grid_a) < 0.01,
        "{:?} vs {grid_a:?}",
        m.center
    );
    assert_eq!(
        m.miss_probability,
        s.prob_outside_ball(&m.center, r).unwrap()
    );
}

fn dist(a: &[f64], b: &[f64]) -> f64 {
    a.iter()
        .zip(b)
        .map(|(x, y)| (x - y) * (x - y))
        .sum::<f64>()
        .sqrt()
}

#[test]
fn eq12_mixture_mmuc_matches_grid_search_on_an_asymmetric_mixture() {
    // Three components of different weights and correlations; the best ball sits on the
    // heavy pair, away from both the mixture mean and any component mean.
    let s = mixture(&[
        (0.35, &[0.0, 0.0], &[0.25, 0.1, 0.1, 0.2]),
        (0.4, &[1.2, 0.6], &[0.1, -0.04, -0.04, 0.15]),
        (0.25, &[-2.5, 1.5], &[0.05, 0.0, 0.0, 0.05]),
    ]);
    let r = 1.0;
    let m = s.mmuc(r).unwrap();
    let (grid_q, grid_a) = grid_search_2d(&s, r, [-3.5, -1.0], [2.5, 2.5], 0.025);
    assert!(
        m.miss_probability <= grid_q + 1e-9,
        "{m:?} vs grid {grid_q} at {grid_a:?}"
    );
    assert!(dist(&m.center, &grid_a) < 0.02);
    let mean = s.mean();
    assert!(s.prob_outside_ball(&mean, r).unwrap() > m.miss_probability + 0.01);
}

#[test]
fn eq12_mixture_mmuc_in_one_and_three_dimensions() {
    // 1D: compare with a grid of 40 001 points; the optimum covers both modes.
    let s = mixture(&[
        (0.5, &[0.0], &[0.04]),
        (0.3, &[1.6], &[0.09]),
        (0.2, &[5.0], &[0.01]),
    ]);
    let r = 1.0;
    let m = s.mmuc(r).unwrap();
    let mut best = (f64::INFINITY, 0.0);
    for i in 0..=40_000 {
        let a = -2.0 + 8.0 * i as f64 / 40_000.0;
        let q = s.prob_outside_ball(&[a], r).unwrap();
        if q < best.0 {
            best = (q, a);
        }
    }
    assert!(m.miss_probability <= best.0 + 1e-9, "{m:?} vs {best:?}");
    assert!((m.center[0] - best.1).abs() < 1e-3);
    // 3D: two correlated components; the search must beat both means and the mixture mean
    // and be a local minimum.
    let s = mixture(&[
        (
            0.6,
            &[0.0, 0.0, 0.0],
            &[0.1, 0.02, 0.0, 0.02, 0.1, 0.01, 0.0, 0.01, 0.1],
        ),
        (
            0.4,
            &[1.4, 0.3, -0.2],
            &[0.08, 0.0, 0.01, 0.0, 0.08, 0.0, 0.01, 0.0, 0.08],
        ),
    ]);
    let m = s.mmuc(1.0).unwrap();
    for a in [vec![0.0, 0.0, 0.0], vec![1.4, 0.3, -0.2], s.mean()] {
        assert!(m.miss_probability <= s.prob_outside_ball(&a, 1.0).unwrap());
    }
    for k in 0..6 {
        let mut a = m.center.clone();
        a[k / 2] += if k % 2 == 0 { 0.01 } else { -0.01 };
        assert!(m.miss_probability <= s.prob_outside_ball(&a, 1.0).unwrap() + 1e-10);
    }
}

#[test]
fn eq12_mixture_with_a_shared_mean_uses_sherman_per_component() {
    let s = mixture(&[
        (0.5, &[1.0, 1.0], &[1.0, 0.5, 0.5, 1.0]),
        (0.5, &[1.0, 1.0], &[0.1, 0.0, 0.0, 3.0]),
    ]);
    let m = s.mmuc(0.8).unwrap();
    assert_eq!(m.method, MmucMethod::SharedMean);
    assert_eq!(m.center, vec![1.0, 1.0]);
}

/// Best covered weight by brute force over the classical candidate centres in 2D: each
/// particle, and the two centres at distance r from each pair within 2r.
fn brute_particles_2d(pts: &[[f64; 2]], w: &[f64], r: f64) -> f64 {
    let cover = |c: [f64; 2]| -> f64 {
        let rr = r * (1.0 + 1e-9);
        pts.iter()
            .zip(w)
            .filter(|(p, _)| (p[0] - c[0]).powi(2) + (p[1] - c[1]).powi(2) <= rr * rr)
            .map(|(_, w)| w)
            .sum()
    };
    let mut best: f64 = 0.0;
    for (i, p) in pts.iter().enumerate() {
        best = best.max(cover(*p));
        for q in &pts[i + 1..] {
            let d = ((p[0] - q[0]).powi(2) + (p[1] - q[1]).powi(2)).sqrt();
            if d > 2.0 * r || d == 0.0 {
                continue;
            }
            let mid = [(p[0] + q[0]) / 2.0, (p[1] + q[1]) / 2.0];
            let h = (r * r - d * d / 4.0).max(0.0).sqrt();
            let n = [-(q[1] - p[1]) / d, (q[0] - p[0]) / d];
            for sgn in [1.0, -1.0] {
                best = best.max(cover([mid[0] + sgn * h * n[0], mid[1] + sgn * h * n[1]]));
            }
        }
    }
    best
}

#[test]
fn eq12_particle_mmuc_is_exact_in_1d_and_2d() {
    use rand::RngExt;
    let mut rng = rng(5);
    let total_w = |w: &[f64]| w.iter().sum::<f64>();
    for trial in 0..30 {
        let n = 5 + trial % 40;
        let pts: Vec<[f64; 2]> = (0..n)
            .map(|_| [rng.random::<f64>() * 4.0, rng.random::<f64>() * 3.0])
            .collect();
        let w: Vec<f64> = (0..n).map(|_| rng.random::<f64>() + 0.05).collect();
        let r = 0.4 + 0.8 * rng.random::<f64>();
        let s = SpatialDensity::particles(ParticleSet::new(&pts, Some(&w)).unwrap());
        let m = s.mmuc(r).unwrap();
        assert_eq!(m.method, MmucMethod::ParticlesExact);
        let best = brute_particles_2d(&pts, &w, r) / total_w(&w);
        assert!(
            (1.0 - m.miss_probability - best).abs() < 1e-12,
            "trial {trial}: {} vs {best}",
            1.0 - m.miss_probability
        );
        assert_eq!(
            m.miss_probability,
            s.prob_outside_ball(&m.center, r).unwrap()
        );
        // 1D: project on x and compare with all intervals [x_i, x_i + 2r].
        let xs: Vec<[f64; 1]> = pts.iter().map(|p| [p[0]]).collect();
        let s1 = SpatialDensity::particles(ParticleSet::new(&xs, Some(&w)).unwrap());
        let m1 = s1.mmuc(r).unwrap();
        let mut best1: f64 = 0.0;
        for x in &xs {
            let c: f64 = xs
                .iter()
                .zip(&w)
                .filter(|(y, _)| y[0] >= x[0] && y[0] - x[0] <= 2.0 * r)
                .map(|(_, w)| w)
                .sum();
            best1 = best1.max(c);
        }
        assert!((1.0 - m1.miss_probability - best1 / total_w(&w)).abs() < 1e-12);
    }
}

#[test]
fn eq12_particle_mmuc_in_3d_beats_every_sampled_centre() {
    use rand::RngExt;
    let mut rng = rng(6);
    for trial in 0..6 {
        let n = 12 + 6 * trial;
        let pts: Vec<[f64; 3]> = (0..n)
            .map(|_| {
                [
                    rng.random::<f64>() * 2.0,
                    rng.random::<f64>() * 2.0,
                    rng.random::<f64>(),
                ]
            })
            .collect();
        let s = SpatialDensity::particles(ParticleSet::new(&pts, None).unwrap());
        let r = 0.6;
        let m = s.mmuc(r).unwrap();
        assert_eq!(m.method, MmucMethod::ParticlesExact);
        // Lower bound on the optimum: 20 000 random centres and every particle.
        let mut best = 1.0f64;
        for p in &pts {
            best = best.min(s.prob_outside_ball(p, r).unwrap());
        }
        for _ in 0..20_000 {
            let c = [
                rng.random::<f64>() * 2.0,
                rng.random::<f64>() * 2.0,
                rng.random::<f64>(),
            ];
            best = best.min(s.prob_outside_ball(&c, r).unwrap());
        }
        assert!(
            m.miss_probability <= best,
            "trial {trial}: {} vs {best}",
            m.miss_probability
        );
    }
    // A cluster of 5 particles that fits a ball only when centred between them.
    let pts = [
        [0.0, 0.0, 0.0],
        [1.0, 0.0, 0.0],
        [0.5, 0.86, 0.0],
        [0.5, 0.29, 0.8],
        [5.0, 5.0, 5.0],
        [5.2, 5.0, 5.0],
    ];
    let s = SpatialDensity::particles(ParticleSet::new(&pts, None).unwrap());
    let m = s.mmuc(0.62).unwrap();
    assert!((m.miss_probability - 2.0 / 6.0).abs() < 1e-15, "{m:?}");
}

// ---------------------------------------------------------------------------------------
// Theorem III.3, Corollaries IV.1 and IV.2, Fig. 3
// ---------------------------------------------------------------------------------------

fn loss(costs: Costs, r: f64) -> ApplicationLoss {
    ApplicationLoss::new(costs, r).unwrap()
}

#[test]
fn fig2_published_thresholds_of_section_four() {
    // μ = 0, σ = 1, r0 = 1 (Figs. 2a, 2b): Γ_MPE = 0.5943, Γ_MMOL = 0.1628 (c_A = 0.9,
    // c_M = 0.1), printed to four decimals.
    let s = gaussian(&[0.0], &[1.0]);
    let mpe = estimate(0.5, &s, &loss(Costs::mpe(), 1.0)).unwrap();
    assert!(
        (mpe.threshold.gamma - 0.5943).abs() < 5e-5,
        "{}",
        mpe.threshold.gamma
    );
    assert_eq!(mpe.threshold.direction, Direction::Above);
    let mmol = estimate(0.5, &s, &loss(Costs::mmol(0.9, 0.1).unwrap(), 1.0)).unwrap();
    assert!(
        (mmol.threshold.gamma - 0.1628).abs() < 5e-5,
        "{}",
        mmol.threshold.gamma
    );
    // The exact values: q = 2Φ(−1).
    let q = 2.0 * normal::cdf(-1.0);
    assert!((mpe.threshold.gamma - 1.0 / (2.0 - q)).abs() < 1e-15);
    assert!((mmol.threshold.gamma - (0.1 / 0.9) / (1.0 - q)).abs() < 1e-15);
    // Fig. 2: between the two thresholds the optimal and the p > 0.5 rules disagree.
    let p = 0.55;
    let e = estimate(p, &s, &loss(Costs::mpe(), 1.0)).unwrap();
    assert!(!e.declare && e.estimate.is_none());
    assert!(e.expected_loss_empty < e.expected_loss_singleton);
    let e = estimate(0.3, &s, &loss(Costs::mmol(0.9, 0.1).unwrap(), 1.0)).unwrap();
    assert!(e.declare && e.estimate == Some(vec![0.0]));
    assert!(e.expected_loss_singleton < e.expected_loss_empty);
    // The same numbers from the closed-form curve.
    let c = isotropic_threshold_curve(&[1.0], 1.0, &Costs::mpe(), 1).unwrap();
    assert!((c[0] - mpe.threshold.gamma).abs() < 1e-15);
}

#[test]
fn cor1_cor2_follow_from_the_general_form() {
    for i in 0..=20 {
        let q = i as f64 / 20.0;
        for j in 0..=10 {
            let p = j as f64 / 10.0;
            // IV.1 (MPE): Γ = 1/(2 − q) (15); ρ_{a*} = G_Φ[1_B] = 1 − p + p q (16), (18);
            // ρ_∅ = p (17).
            let c = Costs::mpe();
            let t = threshold(&c, q).unwrap();
            assert!((t.gamma - 1.0 / (2.0 - q)).abs() < 1e-15);
            assert_eq!(t.direction, Direction::Above);
            let rho_a = expected_loss_singleton(&c, p, q).unwrap();
            assert!((rho_a - (1.0 - p + p * q)).abs() < 1e-15);
            assert!((expected_loss_empty(&c, p).unwrap() - p).abs() < 1e-15);
            // IV.2 (MMOL): Γ = (c_M/c_A)/(1 − q) (19); ρ_{a*} = c_M + p c_A q (20);
            // ρ_∅ = p c_A (21).
            for &(ca, cm) in &[(0.9, 0.1), (1.0, 0.25), (3.0, 2.0), (2.0, 0.0)] {
                let c = Costs::mmol(ca, cm).unwrap();
                if q < 1.0 {
                    let t = threshold(&c, q).unwrap();
                    let g = (cm / ca) / (1.0 - q);
                    assert!((t.gamma - g).abs() < 1e-14 * g.max(1.0), "q={q} {ca} {cm}");
                }
                let rho_a = expected_loss_singleton(&c, p, q).unwrap();
                assert!((rho_a - (cm + p * ca * q)).abs() < 1e-15);
                assert!((expected_loss_empty(&c, p).unwrap() - p * ca).abs() < 1e-15);
            }
        }
    }
}

#[test]
fn eq24_decision_is_the_smaller_expected_loss_for_any_costs() {
    // Eq. (24): report exactly when ρ_{a*} < ρ_∅, including cost matrices that reverse the
    // comparison (Direction::Below) or make it independent of p (Γ = ±∞).
    use rand::RngExt;
    let mut rng = rng(17);
    let mut reversed = 0;
    for _ in 0..20_000 {
        let mut c = [0.0; 5];
        for x in &mut c {
            // Some exact zeros and ties.
            *x = if rng.random::<f64>() < 0.2 {
                0.0
            } else {
                (rng.random::<f64>() * 4.0).round() / 2.0
            };
        }
        let costs = Costs::new(c[0], c[1], c[2], c[3], c[4]).unwrap();
        let q = rng.random::<f64>();
        let p = rng.random::<f64>();
        let t = threshold(&costs, q).unwrap();
        if t.direction == Direction::Below {
            reversed += 1;
        }
        let rho_a = expected_loss_singleton(&costs, p, q).unwrap();
        let rho_e = expected_loss_empty(&costs, p).unwrap();
        if (rho_a - rho_e).abs() > 1e-12 {
            assert_eq!(t.declares(p), rho_a < rho_e, "{c:?} q={q} p={p} {t:?}");
        }
    }
    assert!(reversed > 100);
    // Denominator 0: c00 − c01 − c10 + c11 + c q = 0.
    let always = threshold(&Costs::new(1.0, 1.0, 0.0, 0.0, 0.0).unwrap(), 0.3).unwrap();
    assert_eq!(always.gamma, f64::NEG_INFINITY);
    assert!(always.declares(0.0) && always.declares(1.0));
    let never = threshold(&Costs::new(0.0, 0.0, 0.0, 0.0, 0.0).unwrap(), 0.3).unwrap();
    assert_eq!(never.gamma, f64::INFINITY);
    assert!(!never.declares(1.0));
    assert_eq!(
        threshold(&Costs::mpe(), 1.5).unwrap_err().field(),
        "missProbability"
    );
    assert_eq!(
        expected_loss_empty(&Costs::mpe(), -0.1)
            .unwrap_err()
            .field(),
        "existence"
    );
    let s = gaussian(&[0.0], &[1.0]);
    assert_eq!(
        estimate(f64::NAN, &s, &loss(Costs::mpe(), 1.0))
            .unwrap_err()
            .field(),
        "existence"
    );
}

#[test]
fn eq10_ties_report_nothing() {
    // MMOL with q = 0 (particles all inside the ball): Γ = c_M/c_A exactly; p = Γ is a tie.
    let pts = [[0.0, 0.0], [0.1, 0.0]];
    let s = SpatialDensity::particles(ParticleSet::new(&pts, None).unwrap());
    let l = loss(Costs::mmol(1.0, 0.25).unwrap(), 1.0);
    let e = estimate(0.25, &s, &l).unwrap();
    assert_eq!(e.miss_probability(), 0.0);
    assert_eq!(e.threshold.gamma, 0.25);
    assert_eq!(e.expected_loss_empty, e.expected_loss_singleton);
    assert!(!e.declare);
    assert!(estimate(0.250_000_1, &s, &l).unwrap().declare);
}

#[test]
fn cor2_free_countermeasure_threshold_is_positive_zero() {
    // MMOL with c_M = 0: Γ = 0/(c_A (q − 1)) is +0, not −0 (which JS prints as "-0").
    for q in [0.0, 0.3, 0.999] {
        let t = threshold(&Costs::mmol(0.9, 0.0).unwrap(), q).unwrap();
        assert_eq!(t.gamma.to_bits(), 0.0f64.to_bits(), "q={q}");
        assert!(t.declares(1e-300) && !t.declares(0.0));
    }
    let g =
        isotropic_threshold_curve(&[0.5, 2.0], 1.0, &Costs::mmol(1.0, 0.0).unwrap(), 1).unwrap();
    assert!(g.iter().all(|x| x.to_bits() == 0));
}

#[test]
fn fig3_properties() {
    let sigmas: Vec<f64> = (1..=200).map(|i| 0.05 * i as f64).collect();
    for d in [1usize, 2, 3] {
        for &r in &[0.1, 1.0, 3.0, 5.0, 10.0] {
            // MPE: Γ ≥ ½, increasing with σ (Fig. 3a).
            let g = isotropic_threshold_curve(&sigmas, r, &Costs::mpe(), d).unwrap();
            assert!(g.iter().all(|&x| (0.5..=1.0).contains(&x)));
            assert!(g.windows(2).all(|w| w[1] >= w[0]), "d={d} r={r}");
            assert!(g[199] > g[0]);
            // MMOL: Γ ≥ c_M/c_A, increasing (Fig. 3b).
            for &ratio in &[0.0, 0.25, 0.5, 0.75, 1.0] {
                let costs = Costs::mmol(1.0, ratio).unwrap();
                let g = isotropic_threshold_curve(&sigmas, r, &costs, d).unwrap();
                assert!(g.iter().all(|&x| x >= ratio));
                assert!(g.windows(2).all(|w| w[1] >= w[0]));
                for &x in &g {
                    let t = Threshold {
                        gamma: x,
                        direction: Direction::Above,
                    };
                    if ratio == 0.0 {
                        // c_M = 0: always reported (every p > 0).
                        assert_eq!(x, 0.0);
                        assert!(t.declares(1e-9));
                    }
                    if ratio >= 1.0 {
                        // c_M ≥ c_A: never reported.
                        assert!(!t.declares(1.0));
                    }
                }
            }
        }
    }
    // c_M > c_A too.
    let g = isotropic_threshold_curve(&[0.5], 1.0, &Costs::mmol(1.0, 1.5).unwrap(), 2).unwrap();
    assert!(g[0] > 1.0);
}

#[test]
fn fig3_curve_matches_the_general_estimator() {
    // The closed form against the quadrature (2D, 3D) and the exact 1D q.
    for d in [1usize, 2, 3] {
        for &sigma in &[0.3, 1.0, 2.5] {
            let mean = vec![0.7; d];
            let cov: Vec<f64> = (0..d * d)
                .map(|k| if k % (d + 1) == 0 { sigma * sigma } else { 0.0 })
                .collect();
            let s = gaussian(&mean, &cov);
            let costs = Costs::new(0.1, 2.0, 1.0, 0.3, 1.5).unwrap();
            let e = estimate(0.5, &s, &loss(costs, 1.2)).unwrap();
            let g = isotropic_threshold_curve(&[sigma], 1.2, &costs, d).unwrap()[0];
            assert!((e.threshold.gamma - g).abs() < 1e-9, "d={d} σ={sigma}");
            let q = isotropic_miss_probability(sigma, 1.2, d).unwrap();
            assert!((e.miss_probability() - q).abs() < 1e-9);
        }
    }
}

#[test]
fn fig2_loss_curve_follows_the_rule_and_names_the_entry() {
    let costs = Costs::mmol(0.9, 0.1).unwrap();
    let q = 0.3;
    let ps = vec![0.0, 0.05, 0.2, 0.5, 1.0];
    let o = LossCurveOptions {
        existences: ps.clone(),
        miss_probability: q,
        costs,
        threshold: None,
    };
    let c = loss_curve(&o).unwrap();
    let t = threshold(&costs, q).unwrap();
    assert_eq!(c.threshold, t.gamma);
    for (i, &p) in ps.iter().enumerate() {
        let e = expected_loss_empty(&costs, p).unwrap();
        let a = expected_loss_singleton(&costs, p, q).unwrap();
        assert_eq!((c.empty[i], c.singleton[i]), (e, a));
        assert_eq!(c.rule[i], if t.declares(p) { a } else { e });
        // The optimal rule is never worse than either report.
        assert!(c.rule[i] <= e.min(a));
    }
    let fixed = loss_curve(&LossCurveOptions {
        threshold: Some(0.5),
        ..o.clone()
    })
    .unwrap();
    assert_eq!(fixed.threshold, 0.5);
    assert_eq!(fixed.rule[2], fixed.empty[2]);
    assert_eq!(fixed.rule[4], fixed.singleton[4]);
    let bad = loss_curve(&LossCurveOptions {
        existences: vec![0.5, 1.5],
        ..o.clone()
    })
    .unwrap_err();
    assert_eq!(bad, crate::Error::probability("existences[1]", 1.5));
    let bad = loss_curve(&LossCurveOptions {
        miss_probability: -1.0,
        ..o
    })
    .unwrap_err();
    assert_eq!(bad.field(), "missProbability");
}

#[test]
fn eq13_eq14_expected_losses_match_a_monte_carlo_of_the_loss() {
    // Simulate the Bernoulli (exists with probability p, then x ~ s) and average L(α, φ)
    // of eq. (7) for α = {a*} and α = ∅; costs with c01 ≠ c10 check the erratum (23c).
    use rand::RngExt;
    let costs = Costs::new(0.2, 3.0, 1.0, 0.5, 2.0).unwrap();
    let densities = [
        gaussian(&[1.0, -1.0], &[1.0, 0.6, 0.6, 0.8]),
        mixture(&[
            (0.7, &[0.0, 0.0], &[0.2, 0.0, 0.0, 0.2]),
            (0.3, &[1.5, 0.5], &[0.1, 0.03, 0.03, 0.1]),
        ]),
        SpatialDensity::particles(
            ParticleSet::new(
                &[[0.0, 0.0], [0.5, 0.2], [3.0, 3.0]],
                Some(&[2.0, 1.0, 1.0]),
            )
            .unwrap(),
        ),
    ];
    for (k, s) in densities.iter().enumerate() {
        let l = loss(costs, 1.0);
        let p = 0.6;
        let e = estimate(p, s, &l).unwrap();
        let a = e.mmuc.center.clone();
        let mut rng = rng(100 + k as u64);
        let n = 400_000;
        let (mut sum_a, mut sum_a2, mut sum_e, mut sum_e2) = (0.0, 0.0, 0.0, 0.0);
        for _ in 0..n {
            let truth = if rng.random::<f64>() < p {
                Some(s.sample(&mut rng))
            } else {
                None
            };
            let la = l.loss(Some(&a), truth.as_deref()).unwrap();
            let le = l.loss(None, truth.as_deref()).unwrap();
            sum_a += la;
            sum_a2 += la * la;
            sum_e += le;
            sum_e2 += le * le;
        }
        let nf = n as f64;
        let (ma, me) = (sum_a / nf, sum_e / nf);
        let se_a = ((sum_a2 / nf - ma * ma) / nf).sqrt();
        let se_e = ((sum_e2 / nf - me * me) / nf).sqrt();
        assert!(
            (ma - e.expected_loss_singleton).abs() < 5.0 * se_a,
            "{k}: {ma} vs {}",
            e.expected_loss_singleton
        );
        assert!(
            (me - e.expected_loss_empty).abs() < 5.0 * se_e,
            "{k}: {me} vs {}",
            e.expected_loss_empty
        );
    }
}

#[test]
fn thm3_per_component_of_a_multi_bernoulli() {
    let comps = vec![
        (0.9, gaussian(&[0.0, 0.0], &[0.2, 0.0, 0.0, 0.2])),
        (0.55, gaussian(&[5.0, 5.0], &[4.0, 0.0, 0.0, 4.0])),
        (0.3, gaussian(&[-5.0, 2.0], &[0.1, 0.0, 0.0, 0.1])),
        (
            0.7,
            SpatialDensity::particles(ParticleSet::new(&[[9.0, 9.0]], None).unwrap()),
        ),
    ];
    let l = loss(Costs::mpe(), 1.0);
    let m = multi_bernoulli_estimate(&comps, &l).unwrap();
    for (i, (p, s)) in comps.iter().enumerate() {
        let e = estimate(*p, s, &l).unwrap();
        assert_eq!(m.components[i], e);
    }
    // Component 1 has p > ½ but too spread a density; component 2 has p < ½.
    assert_eq!(m.reported, vec![0, 3]);
    assert_eq!(m.points(), vec![&[0.0, 0.0][..], &[9.0, 9.0][..]]);
    let bad = vec![(1.2, gaussian(&[0.0], &[1.0]))];
    assert_eq!(
        multi_bernoulli_estimate(&bad, &l).unwrap_err().field(),
        "components[0].existence"
    );
    // at most MAX_MULTI_BERNOULLI_COMPONENTS components
    assert!(check_multi_bernoulli_count(MAX_MULTI_BERNOULLI_COMPONENTS).is_ok());
    let point = SpatialDensity::particles(ParticleSet::new(&[[0.0]], None).unwrap());
    let many = vec![(0.5, point); MAX_MULTI_BERNOULLI_COMPONENTS + 1];
    let e = multi_bernoulli_estimate(&many, &l).unwrap_err();
    assert_eq!(
        alloc::string::ToString::to_string(&e),
        "components has 10001 entries, at most 10000 are supported"
    );
}

#[test]
fn gradient_of_q_matches_finite_differences() {
    use super::ball::GaussianBall;
    for eig in [
        &[0.8][..],
        &[0.3, 1.0],
        &[0.2, 0.5, 1.1],
        &[0.3, 0.4, 0.8, 1.0],
        &[0.3, 0.4, 0.6, 0.8, 1.0],
    ] {
        let d = eig.len();
        let mean: Vec<f64> = (0..d).map(|i| 0.2 * i as f64).collect();
        let cov = if d == 1 {
            eig.to_vec()
        } else {
            rotated_cov(eig)
        };
        let ball =
            GaussianBall::new(Gaussian::from_slices(&mean, &cov, "d").unwrap(), "d").unwrap();
        let center: Vec<f64> = (0..d).map(|i| 0.5 - 0.3 * i as f64).collect();
        let r = 1.1;
        let (b, g) =
            ball.outside_with_gradient(&center, r, 1e-12, &core::cell::Cell::new(usize::MAX));
        assert!((b.outside - ball.outside(&center, r, 1e-12).outside).abs() < 1e-11);
        let h = 1e-4;
        for i in 0..d {
            let mut a = center.clone();
            a[i] += h;
            let up = ball.outside(&a, r, 1e-13).outside;
            a[i] -= 2.0 * h;
            let down = ball.outside(&a, r, 1e-13).outside;
            let fd = (up - down) / (2.0 * h);
            assert!((g[i] - fd).abs() < 1e-6, "d={d} i={i}: {} vs {fd}", g[i]);
        }
        assert!(g.iter().any(|x| x.abs() > 1e-3));
    }
}

#[test]
fn nearly_singular_covariances_reduce_to_lower_dimensions() {
    // A direction with variance 1e-14 (2D, nested) or 1e-12 (6D, inversion) is almost
    // deterministic: q equals the lower-dimensional q with the radius shrunk by the offset
    // along it, √(r² − c²).
    let (r, c) = (1.0, 0.6);
    let thin = gaussian(&[0.0, 0.0], &[1e-14, 0.0, 0.0, 0.7]);
    let q2 = thin.prob_outside_ball(&[c, 0.2], r).unwrap();
    let q1 = gaussian(&[0.0], &[0.7])
        .prob_outside_ball(&[0.2], (r * r - c * c).sqrt())
        .unwrap();
    assert!((q2 - q1).abs() < 1e-9, "{q2} vs {q1}");
    let eig = [1e-12, 0.3, 0.5, 0.7, 0.9, 1.1];
    let cov6: Vec<f64> = (0..36)
        .map(|k| if k % 7 == 0 { eig[k / 7] } else { 0.0 })
        .collect();
    let cov5: Vec<f64> = (0..25)
        .map(|k| if k % 6 == 0 { eig[1 + k / 6] } else { 0.0 })
        .collect();
    let r = 2.0;
    let q6 = gaussian(&[0.0; 6], &cov6)
        .prob_outside_ball(&[c, 0.1, 0.2, 0.0, -0.1, 0.3], r)
        .unwrap();
    let q5 = gaussian(&[0.0; 5], &cov5)
        .prob_outside_ball(&[0.1, 0.2, 0.0, -0.1, 0.3], (r * r - c * c).sqrt())
        .unwrap();
    assert!((q6 - q5).abs() < 1e-9, "{q6} vs {q5}");
}

#[test]
fn eq12_mmuc_of_a_mixture_with_a_point_like_component() {
    // Found by the boundary fuzzer: a 3D component 1e-75 wide made the search's tolerance
    // 1e-82 and one estimate took 15 s. With the length scale floored at 1e-6 r0 the search
    // still finds the point that covers the wide component (weight 0.83): its mean, to well
    // within the ball.
    let a = gaussian(
        &[0.0, 0.0, -0.018],
        &[1e-4, 0.0, 0.0, 0.0, 1e-4, 0.0, 0.0, 0.0, 1e-4],
    );
    let b_g = Gaussian::from_slices(
        &[0.0, 1.0, 2.0],
        &[1e-150, 0.0, 0.0, 0.0, 1e-150, 0.0, 0.0, 0.0, 1e-150],
        "b",
    )
    .unwrap();
    let a_g = a.as_gaussian().unwrap().clone();
    let m = GaussianMixture::new(vec![(5.7e-200, a_g), (1.14e-200, b_g)], "m").unwrap();
    let s = SpatialDensity::mixture(&m).unwrap();
    let r = 0.0648;
    let best = s.mmuc(r).unwrap();
    let at_a = s.prob_outside_ball(&[0.0, 0.0, -0.018], r).unwrap();
    assert!(
        best.miss_probability <= at_a + 1e-9,
        "{} vs {at_a}",
        best.miss_probability
    );
    let off: f64 = best
        .center
        .iter()
        .zip([0.0, 0.0, -0.018])
        .map(|(x, y)| (x - y) * (x - y))
        .sum();
    assert!(off.sqrt() < 1e-3, "{:?}", best.center);
}

/// Issue 26 (point 7): a radius near the largest double made the particle search's squared
/// lengths overflow and the centre NaN; the search now runs on an exactly scaled copy.
#[test]
fn eq12_particle_mmuc_with_a_huge_radius_is_finite() {
    let pts = [[1e-53, 0.0], [1e308, 0.0], [0.0, 0.0]];
    let s = SpatialDensity::particles(ParticleSet::new(&pts, None).unwrap());
    for r in [1e308, f64::MAX, 1e200, 2.6e120] {
        let m = s.mmuc(r).unwrap();
        assert!(
            m.center.iter().all(|c| c.is_finite()),
            "r={r}: {:?}",
            m.center
        );
        assert!((0.0..=1.0).contains(&m.miss_probability), "r={r}");
        let e = estimate(0.9, &s, &loss(Costs::mpe(), r)).unwrap();
        assert!(e.estimate.as_ref().unwrap().iter().all(|c| c.is_finite()));
        assert!(!e.expected_loss().is_nan());
    }
    // The ball of radius 1e308 about the centre covers all three (their span is 1e308).
    let m = s.mmuc(1e308).unwrap();
    assert_eq!(m.miss_probability, 0.0);
    assert!((m.center[0] - 5e307).abs() <= 1e292, "{:?}", m.center);
    // 1D and 3D take the same path.
    let line = [[0.0], [1e308], [-1e308], [3.0]];
    let s = SpatialDensity::particles(ParticleSet::new(&line, None).unwrap());
    let m = s.mmuc(1e308).unwrap();
    assert!(
        m.center[0].is_finite() && m.miss_probability <= 0.25,
        "{m:?}"
    );
    let cube = [
        [0.0, 0.0, 1e308],
        [1e308, 0.0, 0.0],
        [0.0, 1e-53, 0.0],
        [0.0, 0.0, 0.0],
    ];
    let s = SpatialDensity::particles(ParticleSet::new(&cube, None).unwrap());
    let m = s.mmuc(1e308).unwrap();
    assert!(m.center.iter().all(|c| c.is_finite()), "{m:?}");
}

/// Issue 26 (point 7): the MMUC search's size caps, named by the array that passes them.
#[test]
fn eq12_mmuc_size_caps_name_the_array() {
    let comps: Vec<(f64, &[f64], &[f64])> = (0..=MAX_MMUC_COMPONENTS)
        .map(|_| (1.0, &[0.0, 0.0][..], &[1.0, 0.0, 0.0, 1.0][..]))
        .collect();
    let big = mixture(&comps);
    let e = big.check_mmuc_size().unwrap_err();
    assert_eq!(e.field(), "density.mixture");
    assert!(mixture(&comps[1..]).check_mmuc_size().is_ok());
    let pts: Vec<[f64; 2]> = (0..=MAX_MMUC_PARTICLES).map(|i| [i as f64, 0.0]).collect();
    let s = SpatialDensity::particles(ParticleSet::new(&pts, None).unwrap());
    assert_eq!(
        s.check_mmuc_size().unwrap_err().field(),
        "density.particles"
    );
    let s = SpatialDensity::particles(ParticleSet::new(&pts[1..], None).unwrap());
    assert!(s.check_mmuc_size().is_ok());
    let line: Vec<[f64; 1]> = (0..100_000).map(|i| [i as f64]).collect();
    let s = SpatialDensity::particles(ParticleSet::new(&line, None).unwrap());
    assert!(s.check_mmuc_size().is_ok());
}

/// Fuzz seed 198626: costs at the largest double. ρ_{a} = (1 − p) c10 + p (c11 + c q)
/// met 0 · ∞ at p = 0 (c11 + c q overflowed); the loss is now c10 there, and ±∞ or finite,
/// never NaN, for every p and q.
#[test]
fn eq13_expected_loss_at_the_largest_costs_is_never_nan() {
    let m = f64::MAX;
    let c = Costs::new(m, m, m, m, m).unwrap();
    assert_eq!(expected_loss_singleton(&c, 0.0, 0.5).unwrap(), m);
    for p in [0.0, 1e-300, 0.25, 0.5, 1.0] {
        for q in [0.0, 0.5, 1.0] {
            let rho = expected_loss_singleton(&c, p, q).unwrap();
            assert!(!rho.is_nan(), "p {p} q {q}");
            assert!(!expected_loss_empty(&c, p).unwrap().is_nan(), "p {p}");
        }
    }
    // in range the formula's bits are unchanged
    let c = Costs::new(0.5, 2.0, 3.0, 0.25, 7.0).unwrap();
    let (p, q) = (0.3, 0.2);
    assert_eq!(
        expected_loss_singleton(&c, p, q).unwrap(),
        (1.0 - p) * 3.0 + p * (0.25 + 7.0 * q)
    );
}

#[test]
fn density_covariances_say_which_property_fails() {
    use alloc::string::ToString;
    let say = |cov: &[f64]| {
        SpatialDensity::gaussian_from_slices(&[0.0, 0.0], cov)
            .unwrap_err()
            .to_string()
    };
    assert_eq!(
        say(&[1.0, 0.5, 0.4, 1.0]),
        "density.cov is not symmetric: [0][1] = 0.5 but [1][0] = 0.4"
    );
    assert_eq!(
        say(&[1.25, 0.0, 0.0, -0.25]),
        "density.cov is not positive definite (smallest eigenvalue -0.25)"
    );
    let g = |cov: &[f64]| Gaussian::from_slices(&[0.0, 0.0], cov, "density.mixture[1]");
    let ok = g(&[1.0, 0.0, 0.0, 1.0]).unwrap();
    assert_eq!(
        g(&[1.0, 0.5, 0.4, 1.0]).unwrap_err().to_string(),
        "density.mixture[1].cov is not symmetric: [0][1] = 0.5 but [1][0] = 0.4"
    );
    assert_eq!(
        g(&[1.25, 0.0, 0.0, -0.25]).unwrap_err().to_string(),
        "density.mixture[1].cov is not positive definite (smallest eigenvalue -0.25)"
    );
    let mix = GaussianMixture::new(vec![(1.0, ok.clone()), (1.0, ok)], "density.mixture").unwrap();
    assert!(SpatialDensity::mixture(&mix).is_ok());
}

/// The fuzzer's slow MMUC search (issue 26, seed 602302): a 3-D mixture whose heavy
/// component is nearly degenerate (variances 1.8e-292 to 8.4e-9; one eigenvalue rounds to 0)
/// and whose other component weighs 1.6e-127. Each evaluation of q was within its own budget,
/// but the search evaluated q some 1,600 times (2.6 s in Node). The whole search now stops at
/// [`mmuc::MMUC_SEARCH_BUDGET`]: this one spends all of it, and still returns a centre inside
/// which the heavy component lies (q ≈ 2.5e-140, the light component's tail).
#[test]
fn mmuc_search_over_a_degenerate_mixture_stops_at_its_budget() {
    use nalgebra::{DMatrix, DVector};
    let light = Gaussian::new(
        DVector::from_vec(vec![
            -1.4035815575359678e-285,
            -4.5651984964795094e-178,
            -2.9309333900897442e-173,
        ]),
        DMatrix::from_row_slice(3, 3, &[0.001, 0.0, 0.0, 0.0, 0.001, 0.0, 0.0, 0.0, 0.001]),
        "light",
    )
    .unwrap();
    let heavy = Gaussian::new(
        DVector::from_vec(vec![
            1.3842930252453666e-130,
            -1.3556882110795213e-61,
            -9.471772948376036e-132,
        ]),
        DMatrix::from_row_slice(
            3,
            3,
            &[
                1.1150655654625976e-11,
                -5.173865028903137e-271,
                -2.9191461212067335e-110,
                -5.173865028903137e-271,
                1.8461991266345536e-292,
                1.3789151307041794e-249,
                -2.9191461212067335e-110,
                1.3789151307041794e-249,
                8.405850856824145e-9,
            ],
        ),
        "heavy",
    )
    .unwrap();
    let m =
        GaussianMixture::new(vec![(1.5943428659959995e-127, light), (1.0, heavy)], "m").unwrap();
    let d = SpatialDensity::mixture(&m).unwrap();
    let radius = 0.2503930865808104;
    let density::Repr::Mixture { components, mean } = d.repr() else {
        panic!("a mixture")
    };
    let (r, spent) = mmuc::mixture_mmuc_within(components, mean, radius, mmuc::MMUC_SEARCH_BUDGET);
    assert_eq!(spent, mmuc::MMUC_SEARCH_BUDGET);
    assert_eq!(r, d.mmuc(radius).unwrap());
    assert_eq!(r.method, MmucMethod::MixtureSearch);
    // Within 1e-6 r0 of the heavy component's mean, and q is the light one's tail only.
    assert!(
        r.center.iter().all(|c| c.abs() < 1e-6 * radius),
        "{:?}",
        r.center
    );
    assert!(r.miss_probability < 1e-130 && r.error < 1e-130, "{r:?}");
}

/// A search cut short (a budget of 0, or of a few evaluations) still returns a starting point
/// or better, with q at it computed in full: the same value as a fresh evaluation there.
#[test]
fn mmuc_search_cut_short_returns_a_start_with_q_in_full() {
    let a = Gaussian::from_slices(&[0.0, 0.0], &[0.3, 0.1, 0.1, 0.2], "a").unwrap();
    let b = Gaussian::from_slices(&[1.0, 0.5], &[0.2, 0.0, 0.0, 0.4], "b").unwrap();
    let m = GaussianMixture::new(vec![(0.6, a), (0.4, b)], "m").unwrap();
    let d = SpatialDensity::mixture(&m).unwrap();
    let density::Repr::Mixture { components, mean } = d.repr() else {
        panic!("a mixture")
    };
    let radius = 0.5;
    let (full, spent) = mmuc::mixture_mmuc_within(components, mean, radius, usize::MAX);
    assert!(spent > 0 && spent < mmuc::MMUC_SEARCH_BUDGET, "{spent}");
    for budget in [0, 1, 50, spent / 2] {
        let (cut, used) = mmuc::mixture_mmuc_within(components, mean, radius, budget);
        assert!(used <= budget);
        let q = d.prob_outside_ball(&cut.center, radius).unwrap();
        assert_eq!(cut.miss_probability, q, "budget {budget}");
        // never better than the full search (up to its tolerance)
        assert!(
            cut.miss_probability >= full.miss_probability - 1e-9,
            "budget {budget}"
        );
    }
    let (zero, _) = mmuc::mixture_mmuc_within(components, mean, radius, 0);
    assert_eq!(
        zero.center,
        vec![0.0, 0.0],
        "the first start, the first component's mean"
    );
}

/// The options types of the bindings: the same numbers as [`estimate`], [`SpatialDensity::mmuc`]
/// and [`multi_bernoulli_estimate`], flattened, and their validation naming the Rust path.
#[test]
fn options_types_flatten_the_estimates_and_name_the_field() {
    let s = gaussian(&[1.0, -2.0], &[1.0, 0.3, 0.3, 0.5]);
    let o = BernoulliEstimateOptions {
        existence: 0.7,
        density: s.clone(),
        radius: 1.0,
        costs: Costs::mpe(),
    };
    let full = estimate(0.7, &s, &loss(Costs::mpe(), 1.0)).unwrap();
    let r = o.estimate().unwrap();
    assert_eq!(r, BernoulliReport::from(&full));
    assert_eq!(
        (r.declare, r.estimate.as_deref(), &r.mmuc[..]),
        (
            full.declare,
            full.estimate.as_deref(),
            &full.mmuc.center[..]
        )
    );
    assert_eq!(r.threshold.to_bits(), full.threshold.gamma.to_bits());
    assert_eq!(r.miss_probability, full.mmuc.miss_probability);
    let bad = |o: BernoulliEstimateOptions| {
        alloc::string::String::from(o.estimate().unwrap_err().field())
    };
    assert_eq!(
        bad(BernoulliEstimateOptions {
            existence: 1.5,
            ..o.clone()
        }),
        "existence"
    );
    assert_eq!(
        bad(BernoulliEstimateOptions {
            radius: 0.0,
            ..o.clone()
        }),
        "radius"
    );
    // the MMUC search's size cap, before anything else
    let points: Vec<[f64; 2]> = (0..=MAX_MMUC_PARTICLES).map(|i| [i as f64, 0.0]).collect();
    let many = SpatialDensity::particles(ParticleSet::new(&points, None).unwrap());
    assert_eq!(
        bad(BernoulliEstimateOptions {
            existence: 1.5,
            density: many.clone(),
            ..o.clone()
        }),
        "density.particles"
    );

    let m = MmucOptions {
        density: s.clone(),
        radius: 1.0,
    };
    let mm = s.mmuc(1.0).unwrap();
    assert_eq!(
        m.estimate().unwrap(),
        MmucEstimate {
            center: mm.center.clone(),
            miss_probability: mm.miss_probability,
            method: MmucMethod::GaussianMean
        }
    );
    let m_bad = MmucOptions {
        density: many.clone(),
        radius: 1.0,
    };
    assert_eq!(m_bad.estimate().unwrap_err().field(), "density.particles");

    let comps = vec![
        BernoulliComponent {
            existence: 0.9,
            density: s.clone(),
        },
        BernoulliComponent {
            existence: 0.2,
            density: gaussian(&[4.0, 4.0], &[1.0, 0.0, 0.0, 1.0]),
        },
    ];
    let mb = MultiBernoulliPointOptions {
        components: comps.clone(),
        radius: 1.0,
        costs: Costs::mpe(),
    };
    let pairs: Vec<(f64, SpatialDensity)> = comps
        .iter()
        .map(|c| (c.existence, c.density.clone()))
        .collect();
    let full = multi_bernoulli_estimate(&pairs, &loss(Costs::mpe(), 1.0)).unwrap();
    let r = mb.estimate().unwrap();
    assert_eq!(r, MultiBernoulliReport::from(&full));
    assert_eq!(r.reported, vec![0]);
    assert_eq!(r.estimates, vec![full.components[0].mmuc.center.clone()]);
    let mut capped = mb.clone();
    capped.components[1].density = many;
    assert_eq!(
        capped.estimate().unwrap_err().field(),
        "components[1].density.particles"
    );
    let mut improbable = mb.clone();
    improbable.components[1].existence = -0.1;
    assert_eq!(
        improbable.estimate().unwrap_err().field(),
        "components[1].existence"
    );
    let mut far = mb;
    far.radius = f64::NAN;
    assert_eq!(far.estimate().unwrap_err().field(), "radius");
}

#[test]
fn eq7_probability_outside_ball_options_ask_the_density() {
    let density = SpatialDensity::gaussian_from_slices(&[0.0], &[1.0]).unwrap();
    let o = ProbabilityOutsideBallOptions {
        density: density.clone(),
        center: vec![0.5],
        radius: 1.0,
    };
    let q = |c: &[f64], r| density.prob_outside_ball(c, r);
    assert_eq!(o.probability(), q(&[0.5], 1.0));
    let wrong = ProbabilityOutsideBallOptions {
        center: vec![0.0, 0.0],
        ..o.clone()
    };
    assert_eq!(wrong.probability(), q(&[0.0, 0.0], 1.0));
    assert!(wrong.probability().is_err());
    let bad = ProbabilityOutsideBallOptions { radius: -1.0, ..o };
    assert_eq!(bad.probability(), q(&[0.5], -1.0));
    assert!(bad.probability().is_err());
}
