//! Tests of pruning, merging and Runnalls' reduction.

extern crate std;

use std::vec;
use std::vec::Vec;

use nalgebra::{DMatrix, DVector};
use rand::{RngExt, SeedableRng, rngs::SmallRng};

use super::*;
use crate::gaussian::{Gaussian, GaussianMixture};

fn random_mixture(rng: &mut SmallRng, len: usize, n: usize) -> GaussianMixture {
    let comps = (0..len)
        .map(|_| {
            let a = DMatrix::from_fn(n, n, |_, _| rng.random_range(-1.0..1.0));
            let p = &a * a.transpose() + DMatrix::identity(n, n) * 0.1;
            let p = (&p + p.transpose()) * 0.5;
            let m = DVector::from_fn(n, |_, _| rng.random_range(-4.0..4.0));
            let w = rng.random_range(0.01..1.0);
            (w, Gaussian::new(m, p, "c").unwrap())
        })
        .collect();
    GaussianMixture::new(comps, "mixture").unwrap()
}

fn assert_moments_equal(a: &GaussianMixture, b: &GaussianMixture, tol: f64) {
    let (wa, ma, pa) = moments(a).unwrap();
    let (wb, mb, pb) = moments(b).unwrap();
    assert!((wa - wb).abs() < tol * wa, "weight {wa} vs {wb}");
    assert!((&ma - &mb).amax() < tol * (1.0 + ma.amax()), "mean");
    assert!((&pa - &pb).amax() < tol * (1.0 + pa.amax()), "covariance");
}

#[test]
fn prune_keeps_the_total_weight() {
    let c = |x: f64, w: f64| (w, Gaussian::from_slices(&[x], &[1.0], "c").unwrap());
    let p = GaussianMixture::new(
        vec![c(0.0, 0.5), c(1.0, 0.001), c(2.0, 0.3), c(3.0, 0.2)],
        "m",
    )
    .unwrap();
    let out = prune(&p, 0.01).unwrap();
    assert_eq!(out.len(), 3);
    assert!((out.total_weight() - p.total_weight()).abs() < 1e-15);
    // Order kept; weights scaled by 1.001 / 1.0.
    assert_eq!(out.components()[1].1.mean()[0], 2.0);
    assert!((out.components()[0].0 - 0.5 * 1.001).abs() < 1e-15);
    // A threshold of 0 keeps everything; one above every weight keeps the heaviest.
    assert_eq!(prune(&p, 0.0).unwrap(), p);
    let one = prune(&p, 0.9).unwrap();
    assert_eq!(one.len(), 1);
    assert_eq!(one.components()[0].1.mean()[0], 0.0);
    assert!((one.total_weight() - 1.001).abs() < 1e-15);
    assert_eq!(prune(&GaussianMixture::default(), 0.5).unwrap().len(), 0);
    for bad in [-0.1, f64::NAN, f64::INFINITY] {
        assert_eq!(prune(&p, bad).unwrap_err().field(), "pruneBelow");
    }
}

#[test]
fn merge_close_preserves_the_merged_moments() {
    let mut rng = SmallRng::seed_from_u64(3);
    for n in [1, 2, 4] {
        let p = random_mixture(&mut rng, 40, n);
        for d in [0.5, 1.0, 2.0, 4.0] {
            let out = merge_close(&p, d).unwrap();
            if d >= 4.0 {
                assert!(out.len() < p.len(), "n {n}: nothing merged");
            }
            // Total weight, mean and covariance of the whole mixture preserved.
            assert_moments_equal(&p, &out, 1e-12);
        }
    }
}

#[test]
fn merge_close_follows_vo_and_ma() {
    // 1D, unit variances: the heaviest (x = 0) absorbs x = 1.9 (distance 1.9 ≤ 2) but not
    // x = 2.1; then x = 2.1 seeds its own group with x = 3.
    let c = |x: f64, w: f64| (w, Gaussian::from_slices(&[x], &[1.0], "c").unwrap());
    let p = GaussianMixture::new(
        vec![c(1.9, 0.2), c(0.0, 0.5), c(2.1, 0.2), c(3.0, 0.1)],
        "m",
    )
    .unwrap();
    let out = merge_close(&p, 2.0).unwrap();
    assert_eq!(out.len(), 2);
    let (w0, g0) = &out.components()[0];
    assert!((w0 - 0.7).abs() < 1e-15);
    let m0 = 0.2 * 1.9 / 0.7;
    assert!((g0.mean()[0] - m0).abs() < 1e-15);
    // P̃ = Σ w (P + (m̃ − m)²) / w̃: the spread-of-means term.
    let p0 = (0.2 * (1.0 + (m0 - 1.9f64).powi(2)) + 0.5 * (1.0 + m0 * m0)) / 0.7;
    assert!((g0.cov()[(0, 0)] - p0).abs() < 1e-14);
    // The merged moments equal the group's.
    let group = merge_components(&[c(1.9, 0.2), c(0.0, 0.5)], "g").unwrap();
    assert!((group.1.cov()[(0, 0)] - p0).abs() < 1e-14);
    // distance = 0 merges only coincident means.
    let dup = GaussianMixture::new(vec![c(1.0, 0.5), c(1.0, 0.5), c(2.0, 0.1)], "m").unwrap();
    assert_eq!(merge_close(&dup, 0.0).unwrap().len(), 2);
    assert_eq!(merge_close(&p, -1.0).unwrap_err().field(), "mergeDistance");
    assert_eq!(
        merge_components(&[], "g").unwrap_err().field(),
        "components"
    );
}

