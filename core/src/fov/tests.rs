//! Every proposition of Section VI against a Monte Carlo simulation of the RFS itself, the
//! multi-Bernoulli forms against each other, and the pmfs' sums and moments.

use super::*;
use crate::Error;
use crate::gaussian::{Gaussian, GaussianMixture};
use crate::regions::Region;
use alloc::string::ToString;
use alloc::vec;
use alloc::vec::Vec;
use rand::{RngExt, SeedableRng, rngs::SmallRng};

fn g2(m: [f64; 2], sx: f64, sy: f64, r: f64) -> Gaussian {
    Gaussian::from_slices(&m, &[sx * sx, r * sx * sy, r * sx * sy, sy * sy], "p").unwrap()
}

/// A FoV and a handful of Gaussians straddling its boundary.
fn setup() -> (Region, Vec<Gaussian>) {
    let fov =
        Region::polygon(&[[-1.0, -1.0], [1.5, -0.5], [1.0, 1.2], [-0.5, 0.8]], "fov").unwrap();
    let gs = vec![
        g2([0.0, 0.0], 0.5, 0.4, 0.3),
        g2([1.2, 0.2], 0.3, 0.6, -0.5),
        g2([-1.0, 1.0], 0.7, 0.7, 0.0),
        g2([2.5, -2.0], 0.4, 0.3, 0.8),
        g2([0.5, -0.8], 0.2, 0.2, 0.1),
    ];
    (fov, gs)
}

fn pmf_stats(pmf: &[f64]) -> (f64, f64, f64) {
    let total: f64 = pmf.iter().sum();
    let mean: f64 = pmf.iter().enumerate().map(|(n, p)| n as f64 * p).sum();
    let var: f64 = pmf
        .iter()
        .enumerate()
        .map(|(n, p)| (n as f64 - mean) * (n as f64 - mean) * p)
        .sum();
    (total, mean, var)
}

/// Empirical frequencies of `trials` draws against `pmf`: every bin within 5 standard
/// errors (plus 1/trials), and no draws beyond the pmf's support where it is < 1e-6.
fn assert_matches_mc(pmf: &[f64], counts: &[usize], trials: usize, label: &str) {
    let t = trials as f64;
    for n in 0..pmf.len().max(counts.len()) {
        let p = pmf.get(n).copied().unwrap_or(0.0);
        let f = counts.get(n).copied().unwrap_or(0) as f64 / t;
        let se = (p * (1.0 - p) / t).sqrt();
        assert!(
            (f - p).abs() <= 5.0 * se + 1.0 / t,
            "{label}: n={n}: simulated {f} vs pmf {p} (se {se})"
        );
    }
}

fn count_inside(fov: &Region, states: &[nalgebra::DVector<f64>]) -> usize {
    states.iter().filter(|x| fov.contains(x.as_slice())).count()
}

fn bump(counts: &mut Vec<usize>, n: usize) {
    if counts.len() <= n {
        counts.resize(n + 1, 0);
    }
    counts[n] += 1;
}

/// A Poisson draw by inversion (small means).
fn poisson_draw(rng: &mut SmallRng, mean: f64) -> usize {
    let u: f64 = rng.random_range(0.0..1.0);
    let mut p = (-mean).exp();
    let mut cdf = p;
    let mut n = 0;
    while u > cdf && n < 1000 {
        n += 1;
        p *= mean / n as f64;
        cdf += p;
    }
    n
}

