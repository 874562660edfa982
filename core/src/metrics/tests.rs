//! Cross-checks of the sparse path (grid, graph, sparse and dense per-component solvers)
//! against the dense solver on all pairs and brute force, on scenes of every density.

use alloc::vec;
use alloc::vec::Vec;

use rand::{Rng, RngExt, SeedableRng, rngs::SmallRng};

use super::test_util::brute_force_cut_sum;
use super::*;
use crate::math::linear_assignment;

/// The Euclidean distance without grid coordinates: the set metrics evaluate all pairs.
struct AllPairs;

impl Metric<Vec<f64>> for AllPairs {
    fn distance(&self, a: &Vec<f64>, b: &Vec<f64>) -> f64 {
        Euclidean.distance(a, b)
    }
}

/// The dense oracle: the full `min(d, c)^p` matrix and the dense solver.
fn dense_cut_sum(x: &[Vec<f64>], y: &[Vec<f64>], c: f64, p: f64) -> f64 {
    let cost: Vec<f64> = x
        .iter()
        .flat_map(|a| {
            y.iter()
                .map(|b| fns::powp(Euclidean.distance(a, b).min(c), p))
        })
        .collect();
    linear_assignment(&cost, x.len(), y.len()).unwrap().cost
}

/// A scene: `n` truths uniform in `[0, side]^dim`, a share of the estimates within `jitter`
/// of a truth and the rest uniform; with `lattice > 0` every coordinate is rounded to a
/// multiple of it (coincident points and tied distances).
fn scene<R: Rng>(
    rng: &mut R,
    (n, m, dim): (usize, usize, usize),
    side: f64,
    jitter: f64,
    lattice: f64,
) -> (Vec<Vec<f64>>, Vec<Vec<f64>>) {
    let round = |v: f64| {
        if lattice > 0.0 {
            libm::round(v / lattice) * lattice
        } else {
            v
        }
    };
    let x: Vec<Vec<f64>> = (0..n)
        .map(|_| {
            (0..dim)
                .map(|_| round(rng.random_range(0.0..side)))
                .collect()
        })
        .collect();
    let y = (0..m)
        .map(|j| {
            if n > 0 && j % 3 != 2 {
                let t = &x[rng.random_range(0..n)];
                t.iter()
                    .map(|&v| round(v + rng.random_range(-jitter..=jitter)))
                    .collect()
            } else {
                (0..dim)
                    .map(|_| round(rng.random_range(0.0..side)))
                    .collect()
            }
        })
        .collect();
    (x, y)
}

/// Checks one instance: a valid permutation, consistent costs, the optimum of the dense
/// oracle, and the same value with and without the grid.
fn check(x: &[Vec<f64>], y: &[Vec<f64>], c: f64, p: f64, exact: Option<f64>) {
    // The automatic choice, and the graph path (grid, sparse and dense blocks) whatever the
    // size.
    check_path(x, y, c, p, exact, false);
    check_path(x, y, c, p, exact, true);
}

fn check_path(x: &[Vec<f64>], y: &[Vec<f64>], c: f64, p: f64, exact: Option<f64>, graph: bool) {
    let a = cutoff_assignment_capped(x, y, &Euclidean, c, p, MAX_CLOSE_PAIRS, graph).unwrap();
    let cp = fns::powp(c, p);
    assert_eq!(a.pairs.len(), x.len().min(y.len()));
    let mut used_t = vec![false; x.len()];
    let mut used_e = vec![false; y.len()];
    for q in &a.pairs {
        assert!(!used_t[q.truth] && !used_e[q.estimate], "not one-to-one");
        used_t[q.truth] = true;
        used_e[q.estimate] = true;
        let d = Euclidean.distance(&x[q.truth], &y[q.estimate]);
        if q.close {
            assert!(d < c && q.cost == fns::powp(d, p) && q.cost < cp);
        } else {
            assert_eq!(q.cost, cp);
        }
    }
    assert!(a.pairs.windows(2).all(|w| w[0].truth < w[1].truth));
    let total: f64 = crate::math::sum::sum(a.pairs.iter().map(|q| q.cost));
    assert_eq!(a.total, total);
    let dense = dense_cut_sum(x, y, c, p);
    let tol = 1e-12 * (1.0 + dense);
    assert!(
        (a.total - dense).abs() <= tol,
        "sparse {} vs dense {dense} (n {}, m {}, c {c}, p {p})",
        a.total,
        x.len(),
        y.len()
    );
    if let Some(best) = exact {
        assert!((a.total - best).abs() <= 1e-12 * (1.0 + best));
    }
    let all = cutoff_assignment_capped(x, y, &AllPairs, c, p, MAX_CLOSE_PAIRS, graph).unwrap();
    assert!((all.total - a.total).abs() <= tol, "grid vs all pairs");
    let close = |a: &CutoffAssignment| a.pairs.iter().filter(|q| q.close).count();
    // The number of assigned pairs can differ only between equally good assignments.
    if close(&a) != close(&all) {
        assert!((all.total - a.total).abs() <= tol);
    }
}