/// Runnalls' greedy reduction by brute force: recompute every pair's bound each step.
fn runnalls_brute_force(mixture: &GaussianMixture, max: usize) -> GaussianMixture {
    let mut comps: Vec<Option<(f64, Gaussian)>> =
        mixture.components().iter().cloned().map(Some).collect();
    let bound = |a: &(f64, Gaussian), b: &(f64, Gaussian)| {
        let (w, g) = merge_components(&[a.clone(), b.clone()], "g").unwrap();
        0.5 * (w * g.ln_det() - a.0 * a.1.ln_det() - b.0 * b.1.ln_det())
    };
    while comps.iter().flatten().count() > max {
        let mut best: Option<(usize, usize, f64)> = None;
        for i in 0..comps.len() {
            for j in i + 1..comps.len() {
                if let (Some(a), Some(b)) = (&comps[i], &comps[j]) {
                    let c = bound(a, b);
                    if best.is_none_or(|(_, _, bc)| c < bc) {
                        best = Some((i, j, c));
                    }
                }
            }
        }
        let (i, j, _) = best.unwrap();
        let merged =
            merge_components(&[comps[i].clone().unwrap(), comps[j].clone().unwrap()], "g").unwrap();
        comps[i] = Some(merged);
        comps[j] = None;
    }
    GaussianMixture::new(comps.into_iter().flatten().collect(), "m").unwrap()
}

#[test]
fn runnalls_matches_a_brute_force_greedy_reduction() {
    let mut rng = SmallRng::seed_from_u64(11);
    for trial in 0..20 {
        let n = 1 + trial % 4;
        let p = random_mixture(&mut rng, 15, n);
        for max in [1, 4, 10] {
            let fast = runnalls(&p, max).unwrap();
            let slow = runnalls_brute_force(&p, max);
            assert_eq!(fast.len(), max);
            assert_eq!(fast.len(), slow.len());
            for ((wf, gf), (ws, gs)) in fast.components().iter().zip(slow.components()) {
                assert!((wf - ws).abs() < 1e-12);
                assert!((gf.mean() - gs.mean()).amax() < 1e-10);
                assert!((gf.cov() - gs.cov()).amax() < 1e-10);
            }
        }
    }
}

#[test]
fn runnalls_preserves_weight_mean_and_covariance() {
    let mut rng = SmallRng::seed_from_u64(5);
    let p = random_mixture(&mut rng, 300, 4);
    let out = runnalls(&p, 30).unwrap();
    assert_eq!(out.len(), 30);
    assert_moments_equal(&p, &out, 1e-11);
    // Fewer components than the cap: unchanged.
    assert_eq!(runnalls(&p, 300).unwrap(), p);
    assert_eq!(runnalls(&p, 0).unwrap_err().field(), "maxComponents");
}

#[test]
fn runnalls_merges_identical_components_first() {
    let c = |x: f64, w: f64| {
        (
            w,
            Gaussian::from_slices(&[x, 0.0], &[1.0, 0.0, 0.0, 1.0], "c").unwrap(),
        )
    };
    let p = GaussianMixture::new(vec![c(0.0, 0.3), c(5.0, 0.3), c(0.0, 0.4)], "m").unwrap();
    let out = runnalls(&p, 2).unwrap();
    // B = 0 for identical Gaussians: components 0 and 2 merge, weight 0.7, same Gaussian.
    assert!((out.components()[0].0 - 0.7).abs() < 1e-15);
    assert_eq!(out.components()[0].1.mean().as_slice(), &[0.0, 0.0]);
    assert_eq!(out.components()[1].1.mean().as_slice(), &[5.0, 0.0]);
}

#[test]
fn reduce_runs_the_enabled_passes_in_order() {
    let mut rng = SmallRng::seed_from_u64(9);
    let p = random_mixture(&mut rng, 200, 2);
    assert_eq!(reduce(&p, &ReductionOptions::default()).unwrap(), p);
    let opts = ReductionOptions {
        prune_below: 0.05,
        merge_distance: Some(1.0),
        max_components: Some(20),
    };
    let out = reduce(&p, &opts).unwrap();
    assert!(out.len() <= 20);
    assert!((out.total_weight() - p.total_weight()).abs() < 1e-12 * p.total_weight());
    let manual = runnalls(&merge_close(&prune(&p, 0.05).unwrap(), 1.0).unwrap(), 20).unwrap();
    assert_eq!(out, manual);
}