#[test]
fn eq78_poisson_closed_form_is_the_series_and_the_simulation() {
    // The literal double series (78), truncated far out, against the closed form.
    for (lin, lout) in [(0.3, 2.0), (2.5, 0.7), (7.0, 11.0)] {
        let c = poisson(lin).unwrap();
        for (n, &p) in c.pmf.iter().enumerate() {
            let mut s = 0.0;
            for m in n..n + 200 {
                let ln = -(lin + lout) + n as f64 * f64::ln(lin) + (m - n) as f64 * f64::ln(lout)
                    - crate::math::special::ln_factorial(n)
                    - crate::math::special::ln_factorial(m - n);
                s += ln.exp();
            }
            assert!((p - s).abs() <= 1e-15 + 1e-13 * p, "n={n}: {p} vs {s}");
        }
        let (total, mean, var) = pmf_stats(&c.pmf);
        assert!(c.truncated < 1e-15);
        assert!((total + c.truncated - 1.0).abs() < 1e-14);
        assert!((mean - lin).abs() < 1e-12 && (var - lin).abs() < 1e-11);
    }
    // Large means stay accurate (Loader's form) and are bounded in length.
    for lam in [150.0, 1e4, 2e5] {
        let c = poisson(lam).unwrap();
        let (total, mean, _) = pmf_stats(&c.pmf);
        assert!((total - 1.0).abs() < 1e-12, "λ={lam}: sum {total}");
        assert!((mean - lam).abs() < 1e-8 * lam);
        assert!(c.pmf.len() < (lam + 10.0 * lam.sqrt() + 50.0) as usize);
    }
    assert_eq!(poisson(0.0).unwrap().pmf, vec![1.0]);
    assert_eq!(poisson(-1.0).unwrap_err().field(), "inside");
    assert!(matches!(poisson(2e6), Err(Error::Unsupported { .. })));

    // Simulation of the Poisson RFS: N ~ Poisson(N_X), each object from D/N_X.
    let (fov, gs) = setup();
    let weights = [0.8, 1.1, 0.4, 0.9, 0.3];
    let phd = GaussianMixture::new(
        weights.iter().copied().zip(gs.iter().cloned()).collect(),
        "rfs.poisson",
    )
    .unwrap();
    for pd in [1.0, 0.6] {
        let res = fov_cardinality(&MultiObjectDensity::Poisson(phd.clone()), &fov, pd).unwrap();
        let nx: f64 = weights.iter().sum();
        let mut rng = SmallRng::seed_from_u64(51);
        let trials = 40_000;
        let mut counts = Vec::new();
        for _ in 0..trials {
            let n = poisson_draw(&mut rng, nx);
            let mut inside = 0;
            for _ in 0..n {
                let mut u = rng.random_range(0.0..nx);
                let mut k = 0;
                while k + 1 < weights.len() && u >= weights[k] {
                    u -= weights[k];
                    k += 1;
                }
                let x = gs[k].sample(&mut rng);
                if fov.contains(x.as_slice()) && rng.random_range(0.0..1.0) < pd {
                    inside += 1;
                }
            }
            bump(&mut counts, inside);
        }
        assert_matches_mc(&res.cardinality.pmf, &counts, trials, "poisson");
        assert_eq!(res.mass_in_fov.len(), 5);
    }
}

#[test]
fn eq84_iid_cluster_matches_the_series_and_the_simulation() {
    let rho = [0.1, 0.2, 0.3, 0.25, 0.1, 0.05];
    for q in [0.0, 0.37, 1.0] {
        let c = iid_cluster(&rho, q).unwrap();
        for n in 0..rho.len() {
            let mut s = 0.0;
            for (m, &p) in rho.iter().enumerate().skip(n) {
                let binom = (0..n).fold(1.0, |b, i| b * (m - i) as f64 / (i + 1) as f64);
                s += p * binom * q.powi(n as i32) * (1.0 - q).powi((m - n) as i32);
            }
            let got = c.pmf.get(n).copied().unwrap_or(0.0);
            assert!((got - s).abs() < 1e-15, "q={q} n={n}: {got} vs {s}");
        }
        let (total, mean, var) = pmf_stats(&c.pmf);
        assert!((total - 1.0).abs() < 1e-14);
        assert!((mean - c.mean).abs() < 1e-14 && (var - c.variance).abs() < 1e-13);
    }
    // The tail is trimmed below 1e-15: a Poisson(3) cardinality given to n = 60.
    let long: Vec<f64> = (0..=60)
        .map(|n| crate::math::special::poisson_pmf(3.0, n))
        .collect();
    let c = iid_cluster(&long, 0.5).unwrap();
    assert!(c.pmf.len() < 30 && c.truncated < 1e-15);
    assert_eq!(
        iid_cluster(&[0.5, 0.6], 0.5).unwrap_err().field(),
        "cardinality"
    );
    assert_eq!(
        iid_cluster(&[0.5, -0.5, 1.0], 0.5).unwrap_err().field(),
        "cardinality[1]"
    );

    // Simulation: N ~ ρ, objects i.i.d. from the mixture p.
    let (fov, gs) = setup();
    let w = [0.3, 0.25, 0.2, 0.15, 0.1];
    let density =
        GaussianMixture::new(w.iter().copied().zip(gs.iter().cloned()).collect(), "d").unwrap();
    let res = fov_cardinality(
        &MultiObjectDensity::IidCluster(IidCluster {
            cardinality: rho.to_vec(),
            density,
        }),
        &fov,
        0.8,
    )
    .unwrap();
    let mut rng = SmallRng::seed_from_u64(52);
    let trials = 40_000;
    let mut counts = Vec::new();
    for _ in 0..trials {
        let mut u = rng.random_range(0.0..1.0);
        let mut n = 0;
        while n + 1 < rho.len() && u >= rho[n] {
            u -= rho[n];
            n += 1;
        }
        let mut inside = 0;
        for _ in 0..n {
            let mut v = rng.random_range(0.0..1.0);
            let mut k = 0;
            while k + 1 < w.len() && v >= w[k] {
                v -= w[k];
                k += 1;
            }
            let x = gs[k].sample(&mut rng);
            if fov.contains(x.as_slice()) && rng.random_range(0.0..1.0) < 0.8 {
                inside += 1;
            }
        }
        bump(&mut counts, inside);
    }
    assert_matches_mc(&res.cardinality.pmf, &counts, trials, "iid cluster");
}