#[test]
fn small_instances_match_brute_force_in_1d_to_3d_with_ties() {
    let mut rng = SmallRng::seed_from_u64(151);
    for t in 0..1500 {
        let dim = 1 + t % 3;
        let (n, m) = (rng.random_range(0..=6), rng.random_range(0..=6));
        let lattice = [0.0, 0.5, 1.0][t % 3];
        let (x, y) = scene(&mut rng, (n, m, dim), 4.0, 1.0, lattice);
        let c = [0.3, 1.0, 1.5, 3.0, 10.0][(t / 3) % 5];
        let p = [1.0, 1.5, 2.0, 3.0, 7.5][(t / 15) % 5];
        let best = brute_force_cut_sum(&x, &y, c, p);
        check(&x, &y, c, p, Some(best));
    }
}

#[test]
fn every_density_matches_the_dense_solver() {
    // Sparse (small components), percolating (a giant component), dense blocks, and all
    // pairs closer than c; n ≠ m both ways, ties and coincident points, 1D to 4D.
    let mut rng = SmallRng::seed_from_u64(152);
    let mut t = 0;
    for dim in 1..=4 {
        for (n, m) in [(60, 60), (90, 40), (40, 90), (150, 140)] {
            for density in 0..4 {
                let side = 100.0;
                let c = match density {
                    0 => side / n as f64 * 0.8,
                    1 => side / (n as f64).powf(1.0 / dim as f64) * 1.2,
                    2 => side * 0.6,
                    _ => side * 3.0,
                };
                let lattice = [0.0, 0.0, side / 20.0][t % 3];
                let p = [1.0, 2.0, 2.5, 4.0][t % 4];
                let (x, y) = scene(&mut rng, (n, m, dim), side, c * 0.5, lattice);
                check(&x, &y, c, p, None);
                let axes = pairs::grid_axes(&x, &y, &Euclidean, c);
                let g = pairs::graph_for_tests(&x, &y, &Euclidean, c, p).unwrap();
                match density {
                    0 => assert_eq!((axes, g.blocks.len()), (dim.min(3), 0)),
                    1 if dim <= 2 => assert_eq!((axes, g.blocks.len()), (dim, 0)),
                    1 => {}
                    2 => assert_eq!(axes, 0),
                    _ => assert!(axes == 0 && g.blocks.len() == 1 && g.sparse_rows.is_empty()),
                }
                t += 1;
            }
        }
    }
}

#[test]
fn coincident_points_exact_cutoff_and_cell_boundaries() {
    // Distance exactly c is not an edge; just below is; cell boundaries on both sides.
    let c = 1.0;
    let x = vec![
        vec![0.0, 0.0],
        vec![1.0, 0.0],
        vec![3.0, 3.0],
        vec![3.0, 3.0],
    ];
    let y = vec![
        vec![1.0, 0.0],
        vec![2.0, 0.0],
        vec![3.0, 3.0],
        vec![3.0, 3.0 + (1.0 - f64::EPSILON)],
        vec![0.0, 1.0],
    ];
    for p in [1.0, 2.0, 3.0] {
        check(&x, &y, c, p, Some(brute_force_cut_sum(&x, &y, c, p)));
    }
    // Points exactly on multiples of the cell width, at distance just below c across cells.
    let h = c * (1.0 + 1.0 / 1_048_576.0);
    let x: Vec<Vec<f64>> = (0..40).map(|i| vec![f64::from(i) * h, 0.0]).collect();
    let y: Vec<Vec<f64>> = (0..40)
        .map(|i| vec![f64::from(i) * h + (c - 1e-12), 0.0])
        .collect();
    check(&x, &y, c, 2.0, None);
    // Every point at one place: all pairs at distance 0.
    let x = vec![vec![5.0, 5.0]; 30];
    let y = vec![vec![5.0, 5.0]; 20];
    let a = cutoff_assignment(&x, &y, &Euclidean, 1.0, 2.0).unwrap();
    assert_eq!(a.total, 0.0);
    assert!(a.pairs.iter().all(|q| q.close));
}

#[test]
fn far_offsets_and_spreads_the_grid_cannot_split_stay_exact() {
    let mut rng = SmallRng::seed_from_u64(153);
    for (offset, side, c) in [
        (1e12, 50.0, 2.0),   // large coordinates: rounding of the cell coordinates
        (0.0, 1e6, 1e-4),    // 1e10 cells on each axis: not gridded
        (-3e8, 1e9, 0.5),    // 2e9 cells: not gridded; second axis narrow
        (7.0, 30.0, 1e-300), // nothing closer than c but coincident points
    ] {
        let (mut x, mut y) = scene(&mut rng, (80, 70, 2), side, 4.0 * c, 0.0);
        for pt in x.iter_mut().chain(y.iter_mut()) {
            pt[0] += offset;
            pt[1] = pt[1] * 1e-6 + offset;
        }
        y[0] = x[0].clone();
        check(&x, &y, c, 2.0, None);
    }
}

#[test]
fn dense_blocks_in_both_orientations_and_mixed_components() {
    // One big all-close cluster (dense block, r > k and r < k) next to sparse pairs.
    let mut rng = SmallRng::seed_from_u64(154);
    for (nr, nk) in [(40, 25), (25, 40), (30, 30)] {
        let mut x: Vec<Vec<f64>> = (0..nr)
            .map(|_| vec![rng.random_range(0.0..1.0), rng.random_range(0.0..1.0)])
            .collect();
        let mut y: Vec<Vec<f64>> = (0..nk)
            .map(|_| vec![rng.random_range(0.0..1.0), rng.random_range(0.0..1.0)])
            .collect();
        for i in 0..50 {
            let base = 10.0 + 5.0 * f64::from(i);
            x.push(vec![base, 0.0]);
            y.push(vec![base + rng.random_range(0.0..1.5), 0.0]);
        }
        let g = pairs::graph_for_tests(&x, &y, &Euclidean, 2.0, 2.0).unwrap();
        assert_eq!(g.blocks.len(), 1, "the cluster is one dense block");
        let b = &g.blocks[0];
        assert_eq!((b.rows.len(), b.cols.len()), (nr, nk));
        assert!(g.sparse_rows.len() >= 40, "the pairs stay sparse");
        check(&x, &y, 2.0, 2.0, None);
        check(&x, &y, 2.0, 1.0, None);
    }
}

#[test]
fn custom_metrics_with_and_without_grid_coordinates() {
    /// ℓ1 and ℓ∞ on the coordinates: both dominate every coordinate difference.
    struct Lq(bool, bool);
    impl Metric<Vec<f64>> for Lq {
        fn distance(&self, a: &Vec<f64>, b: &Vec<f64>) -> f64 {
            let diffs = a.iter().zip(b).map(|(u, v)| fns::abs(u - v));
            if self.0 {
                diffs.sum()
            } else {
                diffs.fold(0.0, f64::max)
            }
        }
        fn grid_coordinates<'a>(&self, point: &'a Vec<f64>) -> Option<&'a [f64]> {
            self.1.then_some(point.as_slice())
        }
    }
    let mut rng = SmallRng::seed_from_u64(155);
    for t in 0..40 {
        let dim = 1 + t % 3;
        let (x, y) = scene(&mut rng, (70, 60, dim), 30.0, 1.5, [0.0, 0.5][t % 2]);
        let c = [1.0, 3.0, 8.0][t % 3];
        let l1 = t % 2 == 0;
        let gridded = cutoff_assignment(&x, &y, &Lq(l1, true), c, 2.0).unwrap();
        let plain = cutoff_assignment(&x, &y, &Lq(l1, false), c, 2.0).unwrap();
        assert!((gridded.total - plain.total).abs() <= 1e-12 * (1.0 + plain.total));
        let cost: Vec<f64> = x
            .iter()
            .flat_map(|a| {
                y.iter()
                    .map(|b| fns::powp(Lq(l1, false).distance(a, b).min(c), 2.0))
            })
            .collect();
        let dense = linear_assignment(&cost, x.len(), y.len()).unwrap().cost;
        assert!((plain.total - dense).abs() <= 1e-12 * (1.0 + dense));
    }
}