#[test]
fn eq88_eq90_multi_bernoulli_forms_agree() {
    let mut rng = SmallRng::seed_from_u64(53);
    for m in 0..=MAX_ENUM {
        for _ in 0..3 {
            let r: Vec<f64> = (0..m)
                .map(|_| match rng.random_range(0..6) {
                    0 => 1.0,
                    1 => 0.0,
                    _ => rng.random_range(0.0..1.0),
                })
                .collect();
            let mass: Vec<f64> = (0..m).map(|_| rng.random_range(0.0..1.0)).collect();
            let inside: Vec<f64> = r.iter().zip(&mass).map(|(a, b)| a * b).collect();
            let stable = multi_bernoulli(&inside).unwrap();
            let enumerated = multi_bernoulli_enumerated(&r, &mass).unwrap();
            let dft = multi_bernoulli_dft(&inside).unwrap();
            assert_eq!(stable.pmf.len(), m + 1);
            for n in 0..=m {
                assert!((stable.pmf[n] - enumerated[n]).abs() < 1e-14, "m={m}");
                assert!((stable.pmf[n] - dft[n]).abs() < 1e-14);
            }
            let (total, mean, var) = pmf_stats(&stable.pmf);
            assert!((total - 1.0).abs() < 1e-14);
            assert!((mean - stable.mean).abs() < 1e-13 && (var - stable.variance).abs() < 1e-13);
        }
    }
    // Large M: the stable form is exact, nonnegative and sums to 1; the DFT agrees.
    for m in [100usize, 1000, 10_000] {
        let inside: Vec<f64> = (0..m).map(|_| rng.random_range(0.0..1.0)).collect();
        let stable = multi_bernoulli(&inside).unwrap();
        assert!(stable.pmf.iter().all(|&p| p >= 0.0 && p.is_finite()));
        let total = crate::math::sum::sum(stable.pmf.iter().copied());
        assert!((total - 1.0).abs() <= 1e-12, "M={m}: {total}");
        let (_, mean, var) = pmf_stats(&stable.pmf);
        assert!((mean - stable.mean).abs() < 1e-9 * stable.mean);
        assert!((var - stable.variance).abs() < 1e-8 * stable.variance);
        if m <= 1000 {
            let dft = multi_bernoulli_dft(&inside).unwrap();
            let worst = stable
                .pmf
                .iter()
                .zip(&dft)
                .map(|(a, b)| (a - b).abs())
                .fold(0.0, f64::max);
            assert!(worst < 1e-13, "M={m}: DFT differs by {worst:e}");
        }
    }
    let e = multi_bernoulli_enumerated(&[0.5; 13], &[0.5; 13]).unwrap_err();
    assert!(matches!(e, Error::Unsupported { .. }), "{e}");
    assert_eq!(e.field(), "existence");
    assert_eq!(
        multi_bernoulli(&[0.2, 1.5]).unwrap_err().field(),
        "inside[1]"
    );
    assert_eq!(
        multi_bernoulli_enumerated(&[0.5], &[0.5, 0.5])
            .unwrap_err()
            .field(),
        "mass"
    );
}