#[test]
fn grid_coordinate_errors_name_the_point() {
    struct Ragged;
    impl Metric<Vec<f64>> for Ragged {
        fn distance(&self, a: &Vec<f64>, b: &Vec<f64>) -> f64 {
            Euclidean.distance(&a[..1], &b[..1])
        }
        fn grid_coordinates<'a>(&self, point: &'a Vec<f64>) -> Option<&'a [f64]> {
            Some(point.as_slice())
        }
    }
    let x = vec![vec![0.0, 1.0], vec![0.0]];
    let y = vec![vec![0.0, 1.0]];
    let e = cutoff_assignment(&x, &y, &Ragged, 1.0, 2.0).unwrap_err();
    assert_eq!(e.field(), "truth[1]");
    let y = vec![vec![0.0, f64::INFINITY]];
    let e = cutoff_assignment(&x[..1], &y, &Ragged, 1.0, 2.0).unwrap_err();
    assert_eq!(e.field(), "estimate[0][1]");
    let nan = FnMetric(|a: &f64, b: &f64| if a > b { f64::NAN } else { b - a });
    let e = cutoff_assignment(&[0.0, 2.0], &[1.0], &nan, 5.0, 2.0).unwrap_err();
    assert_eq!(e.field(), "distance(truth[1], estimate[0])");
}

#[test]
fn the_cap_on_pairs_closer_than_c_is_an_error_with_the_count() {
    // 40 points on a line, c = 2.5: each is within c of itself and up to two neighbours on
    // each side (40 · 40 pairs: the grid path).
    let x: Vec<[f64; 2]> = (0..40).map(|i| [f64::from(i), 0.0]).collect();
    let y = x.clone();
    let pairs = 40 + 2 * 39 + 2 * 38;
    for graph in [false, true] {
        let ok = cutoff_assignment_capped(&x, &y, &Euclidean, 2.5, 2.0, pairs, graph).unwrap();
        assert_eq!(ok.total, 0.0);
        let e =
            cutoff_assignment_capped(&x, &y, &Euclidean, 2.5, 2.0, pairs - 1, graph).unwrap_err();
        assert_eq!(e.field(), pairs::PAIRS_FIELD);
        assert!(matches!(e, Error::InvalidParameter { value, .. } if value == pairs as f64));
        assert!(alloc::format!("{e}").contains("MAX_CLOSE_PAIRS"));
    }
    // Without grid coordinates, with every pair close (the count comes first).
    let all = FnMetric(|a: &[f64; 2], b: &[f64; 2]| Euclidean.distance(a, b));
    let e = cutoff_assignment_capped(&x, &y, &all, 100.0, 1.0, 1599, true).unwrap_err();
    assert!(matches!(e, Error::InvalidParameter { value, .. } if value == 1600.0));
    #[cfg(target_pointer_width = "64")]
    assert_eq!(MAX_CLOSE_PAIRS, 1 << 27);
}