const MAX_ENUM: usize = super::pmf::MAX_ENUMERATED;

#[test]
fn eq88_multi_bernoulli_matches_the_simulation() {
    let (fov, gs) = setup();
    let r = [0.9, 0.5, 1.0, 0.7, 0.35];
    let comps: Vec<(f64, Gaussian)> = r.iter().copied().zip(gs.iter().cloned()).collect();
    for pd in [1.0, 0.7] {
        let res =
            fov_cardinality(&MultiObjectDensity::MultiBernoulli(comps.clone()), &fov, pd).unwrap();
        // masses against Monte Carlo of each density alone
        let mut rng = SmallRng::seed_from_u64(54);
        let trials = 40_000;
        let mut counts = Vec::new();
        for _ in 0..trials {
            let mut states = Vec::new();
            for (ri, g) in &comps {
                if rng.random_range(0.0..1.0) < *ri {
                    states.push(g.sample(&mut rng));
                }
            }
            let n = states
                .iter()
                .filter(|x| fov.contains(x.as_slice()) && rng.random_range(0.0..1.0) < pd)
                .count();
            bump(&mut counts, n);
        }
        assert_matches_mc(&res.cardinality.pmf, &counts, trials, "multi-Bernoulli");
        let want_mean: f64 = r
            .iter()
            .zip(&res.mass_in_fov)
            .map(|(a, m)| pd * a * m)
            .sum();
        assert!((res.cardinality.mean - want_mean).abs() < 1e-14);
    }
    let mut bad = comps.clone();
    bad[3].0 = 1.5;
    let e = fov_cardinality(&MultiObjectDensity::MultiBernoulli(bad), &fov, 1.0).unwrap_err();
    assert_eq!(e.field(), "rfs.multi_bernoulli[3].existence");
    let e = fov_cardinality(&MultiObjectDensity::MultiBernoulli(comps), &fov, 1.1).unwrap_err();
    assert_eq!(e.field(), "detection_probability");
}

#[test]
fn eq92_glmb_matches_the_simulation_and_reduces_to_multi_bernoulli() {
    let (fov, gs) = setup();
    let hyps = vec![
        (0.2, vec![]),
        (0.3, vec![gs[0].clone(), gs[1].clone()]),
        (0.4, vec![gs[0].clone(), gs[2].clone(), gs[4].clone()]),
        (0.1, vec![gs[3].clone()]),
    ];
    let res = fov_cardinality(&MultiObjectDensity::Glmb(hyps.clone()), &fov, 1.0).unwrap();
    assert_eq!(res.mass_in_fov.len(), 6);
    assert_eq!(res.cardinality.pmf.len(), 4);
    let (total, mean, var) = pmf_stats(&res.cardinality.pmf);
    assert!((total - 1.0).abs() < 1e-15);
    assert!((mean - res.cardinality.mean).abs() < 1e-14);
    assert!((var - res.cardinality.variance).abs() < 1e-14);
    let mut rng = SmallRng::seed_from_u64(55);
    let trials = 40_000;
    let mut counts = Vec::new();
    let w: Vec<f64> = hyps.iter().map(|h| h.0).collect();
    for _ in 0..trials {
        let mut u = rng.random_range(0.0..1.0);
        let mut h = 0;
        while h + 1 < w.len() && u >= w[h] {
            u -= w[h];
            h += 1;
        }
        let states: Vec<_> = hyps[h].1.iter().map(|g| g.sample(&mut rng)).collect();
        bump(&mut counts, count_inside(&fov, &states));
    }
    assert_matches_mc(&res.cardinality.pmf, &counts, trials, "GLMB");
    // One hypothesis with all labels: a multi-Bernoulli with r = 1.
    let one = fov_cardinality(
        &MultiObjectDensity::Glmb(vec![(1.0, gs.clone())]),
        &fov,
        0.9,
    )
    .unwrap();
    let mb = fov_cardinality(
        &MultiObjectDensity::MultiBernoulli(gs.iter().map(|g| (1.0, g.clone())).collect()),
        &fov,
        0.9,
    )
    .unwrap();
    for (a, b) in one.cardinality.pmf.iter().zip(&mb.cardinality.pmf) {
        assert!((a - b).abs() < 1e-15);
    }
    let e = fov_cardinality(&MultiObjectDensity::Glmb(vec![(0.5, vec![])]), &fov, 1.0).unwrap_err();
    assert_eq!(e.field(), "rfs.glmb");
    let e = fov_cardinality(
        &MultiObjectDensity::Glmb(vec![(1.5, vec![]), (-0.5, vec![])]),
        &fov,
        1.0,
    )
    .unwrap_err();
    assert_eq!(e.field(), "rfs.glmb[1].weight");
}

#[test]
fn front_door_names_fields() {
    let (fov, gs) = setup();
    let one_d = Gaussian::from_slices(&[0.0], &[1.0], "p").unwrap();
    let e = fov_cardinality(
        &MultiObjectDensity::MultiBernoulli(vec![(0.5, gs[0].clone()), (0.5, one_d.clone())]),
        &fov,
        1.0,
    )
    .unwrap_err();
    assert_eq!(e.field(), "rfs.multi_bernoulli[1].mean");
    let phd = GaussianMixture::new(vec![(1.0, gs[0].clone()), (2.0, one_d)], "rfs.poisson");
    // a mixture of mixed dimensions is already rejected when it is built
    assert_eq!(phd.unwrap_err().field(), "rfs.poisson[1].mean");
    let density = GaussianMixture::new(vec![(0.5, gs[0].clone())], "d").unwrap();
    let e = fov_cardinality(
        &MultiObjectDensity::IidCluster(IidCluster {
            cardinality: vec![0.5, 0.5],
            density,
        }),
        &fov,
        1.0,
    )
    .unwrap_err();
    assert_eq!(e.field(), "rfs.iid_cluster.density");
    let density = GaussianMixture::new(vec![(1.0, gs[0].clone())], "d").unwrap();
    let e = fov_cardinality(
        &MultiObjectDensity::IidCluster(IidCluster {
            cardinality: vec![0.5, f64::NAN],
            density,
        }),
        &fov,
        1.0,
    )
    .unwrap_err();
    assert_eq!(e.field(), "rfs.iid_cluster.cardinality[1]");
}

/// Issue 26 (point 7): a FoV box whose corner has both coordinates near the largest double
/// under a correlated Gaussian gave a NaN mass, pmf and moments; they are finite now.
#[test]
fn eq8_fov_box_at_the_largest_doubles_gives_finite_pmfs() {
    let fov = Region::axis_box(&[0.0, 0.0], &[1e308, 1e308], "fov").unwrap();
    let g = g2([0.0, 0.0], 1.0, 1.0, 0.5);
    let res = fov_cardinality(
        &MultiObjectDensity::MultiBernoulli(vec![(0.5, g.clone())]),
        &fov,
        1.0,
    )
    .unwrap();
    assert!((res.mass_in_fov[0] - 1.0 / 3.0).abs() < 1e-15);
    assert!((res.cardinality.pmf[1] - 0.5 / 3.0).abs() < 1e-15);
    assert!(res.cardinality.mean.is_finite() && res.cardinality.variance.is_finite());
    let phd = GaussianMixture::new(vec![(1.0, g)], "rfs.poisson").unwrap();
    let res = fov_cardinality(&MultiObjectDensity::Poisson(phd), &fov, 1.0).unwrap();
    assert!((res.cardinality.mean - 1.0 / 3.0).abs() < 1e-15);
}

/// A FoV of more dimensions than the density (a 3-D box over 2-D objects, the likelier
/// mistake) names the FoV's field first and the mean it disagrees with, in matrix terms.
#[test]
fn eq75_a_fov_of_more_dimensions_names_its_own_field() {
    let mb = MultiObjectDensity::MultiBernoulli(vec![(0.5, g2([0.0, 0.0], 1.0, 1.0, 0.0))]);
    let fov = Region::axis_box(&[-1.0, -1.0, -1.0], &[1.0, 1.0, 1.0], "fov").unwrap();
    let e = fov_cardinality(&mb, &fov, 1.0).unwrap_err();
    assert_eq!(
        e.to_string(),
        "fov.box.min has length 3 but rfs.multi_bernoulli[0].mean has length 2"
    );
    let ball = Region::ball(&[0.0, 0.0, 0.0], 1.0, "fov").unwrap();
    let e = fov_cardinality(&mb, &ball, 1.0).unwrap_err();
    assert!(
        e.to_string().starts_with("fov.ball.center has length 3"),
        "{e}"
    );
}