#[test]
fn gospa_and_ospa_agree_with_the_dense_oracle_on_a_percolating_scene() {
    // Issue 15's percolating density at n = 300: truths in [0, 100·√0.3]², 90 % detected
    // within σ ≈ 1, 10 % clutter, c = 5.
    let mut rng = SmallRng::seed_from_u64(156);
    let side = 100.0 * libm::sqrt(0.3);
    let x: Vec<Vec<f64>> = (0..300)
        .map(|_| vec![rng.random_range(0.0..side), rng.random_range(0.0..side)])
        .collect();
    let mut y: Vec<Vec<f64>> = x[..270]
        .iter()
        .map(|t| t.iter().map(|v| v + rng.random_range(-1.7..1.7)).collect())
        .collect();
    y.extend((0..30).map(|_| vec![rng.random_range(0.0..side), rng.random_range(0.0..side)]));
    for p in [1.0, 2.0, 3.0] {
        check(&x, &y, 5.0, p, None);
        let g = Gospa::new(5.0, p, 2.0).unwrap();
        let d = g.decompose(&x, &y).unwrap();
        let dense = dense_cut_sum(&x, &y, 5.0, p);
        let expected = fns::rootp(dense, p);
        assert!((d.distance - expected).abs() <= 1e-12 * expected);
        let o = Ospa::new(5.0, p).unwrap().distance(&x, &y).unwrap();
        assert!((o - fns::rootp(dense / 300.0, p)).abs() <= 1e-12 * o);
    }
}

#[test]
fn extreme_cut_offs_are_computed_in_units_of_c() {
    // Found by the boundary fuzzer: c = 1e300 made c^p overflow, and ∞ · 0 gave NaN (or the
    // assignment solver trapped); c = 1e-300 made it underflow to 0.
    use crate::metrics::{Gospa, Ospa};
    for c in [1e300, 1e308, 1e-300] {
        let g = Gospa::new(c, 2.0, 2.0).unwrap();
        let o = Ospa::new(c, 2.0).unwrap();
        let u = Gospa::uospa(c, 2.0).unwrap();
        let empty: [[f64; 2]; 0] = [];
        assert_eq!(g.distance(&empty, &empty).unwrap(), 0.0);
        assert_eq!(
            o.decompose(&[[0.0, 0.0, 0.0]], &[[0.0, 0.0, 0.0]])
                .unwrap()
                .distance,
            0.0
        );
        assert_eq!(
            u.distance(&[[0.0, 0.0, 0.0]], &[[0.0, 0.0, 0.0]]).unwrap(),
            0.0
        );
        // One missed point: c/√2, and one OSPA cardinality error: c.
        let d = g.decompose(&[[0.0, 0.0]], &empty).unwrap();
        assert!(
            (d.distance / (c / 2f64.sqrt()) - 1.0).abs() < 1e-15,
            "{d:?}"
        );
        assert_eq!((d.missed, d.false_targets), (1, 0));
        let d = o.decompose(&[[0.0]], &[[0.0], [1.5 * c.max(1.0)]]).unwrap();
        assert!(
            (d.distance / (c / 2f64.sqrt()) - 1.0).abs() < 1e-15,
            "{d:?}"
        );
        assert!(
            (d.cardinality / (c / 2f64.sqrt()) - 1.0).abs() < 1e-15,
            "{d:?}"
        );
        assert_eq!(d.localisation, 0.0);
    }
    // A pair well inside the cut-off: the distance and Σ d^p (1e300, finite) exactly.
    let g = Gospa::new(1e300, 2.0, 2.0).unwrap();
    let d = g.decompose(&[[1e150, 0.0]], &[[0.0, 0.0]]).unwrap();
    assert_eq!(d.missed, 0);
    assert!((d.distance / 1e150 - 1.0).abs() < 1e-15, "{d:?}");
    assert!((d.localisation / 1e300 - 1.0).abs() < 1e-14, "{d:?}");
    let o = Ospa::new(1e300, 2.055031437066112).unwrap();
    let d = o
        .decompose(&[[0.0, 1e150]], &[[0.0, 0.0], [0.0, 0.0]])
        .unwrap();
    assert!(d.distance.is_finite() && d.distance > 0.0, "{d:?}");
}

#[test]
fn a_tiny_alpha_with_every_point_matched_is_not_nan() {
    // Found by the boundary fuzzer: c^p/α overflows for α = 5e-324, and multiplying it by
    // zero unmatched points gave NaN. No unmatched point, no term.
    use crate::metrics::Gospa;
    for c in [1.0, 1e-300] {
        let g = Gospa::new(c, 2.0, 5e-324).unwrap();
        assert_eq!(g.distance(&[[0.0, 0.0]], &[[0.0, 0.0]]).unwrap(), 0.0);
        // One unmatched point: c^p/α is beyond f64 but the distance, c/α^(1/2), is not
        // (computed times α; it was +∞ before the fuzzer's gospaSeries-alpha-subnormal).
        let d = g
            .distance(&[[0.0, 0.0]], &[[0.0, 0.0], [1.0, 1.0]])
            .unwrap();
        let expected = c / 5e-324f64.sqrt();
        assert!(
            (d - expected).abs() <= 1e-15 * expected,
            "{d} vs {expected}"
        );
    }
}

#[test]
fn the_caps_on_points_candidates_and_dense_work_are_errors_naming_the_field() {
    // Found by the boundary fuzzer: 10^6 × 10^6 points (1D, every point within 3c of 10^5
    // others) and 10^6 series steps ran for many seconds.
    use crate::metrics::{
        Gospa, MAX_CANDIDATE_PAIRS, MAX_DENSE_WORK, MAX_SERIES_POINTS, MAX_TOTAL_POINTS, Ospa,
    };
    let g = Gospa::new(1.0, 2.0, 2.0).unwrap();
    let line =
        |n: usize, step: f64| -> Vec<[f64; 1]> { (0..n).map(|i| [i as f64 * step]).collect() };
    let many = line(MAX_TOTAL_POINTS, 10.0);
    let e = g.distance(&many, &line(1, 10.0)).unwrap_err();
    assert!(matches!(e, Error::OverBudget { .. }), "{e}");
    assert_eq!(e.field(), "truth");
    let e = Ospa::new(1.0, 2.0)
        .unwrap()
        .decompose(&line(1, 10.0), &many)
        .unwrap_err();
    assert_eq!(e.field(), "estimate");
    assert_eq!(
        alloc::format!("{e}"),
        "estimate: points in truth and estimate = 524289 exceeds MAX_TOTAL_POINTS = 2^19 per \
         evaluation (at most 524287)"
    );
    // At the cap: a sparse line, fine.
    assert_eq!(
        g.distance(&many, &[] as &[[f64; 1]]).unwrap(),
        (many.len() as f64 / 2.0).sqrt()
    );
    // Candidate pairs: every pair within c and more of them than the cap, at once.
    let side = ((MAX_CANDIDATE_PAIRS as f64).sqrt() as usize) + 1;
    let dense = line(side, 1e-9);
    let e = g.distance(&dense, &dense).unwrap_err();
    assert!(
        matches!(e, Error::InvalidParameter { value, .. } if value == (side * side) as f64),
        "{e}"
    );
    assert_eq!(e.field(), caps::CANDIDATES_FIELD);
    // Dense work: 1100 × 1100 points within c, directly dense and through the graph.
    let block = line(1100, 1e-6);
    assert!(super::caps::dense_work(1100, 1100) > MAX_DENSE_WORK);
    for graph in [false, true] {
        let e =
            cutoff_assignment_capped(&block, &block, &Euclidean, 1.0, 2.0, MAX_CLOSE_PAIRS, graph)
                .unwrap_err();
        assert!(
            matches!(e, Error::InvalidParameter { value, .. } if value == 1100.0f64.powi(3)),
            "{e}"
        );
        assert_eq!(e.field(), caps::WORK_FIELD);
    }
    assert_eq!(super::caps::dense_work(1024, 1024), MAX_DENSE_WORK);
    // A series: the points over all steps.
    let steps = vec![vec![[0.0]]; MAX_SERIES_POINTS / 2 + 1];
    let e = g.series(&steps, &steps).unwrap_err();
    assert!(matches!(e, Error::OverBudget { .. }), "{e}");
    assert_eq!(e.field(), "truths");
    let s = g.series(&steps[1..], &steps[1..]).unwrap();
    assert_eq!(s.mean_distance, 0.0);
    let empty: Vec<Vec<[f64; 1]>> = vec![vec![]; super::MAX_SERIES_STEPS + 1];
    let e = g.series(&empty, &empty).unwrap_err();
    assert!(matches!(e, Error::Count { .. }), "{e}");
    assert_eq!(e.field(), "truths");
}
